; holon proof obligation: system planner_general2, region square:3x2, property progress
; expected: unsat (the property holds for every configuration of the region)
(set-logic ALL)
; 
(set-info :status unknown)
(declare-fun c_0_18 () Bool)
(declare-fun c_0_17 () Bool)
(declare-fun c_0_16 () Bool)
(declare-fun c_0_15 () Bool)
(declare-fun c_0_14 () Bool)
(declare-fun c_0_13 () Bool)
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
(declare-fun c_1_18 () Bool)
(declare-fun c_1_17 () Bool)
(declare-fun c_1_16 () Bool)
(declare-fun c_1_15 () Bool)
(declare-fun c_1_14 () Bool)
(declare-fun c_1_13 () Bool)
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
(declare-fun c_2_18 () Bool)
(declare-fun c_2_17 () Bool)
(declare-fun c_2_16 () Bool)
(declare-fun c_2_15 () Bool)
(declare-fun c_2_14 () Bool)
(declare-fun c_2_13 () Bool)
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
(declare-fun c_3_18 () Bool)
(declare-fun c_3_17 () Bool)
(declare-fun c_3_16 () Bool)
(declare-fun c_3_15 () Bool)
(declare-fun c_3_14 () Bool)
(declare-fun c_3_13 () Bool)
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
(declare-fun c_4_18 () Bool)
(declare-fun c_4_17 () Bool)
(declare-fun c_4_16 () Bool)
(declare-fun c_4_15 () Bool)
(declare-fun c_4_14 () Bool)
(declare-fun c_4_13 () Bool)
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
(declare-fun c_5_18 () Bool)
(declare-fun c_5_17 () Bool)
(declare-fun c_5_16 () Bool)
(declare-fun c_5_15 () Bool)
(declare-fun c_5_14 () Bool)
(declare-fun c_5_13 () Bool)
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
(declare-fun prank_24 () Int)
(declare-fun prank_25 () Int)
(declare-fun prank_26 () Int)
(declare-fun prank_27 () Int)
(declare-fun prank_28 () Int)
(declare-fun prank_29 () Int)
(declare-fun prank_32 () Int)
(declare-fun prank_33 () Int)
(declare-fun prank_34 () Int)
(declare-fun prank_35 () Int)
(declare-fun prank_36 () Int)
(declare-fun prank_37 () Int)
(declare-fun rank_40 () Int)
(declare-fun rank_42 () Int)
(declare-fun rank_44 () Int)
(declare-fun rank_46 () Int)
(declare-fun rank_48 () Int)
(declare-fun rank_50 () Int)
(declare-fun root_51 () Bool)
(declare-fun root_49 () Bool)
(declare-fun root_47 () Bool)
(declare-fun root_45 () Bool)
(declare-fun root_43 () Bool)
(declare-fun root_41 () Bool)
(declare-fun prank_high_39 () Int)
(declare-fun prank_low_38 () Int)
(declare-fun prank_high_31 () Int)
(declare-fun prank_low_30 () Int)
(declare-fun in_target_5 () Bool)
(declare-fun in_target_4 () Bool)
(declare-fun in_target_3 () Bool)
(declare-fun in_target_2 () Bool)
(declare-fun in_target_1 () Bool)
(declare-fun in_target_0 () Bool)
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
 (let (($x12 (or false c_0_0)))
 (let (($x14 (or $x12 c_0_1)))
 (let (($x16 (or $x14 c_0_2)))
 (let (($x18 (or $x16 c_0_3)))
 (let (($x20 (or $x18 c_0_4)))
 (let (($x22 (or $x20 c_0_5)))
 (let (($x24 (or $x22 c_0_6)))
 (let (($x26 (or $x24 c_0_7)))
 (let (($x28 (or $x26 c_0_8)))
 (let (($x30 (or $x28 c_0_9)))
 (let (($x32 (or $x30 c_0_10)))
 (let (($x34 (or $x32 c_0_11)))
 (let (($x36 (or $x34 c_0_12)))
 (let (($x38 (or $x36 c_0_13)))
 (let (($x40 (or $x38 c_0_14)))
 (let (($x42 (or $x40 c_0_15)))
 (let (($x44 (or $x42 c_0_16)))
 (let (($x46 (or $x44 c_0_17)))
 (or $x46 c_0_18))))))))))))))))))))
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
 (not (and c_0_0 c_0_13)))
(assert
 (not (and c_0_0 c_0_14)))
(assert
 (not (and c_0_0 c_0_15)))
(assert
 (not (and c_0_0 c_0_16)))
(assert
 (not (and c_0_0 c_0_17)))
(assert
 (not (and c_0_0 c_0_18)))
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
 (not (and c_0_1 c_0_13)))
(assert
 (not (and c_0_1 c_0_14)))
(assert
 (not (and c_0_1 c_0_15)))
(assert
 (not (and c_0_1 c_0_16)))
(assert
 (not (and c_0_1 c_0_17)))
(assert
 (not (and c_0_1 c_0_18)))
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
 (not (and c_0_2 c_0_13)))
(assert
 (not (and c_0_2 c_0_14)))
(assert
 (not (and c_0_2 c_0_15)))
(assert
 (not (and c_0_2 c_0_16)))
(assert
 (not (and c_0_2 c_0_17)))
(assert
 (not (and c_0_2 c_0_18)))
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
 (not (and c_0_3 c_0_13)))
(assert
 (not (and c_0_3 c_0_14)))
(assert
 (not (and c_0_3 c_0_15)))
(assert
 (not (and c_0_3 c_0_16)))
(assert
 (not (and c_0_3 c_0_17)))
(assert
 (not (and c_0_3 c_0_18)))
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
 (not (and c_0_4 c_0_13)))
(assert
 (not (and c_0_4 c_0_14)))
(assert
 (not (and c_0_4 c_0_15)))
(assert
 (not (and c_0_4 c_0_16)))
(assert
 (not (and c_0_4 c_0_17)))
(assert
 (not (and c_0_4 c_0_18)))
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
 (not (and c_0_5 c_0_13)))
(assert
 (not (and c_0_5 c_0_14)))
(assert
 (not (and c_0_5 c_0_15)))
(assert
 (not (and c_0_5 c_0_16)))
(assert
 (not (and c_0_5 c_0_17)))
(assert
 (not (and c_0_5 c_0_18)))
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
 (not (and c_0_6 c_0_13)))
(assert
 (not (and c_0_6 c_0_14)))
(assert
 (not (and c_0_6 c_0_15)))
(assert
 (not (and c_0_6 c_0_16)))
(assert
 (not (and c_0_6 c_0_17)))
(assert
 (not (and c_0_6 c_0_18)))
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
 (not (and c_0_7 c_0_13)))
(assert
 (not (and c_0_7 c_0_14)))
(assert
 (not (and c_0_7 c_0_15)))
(assert
 (not (and c_0_7 c_0_16)))
(assert
 (not (and c_0_7 c_0_17)))
(assert
 (not (and c_0_7 c_0_18)))
(assert
 (not (and c_0_8 c_0_9)))
(assert
 (not (and c_0_8 c_0_10)))
(assert
 (not (and c_0_8 c_0_11)))
(assert
 (not (and c_0_8 c_0_12)))
(assert
 (not (and c_0_8 c_0_13)))
(assert
 (not (and c_0_8 c_0_14)))
(assert
 (not (and c_0_8 c_0_15)))
(assert
 (not (and c_0_8 c_0_16)))
(assert
 (not (and c_0_8 c_0_17)))
(assert
 (not (and c_0_8 c_0_18)))
(assert
 (not (and c_0_9 c_0_10)))
(assert
 (not (and c_0_9 c_0_11)))
(assert
 (not (and c_0_9 c_0_12)))
(assert
 (not (and c_0_9 c_0_13)))
(assert
 (not (and c_0_9 c_0_14)))
(assert
 (not (and c_0_9 c_0_15)))
(assert
 (not (and c_0_9 c_0_16)))
(assert
 (not (and c_0_9 c_0_17)))
(assert
 (not (and c_0_9 c_0_18)))
(assert
 (not (and c_0_10 c_0_11)))
(assert
 (not (and c_0_10 c_0_12)))
(assert
 (not (and c_0_10 c_0_13)))
(assert
 (not (and c_0_10 c_0_14)))
(assert
 (not (and c_0_10 c_0_15)))
(assert
 (not (and c_0_10 c_0_16)))
(assert
 (not (and c_0_10 c_0_17)))
(assert
 (not (and c_0_10 c_0_18)))
(assert
 (not (and c_0_11 c_0_12)))
(assert
 (not (and c_0_11 c_0_13)))
(assert
 (not (and c_0_11 c_0_14)))
(assert
 (not (and c_0_11 c_0_15)))
(assert
 (not (and c_0_11 c_0_16)))
(assert
 (not (and c_0_11 c_0_17)))
(assert
 (not (and c_0_11 c_0_18)))
(assert
 (not (and c_0_12 c_0_13)))
(assert
 (not (and c_0_12 c_0_14)))
(assert
 (not (and c_0_12 c_0_15)))
(assert
 (not (and c_0_12 c_0_16)))
(assert
 (not (and c_0_12 c_0_17)))
(assert
 (not (and c_0_12 c_0_18)))
(assert
 (not (and c_0_13 c_0_14)))
(assert
 (not (and c_0_13 c_0_15)))
(assert
 (not (and c_0_13 c_0_16)))
(assert
 (not (and c_0_13 c_0_17)))
(assert
 (not (and c_0_13 c_0_18)))
(assert
 (not (and c_0_14 c_0_15)))
(assert
 (not (and c_0_14 c_0_16)))
(assert
 (not (and c_0_14 c_0_17)))
(assert
 (not (and c_0_14 c_0_18)))
(assert
 (not (and c_0_15 c_0_16)))
(assert
 (not (and c_0_15 c_0_17)))
(assert
 (not (and c_0_15 c_0_18)))
(assert
 (not (and c_0_16 c_0_17)))
(assert
 (not (and c_0_16 c_0_18)))
(assert
 (not (and c_0_17 c_0_18)))
(assert
 (let (($x392 (or false c_1_0)))
 (let (($x394 (or $x392 c_1_1)))
 (let (($x396 (or $x394 c_1_2)))
 (let (($x398 (or $x396 c_1_3)))
 (let (($x400 (or $x398 c_1_4)))
 (let (($x402 (or $x400 c_1_5)))
 (let (($x404 (or $x402 c_1_6)))
 (let (($x406 (or $x404 c_1_7)))
 (let (($x408 (or $x406 c_1_8)))
 (let (($x410 (or $x408 c_1_9)))
 (let (($x412 (or $x410 c_1_10)))
 (let (($x414 (or $x412 c_1_11)))
 (let (($x416 (or $x414 c_1_12)))
 (let (($x418 (or $x416 c_1_13)))
 (let (($x420 (or $x418 c_1_14)))
 (let (($x422 (or $x420 c_1_15)))
 (let (($x424 (or $x422 c_1_16)))
 (let (($x426 (or $x424 c_1_17)))
 (or $x426 c_1_18))))))))))))))))))))
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
 (not (and c_1_0 c_1_13)))
(assert
 (not (and c_1_0 c_1_14)))
(assert
 (not (and c_1_0 c_1_15)))
(assert
 (not (and c_1_0 c_1_16)))
(assert
 (not (and c_1_0 c_1_17)))
(assert
 (not (and c_1_0 c_1_18)))
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
 (not (and c_1_1 c_1_13)))
(assert
 (not (and c_1_1 c_1_14)))
(assert
 (not (and c_1_1 c_1_15)))
(assert
 (not (and c_1_1 c_1_16)))
(assert
 (not (and c_1_1 c_1_17)))
(assert
 (not (and c_1_1 c_1_18)))
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
 (not (and c_1_2 c_1_13)))
(assert
 (not (and c_1_2 c_1_14)))
(assert
 (not (and c_1_2 c_1_15)))
(assert
 (not (and c_1_2 c_1_16)))
(assert
 (not (and c_1_2 c_1_17)))
(assert
 (not (and c_1_2 c_1_18)))
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
 (not (and c_1_3 c_1_13)))
(assert
 (not (and c_1_3 c_1_14)))
(assert
 (not (and c_1_3 c_1_15)))
(assert
 (not (and c_1_3 c_1_16)))
(assert
 (not (and c_1_3 c_1_17)))
(assert
 (not (and c_1_3 c_1_18)))
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
 (not (and c_1_4 c_1_13)))
(assert
 (not (and c_1_4 c_1_14)))
(assert
 (not (and c_1_4 c_1_15)))
(assert
 (not (and c_1_4 c_1_16)))
(assert
 (not (and c_1_4 c_1_17)))
(assert
 (not (and c_1_4 c_1_18)))
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
 (not (and c_1_5 c_1_13)))
(assert
 (not (and c_1_5 c_1_14)))
(assert
 (not (and c_1_5 c_1_15)))
(assert
 (not (and c_1_5 c_1_16)))
(assert
 (not (and c_1_5 c_1_17)))
(assert
 (not (and c_1_5 c_1_18)))
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
 (not (and c_1_6 c_1_13)))
(assert
 (not (and c_1_6 c_1_14)))
(assert
 (not (and c_1_6 c_1_15)))
(assert
 (not (and c_1_6 c_1_16)))
(assert
 (not (and c_1_6 c_1_17)))
(assert
 (not (and c_1_6 c_1_18)))
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
 (not (and c_1_7 c_1_13)))
(assert
 (not (and c_1_7 c_1_14)))
(assert
 (not (and c_1_7 c_1_15)))
(assert
 (not (and c_1_7 c_1_16)))
(assert
 (not (and c_1_7 c_1_17)))
(assert
 (not (and c_1_7 c_1_18)))
(assert
 (not (and c_1_8 c_1_9)))
(assert
 (not (and c_1_8 c_1_10)))
(assert
 (not (and c_1_8 c_1_11)))
(assert
 (not (and c_1_8 c_1_12)))
(assert
 (not (and c_1_8 c_1_13)))
(assert
 (not (and c_1_8 c_1_14)))
(assert
 (not (and c_1_8 c_1_15)))
(assert
 (not (and c_1_8 c_1_16)))
(assert
 (not (and c_1_8 c_1_17)))
(assert
 (not (and c_1_8 c_1_18)))
(assert
 (not (and c_1_9 c_1_10)))
(assert
 (not (and c_1_9 c_1_11)))
(assert
 (not (and c_1_9 c_1_12)))
(assert
 (not (and c_1_9 c_1_13)))
(assert
 (not (and c_1_9 c_1_14)))
(assert
 (not (and c_1_9 c_1_15)))
(assert
 (not (and c_1_9 c_1_16)))
(assert
 (not (and c_1_9 c_1_17)))
(assert
 (not (and c_1_9 c_1_18)))
(assert
 (not (and c_1_10 c_1_11)))
(assert
 (not (and c_1_10 c_1_12)))
(assert
 (not (and c_1_10 c_1_13)))
(assert
 (not (and c_1_10 c_1_14)))
(assert
 (not (and c_1_10 c_1_15)))
(assert
 (not (and c_1_10 c_1_16)))
(assert
 (not (and c_1_10 c_1_17)))
(assert
 (not (and c_1_10 c_1_18)))
(assert
 (not (and c_1_11 c_1_12)))
(assert
 (not (and c_1_11 c_1_13)))
