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
 (let (($x4748 (>= rank_12 0)))
 (and $x4748 (< rank_12 6))))
(assert
 (let (($x4753 (>= rank_14 0)))
 (and $x4753 (< rank_14 6))))
(assert
 (let (($x4758 (>= rank_16 0)))
 (and $x4758 (< rank_16 6))))
(assert
 (let (($x4763 (>= rank_18 0)))
 (and $x4763 (< rank_18 6))))
(assert
 (let (($x4768 (>= rank_20 0)))
 (and $x4768 (< rank_20 6))))
(assert
 (let (($x4773 (>= rank_22 0)))
 (and $x4773 (< rank_22 6))))
(assert
 (let (($x4938 (>= prank_24 0)))
 (and $x4938 (< prank_24 6))))
(assert
 (let (($x4930 (>= prank_25 0)))
 (and $x4930 (< prank_25 6))))
(assert
 (let (($x4945 (>= prank_26 0)))
 (and $x4945 (< prank_26 6))))
(assert
 (let (($x4949 (>= prank_27 0)))
 (and $x4949 (< prank_27 6))))
(assert
 (let (($x4953 (>= prank_28 0)))
 (and $x4953 (< prank_28 6))))
(assert
 (let (($x4957 (>= prank_29 0)))
 (and $x4957 (< prank_29 6))))
(assert
 (let (($x5176 (>= prank_32 0)))
 (and $x5176 (< prank_32 6))))
(assert
 (let (($x5193 (>= prank_33 0)))
 (and $x5193 (< prank_33 6))))
(assert
 (let (($x5195 (>= prank_34 0)))
 (and $x5195 (< prank_34 6))))
(assert
 (let (($x5197 (>= prank_35 0)))
 (and $x5197 (< prank_35 6))))
(assert
 (let (($x5203 (>= prank_36 0)))
 (and $x5203 (< prank_36 6))))
(assert
 (let (($x5207 (>= prank_37 0)))
 (and $x5207 (< prank_37 6))))
(assert
 (let (($x5460 (>= rank_40 0)))
 (and $x5460 (< rank_40 6))))
(assert
 (let (($x5459 (>= rank_42 0)))
 (and $x5459 (< rank_42 6))))
(assert
 (let (($x5437 (>= rank_44 0)))
 (and $x5437 (< rank_44 6))))
(assert
 (let (($x5465 (>= rank_46 0)))
 (and $x5465 (< rank_46 6))))
(assert
 (let (($x5470 (>= rank_48 0)))
 (and $x5470 (< rank_48 6))))
(assert
 (let (($x5475 (>= rank_50 0)))
 (and $x5475 (< rank_50 6))))
