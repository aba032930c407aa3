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
 (let (($x4299 (>= rank_18 0)))
 (and $x4299 (< rank_18 9))))
(assert
 (let (($x4304 (>= rank_20 0)))
 (and $x4304 (< rank_20 9))))
(assert
 (let (($x4309 (>= rank_22 0)))
 (and $x4309 (< rank_22 9))))
(assert
 (let (($x4314 (>= rank_24 0)))
 (and $x4314 (< rank_24 9))))
(assert
 (let (($x4319 (>= rank_26 0)))
 (and $x4319 (< rank_26 9))))
(assert
 (let (($x4324 (>= rank_28 0)))
 (and $x4324 (< rank_28 9))))
(assert
 (let (($x4329 (>= rank_30 0)))
 (and $x4329 (< rank_30 9))))
(assert
 (let (($x4334 (>= rank_32 0)))
 (and $x4334 (< rank_32 9))))
(assert
 (let (($x4339 (>= rank_34 0)))
 (and $x4339 (< rank_34 9))))
(assert
 (let (($x4554 (>= prank_36 0)))
 (and $x4554 (< prank_36 9))))
(assert
 (let (($x4563 (>= prank_37 0)))
 (and $x4563 (< prank_37 9))))
(assert
 (let (($x4567 (>= prank_38 0)))
 (and $x4567 (< prank_38 9))))
(assert
 (let (($x4571 (>= prank_39 0)))
 (and $x4571 (< prank_39 9))))
(assert
 (let (($x4575 (>= prank_40 0)))
 (and $x4575 (< prank_40 9))))
(assert
 (let (($x4579 (>= prank_41 0)))
 (and $x4579 (< prank_41 9))))
(assert
 (let (($x4583 (>= prank_42 0)))
 (and $x4583 (< prank_42 9))))
(assert
 (let (($x4587 (>= prank_43 0)))
 (and $x4587 (< prank_43 9))))
(assert
 (let (($x4591 (>= prank_44 0)))
 (and $x4591 (< prank_44 9))))
(assert
 (let (($x4891 (>= prank_47 0)))
 (and $x4891 (< prank_47 9))))
(assert
 (let (($x4892 (>= prank_48 0)))
 (and $x4892 (< prank_48 9))))
(assert
 (let (($x4900 (>= prank_49 0)))
 (and $x4900 (< prank_49 9))))
(assert
 (let (($x4904 (>= prank_50 0)))
 (and $x4904 (< prank_50 9))))
(assert
 (let (($x4908 (>= prank_51 0)))
 (and $x4908 (< prank_51 9))))
(assert
 (let (($x4912 (>= prank_52 0)))
 (and $x4912 (< prank_52 9))))
(assert
 (let (($x4916 (>= prank_53 0)))
 (and $x4916 (< prank_53 9))))
(assert
 (let (($x4920 (>= prank_54 0)))
 (and $x4920 (< prank_54 9))))
(assert
 (let (($x4924 (>= prank_55 0)))
 (and $x4924 (< prank_55 9))))
(assert
 (let (($x5237 (>= rank_58 0)))
 (and $x5237 (< rank_58 9))))
(assert
 (let (($x5238 (>= rank_60 0)))
 (and $x5238 (< rank_60 9))))
(assert
 (let (($x5245 (>= rank_62 0)))
 (and $x5245 (< rank_62 9))))
(assert
 (let (($x5250 (>= rank_64 0)))
 (and $x5250 (< rank_64 9))))
(assert
 (let (($x5255 (>= rank_66 0)))
 (and $x5255 (< rank_66 9))))
(assert
 (let (($x5260 (>= rank_68 0)))
 (and $x5260 (< rank_68 9))))
(assert
 (let (($x5265 (>= rank_70 0)))
 (and $x5265 (< rank_70 9))))
(assert
 (let (($x5270 (>= rank_72 0)))
 (and $x5270 (< rank_72 9))))
(assert
 (let (($x5275 (>= rank_74 0)))
 (and $x5275 (< rank_74 9))))