(assert
 (not (and c_1_11 c_1_14)))
(assert
 (not (and c_1_11 c_1_15)))
(assert
 (not (and c_1_11 c_1_16)))
(assert
 (not (and c_1_11 c_1_17)))
(assert
 (not (and c_1_11 c_1_18)))
(assert
 (not (and c_1_12 c_1_13)))
(assert
 (not (and c_1_12 c_1_14)))
(assert
 (not (and c_1_12 c_1_15)))
(assert
 (not (and c_1_12 c_1_16)))
(assert
 (not (and c_1_12 c_1_17)))
(assert
 (not (and c_1_12 c_1_18)))
(assert
 (not (and c_1_13 c_1_14)))
(assert
 (not (and c_1_13 c_1_15)))
(assert
 (not (and c_1_13 c_1_16)))
(assert
 (not (and c_1_13 c_1_17)))
(assert
 (not (and c_1_13 c_1_18)))
(assert
 (not (and c_1_14 c_1_15)))
(assert
 (not (and c_1_14 c_1_16)))
(assert
 (not (and c_1_14 c_1_17)))
(assert
 (not (and c_1_14 c_1_18)))
(assert
 (not (and c_1_15 c_1_16)))
(assert
 (not (and c_1_15 c_1_17)))
(assert
 (not (and c_1_15 c_1_18)))
(assert
 (not (and c_1_16 c_1_17)))
(assert
 (not (and c_1_16 c_1_18)))
(assert
 (not (and c_1_17 c_1_18)))
(assert
 (let (($x772 (or false c_2_0)))
 (let (($x774 (or $x772 c_2_1)))
 (let (($x776 (or $x774 c_2_2)))
 (let (($x778 (or $x776 c_2_3)))
 (let (($x780 (or $x778 c_2_4)))
 (let (($x782 (or $x780 c_2_5)))
 (let (($x784 (or $x782 c_2_6)))
 (let (($x786 (or $x784 c_2_7)))
 (let (($x788 (or $x786 c_2_8)))
 (let (($x790 (or $x788 c_2_9)))
 (let (($x792 (or $x790 c_2_10)))
 (let (($x794 (or $x792 c_2_11)))
 (let (($x796 (or $x794 c_2_12)))
 (let (($x798 (or $x796 c_2_13)))
 (let (($x800 (or $x798 c_2_14)))
 (let (($x802 (or $x800 c_2_15)))
 (let (($x804 (or $x802 c_2_16)))
 (let (($x806 (or $x804 c_2_17)))
 (or $x806 c_2_18))))))))))))))))))))
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
 (not (and c_2_0 c_2_13)))
(assert
 (not (and c_2_0 c_2_14)))
(assert
 (not (and c_2_0 c_2_15)))
(assert
 (not (and c_2_0 c_2_16)))
(assert
 (not (and c_2_0 c_2_17)))
(assert
 (not (and c_2_0 c_2_18)))
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
 (not (and c_2_1 c_2_13)))
(assert
 (not (and c_2_1 c_2_14)))
(assert
 (not (and c_2_1 c_2_15)))
(assert
 (not (and c_2_1 c_2_16)))
(assert
 (not (and c_2_1 c_2_17)))
(assert
 (not (and c_2_1 c_2_18)))
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
 (not (and c_2_2 c_2_13)))
(assert
 (not (and c_2_2 c_2_14)))
(assert
 (not (and c_2_2 c_2_15)))
(assert
 (not (and c_2_2 c_2_16)))
(assert
 (not (and c_2_2 c_2_17)))
(assert
 (not (and c_2_2 c_2_18)))
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
 (not (and c_2_3 c_2_13)))
(assert
 (not (and c_2_3 c_2_14)))
(assert
 (not (and c_2_3 c_2_15)))
(assert
 (not (and c_2_3 c_2_16)))
(assert
 (not (and c_2_3 c_2_17)))
(assert
 (not (and c_2_3 c_2_18)))
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
 (not (and c_2_4 c_2_13)))
(assert
 (not (and c_2_4 c_2_14)))
(assert
 (not (and c_2_4 c_2_15)))
(assert
 (not (and c_2_4 c_2_16)))
(assert
 (not (and c_2_4 c_2_17)))
(assert
 (not (and c_2_4 c_2_18)))
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
 (not (and c_2_5 c_2_13)))
(assert
 (not (and c_2_5 c_2_14)))
(assert
 (not (and c_2_5 c_2_15)))
(assert
 (not (and c_2_5 c_2_16)))
(assert
 (not (and c_2_5 c_2_17)))
(assert
 (not (and c_2_5 c_2_18)))
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
 (not (and c_2_6 c_2_13)))
(assert
 (not (and c_2_6 c_2_14)))
(assert
 (not (and c_2_6 c_2_15)))
(assert
 (not (and c_2_6 c_2_16)))
(assert
 (not (and c_2_6 c_2_17)))
(assert
 (not (and c_2_6 c_2_18)))
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
 (not (and c_2_7 c_2_13)))
(assert
 (not (and c_2_7 c_2_14)))
(assert
 (not (and c_2_7 c_2_15)))
(assert
 (not (and c_2_7 c_2_16)))
(assert
 (not (and c_2_7 c_2_17)))
(assert
 (not (and c_2_7 c_2_18)))
(assert
 (not (and c_2_8 c_2_9)))
(assert
 (not (and c_2_8 c_2_10)))
(assert
 (not (and c_2_8 c_2_11)))
(assert
 (not (and c_2_8 c_2_12)))
(assert
 (not (and c_2_8 c_2_13)))
(assert
 (not (and c_2_8 c_2_14)))
(assert
 (not (and c_2_8 c_2_15)))
(assert
 (not (and c_2_8 c_2_16)))
(assert
 (not (and c_2_8 c_2_17)))
(assert
 (not (and c_2_8 c_2_18)))
(assert
 (not (and c_2_9 c_2_10)))
(assert
 (not (and c_2_9 c_2_11)))
(assert
 (not (and c_2_9 c_2_12)))
(assert
 (not (and c_2_9 c_2_13)))
(assert
 (not (and c_2_9 c_2_14)))
(assert
 (not (and c_2_9 c_2_15)))
(assert
 (not (and c_2_9 c_2_16)))
(assert
 (not (and c_2_9 c_2_17)))
(assert
 (not (and c_2_9 c_2_18)))
(assert
 (not (and c_2_10 c_2_11)))
(assert
 (not (and c_2_10 c_2_12)))
(assert
 (not (and c_2_10 c_2_13)))
(assert
 (not (and c_2_10 c_2_14)))
(assert
 (not (and c_2_10 c_2_15)))
(assert
 (not (and c_2_10 c_2_16)))
(assert
 (not (and c_2_10 c_2_17)))
(assert
 (not (and c_2_10 c_2_18)))
(assert
 (not (and c_2_11 c_2_12)))
(assert
 (not (and c_2_11 c_2_13)))
(assert
 (not (and c_2_11 c_2_14)))
(assert
 (not (and c_2_11 c_2_15)))
(assert
 (not (and c_2_11 c_2_16)))
(assert
 (not (and c_2_11 c_2_17)))
(assert
 (not (and c_2_11 c_2_18)))
(assert
 (not (and c_2_12 c_2_13)))
(assert
 (not (and c_2_12 c_2_14)))
(assert
 (not (and c_2_12 c_2_15)))
(assert
 (not (and c_2_12 c_2_16)))
(assert
 (not (and c_2_12 c_2_17)))
(assert
 (not (and c_2_12 c_2_18)))
(assert
 (not (and c_2_13 c_2_14)))
(assert
 (not (and c_2_13 c_2_15)))
(assert
 (not (and c_2_13 c_2_16)))
(assert
 (not (and c_2_13 c_2_17)))
(assert
 (not (and c_2_13 c_2_18)))
(assert
 (not (and c_2_14 c_2_15)))
(assert
 (not (and c_2_14 c_2_16)))
(assert
 (not (and c_2_14 c_2_17)))
(assert
 (not (and c_2_14 c_2_18)))
(assert
 (not (and c_2_15 c_2_16)))
(assert
 (not (and c_2_15 c_2_17)))
(assert
 (not (and c_2_15 c_2_18)))
(assert
 (not (and c_2_16 c_2_17)))
(assert
 (not (and c_2_16 c_2_18)))
(assert
 (not (and c_2_17 c_2_18)))
(assert
 (let (($x1152 (or false c_3_0)))
 (let (($x1154 (or $x1152 c_3_1)))
 (let (($x1156 (or $x1154 c_3_2)))
 (let (($x1158 (or $x1156 c_3_3)))
 (let (($x1160 (or $x1158 c_3_4)))
 (let (($x1162 (or $x1160 c_3_5)))
 (let (($x1164 (or $x1162 c_3_6)))
 (let (($x1166 (or $x1164 c_3_7)))
 (let (($x1168 (or $x1166 c_3_8)))
 (let (($x1170 (or $x1168 c_3_9)))
 (let (($x1172 (or $x1170 c_3_10)))
 (let (($x1174 (or $x1172 c_3_11)))
 (let (($x1176 (or $x1174 c_3_12)))
 (let (($x1178 (or $x1176 c_3_13)))
 (let (($x1180 (or $x1178 c_3_14)))
 (let (($x1182 (or $x1180 c_3_15)))
 (let (($x1184 (or $x1182 c_3_16)))
 (let (($x1186 (or $x1184 c_3_17)))
 (or $x1186 c_3_18))))))))))))))))))))
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
 (not (and c_3_0 c_3_13)))
(assert
 (not (and c_3_0 c_3_14)))
(assert
 (not (and c_3_0 c_3_15)))
(assert
 (not (and c_3_0 c_3_16)))
(assert
 (not (and c_3_0 c_3_17)))
(assert
 (not (and c_3_0 c_3_18)))
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
 (not (and c_3_1 c_3_13)))
(assert
 (not (and c_3_1 c_3_14)))
(assert
 (not (and c_3_1 c_3_15)))
(assert
 (not (and c_3_1 c_3_16)))
(assert
 (not (and c_3_1 c_3_17)))
(assert
 (not (and c_3_1 c_3_18)))
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
 (not (and c_3_2 c_3_13)))
(assert
 (not (and c_3_2 c_3_14)))
(assert
 (not (and c_3_2 c_3_15)))
(assert
 (not (and c_3_2 c_3_16)))
(assert
 (not (and c_3_2 c_3_17)))
(assert
 (not (and c_3_2 c_3_18)))
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
 (not (and c_3_3 c_3_13)))
(assert
 (not (and c_3_3 c_3_14)))
(assert
 (not (and c_3_3 c_3_15)))
(assert
 (not (and c_3_3 c_3_16)))
(assert
 (not (and c_3_3 c_3_17)))
(assert
 (not (and c_3_3 c_3_18)))
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
 (not (and c_3_4 c_3_13)))
(assert
 (not (and c_3_4 c_3_14)))
(assert
 (not (and c_3_4 c_3_15)))
(assert
 (not (and c_3_4 c_3_16)))
(assert
 (not (and c_3_4 c_3_17)))
(assert
 (not (and c_3_4 c_3_18)))
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
 (not (and c_3_5 c_3_13)))
(assert
 (not (and c_3_5 c_3_14)))
(assert
 (not (and c_3_5 c_3_15)))
(assert
 (not (and c_3_5 c_3_16)))
(assert
 (not (and c_3_5 c_3_17)))
(assert
 (not (and c_3_5 c_3_18)))
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
 (not (and c_3_6 c_3_13)))
(assert
 (not (and c_3_6 c_3_14)))
(assert
 (not (and c_3_6 c_3_15)))
(assert
 (not (and c_3_6 c_3_16)))
(assert
 (not (and c_3_6 c_3_17)))
(assert
 (not (and c_3_6 c_3_18)))
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
 (not (and c_3_7 c_3_13)))
(assert
 (not (and c_3_7 c_3_14)))
(assert
 (not (and c_3_7 c_3_15)))
(assert
 (not (and c_3_7 c_3_16)))
(assert
 (not (and c_3_7 c_3_17)))
(assert
 (not (and c_3_7 c_3_18)))
(assert
 (not (and c_3_8 c_3_9)))
(assert
 (not (and c_3_8 c_3_10)))
(assert
 (not (and c_3_8 c_3_11)))
(assert
 (not (and c_3_8 c_3_12)))
(assert
 (not (and c_3_8 c_3_13)))
(assert
 (not (and c_3_8 c_3_14)))
(assert
 (not (and c_3_8 c_3_15)))
(assert
 (not (and c_3_8 c_3_16)))
(assert
 (not (and c_3_8 c_3_17)))
(assert
 (not (and c_3_8 c_3_18)))
(assert
 (not (and c_3_9 c_3_10)))
(assert
 (not (and c_3_9 c_3_11)))
(assert
 (not (and c_3_9 c_3_12)))
(assert
 (not (and c_3_9 c_3_13)))
(assert
 (not (and c_3_9 c_3_14)))
(assert
 (not (and c_3_9 c_3_15)))
(assert
 (not (and c_3_9 c_3_16)))
(assert
 (not (and c_3_9 c_3_17)))
(assert
 (not (and c_3_9 c_3_18)))
(assert
 (not (and c_3_10 c_3_11)))
(assert
 (not (and c_3_10 c_3_12)))
(assert
 (not (and c_3_10 c_3_13)))
(assert
 (not (and c_3_10 c_3_14)))
(assert
 (not (and c_3_10 c_3_15)))
(assert
 (not (and c_3_10 c_3_16)))
(assert
 (not (and c_3_10 c_3_17)))
(assert
 (not (and c_3_10 c_3_18)))
(assert
 (not (and c_3_11 c_3_12)))
(assert
 (not (and c_3_11 c_3_13)))
(assert
 (not (and c_3_11 c_3_14)))
(assert
 (not (and c_3_11 c_3_15)))
(assert
 (not (and c_3_11 c_3_16)))
(assert
 (not (and c_3_11 c_3_17)))
(assert
 (not (and c_3_11 c_3_18)))
(assert
 (not (and c_3_12 c_3_13)))
(assert
 (not (and c_3_12 c_3_14)))
(assert
 (not (and c_3_12 c_3_15)))
(assert
 (not (and c_3_12 c_3_16)))
(assert
 (not (and c_3_12 c_3_17)))
(assert
 (not (and c_3_12 c_3_18)))
(assert
 (not (and c_3_13 c_3_14)))
(assert
 (not (and c_3_13 c_3_15)))
(assert
 (not (and c_3_13 c_3_16)))
(assert
 (not (and c_3_13 c_3_17)))
(assert
 (not (and c_3_13 c_3_18)))
(assert
 (not (and c_3_14 c_3_15)))
(assert
 (not (and c_3_14 c_3_16)))
(assert
 (not (and c_3_14 c_3_17)))
(assert
 (not (and c_3_14 c_3_18)))
(assert
 (not (and c_3_15 c_3_16)))
(assert
 (not (and c_3_15 c_3_17)))
(assert
 (not (and c_3_15 c_3_18)))
(assert
 (not (and c_3_16 c_3_17)))
(assert
 (not (and c_3_16 c_3_18)))
(assert
 (not (and c_3_17 c_3_18)))
