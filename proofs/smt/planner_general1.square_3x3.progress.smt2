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
 (let (($x4541 (>= rank_18 0)))
 (and $x4541 (< rank_18 9))))
(assert
 (let (($x4546 (>= rank_20 0)))
 (and $x4546 (< rank_20 9))))
(assert
 (let (($x4551 (>= rank_22 0)))
 (and $x4551 (< rank_22 9))))
(assert
 (let (($x4556 (>= rank_24 0)))
 (and $x4556 (< rank_24 9))))
(assert
 (let (($x4561 (>= rank_26 0)))
 (and $x4561 (< rank_26 9))))
(assert
 (let (($x4566 (>= rank_28 0)))
 (and $x4566 (< rank_28 9))))
(assert
 (let (($x4571 (>= rank_30 0)))
 (and $x4571 (< rank_30 9))))
(assert
 (let (($x4576 (>= rank_32 0)))
 (and $x4576 (< rank_32 9))))
(assert
 (let (($x4581 (>= rank_34 0)))
 (and $x4581 (< rank_34 9))))
(assert
 (let (($x4796 (>= prank_36 0)))
 (and $x4796 (< prank_36 9))))
(assert
 (let (($x4805 (>= prank_37 0)))
 (and $x4805 (< prank_37 9))))
(assert
 (let (($x4809 (>= prank_38 0)))
 (and $x4809 (< prank_38 9))))
(assert
 (let (($x4813 (>= prank_39 0)))
 (and $x4813 (< prank_39 9))))
(assert
 (let (($x4817 (>= prank_40 0)))
 (and $x4817 (< prank_40 9))))
(assert
 (let (($x4821 (>= prank_41 0)))
 (and $x4821 (< prank_41 9))))
(assert
 (let (($x4825 (>= prank_42 0)))
 (and $x4825 (< prank_42 9))))
(assert
 (let (($x4829 (>= prank_43 0)))
 (and $x4829 (< prank_43 9))))
(assert
 (let (($x4833 (>= prank_44 0)))
 (and $x4833 (< prank_44 9))))
(assert
 (let (($x5133 (>= prank_47 0)))
 (and $x5133 (< prank_47 9))))
(assert
 (let (($x5134 (>= prank_48 0)))
 (and $x5134 (< prank_48 9))))
(assert
 (let (($x5142 (>= prank_49 0)))
 (and $x5142 (< prank_49 9))))
(assert
 (let (($x5146 (>= prank_50 0)))
 (and $x5146 (< prank_50 9))))
(assert
 (let (($x5150 (>= prank_51 0)))
 (and $x5150 (< prank_51 9))))
(assert
 (let (($x5154 (>= prank_52 0)))
 (and $x5154 (< prank_52 9))))
(assert
 (let (($x5158 (>= prank_53 0)))
 (and $x5158 (< prank_53 9))))
(assert
 (let (($x5162 (>= prank_54 0)))
 (and $x5162 (< prank_54 9))))
(assert
 (let (($x5166 (>= prank_55 0)))
 (and $x5166 (< prank_55 9))))
(assert
 (let (($x5479 (>= rank_58 0)))
 (and $x5479 (< rank_58 9))))
(assert
 (let (($x5480 (>= rank_60 0)))
 (and $x5480 (< rank_60 9))))
(assert
 (let (($x5487 (>= rank_62 0)))
 (and $x5487 (< rank_62 9))))
(assert
 (let (($x5492 (>= rank_64 0)))
 (and $x5492 (< rank_64 9))))
(assert
 (let (($x5497 (>= rank_66 0)))
 (and $x5497 (< rank_66 9))))
(assert
 (let (($x5502 (>= rank_68 0)))
 (and $x5502 (< rank_68 9))))
(assert
 (let (($x5507 (>= rank_70 0)))
 (and $x5507 (< rank_70 9))))
(assert
 (let (($x5512 (>= rank_72 0)))
 (and $x5512 (< rank_72 9))))
(assert
 (let (($x5517 (>= rank_74 0)))
 (and $x5517 (< rank_74 9))))
