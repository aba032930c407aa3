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
 (let (($x860 (>= prank_18 0)))
 (and $x860 (< prank_18 9))))
(assert
 (let (($x865 (>= prank_19 0)))
 (and $x865 (< prank_19 9))))
(assert
 (let (($x869 (>= prank_20 0)))
 (and $x869 (< prank_20 9))))
(assert
 (let (($x873 (>= prank_21 0)))
 (and $x873 (< prank_21 9))))
(assert
 (let (($x877 (>= prank_22 0)))
 (and $x877 (< prank_22 9))))
(assert
 (let (($x881 (>= prank_23 0)))
 (and $x881 (< prank_23 9))))
(assert
 (let (($x885 (>= prank_24 0)))
 (and $x885 (< prank_24 9))))
(assert
 (let (($x889 (>= prank_25 0)))
 (and $x889 (< prank_25 9))))
(assert
 (let (($x893 (>= prank_26 0)))
 (and $x893 (< prank_26 9))))
(assert
 (let (($x1165 (>= prank_29 0)))
 (and $x1165 (< prank_29 9))))
(assert
 (let (($x1171 (>= prank_30 0)))
 (and $x1171 (< prank_30 9))))
(assert
 (let (($x1175 (>= prank_31 0)))
 (and $x1175 (< prank_31 9))))
(assert
 (let (($x1179 (>= prank_32 0)))
 (and $x1179 (< prank_32 9))))
(assert
 (let (($x1183 (>= prank_33 0)))
 (and $x1183 (< prank_33 9))))
(assert
 (let (($x1187 (>= prank_34 0)))
 (and $x1187 (< prank_34 9))))
(assert
 (let (($x1191 (>= prank_35 0)))
 (and $x1191 (< prank_35 9))))
(assert
 (let (($x1195 (>= prank_36 0)))
 (and $x1195 (< prank_36 9))))
(assert
 (let (($x1199 (>= prank_37 0)))
 (and $x1199 (< prank_37 9))))
