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
 (let (($x4874 (>= rank_12 0)))
 (and $x4874 (< rank_12 6))))
(assert
 (let (($x4879 (>= rank_14 0)))
 (and $x4879 (< rank_14 6))))
(assert
 (let (($x4884 (>= rank_16 0)))
 (and $x4884 (< rank_16 6))))
(assert
 (let (($x4889 (>= rank_18 0)))
 (and $x4889 (< rank_18 6))))
(assert
 (let (($x4894 (>= rank_20 0)))
 (and $x4894 (< rank_20 6))))
(assert
 (let (($x4899 (>= rank_22 0)))
 (and $x4899 (< rank_22 6))))
(assert
 (let (($x5064 (>= prank_24 0)))
 (and $x5064 (< prank_24 6))))
(assert
 (let (($x5056 (>= prank_25 0)))
 (and $x5056 (< prank_25 6))))
(assert
 (let (($x5071 (>= prank_26 0)))
 (and $x5071 (< prank_26 6))))
(assert
 (let (($x5075 (>= prank_27 0)))
 (and $x5075 (< prank_27 6))))
(assert
 (let (($x5079 (>= prank_28 0)))
 (and $x5079 (< prank_28 6))))
(assert
 (let (($x5083 (>= prank_29 0)))
 (and $x5083 (< prank_29 6))))
(assert
 (let (($x5302 (>= prank_32 0)))
 (and $x5302 (< prank_32 6))))
(assert
 (let (($x5319 (>= prank_33 0)))
 (and $x5319 (< prank_33 6))))
(assert
 (let (($x5321 (>= prank_34 0)))
 (and $x5321 (< prank_34 6))))
(assert
 (let (($x5323 (>= prank_35 0)))
 (and $x5323 (< prank_35 6))))
(assert
 (let (($x5329 (>= prank_36 0)))
 (and $x5329 (< prank_36 6))))
(assert
 (let (($x5333 (>= prank_37 0)))
 (and $x5333 (< prank_37 6))))
(assert
 (let (($x5586 (>= rank_40 0)))
 (and $x5586 (< rank_40 6))))
(assert
 (let (($x5585 (>= rank_42 0)))
 (and $x5585 (< rank_42 6))))
(assert
 (let (($x5563 (>= rank_44 0)))
 (and $x5563 (< rank_44 6))))
(assert
 (let (($x5591 (>= rank_46 0)))
 (and $x5591 (< rank_46 6))))
(assert
 (let (($x5596 (>= rank_48 0)))
 (and $x5596 (< rank_48 6))))
(assert
 (let (($x5601 (>= rank_50 0)))
 (and $x5601 (< rank_50 6))))
