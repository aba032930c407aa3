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
(declare-fun prank_27 () Int)
(declare-fun prank_28 () Int)
(declare-fun prank_29 () Int)
(declare-fun prank_30 () Int)
(declare-fun prank_31 () Int)
(declare-fun prank_32 () Int)
(declare-fun prank_33 () Int)
(declare-fun prank_34 () Int)
(declare-fun prank_35 () Int)
(declare-fun cut_44 () Bool)
(declare-fun cut_43 () Bool)
(declare-fun cut_42 () Bool)
(declare-fun cut_41 () Bool)
(declare-fun cut_40 () Bool)
(declare-fun cut_39 () Bool)
(declare-fun cut_38 () Bool)
(declare-fun cut_37 () Bool)
(declare-fun cut_36 () Bool)
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
 (let (($x1007 (>= prank_27 0)))
 (and $x1007 (< prank_27 9))))
(assert
 (let (($x1013 (>= prank_28 0)))
 (and $x1013 (< prank_28 9))))
(assert
 (let (($x1017 (>= prank_29 0)))
 (and $x1017 (< prank_29 9))))
(assert
 (let (($x1021 (>= prank_30 0)))
 (and $x1021 (< prank_30 9))))
(assert
 (let (($x1025 (>= prank_31 0)))
 (and $x1025 (< prank_31 9))))
(assert
 (let (($x1029 (>= prank_32 0)))
 (and $x1029 (< prank_32 9))))
(assert
 (let (($x1033 (>= prank_33 0)))
 (and $x1033 (< prank_33 9))))
(assert
 (let (($x1037 (>= prank_34 0)))
 (and $x1037 (< prank_34 9))))
(assert
 (let (($x1041 (>= prank_35 0)))
 (and $x1041 (< prank_35 9))))
