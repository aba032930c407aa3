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
 (let (($x4680 (>= rank_12 0)))
 (and $x4680 (< rank_12 6))))
(assert
 (let (($x4685 (>= rank_14 0)))
 (and $x4685 (< rank_14 6))))
(assert
 (let (($x4690 (>= rank_16 0)))
 (and $x4690 (< rank_16 6))))
(assert
 (let (($x4695 (>= rank_18 0)))
 (and $x4695 (< rank_18 6))))
(assert
 (let (($x4700 (>= rank_20 0)))
 (and $x4700 (< rank_20 6))))
(assert
 (let (($x4705 (>= rank_22 0)))
 (and $x4705 (< rank_22 6))))
(assert
 (let (($x4852 (>= prank_24 0)))
 (and $x4852 (< prank_24 6))))
(assert
 (let (($x4873 (>= prank_25 0)))
 (and $x4873 (< prank_25 6))))
(assert
 (let (($x4877 (>= prank_26 0)))
 (and $x4877 (< prank_26 6))))
(assert
 (let (($x4881 (>= prank_27 0)))
 (and $x4881 (< prank_27 6))))
(assert
 (let (($x4885 (>= prank_28 0)))
 (and $x4885 (< prank_28 6))))
(assert
 (let (($x4889 (>= prank_29 0)))
 (and $x4889 (< prank_29 6))))
(assert
 (let (($x5121 (>= prank_32 0)))
 (and $x5121 (< prank_32 6))))
(assert
 (let (($x5107 (>= prank_33 0)))
 (and $x5107 (< prank_33 6))))
(assert
 (let (($x5115 (>= prank_34 0)))
 (and $x5115 (< prank_34 6))))
(assert
 (let (($x5125 (>= prank_35 0)))
 (and $x5125 (< prank_35 6))))
(assert
 (let (($x5129 (>= prank_36 0)))
 (and $x5129 (< prank_36 6))))
(assert
 (let (($x5133 (>= prank_37 0)))
 (and $x5133 (< prank_37 6))))
(assert
 (let (($x5377 (>= rank_40 0)))
 (and $x5377 (< rank_40 6))))
(assert
 (let (($x5371 (>= rank_42 0)))
 (and $x5371 (< rank_42 6))))
(assert
 (let (($x5379 (>= rank_44 0)))
 (and $x5379 (< rank_44 6))))
(assert
 (let (($x5385 (>= rank_46 0)))
 (and $x5385 (< rank_46 6))))
(assert
 (let (($x5390 (>= rank_48 0)))
 (and $x5390 (< rank_48 6))))
(assert
 (let (($x5395 (>= rank_50 0)))
 (and $x5395 (< rank_50 6))))
