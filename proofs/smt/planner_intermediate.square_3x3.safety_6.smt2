; holon proof obligation: system planner_intermediate, region square:3x3, property safety.6
; expected: unsat (the property holds for every configuration of the region)
(set-logic ALL)
; 
(set-info :status unknown)
(declare-fun d_0_6 () Bool)
(declare-fun d_0_5 () Bool)
(declare-fun d_0_4 () Bool)
(declare-fun d_0_3 () Bool)
(declare-fun d_0_2 () Bool)
(declare-fun d_0_1 () Bool)
(declare-fun d_0_0 () Bool)
(declare-fun d_1_6 () Bool)
(declare-fun d_1_5 () Bool)
(declare-fun d_1_4 () Bool)
(declare-fun d_1_3 () Bool)
(declare-fun d_1_2 () Bool)
(declare-fun d_1_1 () Bool)
(declare-fun d_1_0 () Bool)
(declare-fun d_2_6 () Bool)
(declare-fun d_2_5 () Bool)
(declare-fun d_2_4 () Bool)
(declare-fun d_2_3 () Bool)
(declare-fun d_2_2 () Bool)
(declare-fun d_2_1 () Bool)
(declare-fun d_2_0 () Bool)
(declare-fun d_3_6 () Bool)
(declare-fun d_3_5 () Bool)
(declare-fun d_3_4 () Bool)
(declare-fun d_3_3 () Bool)
(declare-fun d_3_2 () Bool)
(declare-fun d_3_1 () Bool)
(declare-fun d_3_0 () Bool)
(declare-fun d_4_6 () Bool)
(declare-fun d_4_5 () Bool)
(declare-fun d_4_4 () Bool)
(declare-fun d_4_3 () Bool)
(declare-fun d_4_2 () Bool)
(declare-fun d_4_1 () Bool)
(declare-fun d_4_0 () Bool)
(declare-fun d_5_6 () Bool)
(declare-fun d_5_5 () Bool)
(declare-fun d_5_4 () Bool)
(declare-fun d_5_3 () Bool)
(declare-fun d_5_2 () Bool)
(declare-fun d_5_1 () Bool)
(declare-fun d_5_0 () Bool)
(declare-fun d_6_6 () Bool)
(declare-fun d_6_5 () Bool)
(declare-fun d_6_4 () Bool)
(declare-fun d_6_3 () Bool)
(declare-fun d_6_2 () Bool)
(declare-fun d_6_1 () Bool)
(declare-fun d_6_0 () Bool)
(declare-fun d_7_6 () Bool)
(declare-fun d_7_5 () Bool)
(declare-fun d_7_4 () Bool)
(declare-fun d_7_3 () Bool)
(declare-fun d_7_2 () Bool)
(declare-fun d_7_1 () Bool)
(declare-fun d_7_0 () Bool)
(declare-fun d_8_6 () Bool)
(declare-fun d_8_5 () Bool)
(declare-fun d_8_4 () Bool)
(declare-fun d_8_3 () Bool)
(declare-fun d_8_2 () Bool)
(declare-fun d_8_1 () Bool)
(declare-fun d_8_0 () Bool)
(declare-fun rank_0 () Int)
(declare-fun rank_2 () Int)
(declare-fun rank_4 () Int)
(declare-fun rank_6 () Int)
(declare-fun rank_8 () Int)
(declare-fun rank_10 () Int)
(declare-fun rank_12 () Int)
(declare-fun rank_14 () Int)
(declare-fun rank_16 () Int)
(declare-fun prank_18 () Int)
(declare-fun prank_19 () Int)
(declare-fun prank_20 () Int)
(declare-fun prank_21 () Int)
(declare-fun prank_22 () Int)
(declare-fun prank_23 () Int)
(declare-fun prank_24 () Int)
(declare-fun prank_25 () Int)
(declare-fun prank_26 () Int)
(declare-fun prank_29 () Int)
(declare-fun prank_30 () Int)
(declare-fun prank_31 () Int)
(declare-fun prank_32 () Int)
(declare-fun prank_33 () Int)
(declare-fun prank_34 () Int)
(declare-fun prank_35 () Int)
(declare-fun prank_36 () Int)
(declare-fun prank_37 () Int)
(declare-fun cut_48 () Bool)
(declare-fun cut_47 () Bool)
(declare-fun cut_46 () Bool)
(declare-fun cut_45 () Bool)
(declare-fun cut_44 () Bool)
(declare-fun cut_43 () Bool)
(declare-fun cut_42 () Bool)
(declare-fun cut_41 () Bool)
(declare-fun cut_40 () Bool)
(declare-fun prank_high_39 () Int)
(declare-fun prank_low_38 () Int)
(declare-fun prank_high_28 () Int)
(declare-fun prank_low_27 () Int)
(declare-fun in_target_8 () Bool)
(declare-fun in_target_7 () Bool)
(declare-fun in_target_6 () Bool)
(declare-fun in_target_5 () Bool)
(declare-fun in_target_4 () Bool)
(declare-fun in_target_3 () Bool)
(declare-fun in_target_2 () Bool)
(declare-fun in_target_1 () Bool)
(declare-fun in_target_0 () Bool)
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
 (let (($x15 (or false d_0_0)))
 (let (($x17 (or $x15 d_0_1)))
 (let (($x19 (or $x17 d_0_2)))
 (let (($x21 (or $x19 d_0_3)))
 (let (($x23 (or $x21 d_0_4)))
 (let (($x25 (or $x23 d_0_5)))
 (or $x25 d_0_6))))))))
(assert
 (not (and d_0_0 d_0_1)))
(assert
 (not (and d_0_0 d_0_2)))
(assert
 (not (and d_0_0 d_0_3)))
(assert
 (not (and d_0_0 d_0_4)))
(assert
 (not (and d_0_0 d_0_5)))
(assert
 (not (and d_0_0 d_0_6)))
(assert
 (not (and d_0_1 d_0_2)))
(assert
 (not (and d_0_1 d_0_3)))
(assert
 (not (and d_0_1 d_0_4)))
(assert
 (not (and d_0_1 d_0_5)))
(assert
 (not (and d_0_1 d_0_6)))
(assert
 (not (and d_0_2 d_0_3)))
(assert
 (not (and d_0_2 d_0_4)))
(assert
 (not (and d_0_2 d_0_5)))
(assert
 (not (and d_0_2 d_0_6)))
(assert
 (not (and d_0_3 d_0_4)))
(assert
 (not (and d_0_3 d_0_5)))
(assert
 (not (and d_0_3 d_0_6)))
