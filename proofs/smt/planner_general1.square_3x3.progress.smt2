; holon proof obligation: system planner_general1, region square:3x3, property progress
; expected: unsat (the property holds for every configuration of the region)
(set-logic ALL)
; 
(set-info :status unknown)
(declare-fun c_0_12 () Bool)
(declare-fun c_0_11 () Bool)
(declare-fun c_0_10 () Bool)
(declare-fun c_0_9 () Bool)
(declare-fun c_0_8 () Bool)
(declare-fun c_0_7 () Bool)
(declare-fun c_0_6 () Bool)
(declare-fun c_0_5 () Bool)
(declare-fun c_0_4 () Bool)
(declare-fun c_0_3 () Bool)
(declare-fun c_0_2 () Bool)
(declare-fun c_0_1 () Bool)
(declare-fun c_0_0 () Bool)
(declare-fun c_1_12 () Bool)
(declare-fun c_1_11 () Bool)
(declare-fun c_1_10 () Bool)
(declare-fun c_1_9 () Bool)
(declare-fun c_1_8 () Bool)
(declare-fun c_1_7 () Bool)
(declare-fun c_1_6 () Bool)
(declare-fun c_1_5 () Bool)
(declare-fun c_1_4 () Bool)
(declare-fun c_1_3 () Bool)
(declare-fun c_1_2 () Bool)
(declare-fun c_1_1 () Bool)
(declare-fun c_1_0 () Bool)
(declare-fun c_2_12 () Bool)
(declare-fun c_2_11 () Bool)
(declare-fun c_2_10 () Bool)
(declare-fun c_2_9 () Bool)
(declare-fun c_2_8 () Bool)
(declare-fun c_2_7 () Bool)
(declare-fun c_2_6 () Bool)
(declare-fun c_2_5 () Bool)
(declare-fun c_2_4 () Bool)
(declare-fun c_2_3 () Bool)
(declare-fun c_2_2 () Bool)
(declare-fun c_2_1 () Bool)
(declare-fun c_2_0 () Bool)
(declare-fun c_3_12 () Bool)
(declare-fun c_3_11 () Bool)
(declare-fun c_3_10 () Bool)
(declare-fun c_3_9 () Bool)
(declare-fun c_3_8 () Bool)
(declare-fun c_3_7 () Bool)
(declare-fun c_3_6 () Bool)
(declare-fun c_3_5 () Bool)
(declare-fun c_3_4 () Bool)
(declare-fun c_3_3 () Bool)
(declare-fun c_3_2 () Bool)
(declare-fun c_3_1 () Bool)
(declare-fun c_3_0 () Bool)
(declare-fun c_4_12 () Bool)
(declare-fun c_4_11 () Bool)
(declare-fun c_4_10 () Bool)
(declare-fun c_4_9 () Bool)
(declare-fun c_4_8 () Bool)
(declare-fun c_4_7 () Bool)
(declare-fun c_4_6 () Bool)
(declare-fun c_4_5 () Bool)
(declare-fun c_4_4 () Bool)
(declare-fun c_4_3 () Bool)
(declare-fun c_4_2 () Bool)
(declare-fun c_4_1 () Bool)
(declare-fun c_4_0 () Bool)
(declare-fun c_5_12 () Bool)
(declare-fun c_5_11 () Bool)
(declare-fun c_5_10 () Bool)
(declare-fun c_5_9 () Bool)
(declare-fun c_5_8 () Bool)
(declare-fun c_5_7 () Bool)
(declare-fun c_5_6 () Bool)
(declare-fun c_5_5 () Bool)
(declare-fun c_5_4 () Bool)
(declare-fun c_5_3 () Bool)
(declare-fun c_5_2 () Bool)
(declare-fun c_5_1 () Bool)
(declare-fun c_5_0 () Bool)
(declare-fun c_6_12 () Bool)
(declare-fun c_6_11 () Bool)
(declare-fun c_6_10 () Bool)
(declare-fun c_6_9 () Bool)
(declare-fun c_6_8 () Bool)
(declare-fun c_6_7 () Bool)
(declare-fun c_6_6 () Bool)
(declare-fun c_6_5 () Bool)
(declare-fun c_6_4 () Bool)
(declare-fun c_6_3 () Bool)
(declare-fun c_6_2 () Bool)
(declare-fun c_6_1 () Bool)
(declare-fun c_6_0 () Bool)
(declare-fun c_7_12 () Bool)
(declare-fun c_7_11 () Bool)
(declare-fun c_7_10 () Bool)
(declare-fun c_7_9 () Bool)
(declare-fun c_7_8 () Bool)
(declare-fun c_7_7 () Bool)
(declare-fun c_7_6 () Bool)
(declare-fun c_7_5 () Bool)
(declare-fun c_7_4 () Bool)
(declare-fun c_7_3 () Bool)
(declare-fun c_7_2 () Bool)
(declare-fun c_7_1 () Bool)
(declare-fun c_7_0 () Bool)
(declare-fun c_8_12 () Bool)
(declare-fun c_8_11 () Bool)
(declare-fun c_8_10 () Bool)
(declare-fun c_8_9 () Bool)
(declare-fun c_8_8 () Bool)
(declare-fun c_8_7 () Bool)
(declare-fun c_8_6 () Bool)
(declare-fun c_8_5 () Bool)
(declare-fun c_8_4 () Bool)
(declare-fun c_8_3 () Bool)
(declare-fun c_8_2 () Bool)
(declare-fun c_8_1 () Bool)
(declare-fun c_8_0 () Bool)
(declare-fun rank_0 () Int)
(declare-fun rank_2 () Int)
(declare-fun rank_4 () Int)
(declare-fun rank_6 () Int)
(declare-fun rank_8 () Int)
(declare-fun rank_10 () Int)
(declare-fun rank_12 () Int)
(declare-fun rank_14 () Int)
(declare-fun rank_16 () Int)
(declare-fun rank_18 () Int)
(declare-fun rank_20 () Int)
(declare-fun rank_22 () Int)
(declare-fun rank_24 () Int)
(declare-fun rank_26 () Int)
(declare-fun rank_28 () Int)
(declare-fun rank_30 () Int)
(declare-fun rank_32 () Int)
(declare-fun rank_34 () Int)
(declare-fun prank_36 () Int)
(declare-fun prank_37 () Int)
(declare-fun prank_38 () Int)
(declare-fun prank_39 () Int)
(declare-fun prank_40 () Int)
(declare-fun prank_41 () Int)
(declare-fun prank_42 () Int)
(declare-fun prank_43 () Int)
(declare-fun prank_44 () Int)
(declare-fun prank_47 () Int)
(declare-fun prank_48 () Int)
(declare-fun prank_49 () Int)
(declare-fun prank_50 () Int)
(declare-fun prank_51 () Int)
(declare-fun prank_52 () Int)
(declare-fun prank_53 () Int)
(declare-fun prank_54 () Int)
(declare-fun prank_55 () Int)
(declare-fun rank_58 () Int)
(declare-fun rank_60 () Int)
(declare-fun rank_62 () Int)
(declare-fun rank_64 () Int)
(declare-fun rank_66 () Int)
(declare-fun rank_68 () Int)
(declare-fun rank_70 () Int)
(declare-fun rank_72 () Int)
(declare-fun rank_74 () Int)
(declare-fun root_75 () Bool)
(declare-fun root_73 () Bool)
(declare-fun root_71 () Bool)
(declare-fun root_69 () Bool)
(declare-fun root_67 () Bool)
(declare-fun root_65 () Bool)
(declare-fun root_63 () Bool)
(declare-fun root_61 () Bool)
(declare-fun root_59 () Bool)
(declare-fun prank_high_57 () Int)
(declare-fun prank_low_56 () Int)
(declare-fun prank_high_46 () Int)
(declare-fun prank_low_45 () Int)
(declare-fun in_target_8 () Bool)
(declare-fun in_target_7 () Bool)
(declare-fun in_target_6 () Bool)
(declare-fun in_target_5 () Bool)
(declare-fun in_target_4 () Bool)
(declare-fun in_target_3 () Bool)
(declare-fun in_target_2 () Bool)
(declare-fun in_target_1 () Bool)
(declare-fun in_target_0 () Bool)
(declare-fun root_35 () Bool)
(declare-fun root_33 () Bool)
(declare-fun root_31 () Bool)
(declare-fun root_29 () Bool)
(declare-fun root_27 () Bool)
(declare-fun root_25 () Bool)
(declare-fun root_23 () Bool)
(declare-fun root_21 () Bool)
(declare-fun root_19 () Bool)
(declare-fun in_target_36 () Bool)
(declare-fun in_target_35 () Bool)
(declare-fun in_target_34 () Bool)
(declare-fun in_target_33 () Bool)
(declare-fun in_target_32 () Bool)
(declare-fun in_target_31 () Bool)
(declare-fun in_target_30 () Bool)
(declare-fun in_target_29 () Bool)
(declare-fun in_target_28 () Bool)
(declare-fun in_target_27 () Bool)
(declare-fun in_target_26 () Bool)
(declare-fun in_target_25 () Bool)
(declare-fun in_target_24 () Bool)
(declare-fun in_target_23 () Bool)
(declare-fun in_target_22 () Bool)
(declare-fun in_target_21 () Bool)
(declare-fun in_target_20 () Bool)
(declare-fun in_target_19 () Bool)
(declare-fun in_target_18 () Bool)
(declare-fun in_target_17 () Bool)
(declare-fun in_target_16 () Bool)
(declare-fun in_target_15 () Bool)
(declare-fun in_target_14 () Bool)
(declare-fun in_target_13 () Bool)
(declare-fun in_target_12 () Bool)
(declare-fun in_target_11 () Bool)
(declare-fun in_target_10 () Bool)
(declare-fun in_target_9 () Bool)
(declare-fun root_17 () Bool)
(declare-fun root_15 () Bool)
(declare-fun root_13 () Bool)
(declare-fun root_11 () Bool)
(declare-fun root_9 () Bool)
(declare-fun root_7 () Bool)
(declare-fun root_5 () Bool)
(declare-fun root_3 () Bool)
(declare-fun root_1 () Bool)
(assert
 (let (($x15 (or false c_0_0)))
 (let (($x17 (or $x15 c_0_1)))
 (let (($x19 (or $x17 c_0_2)))
 (let (($x21 (or $x19 c_0_3)))
 (let (($x23 (or $x21 c_0_4)))
 (let (($x25 (or $x23 c_0_5)))
 (let (($x27 (or $x25 c_0_6)))
 (let (($x29 (or $x27 c_0_7)))
 (let (($x31 (or $x29 c_0_8)))
 (let (($x33 (or $x31 c_0_9)))
 (let (($x35 (or $x33 c_0_10)))
 (let (($x37 (or $x35 c_0_11)))
 (or $x37 c_0_12))))))))))))))
(assert
 (not (and c_0_0 c_0_1)))
(assert
 (not (and c_0_0 c_0_2)))
(assert
 (not (and c_0_0 c_0_3)))
(assert
 (not (and c_0_0 c_0_4)))
(assert
 (not (and c_0_0 c_0_5)))
(assert
 (not (and c_0_0 c_0_6)))
(assert
 (not (and c_0_0 c_0_7)))
(assert
 (not (and c_0_0 c_0_8)))
(assert
 (not (and c_0_0 c_0_9)))
(assert
 (not (and c_0_0 c_0_10)))
(assert
 (not (and c_0_0 c_0_11)))
(assert
 (not (and c_0_0 c_0_12)))
(assert
 (not (and c_0_1 c_0_2)))
(assert
 (not (and c_0_1 c_0_3)))
(assert
 (not (and c_0_1 c_0_4)))
(assert
 (not (and c_0_1 c_0_5)))
(assert
 (not (and c_0_1 c_0_6)))
(assert
 (not (and c_0_1 c_0_7)))
(assert
 (not (and c_0_1 c_0_8)))
(assert
 (not (and c_0_1 c_0_9)))
(assert
 (not (and c_0_1 c_0_10)))
(assert
 (not (and c_0_1 c_0_11)))
(assert
 (not (and c_0_1 c_0_12)))
(assert
 (not (and c_0_2 c_0_3)))
(assert
 (not (and c_0_2 c_0_4)))
(assert
 (not (and c_0_2 c_0_5)))
(assert
 (not (and c_0_2 c_0_6)))
(assert
 (not (and c_0_2 c_0_7)))
(assert
 (not (and c_0_2 c_0_8)))
(assert
 (not (and c_0_2 c_0_9)))
(assert
 (not (and c_0_2 c_0_10)))
(assert
 (not (and c_0_2 c_0_11)))
(assert
 (not (and c_0_2 c_0_12)))
(assert
 (not (and c_0_3 c_0_4)))
(assert
 (not (and c_0_3 c_0_5)))
(assert
 (not (and c_0_3 c_0_6)))
(assert
 (not (and c_0_3 c_0_7)))
(assert
 (not (and c_0_3 c_0_8)))
(assert
 (not (and c_0_3 c_0_9)))
(assert
 (not (and c_0_3 c_0_10)))
(assert
 (not (and c_0_3 c_0_11)))
(assert
 (not (and c_0_3 c_0_12)))
(assert
 (not (and c_0_4 c_0_5)))
(assert
 (not (and c_0_4 c_0_6)))
(assert
 (not (and c_0_4 c_0_7)))
(assert
 (not (and c_0_4 c_0_8)))
(assert
 (not (and c_0_4 c_0_9)))
(assert
 (not (and c_0_4 c_0_10)))
(assert
 (not (and c_0_4 c_0_11)))
(assert
 (not (and c_0_4 c_0_12)))
(assert
 (not (and c_0_5 c_0_6)))
(assert
 (not (and c_0_5 c_0_7)))
(assert
 (not (and c_0_5 c_0_8)))
(assert
 (not (and c_0_5 c_0_9)))
(assert
 (not (and c_0_5 c_0_10)))
(assert
 (not (and c_0_5 c_0_11)))
(assert
 (not (and c_0_5 c_0_12)))
(assert
 (not (and c_0_6 c_0_7)))
(assert
 (not (and c_0_6 c_0_8)))
(assert
 (not (and c_0_6 c_0_9)))
(assert
 (not (and c_0_6 c_0_10)))
(assert
 (not (and c_0_6 c_0_11)))
(assert
 (not (and c_0_6 c_0_12)))
(assert
 (not (and c_0_7 c_0_8)))
(assert
 (not (and c_0_7 c_0_9)))
(assert
 (not (and c_0_7 c_0_10)))
(assert
 (not (and c_0_7 c_0_11)))
(assert
 (not (and c_0_7 c_0_12)))
(assert
 (not (and c_0_8 c_0_9)))
(assert
 (not (and c_0_8 c_0_10)))
(assert
 (not (and c_0_8 c_0_11)))
(assert
 (not (and c_0_8 c_0_12)))
(assert
 (not (and c_0_9 c_0_10)))
(assert
 (not (and c_0_9 c_0_11)))
(assert
 (not (and c_0_9 c_0_12)))
(assert
 (not (and c_0_10 c_0_11)))
(assert
 (not (and c_0_10 c_0_12)))
(assert
 (not (and c_0_11 c_0_12)))
(assert
 (let (($x197 (or false c_1_0)))
 (let (($x199 (or $x197 c_1_1)))
 (let (($x201 (or $x199 c_1_2)))
 (let (($x203 (or $x201 c_1_3)))
 (let (($x205 (or $x203 c_1_4)))
 (let (($x207 (or $x205 c_1_5)))
 (let (($x209 (or $x207 c_1_6)))
 (let (($x211 (or $x209 c_1_7)))
 (let (($x213 (or $x211 c_1_8)))
 (let (($x215 (or $x213 c_1_9)))
 (let (($x217 (or $x215 c_1_10)))
 (let (($x219 (or $x217 c_1_11)))
 (or $x219 c_1_12))))))))))))))
(assert
 (not (and c_1_0 c_1_1)))
(assert
 (not (and c_1_0 c_1_2)))
(assert
 (not (and c_1_0 c_1_3)))
(assert
 (not (and c_1_0 c_1_4)))
(assert
 (not (and c_1_0 c_1_5)))
(assert
 (not (and c_1_0 c_1_6)))
(assert
 (not (and c_1_0 c_1_7)))
(assert
 (not (and c_1_0 c_1_8)))
(assert
 (not (and c_1_0 c_1_9)))
(assert
 (not (and c_1_0 c_1_10)))
(assert
 (not (and c_1_0 c_1_11)))
(assert
 (not (and c_1_0 c_1_12)))
(assert
 (not (and c_1_1 c_1_2)))
(assert
 (not (and c_1_1 c_1_3)))
(assert
 (not (and c_1_1 c_1_4)))
(assert
 (not (and c_1_1 c_1_5)))
(assert
 (not (and c_1_1 c_1_6)))
(assert
 (not (and c_1_1 c_1_7)))
(assert
 (not (and c_1_1 c_1_8)))
(assert
 (not (and c_1_1 c_1_9)))
(assert
 (not (and c_1_1 c_1_10)))
(assert
 (not (and c_1_1 c_1_11)))
(assert
 (not (and c_1_1 c_1_12)))
(assert
 (not (and c_1_2 c_1_3)))
(assert
 (not (and c_1_2 c_1_4)))
(assert
 (not (and c_1_2 c_1_5)))
(assert
 (not (and c_1_2 c_1_6)))
(assert
 (not (and c_1_2 c_1_7)))
(assert
 (not (and c_1_2 c_1_8)))
(assert
 (not (and c_1_2 c_1_9)))
(assert
 (not (and c_1_2 c_1_10)))
(assert
 (not (and c_1_2 c_1_11)))
(assert
 (not (and c_1_2 c_1_12)))
(assert
 (not (and c_1_3 c_1_4)))
(assert
 (not (and c_1_3 c_1_5)))
(assert
 (not (and c_1_3 c_1_6)))
(assert
 (not (and c_1_3 c_1_7)))
(assert
 (not (and c_1_3 c_1_8)))
(assert
 (not (and c_1_3 c_1_9)))
(assert
 (not (and c_1_3 c_1_10)))
(assert
 (not (and c_1_3 c_1_11)))
(assert
 (not (and c_1_3 c_1_12)))
(assert
 (not (and c_1_4 c_1_5)))
(assert
 (not (and c_1_4 c_1_6)))
(assert
 (not (and c_1_4 c_1_7)))
(assert
 (not (and c_1_4 c_1_8)))
(assert
 (not (and c_1_4 c_1_9)))
(assert
 (not (and c_1_4 c_1_10)))
(assert
 (not (and c_1_4 c_1_11)))
(assert
 (not (and c_1_4 c_1_12)))
(assert
 (not (and c_1_5 c_1_6)))
(assert
 (not (and c_1_5 c_1_7)))
(assert
 (not (and c_1_5 c_1_8)))
(assert
 (not (and c_1_5 c_1_9)))
(assert
 (not (and c_1_5 c_1_10)))
(assert
 (not (and c_1_5 c_1_11)))
(assert
 (not (and c_1_5 c_1_12)))
(assert
 (not (and c_1_6 c_1_7)))
(assert
 (not (and c_1_6 c_1_8)))
(assert
 (not (and c_1_6 c_1_9)))
(assert
 (not (and c_1_6 c_1_10)))
(assert
 (not (and c_1_6 c_1_11)))
(assert
 (not (and c_1_6 c_1_12)))
(assert
 (not (and c_1_7 c_1_8)))
(assert
 (not (and c_1_7 c_1_9)))
(assert
 (not (and c_1_7 c_1_10)))
(assert
 (not (and c_1_7 c_1_11)))
(assert
 (not (and c_1_7 c_1_12)))
(assert
 (not (and c_1_8 c_1_9)))
(assert
 (not (and c_1_8 c_1_10)))
(assert
 (not (and c_1_8 c_1_11)))
(assert
 (not (and c_1_8 c_1_12)))
(assert
 (not (and c_1_9 c_1_10)))
