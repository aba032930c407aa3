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
(declare-fun in_target_8 () Bool)
(declare-fun in_target_7 () Bool)
(declare-fun in_target_6 () Bool)
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
 (let (($x4752 (>= rank_12 0)))
 (and $x4752 (< rank_12 6))))
(assert
 (let (($x4757 (>= rank_14 0)))
 (and $x4757 (< rank_14 6))))
(assert
 (let (($x4762 (>= rank_16 0)))
 (and $x4762 (< rank_16 6))))
(assert
 (let (($x4767 (>= rank_18 0)))
 (and $x4767 (< rank_18 6))))
(assert
 (let (($x4772 (>= rank_20 0)))
 (and $x4772 (< rank_20 6))))
(assert
 (let (($x4777 (>= rank_22 0)))
 (and $x4777 (< rank_22 6))))
(assert
 (let (($x4942 (>= prank_24 0)))
 (and $x4942 (< prank_24 6))))
(assert
 (let (($x4934 (>= prank_25 0)))
 (and $x4934 (< prank_25 6))))
(assert
 (let (($x4949 (>= prank_26 0)))
 (and $x4949 (< prank_26 6))))
(assert
 (let (($x4953 (>= prank_27 0)))
 (and $x4953 (< prank_27 6))))
(assert
 (let (($x4957 (>= prank_28 0)))
 (and $x4957 (< prank_28 6))))
(assert
 (let (($x4961 (>= prank_29 0)))
 (and $x4961 (< prank_29 6))))
(assert
 (let (($x5180 (>= prank_32 0)))
 (and $x5180 (< prank_32 6))))
(assert
 (let (($x5197 (>= prank_33 0)))
 (and $x5197 (< prank_33 6))))
(assert
 (let (($x5199 (>= prank_34 0)))
 (and $x5199 (< prank_34 6))))
(assert
 (let (($x5201 (>= prank_35 0)))
 (and $x5201 (< prank_35 6))))
(assert
 (let (($x5207 (>= prank_36 0)))
 (and $x5207 (< prank_36 6))))
(assert
 (let (($x5211 (>= prank_37 0)))
 (and $x5211 (< prank_37 6))))
(assert
 (let (($x5464 (>= rank_40 0)))
 (and $x5464 (< rank_40 6))))
(assert
 (let (($x5463 (>= rank_42 0)))
 (and $x5463 (< rank_42 6))))
(assert
 (let (($x5441 (>= rank_44 0)))
 (and $x5441 (< rank_44 6))))
(assert
 (let (($x5469 (>= rank_46 0)))
 (and $x5469 (< rank_46 6))))
(assert
 (let (($x5474 (>= rank_48 0)))
 (and $x5474 (< rank_48 6))))
(assert
 (let (($x5479 (>= rank_50 0)))
 (and $x5479 (< rank_50 6))))