(assert
 (let (($x1532 (or false c_4_0)))
 (let (($x1534 (or $x1532 c_4_1)))
 (let (($x1536 (or $x1534 c_4_2)))
 (let (($x1538 (or $x1536 c_4_3)))
 (let (($x1540 (or $x1538 c_4_4)))
 (let (($x1542 (or $x1540 c_4_5)))
 (let (($x1544 (or $x1542 c_4_6)))
 (let (($x1546 (or $x1544 c_4_7)))
 (let (($x1548 (or $x1546 c_4_8)))
 (let (($x1550 (or $x1548 c_4_9)))
 (let (($x1552 (or $x1550 c_4_10)))
 (let (($x1554 (or $x1552 c_4_11)))
 (let (($x1556 (or $x1554 c_4_12)))
 (let (($x1558 (or $x1556 c_4_13)))
 (let (($x1560 (or $x1558 c_4_14)))
 (let (($x1562 (or $x1560 c_4_15)))
 (let (($x1564 (or $x1562 c_4_16)))
 (let (($x1566 (or $x1564 c_4_17)))
 (or $x1566 c_4_18))))))))))))))))))))
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
 (not (and c_4_0 c_4_13)))
(assert
 (not (and c_4_0 c_4_14)))
(assert
 (not (and c_4_0 c_4_15)))
(assert
 (not (and c_4_0 c_4_16)))
(assert
 (not (and c_4_0 c_4_17)))
(assert
 (not (and c_4_0 c_4_18)))
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
 (not (and c_4_1 c_4_13)))
(assert
 (not (and c_4_1 c_4_14)))
(assert
 (not (and c_4_1 c_4_15)))
(assert
 (not (and c_4_1 c_4_16)))
(assert
 (not (and c_4_1 c_4_17)))
(assert
 (not (and c_4_1 c_4_18)))
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
 (not (and c_4_2 c_4_13)))
(assert
 (not (and c_4_2 c_4_14)))
(assert
 (not (and c_4_2 c_4_15)))
(assert
 (not (and c_4_2 c_4_16)))
(assert
 (not (and c_4_2 c_4_17)))
(assert
 (not (and c_4_2 c_4_18)))
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
 (not (and c_4_3 c_4_13)))
(assert
 (not (and c_4_3 c_4_14)))
(assert
 (not (and c_4_3 c_4_15)))
(assert
 (not (and c_4_3 c_4_16)))
(assert
 (not (and c_4_3 c_4_17)))
(assert
 (not (and c_4_3 c_4_18)))
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
 (not (and c_4_4 c_4_13)))
(assert
 (not (and c_4_4 c_4_14)))
(assert
 (not (and c_4_4 c_4_15)))
(assert
 (not (and c_4_4 c_4_16)))
(assert
 (not (and c_4_4 c_4_17)))
(assert
 (not (and c_4_4 c_4_18)))
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
 (not (and c_4_5 c_4_13)))
(assert
 (not (and c_4_5 c_4_14)))
(assert
 (not (and c_4_5 c_4_15)))
(assert
 (not (and c_4_5 c_4_16)))
(assert
 (not (and c_4_5 c_4_17)))
(assert
 (not (and c_4_5 c_4_18)))
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
 (not (and c_4_6 c_4_13)))
(assert
 (not (and c_4_6 c_4_14)))
(assert
 (not (and c_4_6 c_4_15)))
(assert
 (not (and c_4_6 c_4_16)))
(assert
 (not (and c_4_6 c_4_17)))
(assert
 (not (and c_4_6 c_4_18)))
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
 (not (and c_4_7 c_4_13)))
(assert
 (not (and c_4_7 c_4_14)))
(assert
 (not (and c_4_7 c_4_15)))
(assert
 (not (and c_4_7 c_4_16)))
(assert
 (not (and c_4_7 c_4_17)))
(assert
 (not (and c_4_7 c_4_18)))
(assert
 (not (and c_4_8 c_4_9)))
(assert
 (not (and c_4_8 c_4_10)))
(assert
 (not (and c_4_8 c_4_11)))
(assert
 (not (and c_4_8 c_4_12)))
(assert
 (not (and c_4_8 c_4_13)))
(assert
 (not (and c_4_8 c_4_14)))
(assert
 (not (and c_4_8 c_4_15)))
(assert
 (not (and c_4_8 c_4_16)))
(assert
 (not (and c_4_8 c_4_17)))
(assert
 (not (and c_4_8 c_4_18)))
(assert
 (not (and c_4_9 c_4_10)))
(assert
 (not (and c_4_9 c_4_11)))
(assert
 (not (and c_4_9 c_4_12)))
(assert
 (not (and c_4_9 c_4_13)))
(assert
 (not (and c_4_9 c_4_14)))
(assert
 (not (and c_4_9 c_4_15)))
(assert
 (not (and c_4_9 c_4_16)))
(assert
 (not (and c_4_9 c_4_17)))
(assert
 (not (and c_4_9 c_4_18)))
(assert
 (not (and c_4_10 c_4_11)))
(assert
 (not (and c_4_10 c_4_12)))
(assert
 (not (and c_4_10 c_4_13)))
(assert
 (not (and c_4_10 c_4_14)))
(assert
 (not (and c_4_10 c_4_15)))
(assert
 (not (and c_4_10 c_4_16)))
(assert
 (not (and c_4_10 c_4_17)))
(assert
 (not (and c_4_10 c_4_18)))
(assert
 (not (and c_4_11 c_4_12)))
(assert
 (not (and c_4_11 c_4_13)))
(assert
 (not (and c_4_11 c_4_14)))
(assert
 (not (and c_4_11 c_4_15)))
(assert
 (not (and c_4_11 c_4_16)))
(assert
 (not (and c_4_11 c_4_17)))
(assert
 (not (and c_4_11 c_4_18)))
(assert
 (not (and c_4_12 c_4_13)))
(assert
 (not (and c_4_12 c_4_14)))
(assert
 (not (and c_4_12 c_4_15)))
(assert
 (not (and c_4_12 c_4_16)))
(assert
 (not (and c_4_12 c_4_17)))
(assert
 (not (and c_4_12 c_4_18)))
(assert
 (not (and c_4_13 c_4_14)))
(assert
 (not (and c_4_13 c_4_15)))
(assert
 (not (and c_4_13 c_4_16)))
(assert
 (not (and c_4_13 c_4_17)))
(assert
 (not (and c_4_13 c_4_18)))
(assert
 (not (and c_4_14 c_4_15)))
(assert
 (not (and c_4_14 c_4_16)))
(assert
 (not (and c_4_14 c_4_17)))
(assert
 (not (and c_4_14 c_4_18)))
(assert
 (not (and c_4_15 c_4_16)))
(assert
 (not (and c_4_15 c_4_17)))
(assert
 (not (and c_4_15 c_4_18)))
(assert
 (not (and c_4_16 c_4_17)))
(assert
 (not (and c_4_16 c_4_18)))
(assert
 (not (and c_4_17 c_4_18)))
(assert
 (let (($x1912 (or false c_5_0)))
 (let (($x1914 (or $x1912 c_5_1)))
 (let (($x1916 (or $x1914 c_5_2)))
 (let (($x1918 (or $x1916 c_5_3)))
 (let (($x1920 (or $x1918 c_5_4)))
 (let (($x1922 (or $x1920 c_5_5)))
 (let (($x1924 (or $x1922 c_5_6)))
 (let (($x1926 (or $x1924 c_5_7)))
 (let (($x1928 (or $x1926 c_5_8)))
 (let (($x1930 (or $x1928 c_5_9)))
 (let (($x1932 (or $x1930 c_5_10)))
 (let (($x1934 (or $x1932 c_5_11)))
 (let (($x1936 (or $x1934 c_5_12)))
 (let (($x1938 (or $x1936 c_5_13)))
 (let (($x1940 (or $x1938 c_5_14)))
 (let (($x1942 (or $x1940 c_5_15)))
 (let (($x1944 (or $x1942 c_5_16)))
 (let (($x1946 (or $x1944 c_5_17)))
 (or $x1946 c_5_18))))))))))))))))))))
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
 (not (and c_5_0 c_5_13)))
(assert
 (not (and c_5_0 c_5_14)))
(assert
 (not (and c_5_0 c_5_15)))
(assert
 (not (and c_5_0 c_5_16)))
(assert
 (not (and c_5_0 c_5_17)))
(assert
 (not (and c_5_0 c_5_18)))
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
 (not (and c_5_1 c_5_13)))
(assert
 (not (and c_5_1 c_5_14)))
(assert
 (not (and c_5_1 c_5_15)))
(assert
 (not (and c_5_1 c_5_16)))
(assert
 (not (and c_5_1 c_5_17)))
(assert
 (not (and c_5_1 c_5_18)))
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
 (not (and c_5_2 c_5_13)))
(assert
 (not (and c_5_2 c_5_14)))
(assert
 (not (and c_5_2 c_5_15)))
(assert
 (not (and c_5_2 c_5_16)))
(assert
 (not (and c_5_2 c_5_17)))
(assert
 (not (and c_5_2 c_5_18)))
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
 (not (and c_5_3 c_5_13)))
(assert
 (not (and c_5_3 c_5_14)))
(assert
 (not (and c_5_3 c_5_15)))
(assert
 (not (and c_5_3 c_5_16)))
(assert
 (not (and c_5_3 c_5_17)))
(assert
 (not (and c_5_3 c_5_18)))
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
 (not (and c_5_4 c_5_13)))
(assert
 (not (and c_5_4 c_5_14)))
(assert
 (not (and c_5_4 c_5_15)))
(assert
 (not (and c_5_4 c_5_16)))
(assert
 (not (and c_5_4 c_5_17)))
(assert
 (not (and c_5_4 c_5_18)))
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
 (not (and c_5_5 c_5_13)))
(assert
 (not (and c_5_5 c_5_14)))
(assert
 (not (and c_5_5 c_5_15)))
(assert
 (not (and c_5_5 c_5_16)))
(assert
 (not (and c_5_5 c_5_17)))
(assert
 (not (and c_5_5 c_5_18)))
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
 (not (and c_5_6 c_5_13)))
(assert
 (not (and c_5_6 c_5_14)))
(assert
 (not (and c_5_6 c_5_15)))
(assert
 (not (and c_5_6 c_5_16)))
(assert
 (not (and c_5_6 c_5_17)))
(assert
 (not (and c_5_6 c_5_18)))
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
 (not (and c_5_7 c_5_13)))
(assert
 (not (and c_5_7 c_5_14)))
(assert
 (not (and c_5_7 c_5_15)))
(assert
 (not (and c_5_7 c_5_16)))
(assert
 (not (and c_5_7 c_5_17)))
(assert
 (not (and c_5_7 c_5_18)))
(assert
 (not (and c_5_8 c_5_9)))
(assert
 (not (and c_5_8 c_5_10)))
(assert
 (not (and c_5_8 c_5_11)))
(assert
 (not (and c_5_8 c_5_12)))
(assert
 (not (and c_5_8 c_5_13)))
(assert
 (not (and c_5_8 c_5_14)))
(assert
 (not (and c_5_8 c_5_15)))
(assert
 (not (and c_5_8 c_5_16)))
(assert
 (not (and c_5_8 c_5_17)))
(assert
 (not (and c_5_8 c_5_18)))
(assert
 (not (and c_5_9 c_5_10)))
(assert
 (not (and c_5_9 c_5_11)))
(assert
 (not (and c_5_9 c_5_12)))
(assert
 (not (and c_5_9 c_5_13)))
(assert
 (not (and c_5_9 c_5_14)))
(assert
 (not (and c_5_9 c_5_15)))
(assert
 (not (and c_5_9 c_5_16)))
(assert
 (not (and c_5_9 c_5_17)))
(assert
 (not (and c_5_9 c_5_18)))
(assert
 (not (and c_5_10 c_5_11)))
(assert
 (not (and c_5_10 c_5_12)))
(assert
 (not (and c_5_10 c_5_13)))
(assert
 (not (and c_5_10 c_5_14)))
(assert
 (not (and c_5_10 c_5_15)))
(assert
 (not (and c_5_10 c_5_16)))
(assert
 (not (and c_5_10 c_5_17)))
(assert
 (not (and c_5_10 c_5_18)))
(assert
 (not (and c_5_11 c_5_12)))
(assert
 (not (and c_5_11 c_5_13)))
(assert
 (not (and c_5_11 c_5_14)))
(assert
 (not (and c_5_11 c_5_15)))
(assert
 (not (and c_5_11 c_5_16)))
(assert
 (not (and c_5_11 c_5_17)))
(assert
 (not (and c_5_11 c_5_18)))
(assert
 (not (and c_5_12 c_5_13)))
(assert
 (not (and c_5_12 c_5_14)))
(assert
 (not (and c_5_12 c_5_15)))
(assert
 (not (and c_5_12 c_5_16)))
(assert
 (not (and c_5_12 c_5_17)))
(assert
 (not (and c_5_12 c_5_18)))
(assert
 (not (and c_5_13 c_5_14)))
(assert
 (not (and c_5_13 c_5_15)))
(assert
 (not (and c_5_13 c_5_16)))
(assert
 (not (and c_5_13 c_5_17)))
(assert
 (not (and c_5_13 c_5_18)))
(assert
 (not (and c_5_14 c_5_15)))
(assert
 (not (and c_5_14 c_5_16)))
(assert
 (not (and c_5_14 c_5_17)))
(assert
 (not (and c_5_14 c_5_18)))
(assert
 (not (and c_5_15 c_5_16)))
(assert
 (not (and c_5_15 c_5_17)))
(assert
 (not (and c_5_15 c_5_18)))
(assert
 (not (and c_5_16 c_5_17)))
(assert
 (not (and c_5_16 c_5_18)))
(assert
 (not (and c_5_17 c_5_18)))
(assert
 (let (($x2691 (>= rank_0 0)))
 (and $x2691 (< rank_0 6))))
(assert
 (let (($x2702 (>= rank_2 0)))
 (and $x2702 (< rank_2 6))))
(assert
 (let (($x2705 (>= rank_4 0)))
 (and $x2705 (< rank_4 6))))
(assert
 (let (($x2718 (>= rank_6 0)))
 (and $x2718 (< rank_6 6))))
(assert
 (let (($x2723 (>= rank_8 0)))
 (and $x2723 (< rank_8 6))))
(assert
 (let (($x2728 (>= rank_10 0)))
 (and $x2728 (< rank_10 6))))
(assert
 (let (($x4010 (>= rank_12 0)))
 (and $x4010 (< rank_12 6))))
(assert
 (let (($x4015 (>= rank_14 0)))
 (and $x4015 (< rank_14 6))))
(assert
 (let (($x4020 (>= rank_16 0)))
 (and $x4020 (< rank_16 6))))
(assert
 (let (($x4025 (>= rank_18 0)))
 (and $x4025 (< rank_18 6))))
(assert
 (let (($x4030 (>= rank_20 0)))
 (and $x4030 (< rank_20 6))))
(assert
 (let (($x4035 (>= rank_22 0)))
 (and $x4035 (< rank_22 6))))
(assert
 (let (($x4212 (>= prank_24 0)))
 (and $x4212 (< prank_24 6))))
(assert
 (let (($x4233 (>= prank_25 0)))
 (and $x4233 (< prank_25 6))))
(assert
 (let (($x4237 (>= prank_26 0)))
 (and $x4237 (< prank_26 6))))