(assert
 (let ((?x5728 (ite (or c_2_1 c_2_3 c_2_7 c_2_9 c_2_13 c_2_15) 1 0)))
 (let ((?x5721 (ite (or c_4_1 c_4_2 c_4_7 c_4_8 c_4_13 c_4_14) 1 0)))
 (let ((?x4284 (ite false 1 0)))
 (let ((?x4430 (+ 0 ?x4284)))
 (let ((?x4472 (+ ?x4430 ?x4284)))
 (let ((?x5727 (+ ?x4472 ?x5721)))
 (let (($x4576 (or c_5_14 c_5_15 c_5_16 c_5_17)))
 (let ((?x5708 (ite (or c_1_1 c_1_3 c_1_7 c_1_9 c_1_13 c_1_15) 1 0)))
 (let ((?x5704 (ite (or c_3_1 c_3_2 c_3_7 c_3_8 c_3_13 c_3_14) 1 0)))
 (let ((?x5694 (ite (or c_5_1 c_5_4 c_5_7 c_5_10 c_5_13 c_5_16) 1 0)))
 (let ((?x5705 (+ 0 ?x5694)))
 (let ((?x5703 (+ ?x5705 ?x4284)))
 (let ((?x5706 (+ ?x5703 ?x5704)))
 (let (($x4538 (or c_4_14 c_4_15 c_4_16 c_4_17)))
 (let (($x5712 (and $x4538 (> (to_real (+ ?x5706 ?x5708)) 0.0))))
 (let ((?x5679 (ite (or c_0_1 c_0_3 c_0_7 c_0_9 c_0_13 c_0_15) 1 0)))
 (let ((?x5675 (ite (or c_4_1 c_4_4 c_4_7 c_4_10 c_4_13 c_4_16) 1 0)))
 (let ((?x5678 (+ 0 ?x5675)))
 (let ((?x5677 (+ ?x5678 ?x4284)))
 (let ((?x5680 (+ ?x5677 ?x4284)))
 (let (($x4529 (or c_3_14 c_3_15 c_3_16 c_3_17)))
 (let (($x5685 (and $x4529 (> (to_real (+ ?x5680 ?x5679)) 0.0))))
 (let ((?x5658 (ite (or c_1_1 c_1_2 c_1_7 c_1_8 c_1_13 c_1_14) 1 0)))
 (let ((?x5655 (ite (or c_5_1 c_5_5 c_5_7 c_5_11 c_5_13 c_5_17) 1 0)))
 (let ((?x5652 (+ ?x4430 ?x5655)))
 (let ((?x5657 (+ ?x5652 ?x5658)))
 (let (($x4555 (or c_2_14 c_2_15 c_2_16 c_2_17)))
 (let (($x5663 (and $x4555 (> (to_real (+ ?x5657 ?x4284)) 0.0))))
 (let ((?x5635 (ite (or c_0_1 c_0_2 c_0_7 c_0_8 c_0_13 c_0_14) 1 0)))
 (let ((?x5630 (ite (or c_4_1 c_4_5 c_4_7 c_4_11 c_4_13 c_4_17) 1 0)))
 (let ((?x5633 (ite (or c_2_1 c_2_4 c_2_7 c_2_10 c_2_13 c_2_16) 1 0)))
 (let ((?x5637 (+ 0 ?x5633)))
 (let ((?x5636 (+ ?x5637 ?x5630)))
 (let ((?x5639 (+ ?x5636 ?x5635)))
 (let (($x4520 (or c_1_14 c_1_15 c_1_16 c_1_17)))
 (let (($x5643 (and $x4520 (> (to_real (+ ?x5639 ?x4284)) 0.0))))
 (let ((?x5609 (ite (or c_3_1 c_3_5 c_3_7 c_3_11 c_3_13 c_3_17) 1 0)))
 (let ((?x5603 (ite (or c_1_1 c_1_4 c_1_7 c_1_10 c_1_13 c_1_16) 1 0)))
 (let ((?x5610 (+ 0 ?x5603)))
 (let ((?x5611 (+ ?x5610 ?x5609)))
 (let ((?x5608 (+ ?x5611 ?x4284)))
 (let (($x4511 (or c_0_14 c_0_15 c_0_16 c_0_17)))
 (let (($x5616 (and $x4511 (> (to_real (+ ?x5608 ?x4284)) 0.0))))
 (let (($x5617 (or false $x5616)))
 (let (($x5644 (or $x5617 $x5643)))
 (let (($x5664 (or $x5644 $x5663)))
 (let (($x5686 (or $x5664 $x5685)))
 (let (($x5713 (or $x5686 $x5712)))
 (let (($x5585 (or false c_0_13)))
 (let (($x5587 (or $x5585 c_1_13)))
 (let (($x5589 (or $x5587 c_2_13)))
 (let (($x5591 (or $x5589 c_3_13)))
 (let (($x5593 (or $x5591 c_4_13)))
 (let ((?x5566 (ite root_51 1 0)))
 (let ((?x5547 (ite root_49 1 0)))
 (let ((?x5531 (ite root_47 1 0)))
 (let ((?x5515 (ite root_45 1 0)))
 (let ((?x5496 (ite root_43 1 0)))
 (let ((?x5480 (ite root_41 1 0)))
 (let ((?x5481 (+ 0 ?x5480)))
 (let ((?x5497 (+ ?x5481 ?x5496)))
 (let ((?x5516 (+ ?x5497 ?x5515)))
 (let ((?x5532 (+ ?x5516 ?x5531)))
 (let ((?x5548 (+ ?x5532 ?x5547)))
 (let (($x5479 (or false root_41)))
 (let (($x5495 (or $x5479 root_43)))
 (let (($x5514 (or $x5495 root_45)))
 (let (($x5530 (or $x5514 root_47)))
 (let (($x5546 (or $x5530 root_49)))
 (let (($x5464 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_13 c_5_14 c_5_15 c_5_16 c_5_17 c_5_18)))
 (let (($x5450 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_13 c_4_14 c_4_15 c_4_16 c_4_17 c_4_18)))
 (let (($x5436 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_13 c_3_14 c_3_15 c_3_16 c_3_17 c_3_18)))
 (let (($x5422 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_13 c_2_14 c_2_15 c_2_16 c_2_17 c_2_18)))
 (let (($x5408 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_13 c_1_14 c_1_15 c_1_16 c_1_17 c_1_18)))
 (let (($x5394 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_13 c_0_14 c_0_15 c_0_16 c_0_17 c_0_18)))
 (let (($x5478 (or false $x5394)))
 (let (($x5494 (or $x5478 $x5408)))
 (let (($x5513 (or $x5494 $x5422)))
 (let (($x5529 (or $x5513 $x5436)))
 (let (($x5545 (or $x5529 $x5450)))
 (let (($x5572 (or false (and $x5450 (< rank_48 rank_50)))))
 (let (($x5576 (not root_51)))
 (let (($x5577 (and $x5464 $x5576)))
 (let (($x5553 (or false (and $x5464 (< rank_50 rank_48)))))
 (let (($x5556 (or $x5553 (and $x5436 (< rank_46 rank_48)))))
 (let (($x5560 (not root_49)))
 (let (($x5561 (and $x5450 $x5560)))
 (let (($x5537 (or false (and $x5450 (< rank_48 rank_46)))))
 (let (($x5541 (not root_47)))
 (let (($x5542 (and $x5436 $x5541)))
 (let (($x5521 (or false (and $x5464 (< rank_50 rank_44)))))
 (let (($x5525 (not root_45)))
 (let (($x5526 (and $x5422 $x5525)))
 (let (($x5502 (or false (and $x5422 (< rank_44 rank_42)))))
 (let (($x5505 (or $x5502 (and $x5450 (< rank_48 rank_42)))))
 (let (($x5509 (not root_43)))
 (let (($x5510 (and $x5408 $x5509)))
 (let (($x5486 (or false (and $x5408 (< rank_42 rank_40)))))
 (let (($x5490 (not root_41)))
 (let (($x5491 (and $x5394 $x5490)))
 (let (($x5483 (and true (=> root_41 $x5394))))
 (let (($x5493 (and $x5483 (=> $x5491 (or $x5486 (and $x5436 (< rank_46 rank_40)))))))
 (let (($x5499 (and $x5493 (=> root_43 $x5408))))
 (let (($x5512 (and $x5499 (=> $x5510 (or $x5505 (and $x5394 (< rank_40 rank_42)))))))
 (let (($x5518 (and $x5512 (=> root_45 $x5422))))
 (let (($x5528 (and $x5518 (=> $x5526 (or $x5521 (and $x5408 (< rank_42 rank_44)))))))
 (let (($x5534 (and $x5528 (=> root_47 $x5436))))
 (let (($x5544 (and $x5534 (=> $x5542 (or $x5537 (and $x5394 (< rank_40 rank_46)))))))
 (let (($x5550 (and $x5544 (=> root_49 $x5450))))
 (let (($x5563 (and $x5550 (=> $x5561 (or $x5556 (and $x5408 (< rank_42 rank_48)))))))
 (let (($x5569 (and $x5563 (=> root_51 $x5464))))
 (let (($x5581 (and (and $x5569 (=> $x5577 (or $x5572 (and $x5422 (< rank_44 rank_50))))) (=> (or $x5545 $x5464) (or $x5546 root_51)))))
 (let (($x5583 (and $x5581 (<= (+ ?x5548 ?x5566) 1))))
 (let (($x4061 (or c_5_1 c_5_7 c_5_13)))
 (let (($x5358 (and $x4061 (= prank_37 prank_high_39))))
 (let (($x4031 (or c_4_1 c_4_7 c_4_13)))
 (let (($x5335 (and $x4031 (= prank_36 prank_high_39))))
 (let (($x4062 (or c_3_1 c_3_7 c_3_13)))
 (let (($x5307 (and $x4062 (= prank_35 prank_high_39))))
 (let (($x4001 (or c_2_1 c_2_7 c_2_13)))
 (let (($x5284 (and $x4001 (= prank_34 prank_high_39))))
 (let (($x3978 (or c_1_1 c_1_7 c_1_13)))
 (let (($x5261 (and $x3978 (= prank_33 prank_high_39))))
 (let (($x4096 (or c_0_1 c_0_7 c_0_13)))
 (let (($x5233 (and $x4096 (= prank_32 prank_high_39))))
 (let (($x5234 (or false $x5233)))
 (let (($x5262 (or $x5234 $x5261)))
 (let (($x5285 (or $x5262 $x5284)))
 (let (($x5308 (or $x5285 $x5307)))
 (let (($x5336 (or $x5308 $x5335)))
 (let (($x5355 (and $x4061 (= prank_37 prank_low_38))))
 (let (($x5332 (and $x4031 (= prank_36 prank_low_38))))
 (let (($x5304 (and $x4062 (= prank_35 prank_low_38))))
 (let (($x5281 (and $x4001 (= prank_34 prank_low_38))))
 (let (($x5258 (and $x3978 (= prank_33 prank_low_38))))
 (let (($x5230 (and $x4096 (= prank_32 prank_low_38))))
 (let (($x5231 (or false $x5230)))
 (let (($x5259 (or $x5231 $x5258)))
 (let (($x5282 (or $x5259 $x5281)))
 (let (($x5305 (or $x5282 $x5304)))
 (let (($x5333 (or $x5305 $x5332)))
 (let (($x5361 (=> (or (or (or (or (or (or false $x4096) $x3978) $x4001) $x4062) $x4031) $x4061) (and (or $x5333 $x5355) (or $x5336 $x5358)))))
 (let (($x5163 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_14 c_2_15 c_2_16 c_2_17 c_2_18)))
 (let (($x5187 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_14 c_4_15 c_4_16 c_4_17 c_4_18)))
 (let (($x5341 (or false (and true (or $x5187 (and $x4031 (< prank_36 prank_37)))))))
 (let (($x5348 (and (or $x5341 (and true (or $x5163 (and $x4001 (< prank_34 prank_37))))) (<= prank_low_38 prank_37))))
 (let (($x5151 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_14 c_1_15 c_1_16 c_1_17 c_1_18)))
 (let (($x5175 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_14 c_3_15 c_3_16 c_3_17 c_3_18)))
 (let (($x5199 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_14 c_5_15 c_5_16 c_5_17 c_5_18)))
 (let (($x5313 (or false (and true (or $x5199 (and $x4061 (< prank_37 prank_36)))))))
 (let (($x5318 (or $x5313 (and true (or $x5175 (and $x4062 (< prank_35 prank_36)))))))
 (let (($x5325 (and (or $x5318 (and true (or $x5151 (and $x3978 (< prank_33 prank_36))))) (<= prank_low_38 prank_36))))
 (let (($x5139 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_14 c_0_15 c_0_16 c_0_17 c_0_18)))
 (let (($x5290 (or false (and true (or $x5187 (and $x4031 (< prank_36 prank_35)))))))
 (let (($x5297 (and (or $x5290 (and true (or $x5139 (and $x4096 (< prank_32 prank_35))))) (<= prank_low_38 prank_35))))
 (let (($x5267 (or false (and true (or $x5199 (and $x4061 (< prank_37 prank_34)))))))
 (let (($x5274 (and (or $x5267 (and true (or $x5151 (and $x3978 (< prank_33 prank_34))))) (<= prank_low_38 prank_34))))
 (let (($x5239 (or false (and true (or $x5163 (and $x4001 (< prank_34 prank_33)))))))
 (let (($x5244 (or $x5239 (and true (or $x5187 (and $x4031 (< prank_36 prank_33)))))))
 (let (($x5251 (and (or $x5244 (and true (or $x5139 (and $x4096 (< prank_32 prank_33))))) (<= prank_low_38 prank_33))))
 (let (($x5216 (or false (and true (or $x5151 (and $x3978 (< prank_33 prank_32)))))))
 (let (($x5223 (and (or $x5216 (and true (or $x5175 (and $x4062 (< prank_35 prank_32))))) (<= prank_low_38 prank_32))))
 (let (($x5227 (and true (=> $x4096 (and $x5223 (<= prank_32 prank_high_39))))))
 (let (($x5255 (and $x5227 (=> $x3978 (and $x5251 (<= prank_33 prank_high_39))))))
 (let (($x5278 (and $x5255 (=> $x4001 (and $x5274 (<= prank_34 prank_high_39))))))
 (let (($x5301 (and $x5278 (=> $x4062 (and $x5297 (<= prank_35 prank_high_39))))))
 (let (($x5329 (and $x5301 (=> $x4031 (and $x5325 (<= prank_36 prank_high_39))))))
 (let (($x5352 (and $x5329 (=> $x4061 (and $x5348 (<= prank_37 prank_high_39))))))
 (let (($x5362 (and $x5352 $x5361)))
 (let (($x4138 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_8 c_5_9 c_5_10 c_5_11 c_5_14 c_5_15 c_5_16 c_5_17)))
 (let (($x5108 (and $x4138 (= prank_29 prank_high_31))))
 (let (($x4065 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_8 c_4_9 c_4_10 c_4_11 c_4_14 c_4_15 c_4_16 c_4_17)))
 (let (($x5085 (and $x4065 (= prank_28 prank_high_31))))
 (let (($x4038 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_8 c_3_9 c_3_10 c_3_11 c_3_14 c_3_15 c_3_16 c_3_17)))
 (let (($x5057 (and $x4038 (= prank_27 prank_high_31))))
 (let (($x4102 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_8 c_2_9 c_2_10 c_2_11 c_2_14 c_2_15 c_2_16 c_2_17)))
 (let (($x5034 (and $x4102 (= prank_26 prank_high_31))))
 (let (($x4011 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_8 c_1_9 c_1_10 c_1_11 c_1_14 c_1_15 c_1_16 c_1_17)))
 (let (($x5011 (and $x4011 (= prank_25 prank_high_31))))
 (let (($x3984 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_8 c_0_9 c_0_10 c_0_11 c_0_14 c_0_15 c_0_16 c_0_17)))
 (let (($x4983 (and $x3984 (= prank_24 prank_high_31))))
 (let (($x4984 (or false $x4983)))
 (let (($x5012 (or $x4984 $x5011)))
 (let (($x5035 (or $x5012 $x5034)))
 (let (($x5058 (or $x5035 $x5057)))
 (let (($x5086 (or $x5058 $x5085)))
 (let (($x5105 (and $x4138 (= prank_29 prank_low_30))))
 (let (($x5082 (and $x4065 (= prank_28 prank_low_30))))
 (let (($x5054 (and $x4038 (= prank_27 prank_low_30))))
 (let (($x5031 (and $x4102 (= prank_26 prank_low_30))))
 (let (($x5008 (and $x4011 (= prank_25 prank_low_30))))
 (let (($x4980 (and $x3984 (= prank_24 prank_low_30))))
 (let (($x4981 (or false $x4980)))
 (let (($x5009 (or $x4981 $x5008)))
 (let (($x5032 (or $x5009 $x5031)))
 (let (($x5055 (or $x5032 $x5054)))
 (let (($x5083 (or $x5055 $x5082)))
 (let (($x5111 (=> (or (or (or (or (or (or false $x3984) $x4011) $x4102) $x4038) $x4065) $x4138) (and (or $x5083 $x5105) (or $x5086 $x5108)))))
 (let (($x3756 (or c_2_6 c_2_12 c_2_18)))
 (let (($x4441 (or c_5_5 c_5_11 c_5_17)))
 (let (($x3738 (or c_4_6 c_4_12 c_4_18)))
 (let (($x4397 (or c_5_4 c_5_10 c_5_16)))
 (let (($x5091 (or false (and $x4397 (or $x3738 (and $x4065 (< prank_28 prank_29)))))))
 (let (($x5098 (and (or $x5091 (and $x4441 (or $x3756 (and $x4102 (< prank_26 prank_29))))) (<= prank_low_30 prank_29))))
 (let (($x3718 (or c_1_6 c_1_12 c_1_18)))
 (let (($x4333 (or c_4_5 c_4_11 c_4_17)))
 (let (($x3728 (or c_3_6 c_3_12 c_3_18)))
 (let (($x4364 (or c_4_4 c_4_10 c_4_16)))
 (let (($x3775 (or c_5_6 c_5_12 c_5_18)))
 (let (($x4480 (or c_4_2 c_4_8 c_4_14)))
 (let (($x5063 (or false (and $x4480 (or $x3775 (and $x4138 (< prank_29 prank_28)))))))
 (let (($x5068 (or $x5063 (and $x4364 (or $x3728 (and $x4038 (< prank_27 prank_28)))))))
 (let (($x5075 (and (or $x5068 (and $x4333 (or $x3718 (and $x4011 (< prank_25 prank_28))))) (<= prank_low_30 prank_28))))
 (let (($x3708 (or c_0_6 c_0_12 c_0_18)))
 (let (($x4298 (or c_3_5 c_3_11 c_3_17)))
 (let (($x4399 (or c_3_2 c_3_8 c_3_14)))
 (let (($x5040 (or false (and $x4399 (or $x3738 (and $x4065 (< prank_28 prank_27)))))))
 (let (($x5047 (and (or $x5040 (and $x4298 (or $x3708 (and $x3984 (< prank_24 prank_27))))) (<= prank_low_30 prank_27))))
 (let (($x4329 (or c_2_4 c_2_10 c_2_16)))
 (let (($x4483 (or c_2_3 c_2_9 c_2_15)))
 (let (($x5017 (or false (and $x4483 (or $x3775 (and $x4138 (< prank_29 prank_26)))))))
 (let (($x5024 (and (or $x5017 (and $x4329 (or $x3718 (and $x4011 (< prank_25 prank_26))))) (<= prank_low_30 prank_26))))
 (let (($x4294 (or c_1_4 c_1_10 c_1_16)))
 (let (($x4402 (or c_1_3 c_1_9 c_1_15)))
 (let (($x4442 (or c_1_2 c_1_8 c_1_14)))
 (let (($x4989 (or false (and $x4442 (or $x3756 (and $x4102 (< prank_26 prank_25)))))))
 (let (($x4994 (or $x4989 (and $x4402 (or $x3738 (and $x4065 (< prank_28 prank_25)))))))
 (let (($x5001 (and (or $x4994 (and $x4294 (or $x3708 (and $x3984 (< prank_24 prank_25))))) (<= prank_low_30 prank_25))))
 (let (($x4367 (or c_0_3 c_0_9 c_0_15)))
 (let (($x4334 (or c_0_2 c_0_8 c_0_14)))
 (let (($x4966 (or false (and $x4334 (or $x3718 (and $x4011 (< prank_25 prank_24)))))))
 (let (($x4973 (and (or $x4966 (and $x4367 (or $x3728 (and $x4038 (< prank_27 prank_24))))) (<= prank_low_30 prank_24))))
 (let (($x4977 (and true (=> $x3984 (and $x4973 (<= prank_24 prank_high_31))))))
 (let (($x5005 (and $x4977 (=> $x4011 (and $x5001 (<= prank_25 prank_high_31))))))
 (let (($x5028 (and $x5005 (=> $x4102 (and $x5024 (<= prank_26 prank_high_31))))))
 (let (($x5051 (and $x5028 (=> $x4038 (and $x5047 (<= prank_27 prank_high_31))))))
 (let (($x5079 (and $x5051 (=> $x4065 (and $x5075 (<= prank_28 prank_high_31))))))
 (let (($x5102 (and $x5079 (=> $x4138 (and $x5098 (<= prank_29 prank_high_31))))))
 (let (($x5112 (and $x5102 $x5111)))
 (let (($x2364 (not in_target_5)))
 (let (($x3412 (and c_5_12 $x2364)))
 (let (($x3393 (and c_5_6 $x2364)))
 (let (($x3380 (and c_5_18 $x2364)))
 (let (($x2349 (not in_target_4)))
 (let (($x3313 (and c_4_12 $x2349)))
 (let (($x3294 (and c_4_6 $x2349)))
 (let (($x3281 (and c_4_18 $x2349)))
 (let (($x4902 (or $x3281 $x3294 $x3313)))
 (let (($x2334 (not in_target_3)))
 (let (($x3214 (and c_3_12 $x2334)))
 (let (($x3195 (and c_3_6 $x2334)))
 (let (($x3182 (and c_3_18 $x2334)))
 (let (($x4897 (or $x3182 $x3195 $x3214)))
 (let (($x2319 (not in_target_2)))
 (let (($x3115 (and c_2_12 $x2319)))
 (let (($x3096 (and c_2_6 $x2319)))
 (let (($x3083 (and c_2_18 $x2319)))
 (let (($x4892 (or $x3083 $x3096 $x3115)))
 (let (($x2304 (not in_target_1)))
 (let (($x3016 (and c_1_12 $x2304)))
 (let (($x2997 (and c_1_6 $x2304)))
 (let (($x2984 (and c_1_18 $x2304)))
 (let (($x4887 (or $x2984 $x2997 $x3016)))
 (let (($x2291 (not in_target_0)))
 (let (($x2917 (and c_0_12 $x2291)))
 (let (($x2897 (and c_0_6 $x2291)))
 (let (($x2883 (and c_0_18 $x2291)))
 (let (($x4882 (or $x2883 $x2897 $x2917)))
 (let (($x4879 (or false $x4882)))
 (let (($x4884 (or $x4879 $x4887)))
 (let (($x4889 (or $x4884 $x4892)))
 (let (($x4894 (or $x4889 $x4897)))
 (let (($x4899 (or $x4894 $x4902)))
 (let ((?x4858 (ite root_23 1 0)))
 (let ((?x4840 (ite root_21 1 0)))
 (let ((?x4825 (ite root_19 1 0)))
 (let ((?x4810 (ite root_17 1 0)))
 (let ((?x4792 (ite root_15 1 0)))
 (let ((?x4777 (ite root_13 1 0)))
 (let ((?x4778 (+ 0 ?x4777)))
 (let ((?x4793 (+ ?x4778 ?x4792)))
 (let ((?x4811 (+ ?x4793 ?x4810)))
 (let ((?x4826 (+ ?x4811 ?x4825)))
 (let ((?x4841 (+ ?x4826 ?x4840)))
 (let (($x4776 (or false root_13)))
 (let (($x4791 (or $x4776 root_15)))
 (let (($x4809 (or $x4791 root_17)))
 (let (($x4824 (or $x4809 root_19)))
 (let (($x4839 (or $x4824 root_21)))
 (let (($x4737 (or false $x3708)))
 (let (($x4732 (or $x4737 $x3718)))
 (let (($x4739 (or $x4732 $x3756)))
 (let (($x4741 (or $x4739 $x3728)))
 (let (($x4743 (or $x4741 $x3738)))
 (let (($x4745 (or $x4743 $x3775)))
 (let (($x4864 (or false (and $x3738 (< rank_20 rank_22)))))
 (let (($x4868 (not root_23)))
 (let (($x4869 (and $x3775 $x4868)))
 (let (($x4846 (or false (and $x3775 (< rank_22 rank_20)))))
 (let (($x4849 (or $x4846 (and $x3728 (< rank_18 rank_20)))))
 (let (($x4853 (not root_21)))
 (let (($x4854 (and $x3738 $x4853)))
 (let (($x4831 (or false (and $x3738 (< rank_20 rank_18)))))
 (let (($x4835 (not root_19)))
 (let (($x4836 (and $x3728 $x4835)))
 (let (($x4816 (or false (and $x3775 (< rank_22 rank_16)))))
 (let (($x4820 (not root_17)))
 (let (($x4821 (and $x3756 $x4820)))
 (let (($x4798 (or false (and $x3756 (< rank_16 rank_14)))))
 (let (($x4801 (or $x4798 (and $x3738 (< rank_20 rank_14)))))
 (let (($x4805 (not root_15)))
 (let (($x4806 (and $x3718 $x4805)))
 (let (($x4783 (or false (and $x3718 (< rank_14 rank_12)))))
 (let (($x4787 (not root_13)))
 (let (($x4788 (and $x3708 $x4787)))
 (let (($x4780 (and true (=> root_13 $x3708))))
 (let (($x4790 (and $x4780 (=> $x4788 (or $x4783 (and $x3728 (< rank_18 rank_12)))))))
 (let (($x4795 (and $x4790 (=> root_15 $x3718))))
 (let (($x4808 (and $x4795 (=> $x4806 (or $x4801 (and $x3708 (< rank_12 rank_14)))))))
 (let (($x4813 (and $x4808 (=> root_17 $x3756))))
 (let (($x4823 (and $x4813 (=> $x4821 (or $x4816 (and $x3718 (< rank_14 rank_16)))))))
 (let (($x4828 (and $x4823 (=> root_19 $x3728))))
 (let (($x4838 (and $x4828 (=> $x4836 (or $x4831 (and $x3708 (< rank_12 rank_18)))))))
 (let (($x4843 (and $x4838 (=> root_21 $x3738))))
 (let (($x4856 (and $x4843 (=> $x4854 (or $x4849 (and $x3718 (< rank_14 rank_20)))))))
 (let (($x4861 (and $x4856 (=> root_23 $x3775))))
 (let (($x4873 (and (and $x4861 (=> $x4869 (or $x4864 (and $x3756 (< rank_16 rank_22))))) (=> $x4745 (or $x4839 root_23)))))
 (let (($x4875 (and $x4873 (<= (+ ?x4841 ?x4858) 1))))
 (let (($x5113 (and (and (and $x4745 $x4875) (not (or $x4899 (or $x3380 $x3393 $x3412)))) $x5112)))
 (let (($x5733 (and (and (and (and $x5113 $x5362) $x5583) (not (or $x5593 c_5_13))) (not (or $x5713 (and $x4576 (> (to_real (+ ?x5727 ?x5728)) 0.0)))))))
 (let (($x4487 (= (to_real (+ (+ ?x4472 (ite $x4480 1 0)) (ite $x4483 1 0))) 0.0)))
 (let (($x4476 (= (to_real (+ (+ ?x4472 (ite $x4031 1 0)) (ite $x4001 1 0))) 0.0)))
 (let (($x4488 (and $x4476 $x4487)))
 (let (($x4319 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6)))
 (let (($x4572 (and true $x4576)))
 (let (($x4585 (and $x4572 $x4319)))
 (let (($x4588 (not (and $x4585 $x4488))))
 (let ((?x4406 (ite $x4402 1 0)))
 (let ((?x4404 (ite $x4399 1 0)))
 (let ((?x4400 (ite $x4397 1 0)))
 (let ((?x4401 (+ 0 ?x4400)))
 (let ((?x4403 (+ ?x4401 ?x4284)))
 (let ((?x4405 (+ ?x4403 ?x4404)))
 (let ((?x4280 (ite $x3978 1 0)))
 (let ((?x4282 (ite $x4062 1 0)))
 (let ((?x4385 (ite $x4061 1 0)))
 (let ((?x4386 (+ 0 ?x4385)))
 (let ((?x4388 (+ ?x4386 ?x4284)))
 (let ((?x4387 (+ ?x4388 ?x4282)))
 (let (($x4410 (and (= (to_real (+ ?x4387 ?x4280)) 0.0) (= (to_real (+ ?x4405 ?x4406)) 0.0))))
 (let (($x4283 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6)))
 (let (($x4534 (and true $x4538)))
 (let (($x4579 (and $x4534 $x4283)))
 (let (($x4583 (not (and $x4579 $x4410))))
 (let ((?x4370 (ite $x4367 1 0)))
 (let ((?x4365 (ite $x4364 1 0)))
 (let ((?x4366 (+ 0 ?x4365)))
 (let ((?x4368 (+ ?x4366 ?x4284)))
 (let ((?x4369 (+ ?x4368 ?x4284)))
 (let ((?x4320 (ite $x4096 1 0)))
 (let ((?x4315 (ite $x4031 1 0)))
 (let ((?x4353 (+ 0 ?x4315)))
 (let ((?x4356 (+ ?x4353 ?x4284)))
 (let ((?x4354 (+ ?x4356 ?x4284)))
 (let (($x4374 (and (= (to_real (+ ?x4354 ?x4320)) 0.0) (= (to_real (+ ?x4369 ?x4370)) 0.0))))
 (let (($x4461 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6)))
 (let (($x4525 (and true $x4529)))
 (let (($x4577 (and $x4525 $x4461)))
 (let (($x4580 (not (and $x4577 $x4374))))
 (let (($x4357 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6)))
 (let (($x4573 (and $x4572 $x4357)))
 (let (($x4578 (not (and $x4573 $x4488))))
 (let (($x4423 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6)))
 (let (($x4563 (and $x4534 $x4423)))
 (let (($x4569 (not (and $x4563 $x4410))))
 (let ((?x4446 (to_real (+ (+ (+ ?x4430 (ite $x4441 1 0)) (ite $x4442 1 0)) ?x4284))))
 (let (($x4448 (and (= (to_real (+ (+ (+ ?x4430 ?x4385) ?x4280) ?x4284)) 0.0) (= ?x4446 0.0))))
 (let (($x4551 (and true $x4555)))
 (let (($x4558 (and $x4551 $x4283)))
 (let (($x4562 (not (and $x4558 $x4448))))
 (let ((?x4337 (ite $x4334 1 0)))
 (let ((?x4335 (ite $x4333 1 0)))
 (let ((?x4331 (ite $x4329 1 0)))
 (let ((?x4332 (+ 0 ?x4331)))
 (let ((?x4336 (+ ?x4332 ?x4335)))
 (let ((?x4338 (+ ?x4336 ?x4337)))
 (let ((?x4323 (to_real (+ (+ (+ (+ 0 (ite $x4001 1 0)) ?x4315) ?x4320) ?x4284))))
 (let (($x4342 (and (= ?x4323 0.0) (= (to_real (+ ?x4338 ?x4284)) 0.0))))
 (let (($x4516 (and true $x4520)))
 (let (($x4556 (and $x4516 $x4461)))
 (let (($x4560 (not (and $x4556 $x4342))))
 (let (($x4389 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6)))
 (let (($x4552 (and $x4551 $x4389)))
 (let (($x4553 (not (and $x4552 $x4448))))
 (let (($x4548 (not (and (and $x4516 $x4357) $x4342))))
 (let ((?x4297 (ite $x4298 1 0)))
 (let ((?x4295 (ite $x4294 1 0)))
 (let ((?x4296 (+ 0 ?x4295)))
 (let ((?x4299 (+ ?x4296 ?x4297)))
 (let ((?x4300 (+ ?x4299 ?x4284)))
 (let (($x4304 (and (= (to_real (+ (+ (+ (+ 0 ?x4280) ?x4282) ?x4284) ?x4284)) 0.0) (= (to_real (+ ?x4300 ?x4284)) 0.0))))
 (let (($x4507 (and true $x4511)))
 (let (($x4539 (and $x4507 $x4423)))
 (let (($x4544 (not (and $x4539 $x4304))))
 (let (($x4537 (not (and (and $x4534 $x4389) $x4410))))
 (let (($x4531 (not (and (and $x4525 $x4357) $x4374))))
 (let (($x4519 (not (and (and $x4516 $x4319) $x4342))))
 (let (($x4510 (not (and (and $x4507 $x4283) $x4304))))
 (let (($x4471 (or c_5_2 c_5_3 c_5_4 c_5_5)))
 (let (($x4466 (and true $x4471)))
 (let (($x4499 (and $x4466 $x4319)))
 (let (($x4502 (not (and $x4499 $x4488))))
 (let (($x4380 (or c_4_2 c_4_3 c_4_4 c_4_5)))
 (let (($x4378 (and true $x4380)))
 (let (($x4493 (and $x4378 $x4283)))
 (let (($x4497 (not (and $x4493 $x4410))))
 (let (($x4348 (or c_3_2 c_3_3 c_3_4 c_3_5)))
 (let (($x4346 (and true $x4348)))
 (let (($x4492 (and $x4346 $x4461)))
 (let (($x4495 (not (and $x4492 $x4374))))
 (let (($x4490 (not (and (and $x4466 $x4357) $x4488))))
 (let (($x4469 (not (and (and $x4378 $x4423) $x4410))))
 (let (($x4429 (or c_2_2 c_2_3 c_2_4 c_2_5)))
 (let (($x4426 (and true $x4429)))
 (let (($x4457 (and $x4426 $x4283)))
 (let (($x4462 (not (and $x4457 $x4448))))
 (let (($x4310 (or c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x4309 (and true $x4310)))
 (let (($x4456 (and $x4309 $x4461)))
 (let (($x4459 (not (and $x4456 $x4342))))
 (let (($x4450 (not (and (and $x4426 $x4389) $x4448))))
 (let (($x4427 (not (and (and $x4309 $x4357) $x4342))))
 (let (($x4274 (or c_0_2 c_0_3 c_0_4 c_0_5)))
 (let (($x4272 (and true $x4274)))
 (let (($x4418 (and $x4272 $x4423)))
 (let (($x4422 (not (and $x4418 $x4304))))
 (let (($x4412 (not (and (and $x4378 $x4389) $x4410))))
 (let (($x4376 (not (and (and $x4346 $x4357) $x4374))))
 (let (($x4344 (not (and (and $x4309 $x4319) $x4342))))
 (let (($x4306 (not (and (and $x4272 $x4283) $x4304))))
 (let (($x4702 (not in_target_29)))
 (let (($x4700 (not in_target_28)))
 (let (($x4698 (not in_target_27)))
 (let (($x4696 (not in_target_26)))
 (let (($x4694 (not in_target_25)))
 (let (($x4692 (not in_target_24)))
 (let (($x4690 (not in_target_23)))
 (let (($x4688 (not in_target_22)))
 (let (($x4686 (not in_target_21)))
 (let (($x4684 (not in_target_20)))
 (let (($x4682 (not in_target_19)))
 (let (($x4680 (not in_target_18)))
 (let (($x4678 (not in_target_17)))
 (let (($x4676 (not in_target_16)))
 (let (($x4674 (not in_target_15)))
 (let (($x4672 (not in_target_14)))
 (let (($x4670 (not in_target_13)))
 (let (($x4668 (not in_target_12)))
 (let (($x4666 (not in_target_11)))
 (let (($x4664 (not in_target_10)))
 (let (($x4662 (not in_target_9)))
 (let (($x4660 (not in_target_8)))
 (let (($x4658 (not in_target_7)))
 (let (($x4656 (not in_target_6)))
 (let (($x4657 (and true $x4656)))
 (let (($x4659 (and $x4657 $x4658)))
 (let (($x4661 (and $x4659 $x4660)))
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
 (let (($x4708 (and $x4703 $x4306)))
 (let (($x4709 (and $x4708 $x4344)))
 (let (($x4711 (and $x4709 $x4376)))
 (let (($x4710 (and $x4711 $x4412)))
 (let (($x4707 (and $x4710 $x4422)))
 (let (($x4715 (and $x4707 $x4427)))
 (let (($x4714 (and $x4715 $x4450)))
 (let (($x4712 (and $x4714 $x4459)))
 (let (($x4717 (and $x4712 $x4462)))
 (let (($x4718 (and $x4717 $x4469)))
 (let (($x4719 (and $x4718 $x4490)))
 (let (($x4720 (and $x4719 $x4495)))
 (let (($x4716 (and $x4720 $x4497)))
 (let (($x4722 (and $x4716 $x4502)))
 (let (($x4721 (and $x4722 $x4510)))
 (let (($x4724 (and $x4721 $x4519)))
 (let (($x4713 (and $x4724 $x4531)))
 (let (($x4725 (and $x4713 $x4537)))
 (let (($x4727 (and $x4725 $x4544)))
 (let (($x4723 (and $x4727 $x4548)))
 (let (($x4729 (and $x4723 $x4553)))
 (let (($x4730 (and $x4729 $x4560)))
 (let (($x4731 (and $x4730 $x4562)))
 (let (($x4726 (and $x4731 $x4569)))
 (let (($x4733 (and $x4726 $x4578)))
 (let (($x4734 (and $x4733 $x4580)))
 (let (($x4728 (and $x4734 $x4583)))
 (let (($x4263 (or c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12)))
 (let (($x4258 (and true $x4263)))
 (let (($x4228 (or c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12)))
 (let (($x4223 (and true $x4228)))
 (let (($x4218 (or c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12)))
 (let (($x4213 (and true $x4218)))
 (let (($x4244 (or c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12)))
 (let (($x4239 (and true $x4244)))
 (let (($x4208 (or c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12)))
 (let (($x4203 (and true $x4208)))
 (let (($x4198 (or c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12)))
 (let (($x4193 (and true $x4198)))
 (let (($x3106 (and c_2_7 $x2319)))
 (let (($x3087 (and c_2_1 $x2319)))
 (let (($x3073 (and c_2_13 $x2319)))
 (let (($x3908 (or $x3073 $x3087 $x3106)))
 (let (($x3772 (and true $x3775)))
 (let (($x3007 (and c_1_7 $x2304)))
 (let (($x2988 (and c_1_1 $x2304)))
 (let (($x2974 (and c_1_13 $x2304)))
 (let (($x3903 (or $x2974 $x2988 $x3007)))
 (let (($x3735 (and true $x3738)))
 (let (($x2908 (and c_0_7 $x2291)))
 (let (($x2888 (and c_0_1 $x2291)))
 (let (($x2873 (and c_0_13 $x2291)))
 (let (($x3934 (or $x2873 $x2888 $x2908)))
 (let (($x3725 (and true $x3728)))
 (let (($x3304 (and c_4_7 $x2349)))
 (let (($x3285 (and c_4_1 $x2349)))
 (let (($x3271 (and c_4_13 $x2349)))
 (let (($x3913 (or $x3271 $x3285 $x3304)))
 (let (($x3205 (and c_3_7 $x2334)))
 (let (($x3186 (and c_3_1 $x2334)))
 (let (($x3172 (and c_3_13 $x2334)))
 (let (($x3923 (or $x3172 $x3186 $x3205)))
 (let (($x3403 (and c_5_7 $x2364)))
 (let (($x3384 (and c_5_1 $x2364)))
 (let (($x3370 (and c_5_13 $x2364)))
 (let (($x3918 (or $x3370 $x3384 $x3403)))
 (let (($x3753 (and true $x3756)))
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
 (let (($x3823 (or $x2527 $x2529 $x2531 $x2533 $x2538 $x2540 $x2542 $x2544 $x2549 $x2551 $x2553 $x2555)))
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
 (let (($x3808 (or $x2474 $x2476 $x2478 $x2480 $x2485 $x2487 $x2489 $x2491 $x2496 $x2498 $x2500 $x2502)))
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
 (let (($x3889 (or $x2421 $x2423 $x2425 $x2427 $x2432 $x2434 $x2436 $x2438 $x2443 $x2445 $x2447 $x2449)))
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
 (let (($x3838 (or $x2633 $x2635 $x2637 $x2639 $x2644 $x2646 $x2648 $x2650 $x2655 $x2657 $x2659 $x2661)))
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
 (let (($x3868 (or $x2580 $x2582 $x2584 $x2586 $x2591 $x2593 $x2595 $x2597 $x2602 $x2604 $x2606 $x2608)))
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
 (let (($x3853 (or $x2686 $x2688 $x2690 $x2692 $x2697 $x2699 $x2701 $x2703 $x2708 $x2710 $x2712 $x2714)))
 (let (($x2547 (and c_2_13 in_target_2)))
 (let (($x2536 (and c_2_7 in_target_2)))
 (let (($x2525 (and c_2_1 in_target_2)))
 (let (($x3720 (or $x2525 $x2536 $x2547)))
 (let (($x2494 (and c_1_13 in_target_1)))
 (let (($x2483 (and c_1_7 in_target_1)))
 (let (($x2472 (and c_1_1 in_target_1)))
 (let (($x3710 (or $x2472 $x2483 $x2494)))
 (let (($x2441 (and c_0_13 in_target_0)))
 (let (($x2430 (and c_0_7 in_target_0)))
 (let (($x2419 (and c_0_1 in_target_0)))
 (let (($x3761 (or $x2419 $x2430 $x2441)))
 (let (($x2653 (and c_4_13 in_target_4)))
 (let (($x2642 (and c_4_7 in_target_4)))
 (let (($x2631 (and c_4_1 in_target_4)))
 (let (($x3730 (or $x2631 $x2642 $x2653)))
 (let (($x2600 (and c_3_13 in_target_3)))
 (let (($x2589 (and c_3_7 in_target_3)))
 (let (($x2578 (and c_3_1 in_target_3)))
 (let (($x3745 (or $x2578 $x2589 $x2600)))
 (let (($x2706 (and c_5_13 in_target_5)))
 (let (($x2695 (and c_5_7 in_target_5)))
 (let (($x2684 (and c_5_1 in_target_5)))
 (let (($x3740 (or $x2684 $x2695 $x2706)))
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
 (let ((?x3668 (ite (or $x3370 $x3372 $x3374 $x3376 $x3378 $x3380) 1 0)))
 (let ((?x3654 (ite (or (and c_5_6 in_target_5) $x2684 $x2686 $x2688 $x2690 $x2692) (- 1) 0)))
 (let (($x2716 (and c_5_18 in_target_5)))
 (let (($x3350 (or $x2706 $x2708 $x2710 $x2712 $x2714 $x2716)))
 (let ((?x3658 (ite $x3350 (- 2) 0)))
 (let (($x2683 (and c_5_0 in_target_5)))
 (let ((?x3656 (ite $x2683 (- 3) 0)))
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
 (let ((?x3627 (ite (or $x3271 $x3273 $x3275 $x3277 $x3279 $x3281) 1 0)))
 (let ((?x3619 (ite (or (and c_4_6 in_target_4) $x2631 $x2633 $x2635 $x2637 $x2639) (- 1) 0)))
 (let (($x2663 (and c_4_18 in_target_4)))
 (let (($x3251 (or $x2653 $x2655 $x2657 $x2659 $x2661 $x2663)))
 (let ((?x3605 (ite $x3251 (- 2) 0)))
 (let (($x2630 (and c_4_0 in_target_4)))
 (let ((?x3615 (ite $x2630 (- 3) 0)))
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
 (let ((?x3586 (ite (or $x3172 $x3174 $x3176 $x3178 $x3180 $x3182) 1 0)))
 (let ((?x3577 (ite (or (and c_3_6 in_target_3) $x2578 $x2580 $x2582 $x2584 $x2586) (- 1) 0)))
 (let (($x2610 (and c_3_18 in_target_3)))
 (let (($x3152 (or $x2600 $x2602 $x2604 $x2606 $x2608 $x2610)))
 (let ((?x3569 (ite $x3152 (- 2) 0)))
 (let (($x2577 (and c_3_0 in_target_3)))
 (let ((?x3578 (ite $x2577 (- 3) 0)))
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
 (let ((?x3545 (ite (or $x3073 $x3075 $x3077 $x3079 $x3081 $x3083) 1 0)))
 (let ((?x3539 (ite (or (and c_2_6 in_target_2) $x2525 $x2527 $x2529 $x2531 $x2533) (- 1) 0)))
 (let (($x2557 (and c_2_18 in_target_2)))
 (let (($x3053 (or $x2547 $x2549 $x2551 $x2553 $x2555 $x2557)))
 (let ((?x3527 (ite $x3053 (- 2) 0)))
 (let (($x2524 (and c_2_0 in_target_2)))
 (let ((?x3523 (ite $x2524 (- 3) 0)))
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
 (let ((?x3504 (ite (or $x2974 $x2976 $x2978 $x2980 $x2982 $x2984) 1 0)))
 (let ((?x3495 (ite (or (and c_1_6 in_target_1) $x2472 $x2474 $x2476 $x2478 $x2480) (- 1) 0)))
 (let (($x2504 (and c_1_18 in_target_1)))
 (let (($x2954 (or $x2494 $x2496 $x2498 $x2500 $x2502 $x2504)))
 (let ((?x3498 (ite $x2954 (- 2) 0)))
 (let (($x2471 (and c_1_0 in_target_1)))
 (let ((?x3487 (ite $x2471 (- 3) 0)))
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
 (let ((?x3463 (ite (or $x2873 $x2875 $x2877 $x2879 $x2881 $x2883) 1 0)))
 (let ((?x3455 (ite (or (and c_0_6 in_target_0) $x2419 $x2421 $x2423 $x2425 $x2427) (- 1) 0)))
 (let (($x2451 (and c_0_18 in_target_0)))
 (let (($x2853 (or $x2441 $x2443 $x2445 $x2447 $x2449 $x2451)))
 (let ((?x3448 (ite $x2853 (- 2) 0)))
 (let (($x2418 (and c_0_0 in_target_0)))
 (let ((?x3440 (ite $x2418 (- 3) 0)))
 (let ((?x3447 (+ 0 ?x3440)))
 (let ((?x3449 (+ ?x3447 ?x3448)))
 (let ((?x3458 (+ ?x3449 ?x3455)))
 (let ((?x3464 (+ ?x3458 ?x3463)))
 (let ((?x3465 (+ ?x3464 ?x2886)))
 (let ((?x3468 (+ ?x3465 ?x2906)))
 (let ((?x3482 (+ ?x3468 ?x3487)))
 (let ((?x3491 (+ ?x3482 ?x3498)))
 (let ((?x3486 (+ ?x3491 ?x3495)))
 (let ((?x3505 (+ ?x3486 ?x3504)))
 (let ((?x3509 (+ ?x3505 ?x2986)))
 (let ((?x3507 (+ ?x3509 ?x3005)))
 (let ((?x3535 (+ ?x3507 ?x3523)))
 (let ((?x3536 (+ ?x3535 ?x3527)))
 (let ((?x3528 (+ ?x3536 ?x3539)))
 (let ((?x3546 (+ ?x3528 ?x3545)))
 (let ((?x3549 (+ ?x3546 ?x3085)))
 (let ((?x3548 (+ ?x3549 ?x3104)))
 (let ((?x3574 (+ ?x3548 ?x3578)))
 (let ((?x3571 (+ ?x3574 ?x3569)))
 (let ((?x3582 (+ ?x3571 ?x3577)))
 (let ((?x3587 (+ ?x3582 ?x3586)))
 (let ((?x3589 (+ ?x3587 ?x3184)))
 (let ((?x3588 (+ ?x3589 ?x3203)))
 (let ((?x3609 (+ ?x3588 ?x3615)))
 (let ((?x3612 (+ ?x3609 ?x3605)))
 (let ((?x3623 (+ ?x3612 ?x3619)))
 (let ((?x3628 (+ ?x3623 ?x3627)))
 (let ((?x3632 (+ ?x3628 ?x3283)))
 (let ((?x3630 (+ ?x3632 ?x3302)))
 (let ((?x3655 (+ ?x3630 ?x3656)))
 (let ((?x3662 (+ ?x3655 ?x3658)))
 (let ((?x3646 (+ ?x3662 ?x3654)))
 (let ((?x3669 (+ ?x3646 ?x3668)))
 (let ((?x3670 (+ ?x3669 ?x3382)))
 (let (($x3699 (<= (+ ?x3670 ?x3401) 0)))
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
 (let (($x3693 (and $x2375 (and (and $x2837 $x3432) $x3699))))
 (let (($x3711 (and $x3693 (not (and (and true $x3708) $x3710)))))
 (let (($x3721 (and $x3711 (not (and (and true $x3718) $x3720)))))
 (let (($x3731 (and $x3721 (not (and $x3725 $x3730)))))
 (let (($x3741 (and $x3731 (not (and $x3735 $x3740)))))
 (let (($x3746 (and $x3741 (not (and (and true $x3708) $x3745)))))
 (let (($x3749 (and $x3746 (not (and (and true $x3718) $x3730)))))
 (let (($x3757 (and $x3749 (not (and $x3753 $x3740)))))
 (let (($x3762 (and $x3757 (not (and (and true $x3718) $x3761)))))
 (let (($x3765 (and $x3762 (not (and $x3753 $x3710)))))
 (let (($x3768 (and $x3765 (not (and $x3735 $x3745)))))
 (let (($x3776 (and $x3768 (not (and $x3772 $x3730)))))
 (let (($x3779 (and $x3776 (not (and $x3725 $x3761)))))
 (let (($x3782 (and $x3779 (not (and $x3735 $x3710)))))
 (let (($x3785 (and $x3782 (not (and $x3772 $x3720)))))
 (let (($x3801 (and $x3785 (not (and (and true $x3708) $x3808)))))
 (let (($x3815 (and $x3801 (not (and (and true $x3718) $x3823)))))
 (let (($x3835 (and $x3815 (not (and $x3725 $x3838)))))
 (let (($x3847 (and $x3835 (not (and $x3735 $x3853)))))
 (let (($x3865 (and $x3847 (not (and (and true $x3708) $x3868)))))
 (let (($x3869 (and $x3865 (not (and (and true $x3718) $x3838)))))
 (let (($x3860 (and $x3869 (not (and $x3753 $x3853)))))
 (let (($x3888 (and $x3860 (not (and (and true $x3718) $x3889)))))
 (let (($x3886 (and $x3888 (not (and $x3753 $x3808)))))
 (let (($x3893 (and $x3886 (not (and $x3735 $x3868)))))
 (let (($x3896 (and $x3893 (not (and $x3772 $x3838)))))
 (let (($x3901 (and $x3896 (not (and $x3725 $x3889)))))
 (let (($x3899 (and $x3901 (not (and $x3735 $x3808)))))
 (let (($x3898 (and $x3899 (not (and $x3772 $x3823)))))
 (let (($x3907 (and $x3898 (not (and (and true $x3708) $x3903)))))
 (let (($x3909 (and $x3907 (not (and (and true $x3718) $x3908)))))
 (let (($x3914 (and $x3909 (not (and $x3725 $x3913)))))
 (let (($x3919 (and $x3914 (not (and $x3735 $x3918)))))
 (let (($x3924 (and $x3919 (not (and (and true $x3708) $x3923)))))
 (let (($x3927 (and $x3924 (not (and (and true $x3718) $x3913)))))
 (let (($x3930 (and $x3927 (not (and $x3753 $x3918)))))
 (let (($x3935 (and $x3930 (not (and (and true $x3718) $x3934)))))
 (let (($x3938 (and $x3935 (not (and $x3753 $x3903)))))
 (let (($x3941 (and $x3938 (not (and $x3735 $x3923)))))
 (let (($x3944 (and $x3941 (not (and $x3772 $x3913)))))
 (let (($x3947 (and $x3944 (not (and $x3725 $x3934)))))
 (let (($x3950 (and $x3947 (not (and $x3735 $x3903)))))
 (let (($x3953 (and $x3950 (not (and $x3772 $x3908)))))
 (let (($x3974 (and $x3953 (not (and (and true $x3984) $x3978)))))
 (let (($x4005 (and $x3974 (not (and (and true $x4011) $x4001)))))
 (let (($x4032 (and $x4005 (not (and (and true $x4038) $x4031)))))
 (let (($x4055 (and $x4032 (not (and (and true $x4065) $x4061)))))
 (let (($x4070 (and $x4055 (not (and (and true $x3984) $x4062)))))
 (let (($x4071 (and $x4070 (not (and (and true $x4011) $x4031)))))
 (let (($x4093 (and $x4071 (not (and (and true $x4102) $x4061)))))
 (let (($x4099 (and $x4093 (not (and (and true $x4011) $x4096)))))
 (let (($x4110 (and $x4099 (not (and (and true $x4102) $x3978)))))
 (let (($x4111 (and $x4110 (not (and (and true $x4065) $x4062)))))
 (let (($x4131 (and $x4111 (not (and (and true $x4138) $x4031)))))
 (let (($x4134 (and $x4131 (not (and (and true $x4038) $x4096)))))
 (let (($x4128 (and $x4134 (not (and (and true $x4065) $x3978)))))
 (let (($x4142 (and $x4128 (not (and (and true $x4138) $x4001)))))
 (let (($x4145 (and $x4142 (not (and (and true c_0_12) $x2471)))))
 (let (($x4139 (and $x4145 (not (and (and true c_1_12) $x2524)))))
 (let (($x4151 (and $x4139 (not (and (and true c_3_12) $x2630)))))
 (let (($x4155 (and $x4151 (not (and (and true c_4_12) $x2683)))))
 (let (($x4158 (and $x4155 (not (and (and true c_0_12) $x2577)))))
 (let (($x4161 (and $x4158 (not (and (and true c_1_12) $x2630)))))
 (let (($x4165 (and $x4161 (not (and (and true c_2_12) $x2683)))))
 (let (($x4168 (and $x4165 (not (and (and true c_1_12) $x2418)))))
 (let (($x4171 (and $x4168 (not (and (and true c_2_12) $x2471)))))
 (let (($x4174 (and $x4171 (not (and (and true c_4_12) $x2577)))))
 (let (($x4178 (and $x4174 (not (and (and true c_5_12) $x2630)))))
 (let (($x4181 (and $x4178 (not (and (and true c_3_12) $x2418)))))
 (let (($x4184 (and $x4181 (not (and (and true c_4_12) $x2471)))))
 (let (($x4187 (and $x4184 (not (and (and true c_5_12) $x2524)))))
 (let (($x4194 (and $x4187 (not (and $x4193 c_1_18)))))
 (let (($x4207 (and $x4194 (not (and $x4203 c_2_18)))))
 (let (($x4214 (and $x4207 (not (and $x4213 c_4_18)))))
 (let (($x4227 (and $x4214 (not (and $x4223 c_5_18)))))
 (let (($x4232 (and $x4227 (not (and $x4193 c_3_18)))))
 (let (($x4230 (and $x4232 (not (and $x4203 c_4_18)))))
 (let (($x4242 (and $x4230 (not (and $x4239 c_5_18)))))
 (let (($x4245 (and $x4242 (not (and $x4203 c_0_18)))))
 (let (($x4246 (and $x4245 (not (and $x4239 c_1_18)))))
 (let (($x4251 (and $x4246 (not (and $x4223 c_3_18)))))
 (let (($x4261 (and $x4251 (not (and $x4258 c_4_18)))))
 (let (($x4265 (and $x4261 (not (and $x4213 c_0_18)))))
 (let (($x4266 (and $x4265 (not (and $x4223 c_1_18)))))
 (let (($x4268 (and $x4266 (not (and $x4258 c_2_18)))))
 (let (($x4307 (and $x4268 $x4306)))
 (let (($x4345 (and $x4307 $x4344)))
 (let (($x4377 (and $x4345 $x4376)))
 (let (($x4413 (and $x4377 $x4412)))
 (let (($x4421 (and $x4413 $x4422)))
 (let (($x4425 (and $x4421 $x4427)))
 (let (($x4451 (and $x4425 $x4450)))
 (let (($x4460 (and $x4451 $x4459)))
 (let (($x4465 (and $x4460 $x4462)))
 (let (($x4468 (and $x4465 $x4469)))
 (let (($x4491 (and $x4468 $x4490)))
 (let (($x4496 (and $x4491 $x4495)))
 (let (($x4500 (and $x4496 $x4497)))
 (let (($x4501 (and $x4500 $x4502)))
 (let (($x4513 (and $x4501 $x4510)))
 (let (($x4518 (and $x4513 $x4519)))
 (let (($x4527 (and $x4518 $x4531)))
 (let (($x4540 (and $x4527 $x4537)))
 (let (($x4542 (and $x4540 $x4544)))
 (let (($x4546 (and $x4542 $x4548)))
 (let (($x4557 (and $x4546 $x4553)))
 (let (($x4561 (and $x4557 $x4560)))
 (let (($x4565 (and $x4561 $x4562)))
 (let (($x4568 (and $x4565 $x4569)))
 (let (($x4575 (and $x4568 $x4578)))
 (let (($x4582 (and $x4575 $x4580)))
 (let (($x4586 (and $x4582 $x4583)))
 (let (($x4587 (and $x4586 $x4588)))
 (let (($x4593 (and $x4587 (not (and $x4193 $x4283)))))
 (let (($x4591 (and $x4593 (not (and $x4203 $x4319)))))
 (let (($x4599 (and $x4591 (not (and $x4213 $x4357)))))
 (let (($x4595 (and $x4599 (not (and $x4223 $x4389)))))
 (let (($x4604 (and $x4595 (not (and $x4193 $x4423)))))
 (let (($x4607 (and $x4604 (not (and $x4203 $x4357)))))
 (let (($x4609 (and $x4607 (not (and $x4239 $x4389)))))
 (let (($x4615 (and $x4609 (not (and $x4203 $x4461)))))
 (let (($x4616 (and $x4615 (not (and $x4239 $x4283)))))
 (let (($x4619 (and $x4616 (not (and $x4223 $x4423)))))
 (let (($x4622 (and $x4619 (not (and $x4258 $x4357)))))
 (let (($x4623 (and $x4622 (not (and $x4213 $x4461)))))
 (let (($x4629 (and $x4623 (not (and $x4223 $x4283)))))
 (let (($x4630 (and $x4629 (not (and $x4258 $x4319)))))
 (let (($x4735 (and $x4630 (and $x4728 $x4588))))
 (and $x4735 $x5733)))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