(assert
 (let (($x1533 (not cut_48)))
 (let (($x1513 (or d_8_1 d_8_2 d_8_3 d_8_4 d_8_5 d_8_6)))
 (let (($x1534 (and $x1513 $x1533)))
 (let (($x1530 (not cut_47)))
 (let (($x1506 (or d_7_1 d_7_2 d_7_3 d_7_4 d_7_5 d_7_6)))
 (let (($x1531 (and $x1506 $x1530)))
 (let (($x1527 (not cut_46)))
 (let (($x1499 (or d_6_1 d_6_2 d_6_3 d_6_4 d_6_5 d_6_6)))
 (let (($x1528 (and $x1499 $x1527)))
 (let (($x1524 (not cut_45)))
 (let (($x1492 (or d_5_1 d_5_2 d_5_3 d_5_4 d_5_5 d_5_6)))
 (let (($x1525 (and $x1492 $x1524)))
 (let (($x1521 (not cut_44)))
 (let (($x1485 (or d_4_1 d_4_2 d_4_3 d_4_4 d_4_5 d_4_6)))
 (let (($x1522 (and $x1485 $x1521)))
 (let (($x1518 (not cut_43)))
 (let (($x1478 (or d_3_1 d_3_2 d_3_3 d_3_4 d_3_5 d_3_6)))
 (let (($x1519 (and $x1478 $x1518)))
 (let (($x1515 (not cut_42)))
 (let (($x1471 (or d_2_1 d_2_2 d_2_3 d_2_4 d_2_5 d_2_6)))
 (let (($x1516 (and $x1471 $x1515)))
 (let (($x1509 (not cut_41)))
 (let (($x1464 (or d_1_1 d_1_2 d_1_3 d_1_4 d_1_5 d_1_6)))
 (let (($x1512 (and $x1464 $x1509)))
 (let (($x1508 (not cut_40)))
 (let (($x1457 (or d_0_1 d_0_2 d_0_3 d_0_4 d_0_5 d_0_6)))
 (let (($x1510 (and $x1457 $x1508)))
 (let (($x1538 (or false $x1510)))
 (let (($x1548 (or $x1538 $x1512)))
 (let (($x1561 (or $x1548 $x1516)))
 (let (($x1571 (or $x1561 $x1519)))
 (let (($x1584 (or $x1571 $x1522)))
 (let (($x1600 (or $x1584 $x1525)))
 (let (($x1613 (or $x1600 $x1528)))
 (let (($x1623 (or $x1613 $x1531)))
 (let (($x1537 (or false cut_40)))
 (let (($x1547 (or $x1537 cut_41)))
 (let (($x1560 (or $x1547 cut_42)))
 (let (($x1570 (or $x1560 cut_43)))
 (let (($x1583 (or $x1570 cut_44)))
 (let (($x1599 (or $x1583 cut_45)))
 (let (($x1612 (or $x1599 cut_46)))
 (let (($x1622 (or $x1612 cut_47)))
 (let (($x1536 (and true (=> cut_40 $x1457))))
 (let (($x1541 (and $x1536 (=> (and cut_40 $x1464) cut_41))))
 (let (($x1544 (and $x1541 (=> (and cut_40 $x1478) cut_43))))
 (let (($x1546 (and $x1544 (=> cut_41 $x1464))))
 (let (($x1551 (and $x1546 (=> (and cut_41 $x1471) cut_42))))
 (let (($x1554 (and $x1551 (=> (and cut_41 $x1485) cut_44))))
 (let (($x1557 (and $x1554 (=> (and cut_41 $x1457) cut_40))))
 (let (($x1559 (and $x1557 (=> cut_42 $x1471))))
 (let (($x1564 (and $x1559 (=> (and cut_42 $x1492) cut_45))))
 (let (($x1567 (and $x1564 (=> (and cut_42 $x1464) cut_41))))
 (let (($x1569 (and $x1567 (=> cut_43 $x1478))))
 (let (($x1574 (and $x1569 (=> (and cut_43 $x1485) cut_44))))
 (let (($x1577 (and $x1574 (=> (and cut_43 $x1499) cut_46))))
 (let (($x1580 (and $x1577 (=> (and cut_43 $x1457) cut_40))))
 (let (($x1582 (and $x1580 (=> cut_44 $x1485))))
 (let (($x1587 (and $x1582 (=> (and cut_44 $x1492) cut_45))))
 (let (($x1590 (and $x1587 (=> (and cut_44 $x1506) cut_47))))
 (let (($x1593 (and $x1590 (=> (and cut_44 $x1478) cut_43))))
 (let (($x1596 (and $x1593 (=> (and cut_44 $x1464) cut_41))))
 (let (($x1598 (and $x1596 (=> cut_45 $x1492))))
 (let (($x1603 (and $x1598 (=> (and cut_45 $x1513) cut_48))))
 (let (($x1606 (and $x1603 (=> (and cut_45 $x1485) cut_44))))
 (let (($x1609 (and $x1606 (=> (and cut_45 $x1471) cut_42))))
 (let (($x1611 (and $x1609 (=> cut_46 $x1499))))
 (let (($x1616 (and $x1611 (=> (and cut_46 $x1506) cut_47))))
 (let (($x1619 (and $x1616 (=> (and cut_46 $x1478) cut_43))))
 (let (($x1621 (and $x1619 (=> cut_47 $x1506))))
 (let (($x1626 (and $x1621 (=> (and cut_47 $x1513) cut_48))))
 (let (($x1629 (and $x1626 (=> (and cut_47 $x1499) cut_46))))
 (let (($x1632 (and $x1629 (=> (and cut_47 $x1485) cut_44))))
 (let (($x1634 (and $x1632 (=> cut_48 $x1513))))
 (let (($x1639 (and $x1634 (=> (and cut_48 $x1506) cut_47))))
 (let (($x1644 (and (and (and $x1639 (=> (and cut_48 $x1492) cut_45)) (or $x1622 cut_48)) (or $x1623 $x1534))))
 (let (($x1439 (and d_8_1 (= prank_37 prank_high_39))))
 (let (($x1416 (and d_7_1 (= prank_36 prank_high_39))))
 (let (($x1388 (and d_6_1 (= prank_35 prank_high_39))))
 (let (($x1365 (and d_5_1 (= prank_34 prank_high_39))))
 (let (($x1337 (and d_4_1 (= prank_33 prank_high_39))))
 (let (($x1304 (and d_3_1 (= prank_32 prank_high_39))))
 (let (($x1276 (and d_2_1 (= prank_31 prank_high_39))))
 (let (($x1253 (and d_1_1 (= prank_30 prank_high_39))))
 (let (($x1225 (and d_0_1 (= prank_29 prank_high_39))))
 (let (($x1226 (or false $x1225)))
 (let (($x1254 (or $x1226 $x1253)))
 (let (($x1277 (or $x1254 $x1276)))
 (let (($x1305 (or $x1277 $x1304)))
 (let (($x1338 (or $x1305 $x1337)))
 (let (($x1366 (or $x1338 $x1365)))
 (let (($x1389 (or $x1366 $x1388)))
 (let (($x1417 (or $x1389 $x1416)))
 (let (($x1436 (and d_8_1 (= prank_37 prank_low_38))))
 (let (($x1413 (and d_7_1 (= prank_36 prank_low_38))))
 (let (($x1385 (and d_6_1 (= prank_35 prank_low_38))))
 (let (($x1362 (and d_5_1 (= prank_34 prank_low_38))))
 (let (($x1334 (and d_4_1 (= prank_33 prank_low_38))))
 (let (($x1301 (and d_3_1 (= prank_32 prank_low_38))))
 (let (($x1273 (and d_2_1 (= prank_31 prank_low_38))))
 (let (($x1250 (and d_1_1 (= prank_30 prank_low_38))))
 (let (($x1222 (and d_0_1 (= prank_29 prank_low_38))))
 (let (($x1223 (or false $x1222)))
 (let (($x1251 (or $x1223 $x1250)))
 (let (($x1274 (or $x1251 $x1273)))
 (let (($x1302 (or $x1274 $x1301)))
 (let (($x1335 (or $x1302 $x1334)))
 (let (($x1363 (or $x1335 $x1362)))
 (let (($x1386 (or $x1363 $x1385)))
 (let (($x1414 (or $x1386 $x1413)))
 (let (($x1220 (or false d_0_1)))
 (let (($x1248 (or $x1220 d_1_1)))
 (let (($x1271 (or $x1248 d_2_1)))
 (let (($x1299 (or $x1271 d_3_1)))
 (let (($x1332 (or $x1299 d_4_1)))
 (let (($x1360 (or $x1332 d_5_1)))
 (let (($x1383 (or $x1360 d_6_1)))
 (let (($x1411 (or $x1383 d_7_1)))
 (let (($x1160 (or d_5_2 d_5_3 d_5_4 d_5_5 d_5_6)))
 (let (($x1166 (or d_7_2 d_7_3 d_7_4 d_7_5 d_7_6)))
 (let (($x1422 (or false (and true (or $x1166 (and d_7_1 (< prank_36 prank_37)))))))
 (let (($x1427 (or $x1422 (and true (or $x1160 (and d_5_1 (< prank_34 prank_37)))))))
 (let (($x1431 (and (and $x1427 (<= prank_low_38 prank_37)) (<= prank_37 prank_high_39))))
 (let (($x1157 (or d_4_2 d_4_3 d_4_4 d_4_5 d_4_6)))
 (let (($x1163 (or d_6_2 d_6_3 d_6_4 d_6_5 d_6_6)))
 (let (($x1169 (or d_8_2 d_8_3 d_8_4 d_8_5 d_8_6)))
 (let (($x1394 (or false (and true (or $x1169 (and d_8_1 (< prank_37 prank_36)))))))
 (let (($x1399 (or $x1394 (and true (or $x1163 (and d_6_1 (< prank_35 prank_36)))))))
 (let (($x1404 (or $x1399 (and true (or $x1157 (and d_4_1 (< prank_33 prank_36)))))))
 (let (($x1408 (and (and $x1404 (<= prank_low_38 prank_36)) (<= prank_36 prank_high_39))))
 (let (($x1154 (or d_3_2 d_3_3 d_3_4 d_3_5 d_3_6)))
 (let (($x1371 (or false (and true (or $x1166 (and d_7_1 (< prank_36 prank_35)))))))
 (let (($x1376 (or $x1371 (and true (or $x1154 (and d_3_1 (< prank_32 prank_35)))))))
 (let (($x1380 (and (and $x1376 (<= prank_low_38 prank_35)) (<= prank_35 prank_high_39))))
 (let (($x1151 (or d_2_2 d_2_3 d_2_4 d_2_5 d_2_6)))
 (let (($x1343 (or false (and true (or $x1169 (and d_8_1 (< prank_37 prank_34)))))))
 (let (($x1348 (or $x1343 (and true (or $x1157 (and d_4_1 (< prank_33 prank_34)))))))
 (let (($x1353 (or $x1348 (and true (or $x1151 (and d_2_1 (< prank_31 prank_34)))))))
 (let (($x1357 (and (and $x1353 (<= prank_low_38 prank_34)) (<= prank_34 prank_high_39))))
 (let (($x1148 (or d_1_2 d_1_3 d_1_4 d_1_5 d_1_6)))
 (let (($x1310 (or false (and true (or $x1160 (and d_5_1 (< prank_34 prank_33)))))))
 (let (($x1315 (or $x1310 (and true (or $x1166 (and d_7_1 (< prank_36 prank_33)))))))
 (let (($x1320 (or $x1315 (and true (or $x1154 (and d_3_1 (< prank_32 prank_33)))))))
 (let (($x1325 (or $x1320 (and true (or $x1148 (and d_1_1 (< prank_30 prank_33)))))))
 (let (($x1329 (and (and $x1325 (<= prank_low_38 prank_33)) (<= prank_33 prank_high_39))))
 (let (($x1145 (or d_0_2 d_0_3 d_0_4 d_0_5 d_0_6)))
 (let (($x1282 (or false (and true (or $x1157 (and d_4_1 (< prank_33 prank_32)))))))
 (let (($x1287 (or $x1282 (and true (or $x1163 (and d_6_1 (< prank_35 prank_32)))))))
 (let (($x1292 (or $x1287 (and true (or $x1145 (and d_0_1 (< prank_29 prank_32)))))))
 (let (($x1296 (and (and $x1292 (<= prank_low_38 prank_32)) (<= prank_32 prank_high_39))))
 (let (($x1259 (or false (and true (or $x1160 (and d_5_1 (< prank_34 prank_31)))))))
 (let (($x1264 (or $x1259 (and true (or $x1148 (and d_1_1 (< prank_30 prank_31)))))))
 (let (($x1268 (and (and $x1264 (<= prank_low_38 prank_31)) (<= prank_31 prank_high_39))))
 (let (($x1231 (or false (and true (or $x1151 (and d_2_1 (< prank_31 prank_30)))))))
 (let (($x1236 (or $x1231 (and true (or $x1157 (and d_4_1 (< prank_33 prank_30)))))))
 (let (($x1241 (or $x1236 (and true (or $x1145 (and d_0_1 (< prank_29 prank_30)))))))
 (let (($x1245 (and (and $x1241 (<= prank_low_38 prank_30)) (<= prank_30 prank_high_39))))
 (let (($x1208 (or false (and true (or $x1148 (and d_1_1 (< prank_30 prank_29)))))))
 (let (($x1213 (or $x1208 (and true (or $x1154 (and d_3_1 (< prank_32 prank_29)))))))
 (let (($x1217 (and (and $x1213 (<= prank_low_38 prank_29)) (<= prank_29 prank_high_39))))
 (let (($x1219 (and true (=> d_0_1 $x1217))))
 (let (($x1247 (and $x1219 (=> d_1_1 $x1245))))
 (let (($x1270 (and $x1247 (=> d_2_1 $x1268))))
 (let (($x1298 (and $x1270 (=> d_3_1 $x1296))))
 (let (($x1331 (and $x1298 (=> d_4_1 $x1329))))
 (let (($x1359 (and $x1331 (=> d_5_1 $x1357))))
 (let (($x1382 (and $x1359 (=> d_6_1 $x1380))))
 (let (($x1410 (and $x1382 (=> d_7_1 $x1408))))
 (let (($x1433 (and $x1410 (=> d_8_1 $x1431))))
 (let (($x1443 (and $x1433 (=> (or $x1411 d_8_1) (and (or $x1414 $x1436) (or $x1417 $x1439))))))
 (let (($x863 (or d_8_2 d_8_3 d_8_4 d_8_5)))
 (let (($x1133 (and $x863 (= prank_26 prank_high_28))))
 (let (($x856 (or d_7_2 d_7_3 d_7_4 d_7_5)))
 (let (($x1110 (and $x856 (= prank_25 prank_high_28))))
 (let (($x849 (or d_6_2 d_6_3 d_6_4 d_6_5)))
 (let (($x1082 (and $x849 (= prank_24 prank_high_28))))
 (let (($x842 (or d_5_2 d_5_3 d_5_4 d_5_5)))
 (let (($x1059 (and $x842 (= prank_23 prank_high_28))))
 (let (($x835 (or d_4_2 d_4_3 d_4_4 d_4_5)))
 (let (($x1031 (and $x835 (= prank_22 prank_high_28))))
 (let (($x828 (or d_3_2 d_3_3 d_3_4 d_3_5)))
 (let (($x998 (and $x828 (= prank_21 prank_high_28))))
 (let (($x821 (or d_2_2 d_2_3 d_2_4 d_2_5)))
 (let (($x970 (and $x821 (= prank_20 prank_high_28))))
 (let (($x814 (or d_1_2 d_1_3 d_1_4 d_1_5)))
 (let (($x947 (and $x814 (= prank_19 prank_high_28))))
 (let (($x807 (or d_0_2 d_0_3 d_0_4 d_0_5)))
 (let (($x919 (and $x807 (= prank_18 prank_high_28))))
 (let (($x920 (or false $x919)))
 (let (($x948 (or $x920 $x947)))
 (let (($x971 (or $x948 $x970)))
 (let (($x999 (or $x971 $x998)))
 (let (($x1032 (or $x999 $x1031)))
 (let (($x1060 (or $x1032 $x1059)))
 (let (($x1083 (or $x1060 $x1082)))
 (let (($x1111 (or $x1083 $x1110)))
 (let (($x1130 (and $x863 (= prank_26 prank_low_27))))
 (let (($x1107 (and $x856 (= prank_25 prank_low_27))))
 (let (($x1079 (and $x849 (= prank_24 prank_low_27))))
 (let (($x1056 (and $x842 (= prank_23 prank_low_27))))
 (let (($x1028 (and $x835 (= prank_22 prank_low_27))))
 (let (($x995 (and $x828 (= prank_21 prank_low_27))))
 (let (($x967 (and $x821 (= prank_20 prank_low_27))))
 (let (($x944 (and $x814 (= prank_19 prank_low_27))))
 (let (($x916 (and $x807 (= prank_18 prank_low_27))))
 (let (($x917 (or false $x916)))
 (let (($x945 (or $x917 $x944)))
 (let (($x968 (or $x945 $x967)))
 (let (($x996 (or $x968 $x995)))
 (let (($x1029 (or $x996 $x1028)))
 (let (($x1057 (or $x1029 $x1056)))
 (let (($x1080 (or $x1057 $x1079)))
 (let (($x1108 (or $x1080 $x1107)))
 (let (($x914 (or false $x807)))
 (let (($x942 (or $x914 $x814)))
 (let (($x965 (or $x942 $x821)))
 (let (($x993 (or $x965 $x828)))
 (let (($x1026 (or $x993 $x835)))
 (let (($x1054 (or $x1026 $x842)))
 (let (($x1077 (or $x1054 $x849)))
 (let (($x1105 (or $x1077 $x856)))
 (let (($x1116 (or false (and d_8_4 (or d_7_6 (and $x856 (< prank_25 prank_26)))))))
 (let (($x1121 (or $x1116 (and d_8_5 (or d_5_6 (and $x842 (< prank_23 prank_26)))))))
 (let (($x1125 (and (and $x1121 (<= prank_low_27 prank_26)) (<= prank_26 prank_high_28))))
 (let (($x1088 (or false (and d_7_2 (or d_8_6 (and $x863 (< prank_26 prank_25)))))))
 (let (($x1093 (or $x1088 (and d_7_4 (or d_6_6 (and $x849 (< prank_24 prank_25)))))))
 (let (($x1098 (or $x1093 (and d_7_5 (or d_4_6 (and $x835 (< prank_22 prank_25)))))))
 (let (($x1102 (and (and $x1098 (<= prank_low_27 prank_25)) (<= prank_25 prank_high_28))))
 (let (($x1065 (or false (and d_6_2 (or d_7_6 (and $x856 (< prank_25 prank_24)))))))
 (let (($x1070 (or $x1065 (and d_6_5 (or d_3_6 (and $x828 (< prank_21 prank_24)))))))
 (let (($x1074 (and (and $x1070 (<= prank_low_27 prank_24)) (<= prank_24 prank_high_28))))
 (let (($x1037 (or false (and d_5_3 (or d_8_6 (and $x863 (< prank_26 prank_23)))))))
 (let (($x1042 (or $x1037 (and d_5_4 (or d_4_6 (and $x835 (< prank_22 prank_23)))))))
 (let (($x1047 (or $x1042 (and d_5_5 (or d_2_6 (and $x821 (< prank_20 prank_23)))))))
 (let (($x1051 (and (and $x1047 (<= prank_low_27 prank_23)) (<= prank_23 prank_high_28))))
 (let (($x1004 (or false (and d_4_2 (or d_5_6 (and $x842 (< prank_23 prank_22)))))))
 (let (($x1009 (or $x1004 (and d_4_3 (or d_7_6 (and $x856 (< prank_25 prank_22)))))))
 (let (($x1014 (or $x1009 (and d_4_4 (or d_3_6 (and $x828 (< prank_21 prank_22)))))))
 (let (($x1019 (or $x1014 (and d_4_5 (or d_1_6 (and $x814 (< prank_19 prank_22)))))))
 (let (($x1023 (and (and $x1019 (<= prank_low_27 prank_22)) (<= prank_22 prank_high_28))))
 (let (($x976 (or false (and d_3_2 (or d_4_6 (and $x835 (< prank_22 prank_21)))))))
 (let (($x981 (or $x976 (and d_3_3 (or d_6_6 (and $x849 (< prank_24 prank_21)))))))
 (let (($x986 (or $x981 (and d_3_5 (or d_0_6 (and $x807 (< prank_18 prank_21)))))))
 (let (($x990 (and (and $x986 (<= prank_low_27 prank_21)) (<= prank_21 prank_high_28))))
 (let (($x953 (or false (and d_2_3 (or d_5_6 (and $x842 (< prank_23 prank_20)))))))
 (let (($x958 (or $x953 (and d_2_4 (or d_1_6 (and $x814 (< prank_19 prank_20)))))))
 (let (($x962 (and (and $x958 (<= prank_low_27 prank_20)) (<= prank_20 prank_high_28))))
 (let (($x925 (or false (and d_1_2 (or d_2_6 (and $x821 (< prank_20 prank_19)))))))
 (let (($x930 (or $x925 (and d_1_3 (or d_4_6 (and $x835 (< prank_22 prank_19)))))))
 (let (($x935 (or $x930 (and d_1_4 (or d_0_6 (and $x807 (< prank_18 prank_19)))))))
 (let (($x939 (and (and $x935 (<= prank_low_27 prank_19)) (<= prank_19 prank_high_28))))
 (let (($x902 (or false (and d_0_2 (or d_1_6 (and $x814 (< prank_19 prank_18)))))))
 (let (($x907 (or $x902 (and d_0_3 (or d_3_6 (and $x828 (< prank_21 prank_18)))))))
 (let (($x911 (and (and $x907 (<= prank_low_27 prank_18)) (<= prank_18 prank_high_28))))
 (let (($x913 (and true (=> $x807 $x911))))
 (let (($x941 (and $x913 (=> $x814 $x939))))
 (let (($x964 (and $x941 (=> $x821 $x962))))
 (let (($x992 (and $x964 (=> $x828 $x990))))
 (let (($x1025 (and $x992 (=> $x835 $x1023))))
 (let (($x1053 (and $x1025 (=> $x842 $x1051))))
 (let (($x1076 (and $x1053 (=> $x849 $x1074))))
 (let (($x1104 (and $x1076 (=> $x856 $x1102))))
 (let (($x1127 (and $x1104 (=> $x863 $x1125))))
 (let (($x1137 (and $x1127 (=> (or $x1105 $x863) (and (or $x1108 $x1130) (or $x1111 $x1133))))))
 (let (($x790 (not in_target_8)))
 (let (($x795 (and d_8_6 $x790)))
 (let (($x784 (not in_target_7)))
 (let (($x789 (and d_7_6 $x784)))
 (let (($x778 (not in_target_6)))
 (let (($x783 (and d_6_6 $x778)))
 (let (($x772 (not in_target_5)))
 (let (($x777 (and d_5_6 $x772)))
 (let (($x766 (not in_target_4)))
 (let (($x771 (and d_4_6 $x766)))
 (let (($x760 (not in_target_3)))
 (let (($x765 (and d_3_6 $x760)))
 (let (($x754 (not in_target_2)))
 (let (($x759 (and d_2_6 $x754)))
 (let (($x748 (not in_target_1)))
 (let (($x753 (and d_1_6 $x748)))
 (let (($x742 (not in_target_0)))
 (let (($x747 (and d_0_6 $x742)))
 (let (($x745 (or false $x747)))
 (let (($x751 (or $x745 $x753)))
 (let (($x757 (or $x751 $x759)))
 (let (($x763 (or $x757 $x765)))
 (let (($x769 (or $x763 $x771)))
 (let (($x775 (or $x769 $x777)))
 (let (($x781 (or $x775 $x783)))
 (let (($x787 (or $x781 $x789)))
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
 (let (($x794 (and $x741 (not (or $x787 $x795)))))
 (let (($x1138 (and $x794 $x1137)))
 (let (($x1444 (and $x1138 $x1443)))
 (and $x1444 (not (not $x1644)))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