(assert
 (let ((?x5732 (ite (or c_2_1 c_2_3 c_2_7 c_2_9 c_2_13 c_2_15) 1 0)))
 (let ((?x5725 (ite (or c_4_1 c_4_2 c_4_7 c_4_8 c_4_13 c_4_14) 1 0)))
 (let ((?x4288 (ite false 1 0)))
 (let ((?x4434 (+ 0 ?x4288)))
 (let ((?x4476 (+ ?x4434 ?x4288)))
 (let ((?x5731 (+ ?x4476 ?x5725)))
 (let (($x4580 (or c_5_14 c_5_15 c_5_16 c_5_17)))
 (let ((?x5712 (ite (or c_1_1 c_1_3 c_1_7 c_1_9 c_1_13 c_1_15) 1 0)))
 (let ((?x5708 (ite (or c_3_1 c_3_2 c_3_7 c_3_8 c_3_13 c_3_14) 1 0)))
 (let ((?x5698 (ite (or c_5_1 c_5_4 c_5_7 c_5_10 c_5_13 c_5_16) 1 0)))
 (let ((?x5709 (+ 0 ?x5698)))
 (let ((?x5707 (+ ?x5709 ?x4288)))
 (let ((?x5710 (+ ?x5707 ?x5708)))
 (let (($x4542 (or c_4_14 c_4_15 c_4_16 c_4_17)))
 (let (($x5716 (and $x4542 (> (to_real (+ ?x5710 ?x5712)) 0.0))))
 (let ((?x5683 (ite (or c_0_1 c_0_3 c_0_7 c_0_9 c_0_13 c_0_15) 1 0)))
 (let ((?x5679 (ite (or c_4_1 c_4_4 c_4_7 c_4_10 c_4_13 c_4_16) 1 0)))
 (let ((?x5682 (+ 0 ?x5679)))
 (let ((?x5681 (+ ?x5682 ?x4288)))
 (let ((?x5684 (+ ?x5681 ?x4288)))
 (let (($x4533 (or c_3_14 c_3_15 c_3_16 c_3_17)))
 (let (($x5689 (and $x4533 (> (to_real (+ ?x5684 ?x5683)) 0.0))))
 (let ((?x5662 (ite (or c_1_1 c_1_2 c_1_7 c_1_8 c_1_13 c_1_14) 1 0)))
 (let ((?x5659 (ite (or c_5_1 c_5_5 c_5_7 c_5_11 c_5_13 c_5_17) 1 0)))
 (let ((?x5656 (+ ?x4434 ?x5659)))
 (let ((?x5661 (+ ?x5656 ?x5662)))
 (let (($x4559 (or c_2_14 c_2_15 c_2_16 c_2_17)))
 (let (($x5667 (and $x4559 (> (to_real (+ ?x5661 ?x4288)) 0.0))))
 (let ((?x5639 (ite (or c_0_1 c_0_2 c_0_7 c_0_8 c_0_13 c_0_14) 1 0)))
 (let ((?x5634 (ite (or c_4_1 c_4_5 c_4_7 c_4_11 c_4_13 c_4_17) 1 0)))
 (let ((?x5637 (ite (or c_2_1 c_2_4 c_2_7 c_2_10 c_2_13 c_2_16) 1 0)))
 (let ((?x5641 (+ 0 ?x5637)))
 (let ((?x5640 (+ ?x5641 ?x5634)))
 (let ((?x5643 (+ ?x5640 ?x5639)))
 (let (($x4524 (or c_1_14 c_1_15 c_1_16 c_1_17)))
 (let (($x5647 (and $x4524 (> (to_real (+ ?x5643 ?x4288)) 0.0))))
 (let ((?x5613 (ite (or c_3_1 c_3_5 c_3_7 c_3_11 c_3_13 c_3_17) 1 0)))
 (let ((?x5607 (ite (or c_1_1 c_1_4 c_1_7 c_1_10 c_1_13 c_1_16) 1 0)))
 (let ((?x5614 (+ 0 ?x5607)))
 (let ((?x5615 (+ ?x5614 ?x5613)))
 (let ((?x5612 (+ ?x5615 ?x4288)))
 (let (($x4515 (or c_0_14 c_0_15 c_0_16 c_0_17)))
 (let (($x5620 (and $x4515 (> (to_real (+ ?x5612 ?x4288)) 0.0))))
 (let (($x5621 (or false $x5620)))
 (let (($x5648 (or $x5621 $x5647)))
 (let (($x5668 (or $x5648 $x5667)))
 (let (($x5690 (or $x5668 $x5689)))
 (let (($x5717 (or $x5690 $x5716)))
 (let (($x5589 (or false c_0_13)))
 (let (($x5591 (or $x5589 c_1_13)))
 (let (($x5593 (or $x5591 c_2_13)))
 (let (($x5595 (or $x5593 c_3_13)))
 (let (($x5597 (or $x5595 c_4_13)))
 (let ((?x5570 (ite root_51 1 0)))
 (let ((?x5551 (ite root_49 1 0)))
 (let ((?x5535 (ite root_47 1 0)))
 (let ((?x5519 (ite root_45 1 0)))
 (let ((?x5500 (ite root_43 1 0)))
 (let ((?x5484 (ite root_41 1 0)))
 (let ((?x5485 (+ 0 ?x5484)))
 (let ((?x5501 (+ ?x5485 ?x5500)))
 (let ((?x5520 (+ ?x5501 ?x5519)))
 (let ((?x5536 (+ ?x5520 ?x5535)))
 (let ((?x5552 (+ ?x5536 ?x5551)))
 (let (($x5483 (or false root_41)))
 (let (($x5499 (or $x5483 root_43)))
 (let (($x5518 (or $x5499 root_45)))
 (let (($x5534 (or $x5518 root_47)))
 (let (($x5550 (or $x5534 root_49)))
 (let (($x5468 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_13 c_5_14 c_5_15 c_5_16 c_5_17 c_5_18)))
 (let (($x5454 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_13 c_4_14 c_4_15 c_4_16 c_4_17 c_4_18)))
 (let (($x5440 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_13 c_3_14 c_3_15 c_3_16 c_3_17 c_3_18)))
 (let (($x5426 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_13 c_2_14 c_2_15 c_2_16 c_2_17 c_2_18)))
 (let (($x5412 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_13 c_1_14 c_1_15 c_1_16 c_1_17 c_1_18)))
 (let (($x5398 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_13 c_0_14 c_0_15 c_0_16 c_0_17 c_0_18)))
 (let (($x5482 (or false $x5398)))
 (let (($x5498 (or $x5482 $x5412)))
 (let (($x5517 (or $x5498 $x5426)))
 (let (($x5533 (or $x5517 $x5440)))
 (let (($x5549 (or $x5533 $x5454)))
 (let (($x5576 (or false (and $x5454 (< rank_48 rank_50)))))
 (let (($x5580 (not root_51)))
 (let (($x5581 (and $x5468 $x5580)))
 (let (($x5557 (or false (and $x5468 (< rank_50 rank_48)))))
 (let (($x5560 (or $x5557 (and $x5440 (< rank_46 rank_48)))))
 (let (($x5564 (not root_49)))
 (let (($x5565 (and $x5454 $x5564)))
 (let (($x5541 (or false (and $x5454 (< rank_48 rank_46)))))
 (let (($x5545 (not root_47)))
 (let (($x5546 (and $x5440 $x5545)))
 (let (($x5525 (or false (and $x5468 (< rank_50 rank_44)))))
 (let (($x5529 (not root_45)))
 (let (($x5530 (and $x5426 $x5529)))
 (let (($x5506 (or false (and $x5426 (< rank_44 rank_42)))))
 (let (($x5509 (or $x5506 (and $x5454 (< rank_48 rank_42)))))
 (let (($x5513 (not root_43)))
 (let (($x5514 (and $x5412 $x5513)))
 (let (($x5490 (or false (and $x5412 (< rank_42 rank_40)))))
 (let (($x5494 (not root_41)))
 (let (($x5495 (and $x5398 $x5494)))
 (let (($x5487 (and true (=> root_41 $x5398))))
 (let (($x5497 (and $x5487 (=> $x5495 (or $x5490 (and $x5440 (< rank_46 rank_40)))))))
 (let (($x5503 (and $x5497 (=> root_43 $x5412))))
 (let (($x5516 (and $x5503 (=> $x5514 (or $x5509 (and $x5398 (< rank_40 rank_42)))))))
 (let (($x5522 (and $x5516 (=> root_45 $x5426))))
 (let (($x5532 (and $x5522 (=> $x5530 (or $x5525 (and $x5412 (< rank_42 rank_44)))))))
 (let (($x5538 (and $x5532 (=> root_47 $x5440))))
 (let (($x5548 (and $x5538 (=> $x5546 (or $x5541 (and $x5398 (< rank_40 rank_46)))))))
 (let (($x5554 (and $x5548 (=> root_49 $x5454))))
 (let (($x5567 (and $x5554 (=> $x5565 (or $x5560 (and $x5412 (< rank_42 rank_48)))))))
 (let (($x5573 (and $x5567 (=> root_51 $x5468))))
 (let (($x5585 (and (and $x5573 (=> $x5581 (or $x5576 (and $x5426 (< rank_44 rank_50))))) (=> (or $x5549 $x5468) (or $x5550 root_51)))))
 (let (($x5587 (and $x5585 (<= (+ ?x5552 ?x5570) 1))))
 (let (($x4065 (or c_5_1 c_5_7 c_5_13)))
 (let (($x5362 (and $x4065 (= prank_37 prank_high_39))))
 (let (($x4035 (or c_4_1 c_4_7 c_4_13)))
 (let (($x5339 (and $x4035 (= prank_36 prank_high_39))))
 (let (($x4066 (or c_3_1 c_3_7 c_3_13)))
 (let (($x5311 (and $x4066 (= prank_35 prank_high_39))))
 (let (($x4005 (or c_2_1 c_2_7 c_2_13)))
 (let (($x5288 (and $x4005 (= prank_34 prank_high_39))))
 (let (($x3982 (or c_1_1 c_1_7 c_1_13)))
 (let (($x5265 (and $x3982 (= prank_33 prank_high_39))))
 (let (($x4100 (or c_0_1 c_0_7 c_0_13)))
 (let (($x5237 (and $x4100 (= prank_32 prank_high_39))))
 (let (($x5238 (or false $x5237)))
 (let (($x5266 (or $x5238 $x5265)))
 (let (($x5289 (or $x5266 $x5288)))
 (let (($x5312 (or $x5289 $x5311)))
 (let (($x5340 (or $x5312 $x5339)))
 (let (($x5359 (and $x4065 (= prank_37 prank_low_38))))
 (let (($x5336 (and $x4035 (= prank_36 prank_low_38))))
 (let (($x5308 (and $x4066 (= prank_35 prank_low_38))))
 (let (($x5285 (and $x4005 (= prank_34 prank_low_38))))
 (let (($x5262 (and $x3982 (= prank_33 prank_low_38))))
 (let (($x5234 (and $x4100 (= prank_32 prank_low_38))))
 (let (($x5235 (or false $x5234)))
 (let (($x5263 (or $x5235 $x5262)))
 (let (($x5286 (or $x5263 $x5285)))
 (let (($x5309 (or $x5286 $x5308)))
 (let (($x5337 (or $x5309 $x5336)))
 (let (($x5365 (=> (or (or (or (or (or (or false $x4100) $x3982) $x4005) $x4066) $x4035) $x4065) (and (or $x5337 $x5359) (or $x5340 $x5362)))))
 (let (($x5167 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_14 c_2_15 c_2_16 c_2_17 c_2_18)))
 (let (($x5191 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_14 c_4_15 c_4_16 c_4_17 c_4_18)))
 (let (($x5345 (or false (and true (or $x5191 (and $x4035 (< prank_36 prank_37)))))))
 (let (($x5352 (and (or $x5345 (and true (or $x5167 (and $x4005 (< prank_34 prank_37))))) (<= prank_low_38 prank_37))))
 (let (($x5155 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_14 c_1_15 c_1_16 c_1_17 c_1_18)))
 (let (($x5179 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_14 c_3_15 c_3_16 c_3_17 c_3_18)))
 (let (($x5203 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_14 c_5_15 c_5_16 c_5_17 c_5_18)))
 (let (($x5317 (or false (and true (or $x5203 (and $x4065 (< prank_37 prank_36)))))))
 (let (($x5322 (or $x5317 (and true (or $x5179 (and $x4066 (< prank_35 prank_36)))))))
 (let (($x5329 (and (or $x5322 (and true (or $x5155 (and $x3982 (< prank_33 prank_36))))) (<= prank_low_38 prank_36))))
 (let (($x5143 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_14 c_0_15 c_0_16 c_0_17 c_0_18)))
 (let (($x5294 (or false (and true (or $x5191 (and $x4035 (< prank_36 prank_35)))))))
 (let (($x5301 (and (or $x5294 (and true (or $x5143 (and $x4100 (< prank_32 prank_35))))) (<= prank_low_38 prank_35))))
 (let (($x5271 (or false (and true (or $x5203 (and $x4065 (< prank_37 prank_34)))))))
 (let (($x5278 (and (or $x5271 (and true (or $x5155 (and $x3982 (< prank_33 prank_34))))) (<= prank_low_38 prank_34))))
 (let (($x5243 (or false (and true (or $x5167 (and $x4005 (< prank_34 prank_33)))))))
 (let (($x5248 (or $x5243 (and true (or $x5191 (and $x4035 (< prank_36 prank_33)))))))
 (let (($x5255 (and (or $x5248 (and true (or $x5143 (and $x4100 (< prank_32 prank_33))))) (<= prank_low_38 prank_33))))
 (let (($x5220 (or false (and true (or $x5155 (and $x3982 (< prank_33 prank_32)))))))
 (let (($x5227 (and (or $x5220 (and true (or $x5179 (and $x4066 (< prank_35 prank_32))))) (<= prank_low_38 prank_32))))
 (let (($x5231 (and true (=> $x4100 (and $x5227 (<= prank_32 prank_high_39))))))
 (let (($x5259 (and $x5231 (=> $x3982 (and $x5255 (<= prank_33 prank_high_39))))))
 (let (($x5282 (and $x5259 (=> $x4005 (and $x5278 (<= prank_34 prank_high_39))))))
 (let (($x5305 (and $x5282 (=> $x4066 (and $x5301 (<= prank_35 prank_high_39))))))
 (let (($x5333 (and $x5305 (=> $x4035 (and $x5329 (<= prank_36 prank_high_39))))))
 (let (($x5356 (and $x5333 (=> $x4065 (and $x5352 (<= prank_37 prank_high_39))))))
 (let (($x5366 (and $x5356 $x5365)))
 (let (($x4142 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_8 c_5_9 c_5_10 c_5_11 c_5_14 c_5_15 c_5_16 c_5_17)))
 (let (($x5112 (and $x4142 (= prank_29 prank_high_31))))
 (let (($x4069 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_8 c_4_9 c_4_10 c_4_11 c_4_14 c_4_15 c_4_16 c_4_17)))
 (let (($x5089 (and $x4069 (= prank_28 prank_high_31))))
 (let (($x4042 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_8 c_3_9 c_3_10 c_3_11 c_3_14 c_3_15 c_3_16 c_3_17)))
 (let (($x5061 (and $x4042 (= prank_27 prank_high_31))))
 (let (($x4106 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_8 c_2_9 c_2_10 c_2_11 c_2_14 c_2_15 c_2_16 c_2_17)))
 (let (($x5038 (and $x4106 (= prank_26 prank_high_31))))
 (let (($x4015 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_8 c_1_9 c_1_10 c_1_11 c_1_14 c_1_15 c_1_16 c_1_17)))
 (let (($x5015 (and $x4015 (= prank_25 prank_high_31))))
 (let (($x3988 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_8 c_0_9 c_0_10 c_0_11 c_0_14 c_0_15 c_0_16 c_0_17)))
 (let (($x4987 (and $x3988 (= prank_24 prank_high_31))))
 (let (($x4988 (or false $x4987)))
 (let (($x5016 (or $x4988 $x5015)))
 (let (($x5039 (or $x5016 $x5038)))
 (let (($x5062 (or $x5039 $x5061)))
 (let (($x5090 (or $x5062 $x5089)))
 (let (($x5109 (and $x4142 (= prank_29 prank_low_30))))
 (let (($x5086 (and $x4069 (= prank_28 prank_low_30))))
 (let (($x5058 (and $x4042 (= prank_27 prank_low_30))))
 (let (($x5035 (and $x4106 (= prank_26 prank_low_30))))
 (let (($x5012 (and $x4015 (= prank_25 prank_low_30))))
 (let (($x4984 (and $x3988 (= prank_24 prank_low_30))))
 (let (($x4985 (or false $x4984)))
 (let (($x5013 (or $x4985 $x5012)))
 (let (($x5036 (or $x5013 $x5035)))
 (let (($x5059 (or $x5036 $x5058)))
 (let (($x5087 (or $x5059 $x5086)))
 (let (($x5115 (=> (or (or (or (or (or (or false $x3988) $x4015) $x4106) $x4042) $x4069) $x4142) (and (or $x5087 $x5109) (or $x5090 $x5112)))))
 (let (($x3760 (or c_2_6 c_2_12 c_2_18)))
 (let (($x4445 (or c_5_5 c_5_11 c_5_17)))
 (let (($x3742 (or c_4_6 c_4_12 c_4_18)))
 (let (($x4401 (or c_5_4 c_5_10 c_5_16)))
 (let (($x5095 (or false (and $x4401 (or $x3742 (and $x4069 (< prank_28 prank_29)))))))
 (let (($x5102 (and (or $x5095 (and $x4445 (or $x3760 (and $x4106 (< prank_26 prank_29))))) (<= prank_low_30 prank_29))))
 (let (($x3722 (or c_1_6 c_1_12 c_1_18)))
 (let (($x4337 (or c_4_5 c_4_11 c_4_17)))
 (let (($x3732 (or c_3_6 c_3_12 c_3_18)))
 (let (($x4368 (or c_4_4 c_4_10 c_4_16)))
 (let (($x3779 (or c_5_6 c_5_12 c_5_18)))
 (let (($x4484 (or c_4_2 c_4_8 c_4_14)))
 (let (($x5067 (or false (and $x4484 (or $x3779 (and $x4142 (< prank_29 prank_28)))))))
 (let (($x5072 (or $x5067 (and $x4368 (or $x3732 (and $x4042 (< prank_27 prank_28)))))))
 (let (($x5079 (and (or $x5072 (and $x4337 (or $x3722 (and $x4015 (< prank_25 prank_28))))) (<= prank_low_30 prank_28))))
 (let (($x3712 (or c_0_6 c_0_12 c_0_18)))
 (let (($x4302 (or c_3_5 c_3_11 c_3_17)))
 (let (($x4403 (or c_3_2 c_3_8 c_3_14)))
 (let (($x5044 (or false (and $x4403 (or $x3742 (and $x4069 (< prank_28 prank_27)))))))
 (let (($x5051 (and (or $x5044 (and $x4302 (or $x3712 (and $x3988 (< prank_24 prank_27))))) (<= prank_low_30 prank_27))))
 (let (($x4333 (or c_2_4 c_2_10 c_2_16)))
 (let (($x4487 (or c_2_3 c_2_9 c_2_15)))
 (let (($x5021 (or false (and $x4487 (or $x3779 (and $x4142 (< prank_29 prank_26)))))))
 (let (($x5028 (and (or $x5021 (and $x4333 (or $x3722 (and $x4015 (< prank_25 prank_26))))) (<= prank_low_30 prank_26))))
 (let (($x4298 (or c_1_4 c_1_10 c_1_16)))
 (let (($x4406 (or c_1_3 c_1_9 c_1_15)))
 (let (($x4446 (or c_1_2 c_1_8 c_1_14)))
 (let (($x4993 (or false (and $x4446 (or $x3760 (and $x4106 (< prank_26 prank_25)))))))
 (let (($x4998 (or $x4993 (and $x4406 (or $x3742 (and $x4069 (< prank_28 prank_25)))))))
 (let (($x5005 (and (or $x4998 (and $x4298 (or $x3712 (and $x3988 (< prank_24 prank_25))))) (<= prank_low_30 prank_25))))
 (let (($x4371 (or c_0_3 c_0_9 c_0_15)))
 (let (($x4338 (or c_0_2 c_0_8 c_0_14)))
 (let (($x4970 (or false (and $x4338 (or $x3722 (and $x4015 (< prank_25 prank_24)))))))
 (let (($x4977 (and (or $x4970 (and $x4371 (or $x3732 (and $x4042 (< prank_27 prank_24))))) (<= prank_low_30 prank_24))))
 (let (($x4981 (and true (=> $x3988 (and $x4977 (<= prank_24 prank_high_31))))))
 (let (($x5009 (and $x4981 (=> $x4015 (and $x5005 (<= prank_25 prank_high_31))))))
 (let (($x5032 (and $x5009 (=> $x4106 (and $x5028 (<= prank_26 prank_high_31))))))
 (let (($x5055 (and $x5032 (=> $x4042 (and $x5051 (<= prank_27 prank_high_31))))))
 (let (($x5083 (and $x5055 (=> $x4069 (and $x5079 (<= prank_28 prank_high_31))))))
 (let (($x5106 (and $x5083 (=> $x4142 (and $x5102 (<= prank_29 prank_high_31))))))
 (let (($x5116 (and $x5106 $x5115)))
 (let (($x2364 (not in_target_5)))
 (let (($x3412 (and c_5_12 $x2364)))
 (let (($x3393 (and c_5_6 $x2364)))
 (let (($x3380 (and c_5_18 $x2364)))
 (let (($x2349 (not in_target_4)))
 (let (($x3313 (and c_4_12 $x2349)))
 (let (($x3294 (and c_4_6 $x2349)))
 (let (($x3281 (and c_4_18 $x2349)))
 (let (($x4906 (or $x3281 $x3294 $x3313)))
 (let (($x2334 (not in_target_3)))
 (let (($x3214 (and c_3_12 $x2334)))
 (let (($x3195 (and c_3_6 $x2334)))
 (let (($x3182 (and c_3_18 $x2334)))
 (let (($x4901 (or $x3182 $x3195 $x3214)))
 (let (($x2319 (not in_target_2)))
 (let (($x3115 (and c_2_12 $x2319)))
 (let (($x3096 (and c_2_6 $x2319)))
 (let (($x3083 (and c_2_18 $x2319)))
 (let (($x4896 (or $x3083 $x3096 $x3115)))
 (let (($x2304 (not in_target_1)))
 (let (($x3016 (and c_1_12 $x2304)))
 (let (($x2997 (and c_1_6 $x2304)))
 (let (($x2984 (and c_1_18 $x2304)))
 (let (($x4891 (or $x2984 $x2997 $x3016)))
 (let (($x2291 (not in_target_0)))
 (let (($x2917 (and c_0_12 $x2291)))
 (let (($x2897 (and c_0_6 $x2291)))
 (let (($x2883 (and c_0_18 $x2291)))
 (let (($x4886 (or $x2883 $x2897 $x2917)))
 (let (($x4883 (or false $x4886)))
 (let (($x4888 (or $x4883 $x4891)))
 (let (($x4893 (or $x4888 $x4896)))
 (let (($x4898 (or $x4893 $x4901)))
 (let (($x4903 (or $x4898 $x4906)))
 (let ((?x4862 (ite root_23 1 0)))
 (let ((?x4844 (ite root_21 1 0)))
 (let ((?x4829 (ite root_19 1 0)))
 (let ((?x4814 (ite root_17 1 0)))
 (let ((?x4796 (ite root_15 1 0)))
 (let ((?x4781 (ite root_13 1 0)))
 (let ((?x4782 (+ 0 ?x4781)))
 (let ((?x4797 (+ ?x4782 ?x4796)))
 (let ((?x4815 (+ ?x4797 ?x4814)))
 (let ((?x4830 (+ ?x4815 ?x4829)))
 (let ((?x4845 (+ ?x4830 ?x4844)))
 (let (($x4780 (or false root_13)))
 (let (($x4795 (or $x4780 root_15)))
 (let (($x4813 (or $x4795 root_17)))
 (let (($x4828 (or $x4813 root_19)))
 (let (($x4843 (or $x4828 root_21)))
 (let (($x4741 (or false $x3712)))
 (let (($x4736 (or $x4741 $x3722)))
 (let (($x4743 (or $x4736 $x3760)))
 (let (($x4745 (or $x4743 $x3732)))
 (let (($x4747 (or $x4745 $x3742)))
 (let (($x4749 (or $x4747 $x3779)))
 (let (($x4868 (or false (and $x3742 (< rank_20 rank_22)))))
 (let (($x4872 (not root_23)))
 (let (($x4873 (and $x3779 $x4872)))
 (let (($x4850 (or false (and $x3779 (< rank_22 rank_20)))))
 (let (($x4853 (or $x4850 (and $x3732 (< rank_18 rank_20)))))
 (let (($x4857 (not root_21)))
 (let (($x4858 (and $x3742 $x4857)))
 (let (($x4835 (or false (and $x3742 (< rank_20 rank_18)))))
 (let (($x4839 (not root_19)))
 (let (($x4840 (and $x3732 $x4839)))
 (let (($x4820 (or false (and $x3779 (< rank_22 rank_16)))))
 (let (($x4824 (not root_17)))
 (let (($x4825 (and $x3760 $x4824)))
 (let (($x4802 (or false (and $x3760 (< rank_16 rank_14)))))
 (let (($x4805 (or $x4802 (and $x3742 (< rank_20 rank_14)))))
 (let (($x4809 (not root_15)))
 (let (($x4810 (and $x3722 $x4809)))
 (let (($x4787 (or false (and $x3722 (< rank_14 rank_12)))))
 (let (($x4791 (not root_13)))
 (let (($x4792 (and $x3712 $x4791)))
 (let (($x4784 (and true (=> root_13 $x3712))))
 (let (($x4794 (and $x4784 (=> $x4792 (or $x4787 (and $x3732 (< rank_18 rank_12)))))))
 (let (($x4799 (and $x4794 (=> root_15 $x3722))))
 (let (($x4812 (and $x4799 (=> $x4810 (or $x4805 (and $x3712 (< rank_12 rank_14)))))))
 (let (($x4817 (and $x4812 (=> root_17 $x3760))))
 (let (($x4827 (and $x4817 (=> $x4825 (or $x4820 (and $x3722 (< rank_14 rank_16)))))))
 (let (($x4832 (and $x4827 (=> root_19 $x3732))))
 (let (($x4842 (and $x4832 (=> $x4840 (or $x4835 (and $x3712 (< rank_12 rank_18)))))))
 (let (($x4847 (and $x4842 (=> root_21 $x3742))))
 (let (($x4860 (and $x4847 (=> $x4858 (or $x4853 (and $x3722 (< rank_14 rank_20)))))))
 (let (($x4865 (and $x4860 (=> root_23 $x3779))))
 (let (($x4877 (and (and $x4865 (=> $x4873 (or $x4868 (and $x3760 (< rank_16 rank_22))))) (=> $x4749 (or $x4843 root_23)))))
 (let (($x4879 (and $x4877 (<= (+ ?x4845 ?x4862) 1))))
 (let (($x5117 (and (and (and $x4749 $x4879) (not (or $x4903 (or $x3380 $x3393 $x3412)))) $x5116)))
 (let (($x5737 (and (and (and (and $x5117 $x5366) $x5587) (not (or $x5597 c_5_13))) (not (or $x5717 (and $x4580 (> (to_real (+ ?x5731 ?x5732)) 0.0)))))))
 (let (($x4491 (= (to_real (+ (+ ?x4476 (ite $x4484 1 0)) (ite $x4487 1 0))) 0.0)))
 (let (($x4480 (= (to_real (+ (+ ?x4476 (ite $x4035 1 0)) (ite $x4005 1 0))) 0.0)))
 (let (($x4492 (and $x4480 $x4491)))
 (let (($x4323 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6)))
 (let (($x4576 (and true $x4580)))
 (let (($x4589 (and $x4576 $x4323)))
 (let (($x4592 (not (and $x4589 $x4492))))
 (let ((?x4410 (ite $x4406 1 0)))
 (let ((?x4408 (ite $x4403 1 0)))
 (let ((?x4404 (ite $x4401 1 0)))
 (let ((?x4405 (+ 0 ?x4404)))
 (let ((?x4407 (+ ?x4405 ?x4288)))
 (let ((?x4409 (+ ?x4407 ?x4408)))
 (let ((?x4284 (ite $x3982 1 0)))
 (let ((?x4286 (ite $x4066 1 0)))
 (let ((?x4389 (ite $x4065 1 0)))
 (let ((?x4390 (+ 0 ?x4389)))
 (let ((?x4392 (+ ?x4390 ?x4288)))
 (let ((?x4391 (+ ?x4392 ?x4286)))
 (let (($x4414 (and (= (to_real (+ ?x4391 ?x4284)) 0.0) (= (to_real (+ ?x4409 ?x4410)) 0.0))))
 (let (($x4287 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6)))
 (let (($x4538 (and true $x4542)))
 (let (($x4583 (and $x4538 $x4287)))
 (let (($x4587 (not (and $x4583 $x4414))))
 (let ((?x4374 (ite $x4371 1 0)))
 (let ((?x4369 (ite $x4368 1 0)))
 (let ((?x4370 (+ 0 ?x4369)))
 (let ((?x4372 (+ ?x4370 ?x4288)))
 (let ((?x4373 (+ ?x4372 ?x4288)))
 (let ((?x4324 (ite $x4100 1 0)))
 (let ((?x4319 (ite $x4035 1 0)))
 (let ((?x4357 (+ 0 ?x4319)))
 (let ((?x4360 (+ ?x4357 ?x4288)))
 (let ((?x4358 (+ ?x4360 ?x4288)))
 (let (($x4378 (and (= (to_real (+ ?x4358 ?x4324)) 0.0) (= (to_real (+ ?x4373 ?x4374)) 0.0))))
 (let (($x4465 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6)))
 (let (($x4529 (and true $x4533)))
 (let (($x4581 (and $x4529 $x4465)))
 (let (($x4584 (not (and $x4581 $x4378))))
 (let (($x4361 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6)))
 (let (($x4577 (and $x4576 $x4361)))
 (let (($x4582 (not (and $x4577 $x4492))))
 (let (($x4427 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6)))
 (let (($x4567 (and $x4538 $x4427)))
 (let (($x4573 (not (and $x4567 $x4414))))
 (let ((?x4450 (to_real (+ (+ (+ ?x4434 (ite $x4445 1 0)) (ite $x4446 1 0)) ?x4288))))
 (let (($x4452 (and (= (to_real (+ (+ (+ ?x4434 ?x4389) ?x4284) ?x4288)) 0.0) (= ?x4450 0.0))))
 (let (($x4555 (and true $x4559)))
 (let (($x4562 (and $x4555 $x4287)))
 (let (($x4566 (not (and $x4562 $x4452))))
 (let ((?x4341 (ite $x4338 1 0)))
 (let ((?x4339 (ite $x4337 1 0)))
 (let ((?x4335 (ite $x4333 1 0)))
 (let ((?x4336 (+ 0 ?x4335)))
 (let ((?x4340 (+ ?x4336 ?x4339)))
 (let ((?x4342 (+ ?x4340 ?x4341)))
 (let ((?x4327 (to_real (+ (+ (+ (+ 0 (ite $x4005 1 0)) ?x4319) ?x4324) ?x4288))))
 (let (($x4346 (and (= ?x4327 0.0) (= (to_real (+ ?x4342 ?x4288)) 0.0))))
 (let (($x4520 (and true $x4524)))
 (let (($x4560 (and $x4520 $x4465)))
 (let (($x4564 (not (and $x4560 $x4346))))
 (let (($x4393 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6)))
 (let (($x4556 (and $x4555 $x4393)))
 (let (($x4557 (not (and $x4556 $x4452))))
 (let (($x4552 (not (and (and $x4520 $x4361) $x4346))))
 (let ((?x4301 (ite $x4302 1 0)))
 (let ((?x4299 (ite $x4298 1 0)))
 (let ((?x4300 (+ 0 ?x4299)))
 (let ((?x4303 (+ ?x4300 ?x4301)))
 (let ((?x4304 (+ ?x4303 ?x4288)))
 (let (($x4308 (and (= (to_real (+ (+ (+ (+ 0 ?x4284) ?x4286) ?x4288) ?x4288)) 0.0) (= (to_real (+ ?x4304 ?x4288)) 0.0))))
 (let (($x4511 (and true $x4515)))
 (let (($x4543 (and $x4511 $x4427)))
 (let (($x4548 (not (and $x4543 $x4308))))
 (let (($x4541 (not (and (and $x4538 $x4393) $x4414))))
 (let (($x4535 (not (and (and $x4529 $x4361) $x4378))))
 (let (($x4523 (not (and (and $x4520 $x4323) $x4346))))
 (let (($x4514 (not (and (and $x4511 $x4287) $x4308))))
 (let (($x4475 (or c_5_2 c_5_3 c_5_4 c_5_5)))
 (let (($x4470 (and true $x4475)))
 (let (($x4503 (and $x4470 $x4323)))
 (let (($x4506 (not (and $x4503 $x4492))))
 (let (($x4384 (or c_4_2 c_4_3 c_4_4 c_4_5)))
 (let (($x4382 (and true $x4384)))
 (let (($x4497 (and $x4382 $x4287)))
 (let (($x4501 (not (and $x4497 $x4414))))
 (let (($x4352 (or c_3_2 c_3_3 c_3_4 c_3_5)))
 (let (($x4350 (and true $x4352)))
 (let (($x4496 (and $x4350 $x4465)))
 (let (($x4499 (not (and $x4496 $x4378))))
 (let (($x4494 (not (and (and $x4470 $x4361) $x4492))))
 (let (($x4473 (not (and (and $x4382 $x4427) $x4414))))
 (let (($x4433 (or c_2_2 c_2_3 c_2_4 c_2_5)))
 (let (($x4430 (and true $x4433)))
 (let (($x4461 (and $x4430 $x4287)))
 (let (($x4466 (not (and $x4461 $x4452))))
 (let (($x4314 (or c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x4313 (and true $x4314)))
 (let (($x4460 (and $x4313 $x4465)))
 (let (($x4463 (not (and $x4460 $x4346))))
 (let (($x4454 (not (and (and $x4430 $x4393) $x4452))))
 (let (($x4431 (not (and (and $x4313 $x4361) $x4346))))
 (let (($x4278 (or c_0_2 c_0_3 c_0_4 c_0_5)))
 (let (($x4276 (and true $x4278)))
 (let (($x4422 (and $x4276 $x4427)))
 (let (($x4426 (not (and $x4422 $x4308))))
 (let (($x4416 (not (and (and $x4382 $x4393) $x4414))))
 (let (($x4380 (not (and (and $x4350 $x4361) $x4378))))
 (let (($x4348 (not (and (and $x4313 $x4323) $x4346))))
 (let (($x4310 (not (and (and $x4276 $x4287) $x4308))))
 (let (($x4706 (not in_target_29)))
 (let (($x4704 (not in_target_28)))
 (let (($x4702 (not in_target_27)))
 (let (($x4700 (not in_target_26)))
 (let (($x4698 (not in_target_25)))
 (let (($x4696 (not in_target_24)))
 (let (($x4694 (not in_target_23)))
 (let (($x4692 (not in_target_22)))
 (let (($x4690 (not in_target_21)))
 (let (($x4688 (not in_target_20)))
 (let (($x4686 (not in_target_19)))
 (let (($x4684 (not in_target_18)))
 (let (($x4682 (not in_target_17)))
 (let (($x4680 (not in_target_16)))
 (let (($x4678 (not in_target_15)))
 (let (($x4676 (not in_target_14)))
 (let (($x4674 (not in_target_13)))
 (let (($x4672 (not in_target_12)))
 (let (($x4670 (not in_target_11)))
 (let (($x4668 (not in_target_10)))
 (let (($x4666 (not in_target_9)))
 (let (($x4664 (not in_target_8)))
 (let (($x4662 (not in_target_7)))
 (let (($x4660 (not in_target_6)))
 (let (($x4661 (and true $x4660)))
 (let (($x4663 (and $x4661 $x4662)))
 (let (($x4665 (and $x4663 $x4664)))
 (let (($x4667 (and $x4665 $x4666)))
 (let (($x4669 (and $x4667 $x4668)))
 (let (($x4671 (and $x4669 $x4670)))
 (let (($x4673 (and $x4671 $x4672)))
 (let (($x4675 (and $x4673 $x4674)))
 (let (($x4677 (and $x4675 $x4676)))
 (let (($x4679 (and $x4677 $x4678)))
 (let (($x4681 (and $x4679 $x4680)))
 (let (($x4683 (and $x4681 $x4682)))
 (let (($x4685 (and $x4683 $x4684)))
 (let (($x4687 (and $x4685 $x4686)))
 (let (($x4689 (and $x4687 $x4688)))
 (let (($x4691 (and $x4689 $x4690)))
 (let (($x4693 (and $x4691 $x4692)))
 (let (($x4695 (and $x4693 $x4694)))
 (let (($x4697 (and $x4695 $x4696)))
 (let (($x4699 (and $x4697 $x4698)))
 (let (($x4701 (and $x4699 $x4700)))
 (let (($x4703 (and $x4701 $x4702)))
 (let (($x4705 (and $x4703 $x4704)))
 (let (($x4707 (and $x4705 $x4706)))
 (let (($x4712 (and $x4707 $x4310)))
 (let (($x4713 (and $x4712 $x4348)))
 (let (($x4715 (and $x4713 $x4380)))
 (let (($x4714 (and $x4715 $x4416)))
 (let (($x4711 (and $x4714 $x4426)))
 (let (($x4719 (and $x4711 $x4431)))
 (let (($x4718 (and $x4719 $x4454)))
 (let (($x4716 (and $x4718 $x4463)))
 (let (($x4721 (and $x4716 $x4466)))
 (let (($x4722 (and $x4721 $x4473)))
 (let (($x4723 (and $x4722 $x4494)))
 (let (($x4724 (and $x4723 $x4499)))
 (let (($x4720 (and $x4724 $x4501)))
 (let (($x4726 (and $x4720 $x4506)))
 (let (($x4725 (and $x4726 $x4514)))
 (let (($x4728 (and $x4725 $x4523)))
 (let (($x4717 (and $x4728 $x4535)))
 (let (($x4729 (and $x4717 $x4541)))
 (let (($x4731 (and $x4729 $x4548)))
 (let (($x4727 (and $x4731 $x4552)))
 (let (($x4733 (and $x4727 $x4557)))
 (let (($x4734 (and $x4733 $x4564)))
 (let (($x4735 (and $x4734 $x4566)))
 (let (($x4730 (and $x4735 $x4573)))
 (let (($x4737 (and $x4730 $x4582)))
 (let (($x4738 (and $x4737 $x4584)))
 (let (($x4732 (and $x4738 $x4587)))
 (let (($x4267 (or c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4262 (and true $x4267)))
 (let (($x4232 (or c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4227 (and true $x4232)))
 (let (($x4222 (or c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x4217 (and true $x4222)))
 (let (($x4248 (or c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x4243 (and true $x4248)))
 (let (($x4212 (or c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x4207 (and true $x4212)))
 (let (($x4202 (or c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x4197 (and true $x4202)))
 (let (($x3106 (and c_2_7 $x2319)))
 (let (($x3087 (and c_2_1 $x2319)))
 (let (($x3073 (and c_2_13 $x2319)))
 (let (($x3912 (or $x3073 $x3087 $x3106)))
 (let (($x3776 (and true $x3779)))
 (let (($x3007 (and c_1_7 $x2304)))
 (let (($x2988 (and c_1_1 $x2304)))
 (let (($x2974 (and c_1_13 $x2304)))
 (let (($x3907 (or $x2974 $x2988 $x3007)))
 (let (($x3739 (and true $x3742)))
 (let (($x2908 (and c_0_7 $x2291)))
 (let (($x2888 (and c_0_1 $x2291)))
 (let (($x2873 (and c_0_13 $x2291)))
 (let (($x3938 (or $x2873 $x2888 $x2908)))
 (let (($x3729 (and true $x3732)))
 (let (($x3304 (and c_4_7 $x2349)))
 (let (($x3285 (and c_4_1 $x2349)))
 (let (($x3271 (and c_4_13 $x2349)))
 (let (($x3917 (or $x3271 $x3285 $x3304)))
 (let (($x3205 (and c_3_7 $x2334)))
 (let (($x3186 (and c_3_1 $x2334)))
 (let (($x3172 (and c_3_13 $x2334)))
 (let (($x3927 (or $x3172 $x3186 $x3205)))
 (let (($x3403 (and c_5_7 $x2364)))
 (let (($x3384 (and c_5_1 $x2364)))
 (let (($x3370 (and c_5_13 $x2364)))
 (let (($x3922 (or $x3370 $x3384 $x3403)))
 (let (($x3757 (and true $x3760)))
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
 (let (($x3827 (or $x2527 $x2529 $x2531 $x2533 $x2538 $x2540 $x2542 $x2544 $x2549 $x2551 $x2553 $x2555)))
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
 (let (($x3812 (or $x2474 $x2476 $x2478 $x2480 $x2485 $x2487 $x2489 $x2491 $x2496 $x2498 $x2500 $x2502)))
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
 (let (($x3893 (or $x2421 $x2423 $x2425 $x2427 $x2432 $x2434 $x2436 $x2438 $x2443 $x2445 $x2447 $x2449)))
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
 (let (($x3842 (or $x2633 $x2635 $x2637 $x2639 $x2644 $x2646 $x2648 $x2650 $x2655 $x2657 $x2659 $x2661)))
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
 (let (($x3872 (or $x2580 $x2582 $x2584 $x2586 $x2591 $x2593 $x2595 $x2597 $x2602 $x2604 $x2606 $x2608)))
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
 (let (($x3857 (or $x2686 $x2688 $x2690 $x2692 $x2697 $x2699 $x2701 $x2703 $x2708 $x2710 $x2712 $x2714)))
 (let (($x2547 (and c_2_13 in_target_2)))
 (let (($x2536 (and c_2_7 in_target_2)))
 (let (($x2525 (and c_2_1 in_target_2)))
 (let (($x3724 (or $x2525 $x2536 $x2547)))
 (let (($x2494 (and c_1_13 in_target_1)))
 (let (($x2483 (and c_1_7 in_target_1)))
 (let (($x2472 (and c_1_1 in_target_1)))
 (let (($x3714 (or $x2472 $x2483 $x2494)))
 (let (($x2441 (and c_0_13 in_target_0)))
 (let (($x2430 (and c_0_7 in_target_0)))
 (let (($x2419 (and c_0_1 in_target_0)))
 (let (($x3765 (or $x2419 $x2430 $x2441)))
 (let (($x2653 (and c_4_13 in_target_4)))
 (let (($x2642 (and c_4_7 in_target_4)))
 (let (($x2631 (and c_4_1 in_target_4)))
 (let (($x3734 (or $x2631 $x2642 $x2653)))
 (let (($x2600 (and c_3_13 in_target_3)))
 (let (($x2589 (and c_3_7 in_target_3)))
 (let (($x2578 (and c_3_1 in_target_3)))
 (let (($x3749 (or $x2578 $x2589 $x2600)))
 (let (($x2706 (and c_5_13 in_target_5)))
 (let (($x2695 (and c_5_7 in_target_5)))
 (let (($x2684 (and c_5_1 in_target_5)))
 (let (($x3744 (or $x2684 $x2695 $x2706)))
 (let (($x3410 (and c_5_11 $x2364)))
 (let (($x3408 (and c_5_10 $x2364)))
 (let (($x3406 (and c_5_9 $x2364)))
 (let (($x3404 (and c_5_8 $x2364)))
 (let ((?x3401 (ite (or $x3403 $x3404 $x3406 $x3408 $x3410 $x3412) 3 0)))
 (let (($x3391 (and c_5_5 $x2364)))
 (let (($x3389 (and c_5_4 $x2364)))
 (let (($x3387 (and c_5_3 $x2364)))
 (let (($x3385 (and c_5_2 $x2364)))
 (let ((?x3382 (ite (or $x3384 $x3385 $x3387 $x3389 $x3391 $x3393) 2 0)))
 (let (($x3378 (and c_5_17 $x2364)))
 (let (($x3376 (and c_5_16 $x2364)))
 (let (($x3374 (and c_5_15 $x2364)))
 (let (($x3372 (and c_5_14 $x2364)))
 (let ((?x3670 (ite (or $x3370 $x3372 $x3374 $x3376 $x3378 $x3380) 1 0)))
 (let ((?x3656 (ite (or (and c_5_6 in_target_5) $x2684 $x2686 $x2688 $x2690 $x2692) (- 1) 0)))
 (let (($x2716 (and c_5_18 in_target_5)))
 (let (($x3350 (or $x2706 $x2708 $x2710 $x2712 $x2714 $x2716)))
 (let ((?x3660 (ite $x3350 (- 2) 0)))
 (let (($x2683 (and c_5_0 in_target_5)))
 (let ((?x3658 (ite $x2683 (- 3) 0)))
 (let (($x3311 (and c_4_11 $x2349)))
 (let (($x3309 (and c_4_10 $x2349)))
 (let (($x3307 (and c_4_9 $x2349)))
 (let (($x3305 (and c_4_8 $x2349)))
 (let ((?x3302 (ite (or $x3304 $x3305 $x3307 $x3309 $x3311 $x3313) 3 0)))
 (let (($x3292 (and c_4_5 $x2349)))
 (let (($x3290 (and c_4_4 $x2349)))
 (let (($x3288 (and c_4_3 $x2349)))
 (let (($x3286 (and c_4_2 $x2349)))
 (let ((?x3283 (ite (or $x3285 $x3286 $x3288 $x3290 $x3292 $x3294) 2 0)))
 (let (($x3279 (and c_4_17 $x2349)))
 (let (($x3277 (and c_4_16 $x2349)))
 (let (($x3275 (and c_4_15 $x2349)))
 (let (($x3273 (and c_4_14 $x2349)))
 (let ((?x3629 (ite (or $x3271 $x3273 $x3275 $x3277 $x3279 $x3281) 1 0)))
 (let ((?x3621 (ite (or (and c_4_6 in_target_4) $x2631 $x2633 $x2635 $x2637 $x2639) (- 1) 0)))
 (let (($x2663 (and c_4_18 in_target_4)))
 (let (($x3251 (or $x2653 $x2655 $x2657 $x2659 $x2661 $x2663)))
 (let ((?x3607 (ite $x3251 (- 2) 0)))
 (let (($x2630 (and c_4_0 in_target_4)))
 (let ((?x3617 (ite $x2630 (- 3) 0)))
 (let (($x3212 (and c_3_11 $x2334)))
 (let (($x3210 (and c_3_10 $x2334)))
 (let (($x3208 (and c_3_9 $x2334)))
 (let (($x3206 (and c_3_8 $x2334)))
 (let ((?x3203 (ite (or $x3205 $x3206 $x3208 $x3210 $x3212 $x3214) 3 0)))
 (let (($x3193 (and c_3_5 $x2334)))
 (let (($x3191 (and c_3_4 $x2334)))
 (let (($x3189 (and c_3_3 $x2334)))
 (let (($x3187 (and c_3_2 $x2334)))
 (let ((?x3184 (ite (or $x3186 $x3187 $x3189 $x3191 $x3193 $x3195) 2 0)))
 (let (($x3180 (and c_3_17 $x2334)))
 (let (($x3178 (and c_3_16 $x2334)))
 (let (($x3176 (and c_3_15 $x2334)))
 (let (($x3174 (and c_3_14 $x2334)))
 (let ((?x3588 (ite (or $x3172 $x3174 $x3176 $x3178 $x3180 $x3182) 1 0)))
 (let ((?x3579 (ite (or (and c_3_6 in_target_3) $x2578 $x2580 $x2582 $x2584 $x2586) (- 1) 0)))
 (let (($x2610 (and c_3_18 in_target_3)))
 (let (($x3152 (or $x2600 $x2602 $x2604 $x2606 $x2608 $x2610)))
 (let ((?x3571 (ite $x3152 (- 2) 0)))
 (let (($x2577 (and c_3_0 in_target_3)))
 (let ((?x3580 (ite $x2577 (- 3) 0)))
 (let (($x3113 (and c_2_11 $x2319)))
 (let (($x3111 (and c_2_10 $x2319)))
 (let (($x3109 (and c_2_9 $x2319)))
 (let (($x3107 (and c_2_8 $x2319)))
 (let ((?x3104 (ite (or $x3106 $x3107 $x3109 $x3111 $x3113 $x3115) 3 0)))
 (let (($x3094 (and c_2_5 $x2319)))
 (let (($x3092 (and c_2_4 $x2319)))
 (let (($x3090 (and c_2_3 $x2319)))
 (let (($x3088 (and c_2_2 $x2319)))
 (let ((?x3085 (ite (or $x3087 $x3088 $x3090 $x3092 $x3094 $x3096) 2 0)))
 (let (($x3081 (and c_2_17 $x2319)))
 (let (($x3079 (and c_2_16 $x2319)))
 (let (($x3077 (and c_2_15 $x2319)))
 (let (($x3075 (and c_2_14 $x2319)))
 (let ((?x3547 (ite (or $x3073 $x3075 $x3077 $x3079 $x3081 $x3083) 1 0)))
 (let ((?x3541 (ite (or (and c_2_6 in_target_2) $x2525 $x2527 $x2529 $x2531 $x2533) (- 1) 0)))
 (let (($x2557 (and c_2_18 in_target_2)))
 (let (($x3053 (or $x2547 $x2549 $x2551 $x2553 $x2555 $x2557)))
 (let ((?x3529 (ite $x3053 (- 2) 0)))
 (let (($x2524 (and c_2_0 in_target_2)))
 (let ((?x3525 (ite $x2524 (- 3) 0)))
 (let (($x3014 (and c_1_11 $x2304)))
 (let (($x3012 (and c_1_10 $x2304)))
 (let (($x3010 (and c_1_9 $x2304)))
 (let (($x3008 (and c_1_8 $x2304)))
 (let ((?x3005 (ite (or $x3007 $x3008 $x3010 $x3012 $x3014 $x3016) 3 0)))
 (let (($x2995 (and c_1_5 $x2304)))
 (let (($x2993 (and c_1_4 $x2304)))
 (let (($x2991 (and c_1_3 $x2304)))
 (let (($x2989 (and c_1_2 $x2304)))
 (let ((?x2986 (ite (or $x2988 $x2989 $x2991 $x2993 $x2995 $x2997) 2 0)))
 (let (($x2982 (and c_1_17 $x2304)))
 (let (($x2980 (and c_1_16 $x2304)))
 (let (($x2978 (and c_1_15 $x2304)))
 (let (($x2976 (and c_1_14 $x2304)))
 (let ((?x3506 (ite (or $x2974 $x2976 $x2978 $x2980 $x2982 $x2984) 1 0)))
 (let ((?x3497 (ite (or (and c_1_6 in_target_1) $x2472 $x2474 $x2476 $x2478 $x2480) (- 1) 0)))
 (let (($x2504 (and c_1_18 in_target_1)))
 (let (($x2954 (or $x2494 $x2496 $x2498 $x2500 $x2502 $x2504)))
 (let ((?x3500 (ite $x2954 (- 2) 0)))
 (let (($x2471 (and c_1_0 in_target_1)))
 (let ((?x3489 (ite $x2471 (- 3) 0)))
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
 (let ((?x3465 (ite (or $x2873 $x2875 $x2877 $x2879 $x2881 $x2883) 1 0)))
 (let ((?x3457 (ite (or (and c_0_6 in_target_0) $x2419 $x2421 $x2423 $x2425 $x2427) (- 1) 0)))
 (let (($x2451 (and c_0_18 in_target_0)))
 (let (($x2853 (or $x2441 $x2443 $x2445 $x2447 $x2449 $x2451)))
 (let ((?x3450 (ite $x2853 (- 2) 0)))
 (let (($x2418 (and c_0_0 in_target_0)))
 (let ((?x3448 (ite $x2418 (- 3) 0)))
 (let ((?x3449 (+ 0 ?x3448)))
 (let ((?x3451 (+ ?x3449 ?x3450)))
 (let ((?x3460 (+ ?x3451 ?x3457)))
 (let ((?x3466 (+ ?x3460 ?x3465)))
 (let ((?x3467 (+ ?x3466 ?x2886)))
 (let ((?x3470 (+ ?x3467 ?x2906)))
 (let ((?x3484 (+ ?x3470 ?x3489)))
 (let ((?x3493 (+ ?x3484 ?x3500)))
 (let ((?x3488 (+ ?x3493 ?x3497)))
 (let ((?x3507 (+ ?x3488 ?x3506)))
 (let ((?x3511 (+ ?x3507 ?x2986)))
 (let ((?x3509 (+ ?x3511 ?x3005)))
 (let ((?x3537 (+ ?x3509 ?x3525)))
 (let ((?x3538 (+ ?x3537 ?x3529)))
 (let ((?x3530 (+ ?x3538 ?x3541)))
 (let ((?x3548 (+ ?x3530 ?x3547)))
 (let ((?x3551 (+ ?x3548 ?x3085)))
 (let ((?x3550 (+ ?x3551 ?x3104)))
 (let ((?x3576 (+ ?x3550 ?x3580)))
 (let ((?x3573 (+ ?x3576 ?x3571)))
 (let ((?x3584 (+ ?x3573 ?x3579)))
 (let ((?x3589 (+ ?x3584 ?x3588)))
 (let ((?x3591 (+ ?x3589 ?x3184)))
 (let ((?x3590 (+ ?x3591 ?x3203)))
 (let ((?x3611 (+ ?x3590 ?x3617)))
 (let ((?x3614 (+ ?x3611 ?x3607)))
 (let ((?x3625 (+ ?x3614 ?x3621)))
 (let ((?x3630 (+ ?x3625 ?x3629)))
 (let ((?x3634 (+ ?x3630 ?x3283)))
 (let ((?x3632 (+ ?x3634 ?x3302)))
 (let ((?x3657 (+ ?x3632 ?x3658)))
 (let ((?x3664 (+ ?x3657 ?x3660)))
 (let ((?x3648 (+ ?x3664 ?x3656)))
 (let ((?x3671 (+ ?x3648 ?x3670)))
 (let ((?x3672 (+ ?x3671 ?x3382)))
 (let (($x3701 (<= (+ ?x3672 ?x3401) 0)))
 (let (($x2380 (and c_5_12 in_target_5)))
 (let ((?x3363 (ite (or $x2380 $x2695 $x2697 $x2699 $x2701 $x2703 $x3370 $x3372 $x3374 $x3376 $x3378 $x3380) 1 0)))
 (let ((?x3341 (ite $x3350 (- 1) 0)))
 (let ((?x3343 (ite $x2683 (- 2) 0)))
 (let (($x2365 (and c_4_12 in_target_4)))
 (let ((?x3264 (ite (or $x2365 $x2642 $x2644 $x2646 $x2648 $x2650 $x3271 $x3273 $x3275 $x3277 $x3279 $x3281) 1 0)))
 (let ((?x3235 (ite $x3251 (- 1) 0)))
 (let ((?x3243 (ite $x2630 (- 2) 0)))
 (let (($x2350 (and c_3_12 in_target_3)))
 (let ((?x3165 (ite (or $x2350 $x2589 $x2591 $x2593 $x2595 $x2597 $x3172 $x3174 $x3176 $x3178 $x3180 $x3182) 1 0)))
 (let ((?x3143 (ite $x3152 (- 1) 0)))
 (let ((?x3136 (ite $x2577 (- 2) 0)))
 (let (($x2335 (and c_2_12 in_target_2)))
 (let ((?x3066 (ite (or $x2335 $x2536 $x2538 $x2540 $x2542 $x2544 $x3073 $x3075 $x3077 $x3079 $x3081 $x3083) 1 0)))
 (let ((?x3038 (ite $x3053 (- 1) 0)))
 (let ((?x3047 (ite $x2524 (- 2) 0)))
 (let (($x2320 (and c_1_12 in_target_1)))
 (let ((?x2967 (ite (or $x2320 $x2483 $x2485 $x2487 $x2489 $x2491 $x2974 $x2976 $x2978 $x2980 $x2982 $x2984) 1 0)))
 (let ((?x2939 (ite $x2954 (- 1) 0)))
 (let ((?x2942 (ite $x2471 (- 2) 0)))
 (let (($x2305 (and c_0_12 in_target_0)))
 (let ((?x2866 (ite (or $x2305 $x2430 $x2432 $x2434 $x2436 $x2438 $x2873 $x2875 $x2877 $x2879 $x2881 $x2883) 1 0)))
 (let ((?x2847 (ite $x2853 (- 1) 0)))
 (let ((?x2839 (ite $x2418 (- 2) 0)))
 (let ((?x2840 (+ 0 ?x2839)))
 (let ((?x2848 (+ ?x2840 ?x2847)))
 (let ((?x2867 (+ ?x2848 ?x2866)))
 (let ((?x2887 (+ ?x2867 ?x2886)))
 (let ((?x2907 (+ ?x2887 ?x2906)))
 (let ((?x2950 (+ ?x2907 ?x2942)))
 (let ((?x2949 (+ ?x2950 ?x2939)))
 (let ((?x2968 (+ ?x2949 ?x2967)))
 (let ((?x2987 (+ ?x2968 ?x2986)))
 (let ((?x3006 (+ ?x2987 ?x3005)))
 (let ((?x3041 (+ ?x3006 ?x3047)))
 (let ((?x3048 (+ ?x3041 ?x3038)))
 (let ((?x3067 (+ ?x3048 ?x3066)))
 (let ((?x3086 (+ ?x3067 ?x3085)))
 (let ((?x3105 (+ ?x3086 ?x3104)))
 (let ((?x3137 (+ ?x3105 ?x3136)))
 (let ((?x3147 (+ ?x3137 ?x3143)))
 (let ((?x3166 (+ ?x3147 ?x3165)))
 (let ((?x3185 (+ ?x3166 ?x3184)))
 (let ((?x3204 (+ ?x3185 ?x3203)))
 (let ((?x3234 (+ ?x3204 ?x3243)))
 (let ((?x3233 (+ ?x3234 ?x3235)))
 (let ((?x3265 (+ ?x3233 ?x3264)))
 (let ((?x3284 (+ ?x3265 ?x3283)))
 (let ((?x3303 (+ ?x3284 ?x3302)))
 (let ((?x3333 (+ ?x3303 ?x3343)))
 (let ((?x3334 (+ ?x3333 ?x3341)))
 (let ((?x3364 (+ ?x3334 ?x3363)))
 (let ((?x3383 (+ ?x3364 ?x3382)))
 (let (($x3432 (>= (+ ?x3383 ?x3401) 0)))
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
 (let (($x3703 (and $x2375 (and (and $x2837 $x3432) $x3701))))
 (let (($x3715 (and $x3703 (not (and (and true $x3712) $x3714)))))
 (let (($x3725 (and $x3715 (not (and (and true $x3722) $x3724)))))
 (let (($x3735 (and $x3725 (not (and $x3729 $x3734)))))
 (let (($x3745 (and $x3735 (not (and $x3739 $x3744)))))
 (let (($x3750 (and $x3745 (not (and (and true $x3712) $x3749)))))
 (let (($x3753 (and $x3750 (not (and (and true $x3722) $x3734)))))
 (let (($x3761 (and $x3753 (not (and $x3757 $x3744)))))
 (let (($x3766 (and $x3761 (not (and (and true $x3722) $x3765)))))
 (let (($x3769 (and $x3766 (not (and $x3757 $x3714)))))
 (let (($x3772 (and $x3769 (not (and $x3739 $x3749)))))
 (let (($x3780 (and $x3772 (not (and $x3776 $x3734)))))
 (let (($x3783 (and $x3780 (not (and $x3729 $x3765)))))
 (let (($x3786 (and $x3783 (not (and $x3739 $x3714)))))
 (let (($x3789 (and $x3786 (not (and $x3776 $x3724)))))
 (let (($x3805 (and $x3789 (not (and (and true $x3712) $x3812)))))
 (let (($x3819 (and $x3805 (not (and (and true $x3722) $x3827)))))
 (let (($x3839 (and $x3819 (not (and $x3729 $x3842)))))
 (let (($x3851 (and $x3839 (not (and $x3739 $x3857)))))
 (let (($x3869 (and $x3851 (not (and (and true $x3712) $x3872)))))
 (let (($x3873 (and $x3869 (not (and (and true $x3722) $x3842)))))
 (let (($x3864 (and $x3873 (not (and $x3757 $x3857)))))
 (let (($x3892 (and $x3864 (not (and (and true $x3722) $x3893)))))
 (let (($x3890 (and $x3892 (not (and $x3757 $x3812)))))
 (let (($x3897 (and $x3890 (not (and $x3739 $x3872)))))
 (let (($x3900 (and $x3897 (not (and $x3776 $x3842)))))
 (let (($x3905 (and $x3900 (not (and $x3729 $x3893)))))
 (let (($x3903 (and $x3905 (not (and $x3739 $x3812)))))
 (let (($x3902 (and $x3903 (not (and $x3776 $x3827)))))
 (let (($x3911 (and $x3902 (not (and (and true $x3712) $x3907)))))
 (let (($x3913 (and $x3911 (not (and (and true $x3722) $x3912)))))
 (let (($x3918 (and $x3913 (not (and $x3729 $x3917)))))
 (let (($x3923 (and $x3918 (not (and $x3739 $x3922)))))
 (let (($x3928 (and $x3923 (not (and (and true $x3712) $x3927)))))
 (let (($x3931 (and $x3928 (not (and (and true $x3722) $x3917)))))
 (let (($x3934 (and $x3931 (not (and $x3757 $x3922)))))
 (let (($x3939 (and $x3934 (not (and (and true $x3722) $x3938)))))
 (let (($x3942 (and $x3939 (not (and $x3757 $x3907)))))
 (let (($x3945 (and $x3942 (not (and $x3739 $x3927)))))
 (let (($x3948 (and $x3945 (not (and $x3776 $x3917)))))
 (let (($x3951 (and $x3948 (not (and $x3729 $x3938)))))
 (let (($x3954 (and $x3951 (not (and $x3739 $x3907)))))
 (let (($x3957 (and $x3954 (not (and $x3776 $x3912)))))
 (let (($x3978 (and $x3957 (not (and (and true $x3988) $x3982)))))
 (let (($x4009 (and $x3978 (not (and (and true $x4015) $x4005)))))
 (let (($x4036 (and $x4009 (not (and (and true $x4042) $x4035)))))
 (let (($x4059 (and $x4036 (not (and (and true $x4069) $x4065)))))
 (let (($x4074 (and $x4059 (not (and (and true $x3988) $x4066)))))
 (let (($x4075 (and $x4074 (not (and (and true $x4015) $x4035)))))
 (let (($x4097 (and $x4075 (not (and (and true $x4106) $x4065)))))
 (let (($x4103 (and $x4097 (not (and (and true $x4015) $x4100)))))
 (let (($x4114 (and $x4103 (not (and (and true $x4106) $x3982)))))
 (let (($x4115 (and $x4114 (not (and (and true $x4069) $x4066)))))
 (let (($x4135 (and $x4115 (not (and (and true $x4142) $x4035)))))
 (let (($x4138 (and $x4135 (not (and (and true $x4042) $x4100)))))
 (let (($x4132 (and $x4138 (not (and (and true $x4069) $x3982)))))
 (let (($x4146 (and $x4132 (not (and (and true $x4142) $x4005)))))
 (let (($x4149 (and $x4146 (not (and (and true c_0_12) $x2471)))))
 (let (($x4143 (and $x4149 (not (and (and true c_1_12) $x2524)))))
 (let (($x4155 (and $x4143 (not (and (and true c_3_12) $x2630)))))
 (let (($x4159 (and $x4155 (not (and (and true c_4_12) $x2683)))))
 (let (($x4162 (and $x4159 (not (and (and true c_0_12) $x2577)))))
 (let (($x4165 (and $x4162 (not (and (and true c_1_12) $x2630)))))
 (let (($x4169 (and $x4165 (not (and (and true c_2_12) $x2683)))))
 (let (($x4172 (and $x4169 (not (and (and true c_1_12) $x2418)))))
 (let (($x4175 (and $x4172 (not (and (and true c_2_12) $x2471)))))
 (let (($x4178 (and $x4175 (not (and (and true c_4_12) $x2577)))))
 (let (($x4182 (and $x4178 (not (and (and true c_5_12) $x2630)))))
 (let (($x4185 (and $x4182 (not (and (and true c_3_12) $x2418)))))
 (let (($x4188 (and $x4185 (not (and (and true c_4_12) $x2471)))))
 (let (($x4191 (and $x4188 (not (and (and true c_5_12) $x2524)))))
 (let (($x4198 (and $x4191 (not (and $x4197 c_1_18)))))
 (let (($x4211 (and $x4198 (not (and $x4207 c_2_18)))))
 (let (($x4218 (and $x4211 (not (and $x4217 c_4_18)))))
 (let (($x4231 (and $x4218 (not (and $x4227 c_5_18)))))
 (let (($x4236 (and $x4231 (not (and $x4197 c_3_18)))))
 (let (($x4234 (and $x4236 (not (and $x4207 c_4_18)))))
 (let (($x4246 (and $x4234 (not (and $x4243 c_5_18)))))
 (let (($x4249 (and $x4246 (not (and $x4207 c_0_18)))))
 (let (($x4250 (and $x4249 (not (and $x4243 c_1_18)))))
 (let (($x4255 (and $x4250 (not (and $x4227 c_3_18)))))
 (let (($x4265 (and $x4255 (not (and $x4262 c_4_18)))))
 (let (($x4269 (and $x4265 (not (and $x4217 c_0_18)))))
 (let (($x4270 (and $x4269 (not (and $x4227 c_1_18)))))
 (let (($x4272 (and $x4270 (not (and $x4262 c_2_18)))))
 (let (($x4311 (and $x4272 $x4310)))
 (let (($x4349 (and $x4311 $x4348)))
 (let (($x4381 (and $x4349 $x4380)))
 (let (($x4417 (and $x4381 $x4416)))
 (let (($x4425 (and $x4417 $x4426)))
 (let (($x4429 (and $x4425 $x4431)))
 (let (($x4455 (and $x4429 $x4454)))
 (let (($x4464 (and $x4455 $x4463)))
 (let (($x4469 (and $x4464 $x4466)))
 (let (($x4472 (and $x4469 $x4473)))
 (let (($x4495 (and $x4472 $x4494)))
 (let (($x4500 (and $x4495 $x4499)))
 (let (($x4504 (and $x4500 $x4501)))
 (let (($x4505 (and $x4504 $x4506)))
 (let (($x4517 (and $x4505 $x4514)))
 (let (($x4522 (and $x4517 $x4523)))
 (let (($x4531 (and $x4522 $x4535)))
 (let (($x4544 (and $x4531 $x4541)))
 (let (($x4546 (and $x4544 $x4548)))
 (let (($x4550 (and $x4546 $x4552)))
 (let (($x4561 (and $x4550 $x4557)))
 (let (($x4565 (and $x4561 $x4564)))
 (let (($x4569 (and $x4565 $x4566)))
 (let (($x4572 (and $x4569 $x4573)))
 (let (($x4579 (and $x4572 $x4582)))
 (let (($x4586 (and $x4579 $x4584)))
 (let (($x4590 (and $x4586 $x4587)))
 (let (($x4591 (and $x4590 $x4592)))
 (let (($x4597 (and $x4591 (not (and $x4197 $x4287)))))
 (let (($x4595 (and $x4597 (not (and $x4207 $x4323)))))
 (let (($x4603 (and $x4595 (not (and $x4217 $x4361)))))
 (let (($x4599 (and $x4603 (not (and $x4227 $x4393)))))
 (let (($x4608 (and $x4599 (not (and $x4197 $x4427)))))
 (let (($x4611 (and $x4608 (not (and $x4207 $x4361)))))
 (let (($x4613 (and $x4611 (not (and $x4243 $x4393)))))
 (let (($x4619 (and $x4613 (not (and $x4207 $x4465)))))
 (let (($x4620 (and $x4619 (not (and $x4243 $x4287)))))
 (let (($x4623 (and $x4620 (not (and $x4227 $x4427)))))
 (let (($x4626 (and $x4623 (not (and $x4262 $x4361)))))
 (let (($x4627 (and $x4626 (not (and $x4217 $x4465)))))
 (let (($x4633 (and $x4627 (not (and $x4227 $x4287)))))
 (let (($x4634 (and $x4633 (not (and $x4262 $x4323)))))
 (let (($x4739 (and $x4634 (and $x4732 $x4592))))
 (and $x4739 $x5737)))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