(assert
 (let ((?x5646 (ite (or c_2_1 c_2_3 c_2_7 c_2_9 c_2_13 c_2_15) 1 0)))
 (let ((?x5641 (ite (or c_4_1 c_4_2 c_4_7 c_4_8 c_4_13 c_4_14) 1 0)))
 (let ((?x4320 (ite false 1 0)))
 (let ((?x4466 (+ 0 ?x4320)))
 (let ((?x4508 (+ ?x4466 ?x4320)))
 (let ((?x5648 (+ ?x4508 ?x5641)))
 (let (($x4611 (or c_5_14 c_5_15 c_5_16 c_5_17)))
 (let ((?x5628 (ite (or c_1_1 c_1_3 c_1_7 c_1_9 c_1_13 c_1_15) 1 0)))
 (let ((?x5623 (ite (or c_3_1 c_3_2 c_3_7 c_3_8 c_3_13 c_3_14) 1 0)))
 (let ((?x5617 (ite (or c_5_1 c_5_4 c_5_7 c_5_10 c_5_13 c_5_16) 1 0)))
 (let ((?x5625 (+ 0 ?x5617)))
 (let ((?x5624 (+ ?x5625 ?x4320)))
 (let ((?x5626 (+ ?x5624 ?x5623)))
 (let (($x4573 (or c_4_14 c_4_15 c_4_16 c_4_17)))
 (let (($x5632 (and $x4573 (> (to_real (+ ?x5626 ?x5628)) 0.0))))
 (let ((?x5599 (ite (or c_0_1 c_0_3 c_0_7 c_0_9 c_0_13 c_0_15) 1 0)))
 (let ((?x5595 (ite (or c_4_1 c_4_4 c_4_7 c_4_10 c_4_13 c_4_16) 1 0)))
 (let ((?x5598 (+ 0 ?x5595)))
 (let ((?x5597 (+ ?x5598 ?x4320)))
 (let ((?x5600 (+ ?x5597 ?x4320)))
 (let (($x4564 (or c_3_14 c_3_15 c_3_16 c_3_17)))
 (let (($x5605 (and $x4564 (> (to_real (+ ?x5600 ?x5599)) 0.0))))
 (let ((?x5572 (ite (or c_1_1 c_1_2 c_1_7 c_1_8 c_1_13 c_1_14) 1 0)))
 (let ((?x5575 (ite (or c_5_1 c_5_5 c_5_7 c_5_11 c_5_13 c_5_17) 1 0)))
 (let ((?x5578 (+ ?x4466 ?x5575)))
 (let ((?x5577 (+ ?x5578 ?x5572)))
 (let (($x4590 (or c_2_14 c_2_15 c_2_16 c_2_17)))
 (let (($x5583 (and $x4590 (> (to_real (+ ?x5577 ?x4320)) 0.0))))
 (let ((?x5557 (ite (or c_0_1 c_0_2 c_0_7 c_0_8 c_0_13 c_0_14) 1 0)))
 (let ((?x5555 (ite (or c_4_1 c_4_5 c_4_7 c_4_11 c_4_13 c_4_17) 1 0)))
 (let ((?x5553 (ite (or c_2_1 c_2_4 c_2_7 c_2_10 c_2_13 c_2_16) 1 0)))
 (let ((?x5556 (+ 0 ?x5553)))
 (let ((?x5550 (+ ?x5556 ?x5555)))
 (let ((?x5559 (+ ?x5550 ?x5557)))
 (let (($x4555 (or c_1_14 c_1_15 c_1_16 c_1_17)))
 (let (($x5563 (and $x4555 (> (to_real (+ ?x5559 ?x4320)) 0.0))))
 (let ((?x5530 (ite (or c_3_1 c_3_5 c_3_7 c_3_11 c_3_13 c_3_17) 1 0)))
 (let ((?x5523 (ite (or c_1_1 c_1_4 c_1_7 c_1_10 c_1_13 c_1_16) 1 0)))
 (let ((?x5531 (+ 0 ?x5523)))
 (let ((?x5528 (+ ?x5531 ?x5530)))
 (let ((?x5529 (+ ?x5528 ?x4320)))
 (let (($x4546 (or c_0_14 c_0_15 c_0_16 c_0_17)))
 (let (($x5536 (and $x4546 (> (to_real (+ ?x5529 ?x4320)) 0.0))))
 (let (($x5537 (or false $x5536)))
 (let (($x5564 (or $x5537 $x5563)))
 (let (($x5584 (or $x5564 $x5583)))
 (let (($x5606 (or $x5584 $x5605)))
 (let (($x5633 (or $x5606 $x5632)))
 (let (($x5505 (or false c_0_13)))
 (let (($x5507 (or $x5505 c_1_13)))
 (let (($x5509 (or $x5507 c_2_13)))
 (let (($x5511 (or $x5509 c_3_13)))
 (let (($x5513 (or $x5511 c_4_13)))
 (let ((?x5486 (ite root_51 1 0)))
 (let ((?x5467 (ite root_49 1 0)))
 (let ((?x5451 (ite root_47 1 0)))
 (let ((?x5435 (ite root_45 1 0)))
 (let ((?x5416 (ite root_43 1 0)))
 (let ((?x5400 (ite root_41 1 0)))
 (let ((?x5401 (+ 0 ?x5400)))
 (let ((?x5417 (+ ?x5401 ?x5416)))
 (let ((?x5436 (+ ?x5417 ?x5435)))
 (let ((?x5452 (+ ?x5436 ?x5451)))
 (let ((?x5468 (+ ?x5452 ?x5467)))
 (let (($x5399 (or false root_41)))
 (let (($x5415 (or $x5399 root_43)))
 (let (($x5434 (or $x5415 root_45)))
 (let (($x5450 (or $x5434 root_47)))
 (let (($x5466 (or $x5450 root_49)))
 (let (($x5383 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_13 c_5_14 c_5_15 c_5_16 c_5_17 c_5_18)))
 (let (($x5370 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_13 c_4_14 c_4_15 c_4_16 c_4_17 c_4_18)))
 (let (($x5357 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_13 c_3_14 c_3_15 c_3_16 c_3_17 c_3_18)))
 (let (($x5344 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_13 c_2_14 c_2_15 c_2_16 c_2_17 c_2_18)))
 (let (($x5331 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_13 c_1_14 c_1_15 c_1_16 c_1_17 c_1_18)))
 (let (($x5318 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_13 c_0_14 c_0_15 c_0_16 c_0_17 c_0_18)))
 (let (($x5398 (or false $x5318)))
 (let (($x5414 (or $x5398 $x5331)))
 (let (($x5433 (or $x5414 $x5344)))
 (let (($x5449 (or $x5433 $x5357)))
 (let (($x5465 (or $x5449 $x5370)))
 (let (($x5492 (or false (and $x5370 (< rank_48 rank_50)))))
 (let (($x5496 (not root_51)))
 (let (($x5497 (and $x5383 $x5496)))
 (let (($x5473 (or false (and $x5383 (< rank_50 rank_48)))))
 (let (($x5476 (or $x5473 (and $x5357 (< rank_46 rank_48)))))
 (let (($x5480 (not root_49)))
 (let (($x5481 (and $x5370 $x5480)))
 (let (($x5457 (or false (and $x5370 (< rank_48 rank_46)))))
 (let (($x5461 (not root_47)))
 (let (($x5462 (and $x5357 $x5461)))
 (let (($x5441 (or false (and $x5383 (< rank_50 rank_44)))))
 (let (($x5445 (not root_45)))
 (let (($x5446 (and $x5344 $x5445)))
 (let (($x5422 (or false (and $x5344 (< rank_44 rank_42)))))
 (let (($x5425 (or $x5422 (and $x5370 (< rank_48 rank_42)))))
 (let (($x5429 (not root_43)))
 (let (($x5430 (and $x5331 $x5429)))
 (let (($x5406 (or false (and $x5331 (< rank_42 rank_40)))))
 (let (($x5410 (not root_41)))
 (let (($x5411 (and $x5318 $x5410)))
 (let (($x5403 (and true (=> root_41 $x5318))))
 (let (($x5413 (and $x5403 (=> $x5411 (or $x5406 (and $x5357 (< rank_46 rank_40)))))))
 (let (($x5419 (and $x5413 (=> root_43 $x5331))))
 (let (($x5432 (and $x5419 (=> $x5430 (or $x5425 (and $x5318 (< rank_40 rank_42)))))))
 (let (($x5438 (and $x5432 (=> root_45 $x5344))))
 (let (($x5448 (and $x5438 (=> $x5446 (or $x5441 (and $x5331 (< rank_42 rank_44)))))))
 (let (($x5454 (and $x5448 (=> root_47 $x5357))))
 (let (($x5464 (and $x5454 (=> $x5462 (or $x5457 (and $x5318 (< rank_40 rank_46)))))))
 (let (($x5470 (and $x5464 (=> root_49 $x5370))))
 (let (($x5483 (and $x5470 (=> $x5481 (or $x5476 (and $x5331 (< rank_42 rank_48)))))))
 (let (($x5489 (and $x5483 (=> root_51 $x5383))))
 (let (($x5501 (and (and $x5489 (=> $x5497 (or $x5492 (and $x5344 (< rank_44 rank_50))))) (=> (or $x5465 $x5383) (or $x5466 root_51)))))
 (let (($x5503 (and $x5501 (<= (+ ?x5468 ?x5486) 1))))
 (let (($x4115 (or c_5_1 c_5_7 c_5_13)))
 (let (($x5284 (and $x4115 (= prank_37 prank_high_39))))
 (let (($x4089 (or c_4_1 c_4_7 c_4_13)))
 (let (($x5261 (and $x4089 (= prank_36 prank_high_39))))
 (let (($x4116 (or c_3_1 c_3_7 c_3_13)))
 (let (($x5233 (and $x4116 (= prank_35 prank_high_39))))
 (let (($x4076 (or c_2_1 c_2_7 c_2_13)))
 (let (($x5210 (and $x4076 (= prank_34 prank_high_39))))
 (let (($x4056 (or c_1_1 c_1_7 c_1_13)))
 (let (($x5187 (and $x4056 (= prank_33 prank_high_39))))
 (let (($x4148 (or c_0_1 c_0_7 c_0_13)))
 (let (($x5159 (and $x4148 (= prank_32 prank_high_39))))
 (let (($x5160 (or false $x5159)))
 (let (($x5188 (or $x5160 $x5187)))
 (let (($x5211 (or $x5188 $x5210)))
 (let (($x5234 (or $x5211 $x5233)))
 (let (($x5262 (or $x5234 $x5261)))
 (let (($x5281 (and $x4115 (= prank_37 prank_low_38))))
 (let (($x5258 (and $x4089 (= prank_36 prank_low_38))))
 (let (($x5230 (and $x4116 (= prank_35 prank_low_38))))
 (let (($x5207 (and $x4076 (= prank_34 prank_low_38))))
 (let (($x5184 (and $x4056 (= prank_33 prank_low_38))))
 (let (($x5156 (and $x4148 (= prank_32 prank_low_38))))
 (let (($x5157 (or false $x5156)))
 (let (($x5185 (or $x5157 $x5184)))
 (let (($x5208 (or $x5185 $x5207)))
 (let (($x5231 (or $x5208 $x5230)))
 (let (($x5259 (or $x5231 $x5258)))
 (let (($x5287 (=> (or (or (or (or (or (or false $x4148) $x4056) $x4076) $x4116) $x4089) $x4115) (and (or $x5259 $x5281) (or $x5262 $x5284)))))
 (let (($x5091 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_14 c_2_15 c_2_16 c_2_17 c_2_18)))
 (let (($x5113 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_14 c_4_15 c_4_16 c_4_17 c_4_18)))
 (let (($x5267 (or false (and true (or $x5113 (and $x4089 (< prank_36 prank_37)))))))
 (let (($x5274 (and (or $x5267 (and true (or $x5091 (and $x4076 (< prank_34 prank_37))))) (<= prank_low_38 prank_37))))
 (let (($x5080 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_14 c_1_15 c_1_16 c_1_17 c_1_18)))
 (let (($x5102 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_14 c_3_15 c_3_16 c_3_17 c_3_18)))
 (let (($x5124 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_14 c_5_15 c_5_16 c_5_17 c_5_18)))
 (let (($x5239 (or false (and true (or $x5124 (and $x4115 (< prank_37 prank_36)))))))
 (let (($x5244 (or $x5239 (and true (or $x5102 (and $x4116 (< prank_35 prank_36)))))))
 (let (($x5251 (and (or $x5244 (and true (or $x5080 (and $x4056 (< prank_33 prank_36))))) (<= prank_low_38 prank_36))))
 (let (($x5069 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_14 c_0_15 c_0_16 c_0_17 c_0_18)))
 (let (($x5216 (or false (and true (or $x5113 (and $x4089 (< prank_36 prank_35)))))))
 (let (($x5223 (and (or $x5216 (and true (or $x5069 (and $x4148 (< prank_32 prank_35))))) (<= prank_low_38 prank_35))))
 (let (($x5193 (or false (and true (or $x5124 (and $x4115 (< prank_37 prank_34)))))))
 (let (($x5200 (and (or $x5193 (and true (or $x5080 (and $x4056 (< prank_33 prank_34))))) (<= prank_low_38 prank_34))))
 (let (($x5165 (or false (and true (or $x5091 (and $x4076 (< prank_34 prank_33)))))))
 (let (($x5170 (or $x5165 (and true (or $x5113 (and $x4089 (< prank_36 prank_33)))))))
 (let (($x5177 (and (or $x5170 (and true (or $x5069 (and $x4148 (< prank_32 prank_33))))) (<= prank_low_38 prank_33))))
 (let (($x5142 (or false (and true (or $x5080 (and $x4056 (< prank_33 prank_32)))))))
 (let (($x5149 (and (or $x5142 (and true (or $x5102 (and $x4116 (< prank_35 prank_32))))) (<= prank_low_38 prank_32))))
 (let (($x5153 (and true (=> $x4148 (and $x5149 (<= prank_32 prank_high_39))))))
 (let (($x5181 (and $x5153 (=> $x4056 (and $x5177 (<= prank_33 prank_high_39))))))
 (let (($x5204 (and $x5181 (=> $x4076 (and $x5200 (<= prank_34 prank_high_39))))))
 (let (($x5227 (and $x5204 (=> $x4116 (and $x5223 (<= prank_35 prank_high_39))))))
 (let (($x5255 (and $x5227 (=> $x4089 (and $x5251 (<= prank_36 prank_high_39))))))
 (let (($x5278 (and $x5255 (=> $x4115 (and $x5274 (<= prank_37 prank_high_39))))))
 (let (($x5288 (and $x5278 $x5287)))
 (let (($x4173 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_8 c_5_9 c_5_10 c_5_11 c_5_14 c_5_15 c_5_16 c_5_17)))
 (let (($x5040 (and $x4173 (= prank_29 prank_high_31))))
 (let (($x4117 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_8 c_4_9 c_4_10 c_4_11 c_4_14 c_4_15 c_4_16 c_4_17)))
 (let (($x5017 (and $x4117 (= prank_28 prank_high_31))))
 (let (($x4098 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_8 c_3_9 c_3_10 c_3_11 c_3_14 c_3_15 c_3_16 c_3_17)))
 (let (($x4989 (and $x4098 (= prank_27 prank_high_31))))
 (let (($x4145 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_8 c_2_9 c_2_10 c_2_11 c_2_14 c_2_15 c_2_16 c_2_17)))
 (let (($x4966 (and $x4145 (= prank_26 prank_high_31))))
 (let (($x4079 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_8 c_1_9 c_1_10 c_1_11 c_1_14 c_1_15 c_1_16 c_1_17)))
 (let (($x4943 (and $x4079 (= prank_25 prank_high_31))))
 (let (($x4060 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_8 c_0_9 c_0_10 c_0_11 c_0_14 c_0_15 c_0_16 c_0_17)))
 (let (($x4915 (and $x4060 (= prank_24 prank_high_31))))
 (let (($x4916 (or false $x4915)))
 (let (($x4944 (or $x4916 $x4943)))
 (let (($x4967 (or $x4944 $x4966)))
 (let (($x4990 (or $x4967 $x4989)))
 (let (($x5018 (or $x4990 $x5017)))
 (let (($x5037 (and $x4173 (= prank_29 prank_low_30))))
 (let (($x5014 (and $x4117 (= prank_28 prank_low_30))))
 (let (($x4986 (and $x4098 (= prank_27 prank_low_30))))
 (let (($x4963 (and $x4145 (= prank_26 prank_low_30))))
 (let (($x4940 (and $x4079 (= prank_25 prank_low_30))))
 (let (($x4912 (and $x4060 (= prank_24 prank_low_30))))
 (let (($x4913 (or false $x4912)))
 (let (($x4941 (or $x4913 $x4940)))
 (let (($x4964 (or $x4941 $x4963)))
 (let (($x4987 (or $x4964 $x4986)))
 (let (($x5015 (or $x4987 $x5014)))
 (let (($x5043 (=> (or (or (or (or (or (or false $x4060) $x4079) $x4145) $x4098) $x4117) $x4173) (and (or $x5015 $x5037) (or $x5018 $x5040)))))
 (let (($x3840 (or c_2_6 c_2_12 c_2_18)))
 (let (($x4476 (or c_5_5 c_5_11 c_5_17)))
 (let (($x3823 (or c_4_6 c_4_12 c_4_18)))
 (let (($x4433 (or c_5_4 c_5_10 c_5_16)))
 (let (($x5023 (or false (and $x4433 (or $x3823 (and $x4117 (< prank_28 prank_29)))))))
 (let (($x5030 (and (or $x5023 (and $x4476 (or $x3840 (and $x4145 (< prank_26 prank_29))))) (<= prank_low_30 prank_29))))
 (let (($x3805 (or c_1_6 c_1_12 c_1_18)))
 (let (($x4368 (or c_4_5 c_4_11 c_4_17)))
 (let (($x3814 (or c_3_6 c_3_12 c_3_18)))
 (let (($x4400 (or c_4_4 c_4_10 c_4_16)))
 (let (($x3858 (or c_5_6 c_5_12 c_5_18)))
 (let (($x4516 (or c_4_2 c_4_8 c_4_14)))
 (let (($x4995 (or false (and $x4516 (or $x3858 (and $x4173 (< prank_29 prank_28)))))))
 (let (($x5000 (or $x4995 (and $x4400 (or $x3814 (and $x4098 (< prank_27 prank_28)))))))
 (let (($x5007 (and (or $x5000 (and $x4368 (or $x3805 (and $x4079 (< prank_25 prank_28))))) (<= prank_low_30 prank_28))))
 (let (($x3796 (or c_0_6 c_0_12 c_0_18)))
 (let (($x4333 (or c_3_5 c_3_11 c_3_17)))
 (let (($x4435 (or c_3_2 c_3_8 c_3_14)))
 (let (($x4972 (or false (and $x4435 (or $x3823 (and $x4117 (< prank_28 prank_27)))))))
 (let (($x4979 (and (or $x4972 (and $x4333 (or $x3796 (and $x4060 (< prank_24 prank_27))))) (<= prank_low_30 prank_27))))
 (let (($x4365 (or c_2_4 c_2_10 c_2_16)))
 (let (($x4519 (or c_2_3 c_2_9 c_2_15)))
 (let (($x4949 (or false (and $x4519 (or $x3858 (and $x4173 (< prank_29 prank_26)))))))
 (let (($x4956 (and (or $x4949 (and $x4365 (or $x3805 (and $x4079 (< prank_25 prank_26))))) (<= prank_low_30 prank_26))))
 (let (($x4330 (or c_1_4 c_1_10 c_1_16)))
 (let (($x4438 (or c_1_3 c_1_9 c_1_15)))
 (let (($x4478 (or c_1_2 c_1_8 c_1_14)))
 (let (($x4921 (or false (and $x4478 (or $x3840 (and $x4145 (< prank_26 prank_25)))))))
 (let (($x4926 (or $x4921 (and $x4438 (or $x3823 (and $x4117 (< prank_28 prank_25)))))))
 (let (($x4933 (and (or $x4926 (and $x4330 (or $x3796 (and $x4060 (< prank_24 prank_25))))) (<= prank_low_30 prank_25))))
 (let (($x4403 (or c_0_3 c_0_9 c_0_15)))
 (let (($x4370 (or c_0_2 c_0_8 c_0_14)))
 (let (($x4898 (or false (and $x4370 (or $x3805 (and $x4079 (< prank_25 prank_24)))))))
 (let (($x4905 (and (or $x4898 (and $x4403 (or $x3814 (and $x4098 (< prank_27 prank_24))))) (<= prank_low_30 prank_24))))
 (let (($x4909 (and true (=> $x4060 (and $x4905 (<= prank_24 prank_high_31))))))
 (let (($x4937 (and $x4909 (=> $x4079 (and $x4933 (<= prank_25 prank_high_31))))))
 (let (($x4960 (and $x4937 (=> $x4145 (and $x4956 (<= prank_26 prank_high_31))))))
 (let (($x4983 (and $x4960 (=> $x4098 (and $x4979 (<= prank_27 prank_high_31))))))
 (let (($x5011 (and $x4983 (=> $x4117 (and $x5007 (<= prank_28 prank_high_31))))))
 (let (($x5034 (and $x5011 (=> $x4173 (and $x5030 (<= prank_29 prank_high_31))))))
 (let (($x5044 (and $x5034 $x5043)))
 (let (($x2364 (not in_target_5)))
 (let (($x3382 (and c_5_12 $x2364)))
 (let (($x3363 (and c_5_6 $x2364)))
 (let (($x3350 (and c_5_18 $x2364)))
 (let (($x2349 (not in_target_4)))
 (let (($x3289 (and c_4_12 $x2349)))
 (let (($x3270 (and c_4_6 $x2349)))
 (let (($x3257 (and c_4_18 $x2349)))
 (let (($x4834 (or $x3257 $x3270 $x3289)))
 (let (($x2334 (not in_target_3)))
 (let (($x3196 (and c_3_12 $x2334)))
 (let (($x3177 (and c_3_6 $x2334)))
 (let (($x3164 (and c_3_18 $x2334)))
 (let (($x4829 (or $x3164 $x3177 $x3196)))
 (let (($x2319 (not in_target_2)))
 (let (($x3103 (and c_2_12 $x2319)))
 (let (($x3084 (and c_2_6 $x2319)))
 (let (($x3071 (and c_2_18 $x2319)))
 (let (($x4824 (or $x3071 $x3084 $x3103)))
 (let (($x2304 (not in_target_1)))
 (let (($x3010 (and c_1_12 $x2304)))
 (let (($x2991 (and c_1_6 $x2304)))
 (let (($x2978 (and c_1_18 $x2304)))
 (let (($x4819 (or $x2978 $x2991 $x3010)))
 (let (($x2291 (not in_target_0)))
 (let (($x2917 (and c_0_12 $x2291)))
 (let (($x2897 (and c_0_6 $x2291)))
 (let (($x2883 (and c_0_18 $x2291)))
 (let (($x4814 (or $x2883 $x2897 $x2917)))
 (let (($x4811 (or false $x4814)))
 (let (($x4816 (or $x4811 $x4819)))
 (let (($x4821 (or $x4816 $x4824)))
 (let (($x4826 (or $x4821 $x4829)))
 (let (($x4831 (or $x4826 $x4834)))
 (let ((?x4790 (ite root_23 1 0)))
 (let ((?x4772 (ite root_21 1 0)))
 (let ((?x4757 (ite root_19 1 0)))
 (let ((?x4742 (ite root_17 1 0)))
 (let ((?x4724 (ite root_15 1 0)))
 (let ((?x4709 (ite root_13 1 0)))
 (let ((?x4710 (+ 0 ?x4709)))
 (let ((?x4725 (+ ?x4710 ?x4724)))
 (let ((?x4743 (+ ?x4725 ?x4742)))
 (let ((?x4758 (+ ?x4743 ?x4757)))
 (let ((?x4773 (+ ?x4758 ?x4772)))
 (let (($x4708 (or false root_13)))
 (let (($x4723 (or $x4708 root_15)))
 (let (($x4741 (or $x4723 root_17)))
 (let (($x4756 (or $x4741 root_19)))
 (let (($x4771 (or $x4756 root_21)))
 (let (($x4664 (or false $x3796)))
 (let (($x4672 (or $x4664 $x3805)))
 (let (($x4675 (or $x4672 $x3840)))
 (let (($x4676 (or $x4675 $x3814)))
 (let (($x4677 (or $x4676 $x3823)))
 (let (($x4671 (or $x4677 $x3858)))
 (let (($x4796 (or false (and $x3823 (< rank_20 rank_22)))))
 (let (($x4800 (not root_23)))
 (let (($x4801 (and $x3858 $x4800)))
 (let (($x4778 (or false (and $x3858 (< rank_22 rank_20)))))
 (let (($x4781 (or $x4778 (and $x3814 (< rank_18 rank_20)))))
 (let (($x4785 (not root_21)))
 (let (($x4786 (and $x3823 $x4785)))
 (let (($x4763 (or false (and $x3823 (< rank_20 rank_18)))))
 (let (($x4767 (not root_19)))
 (let (($x4768 (and $x3814 $x4767)))
 (let (($x4748 (or false (and $x3858 (< rank_22 rank_16)))))
 (let (($x4752 (not root_17)))
 (let (($x4753 (and $x3840 $x4752)))
 (let (($x4730 (or false (and $x3840 (< rank_16 rank_14)))))
 (let (($x4733 (or $x4730 (and $x3823 (< rank_20 rank_14)))))
 (let (($x4737 (not root_15)))
 (let (($x4738 (and $x3805 $x4737)))
 (let (($x4715 (or false (and $x3805 (< rank_14 rank_12)))))
 (let (($x4719 (not root_13)))
 (let (($x4720 (and $x3796 $x4719)))
 (let (($x4712 (and true (=> root_13 $x3796))))
 (let (($x4722 (and $x4712 (=> $x4720 (or $x4715 (and $x3814 (< rank_18 rank_12)))))))
 (let (($x4727 (and $x4722 (=> root_15 $x3805))))
 (let (($x4740 (and $x4727 (=> $x4738 (or $x4733 (and $x3796 (< rank_12 rank_14)))))))
 (let (($x4745 (and $x4740 (=> root_17 $x3840))))
 (let (($x4755 (and $x4745 (=> $x4753 (or $x4748 (and $x3805 (< rank_14 rank_16)))))))
 (let (($x4760 (and $x4755 (=> root_19 $x3814))))
 (let (($x4770 (and $x4760 (=> $x4768 (or $x4763 (and $x3796 (< rank_12 rank_18)))))))
 (let (($x4775 (and $x4770 (=> root_21 $x3823))))
 (let (($x4788 (and $x4775 (=> $x4786 (or $x4781 (and $x3805 (< rank_14 rank_20)))))))
 (let (($x4793 (and $x4788 (=> root_23 $x3858))))
 (let (($x4805 (and (and $x4793 (=> $x4801 (or $x4796 (and $x3840 (< rank_16 rank_22))))) (=> $x4671 (or $x4771 root_23)))))
 (let (($x4807 (and $x4805 (<= (+ ?x4773 ?x4790) 1))))
 (let (($x5045 (and (and (and $x4671 $x4807) (not (or $x4831 (or $x3350 $x3363 $x3382)))) $x5044)))
 (let (($x5653 (and (and (and (and $x5045 $x5288) $x5503) (not (or $x5513 c_5_13))) (not (or $x5633 (and $x4611 (> (to_real (+ ?x5648 ?x5646)) 0.0)))))))
 (let (($x4355 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6)))
 (let (($x4299 (or c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4294 (and true $x4299)))
 (let (($x4319 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6)))
 (let (($x4264 (or c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4259 (and true $x4264)))
 (let (($x4497 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6)))
 (let (($x4254 (or c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x4249 (and true $x4254)))
 (let (($x4280 (or c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x4275 (and true $x4280)))
 (let (($x4244 (or c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x4239 (and true $x4244)))
 (let (($x4459 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6)))
 (let (($x4234 (or c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x4229 (and true $x4234)))
 (let (($x4523 (= (to_real (+ (+ ?x4508 (ite $x4516 1 0)) (ite $x4519 1 0))) 0.0)))
 (let (($x4512 (= (to_real (+ (+ ?x4508 (ite $x4089 1 0)) (ite $x4076 1 0))) 0.0)))
 (let (($x4524 (and $x4512 $x4523)))
 (let (($x4608 (and true $x4611)))
 (let (($x4621 (and $x4608 $x4355)))
 (let ((?x4442 (ite $x4438 1 0)))
 (let ((?x4440 (ite $x4435 1 0)))
 (let ((?x4436 (ite $x4433 1 0)))
 (let ((?x4437 (+ 0 ?x4436)))
 (let ((?x4439 (+ ?x4437 ?x4320)))
 (let ((?x4441 (+ ?x4439 ?x4440)))
 (let ((?x4316 (ite $x4056 1 0)))
 (let ((?x4318 (ite $x4116 1 0)))
 (let ((?x4421 (ite $x4115 1 0)))
 (let ((?x4422 (+ 0 ?x4421)))
 (let ((?x4424 (+ ?x4422 ?x4320)))
 (let ((?x4423 (+ ?x4424 ?x4318)))
 (let (($x4446 (and (= (to_real (+ ?x4423 ?x4316)) 0.0) (= (to_real (+ ?x4441 ?x4442)) 0.0))))
 (let (($x4570 (and true $x4573)))
 (let (($x4616 (and $x4570 $x4319)))
 (let ((?x4406 (ite $x4403 1 0)))
 (let ((?x4401 (ite $x4400 1 0)))
 (let ((?x4402 (+ 0 ?x4401)))
 (let ((?x4404 (+ ?x4402 ?x4320)))
 (let ((?x4405 (+ ?x4404 ?x4320)))
 (let ((?x4356 (ite $x4148 1 0)))
 (let ((?x4351 (ite $x4089 1 0)))
 (let ((?x4389 (+ 0 ?x4351)))
 (let ((?x4392 (+ ?x4389 ?x4320)))
 (let ((?x4390 (+ ?x4392 ?x4320)))
 (let (($x4410 (and (= (to_real (+ ?x4390 ?x4356)) 0.0) (= (to_real (+ ?x4405 ?x4406)) 0.0))))
 (let (($x4561 (and true $x4564)))
 (let (($x4613 (and $x4561 $x4497)))
 (let (($x4393 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6)))
 (let (($x4609 (and $x4608 $x4393)))
 (let ((?x4482 (to_real (+ (+ (+ ?x4466 (ite $x4476 1 0)) (ite $x4478 1 0)) ?x4320))))
 (let (($x4484 (and (= (to_real (+ (+ (+ ?x4466 ?x4421) ?x4316) ?x4320)) 0.0) (= ?x4482 0.0))))
 (let (($x4587 (and true $x4590)))
 (let (($x4594 (and $x4587 $x4319)))
 (let ((?x4373 (ite $x4370 1 0)))
 (let ((?x4371 (ite $x4368 1 0)))
 (let ((?x4367 (ite $x4365 1 0)))
 (let ((?x4369 (+ 0 ?x4367)))
 (let ((?x4372 (+ ?x4369 ?x4371)))
 (let ((?x4374 (+ ?x4372 ?x4373)))
 (let ((?x4359 (to_real (+ (+ (+ (+ 0 (ite $x4076 1 0)) ?x4351) ?x4356) ?x4320))))
 (let (($x4378 (and (= ?x4359 0.0) (= (to_real (+ ?x4374 ?x4320)) 0.0))))
 (let (($x4552 (and true $x4555)))
 (let (($x4592 (and $x4552 $x4497)))
 (let (($x4425 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6)))
 (let (($x4589 (and $x4587 $x4425)))
 (let ((?x4334 (ite $x4333 1 0)))
 (let ((?x4331 (ite $x4330 1 0)))
 (let ((?x4332 (+ 0 ?x4331)))
 (let ((?x4335 (+ ?x4332 ?x4334)))
 (let ((?x4336 (+ ?x4335 ?x4320)))
 (let (($x4340 (and (= (to_real (+ (+ (+ (+ 0 ?x4316) ?x4318) ?x4320) ?x4320)) 0.0) (= (to_real (+ ?x4336 ?x4320)) 0.0))))
 (let (($x4543 (and true $x4546)))
 (let (($x4575 (and $x4543 $x4459)))
 (let (($x4507 (or c_5_2 c_5_3 c_5_4 c_5_5)))
 (let (($x4504 (and true $x4507)))
 (let (($x4535 (and $x4504 $x4355)))
 (let (($x4416 (or c_4_2 c_4_3 c_4_4 c_4_5)))
 (let (($x4414 (and true $x4416)))
 (let (($x4529 (and $x4414 $x4319)))
 (let (($x4384 (or c_3_2 c_3_3 c_3_4 c_3_5)))
 (let (($x4382 (and true $x4384)))
 (let (($x4528 (and $x4382 $x4497)))
 (let (($x4465 (or c_2_2 c_2_3 c_2_4 c_2_5)))
 (let (($x4462 (and true $x4465)))
 (let (($x4493 (and $x4462 $x4319)))
 (let (($x4346 (or c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x4344 (and true $x4346)))
 (let (($x4492 (and $x4344 $x4497)))
 (let (($x4310 (or c_0_2 c_0_3 c_0_4 c_0_5)))
 (let (($x4307 (and true $x4310)))
 (let (($x4454 (and $x4307 $x4459)))
 (let (($x3094 (and c_2_7 $x2319)))
 (let (($x3075 (and c_2_1 $x2319)))
 (let (($x3061 (and c_2_13 $x2319)))
 (let (($x3992 (or $x3061 $x3075 $x3094)))
 (let (($x3856 (and true $x3858)))
 (let (($x3001 (and c_1_7 $x2304)))
 (let (($x2982 (and c_1_1 $x2304)))
 (let (($x2968 (and c_1_13 $x2304)))
 (let (($x3987 (or $x2968 $x2982 $x3001)))
 (let (($x3821 (and true $x3823)))
 (let (($x2908 (and c_0_7 $x2291)))
 (let (($x2888 (and c_0_1 $x2291)))
 (let (($x2873 (and c_0_13 $x2291)))
 (let (($x4018 (or $x2873 $x2888 $x2908)))
 (let (($x3812 (and true $x3814)))
 (let (($x3280 (and c_4_7 $x2349)))
 (let (($x3261 (and c_4_1 $x2349)))
 (let (($x3247 (and c_4_13 $x2349)))
 (let (($x3997 (or $x3247 $x3261 $x3280)))
 (let (($x3187 (and c_3_7 $x2334)))
 (let (($x3168 (and c_3_1 $x2334)))
 (let (($x3154 (and c_3_13 $x2334)))
 (let (($x4007 (or $x3154 $x3168 $x3187)))
 (let (($x3373 (and c_5_7 $x2364)))
 (let (($x3354 (and c_5_1 $x2364)))
 (let (($x3340 (and c_5_13 $x2364)))
 (let (($x4002 (or $x3340 $x3354 $x3373)))
 (let (($x3838 (and true $x3840)))
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
 (let (($x3907 (or $x2527 $x2529 $x2531 $x2533 $x2538 $x2540 $x2542 $x2544 $x2549 $x2551 $x2553 $x2555)))
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
 (let (($x3892 (or $x2474 $x2476 $x2478 $x2480 $x2485 $x2487 $x2489 $x2491 $x2496 $x2498 $x2500 $x2502)))
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
 (let (($x3973 (or $x2421 $x2423 $x2425 $x2427 $x2432 $x2434 $x2436 $x2438 $x2443 $x2445 $x2447 $x2449)))
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
 (let (($x3922 (or $x2633 $x2635 $x2637 $x2639 $x2644 $x2646 $x2648 $x2650 $x2655 $x2657 $x2659 $x2661)))
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
 (let (($x3952 (or $x2580 $x2582 $x2584 $x2586 $x2591 $x2593 $x2595 $x2597 $x2602 $x2604 $x2606 $x2608)))
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
 (let (($x3937 (or $x2686 $x2688 $x2690 $x2692 $x2697 $x2699 $x2701 $x2703 $x2708 $x2710 $x2712 $x2714)))
 (let (($x2547 (and c_2_13 in_target_2)))
 (let (($x2536 (and c_2_7 in_target_2)))
 (let (($x2525 (and c_2_1 in_target_2)))
 (let (($x3808 (or $x2525 $x2536 $x2547)))
 (let (($x2494 (and c_1_13 in_target_1)))
 (let (($x2483 (and c_1_7 in_target_1)))
 (let (($x2472 (and c_1_1 in_target_1)))
 (let (($x3799 (or $x2472 $x2483 $x2494)))
 (let (($x2441 (and c_0_13 in_target_0)))
 (let (($x2430 (and c_0_7 in_target_0)))
 (let (($x2419 (and c_0_1 in_target_0)))
 (let (($x3846 (or $x2419 $x2430 $x2441)))
 (let (($x2653 (and c_4_13 in_target_4)))
 (let (($x2642 (and c_4_7 in_target_4)))
 (let (($x2631 (and c_4_1 in_target_4)))
 (let (($x3817 (or $x2631 $x2642 $x2653)))
 (let (($x2600 (and c_3_13 in_target_3)))
 (let (($x2589 (and c_3_7 in_target_3)))
 (let (($x2578 (and c_3_1 in_target_3)))
 (let (($x3831 (or $x2578 $x2589 $x2600)))
 (let (($x2706 (and c_5_13 in_target_5)))
 (let (($x2695 (and c_5_7 in_target_5)))
 (let (($x2684 (and c_5_1 in_target_5)))
 (let (($x3826 (or $x2684 $x2695 $x2706)))
 (let (($x3380 (and c_5_11 $x2364)))
 (let (($x3378 (and c_5_10 $x2364)))
 (let (($x3376 (and c_5_9 $x2364)))
 (let (($x3374 (and c_5_8 $x2364)))
 (let ((?x3371 (ite (or $x3373 $x3374 $x3376 $x3378 $x3380 $x3382) 3 0)))
 (let (($x3361 (and c_5_5 $x2364)))
 (let (($x3359 (and c_5_4 $x2364)))
 (let (($x3357 (and c_5_3 $x2364)))
 (let (($x3355 (and c_5_2 $x2364)))
 (let ((?x3352 (ite (or $x3354 $x3355 $x3357 $x3359 $x3361 $x3363) 2 0)))
 (let (($x3348 (and c_5_17 $x2364)))
 (let (($x3346 (and c_5_16 $x2364)))
 (let (($x3344 (and c_5_15 $x2364)))
 (let (($x3342 (and c_5_14 $x2364)))
 (let ((?x3695 (ite (or $x3340 $x3342 $x3344 $x3346 $x3348 $x3350) 1 0)))
 (let ((?x3681 (ite (or (and c_5_6 in_target_5) $x2684 $x2686 $x2688 $x2690 $x2692) (- 1) 0)))
 (let (($x2716 (and c_5_18 in_target_5)))
 (let (($x3320 (or $x2706 $x2708 $x2710 $x2712 $x2714 $x2716)))
 (let ((?x3685 (ite $x3320 (- 2) 0)))
 (let (($x2683 (and c_5_0 in_target_5)))
 (let ((?x3683 (ite $x2683 (- 3) 0)))
 (let (($x3287 (and c_4_11 $x2349)))
 (let (($x3285 (and c_4_10 $x2349)))
 (let (($x3283 (and c_4_9 $x2349)))
 (let (($x3281 (and c_4_8 $x2349)))
 (let ((?x3278 (ite (or $x3280 $x3281 $x3283 $x3285 $x3287 $x3289) 3 0)))
 (let (($x3268 (and c_4_5 $x2349)))
 (let (($x3266 (and c_4_4 $x2349)))
 (let (($x3264 (and c_4_3 $x2349)))
 (let (($x3262 (and c_4_2 $x2349)))
 (let ((?x3259 (ite (or $x3261 $x3262 $x3264 $x3266 $x3268 $x3270) 2 0)))
 (let (($x3255 (and c_4_17 $x2349)))
 (let (($x3253 (and c_4_16 $x2349)))
 (let (($x3251 (and c_4_15 $x2349)))
 (let (($x3249 (and c_4_14 $x2349)))
 (let ((?x3654 (ite (or $x3247 $x3249 $x3251 $x3253 $x3255 $x3257) 1 0)))
 (let ((?x3646 (ite (or (and c_4_6 in_target_4) $x2631 $x2633 $x2635 $x2637 $x2639) (- 1) 0)))
 (let (($x2663 (and c_4_18 in_target_4)))
 (let (($x3227 (or $x2653 $x2655 $x2657 $x2659 $x2661 $x2663)))
 (let ((?x3632 (ite $x3227 (- 2) 0)))
 (let (($x2630 (and c_4_0 in_target_4)))
 (let ((?x3642 (ite $x2630 (- 3) 0)))
 (let (($x3194 (and c_3_11 $x2334)))
 (let (($x3192 (and c_3_10 $x2334)))
 (let (($x3190 (and c_3_9 $x2334)))
 (let (($x3188 (and c_3_8 $x2334)))
 (let ((?x3185 (ite (or $x3187 $x3188 $x3190 $x3192 $x3194 $x3196) 3 0)))
 (let (($x3175 (and c_3_5 $x2334)))
 (let (($x3173 (and c_3_4 $x2334)))
 (let (($x3171 (and c_3_3 $x2334)))
 (let (($x3169 (and c_3_2 $x2334)))
 (let ((?x3166 (ite (or $x3168 $x3169 $x3171 $x3173 $x3175 $x3177) 2 0)))
 (let (($x3162 (and c_3_17 $x2334)))
 (let (($x3160 (and c_3_16 $x2334)))
 (let (($x3158 (and c_3_15 $x2334)))
 (let (($x3156 (and c_3_14 $x2334)))
 (let ((?x3613 (ite (or $x3154 $x3156 $x3158 $x3160 $x3162 $x3164) 1 0)))
 (let ((?x3604 (ite (or (and c_3_6 in_target_3) $x2578 $x2580 $x2582 $x2584 $x2586) (- 1) 0)))
 (let (($x2610 (and c_3_18 in_target_3)))
 (let (($x3134 (or $x2600 $x2602 $x2604 $x2606 $x2608 $x2610)))
 (let ((?x3596 (ite $x3134 (- 2) 0)))
 (let (($x2577 (and c_3_0 in_target_3)))
 (let ((?x3605 (ite $x2577 (- 3) 0)))
 (let (($x3101 (and c_2_11 $x2319)))
 (let (($x3099 (and c_2_10 $x2319)))
 (let (($x3097 (and c_2_9 $x2319)))
 (let (($x3095 (and c_2_8 $x2319)))
 (let ((?x3092 (ite (or $x3094 $x3095 $x3097 $x3099 $x3101 $x3103) 3 0)))
 (let (($x3082 (and c_2_5 $x2319)))
 (let (($x3080 (and c_2_4 $x2319)))
 (let (($x3078 (and c_2_3 $x2319)))
 (let (($x3076 (and c_2_2 $x2319)))
 (let ((?x3073 (ite (or $x3075 $x3076 $x3078 $x3080 $x3082 $x3084) 2 0)))
 (let (($x3069 (and c_2_17 $x2319)))
 (let (($x3067 (and c_2_16 $x2319)))
 (let (($x3065 (and c_2_15 $x2319)))
 (let (($x3063 (and c_2_14 $x2319)))
 (let ((?x3572 (ite (or $x3061 $x3063 $x3065 $x3067 $x3069 $x3071) 1 0)))
 (let ((?x3566 (ite (or (and c_2_6 in_target_2) $x2525 $x2527 $x2529 $x2531 $x2533) (- 1) 0)))
 (let (($x2557 (and c_2_18 in_target_2)))
 (let (($x3041 (or $x2547 $x2549 $x2551 $x2553 $x2555 $x2557)))
 (let ((?x3554 (ite $x3041 (- 2) 0)))
 (let (($x2524 (and c_2_0 in_target_2)))
 (let ((?x3550 (ite $x2524 (- 3) 0)))
 (let (($x3008 (and c_1_11 $x2304)))
 (let (($x3006 (and c_1_10 $x2304)))
 (let (($x3004 (and c_1_9 $x2304)))
 (let (($x3002 (and c_1_8 $x2304)))
 (let ((?x2999 (ite (or $x3001 $x3002 $x3004 $x3006 $x3008 $x3010) 3 0)))
 (let (($x2989 (and c_1_5 $x2304)))
 (let (($x2987 (and c_1_4 $x2304)))
 (let (($x2985 (and c_1_3 $x2304)))
 (let (($x2983 (and c_1_2 $x2304)))
 (let ((?x2980 (ite (or $x2982 $x2983 $x2985 $x2987 $x2989 $x2991) 2 0)))
 (let (($x2976 (and c_1_17 $x2304)))
 (let (($x2974 (and c_1_16 $x2304)))
 (let (($x2972 (and c_1_15 $x2304)))
 (let (($x2970 (and c_1_14 $x2304)))
 (let ((?x3531 (ite (or $x2968 $x2970 $x2972 $x2974 $x2976 $x2978) 1 0)))
 (let ((?x3522 (ite (or (and c_1_6 in_target_1) $x2472 $x2474 $x2476 $x2478 $x2480) (- 1) 0)))
 (let (($x2504 (and c_1_18 in_target_1)))
 (let (($x2948 (or $x2494 $x2496 $x2498 $x2500 $x2502 $x2504)))
 (let ((?x3525 (ite $x2948 (- 2) 0)))
 (let (($x2471 (and c_1_0 in_target_1)))
 (let ((?x3514 (ite $x2471 (- 3) 0)))
 (let (($x2915 (and c_0_11 $x2291)))
 (let (($x2913 (and c_0_10 $x2291)))
 (let (($x2911 (and c_0_9 $x2291)))
 (let (($x2909 (and c_0_8 $x2291)))
 (let ((?x2906 (ite (or $x2908 $x2909 $x2911 $x2913 $x2915 $x2917) 3 0)))
 (let (($x2895 (and c_0_5 $x2291)))
 (let (($x2893 (and c_0_4 $x2291)))
 (let (($x2891 (and c_0_3 $x2291)))
 (let (($x2889 (and c_0_2 $x2291)))
 (let ((?x2886 (ite (or $x2888 $x2889 $x2891 $x2893 $x2895 $x2897) 2 0)))
 (let (($x2881 (and c_0_17 $x2291)))
 (let (($x2879 (and c_0_16 $x2291)))
 (let (($x2877 (and c_0_15 $x2291)))
 (let (($x2875 (and c_0_14 $x2291)))
 (let ((?x3490 (ite (or $x2873 $x2875 $x2877 $x2879 $x2881 $x2883) 1 0)))
 (let ((?x3482 (ite (or (and c_0_6 in_target_0) $x2419 $x2421 $x2423 $x2425 $x2427) (- 1) 0)))
 (let (($x2451 (and c_0_18 in_target_0)))
 (let (($x2853 (or $x2441 $x2443 $x2445 $x2447 $x2449 $x2451)))
 (let ((?x3475 (ite $x2853 (- 2) 0)))
 (let (($x2418 (and c_0_0 in_target_0)))
 (let ((?x3473 (ite $x2418 (- 3) 0)))
 (let ((?x3474 (+ 0 ?x3473)))
 (let ((?x3476 (+ ?x3474 ?x3475)))
 (let ((?x3485 (+ ?x3476 ?x3482)))
 (let ((?x3491 (+ ?x3485 ?x3490)))
 (let ((?x3492 (+ ?x3491 ?x2886)))
 (let ((?x3495 (+ ?x3492 ?x2906)))
 (let ((?x3509 (+ ?x3495 ?x3514)))
 (let ((?x3518 (+ ?x3509 ?x3525)))
 (let ((?x3513 (+ ?x3518 ?x3522)))
 (let ((?x3532 (+ ?x3513 ?x3531)))
 (let ((?x3536 (+ ?x3532 ?x2980)))
 (let ((?x3534 (+ ?x3536 ?x2999)))
 (let ((?x3562 (+ ?x3534 ?x3550)))
 (let ((?x3563 (+ ?x3562 ?x3554)))
 (let ((?x3555 (+ ?x3563 ?x3566)))
 (let ((?x3573 (+ ?x3555 ?x3572)))
 (let ((?x3576 (+ ?x3573 ?x3073)))
 (let ((?x3575 (+ ?x3576 ?x3092)))
 (let ((?x3601 (+ ?x3575 ?x3605)))
 (let ((?x3598 (+ ?x3601 ?x3596)))
 (let ((?x3609 (+ ?x3598 ?x3604)))
 (let ((?x3614 (+ ?x3609 ?x3613)))
 (let ((?x3616 (+ ?x3614 ?x3166)))
 (let ((?x3615 (+ ?x3616 ?x3185)))
 (let ((?x3636 (+ ?x3615 ?x3642)))
 (let ((?x3639 (+ ?x3636 ?x3632)))
 (let ((?x3650 (+ ?x3639 ?x3646)))
 (let ((?x3655 (+ ?x3650 ?x3654)))
 (let ((?x3659 (+ ?x3655 ?x3259)))
 (let ((?x3657 (+ ?x3659 ?x3278)))
 (let ((?x3682 (+ ?x3657 ?x3683)))
 (let ((?x3689 (+ ?x3682 ?x3685)))
 (let ((?x3673 (+ ?x3689 ?x3681)))
 (let ((?x3696 (+ ?x3673 ?x3695)))
 (let ((?x3697 (+ ?x3696 ?x3352)))
 (let (($x3726 (<= (+ ?x3697 ?x3371) 0)))
 (let (($x2380 (and c_5_12 in_target_5)))
 (let ((?x3333 (ite (or $x2380 $x2695 $x2697 $x2699 $x2701 $x2703 $x3340 $x3342 $x3344 $x3346 $x3348 $x3350) 1 0)))
 (let ((?x3310 (ite $x3320 (- 1) 0)))
 (let ((?x3303 (ite $x2683 (- 2) 0)))
 (let (($x2365 (and c_4_12 in_target_4)))
 (let ((?x3240 (ite (or $x2365 $x2642 $x2644 $x2646 $x2648 $x2650 $x3247 $x3249 $x3251 $x3253 $x3255 $x3257) 1 0)))
 (let ((?x3211 (ite $x3227 (- 1) 0)))
 (let ((?x3219 (ite $x2630 (- 2) 0)))
 (let (($x2350 (and c_3_12 in_target_3)))
 (let ((?x3147 (ite (or $x2350 $x2589 $x2591 $x2593 $x2595 $x2597 $x3154 $x3156 $x3158 $x3160 $x3162 $x3164) 1 0)))
 (let ((?x3127 (ite $x3134 (- 1) 0)))
 (let ((?x3125 (ite $x2577 (- 2) 0)))
 (let (($x2335 (and c_2_12 in_target_2)))
 (let ((?x3054 (ite (or $x2335 $x2536 $x2538 $x2540 $x2542 $x2544 $x3061 $x3063 $x3065 $x3067 $x3069 $x3071) 1 0)))
 (let ((?x3034 (ite $x3041 (- 1) 0)))
 (let ((?x3029 (ite $x2524 (- 2) 0)))
 (let (($x2320 (and c_1_12 in_target_1)))
 (let ((?x2961 (ite (or $x2320 $x2483 $x2485 $x2487 $x2489 $x2491 $x2968 $x2970 $x2972 $x2974 $x2976 $x2978) 1 0)))
 (let ((?x2933 (ite $x2948 (- 1) 0)))
 (let ((?x2931 (ite $x2471 (- 2) 0)))
 (let (($x2305 (and c_0_12 in_target_0)))
 (let ((?x2866 (ite (or $x2305 $x2430 $x2432 $x2434 $x2436 $x2438 $x2873 $x2875 $x2877 $x2879 $x2881 $x2883) 1 0)))
 (let ((?x2847 (ite $x2853 (- 1) 0)))
 (let ((?x2839 (ite $x2418 (- 2) 0)))
 (let ((?x2840 (+ 0 ?x2839)))
 (let ((?x2848 (+ ?x2840 ?x2847)))
 (let ((?x2867 (+ ?x2848 ?x2866)))
 (let ((?x2887 (+ ?x2867 ?x2886)))
 (let ((?x2907 (+ ?x2887 ?x2906)))
 (let ((?x2943 (+ ?x2907 ?x2931)))
 (let ((?x2934 (+ ?x2943 ?x2933)))
 (let ((?x2962 (+ ?x2934 ?x2961)))
 (let ((?x2981 (+ ?x2962 ?x2980)))
 (let ((?x3000 (+ ?x2981 ?x2999)))
 (let ((?x3027 (+ ?x3000 ?x3029)))
 (let ((?x3032 (+ ?x3027 ?x3034)))
 (let ((?x3055 (+ ?x3032 ?x3054)))
 (let ((?x3074 (+ ?x3055 ?x3073)))
 (let ((?x3093 (+ ?x3074 ?x3092)))
 (let ((?x3121 (+ ?x3093 ?x3125)))
 (let ((?x3130 (+ ?x3121 ?x3127)))
 (let ((?x3148 (+ ?x3130 ?x3147)))
 (let ((?x3167 (+ ?x3148 ?x3166)))
 (let ((?x3186 (+ ?x3167 ?x3185)))
 (let ((?x3210 (+ ?x3186 ?x3219)))
 (let ((?x3209 (+ ?x3210 ?x3211)))
 (let ((?x3241 (+ ?x3209 ?x3240)))
 (let ((?x3260 (+ ?x3241 ?x3259)))
 (let ((?x3279 (+ ?x3260 ?x3278)))
 (let ((?x3312 (+ ?x3279 ?x3303)))
 (let ((?x3304 (+ ?x3312 ?x3310)))
 (let ((?x3334 (+ ?x3304 ?x3333)))
 (let ((?x3353 (+ ?x3334 ?x3352)))
 (let (($x3396 (>= (+ ?x3353 ?x3371) 0)))
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
 (let (($x2378 (and c_5_6 in_target_5)))
 (let (($x2717 (or $x2378 $x2380 $x2683 $x2684 $x2686 $x2688 $x2690 $x2692 $x2695 $x2697 $x2699 $x2701 $x2703 $x2706 $x2708 $x2710 $x2712 $x2714 $x2716)))
 (let (($x2363 (and c_4_6 in_target_4)))
 (let (($x2664 (or $x2363 $x2365 $x2630 $x2631 $x2633 $x2635 $x2637 $x2639 $x2642 $x2644 $x2646 $x2648 $x2650 $x2653 $x2655 $x2657 $x2659 $x2661 $x2663)))
 (let (($x2348 (and c_3_6 in_target_3)))
 (let (($x2611 (or $x2348 $x2350 $x2577 $x2578 $x2580 $x2582 $x2584 $x2586 $x2589 $x2591 $x2593 $x2595 $x2597 $x2600 $x2602 $x2604 $x2606 $x2608 $x2610)))
 (let (($x2333 (and c_2_6 in_target_2)))
 (let (($x2558 (or $x2333 $x2335 $x2524 $x2525 $x2527 $x2529 $x2531 $x2533 $x2536 $x2538 $x2540 $x2542 $x2544 $x2547 $x2549 $x2551 $x2553 $x2555 $x2557)))
 (let (($x2318 (and c_1_6 in_target_1)))
 (let (($x2505 (or $x2318 $x2320 $x2471 $x2472 $x2474 $x2476 $x2478 $x2480 $x2483 $x2485 $x2487 $x2489 $x2491 $x2494 $x2496 $x2498 $x2500 $x2502 $x2504)))
 (let (($x2303 (and c_0_6 in_target_0)))
 (let (($x2452 (or $x2303 $x2305 $x2418 $x2419 $x2421 $x2423 $x2425 $x2427 $x2430 $x2432 $x2434 $x2436 $x2438 $x2441 $x2443 $x2445 $x2447 $x2449 $x2451)))
 (let (($x2731 (or false $x2452)))
 (let (($x2748 (or $x2731 $x2505)))
 (let (($x2767 (or $x2748 $x2558)))
 (let (($x2783 (or $x2767 $x2611)))
 (let (($x2799 (or $x2783 $x2664)))
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
 (let (($x2835 (and (and $x2823 (=> $x2831 (or $x2826 (and $x2558 (< rank_4 rank_10))))) (=> (or $x2799 $x2717) (or $x2800 root_11)))))
 (let (($x2837 (and $x2835 (<= (+ ?x2802 ?x2820) 1))))
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
 (let (($x3791 (and $x2375 (and (and $x2837 $x3396) $x3726))))
 (let (($x3800 (and $x3791 (not (and (and true $x3796) $x3799)))))
 (let (($x3809 (and $x3800 (not (and (and true $x3805) $x3808)))))
 (let (($x3818 (and $x3809 (not (and $x3812 $x3817)))))
 (let (($x3827 (and $x3818 (not (and $x3821 $x3826)))))
 (let (($x3832 (and $x3827 (not (and (and true $x3796) $x3831)))))
 (let (($x3835 (and $x3832 (not (and (and true $x3805) $x3817)))))
 (let (($x3842 (and $x3835 (not (and $x3838 $x3826)))))
 (let (($x3847 (and $x3842 (not (and (and true $x3805) $x3846)))))
 (let (($x3850 (and $x3847 (not (and $x3838 $x3799)))))
 (let (($x3853 (and $x3850 (not (and $x3821 $x3831)))))
 (let (($x3860 (and $x3853 (not (and $x3856 $x3817)))))
 (let (($x3863 (and $x3860 (not (and $x3812 $x3846)))))
 (let (($x3866 (and $x3863 (not (and $x3821 $x3799)))))
 (let (($x3869 (and $x3866 (not (and $x3856 $x3808)))))
 (let (($x3885 (and $x3869 (not (and (and true $x3796) $x3892)))))
 (let (($x3899 (and $x3885 (not (and (and true $x3805) $x3907)))))
 (let (($x3919 (and $x3899 (not (and $x3812 $x3922)))))
 (let (($x3931 (and $x3919 (not (and $x3821 $x3937)))))
 (let (($x3949 (and $x3931 (not (and (and true $x3796) $x3952)))))
 (let (($x3953 (and $x3949 (not (and (and true $x3805) $x3922)))))
 (let (($x3944 (and $x3953 (not (and $x3838 $x3937)))))
 (let (($x3972 (and $x3944 (not (and (and true $x3805) $x3973)))))
 (let (($x3970 (and $x3972 (not (and $x3838 $x3892)))))
 (let (($x3977 (and $x3970 (not (and $x3821 $x3952)))))
 (let (($x3980 (and $x3977 (not (and $x3856 $x3922)))))
 (let (($x3985 (and $x3980 (not (and $x3812 $x3973)))))
 (let (($x3983 (and $x3985 (not (and $x3821 $x3892)))))
 (let (($x3982 (and $x3983 (not (and $x3856 $x3907)))))
 (let (($x3991 (and $x3982 (not (and (and true $x3796) $x3987)))))
 (let (($x3993 (and $x3991 (not (and (and true $x3805) $x3992)))))
 (let (($x3998 (and $x3993 (not (and $x3812 $x3997)))))
 (let (($x4003 (and $x3998 (not (and $x3821 $x4002)))))
 (let (($x4008 (and $x4003 (not (and (and true $x3796) $x4007)))))
 (let (($x4011 (and $x4008 (not (and (and true $x3805) $x3997)))))
 (let (($x4014 (and $x4011 (not (and $x3838 $x4002)))))
 (let (($x4019 (and $x4014 (not (and (and true $x3805) $x4018)))))
 (let (($x4022 (and $x4019 (not (and $x3838 $x3987)))))
 (let (($x4025 (and $x4022 (not (and $x3821 $x4007)))))
 (let (($x4028 (and $x4025 (not (and $x3856 $x3997)))))
 (let (($x4031 (and $x4028 (not (and $x3812 $x4018)))))
 (let (($x4034 (and $x4031 (not (and $x3821 $x3987)))))
 (let (($x4037 (and $x4034 (not (and $x3856 $x3992)))))
 (let (($x4055 (and $x4037 (not (and (and true $x4060) $x4056)))))
 (let (($x4078 (and $x4055 (not (and (and true $x4079) $x4076)))))
 (let (($x4095 (and $x4078 (not (and (and true $x4098) $x4089)))))
 (let (($x4113 (and $x4095 (not (and (and true $x4117) $x4115)))))
 (let (($x4121 (and $x4113 (not (and (and true $x4060) $x4116)))))
 (let (($x4126 (and $x4121 (not (and (and true $x4079) $x4089)))))
 (let (($x4137 (and $x4126 (not (and (and true $x4145) $x4115)))))
 (let (($x4147 (and $x4137 (not (and (and true $x4079) $x4148)))))
 (let (($x4154 (and $x4147 (not (and (and true $x4145) $x4056)))))
 (let (($x4151 (and $x4154 (not (and (and true $x4117) $x4116)))))
 (let (($x4164 (and $x4151 (not (and (and true $x4173) $x4089)))))
 (let (($x4169 (and $x4164 (not (and (and true $x4098) $x4148)))))
 (let (($x4175 (and $x4169 (not (and (and true $x4117) $x4056)))))
 (let (($x4172 (and $x4175 (not (and (and true $x4173) $x4076)))))
 (let (($x4181 (and $x4172 (not (and (and true c_0_12) $x2471)))))
 (let (($x4180 (and $x4181 (not (and (and true c_1_12) $x2524)))))
 (let (($x4187 (and $x4180 (not (and (and true c_3_12) $x2630)))))
 (let (($x4191 (and $x4187 (not (and (and true c_4_12) $x2683)))))
 (let (($x4194 (and $x4191 (not (and (and true c_0_12) $x2577)))))
 (let (($x4197 (and $x4194 (not (and (and true c_1_12) $x2630)))))
 (let (($x4201 (and $x4197 (not (and (and true c_2_12) $x2683)))))
 (let (($x4204 (and $x4201 (not (and (and true c_1_12) $x2418)))))
 (let (($x4207 (and $x4204 (not (and (and true c_2_12) $x2471)))))
 (let (($x4210 (and $x4207 (not (and (and true c_4_12) $x2577)))))
 (let (($x4214 (and $x4210 (not (and (and true c_5_12) $x2630)))))
 (let (($x4217 (and $x4214 (not (and (and true c_3_12) $x2418)))))
 (let (($x4220 (and $x4217 (not (and (and true c_4_12) $x2471)))))
 (let (($x4223 (and $x4220 (not (and (and true c_5_12) $x2524)))))
 (let (($x4233 (and $x4223 (not (and $x4229 c_1_18)))))
 (let (($x4240 (and $x4233 (not (and $x4239 c_2_18)))))
 (let (($x4250 (and $x4240 (not (and $x4249 c_4_18)))))
 (let (($x4261 (and $x4250 (not (and $x4259 c_5_18)))))
 (let (($x4267 (and $x4261 (not (and $x4229 c_3_18)))))
 (let (($x4270 (and $x4267 (not (and $x4239 c_4_18)))))
 (let (($x4278 (and $x4270 (not (and $x4275 c_5_18)))))
 (let (($x4283 (and $x4278 (not (and $x4239 c_0_18)))))
 (let (($x4284 (and $x4283 (not (and $x4275 c_1_18)))))
 (let (($x4290 (and $x4284 (not (and $x4259 c_3_18)))))
 (let (($x4296 (and $x4290 (not (and $x4294 c_4_18)))))
 (let (($x4301 (and $x4296 (not (and $x4249 c_0_18)))))
 (let (($x4306 (and $x4301 (not (and $x4259 c_1_18)))))
 (let (($x4308 (and $x4306 (not (and $x4294 c_2_18)))))
 (let (($x4343 (and $x4308 (not (and (and $x4307 $x4319) $x4340)))))
 (let (($x4381 (and $x4343 (not (and (and $x4344 $x4355) $x4378)))))
 (let (($x4413 (and $x4381 (not (and (and $x4382 $x4393) $x4410)))))
 (let (($x4449 (and $x4413 (not (and (and $x4414 $x4425) $x4446)))))
 (let (($x4455 (and $x4449 (not (and $x4454 $x4340)))))
 (let (($x4461 (and $x4455 (not (and (and $x4344 $x4393) $x4378)))))
 (let (($x4487 (and $x4461 (not (and (and $x4462 $x4425) $x4484)))))
 (let (($x4496 (and $x4487 (not (and $x4492 $x4378)))))
 (let (($x4501 (and $x4496 (not (and $x4493 $x4484)))))
 (let (($x4502 (and $x4501 (not (and (and $x4414 $x4459) $x4446)))))
 (let (($x4527 (and $x4502 (not (and (and $x4504 $x4393) $x4524)))))
 (let (($x4532 (and $x4527 (not (and $x4528 $x4410)))))
 (let (($x4536 (and $x4532 (not (and $x4529 $x4446)))))
 (let (($x4537 (and $x4536 (not (and $x4535 $x4524)))))
 (let (($x4549 (and $x4537 (not (and (and $x4543 $x4319) $x4340)))))
 (let (($x4554 (and $x4549 (not (and (and $x4552 $x4355) $x4378)))))
 (let (($x4565 (and $x4554 (not (and (and $x4561 $x4393) $x4410)))))
 (let (($x4576 (and $x4565 (not (and (and $x4570 $x4425) $x4446)))))
 (let (($x4578 (and $x4576 (not (and $x4575 $x4340)))))
 (let (($x4582 (and $x4578 (not (and (and $x4552 $x4393) $x4378)))))
 (let (($x4593 (and $x4582 (not (and $x4589 $x4484)))))
 (let (($x4597 (and $x4593 (not (and $x4592 $x4378)))))
 (let (($x4601 (and $x4597 (not (and $x4594 $x4484)))))
 (let (($x4602 (and $x4601 (not (and (and $x4570 $x4459) $x4446)))))
 (let (($x4612 (and $x4602 (not (and $x4609 $x4524)))))
 (let (($x4618 (and $x4612 (not (and $x4613 $x4410)))))
 (let (($x4622 (and $x4618 (not (and $x4616 $x4446)))))
 (let (($x4623 (and $x4622 (not (and $x4621 $x4524)))))
 (let (($x4628 (and $x4623 (not (and $x4229 $x4319)))))
 (let (($x4632 (and $x4628 (not (and $x4239 $x4355)))))
 (let (($x4635 (and $x4632 (not (and $x4249 $x4393)))))
 (let (($x4639 (and $x4635 (not (and $x4259 $x4425)))))
 (let (($x4637 (and $x4639 (not (and $x4229 $x4459)))))
 (let (($x4645 (and $x4637 (not (and $x4239 $x4393)))))
 (let (($x4642 (and $x4645 (not (and $x4275 $x4425)))))
 (let (($x4650 (and $x4642 (not (and $x4239 $x4497)))))
 (let (($x4652 (and $x4650 (not (and $x4275 $x4319)))))
 (let (($x4653 (and $x4652 (not (and $x4259 $x4459)))))
 (let (($x4660 (and $x4653 (not (and $x4294 $x4393)))))
 (let (($x4661 (and $x4660 (not (and $x4249 $x4497)))))
 (let (($x4665 (and $x4661 (not (and $x4259 $x4319)))))
 (let (($x4668 (and $x4665 (not (and $x4294 $x4355)))))
 (and $x4668 $x5653))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