(assert
 (not (and d_0_4 d_0_5)))
(assert
 (not (and d_0_4 d_0_6)))
(assert
 (not (and d_0_5 d_0_6)))
(assert
 (let (($x71 (or false d_1_0)))
 (let (($x73 (or $x71 d_1_1)))
 (let (($x75 (or $x73 d_1_2)))
 (let (($x77 (or $x75 d_1_3)))
 (let (($x79 (or $x77 d_1_4)))
 (let (($x81 (or $x79 d_1_5)))
 (or $x81 d_1_6))))))))
(assert
 (not (and d_1_0 d_1_1)))
(assert
 (not (and d_1_0 d_1_2)))
(assert
 (not (and d_1_0 d_1_3)))
(assert
 (not (and d_1_0 d_1_4)))
(assert
 (not (and d_1_0 d_1_5)))
(assert
 (not (and d_1_0 d_1_6)))
(assert
 (not (and d_1_1 d_1_2)))
(assert
 (not (and d_1_1 d_1_3)))
(assert
 (not (and d_1_1 d_1_4)))
(assert
 (not (and d_1_1 d_1_5)))
(assert
 (not (and d_1_1 d_1_6)))
(assert
 (not (and d_1_2 d_1_3)))
(assert
 (not (and d_1_2 d_1_4)))
(assert
 (not (and d_1_2 d_1_5)))
(assert
 (not (and d_1_2 d_1_6)))
(assert
 (not (and d_1_3 d_1_4)))
(assert
 (not (and d_1_3 d_1_5)))
(assert
 (not (and d_1_3 d_1_6)))
(assert
 (not (and d_1_4 d_1_5)))
(assert
 (not (and d_1_4 d_1_6)))
(assert
 (not (and d_1_5 d_1_6)))
(assert
 (let (($x127 (or false d_2_0)))
 (let (($x129 (or $x127 d_2_1)))
 (let (($x131 (or $x129 d_2_2)))
 (let (($x133 (or $x131 d_2_3)))
 (let (($x135 (or $x133 d_2_4)))
 (let (($x137 (or $x135 d_2_5)))
 (or $x137 d_2_6))))))))
(assert
 (not (and d_2_0 d_2_1)))
(assert
 (not (and d_2_0 d_2_2)))
(assert
 (not (and d_2_0 d_2_3)))
(assert
 (not (and d_2_0 d_2_4)))
(assert
 (not (and d_2_0 d_2_5)))
(assert
 (not (and d_2_0 d_2_6)))
(assert
 (not (and d_2_1 d_2_2)))
(assert
 (not (and d_2_1 d_2_3)))
(assert
 (not (and d_2_1 d_2_4)))
(assert
 (not (and d_2_1 d_2_5)))
(assert
 (not (and d_2_1 d_2_6)))
(assert
 (not (and d_2_2 d_2_3)))
(assert
 (not (and d_2_2 d_2_4)))
(assert
 (not (and d_2_2 d_2_5)))
(assert
 (not (and d_2_2 d_2_6)))
(assert
 (not (and d_2_3 d_2_4)))
(assert
 (not (and d_2_3 d_2_5)))
(assert
 (not (and d_2_3 d_2_6)))
(assert
 (not (and d_2_4 d_2_5)))
(assert
 (not (and d_2_4 d_2_6)))
(assert
 (not (and d_2_5 d_2_6)))
(assert
 (let (($x183 (or false d_3_0)))
 (let (($x185 (or $x183 d_3_1)))
 (let (($x187 (or $x185 d_3_2)))
 (let (($x189 (or $x187 d_3_3)))
 (let (($x191 (or $x189 d_3_4)))
 (let (($x193 (or $x191 d_3_5)))
 (or $x193 d_3_6))))))))
(assert
 (not (and d_3_0 d_3_1)))
(assert
 (not (and d_3_0 d_3_2)))
(assert
 (not (and d_3_0 d_3_3)))
(assert
 (not (and d_3_0 d_3_4)))
(assert
 (not (and d_3_0 d_3_5)))
(assert
 (not (and d_3_0 d_3_6)))
(assert
 (not (and d_3_1 d_3_2)))
(assert
 (not (and d_3_1 d_3_3)))
(assert
 (not (and d_3_1 d_3_4)))
(assert
 (not (and d_3_1 d_3_5)))
(assert
 (not (and d_3_1 d_3_6)))
(assert
 (not (and d_3_2 d_3_3)))
(assert
 (not (and d_3_2 d_3_4)))
(assert
 (not (and d_3_2 d_3_5)))
(assert
 (not (and d_3_2 d_3_6)))
(assert
 (not (and d_3_3 d_3_4)))
(assert
 (not (and d_3_3 d_3_5)))
(assert
 (not (and d_3_3 d_3_6)))
(assert
 (not (and d_3_4 d_3_5)))
(assert
 (not (and d_3_4 d_3_6)))
(assert
 (not (and d_3_5 d_3_6)))
(assert
 (let (($x239 (or false d_4_0)))
 (let (($x241 (or $x239 d_4_1)))
 (let (($x243 (or $x241 d_4_2)))
 (let (($x245 (or $x243 d_4_3)))
 (let (($x247 (or $x245 d_4_4)))
 (let (($x249 (or $x247 d_4_5)))
 (or $x249 d_4_6))))))))
(assert
 (not (and d_4_0 d_4_1)))
(assert
 (not (and d_4_0 d_4_2)))
(assert
 (not (and d_4_0 d_4_3)))
(assert
 (not (and d_4_0 d_4_4)))
(assert
 (not (and d_4_0 d_4_5)))
(assert
 (not (and d_4_0 d_4_6)))
(assert
 (not (and d_4_1 d_4_2)))
(assert
 (not (and d_4_1 d_4_3)))
(assert
 (not (and d_4_1 d_4_4)))
(assert
 (not (and d_4_1 d_4_5)))
(assert
 (not (and d_4_1 d_4_6)))
(assert
 (not (and d_4_2 d_4_3)))
(assert
 (not (and d_4_2 d_4_4)))
(assert
 (not (and d_4_2 d_4_5)))
(assert
 (not (and d_4_2 d_4_6)))
(assert
 (not (and d_4_3 d_4_4)))
(assert
 (not (and d_4_3 d_4_5)))
(assert
 (not (and d_4_3 d_4_6)))
(assert
 (not (and d_4_4 d_4_5)))
(assert
 (not (and d_4_4 d_4_6)))
(assert
 (not (and d_4_5 d_4_6)))
