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
 (let (($x4335 (>= rank_18 0)))
 (and $x4335 (< rank_18 9))))
(assert
 (let (($x4340 (>= rank_20 0)))
 (and $x4340 (< rank_20 9))))
(assert
 (let (($x4345 (>= rank_22 0)))
 (and $x4345 (< rank_22 9))))
(assert
 (let (($x4350 (>= rank_24 0)))
 (and $x4350 (< rank_24 9))))
(assert
 (let (($x4355 (>= rank_26 0)))
 (and $x4355 (< rank_26 9))))
(assert
 (let (($x4360 (>= rank_28 0)))
 (and $x4360 (< rank_28 9))))
(assert
 (let (($x4365 (>= rank_30 0)))
 (and $x4365 (< rank_30 9))))
(assert
 (let (($x4370 (>= rank_32 0)))
 (and $x4370 (< rank_32 9))))
(assert
 (let (($x4375 (>= rank_34 0)))
 (and $x4375 (< rank_34 9))))
(assert
 (let (($x4591 (>= prank_36 0)))
 (and $x4591 (< prank_36 9))))
(assert
 (let (($x4599 (>= prank_37 0)))
 (and $x4599 (< prank_37 9))))
(assert
 (let (($x4603 (>= prank_38 0)))
 (and $x4603 (< prank_38 9))))
(assert
 (let (($x4607 (>= prank_39 0)))
 (and $x4607 (< prank_39 9))))
(assert
 (let (($x4611 (>= prank_40 0)))
 (and $x4611 (< prank_40 9))))
(assert
 (let (($x4615 (>= prank_41 0)))
 (and $x4615 (< prank_41 9))))
(assert
 (let (($x4619 (>= prank_42 0)))
 (and $x4619 (< prank_42 9))))
(assert
 (let (($x4623 (>= prank_43 0)))
 (and $x4623 (< prank_43 9))))
(assert
 (let (($x4627 (>= prank_44 0)))
 (and $x4627 (< prank_44 9))))
(assert
 (let (($x4929 (>= prank_47 0)))
 (and $x4929 (< prank_47 9))))
(assert
 (let (($x4933 (>= prank_48 0)))
 (and $x4933 (< prank_48 9))))
(assert
 (let (($x4936 (>= prank_49 0)))
 (and $x4936 (< prank_49 9))))
(assert
 (let (($x4940 (>= prank_50 0)))
 (and $x4940 (< prank_50 9))))
(assert
 (let (($x4944 (>= prank_51 0)))
 (and $x4944 (< prank_51 9))))
(assert
 (let (($x4948 (>= prank_52 0)))
 (and $x4948 (< prank_52 9))))
(assert
 (let (($x4952 (>= prank_53 0)))
 (and $x4952 (< prank_53 9))))
(assert
 (let (($x4956 (>= prank_54 0)))
 (and $x4956 (< prank_54 9))))
(assert
 (let (($x4960 (>= prank_55 0)))
 (and $x4960 (< prank_55 9))))
(assert
 (let (($x5273 (>= rank_58 0)))
 (and $x5273 (< rank_58 9))))
(assert
 (let (($x5267 (>= rank_60 0)))
 (and $x5267 (< rank_60 9))))
(assert
 (let (($x5281 (>= rank_62 0)))
 (and $x5281 (< rank_62 9))))
(assert
 (let (($x5286 (>= rank_64 0)))
 (and $x5286 (< rank_64 9))))
(assert
 (let (($x5291 (>= rank_66 0)))
 (and $x5291 (< rank_66 9))))
(assert
 (let (($x5296 (>= rank_68 0)))
 (and $x5296 (< rank_68 9))))
(assert
 (let (($x5301 (>= rank_70 0)))
 (and $x5301 (< rank_70 9))))
(assert
 (let (($x5306 (>= rank_72 0)))
 (and $x5306 (< rank_72 9))))
(assert
 (let (($x5311 (>= rank_74 0)))
 (and $x5311 (< rank_74 9))))