(assert
 (let ((?x5668 (ite root_75 1 0)))
 (let ((?x5649 (ite root_73 1 0)))
 (let ((?x5633 (ite root_71 1 0)))
 (let ((?x5614 (ite root_69 1 0)))
 (let ((?x5592 (ite root_67 1 0)))
 (let ((?x5573 (ite root_65 1 0)))
 (let ((?x5557 (ite root_63 1 0)))
 (let ((?x5538 (ite root_61 1 0)))
 (let ((?x5522 (ite root_59 1 0)))
 (let ((?x5523 (+ 0 ?x5522)))
 (let ((?x5539 (+ ?x5523 ?x5538)))
 (let ((?x5558 (+ ?x5539 ?x5557)))
 (let ((?x5574 (+ ?x5558 ?x5573)))
 (let ((?x5593 (+ ?x5574 ?x5592)))
 (let ((?x5615 (+ ?x5593 ?x5614)))
 (let ((?x5634 (+ ?x5615 ?x5633)))
 (let ((?x5650 (+ ?x5634 ?x5649)))
 (let (($x5521 (or false root_59)))
 (let (($x5537 (or $x5521 root_61)))
 (let (($x5556 (or $x5537 root_63)))
 (let (($x5572 (or $x5556 root_65)))
 (let (($x5591 (or $x5572 root_67)))
 (let (($x5613 (or $x5591 root_69)))
 (let (($x5632 (or $x5613 root_71)))
 (let (($x5648 (or $x5632 root_73)))
 (let (($x5485 (or c_8_1 c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_7 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x5478 (or c_7_1 c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_7 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x5471 (or c_6_1 c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_7 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x5464 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x5457 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x5450 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x5443 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x5436 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x5429 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x5520 (or false $x5429)))
 (let (($x5536 (or $x5520 $x5436)))
 (let (($x5555 (or $x5536 $x5443)))
 (let (($x5571 (or $x5555 $x5450)))
 (let (($x5590 (or $x5571 $x5457)))
 (let (($x5612 (or $x5590 $x5464)))
 (let (($x5631 (or $x5612 $x5471)))
 (let (($x5647 (or $x5631 $x5478)))
 (let (($x5674 (or false (and $x5478 (< rank_72 rank_74)))))
 (let (($x5678 (not root_75)))
 (let (($x5679 (and $x5485 $x5678)))
 (let (($x5655 (or false (and $x5485 (< rank_74 rank_72)))))
 (let (($x5658 (or $x5655 (and $x5471 (< rank_70 rank_72)))))
 (let (($x5662 (not root_73)))
 (let (($x5663 (and $x5478 $x5662)))
 (let (($x5639 (or false (and $x5478 (< rank_72 rank_70)))))
 (let (($x5643 (not root_71)))
 (let (($x5644 (and $x5471 $x5643)))
 (let (($x5620 (or false (and $x5485 (< rank_74 rank_68)))))
 (let (($x5623 (or $x5620 (and $x5457 (< rank_66 rank_68)))))
 (let (($x5627 (not root_69)))
 (let (($x5628 (and $x5464 $x5627)))
 (let (($x5598 (or false (and $x5464 (< rank_68 rank_66)))))
 (let (($x5601 (or $x5598 (and $x5478 (< rank_72 rank_66)))))
 (let (($x5604 (or $x5601 (and $x5450 (< rank_64 rank_66)))))
 (let (($x5608 (not root_67)))
 (let (($x5609 (and $x5457 $x5608)))
 (let (($x5579 (or false (and $x5457 (< rank_66 rank_64)))))
 (let (($x5582 (or $x5579 (and $x5471 (< rank_70 rank_64)))))
 (let (($x5586 (not root_65)))
 (let (($x5587 (and $x5450 $x5586)))
 (let (($x5563 (or false (and $x5464 (< rank_68 rank_62)))))
 (let (($x5567 (not root_63)))
 (let (($x5568 (and $x5443 $x5567)))
 (let (($x5544 (or false (and $x5443 (< rank_62 rank_60)))))
 (let (($x5547 (or $x5544 (and $x5457 (< rank_66 rank_60)))))
 (let (($x5551 (not root_61)))
 (let (($x5552 (and $x5436 $x5551)))
 (let (($x5528 (or false (and $x5436 (< rank_60 rank_58)))))
 (let (($x5532 (not root_59)))
 (let (($x5533 (and $x5429 $x5532)))
 (let (($x5525 (and true (=> root_59 $x5429))))
 (let (($x5535 (and $x5525 (=> $x5533 (or $x5528 (and $x5450 (< rank_64 rank_58)))))))
 (let (($x5541 (and $x5535 (=> root_61 $x5436))))
 (let (($x5554 (and $x5541 (=> $x5552 (or $x5547 (and $x5429 (< rank_58 rank_60)))))))
 (let (($x5560 (and $x5554 (=> root_63 $x5443))))
 (let (($x5570 (and $x5560 (=> $x5568 (or $x5563 (and $x5436 (< rank_60 rank_62)))))))
 (let (($x5576 (and $x5570 (=> root_65 $x5450))))
 (let (($x5589 (and $x5576 (=> $x5587 (or $x5582 (and $x5429 (< rank_58 rank_64)))))))
 (let (($x5595 (and $x5589 (=> root_67 $x5457))))
 (let (($x5611 (and $x5595 (=> $x5609 (or $x5604 (and $x5436 (< rank_60 rank_66)))))))
 (let (($x5617 (and $x5611 (=> root_69 $x5464))))
 (let (($x5630 (and $x5617 (=> $x5628 (or $x5623 (and $x5443 (< rank_62 rank_68)))))))
 (let (($x5636 (and $x5630 (=> root_71 $x5471))))
 (let (($x5646 (and $x5636 (=> $x5644 (or $x5639 (and $x5450 (< rank_64 rank_70)))))))
 (let (($x5652 (and $x5646 (=> root_73 $x5478))))
 (let (($x5665 (and $x5652 (=> $x5663 (or $x5658 (and $x5457 (< rank_66 rank_72)))))))
 (let (($x5671 (and $x5665 (=> root_75 $x5485))))
 (let (($x5683 (and (and $x5671 (=> $x5679 (or $x5674 (and $x5464 (< rank_68 rank_74))))) (=> (or $x5647 $x5485) (or $x5648 root_75)))))
 (let (($x5685 (and $x5683 (<= (+ ?x5650 ?x5668) 1))))
 (let (($x3746 (or c_8_1 c_8_7)))
 (let (($x5406 (and $x3746 (= prank_55 prank_high_57))))
 (let (($x3726 (or c_7_1 c_7_7)))
 (let (($x5383 (and $x3726 (= prank_54 prank_high_57))))
 (let (($x3781 (or c_6_1 c_6_7)))
 (let (($x5355 (and $x3781 (= prank_53 prank_high_57))))
 (let (($x3706 (or c_5_1 c_5_7)))
 (let (($x5332 (and $x3706 (= prank_52 prank_high_57))))
 (let (($x3690 (or c_4_1 c_4_7)))
 (let (($x5304 (and $x3690 (= prank_51 prank_high_57))))
 (let (($x3753 (or c_3_1 c_3_7)))
 (let (($x5271 (and $x3753 (= prank_50 prank_high_57))))
 (let (($x3671 (or c_2_1 c_2_7)))
 (let (($x5243 (and $x3671 (= prank_49 prank_high_57))))
 (let (($x3649 (or c_1_1 c_1_7)))
 (let (($x5220 (and $x3649 (= prank_48 prank_high_57))))
 (let (($x3807 (or c_0_1 c_0_7)))
 (let (($x5192 (and $x3807 (= prank_47 prank_high_57))))
 (let (($x5193 (or false $x5192)))
 (let (($x5221 (or $x5193 $x5220)))
 (let (($x5244 (or $x5221 $x5243)))
 (let (($x5272 (or $x5244 $x5271)))
 (let (($x5305 (or $x5272 $x5304)))
 (let (($x5333 (or $x5305 $x5332)))
 (let (($x5356 (or $x5333 $x5355)))
 (let (($x5384 (or $x5356 $x5383)))
 (let (($x5403 (and $x3746 (= prank_55 prank_low_56))))
 (let (($x5380 (and $x3726 (= prank_54 prank_low_56))))
 (let (($x5352 (and $x3781 (= prank_53 prank_low_56))))
 (let (($x5329 (and $x3706 (= prank_52 prank_low_56))))
 (let (($x5301 (and $x3690 (= prank_51 prank_low_56))))
 (let (($x5268 (and $x3753 (= prank_50 prank_low_56))))
 (let (($x5240 (and $x3671 (= prank_49 prank_low_56))))
 (let (($x5217 (and $x3649 (= prank_48 prank_low_56))))
 (let (($x5189 (and $x3807 (= prank_47 prank_low_56))))
 (let (($x5190 (or false $x5189)))
 (let (($x5218 (or $x5190 $x5217)))
 (let (($x5241 (or $x5218 $x5240)))
 (let (($x5269 (or $x5241 $x5268)))
 (let (($x5302 (or $x5269 $x5301)))
 (let (($x5330 (or $x5302 $x5329)))
 (let (($x5353 (or $x5330 $x5352)))
 (let (($x5381 (or $x5353 $x5380)))
 (let (($x5187 (or false $x3807)))
 (let (($x5215 (or $x5187 $x3649)))
 (let (($x5238 (or $x5215 $x3671)))
 (let (($x5266 (or $x5238 $x3753)))
 (let (($x5299 (or $x5266 $x3690)))
 (let (($x5327 (or $x5299 $x3706)))
 (let (($x5350 (or $x5327 $x3781)))
 (let (($x5378 (or $x5350 $x3726)))
 (let (($x5123 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x5135 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x5389 (or false (and true (or $x5135 (and $x3726 (< prank_54 prank_55)))))))
 (let (($x5396 (and (or $x5389 (and true (or $x5123 (and $x3706 (< prank_52 prank_55))))) (<= prank_low_56 prank_55))))
 (let (($x5117 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x5129 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x5141 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x5361 (or false (and true (or $x5141 (and $x3746 (< prank_55 prank_54)))))))
 (let (($x5366 (or $x5361 (and true (or $x5129 (and $x3781 (< prank_53 prank_54)))))))
 (let (($x5373 (and (or $x5366 (and true (or $x5117 (and $x3690 (< prank_51 prank_54))))) (<= prank_low_56 prank_54))))
 (let (($x5111 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x5338 (or false (and true (or $x5135 (and $x3726 (< prank_54 prank_53)))))))
 (let (($x5345 (and (or $x5338 (and true (or $x5111 (and $x3753 (< prank_50 prank_53))))) (<= prank_low_56 prank_53))))
 (let (($x5105 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x5310 (or false (and true (or $x5141 (and $x3746 (< prank_55 prank_52)))))))
 (let (($x5315 (or $x5310 (and true (or $x5117 (and $x3690 (< prank_51 prank_52)))))))
 (let (($x5322 (and (or $x5315 (and true (or $x5105 (and $x3671 (< prank_49 prank_52))))) (<= prank_low_56 prank_52))))
 (let (($x5099 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x5277 (or false (and true (or $x5123 (and $x3706 (< prank_52 prank_51)))))))
 (let (($x5282 (or $x5277 (and true (or $x5135 (and $x3726 (< prank_54 prank_51)))))))
 (let (($x5287 (or $x5282 (and true (or $x5111 (and $x3753 (< prank_50 prank_51)))))))
 (let (($x5294 (and (or $x5287 (and true (or $x5099 (and $x3649 (< prank_48 prank_51))))) (<= prank_low_56 prank_51))))
 (let (($x5093 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x5249 (or false (and true (or $x5117 (and $x3690 (< prank_51 prank_50)))))))
 (let (($x5254 (or $x5249 (and true (or $x5129 (and $x3781 (< prank_53 prank_50)))))))
 (let (($x5261 (and (or $x5254 (and true (or $x5093 (and $x3807 (< prank_47 prank_50))))) (<= prank_low_56 prank_50))))
 (let (($x5226 (or false (and true (or $x5123 (and $x3706 (< prank_52 prank_49)))))))
 (let (($x5233 (and (or $x5226 (and true (or $x5099 (and $x3649 (< prank_48 prank_49))))) (<= prank_low_56 prank_49))))
 (let (($x5198 (or false (and true (or $x5105 (and $x3671 (< prank_49 prank_48)))))))
 (let (($x5203 (or $x5198 (and true (or $x5117 (and $x3690 (< prank_51 prank_48)))))))
 (let (($x5210 (and (or $x5203 (and true (or $x5093 (and $x3807 (< prank_47 prank_48))))) (<= prank_low_56 prank_48))))
 (let (($x5175 (or false (and true (or $x5099 (and $x3649 (< prank_48 prank_47)))))))
 (let (($x5182 (and (or $x5175 (and true (or $x5111 (and $x3753 (< prank_50 prank_47))))) (<= prank_low_56 prank_47))))
 (let (($x5186 (and true (=> $x3807 (and $x5182 (<= prank_47 prank_high_57))))))
 (let (($x5214 (and $x5186 (=> $x3649 (and $x5210 (<= prank_48 prank_high_57))))))
 (let (($x5237 (and $x5214 (=> $x3671 (and $x5233 (<= prank_49 prank_high_57))))))
 (let (($x5265 (and $x5237 (=> $x3753 (and $x5261 (<= prank_50 prank_high_57))))))
 (let (($x5298 (and $x5265 (=> $x3690 (and $x5294 (<= prank_51 prank_high_57))))))
 (let (($x5326 (and $x5298 (=> $x3706 (and $x5322 (<= prank_52 prank_high_57))))))
 (let (($x5349 (and $x5326 (=> $x3781 (and $x5345 (<= prank_53 prank_high_57))))))
 (let (($x5377 (and $x5349 (=> $x3726 (and $x5373 (<= prank_54 prank_high_57))))))
 (let (($x5400 (and $x5377 (=> $x3746 (and $x5396 (<= prank_55 prank_high_57))))))
 (let (($x5410 (and $x5400 (=> (or $x5378 $x3746) (and (or $x5381 $x5403) (or $x5384 $x5406))))))
 (let (($x3837 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_8 c_8_9 c_8_10 c_8_11)))
 (let (($x5073 (and $x3837 (= prank_44 prank_high_46))))
 (let (($x3750 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_8 c_7_9 c_7_10 c_7_11)))
 (let (($x5050 (and $x3750 (= prank_43 prank_high_46))))
 (let (($x3731 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_8 c_6_9 c_6_10 c_6_11)))
 (let (($x5022 (and $x3731 (= prank_42 prank_high_46))))
 (let (($x3803 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_8 c_5_9 c_5_10 c_5_11)))
 (let (($x4999 (and $x3803 (= prank_41 prank_high_46))))
 (let (($x3712 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_8 c_4_9 c_4_10 c_4_11)))
 (let (($x4971 (and $x3712 (= prank_40 prank_high_46))))
 (let (($x3693 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_8 c_3_9 c_3_10 c_3_11)))
 (let (($x4938 (and $x3693 (= prank_39 prank_high_46))))
 (let (($x3778 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_8 c_2_9 c_2_10 c_2_11)))
 (let (($x4910 (and $x3778 (= prank_38 prank_high_46))))
 (let (($x3674 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_8 c_1_9 c_1_10 c_1_11)))
 (let (($x4887 (and $x3674 (= prank_37 prank_high_46))))
 (let (($x3655 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_8 c_0_9 c_0_10 c_0_11)))
 (let (($x4859 (and $x3655 (= prank_36 prank_high_46))))
 (let (($x4860 (or false $x4859)))
 (let (($x4888 (or $x4860 $x4887)))
 (let (($x4911 (or $x4888 $x4910)))
 (let (($x4939 (or $x4911 $x4938)))
 (let (($x4972 (or $x4939 $x4971)))
 (let (($x5000 (or $x4972 $x4999)))
 (let (($x5023 (or $x5000 $x5022)))
 (let (($x5051 (or $x5023 $x5050)))
 (let (($x5070 (and $x3837 (= prank_44 prank_low_45))))
 (let (($x5047 (and $x3750 (= prank_43 prank_low_45))))
 (let (($x5019 (and $x3731 (= prank_42 prank_low_45))))
 (let (($x4996 (and $x3803 (= prank_41 prank_low_45))))
 (let (($x4968 (and $x3712 (= prank_40 prank_low_45))))
 (let (($x4935 (and $x3693 (= prank_39 prank_low_45))))
 (let (($x4907 (and $x3778 (= prank_38 prank_low_45))))
 (let (($x4884 (and $x3674 (= prank_37 prank_low_45))))
 (let (($x4856 (and $x3655 (= prank_36 prank_low_45))))
 (let (($x4857 (or false $x4856)))
 (let (($x4885 (or $x4857 $x4884)))
 (let (($x4908 (or $x4885 $x4907)))
 (let (($x4936 (or $x4908 $x4935)))
 (let (($x4969 (or $x4936 $x4968)))
 (let (($x4997 (or $x4969 $x4996)))
 (let (($x5020 (or $x4997 $x5019)))
 (let (($x5048 (or $x5020 $x5047)))
 (let (($x4854 (or false $x3655)))
 (let (($x4882 (or $x4854 $x3674)))
 (let (($x4905 (or $x4882 $x3778)))
 (let (($x4933 (or $x4905 $x3693)))
 (let (($x4966 (or $x4933 $x3712)))
 (let (($x4994 (or $x4966 $x3803)))
 (let (($x5017 (or $x4994 $x3731)))
 (let (($x5045 (or $x5017 $x3750)))
 (let (($x4196 (or c_8_5 c_8_11)))
 (let (($x5060 (and $x4196 (or (or c_5_6 c_5_12) (and $x3803 (< prank_41 prank_44))))))
 (let (($x4121 (or c_8_4 c_8_10)))
 (let (($x5055 (and $x4121 (or (or c_7_6 c_7_12) (and $x3750 (< prank_43 prank_44))))))
 (let (($x5056 (or false $x5055)))
 (let (($x5065 (and (and (or $x5056 $x5060) (<= prank_low_45 prank_44)) (<= prank_44 prank_high_46))))
 (let (($x4057 (or c_7_5 c_7_11)))
 (let (($x5037 (and $x4057 (or (or c_4_6 c_4_12) (and $x3712 (< prank_40 prank_43))))))
 (let (($x4090 (or c_7_4 c_7_10)))
 (let (($x5032 (and $x4090 (or (or c_6_6 c_6_12) (and $x3731 (< prank_42 prank_43))))))
 (let (($x4245 (or c_7_2 c_7_8)))
 (let (($x5027 (and $x4245 (or (or c_8_6 c_8_12) (and $x3837 (< prank_44 prank_43))))))
 (let (($x5028 (or false $x5027)))
 (let (($x5033 (or $x5028 $x5032)))
 (let (($x5042 (and (and (or $x5033 $x5037) (<= prank_low_45 prank_43)) (<= prank_43 prank_high_46))))
 (let (($x4022 (or c_6_5 c_6_11)))
 (let (($x5009 (and $x4022 (or (or c_3_6 c_3_12) (and $x3693 (< prank_39 prank_42))))))
 (let (($x4122 (or c_6_2 c_6_8)))
 (let (($x5004 (and $x4122 (or (or c_7_6 c_7_12) (and $x3750 (< prank_43 prank_42))))))
 (let (($x5005 (or false $x5004)))
 (let (($x5014 (and (and (or $x5005 $x5009) (<= prank_low_45 prank_42)) (<= prank_42 prank_high_46))))
 (let (($x4161 (or c_5_5 c_5_11)))
 (let (($x4986 (and $x4161 (or (or c_2_6 c_2_12) (and $x3778 (< prank_38 prank_41))))))
 (let (($x4055 (or c_5_4 c_5_10)))
 (let (($x4981 (and $x4055 (or (or c_4_6 c_4_12) (and $x3712 (< prank_40 prank_41))))))
 (let (($x4247 (or c_5_3 c_5_9)))
 (let (($x4976 (and $x4247 (or (or c_8_6 c_8_12) (and $x3837 (< prank_44 prank_41))))))
 (let (($x4977 (or false $x4976)))
 (let (($x4982 (or $x4977 $x4981)))
 (let (($x4991 (and (and (or $x4982 $x4986) (<= prank_low_45 prank_41)) (<= prank_41 prank_high_46))))
 (let (($x3989 (or c_4_5 c_4_11)))
 (let (($x4958 (and $x3989 (or (or c_1_6 c_1_12) (and $x3674 (< prank_37 prank_40))))))
 (let (($x4020 (or c_4_4 c_4_10)))
 (let (($x4953 (and $x4020 (or (or c_3_6 c_3_12) (and $x3693 (< prank_39 prank_40))))))
 (let (($x4124 (or c_4_3 c_4_9)))
 (let (($x4948 (and $x4124 (or (or c_7_6 c_7_12) (and $x3750 (< prank_43 prank_40))))))
 (let (($x4197 (or c_4_2 c_4_8)))
 (let (($x4943 (and $x4197 (or (or c_5_6 c_5_12) (and $x3803 (< prank_41 prank_40))))))
 (let (($x4944 (or false $x4943)))
 (let (($x4949 (or $x4944 $x4948)))
 (let (($x4954 (or $x4949 $x4953)))
 (let (($x4963 (and (and (or $x4954 $x4958) (<= prank_low_45 prank_40)) (<= prank_40 prank_high_46))))
 (let (($x3956 (or c_3_5 c_3_11)))
 (let (($x4925 (and $x3956 (or (or c_0_6 c_0_12) (and $x3655 (< prank_36 prank_39))))))
 (let (($x4092 (or c_3_3 c_3_9)))
 (let (($x4920 (and $x4092 (or (or c_6_6 c_6_12) (and $x3731 (< prank_42 prank_39))))))
 (let (($x4058 (or c_3_2 c_3_8)))
 (let (($x4915 (and $x4058 (or (or c_4_6 c_4_12) (and $x3712 (< prank_40 prank_39))))))
 (let (($x4916 (or false $x4915)))
 (let (($x4921 (or $x4916 $x4920)))
 (let (($x4930 (and (and (or $x4921 $x4925) (<= prank_low_45 prank_39)) (<= prank_39 prank_high_46))))
 (let (($x3987 (or c_2_4 c_2_10)))
 (let (($x4897 (and $x3987 (or (or c_1_6 c_1_12) (and $x3674 (< prank_37 prank_38))))))
 (let (($x4199 (or c_2_3 c_2_9)))
 (let (($x4892 (and $x4199 (or (or c_5_6 c_5_12) (and $x3803 (< prank_41 prank_38))))))
 (let (($x4893 (or false $x4892)))
 (let (($x4902 (and (and (or $x4893 $x4897) (<= prank_low_45 prank_38)) (<= prank_38 prank_high_46))))
 (let (($x3954 (or c_1_4 c_1_10)))
 (let (($x4874 (and $x3954 (or (or c_0_6 c_0_12) (and $x3655 (< prank_36 prank_37))))))
 (let (($x4060 (or c_1_3 c_1_9)))
 (let (($x4869 (and $x4060 (or (or c_4_6 c_4_12) (and $x3712 (< prank_40 prank_37))))))
 (let (($x4162 (or c_1_2 c_1_8)))
 (let (($x4864 (and $x4162 (or (or c_2_6 c_2_12) (and $x3778 (< prank_38 prank_37))))))
 (let (($x4865 (or false $x4864)))
 (let (($x4870 (or $x4865 $x4869)))
 (let (($x4879 (and (and (or $x4870 $x4874) (<= prank_low_45 prank_37)) (<= prank_37 prank_high_46))))
 (let (($x4024 (or c_0_3 c_0_9)))
 (let (($x4846 (and $x4024 (or (or c_3_6 c_3_12) (and $x3693 (< prank_39 prank_36))))))
 (let (($x3990 (or c_0_2 c_0_8)))
 (let (($x4841 (and $x3990 (or (or c_1_6 c_1_12) (and $x3674 (< prank_37 prank_36))))))
 (let (($x4842 (or false $x4841)))
 (let (($x4851 (and (and (or $x4842 $x4846) (<= prank_low_45 prank_36)) (<= prank_36 prank_high_46))))
 (let (($x4853 (and true (=> $x3655 $x4851))))
 (let (($x4881 (and $x4853 (=> $x3674 $x4879))))
 (let (($x4904 (and $x4881 (=> $x3778 $x4902))))
 (let (($x4932 (and $x4904 (=> $x3693 $x4930))))
 (let (($x4965 (and $x4932 (=> $x3712 $x4963))))
 (let (($x4993 (and $x4965 (=> $x3803 $x4991))))
 (let (($x5016 (and $x4993 (=> $x3731 $x5014))))
 (let (($x5044 (and $x5016 (=> $x3750 $x5042))))
 (let (($x5067 (and $x5044 (=> $x3837 $x5065))))
 (let (($x5077 (and $x5067 (=> (or $x5045 $x3837) (and (or $x5048 $x5070) (or $x5051 $x5073))))))
 (let (($x1770 (not in_target_8)))
 (let (($x2831 (and c_8_12 $x1770)))
 (let (($x2812 (and c_8_6 $x1770)))
 (let (($x1755 (not in_target_7)))
 (let (($x2773 (and c_7_12 $x1755)))
 (let (($x2754 (and c_7_6 $x1755)))
 (let (($x4773 (or $x2754 $x2773)))
 (let (($x1740 (not in_target_6)))
 (let (($x2715 (and c_6_12 $x1740)))
 (let (($x2696 (and c_6_6 $x1740)))
 (let (($x4769 (or $x2696 $x2715)))
 (let (($x1725 (not in_target_5)))
 (let (($x2657 (and c_5_12 $x1725)))
 (let (($x2638 (and c_5_6 $x1725)))
 (let (($x4765 (or $x2638 $x2657)))
 (let (($x1710 (not in_target_4)))
 (let (($x2599 (and c_4_12 $x1710)))
 (let (($x2580 (and c_4_6 $x1710)))
 (let (($x4761 (or $x2580 $x2599)))
 (let (($x1695 (not in_target_3)))
 (let (($x2541 (and c_3_12 $x1695)))
 (let (($x2522 (and c_3_6 $x1695)))
 (let (($x4757 (or $x2522 $x2541)))
 (let (($x1680 (not in_target_2)))
 (let (($x2483 (and c_2_12 $x1680)))
 (let (($x2464 (and c_2_6 $x1680)))
 (let (($x4753 (or $x2464 $x2483)))
 (let (($x1665 (not in_target_1)))
 (let (($x2425 (and c_1_12 $x1665)))
 (let (($x2406 (and c_1_6 $x1665)))
 (let (($x4749 (or $x2406 $x2425)))
 (let (($x1652 (not in_target_0)))
 (let (($x2367 (and c_0_12 $x1652)))
 (let (($x2347 (and c_0_6 $x1652)))
 (let (($x4745 (or $x2347 $x2367)))
 (let (($x4743 (or false $x4745)))
 (let (($x4747 (or $x4743 $x4749)))
 (let (($x4751 (or $x4747 $x4753)))
 (let (($x4755 (or $x4751 $x4757)))
 (let (($x4759 (or $x4755 $x4761)))
 (let (($x4763 (or $x4759 $x4765)))
 (let (($x4767 (or $x4763 $x4769)))
 (let (($x4771 (or $x4767 $x4773)))
 (let ((?x4723 (ite root_35 1 0)))
 (let ((?x4705 (ite root_33 1 0)))
 (let ((?x4690 (ite root_31 1 0)))
 (let ((?x4672 (ite root_29 1 0)))
 (let ((?x4651 (ite root_27 1 0)))
 (let ((?x4633 (ite root_25 1 0)))
 (let ((?x4618 (ite root_23 1 0)))
 (let ((?x4600 (ite root_21 1 0)))
 (let ((?x4585 (ite root_19 1 0)))
 (let ((?x4586 (+ 0 ?x4585)))
 (let ((?x4601 (+ ?x4586 ?x4600)))
 (let ((?x4619 (+ ?x4601 ?x4618)))
 (let ((?x4634 (+ ?x4619 ?x4633)))
 (let ((?x4652 (+ ?x4634 ?x4651)))
 (let ((?x4673 (+ ?x4652 ?x4672)))
 (let ((?x4691 (+ ?x4673 ?x4690)))
 (let ((?x4706 (+ ?x4691 ?x4705)))
 (let (($x4584 (or false root_19)))
 (let (($x4599 (or $x4584 root_21)))
 (let (($x4617 (or $x4599 root_23)))
 (let (($x4632 (or $x4617 root_25)))
 (let (($x4650 (or $x4632 root_27)))
 (let (($x4671 (or $x4650 root_29)))
 (let (($x4689 (or $x4671 root_31)))
 (let (($x4704 (or $x4689 root_33)))
 (let (($x3391 (or c_8_6 c_8_12)))
 (let (($x3339 (or c_7_6 c_7_12)))
 (let (($x3331 (or c_6_6 c_6_12)))
 (let (($x3368 (or c_5_6 c_5_12)))
 (let (($x3323 (or c_4_6 c_4_12)))
 (let (($x3315 (or c_3_6 c_3_12)))
 (let (($x3354 (or c_2_6 c_2_12)))
 (let (($x3307 (or c_1_6 c_1_12)))
 (let (($x3299 (or c_0_6 c_0_12)))
 (let (($x4522 (or false $x3299)))
 (let (($x4525 (or $x4522 $x3307)))
 (let (($x4526 (or $x4525 $x3354)))
 (let (($x4528 (or $x4526 $x3315)))
 (let (($x4530 (or $x4528 $x3323)))
 (let (($x4532 (or $x4530 $x3368)))
 (let (($x4534 (or $x4532 $x3331)))
 (let (($x4536 (or $x4534 $x3339)))
 (let (($x4538 (or $x4536 $x3391)))
 (let (($x4729 (or false (and $x3339 (< rank_32 rank_34)))))
 (let (($x4733 (not root_35)))
 (let (($x4734 (and $x3391 $x4733)))
 (let (($x4711 (or false (and $x3391 (< rank_34 rank_32)))))
 (let (($x4714 (or $x4711 (and $x3331 (< rank_30 rank_32)))))
 (let (($x4718 (not root_33)))
 (let (($x4719 (and $x3339 $x4718)))
 (let (($x4696 (or false (and $x3339 (< rank_32 rank_30)))))
 (let (($x4700 (not root_31)))
 (let (($x4701 (and $x3331 $x4700)))
 (let (($x4678 (or false (and $x3391 (< rank_34 rank_28)))))
 (let (($x4681 (or $x4678 (and $x3323 (< rank_26 rank_28)))))
 (let (($x4685 (not root_29)))
 (let (($x4686 (and $x3368 $x4685)))
 (let (($x4657 (or false (and $x3368 (< rank_28 rank_26)))))
 (let (($x4660 (or $x4657 (and $x3339 (< rank_32 rank_26)))))
 (let (($x4663 (or $x4660 (and $x3315 (< rank_24 rank_26)))))
 (let (($x4667 (not root_27)))
 (let (($x4668 (and $x3323 $x4667)))
 (let (($x4639 (or false (and $x3323 (< rank_26 rank_24)))))
 (let (($x4642 (or $x4639 (and $x3331 (< rank_30 rank_24)))))
 (let (($x4646 (not root_25)))
 (let (($x4647 (and $x3315 $x4646)))
 (let (($x4624 (or false (and $x3368 (< rank_28 rank_22)))))
 (let (($x4628 (not root_23)))
 (let (($x4629 (and $x3354 $x4628)))
 (let (($x4606 (or false (and $x3354 (< rank_22 rank_20)))))
 (let (($x4609 (or $x4606 (and $x3323 (< rank_26 rank_20)))))
 (let (($x4613 (not root_21)))
 (let (($x4614 (and $x3307 $x4613)))
 (let (($x4591 (or false (and $x3307 (< rank_20 rank_18)))))
 (let (($x4595 (not root_19)))
 (let (($x4596 (and $x3299 $x4595)))
 (let (($x4588 (and true (=> root_19 $x3299))))
 (let (($x4598 (and $x4588 (=> $x4596 (or $x4591 (and $x3315 (< rank_24 rank_18)))))))
 (let (($x4603 (and $x4598 (=> root_21 $x3307))))
 (let (($x4616 (and $x4603 (=> $x4614 (or $x4609 (and $x3299 (< rank_18 rank_20)))))))
 (let (($x4621 (and $x4616 (=> root_23 $x3354))))
 (let (($x4631 (and $x4621 (=> $x4629 (or $x4624 (and $x3307 (< rank_20 rank_22)))))))
 (let (($x4636 (and $x4631 (=> root_25 $x3315))))
 (let (($x4649 (and $x4636 (=> $x4647 (or $x4642 (and $x3299 (< rank_18 rank_24)))))))
 (let (($x4654 (and $x4649 (=> root_27 $x3323))))
 (let (($x4670 (and $x4654 (=> $x4668 (or $x4663 (and $x3307 (< rank_20 rank_26)))))))
 (let (($x4675 (and $x4670 (=> root_29 $x3368))))
 (let (($x4688 (and $x4675 (=> $x4686 (or $x4681 (and $x3354 (< rank_22 rank_28)))))))
 (let (($x4693 (and $x4688 (=> root_31 $x3331))))
 (let (($x4703 (and $x4693 (=> $x4701 (or $x4696 (and $x3315 (< rank_24 rank_30)))))))
 (let (($x4708 (and $x4703 (=> root_33 $x3339))))
 (let (($x4721 (and $x4708 (=> $x4719 (or $x4714 (and $x3323 (< rank_26 rank_32)))))))
 (let (($x4726 (and $x4721 (=> root_35 $x3391))))
 (let (($x4738 (and (and $x4726 (=> $x4734 (or $x4729 (and $x3368 (< rank_28 rank_34))))) (=> $x4538 (or $x4704 root_35)))))
 (let (($x4740 (and $x4738 (<= (+ ?x4706 ?x4723) 1))))
 (let (($x5411 (and (and (and (and $x4538 $x4740) (not (or $x4771 (or $x2812 $x2831)))) $x5077) $x5410)))
 (let ((?x4249 (ite $x4247 1 0)))
 (let ((?x4246 (ite $x4245 1 0)))
 (let ((?x3946 (ite false 1 0)))
 (let ((?x4153 (+ 0 ?x3946)))
 (let ((?x4241 (+ ?x4153 ?x3946)))
 (let ((?x4248 (+ ?x4241 ?x4246)))
 (let (($x4243 (= (to_real (+ (+ ?x4241 (ite $x3726 1 0)) (ite $x3706 1 0))) 0.0)))
 (let (($x4253 (and $x4243 (= (to_real (+ ?x4248 ?x4249)) 0.0))))
 (let (($x4048 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6)))
 (let (($x4238 (or c_8_2 c_8_3 c_8_4 c_8_5)))
 (let (($x4237 (and true $x4238)))
 (let (($x4278 (and $x4237 $x4048)))
 (let (($x4279 (not (and $x4278 $x4253))))
 (let ((?x4129 (ite $x4124 1 0)))
 (let ((?x4127 (ite $x4122 1 0)))
 (let ((?x4123 (ite $x4121 1 0)))
 (let ((?x4125 (+ 0 ?x4123)))
 (let ((?x4126 (+ ?x4125 ?x3946)))
 (let ((?x4128 (+ ?x4126 ?x4127)))
 (let ((?x3975 (ite $x3690 1 0)))
 (let ((?x4013 (ite $x3781 1 0)))
 (let ((?x4114 (ite $x3746 1 0)))
 (let ((?x4111 (+ 0 ?x4114)))
 (let ((?x4113 (+ ?x4111 ?x3946)))
 (let ((?x4112 (+ ?x4113 ?x4013)))
 (let (($x4133 (and (= (to_real (+ ?x4112 ?x3975)) 0.0) (= (to_real (+ ?x4128 ?x4129)) 0.0))))
 (let (($x4014 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6)))
 (let (($x4106 (or c_7_2 c_7_3 c_7_4 c_7_5)))
 (let (($x4105 (and true $x4106)))
 (let (($x4274 (and $x4105 $x4014)))
 (let (($x4277 (not (and $x4274 $x4133))))
 (let ((?x4096 (ite $x4092 1 0)))
 (let ((?x4091 (ite $x4090 1 0)))
 (let ((?x4093 (+ 0 ?x4091)))
 (let ((?x4094 (+ ?x4093 ?x3946)))
 (let ((?x4095 (+ ?x4094 ?x3946)))
 (let ((?x3944 (ite $x3753 1 0)))
 (let ((?x4047 (ite $x3726 1 0)))
 (let ((?x4083 (+ 0 ?x4047)))
 (let ((?x4082 (+ ?x4083 ?x3946)))
 (let ((?x4081 (+ ?x4082 ?x3946)))
 (let (($x4100 (and (= (to_real (+ ?x4081 ?x3944)) 0.0) (= (to_real (+ ?x4095 ?x4096)) 0.0))))
 (let (($x4146 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6)))
 (let (($x4076 (or c_6_2 c_6_3 c_6_4 c_6_5)))
 (let (($x4075 (and true $x4076)))
 (let (($x4270 (and $x4075 $x4146)))
 (let (($x4273 (not (and $x4270 $x4100))))
 (let ((?x4203 (ite $x4199 1 0)))
 (let ((?x4201 (ite $x4197 1 0)))
 (let ((?x4198 (ite $x4196 1 0)))
 (let ((?x4200 (+ ?x4153 ?x4198)))
 (let ((?x4202 (+ ?x4200 ?x4201)))
 (let (($x4193 (= (to_real (+ (+ (+ ?x4153 ?x4114) ?x3975) (ite $x3671 1 0))) 0.0)))
 (let (($x4207 (and $x4193 (= (to_real (+ ?x4202 ?x4203)) 0.0))))
 (let (($x3979 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6)))
 (let (($x4188 (or c_5_2 c_5_3 c_5_4 c_5_5)))
 (let (($x4186 (and true $x4188)))
 (let (($x4264 (and $x4186 $x3979)))
 (let (($x4267 (not (and $x4264 $x4207))))
 (let ((?x4029 (ite $x4024 1 0)))
 (let ((?x4026 (ite $x4022 1 0)))
 (let ((?x4023 (ite $x4020 1 0)))
 (let ((?x4025 (+ 0 ?x4023)))
 (let ((?x4027 (+ ?x4025 ?x4026)))
 (let ((?x4028 (+ ?x4027 ?x3946)))
 (let ((?x4016 (to_real (+ (+ (+ (+ 0 ?x3975) ?x4013) ?x3946) (ite $x3807 1 0)))))
 (let (($x4033 (and (= ?x4016 0.0) (= (to_real (+ ?x4028 ?x4029)) 0.0))))
 (let (($x4220 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6)))
 (let (($x4005 (or c_3_2 c_3_3 c_3_4 c_3_5)))
 (let (($x4003 (and true $x4005)))
 (let (($x4257 (and $x4003 $x4220)))
 (let (($x4260 (not (and $x4257 $x4033))))
 (let (($x4085 (or c_7_1 c_7_2 c_7_3 c_7_4 c_7_5 c_7_6)))
 (let (($x4231 (and $x4237 $x4085)))
 (let (($x4255 (not (and $x4231 $x4253))))
 (let (($x4182 (or c_6_1 c_6_2 c_6_3 c_6_4 c_6_5 c_6_6)))
 (let (($x4233 (and $x4105 $x4182)))
 (let (($x4236 (not (and $x4233 $x4133))))
 (let (($x4232 (not (and (and $x4186 $x4014) $x4207))))
 (let ((?x4167 (to_real (+ (+ (+ ?x4153 (ite $x4161 1 0)) (ite $x4162 1 0)) ?x3946))))
 (let ((?x4157 (to_real (+ (+ (+ ?x4153 (ite $x3706 1 0)) (ite $x3649 1 0)) ?x3946))))
 (let (($x4169 (and (= ?x4157 0.0) (= ?x4167 0.0))))
 (let (($x3945 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6)))
 (let (($x4152 (or c_2_2 c_2_3 c_2_4 c_2_5)))
 (let (($x4149 (and true $x4152)))
 (let (($x4216 (and $x4149 $x3945)))
 (let (($x4221 (not (and $x4216 $x4169))))
 (let ((?x3994 (ite $x3990 1 0)))
 (let ((?x3992 (ite $x3989 1 0)))
 (let ((?x3988 (ite $x3987 1 0)))
 (let ((?x3991 (+ 0 ?x3988)))
 (let ((?x3993 (+ ?x3991 ?x3992)))
 (let ((?x3995 (+ ?x3993 ?x3994)))
 (let ((?x3980 (ite $x3807 1 0)))
 (let ((?x3977 (ite $x3671 1 0)))
 (let ((?x3976 (+ 0 ?x3977)))
 (let ((?x3978 (+ ?x3976 ?x3975)))
 (let ((?x3981 (+ ?x3978 ?x3980)))
 (let (($x3999 (and (= (to_real (+ ?x3981 ?x3946)) 0.0) (= (to_real (+ ?x3995 ?x3946)) 0.0))))
 (let (($x3970 (or c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x3969 (and true $x3970)))
 (let (($x4215 (and $x3969 $x4220)))
 (let (($x4218 (not (and $x4215 $x3999))))
 (let (($x4115 (or c_8_1 c_8_2 c_8_3 c_8_4 c_8_5 c_8_6)))
 (let (($x4187 (and $x4186 $x4115)))
 (let (($x4209 (not (and $x4187 $x4207))))
 (let (($x4181 (not (and (and $x4003 $x4182) $x4033))))
 (let (($x4171 (not (and (and $x4149 $x4048) $x4169))))
 (let (($x4150 (not (and (and $x3969 $x4014) $x3999))))
 (let ((?x3958 (ite $x3956 1 0)))
 (let ((?x3955 (ite $x3954 1 0)))
 (let ((?x3957 (+ 0 ?x3955)))
 (let ((?x3959 (+ ?x3957 ?x3958)))
 (let ((?x3960 (+ ?x3959 ?x3946)))
 (let ((?x3949 (to_real (+ (+ (+ (+ 0 (ite $x3649 1 0)) ?x3944) ?x3946) ?x3946))))
 (let (($x3964 (and (= ?x3949 0.0) (= (to_real (+ ?x3960 ?x3946)) 0.0))))
 (let (($x3936 (or c_0_2 c_0_3 c_0_4 c_0_5)))
 (let (($x3934 (and true $x3936)))
 (let (($x4141 (and $x3934 $x4146)))
 (let (($x4145 (not (and $x4141 $x3964))))
 (let (($x4135 (not (and (and $x4105 $x4115) $x4133))))
 (let (($x4102 (not (and (and $x4075 $x4085) $x4100))))
 (let (($x4035 (not (and (and $x4003 $x4014) $x4033))))
 (let (($x4001 (not (and (and $x3969 $x3979) $x3999))))
 (let (($x3966 (not (and (and $x3934 $x3945) $x3964))))
 (let (($x4498 (not in_target_36)))
 (let (($x4496 (not in_target_35)))
 (let (($x4494 (not in_target_34)))
 (let (($x4492 (not in_target_33)))
 (let (($x4490 (not in_target_32)))
 (let (($x4488 (not in_target_31)))
 (let (($x4486 (not in_target_30)))
 (let (($x4484 (not in_target_29)))
 (let (($x4482 (not in_target_28)))
 (let (($x4480 (not in_target_27)))
 (let (($x4478 (not in_target_26)))
 (let (($x4476 (not in_target_25)))
 (let (($x4474 (not in_target_24)))
 (let (($x4472 (not in_target_23)))
 (let (($x4470 (not in_target_22)))
 (let (($x4468 (not in_target_21)))
 (let (($x4466 (not in_target_20)))
 (let (($x4464 (not in_target_19)))
 (let (($x4462 (not in_target_18)))
 (let (($x4460 (not in_target_17)))
 (let (($x4458 (not in_target_16)))
 (let (($x4456 (not in_target_15)))
 (let (($x4454 (not in_target_14)))
 (let (($x4452 (not in_target_13)))
 (let (($x4450 (not in_target_12)))
 (let (($x4448 (not in_target_11)))
 (let (($x4446 (not in_target_10)))
 (let (($x4444 (not in_target_9)))
 (let (($x4445 (and true $x4444)))
 (let (($x4447 (and $x4445 $x4446)))
 (let (($x4449 (and $x4447 $x4448)))
 (let (($x4451 (and $x4449 $x4450)))
 (let (($x4453 (and $x4451 $x4452)))
 (let (($x4455 (and $x4453 $x4454)))
 (let (($x4457 (and $x4455 $x4456)))
 (let (($x4459 (and $x4457 $x4458)))
 (let (($x4461 (and $x4459 $x4460)))
 (let (($x4463 (and $x4461 $x4462)))
 (let (($x4465 (and $x4463 $x4464)))
 (let (($x4467 (and $x4465 $x4466)))
 (let (($x4469 (and $x4467 $x4468)))
 (let (($x4471 (and $x4469 $x4470)))
 (let (($x4473 (and $x4471 $x4472)))
 (let (($x4475 (and $x4473 $x4474)))
 (let (($x4477 (and $x4475 $x4476)))
 (let (($x4479 (and $x4477 $x4478)))
 (let (($x4481 (and $x4479 $x4480)))
 (let (($x4483 (and $x4481 $x4482)))
 (let (($x4485 (and $x4483 $x4484)))
 (let (($x4487 (and $x4485 $x4486)))
 (let (($x4489 (and $x4487 $x4488)))
 (let (($x4491 (and $x4489 $x4490)))
 (let (($x4493 (and $x4491 $x4492)))
 (let (($x4495 (and $x4493 $x4494)))
 (let (($x4497 (and $x4495 $x4496)))
 (let (($x4499 (and $x4497 $x4498)))
 (let (($x4500 (and $x4499 $x3966)))
 (let (($x4503 (and $x4500 $x4001)))
 (let (($x4506 (and $x4503 $x4035)))
 (let (($x4508 (and $x4506 $x4102)))
 (let (($x4504 (and $x4508 $x4135)))
 (let (($x4507 (and $x4504 $x4145)))
 (let (($x4511 (and $x4507 $x4150)))
 (let (($x4509 (and $x4511 $x4171)))
 (let (($x4512 (and $x4509 $x4181)))
 (let (($x4513 (and $x4512 $x4209)))
 (let (($x4514 (and $x4513 $x4218)))
 (let (($x4505 (and $x4514 $x4221)))
 (let (($x4516 (and $x4505 $x4232)))
 (let (($x4518 (and $x4516 $x4236)))
 (let (($x4519 (and $x4518 $x4255)))
 (let (($x4510 (and $x4519 $x4260)))
 (let (($x4517 (and $x4510 $x4267)))
 (let (($x4521 (and $x4517 $x4273)))
 (let (($x4523 (and $x4521 $x4277)))
 (let (($x4399 (or c_8_7 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x4393 (and true $x4399)))
 (let (($x4342 (or c_7_7 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x4336 (and true $x4342)))
 (let (($x4332 (or c_6_7 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x4326 (and true $x4332)))
 (let (($x4374 (or c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4368 (and true $x4374)))
 (let (($x4322 (or c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4316 (and true $x4322)))
 (let (($x4312 (or c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x4306 (and true $x4312)))
 (let (($x4358 (or c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x4352 (and true $x4358)))
 (let (($x4302 (or c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x4296 (and true $x4302)))
 (let (($x4292 (or c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x4286 (and true $x4292)))
 (let ((?x4066 (ite $x4060 1 0)))
 (let ((?x4064 (ite $x4058 1 0)))
 (let ((?x4062 (ite $x4057 1 0)))
 (let ((?x4059 (ite $x4055 1 0)))
 (let ((?x4061 (+ 0 ?x4059)))
 (let ((?x4063 (+ ?x4061 ?x4062)))
 (let ((?x4065 (+ ?x4063 ?x4064)))
 (let ((?x3942 (ite $x3649 1 0)))
 (let ((?x4044 (ite $x3706 1 0)))
 (let ((?x4045 (+ 0 ?x4044)))
 (let ((?x4046 (+ ?x4045 ?x4047)))
 (let ((?x4049 (+ ?x4046 ?x3944)))
 (let (($x4070 (and (= (to_real (+ ?x4049 ?x3942)) 0.0) (= (to_real (+ ?x4065 ?x4066)) 0.0))))
 (let (($x4039 (or c_4_2 c_4_3 c_4_4 c_4_5)))
 (let (($x4037 (and true $x4039)))
 (let (($x4258 (and $x4037 $x3945)))
 (let (($x3635 (not (and (and true $x3391) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3632 (not (and (and true $x3339) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3629 (not (and (and true $x3331) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3626 (not (and (and true $x3368) (or (and c_2_1 $x1680) (and c_2_7 $x1680))))))
 (let (($x3623 (not (and (and true $x3323) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x3620 (not (and (and true $x3315) (or (and c_0_1 $x1652) (and c_0_7 $x1652))))))
 (let (($x3617 (not (and (and true $x3391) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3614 (not (and (and true $x3339) (or (and c_6_1 $x1740) (and c_6_7 $x1740))))))
 (let (($x3611 (not (and (and true $x3368) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3608 (not (and (and true $x3323) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3605 (not (and (and true $x3354) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x3602 (not (and (and true $x3307) (or (and c_0_1 $x1652) (and c_0_7 $x1652))))))
 (let (($x3598 (not (and (and true $x3368) (or (and c_8_1 $x1770) (and c_8_7 $x1770))))))
 (let (($x3595 (not (and (and true $x3323) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3592 (not (and (and true $x3315) (or (and c_6_1 $x1740) (and c_6_7 $x1740))))))
 (let (($x3588 (not (and (and true $x3354) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3585 (not (and (and true $x3307) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3582 (not (and (and true $x3299) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3578 (not (and (and true $x3339) (or (and c_8_1 $x1770) (and c_8_7 $x1770))))))
 (let (($x3574 (not (and (and true $x3331) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3570 (not (and (and true $x3323) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3566 (not (and (and true $x3315) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3562 (not (and (and true $x3307) (or (and c_2_1 $x1680) (and c_2_7 $x1680))))))
 (let (($x3557 (not (and (and true $x3299) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x2007 (and c_5_11 in_target_5)))
 (let (($x2005 (and c_5_10 in_target_5)))
 (let (($x2003 (and c_5_9 in_target_5)))
 (let (($x2001 (and c_5_8 in_target_5)))
 (let (($x1996 (and c_5_5 in_target_5)))
 (let (($x1994 (and c_5_4 in_target_5)))
 (let (($x1992 (and c_5_3 in_target_5)))
 (let (($x1990 (and c_5_2 in_target_5)))
 (let (($x3459 (or $x1990 $x1992 $x1994 $x1996 $x2001 $x2003 $x2005 $x2007)))
 (let (($x3389 (and true $x3391)))
 (let (($x1972 (and c_4_11 in_target_4)))
 (let (($x1970 (and c_4_10 in_target_4)))
 (let (($x1968 (and c_4_9 in_target_4)))
 (let (($x1966 (and c_4_8 in_target_4)))
 (let (($x1961 (and c_4_5 in_target_4)))
 (let (($x1959 (and c_4_4 in_target_4)))
 (let (($x1957 (and c_4_3 in_target_4)))
 (let (($x1955 (and c_4_2 in_target_4)))
 (let (($x3448 (or $x1955 $x1957 $x1959 $x1961 $x1966 $x1968 $x1970 $x1972)))
 (let (($x3337 (and true $x3339)))
 (let (($x1937 (and c_3_11 in_target_3)))
 (let (($x1935 (and c_3_10 in_target_3)))
 (let (($x1933 (and c_3_9 in_target_3)))
 (let (($x1931 (and c_3_8 in_target_3)))
 (let (($x1926 (and c_3_5 in_target_3)))
 (let (($x1924 (and c_3_4 in_target_3)))
 (let (($x1922 (and c_3_3 in_target_3)))
 (let (($x1920 (and c_3_2 in_target_3)))
 (let (($x3492 (or $x1920 $x1922 $x1924 $x1926 $x1931 $x1933 $x1935 $x1937)))
 (let (($x3329 (and true $x3331)))
 (let (($x1902 (and c_2_11 in_target_2)))
 (let (($x1900 (and c_2_10 in_target_2)))
 (let (($x1898 (and c_2_9 in_target_2)))
 (let (($x1896 (and c_2_8 in_target_2)))
 (let (($x1891 (and c_2_5 in_target_2)))
 (let (($x1889 (and c_2_4 in_target_2)))
 (let (($x1887 (and c_2_3 in_target_2)))
 (let (($x1885 (and c_2_2 in_target_2)))
 (let (($x3437 (or $x1885 $x1887 $x1889 $x1891 $x1896 $x1898 $x1900 $x1902)))
 (let (($x3366 (and true $x3368)))
 (let (($x1867 (and c_1_11 in_target_1)))
 (let (($x1865 (and c_1_10 in_target_1)))
 (let (($x1863 (and c_1_9 in_target_1)))
 (let (($x1861 (and c_1_8 in_target_1)))
 (let (($x1856 (and c_1_5 in_target_1)))
 (let (($x1854 (and c_1_4 in_target_1)))
 (let (($x1852 (and c_1_3 in_target_1)))
 (let (($x1850 (and c_1_2 in_target_1)))
 (let (($x3426 (or $x1850 $x1852 $x1854 $x1856 $x1861 $x1863 $x1865 $x1867)))
 (let (($x3321 (and true $x3323)))
 (let (($x1832 (and c_0_11 in_target_0)))
 (let (($x1830 (and c_0_10 in_target_0)))
 (let (($x1828 (and c_0_9 in_target_0)))
 (let (($x1826 (and c_0_8 in_target_0)))
 (let (($x1821 (and c_0_5 in_target_0)))
 (let (($x1819 (and c_0_4 in_target_0)))
 (let (($x1817 (and c_0_3 in_target_0)))
 (let (($x1815 (and c_0_2 in_target_0)))
 (let (($x3526 (or $x1815 $x1817 $x1819 $x1821 $x1826 $x1828 $x1830 $x1832)))
 (let (($x3313 (and true $x3315)))
 (let (($x2077 (and c_7_11 in_target_7)))
 (let (($x2075 (and c_7_10 in_target_7)))
 (let (($x2073 (and c_7_9 in_target_7)))
 (let (($x2071 (and c_7_8 in_target_7)))
 (let (($x2066 (and c_7_5 in_target_7)))
 (let (($x2064 (and c_7_4 in_target_7)))
 (let (($x2062 (and c_7_3 in_target_7)))
 (let (($x2060 (and c_7_2 in_target_7)))
 (let (($x3470 (or $x2060 $x2062 $x2064 $x2066 $x2071 $x2073 $x2075 $x2077)))
 (let (($x2042 (and c_6_11 in_target_6)))
 (let (($x2040 (and c_6_10 in_target_6)))
 (let (($x2038 (and c_6_9 in_target_6)))
 (let (($x2036 (and c_6_8 in_target_6)))
 (let (($x2031 (and c_6_5 in_target_6)))
 (let (($x2029 (and c_6_4 in_target_6)))
 (let (($x2027 (and c_6_3 in_target_6)))
 (let (($x2025 (and c_6_2 in_target_6)))
 (let (($x3509 (or $x2025 $x2027 $x2029 $x2031 $x2036 $x2038 $x2040 $x2042)))
 (let (($x2112 (and c_8_11 in_target_8)))
 (let (($x2110 (and c_8_10 in_target_8)))
 (let (($x2108 (and c_8_9 in_target_8)))
 (let (($x2106 (and c_8_8 in_target_8)))
 (let (($x2101 (and c_8_5 in_target_8)))
 (let (($x2099 (and c_8_4 in_target_8)))
 (let (($x2097 (and c_8_3 in_target_8)))
 (let (($x2095 (and c_8_2 in_target_8)))
 (let (($x3481 (or $x2095 $x2097 $x2099 $x2101 $x2106 $x2108 $x2110 $x2112)))
 (let (($x3410 (not (and $x3389 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3407 (not (and $x3337 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3404 (not (and $x3329 (or (and c_3_1 in_target_3) (and c_3_7 in_target_3))))))
 (let (($x3401 (not (and $x3366 (or (and c_2_1 in_target_2) (and c_2_7 in_target_2))))))
 (let (($x3398 (not (and $x3321 (or (and c_1_1 in_target_1) (and c_1_7 in_target_1))))))
 (let (($x3395 (not (and $x3313 (or (and c_0_1 in_target_0) (and c_0_7 in_target_0))))))
 (let (($x3392 (not (and $x3389 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3385 (not (and $x3337 (or (and c_6_1 in_target_6) (and c_6_7 in_target_6))))))
 (let (($x3382 (not (and $x3366 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3379 (not (and $x3321 (or (and c_3_1 in_target_3) (and c_3_7 in_target_3))))))
 (let (($x1859 (and c_1_7 in_target_1)))
 (let (($x1848 (and c_1_1 in_target_1)))
 (let (($x3300 (or $x1848 $x1859)))
 (let (($x3352 (and true $x3354)))
 (let (($x1824 (and c_0_7 in_target_0)))
 (let (($x1813 (and c_0_1 in_target_0)))
 (let (($x3372 (or $x1813 $x1824)))
 (let (($x3305 (and true $x3307)))
 (let (($x3369 (not (and $x3366 (or (and c_8_1 in_target_8) (and c_8_7 in_target_8))))))
 (let (($x3362 (not (and $x3321 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3359 (not (and $x3313 (or (and c_6_1 in_target_6) (and c_6_7 in_target_6))))))
 (let (($x3355 (not (and $x3352 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3348 (not (and $x3305 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x1929 (and c_3_7 in_target_3)))
 (let (($x1918 (and c_3_1 in_target_3)))
 (let (($x3344 (or $x1918 $x1929)))
 (let (($x3297 (and true $x3299)))
 (let (($x3341 (not (and $x3337 (or (and c_8_1 in_target_8) (and c_8_7 in_target_8))))))
 (let (($x3333 (not (and $x3329 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3325 (not (and $x3321 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3317 (not (and $x3313 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3309 (not (and $x3305 (or (and c_2_1 in_target_2) (and c_2_7 in_target_2))))))
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
 (let ((?x3148 (ite (or $x2803 $x2804 $x2806 $x2808 $x2810 $x2812) 1 0)))
 (let (($x2093 (and c_8_1 in_target_8)))
 (let (($x1784 (and c_8_6 in_target_8)))
 (let ((?x3146 (ite (or $x1784 $x2093 $x2095 $x2097 $x2099 $x2101) (- 1) 0)))
 (let (($x2092 (and c_8_0 in_target_8)))
 (let ((?x3147 (ite $x2092 (- 2) 0)))
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
 (let ((?x3125 (ite (or $x2745 $x2746 $x2748 $x2750 $x2752 $x2754) 1 0)))
 (let (($x2058 (and c_7_1 in_target_7)))
 (let (($x1769 (and c_7_6 in_target_7)))
 (let ((?x3121 (ite (or $x1769 $x2058 $x2060 $x2062 $x2064 $x2066) (- 1) 0)))
 (let (($x2057 (and c_7_0 in_target_7)))
 (let ((?x3118 (ite $x2057 (- 2) 0)))
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
 (let ((?x3112 (ite (or $x2687 $x2688 $x2690 $x2692 $x2694 $x2696) 1 0)))
 (let (($x2023 (and c_6_1 in_target_6)))
 (let (($x1754 (and c_6_6 in_target_6)))
 (let ((?x3105 (ite (or $x1754 $x2023 $x2025 $x2027 $x2029 $x2031) (- 1) 0)))
 (let (($x2022 (and c_6_0 in_target_6)))
 (let ((?x3100 (ite $x2022 (- 2) 0)))
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
 (let ((?x3078 (ite (or $x2629 $x2630 $x2632 $x2634 $x2636 $x2638) 1 0)))
 (let (($x1988 (and c_5_1 in_target_5)))
 (let (($x1739 (and c_5_6 in_target_5)))
 (let ((?x3086 (ite (or $x1739 $x1988 $x1990 $x1992 $x1994 $x1996) (- 1) 0)))
 (let (($x1987 (and c_5_0 in_target_5)))
 (let ((?x3081 (ite $x1987 (- 2) 0)))
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
 (let ((?x3070 (ite (or $x2571 $x2572 $x2574 $x2576 $x2578 $x2580) 1 0)))
 (let (($x1953 (and c_4_1 in_target_4)))
 (let (($x1724 (and c_4_6 in_target_4)))
 (let ((?x3059 (ite (or $x1724 $x1953 $x1955 $x1957 $x1959 $x1961) (- 1) 0)))
 (let (($x1952 (and c_4_0 in_target_4)))
 (let ((?x3065 (ite $x1952 (- 2) 0)))
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
 (let ((?x3049 (ite (or $x2513 $x2514 $x2516 $x2518 $x2520 $x2522) 1 0)))
 (let ((?x3043 (ite (or (and c_3_6 in_target_3) $x1918 $x1920 $x1922 $x1924 $x1926) (- 1) 0)))
 (let (($x1917 (and c_3_0 in_target_3)))
 (let ((?x3039 (ite $x1917 (- 2) 0)))
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
 (let ((?x3020 (ite (or $x2455 $x2456 $x2458 $x2460 $x2462 $x2464) 1 0)))
 (let (($x1883 (and c_2_1 in_target_2)))
 (let (($x1694 (and c_2_6 in_target_2)))
 (let ((?x3018 (ite (or $x1694 $x1883 $x1885 $x1887 $x1889 $x1891) (- 1) 0)))
 (let (($x1882 (and c_2_0 in_target_2)))
 (let ((?x3019 (ite $x1882 (- 2) 0)))
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
 (let ((?x3004 (ite (or $x2397 $x2398 $x2400 $x2402 $x2404 $x2406) 1 0)))
 (let ((?x2997 (ite (or (and c_1_6 in_target_1) $x1848 $x1850 $x1852 $x1854 $x1856) (- 1) 0)))
 (let (($x1847 (and c_1_0 in_target_1)))
 (let ((?x2996 (ite $x1847 (- 2) 0)))
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
 (let ((?x2984 (ite (or $x2338 $x2339 $x2341 $x2343 $x2345 $x2347) 1 0)))
 (let ((?x2980 (ite (or (and c_0_6 in_target_0) $x1813 $x1815 $x1817 $x1819 $x1821) (- 1) 0)))
 (let (($x1812 (and c_0_0 in_target_0)))
 (let ((?x2973 (ite $x1812 (- 2) 0)))
 (let ((?x2974 (+ 0 ?x2973)))
 (let ((?x2983 (+ ?x2974 ?x2980)))
 (let ((?x2981 (+ ?x2983 ?x2984)))
 (let ((?x2982 (+ ?x2981 ?x2356)))
 (let ((?x3000 (+ ?x2982 ?x2996)))
 (let ((?x3001 (+ ?x3000 ?x2997)))
 (let ((?x3005 (+ ?x3001 ?x3004)))
 (let ((?x3002 (+ ?x3005 ?x2414)))
 (let ((?x3016 (+ ?x3002 ?x3019)))
 (let ((?x3025 (+ ?x3016 ?x3018)))
 (let ((?x3028 (+ ?x3025 ?x3020)))
 (let ((?x3022 (+ ?x3028 ?x2472)))
 (let ((?x3037 (+ ?x3022 ?x3039)))
 (let ((?x3047 (+ ?x3037 ?x3043)))
 (let ((?x3041 (+ ?x3047 ?x3049)))
 (let ((?x3040 (+ ?x3041 ?x2530)))
 (let ((?x3056 (+ ?x3040 ?x3065)))
 (let ((?x3068 (+ ?x3056 ?x3059)))
 (let ((?x3058 (+ ?x3068 ?x3070)))
 (let ((?x3064 (+ ?x3058 ?x2588)))
 (let ((?x3077 (+ ?x3064 ?x3081)))
 (let ((?x3083 (+ ?x3077 ?x3086)))
 (let ((?x3089 (+ ?x3083 ?x3078)))
 (let ((?x3091 (+ ?x3089 ?x2646)))
 (let ((?x3099 (+ ?x3091 ?x3100)))
 (let ((?x3110 (+ ?x3099 ?x3105)))
 (let ((?x3107 (+ ?x3110 ?x3112)))
 (let ((?x3109 (+ ?x3107 ?x2704)))
 (let ((?x3126 (+ ?x3109 ?x3118)))
 (let ((?x3130 (+ ?x3126 ?x3121)))
 (let ((?x3133 (+ ?x3130 ?x3125)))
 (let ((?x3127 (+ ?x3133 ?x2762)))
 (let ((?x3139 (+ ?x3127 ?x3147)))
 (let ((?x3141 (+ ?x3139 ?x3146)))
 (let ((?x3152 (+ ?x3141 ?x3148)))
 (let (($x3166 (<= (+ ?x3152 ?x2820) 0)))
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
 (let (($x3294 (and $x1781 (and (and $x2315 $x2839) $x3166))))
 (let (($x3302 (and $x3294 (not (and $x3297 $x3300)))))
 (let (($x3310 (and $x3302 $x3309)))
 (let (($x3318 (and $x3310 $x3317)))
 (let (($x3326 (and $x3318 $x3325)))
 (let (($x3334 (and $x3326 $x3333)))
 (let (($x3342 (and $x3334 $x3341)))
 (let (($x3346 (and $x3342 (not (and $x3297 $x3344)))))
 (let (($x3349 (and $x3346 $x3348)))
 (let (($x3356 (and $x3349 $x3355)))
 (let (($x3360 (and $x3356 $x3359)))
 (let (($x3363 (and $x3360 $x3362)))
 (let (($x3370 (and $x3363 $x3369)))
 (let (($x3374 (and $x3370 (not (and $x3305 $x3372)))))
 (let (($x3377 (and $x3374 (not (and $x3352 $x3300)))))
 (let (($x3380 (and $x3377 $x3379)))
 (let (($x3383 (and $x3380 $x3382)))
 (let (($x3386 (and $x3383 $x3385)))
 (let (($x3393 (and $x3386 $x3392)))
 (let (($x3396 (and $x3393 $x3395)))
 (let (($x3399 (and $x3396 $x3398)))
 (let (($x3402 (and $x3399 $x3401)))
 (let (($x3405 (and $x3402 $x3404)))
 (let (($x3408 (and $x3405 $x3407)))
 (let (($x3411 (and $x3408 $x3410)))
 (let (($x3420 (and $x3411 (not (and $x3297 $x3426)))))
 (let (($x3433 (and $x3420 (not (and $x3305 $x3437)))))
 (let (($x3442 (and $x3433 (not (and $x3313 $x3448)))))
 (let (($x3454 (and $x3442 (not (and $x3321 $x3459)))))
 (let (($x3464 (and $x3454 (not (and $x3329 $x3470)))))
 (let (($x3476 (and $x3464 (not (and $x3337 $x3481)))))
 (let (($x3490 (and $x3476 (not (and $x3297 $x3492)))))
 (let (($x3488 (and $x3490 (not (and $x3305 $x3448)))))
 (let (($x3495 (and $x3488 (not (and $x3352 $x3459)))))
 (let (($x3507 (and $x3495 (not (and $x3313 $x3509)))))
 (let (($x3505 (and $x3507 (not (and $x3321 $x3470)))))
 (let (($x3512 (and $x3505 (not (and $x3366 $x3481)))))
 (let (($x3520 (and $x3512 (not (and $x3305 $x3526)))))
 (let (($x3523 (and $x3520 (not (and $x3352 $x3426)))))
 (let (($x3531 (and $x3523 (not (and $x3321 $x3492)))))
 (let (($x3521 (and $x3531 (not (and $x3366 $x3448)))))
 (let (($x3537 (and $x3521 (not (and $x3337 $x3509)))))
 (let (($x3532 (and $x3537 (not (and $x3389 $x3470)))))
 (let (($x3539 (and $x3532 (not (and $x3313 $x3526)))))
 (let (($x3542 (and $x3539 (not (and $x3321 $x3426)))))
 (let (($x3541 (and $x3542 (not (and $x3366 $x3437)))))
 (let (($x3552 (and $x3541 (not (and $x3329 $x3492)))))
 (let (($x3548 (and $x3552 (not (and $x3337 $x3448)))))
 (let (($x3556 (and $x3548 (not (and $x3389 $x3459)))))
 (let (($x3553 (and $x3556 $x3557)))
 (let (($x3563 (and $x3553 $x3562)))
 (let (($x3567 (and $x3563 $x3566)))
 (let (($x3571 (and $x3567 $x3570)))
 (let (($x3575 (and $x3571 $x3574)))
 (let (($x3579 (and $x3575 $x3578)))
 (let (($x3583 (and $x3579 $x3582)))
 (let (($x3586 (and $x3583 $x3585)))
 (let (($x3589 (and $x3586 $x3588)))
 (let (($x3593 (and $x3589 $x3592)))
 (let (($x3596 (and $x3593 $x3595)))
 (let (($x3599 (and $x3596 $x3598)))
 (let (($x3603 (and $x3599 $x3602)))
 (let (($x3606 (and $x3603 $x3605)))
 (let (($x3609 (and $x3606 $x3608)))
 (let (($x3612 (and $x3609 $x3611)))
 (let (($x3615 (and $x3612 $x3614)))
 (let (($x3618 (and $x3615 $x3617)))
 (let (($x3621 (and $x3618 $x3620)))
 (let (($x3624 (and $x3621 $x3623)))
 (let (($x3627 (and $x3624 $x3626)))
 (let (($x3630 (and $x3627 $x3629)))
 (let (($x3633 (and $x3630 $x3632)))
 (let (($x3636 (and $x3633 $x3635)))
 (let (($x3651 (and $x3636 (not (and (and true $x3655) $x3649)))))
 (let (($x3672 (and $x3651 (not (and (and true $x3674) $x3671)))))
 (let (($x3692 (and $x3672 (not (and (and true $x3693) $x3690)))))
 (let (($x3707 (and $x3692 (not (and (and true $x3712) $x3706)))))
 (let (($x3730 (and $x3707 (not (and (and true $x3731) $x3726)))))
 (let (($x3747 (and $x3730 (not (and (and true $x3750) $x3746)))))
 (let (($x3756 (and $x3747 (not (and (and true $x3655) $x3753)))))
 (let (($x3759 (and $x3756 (not (and (and true $x3674) $x3690)))))
 (let (($x3777 (and $x3759 (not (and (and true $x3778) $x3706)))))
 (let (($x3779 (and $x3777 (not (and (and true $x3693) $x3781)))))
 (let (($x3788 (and $x3779 (not (and (and true $x3712) $x3726)))))
 (let (($x3797 (and $x3788 (not (and (and true $x3803) $x3746)))))
 (let (($x3801 (and $x3797 (not (and (and true $x3674) $x3807)))))
 (let (($x3811 (and $x3801 (not (and (and true $x3778) $x3649)))))
 (let (($x3816 (and $x3811 (not (and (and true $x3712) $x3753)))))
 (let (($x3812 (and $x3816 (not (and (and true $x3803) $x3690)))))
 (let (($x3818 (and $x3812 (not (and (and true $x3750) $x3781)))))
 (let (($x3835 (and $x3818 (not (and (and true $x3837) $x3726)))))
 (let (($x3836 (and $x3835 (not (and (and true $x3693) $x3807)))))
 (let (($x3844 (and $x3836 (not (and (and true $x3712) $x3649)))))
 (let (($x3838 (and $x3844 (not (and (and true $x3803) $x3671)))))
 (let (($x3847 (and $x3838 (not (and (and true $x3731) $x3753)))))
 (let (($x3843 (and $x3847 (not (and (and true $x3750) $x3690)))))
 (let (($x3854 (and $x3843 (not (and (and true $x3837) $x3706)))))
 (let (($x3856 (and $x3854 (not (and (and true c_0_12) $x1847)))))
 (let (($x3860 (and $x3856 (not (and (and true c_1_12) $x1882)))))
 (let (($x3864 (and $x3860 (not (and (and true c_3_12) $x1952)))))
 (let (($x3868 (and $x3864 (not (and (and true c_4_12) $x1987)))))
 (let (($x3872 (and $x3868 (not (and (and true c_6_12) $x2057)))))
 (let (($x3876 (and $x3872 (not (and (and true c_7_12) $x2092)))))
 (let (($x3879 (and $x3876 (not (and (and true c_0_12) $x1917)))))
 (let (($x3882 (and $x3879 (not (and (and true c_1_12) $x1952)))))
 (let (($x3886 (and $x3882 (not (and (and true c_2_12) $x1987)))))
 (let (($x3889 (and $x3886 (not (and (and true c_3_12) $x2022)))))
 (let (($x3892 (and $x3889 (not (and (and true c_4_12) $x2057)))))
 (let (($x3896 (and $x3892 (not (and (and true c_5_12) $x2092)))))
 (let (($x3899 (and $x3896 (not (and (and true c_1_12) $x1812)))))
 (let (($x3902 (and $x3899 (not (and (and true c_2_12) $x1847)))))
 (let (($x3905 (and $x3902 (not (and (and true c_4_12) $x1917)))))
 (let (($x3908 (and $x3905 (not (and (and true c_5_12) $x1952)))))
 (let (($x3911 (and $x3908 (not (and (and true c_7_12) $x2022)))))
 (let (($x3915 (and $x3911 (not (and (and true c_8_12) $x2057)))))
 (let (($x3918 (and $x3915 (not (and (and true c_3_12) $x1812)))))
 (let (($x3921 (and $x3918 (not (and (and true c_4_12) $x1847)))))
 (let (($x3924 (and $x3921 (not (and (and true c_5_12) $x1882)))))
 (let (($x3927 (and $x3924 (not (and (and true c_6_12) $x1917)))))
 (let (($x3930 (and $x3927 (not (and (and true c_7_12) $x1952)))))
 (let (($x3933 (and $x3930 (not (and (and true c_8_12) $x1987)))))
 (let (($x3967 (and $x3933 $x3966)))
 (let (($x4002 (and $x3967 $x4001)))
 (let (($x4036 (and $x4002 $x4035)))
 (let (($x4073 (and $x4036 (not (and (and $x4037 $x4048) $x4070)))))
 (let (($x4103 (and $x4073 $x4102)))
 (let (($x4136 (and $x4103 $x4135)))
 (let (($x4144 (and $x4136 $x4145)))
 (let (($x4148 (and $x4144 $x4150)))
 (let (($x4172 (and $x4148 $x4171)))
 (let (($x4180 (and $x4172 $x4181)))
 (let (($x4183 (and $x4180 (not (and (and $x4037 $x4085) $x4070)))))
 (let (($x4210 (and $x4183 $x4209)))
 (let (($x4219 (and $x4210 $x4218)))
 (let (($x4224 (and $x4219 $x4221)))
 (let (($x4227 (and $x4224 (not (and (and $x4037 $x4146) $x4070)))))
 (let (($x4230 (and $x4227 $x4232)))
 (let (($x4235 (and $x4230 $x4236)))
 (let (($x4256 (and $x4235 $x4255)))
 (let (($x4261 (and $x4256 $x4260)))
 (let (($x4265 (and $x4261 (not (and $x4258 $x4070)))))
 (let (($x4266 (and $x4265 $x4267)))
 (let (($x4272 (and $x4266 $x4273)))
 (let (($x4275 (and $x4272 $x4277)))
 (let (($x4281 (and $x4275 $x4279)))
 (let (($x4290 (and $x4281 (not (and $x4286 $x3945)))))
 (let (($x4298 (and $x4290 (not (and $x4296 $x3979)))))
 (let (($x4310 (and $x4298 (not (and $x4306 $x4014)))))
 (let (($x4321 (and $x4310 (not (and $x4316 $x4048)))))
 (let (($x4328 (and $x4321 (not (and $x4326 $x4085)))))
 (let (($x4338 (and $x4328 (not (and $x4336 $x4115)))))
 (let (($x4343 (and $x4338 (not (and $x4286 $x4146)))))
 (let (($x4349 (and $x4343 (not (and $x4296 $x4014)))))
 (let (($x4354 (and $x4349 (not (and $x4352 $x4048)))))
 (let (($x4359 (and $x4354 (not (and $x4306 $x4182)))))
 (let (($x4364 (and $x4359 (not (and $x4316 $x4085)))))
 (let (($x4370 (and $x4364 (not (and $x4368 $x4115)))))
 (let (($x4375 (and $x4370 (not (and $x4296 $x4220)))))
 (let (($x4371 (and $x4375 (not (and $x4352 $x3945)))))
 (let (($x4382 (and $x4371 (not (and $x4316 $x4146)))))
 (let (($x4386 (and $x4382 (not (and $x4368 $x4014)))))
 (let (($x4389 (and $x4386 (not (and $x4336 $x4182)))))
 (let (($x4396 (and $x4389 (not (and $x4393 $x4085)))))
 (let (($x4401 (and $x4396 (not (and $x4306 $x4220)))))
 (let (($x4398 (and $x4401 (not (and $x4316 $x3945)))))
 (let (($x4402 (and $x4398 (not (and $x4368 $x3979)))))
 (let (($x4411 (and $x4402 (not (and $x4326 $x4146)))))
 (let (($x4414 (and $x4411 (not (and $x4336 $x4014)))))
 (let (($x4415 (and $x4414 (not (and $x4393 $x4048)))))
 (let (($x4520 (and $x4415 (and $x4523 $x4279))))
 (and $x4520 (and $x5411 $x5685))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