(assert
 (let (($x295 (or false d_5_0)))
 (let (($x297 (or $x295 d_5_1)))
 (let (($x299 (or $x297 d_5_2)))
 (let (($x301 (or $x299 d_5_3)))
 (let (($x303 (or $x301 d_5_4)))
 (let (($x305 (or $x303 d_5_5)))
 (or $x305 d_5_6))))))))
(assert
 (not (and d_5_0 d_5_1)))
(assert
 (not (and d_5_0 d_5_2)))
(assert
 (not (and d_5_0 d_5_3)))
(assert
 (not (and d_5_0 d_5_4)))
(assert
 (not (and d_5_0 d_5_5)))
(assert
 (not (and d_5_0 d_5_6)))
(assert
 (not (and d_5_1 d_5_2)))
(assert
 (not (and d_5_1 d_5_3)))
(assert
 (not (and d_5_1 d_5_4)))
(assert
 (not (and d_5_1 d_5_5)))
(assert
 (not (and d_5_1 d_5_6)))
(assert
 (not (and d_5_2 d_5_3)))
(assert
 (not (and d_5_2 d_5_4)))
(assert
 (not (and d_5_2 d_5_5)))
(assert
 (not (and d_5_2 d_5_6)))
(assert
 (not (and d_5_3 d_5_4)))
(assert
 (not (and d_5_3 d_5_5)))
(assert
 (not (and d_5_3 d_5_6)))
(assert
 (not (and d_5_4 d_5_5)))
(assert
 (not (and d_5_4 d_5_6)))
(assert
 (not (and d_5_5 d_5_6)))
(assert
 (let (($x351 (or false d_6_0)))
 (let (($x353 (or $x351 d_6_1)))
 (let (($x355 (or $x353 d_6_2)))
 (let (($x357 (or $x355 d_6_3)))
 (let (($x359 (or $x357 d_6_4)))
 (let (($x361 (or $x359 d_6_5)))
 (or $x361 d_6_6))))))))
(assert
 (not (and d_6_0 d_6_1)))
(assert
 (not (and d_6_0 d_6_2)))
(assert
 (not (and d_6_0 d_6_3)))
(assert
 (not (and d_6_0 d_6_4)))
(assert
 (not (and d_6_0 d_6_5)))
(assert
 (not (and d_6_0 d_6_6)))
(assert
 (not (and d_6_1 d_6_2)))
(assert
 (not (and d_6_1 d_6_3)))
(assert
 (not (and d_6_1 d_6_4)))
(assert
 (not (and d_6_1 d_6_5)))
(assert
 (not (and d_6_1 d_6_6)))
(assert
 (not (and d_6_2 d_6_3)))
(assert
 (not (and d_6_2 d_6_4)))
(assert
 (not (and d_6_2 d_6_5)))
(assert
 (not (and d_6_2 d_6_6)))
(assert
 (not (and d_6_3 d_6_4)))
(assert
 (not (and d_6_3 d_6_5)))
(assert
 (not (and d_6_3 d_6_6)))
(assert
 (not (and d_6_4 d_6_5)))
(assert
 (not (and d_6_4 d_6_6)))
(assert
 (not (and d_6_5 d_6_6)))
(assert
 (let (($x407 (or false d_7_0)))
 (let (($x409 (or $x407 d_7_1)))
 (let (($x411 (or $x409 d_7_2)))
 (let (($x413 (or $x411 d_7_3)))
 (let (($x415 (or $x413 d_7_4)))
 (let (($x417 (or $x415 d_7_5)))
 (or $x417 d_7_6))))))))
(assert
 (not (and d_7_0 d_7_1)))
(assert
 (not (and d_7_0 d_7_2)))
(assert
 (not (and d_7_0 d_7_3)))
(assert
 (not (and d_7_0 d_7_4)))
(assert
 (not (and d_7_0 d_7_5)))
(assert
 (not (and d_7_0 d_7_6)))
(assert
 (not (and d_7_1 d_7_2)))
(assert
 (not (and d_7_1 d_7_3)))
(assert
 (not (and d_7_1 d_7_4)))
(assert
 (not (and d_7_1 d_7_5)))
(assert
 (not (and d_7_1 d_7_6)))
(assert
 (not (and d_7_2 d_7_3)))
(assert
 (not (and d_7_2 d_7_4)))
(assert
 (not (and d_7_2 d_7_5)))
(assert
 (not (and d_7_2 d_7_6)))
(assert
 (not (and d_7_3 d_7_4)))
(assert
 (not (and d_7_3 d_7_5)))
(assert
 (not (and d_7_3 d_7_6)))
(assert
 (not (and d_7_4 d_7_5)))
(assert
 (not (and d_7_4 d_7_6)))
(assert
 (not (and d_7_5 d_7_6)))
(assert
 (let (($x463 (or false d_8_0)))
 (let (($x465 (or $x463 d_8_1)))
 (let (($x467 (or $x465 d_8_2)))
 (let (($x469 (or $x467 d_8_3)))
 (let (($x471 (or $x469 d_8_4)))
 (let (($x473 (or $x471 d_8_5)))
 (or $x473 d_8_6))))))))
(assert
 (not (and d_8_0 d_8_1)))
(assert
 (not (and d_8_0 d_8_2)))
(assert
 (not (and d_8_0 d_8_3)))
(assert
 (not (and d_8_0 d_8_4)))
(assert
 (not (and d_8_0 d_8_5)))
(assert
 (not (and d_8_0 d_8_6)))
(assert
 (not (and d_8_1 d_8_2)))
(assert
 (not (and d_8_1 d_8_3)))
(assert
 (not (and d_8_1 d_8_4)))
(assert
 (not (and d_8_1 d_8_5)))
(assert
 (not (and d_8_1 d_8_6)))
(assert
 (not (and d_8_2 d_8_3)))
(assert
 (not (and d_8_2 d_8_4)))
(assert
 (not (and d_8_2 d_8_5)))
(assert
 (not (and d_8_2 d_8_6)))
(assert
 (not (and d_8_3 d_8_4)))
(assert
 (not (and d_8_3 d_8_5)))
(assert
 (not (and d_8_3 d_8_6)))
(assert
 (not (and d_8_4 d_8_5)))
(assert
 (not (and d_8_4 d_8_6)))
(assert
 (not (and d_8_5 d_8_6)))
(assert
 (let (($x539 (>= rank_0 0)))
 (and $x539 (< rank_0 9))))
(assert
 (let (($x545 (>= rank_2 0)))
 (and $x545 (< rank_2 9))))
(assert
 (let (($x550 (>= rank_4 0)))
 (and $x550 (< rank_4 9))))