(assert
 (let ((?x5462 (ite root_75 1 0)))
 (let ((?x5443 (ite root_73 1 0)))
 (let ((?x5427 (ite root_71 1 0)))
 (let ((?x5408 (ite root_69 1 0)))
 (let ((?x5386 (ite root_67 1 0)))
 (let ((?x5367 (ite root_65 1 0)))
 (let ((?x5351 (ite root_63 1 0)))
 (let ((?x5332 (ite root_61 1 0)))
 (let ((?x5316 (ite root_59 1 0)))
 (let ((?x5317 (+ 0 ?x5316)))
 (let ((?x5333 (+ ?x5317 ?x5332)))
 (let ((?x5352 (+ ?x5333 ?x5351)))
 (let ((?x5368 (+ ?x5352 ?x5367)))
 (let ((?x5387 (+ ?x5368 ?x5386)))
 (let ((?x5409 (+ ?x5387 ?x5408)))
 (let ((?x5428 (+ ?x5409 ?x5427)))
 (let ((?x5444 (+ ?x5428 ?x5443)))
 (let (($x5315 (or false root_59)))
 (let (($x5331 (or $x5315 root_61)))
 (let (($x5350 (or $x5331 root_63)))
 (let (($x5366 (or $x5350 root_65)))
 (let (($x5385 (or $x5366 root_67)))
 (let (($x5407 (or $x5385 root_69)))
 (let (($x5426 (or $x5407 root_71)))
 (let (($x5442 (or $x5426 root_73)))
 (let (($x5278 (or c_8_1 c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_7 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x5271 (or c_7_1 c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_7 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x5264 (or c_6_1 c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_7 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x5257 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x5250 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x5243 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x5236 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x5229 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x5222 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x5314 (or false $x5222)))
 (let (($x5330 (or $x5314 $x5229)))
 (let (($x5349 (or $x5330 $x5236)))
 (let (($x5365 (or $x5349 $x5243)))
 (let (($x5384 (or $x5365 $x5250)))
 (let (($x5406 (or $x5384 $x5257)))
 (let (($x5425 (or $x5406 $x5264)))
 (let (($x5441 (or $x5425 $x5271)))
 (let (($x5468 (or false (and $x5271 (< rank_72 rank_74)))))
 (let (($x5472 (not root_75)))
 (let (($x5473 (and $x5278 $x5472)))
 (let (($x5449 (or false (and $x5278 (< rank_74 rank_72)))))
 (let (($x5452 (or $x5449 (and $x5264 (< rank_70 rank_72)))))
 (let (($x5456 (not root_73)))
 (let (($x5457 (and $x5271 $x5456)))
 (let (($x5433 (or false (and $x5271 (< rank_72 rank_70)))))
 (let (($x5437 (not root_71)))
 (let (($x5438 (and $x5264 $x5437)))
 (let (($x5414 (or false (and $x5278 (< rank_74 rank_68)))))
 (let (($x5417 (or $x5414 (and $x5250 (< rank_66 rank_68)))))
 (let (($x5421 (not root_69)))
 (let (($x5422 (and $x5257 $x5421)))
 (let (($x5392 (or false (and $x5257 (< rank_68 rank_66)))))
 (let (($x5395 (or $x5392 (and $x5271 (< rank_72 rank_66)))))
 (let (($x5398 (or $x5395 (and $x5243 (< rank_64 rank_66)))))
 (let (($x5402 (not root_67)))
 (let (($x5403 (and $x5250 $x5402)))
 (let (($x5373 (or false (and $x5250 (< rank_66 rank_64)))))
 (let (($x5376 (or $x5373 (and $x5264 (< rank_70 rank_64)))))
 (let (($x5380 (not root_65)))
 (let (($x5381 (and $x5243 $x5380)))
 (let (($x5357 (or false (and $x5257 (< rank_68 rank_62)))))
 (let (($x5361 (not root_63)))
 (let (($x5362 (and $x5236 $x5361)))
 (let (($x5338 (or false (and $x5236 (< rank_62 rank_60)))))
 (let (($x5341 (or $x5338 (and $x5250 (< rank_66 rank_60)))))
 (let (($x5345 (not root_61)))
 (let (($x5346 (and $x5229 $x5345)))
 (let (($x5322 (or false (and $x5229 (< rank_60 rank_58)))))
 (let (($x5326 (not root_59)))
 (let (($x5327 (and $x5222 $x5326)))
 (let (($x5319 (and true (=> root_59 $x5222))))
 (let (($x5329 (and $x5319 (=> $x5327 (or $x5322 (and $x5243 (< rank_64 rank_58)))))))
 (let (($x5335 (and $x5329 (=> root_61 $x5229))))
 (let (($x5348 (and $x5335 (=> $x5346 (or $x5341 (and $x5222 (< rank_58 rank_60)))))))
 (let (($x5354 (and $x5348 (=> root_63 $x5236))))
 (let (($x5364 (and $x5354 (=> $x5362 (or $x5357 (and $x5229 (< rank_60 rank_62)))))))
 (let (($x5370 (and $x5364 (=> root_65 $x5243))))
 (let (($x5383 (and $x5370 (=> $x5381 (or $x5376 (and $x5222 (< rank_58 rank_64)))))))
 (let (($x5389 (and $x5383 (=> root_67 $x5250))))
 (let (($x5405 (and $x5389 (=> $x5403 (or $x5398 (and $x5229 (< rank_60 rank_66)))))))
 (let (($x5411 (and $x5405 (=> root_69 $x5257))))
 (let (($x5424 (and $x5411 (=> $x5422 (or $x5417 (and $x5236 (< rank_62 rank_68)))))))
 (let (($x5430 (and $x5424 (=> root_71 $x5264))))
 (let (($x5440 (and $x5430 (=> $x5438 (or $x5433 (and $x5243 (< rank_64 rank_70)))))))
 (let (($x5446 (and $x5440 (=> root_73 $x5271))))
 (let (($x5459 (and $x5446 (=> $x5457 (or $x5452 (and $x5250 (< rank_66 rank_72)))))))
 (let (($x5465 (and $x5459 (=> root_75 $x5278))))
 (let (($x5477 (and (and $x5465 (=> $x5473 (or $x5468 (and $x5257 (< rank_68 rank_74))))) (=> (or $x5441 $x5278) (or $x5442 root_75)))))
 (let (($x5479 (and $x5477 (<= (+ ?x5444 ?x5462) 1))))
 (let (($x3666 (or c_8_1 c_8_7)))
 (let (($x5200 (and $x3666 (= prank_55 prank_high_57))))
 (let (($x3651 (or c_7_1 c_7_7)))
 (let (($x5177 (and $x3651 (= prank_54 prank_high_57))))
 (let (($x3687 (or c_6_1 c_6_7)))
 (let (($x5149 (and $x3687 (= prank_53 prank_high_57))))
 (let (($x3633 (or c_5_1 c_5_7)))
 (let (($x5126 (and $x3633 (= prank_52 prank_high_57))))
 (let (($x3622 (or c_4_1 c_4_7)))
 (let (($x5098 (and $x3622 (= prank_51 prank_high_57))))
 (let (($x3671 (or c_3_1 c_3_7)))
 (let (($x5065 (and $x3671 (= prank_50 prank_high_57))))
 (let (($x3610 (or c_2_1 c_2_7)))
 (let (($x5037 (and $x3610 (= prank_49 prank_high_57))))
 (let (($x3592 (or c_1_1 c_1_7)))
 (let (($x5014 (and $x3592 (= prank_48 prank_high_57))))
 (let (($x3708 (or c_0_1 c_0_7)))
 (let (($x4986 (and $x3708 (= prank_47 prank_high_57))))
 (let (($x4987 (or false $x4986)))
 (let (($x5015 (or $x4987 $x5014)))
 (let (($x5038 (or $x5015 $x5037)))
 (let (($x5066 (or $x5038 $x5065)))
 (let (($x5099 (or $x5066 $x5098)))
 (let (($x5127 (or $x5099 $x5126)))
 (let (($x5150 (or $x5127 $x5149)))
 (let (($x5178 (or $x5150 $x5177)))
 (let (($x5197 (and $x3666 (= prank_55 prank_low_56))))
 (let (($x5174 (and $x3651 (= prank_54 prank_low_56))))
 (let (($x5146 (and $x3687 (= prank_53 prank_low_56))))
 (let (($x5123 (and $x3633 (= prank_52 prank_low_56))))
 (let (($x5095 (and $x3622 (= prank_51 prank_low_56))))
 (let (($x5062 (and $x3671 (= prank_50 prank_low_56))))
 (let (($x5034 (and $x3610 (= prank_49 prank_low_56))))
 (let (($x5011 (and $x3592 (= prank_48 prank_low_56))))
 (let (($x4983 (and $x3708 (= prank_47 prank_low_56))))
 (let (($x4984 (or false $x4983)))
 (let (($x5012 (or $x4984 $x5011)))
 (let (($x5035 (or $x5012 $x5034)))
 (let (($x5063 (or $x5035 $x5062)))
 (let (($x5096 (or $x5063 $x5095)))
 (let (($x5124 (or $x5096 $x5123)))
 (let (($x5147 (or $x5124 $x5146)))
 (let (($x5175 (or $x5147 $x5174)))
 (let (($x4981 (or false $x3708)))
 (let (($x5009 (or $x4981 $x3592)))
 (let (($x5032 (or $x5009 $x3610)))
 (let (($x5060 (or $x5032 $x3671)))
 (let (($x5093 (or $x5060 $x3622)))
 (let (($x5121 (or $x5093 $x3633)))
 (let (($x5144 (or $x5121 $x3687)))
 (let (($x5172 (or $x5144 $x3651)))
 (let (($x4916 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4928 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x5183 (or false (and true (or $x4928 (and $x3651 (< prank_54 prank_55)))))))
 (let (($x5190 (and (or $x5183 (and true (or $x4916 (and $x3633 (< prank_52 prank_55))))) (<= prank_low_56 prank_55))))
 (let (($x4910 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4922 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x4934 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x5155 (or false (and true (or $x4934 (and $x3666 (< prank_55 prank_54)))))))
 (let (($x5160 (or $x5155 (and true (or $x4922 (and $x3687 (< prank_53 prank_54)))))))
 (let (($x5167 (and (or $x5160 (and true (or $x4910 (and $x3622 (< prank_51 prank_54))))) (<= prank_low_56 prank_54))))
 (let (($x4904 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x5132 (or false (and true (or $x4928 (and $x3651 (< prank_54 prank_53)))))))
 (let (($x5139 (and (or $x5132 (and true (or $x4904 (and $x3671 (< prank_50 prank_53))))) (<= prank_low_56 prank_53))))
 (let (($x4898 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x5104 (or false (and true (or $x4934 (and $x3666 (< prank_55 prank_52)))))))
 (let (($x5109 (or $x5104 (and true (or $x4910 (and $x3622 (< prank_51 prank_52)))))))
 (let (($x5116 (and (or $x5109 (and true (or $x4898 (and $x3610 (< prank_49 prank_52))))) (<= prank_low_56 prank_52))))
 (let (($x4892 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x5071 (or false (and true (or $x4916 (and $x3633 (< prank_52 prank_51)))))))
 (let (($x5076 (or $x5071 (and true (or $x4928 (and $x3651 (< prank_54 prank_51)))))))
 (let (($x5081 (or $x5076 (and true (or $x4904 (and $x3671 (< prank_50 prank_51)))))))
 (let (($x5088 (and (or $x5081 (and true (or $x4892 (and $x3592 (< prank_48 prank_51))))) (<= prank_low_56 prank_51))))
 (let (($x4886 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x5043 (or false (and true (or $x4910 (and $x3622 (< prank_51 prank_50)))))))
 (let (($x5048 (or $x5043 (and true (or $x4922 (and $x3687 (< prank_53 prank_50)))))))
 (let (($x5055 (and (or $x5048 (and true (or $x4886 (and $x3708 (< prank_47 prank_50))))) (<= prank_low_56 prank_50))))
 (let (($x5020 (or false (and true (or $x4916 (and $x3633 (< prank_52 prank_49)))))))
 (let (($x5027 (and (or $x5020 (and true (or $x4892 (and $x3592 (< prank_48 prank_49))))) (<= prank_low_56 prank_49))))
 (let (($x4992 (or false (and true (or $x4898 (and $x3610 (< prank_49 prank_48)))))))
 (let (($x4997 (or $x4992 (and true (or $x4910 (and $x3622 (< prank_51 prank_48)))))))
 (let (($x5004 (and (or $x4997 (and true (or $x4886 (and $x3708 (< prank_47 prank_48))))) (<= prank_low_56 prank_48))))
 (let (($x4969 (or false (and true (or $x4892 (and $x3592 (< prank_48 prank_47)))))))
 (let (($x4976 (and (or $x4969 (and true (or $x4904 (and $x3671 (< prank_50 prank_47))))) (<= prank_low_56 prank_47))))
 (let (($x4980 (and true (=> $x3708 (and $x4976 (<= prank_47 prank_high_57))))))
 (let (($x5008 (and $x4980 (=> $x3592 (and $x5004 (<= prank_48 prank_high_57))))))
 (let (($x5031 (and $x5008 (=> $x3610 (and $x5027 (<= prank_49 prank_high_57))))))
 (let (($x5059 (and $x5031 (=> $x3671 (and $x5055 (<= prank_50 prank_high_57))))))
 (let (($x5092 (and $x5059 (=> $x3622 (and $x5088 (<= prank_51 prank_high_57))))))
 (let (($x5120 (and $x5092 (=> $x3633 (and $x5116 (<= prank_52 prank_high_57))))))
 (let (($x5143 (and $x5120 (=> $x3687 (and $x5139 (<= prank_53 prank_high_57))))))
 (let (($x5171 (and $x5143 (=> $x3651 (and $x5167 (<= prank_54 prank_high_57))))))
 (let (($x5194 (and $x5171 (=> $x3666 (and $x5190 (<= prank_55 prank_high_57))))))
 (let (($x5204 (and $x5194 (=> (or $x5172 $x3666) (and (or $x5175 $x5197) (or $x5178 $x5200))))))
 (let (($x3738 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_8 c_8_9 c_8_10 c_8_11)))
 (let (($x4867 (and $x3738 (= prank_44 prank_high_46))))
 (let (($x3667 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_8 c_7_9 c_7_10 c_7_11)))
 (let (($x4844 (and $x3667 (= prank_43 prank_high_46))))
 (let (($x3653 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_8 c_6_9 c_6_10 c_6_11)))
 (let (($x4816 (and $x3653 (= prank_42 prank_high_46))))
 (let (($x3709 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_8 c_5_9 c_5_10 c_5_11)))
 (let (($x4793 (and $x3709 (= prank_41 prank_high_46))))
 (let (($x3639 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_8 c_4_9 c_4_10 c_4_11)))
 (let (($x4765 (and $x3639 (= prank_40 prank_high_46))))
 (let (($x3625 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_8 c_3_9 c_3_10 c_3_11)))
 (let (($x4732 (and $x3625 (= prank_39 prank_high_46))))
 (let (($x3689 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_8 c_2_9 c_2_10 c_2_11)))
 (let (($x4704 (and $x3689 (= prank_38 prank_high_46))))
 (let (($x3611 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_8 c_1_9 c_1_10 c_1_11)))
 (let (($x4681 (and $x3611 (= prank_37 prank_high_46))))
 (let (($x3597 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_8 c_0_9 c_0_10 c_0_11)))
 (let (($x4653 (and $x3597 (= prank_36 prank_high_46))))
 (let (($x4654 (or false $x4653)))
 (let (($x4682 (or $x4654 $x4681)))
 (let (($x4705 (or $x4682 $x4704)))
 (let (($x4733 (or $x4705 $x4732)))
 (let (($x4766 (or $x4733 $x4765)))
 (let (($x4794 (or $x4766 $x4793)))
 (let (($x4817 (or $x4794 $x4816)))
 (let (($x4845 (or $x4817 $x4844)))
 (let (($x4864 (and $x3738 (= prank_44 prank_low_45))))
 (let (($x4841 (and $x3667 (= prank_43 prank_low_45))))
 (let (($x4813 (and $x3653 (= prank_42 prank_low_45))))
 (let (($x4790 (and $x3709 (= prank_41 prank_low_45))))
 (let (($x4762 (and $x3639 (= prank_40 prank_low_45))))
 (let (($x4729 (and $x3625 (= prank_39 prank_low_45))))
 (let (($x4701 (and $x3689 (= prank_38 prank_low_45))))
 (let (($x4678 (and $x3611 (= prank_37 prank_low_45))))
 (let (($x4650 (and $x3597 (= prank_36 prank_low_45))))
 (let (($x4651 (or false $x4650)))
 (let (($x4679 (or $x4651 $x4678)))
 (let (($x4702 (or $x4679 $x4701)))
 (let (($x4730 (or $x4702 $x4729)))
 (let (($x4763 (or $x4730 $x4762)))
 (let (($x4791 (or $x4763 $x4790)))
 (let (($x4814 (or $x4791 $x4813)))
 (let (($x4842 (or $x4814 $x4841)))
 (let (($x4648 (or false $x3597)))
 (let (($x4676 (or $x4648 $x3611)))
 (let (($x4699 (or $x4676 $x3689)))
 (let (($x4727 (or $x4699 $x3625)))
 (let (($x4760 (or $x4727 $x3639)))
 (let (($x4788 (or $x4760 $x3709)))
 (let (($x4811 (or $x4788 $x3653)))
 (let (($x4839 (or $x4811 $x3667)))
 (let (($x4097 (or c_8_5 c_8_11)))
 (let (($x4854 (and $x4097 (or (or c_5_6 c_5_12) (and $x3709 (< prank_41 prank_44))))))
 (let (($x4022 (or c_8_4 c_8_10)))
 (let (($x4849 (and $x4022 (or (or c_7_6 c_7_12) (and $x3667 (< prank_43 prank_44))))))
 (let (($x4850 (or false $x4849)))
 (let (($x4859 (and (and (or $x4850 $x4854) (<= prank_low_45 prank_44)) (<= prank_44 prank_high_46))))
 (let (($x3958 (or c_7_5 c_7_11)))
 (let (($x4831 (and $x3958 (or (or c_4_6 c_4_12) (and $x3639 (< prank_40 prank_43))))))
 (let (($x3991 (or c_7_4 c_7_10)))
 (let (($x4826 (and $x3991 (or (or c_6_6 c_6_12) (and $x3653 (< prank_42 prank_43))))))
 (let (($x4146 (or c_7_2 c_7_8)))
 (let (($x4821 (and $x4146 (or (or c_8_6 c_8_12) (and $x3738 (< prank_44 prank_43))))))
 (let (($x4822 (or false $x4821)))
 (let (($x4827 (or $x4822 $x4826)))
 (let (($x4836 (and (and (or $x4827 $x4831) (<= prank_low_45 prank_43)) (<= prank_43 prank_high_46))))
 (let (($x3923 (or c_6_5 c_6_11)))
 (let (($x4803 (and $x3923 (or (or c_3_6 c_3_12) (and $x3625 (< prank_39 prank_42))))))
 (let (($x4023 (or c_6_2 c_6_8)))
 (let (($x4798 (and $x4023 (or (or c_7_6 c_7_12) (and $x3667 (< prank_43 prank_42))))))
 (let (($x4799 (or false $x4798)))
 (let (($x4808 (and (and (or $x4799 $x4803) (<= prank_low_45 prank_42)) (<= prank_42 prank_high_46))))
 (let (($x4062 (or c_5_5 c_5_11)))
 (let (($x4780 (and $x4062 (or (or c_2_6 c_2_12) (and $x3689 (< prank_38 prank_41))))))
 (let (($x3956 (or c_5_4 c_5_10)))
 (let (($x4775 (and $x3956 (or (or c_4_6 c_4_12) (and $x3639 (< prank_40 prank_41))))))
 (let (($x4148 (or c_5_3 c_5_9)))
 (let (($x4770 (and $x4148 (or (or c_8_6 c_8_12) (and $x3738 (< prank_44 prank_41))))))
 (let (($x4771 (or false $x4770)))
 (let (($x4776 (or $x4771 $x4775)))
 (let (($x4785 (and (and (or $x4776 $x4780) (<= prank_low_45 prank_41)) (<= prank_41 prank_high_46))))
 (let (($x3890 (or c_4_5 c_4_11)))
 (let (($x4752 (and $x3890 (or (or c_1_6 c_1_12) (and $x3611 (< prank_37 prank_40))))))
 (let (($x3921 (or c_4_4 c_4_10)))
 (let (($x4747 (and $x3921 (or (or c_3_6 c_3_12) (and $x3625 (< prank_39 prank_40))))))
 (let (($x4025 (or c_4_3 c_4_9)))
 (let (($x4742 (and $x4025 (or (or c_7_6 c_7_12) (and $x3667 (< prank_43 prank_40))))))
 (let (($x4098 (or c_4_2 c_4_8)))
 (let (($x4737 (and $x4098 (or (or c_5_6 c_5_12) (and $x3709 (< prank_41 prank_40))))))
 (let (($x4738 (or false $x4737)))
 (let (($x4743 (or $x4738 $x4742)))
 (let (($x4748 (or $x4743 $x4747)))
 (let (($x4757 (and (and (or $x4748 $x4752) (<= prank_low_45 prank_40)) (<= prank_40 prank_high_46))))
 (let (($x3857 (or c_3_5 c_3_11)))
 (let (($x4719 (and $x3857 (or (or c_0_6 c_0_12) (and $x3597 (< prank_36 prank_39))))))
 (let (($x3993 (or c_3_3 c_3_9)))
 (let (($x4714 (and $x3993 (or (or c_6_6 c_6_12) (and $x3653 (< prank_42 prank_39))))))
 (let (($x3959 (or c_3_2 c_3_8)))
 (let (($x4709 (and $x3959 (or (or c_4_6 c_4_12) (and $x3639 (< prank_40 prank_39))))))
 (let (($x4710 (or false $x4709)))
 (let (($x4715 (or $x4710 $x4714)))
 (let (($x4724 (and (and (or $x4715 $x4719) (<= prank_low_45 prank_39)) (<= prank_39 prank_high_46))))
 (let (($x3888 (or c_2_4 c_2_10)))
 (let (($x4691 (and $x3888 (or (or c_1_6 c_1_12) (and $x3611 (< prank_37 prank_38))))))
 (let (($x4100 (or c_2_3 c_2_9)))
 (let (($x4686 (and $x4100 (or (or c_5_6 c_5_12) (and $x3709 (< prank_41 prank_38))))))
 (let (($x4687 (or false $x4686)))
 (let (($x4696 (and (and (or $x4687 $x4691) (<= prank_low_45 prank_38)) (<= prank_38 prank_high_46))))
 (let (($x3855 (or c_1_4 c_1_10)))
 (let (($x4668 (and $x3855 (or (or c_0_6 c_0_12) (and $x3597 (< prank_36 prank_37))))))
 (let (($x3961 (or c_1_3 c_1_9)))
 (let (($x4663 (and $x3961 (or (or c_4_6 c_4_12) (and $x3639 (< prank_40 prank_37))))))
 (let (($x4063 (or c_1_2 c_1_8)))
 (let (($x4658 (and $x4063 (or (or c_2_6 c_2_12) (and $x3689 (< prank_38 prank_37))))))
 (let (($x4659 (or false $x4658)))
 (let (($x4664 (or $x4659 $x4663)))
 (let (($x4673 (and (and (or $x4664 $x4668) (<= prank_low_45 prank_37)) (<= prank_37 prank_high_46))))
 (let (($x3925 (or c_0_3 c_0_9)))
 (let (($x4640 (and $x3925 (or (or c_3_6 c_3_12) (and $x3625 (< prank_39 prank_36))))))
 (let (($x3891 (or c_0_2 c_0_8)))
 (let (($x4635 (and $x3891 (or (or c_1_6 c_1_12) (and $x3611 (< prank_37 prank_36))))))
 (let (($x4636 (or false $x4635)))
 (let (($x4645 (and (and (or $x4636 $x4640) (<= prank_low_45 prank_36)) (<= prank_36 prank_high_46))))
 (let (($x4647 (and true (=> $x3597 $x4645))))
 (let (($x4675 (and $x4647 (=> $x3611 $x4673))))
 (let (($x4698 (and $x4675 (=> $x3689 $x4696))))
 (let (($x4726 (and $x4698 (=> $x3625 $x4724))))
 (let (($x4759 (and $x4726 (=> $x3639 $x4757))))
 (let (($x4787 (and $x4759 (=> $x3709 $x4785))))
 (let (($x4810 (and $x4787 (=> $x3653 $x4808))))
 (let (($x4838 (and $x4810 (=> $x3667 $x4836))))
 (let (($x4861 (and $x4838 (=> $x3738 $x4859))))
 (let (($x4871 (and $x4861 (=> (or $x4839 $x3738) (and (or $x4842 $x4864) (or $x4845 $x4867))))))
 (let (($x1770 (not in_target_8)))
 (let (($x2791 (and c_8_12 $x1770)))
 (let (($x2772 (and c_8_6 $x1770)))
 (let (($x1755 (not in_target_7)))
 (let (($x2738 (and c_7_12 $x1755)))
 (let (($x2719 (and c_7_6 $x1755)))
 (let (($x4567 (or $x2719 $x2738)))
 (let (($x1740 (not in_target_6)))
 (let (($x2685 (and c_6_12 $x1740)))
 (let (($x2666 (and c_6_6 $x1740)))
 (let (($x4563 (or $x2666 $x2685)))
 (let (($x1725 (not in_target_5)))
 (let (($x2632 (and c_5_12 $x1725)))
 (let (($x2613 (and c_5_6 $x1725)))
 (let (($x4559 (or $x2613 $x2632)))
 (let (($x1710 (not in_target_4)))
 (let (($x2579 (and c_4_12 $x1710)))
 (let (($x2560 (and c_4_6 $x1710)))
 (let (($x4555 (or $x2560 $x2579)))
 (let (($x1695 (not in_target_3)))
 (let (($x2526 (and c_3_12 $x1695)))
 (let (($x2507 (and c_3_6 $x1695)))
 (let (($x4551 (or $x2507 $x2526)))
 (let (($x1680 (not in_target_2)))
 (let (($x2473 (and c_2_12 $x1680)))
 (let (($x2454 (and c_2_6 $x1680)))
 (let (($x4547 (or $x2454 $x2473)))
 (let (($x1665 (not in_target_1)))
 (let (($x2420 (and c_1_12 $x1665)))
 (let (($x2401 (and c_1_6 $x1665)))
 (let (($x4543 (or $x2401 $x2420)))
 (let (($x1652 (not in_target_0)))
 (let (($x2367 (and c_0_12 $x1652)))
 (let (($x2347 (and c_0_6 $x1652)))
 (let (($x4539 (or $x2347 $x2367)))
 (let (($x4537 (or false $x4539)))
 (let (($x4541 (or $x4537 $x4543)))
 (let (($x4545 (or $x4541 $x4547)))
 (let (($x4549 (or $x4545 $x4551)))
 (let (($x4553 (or $x4549 $x4555)))
 (let (($x4557 (or $x4553 $x4559)))
 (let (($x4561 (or $x4557 $x4563)))
 (let (($x4565 (or $x4561 $x4567)))
 (let ((?x4517 (ite root_35 1 0)))
 (let ((?x4499 (ite root_33 1 0)))
 (let ((?x4484 (ite root_31 1 0)))
 (let ((?x4466 (ite root_29 1 0)))
 (let ((?x4445 (ite root_27 1 0)))
 (let ((?x4427 (ite root_25 1 0)))
 (let ((?x4412 (ite root_23 1 0)))
 (let ((?x4394 (ite root_21 1 0)))
 (let ((?x4379 (ite root_19 1 0)))
 (let ((?x4380 (+ 0 ?x4379)))
 (let ((?x4395 (+ ?x4380 ?x4394)))
 (let ((?x4413 (+ ?x4395 ?x4412)))
 (let ((?x4428 (+ ?x4413 ?x4427)))
 (let ((?x4446 (+ ?x4428 ?x4445)))
 (let ((?x4467 (+ ?x4446 ?x4466)))
 (let ((?x4485 (+ ?x4467 ?x4484)))
 (let ((?x4500 (+ ?x4485 ?x4499)))
 (let (($x4378 (or false root_19)))
 (let (($x4393 (or $x4378 root_21)))
 (let (($x4411 (or $x4393 root_23)))
 (let (($x4426 (or $x4411 root_25)))
 (let (($x4444 (or $x4426 root_27)))
 (let (($x4465 (or $x4444 root_29)))
 (let (($x4483 (or $x4465 root_31)))
 (let (($x4498 (or $x4483 root_33)))
 (let (($x3336 (or c_8_6 c_8_12)))
 (let (($x3287 (or c_7_6 c_7_12)))
 (let (($x3280 (or c_6_6 c_6_12)))
 (let (($x3314 (or c_5_6 c_5_12)))
 (let (($x3273 (or c_4_6 c_4_12)))
 (let (($x3266 (or c_3_6 c_3_12)))
 (let (($x3301 (or c_2_6 c_2_12)))
 (let (($x3259 (or c_1_6 c_1_12)))
 (let (($x3252 (or c_0_6 c_0_12)))
 (let (($x4318 (or false $x3252)))
 (let (($x4322 (or $x4318 $x3259)))
 (let (($x4321 (or $x4322 $x3301)))
 (let (($x4319 (or $x4321 $x3266)))
 (let (($x4324 (or $x4319 $x3273)))
 (let (($x4326 (or $x4324 $x3314)))
 (let (($x4328 (or $x4326 $x3280)))
 (let (($x4330 (or $x4328 $x3287)))
 (let (($x4332 (or $x4330 $x3336)))
 (let (($x4523 (or false (and $x3287 (< rank_32 rank_34)))))
 (let (($x4527 (not root_35)))
 (let (($x4528 (and $x3336 $x4527)))
 (let (($x4505 (or false (and $x3336 (< rank_34 rank_32)))))
 (let (($x4508 (or $x4505 (and $x3280 (< rank_30 rank_32)))))
 (let (($x4512 (not root_33)))
 (let (($x4513 (and $x3287 $x4512)))
 (let (($x4490 (or false (and $x3287 (< rank_32 rank_30)))))
 (let (($x4494 (not root_31)))
 (let (($x4495 (and $x3280 $x4494)))
 (let (($x4472 (or false (and $x3336 (< rank_34 rank_28)))))
 (let (($x4475 (or $x4472 (and $x3273 (< rank_26 rank_28)))))
 (let (($x4479 (not root_29)))
 (let (($x4480 (and $x3314 $x4479)))
 (let (($x4451 (or false (and $x3314 (< rank_28 rank_26)))))
 (let (($x4454 (or $x4451 (and $x3287 (< rank_32 rank_26)))))
 (let (($x4457 (or $x4454 (and $x3266 (< rank_24 rank_26)))))
 (let (($x4461 (not root_27)))
 (let (($x4462 (and $x3273 $x4461)))
 (let (($x4433 (or false (and $x3273 (< rank_26 rank_24)))))
 (let (($x4436 (or $x4433 (and $x3280 (< rank_30 rank_24)))))
 (let (($x4440 (not root_25)))
 (let (($x4441 (and $x3266 $x4440)))
 (let (($x4418 (or false (and $x3314 (< rank_28 rank_22)))))
 (let (($x4422 (not root_23)))
 (let (($x4423 (and $x3301 $x4422)))
 (let (($x4400 (or false (and $x3301 (< rank_22 rank_20)))))
 (let (($x4403 (or $x4400 (and $x3273 (< rank_26 rank_20)))))
 (let (($x4407 (not root_21)))
 (let (($x4408 (and $x3259 $x4407)))
 (let (($x4385 (or false (and $x3259 (< rank_20 rank_18)))))
 (let (($x4389 (not root_19)))
 (let (($x4390 (and $x3252 $x4389)))
 (let (($x4382 (and true (=> root_19 $x3252))))
 (let (($x4392 (and $x4382 (=> $x4390 (or $x4385 (and $x3266 (< rank_24 rank_18)))))))
 (let (($x4397 (and $x4392 (=> root_21 $x3259))))
 (let (($x4410 (and $x4397 (=> $x4408 (or $x4403 (and $x3252 (< rank_18 rank_20)))))))
 (let (($x4415 (and $x4410 (=> root_23 $x3301))))
 (let (($x4425 (and $x4415 (=> $x4423 (or $x4418 (and $x3259 (< rank_20 rank_22)))))))
 (let (($x4430 (and $x4425 (=> root_25 $x3266))))
 (let (($x4443 (and $x4430 (=> $x4441 (or $x4436 (and $x3252 (< rank_18 rank_24)))))))
 (let (($x4448 (and $x4443 (=> root_27 $x3273))))
 (let (($x4464 (and $x4448 (=> $x4462 (or $x4457 (and $x3259 (< rank_20 rank_26)))))))
 (let (($x4469 (and $x4464 (=> root_29 $x3314))))
 (let (($x4482 (and $x4469 (=> $x4480 (or $x4475 (and $x3301 (< rank_22 rank_28)))))))
 (let (($x4487 (and $x4482 (=> root_31 $x3280))))
 (let (($x4497 (and $x4487 (=> $x4495 (or $x4490 (and $x3266 (< rank_24 rank_30)))))))
 (let (($x4502 (and $x4497 (=> root_33 $x3287))))
 (let (($x4515 (and $x4502 (=> $x4513 (or $x4508 (and $x3273 (< rank_26 rank_32)))))))
 (let (($x4520 (and $x4515 (=> root_35 $x3336))))
 (let (($x4532 (and (and $x4520 (=> $x4528 (or $x4523 (and $x3314 (< rank_28 rank_34))))) (=> $x4332 (or $x4498 root_35)))))
 (let (($x4534 (and $x4532 (<= (+ ?x4500 ?x4517) 1))))
 (let (($x5205 (and (and (and (and $x4332 $x4534) (not (or $x4565 (or $x2772 $x2791)))) $x4871) $x5204)))
 (let (($x3949 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6)))
 (let (($x4299 (or c_8_7 c_8_8 c_8_9 c_8_10 c_8_11 c_8_12)))
 (let (($x4294 (and true $x4299)))
 (let (($x3915 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6)))
 (let (($x4242 (or c_7_7 c_7_8 c_7_9 c_7_10 c_7_11 c_7_12)))
 (let (($x4237 (and true $x4242)))
 (let (($x4047 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6)))
 (let (($x4232 (or c_6_7 c_6_8 c_6_9 c_6_10 c_6_11 c_6_12)))
 (let (($x4227 (and true $x4232)))
 (let (($x3880 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6)))
 (let (($x4274 (or c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4269 (and true $x4274)))
 (let (($x3846 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6)))
 (let (($x4222 (or c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4217 (and true $x4222)))
 (let (($x4121 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6)))
 (let (($x4212 (or c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x4207 (and true $x4212)))
 (let (($x4258 (or c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x4253 (and true $x4258)))
 (let (($x4202 (or c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x4197 (and true $x4202)))
 (let (($x4192 (or c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x4187 (and true $x4192)))
 (let ((?x4150 (ite $x4148 1 0)))
 (let ((?x4147 (ite $x4146 1 0)))
 (let ((?x3847 (ite false 1 0)))
 (let ((?x4054 (+ 0 ?x3847)))
 (let ((?x4142 (+ ?x4054 ?x3847)))
 (let ((?x4149 (+ ?x4142 ?x4147)))
 (let (($x4144 (= (to_real (+ (+ ?x4142 (ite $x3651 1 0)) (ite $x3633 1 0))) 0.0)))
 (let (($x4154 (and $x4144 (= (to_real (+ ?x4149 ?x4150)) 0.0))))
 (let (($x4139 (or c_8_2 c_8_3 c_8_4 c_8_5)))
 (let (($x4136 (and true $x4139)))
 (let (($x4177 (and $x4136 $x3949)))
 (let ((?x4030 (ite $x4025 1 0)))
 (let ((?x4028 (ite $x4023 1 0)))
 (let ((?x4024 (ite $x4022 1 0)))
 (let ((?x4026 (+ 0 ?x4024)))
 (let ((?x4027 (+ ?x4026 ?x3847)))
 (let ((?x4029 (+ ?x4027 ?x4028)))
 (let ((?x3876 (ite $x3622 1 0)))
 (let ((?x3914 (ite $x3687 1 0)))
 (let ((?x4015 (ite $x3666 1 0)))
 (let ((?x4014 (+ 0 ?x4015)))
 (let ((?x4012 (+ ?x4014 ?x3847)))
 (let ((?x4013 (+ ?x4012 ?x3914)))
 (let (($x4034 (and (= (to_real (+ ?x4013 ?x3876)) 0.0) (= (to_real (+ ?x4029 ?x4030)) 0.0))))
 (let (($x4007 (or c_7_2 c_7_3 c_7_4 c_7_5)))
 (let (($x4006 (and true $x4007)))
 (let (($x4175 (and $x4006 $x3915)))
 (let ((?x3997 (ite $x3993 1 0)))
 (let ((?x3992 (ite $x3991 1 0)))
 (let ((?x3994 (+ 0 ?x3992)))
 (let ((?x3995 (+ ?x3994 ?x3847)))
 (let ((?x3996 (+ ?x3995 ?x3847)))
 (let ((?x3845 (ite $x3671 1 0)))
 (let ((?x3948 (ite $x3651 1 0)))
 (let ((?x3984 (+ 0 ?x3948)))
 (let ((?x3983 (+ ?x3984 ?x3847)))
 (let ((?x3982 (+ ?x3983 ?x3847)))
 (let (($x4001 (and (= (to_real (+ ?x3982 ?x3845)) 0.0) (= (to_real (+ ?x3996 ?x3997)) 0.0))))
 (let (($x3977 (or c_6_2 c_6_3 c_6_4 c_6_5)))
 (let (($x3976 (and true $x3977)))
 (let (($x4171 (and $x3976 $x4047)))
 (let ((?x4104 (ite $x4100 1 0)))
 (let ((?x4102 (ite $x4098 1 0)))
 (let ((?x4099 (ite $x4097 1 0)))
 (let ((?x4101 (+ ?x4054 ?x4099)))
 (let ((?x4103 (+ ?x4101 ?x4102)))
 (let (($x4094 (= (to_real (+ (+ (+ ?x4054 ?x4015) ?x3876) (ite $x3610 1 0))) 0.0)))
 (let (($x4108 (and $x4094 (= (to_real (+ ?x4103 ?x4104)) 0.0))))
 (let (($x4089 (or c_5_2 c_5_3 c_5_4 c_5_5)))
 (let (($x4087 (and true $x4089)))
 (let (($x4165 (and $x4087 $x3880)))
 (let ((?x3967 (ite $x3961 1 0)))
 (let ((?x3965 (ite $x3959 1 0)))
 (let ((?x3963 (ite $x3958 1 0)))
 (let ((?x3960 (ite $x3956 1 0)))
 (let ((?x3962 (+ 0 ?x3960)))
 (let ((?x3964 (+ ?x3962 ?x3963)))
 (let ((?x3966 (+ ?x3964 ?x3965)))
 (let ((?x3843 (ite $x3592 1 0)))
 (let ((?x3945 (ite $x3633 1 0)))
 (let ((?x3946 (+ 0 ?x3945)))
 (let ((?x3947 (+ ?x3946 ?x3948)))
 (let ((?x3950 (+ ?x3947 ?x3845)))
 (let (($x3971 (and (= (to_real (+ ?x3950 ?x3843)) 0.0) (= (to_real (+ ?x3966 ?x3967)) 0.0))))
 (let (($x3940 (or c_4_2 c_4_3 c_4_4 c_4_5)))
 (let (($x3938 (and true $x3940)))
 (let (($x4159 (and $x3938 $x3846)))
 (let ((?x3930 (ite $x3925 1 0)))
 (let ((?x3927 (ite $x3923 1 0)))
 (let ((?x3924 (ite $x3921 1 0)))
 (let ((?x3926 (+ 0 ?x3924)))
 (let ((?x3928 (+ ?x3926 ?x3927)))
 (let ((?x3929 (+ ?x3928 ?x3847)))
 (let ((?x3917 (to_real (+ (+ (+ (+ 0 ?x3876) ?x3914) ?x3847) (ite $x3708 1 0)))))
 (let (($x3934 (and (= ?x3917 0.0) (= (to_real (+ ?x3929 ?x3930)) 0.0))))
 (let (($x3906 (or c_3_2 c_3_3 c_3_4 c_3_5)))
 (let (($x3904 (and true $x3906)))
 (let (($x4158 (and $x3904 $x4121)))
 (let (($x3986 (or c_7_1 c_7_2 c_7_3 c_7_4 c_7_5 c_7_6)))
 (let (($x4138 (and $x4136 $x3986)))
 (let (($x4083 (or c_6_1 c_6_2 c_6_3 c_6_4 c_6_5 c_6_6)))
 (let (($x4134 (and $x4006 $x4083)))
 (let ((?x4068 (to_real (+ (+ (+ ?x4054 (ite $x4062 1 0)) (ite $x4063 1 0)) ?x3847))))
 (let (($x4070 (and (= (to_real (+ (+ (+ ?x4054 ?x3945) ?x3843) ?x3847)) 0.0) (= ?x4068 0.0))))
 (let (($x4053 (or c_2_2 c_2_3 c_2_4 c_2_5)))
 (let (($x4050 (and true $x4053)))
 (let (($x4117 (and $x4050 $x3846)))
 (let ((?x3895 (ite $x3891 1 0)))
 (let ((?x3893 (ite $x3890 1 0)))
 (let ((?x3889 (ite $x3888 1 0)))
 (let ((?x3892 (+ 0 ?x3889)))
 (let ((?x3894 (+ ?x3892 ?x3893)))
 (let ((?x3896 (+ ?x3894 ?x3895)))
 (let ((?x3881 (ite $x3708 1 0)))
 (let ((?x3878 (ite $x3610 1 0)))
 (let ((?x3877 (+ 0 ?x3878)))
 (let ((?x3879 (+ ?x3877 ?x3876)))
 (let ((?x3882 (+ ?x3879 ?x3881)))
 (let (($x3900 (and (= (to_real (+ ?x3882 ?x3847)) 0.0) (= (to_real (+ ?x3896 ?x3847)) 0.0))))
 (let (($x3871 (or c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x3869 (and true $x3871)))
 (let (($x4116 (and $x3869 $x4121)))
 (let (($x4016 (or c_8_1 c_8_2 c_8_3 c_8_4 c_8_5 c_8_6)))
 (let (($x4088 (and $x4087 $x4016)))
 (let ((?x3859 (ite $x3857 1 0)))
 (let ((?x3856 (ite $x3855 1 0)))
 (let ((?x3858 (+ 0 ?x3856)))
 (let ((?x3860 (+ ?x3858 ?x3859)))
 (let ((?x3861 (+ ?x3860 ?x3847)))
 (let (($x3865 (and (= (to_real (+ (+ (+ (+ 0 ?x3843) ?x3845) ?x3847) ?x3847)) 0.0) (= (to_real (+ ?x3861 ?x3847)) 0.0))))
 (let (($x3837 (or c_0_2 c_0_3 c_0_4 c_0_5)))
 (let (($x3835 (and true $x3837)))
 (let (($x4042 (and $x3835 $x4047)))
 (let (($x3581 (not (and (and true $x3336) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3578 (not (and (and true $x3287) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3575 (not (and (and true $x3280) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3572 (not (and (and true $x3314) (or (and c_2_1 $x1680) (and c_2_7 $x1680))))))
 (let (($x3569 (not (and (and true $x3273) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x3566 (not (and (and true $x3266) (or (and c_0_1 $x1652) (and c_0_7 $x1652))))))
 (let (($x3563 (not (and (and true $x3336) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3560 (not (and (and true $x3287) (or (and c_6_1 $x1740) (and c_6_7 $x1740))))))
 (let (($x3557 (not (and (and true $x3314) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3554 (not (and (and true $x3273) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3551 (not (and (and true $x3301) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x3548 (not (and (and true $x3259) (or (and c_0_1 $x1652) (and c_0_7 $x1652))))))
 (let (($x3544 (not (and (and true $x3314) (or (and c_8_1 $x1770) (and c_8_7 $x1770))))))
 (let (($x3541 (not (and (and true $x3273) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3538 (not (and (and true $x3266) (or (and c_6_1 $x1740) (and c_6_7 $x1740))))))
 (let (($x3534 (not (and (and true $x3301) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3531 (not (and (and true $x3259) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3528 (not (and (and true $x3252) (or (and c_3_1 $x1695) (and c_3_7 $x1695))))))
 (let (($x3524 (not (and (and true $x3287) (or (and c_8_1 $x1770) (and c_8_7 $x1770))))))
 (let (($x3520 (not (and (and true $x3280) (or (and c_7_1 $x1755) (and c_7_7 $x1755))))))
 (let (($x3516 (not (and (and true $x3273) (or (and c_5_1 $x1725) (and c_5_7 $x1725))))))
 (let (($x3512 (not (and (and true $x3266) (or (and c_4_1 $x1710) (and c_4_7 $x1710))))))
 (let (($x3508 (not (and (and true $x3259) (or (and c_2_1 $x1680) (and c_2_7 $x1680))))))
 (let (($x3503 (not (and (and true $x3252) (or (and c_1_1 $x1665) (and c_1_7 $x1665))))))
 (let (($x2007 (and c_5_11 in_target_5)))
 (let (($x2005 (and c_5_10 in_target_5)))
 (let (($x2003 (and c_5_9 in_target_5)))
 (let (($x2001 (and c_5_8 in_target_5)))
 (let (($x1996 (and c_5_5 in_target_5)))
 (let (($x1994 (and c_5_4 in_target_5)))
 (let (($x1992 (and c_5_3 in_target_5)))
 (let (($x1990 (and c_5_2 in_target_5)))
 (let (($x3405 (or $x1990 $x1992 $x1994 $x1996 $x2001 $x2003 $x2005 $x2007)))
 (let (($x3335 (and true $x3336)))
 (let (($x1972 (and c_4_11 in_target_4)))
 (let (($x1970 (and c_4_10 in_target_4)))
 (let (($x1968 (and c_4_9 in_target_4)))
 (let (($x1966 (and c_4_8 in_target_4)))
 (let (($x1961 (and c_4_5 in_target_4)))
 (let (($x1959 (and c_4_4 in_target_4)))
 (let (($x1957 (and c_4_3 in_target_4)))
 (let (($x1955 (and c_4_2 in_target_4)))
 (let (($x3394 (or $x1955 $x1957 $x1959 $x1961 $x1966 $x1968 $x1970 $x1972)))
 (let (($x3286 (and true $x3287)))
 (let (($x1937 (and c_3_11 in_target_3)))
 (let (($x1935 (and c_3_10 in_target_3)))
 (let (($x1933 (and c_3_9 in_target_3)))
 (let (($x1931 (and c_3_8 in_target_3)))
 (let (($x1926 (and c_3_5 in_target_3)))
 (let (($x1924 (and c_3_4 in_target_3)))
 (let (($x1922 (and c_3_3 in_target_3)))
 (let (($x1920 (and c_3_2 in_target_3)))
 (let (($x3438 (or $x1920 $x1922 $x1924 $x1926 $x1931 $x1933 $x1935 $x1937)))
 (let (($x3279 (and true $x3280)))
 (let (($x1902 (and c_2_11 in_target_2)))
 (let (($x1900 (and c_2_10 in_target_2)))
 (let (($x1898 (and c_2_9 in_target_2)))
 (let (($x1896 (and c_2_8 in_target_2)))
 (let (($x1891 (and c_2_5 in_target_2)))
 (let (($x1889 (and c_2_4 in_target_2)))
 (let (($x1887 (and c_2_3 in_target_2)))
 (let (($x1885 (and c_2_2 in_target_2)))
 (let (($x3383 (or $x1885 $x1887 $x1889 $x1891 $x1896 $x1898 $x1900 $x1902)))
 (let (($x3313 (and true $x3314)))
 (let (($x1867 (and c_1_11 in_target_1)))
 (let (($x1865 (and c_1_10 in_target_1)))
 (let (($x1863 (and c_1_9 in_target_1)))
 (let (($x1861 (and c_1_8 in_target_1)))
 (let (($x1856 (and c_1_5 in_target_1)))
 (let (($x1854 (and c_1_4 in_target_1)))
 (let (($x1852 (and c_1_3 in_target_1)))
 (let (($x1850 (and c_1_2 in_target_1)))
 (let (($x3372 (or $x1850 $x1852 $x1854 $x1856 $x1861 $x1863 $x1865 $x1867)))
 (let (($x3272 (and true $x3273)))
 (let (($x1832 (and c_0_11 in_target_0)))
 (let (($x1830 (and c_0_10 in_target_0)))
 (let (($x1828 (and c_0_9 in_target_0)))
 (let (($x1826 (and c_0_8 in_target_0)))
 (let (($x1821 (and c_0_5 in_target_0)))
 (let (($x1819 (and c_0_4 in_target_0)))
 (let (($x1817 (and c_0_3 in_target_0)))
 (let (($x1815 (and c_0_2 in_target_0)))
 (let (($x3472 (or $x1815 $x1817 $x1819 $x1821 $x1826 $x1828 $x1830 $x1832)))
 (let (($x3265 (and true $x3266)))
 (let (($x2077 (and c_7_11 in_target_7)))
 (let (($x2075 (and c_7_10 in_target_7)))
 (let (($x2073 (and c_7_9 in_target_7)))
 (let (($x2071 (and c_7_8 in_target_7)))
 (let (($x2066 (and c_7_5 in_target_7)))
 (let (($x2064 (and c_7_4 in_target_7)))
 (let (($x2062 (and c_7_3 in_target_7)))
 (let (($x2060 (and c_7_2 in_target_7)))
 (let (($x3416 (or $x2060 $x2062 $x2064 $x2066 $x2071 $x2073 $x2075 $x2077)))
 (let (($x2042 (and c_6_11 in_target_6)))
 (let (($x2040 (and c_6_10 in_target_6)))
 (let (($x2038 (and c_6_9 in_target_6)))
 (let (($x2036 (and c_6_8 in_target_6)))
 (let (($x2031 (and c_6_5 in_target_6)))
 (let (($x2029 (and c_6_4 in_target_6)))
 (let (($x2027 (and c_6_3 in_target_6)))
 (let (($x2025 (and c_6_2 in_target_6)))
 (let (($x3455 (or $x2025 $x2027 $x2029 $x2031 $x2036 $x2038 $x2040 $x2042)))
 (let (($x2112 (and c_8_11 in_target_8)))
 (let (($x2110 (and c_8_10 in_target_8)))
 (let (($x2108 (and c_8_9 in_target_8)))
 (let (($x2106 (and c_8_8 in_target_8)))
 (let (($x2101 (and c_8_5 in_target_8)))
 (let (($x2099 (and c_8_4 in_target_8)))
 (let (($x2097 (and c_8_3 in_target_8)))
 (let (($x2095 (and c_8_2 in_target_8)))
 (let (($x3427 (or $x2095 $x2097 $x2099 $x2101 $x2106 $x2108 $x2110 $x2112)))
 (let (($x3356 (not (and $x3335 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3353 (not (and $x3286 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3350 (not (and $x3279 (or (and c_3_1 in_target_3) (and c_3_7 in_target_3))))))
 (let (($x3347 (not (and $x3313 (or (and c_2_1 in_target_2) (and c_2_7 in_target_2))))))
 (let (($x3344 (not (and $x3272 (or (and c_1_1 in_target_1) (and c_1_7 in_target_1))))))
 (let (($x3341 (not (and $x3265 (or (and c_0_1 in_target_0) (and c_0_7 in_target_0))))))
 (let (($x3338 (not (and $x3335 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3332 (not (and $x3286 (or (and c_6_1 in_target_6) (and c_6_7 in_target_6))))))
 (let (($x3329 (not (and $x3313 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3326 (not (and $x3272 (or (and c_3_1 in_target_3) (and c_3_7 in_target_3))))))
 (let (($x1859 (and c_1_7 in_target_1)))
 (let (($x1848 (and c_1_1 in_target_1)))
 (let (($x3254 (or $x1848 $x1859)))
 (let (($x3300 (and true $x3301)))
 (let (($x1824 (and c_0_7 in_target_0)))
 (let (($x1813 (and c_0_1 in_target_0)))
 (let (($x3319 (or $x1813 $x1824)))
 (let (($x3258 (and true $x3259)))
 (let (($x3316 (not (and $x3313 (or (and c_8_1 in_target_8) (and c_8_7 in_target_8))))))
 (let (($x3310 (not (and $x3272 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3307 (not (and $x3265 (or (and c_6_1 in_target_6) (and c_6_7 in_target_6))))))
 (let (($x3303 (not (and $x3300 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3297 (not (and $x3258 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x1929 (and c_3_7 in_target_3)))
 (let (($x1918 (and c_3_1 in_target_3)))
 (let (($x3293 (or $x1918 $x1929)))
 (let (($x3251 (and true $x3252)))
 (let (($x3290 (not (and $x3286 (or (and c_8_1 in_target_8) (and c_8_7 in_target_8))))))
 (let (($x3283 (not (and $x3279 (or (and c_7_1 in_target_7) (and c_7_7 in_target_7))))))
 (let (($x3276 (not (and $x3272 (or (and c_5_1 in_target_5) (and c_5_7 in_target_5))))))
 (let (($x3269 (not (and $x3265 (or (and c_4_1 in_target_4) (and c_4_7 in_target_4))))))
 (let (($x3262 (not (and $x3258 (or (and c_2_1 in_target_2) (and c_2_7 in_target_2))))))
 (let (($x2789 (and c_8_11 $x1770)))
 (let (($x2787 (and c_8_10 $x1770)))
 (let (($x2785 (and c_8_9 $x1770)))
 (let (($x2783 (and c_8_8 $x1770)))
 (let (($x2782 (and c_8_7 $x1770)))
 (let ((?x2780 (ite (or $x2782 $x2783 $x2785 $x2787 $x2789 $x2791) 2 0)))
 (let (($x2770 (and c_8_5 $x1770)))
 (let (($x2768 (and c_8_4 $x1770)))
 (let (($x2766 (and c_8_3 $x1770)))
 (let (($x2764 (and c_8_2 $x1770)))
 (let (($x2763 (and c_8_1 $x1770)))
 (let ((?x3103 (ite (or $x2763 $x2764 $x2766 $x2768 $x2770 $x2772) 1 0)))
 (let (($x2093 (and c_8_1 in_target_8)))
 (let (($x1784 (and c_8_6 in_target_8)))
 (let ((?x3101 (ite (or $x1784 $x2093 $x2095 $x2097 $x2099 $x2101) (- 1) 0)))
 (let (($x2092 (and c_8_0 in_target_8)))
 (let ((?x3102 (ite $x2092 (- 2) 0)))
 (let (($x2736 (and c_7_11 $x1755)))
 (let (($x2734 (and c_7_10 $x1755)))
 (let (($x2732 (and c_7_9 $x1755)))
 (let (($x2730 (and c_7_8 $x1755)))
 (let (($x2729 (and c_7_7 $x1755)))
 (let ((?x2727 (ite (or $x2729 $x2730 $x2732 $x2734 $x2736 $x2738) 2 0)))
 (let (($x2717 (and c_7_5 $x1755)))
 (let (($x2715 (and c_7_4 $x1755)))
 (let (($x2713 (and c_7_3 $x1755)))
 (let (($x2711 (and c_7_2 $x1755)))
 (let (($x2710 (and c_7_1 $x1755)))
 (let ((?x3080 (ite (or $x2710 $x2711 $x2713 $x2715 $x2717 $x2719) 1 0)))
 (let (($x2058 (and c_7_1 in_target_7)))
 (let (($x1769 (and c_7_6 in_target_7)))
 (let ((?x3076 (ite (or $x1769 $x2058 $x2060 $x2062 $x2064 $x2066) (- 1) 0)))
 (let (($x2057 (and c_7_0 in_target_7)))
 (let ((?x3073 (ite $x2057 (- 2) 0)))
 (let (($x2683 (and c_6_11 $x1740)))
 (let (($x2681 (and c_6_10 $x1740)))
 (let (($x2679 (and c_6_9 $x1740)))
 (let (($x2677 (and c_6_8 $x1740)))
 (let (($x2676 (and c_6_7 $x1740)))
 (let ((?x2674 (ite (or $x2676 $x2677 $x2679 $x2681 $x2683 $x2685) 2 0)))
 (let (($x2664 (and c_6_5 $x1740)))
 (let (($x2662 (and c_6_4 $x1740)))
 (let (($x2660 (and c_6_3 $x1740)))
 (let (($x2658 (and c_6_2 $x1740)))
 (let (($x2657 (and c_6_1 $x1740)))
 (let ((?x3067 (ite (or $x2657 $x2658 $x2660 $x2662 $x2664 $x2666) 1 0)))
 (let (($x2023 (and c_6_1 in_target_6)))
 (let (($x1754 (and c_6_6 in_target_6)))
 (let ((?x3060 (ite (or $x1754 $x2023 $x2025 $x2027 $x2029 $x2031) (- 1) 0)))
 (let (($x2022 (and c_6_0 in_target_6)))
 (let ((?x3055 (ite $x2022 (- 2) 0)))
 (let (($x2630 (and c_5_11 $x1725)))
 (let (($x2628 (and c_5_10 $x1725)))
 (let (($x2626 (and c_5_9 $x1725)))
 (let (($x2624 (and c_5_8 $x1725)))
 (let (($x2623 (and c_5_7 $x1725)))
 (let ((?x2621 (ite (or $x2623 $x2624 $x2626 $x2628 $x2630 $x2632) 2 0)))
 (let (($x2611 (and c_5_5 $x1725)))
 (let (($x2609 (and c_5_4 $x1725)))
 (let (($x2607 (and c_5_3 $x1725)))
 (let (($x2605 (and c_5_2 $x1725)))
 (let (($x2604 (and c_5_1 $x1725)))
 (let ((?x3033 (ite (or $x2604 $x2605 $x2607 $x2609 $x2611 $x2613) 1 0)))
 (let (($x1988 (and c_5_1 in_target_5)))
 (let (($x1739 (and c_5_6 in_target_5)))
 (let ((?x3041 (ite (or $x1739 $x1988 $x1990 $x1992 $x1994 $x1996) (- 1) 0)))
 (let (($x1987 (and c_5_0 in_target_5)))
 (let ((?x3036 (ite $x1987 (- 2) 0)))
 (let (($x2577 (and c_4_11 $x1710)))
 (let (($x2575 (and c_4_10 $x1710)))
 (let (($x2573 (and c_4_9 $x1710)))
 (let (($x2571 (and c_4_8 $x1710)))
 (let (($x2570 (and c_4_7 $x1710)))
 (let ((?x2568 (ite (or $x2570 $x2571 $x2573 $x2575 $x2577 $x2579) 2 0)))
 (let (($x2558 (and c_4_5 $x1710)))
 (let (($x2556 (and c_4_4 $x1710)))
 (let (($x2554 (and c_4_3 $x1710)))
 (let (($x2552 (and c_4_2 $x1710)))
 (let (($x2551 (and c_4_1 $x1710)))
 (let ((?x3025 (ite (or $x2551 $x2552 $x2554 $x2556 $x2558 $x2560) 1 0)))
 (let (($x1953 (and c_4_1 in_target_4)))
 (let (($x1724 (and c_4_6 in_target_4)))
 (let ((?x3014 (ite (or $x1724 $x1953 $x1955 $x1957 $x1959 $x1961) (- 1) 0)))
 (let (($x1952 (and c_4_0 in_target_4)))
 (let ((?x3020 (ite $x1952 (- 2) 0)))
 (let (($x2524 (and c_3_11 $x1695)))
 (let (($x2522 (and c_3_10 $x1695)))
 (let (($x2520 (and c_3_9 $x1695)))
 (let (($x2518 (and c_3_8 $x1695)))
 (let (($x2517 (and c_3_7 $x1695)))
 (let ((?x2515 (ite (or $x2517 $x2518 $x2520 $x2522 $x2524 $x2526) 2 0)))
 (let (($x2505 (and c_3_5 $x1695)))
 (let (($x2503 (and c_3_4 $x1695)))
 (let (($x2501 (and c_3_3 $x1695)))
 (let (($x2499 (and c_3_2 $x1695)))
 (let (($x2498 (and c_3_1 $x1695)))
 (let ((?x3004 (ite (or $x2498 $x2499 $x2501 $x2503 $x2505 $x2507) 1 0)))
 (let ((?x2998 (ite (or (and c_3_6 in_target_3) $x1918 $x1920 $x1922 $x1924 $x1926) (- 1) 0)))
 (let (($x1917 (and c_3_0 in_target_3)))
 (let ((?x2994 (ite $x1917 (- 2) 0)))
 (let (($x2471 (and c_2_11 $x1680)))
 (let (($x2469 (and c_2_10 $x1680)))
 (let (($x2467 (and c_2_9 $x1680)))
 (let (($x2465 (and c_2_8 $x1680)))
 (let (($x2464 (and c_2_7 $x1680)))
 (let ((?x2462 (ite (or $x2464 $x2465 $x2467 $x2469 $x2471 $x2473) 2 0)))
 (let (($x2452 (and c_2_5 $x1680)))
 (let (($x2450 (and c_2_4 $x1680)))
 (let (($x2448 (and c_2_3 $x1680)))
 (let (($x2446 (and c_2_2 $x1680)))
 (let (($x2445 (and c_2_1 $x1680)))
 (let ((?x2975 (ite (or $x2445 $x2446 $x2448 $x2450 $x2452 $x2454) 1 0)))
 (let (($x1883 (and c_2_1 in_target_2)))
 (let (($x1694 (and c_2_6 in_target_2)))
 (let ((?x2973 (ite (or $x1694 $x1883 $x1885 $x1887 $x1889 $x1891) (- 1) 0)))
 (let (($x1882 (and c_2_0 in_target_2)))
 (let ((?x2974 (ite $x1882 (- 2) 0)))
 (let (($x2418 (and c_1_11 $x1665)))
 (let (($x2416 (and c_1_10 $x1665)))
 (let (($x2414 (and c_1_9 $x1665)))
 (let (($x2412 (and c_1_8 $x1665)))
 (let (($x2411 (and c_1_7 $x1665)))
 (let ((?x2409 (ite (or $x2411 $x2412 $x2414 $x2416 $x2418 $x2420) 2 0)))
 (let (($x2399 (and c_1_5 $x1665)))
 (let (($x2397 (and c_1_4 $x1665)))
 (let (($x2395 (and c_1_3 $x1665)))
 (let (($x2393 (and c_1_2 $x1665)))
 (let (($x2392 (and c_1_1 $x1665)))
 (let ((?x2959 (ite (or $x2392 $x2393 $x2395 $x2397 $x2399 $x2401) 1 0)))
 (let ((?x2952 (ite (or (and c_1_6 in_target_1) $x1848 $x1850 $x1852 $x1854 $x1856) (- 1) 0)))
 (let (($x1847 (and c_1_0 in_target_1)))
 (let ((?x2951 (ite $x1847 (- 2) 0)))
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
 (let ((?x2939 (ite (or $x2338 $x2339 $x2341 $x2343 $x2345 $x2347) 1 0)))
 (let ((?x2935 (ite (or (and c_0_6 in_target_0) $x1813 $x1815 $x1817 $x1819 $x1821) (- 1) 0)))
 (let (($x1812 (and c_0_0 in_target_0)))
 (let ((?x2928 (ite $x1812 (- 2) 0)))
 (let ((?x2929 (+ 0 ?x2928)))
 (let ((?x2938 (+ ?x2929 ?x2935)))
 (let ((?x2936 (+ ?x2938 ?x2939)))
 (let ((?x2937 (+ ?x2936 ?x2356)))
 (let ((?x2955 (+ ?x2937 ?x2951)))
 (let ((?x2956 (+ ?x2955 ?x2952)))
 (let ((?x2960 (+ ?x2956 ?x2959)))
 (let ((?x2957 (+ ?x2960 ?x2409)))
 (let ((?x2971 (+ ?x2957 ?x2974)))
 (let ((?x2980 (+ ?x2971 ?x2973)))
 (let ((?x2983 (+ ?x2980 ?x2975)))
 (let ((?x2977 (+ ?x2983 ?x2462)))
 (let ((?x2992 (+ ?x2977 ?x2994)))
 (let ((?x3002 (+ ?x2992 ?x2998)))
 (let ((?x2996 (+ ?x3002 ?x3004)))
 (let ((?x2995 (+ ?x2996 ?x2515)))
 (let ((?x3011 (+ ?x2995 ?x3020)))
 (let ((?x3023 (+ ?x3011 ?x3014)))
 (let ((?x3013 (+ ?x3023 ?x3025)))
 (let ((?x3019 (+ ?x3013 ?x2568)))
 (let ((?x3032 (+ ?x3019 ?x3036)))
 (let ((?x3038 (+ ?x3032 ?x3041)))
 (let ((?x3044 (+ ?x3038 ?x3033)))
 (let ((?x3046 (+ ?x3044 ?x2621)))
 (let ((?x3054 (+ ?x3046 ?x3055)))
 (let ((?x3065 (+ ?x3054 ?x3060)))
 (let ((?x3062 (+ ?x3065 ?x3067)))
 (let ((?x3064 (+ ?x3062 ?x2674)))
 (let ((?x3081 (+ ?x3064 ?x3073)))
 (let ((?x3085 (+ ?x3081 ?x3076)))
 (let ((?x3088 (+ ?x3085 ?x3080)))
 (let ((?x3082 (+ ?x3088 ?x2727)))
 (let ((?x3094 (+ ?x3082 ?x3102)))
 (let ((?x3096 (+ ?x3094 ?x3101)))
 (let ((?x3107 (+ ?x3096 ?x3103)))
 (let (($x3121 (<= (+ ?x3107 ?x2780) 0)))
 (let (($x2104 (and c_8_7 in_target_8)))
 (let (($x1786 (and c_8_12 in_target_8)))
 (let ((?x2761 (ite (or $x1786 $x2104 $x2106 $x2108 $x2110 $x2112 $x2763 $x2764 $x2766 $x2768 $x2770 $x2772) 1 0)))
 (let ((?x2741 (ite $x2092 (- 1) 0)))
 (let (($x2069 (and c_7_7 in_target_7)))
 (let (($x1771 (and c_7_12 in_target_7)))
 (let ((?x2708 (ite (or $x1771 $x2069 $x2071 $x2073 $x2075 $x2077 $x2710 $x2711 $x2713 $x2715 $x2717 $x2719) 1 0)))
 (let ((?x2688 (ite $x2057 (- 1) 0)))
 (let (($x2034 (and c_6_7 in_target_6)))
 (let (($x1756 (and c_6_12 in_target_6)))
 (let ((?x2655 (ite (or $x1756 $x2034 $x2036 $x2038 $x2040 $x2042 $x2657 $x2658 $x2660 $x2662 $x2664 $x2666) 1 0)))
 (let ((?x2635 (ite $x2022 (- 1) 0)))
 (let (($x1999 (and c_5_7 in_target_5)))
 (let (($x1741 (and c_5_12 in_target_5)))
 (let ((?x2602 (ite (or $x1741 $x1999 $x2001 $x2003 $x2005 $x2007 $x2604 $x2605 $x2607 $x2609 $x2611 $x2613) 1 0)))
 (let ((?x2582 (ite $x1987 (- 1) 0)))
 (let (($x1964 (and c_4_7 in_target_4)))
 (let (($x1726 (and c_4_12 in_target_4)))
 (let ((?x2549 (ite (or $x1726 $x1964 $x1966 $x1968 $x1970 $x1972 $x2551 $x2552 $x2554 $x2556 $x2558 $x2560) 1 0)))
 (let ((?x2529 (ite $x1952 (- 1) 0)))
 (let (($x1711 (and c_3_12 in_target_3)))
 (let ((?x2496 (ite (or $x1711 $x1929 $x1931 $x1933 $x1935 $x1937 $x2498 $x2499 $x2501 $x2503 $x2505 $x2507) 1 0)))
 (let ((?x2476 (ite $x1917 (- 1) 0)))
 (let (($x1894 (and c_2_7 in_target_2)))
 (let (($x1696 (and c_2_12 in_target_2)))
 (let ((?x2443 (ite (or $x1696 $x1894 $x1896 $x1898 $x1900 $x1902 $x2445 $x2446 $x2448 $x2450 $x2452 $x2454) 1 0)))
 (let ((?x2423 (ite $x1882 (- 1) 0)))
 (let (($x1681 (and c_1_12 in_target_1)))
 (let ((?x2390 (ite (or $x1681 $x1859 $x1861 $x1863 $x1865 $x1867 $x2392 $x2393 $x2395 $x2397 $x2399 $x2401) 1 0)))
 (let ((?x2370 (ite $x1847 (- 1) 0)))
 (let (($x1666 (and c_0_12 in_target_0)))
 (let ((?x2336 (ite (or $x1666 $x1824 $x1826 $x1828 $x1830 $x1832 $x2338 $x2339 $x2341 $x2343 $x2345 $x2347) 1 0)))
 (let ((?x2317 (ite $x1812 (- 1) 0)))
 (let ((?x2318 (+ 0 ?x2317)))
 (let ((?x2337 (+ ?x2318 ?x2336)))
 (let ((?x2357 (+ ?x2337 ?x2356)))
 (let ((?x2373 (+ ?x2357 ?x2370)))
 (let ((?x2391 (+ ?x2373 ?x2390)))
 (let ((?x2410 (+ ?x2391 ?x2409)))
 (let ((?x2433 (+ ?x2410 ?x2423)))
 (let ((?x2444 (+ ?x2433 ?x2443)))
 (let ((?x2463 (+ ?x2444 ?x2462)))
 (let ((?x2482 (+ ?x2463 ?x2476)))
 (let ((?x2497 (+ ?x2482 ?x2496)))
 (let ((?x2516 (+ ?x2497 ?x2515)))
 (let ((?x2533 (+ ?x2516 ?x2529)))
 (let ((?x2550 (+ ?x2533 ?x2549)))
 (let ((?x2569 (+ ?x2550 ?x2568)))
 (let ((?x2586 (+ ?x2569 ?x2582)))
 (let ((?x2603 (+ ?x2586 ?x2602)))
 (let ((?x2622 (+ ?x2603 ?x2621)))
 (let ((?x2636 (+ ?x2622 ?x2635)))
 (let ((?x2656 (+ ?x2636 ?x2655)))
 (let ((?x2675 (+ ?x2656 ?x2674)))
 (let ((?x2693 (+ ?x2675 ?x2688)))
 (let ((?x2709 (+ ?x2693 ?x2708)))
 (let ((?x2728 (+ ?x2709 ?x2727)))
 (let ((?x2744 (+ ?x2728 ?x2741)))
 (let ((?x2762 (+ ?x2744 ?x2761)))
 (let (($x2794 (>= (+ ?x2762 ?x2780) 0)))
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
 (let (($x3249 (and $x1781 (and (and $x2315 $x2794) $x3121))))
 (let (($x3256 (and $x3249 (not (and $x3251 $x3254)))))
 (let (($x3263 (and $x3256 $x3262)))
 (let (($x3270 (and $x3263 $x3269)))
 (let (($x3277 (and $x3270 $x3276)))
 (let (($x3284 (and $x3277 $x3283)))
 (let (($x3291 (and $x3284 $x3290)))
 (let (($x3295 (and $x3291 (not (and $x3251 $x3293)))))
 (let (($x3298 (and $x3295 $x3297)))
 (let (($x3304 (and $x3298 $x3303)))
 (let (($x3308 (and $x3304 $x3307)))
 (let (($x3311 (and $x3308 $x3310)))
 (let (($x3317 (and $x3311 $x3316)))
 (let (($x3321 (and $x3317 (not (and $x3258 $x3319)))))
 (let (($x3324 (and $x3321 (not (and $x3300 $x3254)))))
 (let (($x3327 (and $x3324 $x3326)))
 (let (($x3330 (and $x3327 $x3329)))
 (let (($x3333 (and $x3330 $x3332)))
 (let (($x3339 (and $x3333 $x3338)))
 (let (($x3342 (and $x3339 $x3341)))
 (let (($x3345 (and $x3342 $x3344)))
 (let (($x3348 (and $x3345 $x3347)))
 (let (($x3351 (and $x3348 $x3350)))
 (let (($x3354 (and $x3351 $x3353)))
 (let (($x3357 (and $x3354 $x3356)))
 (let (($x3366 (and $x3357 (not (and $x3251 $x3372)))))
 (let (($x3379 (and $x3366 (not (and $x3258 $x3383)))))
 (let (($x3388 (and $x3379 (not (and $x3265 $x3394)))))
 (let (($x3400 (and $x3388 (not (and $x3272 $x3405)))))
 (let (($x3410 (and $x3400 (not (and $x3279 $x3416)))))
 (let (($x3422 (and $x3410 (not (and $x3286 $x3427)))))
 (let (($x3436 (and $x3422 (not (and $x3251 $x3438)))))
 (let (($x3434 (and $x3436 (not (and $x3258 $x3394)))))
 (let (($x3441 (and $x3434 (not (and $x3300 $x3405)))))
 (let (($x3453 (and $x3441 (not (and $x3265 $x3455)))))
 (let (($x3451 (and $x3453 (not (and $x3272 $x3416)))))
 (let (($x3458 (and $x3451 (not (and $x3313 $x3427)))))
 (let (($x3466 (and $x3458 (not (and $x3258 $x3472)))))
 (let (($x3469 (and $x3466 (not (and $x3300 $x3372)))))
 (let (($x3477 (and $x3469 (not (and $x3272 $x3438)))))
 (let (($x3467 (and $x3477 (not (and $x3313 $x3394)))))
 (let (($x3483 (and $x3467 (not (and $x3286 $x3455)))))
 (let (($x3478 (and $x3483 (not (and $x3335 $x3416)))))
 (let (($x3485 (and $x3478 (not (and $x3265 $x3472)))))
 (let (($x3488 (and $x3485 (not (and $x3272 $x3372)))))
 (let (($x3487 (and $x3488 (not (and $x3313 $x3383)))))
 (let (($x3498 (and $x3487 (not (and $x3279 $x3438)))))
 (let (($x3494 (and $x3498 (not (and $x3286 $x3394)))))
 (let (($x3502 (and $x3494 (not (and $x3335 $x3405)))))
 (let (($x3499 (and $x3502 $x3503)))
 (let (($x3509 (and $x3499 $x3508)))
 (let (($x3513 (and $x3509 $x3512)))
 (let (($x3517 (and $x3513 $x3516)))
 (let (($x3521 (and $x3517 $x3520)))
 (let (($x3525 (and $x3521 $x3524)))
 (let (($x3529 (and $x3525 $x3528)))
 (let (($x3532 (and $x3529 $x3531)))
 (let (($x3535 (and $x3532 $x3534)))
 (let (($x3539 (and $x3535 $x3538)))
 (let (($x3542 (and $x3539 $x3541)))
 (let (($x3545 (and $x3542 $x3544)))
 (let (($x3549 (and $x3545 $x3548)))
 (let (($x3552 (and $x3549 $x3551)))
 (let (($x3555 (and $x3552 $x3554)))
 (let (($x3558 (and $x3555 $x3557)))
 (let (($x3561 (and $x3558 $x3560)))
 (let (($x3564 (and $x3561 $x3563)))
 (let (($x3567 (and $x3564 $x3566)))
 (let (($x3570 (and $x3567 $x3569)))
 (let (($x3573 (and $x3570 $x3572)))
 (let (($x3576 (and $x3573 $x3575)))
 (let (($x3579 (and $x3576 $x3578)))
 (let (($x3582 (and $x3579 $x3581)))
 (let (($x3595 (and $x3582 (not (and (and true $x3597) $x3592)))))
 (let (($x3605 (and $x3595 (not (and (and true $x3611) $x3610)))))
 (let (($x3624 (and $x3605 (not (and (and true $x3625) $x3622)))))
 (let (($x3634 (and $x3624 (not (and (and true $x3639) $x3633)))))
 (let (($x3649 (and $x3634 (not (and (and true $x3653) $x3651)))))
 (let (($x3664 (and $x3649 (not (and (and true $x3667) $x3666)))))
 (let (($x3668 (and $x3664 (not (and (and true $x3597) $x3671)))))
 (let (($x3674 (and $x3668 (not (and (and true $x3611) $x3622)))))
 (let (($x3684 (and $x3674 (not (and (and true $x3689) $x3633)))))
 (let (($x3692 (and $x3684 (not (and (and true $x3625) $x3687)))))
 (let (($x3696 (and $x3692 (not (and (and true $x3639) $x3651)))))
 (let (($x3703 (and $x3696 (not (and (and true $x3709) $x3666)))))
 (let (($x3711 (and $x3703 (not (and (and true $x3611) $x3708)))))
 (let (($x3718 (and $x3711 (not (and (and true $x3689) $x3592)))))
 (let (($x3719 (and $x3718 (not (and (and true $x3639) $x3671)))))
 (let (($x3720 (and $x3719 (not (and (and true $x3709) $x3622)))))
 (let (($x3726 (and $x3720 (not (and (and true $x3667) $x3687)))))
 (let (($x3736 (and $x3726 (not (and (and true $x3738) $x3651)))))
 (let (($x3734 (and $x3736 (not (and (and true $x3625) $x3708)))))
 (let (($x3743 (and $x3734 (not (and (and true $x3639) $x3592)))))
 (let (($x3744 (and $x3743 (not (and (and true $x3709) $x3610)))))
 (let (($x3747 (and $x3744 (not (and (and true $x3653) $x3671)))))
 (let (($x3753 (and $x3747 (not (and (and true $x3667) $x3622)))))
 (let (($x3755 (and $x3753 (not (and (and true $x3738) $x3633)))))
 (let (($x3757 (and $x3755 (not (and (and true c_0_12) $x1847)))))
 (let (($x3761 (and $x3757 (not (and (and true c_1_12) $x1882)))))
 (let (($x3765 (and $x3761 (not (and (and true c_3_12) $x1952)))))
 (let (($x3769 (and $x3765 (not (and (and true c_4_12) $x1987)))))
 (let (($x3773 (and $x3769 (not (and (and true c_6_12) $x2057)))))
 (let (($x3777 (and $x3773 (not (and (and true c_7_12) $x2092)))))
 (let (($x3780 (and $x3777 (not (and (and true c_0_12) $x1917)))))
 (let (($x3783 (and $x3780 (not (and (and true c_1_12) $x1952)))))
 (let (($x3787 (and $x3783 (not (and (and true c_2_12) $x1987)))))
 (let (($x3790 (and $x3787 (not (and (and true c_3_12) $x2022)))))
 (let (($x3793 (and $x3790 (not (and (and true c_4_12) $x2057)))))
 (let (($x3797 (and $x3793 (not (and (and true c_5_12) $x2092)))))
 (let (($x3800 (and $x3797 (not (and (and true c_1_12) $x1812)))))
 (let (($x3803 (and $x3800 (not (and (and true c_2_12) $x1847)))))
 (let (($x3806 (and $x3803 (not (and (and true c_4_12) $x1917)))))
 (let (($x3809 (and $x3806 (not (and (and true c_5_12) $x1952)))))
 (let (($x3812 (and $x3809 (not (and (and true c_7_12) $x2022)))))
 (let (($x3816 (and $x3812 (not (and (and true c_8_12) $x2057)))))
 (let (($x3819 (and $x3816 (not (and (and true c_3_12) $x1812)))))
 (let (($x3822 (and $x3819 (not (and (and true c_4_12) $x1847)))))
 (let (($x3825 (and $x3822 (not (and (and true c_5_12) $x1882)))))
 (let (($x3828 (and $x3825 (not (and (and true c_6_12) $x1917)))))
 (let (($x3831 (and $x3828 (not (and (and true c_7_12) $x1952)))))
 (let (($x3834 (and $x3831 (not (and (and true c_8_12) $x1987)))))
 (let (($x3868 (and $x3834 (not (and (and $x3835 $x3846) $x3865)))))
 (let (($x3903 (and $x3868 (not (and (and $x3869 $x3880) $x3900)))))
 (let (($x3937 (and $x3903 (not (and (and $x3904 $x3915) $x3934)))))
 (let (($x3974 (and $x3937 (not (and (and $x3938 $x3949) $x3971)))))
 (let (($x4004 (and $x3974 (not (and (and $x3976 $x3986) $x4001)))))
 (let (($x4037 (and $x4004 (not (and (and $x4006 $x4016) $x4034)))))
 (let (($x4043 (and $x4037 (not (and $x4042 $x3865)))))
 (let (($x4049 (and $x4043 (not (and (and $x3869 $x3915) $x3900)))))
 (let (($x4073 (and $x4049 (not (and (and $x4050 $x3949) $x4070)))))
 (let (($x4079 (and $x4073 (not (and (and $x3904 $x4083) $x3934)))))
 (let (($x4084 (and $x4079 (not (and (and $x3938 $x3986) $x3971)))))
 (let (($x4111 (and $x4084 (not (and $x4088 $x4108)))))
 (let (($x4120 (and $x4111 (not (and $x4116 $x3900)))))
 (let (($x4125 (and $x4120 (not (and $x4117 $x4070)))))
 (let (($x4126 (and $x4125 (not (and (and $x3938 $x4047) $x3971)))))
 (let (($x4131 (and $x4126 (not (and (and $x4087 $x3915) $x4108)))))
 (let (($x4132 (and $x4131 (not (and $x4134 $x4034)))))
 (let (($x4157 (and $x4132 (not (and $x4138 $x4154)))))
 (let (($x4162 (and $x4157 (not (and $x4158 $x3934)))))
 (let (($x4166 (and $x4162 (not (and $x4159 $x3971)))))
 (let (($x4167 (and $x4166 (not (and $x4165 $x4108)))))
 (let (($x4170 (and $x4167 (not (and $x4171 $x4001)))))
 (let (($x4176 (and $x4170 (not (and $x4175 $x4034)))))
 (let (($x4182 (and $x4176 (not (and $x4177 $x4154)))))
 (let (($x4190 (and $x4182 (not (and $x4187 $x3846)))))
 (let (($x4198 (and $x4190 (not (and $x4197 $x3880)))))
 (let (($x4213 (and $x4198 (not (and $x4207 $x3915)))))
 (let (($x4219 (and $x4213 (not (and $x4217 $x3949)))))
 (let (($x4230 (and $x4219 (not (and $x4227 $x3986)))))
 (let (($x4241 (and $x4230 (not (and $x4237 $x4016)))))
 (let (($x4239 (and $x4241 (not (and $x4187 $x4047)))))
 (let (($x4249 (and $x4239 (not (and $x4197 $x3915)))))
 (let (($x4256 (and $x4249 (not (and $x4253 $x3949)))))
 (let (($x4261 (and $x4256 (not (and $x4207 $x4083)))))
 (let (($x4265 (and $x4261 (not (and $x4217 $x3986)))))
 (let (($x4273 (and $x4265 (not (and $x4269 $x4016)))))
 (let (($x4277 (and $x4273 (not (and $x4197 $x4121)))))
 (let (($x4279 (and $x4277 (not (and $x4253 $x3846)))))
 (let (($x4280 (and $x4279 (not (and $x4217 $x4047)))))
 (let (($x4287 (and $x4280 (not (and $x4269 $x3915)))))
 (let (($x4290 (and $x4287 (not (and $x4237 $x4083)))))
 (let (($x4297 (and $x4290 (not (and $x4294 $x3986)))))
 (let (($x4301 (and $x4297 (not (and $x4207 $x4121)))))
 (let (($x4305 (and $x4301 (not (and $x4217 $x3846)))))
 (let (($x4308 (and $x4305 (not (and $x4269 $x3880)))))
 (let (($x4312 (and $x4308 (not (and $x4227 $x4047)))))
 (let (($x4315 (and $x4312 (not (and $x4237 $x3915)))))
 (let (($x4316 (and $x4315 (not (and $x4294 $x3949)))))
 (and $x4316 (and $x5205 $x5479))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