(assert
 (let (($x4241 (>= prank_27 0)))
 (and $x4241 (< prank_27 6))))
(assert
 (let (($x4245 (>= prank_28 0)))
 (and $x4245 (< prank_28 6))))
(assert
 (let (($x4249 (>= prank_29 0)))
 (and $x4249 (< prank_29 6))))
(assert
 (let (($x4481 (>= prank_32 0)))
 (and $x4481 (< prank_32 6))))
(assert
 (let (($x4467 (>= prank_33 0)))
 (and $x4467 (< prank_33 6))))
(assert
 (let (($x4475 (>= prank_34 0)))
 (and $x4475 (< prank_34 6))))
(assert
 (let (($x4485 (>= prank_35 0)))
 (and $x4485 (< prank_35 6))))
(assert
 (let (($x4489 (>= prank_36 0)))
 (and $x4489 (< prank_36 6))))
(assert
 (let (($x4493 (>= prank_37 0)))
 (and $x4493 (< prank_37 6))))
(assert
 (let (($x4737 (>= rank_40 0)))
 (and $x4737 (< rank_40 6))))
(assert
 (let (($x4731 (>= rank_42 0)))
 (and $x4731 (< rank_42 6))))
(assert
 (let (($x4739 (>= rank_44 0)))
 (and $x4739 (< rank_44 6))))
(assert
 (let (($x4745 (>= rank_46 0)))
 (and $x4745 (< rank_46 6))))
(assert
 (let (($x4750 (>= rank_48 0)))
 (and $x4750 (< rank_48 6))))
(assert
 (let (($x4755 (>= rank_50 0)))
 (and $x4755 (< rank_50 6))))