(assert
 (let (($x555 (>= rank_6 0)))
 (and $x555 (< rank_6 9))))
(assert
 (let (($x560 (>= rank_8 0)))
 (and $x560 (< rank_8 9))))
(assert
 (let (($x565 (>= rank_10 0)))
 (and $x565 (< rank_10 9))))
(assert
 (let (($x570 (>= rank_12 0)))
 (and $x570 (< rank_12 9))))
(assert
 (let (($x575 (>= rank_14 0)))
 (and $x575 (< rank_14 9))))
(assert
 (let (($x580 (>= rank_16 0)))
 (and $x580 (< rank_16 9))))
(assert
 (let (($x815 (>= prank_18 0)))
 (and $x815 (< prank_18 9))))
(assert
 (let (($x820 (>= prank_19 0)))
 (and $x820 (< prank_19 9))))
(assert
 (let (($x824 (>= prank_20 0)))
 (and $x824 (< prank_20 9))))
(assert
 (let (($x828 (>= prank_21 0)))
 (and $x828 (< prank_21 9))))
(assert
 (let (($x832 (>= prank_22 0)))
 (and $x832 (< prank_22 9))))
(assert
 (let (($x836 (>= prank_23 0)))
 (and $x836 (< prank_23 9))))
(assert
 (let (($x840 (>= prank_24 0)))
 (and $x840 (< prank_24 9))))
(assert
 (let (($x844 (>= prank_25 0)))
 (and $x844 (< prank_25 9))))
(assert
 (let (($x848 (>= prank_26 0)))
 (and $x848 (< prank_26 9))))
(assert
 (let (($x1111 (>= prank_29 0)))
 (and $x1111 (< prank_29 9))))
(assert
 (let (($x1117 (>= prank_30 0)))
 (and $x1117 (< prank_30 9))))
(assert
 (let (($x1121 (>= prank_31 0)))
 (and $x1121 (< prank_31 9))))
(assert
 (let (($x1125 (>= prank_32 0)))
 (and $x1125 (< prank_32 9))))
(assert
 (let (($x1129 (>= prank_33 0)))
 (and $x1129 (< prank_33 9))))
(assert
 (let (($x1133 (>= prank_34 0)))
 (and $x1133 (< prank_34 9))))
(assert
 (let (($x1137 (>= prank_35 0)))
 (and $x1137 (< prank_35 9))))
(assert
 (let (($x1141 (>= prank_36 0)))
 (and $x1141 (< prank_36 9))))
(assert
 (let (($x1145 (>= prank_37 0)))
 (and $x1145 (< prank_37 9))))