(assert
 (not (and c_1_9 c_1_11)))
(assert
 (not (and c_1_9 c_1_12)))
(assert
 (not (and c_1_10 c_1_11)))
(assert
 (not (and c_1_10 c_1_12)))
(assert
 (not (and c_1_11 c_1_12)))
(assert
 (let (($x379 (or false c_2_0)))
 (let (($x381 (or $x379 c_2_1)))
 (let (($x383 (or $x381 c_2_2)))
 (let (($x385 (or $x383 c_2_3)))
 (let (($x387 (or $x385 c_2_4)))
 (let (($x389 (or $x387 c_2_5)))
 (let (($x391 (or $x389 c_2_6)))
 (let (($x393 (or $x391 c_2_7)))
 (let (($x395 (or $x393 c_2_8)))
 (let (($x397 (or $x395 c_2_9)))
 (let (($x399 (or $x397 c_2_10)))
 (let (($x401 (or $x399 c_2_11)))
 (or $x401 c_2_12))))))))))))))
(assert
 (not (and c_2_0 c_2_1)))
(assert
 (not (and c_2_0 c_2_2)))
(assert
 (not (and c_2_0 c_2_3)))
(assert
 (not (and c_2_0 c_2_4)))
(assert
 (not (and c_2_0 c_2_5)))
(assert
 (not (and c_2_0 c_2_6)))
(assert
 (not (and c_2_0 c_2_7)))
(assert
 (not (and c_2_0 c_2_8)))
(assert
 (not (and c_2_0 c_2_9)))
(assert
 (not (and c_2_0 c_2_10)))
(assert
 (not (and c_2_0 c_2_11)))
(assert
 (not (and c_2_0 c_2_12)))
(assert
 (not (and c_2_1 c_2_2)))
(assert
 (not (and c_2_1 c_2_3)))
(assert
 (not (and c_2_1 c_2_4)))
(assert
 (not (and c_2_1 c_2_5)))
(assert
 (not (and c_2_1 c_2_6)))
(assert
 (not (and c_2_1 c_2_7)))
(assert
 (not (and c_2_1 c_2_8)))
(assert
 (not (and c_2_1 c_2_9)))
(assert
 (not (and c_2_1 c_2_10)))
(assert
 (not (and c_2_1 c_2_11)))
(assert
 (not (and c_2_1 c_2_12)))
(assert
 (not (and c_2_2 c_2_3)))
(assert
 (not (and c_2_2 c_2_4)))
(assert
 (not (and c_2_2 c_2_5)))
(assert
 (not (and c_2_2 c_2_6)))
(assert
 (not (and c_2_2 c_2_7)))
(assert
 (not (and c_2_2 c_2_8)))
(assert
 (not (and c_2_2 c_2_9)))
(assert
 (not (and c_2_2 c_2_10)))
(assert
 (not (and c_2_2 c_2_11)))
(assert
 (not (and c_2_2 c_2_12)))
(assert
 (not (and c_2_3 c_2_4)))
(assert
 (not (and c_2_3 c_2_5)))
(assert
 (not (and c_2_3 c_2_6)))
(assert
 (not (and c_2_3 c_2_7)))
(assert
 (not (and c_2_3 c_2_8)))
(assert
 (not (and c_2_3 c_2_9)))
(assert
 (not (and c_2_3 c_2_10)))
(assert
 (not (and c_2_3 c_2_11)))
(assert
 (not (and c_2_3 c_2_12)))
(assert
 (not (and c_2_4 c_2_5)))
(assert
 (not (and c_2_4 c_2_6)))
(assert
 (not (and c_2_4 c_2_7)))
(assert
 (not (and c_2_4 c_2_8)))
(assert
 (not (and c_2_4 c_2_9)))
(assert
 (not (and c_2_4 c_2_10)))
(assert
 (not (and c_2_4 c_2_11)))
(assert
 (not (and c_2_4 c_2_12)))
(assert
 (not (and c_2_5 c_2_6)))
(assert
 (not (and c_2_5 c_2_7)))
(assert
 (not (and c_2_5 c_2_8)))
(assert
 (not (and c_2_5 c_2_9)))
(assert
 (not (and c_2_5 c_2_10)))
(assert
 (not (and c_2_5 c_2_11)))
(assert
 (not (and c_2_5 c_2_12)))
(assert
 (not (and c_2_6 c_2_7)))
(assert
 (not (and c_2_6 c_2_8)))
(assert
 (not (and c_2_6 c_2_9)))
(assert
 (not (and c_2_6 c_2_10)))
(assert
 (not (and c_2_6 c_2_11)))
(assert
 (not (and c_2_6 c_2_12)))
(assert
 (not (and c_2_7 c_2_8)))
(assert
 (not (and c_2_7 c_2_9)))
(assert
 (not (and c_2_7 c_2_10)))
(assert
 (not (and c_2_7 c_2_11)))
(assert
 (not (and c_2_7 c_2_12)))
(assert
 (not (and c_2_8 c_2_9)))
(assert
 (not (and c_2_8 c_2_10)))
(assert
 (not (and c_2_8 c_2_11)))
(assert
 (not (and c_2_8 c_2_12)))
(assert
 (not (and c_2_9 c_2_10)))
(assert
 (not (and c_2_9 c_2_11)))
(assert
 (not (and c_2_9 c_2_12)))
(assert
 (not (and c_2_10 c_2_11)))
(assert
 (not (and c_2_10 c_2_12)))
(assert
 (not (and c_2_11 c_2_12)))
(assert
 (let (($x561 (or false c_3_0)))
 (let (($x563 (or $x561 c_3_1)))
 (let (($x565 (or $x563 c_3_2)))
 (let (($x567 (or $x565 c_3_3)))
 (let (($x569 (or $x567 c_3_4)))
 (let (($x571 (or $x569 c_3_5)))
 (let (($x573 (or $x571 c_3_6)))
 (let (($x575 (or $x573 c_3_7)))
 (let (($x577 (or $x575 c_3_8)))
 (let (($x579 (or $x577 c_3_9)))
 (let (($x581 (or $x579 c_3_10)))
 (let (($x583 (or $x581 c_3_11)))
 (or $x583 c_3_12))))))))))))))
(assert
 (not (and c_3_0 c_3_1)))
(assert
 (not (and c_3_0 c_3_2)))
(assert
 (not (and c_3_0 c_3_3)))
(assert
 (not (and c_3_0 c_3_4)))
(assert
 (not (and c_3_0 c_3_5)))
(assert
 (not (and c_3_0 c_3_6)))
(assert
 (not (and c_3_0 c_3_7)))
(assert
 (not (and c_3_0 c_3_8)))
(assert
 (not (and c_3_0 c_3_9)))
(assert
 (not (and c_3_0 c_3_10)))
(assert
 (not (and c_3_0 c_3_11)))
(assert
 (not (and c_3_0 c_3_12)))
(assert
 (not (and c_3_1 c_3_2)))
(assert
 (not (and c_3_1 c_3_3)))
(assert
 (not (and c_3_1 c_3_4)))
(assert
 (not (and c_3_1 c_3_5)))
(assert
 (not (and c_3_1 c_3_6)))
(assert
 (not (and c_3_1 c_3_7)))
(assert
 (not (and c_3_1 c_3_8)))
(assert
 (not (and c_3_1 c_3_9)))
(assert
 (not (and c_3_1 c_3_10)))
(assert
 (not (and c_3_1 c_3_11)))
(assert
 (not (and c_3_1 c_3_12)))
(assert
 (not (and c_3_2 c_3_3)))
(assert
 (not (and c_3_2 c_3_4)))
(assert
 (not (and c_3_2 c_3_5)))
(assert
 (not (and c_3_2 c_3_6)))
(assert
 (not (and c_3_2 c_3_7)))
(assert
 (not (and c_3_2 c_3_8)))
(assert
 (not (and c_3_2 c_3_9)))
(assert
 (not (and c_3_2 c_3_10)))
(assert
 (not (and c_3_2 c_3_11)))
(assert
 (not (and c_3_2 c_3_12)))
(assert
 (not (and c_3_3 c_3_4)))
(assert
 (not (and c_3_3 c_3_5)))
(assert
 (not (and c_3_3 c_3_6)))
(assert
 (not (and c_3_3 c_3_7)))
(assert
 (not (and c_3_3 c_3_8)))
(assert
 (not (and c_3_3 c_3_9)))
(assert
 (not (and c_3_3 c_3_10)))
(assert
 (not (and c_3_3 c_3_11)))
(assert
 (not (and c_3_3 c_3_12)))
(assert
 (not (and c_3_4 c_3_5)))
(assert
 (not (and c_3_4 c_3_6)))
(assert
 (not (and c_3_4 c_3_7)))
(assert
 (not (and c_3_4 c_3_8)))
(assert
 (not (and c_3_4 c_3_9)))
(assert
 (not (and c_3_4 c_3_10)))
(assert
 (not (and c_3_4 c_3_11)))
(assert
 (not (and c_3_4 c_3_12)))
(assert
 (not (and c_3_5 c_3_6)))
(assert
 (not (and c_3_5 c_3_7)))
(assert
 (not (and c_3_5 c_3_8)))
(assert
 (not (and c_3_5 c_3_9)))
(assert
 (not (and c_3_5 c_3_10)))
(assert
 (not (and c_3_5 c_3_11)))
(assert
 (not (and c_3_5 c_3_12)))
(assert
 (not (and c_3_6 c_3_7)))
(assert
 (not (and c_3_6 c_3_8)))
(assert
 (not (and c_3_6 c_3_9)))
(assert
 (not (and c_3_6 c_3_10)))
(assert
 (not (and c_3_6 c_3_11)))
(assert
 (not (and c_3_6 c_3_12)))
(assert
 (not (and c_3_7 c_3_8)))
(assert
 (not (and c_3_7 c_3_9)))
(assert
 (not (and c_3_7 c_3_10)))
(assert
 (not (and c_3_7 c_3_11)))
(assert
 (not (and c_3_7 c_3_12)))
(assert
 (not (and c_3_8 c_3_9)))
(assert
 (not (and c_3_8 c_3_10)))
(assert
 (not (and c_3_8 c_3_11)))
(assert
 (not (and c_3_8 c_3_12)))
(assert
 (not (and c_3_9 c_3_10)))
(assert
 (not (and c_3_9 c_3_11)))
(assert
 (not (and c_3_9 c_3_12)))
(assert
 (not (and c_3_10 c_3_11)))
(assert
 (not (and c_3_10 c_3_12)))
(assert
 (not (and c_3_11 c_3_12)))
(assert
 (let (($x743 (or false c_4_0)))
 (let (($x745 (or $x743 c_4_1)))
 (let (($x747 (or $x745 c_4_2)))
 (let (($x749 (or $x747 c_4_3)))
 (let (($x751 (or $x749 c_4_4)))
 (let (($x753 (or $x751 c_4_5)))
 (let (($x755 (or $x753 c_4_6)))
 (let (($x757 (or $x755 c_4_7)))
 (let (($x759 (or $x757 c_4_8)))
 (let (($x761 (or $x759 c_4_9)))
 (let (($x763 (or $x761 c_4_10)))
 (let (($x765 (or $x763 c_4_11)))
 (or $x765 c_4_12))))))))))))))
(assert
 (not (and c_4_0 c_4_1)))
(assert
 (not (and c_4_0 c_4_2)))
(assert
 (not (and c_4_0 c_4_3)))
(assert
 (not (and c_4_0 c_4_4)))
(assert
 (not (and c_4_0 c_4_5)))
(assert
 (not (and c_4_0 c_4_6)))
(assert
 (not (and c_4_0 c_4_7)))
(assert
 (not (and c_4_0 c_4_8)))
(assert
 (not (and c_4_0 c_4_9)))
(assert
 (not (and c_4_0 c_4_10)))
(assert
 (not (and c_4_0 c_4_11)))
(assert
 (not (and c_4_0 c_4_12)))
(assert
 (not (and c_4_1 c_4_2)))
(assert
 (not (and c_4_1 c_4_3)))
(assert
 (not (and c_4_1 c_4_4)))
(assert
 (not (and c_4_1 c_4_5)))
(assert
 (not (and c_4_1 c_4_6)))
(assert
 (not (and c_4_1 c_4_7)))
(assert
 (not (and c_4_1 c_4_8)))
(assert
 (not (and c_4_1 c_4_9)))
(assert
 (not (and c_4_1 c_4_10)))
(assert
 (not (and c_4_1 c_4_11)))
(assert
 (not (and c_4_1 c_4_12)))
(assert
 (not (and c_4_2 c_4_3)))
(assert
 (not (and c_4_2 c_4_4)))
(assert
 (not (and c_4_2 c_4_5)))
(assert
 (not (and c_4_2 c_4_6)))
(assert
 (not (and c_4_2 c_4_7)))
(assert
 (not (and c_4_2 c_4_8)))
(assert
 (not (and c_4_2 c_4_9)))
(assert
 (not (and c_4_2 c_4_10)))
(assert
 (not (and c_4_2 c_4_11)))
(assert
 (not (and c_4_2 c_4_12)))
(assert
 (not (and c_4_3 c_4_4)))
(assert
 (not (and c_4_3 c_4_5)))
(assert
 (not (and c_4_3 c_4_6)))
(assert
 (not (and c_4_3 c_4_7)))
(assert
 (not (and c_4_3 c_4_8)))
(assert
 (not (and c_4_3 c_4_9)))
(assert
 (not (and c_4_3 c_4_10)))
(assert
 (not (and c_4_3 c_4_11)))
(assert
 (not (and c_4_3 c_4_12)))
(assert
 (not (and c_4_4 c_4_5)))
(assert
 (not (and c_4_4 c_4_6)))
(assert
 (not (and c_4_4 c_4_7)))
(assert
 (not (and c_4_4 c_4_8)))
(assert
 (not (and c_4_4 c_4_9)))
(assert
 (not (and c_4_4 c_4_10)))
(assert
 (not (and c_4_4 c_4_11)))
(assert
 (not (and c_4_4 c_4_12)))
(assert
 (not (and c_4_5 c_4_6)))
(assert
 (not (and c_4_5 c_4_7)))
(assert
 (not (and c_4_5 c_4_8)))
(assert
 (not (and c_4_5 c_4_9)))
(assert
 (not (and c_4_5 c_4_10)))
(assert
 (not (and c_4_5 c_4_11)))
(assert
 (not (and c_4_5 c_4_12)))
(assert
 (not (and c_4_6 c_4_7)))
(assert
 (not (and c_4_6 c_4_8)))
(assert
 (not (and c_4_6 c_4_9)))
(assert
 (not (and c_4_6 c_4_10)))
(assert
 (not (and c_4_6 c_4_11)))
(assert
 (not (and c_4_6 c_4_12)))
(assert
 (not (and c_4_7 c_4_8)))
(assert
 (not (and c_4_7 c_4_9)))
(assert
 (not (and c_4_7 c_4_10)))
(assert
 (not (and c_4_7 c_4_11)))
(assert
 (not (and c_4_7 c_4_12)))
(assert
 (not (and c_4_8 c_4_9)))
(assert
 (not (and c_4_8 c_4_10)))
(assert
 (not (and c_4_8 c_4_11)))
(assert
 (not (and c_4_8 c_4_12)))
(assert
 (not (and c_4_9 c_4_10)))
(assert
 (not (and c_4_9 c_4_11)))
(assert
 (not (and c_4_9 c_4_12)))
(assert
 (not (and c_4_10 c_4_11)))
(assert
 (not (and c_4_10 c_4_12)))
(assert
 (not (and c_4_11 c_4_12)))
(assert
 (let (($x925 (or false c_5_0)))
 (let (($x927 (or $x925 c_5_1)))
 (let (($x929 (or $x927 c_5_2)))
 (let (($x931 (or $x929 c_5_3)))
 (let (($x933 (or $x931 c_5_4)))
 (let (($x935 (or $x933 c_5_5)))
 (let (($x937 (or $x935 c_5_6)))
 (let (($x939 (or $x937 c_5_7)))
 (let (($x941 (or $x939 c_5_8)))
 (let (($x943 (or $x941 c_5_9)))
 (let (($x945 (or $x943 c_5_10)))
 (let (($x947 (or $x945 c_5_11)))
 (or $x947 c_5_12))))))))))))))
(assert
 (not (and c_5_0 c_5_1)))
(assert
 (not (and c_5_0 c_5_2)))
(assert
 (not (and c_5_0 c_5_3)))
(assert
 (not (and c_5_0 c_5_4)))
(assert
 (not (and c_5_0 c_5_5)))
(assert
 (not (and c_5_0 c_5_6)))
(assert
 (not (and c_5_0 c_5_7)))
(assert
 (not (and c_5_0 c_5_8)))
(assert
 (not (and c_5_0 c_5_9)))
(assert
 (not (and c_5_0 c_5_10)))
(assert
 (not (and c_5_0 c_5_11)))
(assert
 (not (and c_5_0 c_5_12)))
(assert
 (not (and c_5_1 c_5_2)))
(assert
 (not (and c_5_1 c_5_3)))
(assert
 (not (and c_5_1 c_5_4)))
(assert
 (not (and c_5_1 c_5_5)))
(assert
 (not (and c_5_1 c_5_6)))
(assert
 (not (and c_5_1 c_5_7)))
(assert
 (not (and c_5_1 c_5_8)))
(assert
 (not (and c_5_1 c_5_9)))
(assert
 (not (and c_5_1 c_5_10)))
(assert
 (not (and c_5_1 c_5_11)))
(assert
 (not (and c_5_1 c_5_12)))
(assert
 (not (and c_5_2 c_5_3)))
(assert
 (not (and c_5_2 c_5_4)))
(assert
 (not (and c_5_2 c_5_5)))
(assert
 (not (and c_5_2 c_5_6)))
(assert
 (not (and c_5_2 c_5_7)))
(assert
 (not (and c_5_2 c_5_8)))
(assert
 (not (and c_5_2 c_5_9)))
(assert
 (not (and c_5_2 c_5_10)))
(assert
 (not (and c_5_2 c_5_11)))
(assert
 (not (and c_5_2 c_5_12)))
(assert
 (not (and c_5_3 c_5_4)))
(assert
 (not (and c_5_3 c_5_5)))
(assert
 (not (and c_5_3 c_5_6)))
(assert
 (not (and c_5_3 c_5_7)))
(assert
 (not (and c_5_3 c_5_8)))
(assert
 (not (and c_5_3 c_5_9)))
(assert
 (not (and c_5_3 c_5_10)))
(assert
 (not (and c_5_3 c_5_11)))
(assert
 (not (and c_5_3 c_5_12)))
(assert
 (not (and c_5_4 c_5_5)))
(assert
 (not (and c_5_4 c_5_6)))
(assert
 (not (and c_5_4 c_5_7)))
(assert
 (not (and c_5_4 c_5_8)))
(assert
 (not (and c_5_4 c_5_9)))
(assert
 (not (and c_5_4 c_5_10)))
(assert
 (not (and c_5_4 c_5_11)))
(assert
 (not (and c_5_4 c_5_12)))
(assert
 (not (and c_5_5 c_5_6)))
(assert
 (not (and c_5_5 c_5_7)))
(assert
 (not (and c_5_5 c_5_8)))
(assert
 (not (and c_5_5 c_5_9)))
(assert
 (not (and c_5_5 c_5_10)))
(assert
 (not (and c_5_5 c_5_11)))
(assert
 (not (and c_5_5 c_5_12)))
(assert
 (not (and c_5_6 c_5_7)))
(assert
 (not (and c_5_6 c_5_8)))
(assert
 (not (and c_5_6 c_5_9)))
(assert
 (not (and c_5_6 c_5_10)))
(assert
 (not (and c_5_6 c_5_11)))
(assert
 (not (and c_5_6 c_5_12)))
(assert
 (not (and c_5_7 c_5_8)))
(assert
 (not (and c_5_7 c_5_9)))
(assert
 (not (and c_5_7 c_5_10)))