(assert
 (let ((?x5006 (ite (or c_2_1 c_2_3 c_2_7 c_2_9 c_2_13 c_2_15) 1 0)))
 (let ((?x5001 (ite (or c_4_1 c_4_2 c_4_7 c_4_8 c_4_13 c_4_14) 1 0)))
 (let ((?x3650 (ite false 1 0)))
 (let ((?x3796 (+ 0 ?x3650)))
 (let ((?x3838 (+ ?x3796 ?x3650)))
 (let ((?x5008 (+ ?x3838 ?x5001)))
 (let (($x3941 (or c_5_14 c_5_15 c_5_16 c_5_17)))
 (let ((?x4988 (ite (or c_1_1 c_1_3 c_1_7 c_1_9 c_1_13 c_1_15) 1 0)))
 (let ((?x4983 (ite (or c_3_1 c_3_2 c_3_7 c_3_8 c_3_13 c_3_14) 1 0)))
 (let ((?x4977 (ite (or c_5_1 c_5_4 c_5_7 c_5_10 c_5_13 c_5_16) 1 0)))
 (let ((?x4985 (+ 0 ?x4977)))
 (let ((?x4984 (+ ?x4985 ?x3650)))
 (let ((?x4986 (+ ?x4984 ?x4983)))
 (let (($x3903 (or c_4_14 c_4_15 c_4_16 c_4_17)))
 (let (($x4992 (and $x3903 (> (to_real (+ ?x4986 ?x4988)) 0.0))))
 (let ((?x4959 (ite (or c_0_1 c_0_3 c_0_7 c_0_9 c_0_13 c_0_15) 1 0)))
 (let ((?x4955 (ite (or c_4_1 c_4_4 c_4_7 c_4_10 c_4_13 c_4_16) 1 0)))
 (let ((?x4958 (+ 0 ?x4955)))
 (let ((?x4957 (+ ?x4958 ?x3650)))
 (let ((?x4960 (+ ?x4957 ?x3650)))
 (let (($x3894 (or c_3_14 c_3_15 c_3_16 c_3_17)))
 (let (($x4965 (and $x3894 (> (to_real (+ ?x4960 ?x4959)) 0.0))))
 (let ((?x4932 (ite (or c_1_1 c_1_2 c_1_7 c_1_8 c_1_13 c_1_14) 1 0)))
 (let ((?x4935 (ite (or c_5_1 c_5_5 c_5_7 c_5_11 c_5_13 c_5_17) 1 0)))
 (let ((?x4938 (+ ?x3796 ?x4935)))
 (let ((?x4937 (+ ?x4938 ?x4932)))
 (let (($x3920 (or c_2_14 c_2_15 c_2_16 c_2_17)))
 (let (($x4943 (and $x3920 (> (to_real (+ ?x4937 ?x3650)) 0.0))))
 (let ((?x4917 (ite (or c_0_1 c_0_2 c_0_7 c_0_8 c_0_13 c_0_14) 1 0)))
 (let ((?x4915 (ite (or c_4_1 c_4_5 c_4_7 c_4_11 c_4_13 c_4_17) 1 0)))
 (let ((?x4913 (ite (or c_2_1 c_2_4 c_2_7 c_2_10 c_2_13 c_2_16) 1 0)))
 (let ((?x4916 (+ 0 ?x4913)))
 (let ((?x4910 (+ ?x4916 ?x4915)))
 (let ((?x4919 (+ ?x4910 ?x4917)))
 (let (($x3885 (or c_1_14 c_1_15 c_1_16 c_1_17)))
 (let (($x4923 (and $x3885 (> (to_real (+ ?x4919 ?x3650)) 0.0))))
 (let ((?x4890 (ite (or c_3_1 c_3_5 c_3_7 c_3_11 c_3_13 c_3_17) 1 0)))
 (let ((?x4883 (ite (or c_1_1 c_1_4 c_1_7 c_1_10 c_1_13 c_1_16) 1 0)))
 (let ((?x4891 (+ 0 ?x4883)))
 (let ((?x4888 (+ ?x4891 ?x4890)))
 (let ((?x4889 (+ ?x4888 ?x3650)))
 (let (($x3876 (or c_0_14 c_0_15 c_0_16 c_0_17)))
 (let (($x4896 (and $x3876 (> (to_real (+ ?x4889 ?x3650)) 0.0))))
 (let (($x4897 (or false $x4896)))
 (let (($x4924 (or $x4897 $x4923)))
 (let (($x4944 (or $x4924 $x4943)))
 (let (($x4966 (or $x4944 $x4965)))
 (let (($x4993 (or $x4966 $x4992)))
 (let (($x4865 (or false c_0_13)))
 (let (($x4867 (or $x4865 c_1_13)))
 (let (($x4869 (or $x4867 c_2_13)))
 (let (($x4871 (or $x4869 c_3_13)))
 (let (($x4873 (or $x4871 c_4_13)))
 (let ((?x4846 (ite root_51 1 0)))
 (let ((?x4827 (ite root_49 1 0)))
 (let ((?x4811 (ite root_47 1 0)))
 (let ((?x4795 (ite root_45 1 0)))
 (let ((?x4776 (ite root_43 1 0)))
 (let ((?x4760 (ite root_41 1 0)))
 (let ((?x4761 (+ 0 ?x4760)))
 (let ((?x4777 (+ ?x4761 ?x4776)))
 (let ((?x4796 (+ ?x4777 ?x4795)))
 (let ((?x4812 (+ ?x4796 ?x4811)))
 (let ((?x4828 (+ ?x4812 ?x4827)))
 (let (($x4759 (or false root_41)))
 (let (($x4775 (or $x4759 root_43)))
 (let (($x4794 (or $x4775 root_45)))
 (let (($x4810 (or $x4794 root_47)))
 (let (($x4826 (or $x4810 root_49)))
 (let (($x4743 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_13 c_5_14 c_5_15 c_5_16 c_5_17 c_5_18)))
 (let (($x4730 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_13 c_4_14 c_4_15 c_4_16 c_4_17 c_4_18)))
 (let (($x4717 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_13 c_3_14 c_3_15 c_3_16 c_3_17 c_3_18)))
 (let (($x4704 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_13 c_2_14 c_2_15 c_2_16 c_2_17 c_2_18)))
 (let (($x4691 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_13 c_1_14 c_1_15 c_1_16 c_1_17 c_1_18)))
 (let (($x4678 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_13 c_0_14 c_0_15 c_0_16 c_0_17 c_0_18)))
 (let (($x4758 (or false $x4678)))
 (let (($x4774 (or $x4758 $x4691)))
 (let (($x4793 (or $x4774 $x4704)))
 (let (($x4809 (or $x4793 $x4717)))
 (let (($x4825 (or $x4809 $x4730)))
 (let (($x4852 (or false (and $x4730 (< rank_48 rank_50)))))
 (let (($x4856 (not root_51)))
 (let (($x4857 (and $x4743 $x4856)))
 (let (($x4833 (or false (and $x4743 (< rank_50 rank_48)))))
 (let (($x4836 (or $x4833 (and $x4717 (< rank_46 rank_48)))))
 (let (($x4840 (not root_49)))
 (let (($x4841 (and $x4730 $x4840)))
 (let (($x4817 (or false (and $x4730 (< rank_48 rank_46)))))
 (let (($x4821 (not root_47)))
 (let (($x4822 (and $x4717 $x4821)))
 (let (($x4801 (or false (and $x4743 (< rank_50 rank_44)))))
 (let (($x4805 (not root_45)))
 (let (($x4806 (and $x4704 $x4805)))
 (let (($x4782 (or false (and $x4704 (< rank_44 rank_42)))))
 (let (($x4785 (or $x4782 (and $x4730 (< rank_48 rank_42)))))
 (let (($x4789 (not root_43)))
 (let (($x4790 (and $x4691 $x4789)))
 (let (($x4766 (or false (and $x4691 (< rank_42 rank_40)))))
 (let (($x4770 (not root_41)))
 (let (($x4771 (and $x4678 $x4770)))
 (let (($x4763 (and true (=> root_41 $x4678))))
 (let (($x4773 (and $x4763 (=> $x4771 (or $x4766 (and $x4717 (< rank_46 rank_40)))))))
 (let (($x4779 (and $x4773 (=> root_43 $x4691))))
 (let (($x4792 (and $x4779 (=> $x4790 (or $x4785 (and $x4678 (< rank_40 rank_42)))))))
 (let (($x4798 (and $x4792 (=> root_45 $x4704))))
 (let (($x4808 (and $x4798 (=> $x4806 (or $x4801 (and $x4691 (< rank_42 rank_44)))))))
 (let (($x4814 (and $x4808 (=> root_47 $x4717))))
 (let (($x4824 (and $x4814 (=> $x4822 (or $x4817 (and $x4678 (< rank_40 rank_46)))))))
 (let (($x4830 (and $x4824 (=> root_49 $x4730))))
 (let (($x4843 (and $x4830 (=> $x4841 (or $x4836 (and $x4691 (< rank_42 rank_48)))))))
 (let (($x4849 (and $x4843 (=> root_51 $x4743))))
 (let (($x4861 (and (and $x4849 (=> $x4857 (or $x4852 (and $x4704 (< rank_44 rank_50))))) (=> (or $x4825 $x4743) (or $x4826 root_51)))))
 (let (($x4863 (and $x4861 (<= (+ ?x4828 ?x4846) 1))))
 (let (($x3445 (or c_5_1 c_5_7 c_5_13)))
 (let (($x4644 (and $x3445 (= prank_37 prank_high_39))))
 (let (($x3419 (or c_4_1 c_4_7 c_4_13)))
 (let (($x4621 (and $x3419 (= prank_36 prank_high_39))))
 (let (($x3446 (or c_3_1 c_3_7 c_3_13)))
 (let (($x4593 (and $x3446 (= prank_35 prank_high_39))))
 (let (($x3406 (or c_2_1 c_2_7 c_2_13)))
 (let (($x4570 (and $x3406 (= prank_34 prank_high_39))))
 (let (($x3386 (or c_1_1 c_1_7 c_1_13)))
 (let (($x4547 (and $x3386 (= prank_33 prank_high_39))))
 (let (($x3478 (or c_0_1 c_0_7 c_0_13)))
 (let (($x4519 (and $x3478 (= prank_32 prank_high_39))))
 (let (($x4520 (or false $x4519)))
 (let (($x4548 (or $x4520 $x4547)))
 (let (($x4571 (or $x4548 $x4570)))
 (let (($x4594 (or $x4571 $x4593)))
 (let (($x4622 (or $x4594 $x4621)))
 (let (($x4641 (and $x3445 (= prank_37 prank_low_38))))
 (let (($x4618 (and $x3419 (= prank_36 prank_low_38))))
 (let (($x4590 (and $x3446 (= prank_35 prank_low_38))))
 (let (($x4567 (and $x3406 (= prank_34 prank_low_38))))
 (let (($x4544 (and $x3386 (= prank_33 prank_low_38))))
 (let (($x4516 (and $x3478 (= prank_32 prank_low_38))))
 (let (($x4517 (or false $x4516)))
 (let (($x4545 (or $x4517 $x4544)))
 (let (($x4568 (or $x4545 $x4567)))
 (let (($x4591 (or $x4568 $x4590)))
 (let (($x4619 (or $x4591 $x4618)))
 (let (($x4647 (=> (or (or (or (or (or (or false $x3478) $x3386) $x3406) $x3446) $x3419) $x3445) (and (or $x4619 $x4641) (or $x4622 $x4644)))))
 (let (($x4451 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_14 c_2_15 c_2_16 c_2_17 c_2_18)))
 (let (($x4473 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_14 c_4_15 c_4_16 c_4_17 c_4_18)))
 (let (($x4627 (or false (and true (or $x4473 (and $x3419 (< prank_36 prank_37)))))))
 (let (($x4634 (and (or $x4627 (and true (or $x4451 (and $x3406 (< prank_34 prank_37))))) (<= prank_low_38 prank_37))))
 (let (($x4440 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_14 c_1_15 c_1_16 c_1_17 c_1_18)))
 (let (($x4462 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_14 c_3_15 c_3_16 c_3_17 c_3_18)))
 (let (($x4484 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_14 c_5_15 c_5_16 c_5_17 c_5_18)))
 (let (($x4599 (or false (and true (or $x4484 (and $x3445 (< prank_37 prank_36)))))))
 (let (($x4604 (or $x4599 (and true (or $x4462 (and $x3446 (< prank_35 prank_36)))))))
 (let (($x4611 (and (or $x4604 (and true (or $x4440 (and $x3386 (< prank_33 prank_36))))) (<= prank_low_38 prank_36))))
 (let (($x4429 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_14 c_0_15 c_0_16 c_0_17 c_0_18)))
 (let (($x4576 (or false (and true (or $x4473 (and $x3419 (< prank_36 prank_35)))))))
 (let (($x4583 (and (or $x4576 (and true (or $x4429 (and $x3478 (< prank_32 prank_35))))) (<= prank_low_38 prank_35))))
 (let (($x4553 (or false (and true (or $x4484 (and $x3445 (< prank_37 prank_34)))))))
 (let (($x4560 (and (or $x4553 (and true (or $x4440 (and $x3386 (< prank_33 prank_34))))) (<= prank_low_38 prank_34))))
 (let (($x4525 (or false (and true (or $x4451 (and $x3406 (< prank_34 prank_33)))))))
 (let (($x4530 (or $x4525 (and true (or $x4473 (and $x3419 (< prank_36 prank_33)))))))
 (let (($x4537 (and (or $x4530 (and true (or $x4429 (and $x3478 (< prank_32 prank_33))))) (<= prank_low_38 prank_33))))
 (let (($x4502 (or false (and true (or $x4440 (and $x3386 (< prank_33 prank_32)))))))
 (let (($x4509 (and (or $x4502 (and true (or $x4462 (and $x3446 (< prank_35 prank_32))))) (<= prank_low_38 prank_32))))
 (let (($x4513 (and true (=> $x3478 (and $x4509 (<= prank_32 prank_high_39))))))
 (let (($x4541 (and $x4513 (=> $x3386 (and $x4537 (<= prank_33 prank_high_39))))))
 (let (($x4564 (and $x4541 (=> $x3406 (and $x4560 (<= prank_34 prank_high_39))))))
 (let (($x4587 (and $x4564 (=> $x3446 (and $x4583 (<= prank_35 prank_high_39))))))
 (let (($x4615 (and $x4587 (=> $x3419 (and $x4611 (<= prank_36 prank_high_39))))))
 (let (($x4638 (and $x4615 (=> $x3445 (and $x4634 (<= prank_37 prank_high_39))))))
 (let (($x4648 (and $x4638 $x4647)))
 (let (($x3503 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_8 c_5_9 c_5_10 c_5_11 c_5_14 c_5_15 c_5_16 c_5_17)))
 (let (($x4400 (and $x3503 (= prank_29 prank_high_31))))
 (let (($x3447 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_8 c_4_9 c_4_10 c_4_11 c_4_14 c_4_15 c_4_16 c_4_17)))
 (let (($x4377 (and $x3447 (= prank_28 prank_high_31))))
 (let (($x3428 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_8 c_3_9 c_3_10 c_3_11 c_3_14 c_3_15 c_3_16 c_3_17)))
 (let (($x4349 (and $x3428 (= prank_27 prank_high_31))))
 (let (($x3475 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_8 c_2_9 c_2_10 c_2_11 c_2_14 c_2_15 c_2_16 c_2_17)))
 (let (($x4326 (and $x3475 (= prank_26 prank_high_31))))
 (let (($x3409 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_8 c_1_9 c_1_10 c_1_11 c_1_14 c_1_15 c_1_16 c_1_17)))
 (let (($x4303 (and $x3409 (= prank_25 prank_high_31))))
 (let (($x3390 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_8 c_0_9 c_0_10 c_0_11 c_0_14 c_0_15 c_0_16 c_0_17)))
 (let (($x4275 (and $x3390 (= prank_24 prank_high_31))))
 (let (($x4276 (or false $x4275)))
 (let (($x4304 (or $x4276 $x4303)))
 (let (($x4327 (or $x4304 $x4326)))
 (let (($x4350 (or $x4327 $x4349)))
 (let (($x4378 (or $x4350 $x4377)))
 (let (($x4397 (and $x3503 (= prank_29 prank_low_30))))
 (let (($x4374 (and $x3447 (= prank_28 prank_low_30))))
 (let (($x4346 (and $x3428 (= prank_27 prank_low_30))))
 (let (($x4323 (and $x3475 (= prank_26 prank_low_30))))
 (let (($x4300 (and $x3409 (= prank_25 prank_low_30))))
 (let (($x4272 (and $x3390 (= prank_24 prank_low_30))))
 (let (($x4273 (or false $x4272)))
 (let (($x4301 (or $x4273 $x4300)))
 (let (($x4324 (or $x4301 $x4323)))
 (let (($x4347 (or $x4324 $x4346)))
 (let (($x4375 (or $x4347 $x4374)))
 (let (($x4403 (=> (or (or (or (or (or (or false $x3390) $x3409) $x3475) $x3428) $x3447) $x3503) (and (or $x4375 $x4397) (or $x4378 $x4400)))))
 (let (($x3133 (or c_2_6 c_2_12 c_2_18)))
 (let (($x3806 (or c_5_5 c_5_11 c_5_17)))
 (let (($x3114 (or c_4_6 c_4_12 c_4_18)))
 (let (($x3763 (or c_5_4 c_5_10 c_5_16)))
 (let (($x4383 (or false (and $x3763 (or $x3114 (and $x3447 (< prank_28 prank_29)))))))
 (let (($x4390 (and (or $x4383 (and $x3806 (or $x3133 (and $x3475 (< prank_26 prank_29))))) (<= prank_low_30 prank_29))))
 (let (($x3094 (or c_1_6 c_1_12 c_1_18)))
 (let (($x3698 (or c_4_5 c_4_11 c_4_17)))
 (let (($x3104 (or c_3_6 c_3_12 c_3_18)))
 (let (($x3730 (or c_4_4 c_4_10 c_4_16)))
 (let (($x3152 (or c_5_6 c_5_12 c_5_18)))
 (let (($x3846 (or c_4_2 c_4_8 c_4_14)))
 (let (($x4355 (or false (and $x3846 (or $x3152 (and $x3503 (< prank_29 prank_28)))))))
 (let (($x4360 (or $x4355 (and $x3730 (or $x3104 (and $x3428 (< prank_27 prank_28)))))))
 (let (($x4367 (and (or $x4360 (and $x3698 (or $x3094 (and $x3409 (< prank_25 prank_28))))) (<= prank_low_30 prank_28))))
 (let (($x3086 (or c_0_6 c_0_12 c_0_18)))
 (let (($x3663 (or c_3_5 c_3_11 c_3_17)))
 (let (($x3765 (or c_3_2 c_3_8 c_3_14)))
 (let (($x4332 (or false (and $x3765 (or $x3114 (and $x3447 (< prank_28 prank_27)))))))
 (let (($x4339 (and (or $x4332 (and $x3663 (or $x3086 (and $x3390 (< prank_24 prank_27))))) (<= prank_low_30 prank_27))))
 (let (($x3695 (or c_2_4 c_2_10 c_2_16)))
 (let (($x3849 (or c_2_3 c_2_9 c_2_15)))
 (let (($x4309 (or false (and $x3849 (or $x3152 (and $x3503 (< prank_29 prank_26)))))))
 (let (($x4316 (and (or $x4309 (and $x3695 (or $x3094 (and $x3409 (< prank_25 prank_26))))) (<= prank_low_30 prank_26))))
 (let (($x3660 (or c_1_4 c_1_10 c_1_16)))
 (let (($x3768 (or c_1_3 c_1_9 c_1_15)))
 (let (($x3808 (or c_1_2 c_1_8 c_1_14)))
 (let (($x4281 (or false (and $x3808 (or $x3133 (and $x3475 (< prank_26 prank_25)))))))
 (let (($x4286 (or $x4281 (and $x3768 (or $x3114 (and $x3447 (< prank_28 prank_25)))))))
 (let (($x4293 (and (or $x4286 (and $x3660 (or $x3086 (and $x3390 (< prank_24 prank_25))))) (<= prank_low_30 prank_25))))
 (let (($x3733 (or c_0_3 c_0_9 c_0_15)))
 (let (($x3700 (or c_0_2 c_0_8 c_0_14)))
 (let (($x4258 (or false (and $x3700 (or $x3094 (and $x3409 (< prank_25 prank_24)))))))
 (let (($x4265 (and (or $x4258 (and $x3733 (or $x3104 (and $x3428 (< prank_27 prank_24))))) (<= prank_low_30 prank_24))))
 (let (($x4269 (and true (=> $x3390 (and $x4265 (<= prank_24 prank_high_31))))))
 (let (($x4297 (and $x4269 (=> $x3409 (and $x4293 (<= prank_25 prank_high_31))))))
 (let (($x4320 (and $x4297 (=> $x3475 (and $x4316 (<= prank_26 prank_high_31))))))
 (let (($x4343 (and $x4320 (=> $x3428 (and $x4339 (<= prank_27 prank_high_31))))))
 (let (($x4371 (and $x4343 (=> $x3447 (and $x4367 (<= prank_28 prank_high_31))))))
 (let (($x4394 (and $x4371 (=> $x3503 (and $x4390 (<= prank_29 prank_high_31))))))
 (let (($x4404 (and $x4394 $x4403)))
 (let (($x2364 (not in_target_5)))
 (let (($x4198 (and c_5_18 $x2364)))
 (let (($x4196 (and c_5_12 $x2364)))
 (let (($x4195 (and c_5_6 $x2364)))
 (let (($x2349 (not in_target_4)))
 (let (($x4188 (and c_4_18 $x2349)))
 (let (($x4186 (and c_4_12 $x2349)))
 (let (($x4185 (and c_4_6 $x2349)))
 (let (($x4189 (or $x4185 $x4186 $x4188)))
 (let (($x2334 (not in_target_3)))
 (let (($x4178 (and c_3_18 $x2334)))
 (let (($x4176 (and c_3_12 $x2334)))
 (let (($x4175 (and c_3_6 $x2334)))
 (let (($x4179 (or $x4175 $x4176 $x4178)))
 (let (($x2319 (not in_target_2)))
 (let (($x4168 (and c_2_18 $x2319)))
 (let (($x4166 (and c_2_12 $x2319)))
 (let (($x4165 (and c_2_6 $x2319)))
 (let (($x4169 (or $x4165 $x4166 $x4168)))
 (let (($x2304 (not in_target_1)))
 (let (($x4158 (and c_1_18 $x2304)))
 (let (($x4156 (and c_1_12 $x2304)))
 (let (($x4155 (and c_1_6 $x2304)))
 (let (($x4159 (or $x4155 $x4156 $x4158)))
 (let (($x2291 (not in_target_0)))
 (let (($x4148 (and c_0_18 $x2291)))
 (let (($x4146 (and c_0_12 $x2291)))
 (let (($x4145 (and c_0_6 $x2291)))
 (let (($x4149 (or $x4145 $x4146 $x4148)))
 (let (($x4143 (or false $x4149)))
 (let (($x4153 (or $x4143 $x4159)))
 (let (($x4163 (or $x4153 $x4169)))
 (let (($x4173 (or $x4163 $x4179)))
 (let (($x4183 (or $x4173 $x4189)))
 (let ((?x4120 (ite root_23 1 0)))
 (let ((?x4102 (ite root_21 1 0)))
 (let ((?x4087 (ite root_19 1 0)))
 (let ((?x4072 (ite root_17 1 0)))
 (let ((?x4054 (ite root_15 1 0)))
 (let ((?x4039 (ite root_13 1 0)))
 (let ((?x4040 (+ 0 ?x4039)))
 (let ((?x4055 (+ ?x4040 ?x4054)))
 (let ((?x4073 (+ ?x4055 ?x4072)))
 (let ((?x4088 (+ ?x4073 ?x4087)))
 (let ((?x4103 (+ ?x4088 ?x4102)))
 (let (($x4038 (or false root_13)))
 (let (($x4053 (or $x4038 root_15)))
 (let (($x4071 (or $x4053 root_17)))
 (let (($x4086 (or $x4071 root_19)))
 (let (($x4101 (or $x4086 root_21)))
 (let (($x3994 (or false $x3086)))
 (let (($x3999 (or $x3994 $x3094)))
 (let (($x4001 (or $x3999 $x3133)))
 (let (($x4003 (or $x4001 $x3104)))
 (let (($x4005 (or $x4003 $x3114)))
 (let (($x4007 (or $x4005 $x3152)))
 (let (($x4126 (or false (and $x3114 (< rank_20 rank_22)))))
 (let (($x4130 (not root_23)))
 (let (($x4131 (and $x3152 $x4130)))
 (let (($x4108 (or false (and $x3152 (< rank_22 rank_20)))))
 (let (($x4111 (or $x4108 (and $x3104 (< rank_18 rank_20)))))
 (let (($x4115 (not root_21)))
 (let (($x4116 (and $x3114 $x4115)))
 (let (($x4093 (or false (and $x3114 (< rank_20 rank_18)))))
 (let (($x4097 (not root_19)))
 (let (($x4098 (and $x3104 $x4097)))
 (let (($x4078 (or false (and $x3152 (< rank_22 rank_16)))))
 (let (($x4082 (not root_17)))
 (let (($x4083 (and $x3133 $x4082)))
 (let (($x4060 (or false (and $x3133 (< rank_16 rank_14)))))
 (let (($x4063 (or $x4060 (and $x3114 (< rank_20 rank_14)))))
 (let (($x4067 (not root_15)))
 (let (($x4068 (and $x3094 $x4067)))
 (let (($x4045 (or false (and $x3094 (< rank_14 rank_12)))))
 (let (($x4049 (not root_13)))
 (let (($x4050 (and $x3086 $x4049)))
 (let (($x4042 (and true (=> root_13 $x3086))))
 (let (($x4052 (and $x4042 (=> $x4050 (or $x4045 (and $x3104 (< rank_18 rank_12)))))))
 (let (($x4057 (and $x4052 (=> root_15 $x3094))))
 (let (($x4070 (and $x4057 (=> $x4068 (or $x4063 (and $x3086 (< rank_12 rank_14)))))))
 (let (($x4075 (and $x4070 (=> root_17 $x3133))))
 (let (($x4085 (and $x4075 (=> $x4083 (or $x4078 (and $x3094 (< rank_14 rank_16)))))))
 (let (($x4090 (and $x4085 (=> root_19 $x3104))))
 (let (($x4100 (and $x4090 (=> $x4098 (or $x4093 (and $x3086 (< rank_12 rank_18)))))))
 (let (($x4105 (and $x4100 (=> root_21 $x3114))))
 (let (($x4118 (and $x4105 (=> $x4116 (or $x4111 (and $x3094 (< rank_14 rank_20)))))))
 (let (($x4123 (and $x4118 (=> root_23 $x3152))))
 (let (($x4135 (and (and $x4123 (=> $x4131 (or $x4126 (and $x3133 (< rank_16 rank_22))))) (=> $x4007 (or $x4101 root_23)))))
 (let (($x4137 (and $x4135 (<= (+ ?x4103 ?x4120) 1))))
 (let (($x4405 (and (and (and $x4007 $x4137) (not (or $x4183 (or $x4195 $x4196 $x4198)))) $x4404)))
 (let (($x5013 (and (and (and (and $x4405 $x4648) $x4863) (not (or $x4873 c_5_13))) (not (or $x4993 (and $x3941 (> (to_real (+ ?x5008 ?x5006)) 0.0)))))))
 (let (($x3685 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6)))
 (let (($x3629 (or c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x3624 (and true $x3629)))
 (let (($x3649 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6)))
 (let (($x3594 (or c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x3589 (and true $x3594)))
 (let (($x3827 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6)))
 (let (($x3584 (or c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x3579 (and true $x3584)))
 (let (($x3610 (or c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x3605 (and true $x3610)))
 (let (($x3574 (or c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x3569 (and true $x3574)))
 (let (($x3789 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6)))
 (let (($x3564 (or c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x3559 (and true $x3564)))
 (let (($x3853 (= (to_real (+ (+ ?x3838 (ite $x3846 1 0)) (ite $x3849 1 0))) 0.0)))
 (let (($x3842 (= (to_real (+ (+ ?x3838 (ite $x3419 1 0)) (ite $x3406 1 0))) 0.0)))
 (let (($x3854 (and $x3842 $x3853)))
 (let (($x3938 (and true $x3941)))
 (let (($x3951 (and $x3938 $x3685)))
 (let ((?x3772 (ite $x3768 1 0)))
 (let ((?x3770 (ite $x3765 1 0)))
 (let ((?x3766 (ite $x3763 1 0)))
 (let ((?x3767 (+ 0 ?x3766)))
 (let ((?x3769 (+ ?x3767 ?x3650)))
 (let ((?x3771 (+ ?x3769 ?x3770)))
 (let ((?x3646 (ite $x3386 1 0)))
 (let ((?x3648 (ite $x3446 1 0)))
 (let ((?x3751 (ite $x3445 1 0)))
 (let ((?x3752 (+ 0 ?x3751)))
 (let ((?x3754 (+ ?x3752 ?x3650)))
 (let ((?x3753 (+ ?x3754 ?x3648)))
 (let (($x3776 (and (= (to_real (+ ?x3753 ?x3646)) 0.0) (= (to_real (+ ?x3771 ?x3772)) 0.0))))
 (let (($x3900 (and true $x3903)))
 (let (($x3946 (and $x3900 $x3649)))
 (let ((?x3736 (ite $x3733 1 0)))
 (let ((?x3731 (ite $x3730 1 0)))
 (let ((?x3732 (+ 0 ?x3731)))
 (let ((?x3734 (+ ?x3732 ?x3650)))
 (let ((?x3735 (+ ?x3734 ?x3650)))
 (let ((?x3686 (ite $x3478 1 0)))
 (let ((?x3681 (ite $x3419 1 0)))
 (let ((?x3719 (+ 0 ?x3681)))
 (let ((?x3722 (+ ?x3719 ?x3650)))
 (let ((?x3720 (+ ?x3722 ?x3650)))
 (let (($x3740 (and (= (to_real (+ ?x3720 ?x3686)) 0.0) (= (to_real (+ ?x3735 ?x3736)) 0.0))))
 (let (($x3891 (and true $x3894)))
 (let (($x3943 (and $x3891 $x3827)))
 (let (($x3723 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6)))
 (let (($x3939 (and $x3938 $x3723)))
 (let ((?x3812 (to_real (+ (+ (+ ?x3796 (ite $x3806 1 0)) (ite $x3808 1 0)) ?x3650))))
 (let (($x3814 (and (= (to_real (+ (+ (+ ?x3796 ?x3751) ?x3646) ?x3650)) 0.0) (= ?x3812 0.0))))
 (let (($x3917 (and true $x3920)))
 (let (($x3924 (and $x3917 $x3649)))
 (let ((?x3703 (ite $x3700 1 0)))
 (let ((?x3701 (ite $x3698 1 0)))
 (let ((?x3697 (ite $x3695 1 0)))
 (let ((?x3699 (+ 0 ?x3697)))
 (let ((?x3702 (+ ?x3699 ?x3701)))
 (let ((?x3704 (+ ?x3702 ?x3703)))
 (let ((?x3689 (to_real (+ (+ (+ (+ 0 (ite $x3406 1 0)) ?x3681) ?x3686) ?x3650))))
 (let (($x3708 (and (= ?x3689 0.0) (= (to_real (+ ?x3704 ?x3650)) 0.0))))
 (let (($x3882 (and true $x3885)))
 (let (($x3922 (and $x3882 $x3827)))
 (let (($x3755 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6)))
 (let (($x3919 (and $x3917 $x3755)))
 (let ((?x3664 (ite $x3663 1 0)))
 (let ((?x3661 (ite $x3660 1 0)))
 (let ((?x3662 (+ 0 ?x3661)))
 (let ((?x3665 (+ ?x3662 ?x3664)))
 (let ((?x3666 (+ ?x3665 ?x3650)))
 (let (($x3670 (and (= (to_real (+ (+ (+ (+ 0 ?x3646) ?x3648) ?x3650) ?x3650)) 0.0) (= (to_real (+ ?x3666 ?x3650)) 0.0))))
 (let (($x3873 (and true $x3876)))
 (let (($x3905 (and $x3873 $x3789)))
 (let (($x3837 (or c_5_2 c_5_3 c_5_4 c_5_5)))
 (let (($x3834 (and true $x3837)))
 (let (($x3865 (and $x3834 $x3685)))
 (let (($x3746 (or c_4_2 c_4_3 c_4_4 c_4_5)))
 (let (($x3744 (and true $x3746)))
 (let (($x3859 (and $x3744 $x3649)))
 (let (($x3714 (or c_3_2 c_3_3 c_3_4 c_3_5)))
 (let (($x3712 (and true $x3714)))
 (let (($x3858 (and $x3712 $x3827)))
 (let (($x3795 (or c_2_2 c_2_3 c_2_4 c_2_5)))
 (let (($x3792 (and true $x3795)))
 (let (($x3823 (and $x3792 $x3649)))
 (let (($x3676 (or c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x3674 (and true $x3676)))
 (let (($x3822 (and $x3674 $x3827)))
 (let (($x3640 (or c_0_2 c_0_3 c_0_4 c_0_5)))
 (let (($x3637 (and true $x3640)))
 (let (($x3784 (and $x3637 $x3789)))
 (let (($x3299 (or (and c_2_1 $x2319) (and c_2_7 $x2319) (and c_2_13 $x2319))))
 (let (($x3150 (and true $x3152)))
 (let (($x3288 (or (and c_1_7 $x2304) (and c_1_1 $x2304) (and c_1_13 $x2304))))
 (let (($x3112 (and true $x3114)))
 (let (($x3349 (or (and c_0_1 $x2291) (and c_0_7 $x2291) (and c_0_13 $x2291))))
 (let (($x3102 (and true $x3104)))
 (let (($x3310 (or (and c_4_1 $x2349) (and c_4_7 $x2349) (and c_4_13 $x2349))))
 (let (($x3332 (or (and c_3_1 $x2334) (and c_3_7 $x2334) (and c_3_13 $x2334))))
 (let (($x3321 (or (and c_5_1 $x2364) (and c_5_7 $x2364) (and c_5_13 $x2364))))
 (let (($x3131 (and true $x3133)))
 (let (($x2555 (and c_2_17 in_target_2)))
 (let (($x2553 (and c_2_16 in_target_2)))
 (let (($x2551 (and c_2_15 in_target_2)))
 (let (($x2549 (and c_2_14 in_target_2)))
 (let (($x2544 (and c_2_11 in_target_2)))
 (let (($x2542 (and c_2_10 in_target_2)))
 (let (($x2540 (and c_2_9 in_target_2)))
 (let (($x2538 (and c_2_8 in_target_2)))
 (let (($x2533 (and c_2_5 in_target_2)))
 (let (($x2531 (and c_2_4 in_target_2)))
 (let (($x2529 (and c_2_3 in_target_2)))
 (let (($x2527 (and c_2_2 in_target_2)))
 (let (($x3201 (or $x2527 $x2529 $x2531 $x2533 $x2538 $x2540 $x2542 $x2544 $x2549 $x2551 $x2553 $x2555)))
 (let (($x2502 (and c_1_17 in_target_1)))
 (let (($x2500 (and c_1_16 in_target_1)))
 (let (($x2498 (and c_1_15 in_target_1)))
 (let (($x2496 (and c_1_14 in_target_1)))
 (let (($x2491 (and c_1_11 in_target_1)))
 (let (($x2489 (and c_1_10 in_target_1)))
 (let (($x2487 (and c_1_9 in_target_1)))
 (let (($x2485 (and c_1_8 in_target_1)))
 (let (($x2480 (and c_1_5 in_target_1)))
 (let (($x2478 (and c_1_4 in_target_1)))
 (let (($x2476 (and c_1_3 in_target_1)))
 (let (($x2474 (and c_1_2 in_target_1)))
 (let (($x3186 (or $x2474 $x2476 $x2478 $x2480 $x2485 $x2487 $x2489 $x2491 $x2496 $x2498 $x2500 $x2502)))
 (let (($x2449 (and c_0_17 in_target_0)))
 (let (($x2447 (and c_0_16 in_target_0)))
 (let (($x2445 (and c_0_15 in_target_0)))
 (let (($x2443 (and c_0_14 in_target_0)))
 (let (($x2438 (and c_0_11 in_target_0)))
 (let (($x2436 (and c_0_10 in_target_0)))
 (let (($x2434 (and c_0_9 in_target_0)))
 (let (($x2432 (and c_0_8 in_target_0)))
 (let (($x2427 (and c_0_5 in_target_0)))
 (let (($x2425 (and c_0_4 in_target_0)))
 (let (($x2423 (and c_0_3 in_target_0)))
 (let (($x2421 (and c_0_2 in_target_0)))
 (let (($x3267 (or $x2421 $x2423 $x2425 $x2427 $x2432 $x2434 $x2436 $x2438 $x2443 $x2445 $x2447 $x2449)))
 (let (($x2661 (and c_4_17 in_target_4)))
 (let (($x2659 (and c_4_16 in_target_4)))
 (let (($x2657 (and c_4_15 in_target_4)))
 (let (($x2655 (and c_4_14 in_target_4)))
 (let (($x2650 (and c_4_11 in_target_4)))
 (let (($x2648 (and c_4_10 in_target_4)))
 (let (($x2646 (and c_4_9 in_target_4)))
 (let (($x2644 (and c_4_8 in_target_4)))
 (let (($x2639 (and c_4_5 in_target_4)))
 (let (($x2637 (and c_4_4 in_target_4)))
 (let (($x2635 (and c_4_3 in_target_4)))
 (let (($x2633 (and c_4_2 in_target_4)))
 (let (($x3216 (or $x2633 $x2635 $x2637 $x2639 $x2644 $x2646 $x2648 $x2650 $x2655 $x2657 $x2659 $x2661)))
 (let (($x2608 (and c_3_17 in_target_3)))
 (let (($x2606 (and c_3_16 in_target_3)))
 (let (($x2604 (and c_3_15 in_target_3)))
 (let (($x2602 (and c_3_14 in_target_3)))
 (let (($x2597 (and c_3_11 in_target_3)))
 (let (($x2595 (and c_3_10 in_target_3)))
 (let (($x2593 (and c_3_9 in_target_3)))
 (let (($x2591 (and c_3_8 in_target_3)))
 (let (($x2586 (and c_3_5 in_target_3)))
 (let (($x2584 (and c_3_4 in_target_3)))
 (let (($x2582 (and c_3_3 in_target_3)))
 (let (($x2580 (and c_3_2 in_target_3)))
 (let (($x3246 (or $x2580 $x2582 $x2584 $x2586 $x2591 $x2593 $x2595 $x2597 $x2602 $x2604 $x2606 $x2608)))
 (let (($x2714 (and c_5_17 in_target_5)))
 (let (($x2712 (and c_5_16 in_target_5)))
 (let (($x2710 (and c_5_15 in_target_5)))
 (let (($x2708 (and c_5_14 in_target_5)))
 (let (($x2703 (and c_5_11 in_target_5)))
 (let (($x2701 (and c_5_10 in_target_5)))
 (let (($x2699 (and c_5_9 in_target_5)))
 (let (($x2697 (and c_5_8 in_target_5)))
 (let (($x2692 (and c_5_5 in_target_5)))
 (let (($x2690 (and c_5_4 in_target_5)))
 (let (($x2688 (and c_5_3 in_target_5)))
 (let (($x2686 (and c_5_2 in_target_5)))
 (let (($x3231 (or $x2686 $x2688 $x2690 $x2692 $x2697 $x2699 $x2701 $x2703 $x2708 $x2710 $x2712 $x2714)))
 (let (($x2547 (and c_2_13 in_target_2)))
 (let (($x2536 (and c_2_7 in_target_2)))
 (let (($x2525 (and c_2_1 in_target_2)))
 (let (($x3098 (or $x2525 $x2536 $x2547)))
 (let (($x2494 (and c_1_13 in_target_1)))
 (let (($x2483 (and c_1_7 in_target_1)))
 (let (($x2472 (and c_1_1 in_target_1)))
 (let (($x3087 (or $x2472 $x2483 $x2494)))
 (let (($x2441 (and c_0_13 in_target_0)))
 (let (($x2430 (and c_0_7 in_target_0)))
 (let (($x2419 (and c_0_1 in_target_0)))
 (let (($x3140 (or $x2419 $x2430 $x2441)))
 (let (($x2653 (and c_4_13 in_target_4)))
 (let (($x2642 (and c_4_7 in_target_4)))
 (let (($x2631 (and c_4_1 in_target_4)))
 (let (($x3108 (or $x2631 $x2642 $x2653)))
 (let (($x2600 (and c_3_13 in_target_3)))
 (let (($x2589 (and c_3_7 in_target_3)))
 (let (($x2578 (and c_3_1 in_target_3)))
 (let (($x3124 (or $x2578 $x2589 $x2600)))
 (let (($x2706 (and c_5_13 in_target_5)))
 (let (($x2695 (and c_5_7 in_target_5)))
 (let (($x2684 (and c_5_1 in_target_5)))
 (let (($x3118 (or $x2684 $x2695 $x2706)))
 (let (($x2716 (and c_5_18 in_target_5)))
 (let (($x2683 (and c_5_0 in_target_5)))
 (let (($x2380 (and c_5_12 in_target_5)))
 (let (($x2378 (and c_5_6 in_target_5)))
 (let (($x2717 (or $x2378 $x2380 $x2683 $x2684 $x2686 $x2688 $x2690 $x2692 $x2695 $x2697 $x2699 $x2701 $x2703 $x2706 $x2708 $x2710 $x2712 $x2714 $x2716)))
 (let ((?x2855 (ite $x2717 1 0)))
 (let (($x2663 (and c_4_18 in_target_4)))
 (let (($x2630 (and c_4_0 in_target_4)))
 (let (($x2365 (and c_4_12 in_target_4)))
 (let (($x2363 (and c_4_6 in_target_4)))
 (let (($x2664 (or $x2363 $x2365 $x2630 $x2631 $x2633 $x2635 $x2637 $x2639 $x2642 $x2644 $x2646 $x2648 $x2650 $x2653 $x2655 $x2657 $x2659 $x2661 $x2663)))
 (let ((?x2859 (ite $x2664 1 0)))
 (let (($x2610 (and c_3_18 in_target_3)))
 (let (($x2577 (and c_3_0 in_target_3)))
 (let (($x2350 (and c_3_12 in_target_3)))
 (let (($x2348 (and c_3_6 in_target_3)))
 (let (($x2611 (or $x2348 $x2350 $x2577 $x2578 $x2580 $x2582 $x2584 $x2586 $x2589 $x2591 $x2593 $x2595 $x2597 $x2600 $x2602 $x2604 $x2606 $x2608 $x2610)))
 (let ((?x2840 (ite $x2611 1 0)))
 (let (($x2557 (and c_2_18 in_target_2)))
 (let (($x2524 (and c_2_0 in_target_2)))
 (let (($x2335 (and c_2_12 in_target_2)))
 (let (($x2333 (and c_2_6 in_target_2)))
 (let (($x2558 (or $x2333 $x2335 $x2524 $x2525 $x2527 $x2529 $x2531 $x2533 $x2536 $x2538 $x2540 $x2542 $x2544 $x2547 $x2549 $x2551 $x2553 $x2555 $x2557)))
 (let ((?x2847 (ite $x2558 1 0)))
 (let (($x2504 (and c_1_18 in_target_1)))
 (let (($x2471 (and c_1_0 in_target_1)))
 (let (($x2320 (and c_1_12 in_target_1)))
 (let (($x2318 (and c_1_6 in_target_1)))
 (let (($x2505 (or $x2318 $x2320 $x2471 $x2472 $x2474 $x2476 $x2478 $x2480 $x2483 $x2485 $x2487 $x2489 $x2491 $x2494 $x2496 $x2498 $x2500 $x2502 $x2504)))
 (let ((?x2850 (ite $x2505 1 0)))
 (let (($x2451 (and c_0_18 in_target_0)))
 (let (($x2418 (and c_0_0 in_target_0)))
 (let (($x2305 (and c_0_12 in_target_0)))
 (let (($x2303 (and c_0_6 in_target_0)))
 (let (($x2452 (or $x2303 $x2305 $x2418 $x2419 $x2421 $x2423 $x2425 $x2427 $x2430 $x2432 $x2434 $x2436 $x2438 $x2441 $x2443 $x2445 $x2447 $x2449 $x2451)))
 (let ((?x2838 (ite $x2452 1 0)))
 (let ((?x2839 (+ 0 ?x2838)))
 (let ((?x2844 (+ ?x2839 ?x2850)))
 (let ((?x2846 (+ ?x2844 ?x2847)))
 (let ((?x2851 (+ ?x2846 ?x2840)))
 (let ((?x2861 (+ ?x2851 ?x2859)))
 (let ((?x2856 (to_real (+ ?x2861 ?x2855))))
 (let ((?x3068 (ite c_5_18 1 0)))
 (let ((?x3066 (ite c_5_17 1 0)))
 (let ((?x3064 (ite c_5_16 1 0)))
 (let ((?x3062 (ite c_5_15 1 0)))
 (let ((?x3060 (ite c_5_14 1 0)))
 (let ((?x3058 (ite c_5_13 1 0)))
 (let ((?x3056 (ite c_5_12 3 0)))
 (let ((?x3054 (ite c_5_11 3 0)))
 (let ((?x3052 (ite c_5_10 3 0)))
 (let ((?x3050 (ite c_5_9 3 0)))
 (let ((?x3048 (ite c_5_8 3 0)))
 (let ((?x3046 (ite c_5_7 3 0)))
 (let ((?x3044 (ite c_5_6 2 0)))
 (let ((?x3042 (ite c_5_5 2 0)))
 (let ((?x3040 (ite c_5_4 2 0)))
 (let ((?x3038 (ite c_5_3 2 0)))
 (let ((?x3036 (ite c_5_2 2 0)))
 (let ((?x3034 (ite c_5_1 2 0)))
 (let ((?x3032 (ite c_4_18 1 0)))
 (let ((?x3030 (ite c_4_17 1 0)))
 (let ((?x3028 (ite c_4_16 1 0)))
 (let ((?x3026 (ite c_4_15 1 0)))
 (let ((?x3024 (ite c_4_14 1 0)))
 (let ((?x3022 (ite c_4_13 1 0)))
 (let ((?x3020 (ite c_4_12 3 0)))
 (let ((?x3018 (ite c_4_11 3 0)))
 (let ((?x3016 (ite c_4_10 3 0)))
 (let ((?x3014 (ite c_4_9 3 0)))
 (let ((?x3012 (ite c_4_8 3 0)))
 (let ((?x3010 (ite c_4_7 3 0)))
 (let ((?x3008 (ite c_4_6 2 0)))
 (let ((?x3006 (ite c_4_5 2 0)))
 (let ((?x3004 (ite c_4_4 2 0)))
 (let ((?x3002 (ite c_4_3 2 0)))
 (let ((?x3000 (ite c_4_2 2 0)))
 (let ((?x2998 (ite c_4_1 2 0)))
 (let ((?x2996 (ite c_3_18 1 0)))
 (let ((?x2994 (ite c_3_17 1 0)))
 (let ((?x2992 (ite c_3_16 1 0)))
 (let ((?x2990 (ite c_3_15 1 0)))
 (let ((?x2988 (ite c_3_14 1 0)))
 (let ((?x2986 (ite c_3_13 1 0)))
 (let ((?x2984 (ite c_3_12 3 0)))
 (let ((?x2982 (ite c_3_11 3 0)))
 (let ((?x2980 (ite c_3_10 3 0)))
 (let ((?x2978 (ite c_3_9 3 0)))
 (let ((?x2976 (ite c_3_8 3 0)))
 (let ((?x2974 (ite c_3_7 3 0)))
 (let ((?x2972 (ite c_3_6 2 0)))
 (let ((?x2970 (ite c_3_5 2 0)))
 (let ((?x2968 (ite c_3_4 2 0)))
 (let ((?x2966 (ite c_3_3 2 0)))
 (let ((?x2964 (ite c_3_2 2 0)))
 (let ((?x2962 (ite c_3_1 2 0)))
 (let ((?x2960 (ite c_2_18 1 0)))
 (let ((?x2958 (ite c_2_17 1 0)))
 (let ((?x2956 (ite c_2_16 1 0)))
 (let ((?x2954 (ite c_2_15 1 0)))
 (let ((?x2952 (ite c_2_14 1 0)))
 (let ((?x2950 (ite c_2_13 1 0)))
 (let ((?x2948 (ite c_2_12 3 0)))
 (let ((?x2946 (ite c_2_11 3 0)))
 (let ((?x2944 (ite c_2_10 3 0)))
 (let ((?x2942 (ite c_2_9 3 0)))
 (let ((?x2940 (ite c_2_8 3 0)))
 (let ((?x2938 (ite c_2_7 3 0)))
 (let ((?x2936 (ite c_2_6 2 0)))
 (let ((?x2934 (ite c_2_5 2 0)))
 (let ((?x2932 (ite c_2_4 2 0)))
 (let ((?x2930 (ite c_2_3 2 0)))
 (let ((?x2928 (ite c_2_2 2 0)))
 (let ((?x2926 (ite c_2_1 2 0)))
 (let ((?x2924 (ite c_1_18 1 0)))
 (let ((?x2922 (ite c_1_17 1 0)))
 (let ((?x2920 (ite c_1_16 1 0)))
 (let ((?x2918 (ite c_1_15 1 0)))
 (let ((?x2916 (ite c_1_14 1 0)))
 (let ((?x2914 (ite c_1_13 1 0)))
 (let ((?x2912 (ite c_1_12 3 0)))
 (let ((?x2910 (ite c_1_11 3 0)))
 (let ((?x2908 (ite c_1_10 3 0)))
 (let ((?x2906 (ite c_1_9 3 0)))
 (let ((?x2904 (ite c_1_8 3 0)))
 (let ((?x2902 (ite c_1_7 3 0)))
 (let ((?x2900 (ite c_1_6 2 0)))
 (let ((?x2898 (ite c_1_5 2 0)))
 (let ((?x2896 (ite c_1_4 2 0)))
 (let ((?x2894 (ite c_1_3 2 0)))
 (let ((?x2892 (ite c_1_2 2 0)))
 (let ((?x2890 (ite c_1_1 2 0)))
 (let ((?x2888 (ite c_0_18 1 0)))
 (let ((?x2886 (ite c_0_17 1 0)))
 (let ((?x2884 (ite c_0_16 1 0)))
 (let ((?x2882 (ite c_0_15 1 0)))
 (let ((?x2880 (ite c_0_14 1 0)))
 (let ((?x2878 (ite c_0_13 1 0)))
 (let ((?x2876 (ite c_0_12 3 0)))
 (let ((?x2874 (ite c_0_11 3 0)))
 (let ((?x2872 (ite c_0_10 3 0)))
 (let ((?x2870 (ite c_0_9 3 0)))
 (let ((?x2868 (ite c_0_8 3 0)))
 (let ((?x2865 (ite c_0_7 3 0)))
 (let ((?x2853 (ite c_0_6 2 0)))
 (let ((?x2841 (ite c_0_5 2 0)))
 (let ((?x2854 (ite c_0_4 2 0)))
 (let ((?x2858 (ite c_0_3 2 0)))
 (let ((?x2866 (ite c_0_2 2 0)))
 (let ((?x2843 (ite c_0_1 2 0)))
 (let ((?x2860 (+ 0 ?x2843)))
 (let ((?x2863 (+ ?x2860 ?x2866)))
 (let ((?x2842 (+ ?x2863 ?x2858)))
 (let ((?x2848 (+ ?x2842 ?x2854)))
 (let ((?x2857 (+ ?x2848 ?x2841)))
 (let ((?x2849 (+ ?x2857 ?x2853)))
 (let ((?x2867 (+ ?x2849 ?x2865)))
 (let ((?x2869 (+ ?x2867 ?x2868)))
 (let ((?x2871 (+ ?x2869 ?x2870)))
 (let ((?x2873 (+ ?x2871 ?x2872)))
 (let ((?x2875 (+ ?x2873 ?x2874)))
 (let ((?x2877 (+ ?x2875 ?x2876)))
 (let ((?x2879 (+ ?x2877 ?x2878)))
 (let ((?x2881 (+ ?x2879 ?x2880)))
 (let ((?x2883 (+ ?x2881 ?x2882)))
 (let ((?x2885 (+ ?x2883 ?x2884)))
 (let ((?x2887 (+ ?x2885 ?x2886)))
 (let ((?x2889 (+ ?x2887 ?x2888)))
 (let ((?x2891 (+ ?x2889 ?x2890)))
 (let ((?x2893 (+ ?x2891 ?x2892)))
 (let ((?x2895 (+ ?x2893 ?x2894)))
 (let ((?x2897 (+ ?x2895 ?x2896)))
 (let ((?x2899 (+ ?x2897 ?x2898)))
 (let ((?x2901 (+ ?x2899 ?x2900)))
 (let ((?x2903 (+ ?x2901 ?x2902)))
 (let ((?x2905 (+ ?x2903 ?x2904)))
 (let ((?x2907 (+ ?x2905 ?x2906)))
 (let ((?x2909 (+ ?x2907 ?x2908)))
 (let ((?x2911 (+ ?x2909 ?x2910)))
 (let ((?x2913 (+ ?x2911 ?x2912)))
 (let ((?x2915 (+ ?x2913 ?x2914)))
 (let ((?x2917 (+ ?x2915 ?x2916)))
 (let ((?x2919 (+ ?x2917 ?x2918)))
 (let ((?x2921 (+ ?x2919 ?x2920)))
 (let ((?x2923 (+ ?x2921 ?x2922)))
 (let ((?x2925 (+ ?x2923 ?x2924)))
 (let ((?x2927 (+ ?x2925 ?x2926)))
 (let ((?x2929 (+ ?x2927 ?x2928)))
 (let ((?x2931 (+ ?x2929 ?x2930)))
 (let ((?x2933 (+ ?x2931 ?x2932)))
 (let ((?x2935 (+ ?x2933 ?x2934)))
 (let ((?x2937 (+ ?x2935 ?x2936)))
 (let ((?x2939 (+ ?x2937 ?x2938)))
 (let ((?x2941 (+ ?x2939 ?x2940)))
 (let ((?x2943 (+ ?x2941 ?x2942)))
 (let ((?x2945 (+ ?x2943 ?x2944)))
 (let ((?x2947 (+ ?x2945 ?x2946)))
 (let ((?x2949 (+ ?x2947 ?x2948)))
 (let ((?x2951 (+ ?x2949 ?x2950)))
 (let ((?x2953 (+ ?x2951 ?x2952)))
 (let ((?x2955 (+ ?x2953 ?x2954)))
 (let ((?x2957 (+ ?x2955 ?x2956)))
 (let ((?x2959 (+ ?x2957 ?x2958)))
 (let ((?x2961 (+ ?x2959 ?x2960)))
 (let ((?x2963 (+ ?x2961 ?x2962)))
 (let ((?x2965 (+ ?x2963 ?x2964)))
 (let ((?x2967 (+ ?x2965 ?x2966)))
 (let ((?x2969 (+ ?x2967 ?x2968)))
 (let ((?x2971 (+ ?x2969 ?x2970)))
 (let ((?x2973 (+ ?x2971 ?x2972)))
 (let ((?x2975 (+ ?x2973 ?x2974)))
 (let ((?x2977 (+ ?x2975 ?x2976)))
 (let ((?x2979 (+ ?x2977 ?x2978)))
 (let ((?x2981 (+ ?x2979 ?x2980)))
 (let ((?x2983 (+ ?x2981 ?x2982)))
 (let ((?x2985 (+ ?x2983 ?x2984)))
 (let ((?x2987 (+ ?x2985 ?x2986)))
 (let ((?x2989 (+ ?x2987 ?x2988)))
 (let ((?x2991 (+ ?x2989 ?x2990)))
 (let ((?x2993 (+ ?x2991 ?x2992)))
 (let ((?x2995 (+ ?x2993 ?x2994)))
 (let ((?x2997 (+ ?x2995 ?x2996)))
 (let ((?x2999 (+ ?x2997 ?x2998)))
 (let ((?x3001 (+ ?x2999 ?x3000)))
 (let ((?x3003 (+ ?x3001 ?x3002)))
 (let ((?x3005 (+ ?x3003 ?x3004)))
 (let ((?x3007 (+ ?x3005 ?x3006)))
 (let ((?x3009 (+ ?x3007 ?x3008)))
 (let ((?x3011 (+ ?x3009 ?x3010)))
 (let ((?x3013 (+ ?x3011 ?x3012)))
 (let ((?x3015 (+ ?x3013 ?x3014)))
 (let ((?x3017 (+ ?x3015 ?x3016)))
 (let ((?x3019 (+ ?x3017 ?x3018)))
 (let ((?x3021 (+ ?x3019 ?x3020)))
 (let ((?x3023 (+ ?x3021 ?x3022)))
 (let ((?x3025 (+ ?x3023 ?x3024)))
 (let ((?x3027 (+ ?x3025 ?x3026)))
 (let ((?x3029 (+ ?x3027 ?x3028)))
 (let ((?x3031 (+ ?x3029 ?x3030)))
 (let ((?x3033 (+ ?x3031 ?x3032)))
 (let ((?x3035 (+ ?x3033 ?x3034)))
 (let ((?x3037 (+ ?x3035 ?x3036)))
 (let ((?x3039 (+ ?x3037 ?x3038)))
 (let ((?x3041 (+ ?x3039 ?x3040)))
 (let ((?x3043 (+ ?x3041 ?x3042)))
 (let ((?x3045 (+ ?x3043 ?x3044)))
 (let ((?x3047 (+ ?x3045 ?x3046)))
 (let ((?x3049 (+ ?x3047 ?x3048)))
 (let ((?x3051 (+ ?x3049 ?x3050)))
 (let ((?x3053 (+ ?x3051 ?x3052)))
 (let ((?x3055 (+ ?x3053 ?x3054)))
 (let ((?x3057 (+ ?x3055 ?x3056)))
 (let ((?x3059 (+ ?x3057 ?x3058)))
 (let ((?x3061 (+ ?x3059 ?x3060)))
 (let ((?x3063 (+ ?x3061 ?x3062)))
 (let ((?x3065 (+ ?x3063 ?x3064)))
 (let ((?x3067 (+ ?x3065 ?x3066)))
 (let ((?x3071 (/ (to_real (+ ?x3067 ?x3068)) 2.0)))
 (let ((?x2820 (ite root_11 1 0)))
 (let ((?x2801 (ite root_9 1 0)))
 (let ((?x2785 (ite root_7 1 0)))
 (let ((?x2769 (ite root_5 1 0)))
 (let ((?x2750 (ite root_3 1 0)))
 (let ((?x2734 (ite root_1 1 0)))
 (let ((?x2735 (+ 0 ?x2734)))
 (let ((?x2751 (+ ?x2735 ?x2750)))
 (let ((?x2770 (+ ?x2751 ?x2769)))
 (let ((?x2786 (+ ?x2770 ?x2785)))
 (let ((?x2802 (+ ?x2786 ?x2801)))
 (let (($x2732 (or false root_1)))
 (let (($x2749 (or $x2732 root_3)))
 (let (($x2768 (or $x2749 root_5)))
 (let (($x2784 (or $x2768 root_7)))
 (let (($x2800 (or $x2784 root_9)))
 (let (($x2834 (=> (or (or (or (or (or (or false $x2452) $x2505) $x2558) $x2611) $x2664) $x2717) (or $x2800 root_11))))
 (let (($x2826 (or false (and $x2664 (< rank_8 rank_10)))))
 (let (($x2830 (not root_11)))
 (let (($x2831 (and $x2717 $x2830)))
 (let (($x2807 (or false (and $x2717 (< rank_10 rank_8)))))
 (let (($x2810 (or $x2807 (and $x2611 (< rank_6 rank_8)))))
 (let (($x2814 (not root_9)))
 (let (($x2815 (and $x2664 $x2814)))
 (let (($x2791 (or false (and $x2664 (< rank_8 rank_6)))))
 (let (($x2795 (not root_7)))
 (let (($x2796 (and $x2611 $x2795)))
 (let (($x2775 (or false (and $x2717 (< rank_10 rank_4)))))
 (let (($x2779 (not root_5)))
 (let (($x2780 (and $x2558 $x2779)))
 (let (($x2756 (or false (and $x2558 (< rank_4 rank_2)))))
 (let (($x2759 (or $x2756 (and $x2664 (< rank_8 rank_2)))))
 (let (($x2763 (not root_3)))
 (let (($x2764 (and $x2505 $x2763)))
 (let (($x2740 (or false (and $x2505 (< rank_2 rank_0)))))
 (let (($x2744 (not root_1)))
 (let (($x2745 (and $x2452 $x2744)))
 (let (($x2737 (and true (=> root_1 $x2452))))
 (let (($x2747 (and $x2737 (=> $x2745 (or $x2740 (and $x2611 (< rank_6 rank_0)))))))
 (let (($x2753 (and $x2747 (=> root_3 $x2505))))
 (let (($x2766 (and $x2753 (=> $x2764 (or $x2759 (and $x2452 (< rank_0 rank_2)))))))
 (let (($x2772 (and $x2766 (=> root_5 $x2558))))
 (let (($x2782 (and $x2772 (=> $x2780 (or $x2775 (and $x2505 (< rank_2 rank_4)))))))
 (let (($x2788 (and $x2782 (=> root_7 $x2611))))
 (let (($x2798 (and $x2788 (=> $x2796 (or $x2791 (and $x2452 (< rank_0 rank_6)))))))
 (let (($x2804 (and $x2798 (=> root_9 $x2664))))
 (let (($x2817 (and $x2804 (=> $x2815 (or $x2810 (and $x2505 (< rank_2 rank_8)))))))
 (let (($x2823 (and $x2817 (=> root_11 $x2717))))
 (let (($x2835 (and (and $x2823 (=> $x2831 (or $x2826 (and $x2558 (< rank_4 rank_10))))) $x2834)))
 (let (($x2837 (and $x2835 (<= (+ ?x2802 ?x2820) 1))))
 (let (($x3076 (and (and $x2837 (>= ?x3071 ?x2856)) (<= (+ ?x3071 ?x3071) (+ (+ ?x2856 ?x2856) ?x2856)))))
 (let (($x2381 (or (and c_5_0 $x2364) $x2378 $x2380)))
 (let (($x2366 (or (and c_4_0 $x2349) $x2363 $x2365)))
 (let (($x2351 (or (and c_3_0 $x2334) $x2348 $x2350)))
 (let (($x2336 (or (and c_2_0 $x2319) $x2333 $x2335)))
 (let (($x2321 (or (and c_1_0 $x2304) $x2318 $x2320)))
 (let (($x2306 (or (and c_0_0 $x2291) $x2303 $x2305)))
 (let (($x2301 (and true $x2306)))
 (let (($x2316 (and $x2301 $x2321)))
 (let (($x2331 (and $x2316 $x2336)))
 (let (($x2346 (and $x2331 $x2351)))
 (let (($x2361 (and $x2346 $x2366)))
 (let (($x2375 (not (and $x2361 $x2381))))
 (let (($x3090 (and $x2375 $x3076)))
 (let (($x3092 (and $x3090 (not (and (and true $x3086) $x3087)))))
 (let (($x3099 (and $x3092 (not (and (and true $x3094) $x3098)))))
 (let (($x3109 (and $x3099 (not (and $x3102 $x3108)))))
 (let (($x3119 (and $x3109 (not (and $x3112 $x3118)))))
 (let (($x3125 (and $x3119 (not (and (and true $x3086) $x3124)))))
 (let (($x3128 (and $x3125 (not (and (and true $x3094) $x3108)))))
 (let (($x3135 (and $x3128 (not (and $x3131 $x3118)))))
 (let (($x3141 (and $x3135 (not (and (and true $x3094) $x3140)))))
 (let (($x3144 (and $x3141 (not (and $x3131 $x3087)))))
 (let (($x3147 (and $x3144 (not (and $x3112 $x3124)))))
 (let (($x3154 (and $x3147 (not (and $x3150 $x3108)))))
 (let (($x3157 (and $x3154 (not (and $x3102 $x3140)))))
 (let (($x3160 (and $x3157 (not (and $x3112 $x3087)))))
 (let (($x3163 (and $x3160 (not (and $x3150 $x3098)))))
 (let (($x3179 (and $x3163 (not (and (and true $x3086) $x3186)))))
 (let (($x3193 (and $x3179 (not (and (and true $x3094) $x3201)))))
 (let (($x3213 (and $x3193 (not (and $x3102 $x3216)))))
 (let (($x3225 (and $x3213 (not (and $x3112 $x3231)))))
 (let (($x3243 (and $x3225 (not (and (and true $x3086) $x3246)))))
 (let (($x3247 (and $x3243 (not (and (and true $x3094) $x3216)))))
 (let (($x3238 (and $x3247 (not (and $x3131 $x3231)))))
 (let (($x3266 (and $x3238 (not (and (and true $x3094) $x3267)))))
 (let (($x3264 (and $x3266 (not (and $x3131 $x3186)))))
 (let (($x3271 (and $x3264 (not (and $x3112 $x3246)))))
 (let (($x3274 (and $x3271 (not (and $x3150 $x3216)))))
 (let (($x3279 (and $x3274 (not (and $x3102 $x3267)))))
 (let (($x3277 (and $x3279 (not (and $x3112 $x3186)))))
 (let (($x3276 (and $x3277 (not (and $x3150 $x3201)))))
 (let (($x3286 (and $x3276 (not (and (and true $x3086) $x3288)))))
 (let (($x3297 (and $x3286 (not (and (and true $x3094) $x3299)))))
 (let (($x3308 (and $x3297 (not (and $x3102 $x3310)))))
 (let (($x3319 (and $x3308 (not (and $x3112 $x3321)))))
 (let (($x3330 (and $x3319 (not (and (and true $x3086) $x3332)))))
 (let (($x3335 (and $x3330 (not (and (and true $x3094) $x3310)))))
 (let (($x3338 (and $x3335 (not (and $x3131 $x3321)))))
 (let (($x3347 (and $x3338 (not (and (and true $x3094) $x3349)))))
 (let (($x3352 (and $x3347 (not (and $x3131 $x3288)))))
 (let (($x3355 (and $x3352 (not (and $x3112 $x3332)))))
 (let (($x3358 (and $x3355 (not (and $x3150 $x3310)))))
 (let (($x3361 (and $x3358 (not (and $x3102 $x3349)))))
 (let (($x3364 (and $x3361 (not (and $x3112 $x3288)))))
 (let (($x3367 (and $x3364 (not (and $x3150 $x3299)))))
 (let (($x3385 (and $x3367 (not (and (and true $x3390) $x3386)))))
 (let (($x3408 (and $x3385 (not (and (and true $x3409) $x3406)))))
 (let (($x3425 (and $x3408 (not (and (and true $x3428) $x3419)))))
 (let (($x3443 (and $x3425 (not (and (and true $x3447) $x3445)))))
 (let (($x3451 (and $x3443 (not (and (and true $x3390) $x3446)))))
 (let (($x3456 (and $x3451 (not (and (and true $x3409) $x3419)))))
 (let (($x3467 (and $x3456 (not (and (and true $x3475) $x3445)))))
 (let (($x3477 (and $x3467 (not (and (and true $x3409) $x3478)))))
 (let (($x3484 (and $x3477 (not (and (and true $x3475) $x3386)))))
 (let (($x3481 (and $x3484 (not (and (and true $x3447) $x3446)))))
 (let (($x3494 (and $x3481 (not (and (and true $x3503) $x3419)))))
 (let (($x3499 (and $x3494 (not (and (and true $x3428) $x3478)))))
 (let (($x3505 (and $x3499 (not (and (and true $x3447) $x3386)))))
 (let (($x3502 (and $x3505 (not (and (and true $x3503) $x3406)))))
 (let (($x3511 (and $x3502 (not (and (and true c_0_12) $x2471)))))
 (let (($x3510 (and $x3511 (not (and (and true c_1_12) $x2524)))))
 (let (($x3517 (and $x3510 (not (and (and true c_3_12) $x2630)))))
 (let (($x3521 (and $x3517 (not (and (and true c_4_12) $x2683)))))
 (let (($x3524 (and $x3521 (not (and (and true c_0_12) $x2577)))))
 (let (($x3527 (and $x3524 (not (and (and true c_1_12) $x2630)))))
 (let (($x3531 (and $x3527 (not (and (and true c_2_12) $x2683)))))
 (let (($x3534 (and $x3531 (not (and (and true c_1_12) $x2418)))))
 (let (($x3537 (and $x3534 (not (and (and true c_2_12) $x2471)))))
 (let (($x3540 (and $x3537 (not (and (and true c_4_12) $x2577)))))
 (let (($x3544 (and $x3540 (not (and (and true c_5_12) $x2630)))))
 (let (($x3547 (and $x3544 (not (and (and true c_3_12) $x2418)))))
 (let (($x3550 (and $x3547 (not (and (and true c_4_12) $x2471)))))
 (let (($x3553 (and $x3550 (not (and (and true c_5_12) $x2524)))))
 (let (($x3563 (and $x3553 (not (and $x3559 c_1_18)))))
 (let (($x3570 (and $x3563 (not (and $x3569 c_2_18)))))
 (let (($x3580 (and $x3570 (not (and $x3579 c_4_18)))))
 (let (($x3591 (and $x3580 (not (and $x3589 c_5_18)))))
 (let (($x3597 (and $x3591 (not (and $x3559 c_3_18)))))
 (let (($x3600 (and $x3597 (not (and $x3569 c_4_18)))))
 (let (($x3608 (and $x3600 (not (and $x3605 c_5_18)))))
 (let (($x3613 (and $x3608 (not (and $x3569 c_0_18)))))
 (let (($x3614 (and $x3613 (not (and $x3605 c_1_18)))))
 (let (($x3620 (and $x3614 (not (and $x3589 c_3_18)))))
 (let (($x3626 (and $x3620 (not (and $x3624 c_4_18)))))
 (let (($x3631 (and $x3626 (not (and $x3579 c_0_18)))))
 (let (($x3636 (and $x3631 (not (and $x3589 c_1_18)))))
 (let (($x3638 (and $x3636 (not (and $x3624 c_2_18)))))
 (let (($x3673 (and $x3638 (not (and (and $x3637 $x3649) $x3670)))))
 (let (($x3711 (and $x3673 (not (and (and $x3674 $x3685) $x3708)))))
 (let (($x3743 (and $x3711 (not (and (and $x3712 $x3723) $x3740)))))
 (let (($x3779 (and $x3743 (not (and (and $x3744 $x3755) $x3776)))))
 (let (($x3785 (and $x3779 (not (and $x3784 $x3670)))))
 (let (($x3791 (and $x3785 (not (and (and $x3674 $x3723) $x3708)))))
 (let (($x3817 (and $x3791 (not (and (and $x3792 $x3755) $x3814)))))
 (let (($x3826 (and $x3817 (not (and $x3822 $x3708)))))
 (let (($x3831 (and $x3826 (not (and $x3823 $x3814)))))
 (let (($x3832 (and $x3831 (not (and (and $x3744 $x3789) $x3776)))))
 (let (($x3857 (and $x3832 (not (and (and $x3834 $x3723) $x3854)))))
 (let (($x3862 (and $x3857 (not (and $x3858 $x3740)))))
 (let (($x3866 (and $x3862 (not (and $x3859 $x3776)))))
 (let (($x3867 (and $x3866 (not (and $x3865 $x3854)))))
 (let (($x3879 (and $x3867 (not (and (and $x3873 $x3649) $x3670)))))
 (let (($x3884 (and $x3879 (not (and (and $x3882 $x3685) $x3708)))))
 (let (($x3895 (and $x3884 (not (and (and $x3891 $x3723) $x3740)))))
 (let (($x3906 (and $x3895 (not (and (and $x3900 $x3755) $x3776)))))
 (let (($x3908 (and $x3906 (not (and $x3905 $x3670)))))
 (let (($x3912 (and $x3908 (not (and (and $x3882 $x3723) $x3708)))))
 (let (($x3923 (and $x3912 (not (and $x3919 $x3814)))))
 (let (($x3927 (and $x3923 (not (and $x3922 $x3708)))))
 (let (($x3931 (and $x3927 (not (and $x3924 $x3814)))))
 (let (($x3932 (and $x3931 (not (and (and $x3900 $x3789) $x3776)))))
 (let (($x3942 (and $x3932 (not (and $x3939 $x3854)))))
 (let (($x3948 (and $x3942 (not (and $x3943 $x3740)))))
 (let (($x3952 (and $x3948 (not (and $x3946 $x3776)))))
 (let (($x3953 (and $x3952 (not (and $x3951 $x3854)))))
 (let (($x3958 (and $x3953 (not (and $x3559 $x3649)))))
 (let (($x3962 (and $x3958 (not (and $x3569 $x3685)))))
 (let (($x3965 (and $x3962 (not (and $x3579 $x3723)))))
 (let (($x3969 (and $x3965 (not (and $x3589 $x3755)))))
 (let (($x3967 (and $x3969 (not (and $x3559 $x3789)))))
 (let (($x3975 (and $x3967 (not (and $x3569 $x3723)))))
 (let (($x3972 (and $x3975 (not (and $x3605 $x3755)))))
 (let (($x3980 (and $x3972 (not (and $x3569 $x3827)))))
 (let (($x3982 (and $x3980 (not (and $x3605 $x3649)))))
 (let (($x3983 (and $x3982 (not (and $x3589 $x3789)))))
 (let (($x3990 (and $x3983 (not (and $x3624 $x3723)))))
 (let (($x3991 (and $x3990 (not (and $x3579 $x3827)))))
 (let (($x3995 (and $x3991 (not (and $x3589 $x3649)))))
 (let (($x3998 (and $x3995 (not (and $x3624 $x3685)))))
 (and $x3998 $x5013)))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