(assert
 (let ((?x5854 (ite (or c_2_1 c_2_3 c_2_7 c_2_9 c_2_13 c_2_15) 1 0)))
 (let ((?x5847 (ite (or c_4_1 c_4_2 c_4_7 c_4_8 c_4_13 c_4_14) 1 0)))
 (let ((?x4410 (ite false 1 0)))
 (let ((?x4556 (+ 0 ?x4410)))
 (let ((?x4598 (+ ?x4556 ?x4410)))
 (let ((?x5853 (+ ?x4598 ?x5847)))
 (let (($x4702 (or c_5_14 c_5_15 c_5_16 c_5_17)))
 (let ((?x5834 (ite (or c_1_1 c_1_3 c_1_7 c_1_9 c_1_13 c_1_15) 1 0)))
 (let ((?x5830 (ite (or c_3_1 c_3_2 c_3_7 c_3_8 c_3_13 c_3_14) 1 0)))
 (let ((?x5820 (ite (or c_5_1 c_5_4 c_5_7 c_5_10 c_5_13 c_5_16) 1 0)))
 (let ((?x5831 (+ 0 ?x5820)))
 (let ((?x5829 (+ ?x5831 ?x4410)))
 (let ((?x5832 (+ ?x5829 ?x5830)))
 (let (($x4664 (or c_4_14 c_4_15 c_4_16 c_4_17)))
 (let (($x5838 (and $x4664 (> (to_real (+ ?x5832 ?x5834)) 0.0))))
 (let ((?x5805 (ite (or c_0_1 c_0_3 c_0_7 c_0_9 c_0_13 c_0_15) 1 0)))
 (let ((?x5801 (ite (or c_4_1 c_4_4 c_4_7 c_4_10 c_4_13 c_4_16) 1 0)))
 (let ((?x5804 (+ 0 ?x5801)))
 (let ((?x5803 (+ ?x5804 ?x4410)))
 (let ((?x5806 (+ ?x5803 ?x4410)))
 (let (($x4655 (or c_3_14 c_3_15 c_3_16 c_3_17)))
 (let (($x5811 (and $x4655 (> (to_real (+ ?x5806 ?x5805)) 0.0))))
 (let ((?x5784 (ite (or c_1_1 c_1_2 c_1_7 c_1_8 c_1_13 c_1_14) 1 0)))
 (let ((?x5781 (ite (or c_5_1 c_5_5 c_5_7 c_5_11 c_5_13 c_5_17) 1 0)))
 (let ((?x5778 (+ ?x4556 ?x5781)))
 (let ((?x5783 (+ ?x5778 ?x5784)))
 (let (($x4681 (or c_2_14 c_2_15 c_2_16 c_2_17)))
 (let (($x5789 (and $x4681 (> (to_real (+ ?x5783 ?x4410)) 0.0))))
 (let ((?x5761 (ite (or c_0_1 c_0_2 c_0_7 c_0_8 c_0_13 c_0_14) 1 0)))
 (let ((?x5756 (ite (or c_4_1 c_4_5 c_4_7 c_4_11 c_4_13 c_4_17) 1 0)))
 (let ((?x5759 (ite (or c_2_1 c_2_4 c_2_7 c_2_10 c_2_13 c_2_16) 1 0)))
 (let ((?x5763 (+ 0 ?x5759)))
 (let ((?x5762 (+ ?x5763 ?x5756)))
 (let ((?x5765 (+ ?x5762 ?x5761)))
 (let (($x4646 (or c_1_14 c_1_15 c_1_16 c_1_17)))
 (let (($x5769 (and $x4646 (> (to_real (+ ?x5765 ?x4410)) 0.0))))
 (let ((?x5735 (ite (or c_3_1 c_3_5 c_3_7 c_3_11 c_3_13 c_3_17) 1 0)))
 (let ((?x5729 (ite (or c_1_1 c_1_4 c_1_7 c_1_10 c_1_13 c_1_16) 1 0)))
 (let ((?x5736 (+ 0 ?x5729)))
 (let ((?x5737 (+ ?x5736 ?x5735)))
 (let ((?x5734 (+ ?x5737 ?x4410)))
 (let (($x4637 (or c_0_14 c_0_15 c_0_16 c_0_17)))
 (let (($x5742 (and $x4637 (> (to_real (+ ?x5734 ?x4410)) 0.0))))
 (let (($x5743 (or false $x5742)))
 (let (($x5770 (or $x5743 $x5769)))
 (let (($x5790 (or $x5770 $x5789)))
 (let (($x5812 (or $x5790 $x5811)))
 (let (($x5839 (or $x5812 $x5838)))
 (let (($x5711 (or false c_0_13)))
 (let (($x5713 (or $x5711 c_1_13)))
 (let (($x5715 (or $x5713 c_2_13)))
 (let (($x5717 (or $x5715 c_3_13)))
 (let (($x5719 (or $x5717 c_4_13)))
 (let ((?x5692 (ite root_51 1 0)))
 (let ((?x5673 (ite root_49 1 0)))
 (let ((?x5657 (ite root_47 1 0)))
 (let ((?x5641 (ite root_45 1 0)))
 (let ((?x5622 (ite root_43 1 0)))
 (let ((?x5606 (ite root_41 1 0)))
 (let ((?x5607 (+ 0 ?x5606)))
 (let ((?x5623 (+ ?x5607 ?x5622)))
 (let ((?x5642 (+ ?x5623 ?x5641)))
 (let ((?x5658 (+ ?x5642 ?x5657)))
 (let ((?x5674 (+ ?x5658 ?x5673)))
 (let (($x5605 (or false root_41)))
 (let (($x5621 (or $x5605 root_43)))
 (let (($x5640 (or $x5621 root_45)))
 (let (($x5656 (or $x5640 root_47)))
 (let (($x5672 (or $x5656 root_49)))
 (let (($x5590 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_13 c_5_14 c_5_15 c_5_16 c_5_17 c_5_18)))
 (let (($x5576 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_13 c_4_14 c_4_15 c_4_16 c_4_17 c_4_18)))
 (let (($x5562 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_13 c_3_14 c_3_15 c_3_16 c_3_17 c_3_18)))
 (let (($x5548 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_13 c_2_14 c_2_15 c_2_16 c_2_17 c_2_18)))
 (let (($x5534 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_13 c_1_14 c_1_15 c_1_16 c_1_17 c_1_18)))
 (let (($x5520 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_13 c_0_14 c_0_15 c_0_16 c_0_17 c_0_18)))
 (let (($x5604 (or false $x5520)))
 (let (($x5620 (or $x5604 $x5534)))
 (let (($x5639 (or $x5620 $x5548)))
 (let (($x5655 (or $x5639 $x5562)))
 (let (($x5671 (or $x5655 $x5576)))
 (let (($x5698 (or false (and $x5576 (< rank_48 rank_50)))))
 (let (($x5702 (not root_51)))
 (let (($x5703 (and $x5590 $x5702)))
 (let (($x5679 (or false (and $x5590 (< rank_50 rank_48)))))
 (let (($x5682 (or $x5679 (and $x5562 (< rank_46 rank_48)))))
 (let (($x5686 (not root_49)))
 (let (($x5687 (and $x5576 $x5686)))
 (let (($x5663 (or false (and $x5576 (< rank_48 rank_46)))))
 (let (($x5667 (not root_47)))
 (let (($x5668 (and $x5562 $x5667)))
 (let (($x5647 (or false (and $x5590 (< rank_50 rank_44)))))
 (let (($x5651 (not root_45)))
 (let (($x5652 (and $x5548 $x5651)))
 (let (($x5628 (or false (and $x5548 (< rank_44 rank_42)))))
 (let (($x5631 (or $x5628 (and $x5576 (< rank_48 rank_42)))))
 (let (($x5635 (not root_43)))
 (let (($x5636 (and $x5534 $x5635)))
 (let (($x5612 (or false (and $x5534 (< rank_42 rank_40)))))
 (let (($x5616 (not root_41)))
 (let (($x5617 (and $x5520 $x5616)))
 (let (($x5609 (and true (=> root_41 $x5520))))
 (let (($x5619 (and $x5609 (=> $x5617 (or $x5612 (and $x5562 (< rank_46 rank_40)))))))
 (let (($x5625 (and $x5619 (=> root_43 $x5534))))
 (let (($x5638 (and $x5625 (=> $x5636 (or $x5631 (and $x5520 (< rank_40 rank_42)))))))
 (let (($x5644 (and $x5638 (=> root_45 $x5548))))
 (let (($x5654 (and $x5644 (=> $x5652 (or $x5647 (and $x5534 (< rank_42 rank_44)))))))
 (let (($x5660 (and $x5654 (=> root_47 $x5562))))
 (let (($x5670 (and $x5660 (=> $x5668 (or $x5663 (and $x5520 (< rank_40 rank_46)))))))
 (let (($x5676 (and $x5670 (=> root_49 $x5576))))
 (let (($x5689 (and $x5676 (=> $x5687 (or $x5682 (and $x5534 (< rank_42 rank_48)))))))
 (let (($x5695 (and $x5689 (=> root_51 $x5590))))
 (let (($x5707 (and (and $x5695 (=> $x5703 (or $x5698 (and $x5548 (< rank_44 rank_50))))) (=> (or $x5671 $x5590) (or $x5672 root_51)))))
 (let (($x5709 (and $x5707 (<= (+ ?x5674 ?x5692) 1))))
 (let (($x4187 (or c_5_1 c_5_7 c_5_13)))
 (let (($x5484 (and $x4187 (= prank_37 prank_high_39))))
 (let (($x4157 (or c_4_1 c_4_7 c_4_13)))
 (let (($x5461 (and $x4157 (= prank_36 prank_high_39))))
 (let (($x4188 (or c_3_1 c_3_7 c_3_13)))
 (let (($x5433 (and $x4188 (= prank_35 prank_high_39))))
 (let (($x4127 (or c_2_1 c_2_7 c_2_13)))
 (let (($x5410 (and $x4127 (= prank_34 prank_high_39))))
 (let (($x4104 (or c_1_1 c_1_7 c_1_13)))
 (let (($x5387 (and $x4104 (= prank_33 prank_high_39))))
 (let (($x4222 (or c_0_1 c_0_7 c_0_13)))
 (let (($x5359 (and $x4222 (= prank_32 prank_high_39))))
 (let (($x5360 (or false $x5359)))
 (let (($x5388 (or $x5360 $x5387)))
 (let (($x5411 (or $x5388 $x5410)))
 (let (($x5434 (or $x5411 $x5433)))
 (let (($x5462 (or $x5434 $x5461)))
 (let (($x5481 (and $x4187 (= prank_37 prank_low_38))))
 (let (($x5458 (and $x4157 (= prank_36 prank_low_38))))
 (let (($x5430 (and $x4188 (= prank_35 prank_low_38))))
 (let (($x5407 (and $x4127 (= prank_34 prank_low_38))))
 (let (($x5384 (and $x4104 (= prank_33 prank_low_38))))
 (let (($x5356 (and $x4222 (= prank_32 prank_low_38))))
 (let (($x5357 (or false $x5356)))
 (let (($x5385 (or $x5357 $x5384)))
 (let (($x5408 (or $x5385 $x5407)))
 (let (($x5431 (or $x5408 $x5430)))
 (let (($x5459 (or $x5431 $x5458)))
 (let (($x5487 (=> (or (or (or (or (or (or false $x4222) $x4104) $x4127) $x4188) $x4157) $x4187) (and (or $x5459 $x5481) (or $x5462 $x5484)))))
 (let (($x5289 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_14 c_2_15 c_2_16 c_2_17 c_2_18)))
 (let (($x5313 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_14 c_4_15 c_4_16 c_4_17 c_4_18)))
 (let (($x5467 (or false (and true (or $x5313 (and $x4157 (< prank_36 prank_37)))))))
 (let (($x5474 (and (or $x5467 (and true (or $x5289 (and $x4127 (< prank_34 prank_37))))) (<= prank_low_38 prank_37))))
 (let (($x5277 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_14 c_1_15 c_1_16 c_1_17 c_1_18)))
 (let (($x5301 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_14 c_3_15 c_3_16 c_3_17 c_3_18)))
 (let (($x5325 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_14 c_5_15 c_5_16 c_5_17 c_5_18)))
 (let (($x5439 (or false (and true (or $x5325 (and $x4187 (< prank_37 prank_36)))))))
 (let (($x5444 (or $x5439 (and true (or $x5301 (and $x4188 (< prank_35 prank_36)))))))
 (let (($x5451 (and (or $x5444 (and true (or $x5277 (and $x4104 (< prank_33 prank_36))))) (<= prank_low_38 prank_36))))
 (let (($x5265 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_14 c_0_15 c_0_16 c_0_17 c_0_18)))
 (let (($x5416 (or false (and true (or $x5313 (and $x4157 (< prank_36 prank_35)))))))
 (let (($x5423 (and (or $x5416 (and true (or $x5265 (and $x4222 (< prank_32 prank_35))))) (<= prank_low_38 prank_35))))
 (let (($x5393 (or false (and true (or $x5325 (and $x4187 (< prank_37 prank_34)))))))
 (let (($x5400 (and (or $x5393 (and true (or $x5277 (and $x4104 (< prank_33 prank_34))))) (<= prank_low_38 prank_34))))
 (let (($x5365 (or false (and true (or $x5289 (and $x4127 (< prank_34 prank_33)))))))
 (let (($x5370 (or $x5365 (and true (or $x5313 (and $x4157 (< prank_36 prank_33)))))))
 (let (($x5377 (and (or $x5370 (and true (or $x5265 (and $x4222 (< prank_32 prank_33))))) (<= prank_low_38 prank_33))))
 (let (($x5342 (or false (and true (or $x5277 (and $x4104 (< prank_33 prank_32)))))))
 (let (($x5349 (and (or $x5342 (and true (or $x5301 (and $x4188 (< prank_35 prank_32))))) (<= prank_low_38 prank_32))))
 (let (($x5353 (and true (=> $x4222 (and $x5349 (<= prank_32 prank_high_39))))))
 (let (($x5381 (and $x5353 (=> $x4104 (and $x5377 (<= prank_33 prank_high_39))))))
 (let (($x5404 (and $x5381 (=> $x4127 (and $x5400 (<= prank_34 prank_high_39))))))
 (let (($x5427 (and $x5404 (=> $x4188 (and $x5423 (<= prank_35 prank_high_39))))))
 (let (($x5455 (and $x5427 (=> $x4157 (and $x5451 (<= prank_36 prank_high_39))))))
 (let (($x5478 (and $x5455 (=> $x4187 (and $x5474 (<= prank_37 prank_high_39))))))
 (let (($x5488 (and $x5478 $x5487)))
 (let (($x4264 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_8 c_5_9 c_5_10 c_5_11 c_5_14 c_5_15 c_5_16 c_5_17)))
 (let (($x5234 (and $x4264 (= prank_29 prank_high_31))))
 (let (($x4191 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_8 c_4_9 c_4_10 c_4_11 c_4_14 c_4_15 c_4_16 c_4_17)))
 (let (($x5211 (and $x4191 (= prank_28 prank_high_31))))
 (let (($x4164 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_8 c_3_9 c_3_10 c_3_11 c_3_14 c_3_15 c_3_16 c_3_17)))
 (let (($x5183 (and $x4164 (= prank_27 prank_high_31))))
 (let (($x4228 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_8 c_2_9 c_2_10 c_2_11 c_2_14 c_2_15 c_2_16 c_2_17)))
 (let (($x5160 (and $x4228 (= prank_26 prank_high_31))))
 (let (($x4137 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_8 c_1_9 c_1_10 c_1_11 c_1_14 c_1_15 c_1_16 c_1_17)))
 (let (($x5137 (and $x4137 (= prank_25 prank_high_31))))
 (let (($x4110 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_8 c_0_9 c_0_10 c_0_11 c_0_14 c_0_15 c_0_16 c_0_17)))
 (let (($x5109 (and $x4110 (= prank_24 prank_high_31))))
 (let (($x5110 (or false $x5109)))
 (let (($x5138 (or $x5110 $x5137)))
 (let (($x5161 (or $x5138 $x5160)))
 (let (($x5184 (or $x5161 $x5183)))
 (let (($x5212 (or $x5184 $x5211)))
 (let (($x5231 (and $x4264 (= prank_29 prank_low_30))))
 (let (($x5208 (and $x4191 (= prank_28 prank_low_30))))
 (let (($x5180 (and $x4164 (= prank_27 prank_low_30))))
 (let (($x5157 (and $x4228 (= prank_26 prank_low_30))))
 (let (($x5134 (and $x4137 (= prank_25 prank_low_30))))
 (let (($x5106 (and $x4110 (= prank_24 prank_low_30))))
 (let (($x5107 (or false $x5106)))
 (let (($x5135 (or $x5107 $x5134)))
 (let (($x5158 (or $x5135 $x5157)))
 (let (($x5181 (or $x5158 $x5180)))
 (let (($x5209 (or $x5181 $x5208)))
 (let (($x5237 (=> (or (or (or (or (or (or false $x4110) $x4137) $x4228) $x4164) $x4191) $x4264) (and (or $x5209 $x5231) (or $x5212 $x5234)))))
 (let (($x3882 (or c_2_6 c_2_12 c_2_18)))
 (let (($x4567 (or c_5_5 c_5_11 c_5_17)))
 (let (($x3864 (or c_4_6 c_4_12 c_4_18)))
 (let (($x4523 (or c_5_4 c_5_10 c_5_16)))
 (let (($x5217 (or false (and $x4523 (or $x3864 (and $x4191 (< prank_28 prank_29)))))))
 (let (($x5224 (and (or $x5217 (and $x4567 (or $x3882 (and $x4228 (< prank_26 prank_29))))) (<= prank_low_30 prank_29))))
 (let (($x3844 (or c_1_6 c_1_12 c_1_18)))
 (let (($x4459 (or c_4_5 c_4_11 c_4_17)))
 (let (($x3854 (or c_3_6 c_3_12 c_3_18)))
 (let (($x4490 (or c_4_4 c_4_10 c_4_16)))
 (let (($x3901 (or c_5_6 c_5_12 c_5_18)))
 (let (($x4606 (or c_4_2 c_4_8 c_4_14)))
 (let (($x5189 (or false (and $x4606 (or $x3901 (and $x4264 (< prank_29 prank_28)))))))
 (let (($x5194 (or $x5189 (and $x4490 (or $x3854 (and $x4164 (< prank_27 prank_28)))))))
 (let (($x5201 (and (or $x5194 (and $x4459 (or $x3844 (and $x4137 (< prank_25 prank_28))))) (<= prank_low_30 prank_28))))
 (let (($x3834 (or c_0_6 c_0_12 c_0_18)))
 (let (($x4424 (or c_3_5 c_3_11 c_3_17)))
 (let (($x4525 (or c_3_2 c_3_8 c_3_14)))
 (let (($x5166 (or false (and $x4525 (or $x3864 (and $x4191 (< prank_28 prank_27)))))))
 (let (($x5173 (and (or $x5166 (and $x4424 (or $x3834 (and $x4110 (< prank_24 prank_27))))) (<= prank_low_30 prank_27))))
 (let (($x4455 (or c_2_4 c_2_10 c_2_16)))
 (let (($x4609 (or c_2_3 c_2_9 c_2_15)))
 (let (($x5143 (or false (and $x4609 (or $x3901 (and $x4264 (< prank_29 prank_26)))))))
 (let (($x5150 (and (or $x5143 (and $x4455 (or $x3844 (and $x4137 (< prank_25 prank_26))))) (<= prank_low_30 prank_26))))
 (let (($x4420 (or c_1_4 c_1_10 c_1_16)))
 (let (($x4528 (or c_1_3 c_1_9 c_1_15)))
 (let (($x4568 (or c_1_2 c_1_8 c_1_14)))
 (let (($x5115 (or false (and $x4568 (or $x3882 (and $x4228 (< prank_26 prank_25)))))))
 (let (($x5120 (or $x5115 (and $x4528 (or $x3864 (and $x4191 (< prank_28 prank_25)))))))
 (let (($x5127 (and (or $x5120 (and $x4420 (or $x3834 (and $x4110 (< prank_24 prank_25))))) (<= prank_low_30 prank_25))))
 (let (($x4493 (or c_0_3 c_0_9 c_0_15)))
 (let (($x4460 (or c_0_2 c_0_8 c_0_14)))
 (let (($x5092 (or false (and $x4460 (or $x3844 (and $x4137 (< prank_25 prank_24)))))))
 (let (($x5099 (and (or $x5092 (and $x4493 (or $x3854 (and $x4164 (< prank_27 prank_24))))) (<= prank_low_30 prank_24))))
 (let (($x5103 (and true (=> $x4110 (and $x5099 (<= prank_24 prank_high_31))))))
 (let (($x5131 (and $x5103 (=> $x4137 (and $x5127 (<= prank_25 prank_high_31))))))
 (let (($x5154 (and $x5131 (=> $x4228 (and $x5150 (<= prank_26 prank_high_31))))))
 (let (($x5177 (and $x5154 (=> $x4164 (and $x5173 (<= prank_27 prank_high_31))))))
 (let (($x5205 (and $x5177 (=> $x4191 (and $x5201 (<= prank_28 prank_high_31))))))
 (let (($x5228 (and $x5205 (=> $x4264 (and $x5224 (<= prank_29 prank_high_31))))))
 (let (($x5238 (and $x5228 $x5237)))
 (let (($x2364 (not in_target_5)))
 (let (($x3412 (and c_5_12 $x2364)))
 (let (($x3393 (and c_5_6 $x2364)))
 (let (($x3380 (and c_5_18 $x2364)))
 (let (($x2349 (not in_target_4)))
 (let (($x3313 (and c_4_12 $x2349)))
 (let (($x3294 (and c_4_6 $x2349)))
 (let (($x3281 (and c_4_18 $x2349)))
 (let (($x5028 (or $x3281 $x3294 $x3313)))
 (let (($x2334 (not in_target_3)))
 (let (($x3214 (and c_3_12 $x2334)))
 (let (($x3195 (and c_3_6 $x2334)))
 (let (($x3182 (and c_3_18 $x2334)))
 (let (($x5023 (or $x3182 $x3195 $x3214)))
 (let (($x2319 (not in_target_2)))
 (let (($x3115 (and c_2_12 $x2319)))
 (let (($x3096 (and c_2_6 $x2319)))
 (let (($x3083 (and c_2_18 $x2319)))
 (let (($x5018 (or $x3083 $x3096 $x3115)))
 (let (($x2304 (not in_target_1)))
 (let (($x3016 (and c_1_12 $x2304)))
 (let (($x2997 (and c_1_6 $x2304)))
 (let (($x2984 (and c_1_18 $x2304)))
 (let (($x5013 (or $x2984 $x2997 $x3016)))
 (let (($x2291 (not in_target_0)))
 (let (($x2917 (and c_0_12 $x2291)))
 (let (($x2897 (and c_0_6 $x2291)))
 (let (($x2883 (and c_0_18 $x2291)))
 (let (($x5008 (or $x2883 $x2897 $x2917)))
 (let (($x5005 (or false $x5008)))
 (let (($x5010 (or $x5005 $x5013)))
 (let (($x5015 (or $x5010 $x5018)))
 (let (($x5020 (or $x5015 $x5023)))
 (let (($x5025 (or $x5020 $x5028)))
 (let ((?x4984 (ite root_23 1 0)))
 (let ((?x4966 (ite root_21 1 0)))
 (let ((?x4951 (ite root_19 1 0)))
 (let ((?x4936 (ite root_17 1 0)))
 (let ((?x4918 (ite root_15 1 0)))
 (let ((?x4903 (ite root_13 1 0)))
 (let ((?x4904 (+ 0 ?x4903)))
 (let ((?x4919 (+ ?x4904 ?x4918)))
 (let ((?x4937 (+ ?x4919 ?x4936)))
 (let ((?x4952 (+ ?x4937 ?x4951)))
 (let ((?x4967 (+ ?x4952 ?x4966)))
 (let (($x4902 (or false root_13)))
 (let (($x4917 (or $x4902 root_15)))
 (let (($x4935 (or $x4917 root_17)))
 (let (($x4950 (or $x4935 root_19)))
 (let (($x4965 (or $x4950 root_21)))
 (let (($x4863 (or false $x3834)))
 (let (($x4858 (or $x4863 $x3844)))
 (let (($x4865 (or $x4858 $x3882)))
 (let (($x4867 (or $x4865 $x3854)))
 (let (($x4869 (or $x4867 $x3864)))
 (let (($x4871 (or $x4869 $x3901)))
 (let (($x4990 (or false (and $x3864 (< rank_20 rank_22)))))
 (let (($x4994 (not root_23)))
 (let (($x4995 (and $x3901 $x4994)))
 (let (($x4972 (or false (and $x3901 (< rank_22 rank_20)))))
 (let (($x4975 (or $x4972 (and $x3854 (< rank_18 rank_20)))))
 (let (($x4979 (not root_21)))
 (let (($x4980 (and $x3864 $x4979)))
 (let (($x4957 (or false (and $x3864 (< rank_20 rank_18)))))
 (let (($x4961 (not root_19)))
 (let (($x4962 (and $x3854 $x4961)))
 (let (($x4942 (or false (and $x3901 (< rank_22 rank_16)))))
 (let (($x4946 (not root_17)))
 (let (($x4947 (and $x3882 $x4946)))
 (let (($x4924 (or false (and $x3882 (< rank_16 rank_14)))))
 (let (($x4927 (or $x4924 (and $x3864 (< rank_20 rank_14)))))
 (let (($x4931 (not root_15)))
 (let (($x4932 (and $x3844 $x4931)))
 (let (($x4909 (or false (and $x3844 (< rank_14 rank_12)))))
 (let (($x4913 (not root_13)))
 (let (($x4914 (and $x3834 $x4913)))
 (let (($x4906 (and true (=> root_13 $x3834))))
 (let (($x4916 (and $x4906 (=> $x4914 (or $x4909 (and $x3854 (< rank_18 rank_12)))))))
 (let (($x4921 (and $x4916 (=> root_15 $x3844))))
 (let (($x4934 (and $x4921 (=> $x4932 (or $x4927 (and $x3834 (< rank_12 rank_14)))))))
 (let (($x4939 (and $x4934 (=> root_17 $x3882))))
 (let (($x4949 (and $x4939 (=> $x4947 (or $x4942 (and $x3844 (< rank_14 rank_16)))))))
 (let (($x4954 (and $x4949 (=> root_19 $x3854))))
 (let (($x4964 (and $x4954 (=> $x4962 (or $x4957 (and $x3834 (< rank_12 rank_18)))))))
 (let (($x4969 (and $x4964 (=> root_21 $x3864))))
 (let (($x4982 (and $x4969 (=> $x4980 (or $x4975 (and $x3844 (< rank_14 rank_20)))))))
 (let (($x4987 (and $x4982 (=> root_23 $x3901))))
 (let (($x4999 (and (and $x4987 (=> $x4995 (or $x4990 (and $x3882 (< rank_16 rank_22))))) (=> $x4871 (or $x4965 root_23)))))
 (let (($x5001 (and $x4999 (<= (+ ?x4967 ?x4984) 1))))
 (let (($x5239 (and (and (and $x4871 $x5001) (not (or $x5025 (or $x3380 $x3393 $x3412)))) $x5238)))
 (let (($x5859 (and (and (and (and $x5239 $x5488) $x5709) (not (or $x5719 c_5_13))) (not (or $x5839 (and $x4702 (> (to_real (+ ?x5853 ?x5854)) 0.0)))))))
 (let (($x4613 (= (to_real (+ (+ ?x4598 (ite $x4606 1 0)) (ite $x4609 1 0))) 0.0)))
 (let (($x4602 (= (to_real (+ (+ ?x4598 (ite $x4157 1 0)) (ite $x4127 1 0))) 0.0)))
 (let (($x4614 (and $x4602 $x4613)))
 (let (($x4445 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6)))
 (let (($x4698 (and true $x4702)))
 (let (($x4711 (and $x4698 $x4445)))
 (let (($x4714 (not (and $x4711 $x4614))))
 (let ((?x4532 (ite $x4528 1 0)))
 (let ((?x4530 (ite $x4525 1 0)))
 (let ((?x4526 (ite $x4523 1 0)))
 (let ((?x4527 (+ 0 ?x4526)))
 (let ((?x4529 (+ ?x4527 ?x4410)))
 (let ((?x4531 (+ ?x4529 ?x4530)))
 (let ((?x4406 (ite $x4104 1 0)))
 (let ((?x4408 (ite $x4188 1 0)))
 (let ((?x4511 (ite $x4187 1 0)))
 (let ((?x4512 (+ 0 ?x4511)))
 (let ((?x4514 (+ ?x4512 ?x4410)))
 (let ((?x4513 (+ ?x4514 ?x4408)))
 (let (($x4536 (and (= (to_real (+ ?x4513 ?x4406)) 0.0) (= (to_real (+ ?x4531 ?x4532)) 0.0))))
 (let (($x4409 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6)))
 (let (($x4660 (and true $x4664)))
 (let (($x4705 (and $x4660 $x4409)))
 (let (($x4709 (not (and $x4705 $x4536))))
 (let ((?x4496 (ite $x4493 1 0)))
 (let ((?x4491 (ite $x4490 1 0)))
 (let ((?x4492 (+ 0 ?x4491)))
 (let ((?x4494 (+ ?x4492 ?x4410)))
 (let ((?x4495 (+ ?x4494 ?x4410)))
 (let ((?x4446 (ite $x4222 1 0)))
 (let ((?x4441 (ite $x4157 1 0)))
 (let ((?x4479 (+ 0 ?x4441)))
 (let ((?x4482 (+ ?x4479 ?x4410)))
 (let ((?x4480 (+ ?x4482 ?x4410)))
 (let (($x4500 (and (= (to_real (+ ?x4480 ?x4446)) 0.0) (= (to_real (+ ?x4495 ?x4496)) 0.0))))
 (let (($x4587 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6)))
 (let (($x4651 (and true $x4655)))
 (let (($x4703 (and $x4651 $x4587)))
 (let (($x4706 (not (and $x4703 $x4500))))
 (let (($x4483 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6)))
 (let (($x4699 (and $x4698 $x4483)))
 (let (($x4704 (not (and $x4699 $x4614))))
 (let (($x4549 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6)))
 (let (($x4689 (and $x4660 $x4549)))
 (let (($x4695 (not (and $x4689 $x4536))))
 (let ((?x4572 (to_real (+ (+ (+ ?x4556 (ite $x4567 1 0)) (ite $x4568 1 0)) ?x4410))))
 (let (($x4574 (and (= (to_real (+ (+ (+ ?x4556 ?x4511) ?x4406) ?x4410)) 0.0) (= ?x4572 0.0))))
 (let (($x4677 (and true $x4681)))
 (let (($x4684 (and $x4677 $x4409)))
 (let (($x4688 (not (and $x4684 $x4574))))
 (let ((?x4463 (ite $x4460 1 0)))
 (let ((?x4461 (ite $x4459 1 0)))
 (let ((?x4457 (ite $x4455 1 0)))
 (let ((?x4458 (+ 0 ?x4457)))
 (let ((?x4462 (+ ?x4458 ?x4461)))
 (let ((?x4464 (+ ?x4462 ?x4463)))
 (let ((?x4449 (to_real (+ (+ (+ (+ 0 (ite $x4127 1 0)) ?x4441) ?x4446) ?x4410))))
 (let (($x4468 (and (= ?x4449 0.0) (= (to_real (+ ?x4464 ?x4410)) 0.0))))
 (let (($x4642 (and true $x4646)))
 (let (($x4682 (and $x4642 $x4587)))
 (let (($x4686 (not (and $x4682 $x4468))))
 (let (($x4515 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6)))
 (let (($x4678 (and $x4677 $x4515)))
 (let (($x4679 (not (and $x4678 $x4574))))
 (let (($x4674 (not (and (and $x4642 $x4483) $x4468))))
 (let ((?x4423 (ite $x4424 1 0)))
 (let ((?x4421 (ite $x4420 1 0)))
 (let ((?x4422 (+ 0 ?x4421)))
 (let ((?x4425 (+ ?x4422 ?x4423)))
 (let ((?x4426 (+ ?x4425 ?x4410)))
 (let (($x4430 (and (= (to_real (+ (+ (+ (+ 0 ?x4406) ?x4408) ?x4410) ?x4410)) 0.0) (= (to_real (+ ?x4426 ?x4410)) 0.0))))
 (let (($x4633 (and true $x4637)))
 (let (($x4665 (and $x4633 $x4549)))
 (let (($x4670 (not (and $x4665 $x4430))))
 (let (($x4663 (not (and (and $x4660 $x4515) $x4536))))
 (let (($x4657 (not (and (and $x4651 $x4483) $x4500))))
 (let (($x4645 (not (and (and $x4642 $x4445) $x4468))))
 (let (($x4636 (not (and (and $x4633 $x4409) $x4430))))
 (let (($x4597 (or c_5_2 c_5_3 c_5_4 c_5_5)))
 (let (($x4592 (and true $x4597)))
 (let (($x4625 (and $x4592 $x4445)))
 (let (($x4628 (not (and $x4625 $x4614))))
 (let (($x4506 (or c_4_2 c_4_3 c_4_4 c_4_5)))
 (let (($x4504 (and true $x4506)))
 (let (($x4619 (and $x4504 $x4409)))
 (let (($x4623 (not (and $x4619 $x4536))))
 (let (($x4474 (or c_3_2 c_3_3 c_3_4 c_3_5)))
 (let (($x4472 (and true $x4474)))
 (let (($x4618 (and $x4472 $x4587)))
 (let (($x4621 (not (and $x4618 $x4500))))
 (let (($x4616 (not (and (and $x4592 $x4483) $x4614))))
 (let (($x4595 (not (and (and $x4504 $x4549) $x4536))))
 (let (($x4555 (or c_2_2 c_2_3 c_2_4 c_2_5)))
 (let (($x4552 (and true $x4555)))
 (let (($x4583 (and $x4552 $x4409)))
 (let (($x4588 (not (and $x4583 $x4574))))
 (let (($x4436 (or c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x4435 (and true $x4436)))
 (let (($x4582 (and $x4435 $x4587)))
 (let (($x4585 (not (and $x4582 $x4468))))
 (let (($x4576 (not (and (and $x4552 $x4515) $x4574))))
 (let (($x4553 (not (and (and $x4435 $x4483) $x4468))))
 (let (($x4400 (or c_0_2 c_0_3 c_0_4 c_0_5)))
 (let (($x4398 (and true $x4400)))
 (let (($x4544 (and $x4398 $x4549)))
 (let (($x4548 (not (and $x4544 $x4430))))
 (let (($x4538 (not (and (and $x4504 $x4515) $x4536))))
 (let (($x4502 (not (and (and $x4472 $x4483) $x4500))))
 (let (($x4470 (not (and (and $x4435 $x4445) $x4468))))
 (let (($x4432 (not (and (and $x4398 $x4409) $x4430))))
 (let (($x4828 (not in_target_29)))
 (let (($x4826 (not in_target_28)))
 (let (($x4824 (not in_target_27)))
 (let (($x4822 (not in_target_26)))
 (let (($x4820 (not in_target_25)))
 (let (($x4818 (not in_target_24)))
 (let (($x4816 (not in_target_23)))
 (let (($x4814 (not in_target_22)))
 (let (($x4812 (not in_target_21)))
 (let (($x4810 (not in_target_20)))
 (let (($x4808 (not in_target_19)))
 (let (($x4806 (not in_target_18)))
 (let (($x4804 (not in_target_17)))
 (let (($x4802 (not in_target_16)))
 (let (($x4800 (not in_target_15)))
 (let (($x4798 (not in_target_14)))
 (let (($x4796 (not in_target_13)))
 (let (($x4794 (not in_target_12)))
 (let (($x4792 (not in_target_11)))
 (let (($x4790 (not in_target_10)))
 (let (($x4788 (not in_target_9)))
 (let (($x4786 (not in_target_8)))
 (let (($x4784 (not in_target_7)))
 (let (($x4782 (not in_target_6)))
 (let (($x4783 (and true $x4782)))
 (let (($x4785 (and $x4783 $x4784)))
 (let (($x4787 (and $x4785 $x4786)))
 (let (($x4789 (and $x4787 $x4788)))
 (let (($x4791 (and $x4789 $x4790)))
 (let (($x4793 (and $x4791 $x4792)))
 (let (($x4795 (and $x4793 $x4794)))
 (let (($x4797 (and $x4795 $x4796)))
 (let (($x4799 (and $x4797 $x4798)))
 (let (($x4801 (and $x4799 $x4800)))
 (let (($x4803 (and $x4801 $x4802)))
 (let (($x4805 (and $x4803 $x4804)))
 (let (($x4807 (and $x4805 $x4806)))
 (let (($x4809 (and $x4807 $x4808)))
 (let (($x4811 (and $x4809 $x4810)))
 (let (($x4813 (and $x4811 $x4812)))
 (let (($x4815 (and $x4813 $x4814)))
 (let (($x4817 (and $x4815 $x4816)))
 (let (($x4819 (and $x4817 $x4818)))
 (let (($x4821 (and $x4819 $x4820)))
 (let (($x4823 (and $x4821 $x4822)))
 (let (($x4825 (and $x4823 $x4824)))
 (let (($x4827 (and $x4825 $x4826)))
 (let (($x4829 (and $x4827 $x4828)))
 (let (($x4834 (and $x4829 $x4432)))
 (let (($x4835 (and $x4834 $x4470)))
 (let (($x4837 (and $x4835 $x4502)))
 (let (($x4836 (and $x4837 $x4538)))
 (let (($x4833 (and $x4836 $x4548)))
 (let (($x4841 (and $x4833 $x4553)))
 (let (($x4840 (and $x4841 $x4576)))
 (let (($x4838 (and $x4840 $x4585)))
 (let (($x4843 (and $x4838 $x4588)))
 (let (($x4844 (and $x4843 $x4595)))
 (let (($x4845 (and $x4844 $x4616)))
 (let (($x4846 (and $x4845 $x4621)))
 (let (($x4842 (and $x4846 $x4623)))
 (let (($x4848 (and $x4842 $x4628)))
 (let (($x4847 (and $x4848 $x4636)))
 (let (($x4850 (and $x4847 $x4645)))
 (let (($x4839 (and $x4850 $x4657)))
 (let (($x4851 (and $x4839 $x4663)))
 (let (($x4853 (and $x4851 $x4670)))
 (let (($x4849 (and $x4853 $x4674)))
 (let (($x4855 (and $x4849 $x4679)))
 (let (($x4856 (and $x4855 $x4686)))
 (let (($x4857 (and $x4856 $x4688)))
 (let (($x4852 (and $x4857 $x4695)))
 (let (($x4859 (and $x4852 $x4704)))
 (let (($x4860 (and $x4859 $x4706)))
 (let (($x4854 (and $x4860 $x4709)))
 (let (($x4389 (or c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4384 (and true $x4389)))
 (let (($x4354 (or c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4349 (and true $x4354)))
 (let (($x4344 (or c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x4339 (and true $x4344)))
 (let (($x4370 (or c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x4365 (and true $x4370)))
 (let (($x4334 (or c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x4329 (and true $x4334)))
 (let (($x4324 (or c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x4319 (and true $x4324)))
 (let (($x3106 (and c_2_7 $x2319)))
 (let (($x3087 (and c_2_1 $x2319)))
 (let (($x3073 (and c_2_13 $x2319)))
 (let (($x4034 (or $x3073 $x3087 $x3106)))
 (let (($x3898 (and true $x3901)))
 (let (($x3007 (and c_1_7 $x2304)))
 (let (($x2988 (and c_1_1 $x2304)))
 (let (($x2974 (and c_1_13 $x2304)))
 (let (($x4029 (or $x2974 $x2988 $x3007)))
 (let (($x3861 (and true $x3864)))
 (let (($x2908 (and c_0_7 $x2291)))
 (let (($x2888 (and c_0_1 $x2291)))
 (let (($x2873 (and c_0_13 $x2291)))
 (let (($x4060 (or $x2873 $x2888 $x2908)))
 (let (($x3851 (and true $x3854)))
 (let (($x3304 (and c_4_7 $x2349)))
 (let (($x3285 (and c_4_1 $x2349)))
 (let (($x3271 (and c_4_13 $x2349)))
 (let (($x4039 (or $x3271 $x3285 $x3304)))
 (let (($x3205 (and c_3_7 $x2334)))
 (let (($x3186 (and c_3_1 $x2334)))
 (let (($x3172 (and c_3_13 $x2334)))
 (let (($x4049 (or $x3172 $x3186 $x3205)))
 (let (($x3403 (and c_5_7 $x2364)))
 (let (($x3384 (and c_5_1 $x2364)))
 (let (($x3370 (and c_5_13 $x2364)))
 (let (($x4044 (or $x3370 $x3384 $x3403)))
 (let (($x3879 (and true $x3882)))
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
 (let (($x3949 (or $x2527 $x2529 $x2531 $x2533 $x2538 $x2540 $x2542 $x2544 $x2549 $x2551 $x2553 $x2555)))
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
 (let (($x3934 (or $x2474 $x2476 $x2478 $x2480 $x2485 $x2487 $x2489 $x2491 $x2496 $x2498 $x2500 $x2502)))
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
 (let (($x4015 (or $x2421 $x2423 $x2425 $x2427 $x2432 $x2434 $x2436 $x2438 $x2443 $x2445 $x2447 $x2449)))
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
 (let (($x3964 (or $x2633 $x2635 $x2637 $x2639 $x2644 $x2646 $x2648 $x2650 $x2655 $x2657 $x2659 $x2661)))
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
 (let (($x3994 (or $x2580 $x2582 $x2584 $x2586 $x2591 $x2593 $x2595 $x2597 $x2602 $x2604 $x2606 $x2608)))
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
 (let (($x3979 (or $x2686 $x2688 $x2690 $x2692 $x2697 $x2699 $x2701 $x2703 $x2708 $x2710 $x2712 $x2714)))
 (let (($x2547 (and c_2_13 in_target_2)))
 (let (($x2536 (and c_2_7 in_target_2)))
 (let (($x2525 (and c_2_1 in_target_2)))
 (let (($x3846 (or $x2525 $x2536 $x2547)))
 (let (($x2494 (and c_1_13 in_target_1)))
 (let (($x2483 (and c_1_7 in_target_1)))
 (let (($x2472 (and c_1_1 in_target_1)))
 (let (($x3836 (or $x2472 $x2483 $x2494)))
 (let (($x2441 (and c_0_13 in_target_0)))
 (let (($x2430 (and c_0_7 in_target_0)))
 (let (($x2419 (and c_0_1 in_target_0)))
 (let (($x3887 (or $x2419 $x2430 $x2441)))
 (let (($x2653 (and c_4_13 in_target_4)))
 (let (($x2642 (and c_4_7 in_target_4)))
 (let (($x2631 (and c_4_1 in_target_4)))
 (let (($x3856 (or $x2631 $x2642 $x2653)))
 (let (($x2600 (and c_3_13 in_target_3)))
 (let (($x2589 (and c_3_7 in_target_3)))
 (let (($x2578 (and c_3_1 in_target_3)))
 (let (($x3871 (or $x2578 $x2589 $x2600)))
 (let (($x2706 (and c_5_13 in_target_5)))
 (let (($x2695 (and c_5_7 in_target_5)))
 (let (($x2684 (and c_5_1 in_target_5)))
 (let (($x3866 (or $x2684 $x2695 $x2706)))
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
 (let ((?x3731 (ite (or $x3370 $x3372 $x3374 $x3376 $x3378 $x3380) 1 0)))
 (let ((?x3717 (ite (or (and c_5_6 in_target_5) $x2684 $x2686 $x2688 $x2690 $x2692) (- 1) 0)))
 (let (($x2716 (and c_5_18 in_target_5)))
 (let (($x3350 (or $x2706 $x2708 $x2710 $x2712 $x2714 $x2716)))
 (let ((?x3721 (ite $x3350 (- 2) 0)))
 (let (($x2683 (and c_5_0 in_target_5)))
 (let ((?x3719 (ite $x2683 (- 3) 0)))
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
 (let ((?x3690 (ite (or $x3271 $x3273 $x3275 $x3277 $x3279 $x3281) 1 0)))
 (let ((?x3682 (ite (or (and c_4_6 in_target_4) $x2631 $x2633 $x2635 $x2637 $x2639) (- 1) 0)))
 (let (($x2663 (and c_4_18 in_target_4)))
 (let (($x3251 (or $x2653 $x2655 $x2657 $x2659 $x2661 $x2663)))
 (let ((?x3668 (ite $x3251 (- 2) 0)))
 (let (($x2630 (and c_4_0 in_target_4)))
 (let ((?x3678 (ite $x2630 (- 3) 0)))
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
 (let ((?x3649 (ite (or $x3172 $x3174 $x3176 $x3178 $x3180 $x3182) 1 0)))
 (let ((?x3640 (ite (or (and c_3_6 in_target_3) $x2578 $x2580 $x2582 $x2584 $x2586) (- 1) 0)))
 (let (($x2610 (and c_3_18 in_target_3)))
 (let (($x3152 (or $x2600 $x2602 $x2604 $x2606 $x2608 $x2610)))
 (let ((?x3632 (ite $x3152 (- 2) 0)))
 (let (($x2577 (and c_3_0 in_target_3)))
 (let ((?x3641 (ite $x2577 (- 3) 0)))
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
 (let ((?x3608 (ite (or $x3073 $x3075 $x3077 $x3079 $x3081 $x3083) 1 0)))
 (let ((?x3602 (ite (or (and c_2_6 in_target_2) $x2525 $x2527 $x2529 $x2531 $x2533) (- 1) 0)))
 (let (($x2557 (and c_2_18 in_target_2)))
 (let (($x3053 (or $x2547 $x2549 $x2551 $x2553 $x2555 $x2557)))
 (let ((?x3590 (ite $x3053 (- 2) 0)))
 (let (($x2524 (and c_2_0 in_target_2)))
 (let ((?x3586 (ite $x2524 (- 3) 0)))
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
 (let ((?x3567 (ite (or $x2974 $x2976 $x2978 $x2980 $x2982 $x2984) 1 0)))
 (let ((?x3558 (ite (or (and c_1_6 in_target_1) $x2472 $x2474 $x2476 $x2478 $x2480) (- 1) 0)))
 (let (($x2504 (and c_1_18 in_target_1)))
 (let (($x2954 (or $x2494 $x2496 $x2498 $x2500 $x2502 $x2504)))
 (let ((?x3561 (ite $x2954 (- 2) 0)))
 (let (($x2471 (and c_1_0 in_target_1)))
 (let ((?x3550 (ite $x2471 (- 3) 0)))
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
 (let ((?x3526 (ite (or $x2873 $x2875 $x2877 $x2879 $x2881 $x2883) 1 0)))
 (let ((?x3518 (ite (or (and c_0_6 in_target_0) $x2419 $x2421 $x2423 $x2425 $x2427) (- 1) 0)))
 (let (($x2451 (and c_0_18 in_target_0)))
 (let (($x2853 (or $x2441 $x2443 $x2445 $x2447 $x2449 $x2451)))
 (let ((?x3511 (ite $x2853 (- 2) 0)))
 (let (($x2418 (and c_0_0 in_target_0)))
 (let ((?x3509 (ite $x2418 (- 3) 0)))
 (let ((?x3510 (+ 0 ?x3509)))
 (let ((?x3512 (+ ?x3510 ?x3511)))
 (let ((?x3521 (+ ?x3512 ?x3518)))
 (let ((?x3527 (+ ?x3521 ?x3526)))
 (let ((?x3528 (+ ?x3527 ?x2886)))
 (let ((?x3531 (+ ?x3528 ?x2906)))
 (let ((?x3545 (+ ?x3531 ?x3550)))
 (let ((?x3554 (+ ?x3545 ?x3561)))
 (let ((?x3549 (+ ?x3554 ?x3558)))
 (let ((?x3568 (+ ?x3549 ?x3567)))
 (let ((?x3572 (+ ?x3568 ?x2986)))
 (let ((?x3570 (+ ?x3572 ?x3005)))
 (let ((?x3598 (+ ?x3570 ?x3586)))
 (let ((?x3599 (+ ?x3598 ?x3590)))
 (let ((?x3591 (+ ?x3599 ?x3602)))
 (let ((?x3609 (+ ?x3591 ?x3608)))
 (let ((?x3612 (+ ?x3609 ?x3085)))
 (let ((?x3611 (+ ?x3612 ?x3104)))
 (let ((?x3637 (+ ?x3611 ?x3641)))
 (let ((?x3634 (+ ?x3637 ?x3632)))
 (let ((?x3645 (+ ?x3634 ?x3640)))
 (let ((?x3650 (+ ?x3645 ?x3649)))
 (let ((?x3652 (+ ?x3650 ?x3184)))
 (let ((?x3651 (+ ?x3652 ?x3203)))
 (let ((?x3672 (+ ?x3651 ?x3678)))
 (let ((?x3675 (+ ?x3672 ?x3668)))
 (let ((?x3686 (+ ?x3675 ?x3682)))
 (let ((?x3691 (+ ?x3686 ?x3690)))
 (let ((?x3695 (+ ?x3691 ?x3283)))
 (let ((?x3693 (+ ?x3695 ?x3302)))
 (let ((?x3718 (+ ?x3693 ?x3719)))
 (let ((?x3725 (+ ?x3718 ?x3721)))
 (let ((?x3709 (+ ?x3725 ?x3717)))
 (let ((?x3732 (+ ?x3709 ?x3731)))
 (let ((?x3733 (+ ?x3732 ?x3382)))
 (let (($x3762 (<= (+ ?x3733 ?x3401) 0)))
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
 (let (($x3827 (and $x2375 (and (and $x2837 $x3432) $x3762))))
 (let (($x3837 (and $x3827 (not (and (and true $x3834) $x3836)))))
 (let (($x3847 (and $x3837 (not (and (and true $x3844) $x3846)))))
 (let (($x3857 (and $x3847 (not (and $x3851 $x3856)))))
 (let (($x3867 (and $x3857 (not (and $x3861 $x3866)))))
 (let (($x3872 (and $x3867 (not (and (and true $x3834) $x3871)))))
 (let (($x3875 (and $x3872 (not (and (and true $x3844) $x3856)))))
 (let (($x3883 (and $x3875 (not (and $x3879 $x3866)))))
 (let (($x3888 (and $x3883 (not (and (and true $x3844) $x3887)))))
 (let (($x3891 (and $x3888 (not (and $x3879 $x3836)))))
 (let (($x3894 (and $x3891 (not (and $x3861 $x3871)))))
 (let (($x3902 (and $x3894 (not (and $x3898 $x3856)))))
 (let (($x3905 (and $x3902 (not (and $x3851 $x3887)))))
 (let (($x3908 (and $x3905 (not (and $x3861 $x3836)))))
 (let (($x3911 (and $x3908 (not (and $x3898 $x3846)))))
 (let (($x3927 (and $x3911 (not (and (and true $x3834) $x3934)))))
 (let (($x3941 (and $x3927 (not (and (and true $x3844) $x3949)))))
 (let (($x3961 (and $x3941 (not (and $x3851 $x3964)))))
 (let (($x3973 (and $x3961 (not (and $x3861 $x3979)))))
 (let (($x3991 (and $x3973 (not (and (and true $x3834) $x3994)))))
 (let (($x3995 (and $x3991 (not (and (and true $x3844) $x3964)))))
 (let (($x3986 (and $x3995 (not (and $x3879 $x3979)))))
 (let (($x4014 (and $x3986 (not (and (and true $x3844) $x4015)))))
 (let (($x4012 (and $x4014 (not (and $x3879 $x3934)))))
 (let (($x4019 (and $x4012 (not (and $x3861 $x3994)))))
 (let (($x4022 (and $x4019 (not (and $x3898 $x3964)))))
 (let (($x4027 (and $x4022 (not (and $x3851 $x4015)))))
 (let (($x4025 (and $x4027 (not (and $x3861 $x3934)))))
 (let (($x4024 (and $x4025 (not (and $x3898 $x3949)))))
 (let (($x4033 (and $x4024 (not (and (and true $x3834) $x4029)))))
 (let (($x4035 (and $x4033 (not (and (and true $x3844) $x4034)))))
 (let (($x4040 (and $x4035 (not (and $x3851 $x4039)))))
 (let (($x4045 (and $x4040 (not (and $x3861 $x4044)))))
 (let (($x4050 (and $x4045 (not (and (and true $x3834) $x4049)))))
 (let (($x4053 (and $x4050 (not (and (and true $x3844) $x4039)))))
 (let (($x4056 (and $x4053 (not (and $x3879 $x4044)))))
 (let (($x4061 (and $x4056 (not (and (and true $x3844) $x4060)))))
 (let (($x4064 (and $x4061 (not (and $x3879 $x4029)))))
 (let (($x4067 (and $x4064 (not (and $x3861 $x4049)))))
 (let (($x4070 (and $x4067 (not (and $x3898 $x4039)))))
 (let (($x4073 (and $x4070 (not (and $x3851 $x4060)))))
 (let (($x4076 (and $x4073 (not (and $x3861 $x4029)))))
 (let (($x4079 (and $x4076 (not (and $x3898 $x4034)))))
 (let (($x4100 (and $x4079 (not (and (and true $x4110) $x4104)))))
 (let (($x4131 (and $x4100 (not (and (and true $x4137) $x4127)))))
 (let (($x4158 (and $x4131 (not (and (and true $x4164) $x4157)))))
 (let (($x4181 (and $x4158 (not (and (and true $x4191) $x4187)))))
 (let (($x4196 (and $x4181 (not (and (and true $x4110) $x4188)))))
 (let (($x4197 (and $x4196 (not (and (and true $x4137) $x4157)))))
 (let (($x4219 (and $x4197 (not (and (and true $x4228) $x4187)))))
 (let (($x4225 (and $x4219 (not (and (and true $x4137) $x4222)))))
 (let (($x4236 (and $x4225 (not (and (and true $x4228) $x4104)))))
 (let (($x4237 (and $x4236 (not (and (and true $x4191) $x4188)))))
 (let (($x4257 (and $x4237 (not (and (and true $x4264) $x4157)))))
 (let (($x4260 (and $x4257 (not (and (and true $x4164) $x4222)))))
 (let (($x4254 (and $x4260 (not (and (and true $x4191) $x4104)))))
 (let (($x4268 (and $x4254 (not (and (and true $x4264) $x4127)))))
 (let (($x4271 (and $x4268 (not (and (and true c_0_12) $x2471)))))
 (let (($x4265 (and $x4271 (not (and (and true c_1_12) $x2524)))))
 (let (($x4277 (and $x4265 (not (and (and true c_3_12) $x2630)))))
 (let (($x4281 (and $x4277 (not (and (and true c_4_12) $x2683)))))
 (let (($x4284 (and $x4281 (not (and (and true c_0_12) $x2577)))))
 (let (($x4287 (and $x4284 (not (and (and true c_1_12) $x2630)))))
 (let (($x4291 (and $x4287 (not (and (and true c_2_12) $x2683)))))
 (let (($x4294 (and $x4291 (not (and (and true c_1_12) $x2418)))))
 (let (($x4297 (and $x4294 (not (and (and true c_2_12) $x2471)))))
 (let (($x4300 (and $x4297 (not (and (and true c_4_12) $x2577)))))
 (let (($x4304 (and $x4300 (not (and (and true c_5_12) $x2630)))))
 (let (($x4307 (and $x4304 (not (and (and true c_3_12) $x2418)))))
 (let (($x4310 (and $x4307 (not (and (and true c_4_12) $x2471)))))
 (let (($x4313 (and $x4310 (not (and (and true c_5_12) $x2524)))))
 (let (($x4320 (and $x4313 (not (and $x4319 c_1_18)))))
 (let (($x4333 (and $x4320 (not (and $x4329 c_2_18)))))
 (let (($x4340 (and $x4333 (not (and $x4339 c_4_18)))))
 (let (($x4353 (and $x4340 (not (and $x4349 c_5_18)))))
 (let (($x4358 (and $x4353 (not (and $x4319 c_3_18)))))
 (let (($x4356 (and $x4358 (not (and $x4329 c_4_18)))))
 (let (($x4368 (and $x4356 (not (and $x4365 c_5_18)))))
 (let (($x4371 (and $x4368 (not (and $x4329 c_0_18)))))
 (let (($x4372 (and $x4371 (not (and $x4365 c_1_18)))))
 (let (($x4377 (and $x4372 (not (and $x4349 c_3_18)))))
 (let (($x4387 (and $x4377 (not (and $x4384 c_4_18)))))
 (let (($x4391 (and $x4387 (not (and $x4339 c_0_18)))))
 (let (($x4392 (and $x4391 (not (and $x4349 c_1_18)))))
 (let (($x4394 (and $x4392 (not (and $x4384 c_2_18)))))
 (let (($x4433 (and $x4394 $x4432)))
 (let (($x4471 (and $x4433 $x4470)))
 (let (($x4503 (and $x4471 $x4502)))
 (let (($x4539 (and $x4503 $x4538)))
 (let (($x4547 (and $x4539 $x4548)))
 (let (($x4551 (and $x4547 $x4553)))
 (let (($x4577 (and $x4551 $x4576)))
 (let (($x4586 (and $x4577 $x4585)))
 (let (($x4591 (and $x4586 $x4588)))
 (let (($x4594 (and $x4591 $x4595)))
 (let (($x4617 (and $x4594 $x4616)))
 (let (($x4622 (and $x4617 $x4621)))
 (let (($x4626 (and $x4622 $x4623)))
 (let (($x4627 (and $x4626 $x4628)))
 (let (($x4639 (and $x4627 $x4636)))
 (let (($x4644 (and $x4639 $x4645)))
 (let (($x4653 (and $x4644 $x4657)))
 (let (($x4666 (and $x4653 $x4663)))
 (let (($x4668 (and $x4666 $x4670)))
 (let (($x4672 (and $x4668 $x4674)))
 (let (($x4683 (and $x4672 $x4679)))
 (let (($x4687 (and $x4683 $x4686)))
 (let (($x4691 (and $x4687 $x4688)))
 (let (($x4694 (and $x4691 $x4695)))
 (let (($x4701 (and $x4694 $x4704)))
 (let (($x4708 (and $x4701 $x4706)))
 (let (($x4712 (and $x4708 $x4709)))
 (let (($x4713 (and $x4712 $x4714)))
 (let (($x4719 (and $x4713 (not (and $x4319 $x4409)))))
 (let (($x4717 (and $x4719 (not (and $x4329 $x4445)))))
 (let (($x4725 (and $x4717 (not (and $x4339 $x4483)))))
 (let (($x4721 (and $x4725 (not (and $x4349 $x4515)))))
 (let (($x4730 (and $x4721 (not (and $x4319 $x4549)))))
 (let (($x4733 (and $x4730 (not (and $x4329 $x4483)))))
 (let (($x4735 (and $x4733 (not (and $x4365 $x4515)))))
 (let (($x4741 (and $x4735 (not (and $x4329 $x4587)))))
 (let (($x4742 (and $x4741 (not (and $x4365 $x4409)))))
 (let (($x4745 (and $x4742 (not (and $x4349 $x4549)))))
 (let (($x4748 (and $x4745 (not (and $x4384 $x4483)))))
 (let (($x4749 (and $x4748 (not (and $x4339 $x4587)))))
 (let (($x4755 (and $x4749 (not (and $x4349 $x4409)))))
 (let (($x4756 (and $x4755 (not (and $x4384 $x4445)))))
 (let (($x4861 (and $x4756 (and $x4854 $x4714))))
 (and $x4861 $x5859)))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