(assert
 (not (and c_5_7 c_5_11)))
(assert
 (not (and c_5_7 c_5_12)))
(assert
 (not (and c_5_8 c_5_9)))
(assert
 (not (and c_5_8 c_5_10)))
(assert
 (not (and c_5_8 c_5_11)))
(assert
 (not (and c_5_8 c_5_12)))
(assert
 (not (and c_5_9 c_5_10)))
(assert
 (not (and c_5_9 c_5_11)))
(assert
 (not (and c_5_9 c_5_12)))
(assert
 (not (and c_5_10 c_5_11)))
(assert
 (not (and c_5_10 c_5_12)))
(assert
 (not (and c_5_11 c_5_12)))
(assert
 (let (($x1107 (or false c_6_0)))
 (let (($x1109 (or $x1107 c_6_1)))
 (let (($x1111 (or $x1109 c_6_2)))
 (let (($x1113 (or $x1111 c_6_3)))
 (let (($x1115 (or $x1113 c_6_4)))
 (let (($x1117 (or $x1115 c_6_5)))
 (let (($x1119 (or $x1117 c_6_6)))
 (let (($x1121 (or $x1119 c_6_7)))
 (let (($x1123 (or $x1121 c_6_8)))
 (let (($x1125 (or $x1123 c_6_9)))
 (let (($x1127 (or $x1125 c_6_10)))
 (let (($x1129 (or $x1127 c_6_11)))
 (or $x1129 c_6_12))))))))))))))
(assert
 (not (and c_6_0 c_6_1)))
(assert
 (not (and c_6_0 c_6_2)))
(assert
 (not (and c_6_0 c_6_3)))
(assert
 (not (and c_6_0 c_6_4)))
(assert
 (not (and c_6_0 c_6_5)))
(assert
 (not (and c_6_0 c_6_6)))
(assert
 (not (and c_6_0 c_6_7)))
(assert
 (not (and c_6_0 c_6_8)))
(assert
 (not (and c_6_0 c_6_9)))
(assert
 (not (and c_6_0 c_6_10)))
(assert
 (not (and c_6_0 c_6_11)))
(assert
 (not (and c_6_0 c_6_12)))
(assert
 (not (and c_6_1 c_6_2)))
(assert
 (not (and c_6_1 c_6_3)))
(assert
 (not (and c_6_1 c_6_4)))
(assert
 (not (and c_6_1 c_6_5)))
(assert
 (not (and c_6_1 c_6_6)))
(assert
 (not (and c_6_1 c_6_7)))
(assert
 (not (and c_6_1 c_6_8)))
(assert
 (not (and c_6_1 c_6_9)))
(assert
 (not (and c_6_1 c_6_10)))
(assert
 (not (and c_6_1 c_6_11)))
(assert
 (not (and c_6_1 c_6_12)))
(assert
 (not (and c_6_2 c_6_3)))
(assert
 (not (and c_6_2 c_6_4)))
(assert
 (not (and c_6_2 c_6_5)))
(assert
 (not (and c_6_2 c_6_6)))
(assert
 (not (and c_6_2 c_6_7)))
(assert
 (not (and c_6_2 c_6_8)))
(assert
 (not (and c_6_2 c_6_9)))
(assert
 (not (and c_6_2 c_6_10)))
(assert
 (not (and c_6_2 c_6_11)))
(assert
 (not (and c_6_2 c_6_12)))
(assert
 (not (and c_6_3 c_6_4)))
(assert
 (not (and c_6_3 c_6_5)))
(assert
 (not (and c_6_3 c_6_6)))
(assert
 (not (and c_6_3 c_6_7)))
(assert
 (not (and c_6_3 c_6_8)))
(assert
 (not (and c_6_3 c_6_9)))
(assert
 (not (and c_6_3 c_6_10)))
(assert
 (not (and c_6_3 c_6_11)))
(assert
 (not (and c_6_3 c_6_12)))
(assert
 (not (and c_6_4 c_6_5)))
(assert
 (not (and c_6_4 c_6_6)))
(assert
 (not (and c_6_4 c_6_7)))
(assert
 (not (and c_6_4 c_6_8)))
(assert
 (not (and c_6_4 c_6_9)))
(assert
 (not (and c_6_4 c_6_10)))
(assert
 (not (and c_6_4 c_6_11)))
(assert
 (not (and c_6_4 c_6_12)))
(assert
 (not (and c_6_5 c_6_6)))
(assert
 (not (and c_6_5 c_6_7)))
(assert
 (not (and c_6_5 c_6_8)))
(assert
 (not (and c_6_5 c_6_9)))
(assert
 (not (and c_6_5 c_6_10)))
(assert
 (not (and c_6_5 c_6_11)))
(assert
 (not (and c_6_5 c_6_12)))
(assert
 (not (and c_6_6 c_6_7)))
(assert
 (not (and c_6_6 c_6_8)))
(assert
 (not (and c_6_6 c_6_9)))
(assert
 (not (and c_6_6 c_6_10)))
(assert
 (not (and c_6_6 c_6_11)))
(assert
 (not (and c_6_6 c_6_12)))
(assert
 (not (and c_6_7 c_6_8)))
(assert
 (not (and c_6_7 c_6_9)))
(assert
 (not (and c_6_7 c_6_10)))
(assert
 (not (and c_6_7 c_6_11)))
(assert
 (not (and c_6_7 c_6_12)))
(assert
 (not (and c_6_8 c_6_9)))
(assert
 (not (and c_6_8 c_6_10)))
(assert
 (not (and c_6_8 c_6_11)))
(assert
 (not (and c_6_8 c_6_12)))
(assert
 (not (and c_6_9 c_6_10)))
(assert
 (not (and c_6_9 c_6_11)))
(assert
 (not (and c_6_9 c_6_12)))
(assert
 (not (and c_6_10 c_6_11)))
(assert
 (not (and c_6_10 c_6_12)))
(assert
 (not (and c_6_11 c_6_12)))
(assert
 (let (($x1289 (or false c_7_0)))
 (let (($x1291 (or $x1289 c_7_1)))
 (let (($x1293 (or $x1291 c_7_2)))
 (let (($x1295 (or $x1293 c_7_3)))
 (let (($x1297 (or $x1295 c_7_4)))
 (let (($x1299 (or $x1297 c_7_5)))
 (let (($x1301 (or $x1299 c_7_6)))
 (let (($x1303 (or $x1301 c_7_7)))
 (let (($x1305 (or $x1303 c_7_8)))
 (let (($x1307 (or $x1305 c_7_9)))
 (let (($x1309 (or $x1307 c_7_10)))
 (let (($x1311 (or $x1309 c_7_11)))
 (or $x1311 c_7_12))))))))))))))
(assert
 (not (and c_7_0 c_7_1)))
(assert
 (not (and c_7_0 c_7_2)))
(assert
 (not (and c_7_0 c_7_3)))
(assert
 (not (and c_7_0 c_7_4)))
(assert
 (not (and c_7_0 c_7_5)))
(assert
 (not (and c_7_0 c_7_6)))
(assert
 (not (and c_7_0 c_7_7)))
(assert
 (not (and c_7_0 c_7_8)))
(assert
 (not (and c_7_0 c_7_9)))
(assert
 (not (and c_7_0 c_7_10)))
(assert
 (not (and c_7_0 c_7_11)))
(assert
 (not (and c_7_0 c_7_12)))
(assert
 (not (and c_7_1 c_7_2)))
(assert
 (not (and c_7_1 c_7_3)))
(assert
 (not (and c_7_1 c_7_4)))
(assert
 (not (and c_7_1 c_7_5)))
(assert
 (not (and c_7_1 c_7_6)))
(assert
 (not (and c_7_1 c_7_7)))
(assert
 (not (and c_7_1 c_7_8)))
(assert
 (not (and c_7_1 c_7_9)))
(assert
 (not (and c_7_1 c_7_10)))
(assert
 (not (and c_7_1 c_7_11)))
(assert
 (not (and c_7_1 c_7_12)))
(assert
 (not (and c_7_2 c_7_3)))
(assert
 (not (and c_7_2 c_7_4)))
(assert
 (not (and c_7_2 c_7_5)))
(assert
 (not (and c_7_2 c_7_6)))
(assert
 (not (and c_7_2 c_7_7)))
(assert
 (not (and c_7_2 c_7_8)))
(assert
 (not (and c_7_2 c_7_9)))
(assert
 (not (and c_7_2 c_7_10)))
(assert
 (not (and c_7_2 c_7_11)))
(assert
 (not (and c_7_2 c_7_12)))
(assert
 (not (and c_7_3 c_7_4)))
(assert
 (not (and c_7_3 c_7_5)))
(assert
 (not (and c_7_3 c_7_6)))
(assert
 (not (and c_7_3 c_7_7)))
(assert
 (not (and c_7_3 c_7_8)))
(assert
 (not (and c_7_3 c_7_9)))
(assert
 (not (and c_7_3 c_7_10)))
(assert
 (not (and c_7_3 c_7_11)))
(assert
 (not (and c_7_3 c_7_12)))
(assert
 (not (and c_7_4 c_7_5)))
(assert
 (not (and c_7_4 c_7_6)))
(assert
 (not (and c_7_4 c_7_7)))
(assert
 (not (and c_7_4 c_7_8)))
(assert
 (not (and c_7_4 c_7_9)))
(assert
 (not (and c_7_4 c_7_10)))
(assert
 (not (and c_7_4 c_7_11)))
(assert
 (not (and c_7_4 c_7_12)))
(assert
 (not (and c_7_5 c_7_6)))
(assert
 (not (and c_7_5 c_7_7)))
(assert
 (not (and c_7_5 c_7_8)))
(assert
 (not (and c_7_5 c_7_9)))
(assert
 (not (and c_7_5 c_7_10)))
(assert
 (not (and c_7_5 c_7_11)))
(assert
 (not (and c_7_5 c_7_12)))
(assert
 (not (and c_7_6 c_7_7)))
(assert
 (not (and c_7_6 c_7_8)))
(assert
 (not (and c_7_6 c_7_9)))
(assert
 (not (and c_7_6 c_7_10)))
(assert
 (not (and c_7_6 c_7_11)))
(assert
 (not (and c_7_6 c_7_12)))
(assert
 (not (and c_7_7 c_7_8)))
(assert
 (not (and c_7_7 c_7_9)))
(assert
 (not (and c_7_7 c_7_10)))
(assert
 (not (and c_7_7 c_7_11)))
(assert
 (not (and c_7_7 c_7_12)))
(assert
 (not (and c_7_8 c_7_9)))
(assert
 (not (and c_7_8 c_7_10)))
(assert
 (not (and c_7_8 c_7_11)))
(assert
 (not (and c_7_8 c_7_12)))
(assert
 (not (and c_7_9 c_7_10)))
(assert
 (not (and c_7_9 c_7_11)))
(assert
 (not (and c_7_9 c_7_12)))
(assert
 (not (and c_7_10 c_7_11)))
(assert
 (not (and c_7_10 c_7_12)))
(assert
 (not (and c_7_11 c_7_12)))
(assert
 (let (($x1471 (or false c_8_0)))
 (let (($x1473 (or $x1471 c_8_1)))
 (let (($x1475 (or $x1473 c_8_2)))
 (let (($x1477 (or $x1475 c_8_3)))
 (let (($x1479 (or $x1477 c_8_4)))
 (let (($x1481 (or $x1479 c_8_5)))
 (let (($x1483 (or $x1481 c_8_6)))
 (let (($x1485 (or $x1483 c_8_7)))
 (let (($x1487 (or $x1485 c_8_8)))
 (let (($x1489 (or $x1487 c_8_9)))
 (let (($x1491 (or $x1489 c_8_10)))
 (let (($x1493 (or $x1491 c_8_11)))
 (or $x1493 c_8_12))))))))))))))
(assert
 (not (and c_8_0 c_8_1)))
(assert
 (not (and c_8_0 c_8_2)))
(assert
 (not (and c_8_0 c_8_3)))
(assert
 (not (and c_8_0 c_8_4)))
(assert
 (not (and c_8_0 c_8_5)))
(assert
 (not (and c_8_0 c_8_6)))
(assert
 (not (and c_8_0 c_8_7)))
(assert
 (not (and c_8_0 c_8_8)))
(assert
 (not (and c_8_0 c_8_9)))
(assert
 (not (and c_8_0 c_8_10)))
(assert
 (not (and c_8_0 c_8_11)))
(assert
 (not (and c_8_0 c_8_12)))
(assert
 (not (and c_8_1 c_8_2)))
(assert
 (not (and c_8_1 c_8_3)))
(assert
 (not (and c_8_1 c_8_4)))
(assert
 (not (and c_8_1 c_8_5)))
(assert
 (not (and c_8_1 c_8_6)))
(assert
 (not (and c_8_1 c_8_7)))
(assert
 (not (and c_8_1 c_8_8)))
(assert
 (not (and c_8_1 c_8_9)))
(assert
 (not (and c_8_1 c_8_10)))
(assert
 (not (and c_8_1 c_8_11)))
(assert
 (not (and c_8_1 c_8_12)))
(assert
 (not (and c_8_2 c_8_3)))
(assert
 (not (and c_8_2 c_8_4)))
(assert
 (not (and c_8_2 c_8_5)))
(assert
 (not (and c_8_2 c_8_6)))
(assert
 (not (and c_8_2 c_8_7)))
(assert
 (not (and c_8_2 c_8_8)))
(assert
 (not (and c_8_2 c_8_9)))
(assert
 (not (and c_8_2 c_8_10)))
(assert
 (not (and c_8_2 c_8_11)))
(assert
 (not (and c_8_2 c_8_12)))
(assert
 (not (and c_8_3 c_8_4)))
(assert
 (not (and c_8_3 c_8_5)))
(assert
 (not (and c_8_3 c_8_6)))
(assert
 (not (and c_8_3 c_8_7)))
(assert
 (not (and c_8_3 c_8_8)))
(assert
 (not (and c_8_3 c_8_9)))
(assert
 (not (and c_8_3 c_8_10)))
(assert
 (not (and c_8_3 c_8_11)))
(assert
 (not (and c_8_3 c_8_12)))
(assert
 (not (and c_8_4 c_8_5)))
(assert
 (not (and c_8_4 c_8_6)))
(assert
 (not (and c_8_4 c_8_7)))
(assert
 (not (and c_8_4 c_8_8)))
(assert
 (not (and c_8_4 c_8_9)))
(assert
 (not (and c_8_4 c_8_10)))
(assert
 (not (and c_8_4 c_8_11)))
(assert
 (not (and c_8_4 c_8_12)))
(assert
 (not (and c_8_5 c_8_6)))
(assert
 (not (and c_8_5 c_8_7)))
(assert
 (not (and c_8_5 c_8_8)))
(assert
 (not (and c_8_5 c_8_9)))
(assert
 (not (and c_8_5 c_8_10)))
(assert
 (not (and c_8_5 c_8_11)))
(assert
 (not (and c_8_5 c_8_12)))
(assert
 (not (and c_8_6 c_8_7)))
(assert
 (not (and c_8_6 c_8_8)))
(assert
 (not (and c_8_6 c_8_9)))
(assert
 (not (and c_8_6 c_8_10)))
(assert
 (not (and c_8_6 c_8_11)))
(assert
 (not (and c_8_6 c_8_12)))
(assert
 (not (and c_8_7 c_8_8)))
(assert
 (not (and c_8_7 c_8_9)))
(assert
 (not (and c_8_7 c_8_10)))
(assert
 (not (and c_8_7 c_8_11)))
(assert
 (not (and c_8_7 c_8_12)))
(assert
 (not (and c_8_8 c_8_9)))
(assert
 (not (and c_8_8 c_8_10)))
(assert
 (not (and c_8_8 c_8_11)))
(assert
 (not (and c_8_8 c_8_12)))
(assert
 (not (and c_8_9 c_8_10)))
(assert
 (not (and c_8_9 c_8_11)))
(assert
 (not (and c_8_9 c_8_12)))
(assert
 (not (and c_8_10 c_8_11)))
(assert
 (not (and c_8_10 c_8_12)))
(assert
 (not (and c_8_11 c_8_12)))
(assert
 (let (($x2107 (>= rank_0 0)))
 (and $x2107 (< rank_0 9))))
(assert
 (let (($x2105 (>= rank_2 0)))
 (and $x2105 (< rank_2 9))))
(assert
 (let (($x2116 (>= rank_4 0)))
 (and $x2116 (< rank_4 9))))
(assert
 (let (($x2121 (>= rank_6 0)))
 (and $x2121 (< rank_6 9))))
(assert
 (let (($x2126 (>= rank_8 0)))
 (and $x2126 (< rank_8 9))))
(assert
 (let (($x2131 (>= rank_10 0)))
 (and $x2131 (< rank_10 9))))
(assert
 (let (($x2136 (>= rank_12 0)))
 (and $x2136 (< rank_12 9))))
(assert
 (let (($x2141 (>= rank_14 0)))
 (and $x2141 (< rank_14 9))))
(assert
 (let (($x2146 (>= rank_16 0)))
 (and $x2146 (< rank_16 9))))
(assert
 (let (($x4295 (>= rank_18 0)))
 (and $x4295 (< rank_18 9))))
(assert
 (let (($x4300 (>= rank_20 0)))
 (and $x4300 (< rank_20 9))))
(assert
 (let (($x4305 (>= rank_22 0)))
 (and $x4305 (< rank_22 9))))
(assert
 (let (($x4310 (>= rank_24 0)))
 (and $x4310 (< rank_24 9))))
(assert
 (let (($x4315 (>= rank_26 0)))
 (and $x4315 (< rank_26 9))))
(assert
 (let (($x4320 (>= rank_28 0)))
 (and $x4320 (< rank_28 9))))
(assert
 (let (($x4325 (>= rank_30 0)))
 (and $x4325 (< rank_30 9))))
(assert
 (let (($x4330 (>= rank_32 0)))
 (and $x4330 (< rank_32 9))))
(assert
 (let (($x4335 (>= rank_34 0)))
 (and $x4335 (< rank_34 9))))
(assert
 (let (($x4550 (>= prank_36 0)))
 (and $x4550 (< prank_36 9))))
(assert
 (let (($x4559 (>= prank_37 0)))
 (and $x4559 (< prank_37 9))))
(assert
 (let (($x4563 (>= prank_38 0)))
 (and $x4563 (< prank_38 9))))
(assert
 (let (($x4567 (>= prank_39 0)))
 (and $x4567 (< prank_39 9))))
(assert
 (let (($x4571 (>= prank_40 0)))
 (and $x4571 (< prank_40 9))))
(assert
 (let (($x4575 (>= prank_41 0)))
 (and $x4575 (< prank_41 9))))
(assert
 (let (($x4579 (>= prank_42 0)))
 (and $x4579 (< prank_42 9))))
(assert
 (let (($x4583 (>= prank_43 0)))
 (and $x4583 (< prank_43 9))))
(assert
 (let (($x4587 (>= prank_44 0)))
 (and $x4587 (< prank_44 9))))
(assert
 (let (($x4887 (>= prank_47 0)))
 (and $x4887 (< prank_47 9))))
(assert
 (let (($x4888 (>= prank_48 0)))
 (and $x4888 (< prank_48 9))))
(assert
 (let (($x4896 (>= prank_49 0)))
 (and $x4896 (< prank_49 9))))
(assert
 (let (($x4900 (>= prank_50 0)))
 (and $x4900 (< prank_50 9))))
(assert
 (let (($x4904 (>= prank_51 0)))
 (and $x4904 (< prank_51 9))))
(assert
 (let (($x4908 (>= prank_52 0)))
 (and $x4908 (< prank_52 9))))
(assert
 (let (($x4912 (>= prank_53 0)))
 (and $x4912 (< prank_53 9))))
(assert
 (let (($x4916 (>= prank_54 0)))
 (and $x4916 (< prank_54 9))))
(assert
 (let (($x4920 (>= prank_55 0)))
 (and $x4920 (< prank_55 9))))