(assert
 (let (($x1262 (not cut_44)))
 (let (($x1241 (or d_8_1 d_8_2 d_8_3 d_8_4 d_8_5 d_8_6)))
 (let (($x1263 (and $x1241 $x1262)))
 (let (($x1259 (not cut_43)))
 (let (($x1235 (or d_7_1 d_7_2 d_7_3 d_7_4 d_7_5 d_7_6)))
 (let (($x1260 (and $x1235 $x1259)))
 (let (($x1256 (not cut_42)))
 (let (($x1229 (or d_6_1 d_6_2 d_6_3 d_6_4 d_6_5 d_6_6)))
 (let (($x1257 (and $x1229 $x1256)))
 (let (($x1253 (not cut_41)))
 (let (($x1223 (or d_5_1 d_5_2 d_5_3 d_5_4 d_5_5 d_5_6)))
 (let (($x1254 (and $x1223 $x1253)))
 (let (($x1250 (not cut_40)))
 (let (($x1217 (or d_4_1 d_4_2 d_4_3 d_4_4 d_4_5 d_4_6)))
 (let (($x1251 (and $x1217 $x1250)))
 (let (($x1247 (not cut_39)))
 (let (($x1211 (or d_3_1 d_3_2 d_3_3 d_3_4 d_3_5 d_3_6)))
 (let (($x1248 (and $x1211 $x1247)))
 (let (($x1244 (not cut_38)))
 (let (($x1205 (or d_2_1 d_2_2 d_2_3 d_2_4 d_2_5 d_2_6)))
 (let (($x1245 (and $x1205 $x1244)))
 (let (($x1239 (not cut_37)))
 (let (($x1199 (or d_1_1 d_1_2 d_1_3 d_1_4 d_1_5 d_1_6)))
 (let (($x1242 (and $x1199 $x1239)))
 (let (($x1238 (not cut_36)))
 (let (($x1193 (or d_0_1 d_0_2 d_0_3 d_0_4 d_0_5 d_0_6)))
 (let (($x1237 (and $x1193 $x1238)))
 (let (($x1267 (or false $x1237)))
 (let (($x1277 (or $x1267 $x1242)))
 (let (($x1290 (or $x1277 $x1245)))
 (let (($x1300 (or $x1290 $x1248)))
 (let (($x1313 (or $x1300 $x1251)))
 (let (($x1329 (or $x1313 $x1254)))
 (let (($x1342 (or $x1329 $x1257)))
 (let (($x1352 (or $x1342 $x1260)))
 (let (($x1266 (or false cut_36)))
 (let (($x1276 (or $x1266 cut_37)))
 (let (($x1289 (or $x1276 cut_38)))
 (let (($x1299 (or $x1289 cut_39)))
 (let (($x1312 (or $x1299 cut_40)))
 (let (($x1328 (or $x1312 cut_41)))
 (let (($x1341 (or $x1328 cut_42)))
 (let (($x1351 (or $x1341 cut_43)))
 (let (($x1265 (and true (=> cut_36 $x1193))))
 (let (($x1270 (and $x1265 (=> (and cut_36 $x1199) cut_37))))
 (let (($x1273 (and $x1270 (=> (and cut_36 $x1211) cut_39))))
 (let (($x1275 (and $x1273 (=> cut_37 $x1199))))
 (let (($x1280 (and $x1275 (=> (and cut_37 $x1205) cut_38))))
 (let (($x1283 (and $x1280 (=> (and cut_37 $x1217) cut_40))))
 (let (($x1286 (and $x1283 (=> (and cut_37 $x1193) cut_36))))
 (let (($x1288 (and $x1286 (=> cut_38 $x1205))))
 (let (($x1293 (and $x1288 (=> (and cut_38 $x1223) cut_41))))
 (let (($x1296 (and $x1293 (=> (and cut_38 $x1199) cut_37))))
 (let (($x1298 (and $x1296 (=> cut_39 $x1211))))
 (let (($x1303 (and $x1298 (=> (and cut_39 $x1217) cut_40))))
 (let (($x1306 (and $x1303 (=> (and cut_39 $x1229) cut_42))))
 (let (($x1309 (and $x1306 (=> (and cut_39 $x1193) cut_36))))
 (let (($x1311 (and $x1309 (=> cut_40 $x1217))))
 (let (($x1316 (and $x1311 (=> (and cut_40 $x1223) cut_41))))
 (let (($x1319 (and $x1316 (=> (and cut_40 $x1235) cut_43))))
 (let (($x1322 (and $x1319 (=> (and cut_40 $x1211) cut_39))))
 (let (($x1325 (and $x1322 (=> (and cut_40 $x1199) cut_37))))
 (let (($x1327 (and $x1325 (=> cut_41 $x1223))))
 (let (($x1332 (and $x1327 (=> (and cut_41 $x1241) cut_44))))
 (let (($x1335 (and $x1332 (=> (and cut_41 $x1217) cut_40))))
 (let (($x1338 (and $x1335 (=> (and cut_41 $x1205) cut_38))))
 (let (($x1340 (and $x1338 (=> cut_42 $x1229))))
 (let (($x1345 (and $x1340 (=> (and cut_42 $x1235) cut_43))))
 (let (($x1348 (and $x1345 (=> (and cut_42 $x1211) cut_39))))
 (let (($x1350 (and $x1348 (=> cut_43 $x1235))))
 (let (($x1355 (and $x1350 (=> (and cut_43 $x1241) cut_44))))
 (let (($x1358 (and $x1355 (=> (and cut_43 $x1229) cut_42))))
 (let (($x1361 (and $x1358 (=> (and cut_43 $x1217) cut_40))))
 (let (($x1363 (and $x1361 (=> cut_44 $x1241))))
 (let (($x1368 (and $x1363 (=> (and cut_44 $x1235) cut_43))))
 (let (($x1373 (and (and (and $x1368 (=> (and cut_44 $x1223) cut_41)) (or $x1351 cut_44)) (or $x1352 $x1263))))
 (let (($x1004 (or d_5_2 d_5_3 d_5_4 d_5_5 d_5_6)))
 (let (($x1008 (or d_7_2 d_7_3 d_7_4 d_7_5 d_7_6)))
 (let (($x1174 (or false (and true (or $x1008 (and d_7_1 (< prank_34 prank_35)))))))
 (let (($x1179 (or $x1174 (and true (or $x1004 (and d_5_1 (< prank_32 prank_35)))))))
 (let (($x1002 (or d_4_2 d_4_3 d_4_4 d_4_5 d_4_6)))
 (let (($x1006 (or d_6_2 d_6_3 d_6_4 d_6_5 d_6_6)))
 (let (($x1010 (or d_8_2 d_8_3 d_8_4 d_8_5 d_8_6)))
 (let (($x1157 (or false (and true (or $x1010 (and d_8_1 (< prank_35 prank_34)))))))
 (let (($x1162 (or $x1157 (and true (or $x1006 (and d_6_1 (< prank_33 prank_34)))))))
 (let (($x1167 (or $x1162 (and true (or $x1002 (and d_4_1 (< prank_31 prank_34)))))))
 (let (($x1000 (or d_3_2 d_3_3 d_3_4 d_3_5 d_3_6)))
 (let (($x1145 (or false (and true (or $x1008 (and d_7_1 (< prank_34 prank_33)))))))
 (let (($x1150 (or $x1145 (and true (or $x1000 (and d_3_1 (< prank_30 prank_33)))))))
 (let (($x998 (or d_2_2 d_2_3 d_2_4 d_2_5 d_2_6)))
 (let (($x1128 (or false (and true (or $x1010 (and d_8_1 (< prank_35 prank_32)))))))
 (let (($x1133 (or $x1128 (and true (or $x1002 (and d_4_1 (< prank_31 prank_32)))))))
 (let (($x1138 (or $x1133 (and true (or $x998 (and d_2_1 (< prank_29 prank_32)))))))
 (let (($x996 (or d_1_2 d_1_3 d_1_4 d_1_5 d_1_6)))
 (let (($x1106 (or false (and true (or $x1004 (and d_5_1 (< prank_32 prank_31)))))))
 (let (($x1111 (or $x1106 (and true (or $x1008 (and d_7_1 (< prank_34 prank_31)))))))
 (let (($x1116 (or $x1111 (and true (or $x1000 (and d_3_1 (< prank_30 prank_31)))))))
 (let (($x1121 (or $x1116 (and true (or $x996 (and d_1_1 (< prank_28 prank_31)))))))
 (let (($x994 (or d_0_2 d_0_3 d_0_4 d_0_5 d_0_6)))
 (let (($x1089 (or false (and true (or $x1002 (and d_4_1 (< prank_31 prank_30)))))))
 (let (($x1094 (or $x1089 (and true (or $x1006 (and d_6_1 (< prank_33 prank_30)))))))
 (let (($x1099 (or $x1094 (and true (or $x994 (and d_0_1 (< prank_27 prank_30)))))))
 (let (($x1077 (or false (and true (or $x1004 (and d_5_1 (< prank_32 prank_29)))))))
 (let (($x1082 (or $x1077 (and true (or $x996 (and d_1_1 (< prank_28 prank_29)))))))
 (let (($x1060 (or false (and true (or $x998 (and d_2_1 (< prank_29 prank_28)))))))
 (let (($x1065 (or $x1060 (and true (or $x1002 (and d_4_1 (< prank_31 prank_28)))))))
 (let (($x1070 (or $x1065 (and true (or $x994 (and d_0_1 (< prank_27 prank_28)))))))
 (let (($x1048 (or false (and true (or $x996 (and d_1_1 (< prank_28 prank_27)))))))
 (let (($x1053 (or $x1048 (and true (or $x1000 (and d_3_1 (< prank_30 prank_27)))))))
 (let (($x1055 (and true (=> d_0_1 $x1053))))
 (let (($x1072 (and $x1055 (=> d_1_1 $x1070))))
 (let (($x1084 (and $x1072 (=> d_2_1 $x1082))))
 (let (($x1101 (and $x1084 (=> d_3_1 $x1099))))
 (let (($x1123 (and $x1101 (=> d_4_1 $x1121))))
 (let (($x1140 (and $x1123 (=> d_5_1 $x1138))))
 (let (($x1152 (and $x1140 (=> d_6_1 $x1150))))
 (let (($x1169 (and $x1152 (=> d_7_1 $x1167))))
 (let (($x1181 (and $x1169 (=> d_8_1 $x1179))))
 (let (($x984 (or d_5_6 (and (or d_5_2 d_5_3 d_5_4 d_5_5) (< prank_23 prank_26)))))
 (let (($x979 (or d_7_6 (and (or d_7_2 d_7_3 d_7_4 d_7_5) (< prank_25 prank_26)))))
 (let (($x981 (or false (and d_8_4 $x979))))
 (let (($x817 (or d_8_2 d_8_3 d_8_4 d_8_5)))
 (let (($x972 (or d_4_6 (and (or d_4_2 d_4_3 d_4_4 d_4_5) (< prank_22 prank_25)))))
 (let (($x967 (or d_6_6 (and (or d_6_2 d_6_3 d_6_4 d_6_5) (< prank_24 prank_25)))))
 (let (($x964 (or false (and d_7_2 (or d_8_6 (and $x817 (< prank_26 prank_25)))))))
 (let (($x969 (or $x964 (and d_7_4 $x967))))
 (let (($x813 (or d_7_2 d_7_3 d_7_4 d_7_5)))
 (let (($x955 (or d_3_6 (and (or d_3_2 d_3_3 d_3_4 d_3_5) (< prank_21 prank_24)))))
 (let (($x952 (or false (and d_6_2 (or d_7_6 (and $x813 (< prank_25 prank_24)))))))
 (let (($x809 (or d_6_2 d_6_3 d_6_4 d_6_5)))
 (let (($x943 (or d_2_6 (and (or d_2_2 d_2_3 d_2_4 d_2_5) (< prank_20 prank_23)))))
 (let (($x938 (or d_4_6 (and (or d_4_2 d_4_3 d_4_4 d_4_5) (< prank_22 prank_23)))))
 (let (($x935 (or false (and d_5_3 (or d_8_6 (and $x817 (< prank_26 prank_23)))))))
 (let (($x940 (or $x935 (and d_5_4 $x938))))
 (let (($x805 (or d_5_2 d_5_3 d_5_4 d_5_5)))
 (let (($x926 (or d_1_6 (and (or d_1_2 d_1_3 d_1_4 d_1_5) (< prank_19 prank_22)))))
 (let (($x921 (or d_3_6 (and (or d_3_2 d_3_3 d_3_4 d_3_5) (< prank_21 prank_22)))))
 (let (($x913 (or false (and d_4_2 (or d_5_6 (and $x805 (< prank_23 prank_22)))))))
 (let (($x918 (or $x913 (and d_4_3 (or d_7_6 (and $x813 (< prank_25 prank_22)))))))
 (let (($x923 (or $x918 (and d_4_4 $x921))))
 (let (($x801 (or d_4_2 d_4_3 d_4_4 d_4_5)))
 (let (($x904 (or d_0_6 (and (or d_0_2 d_0_3 d_0_4 d_0_5) (< prank_18 prank_21)))))
 (let (($x896 (or false (and d_3_2 (or d_4_6 (and $x801 (< prank_22 prank_21)))))))
 (let (($x901 (or $x896 (and d_3_3 (or d_6_6 (and $x809 (< prank_24 prank_21)))))))
 (let (($x797 (or d_3_2 d_3_3 d_3_4 d_3_5)))
 (let (($x887 (or d_1_6 (and (or d_1_2 d_1_3 d_1_4 d_1_5) (< prank_19 prank_20)))))
 (let (($x884 (or false (and d_2_3 (or d_5_6 (and $x805 (< prank_23 prank_20)))))))
 (let (($x793 (or d_2_2 d_2_3 d_2_4 d_2_5)))
 (let (($x875 (or d_0_6 (and (or d_0_2 d_0_3 d_0_4 d_0_5) (< prank_18 prank_19)))))
 (let (($x867 (or false (and d_1_2 (or d_2_6 (and $x793 (< prank_20 prank_19)))))))
 (let (($x872 (or $x867 (and d_1_3 (or d_4_6 (and $x801 (< prank_22 prank_19)))))))
 (let (($x789 (or d_1_2 d_1_3 d_1_4 d_1_5)))
 (let (($x855 (or false (and d_0_2 (or d_1_6 (and $x789 (< prank_19 prank_18)))))))
 (let (($x860 (or $x855 (and d_0_3 (or d_3_6 (and $x797 (< prank_21 prank_18)))))))
 (let (($x785 (or d_0_2 d_0_3 d_0_4 d_0_5)))
 (let (($x862 (and true (=> $x785 $x860))))
 (let (($x879 (and $x862 (=> $x789 (or $x872 (and d_1_4 $x875))))))
 (let (($x891 (and $x879 (=> $x793 (or $x884 (and d_2_4 $x887))))))
 (let (($x908 (and $x891 (=> $x797 (or $x901 (and d_3_5 $x904))))))
 (let (($x930 (and $x908 (=> $x801 (or $x923 (and d_4_5 $x926))))))
 (let (($x947 (and $x930 (=> $x805 (or $x940 (and d_5_5 $x943))))))
 (let (($x959 (and $x947 (=> $x809 (or $x952 (and d_6_5 $x955))))))
 (let (($x976 (and $x959 (=> $x813 (or $x969 (and d_7_5 $x972))))))
 (let (($x988 (and $x976 (=> $x817 (or $x981 (and d_8_5 $x984))))))
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
 (let (($x989 (and $x776 $x988)))
 (let (($x1182 (and $x989 $x1181)))
 (and $x1182 (not (not $x1373))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