(assert
 (let ((?x5426 (ite root_75 1 0)))
 (let ((?x5407 (ite root_73 1 0)))
 (let ((?x5391 (ite root_71 1 0)))
 (let ((?x5372 (ite root_69 1 0)))
 (let ((?x5350 (ite root_67 1 0)))
 (let ((?x5331 (ite root_65 1 0)))
 (let ((?x5315 (ite root_63 1 0)))
 (let ((?x5296 (ite root_61 1 0)))
 (let ((?x5280 (ite root_59 1 0)))
 (let ((?x5281 (+ 0 ?x5280)))
 (let ((?x5297 (+ ?x5281 ?x5296)))
 (let ((?x5316 (+ ?x5297 ?x5315)))
 (let ((?x5332 (+ ?x5316 ?x5331)))
 (let ((?x5351 (+ ?x5332 ?x5350)))
 (let ((?x5373 (+ ?x5351 ?x5372)))
 (let ((?x5392 (+ ?x5373 ?x5391)))
 (let ((?x5408 (+ ?x5392 ?x5407)))
 (let (($x5279 (or false root_59)))
 (let (($x5295 (or $x5279 root_61)))
 (let (($x5314 (or $x5295 root_63)))
 (let (($x5330 (or $x5314 root_65)))
 (let (($x5349 (or $x5330 root_67)))
 (let (($x5371 (or $x5349 root_69)))
 (let (($x5390 (or $x5371 root_71)))
 (let (($x5406 (or $x5390 root_73)))
 (let (($x5243 (or c_8_1 c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_7 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x5236 (or c_7_1 c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_7 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x5229 (or c_6_1 c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_7 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x5222 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x5215 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x5208 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x5201 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x5194 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x5187 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x5278 (or false $x5187)))
 (let (($x5294 (or $x5278 $x5194)))
 (let (($x5313 (or $x5294 $x5201)))
 (let (($x5329 (or $x5313 $x5208)))
 (let (($x5348 (or $x5329 $x5215)))
 (let (($x5370 (or $x5348 $x5222)))
 (let (($x5389 (or $x5370 $x5229)))
 (let (($x5405 (or $x5389 $x5236)))
 (let (($x5432 (or false (and $x5236 (< rank_72 rank_74)))))
 (let (($x5436 (not root_75)))
 (let (($x5437 (and $x5243 $x5436)))
 (let (($x5413 (or false (and $x5243 (< rank_74 rank_72)))))
 (let (($x5416 (or $x5413 (and $x5229 (< rank_70 rank_72)))))
 (let (($x5420 (not root_73)))
 (let (($x5421 (and $x5236 $x5420)))
 (let (($x5397 (or false (and $x5236 (< rank_72 rank_70)))))
 (let (($x5401 (not root_71)))
 (let (($x5402 (and $x5229 $x5401)))
 (let (($x5378 (or false (and $x5243 (< rank_74 rank_68)))))
 (let (($x5381 (or $x5378 (and $x5215 (< rank_66 rank_68)))))
 (let (($x5385 (not root_69)))
 (let (($x5386 (and $x5222 $x5385)))
 (let (($x5356 (or false (and $x5222 (< rank_68 rank_66)))))
 (let (($x5359 (or $x5356 (and $x5236 (< rank_72 rank_66)))))
 (let (($x5362 (or $x5359 (and $x5208 (< rank_64 rank_66)))))
 (let (($x5366 (not root_67)))
 (let (($x5367 (and $x5215 $x5366)))
 (let (($x5337 (or false (and $x5215 (< rank_66 rank_64)))))
 (let (($x5340 (or $x5337 (and $x5229 (< rank_70 rank_64)))))
 (let (($x5344 (not root_65)))
 (let (($x5345 (and $x5208 $x5344)))
 (let (($x5321 (or false (and $x5222 (< rank_68 rank_62)))))
 (let (($x5325 (not root_63)))
 (let (($x5326 (and $x5201 $x5325)))
 (let (($x5302 (or false (and $x5201 (< rank_62 rank_60)))))
 (let (($x5305 (or $x5302 (and $x5215 (< rank_66 rank_60)))))
 (let (($x5309 (not root_61)))
 (let (($x5310 (and $x5194 $x5309)))
 (let (($x5286 (or false (and $x5194 (< rank_60 rank_58)))))
 (let (($x5290 (not root_59)))
 (let (($x5291 (and $x5187 $x5290)))
 (let (($x5283 (and true (=> root_59 $x5187))))
 (let (($x5293 (and $x5283 (=> $x5291 (or $x5286 (and $x5208 (< rank_64 rank_58)))))))
 (let (($x5299 (and $x5293 (=> root_61 $x5194))))
 (let (($x5312 (and $x5299 (=> $x5310 (or $x5305 (and $x5187 (< rank_58 rank_60)))))))
 (let (($x5318 (and $x5312 (=> root_63 $x5201))))
 (let (($x5328 (and $x5318 (=> $x5326 (or $x5321 (and $x5194 (< rank_60 rank_62)))))))
 (let (($x5334 (and $x5328 (=> root_65 $x5208))))
 (let (($x5347 (and $x5334 (=> $x5345 (or $x5340 (and $x5187 (< rank_58 rank_64)))))))
 (let (($x5353 (and $x5347 (=> root_67 $x5215))))
 (let (($x5369 (and $x5353 (=> $x5367 (or $x5362 (and $x5194 (< rank_60 rank_66)))))))
 (let (($x5375 (and $x5369 (=> root_69 $x5222))))
 (let (($x5388 (and $x5375 (=> $x5386 (or $x5381 (and $x5201 (< rank_62 rank_68)))))))
 (let (($x5394 (and $x5388 (=> root_71 $x5229))))
 (let (($x5404 (and $x5394 (=> $x5402 (or $x5397 (and $x5208 (< rank_64 rank_70)))))))
 (let (($x5410 (and $x5404 (=> root_73 $x5236))))
 (let (($x5423 (and $x5410 (=> $x5421 (or $x5416 (and $x5215 (< rank_66 rank_72)))))))
 (let (($x5429 (and $x5423 (=> root_75 $x5243))))
 (let (($x5441 (and (and $x5429 (=> $x5437 (or $x5432 (and $x5222 (< rank_68 rank_74))))) (=> (or $x5405 $x5243) (or $x5406 root_75)))))
 (let (($x5443 (and $x5441 (<= (+ ?x5408 ?x5426) 1))))
 (let (($x3504 (or c_8_1 c_8_7)))
 (let (($x5164 (and $x3504 (= prank_55 prank_high_57))))
 (let (($x3484 (or c_7_1 c_7_7)))
 (let (($x5141 (and $x3484 (= prank_54 prank_high_57))))
 (let (($x3539 (or c_6_1 c_6_7)))
 (let (($x5113 (and $x3539 (= prank_53 prank_high_57))))
 (let (($x3464 (or c_5_1 c_5_7)))
 (let (($x5090 (and $x3464 (= prank_52 prank_high_57))))
 (let (($x3448 (or c_4_1 c_4_7)))
 (let (($x5062 (and $x3448 (= prank_51 prank_high_57))))
 (let (($x3511 (or c_3_1 c_3_7)))
 (let (($x5029 (and $x3511 (= prank_50 prank_high_57))))
 (let (($x3429 (or c_2_1 c_2_7)))
 (let (($x5001 (and $x3429 (= prank_49 prank_high_57))))
 (let (($x3407 (or c_1_1 c_1_7)))
 (let (($x4978 (and $x3407 (= prank_48 prank_high_57))))
 (let (($x3565 (or c_0_1 c_0_7)))
 (let (($x4950 (and $x3565 (= prank_47 prank_high_57))))
 (let (($x4951 (or false $x4950)))
 (let (($x4979 (or $x4951 $x4978)))
 (let (($x5002 (or $x4979 $x5001)))
 (let (($x5030 (or $x5002 $x5029)))
 (let (($x5063 (or $x5030 $x5062)))
 (let (($x5091 (or $x5063 $x5090)))
 (let (($x5114 (or $x5091 $x5113)))
 (let (($x5142 (or $x5114 $x5141)))
 (let (($x5161 (and $x3504 (= prank_55 prank_low_56))))
 (let (($x5138 (and $x3484 (= prank_54 prank_low_56))))
 (let (($x5110 (and $x3539 (= prank_53 prank_low_56))))
 (let (($x5087 (and $x3464 (= prank_52 prank_low_56))))
 (let (($x5059 (and $x3448 (= prank_51 prank_low_56))))
 (let (($x5026 (and $x3511 (= prank_50 prank_low_56))))
 (let (($x4998 (and $x3429 (= prank_49 prank_low_56))))
 (let (($x4975 (and $x3407 (= prank_48 prank_low_56))))
 (let (($x4947 (and $x3565 (= prank_47 prank_low_56))))
 (let (($x4948 (or false $x4947)))
 (let (($x4976 (or $x4948 $x4975)))
 (let (($x4999 (or $x4976 $x4998)))
 (let (($x5027 (or $x4999 $x5026)))
 (let (($x5060 (or $x5027 $x5059)))
 (let (($x5088 (or $x5060 $x5087)))
 (let (($x5111 (or $x5088 $x5110)))
 (let (($x5139 (or $x5111 $x5138)))
 (let (($x4945 (or false $x3565)))
 (let (($x4973 (or $x4945 $x3407)))
 (let (($x4996 (or $x4973 $x3429)))
 (let (($x5024 (or $x4996 $x3511)))
 (let (($x5057 (or $x5024 $x3448)))
 (let (($x5085 (or $x5057 $x3464)))
 (let (($x5108 (or $x5085 $x3539)))
 (let (($x5136 (or $x5108 $x3484)))
 (let (($x4881 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4893 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x5147 (or false (and true (or $x4893 (and $x3484 (< prank_54 prank_55)))))))
 (let (($x5154 (and (or $x5147 (and true (or $x4881 (and $x3464 (< prank_52 prank_55))))) (<= prank_low_56 prank_55))))
 (let (($x4875 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4887 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x4899 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x5119 (or false (and true (or $x4899 (and $x3504 (< prank_55 prank_54)))))))
 (let (($x5124 (or $x5119 (and true (or $x4887 (and $x3539 (< prank_53 prank_54)))))))
 (let (($x5131 (and (or $x5124 (and true (or $x4875 (and $x3448 (< prank_51 prank_54))))) (<= prank_low_56 prank_54))))
 (let (($x4869 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x5096 (or false (and true (or $x4893 (and $x3484 (< prank_54 prank_53)))))))
 (let (($x5103 (and (or $x5096 (and true (or $x4869 (and $x3511 (< prank_50 prank_53))))) (<= prank_low_56 prank_53))))
 (let (($x4863 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x5068 (or false (and true (or $x4899 (and $x3504 (< prank_55 prank_52)))))))
 (let (($x5073 (or $x5068 (and true (or $x4875 (and $x3448 (< prank_51 prank_52)))))))
 (let (($x5080 (and (or $x5073 (and true (or $x4863 (and $x3429 (< prank_49 prank_52))))) (<= prank_low_56 prank_52))))
 (let (($x4857 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x5035 (or false (and true (or $x4881 (and $x3464 (< prank_52 prank_51)))))))
 (let (($x5040 (or $x5035 (and true (or $x4893 (and $x3484 (< prank_54 prank_51)))))))
 (let (($x5045 (or $x5040 (and true (or $x4869 (and $x3511 (< prank_50 prank_51)))))))
 (let (($x5052 (and (or $x5045 (and true (or $x4857 (and $x3407 (< prank_48 prank_51))))) (<= prank_low_56 prank_51))))
 (let (($x4851 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x5007 (or false (and true (or $x4875 (and $x3448 (< prank_51 prank_50)))))))
 (let (($x5012 (or $x5007 (and true (or $x4887 (and $x3539 (< prank_53 prank_50)))))))
 (let (($x5019 (and (or $x5012 (and true (or $x4851 (and $x3565 (< prank_47 prank_50))))) (<= prank_low_56 prank_50))))
 (let (($x4984 (or false (and true (or $x4881 (and $x3464 (< prank_52 prank_49)))))))
 (let (($x4991 (and (or $x4984 (and true (or $x4857 (and $x3407 (< prank_48 prank_49))))) (<= prank_low_56 prank_49))))
 (let (($x4956 (or false (and true (or $x4863 (and $x3429 (< prank_49 prank_48)))))))
 (let (($x4961 (or $x4956 (and true (or $x4875 (and $x3448 (< prank_51 prank_48)))))))
 (let (($x4968 (and (or $x4961 (and true (or $x4851 (and $x3565 (< prank_47 prank_48))))) (<= prank_low_56 prank_48))))
 (let (($x4933 (or false (and true (or $x4857 (and $x3407 (< prank_48 prank_47)))))))
 (let (($x4940 (and (or $x4933 (and true (or $x4869 (and $x3511 (< prank_50 prank_47))))) (<= prank_low_56 prank_47))))
 (let (($x4944 (and true (=> $x3565 (and $x4940 (<= prank_47 prank_high_57))))))
 (let (($x4972 (and $x4944 (=> $x3407 (and $x4968 (<= prank_48 prank_high_57))))))
 (let (($x4995 (and $x4972 (=> $x3429 (and $x4991 (<= prank_49 prank_high_57))))))
 (let (($x5023 (and $x4995 (=> $x3511 (and $x5019 (<= prank_50 prank_high_57))))))
 (let (($x5056 (and $x5023 (=> $x3448 (and $x5052 (<= prank_51 prank_high_57))))))
 (let (($x5084 (and $x5056 (=> $x3464 (and $x5080 (<= prank_52 prank_high_57))))))
 (let (($x5107 (and $x5084 (=> $x3539 (and $x5103 (<= prank_53 prank_high_57))))))
 (let (($x5135 (and $x5107 (=> $x3484 (and $x5131 (<= prank_54 prank_high_57))))))
 (let (($x5158 (and $x5135 (=> $x3504 (and $x5154 (<= prank_55 prank_high_57))))))
 (let (($x5168 (and $x5158 (=> (or $x5136 $x3504) (and (or $x5139 $x5161) (or $x5142 $x5164))))))
 (let (($x3595 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_8 c_8_9 c_8_10 c_8_11)))
 (let (($x4831 (and $x3595 (= prank_44 prank_high_46))))
 (let (($x3508 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_8 c_7_9 c_7_10 c_7_11)))
 (let (($x4808 (and $x3508 (= prank_43 prank_high_46))))
 (let (($x3489 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_8 c_6_9 c_6_10 c_6_11)))
 (let (($x4780 (and $x3489 (= prank_42 prank_high_46))))
 (let (($x3561 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_8 c_5_9 c_5_10 c_5_11)))
 (let (($x4757 (and $x3561 (= prank_41 prank_high_46))))
 (let (($x3470 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_8 c_4_9 c_4_10 c_4_11)))
 (let (($x4729 (and $x3470 (= prank_40 prank_high_46))))
 (let (($x3451 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_8 c_3_9 c_3_10 c_3_11)))
 (let (($x4696 (and $x3451 (= prank_39 prank_high_46))))
 (let (($x3536 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_8 c_2_9 c_2_10 c_2_11)))
 (let (($x4668 (and $x3536 (= prank_38 prank_high_46))))
 (let (($x3432 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_8 c_1_9 c_1_10 c_1_11)))
 (let (($x4645 (and $x3432 (= prank_37 prank_high_46))))
 (let (($x3413 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_8 c_0_9 c_0_10 c_0_11)))
 (let (($x4617 (and $x3413 (= prank_36 prank_high_46))))
 (let (($x4618 (or false $x4617)))
 (let (($x4646 (or $x4618 $x4645)))
 (let (($x4669 (or $x4646 $x4668)))
 (let (($x4697 (or $x4669 $x4696)))
 (let (($x4730 (or $x4697 $x4729)))
 (let (($x4758 (or $x4730 $x4757)))
 (let (($x4781 (or $x4758 $x4780)))
 (let (($x4809 (or $x4781 $x4808)))
 (let (($x4828 (and $x3595 (= prank_44 prank_low_45))))
 (let (($x4805 (and $x3508 (= prank_43 prank_low_45))))
 (let (($x4777 (and $x3489 (= prank_42 prank_low_45))))
 (let (($x4754 (and $x3561 (= prank_41 prank_low_45))))
 (let (($x4726 (and $x3470 (= prank_40 prank_low_45))))
 (let (($x4693 (and $x3451 (= prank_39 prank_low_45))))
 (let (($x4665 (and $x3536 (= prank_38 prank_low_45))))
 (let (($x4642 (and $x3432 (= prank_37 prank_low_45))))
 (let (($x4614 (and $x3413 (= prank_36 prank_low_45))))
 (let (($x4615 (or false $x4614)))
 (let (($x4643 (or $x4615 $x4642)))
 (let (($x4666 (or $x4643 $x4665)))
 (let (($x4694 (or $x4666 $x4693)))
 (let (($x4727 (or $x4694 $x4726)))
 (let (($x4755 (or $x4727 $x4754)))
 (let (($x4778 (or $x4755 $x4777)))
 (let (($x4806 (or $x4778 $x4805)))
 (let (($x4612 (or false $x3413)))
 (let (($x4640 (or $x4612 $x3432)))
 (let (($x4663 (or $x4640 $x3536)))
 (let (($x4691 (or $x4663 $x3451)))
 (let (($x4724 (or $x4691 $x3470)))
 (let (($x4752 (or $x4724 $x3561)))
 (let (($x4775 (or $x4752 $x3489)))
 (let (($x4803 (or $x4775 $x3508)))
 (let (($x3954 (or c_8_5 c_8_11)))
 (let (($x4818 (and $x3954 (or (or c_5_6 c_5_12) (and $x3561 (< prank_41 prank_44))))))
 (let (($x3879 (or c_8_4 c_8_10)))
 (let (($x4813 (and $x3879 (or (or c_7_6 c_7_12) (and $x3508 (< prank_43 prank_44))))))
 (let (($x4814 (or false $x4813)))
 (let (($x4823 (and (and (or $x4814 $x4818) (<= prank_low_45 prank_44)) (<= prank_44 prank_high_46))))
 (let (($x3815 (or c_7_5 c_7_11)))
 (let (($x4795 (and $x3815 (or (or c_4_6 c_4_12) (and $x3470 (< prank_40 prank_43))))))
 (let (($x3848 (or c_7_4 c_7_10)))
 (let (($x4790 (and $x3848 (or (or c_6_6 c_6_12) (and $x3489 (< prank_42 prank_43))))))
 (let (($x4003 (or c_7_2 c_7_8)))
 (let (($x4785 (and $x4003 (or (or c_8_6 c_8_12) (and $x3595 (< prank_44 prank_43))))))
 (let (($x4786 (or false $x4785)))
 (let (($x4791 (or $x4786 $x4790)))
 (let (($x4800 (and (and (or $x4791 $x4795) (<= prank_low_45 prank_43)) (<= prank_43 prank_high_46))))
 (let (($x3780 (or c_6_5 c_6_11)))
 (let (($x4767 (and $x3780 (or (or c_3_6 c_3_12) (and $x3451 (< prank_39 prank_42))))))
 (let (($x3880 (or c_6_2 c_6_8)))
 (let (($x4762 (and $x3880 (or (or c_7_6 c_7_12) (and $x3508 (< prank_43 prank_42))))))
 (let (($x4763 (or false $x4762)))
 (let (($x4772 (and (and (or $x4763 $x4767) (<= prank_low_45 prank_42)) (<= prank_42 prank_high_46))))
 (let (($x3919 (or c_5_5 c_5_11)))
 (let (($x4744 (and $x3919 (or (or c_2_6 c_2_12) (and $x3536 (< prank_38 prank_41))))))
 (let (($x3813 (or c_5_4 c_5_10)))
 (let (($x4739 (and $x3813 (or (or c_4_6 c_4_12) (and $x3470 (< prank_40 prank_41))))))
 (let (($x4005 (or c_5_3 c_5_9)))
 (let (($x4734 (and $x4005 (or (or c_8_6 c_8_12) (and $x3595 (< prank_44 prank_41))))))
 (let (($x4735 (or false $x4734)))
 (let (($x4740 (or $x4735 $x4739)))
 (let (($x4749 (and (and (or $x4740 $x4744) (<= prank_low_45 prank_41)) (<= prank_41 prank_high_46))))
 (let (($x3747 (or c_4_5 c_4_11)))
 (let (($x4716 (and $x3747 (or (or c_1_6 c_1_12) (and $x3432 (< prank_37 prank_40))))))
 (let (($x3778 (or c_4_4 c_4_10)))
 (let (($x4711 (and $x3778 (or (or c_3_6 c_3_12) (and $x3451 (< prank_39 prank_40))))))
 (let (($x3882 (or c_4_3 c_4_9)))
 (let (($x4706 (and $x3882 (or (or c_7_6 c_7_12) (and $x3508 (< prank_43 prank_40))))))
 (let (($x3955 (or c_4_2 c_4_8)))
 (let (($x4701 (and $x3955 (or (or c_5_6 c_5_12) (and $x3561 (< prank_41 prank_40))))))
 (let (($x4702 (or false $x4701)))
 (let (($x4707 (or $x4702 $x4706)))
 (let (($x4712 (or $x4707 $x4711)))
 (let (($x4721 (and (and (or $x4712 $x4716) (<= prank_low_45 prank_40)) (<= prank_40 prank_high_46))))
 (let (($x3714 (or c_3_5 c_3_11)))
 (let (($x4683 (and $x3714 (or (or c_0_6 c_0_12) (and $x3413 (< prank_36 prank_39))))))
 (let (($x3850 (or c_3_3 c_3_9)))
 (let (($x4678 (and $x3850 (or (or c_6_6 c_6_12) (and $x3489 (< prank_42 prank_39))))))
 (let (($x3816 (or c_3_2 c_3_8)))
 (let (($x4673 (and $x3816 (or (or c_4_6 c_4_12) (and $x3470 (< prank_40 prank_39))))))
 (let (($x4674 (or false $x4673)))
 (let (($x4679 (or $x4674 $x4678)))
 (let (($x4688 (and (and (or $x4679 $x4683) (<= prank_low_45 prank_39)) (<= prank_39 prank_high_46))))
 (let (($x3745 (or c_2_4 c_2_10)))
 (let (($x4655 (and $x3745 (or (or c_1_6 c_1_12) (and $x3432 (< prank_37 prank_38))))))
 (let (($x3957 (or c_2_3 c_2_9)))
 (let (($x4650 (and $x3957 (or (or c_5_6 c_5_12) (and $x3561 (< prank_41 prank_38))))))
 (let (($x4651 (or false $x4650)))
 (let (($x4660 (and (and (or $x4651 $x4655) (<= prank_low_45 prank_38)) (<= prank_38 prank_high_46))))
 (let (($x3712 (or c_1_4 c_1_10)))
 (let (($x4632 (and $x3712 (or (or c_0_6 c_0_12) (and $x3413 (< prank_36 prank_37))))))
 (let (($x3818 (or c_1_3 c_1_9)))
 (let (($x4627 (and $x3818 (or (or c_4_6 c_4_12) (and $x3470 (< prank_40 prank_37))))))
 (let (($x3920 (or c_1_2 c_1_8)))
 (let (($x4622 (and $x3920 (or (or c_2_6 c_2_12) (and $x3536 (< prank_38 prank_37))))))
 (let (($x4623 (or false $x4622)))
 (let (($x4628 (or $x4623 $x4627)))
 (let (($x4637 (and (and (or $x4628 $x4632) (<= prank_low_45 prank_37)) (<= prank_37 prank_high_46))))
 (let (($x3782 (or c_0_3 c_0_9)))
 (let (($x4604 (and $x3782 (or (or c_3_6 c_3_12) (and $x3451 (< prank_39 prank_36))))))
 (let (($x3748 (or c_0_2 c_0_8)))
 (let (($x4599 (and $x3748 (or (or c_1_6 c_1_12) (and $x3432 (< prank_37 prank_36))))))
 (let (($x4600 (or false $x4599)))
 (let (($x4609 (and (and (or $x4600 $x4604) (<= prank_low_45 prank_36)) (<= prank_36 prank_high_46))))
 (let (($x4611 (and true (=> $x3413 $x4609))))
 (let (($x4639 (and $x4611 (=> $x3432 $x4637))))
 (let (($x4662 (and $x4639 (=> $x3536 $x4660))))
 (let (($x4690 (and $x4662 (=> $x3451 $x4688))))
 (let (($x4723 (and $x4690 (=> $x3470 $x4721))))
 (let (($x4751 (and $x4723 (=> $x3561 $x4749))))
 (let (($x4774 (and $x4751 (=> $x3489 $x4772))))
 (let (($x4802 (and $x4774 (=> $x3508 $x4800))))
 (let (($x4825 (and $x4802 (=> $x3595 $x4823))))
 (let (($x4835 (and $x4825 (=> (or $x4803 $x3595) (and (or $x4806 $x4828) (or $x4809 $x4831))))))
 (let (($x1770 (not in_target_8)))
 (let (($x2831 (and c_8_12 $x1770)))
 (let (($x2812 (and c_8_6 $x1770)))
 (let (($x1755 (not in_target_7)))
 (let (($x2773 (and c_7_12 $x1755)))
 (let (($x2754 (and c_7_6 $x1755)))
 (let (($x4531 (or $x2754 $x2773)))
 (let (($x1740 (not in_target_6)))
 (let (($x2715 (and c_6_12 $x1740)))
 (let (($x2696 (and c_6_6 $x1740)))
 (let (($x4527 (or $x2696 $x2715)))
 (let (($x1725 (not in_target_5)))
 (let (($x2657 (and c_5_12 $x1725)))
 (let (($x2638 (and c_5_6 $x1725)))
 (let (($x4523 (or $x2638 $x2657)))
 (let (($x1710 (not in_target_4)))
 (let (($x2599 (and c_4_12 $x1710)))
 (let (($x2580 (and c_4_6 $x1710)))
 (let (($x4519 (or $x2580 $x2599)))
 (let (($x1695 (not in_target_3)))
 (let (($x2541 (and c_3_12 $x1695)))
 (let (($x2522 (and c_3_6 $x1695)))
 (let (($x4515 (or $x2522 $x2541)))
 (let (($x1680 (not in_target_2)))
 (let (($x2483 (and c_2_12 $x1680)))
 (let (($x2464 (and c_2_6 $x1680)))
 (let (($x4511 (or $x2464 $x2483)))
 (let (($x1665 (not in_target_1)))
 (let (($x2425 (and c_1_12 $x1665)))
 (let (($x2406 (and c_1_6 $x1665)))
 (let (($x4507 (or $x2406 $x2425)))
 (let (($x1652 (not in_target_0)))
 (let (($x2367 (and c_0_12 $x1652)))
 (let (($x2347 (and c_0_6 $x1652)))
 (let (($x4503 (or $x2347 $x2367)))
 (let (($x4501 (or false $x4503)))
 (let (($x4505 (or $x4501 $x4507)))
 (let (($x4509 (or $x4505 $x4511)))
 (let (($x4513 (or $x4509 $x4515)))
 (let (($x4517 (or $x4513 $x4519)))
 (let (($x4521 (or $x4517 $x4523)))
 (let (($x4525 (or $x4521 $x4527)))
 (let (($x4529 (or $x4525 $x4531)))
 (let ((?x4481 (ite root_35 1 0)))
 (let ((?x4463 (ite root_33 1 0)))
 (let ((?x4448 (ite root_31 1 0)))
 (let ((?x4430 (ite root_29 1 0)))
 (let ((?x4409 (ite root_27 1 0)))
 (let ((?x4391 (ite root_25 1 0)))
 (let ((?x4376 (ite root_23 1 0)))
 (let ((?x4358 (ite root_21 1 0)))
 (let ((?x4343 (ite root_19 1 0)))
 (let ((?x4344 (+ 0 ?x4343)))
 (let ((?x4359 (+ ?x4344 ?x4358)))
 (let ((?x4377 (+ ?x4359 ?x4376)))
 (let ((?x4392 (+ ?x4377 ?x4391)))
 (let ((?x4410 (+ ?x4392 ?x4409)))
 (let ((?x4431 (+ ?x4410 ?x4430)))
 (let ((?x4449 (+ ?x4431 ?x4448)))
 (let ((?x4464 (+ ?x4449 ?x4463)))
 (let (($x4342 (or false root_19)))
 (let (($x4357 (or $x4342 root_21)))
 (let (($x4375 (or $x4357 root_23)))
 (let (($x4390 (or $x4375 root_25)))
 (let (($x4408 (or $x4390 root_27)))
 (let (($x4429 (or $x4408 root_29)))
 (let (($x4447 (or $x4429 root_31)))
 (let (($x4462 (or $x4447 root_33)))
 (let (($x3149 (or c_8_6 c_8_12)))
 (let (($x3097 (or c_7_6 c_7_12)))
 (let (($x3089 (or c_6_6 c_6_12)))
 (let (($x3126 (or c_5_6 c_5_12)))
 (let (($x3081 (or c_4_6 c_4_12)))
 (let (($x3073 (or c_3_6 c_3_12)))
 (let (($x3112 (or c_2_6 c_2_12)))
 (let (($x3065 (or c_1_6 c_1_12)))
 (let (($x3057 (or c_0_6 c_0_12)))
 (let (($x4280 (or false $x3057)))
 (let (($x4283 (or $x4280 $x3065)))
 (let (($x4284 (or $x4283 $x3112)))
 (let (($x4286 (or $x4284 $x3073)))
 (let (($x4288 (or $x4286 $x3081)))
 (let (($x4290 (or $x4288 $x3126)))
 (let (($x4292 (or $x4290 $x3089)))
 (let (($x4294 (or $x4292 $x3097)))
 (let (($x4296 (or $x4294 $x3149)))
 (let (($x4487 (or false (and $x3097 (< rank_32 rank_34)))))
 (let (($x4491 (not root_35)))
 (let (($x4492 (and $x3149 $x4491)))
 (let (($x4469 (or false (and $x3149 (< rank_34 rank_32)))))
 (let (($x4472 (or $x4469 (and $x3089 (< rank_30 rank_32)))))
 (let (($x4476 (not root_33)))
 (let (($x4477 (and $x3097 $x4476)))
 (let (($x4454 (or false (and $x3097 (< rank_32 rank_30)))))
 (let (($x4458 (not root_31)))
 (let (($x4459 (and $x3089 $x4458)))
 (let (($x4436 (or false (and $x3149 (< rank_34 rank_28)))))
 (let (($x4439 (or $x4436 (and $x3081 (< rank_26 rank_28)))))
 (let (($x4443 (not root_29)))
 (let (($x4444 (and $x3126 $x4443)))
 (let (($x4415 (or false (and $x3126 (< rank_28 rank_26)))))
 (let (($x4418 (or $x4415 (and $x3097 (< rank_32 rank_26)))))
 (let (($x4421 (or $x4418 (and $x3073 (< rank_24 rank_26)))))
 (let (($x4425 (not root_27)))
 (let (($x4426 (and $x3081 $x4425)))
 (let (($x4397 (or false (and $x3081 (< rank_26 rank_24)))))
 (let (($x4400 (or $x4397 (and $x3089 (< rank_30 rank_24)))))
 (let (($x4404 (not root_25)))
 (let (($x4405 (and $x3073 $x4404)))
 (let (($x4382 (or false (and $x3126 (< rank_28 rank_22)))))
 (let (($x4386 (not root_23)))
 (let (($x4387 (and $x3112 $x4386)))
 (let (($x4364 (or false (and $x3112 (< rank_22 rank_20)))))
 (let (($x4367 (or $x4364 (and $x3081 (< rank_26 rank_20)))))
 (let (($x4371 (not root_21)))
 (let (($x4372 (and $x3065 $x4371)))
 (let (($x4349 (or false (and $x3065 (< rank_20 rank_18)))))
 (let (($x4353 (not root_19)))
 (let (($x4354 (and $x3057 $x4353)))
 (let (($x4346 (and true (=> root_19 $x3057))))
 (let (($x4356 (and $x4346 (=> $x4354 (or $x4349 (and $x3073 (< rank_24 rank_18)))))))
 (let (($x4361 (and $x4356 (=> root_21 $x3065))))
 (let (($x4374 (and $x4361 (=> $x4372 (or $x4367 (and $x3057 (< rank_18 rank_20)))))))
 (let (($x4379 (and $x4374 (=> root_23 $x3112))))
 (let (($x4389 (and $x4379 (=> $x4387 (or $x4382 (and $x3065 (< rank_20 rank_22)))))))
 (let (($x4394 (and $x4389 (=> root_25 $x3073))))
 (let (($x4407 (and $x4394 (=> $x4405 (or $x4400 (and $x3057 (< rank_18 rank_24)))))))
 (let (($x4412 (and $x4407 (=> root_27 $x3081))))
 (let (($x4428 (and $x4412 (=> $x4426 (or $x4421 (and $x3065 (< rank_20 rank_26)))))))
 (let (($x4433 (and $x4428 (=> root_29 $x3126))))
 (let (($x4446 (and $x4433 (=> $x4444 (or $x4439 (and $x3112 (< rank_22 rank_28)))))))
 (let (($x4451 (and $x4446 (=> root_31 $x3089))))
 (let (($x4461 (and $x4451 (=> $x4459 (or $x4454 (and $x3073 (< rank_24 rank_30)))))))
 (let (($x4466 (and $x4461 (=> root_33 $x3097))))
 (let (($x4479 (and $x4466 (=> $x4477 (or $x4472 (and $x3081 (< rank_26 rank_32)))))))
 (let (($x4484 (and $x4479 (=> root_35 $x3149))))
 (let (($x4496 (and (and $x4484 (=> $x4492 (or $x4487 (and $x3126 (< rank_28 rank_34))))) (=> $x4296 (or $x4462 root_35)))))
 (let (($x4498 (and $x4496 (<= (+ ?x4464 ?x4481) 1))))
 (let (($x5169 (and (and (and (and $x4296 $x4498) (not (or $x4529 (or $x2812 $x2831)))) $x4835) $x5168)))
 (let ((?x4007 (ite $x4005 1 0)))
 (let ((?x4004 (ite $x4003 1 0)))
 (let ((?x3704 (ite false 1 0)))
 (let ((?x3911 (+ 0 ?x3704)))
 (let ((?x3999 (+ ?x3911 ?x3704)))
 (let ((?x4006 (+ ?x3999 ?x4004)))
 (let (($x4001 (= (to_real (+ (+ ?x3999 (ite $x3484 1 0)) (ite $x3464 1 0))) 0.0)))
 (let (($x4011 (and $x4001 (= (to_real (+ ?x4006 ?x4007)) 0.0))))
 (let (($x3806 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6)))
 (let (($x3996 (or c_8_2 c_8_3 c_8_4 c_8_5)))
 (let (($x3995 (and true $x3996)))
 (let (($x4036 (and $x3995 $x3806)))
 (let (($x4037 (not (and $x4036 $x4011))))
 (let ((?x3887 (ite $x3882 1 0)))
 (let ((?x3885 (ite $x3880 1 0)))
 (let ((?x3881 (ite $x3879 1 0)))
 (let ((?x3883 (+ 0 ?x3881)))
 (let ((?x3884 (+ ?x3883 ?x3704)))
 (let ((?x3886 (+ ?x3884 ?x3885)))
 (let ((?x3733 (ite $x3448 1 0)))
 (let ((?x3771 (ite $x3539 1 0)))
 (let ((?x3872 (ite $x3504 1 0)))
 (let ((?x3869 (+ 0 ?x3872)))
 (let ((?x3871 (+ ?x3869 ?x3704)))
 (let ((?x3870 (+ ?x3871 ?x3771)))
 (let (($x3891 (and (= (to_real (+ ?x3870 ?x3733)) 0.0) (= (to_real (+ ?x3886 ?x3887)) 0.0))))
 (let (($x3772 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6)))
 (let (($x3864 (or c_7_2 c_7_3 c_7_4 c_7_5)))
 (let (($x3863 (and true $x3864)))
 (let (($x4032 (and $x3863 $x3772)))
 (let (($x4035 (not (and $x4032 $x3891))))
 (let ((?x3854 (ite $x3850 1 0)))
 (let ((?x3849 (ite $x3848 1 0)))
 (let ((?x3851 (+ 0 ?x3849)))
 (let ((?x3852 (+ ?x3851 ?x3704)))
 (let ((?x3853 (+ ?x3852 ?x3704)))
 (let ((?x3702 (ite $x3511 1 0)))
 (let ((?x3805 (ite $x3484 1 0)))
 (let ((?x3841 (+ 0 ?x3805)))
 (let ((?x3840 (+ ?x3841 ?x3704)))
 (let ((?x3839 (+ ?x3840 ?x3704)))
 (let (($x3858 (and (= (to_real (+ ?x3839 ?x3702)) 0.0) (= (to_real (+ ?x3853 ?x3854)) 0.0))))
 (let (($x3904 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6)))
 (let (($x3834 (or c_6_2 c_6_3 c_6_4 c_6_5)))
 (let (($x3833 (and true $x3834)))
 (let (($x4028 (and $x3833 $x3904)))
 (let (($x4031 (not (and $x4028 $x3858))))
 (let ((?x3961 (ite $x3957 1 0)))
 (let ((?x3959 (ite $x3955 1 0)))
 (let ((?x3956 (ite $x3954 1 0)))
 (let ((?x3958 (+ ?x3911 ?x3956)))
 (let ((?x3960 (+ ?x3958 ?x3959)))
 (let (($x3951 (= (to_real (+ (+ (+ ?x3911 ?x3872) ?x3733) (ite $x3429 1 0))) 0.0)))
 (let (($x3965 (and $x3951 (= (to_real (+ ?x3960 ?x3961)) 0.0))))
 (let (($x3737 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6)))
 (let (($x3946 (or c_5_2 c_5_3 c_5_4 c_5_5)))
 (let (($x3944 (and true $x3946)))
 (let (($x4022 (and $x3944 $x3737)))
 (let (($x4025 (not (and $x4022 $x3965))))
 (let ((?x3787 (ite $x3782 1 0)))
 (let ((?x3784 (ite $x3780 1 0)))
 (let ((?x3781 (ite $x3778 1 0)))
 (let ((?x3783 (+ 0 ?x3781)))
 (let ((?x3785 (+ ?x3783 ?x3784)))
 (let ((?x3786 (+ ?x3785 ?x3704)))
 (let ((?x3774 (to_real (+ (+ (+ (+ 0 ?x3733) ?x3771) ?x3704) (ite $x3565 1 0)))))
 (let (($x3791 (and (= ?x3774 0.0) (= (to_real (+ ?x3786 ?x3787)) 0.0))))
 (let (($x3978 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6)))
 (let (($x3763 (or c_3_2 c_3_3 c_3_4 c_3_5)))
 (let (($x3761 (and true $x3763)))
 (let (($x4015 (and $x3761 $x3978)))
 (let (($x4018 (not (and $x4015 $x3791))))
 (let (($x3843 (or c_7_1 c_7_2 c_7_3 c_7_4 c_7_5 c_7_6)))
 (let (($x3989 (and $x3995 $x3843)))
 (let (($x4013 (not (and $x3989 $x4011))))
 (let (($x3940 (or c_6_1 c_6_2 c_6_3 c_6_4 c_6_5 c_6_6)))
 (let (($x3991 (and $x3863 $x3940)))
 (let (($x3994 (not (and $x3991 $x3891))))
 (let (($x3990 (not (and (and $x3944 $x3772) $x3965))))
 (let ((?x3925 (to_real (+ (+ (+ ?x3911 (ite $x3919 1 0)) (ite $x3920 1 0)) ?x3704))))
 (let ((?x3915 (to_real (+ (+ (+ ?x3911 (ite $x3464 1 0)) (ite $x3407 1 0)) ?x3704))))
 (let (($x3927 (and (= ?x3915 0.0) (= ?x3925 0.0))))
 (let (($x3703 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6)))
 (let (($x3910 (or c_2_2 c_2_3 c_2_4 c_2_5)))
 (let (($x3907 (and true $x3910)))
 (let (($x3974 (and $x3907 $x3703)))
 (let (($x3979 (not (and $x3974 $x3927))))
 (let ((?x3752 (ite $x3748 1 0)))
 (let ((?x3750 (ite $x3747 1 0)))
 (let ((?x3746 (ite $x3745 1 0)))
 (let ((?x3749 (+ 0 ?x3746)))
 (let ((?x3751 (+ ?x3749 ?x3750)))
 (let ((?x3753 (+ ?x3751 ?x3752)))
 (let ((?x3738 (ite $x3565 1 0)))
 (let ((?x3735 (ite $x3429 1 0)))
 (let ((?x3734 (+ 0 ?x3735)))
 (let ((?x3736 (+ ?x3734 ?x3733)))
 (let ((?x3739 (+ ?x3736 ?x3738)))
 (let (($x3757 (and (= (to_real (+ ?x3739 ?x3704)) 0.0) (= (to_real (+ ?x3753 ?x3704)) 0.0))))
 (let (($x3728 (or c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x3727 (and true $x3728)))
 (let (($x3973 (and $x3727 $x3978)))
 (let (($x3976 (not (and $x3973 $x3757))))
 (let (($x3873 (or c_8_1 c_8_2 c_8_3 c_8_4 c_8_5 c_8_6)))
 (let (($x3945 (and $x3944 $x3873)))
 (let (($x3967 (not (and $x3945 $x3965))))
 (let (($x3939 (not (and (and $x3761 $x3940) $x3791))))
 (let (($x3929 (not (and (and $x3907 $x3806) $x3927))))
 (let (($x3908 (not (and (and $x3727 $x3772) $x3757))))
 (let ((?x3716 (ite $x3714 1 0)))
 (let ((?x3713 (ite $x3712 1 0)))
 (let ((?x3715 (+ 0 ?x3713)))
 (let ((?x3717 (+ ?x3715 ?x3716)))
 (let ((?x3718 (+ ?x3717 ?x3704)))
 (let ((?x3707 (to_real (+ (+ (+ (+ 0 (ite $x3407 1 0)) ?x3702) ?x3704) ?x3704))))
 (let (($x3722 (and (= ?x3707 0.0) (= (to_real (+ ?x3718 ?x3704)) 0.0))))
 (let (($x3694 (or c_0_2 c_0_3 c_0_4 c_0_5)))
 (let (($x3692 (and true $x3694)))
 (let (($x3899 (and $x3692 $x3904)))
 (let (($x3903 (not (and $x3899 $x3722))))
 (let (($x3893 (not (and (and $x3863 $x3873) $x3891))))
 (let (($x3860 (not (and (and $x3833 $x3843) $x3858))))
 (let (($x3793 (not (and (and $x3761 $x3772) $x3791))))
 (let (($x3759 (not (and (and $x3727 $x3737) $x3757))))
 (let (($x3724 (not (and (and $x3692 $x3703) $x3722))))
 (let (($x4256 (not in_target_36)))
 (let (($x4254 (not in_target_35)))
 (let (($x4252 (not in_target_34)))
 (let (($x4250 (not in_target_33)))
 (let (($x4248 (not in_target_32)))
 (let (($x4246 (not in_target_31)))
 (let (($x4244 (not in_target_30)))
 (let (($x4242 (not in_target_29)))
 (let (($x4240 (not in_target_28)))
 (let (($x4238 (not in_target_27)))
 (let (($x4236 (not in_target_26)))
 (let (($x4234 (not in_target_25)))
 (let (($x4232 (not in_target_24)))
 (let (($x4230 (not in_target_23)))
 (let (($x4228 (not in_target_22)))
 (let (($x4226 (not in_target_21)))
 (let (($x4224 (not in_target_20)))
 (let (($x4222 (not in_target_19)))
 (let (($x4220 (not in_target_18)))
 (let (($x4218 (not in_target_17)))
 (let (($x4216 (not in_target_16)))
 (let (($x4214 (not in_target_15)))
 (let (($x4212 (not in_target_14)))
 (let (($x4210 (not in_target_13)))
 (let (($x4208 (not in_target_12)))
 (let (($x4206 (not in_target_11)))
 (let (($x4204 (not in_target_10)))
 (let (($x4202 (not in_target_9)))
 (let (($x4203 (and true $x4202)))
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
 (let (($x4255 (and $x4253 $x4254)))
 (let (($x4257 (and $x4255 $x4256)))
 (let (($x4258 (and $x4257 $x3724)))
 (let (($x4261 (and $x4258 $x3759)))
 (let (($x4264 (and $x4261 $x3793)))
 (let (($x4266 (and $x4264 $x3860)))
 (let (($x4262 (and $x4266 $x3893)))
 (let (($x4265 (and $x4262 $x3903)))
 (let (($x4269 (and $x4265 $x3908)))
 (let (($x4267 (and $x4269 $x3929)))
 (let (($x4270 (and $x4267 $x3939)))
 (let (($x4271 (and $x4270 $x3967)))
 (let (($x4272 (and $x4271 $x3976)))
 (let (($x4263 (and $x4272 $x3979)))
 (let (($x4274 (and $x4263 $x3990)))
 (let (($x4276 (and $x4274 $x3994)))
 (let (($x4277 (and $x4276 $x4013)))
 (let (($x4268 (and $x4277 $x4018)))
 (let (($x4275 (and $x4268 $x4025)))
 (let (($x4279 (and $x4275 $x4031)))
 (let (($x4281 (and $x4279 $x4035)))
 (let (($x4157 (or c_8_7 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x4151 (and true $x4157)))
 (let (($x4100 (or c_7_7 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x4094 (and true $x4100)))
 (let (($x4090 (or c_6_7 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x4084 (and true $x4090)))
 (let (($x4132 (or c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4126 (and true $x4132)))
 (let (($x4080 (or c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4074 (and true $x4080)))
 (let (($x4070 (or c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x4064 (and true $x4070)))
 (let (($x4116 (or c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x4110 (and true $x4116)))
 (let (($x4060 (or c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x4054 (and true $x4060)))
 (let (($x4050 (or c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x4044 (and true $x4050)))
 (let ((?x3824 (ite $x3818 1 0)))
 (let ((?x3822 (ite $x3816 1 0)))
 (let ((?x3820 (ite $x3815 1 0)))
 (let ((?x3817 (ite $x3813 1 0)))
 (let ((?x3819 (+ 0 ?x3817)))
 (let ((?x3821 (+ ?x3819 ?x3820)))
 (let ((?x3823 (+ ?x3821 ?x3822)))
 (let ((?x3700 (ite $x3407 1 0)))
 (let ((?x3802 (ite $x3464 1 0)))
 (let ((?x3803 (+ 0 ?x3802)))
 (let ((?x3804 (+ ?x3803 ?x3805)))
 (let ((?x3807 (+ ?x3804 ?x3702)))
 (let (($x3828 (and (= (to_real (+ ?x3807 ?x3700)) 0.0) (= (to_real (+ ?x3823 ?x3824)) 0.0))))
 (let (($x3797 (or c_4_2 c_4_3 c_4_4 c_4_5)))
 (let (($x3795 (and true $x3797)))
 (let (($x4016 (and $x3795 $x3703)))
 (let (($x3393 (not (and (and true $x3149) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3390 (not (and (and true $x3097) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3387 (not (and (and true $x3089) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3384 (not (and (and true $x3126) (or (and c_2_1 $x1680) (and c_2_7 $x1680))))))
 (let (($x3381 (not (and (and true $x3081) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x3378 (not (and (and true $x3073) (or (and c_0_1 $x1652) (and c_0_7 $x1652))))))
 (let (($x3375 (not (and (and true $x3149) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3372 (not (and (and true $x3097) (or (and c_6_1 $x1740) (and c_6_7 $x1740))))))
 (let (($x3369 (not (and (and true $x3126) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3366 (not (and (and true $x3081) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3363 (not (and (and true $x3112) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x3360 (not (and (and true $x3065) (or (and c_0_1 $x1652) (and c_0_7 $x1652))))))
 (let (($x3356 (not (and (and true $x3126) (or (and c_8_1 $x1770) (and c_8_7 $x1770))))))
 (let (($x3353 (not (and (and true $x3081) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3350 (not (and (and true $x3073) (or (and c_6_1 $x1740) (and c_6_7 $x1740))))))
 (let (($x3346 (not (and (and true $x3112) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3343 (not (and (and true $x3065) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3340 (not (and (and true $x3057) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3336 (not (and (and true $x3097) (or (and c_8_1 $x1770) (and c_8_7 $x1770))))))
 (let (($x3332 (not (and (and true $x3089) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3328 (not (and (and true $x3081) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3324 (not (and (and true $x3073) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3320 (not (and (and true $x3065) (or (and c_2_1 $x1680) (and c_2_7 $x1680))))))
 (let (($x3315 (not (and (and true $x3057) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x2007 (and c_5_11 in_target_5)))
 (let (($x2005 (and c_5_10 in_target_5)))
 (let (($x2003 (and c_5_9 in_target_5)))
 (let (($x2001 (and c_5_8 in_target_5)))
 (let (($x1996 (and c_5_5 in_target_5)))
 (let (($x1994 (and c_5_4 in_target_5)))
 (let (($x1992 (and c_5_3 in_target_5)))
 (let (($x1990 (and c_5_2 in_target_5)))
 (let (($x3217 (or $x1990 $x1992 $x1994 $x1996 $x2001 $x2003 $x2005 $x2007)))
 (let (($x3147 (and true $x3149)))
 (let (($x1972 (and c_4_11 in_target_4)))
 (let (($x1970 (and c_4_10 in_target_4)))
 (let (($x1968 (and c_4_9 in_target_4)))
 (let (($x1966 (and c_4_8 in_target_4)))
 (let (($x1961 (and c_4_5 in_target_4)))
 (let (($x1959 (and c_4_4 in_target_4)))
 (let (($x1957 (and c_4_3 in_target_4)))
 (let (($x1955 (and c_4_2 in_target_4)))
 (let (($x3206 (or $x1955 $x1957 $x1959 $x1961 $x1966 $x1968 $x1970 $x1972)))
 (let (($x3095 (and true $x3097)))
 (let (($x1937 (and c_3_11 in_target_3)))
 (let (($x1935 (and c_3_10 in_target_3)))
 (let (($x1933 (and c_3_9 in_target_3)))
 (let (($x1931 (and c_3_8 in_target_3)))
 (let (($x1926 (and c_3_5 in_target_3)))
 (let (($x1924 (and c_3_4 in_target_3)))
 (let (($x1922 (and c_3_3 in_target_3)))
 (let (($x1920 (and c_3_2 in_target_3)))
 (let (($x3250 (or $x1920 $x1922 $x1924 $x1926 $x1931 $x1933 $x1935 $x1937)))
 (let (($x3087 (and true $x3089)))
 (let (($x1902 (and c_2_11 in_target_2)))
 (let (($x1900 (and c_2_10 in_target_2)))
 (let (($x1898 (and c_2_9 in_target_2)))
 (let (($x1896 (and c_2_8 in_target_2)))
 (let (($x1891 (and c_2_5 in_target_2)))
 (let (($x1889 (and c_2_4 in_target_2)))
 (let (($x1887 (and c_2_3 in_target_2)))
 (let (($x1885 (and c_2_2 in_target_2)))
 (let (($x3195 (or $x1885 $x1887 $x1889 $x1891 $x1896 $x1898 $x1900 $x1902)))
 (let (($x3124 (and true $x3126)))
 (let (($x1867 (and c_1_11 in_target_1)))
 (let (($x1865 (and c_1_10 in_target_1)))
 (let (($x1863 (and c_1_9 in_target_1)))
 (let (($x1861 (and c_1_8 in_target_1)))
 (let (($x1856 (and c_1_5 in_target_1)))
 (let (($x1854 (and c_1_4 in_target_1)))
 (let (($x1852 (and c_1_3 in_target_1)))
 (let (($x1850 (and c_1_2 in_target_1)))
 (let (($x3184 (or $x1850 $x1852 $x1854 $x1856 $x1861 $x1863 $x1865 $x1867)))
 (let (($x3079 (and true $x3081)))
 (let (($x1832 (and c_0_11 in_target_0)))
 (let (($x1830 (and c_0_10 in_target_0)))
 (let (($x1828 (and c_0_9 in_target_0)))
 (let (($x1826 (and c_0_8 in_target_0)))
 (let (($x1821 (and c_0_5 in_target_0)))
 (let (($x1819 (and c_0_4 in_target_0)))
 (let (($x1817 (and c_0_3 in_target_0)))
 (let (($x1815 (and c_0_2 in_target_0)))
 (let (($x3284 (or $x1815 $x1817 $x1819 $x1821 $x1826 $x1828 $x1830 $x1832)))
 (let (($x3071 (and true $x3073)))
 (let (($x2077 (and c_7_11 in_target_7)))
 (let (($x2075 (and c_7_10 in_target_7)))
 (let (($x2073 (and c_7_9 in_target_7)))
 (let (($x2071 (and c_7_8 in_target_7)))
 (let (($x2066 (and c_7_5 in_target_7)))
 (let (($x2064 (and c_7_4 in_target_7)))
 (let (($x2062 (and c_7_3 in_target_7)))
 (let (($x2060 (and c_7_2 in_target_7)))
 (let (($x3228 (or $x2060 $x2062 $x2064 $x2066 $x2071 $x2073 $x2075 $x2077)))
 (let (($x2042 (and c_6_11 in_target_6)))
 (let (($x2040 (and c_6_10 in_target_6)))
 (let (($x2038 (and c_6_9 in_target_6)))
 (let (($x2036 (and c_6_8 in_target_6)))
 (let (($x2031 (and c_6_5 in_target_6)))
 (let (($x2029 (and c_6_4 in_target_6)))
 (let (($x2027 (and c_6_3 in_target_6)))
 (let (($x2025 (and c_6_2 in_target_6)))
 (let (($x3267 (or $x2025 $x2027 $x2029 $x2031 $x2036 $x2038 $x2040 $x2042)))
 (let (($x2112 (and c_8_11 in_target_8)))
 (let (($x2110 (and c_8_10 in_target_8)))
 (let (($x2108 (and c_8_9 in_target_8)))
 (let (($x2106 (and c_8_8 in_target_8)))
 (let (($x2101 (and c_8_5 in_target_8)))
 (let (($x2099 (and c_8_4 in_target_8)))
 (let (($x2097 (and c_8_3 in_target_8)))
 (let (($x2095 (and c_8_2 in_target_8)))
 (let (($x3239 (or $x2095 $x2097 $x2099 $x2101 $x2106 $x2108 $x2110 $x2112)))
 (let (($x3168 (not (and $x3147 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3165 (not (and $x3095 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3162 (not (and $x3087 (or (and c_3_1 in_target_3) (and c_3_7 in_target_3))))))
 (let (($x3159 (not (and $x3124 (or (and c_2_1 in_target_2) (and c_2_7 in_target_2))))))
 (let (($x3156 (not (and $x3079 (or (and c_1_1 in_target_1) (and c_1_7 in_target_1))))))
 (let (($x3153 (not (and $x3071 (or (and c_0_1 in_target_0) (and c_0_7 in_target_0))))))
 (let (($x3150 (not (and $x3147 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3143 (not (and $x3095 (or (and c_6_1 in_target_6) (and c_6_7 in_target_6))))))
 (let (($x3140 (not (and $x3124 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3137 (not (and $x3079 (or (and c_3_1 in_target_3) (and c_3_7 in_target_3))))))
 (let (($x1859 (and c_1_7 in_target_1)))
 (let (($x1848 (and c_1_1 in_target_1)))
 (let (($x3058 (or $x1848 $x1859)))
 (let (($x3110 (and true $x3112)))
 (let (($x1824 (and c_0_7 in_target_0)))
 (let (($x1813 (and c_0_1 in_target_0)))
 (let (($x3130 (or $x1813 $x1824)))
 (let (($x3063 (and true $x3065)))
 (let (($x3127 (not (and $x3124 (or (and c_8_1 in_target_8) (and c_8_7 in_target_8))))))
 (let (($x3120 (not (and $x3079 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3117 (not (and $x3071 (or (and c_6_1 in_target_6) (and c_6_7 in_target_6))))))
 (let (($x3113 (not (and $x3110 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3106 (not (and $x3063 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x1929 (and c_3_7 in_target_3)))
 (let (($x1918 (and c_3_1 in_target_3)))
 (let (($x3102 (or $x1918 $x1929)))
 (let (($x3055 (and true $x3057)))
 (let (($x3099 (not (and $x3095 (or (and c_8_1 in_target_8) (and c_8_7 in_target_8))))))
 (let (($x3091 (not (and $x3087 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3083 (not (and $x3079 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3075 (not (and $x3071 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3067 (not (and $x3063 (or (and c_2_1 in_target_2) (and c_2_7 in_target_2))))))
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
 (let ((?x3027 (ite (or $x2803 $x2804 $x2806 $x2808 $x2810 $x2812) 1 0)))
 (let (($x2093 (and c_8_1 in_target_8)))
 (let (($x1784 (and c_8_6 in_target_8)))
 (let ((?x3025 (ite (or $x1784 $x2093 $x2095 $x2097 $x2099 $x2101) (- 1) 0)))
 (let (($x2092 (and c_8_0 in_target_8)))
 (let ((?x3026 (ite $x2092 (- 2) 0)))
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
 (let ((?x3004 (ite (or $x2745 $x2746 $x2748 $x2750 $x2752 $x2754) 1 0)))
 (let (($x2058 (and c_7_1 in_target_7)))
 (let (($x1769 (and c_7_6 in_target_7)))
 (let ((?x3000 (ite (or $x1769 $x2058 $x2060 $x2062 $x2064 $x2066) (- 1) 0)))
 (let (($x2057 (and c_7_0 in_target_7)))
 (let ((?x2997 (ite $x2057 (- 2) 0)))
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
 (let ((?x2991 (ite (or $x2687 $x2688 $x2690 $x2692 $x2694 $x2696) 1 0)))
 (let (($x2023 (and c_6_1 in_target_6)))
 (let (($x1754 (and c_6_6 in_target_6)))
 (let ((?x2984 (ite (or $x1754 $x2023 $x2025 $x2027 $x2029 $x2031) (- 1) 0)))
 (let (($x2022 (and c_6_0 in_target_6)))
 (let ((?x2979 (ite $x2022 (- 2) 0)))
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
 (let ((?x2957 (ite (or $x2629 $x2630 $x2632 $x2634 $x2636 $x2638) 1 0)))
 (let (($x1988 (and c_5_1 in_target_5)))
 (let (($x1739 (and c_5_6 in_target_5)))
 (let ((?x2965 (ite (or $x1739 $x1988 $x1990 $x1992 $x1994 $x1996) (- 1) 0)))
 (let (($x1987 (and c_5_0 in_target_5)))
 (let ((?x2960 (ite $x1987 (- 2) 0)))
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
 (let ((?x2949 (ite (or $x2571 $x2572 $x2574 $x2576 $x2578 $x2580) 1 0)))
 (let (($x1953 (and c_4_1 in_target_4)))
 (let (($x1724 (and c_4_6 in_target_4)))
 (let ((?x2938 (ite (or $x1724 $x1953 $x1955 $x1957 $x1959 $x1961) (- 1) 0)))
 (let (($x1952 (and c_4_0 in_target_4)))
 (let ((?x2944 (ite $x1952 (- 2) 0)))
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
 (let ((?x2928 (ite (or $x2513 $x2514 $x2516 $x2518 $x2520 $x2522) 1 0)))
 (let ((?x2922 (ite (or (and c_3_6 in_target_3) $x1918 $x1920 $x1922 $x1924 $x1926) (- 1) 0)))
 (let (($x1917 (and c_3_0 in_target_3)))
 (let ((?x2918 (ite $x1917 (- 2) 0)))
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
 (let ((?x2899 (ite (or $x2455 $x2456 $x2458 $x2460 $x2462 $x2464) 1 0)))
 (let (($x1883 (and c_2_1 in_target_2)))
 (let (($x1694 (and c_2_6 in_target_2)))
 (let ((?x2897 (ite (or $x1694 $x1883 $x1885 $x1887 $x1889 $x1891) (- 1) 0)))
 (let (($x1882 (and c_2_0 in_target_2)))
 (let ((?x2898 (ite $x1882 (- 2) 0)))
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
 (let ((?x2883 (ite (or $x2397 $x2398 $x2400 $x2402 $x2404 $x2406) 1 0)))
 (let ((?x2876 (ite (or (and c_1_6 in_target_1) $x1848 $x1850 $x1852 $x1854 $x1856) (- 1) 0)))
 (let (($x1847 (and c_1_0 in_target_1)))
 (let ((?x2875 (ite $x1847 (- 2) 0)))
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
 (let ((?x2863 (ite (or $x2338 $x2339 $x2341 $x2343 $x2345 $x2347) 1 0)))
 (let ((?x2859 (ite (or (and c_0_6 in_target_0) $x1813 $x1815 $x1817 $x1819 $x1821) (- 1) 0)))
 (let (($x1812 (and c_0_0 in_target_0)))
 (let ((?x2852 (ite $x1812 (- 2) 0)))
 (let ((?x2853 (+ 0 ?x2852)))
 (let ((?x2862 (+ ?x2853 ?x2859)))
 (let ((?x2860 (+ ?x2862 ?x2863)))
 (let ((?x2861 (+ ?x2860 ?x2356)))
 (let ((?x2879 (+ ?x2861 ?x2875)))
 (let ((?x2880 (+ ?x2879 ?x2876)))
 (let ((?x2884 (+ ?x2880 ?x2883)))
 (let ((?x2881 (+ ?x2884 ?x2414)))
 (let ((?x2895 (+ ?x2881 ?x2898)))
 (let ((?x2904 (+ ?x2895 ?x2897)))
 (let ((?x2907 (+ ?x2904 ?x2899)))
 (let ((?x2901 (+ ?x2907 ?x2472)))
 (let ((?x2916 (+ ?x2901 ?x2918)))
 (let ((?x2926 (+ ?x2916 ?x2922)))
 (let ((?x2920 (+ ?x2926 ?x2928)))
 (let ((?x2919 (+ ?x2920 ?x2530)))
 (let ((?x2935 (+ ?x2919 ?x2944)))
 (let ((?x2947 (+ ?x2935 ?x2938)))
 (let ((?x2937 (+ ?x2947 ?x2949)))
 (let ((?x2943 (+ ?x2937 ?x2588)))
 (let ((?x2956 (+ ?x2943 ?x2960)))
 (let ((?x2962 (+ ?x2956 ?x2965)))
 (let ((?x2968 (+ ?x2962 ?x2957)))
 (let ((?x2970 (+ ?x2968 ?x2646)))
 (let ((?x2978 (+ ?x2970 ?x2979)))
 (let ((?x2989 (+ ?x2978 ?x2984)))
 (let ((?x2986 (+ ?x2989 ?x2991)))
 (let ((?x2988 (+ ?x2986 ?x2704)))
 (let ((?x3005 (+ ?x2988 ?x2997)))
 (let ((?x3009 (+ ?x3005 ?x3000)))
 (let ((?x3012 (+ ?x3009 ?x3004)))
 (let ((?x3006 (+ ?x3012 ?x2762)))
 (let ((?x3018 (+ ?x3006 ?x3026)))
 (let ((?x3020 (+ ?x3018 ?x3025)))
 (let ((?x3031 (+ ?x3020 ?x3027)))
 (let (($x3045 (<= (+ ?x3031 ?x2820) 0)))
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
 (let (($x3052 (and $x1781 (and (and $x2315 $x2839) $x3045))))
 (let (($x3060 (and $x3052 (not (and $x3055 $x3058)))))
 (let (($x3068 (and $x3060 $x3067)))
 (let (($x3076 (and $x3068 $x3075)))
 (let (($x3084 (and $x3076 $x3083)))
 (let (($x3092 (and $x3084 $x3091)))
 (let (($x3100 (and $x3092 $x3099)))
 (let (($x3104 (and $x3100 (not (and $x3055 $x3102)))))
 (let (($x3107 (and $x3104 $x3106)))
 (let (($x3114 (and $x3107 $x3113)))
 (let (($x3118 (and $x3114 $x3117)))
 (let (($x3121 (and $x3118 $x3120)))
 (let (($x3128 (and $x3121 $x3127)))
 (let (($x3132 (and $x3128 (not (and $x3063 $x3130)))))
 (let (($x3135 (and $x3132 (not (and $x3110 $x3058)))))
 (let (($x3138 (and $x3135 $x3137)))
 (let (($x3141 (and $x3138 $x3140)))
 (let (($x3144 (and $x3141 $x3143)))
 (let (($x3151 (and $x3144 $x3150)))
 (let (($x3154 (and $x3151 $x3153)))
 (let (($x3157 (and $x3154 $x3156)))
 (let (($x3160 (and $x3157 $x3159)))
 (let (($x3163 (and $x3160 $x3162)))
 (let (($x3166 (and $x3163 $x3165)))
 (let (($x3169 (and $x3166 $x3168)))
 (let (($x3178 (and $x3169 (not (and $x3055 $x3184)))))
 (let (($x3191 (and $x3178 (not (and $x3063 $x3195)))))
 (let (($x3200 (and $x3191 (not (and $x3071 $x3206)))))
 (let (($x3212 (and $x3200 (not (and $x3079 $x3217)))))
 (let (($x3222 (and $x3212 (not (and $x3087 $x3228)))))
 (let (($x3234 (and $x3222 (not (and $x3095 $x3239)))))
 (let (($x3248 (and $x3234 (not (and $x3055 $x3250)))))
 (let (($x3246 (and $x3248 (not (and $x3063 $x3206)))))
 (let (($x3253 (and $x3246 (not (and $x3110 $x3217)))))
 (let (($x3265 (and $x3253 (not (and $x3071 $x3267)))))
 (let (($x3263 (and $x3265 (not (and $x3079 $x3228)))))
 (let (($x3270 (and $x3263 (not (and $x3124 $x3239)))))
 (let (($x3278 (and $x3270 (not (and $x3063 $x3284)))))
 (let (($x3281 (and $x3278 (not (and $x3110 $x3184)))))
 (let (($x3289 (and $x3281 (not (and $x3079 $x3250)))))
 (let (($x3279 (and $x3289 (not (and $x3124 $x3206)))))
 (let (($x3295 (and $x3279 (not (and $x3095 $x3267)))))
 (let (($x3290 (and $x3295 (not (and $x3147 $x3228)))))
 (let (($x3297 (and $x3290 (not (and $x3071 $x3284)))))
 (let (($x3300 (and $x3297 (not (and $x3079 $x3184)))))
 (let (($x3299 (and $x3300 (not (and $x3124 $x3195)))))
 (let (($x3310 (and $x3299 (not (and $x3087 $x3250)))))
 (let (($x3306 (and $x3310 (not (and $x3095 $x3206)))))
 (let (($x3314 (and $x3306 (not (and $x3147 $x3217)))))
 (let (($x3311 (and $x3314 $x3315)))
 (let (($x3321 (and $x3311 $x3320)))
 (let (($x3325 (and $x3321 $x3324)))
 (let (($x3329 (and $x3325 $x3328)))
 (let (($x3333 (and $x3329 $x3332)))
 (let (($x3337 (and $x3333 $x3336)))
 (let (($x3341 (and $x3337 $x3340)))
 (let (($x3344 (and $x3341 $x3343)))
 (let (($x3347 (and $x3344 $x3346)))
 (let (($x3351 (and $x3347 $x3350)))
 (let (($x3354 (and $x3351 $x3353)))
 (let (($x3357 (and $x3354 $x3356)))
 (let (($x3361 (and $x3357 $x3360)))
 (let (($x3364 (and $x3361 $x3363)))
 (let (($x3367 (and $x3364 $x3366)))
 (let (($x3370 (and $x3367 $x3369)))
 (let (($x3373 (and $x3370 $x3372)))
 (let (($x3376 (and $x3373 $x3375)))
 (let (($x3379 (and $x3376 $x3378)))
 (let (($x3382 (and $x3379 $x3381)))
 (let (($x3385 (and $x3382 $x3384)))
 (let (($x3388 (and $x3385 $x3387)))
 (let (($x3391 (and $x3388 $x3390)))
 (let (($x3394 (and $x3391 $x3393)))
 (let (($x3409 (and $x3394 (not (and (and true $x3413) $x3407)))))
 (let (($x3430 (and $x3409 (not (and (and true $x3432) $x3429)))))
 (let (($x3450 (and $x3430 (not (and (and true $x3451) $x3448)))))
 (let (($x3465 (and $x3450 (not (and (and true $x3470) $x3464)))))
 (let (($x3488 (and $x3465 (not (and (and true $x3489) $x3484)))))
 (let (($x3505 (and $x3488 (not (and (and true $x3508) $x3504)))))
 (let (($x3514 (and $x3505 (not (and (and true $x3413) $x3511)))))
 (let (($x3517 (and $x3514 (not (and (and true $x3432) $x3448)))))
 (let (($x3535 (and $x3517 (not (and (and true $x3536) $x3464)))))
 (let (($x3537 (and $x3535 (not (and (and true $x3451) $x3539)))))
 (let (($x3546 (and $x3537 (not (and (and true $x3470) $x3484)))))
 (let (($x3555 (and $x3546 (not (and (and true $x3561) $x3504)))))
 (let (($x3559 (and $x3555 (not (and (and true $x3432) $x3565)))))
 (let (($x3569 (and $x3559 (not (and (and true $x3536) $x3407)))))
 (let (($x3574 (and $x3569 (not (and (and true $x3470) $x3511)))))
 (let (($x3570 (and $x3574 (not (and (and true $x3561) $x3448)))))
 (let (($x3576 (and $x3570 (not (and (and true $x3508) $x3539)))))
 (let (($x3593 (and $x3576 (not (and (and true $x3595) $x3484)))))
 (let (($x3594 (and $x3593 (not (and (and true $x3451) $x3565)))))
 (let (($x3602 (and $x3594 (not (and (and true $x3470) $x3407)))))
 (let (($x3596 (and $x3602 (not (and (and true $x3561) $x3429)))))
 (let (($x3605 (and $x3596 (not (and (and true $x3489) $x3511)))))
 (let (($x3601 (and $x3605 (not (and (and true $x3508) $x3448)))))
 (let (($x3612 (and $x3601 (not (and (and true $x3595) $x3464)))))
 (let (($x3614 (and $x3612 (not (and (and true c_0_12) $x1847)))))
 (let (($x3618 (and $x3614 (not (and (and true c_1_12) $x1882)))))
 (let (($x3622 (and $x3618 (not (and (and true c_3_12) $x1952)))))
 (let (($x3626 (and $x3622 (not (and (and true c_4_12) $x1987)))))
 (let (($x3630 (and $x3626 (not (and (and true c_6_12) $x2057)))))
 (let (($x3634 (and $x3630 (not (and (and true c_7_12) $x2092)))))
 (let (($x3637 (and $x3634 (not (and (and true c_0_12) $x1917)))))
 (let (($x3640 (and $x3637 (not (and (and true c_1_12) $x1952)))))
 (let (($x3644 (and $x3640 (not (and (and true c_2_12) $x1987)))))
 (let (($x3647 (and $x3644 (not (and (and true c_3_12) $x2022)))))
 (let (($x3650 (and $x3647 (not (and (and true c_4_12) $x2057)))))
 (let (($x3654 (and $x3650 (not (and (and true c_5_12) $x2092)))))
 (let (($x3657 (and $x3654 (not (and (and true c_1_12) $x1812)))))
 (let (($x3660 (and $x3657 (not (and (and true c_2_12) $x1847)))))
 (let (($x3663 (and $x3660 (not (and (and true c_4_12) $x1917)))))
 (let (($x3666 (and $x3663 (not (and (and true c_5_12) $x1952)))))
 (let (($x3669 (and $x3666 (not (and (and true c_7_12) $x2022)))))
 (let (($x3673 (and $x3669 (not (and (and true c_8_12) $x2057)))))
 (let (($x3676 (and $x3673 (not (and (and true c_3_12) $x1812)))))
 (let (($x3679 (and $x3676 (not (and (and true c_4_12) $x1847)))))
 (let (($x3682 (and $x3679 (not (and (and true c_5_12) $x1882)))))
 (let (($x3685 (and $x3682 (not (and (and true c_6_12) $x1917)))))
 (let (($x3688 (and $x3685 (not (and (and true c_7_12) $x1952)))))
 (let (($x3691 (and $x3688 (not (and (and true c_8_12) $x1987)))))
 (let (($x3725 (and $x3691 $x3724)))
 (let (($x3760 (and $x3725 $x3759)))
 (let (($x3794 (and $x3760 $x3793)))
 (let (($x3831 (and $x3794 (not (and (and $x3795 $x3806) $x3828)))))
 (let (($x3861 (and $x3831 $x3860)))
 (let (($x3894 (and $x3861 $x3893)))
 (let (($x3902 (and $x3894 $x3903)))
 (let (($x3906 (and $x3902 $x3908)))
 (let (($x3930 (and $x3906 $x3929)))
 (let (($x3938 (and $x3930 $x3939)))
 (let (($x3941 (and $x3938 (not (and (and $x3795 $x3843) $x3828)))))
 (let (($x3968 (and $x3941 $x3967)))
 (let (($x3977 (and $x3968 $x3976)))
 (let (($x3982 (and $x3977 $x3979)))
 (let (($x3985 (and $x3982 (not (and (and $x3795 $x3904) $x3828)))))
 (let (($x3988 (and $x3985 $x3990)))
 (let (($x3993 (and $x3988 $x3994)))
 (let (($x4014 (and $x3993 $x4013)))
 (let (($x4019 (and $x4014 $x4018)))
 (let (($x4023 (and $x4019 (not (and $x4016 $x3828)))))
 (let (($x4024 (and $x4023 $x4025)))
 (let (($x4030 (and $x4024 $x4031)))
 (let (($x4033 (and $x4030 $x4035)))
 (let (($x4039 (and $x4033 $x4037)))
 (let (($x4048 (and $x4039 (not (and $x4044 $x3703)))))
 (let (($x4056 (and $x4048 (not (and $x4054 $x3737)))))
 (let (($x4068 (and $x4056 (not (and $x4064 $x3772)))))
 (let (($x4079 (and $x4068 (not (and $x4074 $x3806)))))
 (let (($x4086 (and $x4079 (not (and $x4084 $x3843)))))
 (let (($x4096 (and $x4086 (not (and $x4094 $x3873)))))
 (let (($x4101 (and $x4096 (not (and $x4044 $x3904)))))
 (let (($x4107 (and $x4101 (not (and $x4054 $x3772)))))
 (let (($x4112 (and $x4107 (not (and $x4110 $x3806)))))
 (let (($x4117 (and $x4112 (not (and $x4064 $x3940)))))
 (let (($x4122 (and $x4117 (not (and $x4074 $x3843)))))
 (let (($x4128 (and $x4122 (not (and $x4126 $x3873)))))
 (let (($x4133 (and $x4128 (not (and $x4054 $x3978)))))
 (let (($x4129 (and $x4133 (not (and $x4110 $x3703)))))
 (let (($x4140 (and $x4129 (not (and $x4074 $x3904)))))
 (let (($x4144 (and $x4140 (not (and $x4126 $x3772)))))
 (let (($x4147 (and $x4144 (not (and $x4094 $x3940)))))
 (let (($x4154 (and $x4147 (not (and $x4151 $x3843)))))
 (let (($x4159 (and $x4154 (not (and $x4064 $x3978)))))
 (let (($x4156 (and $x4159 (not (and $x4074 $x3703)))))
 (let (($x4160 (and $x4156 (not (and $x4126 $x3737)))))
 (let (($x4169 (and $x4160 (not (and $x4084 $x3904)))))
 (let (($x4172 (and $x4169 (not (and $x4094 $x3772)))))
 (let (($x4173 (and $x4172 (not (and $x4151 $x3806)))))
 (let (($x4278 (and $x4173 (and $x4281 $x4037))))
 (and $x4278 (and $x5169 $x5443))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