(assert
 (let (($x5233 (>= rank_58 0)))
 (and $x5233 (< rank_58 9))))
(assert
 (let (($x5234 (>= rank_60 0)))
 (and $x5234 (< rank_60 9))))
(assert
 (let (($x5241 (>= rank_62 0)))
 (and $x5241 (< rank_62 9))))
(assert
 (let (($x5246 (>= rank_64 0)))
 (and $x5246 (< rank_64 9))))
(assert
 (let (($x5251 (>= rank_66 0)))
 (and $x5251 (< rank_66 9))))
(assert
 (let (($x5256 (>= rank_68 0)))
 (and $x5256 (< rank_68 9))))
(assert
 (let (($x5261 (>= rank_70 0)))
 (and $x5261 (< rank_70 9))))
(assert
 (let (($x5266 (>= rank_72 0)))
 (and $x5266 (< rank_72 9))))
(assert
 (let (($x5271 (>= rank_74 0)))
 (and $x5271 (< rank_74 9))))
(assert
 (let ((?x5422 (ite root_75 1 0)))
 (let ((?x5403 (ite root_73 1 0)))
 (let ((?x5387 (ite root_71 1 0)))
 (let ((?x5368 (ite root_69 1 0)))
 (let ((?x5346 (ite root_67 1 0)))
 (let ((?x5327 (ite root_65 1 0)))
 (let ((?x5311 (ite root_63 1 0)))
 (let ((?x5292 (ite root_61 1 0)))
 (let ((?x5276 (ite root_59 1 0)))
 (let ((?x5277 (+ 0 ?x5276)))
 (let ((?x5293 (+ ?x5277 ?x5292)))
 (let ((?x5312 (+ ?x5293 ?x5311)))
 (let ((?x5328 (+ ?x5312 ?x5327)))
 (let ((?x5347 (+ ?x5328 ?x5346)))
 (let ((?x5369 (+ ?x5347 ?x5368)))
 (let ((?x5388 (+ ?x5369 ?x5387)))
 (let ((?x5404 (+ ?x5388 ?x5403)))
 (let (($x5275 (or false root_59)))
 (let (($x5291 (or $x5275 root_61)))
 (let (($x5310 (or $x5291 root_63)))
 (let (($x5326 (or $x5310 root_65)))
 (let (($x5345 (or $x5326 root_67)))
 (let (($x5367 (or $x5345 root_69)))
 (let (($x5386 (or $x5367 root_71)))
 (let (($x5402 (or $x5386 root_73)))
 (let (($x5239 (or c_8_1 c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_7 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x5232 (or c_7_1 c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_7 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x5225 (or c_6_1 c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_7 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x5218 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x5211 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x5204 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x5197 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x5190 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x5183 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x5274 (or false $x5183)))
 (let (($x5290 (or $x5274 $x5190)))
 (let (($x5309 (or $x5290 $x5197)))
 (let (($x5325 (or $x5309 $x5204)))
 (let (($x5344 (or $x5325 $x5211)))
 (let (($x5366 (or $x5344 $x5218)))
 (let (($x5385 (or $x5366 $x5225)))
 (let (($x5401 (or $x5385 $x5232)))
 (let (($x5428 (or false (and $x5232 (< rank_72 rank_74)))))
 (let (($x5432 (not root_75)))
 (let (($x5433 (and $x5239 $x5432)))
 (let (($x5409 (or false (and $x5239 (< rank_74 rank_72)))))
 (let (($x5412 (or $x5409 (and $x5225 (< rank_70 rank_72)))))
 (let (($x5416 (not root_73)))
 (let (($x5417 (and $x5232 $x5416)))
 (let (($x5393 (or false (and $x5232 (< rank_72 rank_70)))))
 (let (($x5397 (not root_71)))
 (let (($x5398 (and $x5225 $x5397)))
 (let (($x5374 (or false (and $x5239 (< rank_74 rank_68)))))
 (let (($x5377 (or $x5374 (and $x5211 (< rank_66 rank_68)))))
 (let (($x5381 (not root_69)))
 (let (($x5382 (and $x5218 $x5381)))
 (let (($x5352 (or false (and $x5218 (< rank_68 rank_66)))))
 (let (($x5355 (or $x5352 (and $x5232 (< rank_72 rank_66)))))
 (let (($x5358 (or $x5355 (and $x5204 (< rank_64 rank_66)))))
 (let (($x5362 (not root_67)))
 (let (($x5363 (and $x5211 $x5362)))
 (let (($x5333 (or false (and $x5211 (< rank_66 rank_64)))))
 (let (($x5336 (or $x5333 (and $x5225 (< rank_70 rank_64)))))
 (let (($x5340 (not root_65)))
 (let (($x5341 (and $x5204 $x5340)))
 (let (($x5317 (or false (and $x5218 (< rank_68 rank_62)))))
 (let (($x5321 (not root_63)))
 (let (($x5322 (and $x5197 $x5321)))
 (let (($x5298 (or false (and $x5197 (< rank_62 rank_60)))))
 (let (($x5301 (or $x5298 (and $x5211 (< rank_66 rank_60)))))
 (let (($x5305 (not root_61)))
 (let (($x5306 (and $x5190 $x5305)))
 (let (($x5282 (or false (and $x5190 (< rank_60 rank_58)))))
 (let (($x5286 (not root_59)))
 (let (($x5287 (and $x5183 $x5286)))
 (let (($x5279 (and true (=> root_59 $x5183))))
 (let (($x5289 (and $x5279 (=> $x5287 (or $x5282 (and $x5204 (< rank_64 rank_58)))))))
 (let (($x5295 (and $x5289 (=> root_61 $x5190))))
 (let (($x5308 (and $x5295 (=> $x5306 (or $x5301 (and $x5183 (< rank_58 rank_60)))))))
 (let (($x5314 (and $x5308 (=> root_63 $x5197))))
 (let (($x5324 (and $x5314 (=> $x5322 (or $x5317 (and $x5190 (< rank_60 rank_62)))))))
 (let (($x5330 (and $x5324 (=> root_65 $x5204))))
 (let (($x5343 (and $x5330 (=> $x5341 (or $x5336 (and $x5183 (< rank_58 rank_64)))))))
 (let (($x5349 (and $x5343 (=> root_67 $x5211))))
 (let (($x5365 (and $x5349 (=> $x5363 (or $x5358 (and $x5190 (< rank_60 rank_66)))))))
 (let (($x5371 (and $x5365 (=> root_69 $x5218))))
 (let (($x5384 (and $x5371 (=> $x5382 (or $x5377 (and $x5197 (< rank_62 rank_68)))))))
 (let (($x5390 (and $x5384 (=> root_71 $x5225))))
 (let (($x5400 (and $x5390 (=> $x5398 (or $x5393 (and $x5204 (< rank_64 rank_70)))))))
 (let (($x5406 (and $x5400 (=> root_73 $x5232))))
 (let (($x5419 (and $x5406 (=> $x5417 (or $x5412 (and $x5211 (< rank_66 rank_72)))))))
 (let (($x5425 (and $x5419 (=> root_75 $x5239))))
 (let (($x5437 (and (and $x5425 (=> $x5433 (or $x5428 (and $x5218 (< rank_68 rank_74))))) (=> (or $x5401 $x5239) (or $x5402 root_75)))))
 (let (($x5439 (and $x5437 (<= (+ ?x5404 ?x5422) 1))))
 (let (($x3500 (or c_8_1 c_8_7)))
 (let (($x5160 (and $x3500 (= prank_55 prank_high_57))))
 (let (($x3480 (or c_7_1 c_7_7)))
 (let (($x5137 (and $x3480 (= prank_54 prank_high_57))))
 (let (($x3535 (or c_6_1 c_6_7)))
 (let (($x5109 (and $x3535 (= prank_53 prank_high_57))))
 (let (($x3460 (or c_5_1 c_5_7)))
 (let (($x5086 (and $x3460 (= prank_52 prank_high_57))))
 (let (($x3444 (or c_4_1 c_4_7)))
 (let (($x5058 (and $x3444 (= prank_51 prank_high_57))))
 (let (($x3507 (or c_3_1 c_3_7)))
 (let (($x5025 (and $x3507 (= prank_50 prank_high_57))))
 (let (($x3425 (or c_2_1 c_2_7)))
 (let (($x4997 (and $x3425 (= prank_49 prank_high_57))))
 (let (($x3403 (or c_1_1 c_1_7)))
 (let (($x4974 (and $x3403 (= prank_48 prank_high_57))))
 (let (($x3561 (or c_0_1 c_0_7)))
 (let (($x4946 (and $x3561 (= prank_47 prank_high_57))))
 (let (($x4947 (or false $x4946)))
 (let (($x4975 (or $x4947 $x4974)))
 (let (($x4998 (or $x4975 $x4997)))
 (let (($x5026 (or $x4998 $x5025)))
 (let (($x5059 (or $x5026 $x5058)))
 (let (($x5087 (or $x5059 $x5086)))
 (let (($x5110 (or $x5087 $x5109)))
 (let (($x5138 (or $x5110 $x5137)))
 (let (($x5157 (and $x3500 (= prank_55 prank_low_56))))
 (let (($x5134 (and $x3480 (= prank_54 prank_low_56))))
 (let (($x5106 (and $x3535 (= prank_53 prank_low_56))))
 (let (($x5083 (and $x3460 (= prank_52 prank_low_56))))
 (let (($x5055 (and $x3444 (= prank_51 prank_low_56))))
 (let (($x5022 (and $x3507 (= prank_50 prank_low_56))))
 (let (($x4994 (and $x3425 (= prank_49 prank_low_56))))
 (let (($x4971 (and $x3403 (= prank_48 prank_low_56))))
 (let (($x4943 (and $x3561 (= prank_47 prank_low_56))))
 (let (($x4944 (or false $x4943)))
 (let (($x4972 (or $x4944 $x4971)))
 (let (($x4995 (or $x4972 $x4994)))
 (let (($x5023 (or $x4995 $x5022)))
 (let (($x5056 (or $x5023 $x5055)))
 (let (($x5084 (or $x5056 $x5083)))
 (let (($x5107 (or $x5084 $x5106)))
 (let (($x5135 (or $x5107 $x5134)))
 (let (($x4941 (or false $x3561)))
 (let (($x4969 (or $x4941 $x3403)))
 (let (($x4992 (or $x4969 $x3425)))
 (let (($x5020 (or $x4992 $x3507)))
 (let (($x5053 (or $x5020 $x3444)))
 (let (($x5081 (or $x5053 $x3460)))
 (let (($x5104 (or $x5081 $x3535)))
 (let (($x5132 (or $x5104 $x3480)))
 (let (($x4877 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4889 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x5143 (or false (and true (or $x4889 (and $x3480 (< prank_54 prank_55)))))))
 (let (($x5150 (and (or $x5143 (and true (or $x4877 (and $x3460 (< prank_52 prank_55))))) (<= prank_low_56 prank_55))))
 (let (($x4871 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4883 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x4895 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x5115 (or false (and true (or $x4895 (and $x3500 (< prank_55 prank_54)))))))
 (let (($x5120 (or $x5115 (and true (or $x4883 (and $x3535 (< prank_53 prank_54)))))))
 (let (($x5127 (and (or $x5120 (and true (or $x4871 (and $x3444 (< prank_51 prank_54))))) (<= prank_low_56 prank_54))))
 (let (($x4865 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x5092 (or false (and true (or $x4889 (and $x3480 (< prank_54 prank_53)))))))
 (let (($x5099 (and (or $x5092 (and true (or $x4865 (and $x3507 (< prank_50 prank_53))))) (<= prank_low_56 prank_53))))
 (let (($x4859 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x5064 (or false (and true (or $x4895 (and $x3500 (< prank_55 prank_52)))))))
 (let (($x5069 (or $x5064 (and true (or $x4871 (and $x3444 (< prank_51 prank_52)))))))
 (let (($x5076 (and (or $x5069 (and true (or $x4859 (and $x3425 (< prank_49 prank_52))))) (<= prank_low_56 prank_52))))
 (let (($x4853 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x5031 (or false (and true (or $x4877 (and $x3460 (< prank_52 prank_51)))))))
 (let (($x5036 (or $x5031 (and true (or $x4889 (and $x3480 (< prank_54 prank_51)))))))
 (let (($x5041 (or $x5036 (and true (or $x4865 (and $x3507 (< prank_50 prank_51)))))))
 (let (($x5048 (and (or $x5041 (and true (or $x4853 (and $x3403 (< prank_48 prank_51))))) (<= prank_low_56 prank_51))))
 (let (($x4847 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x5003 (or false (and true (or $x4871 (and $x3444 (< prank_51 prank_50)))))))
 (let (($x5008 (or $x5003 (and true (or $x4883 (and $x3535 (< prank_53 prank_50)))))))
 (let (($x5015 (and (or $x5008 (and true (or $x4847 (and $x3561 (< prank_47 prank_50))))) (<= prank_low_56 prank_50))))
 (let (($x4980 (or false (and true (or $x4877 (and $x3460 (< prank_52 prank_49)))))))
 (let (($x4987 (and (or $x4980 (and true (or $x4853 (and $x3403 (< prank_48 prank_49))))) (<= prank_low_56 prank_49))))
 (let (($x4952 (or false (and true (or $x4859 (and $x3425 (< prank_49 prank_48)))))))
 (let (($x4957 (or $x4952 (and true (or $x4871 (and $x3444 (< prank_51 prank_48)))))))
 (let (($x4964 (and (or $x4957 (and true (or $x4847 (and $x3561 (< prank_47 prank_48))))) (<= prank_low_56 prank_48))))
 (let (($x4929 (or false (and true (or $x4853 (and $x3403 (< prank_48 prank_47)))))))
 (let (($x4936 (and (or $x4929 (and true (or $x4865 (and $x3507 (< prank_50 prank_47))))) (<= prank_low_56 prank_47))))
 (let (($x4940 (and true (=> $x3561 (and $x4936 (<= prank_47 prank_high_57))))))
 (let (($x4968 (and $x4940 (=> $x3403 (and $x4964 (<= prank_48 prank_high_57))))))
 (let (($x4991 (and $x4968 (=> $x3425 (and $x4987 (<= prank_49 prank_high_57))))))
 (let (($x5019 (and $x4991 (=> $x3507 (and $x5015 (<= prank_50 prank_high_57))))))
 (let (($x5052 (and $x5019 (=> $x3444 (and $x5048 (<= prank_51 prank_high_57))))))
 (let (($x5080 (and $x5052 (=> $x3460 (and $x5076 (<= prank_52 prank_high_57))))))
 (let (($x5103 (and $x5080 (=> $x3535 (and $x5099 (<= prank_53 prank_high_57))))))
 (let (($x5131 (and $x5103 (=> $x3480 (and $x5127 (<= prank_54 prank_high_57))))))
 (let (($x5154 (and $x5131 (=> $x3500 (and $x5150 (<= prank_55 prank_high_57))))))
 (let (($x5164 (and $x5154 (=> (or $x5132 $x3500) (and (or $x5135 $x5157) (or $x5138 $x5160))))))
 (let (($x3591 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_8 c_8_9 c_8_10 c_8_11)))
 (let (($x4827 (and $x3591 (= prank_44 prank_high_46))))
 (let (($x3504 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_8 c_7_9 c_7_10 c_7_11)))
 (let (($x4804 (and $x3504 (= prank_43 prank_high_46))))
 (let (($x3485 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_8 c_6_9 c_6_10 c_6_11)))
 (let (($x4776 (and $x3485 (= prank_42 prank_high_46))))
 (let (($x3557 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_8 c_5_9 c_5_10 c_5_11)))
 (let (($x4753 (and $x3557 (= prank_41 prank_high_46))))
 (let (($x3466 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_8 c_4_9 c_4_10 c_4_11)))
 (let (($x4725 (and $x3466 (= prank_40 prank_high_46))))
 (let (($x3447 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_8 c_3_9 c_3_10 c_3_11)))
 (let (($x4692 (and $x3447 (= prank_39 prank_high_46))))
 (let (($x3532 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_8 c_2_9 c_2_10 c_2_11)))
 (let (($x4664 (and $x3532 (= prank_38 prank_high_46))))
 (let (($x3428 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_8 c_1_9 c_1_10 c_1_11)))
 (let (($x4641 (and $x3428 (= prank_37 prank_high_46))))
 (let (($x3409 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_8 c_0_9 c_0_10 c_0_11)))
 (let (($x4613 (and $x3409 (= prank_36 prank_high_46))))
 (let (($x4614 (or false $x4613)))
 (let (($x4642 (or $x4614 $x4641)))
 (let (($x4665 (or $x4642 $x4664)))
 (let (($x4693 (or $x4665 $x4692)))
 (let (($x4726 (or $x4693 $x4725)))
 (let (($x4754 (or $x4726 $x4753)))
 (let (($x4777 (or $x4754 $x4776)))
 (let (($x4805 (or $x4777 $x4804)))
 (let (($x4824 (and $x3591 (= prank_44 prank_low_45))))
 (let (($x4801 (and $x3504 (= prank_43 prank_low_45))))
 (let (($x4773 (and $x3485 (= prank_42 prank_low_45))))
 (let (($x4750 (and $x3557 (= prank_41 prank_low_45))))
 (let (($x4722 (and $x3466 (= prank_40 prank_low_45))))
 (let (($x4689 (and $x3447 (= prank_39 prank_low_45))))
 (let (($x4661 (and $x3532 (= prank_38 prank_low_45))))
 (let (($x4638 (and $x3428 (= prank_37 prank_low_45))))
 (let (($x4610 (and $x3409 (= prank_36 prank_low_45))))
 (let (($x4611 (or false $x4610)))
 (let (($x4639 (or $x4611 $x4638)))
 (let (($x4662 (or $x4639 $x4661)))
 (let (($x4690 (or $x4662 $x4689)))
 (let (($x4723 (or $x4690 $x4722)))
 (let (($x4751 (or $x4723 $x4750)))
 (let (($x4774 (or $x4751 $x4773)))
 (let (($x4802 (or $x4774 $x4801)))
 (let (($x4608 (or false $x3409)))
 (let (($x4636 (or $x4608 $x3428)))
 (let (($x4659 (or $x4636 $x3532)))
 (let (($x4687 (or $x4659 $x3447)))
 (let (($x4720 (or $x4687 $x3466)))
 (let (($x4748 (or $x4720 $x3557)))
 (let (($x4771 (or $x4748 $x3485)))
 (let (($x4799 (or $x4771 $x3504)))
 (let (($x3950 (or c_8_5 c_8_11)))
 (let (($x4814 (and $x3950 (or (or c_5_6 c_5_12) (and $x3557 (< prank_41 prank_44))))))
 (let (($x3875 (or c_8_4 c_8_10)))
 (let (($x4809 (and $x3875 (or (or c_7_6 c_7_12) (and $x3504 (< prank_43 prank_44))))))
 (let (($x4810 (or false $x4809)))
 (let (($x4819 (and (and (or $x4810 $x4814) (<= prank_low_45 prank_44)) (<= prank_44 prank_high_46))))
 (let (($x3811 (or c_7_5 c_7_11)))
 (let (($x4791 (and $x3811 (or (or c_4_6 c_4_12) (and $x3466 (< prank_40 prank_43))))))
 (let (($x3844 (or c_7_4 c_7_10)))
 (let (($x4786 (and $x3844 (or (or c_6_6 c_6_12) (and $x3485 (< prank_42 prank_43))))))
 (let (($x3999 (or c_7_2 c_7_8)))
 (let (($x4781 (and $x3999 (or (or c_8_6 c_8_12) (and $x3591 (< prank_44 prank_43))))))
 (let (($x4782 (or false $x4781)))
 (let (($x4787 (or $x4782 $x4786)))
 (let (($x4796 (and (and (or $x4787 $x4791) (<= prank_low_45 prank_43)) (<= prank_43 prank_high_46))))
 (let (($x3776 (or c_6_5 c_6_11)))
 (let (($x4763 (and $x3776 (or (or c_3_6 c_3_12) (and $x3447 (< prank_39 prank_42))))))
 (let (($x3876 (or c_6_2 c_6_8)))
 (let (($x4758 (and $x3876 (or (or c_7_6 c_7_12) (and $x3504 (< prank_43 prank_42))))))
 (let (($x4759 (or false $x4758)))
 (let (($x4768 (and (and (or $x4759 $x4763) (<= prank_low_45 prank_42)) (<= prank_42 prank_high_46))))
 (let (($x3915 (or c_5_5 c_5_11)))
 (let (($x4740 (and $x3915 (or (or c_2_6 c_2_12) (and $x3532 (< prank_38 prank_41))))))
 (let (($x3809 (or c_5_4 c_5_10)))
 (let (($x4735 (and $x3809 (or (or c_4_6 c_4_12) (and $x3466 (< prank_40 prank_41))))))
 (let (($x4001 (or c_5_3 c_5_9)))
 (let (($x4730 (and $x4001 (or (or c_8_6 c_8_12) (and $x3591 (< prank_44 prank_41))))))
 (let (($x4731 (or false $x4730)))
 (let (($x4736 (or $x4731 $x4735)))
 (let (($x4745 (and (and (or $x4736 $x4740) (<= prank_low_45 prank_41)) (<= prank_41 prank_high_46))))
 (let (($x3743 (or c_4_5 c_4_11)))
 (let (($x4712 (and $x3743 (or (or c_1_6 c_1_12) (and $x3428 (< prank_37 prank_40))))))
 (let (($x3774 (or c_4_4 c_4_10)))
 (let (($x4707 (and $x3774 (or (or c_3_6 c_3_12) (and $x3447 (< prank_39 prank_40))))))
 (let (($x3878 (or c_4_3 c_4_9)))
 (let (($x4702 (and $x3878 (or (or c_7_6 c_7_12) (and $x3504 (< prank_43 prank_40))))))
 (let (($x3951 (or c_4_2 c_4_8)))
 (let (($x4697 (and $x3951 (or (or c_5_6 c_5_12) (and $x3557 (< prank_41 prank_40))))))
 (let (($x4698 (or false $x4697)))
 (let (($x4703 (or $x4698 $x4702)))
 (let (($x4708 (or $x4703 $x4707)))
 (let (($x4717 (and (and (or $x4708 $x4712) (<= prank_low_45 prank_40)) (<= prank_40 prank_high_46))))
 (let (($x3710 (or c_3_5 c_3_11)))
 (let (($x4679 (and $x3710 (or (or c_0_6 c_0_12) (and $x3409 (< prank_36 prank_39))))))
 (let (($x3846 (or c_3_3 c_3_9)))
 (let (($x4674 (and $x3846 (or (or c_6_6 c_6_12) (and $x3485 (< prank_42 prank_39))))))
 (let (($x3812 (or c_3_2 c_3_8)))
 (let (($x4669 (and $x3812 (or (or c_4_6 c_4_12) (and $x3466 (< prank_40 prank_39))))))
 (let (($x4670 (or false $x4669)))
 (let (($x4675 (or $x4670 $x4674)))
 (let (($x4684 (and (and (or $x4675 $x4679) (<= prank_low_45 prank_39)) (<= prank_39 prank_high_46))))
 (let (($x3741 (or c_2_4 c_2_10)))
 (let (($x4651 (and $x3741 (or (or c_1_6 c_1_12) (and $x3428 (< prank_37 prank_38))))))
 (let (($x3953 (or c_2_3 c_2_9)))
 (let (($x4646 (and $x3953 (or (or c_5_6 c_5_12) (and $x3557 (< prank_41 prank_38))))))
 (let (($x4647 (or false $x4646)))
 (let (($x4656 (and (and (or $x4647 $x4651) (<= prank_low_45 prank_38)) (<= prank_38 prank_high_46))))
 (let (($x3708 (or c_1_4 c_1_10)))
 (let (($x4628 (and $x3708 (or (or c_0_6 c_0_12) (and $x3409 (< prank_36 prank_37))))))
 (let (($x3814 (or c_1_3 c_1_9)))
 (let (($x4623 (and $x3814 (or (or c_4_6 c_4_12) (and $x3466 (< prank_40 prank_37))))))
 (let (($x3916 (or c_1_2 c_1_8)))
 (let (($x4618 (and $x3916 (or (or c_2_6 c_2_12) (and $x3532 (< prank_38 prank_37))))))
 (let (($x4619 (or false $x4618)))
 (let (($x4624 (or $x4619 $x4623)))
 (let (($x4633 (and (and (or $x4624 $x4628) (<= prank_low_45 prank_37)) (<= prank_37 prank_high_46))))
 (let (($x3778 (or c_0_3 c_0_9)))
 (let (($x4600 (and $x3778 (or (or c_3_6 c_3_12) (and $x3447 (< prank_39 prank_36))))))
 (let (($x3744 (or c_0_2 c_0_8)))
 (let (($x4595 (and $x3744 (or (or c_1_6 c_1_12) (and $x3428 (< prank_37 prank_36))))))
 (let (($x4596 (or false $x4595)))
 (let (($x4605 (and (and (or $x4596 $x4600) (<= prank_low_45 prank_36)) (<= prank_36 prank_high_46))))
 (let (($x4607 (and true (=> $x3409 $x4605))))
 (let (($x4635 (and $x4607 (=> $x3428 $x4633))))
 (let (($x4658 (and $x4635 (=> $x3532 $x4656))))
 (let (($x4686 (and $x4658 (=> $x3447 $x4684))))
 (let (($x4719 (and $x4686 (=> $x3466 $x4717))))
 (let (($x4747 (and $x4719 (=> $x3557 $x4745))))
 (let (($x4770 (and $x4747 (=> $x3485 $x4768))))
 (let (($x4798 (and $x4770 (=> $x3504 $x4796))))
 (let (($x4821 (and $x4798 (=> $x3591 $x4819))))
 (let (($x4831 (and $x4821 (=> (or $x4799 $x3591) (and (or $x4802 $x4824) (or $x4805 $x4827))))))
 (let (($x1770 (not in_target_8)))
 (let (($x2831 (and c_8_12 $x1770)))
 (let (($x2812 (and c_8_6 $x1770)))
 (let (($x1755 (not in_target_7)))
 (let (($x2773 (and c_7_12 $x1755)))
 (let (($x2754 (and c_7_6 $x1755)))
 (let (($x4527 (or $x2754 $x2773)))
 (let (($x1740 (not in_target_6)))
 (let (($x2715 (and c_6_12 $x1740)))
 (let (($x2696 (and c_6_6 $x1740)))
 (let (($x4523 (or $x2696 $x2715)))
 (let (($x1725 (not in_target_5)))
 (let (($x2657 (and c_5_12 $x1725)))
 (let (($x2638 (and c_5_6 $x1725)))
 (let (($x4519 (or $x2638 $x2657)))
 (let (($x1710 (not in_target_4)))
 (let (($x2599 (and c_4_12 $x1710)))
 (let (($x2580 (and c_4_6 $x1710)))
 (let (($x4515 (or $x2580 $x2599)))
 (let (($x1695 (not in_target_3)))
 (let (($x2541 (and c_3_12 $x1695)))
 (let (($x2522 (and c_3_6 $x1695)))
 (let (($x4511 (or $x2522 $x2541)))
 (let (($x1680 (not in_target_2)))
 (let (($x2483 (and c_2_12 $x1680)))
 (let (($x2464 (and c_2_6 $x1680)))
 (let (($x4507 (or $x2464 $x2483)))
 (let (($x1665 (not in_target_1)))
 (let (($x2425 (and c_1_12 $x1665)))
 (let (($x2406 (and c_1_6 $x1665)))
 (let (($x4503 (or $x2406 $x2425)))
 (let (($x1652 (not in_target_0)))
 (let (($x2367 (and c_0_12 $x1652)))
 (let (($x2347 (and c_0_6 $x1652)))
 (let (($x4499 (or $x2347 $x2367)))
 (let (($x4497 (or false $x4499)))
 (let (($x4501 (or $x4497 $x4503)))
 (let (($x4505 (or $x4501 $x4507)))
 (let (($x4509 (or $x4505 $x4511)))
 (let (($x4513 (or $x4509 $x4515)))
 (let (($x4517 (or $x4513 $x4519)))
 (let (($x4521 (or $x4517 $x4523)))
 (let (($x4525 (or $x4521 $x4527)))
 (let ((?x4477 (ite root_35 1 0)))
 (let ((?x4459 (ite root_33 1 0)))
 (let ((?x4444 (ite root_31 1 0)))
 (let ((?x4426 (ite root_29 1 0)))
 (let ((?x4405 (ite root_27 1 0)))
 (let ((?x4387 (ite root_25 1 0)))
 (let ((?x4372 (ite root_23 1 0)))
 (let ((?x4354 (ite root_21 1 0)))
 (let ((?x4339 (ite root_19 1 0)))
 (let ((?x4340 (+ 0 ?x4339)))
 (let ((?x4355 (+ ?x4340 ?x4354)))
 (let ((?x4373 (+ ?x4355 ?x4372)))
 (let ((?x4388 (+ ?x4373 ?x4387)))
 (let ((?x4406 (+ ?x4388 ?x4405)))
 (let ((?x4427 (+ ?x4406 ?x4426)))
 (let ((?x4445 (+ ?x4427 ?x4444)))
 (let ((?x4460 (+ ?x4445 ?x4459)))
 (let (($x4338 (or false root_19)))
 (let (($x4353 (or $x4338 root_21)))
 (let (($x4371 (or $x4353 root_23)))
 (let (($x4386 (or $x4371 root_25)))
 (let (($x4404 (or $x4386 root_27)))
 (let (($x4425 (or $x4404 root_29)))
 (let (($x4443 (or $x4425 root_31)))
 (let (($x4458 (or $x4443 root_33)))
 (let (($x3145 (or c_8_6 c_8_12)))
 (let (($x3093 (or c_7_6 c_7_12)))
 (let (($x3085 (or c_6_6 c_6_12)))
 (let (($x3122 (or c_5_6 c_5_12)))
 (let (($x3077 (or c_4_6 c_4_12)))
 (let (($x3069 (or c_3_6 c_3_12)))
 (let (($x3108 (or c_2_6 c_2_12)))
 (let (($x3061 (or c_1_6 c_1_12)))
 (let (($x3053 (or c_0_6 c_0_12)))
 (let (($x4276 (or false $x3053)))
 (let (($x4279 (or $x4276 $x3061)))
 (let (($x4280 (or $x4279 $x3108)))
 (let (($x4282 (or $x4280 $x3069)))
 (let (($x4284 (or $x4282 $x3077)))
 (let (($x4286 (or $x4284 $x3122)))
 (let (($x4288 (or $x4286 $x3085)))
 (let (($x4290 (or $x4288 $x3093)))
 (let (($x4292 (or $x4290 $x3145)))
 (let (($x4483 (or false (and $x3093 (< rank_32 rank_34)))))
 (let (($x4487 (not root_35)))
 (let (($x4488 (and $x3145 $x4487)))
 (let (($x4465 (or false (and $x3145 (< rank_34 rank_32)))))
 (let (($x4468 (or $x4465 (and $x3085 (< rank_30 rank_32)))))
 (let (($x4472 (not root_33)))
 (let (($x4473 (and $x3093 $x4472)))
 (let (($x4450 (or false (and $x3093 (< rank_32 rank_30)))))
 (let (($x4454 (not root_31)))
 (let (($x4455 (and $x3085 $x4454)))
 (let (($x4432 (or false (and $x3145 (< rank_34 rank_28)))))
 (let (($x4435 (or $x4432 (and $x3077 (< rank_26 rank_28)))))
 (let (($x4439 (not root_29)))
 (let (($x4440 (and $x3122 $x4439)))
 (let (($x4411 (or false (and $x3122 (< rank_28 rank_26)))))
 (let (($x4414 (or $x4411 (and $x3093 (< rank_32 rank_26)))))
 (let (($x4417 (or $x4414 (and $x3069 (< rank_24 rank_26)))))
 (let (($x4421 (not root_27)))
 (let (($x4422 (and $x3077 $x4421)))
 (let (($x4393 (or false (and $x3077 (< rank_26 rank_24)))))
 (let (($x4396 (or $x4393 (and $x3085 (< rank_30 rank_24)))))
 (let (($x4400 (not root_25)))
 (let (($x4401 (and $x3069 $x4400)))
 (let (($x4378 (or false (and $x3122 (< rank_28 rank_22)))))
 (let (($x4382 (not root_23)))
 (let (($x4383 (and $x3108 $x4382)))
 (let (($x4360 (or false (and $x3108 (< rank_22 rank_20)))))
 (let (($x4363 (or $x4360 (and $x3077 (< rank_26 rank_20)))))
 (let (($x4367 (not root_21)))
 (let (($x4368 (and $x3061 $x4367)))
 (let (($x4345 (or false (and $x3061 (< rank_20 rank_18)))))
 (let (($x4349 (not root_19)))
 (let (($x4350 (and $x3053 $x4349)))
 (let (($x4342 (and true (=> root_19 $x3053))))
 (let (($x4352 (and $x4342 (=> $x4350 (or $x4345 (and $x3069 (< rank_24 rank_18)))))))
 (let (($x4357 (and $x4352 (=> root_21 $x3061))))
 (let (($x4370 (and $x4357 (=> $x4368 (or $x4363 (and $x3053 (< rank_18 rank_20)))))))
 (let (($x4375 (and $x4370 (=> root_23 $x3108))))
 (let (($x4385 (and $x4375 (=> $x4383 (or $x4378 (and $x3061 (< rank_20 rank_22)))))))
 (let (($x4390 (and $x4385 (=> root_25 $x3069))))
 (let (($x4403 (and $x4390 (=> $x4401 (or $x4396 (and $x3053 (< rank_18 rank_24)))))))
 (let (($x4408 (and $x4403 (=> root_27 $x3077))))
 (let (($x4424 (and $x4408 (=> $x4422 (or $x4417 (and $x3061 (< rank_20 rank_26)))))))
 (let (($x4429 (and $x4424 (=> root_29 $x3122))))
 (let (($x4442 (and $x4429 (=> $x4440 (or $x4435 (and $x3108 (< rank_22 rank_28)))))))
 (let (($x4447 (and $x4442 (=> root_31 $x3085))))
 (let (($x4457 (and $x4447 (=> $x4455 (or $x4450 (and $x3069 (< rank_24 rank_30)))))))
 (let (($x4462 (and $x4457 (=> root_33 $x3093))))
 (let (($x4475 (and $x4462 (=> $x4473 (or $x4468 (and $x3077 (< rank_26 rank_32)))))))
 (let (($x4480 (and $x4475 (=> root_35 $x3145))))
 (let (($x4492 (and (and $x4480 (=> $x4488 (or $x4483 (and $x3122 (< rank_28 rank_34))))) (=> $x4292 (or $x4458 root_35)))))
 (let (($x4494 (and $x4492 (<= (+ ?x4460 ?x4477) 1))))
 (let (($x5165 (and (and (and (and $x4292 $x4494) (not (or $x4525 (or $x2812 $x2831)))) $x4831) $x5164)))
 (let ((?x4003 (ite $x4001 1 0)))
 (let ((?x4000 (ite $x3999 1 0)))
 (let ((?x3700 (ite false 1 0)))
 (let ((?x3907 (+ 0 ?x3700)))
 (let ((?x3995 (+ ?x3907 ?x3700)))
 (let ((?x4002 (+ ?x3995 ?x4000)))
 (let (($x3997 (= (to_real (+ (+ ?x3995 (ite $x3480 1 0)) (ite $x3460 1 0))) 0.0)))
 (let (($x4007 (and $x3997 (= (to_real (+ ?x4002 ?x4003)) 0.0))))
 (let (($x3802 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6)))
 (let (($x3992 (or c_8_2 c_8_3 c_8_4 c_8_5)))
 (let (($x3991 (and true $x3992)))
 (let (($x4032 (and $x3991 $x3802)))
 (let (($x4033 (not (and $x4032 $x4007))))
 (let ((?x3883 (ite $x3878 1 0)))
 (let ((?x3881 (ite $x3876 1 0)))
 (let ((?x3877 (ite $x3875 1 0)))
 (let ((?x3879 (+ 0 ?x3877)))
 (let ((?x3880 (+ ?x3879 ?x3700)))
 (let ((?x3882 (+ ?x3880 ?x3881)))
 (let ((?x3729 (ite $x3444 1 0)))
 (let ((?x3767 (ite $x3535 1 0)))
 (let ((?x3868 (ite $x3500 1 0)))
 (let ((?x3865 (+ 0 ?x3868)))
 (let ((?x3867 (+ ?x3865 ?x3700)))
 (let ((?x3866 (+ ?x3867 ?x3767)))
 (let (($x3887 (and (= (to_real (+ ?x3866 ?x3729)) 0.0) (= (to_real (+ ?x3882 ?x3883)) 0.0))))
 (let (($x3768 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6)))
 (let (($x3860 (or c_7_2 c_7_3 c_7_4 c_7_5)))
 (let (($x3859 (and true $x3860)))
 (let (($x4028 (and $x3859 $x3768)))
 (let (($x4031 (not (and $x4028 $x3887))))
 (let ((?x3850 (ite $x3846 1 0)))
 (let ((?x3845 (ite $x3844 1 0)))
 (let ((?x3847 (+ 0 ?x3845)))
 (let ((?x3848 (+ ?x3847 ?x3700)))
 (let ((?x3849 (+ ?x3848 ?x3700)))
 (let ((?x3698 (ite $x3507 1 0)))
 (let ((?x3801 (ite $x3480 1 0)))
 (let ((?x3837 (+ 0 ?x3801)))
 (let ((?x3836 (+ ?x3837 ?x3700)))
 (let ((?x3835 (+ ?x3836 ?x3700)))
 (let (($x3854 (and (= (to_real (+ ?x3835 ?x3698)) 0.0) (= (to_real (+ ?x3849 ?x3850)) 0.0))))
 (let (($x3900 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6)))
 (let (($x3830 (or c_6_2 c_6_3 c_6_4 c_6_5)))
 (let (($x3829 (and true $x3830)))
 (let (($x4024 (and $x3829 $x3900)))
 (let (($x4027 (not (and $x4024 $x3854))))
 (let ((?x3957 (ite $x3953 1 0)))
 (let ((?x3955 (ite $x3951 1 0)))
 (let ((?x3952 (ite $x3950 1 0)))
 (let ((?x3954 (+ ?x3907 ?x3952)))
 (let ((?x3956 (+ ?x3954 ?x3955)))
 (let (($x3947 (= (to_real (+ (+ (+ ?x3907 ?x3868) ?x3729) (ite $x3425 1 0))) 0.0)))
 (let (($x3961 (and $x3947 (= (to_real (+ ?x3956 ?x3957)) 0.0))))
 (let (($x3733 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6)))
 (let (($x3942 (or c_5_2 c_5_3 c_5_4 c_5_5)))
 (let (($x3940 (and true $x3942)))
 (let (($x4018 (and $x3940 $x3733)))
 (let (($x4021 (not (and $x4018 $x3961))))
 (let ((?x3783 (ite $x3778 1 0)))
 (let ((?x3780 (ite $x3776 1 0)))
 (let ((?x3777 (ite $x3774 1 0)))
 (let ((?x3779 (+ 0 ?x3777)))
 (let ((?x3781 (+ ?x3779 ?x3780)))
 (let ((?x3782 (+ ?x3781 ?x3700)))
 (let ((?x3770 (to_real (+ (+ (+ (+ 0 ?x3729) ?x3767) ?x3700) (ite $x3561 1 0)))))
 (let (($x3787 (and (= ?x3770 0.0) (= (to_real (+ ?x3782 ?x3783)) 0.0))))
 (let (($x3974 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6)))
 (let (($x3759 (or c_3_2 c_3_3 c_3_4 c_3_5)))
 (let (($x3757 (and true $x3759)))
 (let (($x4011 (and $x3757 $x3974)))
 (let (($x4014 (not (and $x4011 $x3787))))
 (let (($x3839 (or c_7_1 c_7_2 c_7_3 c_7_4 c_7_5 c_7_6)))
 (let (($x3985 (and $x3991 $x3839)))
 (let (($x4009 (not (and $x3985 $x4007))))
 (let (($x3936 (or c_6_1 c_6_2 c_6_3 c_6_4 c_6_5 c_6_6)))
 (let (($x3987 (and $x3859 $x3936)))
 (let (($x3990 (not (and $x3987 $x3887))))
 (let (($x3986 (not (and (and $x3940 $x3768) $x3961))))
 (let ((?x3921 (to_real (+ (+ (+ ?x3907 (ite $x3915 1 0)) (ite $x3916 1 0)) ?x3700))))
 (let ((?x3911 (to_real (+ (+ (+ ?x3907 (ite $x3460 1 0)) (ite $x3403 1 0)) ?x3700))))
 (let (($x3923 (and (= ?x3911 0.0) (= ?x3921 0.0))))
 (let (($x3699 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6)))
 (let (($x3906 (or c_2_2 c_2_3 c_2_4 c_2_5)))
 (let (($x3903 (and true $x3906)))
 (let (($x3970 (and $x3903 $x3699)))
 (let (($x3975 (not (and $x3970 $x3923))))
 (let ((?x3748 (ite $x3744 1 0)))
 (let ((?x3746 (ite $x3743 1 0)))
 (let ((?x3742 (ite $x3741 1 0)))
 (let ((?x3745 (+ 0 ?x3742)))
 (let ((?x3747 (+ ?x3745 ?x3746)))
 (let ((?x3749 (+ ?x3747 ?x3748)))
 (let ((?x3734 (ite $x3561 1 0)))
 (let ((?x3731 (ite $x3425 1 0)))
 (let ((?x3730 (+ 0 ?x3731)))
 (let ((?x3732 (+ ?x3730 ?x3729)))
 (let ((?x3735 (+ ?x3732 ?x3734)))
 (let (($x3753 (and (= (to_real (+ ?x3735 ?x3700)) 0.0) (= (to_real (+ ?x3749 ?x3700)) 0.0))))
 (let (($x3724 (or c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x3723 (and true $x3724)))
 (let (($x3969 (and $x3723 $x3974)))
 (let (($x3972 (not (and $x3969 $x3753))))
 (let (($x3869 (or c_8_1 c_8_2 c_8_3 c_8_4 c_8_5 c_8_6)))
 (let (($x3941 (and $x3940 $x3869)))
 (let (($x3963 (not (and $x3941 $x3961))))
 (let (($x3935 (not (and (and $x3757 $x3936) $x3787))))
 (let (($x3925 (not (and (and $x3903 $x3802) $x3923))))
 (let (($x3904 (not (and (and $x3723 $x3768) $x3753))))
 (let ((?x3712 (ite $x3710 1 0)))
 (let ((?x3709 (ite $x3708 1 0)))
 (let ((?x3711 (+ 0 ?x3709)))
 (let ((?x3713 (+ ?x3711 ?x3712)))
 (let ((?x3714 (+ ?x3713 ?x3700)))
 (let ((?x3703 (to_real (+ (+ (+ (+ 0 (ite $x3403 1 0)) ?x3698) ?x3700) ?x3700))))
 (let (($x3718 (and (= ?x3703 0.0) (= (to_real (+ ?x3714 ?x3700)) 0.0))))
 (let (($x3690 (or c_0_2 c_0_3 c_0_4 c_0_5)))
 (let (($x3688 (and true $x3690)))
 (let (($x3895 (and $x3688 $x3900)))
 (let (($x3899 (not (and $x3895 $x3718))))
 (let (($x3889 (not (and (and $x3859 $x3869) $x3887))))
 (let (($x3856 (not (and (and $x3829 $x3839) $x3854))))
 (let (($x3789 (not (and (and $x3757 $x3768) $x3787))))
 (let (($x3755 (not (and (and $x3723 $x3733) $x3753))))
 (let (($x3720 (not (and (and $x3688 $x3699) $x3718))))
 (let (($x4252 (not in_target_36)))
 (let (($x4250 (not in_target_35)))
 (let (($x4248 (not in_target_34)))
 (let (($x4246 (not in_target_33)))
 (let (($x4244 (not in_target_32)))
 (let (($x4242 (not in_target_31)))
 (let (($x4240 (not in_target_30)))
 (let (($x4238 (not in_target_29)))
 (let (($x4236 (not in_target_28)))
 (let (($x4234 (not in_target_27)))
 (let (($x4232 (not in_target_26)))
 (let (($x4230 (not in_target_25)))
 (let (($x4228 (not in_target_24)))
 (let (($x4226 (not in_target_23)))
 (let (($x4224 (not in_target_22)))
 (let (($x4222 (not in_target_21)))
 (let (($x4220 (not in_target_20)))
 (let (($x4218 (not in_target_19)))
 (let (($x4216 (not in_target_18)))
 (let (($x4214 (not in_target_17)))
 (let (($x4212 (not in_target_16)))
 (let (($x4210 (not in_target_15)))
 (let (($x4208 (not in_target_14)))
 (let (($x4206 (not in_target_13)))
 (let (($x4204 (not in_target_12)))
 (let (($x4202 (not in_target_11)))
 (let (($x4200 (not in_target_10)))
 (let (($x4198 (not in_target_9)))
 (let (($x4199 (and true $x4198)))
 (let (($x4201 (and $x4199 $x4200)))
 (let (($x4203 (and $x4201 $x4202)))
 (let (($x4205 (and $x4203 $x4204)))
 (let (($x4207 (and $x4205 $x4206)))
 (let (($x4209 (and $x4207 $x4208)))
 (let (($x4211 (and $x4209 $x4210)))
 (let (($x4213 (and $x4211 $x4212)))
 (let (($x4215 (and $x4213 $x4214)))
 (let (($x4217 (and $x4215 $x4216)))
 (let (($x4219 (and $x4217 $x4218)))
 (let (($x4221 (and $x4219 $x4220)))
 (let (($x4223 (and $x4221 $x4222)))
 (let (($x4225 (and $x4223 $x4224)))
 (let (($x4227 (and $x4225 $x4226)))
 (let (($x4229 (and $x4227 $x4228)))
 (let (($x4231 (and $x4229 $x4230)))
 (let (($x4233 (and $x4231 $x4232)))
 (let (($x4235 (and $x4233 $x4234)))
 (let (($x4237 (and $x4235 $x4236)))
 (let (($x4239 (and $x4237 $x4238)))
 (let (($x4241 (and $x4239 $x4240)))
 (let (($x4243 (and $x4241 $x4242)))
 (let (($x4245 (and $x4243 $x4244)))
 (let (($x4247 (and $x4245 $x4246)))
 (let (($x4249 (and $x4247 $x4248)))
 (let (($x4251 (and $x4249 $x4250)))
 (let (($x4253 (and $x4251 $x4252)))
 (let (($x4254 (and $x4253 $x3720)))
 (let (($x4257 (and $x4254 $x3755)))
 (let (($x4260 (and $x4257 $x3789)))
 (let (($x4262 (and $x4260 $x3856)))
 (let (($x4258 (and $x4262 $x3889)))
 (let (($x4261 (and $x4258 $x3899)))
 (let (($x4265 (and $x4261 $x3904)))
 (let (($x4263 (and $x4265 $x3925)))
 (let (($x4266 (and $x4263 $x3935)))
 (let (($x4267 (and $x4266 $x3963)))
 (let (($x4268 (and $x4267 $x3972)))
 (let (($x4259 (and $x4268 $x3975)))
 (let (($x4270 (and $x4259 $x3986)))
 (let (($x4272 (and $x4270 $x3990)))
 (let (($x4273 (and $x4272 $x4009)))
 (let (($x4264 (and $x4273 $x4014)))
 (let (($x4271 (and $x4264 $x4021)))
 (let (($x4275 (and $x4271 $x4027)))
 (let (($x4277 (and $x4275 $x4031)))
 (let (($x4153 (or c_8_7 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x4147 (and true $x4153)))
 (let (($x4096 (or c_7_7 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x4090 (and true $x4096)))
 (let (($x4086 (or c_6_7 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x4080 (and true $x4086)))
 (let (($x4128 (or c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4122 (and true $x4128)))
 (let (($x4076 (or c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4070 (and true $x4076)))
 (let (($x4066 (or c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x4060 (and true $x4066)))
 (let (($x4112 (or c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x4106 (and true $x4112)))
 (let (($x4056 (or c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x4050 (and true $x4056)))
 (let (($x4046 (or c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x4040 (and true $x4046)))
 (let ((?x3820 (ite $x3814 1 0)))
 (let ((?x3818 (ite $x3812 1 0)))
 (let ((?x3816 (ite $x3811 1 0)))
 (let ((?x3813 (ite $x3809 1 0)))
 (let ((?x3815 (+ 0 ?x3813)))
 (let ((?x3817 (+ ?x3815 ?x3816)))
 (let ((?x3819 (+ ?x3817 ?x3818)))
 (let ((?x3696 (ite $x3403 1 0)))
 (let ((?x3798 (ite $x3460 1 0)))
 (let ((?x3799 (+ 0 ?x3798)))
 (let ((?x3800 (+ ?x3799 ?x3801)))
 (let ((?x3803 (+ ?x3800 ?x3698)))
 (let (($x3824 (and (= (to_real (+ ?x3803 ?x3696)) 0.0) (= (to_real (+ ?x3819 ?x3820)) 0.0))))
 (let (($x3793 (or c_4_2 c_4_3 c_4_4 c_4_5)))
 (let (($x3791 (and true $x3793)))
 (let (($x4012 (and $x3791 $x3699)))
 (let (($x3389 (not (and (and true $x3145) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3386 (not (and (and true $x3093) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3383 (not (and (and true $x3085) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3380 (not (and (and true $x3122) (or (and c_2_1 $x1680) (and c_2_7 $x1680))))))
 (let (($x3377 (not (and (and true $x3077) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x3374 (not (and (and true $x3069) (or (and c_0_1 $x1652) (and c_0_7 $x1652))))))
 (let (($x3371 (not (and (and true $x3145) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3368 (not (and (and true $x3093) (or (and c_6_1 $x1740) (and c_6_7 $x1740))))))
 (let (($x3365 (not (and (and true $x3122) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3362 (not (and (and true $x3077) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3359 (not (and (and true $x3108) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x3356 (not (and (and true $x3061) (or (and c_0_1 $x1652) (and c_0_7 $x1652))))))
 (let (($x3352 (not (and (and true $x3122) (or (and c_8_1 $x1770) (and c_8_7 $x1770))))))
 (let (($x3349 (not (and (and true $x3077) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3346 (not (and (and true $x3069) (or (and c_6_1 $x1740) (and c_6_7 $x1740))))))
 (let (($x3342 (not (and (and true $x3108) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3339 (not (and (and true $x3061) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3336 (not (and (and true $x3053) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3332 (not (and (and true $x3093) (or (and c_8_1 $x1770) (and c_8_7 $x1770))))))
 (let (($x3328 (not (and (and true $x3085) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3324 (not (and (and true $x3077) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3320 (not (and (and true $x3069) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3316 (not (and (and true $x3061) (or (and c_2_1 $x1680) (and c_2_7 $x1680))))))
 (let (($x3311 (not (and (and true $x3053) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x2007 (and c_5_11 in_target_5)))
 (let (($x2005 (and c_5_10 in_target_5)))
 (let (($x2003 (and c_5_9 in_target_5)))
 (let (($x2001 (and c_5_8 in_target_5)))
 (let (($x1996 (and c_5_5 in_target_5)))
 (let (($x1994 (and c_5_4 in_target_5)))
 (let (($x1992 (and c_5_3 in_target_5)))
 (let (($x1990 (and c_5_2 in_target_5)))
 (let (($x3213 (or $x1990 $x1992 $x1994 $x1996 $x2001 $x2003 $x2005 $x2007)))
 (let (($x3143 (and true $x3145)))
 (let (($x1972 (and c_4_11 in_target_4)))
 (let (($x1970 (and c_4_10 in_target_4)))
 (let (($x1968 (and c_4_9 in_target_4)))
 (let (($x1966 (and c_4_8 in_target_4)))
 (let (($x1961 (and c_4_5 in_target_4)))
 (let (($x1959 (and c_4_4 in_target_4)))
 (let (($x1957 (and c_4_3 in_target_4)))
 (let (($x1955 (and c_4_2 in_target_4)))
 (let (($x3202 (or $x1955 $x1957 $x1959 $x1961 $x1966 $x1968 $x1970 $x1972)))
 (let (($x3091 (and true $x3093)))
 (let (($x1937 (and c_3_11 in_target_3)))
 (let (($x1935 (and c_3_10 in_target_3)))
 (let (($x1933 (and c_3_9 in_target_3)))
 (let (($x1931 (and c_3_8 in_target_3)))
 (let (($x1926 (and c_3_5 in_target_3)))
 (let (($x1924 (and c_3_4 in_target_3)))
 (let (($x1922 (and c_3_3 in_target_3)))
 (let (($x1920 (and c_3_2 in_target_3)))
 (let (($x3246 (or $x1920 $x1922 $x1924 $x1926 $x1931 $x1933 $x1935 $x1937)))
 (let (($x3083 (and true $x3085)))
 (let (($x1902 (and c_2_11 in_target_2)))
 (let (($x1900 (and c_2_10 in_target_2)))
 (let (($x1898 (and c_2_9 in_target_2)))
 (let (($x1896 (and c_2_8 in_target_2)))
 (let (($x1891 (and c_2_5 in_target_2)))
 (let (($x1889 (and c_2_4 in_target_2)))
 (let (($x1887 (and c_2_3 in_target_2)))
 (let (($x1885 (and c_2_2 in_target_2)))
 (let (($x3191 (or $x1885 $x1887 $x1889 $x1891 $x1896 $x1898 $x1900 $x1902)))
 (let (($x3120 (and true $x3122)))
 (let (($x1867 (and c_1_11 in_target_1)))
 (let (($x1865 (and c_1_10 in_target_1)))
 (let (($x1863 (and c_1_9 in_target_1)))
 (let (($x1861 (and c_1_8 in_target_1)))
 (let (($x1856 (and c_1_5 in_target_1)))
 (let (($x1854 (and c_1_4 in_target_1)))
 (let (($x1852 (and c_1_3 in_target_1)))
 (let (($x1850 (and c_1_2 in_target_1)))
 (let (($x3180 (or $x1850 $x1852 $x1854 $x1856 $x1861 $x1863 $x1865 $x1867)))
 (let (($x3075 (and true $x3077)))
 (let (($x1832 (and c_0_11 in_target_0)))
 (let (($x1830 (and c_0_10 in_target_0)))
 (let (($x1828 (and c_0_9 in_target_0)))
 (let (($x1826 (and c_0_8 in_target_0)))
 (let (($x1821 (and c_0_5 in_target_0)))
 (let (($x1819 (and c_0_4 in_target_0)))
 (let (($x1817 (and c_0_3 in_target_0)))
 (let (($x1815 (and c_0_2 in_target_0)))
 (let (($x3280 (or $x1815 $x1817 $x1819 $x1821 $x1826 $x1828 $x1830 $x1832)))
 (let (($x3067 (and true $x3069)))
 (let (($x2077 (and c_7_11 in_target_7)))
 (let (($x2075 (and c_7_10 in_target_7)))
 (let (($x2073 (and c_7_9 in_target_7)))
 (let (($x2071 (and c_7_8 in_target_7)))
 (let (($x2066 (and c_7_5 in_target_7)))
 (let (($x2064 (and c_7_4 in_target_7)))
 (let (($x2062 (and c_7_3 in_target_7)))
 (let (($x2060 (and c_7_2 in_target_7)))
 (let (($x3224 (or $x2060 $x2062 $x2064 $x2066 $x2071 $x2073 $x2075 $x2077)))
 (let (($x2042 (and c_6_11 in_target_6)))
 (let (($x2040 (and c_6_10 in_target_6)))
 (let (($x2038 (and c_6_9 in_target_6)))
 (let (($x2036 (and c_6_8 in_target_6)))
 (let (($x2031 (and c_6_5 in_target_6)))
 (let (($x2029 (and c_6_4 in_target_6)))
 (let (($x2027 (and c_6_3 in_target_6)))
 (let (($x2025 (and c_6_2 in_target_6)))
 (let (($x3263 (or $x2025 $x2027 $x2029 $x2031 $x2036 $x2038 $x2040 $x2042)))
 (let (($x2112 (and c_8_11 in_target_8)))
 (let (($x2110 (and c_8_10 in_target_8)))
 (let (($x2108 (and c_8_9 in_target_8)))
 (let (($x2106 (and c_8_8 in_target_8)))
 (let (($x2101 (and c_8_5 in_target_8)))
 (let (($x2099 (and c_8_4 in_target_8)))
 (let (($x2097 (and c_8_3 in_target_8)))
 (let (($x2095 (and c_8_2 in_target_8)))
 (let (($x3235 (or $x2095 $x2097 $x2099 $x2101 $x2106 $x2108 $x2110 $x2112)))
 (let (($x3164 (not (and $x3143 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3161 (not (and $x3091 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3158 (not (and $x3083 (or (and c_3_1 in_target_3) (and c_3_7 in_target_3))))))
 (let (($x3155 (not (and $x3120 (or (and c_2_1 in_target_2) (and c_2_7 in_target_2))))))
 (let (($x3152 (not (and $x3075 (or (and c_1_1 in_target_1) (and c_1_7 in_target_1))))))
 (let (($x3149 (not (and $x3067 (or (and c_0_1 in_target_0) (and c_0_7 in_target_0))))))
 (let (($x3146 (not (and $x3143 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3139 (not (and $x3091 (or (and c_6_1 in_target_6) (and c_6_7 in_target_6))))))
 (let (($x3136 (not (and $x3120 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3133 (not (and $x3075 (or (and c_3_1 in_target_3) (and c_3_7 in_target_3))))))
 (let (($x1859 (and c_1_7 in_target_1)))
 (let (($x1848 (and c_1_1 in_target_1)))
 (let (($x3054 (or $x1848 $x1859)))
 (let (($x3106 (and true $x3108)))
 (let (($x1824 (and c_0_7 in_target_0)))
 (let (($x1813 (and c_0_1 in_target_0)))
 (let (($x3126 (or $x1813 $x1824)))
 (let (($x3059 (and true $x3061)))
 (let (($x3123 (not (and $x3120 (or (and c_8_1 in_target_8) (and c_8_7 in_target_8))))))
 (let (($x3116 (not (and $x3075 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3113 (not (and $x3067 (or (and c_6_1 in_target_6) (and c_6_7 in_target_6))))))
 (let (($x3109 (not (and $x3106 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3102 (not (and $x3059 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x1929 (and c_3_7 in_target_3)))
 (let (($x1918 (and c_3_1 in_target_3)))
 (let (($x3098 (or $x1918 $x1929)))
 (let (($x3051 (and true $x3053)))
 (let (($x3095 (not (and $x3091 (or (and c_8_1 in_target_8) (and c_8_7 in_target_8))))))
 (let (($x3087 (not (and $x3083 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3079 (not (and $x3075 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3071 (not (and $x3067 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3063 (not (and $x3059 (or (and c_2_1 in_target_2) (and c_2_7 in_target_2))))))
 (let (($x2829 (and c_8_11 $x1770)))
 (let (($x2827 (and c_8_10 $x1770)))
 (let (($x2825 (and c_8_9 $x1770)))
 (let (($x2823 (and c_8_8 $x1770)))
 (let (($x2822 (and c_8_7 $x1770)))
 (let ((?x2820 (ite (or $x2822 $x2823 $x2825 $x2827 $x2829 $x2831) 2 0)))
 (let (($x2810 (and c_8_5 $x1770)))
 (let (($x2808 (and c_8_4 $x1770)))
 (let (($x2806 (and c_8_3 $x1770)))
 (let (($x2804 (and c_8_2 $x1770)))
 (let (($x2803 (and c_8_1 $x1770)))
 (let ((?x3025 (ite (or $x2803 $x2804 $x2806 $x2808 $x2810 $x2812) 1 0)))
 (let (($x2093 (and c_8_1 in_target_8)))
 (let (($x1784 (and c_8_6 in_target_8)))
 (let ((?x3023 (ite (or $x1784 $x2093 $x2095 $x2097 $x2099 $x2101) (- 1) 0)))
 (let (($x2092 (and c_8_0 in_target_8)))
 (let ((?x3024 (ite $x2092 (- 2) 0)))
 (let (($x2771 (and c_7_11 $x1755)))
 (let (($x2769 (and c_7_10 $x1755)))
 (let (($x2767 (and c_7_9 $x1755)))
 (let (($x2765 (and c_7_8 $x1755)))
 (let (($x2764 (and c_7_7 $x1755)))
 (let ((?x2762 (ite (or $x2764 $x2765 $x2767 $x2769 $x2771 $x2773) 2 0)))
 (let (($x2752 (and c_7_5 $x1755)))
 (let (($x2750 (and c_7_4 $x1755)))
 (let (($x2748 (and c_7_3 $x1755)))
 (let (($x2746 (and c_7_2 $x1755)))
 (let (($x2745 (and c_7_1 $x1755)))
 (let ((?x3002 (ite (or $x2745 $x2746 $x2748 $x2750 $x2752 $x2754) 1 0)))
 (let (($x2058 (and c_7_1 in_target_7)))
 (let (($x1769 (and c_7_6 in_target_7)))
 (let ((?x2998 (ite (or $x1769 $x2058 $x2060 $x2062 $x2064 $x2066) (- 1) 0)))
 (let (($x2057 (and c_7_0 in_target_7)))
 (let ((?x2995 (ite $x2057 (- 2) 0)))
 (let (($x2713 (and c_6_11 $x1740)))
 (let (($x2711 (and c_6_10 $x1740)))
 (let (($x2709 (and c_6_9 $x1740)))
 (let (($x2707 (and c_6_8 $x1740)))
 (let (($x2706 (and c_6_7 $x1740)))
 (let ((?x2704 (ite (or $x2706 $x2707 $x2709 $x2711 $x2713 $x2715) 2 0)))
 (let (($x2694 (and c_6_5 $x1740)))
 (let (($x2692 (and c_6_4 $x1740)))
 (let (($x2690 (and c_6_3 $x1740)))
 (let (($x2688 (and c_6_2 $x1740)))
 (let (($x2687 (and c_6_1 $x1740)))
 (let ((?x2989 (ite (or $x2687 $x2688 $x2690 $x2692 $x2694 $x2696) 1 0)))
 (let (($x2023 (and c_6_1 in_target_6)))
 (let (($x1754 (and c_6_6 in_target_6)))
 (let ((?x2982 (ite (or $x1754 $x2023 $x2025 $x2027 $x2029 $x2031) (- 1) 0)))
 (let (($x2022 (and c_6_0 in_target_6)))
 (let ((?x2977 (ite $x2022 (- 2) 0)))
 (let (($x2655 (and c_5_11 $x1725)))
 (let (($x2653 (and c_5_10 $x1725)))
 (let (($x2651 (and c_5_9 $x1725)))
 (let (($x2649 (and c_5_8 $x1725)))
 (let (($x2648 (and c_5_7 $x1725)))
 (let ((?x2646 (ite (or $x2648 $x2649 $x2651 $x2653 $x2655 $x2657) 2 0)))
 (let (($x2636 (and c_5_5 $x1725)))
 (let (($x2634 (and c_5_4 $x1725)))
 (let (($x2632 (and c_5_3 $x1725)))
 (let (($x2630 (and c_5_2 $x1725)))
 (let (($x2629 (and c_5_1 $x1725)))
 (let ((?x2955 (ite (or $x2629 $x2630 $x2632 $x2634 $x2636 $x2638) 1 0)))
 (let (($x1988 (and c_5_1 in_target_5)))
 (let (($x1739 (and c_5_6 in_target_5)))
 (let ((?x2963 (ite (or $x1739 $x1988 $x1990 $x1992 $x1994 $x1996) (- 1) 0)))
 (let (($x1987 (and c_5_0 in_target_5)))
 (let ((?x2958 (ite $x1987 (- 2) 0)))
 (let (($x2597 (and c_4_11 $x1710)))
 (let (($x2595 (and c_4_10 $x1710)))
 (let (($x2593 (and c_4_9 $x1710)))
 (let (($x2591 (and c_4_8 $x1710)))
 (let (($x2590 (and c_4_7 $x1710)))
 (let ((?x2588 (ite (or $x2590 $x2591 $x2593 $x2595 $x2597 $x2599) 2 0)))
 (let (($x2578 (and c_4_5 $x1710)))
 (let (($x2576 (and c_4_4 $x1710)))
 (let (($x2574 (and c_4_3 $x1710)))
 (let (($x2572 (and c_4_2 $x1710)))
 (let (($x2571 (and c_4_1 $x1710)))
 (let ((?x2947 (ite (or $x2571 $x2572 $x2574 $x2576 $x2578 $x2580) 1 0)))
 (let (($x1953 (and c_4_1 in_target_4)))
 (let (($x1724 (and c_4_6 in_target_4)))
 (let ((?x2936 (ite (or $x1724 $x1953 $x1955 $x1957 $x1959 $x1961) (- 1) 0)))
 (let (($x1952 (and c_4_0 in_target_4)))
 (let ((?x2942 (ite $x1952 (- 2) 0)))
 (let (($x2539 (and c_3_11 $x1695)))
 (let (($x2537 (and c_3_10 $x1695)))
 (let (($x2535 (and c_3_9 $x1695)))
 (let (($x2533 (and c_3_8 $x1695)))
 (let (($x2532 (and c_3_7 $x1695)))
 (let ((?x2530 (ite (or $x2532 $x2533 $x2535 $x2537 $x2539 $x2541) 2 0)))
 (let (($x2520 (and c_3_5 $x1695)))
 (let (($x2518 (and c_3_4 $x1695)))
 (let (($x2516 (and c_3_3 $x1695)))
 (let (($x2514 (and c_3_2 $x1695)))
 (let (($x2513 (and c_3_1 $x1695)))
 (let ((?x2926 (ite (or $x2513 $x2514 $x2516 $x2518 $x2520 $x2522) 1 0)))
 (let ((?x2920 (ite (or (and c_3_6 in_target_3) $x1918 $x1920 $x1922 $x1924 $x1926) (- 1) 0)))
 (let (($x1917 (and c_3_0 in_target_3)))
 (let ((?x2916 (ite $x1917 (- 2) 0)))
 (let (($x2481 (and c_2_11 $x1680)))
 (let (($x2479 (and c_2_10 $x1680)))
 (let (($x2477 (and c_2_9 $x1680)))
 (let (($x2475 (and c_2_8 $x1680)))
 (let (($x2474 (and c_2_7 $x1680)))
 (let ((?x2472 (ite (or $x2474 $x2475 $x2477 $x2479 $x2481 $x2483) 2 0)))
 (let (($x2462 (and c_2_5 $x1680)))
 (let (($x2460 (and c_2_4 $x1680)))
 (let (($x2458 (and c_2_3 $x1680)))
 (let (($x2456 (and c_2_2 $x1680)))
 (let (($x2455 (and c_2_1 $x1680)))
 (let ((?x2897 (ite (or $x2455 $x2456 $x2458 $x2460 $x2462 $x2464) 1 0)))
 (let (($x1883 (and c_2_1 in_target_2)))
 (let (($x1694 (and c_2_6 in_target_2)))
 (let ((?x2895 (ite (or $x1694 $x1883 $x1885 $x1887 $x1889 $x1891) (- 1) 0)))
 (let (($x1882 (and c_2_0 in_target_2)))
 (let ((?x2896 (ite $x1882 (- 2) 0)))
 (let (($x2423 (and c_1_11 $x1665)))
 (let (($x2421 (and c_1_10 $x1665)))
 (let (($x2419 (and c_1_9 $x1665)))
 (let (($x2417 (and c_1_8 $x1665)))
 (let (($x2416 (and c_1_7 $x1665)))
 (let ((?x2414 (ite (or $x2416 $x2417 $x2419 $x2421 $x2423 $x2425) 2 0)))
 (let (($x2404 (and c_1_5 $x1665)))
 (let (($x2402 (and c_1_4 $x1665)))
 (let (($x2400 (and c_1_3 $x1665)))
 (let (($x2398 (and c_1_2 $x1665)))
 (let (($x2397 (and c_1_1 $x1665)))
 (let ((?x2881 (ite (or $x2397 $x2398 $x2400 $x2402 $x2404 $x2406) 1 0)))
 (let ((?x2874 (ite (or (and c_1_6 in_target_1) $x1848 $x1850 $x1852 $x1854 $x1856) (- 1) 0)))
 (let (($x1847 (and c_1_0 in_target_1)))
 (let ((?x2873 (ite $x1847 (- 2) 0)))
 (let (($x2365 (and c_0_11 $x1652)))
 (let (($x2363 (and c_0_10 $x1652)))
 (let (($x2361 (and c_0_9 $x1652)))
 (let (($x2359 (and c_0_8 $x1652)))
 (let (($x2358 (and c_0_7 $x1652)))
 (let ((?x2356 (ite (or $x2358 $x2359 $x2361 $x2363 $x2365 $x2367) 2 0)))
 (let (($x2345 (and c_0_5 $x1652)))
 (let (($x2343 (and c_0_4 $x1652)))
 (let (($x2341 (and c_0_3 $x1652)))
 (let (($x2339 (and c_0_2 $x1652)))
 (let (($x2338 (and c_0_1 $x1652)))
 (let ((?x2861 (ite (or $x2338 $x2339 $x2341 $x2343 $x2345 $x2347) 1 0)))
 (let ((?x2857 (ite (or (and c_0_6 in_target_0) $x1813 $x1815 $x1817 $x1819 $x1821) (- 1) 0)))
 (let (($x1812 (and c_0_0 in_target_0)))
 (let ((?x2845 (ite $x1812 (- 2) 0)))
 (let ((?x2848 (+ 0 ?x2845)))
 (let ((?x2860 (+ ?x2848 ?x2857)))
 (let ((?x2858 (+ ?x2860 ?x2861)))
 (let ((?x2859 (+ ?x2858 ?x2356)))
 (let ((?x2877 (+ ?x2859 ?x2873)))
 (let ((?x2878 (+ ?x2877 ?x2874)))
 (let ((?x2882 (+ ?x2878 ?x2881)))
 (let ((?x2879 (+ ?x2882 ?x2414)))
 (let ((?x2893 (+ ?x2879 ?x2896)))
 (let ((?x2902 (+ ?x2893 ?x2895)))
 (let ((?x2905 (+ ?x2902 ?x2897)))
 (let ((?x2899 (+ ?x2905 ?x2472)))
 (let ((?x2914 (+ ?x2899 ?x2916)))
 (let ((?x2924 (+ ?x2914 ?x2920)))
 (let ((?x2918 (+ ?x2924 ?x2926)))
 (let ((?x2917 (+ ?x2918 ?x2530)))
 (let ((?x2933 (+ ?x2917 ?x2942)))
 (let ((?x2945 (+ ?x2933 ?x2936)))
 (let ((?x2935 (+ ?x2945 ?x2947)))
 (let ((?x2941 (+ ?x2935 ?x2588)))
 (let ((?x2954 (+ ?x2941 ?x2958)))
 (let ((?x2960 (+ ?x2954 ?x2963)))
 (let ((?x2966 (+ ?x2960 ?x2955)))
 (let ((?x2968 (+ ?x2966 ?x2646)))
 (let ((?x2976 (+ ?x2968 ?x2977)))
 (let ((?x2987 (+ ?x2976 ?x2982)))
 (let ((?x2984 (+ ?x2987 ?x2989)))
 (let ((?x2986 (+ ?x2984 ?x2704)))
 (let ((?x3003 (+ ?x2986 ?x2995)))
 (let ((?x3007 (+ ?x3003 ?x2998)))
 (let ((?x3010 (+ ?x3007 ?x3002)))
 (let ((?x3004 (+ ?x3010 ?x2762)))
 (let ((?x3016 (+ ?x3004 ?x3024)))
 (let ((?x3018 (+ ?x3016 ?x3023)))
 (let ((?x3029 (+ ?x3018 ?x3025)))
 (let (($x3043 (<= (+ ?x3029 ?x2820) 0)))
 (let (($x2104 (and c_8_7 in_target_8)))
 (let (($x1786 (and c_8_12 in_target_8)))
 (let ((?x2801 (ite (or $x1786 $x2104 $x2106 $x2108 $x2110 $x2112 $x2803 $x2804 $x2806 $x2808 $x2810 $x2812) 1 0)))
 (let ((?x2781 (ite $x2092 (- 1) 0)))
 (let (($x2069 (and c_7_7 in_target_7)))
 (let (($x1771 (and c_7_12 in_target_7)))
 (let ((?x2743 (ite (or $x1771 $x2069 $x2071 $x2073 $x2075 $x2077 $x2745 $x2746 $x2748 $x2750 $x2752 $x2754) 1 0)))
 (let ((?x2723 (ite $x2057 (- 1) 0)))
 (let (($x2034 (and c_6_7 in_target_6)))
 (let (($x1756 (and c_6_12 in_target_6)))
 (let ((?x2685 (ite (or $x1756 $x2034 $x2036 $x2038 $x2040 $x2042 $x2687 $x2688 $x2690 $x2692 $x2694 $x2696) 1 0)))
 (let ((?x2665 (ite $x2022 (- 1) 0)))
 (let (($x1999 (and c_5_7 in_target_5)))
 (let (($x1741 (and c_5_12 in_target_5)))
 (let ((?x2627 (ite (or $x1741 $x1999 $x2001 $x2003 $x2005 $x2007 $x2629 $x2630 $x2632 $x2634 $x2636 $x2638) 1 0)))
 (let ((?x2607 (ite $x1987 (- 1) 0)))
 (let (($x1964 (and c_4_7 in_target_4)))
 (let (($x1726 (and c_4_12 in_target_4)))
 (let ((?x2569 (ite (or $x1726 $x1964 $x1966 $x1968 $x1970 $x1972 $x2571 $x2572 $x2574 $x2576 $x2578 $x2580) 1 0)))
 (let ((?x2549 (ite $x1952 (- 1) 0)))
 (let (($x1711 (and c_3_12 in_target_3)))
 (let ((?x2511 (ite (or $x1711 $x1929 $x1931 $x1933 $x1935 $x1937 $x2513 $x2514 $x2516 $x2518 $x2520 $x2522) 1 0)))
 (let ((?x2491 (ite $x1917 (- 1) 0)))
 (let (($x1894 (and c_2_7 in_target_2)))
 (let (($x1696 (and c_2_12 in_target_2)))
 (let ((?x2453 (ite (or $x1696 $x1894 $x1896 $x1898 $x1900 $x1902 $x2455 $x2456 $x2458 $x2460 $x2462 $x2464) 1 0)))
 (let ((?x2433 (ite $x1882 (- 1) 0)))
 (let (($x1681 (and c_1_12 in_target_1)))
 (let ((?x2395 (ite (or $x1681 $x1859 $x1861 $x1863 $x1865 $x1867 $x2397 $x2398 $x2400 $x2402 $x2404 $x2406) 1 0)))
 (let ((?x2375 (ite $x1847 (- 1) 0)))
 (let (($x1666 (and c_0_12 in_target_0)))
 (let ((?x2336 (ite (or $x1666 $x1824 $x1826 $x1828 $x1830 $x1832 $x2338 $x2339 $x2341 $x2343 $x2345 $x2347) 1 0)))
 (let ((?x2317 (ite $x1812 (- 1) 0)))
 (let ((?x2318 (+ 0 ?x2317)))
 (let ((?x2337 (+ ?x2318 ?x2336)))
 (let ((?x2357 (+ ?x2337 ?x2356)))
 (let ((?x2376 (+ ?x2357 ?x2375)))
 (let ((?x2396 (+ ?x2376 ?x2395)))
 (let ((?x2415 (+ ?x2396 ?x2414)))
 (let ((?x2434 (+ ?x2415 ?x2433)))
 (let ((?x2454 (+ ?x2434 ?x2453)))
 (let ((?x2473 (+ ?x2454 ?x2472)))
 (let ((?x2492 (+ ?x2473 ?x2491)))
 (let ((?x2512 (+ ?x2492 ?x2511)))
 (let ((?x2531 (+ ?x2512 ?x2530)))
 (let ((?x2550 (+ ?x2531 ?x2549)))
 (let ((?x2570 (+ ?x2550 ?x2569)))
 (let ((?x2589 (+ ?x2570 ?x2588)))
 (let ((?x2608 (+ ?x2589 ?x2607)))
 (let ((?x2628 (+ ?x2608 ?x2627)))
 (let ((?x2647 (+ ?x2628 ?x2646)))
 (let ((?x2666 (+ ?x2647 ?x2665)))
 (let ((?x2686 (+ ?x2666 ?x2685)))
 (let ((?x2705 (+ ?x2686 ?x2704)))
 (let ((?x2724 (+ ?x2705 ?x2723)))
 (let ((?x2744 (+ ?x2724 ?x2743)))
 (let ((?x2763 (+ ?x2744 ?x2762)))
 (let ((?x2782 (+ ?x2763 ?x2781)))
 (let ((?x2802 (+ ?x2782 ?x2801)))
 (let (($x2839 (>= (+ ?x2802 ?x2820) 0)))
 (let ((?x2298 (ite root_17 1 0)))
 (let ((?x2279 (ite root_15 1 0)))
 (let ((?x2263 (ite root_13 1 0)))
 (let ((?x2244 (ite root_11 1 0)))
 (let ((?x2222 (ite root_9 1 0)))
 (let ((?x2203 (ite root_7 1 0)))
 (let ((?x2187 (ite root_5 1 0)))
 (let ((?x2168 (ite root_3 1 0)))
 (let ((?x2152 (ite root_1 1 0)))
 (let ((?x2153 (+ 0 ?x2152)))
 (let ((?x2169 (+ ?x2153 ?x2168)))
 (let ((?x2188 (+ ?x2169 ?x2187)))
 (let ((?x2204 (+ ?x2188 ?x2203)))
 (let ((?x2223 (+ ?x2204 ?x2222)))
 (let ((?x2245 (+ ?x2223 ?x2244)))
 (let ((?x2264 (+ ?x2245 ?x2263)))
 (let ((?x2280 (+ ?x2264 ?x2279)))
 (let (($x2150 (or false root_1)))
 (let (($x2167 (or $x2150 root_3)))
 (let (($x2186 (or $x2167 root_5)))
 (let (($x2202 (or $x2186 root_7)))
 (let (($x2221 (or $x2202 root_9)))
 (let (($x2243 (or $x2221 root_11)))
 (let (($x2262 (or $x2243 root_13)))
 (let (($x2278 (or $x2262 root_15)))
 (let (($x2114 (or $x1784 $x1786 $x2092 $x2093 $x2095 $x2097 $x2099 $x2101 $x2104 $x2106 $x2108 $x2110 $x2112)))
 (let (($x2079 (or $x1769 $x1771 $x2057 $x2058 $x2060 $x2062 $x2064 $x2066 $x2069 $x2071 $x2073 $x2075 $x2077)))
 (let (($x2044 (or $x1754 $x1756 $x2022 $x2023 $x2025 $x2027 $x2029 $x2031 $x2034 $x2036 $x2038 $x2040 $x2042)))
 (let (($x2009 (or $x1739 $x1741 $x1987 $x1988 $x1990 $x1992 $x1994 $x1996 $x1999 $x2001 $x2003 $x2005 $x2007)))
 (let (($x1974 (or $x1724 $x1726 $x1952 $x1953 $x1955 $x1957 $x1959 $x1961 $x1964 $x1966 $x1968 $x1970 $x1972)))
 (let (($x1709 (and c_3_6 in_target_3)))
 (let (($x1939 (or $x1709 $x1711 $x1917 $x1918 $x1920 $x1922 $x1924 $x1926 $x1929 $x1931 $x1933 $x1935 $x1937)))
 (let (($x1904 (or $x1694 $x1696 $x1882 $x1883 $x1885 $x1887 $x1889 $x1891 $x1894 $x1896 $x1898 $x1900 $x1902)))
 (let (($x1679 (and c_1_6 in_target_1)))
 (let (($x1869 (or $x1679 $x1681 $x1847 $x1848 $x1850 $x1852 $x1854 $x1856 $x1859 $x1861 $x1863 $x1865 $x1867)))
 (let (($x1664 (and c_0_6 in_target_0)))
 (let (($x1834 (or $x1664 $x1666 $x1812 $x1813 $x1815 $x1817 $x1819 $x1821 $x1824 $x1826 $x1828 $x1830 $x1832)))
 (let (($x2149 (or false $x1834)))
 (let (($x2166 (or $x2149 $x1869)))
 (let (($x2185 (or $x2166 $x1904)))
 (let (($x2201 (or $x2185 $x1939)))
 (let (($x2220 (or $x2201 $x1974)))
 (let (($x2242 (or $x2220 $x2009)))
 (let (($x2261 (or $x2242 $x2044)))
 (let (($x2277 (or $x2261 $x2079)))
 (let (($x2304 (or false (and $x2079 (< rank_14 rank_16)))))
 (let (($x2308 (not root_17)))
 (let (($x2309 (and $x2114 $x2308)))
 (let (($x2285 (or false (and $x2114 (< rank_16 rank_14)))))
 (let (($x2288 (or $x2285 (and $x2044 (< rank_12 rank_14)))))
 (let (($x2292 (not root_15)))
 (let (($x2293 (and $x2079 $x2292)))
 (let (($x2269 (or false (and $x2079 (< rank_14 rank_12)))))
 (let (($x2273 (not root_13)))
 (let (($x2274 (and $x2044 $x2273)))
 (let (($x2250 (or false (and $x2114 (< rank_16 rank_10)))))
 (let (($x2253 (or $x2250 (and $x1974 (< rank_8 rank_10)))))
 (let (($x2257 (not root_11)))
 (let (($x2258 (and $x2009 $x2257)))
 (let (($x2228 (or false (and $x2009 (< rank_10 rank_8)))))
 (let (($x2231 (or $x2228 (and $x2079 (< rank_14 rank_8)))))
 (let (($x2234 (or $x2231 (and $x1939 (< rank_6 rank_8)))))
 (let (($x2238 (not root_9)))
 (let (($x2239 (and $x1974 $x2238)))
 (let (($x2209 (or false (and $x1974 (< rank_8 rank_6)))))
 (let (($x2212 (or $x2209 (and $x2044 (< rank_12 rank_6)))))
 (let (($x2216 (not root_7)))
 (let (($x2217 (and $x1939 $x2216)))
 (let (($x2193 (or false (and $x2009 (< rank_10 rank_4)))))
 (let (($x2197 (not root_5)))
 (let (($x2198 (and $x1904 $x2197)))
 (let (($x2174 (or false (and $x1904 (< rank_4 rank_2)))))
 (let (($x2177 (or $x2174 (and $x1974 (< rank_8 rank_2)))))
 (let (($x2181 (not root_3)))
 (let (($x2182 (and $x1869 $x2181)))
 (let (($x2158 (or false (and $x1869 (< rank_2 rank_0)))))
 (let (($x2162 (not root_1)))
 (let (($x2163 (and $x1834 $x2162)))
 (let (($x2155 (and true (=> root_1 $x1834))))
 (let (($x2165 (and $x2155 (=> $x2163 (or $x2158 (and $x1939 (< rank_6 rank_0)))))))
 (let (($x2171 (and $x2165 (=> root_3 $x1869))))
 (let (($x2184 (and $x2171 (=> $x2182 (or $x2177 (and $x1834 (< rank_0 rank_2)))))))
 (let (($x2190 (and $x2184 (=> root_5 $x1904))))
 (let (($x2200 (and $x2190 (=> $x2198 (or $x2193 (and $x1869 (< rank_2 rank_4)))))))
 (let (($x2206 (and $x2200 (=> root_7 $x1939))))
 (let (($x2219 (and $x2206 (=> $x2217 (or $x2212 (and $x1834 (< rank_0 rank_6)))))))
 (let (($x2225 (and $x2219 (=> root_9 $x1974))))
 (let (($x2241 (and $x2225 (=> $x2239 (or $x2234 (and $x1869 (< rank_2 rank_8)))))))
 (let (($x2247 (and $x2241 (=> root_11 $x2009))))
 (let (($x2260 (and $x2247 (=> $x2258 (or $x2253 (and $x1904 (< rank_4 rank_10)))))))
 (let (($x2266 (and $x2260 (=> root_13 $x2044))))
 (let (($x2276 (and $x2266 (=> $x2274 (or $x2269 (and $x1939 (< rank_6 rank_12)))))))
 (let (($x2282 (and $x2276 (=> root_15 $x2079))))
 (let (($x2295 (and $x2282 (=> $x2293 (or $x2288 (and $x1974 (< rank_8 rank_14)))))))
 (let (($x2301 (and $x2295 (=> root_17 $x2114))))
 (let (($x2313 (and (and $x2301 (=> $x2309 (or $x2304 (and $x2009 (< rank_10 rank_16))))) (=> (or $x2277 $x2114) (or $x2278 root_17)))))
 (let (($x2315 (and $x2313 (<= (+ ?x2280 ?x2298) 1))))
 (let (($x1787 (or (and c_8_0 $x1770) $x1784 $x1786)))
 (let (($x1772 (or (and c_7_0 $x1755) $x1769 $x1771)))
 (let (($x1757 (or (and c_6_0 $x1740) $x1754 $x1756)))
 (let (($x1742 (or (and c_5_0 $x1725) $x1739 $x1741)))
 (let (($x1727 (or (and c_4_0 $x1710) $x1724 $x1726)))
 (let (($x1712 (or (and c_3_0 $x1695) $x1709 $x1711)))
 (let (($x1697 (or (and c_2_0 $x1680) $x1694 $x1696)))
 (let (($x1682 (or (and c_1_0 $x1665) $x1679 $x1681)))
 (let (($x1667 (or (and c_0_0 $x1652) $x1664 $x1666)))
 (let (($x1662 (and true $x1667)))
 (let (($x1677 (and $x1662 $x1682)))
 (let (($x1692 (and $x1677 $x1697)))
 (let (($x1707 (and $x1692 $x1712)))
 (let (($x1722 (and $x1707 $x1727)))
 (let (($x1737 (and $x1722 $x1742)))
 (let (($x1752 (and $x1737 $x1757)))
 (let (($x1767 (and $x1752 $x1772)))
 (let (($x1781 (not (and $x1767 $x1787))))
 (let (($x3046 (and $x1781 (and (and $x2315 $x2839) $x3043))))
 (let (($x3056 (and $x3046 (not (and $x3051 $x3054)))))
 (let (($x3064 (and $x3056 $x3063)))
 (let (($x3072 (and $x3064 $x3071)))
 (let (($x3080 (and $x3072 $x3079)))
 (let (($x3088 (and $x3080 $x3087)))
 (let (($x3096 (and $x3088 $x3095)))
 (let (($x3100 (and $x3096 (not (and $x3051 $x3098)))))
 (let (($x3103 (and $x3100 $x3102)))
 (let (($x3110 (and $x3103 $x3109)))
 (let (($x3114 (and $x3110 $x3113)))
 (let (($x3117 (and $x3114 $x3116)))
 (let (($x3124 (and $x3117 $x3123)))
 (let (($x3128 (and $x3124 (not (and $x3059 $x3126)))))
 (let (($x3131 (and $x3128 (not (and $x3106 $x3054)))))
 (let (($x3134 (and $x3131 $x3133)))
 (let (($x3137 (and $x3134 $x3136)))
 (let (($x3140 (and $x3137 $x3139)))
 (let (($x3147 (and $x3140 $x3146)))
 (let (($x3150 (and $x3147 $x3149)))
 (let (($x3153 (and $x3150 $x3152)))
 (let (($x3156 (and $x3153 $x3155)))
 (let (($x3159 (and $x3156 $x3158)))
 (let (($x3162 (and $x3159 $x3161)))
 (let (($x3165 (and $x3162 $x3164)))
 (let (($x3174 (and $x3165 (not (and $x3051 $x3180)))))
 (let (($x3187 (and $x3174 (not (and $x3059 $x3191)))))
 (let (($x3196 (and $x3187 (not (and $x3067 $x3202)))))
 (let (($x3208 (and $x3196 (not (and $x3075 $x3213)))))
 (let (($x3218 (and $x3208 (not (and $x3083 $x3224)))))
 (let (($x3230 (and $x3218 (not (and $x3091 $x3235)))))
 (let (($x3244 (and $x3230 (not (and $x3051 $x3246)))))
 (let (($x3242 (and $x3244 (not (and $x3059 $x3202)))))
 (let (($x3249 (and $x3242 (not (and $x3106 $x3213)))))
 (let (($x3261 (and $x3249 (not (and $x3067 $x3263)))))
 (let (($x3259 (and $x3261 (not (and $x3075 $x3224)))))
 (let (($x3266 (and $x3259 (not (and $x3120 $x3235)))))
 (let (($x3274 (and $x3266 (not (and $x3059 $x3280)))))
 (let (($x3277 (and $x3274 (not (and $x3106 $x3180)))))
 (let (($x3285 (and $x3277 (not (and $x3075 $x3246)))))
 (let (($x3275 (and $x3285 (not (and $x3120 $x3202)))))
 (let (($x3291 (and $x3275 (not (and $x3091 $x3263)))))
 (let (($x3286 (and $x3291 (not (and $x3143 $x3224)))))
 (let (($x3293 (and $x3286 (not (and $x3067 $x3280)))))
 (let (($x3296 (and $x3293 (not (and $x3075 $x3180)))))
 (let (($x3295 (and $x3296 (not (and $x3120 $x3191)))))
 (let (($x3306 (and $x3295 (not (and $x3083 $x3246)))))
 (let (($x3302 (and $x3306 (not (and $x3091 $x3202)))))
 (let (($x3310 (and $x3302 (not (and $x3143 $x3213)))))
 (let (($x3307 (and $x3310 $x3311)))
 (let (($x3317 (and $x3307 $x3316)))
 (let (($x3321 (and $x3317 $x3320)))
 (let (($x3325 (and $x3321 $x3324)))
 (let (($x3329 (and $x3325 $x3328)))
 (let (($x3333 (and $x3329 $x3332)))
 (let (($x3337 (and $x3333 $x3336)))
 (let (($x3340 (and $x3337 $x3339)))
 (let (($x3343 (and $x3340 $x3342)))
 (let (($x3347 (and $x3343 $x3346)))
 (let (($x3350 (and $x3347 $x3349)))
 (let (($x3353 (and $x3350 $x3352)))
 (let (($x3357 (and $x3353 $x3356)))
 (let (($x3360 (and $x3357 $x3359)))
 (let (($x3363 (and $x3360 $x3362)))
 (let (($x3366 (and $x3363 $x3365)))
 (let (($x3369 (and $x3366 $x3368)))
 (let (($x3372 (and $x3369 $x3371)))
 (let (($x3375 (and $x3372 $x3374)))
 (let (($x3378 (and $x3375 $x3377)))
 (let (($x3381 (and $x3378 $x3380)))
 (let (($x3384 (and $x3381 $x3383)))
 (let (($x3387 (and $x3384 $x3386)))
 (let (($x3390 (and $x3387 $x3389)))
 (let (($x3405 (and $x3390 (not (and (and true $x3409) $x3403)))))
 (let (($x3426 (and $x3405 (not (and (and true $x3428) $x3425)))))
 (let (($x3446 (and $x3426 (not (and (and true $x3447) $x3444)))))
 (let (($x3461 (and $x3446 (not (and (and true $x3466) $x3460)))))
 (let (($x3484 (and $x3461 (not (and (and true $x3485) $x3480)))))
 (let (($x3501 (and $x3484 (not (and (and true $x3504) $x3500)))))
 (let (($x3510 (and $x3501 (not (and (and true $x3409) $x3507)))))
 (let (($x3513 (and $x3510 (not (and (and true $x3428) $x3444)))))
 (let (($x3531 (and $x3513 (not (and (and true $x3532) $x3460)))))
 (let (($x3533 (and $x3531 (not (and (and true $x3447) $x3535)))))
 (let (($x3542 (and $x3533 (not (and (and true $x3466) $x3480)))))
 (let (($x3551 (and $x3542 (not (and (and true $x3557) $x3500)))))
 (let (($x3555 (and $x3551 (not (and (and true $x3428) $x3561)))))
 (let (($x3565 (and $x3555 (not (and (and true $x3532) $x3403)))))
 (let (($x3570 (and $x3565 (not (and (and true $x3466) $x3507)))))
 (let (($x3566 (and $x3570 (not (and (and true $x3557) $x3444)))))
 (let (($x3572 (and $x3566 (not (and (and true $x3504) $x3535)))))
 (let (($x3589 (and $x3572 (not (and (and true $x3591) $x3480)))))
 (let (($x3590 (and $x3589 (not (and (and true $x3447) $x3561)))))
 (let (($x3598 (and $x3590 (not (and (and true $x3466) $x3403)))))
 (let (($x3592 (and $x3598 (not (and (and true $x3557) $x3425)))))
 (let (($x3601 (and $x3592 (not (and (and true $x3485) $x3507)))))
 (let (($x3597 (and $x3601 (not (and (and true $x3504) $x3444)))))
 (let (($x3608 (and $x3597 (not (and (and true $x3591) $x3460)))))
 (let (($x3610 (and $x3608 (not (and (and true c_0_12) $x1847)))))
 (let (($x3614 (and $x3610 (not (and (and true c_1_12) $x1882)))))
 (let (($x3618 (and $x3614 (not (and (and true c_3_12) $x1952)))))
 (let (($x3622 (and $x3618 (not (and (and true c_4_12) $x1987)))))
 (let (($x3626 (and $x3622 (not (and (and true c_6_12) $x2057)))))
 (let (($x3630 (and $x3626 (not (and (and true c_7_12) $x2092)))))
 (let (($x3633 (and $x3630 (not (and (and true c_0_12) $x1917)))))
 (let (($x3636 (and $x3633 (not (and (and true c_1_12) $x1952)))))
 (let (($x3640 (and $x3636 (not (and (and true c_2_12) $x1987)))))
 (let (($x3643 (and $x3640 (not (and (and true c_3_12) $x2022)))))
 (let (($x3646 (and $x3643 (not (and (and true c_4_12) $x2057)))))
 (let (($x3650 (and $x3646 (not (and (and true c_5_12) $x2092)))))
 (let (($x3653 (and $x3650 (not (and (and true c_1_12) $x1812)))))
 (let (($x3656 (and $x3653 (not (and (and true c_2_12) $x1847)))))
 (let (($x3659 (and $x3656 (not (and (and true c_4_12) $x1917)))))
 (let (($x3662 (and $x3659 (not (and (and true c_5_12) $x1952)))))
 (let (($x3665 (and $x3662 (not (and (and true c_7_12) $x2022)))))
 (let (($x3669 (and $x3665 (not (and (and true c_8_12) $x2057)))))
 (let (($x3672 (and $x3669 (not (and (and true c_3_12) $x1812)))))
 (let (($x3675 (and $x3672 (not (and (and true c_4_12) $x1847)))))
 (let (($x3678 (and $x3675 (not (and (and true c_5_12) $x1882)))))
 (let (($x3681 (and $x3678 (not (and (and true c_6_12) $x1917)))))
 (let (($x3684 (and $x3681 (not (and (and true c_7_12) $x1952)))))
 (let (($x3687 (and $x3684 (not (and (and true c_8_12) $x1987)))))
 (let (($x3721 (and $x3687 $x3720)))
 (let (($x3756 (and $x3721 $x3755)))
 (let (($x3790 (and $x3756 $x3789)))
 (let (($x3827 (and $x3790 (not (and (and $x3791 $x3802) $x3824)))))
 (let (($x3857 (and $x3827 $x3856)))
 (let (($x3890 (and $x3857 $x3889)))
 (let (($x3898 (and $x3890 $x3899)))
 (let (($x3902 (and $x3898 $x3904)))
 (let (($x3926 (and $x3902 $x3925)))
 (let (($x3934 (and $x3926 $x3935)))
 (let (($x3937 (and $x3934 (not (and (and $x3791 $x3839) $x3824)))))
 (let (($x3964 (and $x3937 $x3963)))
 (let (($x3973 (and $x3964 $x3972)))
 (let (($x3978 (and $x3973 $x3975)))
 (let (($x3981 (and $x3978 (not (and (and $x3791 $x3900) $x3824)))))
 (let (($x3984 (and $x3981 $x3986)))
 (let (($x3989 (and $x3984 $x3990)))
 (let (($x4010 (and $x3989 $x4009)))
 (let (($x4015 (and $x4010 $x4014)))
 (let (($x4019 (and $x4015 (not (and $x4012 $x3824)))))
 (let (($x4020 (and $x4019 $x4021)))
 (let (($x4026 (and $x4020 $x4027)))
 (let (($x4029 (and $x4026 $x4031)))
 (let (($x4035 (and $x4029 $x4033)))
 (let (($x4044 (and $x4035 (not (and $x4040 $x3699)))))
 (let (($x4052 (and $x4044 (not (and $x4050 $x3733)))))
 (let (($x4064 (and $x4052 (not (and $x4060 $x3768)))))
 (let (($x4075 (and $x4064 (not (and $x4070 $x3802)))))
 (let (($x4082 (and $x4075 (not (and $x4080 $x3839)))))
 (let (($x4092 (and $x4082 (not (and $x4090 $x3869)))))
 (let (($x4097 (and $x4092 (not (and $x4040 $x3900)))))
 (let (($x4103 (and $x4097 (not (and $x4050 $x3768)))))
 (let (($x4108 (and $x4103 (not (and $x4106 $x3802)))))
 (let (($x4113 (and $x4108 (not (and $x4060 $x3936)))))
 (let (($x4118 (and $x4113 (not (and $x4070 $x3839)))))
 (let (($x4124 (and $x4118 (not (and $x4122 $x3869)))))
 (let (($x4129 (and $x4124 (not (and $x4050 $x3974)))))
 (let (($x4125 (and $x4129 (not (and $x4106 $x3699)))))
 (let (($x4136 (and $x4125 (not (and $x4070 $x3900)))))
 (let (($x4140 (and $x4136 (not (and $x4122 $x3768)))))
 (let (($x4143 (and $x4140 (not (and $x4090 $x3936)))))
 (let (($x4150 (and $x4143 (not (and $x4147 $x3839)))))
 (let (($x4155 (and $x4150 (not (and $x4060 $x3974)))))
 (let (($x4152 (and $x4155 (not (and $x4070 $x3699)))))
 (let (($x4156 (and $x4152 (not (and $x4122 $x3733)))))
 (let (($x4165 (and $x4156 (not (and $x4080 $x3900)))))
 (let (($x4168 (and $x4165 (not (and $x4090 $x3768)))))
 (let (($x4169 (and $x4168 (not (and $x4147 $x3802)))))
 (let (($x4274 (and $x4169 (and $x4277 $x4033))))
 (and $x4274 (and $x5165 $x5439))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