(assert
 (let (($x1469 (not cut_48)))
 (let (($x1448 (or d_8_1 d_8_2 d_8_3 d_8_4 d_8_5 d_8_6)))
 (let (($x1470 (and $x1448 $x1469)))
 (let (($x1466 (not cut_47)))
 (let (($x1442 (or d_7_1 d_7_2 d_7_3 d_7_4 d_7_5 d_7_6)))
 (let (($x1467 (and $x1442 $x1466)))
 (let (($x1463 (not cut_46)))
 (let (($x1436 (or d_6_1 d_6_2 d_6_3 d_6_4 d_6_5 d_6_6)))
 (let (($x1464 (and $x1436 $x1463)))
 (let (($x1460 (not cut_45)))
 (let (($x1430 (or d_5_1 d_5_2 d_5_3 d_5_4 d_5_5 d_5_6)))
 (let (($x1461 (and $x1430 $x1460)))
 (let (($x1457 (not cut_44)))
 (let (($x1424 (or d_4_1 d_4_2 d_4_3 d_4_4 d_4_5 d_4_6)))
 (let (($x1458 (and $x1424 $x1457)))
 (let (($x1454 (not cut_43)))
 (let (($x1418 (or d_3_1 d_3_2 d_3_3 d_3_4 d_3_5 d_3_6)))
 (let (($x1455 (and $x1418 $x1454)))
 (let (($x1451 (not cut_42)))
 (let (($x1412 (or d_2_1 d_2_2 d_2_3 d_2_4 d_2_5 d_2_6)))
 (let (($x1452 (and $x1412 $x1451)))
 (let (($x1446 (not cut_41)))
 (let (($x1406 (or d_1_1 d_1_2 d_1_3 d_1_4 d_1_5 d_1_6)))
 (let (($x1449 (and $x1406 $x1446)))
 (let (($x1445 (not cut_40)))
 (let (($x1400 (or d_0_1 d_0_2 d_0_3 d_0_4 d_0_5 d_0_6)))
 (let (($x1444 (and $x1400 $x1445)))
 (let (($x1474 (or false $x1444)))
 (let (($x1484 (or $x1474 $x1449)))
 (let (($x1497 (or $x1484 $x1452)))
 (let (($x1507 (or $x1497 $x1455)))
 (let (($x1520 (or $x1507 $x1458)))
 (let (($x1536 (or $x1520 $x1461)))
 (let (($x1549 (or $x1536 $x1464)))
 (let (($x1559 (or $x1549 $x1467)))
 (let (($x1473 (or false cut_40)))
 (let (($x1483 (or $x1473 cut_41)))
 (let (($x1496 (or $x1483 cut_42)))
 (let (($x1506 (or $x1496 cut_43)))
 (let (($x1519 (or $x1506 cut_44)))
 (let (($x1535 (or $x1519 cut_45)))
 (let (($x1548 (or $x1535 cut_46)))
 (let (($x1558 (or $x1548 cut_47)))
 (let (($x1472 (and true (=> cut_40 $x1400))))
 (let (($x1477 (and $x1472 (=> (and cut_40 $x1406) cut_41))))
 (let (($x1480 (and $x1477 (=> (and cut_40 $x1418) cut_43))))
 (let (($x1482 (and $x1480 (=> cut_41 $x1406))))
 (let (($x1487 (and $x1482 (=> (and cut_41 $x1412) cut_42))))
 (let (($x1490 (and $x1487 (=> (and cut_41 $x1424) cut_44))))
 (let (($x1493 (and $x1490 (=> (and cut_41 $x1400) cut_40))))
 (let (($x1495 (and $x1493 (=> cut_42 $x1412))))
 (let (($x1500 (and $x1495 (=> (and cut_42 $x1430) cut_45))))
 (let (($x1503 (and $x1500 (=> (and cut_42 $x1406) cut_41))))
 (let (($x1505 (and $x1503 (=> cut_43 $x1418))))
 (let (($x1510 (and $x1505 (=> (and cut_43 $x1424) cut_44))))
 (let (($x1513 (and $x1510 (=> (and cut_43 $x1436) cut_46))))
 (let (($x1516 (and $x1513 (=> (and cut_43 $x1400) cut_40))))
 (let (($x1518 (and $x1516 (=> cut_44 $x1424))))
 (let (($x1523 (and $x1518 (=> (and cut_44 $x1430) cut_45))))
 (let (($x1526 (and $x1523 (=> (and cut_44 $x1442) cut_47))))
 (let (($x1529 (and $x1526 (=> (and cut_44 $x1418) cut_43))))
 (let (($x1532 (and $x1529 (=> (and cut_44 $x1406) cut_41))))
 (let (($x1534 (and $x1532 (=> cut_45 $x1430))))
 (let (($x1539 (and $x1534 (=> (and cut_45 $x1448) cut_48))))
 (let (($x1542 (and $x1539 (=> (and cut_45 $x1424) cut_44))))
 (let (($x1545 (and $x1542 (=> (and cut_45 $x1412) cut_42))))
 (let (($x1547 (and $x1545 (=> cut_46 $x1436))))
 (let (($x1552 (and $x1547 (=> (and cut_46 $x1442) cut_47))))
 (let (($x1555 (and $x1552 (=> (and cut_46 $x1418) cut_43))))
 (let (($x1557 (and $x1555 (=> cut_47 $x1442))))
 (let (($x1562 (and $x1557 (=> (and cut_47 $x1448) cut_48))))
 (let (($x1565 (and $x1562 (=> (and cut_47 $x1436) cut_46))))
 (let (($x1568 (and $x1565 (=> (and cut_47 $x1424) cut_44))))
 (let (($x1570 (and $x1568 (=> cut_48 $x1448))))
 (let (($x1575 (and $x1570 (=> (and cut_48 $x1442) cut_47))))
 (let (($x1580 (and (and (and $x1575 (=> (and cut_48 $x1430) cut_45)) (or $x1558 cut_48)) (or $x1559 $x1470))))
 (let (($x1385 (and d_8_1 (= prank_37 prank_high_39))))
 (let (($x1362 (and d_7_1 (= prank_36 prank_high_39))))
 (let (($x1334 (and d_6_1 (= prank_35 prank_high_39))))
 (let (($x1311 (and d_5_1 (= prank_34 prank_high_39))))
 (let (($x1283 (and d_4_1 (= prank_33 prank_high_39))))
 (let (($x1250 (and d_3_1 (= prank_32 prank_high_39))))
 (let (($x1222 (and d_2_1 (= prank_31 prank_high_39))))
 (let (($x1199 (and d_1_1 (= prank_30 prank_high_39))))
 (let (($x1171 (and d_0_1 (= prank_29 prank_high_39))))
 (let (($x1172 (or false $x1171)))
 (let (($x1200 (or $x1172 $x1199)))
 (let (($x1223 (or $x1200 $x1222)))
 (let (($x1251 (or $x1223 $x1250)))
 (let (($x1284 (or $x1251 $x1283)))
 (let (($x1312 (or $x1284 $x1311)))
 (let (($x1335 (or $x1312 $x1334)))
 (let (($x1363 (or $x1335 $x1362)))
 (let (($x1382 (and d_8_1 (= prank_37 prank_low_38))))
 (let (($x1359 (and d_7_1 (= prank_36 prank_low_38))))
 (let (($x1331 (and d_6_1 (= prank_35 prank_low_38))))
 (let (($x1308 (and d_5_1 (= prank_34 prank_low_38))))
 (let (($x1280 (and d_4_1 (= prank_33 prank_low_38))))
 (let (($x1247 (and d_3_1 (= prank_32 prank_low_38))))
 (let (($x1219 (and d_2_1 (= prank_31 prank_low_38))))
 (let (($x1196 (and d_1_1 (= prank_30 prank_low_38))))
 (let (($x1168 (and d_0_1 (= prank_29 prank_low_38))))
 (let (($x1169 (or false $x1168)))
 (let (($x1197 (or $x1169 $x1196)))
 (let (($x1220 (or $x1197 $x1219)))
 (let (($x1248 (or $x1220 $x1247)))
 (let (($x1281 (or $x1248 $x1280)))
 (let (($x1309 (or $x1281 $x1308)))
 (let (($x1332 (or $x1309 $x1331)))
 (let (($x1360 (or $x1332 $x1359)))
 (let (($x1166 (or false d_0_1)))
 (let (($x1194 (or $x1166 d_1_1)))
 (let (($x1217 (or $x1194 d_2_1)))
 (let (($x1245 (or $x1217 d_3_1)))
 (let (($x1278 (or $x1245 d_4_1)))
 (let (($x1306 (or $x1278 d_5_1)))
 (let (($x1329 (or $x1306 d_6_1)))
 (let (($x1357 (or $x1329 d_7_1)))
 (let (($x1108 (or d_5_2 d_5_3 d_5_4 d_5_5 d_5_6)))
 (let (($x1112 (or d_7_2 d_7_3 d_7_4 d_7_5 d_7_6)))
 (let (($x1368 (or false (and true (or $x1112 (and d_7_1 (< prank_36 prank_37)))))))
 (let (($x1373 (or $x1368 (and true (or $x1108 (and d_5_1 (< prank_34 prank_37)))))))
 (let (($x1377 (and (and $x1373 (<= prank_low_38 prank_37)) (<= prank_37 prank_high_39))))
 (let (($x1106 (or d_4_2 d_4_3 d_4_4 d_4_5 d_4_6)))
 (let (($x1110 (or d_6_2 d_6_3 d_6_4 d_6_5 d_6_6)))
 (let (($x1114 (or d_8_2 d_8_3 d_8_4 d_8_5 d_8_6)))
 (let (($x1340 (or false (and true (or $x1114 (and d_8_1 (< prank_37 prank_36)))))))
 (let (($x1345 (or $x1340 (and true (or $x1110 (and d_6_1 (< prank_35 prank_36)))))))
 (let (($x1350 (or $x1345 (and true (or $x1106 (and d_4_1 (< prank_33 prank_36)))))))
 (let (($x1354 (and (and $x1350 (<= prank_low_38 prank_36)) (<= prank_36 prank_high_39))))
 (let (($x1104 (or d_3_2 d_3_3 d_3_4 d_3_5 d_3_6)))
 (let (($x1317 (or false (and true (or $x1112 (and d_7_1 (< prank_36 prank_35)))))))
 (let (($x1322 (or $x1317 (and true (or $x1104 (and d_3_1 (< prank_32 prank_35)))))))
 (let (($x1326 (and (and $x1322 (<= prank_low_38 prank_35)) (<= prank_35 prank_high_39))))
 (let (($x1102 (or d_2_2 d_2_3 d_2_4 d_2_5 d_2_6)))
 (let (($x1289 (or false (and true (or $x1114 (and d_8_1 (< prank_37 prank_34)))))))
 (let (($x1294 (or $x1289 (and true (or $x1106 (and d_4_1 (< prank_33 prank_34)))))))
 (let (($x1299 (or $x1294 (and true (or $x1102 (and d_2_1 (< prank_31 prank_34)))))))
 (let (($x1303 (and (and $x1299 (<= prank_low_38 prank_34)) (<= prank_34 prank_high_39))))
 (let (($x1100 (or d_1_2 d_1_3 d_1_4 d_1_5 d_1_6)))
 (let (($x1256 (or false (and true (or $x1108 (and d_5_1 (< prank_34 prank_33)))))))
 (let (($x1261 (or $x1256 (and true (or $x1112 (and d_7_1 (< prank_36 prank_33)))))))
 (let (($x1266 (or $x1261 (and true (or $x1104 (and d_3_1 (< prank_32 prank_33)))))))
 (let (($x1271 (or $x1266 (and true (or $x1100 (and d_1_1 (< prank_30 prank_33)))))))
 (let (($x1275 (and (and $x1271 (<= prank_low_38 prank_33)) (<= prank_33 prank_high_39))))
 (let (($x1098 (or d_0_2 d_0_3 d_0_4 d_0_5 d_0_6)))
 (let (($x1228 (or false (and true (or $x1106 (and d_4_1 (< prank_33 prank_32)))))))
 (let (($x1233 (or $x1228 (and true (or $x1110 (and d_6_1 (< prank_35 prank_32)))))))
 (let (($x1238 (or $x1233 (and true (or $x1098 (and d_0_1 (< prank_29 prank_32)))))))
 (let (($x1242 (and (and $x1238 (<= prank_low_38 prank_32)) (<= prank_32 prank_high_39))))
 (let (($x1205 (or false (and true (or $x1108 (and d_5_1 (< prank_34 prank_31)))))))
 (let (($x1210 (or $x1205 (and true (or $x1100 (and d_1_1 (< prank_30 prank_31)))))))
 (let (($x1214 (and (and $x1210 (<= prank_low_38 prank_31)) (<= prank_31 prank_high_39))))
 (let (($x1177 (or false (and true (or $x1102 (and d_2_1 (< prank_31 prank_30)))))))
 (let (($x1182 (or $x1177 (and true (or $x1106 (and d_4_1 (< prank_33 prank_30)))))))
 (let (($x1187 (or $x1182 (and true (or $x1098 (and d_0_1 (< prank_29 prank_30)))))))
 (let (($x1191 (and (and $x1187 (<= prank_low_38 prank_30)) (<= prank_30 prank_high_39))))
 (let (($x1154 (or false (and true (or $x1100 (and d_1_1 (< prank_30 prank_29)))))))
 (let (($x1159 (or $x1154 (and true (or $x1104 (and d_3_1 (< prank_32 prank_29)))))))
 (let (($x1163 (and (and $x1159 (<= prank_low_38 prank_29)) (<= prank_29 prank_high_39))))
 (let (($x1165 (and true (=> d_0_1 $x1163))))
 (let (($x1193 (and $x1165 (=> d_1_1 $x1191))))
 (let (($x1216 (and $x1193 (=> d_2_1 $x1214))))
 (let (($x1244 (and $x1216 (=> d_3_1 $x1242))))
 (let (($x1277 (and $x1244 (=> d_4_1 $x1275))))
 (let (($x1305 (and $x1277 (=> d_5_1 $x1303))))
 (let (($x1328 (and $x1305 (=> d_6_1 $x1326))))
 (let (($x1356 (and $x1328 (=> d_7_1 $x1354))))
 (let (($x1379 (and $x1356 (=> d_8_1 $x1377))))
 (let (($x1389 (and $x1379 (=> (or $x1357 d_8_1) (and (or $x1360 $x1382) (or $x1363 $x1385))))))
 (let (($x817 (or d_8_2 d_8_3 d_8_4 d_8_5)))
 (let (($x1088 (and $x817 (= prank_26 prank_high_28))))
 (let (($x813 (or d_7_2 d_7_3 d_7_4 d_7_5)))
 (let (($x1065 (and $x813 (= prank_25 prank_high_28))))
 (let (($x809 (or d_6_2 d_6_3 d_6_4 d_6_5)))
 (let (($x1037 (and $x809 (= prank_24 prank_high_28))))
 (let (($x805 (or d_5_2 d_5_3 d_5_4 d_5_5)))
 (let (($x1014 (and $x805 (= prank_23 prank_high_28))))
 (let (($x801 (or d_4_2 d_4_3 d_4_4 d_4_5)))
 (let (($x986 (and $x801 (= prank_22 prank_high_28))))
 (let (($x797 (or d_3_2 d_3_3 d_3_4 d_3_5)))
 (let (($x953 (and $x797 (= prank_21 prank_high_28))))
 (let (($x793 (or d_2_2 d_2_3 d_2_4 d_2_5)))
 (let (($x925 (and $x793 (= prank_20 prank_high_28))))
 (let (($x789 (or d_1_2 d_1_3 d_1_4 d_1_5)))
 (let (($x902 (and $x789 (= prank_19 prank_high_28))))
 (let (($x785 (or d_0_2 d_0_3 d_0_4 d_0_5)))
 (let (($x874 (and $x785 (= prank_18 prank_high_28))))
 (let (($x875 (or false $x874)))
 (let (($x903 (or $x875 $x902)))
 (let (($x926 (or $x903 $x925)))
 (let (($x954 (or $x926 $x953)))
 (let (($x987 (or $x954 $x986)))
 (let (($x1015 (or $x987 $x1014)))
 (let (($x1038 (or $x1015 $x1037)))
 (let (($x1066 (or $x1038 $x1065)))
 (let (($x1085 (and $x817 (= prank_26 prank_low_27))))
 (let (($x1062 (and $x813 (= prank_25 prank_low_27))))
 (let (($x1034 (and $x809 (= prank_24 prank_low_27))))
 (let (($x1011 (and $x805 (= prank_23 prank_low_27))))
 (let (($x983 (and $x801 (= prank_22 prank_low_27))))
 (let (($x950 (and $x797 (= prank_21 prank_low_27))))
 (let (($x922 (and $x793 (= prank_20 prank_low_27))))
 (let (($x899 (and $x789 (= prank_19 prank_low_27))))
 (let (($x871 (and $x785 (= prank_18 prank_low_27))))
 (let (($x872 (or false $x871)))
 (let (($x900 (or $x872 $x899)))
 (let (($x923 (or $x900 $x922)))
 (let (($x951 (or $x923 $x950)))
 (let (($x984 (or $x951 $x983)))
 (let (($x1012 (or $x984 $x1011)))
 (let (($x1035 (or $x1012 $x1034)))
 (let (($x1063 (or $x1035 $x1062)))
 (let (($x869 (or false $x785)))
 (let (($x897 (or $x869 $x789)))
 (let (($x920 (or $x897 $x793)))
 (let (($x948 (or $x920 $x797)))
 (let (($x981 (or $x948 $x801)))
 (let (($x1009 (or $x981 $x805)))
 (let (($x1032 (or $x1009 $x809)))
 (let (($x1060 (or $x1032 $x813)))
 (let (($x1071 (or false (and d_8_4 (or d_7_6 (and $x813 (< prank_25 prank_26)))))))
 (let (($x1076 (or $x1071 (and d_8_5 (or d_5_6 (and $x805 (< prank_23 prank_26)))))))
 (let (($x1080 (and (and $x1076 (<= prank_low_27 prank_26)) (<= prank_26 prank_high_28))))
 (let (($x1043 (or false (and d_7_2 (or d_8_6 (and $x817 (< prank_26 prank_25)))))))
 (let (($x1048 (or $x1043 (and d_7_4 (or d_6_6 (and $x809 (< prank_24 prank_25)))))))
 (let (($x1053 (or $x1048 (and d_7_5 (or d_4_6 (and $x801 (< prank_22 prank_25)))))))
 (let (($x1057 (and (and $x1053 (<= prank_low_27 prank_25)) (<= prank_25 prank_high_28))))
 (let (($x1020 (or false (and d_6_2 (or d_7_6 (and $x813 (< prank_25 prank_24)))))))
 (let (($x1025 (or $x1020 (and d_6_5 (or d_3_6 (and $x797 (< prank_21 prank_24)))))))
 (let (($x1029 (and (and $x1025 (<= prank_low_27 prank_24)) (<= prank_24 prank_high_28))))
 (let (($x992 (or false (and d_5_3 (or d_8_6 (and $x817 (< prank_26 prank_23)))))))
 (let (($x997 (or $x992 (and d_5_4 (or d_4_6 (and $x801 (< prank_22 prank_23)))))))
 (let (($x1002 (or $x997 (and d_5_5 (or d_2_6 (and $x793 (< prank_20 prank_23)))))))
 (let (($x1006 (and (and $x1002 (<= prank_low_27 prank_23)) (<= prank_23 prank_high_28))))
 (let (($x959 (or false (and d_4_2 (or d_5_6 (and $x805 (< prank_23 prank_22)))))))
 (let (($x964 (or $x959 (and d_4_3 (or d_7_6 (and $x813 (< prank_25 prank_22)))))))
 (let (($x969 (or $x964 (and d_4_4 (or d_3_6 (and $x797 (< prank_21 prank_22)))))))
 (let (($x974 (or $x969 (and d_4_5 (or d_1_6 (and $x789 (< prank_19 prank_22)))))))
 (let (($x978 (and (and $x974 (<= prank_low_27 prank_22)) (<= prank_22 prank_high_28))))
 (let (($x931 (or false (and d_3_2 (or d_4_6 (and $x801 (< prank_22 prank_21)))))))
 (let (($x936 (or $x931 (and d_3_3 (or d_6_6 (and $x809 (< prank_24 prank_21)))))))
 (let (($x941 (or $x936 (and d_3_5 (or d_0_6 (and $x785 (< prank_18 prank_21)))))))
 (let (($x945 (and (and $x941 (<= prank_low_27 prank_21)) (<= prank_21 prank_high_28))))
 (let (($x908 (or false (and d_2_3 (or d_5_6 (and $x805 (< prank_23 prank_20)))))))
 (let (($x913 (or $x908 (and d_2_4 (or d_1_6 (and $x789 (< prank_19 prank_20)))))))
 (let (($x917 (and (and $x913 (<= prank_low_27 prank_20)) (<= prank_20 prank_high_28))))
 (let (($x880 (or false (and d_1_2 (or d_2_6 (and $x793 (< prank_20 prank_19)))))))
 (let (($x885 (or $x880 (and d_1_3 (or d_4_6 (and $x801 (< prank_22 prank_19)))))))
 (let (($x890 (or $x885 (and d_1_4 (or d_0_6 (and $x785 (< prank_18 prank_19)))))))
 (let (($x894 (and (and $x890 (<= prank_low_27 prank_19)) (<= prank_19 prank_high_28))))
 (let (($x857 (or false (and d_0_2 (or d_1_6 (and $x789 (< prank_19 prank_18)))))))
 (let (($x862 (or $x857 (and d_0_3 (or d_3_6 (and $x797 (< prank_21 prank_18)))))))
 (let (($x866 (and (and $x862 (<= prank_low_27 prank_18)) (<= prank_18 prank_high_28))))
 (let (($x868 (and true (=> $x785 $x866))))
 (let (($x896 (and $x868 (=> $x789 $x894))))
 (let (($x919 (and $x896 (=> $x793 $x917))))
 (let (($x947 (and $x919 (=> $x797 $x945))))
 (let (($x980 (and $x947 (=> $x801 $x978))))
 (let (($x1008 (and $x980 (=> $x805 $x1006))))
 (let (($x1031 (and $x1008 (=> $x809 $x1029))))
 (let (($x1059 (and $x1031 (=> $x813 $x1057))))
 (let (($x1082 (and $x1059 (=> $x817 $x1080))))
 (let (($x1092 (and $x1082 (=> (or $x1060 $x817) (and (or $x1063 $x1085) (or $x1066 $x1088))))))
 (let (($x779 (and d_8_6 (not in_target_8))))
 (let (($x775 (and d_7_6 (not in_target_7))))
 (let (($x771 (and d_6_6 (not in_target_6))))
 (let (($x767 (and d_5_6 (not in_target_5))))
 (let (($x763 (and d_4_6 (not in_target_4))))
 (let (($x759 (and d_3_6 (not in_target_3))))
 (let (($x755 (and d_2_6 (not in_target_2))))
 (let (($x751 (and d_1_6 (not in_target_1))))
 (let (($x747 (and d_0_6 (not in_target_0))))
 (let (($x743 (or false $x747)))
 (let (($x746 (or $x743 $x751)))
 (let (($x750 (or $x746 $x755)))
 (let (($x754 (or $x750 $x759)))
 (let (($x758 (or $x754 $x763)))
 (let (($x762 (or $x758 $x767)))
 (let (($x766 (or $x762 $x771)))
 (let (($x770 (or $x766 $x775)))
 (let ((?x723 (ite root_17 1 0)))
 (let ((?x705 (ite root_15 1 0)))
 (let ((?x690 (ite root_13 1 0)))
 (let ((?x672 (ite root_11 1 0)))
 (let ((?x651 (ite root_9 1 0)))
 (let ((?x633 (ite root_7 1 0)))
 (let ((?x618 (ite root_5 1 0)))
 (let ((?x600 (ite root_3 1 0)))
 (let ((?x585 (ite root_1 1 0)))
 (let ((?x586 (+ 0 ?x585)))
 (let ((?x601 (+ ?x586 ?x600)))
 (let ((?x619 (+ ?x601 ?x618)))
 (let ((?x634 (+ ?x619 ?x633)))
 (let ((?x652 (+ ?x634 ?x651)))
 (let ((?x673 (+ ?x652 ?x672)))
 (let ((?x691 (+ ?x673 ?x690)))
 (let ((?x706 (+ ?x691 ?x705)))
 (let (($x583 (or false root_1)))
 (let (($x599 (or $x583 root_3)))
 (let (($x617 (or $x599 root_5)))
 (let (($x632 (or $x617 root_7)))
 (let (($x650 (or $x632 root_9)))
 (let (($x671 (or $x650 root_11)))
 (let (($x689 (or $x671 root_13)))
 (let (($x704 (or $x689 root_15)))
 (let (($x518 (or false d_0_6)))
 (let (($x520 (or $x518 d_1_6)))
 (let (($x522 (or $x520 d_2_6)))
 (let (($x524 (or $x522 d_3_6)))
 (let (($x526 (or $x524 d_4_6)))
 (let (($x528 (or $x526 d_5_6)))
 (let (($x530 (or $x528 d_6_6)))
 (let (($x532 (or $x530 d_7_6)))
 (let (($x534 (or $x532 d_8_6)))
 (let (($x729 (or false (and d_7_6 (< rank_14 rank_16)))))
 (let (($x733 (not root_17)))
 (let (($x734 (and d_8_6 $x733)))
 (let (($x711 (or false (and d_8_6 (< rank_16 rank_14)))))
 (let (($x714 (or $x711 (and d_6_6 (< rank_12 rank_14)))))
 (let (($x718 (not root_15)))
 (let (($x719 (and d_7_6 $x718)))
 (let (($x696 (or false (and d_7_6 (< rank_14 rank_12)))))
 (let (($x700 (not root_13)))
 (let (($x701 (and d_6_6 $x700)))
 (let (($x678 (or false (and d_8_6 (< rank_16 rank_10)))))
 (let (($x681 (or $x678 (and d_4_6 (< rank_8 rank_10)))))
 (let (($x685 (not root_11)))
 (let (($x686 (and d_5_6 $x685)))
 (let (($x657 (or false (and d_5_6 (< rank_10 rank_8)))))
 (let (($x660 (or $x657 (and d_7_6 (< rank_14 rank_8)))))
 (let (($x663 (or $x660 (and d_3_6 (< rank_6 rank_8)))))
 (let (($x667 (not root_9)))
 (let (($x668 (and d_4_6 $x667)))
 (let (($x639 (or false (and d_4_6 (< rank_8 rank_6)))))
 (let (($x642 (or $x639 (and d_6_6 (< rank_12 rank_6)))))
 (let (($x646 (not root_7)))
 (let (($x647 (and d_3_6 $x646)))
 (let (($x624 (or false (and d_5_6 (< rank_10 rank_4)))))
 (let (($x628 (not root_5)))
 (let (($x629 (and d_2_6 $x628)))
 (let (($x606 (or false (and d_2_6 (< rank_4 rank_2)))))
 (let (($x609 (or $x606 (and d_4_6 (< rank_8 rank_2)))))
 (let (($x613 (not root_3)))
 (let (($x614 (and d_1_6 $x613)))
 (let (($x591 (or false (and d_1_6 (< rank_2 rank_0)))))
 (let (($x595 (not root_1)))
 (let (($x596 (and d_0_6 $x595)))
 (let (($x588 (and true (=> root_1 d_0_6))))
 (let (($x598 (and $x588 (=> $x596 (or $x591 (and d_3_6 (< rank_6 rank_0)))))))
 (let (($x603 (and $x598 (=> root_3 d_1_6))))
 (let (($x616 (and $x603 (=> $x614 (or $x609 (and d_0_6 (< rank_0 rank_2)))))))
 (let (($x621 (and $x616 (=> root_5 d_2_6))))
 (let (($x631 (and $x621 (=> $x629 (or $x624 (and d_1_6 (< rank_2 rank_4)))))))
 (let (($x636 (and $x631 (=> root_7 d_3_6))))
 (let (($x649 (and $x636 (=> $x647 (or $x642 (and d_0_6 (< rank_0 rank_6)))))))
 (let (($x654 (and $x649 (=> root_9 d_4_6))))
 (let (($x670 (and $x654 (=> $x668 (or $x663 (and d_1_6 (< rank_2 rank_8)))))))
 (let (($x675 (and $x670 (=> root_11 d_5_6))))
 (let (($x688 (and $x675 (=> $x686 (or $x681 (and d_2_6 (< rank_4 rank_10)))))))
 (let (($x693 (and $x688 (=> root_13 d_6_6))))
 (let (($x703 (and $x693 (=> $x701 (or $x696 (and d_3_6 (< rank_6 rank_12)))))))
 (let (($x708 (and $x703 (=> root_15 d_7_6))))
 (let (($x721 (and $x708 (=> $x719 (or $x714 (and d_4_6 (< rank_8 rank_14)))))))
 (let (($x726 (and $x721 (=> root_17 d_8_6))))
 (let (($x738 (and (and $x726 (=> $x734 (or $x729 (and d_5_6 (< rank_10 rank_16))))) (=> $x534 (or $x704 root_17)))))
 (let (($x740 (and $x738 (<= (+ ?x706 ?x723) 1))))
 (let (($x536 (and true $x534)))
 (let (($x741 (and $x536 $x740)))
 (let (($x776 (and $x741 (not (or $x770 $x779)))))
 (let (($x1093 (and $x776 $x1092)))
 (let (($x1390 (and $x1093 $x1389)))
 (and $x1390 (not (not $x1580))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
