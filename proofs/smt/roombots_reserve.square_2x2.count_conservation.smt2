; holon proof obligation: system roombots_reserve, region square:2x2, property count_conservation
; expected: unsat (the property holds for every configuration of the region)
(set-logic ALL)
; 
(set-info :status unknown)
(declare-fun c_0_24 () Bool)
(declare-fun c_0_23 () Bool)
(declare-fun c_0_22 () Bool)
(declare-fun c_0_21 () Bool)
(declare-fun c_0_20 () Bool)
(declare-fun c_0_19 () Bool)
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
(declare-fun c_1_24 () Bool)
(declare-fun c_1_23 () Bool)
(declare-fun c_1_22 () Bool)
(declare-fun c_1_21 () Bool)
(declare-fun c_1_20 () Bool)
(declare-fun c_1_19 () Bool)
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
(declare-fun c_2_24 () Bool)
(declare-fun c_2_23 () Bool)
(declare-fun c_2_22 () Bool)
(declare-fun c_2_21 () Bool)
(declare-fun c_2_20 () Bool)
(declare-fun c_2_19 () Bool)
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
(declare-fun c_3_24 () Bool)
(declare-fun c_3_23 () Bool)
(declare-fun c_3_22 () Bool)
(declare-fun c_3_21 () Bool)
(declare-fun c_3_20 () Bool)
(declare-fun c_3_19 () Bool)
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
(declare-fun d_0_24 () Bool)
(declare-fun d_0_23 () Bool)
(declare-fun d_0_22 () Bool)
(declare-fun d_0_21 () Bool)
(declare-fun d_0_20 () Bool)
(declare-fun d_0_19 () Bool)
(declare-fun d_0_18 () Bool)
(declare-fun d_0_17 () Bool)
(declare-fun d_0_16 () Bool)
(declare-fun d_0_15 () Bool)
(declare-fun d_0_14 () Bool)
(declare-fun d_0_13 () Bool)
(declare-fun d_0_12 () Bool)
(declare-fun d_0_11 () Bool)
(declare-fun d_0_10 () Bool)
(declare-fun d_0_9 () Bool)
(declare-fun d_0_8 () Bool)
(declare-fun d_0_7 () Bool)
(declare-fun d_0_6 () Bool)
(declare-fun d_0_5 () Bool)
(declare-fun d_0_4 () Bool)
(declare-fun d_0_3 () Bool)
(declare-fun d_0_2 () Bool)
(declare-fun d_0_1 () Bool)
(declare-fun d_0_0 () Bool)
(declare-fun d_1_24 () Bool)
(declare-fun d_1_23 () Bool)
(declare-fun d_1_22 () Bool)
(declare-fun d_1_21 () Bool)
(declare-fun d_1_20 () Bool)
(declare-fun d_1_19 () Bool)
(declare-fun d_1_18 () Bool)
(declare-fun d_1_17 () Bool)
(declare-fun d_1_16 () Bool)
(declare-fun d_1_15 () Bool)
(declare-fun d_1_14 () Bool)
(declare-fun d_1_13 () Bool)
(declare-fun d_1_12 () Bool)
(declare-fun d_1_11 () Bool)
(declare-fun d_1_10 () Bool)
(declare-fun d_1_9 () Bool)
(declare-fun d_1_8 () Bool)
(declare-fun d_1_7 () Bool)
(declare-fun d_1_6 () Bool)
(declare-fun d_1_5 () Bool)
(declare-fun d_1_4 () Bool)
(declare-fun d_1_3 () Bool)
(declare-fun d_1_2 () Bool)
(declare-fun d_1_1 () Bool)
(declare-fun d_1_0 () Bool)
(declare-fun d_2_24 () Bool)
(declare-fun d_2_23 () Bool)
(declare-fun d_2_22 () Bool)
(declare-fun d_2_21 () Bool)
(declare-fun d_2_20 () Bool)
(declare-fun d_2_19 () Bool)
(declare-fun d_2_18 () Bool)
(declare-fun d_2_17 () Bool)
(declare-fun d_2_16 () Bool)
(declare-fun d_2_15 () Bool)
(declare-fun d_2_14 () Bool)
(declare-fun d_2_13 () Bool)
(declare-fun d_2_12 () Bool)
(declare-fun d_2_11 () Bool)
(declare-fun d_2_10 () Bool)
(declare-fun d_2_9 () Bool)
(declare-fun d_2_8 () Bool)
(declare-fun d_2_7 () Bool)
(declare-fun d_2_6 () Bool)
(declare-fun d_2_5 () Bool)
(declare-fun d_2_4 () Bool)
(declare-fun d_2_3 () Bool)
(declare-fun d_2_2 () Bool)
(declare-fun d_2_1 () Bool)
(declare-fun d_2_0 () Bool)
(declare-fun d_3_24 () Bool)
(declare-fun d_3_23 () Bool)
(declare-fun d_3_22 () Bool)
(declare-fun d_3_21 () Bool)
(declare-fun d_3_20 () Bool)
(declare-fun d_3_19 () Bool)
(declare-fun d_3_18 () Bool)
(declare-fun d_3_17 () Bool)
(declare-fun d_3_16 () Bool)
(declare-fun d_3_15 () Bool)
(declare-fun d_3_14 () Bool)
(declare-fun d_3_13 () Bool)
(declare-fun d_3_12 () Bool)
(declare-fun d_3_11 () Bool)
(declare-fun d_3_10 () Bool)
(declare-fun d_3_9 () Bool)
(declare-fun d_3_8 () Bool)
(declare-fun d_3_7 () Bool)
(declare-fun d_3_6 () Bool)
(declare-fun d_3_5 () Bool)
(declare-fun d_3_4 () Bool)
(declare-fun d_3_3 () Bool)
(declare-fun d_3_2 () Bool)
(declare-fun d_3_1 () Bool)
(declare-fun d_3_0 () Bool)
(declare-fun in_walk7_3 () Bool)
(declare-fun in_walk8_3 () Bool)
(declare-fun in_walk7_2 () Bool)
(declare-fun in_walk8_2 () Bool)
(declare-fun in_walk7_1 () Bool)
(declare-fun in_walk8_1 () Bool)
(declare-fun in_walk7_0 () Bool)
(declare-fun in_walk8_0 () Bool)
(declare-fun in_walk6_3 () Bool)
(declare-fun in_walk6_2 () Bool)
(declare-fun in_walk6_1 () Bool)
(declare-fun in_walk6_0 () Bool)
(declare-fun in_walk5_3 () Bool)
(declare-fun in_walk5_2 () Bool)
(declare-fun in_walk5_1 () Bool)
(declare-fun in_walk5_0 () Bool)
(declare-fun in_walk4_3 () Bool)
(declare-fun in_walk4_2 () Bool)
(declare-fun in_walk4_1 () Bool)
(declare-fun in_walk4_0 () Bool)
(declare-fun in_walk3_3 () Bool)
(declare-fun in_walk3_2 () Bool)
(declare-fun in_walk3_1 () Bool)
(declare-fun in_walk3_0 () Bool)
(declare-fun in_walk2_3 () Bool)
(declare-fun in_walk2_2 () Bool)
(declare-fun in_walk2_1 () Bool)
(declare-fun in_walk2_0 () Bool)
(declare-fun in_walk1_3 () Bool)
(declare-fun in_walk1_2 () Bool)
(declare-fun in_walk1_1 () Bool)
(declare-fun in_walk1_0 () Bool)
(declare-fun rule_instance () Int)
(assert
 (let (($x38 (or false c_0_0)))
 (let (($x40 (or $x38 c_0_1)))
 (let (($x42 (or $x40 c_0_2)))
 (let (($x44 (or $x42 c_0_3)))
 (let (($x46 (or $x44 c_0_4)))
 (let (($x48 (or $x46 c_0_5)))
 (let (($x50 (or $x48 c_0_6)))
 (let (($x52 (or $x50 c_0_7)))
 (let (($x54 (or $x52 c_0_8)))
 (let (($x56 (or $x54 c_0_9)))
 (let (($x58 (or $x56 c_0_10)))
 (let (($x60 (or $x58 c_0_11)))
 (let (($x62 (or $x60 c_0_12)))
 (let (($x64 (or $x62 c_0_13)))
 (let (($x66 (or $x64 c_0_14)))
 (let (($x68 (or $x66 c_0_15)))
 (let (($x70 (or $x68 c_0_16)))
 (let (($x72 (or $x70 c_0_17)))
 (let (($x74 (or $x72 c_0_18)))
 (let (($x76 (or $x74 c_0_19)))
 (let (($x78 (or $x76 c_0_20)))
 (let (($x80 (or $x78 c_0_21)))
 (let (($x82 (or $x80 c_0_22)))
 (let (($x84 (or $x82 c_0_23)))
 (or $x84 c_0_24))))))))))))))))))))))))))
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
 (not (and c_0_0 c_0_19)))
(assert
 (not (and c_0_0 c_0_20)))
(assert
 (not (and c_0_0 c_0_21)))
(assert
 (not (and c_0_0 c_0_22)))
(assert
 (not (and c_0_0 c_0_23)))
(assert
 (not (and c_0_0 c_0_24)))
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
 (not (and c_0_1 c_0_19)))
(assert
 (not (and c_0_1 c_0_20)))
(assert
 (not (and c_0_1 c_0_21)))
(assert
 (not (and c_0_1 c_0_22)))
(assert
 (not (and c_0_1 c_0_23)))
(assert
 (not (and c_0_1 c_0_24)))
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
 (not (and c_0_2 c_0_19)))
(assert
 (not (and c_0_2 c_0_20)))
(assert
 (not (and c_0_2 c_0_21)))
(assert
 (not (and c_0_2 c_0_22)))
(assert
 (not (and c_0_2 c_0_23)))
(assert
 (not (and c_0_2 c_0_24)))
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
 (not (and c_0_3 c_0_19)))
(assert
 (not (and c_0_3 c_0_20)))
(assert
 (not (and c_0_3 c_0_21)))
(assert
 (not (and c_0_3 c_0_22)))
(assert
 (not (and c_0_3 c_0_23)))
(assert
 (not (and c_0_3 c_0_24)))
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
 (not (and c_0_4 c_0_19)))
(assert
 (not (and c_0_4 c_0_20)))
(assert
 (not (and c_0_4 c_0_21)))
(assert
 (not (and c_0_4 c_0_22)))
(assert
 (not (and c_0_4 c_0_23)))
(assert
 (not (and c_0_4 c_0_24)))
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
 (not (and c_0_5 c_0_19)))
(assert
 (not (and c_0_5 c_0_20)))
(assert
 (not (and c_0_5 c_0_21)))
(assert
 (not (and c_0_5 c_0_22)))
(assert
 (not (and c_0_5 c_0_23)))
(assert
 (not (and c_0_5 c_0_24)))
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
 (not (and c_0_6 c_0_19)))
(assert
 (not (and c_0_6 c_0_20)))
(assert
 (not (and c_0_6 c_0_21)))
(assert
 (not (and c_0_6 c_0_22)))
(assert
 (not (and c_0_6 c_0_23)))
(assert
 (not (and c_0_6 c_0_24)))
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
 (not (and c_0_7 c_0_19)))
(assert
 (not (and c_0_7 c_0_20)))
(assert
 (not (and c_0_7 c_0_21)))
(assert
 (not (and c_0_7 c_0_22)))
(assert
 (not (and c_0_7 c_0_23)))
(assert
 (not (and c_0_7 c_0_24)))
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
 (not (and c_0_8 c_0_19)))
(assert
 (not (and c_0_8 c_0_20)))
(assert
 (not (and c_0_8 c_0_21)))
(assert
 (not (and c_0_8 c_0_22)))
(assert
 (not (and c_0_8 c_0_23)))
(assert
 (not (and c_0_8 c_0_24)))
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
 (not (and c_0_9 c_0_19)))
(assert
 (not (and c_0_9 c_0_20)))
(assert
 (not (and c_0_9 c_0_21)))
(assert
 (not (and c_0_9 c_0_22)))
(assert
 (not (and c_0_9 c_0_23)))
(assert
 (not (and c_0_9 c_0_24)))
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
 (not (and c_0_10 c_0_19)))
(assert
 (not (and c_0_10 c_0_20)))
(assert
 (not (and c_0_10 c_0_21)))
(assert
 (not (and c_0_10 c_0_22)))
(assert
 (not (and c_0_10 c_0_23)))
(assert
 (not (and c_0_10 c_0_24)))
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
 (not (and c_0_11 c_0_19)))
(assert
 (not (and c_0_11 c_0_20)))
(assert
 (not (and c_0_11 c_0_21)))
(assert
 (not (and c_0_11 c_0_22)))
(assert
 (not (and c_0_11 c_0_23)))
(assert
 (not (and c_0_11 c_0_24)))
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
 (not (and c_0_12 c_0_19)))
(assert
 (not (and c_0_12 c_0_20)))
(assert
 (not (and c_0_12 c_0_21)))
(assert
 (not (and c_0_12 c_0_22)))
(assert
 (not (and c_0_12 c_0_23)))
(assert
 (not (and c_0_12 c_0_24)))
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
 (not (and c_0_13 c_0_19)))
(assert
 (not (and c_0_13 c_0_20)))
(assert
 (not (and c_0_13 c_0_21)))
(assert
 (not (and c_0_13 c_0_22)))
(assert
 (not (and c_0_13 c_0_23)))
(assert
 (not (and c_0_13 c_0_24)))
(assert
 (not (and c_0_14 c_0_15)))
(assert
 (not (and c_0_14 c_0_16)))
(assert
 (not (and c_0_14 c_0_17)))
(assert
 (not (and c_0_14 c_0_18)))
(assert
 (not (and c_0_14 c_0_19)))
(assert
 (not (and c_0_14 c_0_20)))
(assert
 (not (and c_0_14 c_0_21)))
(assert
 (not (and c_0_14 c_0_22)))
(assert
 (not (and c_0_14 c_0_23)))
(assert
 (not (and c_0_14 c_0_24)))
(assert
 (not (and c_0_15 c_0_16)))
(assert
 (not (and c_0_15 c_0_17)))
(assert
 (not (and c_0_15 c_0_18)))
(assert
 (not (and c_0_15 c_0_19)))
(assert
 (not (and c_0_15 c_0_20)))
(assert
 (not (and c_0_15 c_0_21)))
(assert
 (not (and c_0_15 c_0_22)))
(assert
 (not (and c_0_15 c_0_23)))
(assert
 (not (and c_0_15 c_0_24)))
(assert
 (not (and c_0_16 c_0_17)))
(assert
 (not (and c_0_16 c_0_18)))
(assert
 (not (and c_0_16 c_0_19)))
(assert
 (not (and c_0_16 c_0_20)))
(assert
 (not (and c_0_16 c_0_21)))
(assert
 (not (and c_0_16 c_0_22)))
(assert
 (not (and c_0_16 c_0_23)))
(assert
 (not (and c_0_16 c_0_24)))
(assert
 (not (and c_0_17 c_0_18)))
(assert
 (not (and c_0_17 c_0_19)))
(assert
 (not (and c_0_17 c_0_20)))
(assert
 (not (and c_0_17 c_0_21)))
(assert
 (not (and c_0_17 c_0_22)))
(assert
 (not (and c_0_17 c_0_23)))
(assert
 (not (and c_0_17 c_0_24)))
(assert
 (not (and c_0_18 c_0_19)))
(assert
 (not (and c_0_18 c_0_20)))
(assert
 (not (and c_0_18 c_0_21)))
(assert
 (not (and c_0_18 c_0_22)))
(assert
 (not (and c_0_18 c_0_23)))
(assert
 (not (and c_0_18 c_0_24)))
(assert
 (not (and c_0_19 c_0_20)))
(assert
 (not (and c_0_19 c_0_21)))
(assert
 (not (and c_0_19 c_0_22)))
(assert
 (not (and c_0_19 c_0_23)))
(assert
 (not (and c_0_19 c_0_24)))
(assert
 (not (and c_0_20 c_0_21)))
(assert
 (not (and c_0_20 c_0_22)))
(assert
 (not (and c_0_20 c_0_23)))
(assert
 (not (and c_0_20 c_0_24)))
(assert
 (not (and c_0_21 c_0_22)))
(assert
 (not (and c_0_21 c_0_23)))
(assert
 (not (and c_0_21 c_0_24)))
(assert
 (not (and c_0_22 c_0_23)))
(assert
 (not (and c_0_22 c_0_24)))
(assert
 (not (and c_0_23 c_0_24)))
(assert
 (let (($x688 (or false c_1_0)))
 (let (($x690 (or $x688 c_1_1)))
 (let (($x692 (or $x690 c_1_2)))
 (let (($x694 (or $x692 c_1_3)))
 (let (($x696 (or $x694 c_1_4)))
 (let (($x698 (or $x696 c_1_5)))
 (let (($x700 (or $x698 c_1_6)))
 (let (($x702 (or $x700 c_1_7)))
 (let (($x704 (or $x702 c_1_8)))
 (let (($x706 (or $x704 c_1_9)))
 (let (($x708 (or $x706 c_1_10)))
 (let (($x710 (or $x708 c_1_11)))
 (let (($x712 (or $x710 c_1_12)))
 (let (($x714 (or $x712 c_1_13)))
 (let (($x716 (or $x714 c_1_14)))
 (let (($x718 (or $x716 c_1_15)))
 (let (($x720 (or $x718 c_1_16)))
 (let (($x722 (or $x720 c_1_17)))
 (let (($x724 (or $x722 c_1_18)))
 (let (($x726 (or $x724 c_1_19)))
 (let (($x728 (or $x726 c_1_20)))
 (let (($x730 (or $x728 c_1_21)))
 (let (($x732 (or $x730 c_1_22)))
 (let (($x734 (or $x732 c_1_23)))
 (or $x734 c_1_24))))))))))))))))))))))))))
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
 (not (and c_1_0 c_1_19)))
(assert
 (not (and c_1_0 c_1_20)))
(assert
 (not (and c_1_0 c_1_21)))
(assert
 (not (and c_1_0 c_1_22)))
(assert
 (not (and c_1_0 c_1_23)))
(assert
 (not (and c_1_0 c_1_24)))
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
 (not (and c_1_1 c_1_19)))
(assert
 (not (and c_1_1 c_1_20)))
(assert
 (not (and c_1_1 c_1_21)))
(assert
 (not (and c_1_1 c_1_22)))
(assert
 (not (and c_1_1 c_1_23)))
(assert
 (not (and c_1_1 c_1_24)))
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
 (not (and c_1_2 c_1_19)))
(assert
 (not (and c_1_2 c_1_20)))
(assert
 (not (and c_1_2 c_1_21)))
(assert
 (not (and c_1_2 c_1_22)))
(assert
 (not (and c_1_2 c_1_23)))
(assert
 (not (and c_1_2 c_1_24)))
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
 (not (and c_1_3 c_1_19)))
(assert
 (not (and c_1_3 c_1_20)))
(assert
 (not (and c_1_3 c_1_21)))
(assert
 (not (and c_1_3 c_1_22)))
(assert
 (not (and c_1_3 c_1_23)))
(assert
 (not (and c_1_3 c_1_24)))
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
 (not (and c_1_4 c_1_19)))
(assert
 (not (and c_1_4 c_1_20)))
(assert
 (not (and c_1_4 c_1_21)))
(assert
 (not (and c_1_4 c_1_22)))
(assert
 (not (and c_1_4 c_1_23)))
(assert
 (not (and c_1_4 c_1_24)))
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
 (not (and c_1_5 c_1_19)))
(assert
 (not (and c_1_5 c_1_20)))
(assert
 (not (and c_1_5 c_1_21)))
(assert
 (not (and c_1_5 c_1_22)))
(assert
 (not (and c_1_5 c_1_23)))
(assert
 (not (and c_1_5 c_1_24)))
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
 (not (and c_1_6 c_1_19)))
(assert
 (not (and c_1_6 c_1_20)))
(assert
 (not (and c_1_6 c_1_21)))
(assert
 (not (and c_1_6 c_1_22)))
(assert
 (not (and c_1_6 c_1_23)))
(assert
 (not (and c_1_6 c_1_24)))
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
 (not (and c_1_7 c_1_19)))
(assert
 (not (and c_1_7 c_1_20)))
(assert
 (not (and c_1_7 c_1_21)))
(assert
 (not (and c_1_7 c_1_22)))
(assert
 (not (and c_1_7 c_1_23)))
(assert
 (not (and c_1_7 c_1_24)))
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
 (not (and c_1_8 c_1_19)))
(assert
 (not (and c_1_8 c_1_20)))
(assert
 (not (and c_1_8 c_1_21)))
(assert
 (not (and c_1_8 c_1_22)))
(assert
 (not (and c_1_8 c_1_23)))
(assert
 (not (and c_1_8 c_1_24)))
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
 (not (and c_1_9 c_1_19)))
(assert
 (not (and c_1_9 c_1_20)))
(assert
 (not (and c_1_9 c_1_21)))
(assert
 (not (and c_1_9 c_1_22)))
(assert
 (not (and c_1_9 c_1_23)))
(assert
 (not (and c_1_9 c_1_24)))
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
 (not (and c_1_10 c_1_19)))
(assert
 (not (and c_1_10 c_1_20)))
(assert
 (not (and c_1_10 c_1_21)))
(assert
 (not (and c_1_10 c_1_22)))
(assert
 (not (and c_1_10 c_1_23)))
(assert
 (not (and c_1_10 c_1_24)))
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
 (not (and c_1_11 c_1_19)))
(assert
 (not (and c_1_11 c_1_20)))
(assert
 (not (and c_1_11 c_1_21)))
(assert
 (not (and c_1_11 c_1_22)))
(assert
 (not (and c_1_11 c_1_23)))
(assert
 (not (and c_1_11 c_1_24)))
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
 (not (and c_1_12 c_1_19)))
(assert
 (not (and c_1_12 c_1_20)))
(assert
 (not (and c_1_12 c_1_21)))
(assert
 (not (and c_1_12 c_1_22)))
(assert
 (not (and c_1_12 c_1_23)))
(assert
 (not (and c_1_12 c_1_24)))
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
 (not (and c_1_13 c_1_19)))
(assert
 (not (and c_1_13 c_1_20)))
(assert
 (not (and c_1_13 c_1_21)))
(assert
 (not (and c_1_13 c_1_22)))
(assert
 (not (and c_1_13 c_1_23)))
(assert
 (not (and c_1_13 c_1_24)))
(assert
 (not (and c_1_14 c_1_15)))
(assert
 (not (and c_1_14 c_1_16)))
(assert
 (not (and c_1_14 c_1_17)))
(assert
 (not (and c_1_14 c_1_18)))
(assert
 (not (and c_1_14 c_1_19)))
(assert
 (not (and c_1_14 c_1_20)))
(assert
 (not (and c_1_14 c_1_21)))
(assert
 (not (and c_1_14 c_1_22)))
(assert
 (not (and c_1_14 c_1_23)))
(assert
 (not (and c_1_14 c_1_24)))
(assert
 (not (and c_1_15 c_1_16)))
(assert
 (not (and c_1_15 c_1_17)))
(assert
 (not (and c_1_15 c_1_18)))
(assert
 (not (and c_1_15 c_1_19)))
(assert
 (not (and c_1_15 c_1_20)))
(assert
 (not (and c_1_15 c_1_21)))
(assert
 (not (and c_1_15 c_1_22)))
(assert
 (not (and c_1_15 c_1_23)))
(assert
 (not (and c_1_15 c_1_24)))
(assert
 (not (and c_1_16 c_1_17)))
(assert
 (not (and c_1_16 c_1_18)))
(assert
 (not (and c_1_16 c_1_19)))
(assert
 (not (and c_1_16 c_1_20)))
(assert
 (not (and c_1_16 c_1_21)))
(assert
 (not (and c_1_16 c_1_22)))
(assert
 (not (and c_1_16 c_1_23)))
(assert
 (not (and c_1_16 c_1_24)))
(assert
 (not (and c_1_17 c_1_18)))
(assert
 (not (and c_1_17 c_1_19)))
(assert
 (not (and c_1_17 c_1_20)))
(assert
 (not (and c_1_17 c_1_21)))
(assert
 (not (and c_1_17 c_1_22)))
(assert
 (not (and c_1_17 c_1_23)))
(assert
 (not (and c_1_17 c_1_24)))
(assert
 (not (and c_1_18 c_1_19)))
(assert
 (not (and c_1_18 c_1_20)))
(assert
 (not (and c_1_18 c_1_21)))
(assert
 (not (and c_1_18 c_1_22)))
(assert
 (not (and c_1_18 c_1_23)))
(assert
 (not (and c_1_18 c_1_24)))
(assert
 (not (and c_1_19 c_1_20)))
(assert
 (not (and c_1_19 c_1_21)))
(assert
 (not (and c_1_19 c_1_22)))
(assert
 (not (and c_1_19 c_1_23)))
(assert
 (not (and c_1_19 c_1_24)))
(assert
 (not (and c_1_20 c_1_21)))
(assert
 (not (and c_1_20 c_1_22)))
(assert
 (not (and c_1_20 c_1_23)))
(assert
 (not (and c_1_20 c_1_24)))
(assert
 (not (and c_1_21 c_1_22)))
(assert
 (not (and c_1_21 c_1_23)))
(assert
 (not (and c_1_21 c_1_24)))
(assert
 (not (and c_1_22 c_1_23)))
(assert
 (not (and c_1_22 c_1_24)))
(assert
 (not (and c_1_23 c_1_24)))
(assert
 (let (($x1338 (or false c_2_0)))
 (let (($x1340 (or $x1338 c_2_1)))
 (let (($x1342 (or $x1340 c_2_2)))
 (let (($x1344 (or $x1342 c_2_3)))
 (let (($x1346 (or $x1344 c_2_4)))
 (let (($x1348 (or $x1346 c_2_5)))
 (let (($x1350 (or $x1348 c_2_6)))
 (let (($x1352 (or $x1350 c_2_7)))
 (let (($x1354 (or $x1352 c_2_8)))
 (let (($x1356 (or $x1354 c_2_9)))
 (let (($x1358 (or $x1356 c_2_10)))
 (let (($x1360 (or $x1358 c_2_11)))
 (let (($x1362 (or $x1360 c_2_12)))
 (let (($x1364 (or $x1362 c_2_13)))
 (let (($x1366 (or $x1364 c_2_14)))
 (let (($x1368 (or $x1366 c_2_15)))
 (let (($x1370 (or $x1368 c_2_16)))
 (let (($x1372 (or $x1370 c_2_17)))
 (let (($x1374 (or $x1372 c_2_18)))
 (let (($x1376 (or $x1374 c_2_19)))
 (let (($x1378 (or $x1376 c_2_20)))
 (let (($x1380 (or $x1378 c_2_21)))
 (let (($x1382 (or $x1380 c_2_22)))
 (let (($x1384 (or $x1382 c_2_23)))
 (or $x1384 c_2_24))))))))))))))))))))))))))
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
 (not (and c_2_0 c_2_19)))
(assert
 (not (and c_2_0 c_2_20)))
(assert
 (not (and c_2_0 c_2_21)))
(assert
 (not (and c_2_0 c_2_22)))
(assert
 (not (and c_2_0 c_2_23)))
(assert
 (not (and c_2_0 c_2_24)))
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
 (not (and c_2_1 c_2_19)))
(assert
 (not (and c_2_1 c_2_20)))
(assert
 (not (and c_2_1 c_2_21)))
(assert
 (not (and c_2_1 c_2_22)))
(assert
 (not (and c_2_1 c_2_23)))
(assert
 (not (and c_2_1 c_2_24)))
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
 (not (and c_2_2 c_2_19)))
(assert
 (not (and c_2_2 c_2_20)))
(assert
 (not (and c_2_2 c_2_21)))
(assert
 (not (and c_2_2 c_2_22)))
(assert
 (not (and c_2_2 c_2_23)))
(assert
 (not (and c_2_2 c_2_24)))
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
 (not (and c_2_3 c_2_19)))
(assert
 (not (and c_2_3 c_2_20)))
(assert
 (not (and c_2_3 c_2_21)))
(assert
 (not (and c_2_3 c_2_22)))
(assert
 (not (and c_2_3 c_2_23)))
(assert
 (not (and c_2_3 c_2_24)))
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
 (not (and c_2_4 c_2_19)))
(assert
 (not (and c_2_4 c_2_20)))
(assert
 (not (and c_2_4 c_2_21)))
(assert
 (not (and c_2_4 c_2_22)))
(assert
 (not (and c_2_4 c_2_23)))
(assert
 (not (and c_2_4 c_2_24)))
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
 (not (and c_2_5 c_2_19)))
(assert
 (not (and c_2_5 c_2_20)))
(assert
 (not (and c_2_5 c_2_21)))
(assert
 (not (and c_2_5 c_2_22)))
(assert
 (not (and c_2_5 c_2_23)))
(assert
 (not (and c_2_5 c_2_24)))
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
 (not (and c_2_6 c_2_19)))
(assert
 (not (and c_2_6 c_2_20)))
(assert
 (not (and c_2_6 c_2_21)))
(assert
 (not (and c_2_6 c_2_22)))
(assert
 (not (and c_2_6 c_2_23)))
(assert
 (not (and c_2_6 c_2_24)))
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
 (not (and c_2_7 c_2_19)))
(assert
 (not (and c_2_7 c_2_20)))
(assert
 (not (and c_2_7 c_2_21)))
(assert
 (not (and c_2_7 c_2_22)))
(assert
 (not (and c_2_7 c_2_23)))
(assert
 (not (and c_2_7 c_2_24)))
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
 (not (and c_2_8 c_2_19)))
(assert
 (not (and c_2_8 c_2_20)))
(assert
 (not (and c_2_8 c_2_21)))
(assert
 (not (and c_2_8 c_2_22)))
(assert
 (not (and c_2_8 c_2_23)))
(assert
 (not (and c_2_8 c_2_24)))
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
 (not (and c_2_9 c_2_19)))
(assert
 (not (and c_2_9 c_2_20)))
(assert
 (not (and c_2_9 c_2_21)))
(assert
 (not (and c_2_9 c_2_22)))
(assert
 (not (and c_2_9 c_2_23)))
(assert
 (not (and c_2_9 c_2_24)))
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
 (not (and c_2_10 c_2_19)))
(assert
 (not (and c_2_10 c_2_20)))
(assert
 (not (and c_2_10 c_2_21)))
(assert
 (not (and c_2_10 c_2_22)))
(assert
 (not (and c_2_10 c_2_23)))
(assert
 (not (and c_2_10 c_2_24)))
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
 (not (and c_2_11 c_2_19)))
(assert
 (not (and c_2_11 c_2_20)))
(assert
 (not (and c_2_11 c_2_21)))
(assert
 (not (and c_2_11 c_2_22)))
(assert
 (not (and c_2_11 c_2_23)))
(assert
 (not (and c_2_11 c_2_24)))
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
 (not (and c_2_12 c_2_19)))
(assert
 (not (and c_2_12 c_2_20)))
(assert
 (not (and c_2_12 c_2_21)))
(assert
 (not (and c_2_12 c_2_22)))
(assert
 (not (and c_2_12 c_2_23)))
(assert
 (not (and c_2_12 c_2_24)))
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
 (not (and c_2_13 c_2_19)))
(assert
 (not (and c_2_13 c_2_20)))
(assert
 (not (and c_2_13 c_2_21)))
(assert
 (not (and c_2_13 c_2_22)))
(assert
 (not (and c_2_13 c_2_23)))
(assert
 (not (and c_2_13 c_2_24)))
(assert
 (not (and c_2_14 c_2_15)))
(assert
 (not (and c_2_14 c_2_16)))
(assert
 (not (and c_2_14 c_2_17)))
(assert
 (not (and c_2_14 c_2_18)))
(assert
 (not (and c_2_14 c_2_19)))
(assert
 (not (and c_2_14 c_2_20)))
(assert
 (not (and c_2_14 c_2_21)))
(assert
 (not (and c_2_14 c_2_22)))
(assert
 (not (and c_2_14 c_2_23)))
(assert
 (not (and c_2_14 c_2_24)))
(assert
 (not (and c_2_15 c_2_16)))
(assert
 (not (and c_2_15 c_2_17)))
(assert
 (not (and c_2_15 c_2_18)))
(assert
 (not (and c_2_15 c_2_19)))
(assert
 (not (and c_2_15 c_2_20)))
(assert
 (not (and c_2_15 c_2_21)))
(assert
 (not (and c_2_15 c_2_22)))
(assert
 (not (and c_2_15 c_2_23)))
(assert
 (not (and c_2_15 c_2_24)))
(assert
 (not (and c_2_16 c_2_17)))
(assert
 (not (and c_2_16 c_2_18)))
(assert
 (not (and c_2_16 c_2_19)))
(assert
 (not (and c_2_16 c_2_20)))
(assert
 (not (and c_2_16 c_2_21)))
(assert
 (not (and c_2_16 c_2_22)))
(assert
 (not (and c_2_16 c_2_23)))
(assert
 (not (and c_2_16 c_2_24)))
(assert
 (not (and c_2_17 c_2_18)))
(assert
 (not (and c_2_17 c_2_19)))
(assert
 (not (and c_2_17 c_2_20)))
(assert
 (not (and c_2_17 c_2_21)))
(assert
 (not (and c_2_17 c_2_22)))
(assert
 (not (and c_2_17 c_2_23)))
(assert
 (not (and c_2_17 c_2_24)))
(assert
 (not (and c_2_18 c_2_19)))
(assert
 (not (and c_2_18 c_2_20)))
(assert
 (not (and c_2_18 c_2_21)))
(assert
 (not (and c_2_18 c_2_22)))
(assert
 (not (and c_2_18 c_2_23)))
(assert
 (not (and c_2_18 c_2_24)))
(assert
 (not (and c_2_19 c_2_20)))
(assert
 (not (and c_2_19 c_2_21)))
(assert
 (not (and c_2_19 c_2_22)))
(assert
 (not (and c_2_19 c_2_23)))
(assert
 (not (and c_2_19 c_2_24)))
(assert
 (not (and c_2_20 c_2_21)))
(assert
 (not (and c_2_20 c_2_22)))
(assert
 (not (and c_2_20 c_2_23)))
(assert
 (not (and c_2_20 c_2_24)))
(assert
 (not (and c_2_21 c_2_22)))
(assert
 (not (and c_2_21 c_2_23)))
(assert
 (not (and c_2_21 c_2_24)))
(assert
 (not (and c_2_22 c_2_23)))
(assert
 (not (and c_2_22 c_2_24)))
(assert
 (not (and c_2_23 c_2_24)))
(assert
 (let (($x1988 (or false c_3_0)))
 (let (($x1990 (or $x1988 c_3_1)))
 (let (($x1992 (or $x1990 c_3_2)))
 (let (($x1994 (or $x1992 c_3_3)))
 (let (($x1996 (or $x1994 c_3_4)))
 (let (($x1998 (or $x1996 c_3_5)))
 (let (($x2000 (or $x1998 c_3_6)))
 (let (($x2002 (or $x2000 c_3_7)))
 (let (($x2004 (or $x2002 c_3_8)))
 (let (($x2006 (or $x2004 c_3_9)))
 (let (($x2008 (or $x2006 c_3_10)))
 (let (($x2010 (or $x2008 c_3_11)))
 (let (($x2012 (or $x2010 c_3_12)))
 (let (($x2014 (or $x2012 c_3_13)))
 (let (($x2016 (or $x2014 c_3_14)))
 (let (($x2018 (or $x2016 c_3_15)))
 (let (($x2020 (or $x2018 c_3_16)))
 (let (($x2022 (or $x2020 c_3_17)))
 (let (($x2024 (or $x2022 c_3_18)))
 (let (($x2026 (or $x2024 c_3_19)))
 (let (($x2028 (or $x2026 c_3_20)))
 (let (($x2030 (or $x2028 c_3_21)))
 (let (($x2032 (or $x2030 c_3_22)))
 (let (($x2034 (or $x2032 c_3_23)))
 (or $x2034 c_3_24))))))))))))))))))))))))))
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
 (not (and c_3_0 c_3_19)))
(assert
 (not (and c_3_0 c_3_20)))
(assert
 (not (and c_3_0 c_3_21)))
(assert
 (not (and c_3_0 c_3_22)))
(assert
 (not (and c_3_0 c_3_23)))
(assert
 (not (and c_3_0 c_3_24)))
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
 (not (and c_3_1 c_3_19)))
(assert
 (not (and c_3_1 c_3_20)))
(assert
 (not (and c_3_1 c_3_21)))
(assert
 (not (and c_3_1 c_3_22)))
(assert
 (not (and c_3_1 c_3_23)))
(assert
 (not (and c_3_1 c_3_24)))
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
 (not (and c_3_2 c_3_19)))
(assert
 (not (and c_3_2 c_3_20)))
(assert
 (not (and c_3_2 c_3_21)))
(assert
 (not (and c_3_2 c_3_22)))
(assert
 (not (and c_3_2 c_3_23)))
(assert
 (not (and c_3_2 c_3_24)))
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
 (not (and c_3_3 c_3_19)))
(assert
 (not (and c_3_3 c_3_20)))
(assert
 (not (and c_3_3 c_3_21)))
(assert
 (not (and c_3_3 c_3_22)))
(assert
 (not (and c_3_3 c_3_23)))
(assert
 (not (and c_3_3 c_3_24)))
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
 (not (and c_3_4 c_3_19)))
(assert
 (not (and c_3_4 c_3_20)))
(assert
 (not (and c_3_4 c_3_21)))
(assert
 (not (and c_3_4 c_3_22)))
(assert
 (not (and c_3_4 c_3_23)))
(assert
 (not (and c_3_4 c_3_24)))
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
 (not (and c_3_5 c_3_19)))
(assert
 (not (and c_3_5 c_3_20)))
(assert
 (not (and c_3_5 c_3_21)))
(assert
 (not (and c_3_5 c_3_22)))
(assert
 (not (and c_3_5 c_3_23)))
(assert
 (not (and c_3_5 c_3_24)))
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
 (not (and c_3_6 c_3_19)))
(assert
 (not (and c_3_6 c_3_20)))
(assert
 (not (and c_3_6 c_3_21)))
(assert
 (not (and c_3_6 c_3_22)))
(assert
 (not (and c_3_6 c_3_23)))
(assert
 (not (and c_3_6 c_3_24)))
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
 (not (and c_3_7 c_3_19)))
(assert
 (not (and c_3_7 c_3_20)))
(assert
 (not (and c_3_7 c_3_21)))
(assert
 (not (and c_3_7 c_3_22)))
(assert
 (not (and c_3_7 c_3_23)))
(assert
 (not (and c_3_7 c_3_24)))
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
 (not (and c_3_8 c_3_19)))
(assert
 (not (and c_3_8 c_3_20)))
(assert
 (not (and c_3_8 c_3_21)))
(assert
 (not (and c_3_8 c_3_22)))
(assert
 (not (and c_3_8 c_3_23)))
(assert
 (not (and c_3_8 c_3_24)))
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
 (not (and c_3_9 c_3_19)))
(assert
 (not (and c_3_9 c_3_20)))
(assert
 (not (and c_3_9 c_3_21)))
(assert
 (not (and c_3_9 c_3_22)))
(assert
 (not (and c_3_9 c_3_23)))
(assert
 (not (and c_3_9 c_3_24)))
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
 (not (and c_3_10 c_3_19)))
(assert
 (not (and c_3_10 c_3_20)))
(assert
 (not (and c_3_10 c_3_21)))
(assert
 (not (and c_3_10 c_3_22)))
(assert
 (not (and c_3_10 c_3_23)))
(assert
 (not (and c_3_10 c_3_24)))
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
 (not (and c_3_11 c_3_19)))
(assert
 (not (and c_3_11 c_3_20)))
(assert
 (not (and c_3_11 c_3_21)))
(assert
 (not (and c_3_11 c_3_22)))
(assert
 (not (and c_3_11 c_3_23)))
(assert
 (not (and c_3_11 c_3_24)))
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
 (not (and c_3_12 c_3_19)))
(assert
 (not (and c_3_12 c_3_20)))
(assert
 (not (and c_3_12 c_3_21)))
(assert
 (not (and c_3_12 c_3_22)))
(assert
 (not (and c_3_12 c_3_23)))
(assert
 (not (and c_3_12 c_3_24)))
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
 (not (and c_3_13 c_3_19)))
(assert
 (not (and c_3_13 c_3_20)))
(assert
 (not (and c_3_13 c_3_21)))
(assert
 (not (and c_3_13 c_3_22)))
(assert
 (not (and c_3_13 c_3_23)))
(assert
 (not (and c_3_13 c_3_24)))
(assert
 (not (and c_3_14 c_3_15)))
(assert
 (not (and c_3_14 c_3_16)))
(assert
 (not (and c_3_14 c_3_17)))
(assert
 (not (and c_3_14 c_3_18)))
(assert
 (not (and c_3_14 c_3_19)))
(assert
 (not (and c_3_14 c_3_20)))
(assert
 (not (and c_3_14 c_3_21)))
(assert
 (not (and c_3_14 c_3_22)))
(assert
 (not (and c_3_14 c_3_23)))
(assert
 (not (and c_3_14 c_3_24)))
(assert
 (not (and c_3_15 c_3_16)))
(assert
 (not (and c_3_15 c_3_17)))
(assert
 (not (and c_3_15 c_3_18)))
(assert
 (not (and c_3_15 c_3_19)))
(assert
 (not (and c_3_15 c_3_20)))
(assert
 (not (and c_3_15 c_3_21)))
(assert
 (not (and c_3_15 c_3_22)))
(assert
 (not (and c_3_15 c_3_23)))
(assert
 (not (and c_3_15 c_3_24)))
(assert
 (not (and c_3_16 c_3_17)))
(assert
 (not (and c_3_16 c_3_18)))
(assert
 (not (and c_3_16 c_3_19)))
(assert
 (not (and c_3_16 c_3_20)))
(assert
 (not (and c_3_16 c_3_21)))
(assert
 (not (and c_3_16 c_3_22)))
(assert
 (not (and c_3_16 c_3_23)))
(assert
 (not (and c_3_16 c_3_24)))
(assert
 (not (and c_3_17 c_3_18)))
(assert
 (not (and c_3_17 c_3_19)))
(assert
 (not (and c_3_17 c_3_20)))
(assert
 (not (and c_3_17 c_3_21)))
(assert
 (not (and c_3_17 c_3_22)))
(assert
 (not (and c_3_17 c_3_23)))
(assert
 (not (and c_3_17 c_3_24)))
(assert
 (not (and c_3_18 c_3_19)))
(assert
 (not (and c_3_18 c_3_20)))
(assert
 (not (and c_3_18 c_3_21)))
(assert
 (not (and c_3_18 c_3_22)))
(assert
 (not (and c_3_18 c_3_23)))
(assert
 (not (and c_3_18 c_3_24)))
(assert
 (not (and c_3_19 c_3_20)))
(assert
 (not (and c_3_19 c_3_21)))
(assert
 (not (and c_3_19 c_3_22)))
(assert
 (not (and c_3_19 c_3_23)))
(assert
 (not (and c_3_19 c_3_24)))
(assert
 (not (and c_3_20 c_3_21)))
(assert
 (not (and c_3_20 c_3_22)))
(assert
 (not (and c_3_20 c_3_23)))
(assert
 (not (and c_3_20 c_3_24)))
(assert
 (not (and c_3_21 c_3_22)))
(assert
 (not (and c_3_21 c_3_23)))
(assert
 (not (and c_3_21 c_3_24)))
(assert
 (not (and c_3_22 c_3_23)))
(assert
 (not (and c_3_22 c_3_24)))
(assert
 (not (and c_3_23 c_3_24)))
(assert
 (let (($x2638 (or false d_0_0)))
 (let (($x2640 (or $x2638 d_0_1)))
 (let (($x2642 (or $x2640 d_0_2)))
 (let (($x2644 (or $x2642 d_0_3)))
 (let (($x2646 (or $x2644 d_0_4)))
 (let (($x2648 (or $x2646 d_0_5)))
 (let (($x2650 (or $x2648 d_0_6)))
 (let (($x2652 (or $x2650 d_0_7)))
 (let (($x2654 (or $x2652 d_0_8)))
 (let (($x2656 (or $x2654 d_0_9)))
 (let (($x2658 (or $x2656 d_0_10)))
 (let (($x2660 (or $x2658 d_0_11)))
 (let (($x2662 (or $x2660 d_0_12)))
 (let (($x2664 (or $x2662 d_0_13)))
 (let (($x2666 (or $x2664 d_0_14)))
 (let (($x2668 (or $x2666 d_0_15)))
 (let (($x2670 (or $x2668 d_0_16)))
 (let (($x2672 (or $x2670 d_0_17)))
 (let (($x2674 (or $x2672 d_0_18)))
 (let (($x2676 (or $x2674 d_0_19)))
 (let (($x2678 (or $x2676 d_0_20)))
 (let (($x2680 (or $x2678 d_0_21)))
 (let (($x2682 (or $x2680 d_0_22)))
 (let (($x2684 (or $x2682 d_0_23)))
 (or $x2684 d_0_24))))))))))))))))))))))))))
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
 (not (and d_0_0 d_0_7)))
(assert
 (not (and d_0_0 d_0_8)))
(assert
 (not (and d_0_0 d_0_9)))
(assert
 (not (and d_0_0 d_0_10)))
(assert
 (not (and d_0_0 d_0_11)))
(assert
 (not (and d_0_0 d_0_12)))
(assert
 (not (and d_0_0 d_0_13)))
(assert
 (not (and d_0_0 d_0_14)))
(assert
 (not (and d_0_0 d_0_15)))
(assert
 (not (and d_0_0 d_0_16)))
(assert
 (not (and d_0_0 d_0_17)))
(assert
 (not (and d_0_0 d_0_18)))
(assert
 (not (and d_0_0 d_0_19)))
(assert
 (not (and d_0_0 d_0_20)))
(assert
 (not (and d_0_0 d_0_21)))
(assert
 (not (and d_0_0 d_0_22)))
(assert
 (not (and d_0_0 d_0_23)))
(assert
 (not (and d_0_0 d_0_24)))
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
 (not (and d_0_1 d_0_7)))
(assert
 (not (and d_0_1 d_0_8)))
(assert
 (not (and d_0_1 d_0_9)))
(assert
 (not (and d_0_1 d_0_10)))
(assert
 (not (and d_0_1 d_0_11)))
(assert
 (not (and d_0_1 d_0_12)))
(assert
 (not (and d_0_1 d_0_13)))
(assert
 (not (and d_0_1 d_0_14)))
(assert
 (not (and d_0_1 d_0_15)))
(assert
 (not (and d_0_1 d_0_16)))
(assert
 (not (and d_0_1 d_0_17)))
(assert
 (not (and d_0_1 d_0_18)))
(assert
 (not (and d_0_1 d_0_19)))
(assert
 (not (and d_0_1 d_0_20)))
(assert
 (not (and d_0_1 d_0_21)))
(assert
 (not (and d_0_1 d_0_22)))
(assert
 (not (and d_0_1 d_0_23)))
(assert
 (not (and d_0_1 d_0_24)))
(assert
 (not (and d_0_2 d_0_3)))
(assert
 (not (and d_0_2 d_0_4)))
(assert
 (not (and d_0_2 d_0_5)))
(assert
 (not (and d_0_2 d_0_6)))
(assert
 (not (and d_0_2 d_0_7)))
(assert
 (not (and d_0_2 d_0_8)))
(assert
 (not (and d_0_2 d_0_9)))
(assert
 (not (and d_0_2 d_0_10)))
(assert
 (not (and d_0_2 d_0_11)))
(assert
 (not (and d_0_2 d_0_12)))
(assert
 (not (and d_0_2 d_0_13)))
(assert
 (not (and d_0_2 d_0_14)))
(assert
 (not (and d_0_2 d_0_15)))
(assert
 (not (and d_0_2 d_0_16)))
(assert
 (not (and d_0_2 d_0_17)))
(assert
 (not (and d_0_2 d_0_18)))
(assert
 (not (and d_0_2 d_0_19)))
(assert
 (not (and d_0_2 d_0_20)))
(assert
 (not (and d_0_2 d_0_21)))
(assert
 (not (and d_0_2 d_0_22)))
(assert
 (not (and d_0_2 d_0_23)))
(assert
 (not (and d_0_2 d_0_24)))
(assert
 (not (and d_0_3 d_0_4)))
(assert
 (not (and d_0_3 d_0_5)))
(assert
 (not (and d_0_3 d_0_6)))
(assert
 (not (and d_0_3 d_0_7)))
(assert
 (not (and d_0_3 d_0_8)))
(assert
 (not (and d_0_3 d_0_9)))
(assert
 (not (and d_0_3 d_0_10)))
(assert
 (not (and d_0_3 d_0_11)))
(assert
 (not (and d_0_3 d_0_12)))
(assert
 (not (and d_0_3 d_0_13)))
(assert
 (not (and d_0_3 d_0_14)))
(assert
 (not (and d_0_3 d_0_15)))
(assert
 (not (and d_0_3 d_0_16)))
(assert
 (not (and d_0_3 d_0_17)))
(assert
 (not (and d_0_3 d_0_18)))
(assert
 (not (and d_0_3 d_0_19)))
(assert
 (not (and d_0_3 d_0_20)))
(assert
 (not (and d_0_3 d_0_21)))
(assert
 (not (and d_0_3 d_0_22)))
(assert
 (not (and d_0_3 d_0_23)))
(assert
 (not (and d_0_3 d_0_24)))
(assert
 (not (and d_0_4 d_0_5)))
(assert
 (not (and d_0_4 d_0_6)))
(assert
 (not (and d_0_4 d_0_7)))
(assert
 (not (and d_0_4 d_0_8)))
(assert
 (not (and d_0_4 d_0_9)))
(assert
 (not (and d_0_4 d_0_10)))
(assert
 (not (and d_0_4 d_0_11)))
(assert
 (not (and d_0_4 d_0_12)))
(assert
 (not (and d_0_4 d_0_13)))
(assert
 (not (and d_0_4 d_0_14)))
(assert
 (not (and d_0_4 d_0_15)))
(assert
 (not (and d_0_4 d_0_16)))
(assert
 (not (and d_0_4 d_0_17)))
(assert
 (not (and d_0_4 d_0_18)))
(assert
 (not (and d_0_4 d_0_19)))
(assert
 (not (and d_0_4 d_0_20)))
(assert
 (not (and d_0_4 d_0_21)))
(assert
 (not (and d_0_4 d_0_22)))
(assert
 (not (and d_0_4 d_0_23)))
(assert
 (not (and d_0_4 d_0_24)))
(assert
 (not (and d_0_5 d_0_6)))
(assert
 (not (and d_0_5 d_0_7)))
(assert
 (not (and d_0_5 d_0_8)))
(assert
 (not (and d_0_5 d_0_9)))
(assert
 (not (and d_0_5 d_0_10)))
(assert
 (not (and d_0_5 d_0_11)))
(assert
 (not (and d_0_5 d_0_12)))
(assert
 (not (and d_0_5 d_0_13)))
(assert
 (not (and d_0_5 d_0_14)))
(assert
 (not (and d_0_5 d_0_15)))
(assert
 (not (and d_0_5 d_0_16)))
(assert
 (not (and d_0_5 d_0_17)))
(assert
 (not (and d_0_5 d_0_18)))
(assert
 (not (and d_0_5 d_0_19)))
(assert
 (not (and d_0_5 d_0_20)))
(assert
 (not (and d_0_5 d_0_21)))
(assert
 (not (and d_0_5 d_0_22)))
(assert
 (not (and d_0_5 d_0_23)))
(assert
 (not (and d_0_5 d_0_24)))
(assert
 (not (and d_0_6 d_0_7)))
(assert
 (not (and d_0_6 d_0_8)))
(assert
 (not (and d_0_6 d_0_9)))
(assert
 (not (and d_0_6 d_0_10)))
(assert
 (not (and d_0_6 d_0_11)))
(assert
 (not (and d_0_6 d_0_12)))
(assert
 (not (and d_0_6 d_0_13)))
(assert
 (not (and d_0_6 d_0_14)))
(assert
 (not (and d_0_6 d_0_15)))
(assert
 (not (and d_0_6 d_0_16)))
(assert
 (not (and d_0_6 d_0_17)))
(assert
 (not (and d_0_6 d_0_18)))
(assert
 (not (and d_0_6 d_0_19)))
(assert
 (not (and d_0_6 d_0_20)))
(assert
 (not (and d_0_6 d_0_21)))
(assert
 (not (and d_0_6 d_0_22)))
(assert
 (not (and d_0_6 d_0_23)))
(assert
 (not (and d_0_6 d_0_24)))
(assert
 (not (and d_0_7 d_0_8)))
(assert
 (not (and d_0_7 d_0_9)))
(assert
 (not (and d_0_7 d_0_10)))
(assert
 (not (and d_0_7 d_0_11)))
(assert
 (not (and d_0_7 d_0_12)))
(assert
 (not (and d_0_7 d_0_13)))
(assert
 (not (and d_0_7 d_0_14)))
(assert
 (not (and d_0_7 d_0_15)))
(assert
 (not (and d_0_7 d_0_16)))
(assert
 (not (and d_0_7 d_0_17)))
(assert
 (not (and d_0_7 d_0_18)))
(assert
 (not (and d_0_7 d_0_19)))
(assert
 (not (and d_0_7 d_0_20)))
(assert
 (not (and d_0_7 d_0_21)))
(assert
 (not (and d_0_7 d_0_22)))
(assert
 (not (and d_0_7 d_0_23)))
(assert
 (not (and d_0_7 d_0_24)))
(assert
 (not (and d_0_8 d_0_9)))
(assert
 (not (and d_0_8 d_0_10)))
(assert
 (not (and d_0_8 d_0_11)))
(assert
 (not (and d_0_8 d_0_12)))
(assert
 (not (and d_0_8 d_0_13)))
(assert
 (not (and d_0_8 d_0_14)))
(assert
 (not (and d_0_8 d_0_15)))
(assert
 (not (and d_0_8 d_0_16)))
(assert
 (not (and d_0_8 d_0_17)))
(assert
 (not (and d_0_8 d_0_18)))
(assert
 (not (and d_0_8 d_0_19)))
(assert
 (not (and d_0_8 d_0_20)))
(assert
 (not (and d_0_8 d_0_21)))
(assert
 (not (and d_0_8 d_0_22)))
(assert
 (not (and d_0_8 d_0_23)))
(assert
 (not (and d_0_8 d_0_24)))
(assert
 (not (and d_0_9 d_0_10)))
(assert
 (not (and d_0_9 d_0_11)))
(assert
 (not (and d_0_9 d_0_12)))
(assert
 (not (and d_0_9 d_0_13)))
(assert
 (not (and d_0_9 d_0_14)))
(assert
 (not (and d_0_9 d_0_15)))
(assert
 (not (and d_0_9 d_0_16)))
(assert
 (not (and d_0_9 d_0_17)))
(assert
 (not (and d_0_9 d_0_18)))
(assert
 (not (and d_0_9 d_0_19)))
(assert
 (not (and d_0_9 d_0_20)))
(assert
 (not (and d_0_9 d_0_21)))
(assert
 (not (and d_0_9 d_0_22)))
(assert
 (not (and d_0_9 d_0_23)))
(assert
 (not (and d_0_9 d_0_24)))
(assert
 (not (and d_0_10 d_0_11)))
(assert
 (not (and d_0_10 d_0_12)))
(assert
 (not (and d_0_10 d_0_13)))
(assert
 (not (and d_0_10 d_0_14)))
(assert
 (not (and d_0_10 d_0_15)))
(assert
 (not (and d_0_10 d_0_16)))
(assert
 (not (and d_0_10 d_0_17)))
(assert
 (not (and d_0_10 d_0_18)))
(assert
 (not (and d_0_10 d_0_19)))
(assert
 (not (and d_0_10 d_0_20)))
(assert
 (not (and d_0_10 d_0_21)))
(assert
 (not (and d_0_10 d_0_22)))
(assert
 (not (and d_0_10 d_0_23)))
(assert
 (not (and d_0_10 d_0_24)))
(assert
 (not (and d_0_11 d_0_12)))
(assert
 (not (and d_0_11 d_0_13)))
(assert
 (not (and d_0_11 d_0_14)))
(assert
 (not (and d_0_11 d_0_15)))
(assert
 (not (and d_0_11 d_0_16)))
(assert
 (not (and d_0_11 d_0_17)))
(assert
 (not (and d_0_11 d_0_18)))
(assert
 (not (and d_0_11 d_0_19)))
(assert
 (not (and d_0_11 d_0_20)))
(assert
 (not (and d_0_11 d_0_21)))
(assert
 (not (and d_0_11 d_0_22)))
(assert
 (not (and d_0_11 d_0_23)))
(assert
 (not (and d_0_11 d_0_24)))
(assert
 (not (and d_0_12 d_0_13)))
(assert
 (not (and d_0_12 d_0_14)))
(assert
 (not (and d_0_12 d_0_15)))
(assert
 (not (and d_0_12 d_0_16)))
(assert
 (not (and d_0_12 d_0_17)))
(assert
 (not (and d_0_12 d_0_18)))
(assert
 (not (and d_0_12 d_0_19)))
(assert
 (not (and d_0_12 d_0_20)))
(assert
 (not (and d_0_12 d_0_21)))
(assert
 (not (and d_0_12 d_0_22)))
(assert
 (not (and d_0_12 d_0_23)))
(assert
 (not (and d_0_12 d_0_24)))
(assert
 (not (and d_0_13 d_0_14)))
(assert
 (not (and d_0_13 d_0_15)))
(assert
 (not (and d_0_13 d_0_16)))
(assert
 (not (and d_0_13 d_0_17)))
(assert
 (not (and d_0_13 d_0_18)))
(assert
 (not (and d_0_13 d_0_19)))
(assert
 (not (and d_0_13 d_0_20)))
(assert
 (not (and d_0_13 d_0_21)))
(assert
 (not (and d_0_13 d_0_22)))
(assert
 (not (and d_0_13 d_0_23)))
(assert
 (not (and d_0_13 d_0_24)))
(assert
 (not (and d_0_14 d_0_15)))
(assert
 (not (and d_0_14 d_0_16)))
(assert
 (not (and d_0_14 d_0_17)))
(assert
 (not (and d_0_14 d_0_18)))
(assert
 (not (and d_0_14 d_0_19)))
(assert
 (not (and d_0_14 d_0_20)))
(assert
 (not (and d_0_14 d_0_21)))
(assert
 (not (and d_0_14 d_0_22)))
(assert
 (not (and d_0_14 d_0_23)))
(assert
 (not (and d_0_14 d_0_24)))
(assert
 (not (and d_0_15 d_0_16)))
(assert
 (not (and d_0_15 d_0_17)))
(assert
 (not (and d_0_15 d_0_18)))
(assert
 (not (and d_0_15 d_0_19)))
(assert
 (not (and d_0_15 d_0_20)))
(assert
 (not (and d_0_15 d_0_21)))
(assert
 (not (and d_0_15 d_0_22)))
(assert
 (not (and d_0_15 d_0_23)))
(assert
 (not (and d_0_15 d_0_24)))
(assert
 (not (and d_0_16 d_0_17)))
(assert
 (not (and d_0_16 d_0_18)))
(assert
 (not (and d_0_16 d_0_19)))
(assert
 (not (and d_0_16 d_0_20)))
(assert
 (not (and d_0_16 d_0_21)))
(assert
 (not (and d_0_16 d_0_22)))
(assert
 (not (and d_0_16 d_0_23)))
(assert
 (not (and d_0_16 d_0_24)))
(assert
 (not (and d_0_17 d_0_18)))
(assert
 (not (and d_0_17 d_0_19)))
(assert
 (not (and d_0_17 d_0_20)))
(assert
 (not (and d_0_17 d_0_21)))
(assert
 (not (and d_0_17 d_0_22)))
(assert
 (not (and d_0_17 d_0_23)))
(assert
 (not (and d_0_17 d_0_24)))
(assert
 (not (and d_0_18 d_0_19)))
(assert
 (not (and d_0_18 d_0_20)))
(assert
 (not (and d_0_18 d_0_21)))
(assert
 (not (and d_0_18 d_0_22)))
(assert
 (not (and d_0_18 d_0_23)))
(assert
 (not (and d_0_18 d_0_24)))
(assert
 (not (and d_0_19 d_0_20)))
(assert
 (not (and d_0_19 d_0_21)))
(assert
 (not (and d_0_19 d_0_22)))
(assert
 (not (and d_0_19 d_0_23)))
(assert
 (not (and d_0_19 d_0_24)))
(assert
 (not (and d_0_20 d_0_21)))
(assert
 (not (and d_0_20 d_0_22)))
(assert
 (not (and d_0_20 d_0_23)))
(assert
 (not (and d_0_20 d_0_24)))
(assert
 (not (and d_0_21 d_0_22)))
(assert
 (not (and d_0_21 d_0_23)))
(assert
 (not (and d_0_21 d_0_24)))
(assert
 (not (and d_0_22 d_0_23)))
(assert
 (not (and d_0_22 d_0_24)))
(assert
 (not (and d_0_23 d_0_24)))
(assert
 (let (($x3288 (or false d_1_0)))
 (let (($x3290 (or $x3288 d_1_1)))
 (let (($x3292 (or $x3290 d_1_2)))
 (let (($x3294 (or $x3292 d_1_3)))
 (let (($x3296 (or $x3294 d_1_4)))
 (let (($x3298 (or $x3296 d_1_5)))
 (let (($x3300 (or $x3298 d_1_6)))
 (let (($x3302 (or $x3300 d_1_7)))
 (let (($x3304 (or $x3302 d_1_8)))
 (let (($x3306 (or $x3304 d_1_9)))
 (let (($x3308 (or $x3306 d_1_10)))
 (let (($x3310 (or $x3308 d_1_11)))
 (let (($x3312 (or $x3310 d_1_12)))
 (let (($x3314 (or $x3312 d_1_13)))
 (let (($x3316 (or $x3314 d_1_14)))
 (let (($x3318 (or $x3316 d_1_15)))
 (let (($x3320 (or $x3318 d_1_16)))
 (let (($x3322 (or $x3320 d_1_17)))
 (let (($x3324 (or $x3322 d_1_18)))
 (let (($x3326 (or $x3324 d_1_19)))
 (let (($x3328 (or $x3326 d_1_20)))
 (let (($x3330 (or $x3328 d_1_21)))
 (let (($x3332 (or $x3330 d_1_22)))
 (let (($x3334 (or $x3332 d_1_23)))
 (or $x3334 d_1_24))))))))))))))))))))))))))
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
 (not (and d_1_0 d_1_7)))
(assert
 (not (and d_1_0 d_1_8)))
(assert
 (not (and d_1_0 d_1_9)))
(assert
 (not (and d_1_0 d_1_10)))
(assert
 (not (and d_1_0 d_1_11)))
(assert
 (not (and d_1_0 d_1_12)))
(assert
 (not (and d_1_0 d_1_13)))
(assert
 (not (and d_1_0 d_1_14)))
(assert
 (not (and d_1_0 d_1_15)))
(assert
 (not (and d_1_0 d_1_16)))
(assert
 (not (and d_1_0 d_1_17)))
(assert
 (not (and d_1_0 d_1_18)))
(assert
 (not (and d_1_0 d_1_19)))
(assert
 (not (and d_1_0 d_1_20)))
(assert
 (not (and d_1_0 d_1_21)))
(assert
 (not (and d_1_0 d_1_22)))
(assert
 (not (and d_1_0 d_1_23)))
(assert
 (not (and d_1_0 d_1_24)))
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
 (not (and d_1_1 d_1_7)))
(assert
 (not (and d_1_1 d_1_8)))
(assert
 (not (and d_1_1 d_1_9)))
(assert
 (not (and d_1_1 d_1_10)))
(assert
 (not (and d_1_1 d_1_11)))
(assert
 (not (and d_1_1 d_1_12)))
(assert
 (not (and d_1_1 d_1_13)))
(assert
 (not (and d_1_1 d_1_14)))
(assert
 (not (and d_1_1 d_1_15)))
(assert
 (not (and d_1_1 d_1_16)))
(assert
 (not (and d_1_1 d_1_17)))
(assert
 (not (and d_1_1 d_1_18)))
(assert
 (not (and d_1_1 d_1_19)))
(assert
 (not (and d_1_1 d_1_20)))
(assert
 (not (and d_1_1 d_1_21)))
(assert
 (not (and d_1_1 d_1_22)))
(assert
 (not (and d_1_1 d_1_23)))
(assert
 (not (and d_1_1 d_1_24)))
(assert
 (not (and d_1_2 d_1_3)))
(assert
 (not (and d_1_2 d_1_4)))
(assert
 (not (and d_1_2 d_1_5)))
(assert
 (not (and d_1_2 d_1_6)))
(assert
 (not (and d_1_2 d_1_7)))
(assert
 (not (and d_1_2 d_1_8)))
(assert
 (not (and d_1_2 d_1_9)))
(assert
 (not (and d_1_2 d_1_10)))
(assert
 (not (and d_1_2 d_1_11)))
(assert
 (not (and d_1_2 d_1_12)))
(assert
 (not (and d_1_2 d_1_13)))
(assert
 (not (and d_1_2 d_1_14)))
(assert
 (not (and d_1_2 d_1_15)))
(assert
 (not (and d_1_2 d_1_16)))
(assert
 (not (and d_1_2 d_1_17)))
(assert
 (not (and d_1_2 d_1_18)))
(assert
 (not (and d_1_2 d_1_19)))
(assert
 (not (and d_1_2 d_1_20)))
(assert
 (not (and d_1_2 d_1_21)))
(assert
 (not (and d_1_2 d_1_22)))
(assert
 (not (and d_1_2 d_1_23)))
(assert
 (not (and d_1_2 d_1_24)))
(assert
 (not (and d_1_3 d_1_4)))
(assert
 (not (and d_1_3 d_1_5)))
(assert
 (not (and d_1_3 d_1_6)))
(assert
 (not (and d_1_3 d_1_7)))
(assert
 (not (and d_1_3 d_1_8)))
(assert
 (not (and d_1_3 d_1_9)))
(assert
 (not (and d_1_3 d_1_10)))
(assert
 (not (and d_1_3 d_1_11)))
(assert
 (not (and d_1_3 d_1_12)))
(assert
 (not (and d_1_3 d_1_13)))
(assert
 (not (and d_1_3 d_1_14)))
(assert
 (not (and d_1_3 d_1_15)))
(assert
 (not (and d_1_3 d_1_16)))
(assert
 (not (and d_1_3 d_1_17)))
(assert
 (not (and d_1_3 d_1_18)))
(assert
 (not (and d_1_3 d_1_19)))
(assert
 (not (and d_1_3 d_1_20)))
(assert
 (not (and d_1_3 d_1_21)))
(assert
 (not (and d_1_3 d_1_22)))
(assert
 (not (and d_1_3 d_1_23)))
(assert
 (not (and d_1_3 d_1_24)))
(assert
 (not (and d_1_4 d_1_5)))
(assert
 (not (and d_1_4 d_1_6)))
(assert
 (not (and d_1_4 d_1_7)))
(assert
 (not (and d_1_4 d_1_8)))
(assert
 (not (and d_1_4 d_1_9)))
(assert
 (not (and d_1_4 d_1_10)))
(assert
 (not (and d_1_4 d_1_11)))
(assert
 (not (and d_1_4 d_1_12)))
(assert
 (not (and d_1_4 d_1_13)))
(assert
 (not (and d_1_4 d_1_14)))
(assert
 (not (and d_1_4 d_1_15)))
(assert
 (not (and d_1_4 d_1_16)))
(assert
 (not (and d_1_4 d_1_17)))
(assert
 (not (and d_1_4 d_1_18)))
(assert
 (not (and d_1_4 d_1_19)))
(assert
 (not (and d_1_4 d_1_20)))
(assert
 (not (and d_1_4 d_1_21)))
(assert
 (not (and d_1_4 d_1_22)))
(assert
 (not (and d_1_4 d_1_23)))
(assert
 (not (and d_1_4 d_1_24)))
(assert
 (not (and d_1_5 d_1_6)))
(assert
 (not (and d_1_5 d_1_7)))
(assert
 (not (and d_1_5 d_1_8)))
(assert
 (not (and d_1_5 d_1_9)))
(assert
 (not (and d_1_5 d_1_10)))
(assert
 (not (and d_1_5 d_1_11)))
(assert
 (not (and d_1_5 d_1_12)))
(assert
 (not (and d_1_5 d_1_13)))
(assert
 (not (and d_1_5 d_1_14)))
(assert
 (not (and d_1_5 d_1_15)))
(assert
 (not (and d_1_5 d_1_16)))
(assert
 (not (and d_1_5 d_1_17)))
(assert
 (not (and d_1_5 d_1_18)))
(assert
 (not (and d_1_5 d_1_19)))
(assert
 (not (and d_1_5 d_1_20)))
(assert
 (not (and d_1_5 d_1_21)))
(assert
 (not (and d_1_5 d_1_22)))
(assert
 (not (and d_1_5 d_1_23)))
(assert
 (not (and d_1_5 d_1_24)))
(assert
 (not (and d_1_6 d_1_7)))
(assert
 (not (and d_1_6 d_1_8)))
(assert
 (not (and d_1_6 d_1_9)))
(assert
 (not (and d_1_6 d_1_10)))
(assert
 (not (and d_1_6 d_1_11)))
(assert
 (not (and d_1_6 d_1_12)))
(assert
 (not (and d_1_6 d_1_13)))
(assert
 (not (and d_1_6 d_1_14)))
(assert
 (not (and d_1_6 d_1_15)))
(assert
 (not (and d_1_6 d_1_16)))
(assert
 (not (and d_1_6 d_1_17)))
(assert
 (not (and d_1_6 d_1_18)))
(assert
 (not (and d_1_6 d_1_19)))
(assert
 (not (and d_1_6 d_1_20)))
(assert
 (not (and d_1_6 d_1_21)))
(assert
 (not (and d_1_6 d_1_22)))
(assert
 (not (and d_1_6 d_1_23)))
(assert
 (not (and d_1_6 d_1_24)))
(assert
 (not (and d_1_7 d_1_8)))
(assert
 (not (and d_1_7 d_1_9)))
(assert
 (not (and d_1_7 d_1_10)))
(assert
 (not (and d_1_7 d_1_11)))
(assert
 (not (and d_1_7 d_1_12)))
(assert
 (not (and d_1_7 d_1_13)))
(assert
 (not (and d_1_7 d_1_14)))
(assert
 (not (and d_1_7 d_1_15)))
(assert
 (not (and d_1_7 d_1_16)))
(assert
 (not (and d_1_7 d_1_17)))
(assert
 (not (and d_1_7 d_1_18)))
(assert
 (not (and d_1_7 d_1_19)))
(assert
 (not (and d_1_7 d_1_20)))
(assert
 (not (and d_1_7 d_1_21)))
(assert
 (not (and d_1_7 d_1_22)))
(assert
 (not (and d_1_7 d_1_23)))
(assert
 (not (and d_1_7 d_1_24)))
(assert
 (not (and d_1_8 d_1_9)))
(assert
 (not (and d_1_8 d_1_10)))
(assert
 (not (and d_1_8 d_1_11)))
(assert
 (not (and d_1_8 d_1_12)))
(assert
 (not (and d_1_8 d_1_13)))
(assert
 (not (and d_1_8 d_1_14)))
(assert
 (not (and d_1_8 d_1_15)))
(assert
 (not (and d_1_8 d_1_16)))
(assert
 (not (and d_1_8 d_1_17)))
(assert
 (not (and d_1_8 d_1_18)))
(assert
 (not (and d_1_8 d_1_19)))
(assert
 (not (and d_1_8 d_1_20)))
(assert
 (not (and d_1_8 d_1_21)))
(assert
 (not (and d_1_8 d_1_22)))
(assert
 (not (and d_1_8 d_1_23)))
(assert
 (not (and d_1_8 d_1_24)))
(assert
 (not (and d_1_9 d_1_10)))
(assert
 (not (and d_1_9 d_1_11)))
(assert
 (not (and d_1_9 d_1_12)))
(assert
 (not (and d_1_9 d_1_13)))
(assert
 (not (and d_1_9 d_1_14)))
(assert
 (not (and d_1_9 d_1_15)))
(assert
 (not (and d_1_9 d_1_16)))
(assert
 (not (and d_1_9 d_1_17)))
(assert
 (not (and d_1_9 d_1_18)))
(assert
 (not (and d_1_9 d_1_19)))
(assert
 (not (and d_1_9 d_1_20)))
(assert
 (not (and d_1_9 d_1_21)))
(assert
 (not (and d_1_9 d_1_22)))
(assert
 (not (and d_1_9 d_1_23)))
(assert
 (not (and d_1_9 d_1_24)))
(assert
 (not (and d_1_10 d_1_11)))
(assert
 (not (and d_1_10 d_1_12)))
(assert
 (not (and d_1_10 d_1_13)))
(assert
 (not (and d_1_10 d_1_14)))
(assert
 (not (and d_1_10 d_1_15)))
(assert
 (not (and d_1_10 d_1_16)))
(assert
 (not (and d_1_10 d_1_17)))
(assert
 (not (and d_1_10 d_1_18)))
(assert
 (not (and d_1_10 d_1_19)))
(assert
 (not (and d_1_10 d_1_20)))
(assert
 (not (and d_1_10 d_1_21)))
(assert
 (not (and d_1_10 d_1_22)))
(assert
 (not (and d_1_10 d_1_23)))
(assert
 (not (and d_1_10 d_1_24)))
(assert
 (not (and d_1_11 d_1_12)))
(assert
 (not (and d_1_11 d_1_13)))
(assert
 (not (and d_1_11 d_1_14)))
(assert
 (not (and d_1_11 d_1_15)))
(assert
 (not (and d_1_11 d_1_16)))
(assert
 (not (and d_1_11 d_1_17)))
(assert
 (not (and d_1_11 d_1_18)))
(assert
 (not (and d_1_11 d_1_19)))
(assert
 (not (and d_1_11 d_1_20)))
(assert
 (not (and d_1_11 d_1_21)))
(assert
 (not (and d_1_11 d_1_22)))
(assert
 (not (and d_1_11 d_1_23)))
(assert
 (not (and d_1_11 d_1_24)))
(assert
 (not (and d_1_12 d_1_13)))
(assert
 (not (and d_1_12 d_1_14)))
(assert
 (not (and d_1_12 d_1_15)))
(assert
 (not (and d_1_12 d_1_16)))
(assert
 (not (and d_1_12 d_1_17)))
(assert
 (not (and d_1_12 d_1_18)))
(assert
 (not (and d_1_12 d_1_19)))
(assert
 (not (and d_1_12 d_1_20)))
(assert
 (not (and d_1_12 d_1_21)))
(assert
 (not (and d_1_12 d_1_22)))
(assert
 (not (and d_1_12 d_1_23)))
(assert
 (not (and d_1_12 d_1_24)))
(assert
 (not (and d_1_13 d_1_14)))
(assert
 (not (and d_1_13 d_1_15)))
(assert
 (not (and d_1_13 d_1_16)))
(assert
 (not (and d_1_13 d_1_17)))
(assert
 (not (and d_1_13 d_1_18)))
(assert
 (not (and d_1_13 d_1_19)))
(assert
 (not (and d_1_13 d_1_20)))
(assert
 (not (and d_1_13 d_1_21)))
(assert
 (not (and d_1_13 d_1_22)))
(assert
 (not (and d_1_13 d_1_23)))
(assert
 (not (and d_1_13 d_1_24)))
(assert
 (not (and d_1_14 d_1_15)))
(assert
 (not (and d_1_14 d_1_16)))
(assert
 (not (and d_1_14 d_1_17)))
(assert
 (not (and d_1_14 d_1_18)))
(assert
 (not (and d_1_14 d_1_19)))
(assert
 (not (and d_1_14 d_1_20)))
(assert
 (not (and d_1_14 d_1_21)))
(assert
 (not (and d_1_14 d_1_22)))
(assert
 (not (and d_1_14 d_1_23)))
(assert
 (not (and d_1_14 d_1_24)))
(assert
 (not (and d_1_15 d_1_16)))
(assert
 (not (and d_1_15 d_1_17)))
(assert
 (not (and d_1_15 d_1_18)))
(assert
 (not (and d_1_15 d_1_19)))
(assert
 (not (and d_1_15 d_1_20)))
(assert
 (not (and d_1_15 d_1_21)))
(assert
 (not (and d_1_15 d_1_22)))
(assert
 (not (and d_1_15 d_1_23)))
(assert
 (not (and d_1_15 d_1_24)))
(assert
 (not (and d_1_16 d_1_17)))
(assert
 (not (and d_1_16 d_1_18)))
(assert
 (not (and d_1_16 d_1_19)))
(assert
 (not (and d_1_16 d_1_20)))
(assert
 (not (and d_1_16 d_1_21)))
(assert
 (not (and d_1_16 d_1_22)))
(assert
 (not (and d_1_16 d_1_23)))
(assert
 (not (and d_1_16 d_1_24)))
(assert
 (not (and d_1_17 d_1_18)))
(assert
 (not (and d_1_17 d_1_19)))
(assert
 (not (and d_1_17 d_1_20)))
(assert
 (not (and d_1_17 d_1_21)))
(assert
 (not (and d_1_17 d_1_22)))
(assert
 (not (and d_1_17 d_1_23)))
(assert
 (not (and d_1_17 d_1_24)))
(assert
 (not (and d_1_18 d_1_19)))
(assert
 (not (and d_1_18 d_1_20)))
(assert
 (not (and d_1_18 d_1_21)))
(assert
 (not (and d_1_18 d_1_22)))
(assert
 (not (and d_1_18 d_1_23)))
(assert
 (not (and d_1_18 d_1_24)))
(assert
 (not (and d_1_19 d_1_20)))
(assert
 (not (and d_1_19 d_1_21)))
(assert
 (not (and d_1_19 d_1_22)))
(assert
 (not (and d_1_19 d_1_23)))
(assert
 (not (and d_1_19 d_1_24)))
(assert
 (not (and d_1_20 d_1_21)))
(assert
 (not (and d_1_20 d_1_22)))
(assert
 (not (and d_1_20 d_1_23)))
(assert
 (not (and d_1_20 d_1_24)))
(assert
 (not (and d_1_21 d_1_22)))
(assert
 (not (and d_1_21 d_1_23)))
(assert
 (not (and d_1_21 d_1_24)))
(assert
 (not (and d_1_22 d_1_23)))
(assert
 (not (and d_1_22 d_1_24)))
(assert
 (not (and d_1_23 d_1_24)))
(assert
 (let (($x3938 (or false d_2_0)))
 (let (($x3940 (or $x3938 d_2_1)))
 (let (($x3942 (or $x3940 d_2_2)))
 (let (($x3944 (or $x3942 d_2_3)))
 (let (($x3946 (or $x3944 d_2_4)))
 (let (($x3948 (or $x3946 d_2_5)))
 (let (($x3950 (or $x3948 d_2_6)))
 (let (($x3952 (or $x3950 d_2_7)))
 (let (($x3954 (or $x3952 d_2_8)))
 (let (($x3956 (or $x3954 d_2_9)))
 (let (($x3958 (or $x3956 d_2_10)))
 (let (($x3960 (or $x3958 d_2_11)))
 (let (($x3962 (or $x3960 d_2_12)))
 (let (($x3964 (or $x3962 d_2_13)))
 (let (($x3966 (or $x3964 d_2_14)))
 (let (($x3968 (or $x3966 d_2_15)))
 (let (($x3970 (or $x3968 d_2_16)))
 (let (($x3972 (or $x3970 d_2_17)))
 (let (($x3974 (or $x3972 d_2_18)))
 (let (($x3976 (or $x3974 d_2_19)))
 (let (($x3978 (or $x3976 d_2_20)))
 (let (($x3980 (or $x3978 d_2_21)))
 (let (($x3982 (or $x3980 d_2_22)))
 (let (($x3984 (or $x3982 d_2_23)))
 (or $x3984 d_2_24))))))))))))))))))))))))))
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
 (not (and d_2_0 d_2_7)))
(assert
 (not (and d_2_0 d_2_8)))
(assert
 (not (and d_2_0 d_2_9)))
(assert
 (not (and d_2_0 d_2_10)))
(assert
 (not (and d_2_0 d_2_11)))
(assert
 (not (and d_2_0 d_2_12)))
(assert
 (not (and d_2_0 d_2_13)))
(assert
 (not (and d_2_0 d_2_14)))
(assert
 (not (and d_2_0 d_2_15)))
(assert
 (not (and d_2_0 d_2_16)))
(assert
 (not (and d_2_0 d_2_17)))
(assert
 (not (and d_2_0 d_2_18)))
(assert
 (not (and d_2_0 d_2_19)))
(assert
 (not (and d_2_0 d_2_20)))
(assert
 (not (and d_2_0 d_2_21)))
(assert
 (not (and d_2_0 d_2_22)))
(assert
 (not (and d_2_0 d_2_23)))
(assert
 (not (and d_2_0 d_2_24)))
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
 (not (and d_2_1 d_2_7)))
(assert
 (not (and d_2_1 d_2_8)))
(assert
 (not (and d_2_1 d_2_9)))
(assert
 (not (and d_2_1 d_2_10)))
(assert
 (not (and d_2_1 d_2_11)))
(assert
 (not (and d_2_1 d_2_12)))
(assert
 (not (and d_2_1 d_2_13)))
(assert
 (not (and d_2_1 d_2_14)))
(assert
 (not (and d_2_1 d_2_15)))
(assert
 (not (and d_2_1 d_2_16)))
(assert
 (not (and d_2_1 d_2_17)))
(assert
 (not (and d_2_1 d_2_18)))
(assert
 (not (and d_2_1 d_2_19)))
(assert
 (not (and d_2_1 d_2_20)))
(assert
 (not (and d_2_1 d_2_21)))
(assert
 (not (and d_2_1 d_2_22)))
(assert
 (not (and d_2_1 d_2_23)))
(assert
 (not (and d_2_1 d_2_24)))
(assert
 (not (and d_2_2 d_2_3)))
(assert
 (not (and d_2_2 d_2_4)))
(assert
 (not (and d_2_2 d_2_5)))
(assert
 (not (and d_2_2 d_2_6)))
(assert
 (not (and d_2_2 d_2_7)))
(assert
 (not (and d_2_2 d_2_8)))
(assert
 (not (and d_2_2 d_2_9)))
(assert
 (not (and d_2_2 d_2_10)))
(assert
 (not (and d_2_2 d_2_11)))
(assert
 (not (and d_2_2 d_2_12)))
(assert
 (not (and d_2_2 d_2_13)))
(assert
 (not (and d_2_2 d_2_14)))
(assert
 (not (and d_2_2 d_2_15)))
(assert
 (not (and d_2_2 d_2_16)))
(assert
 (not (and d_2_2 d_2_17)))
(assert
 (not (and d_2_2 d_2_18)))
(assert
 (not (and d_2_2 d_2_19)))
(assert
 (not (and d_2_2 d_2_20)))
(assert
 (not (and d_2_2 d_2_21)))
(assert
 (not (and d_2_2 d_2_22)))
(assert
 (not (and d_2_2 d_2_23)))
(assert
 (not (and d_2_2 d_2_24)))
(assert
 (not (and d_2_3 d_2_4)))
(assert
 (not (and d_2_3 d_2_5)))
(assert
 (not (and d_2_3 d_2_6)))
(assert
 (not (and d_2_3 d_2_7)))
(assert
 (not (and d_2_3 d_2_8)))
(assert
 (not (and d_2_3 d_2_9)))
(assert
 (not (and d_2_3 d_2_10)))
(assert
 (not (and d_2_3 d_2_11)))
(assert
 (not (and d_2_3 d_2_12)))
(assert
 (not (and d_2_3 d_2_13)))
(assert
 (not (and d_2_3 d_2_14)))
(assert
 (not (and d_2_3 d_2_15)))
(assert
 (not (and d_2_3 d_2_16)))
(assert
 (not (and d_2_3 d_2_17)))
(assert
 (not (and d_2_3 d_2_18)))
(assert
 (not (and d_2_3 d_2_19)))
(assert
 (not (and d_2_3 d_2_20)))
(assert
 (not (and d_2_3 d_2_21)))
(assert
 (not (and d_2_3 d_2_22)))
(assert
 (not (and d_2_3 d_2_23)))
(assert
 (not (and d_2_3 d_2_24)))
(assert
 (not (and d_2_4 d_2_5)))
(assert
 (not (and d_2_4 d_2_6)))
(assert
 (not (and d_2_4 d_2_7)))
(assert
 (not (and d_2_4 d_2_8)))
(assert
 (not (and d_2_4 d_2_9)))
(assert
 (not (and d_2_4 d_2_10)))
(assert
 (not (and d_2_4 d_2_11)))
(assert
 (not (and d_2_4 d_2_12)))
(assert
 (not (and d_2_4 d_2_13)))
(assert
 (not (and d_2_4 d_2_14)))
(assert
 (not (and d_2_4 d_2_15)))
(assert
 (not (and d_2_4 d_2_16)))
(assert
 (not (and d_2_4 d_2_17)))
(assert
 (not (and d_2_4 d_2_18)))
(assert
 (not (and d_2_4 d_2_19)))
(assert
 (not (and d_2_4 d_2_20)))
(assert
 (not (and d_2_4 d_2_21)))
(assert
 (not (and d_2_4 d_2_22)))
(assert
 (not (and d_2_4 d_2_23)))
(assert
 (not (and d_2_4 d_2_24)))
(assert
 (not (and d_2_5 d_2_6)))
(assert
 (not (and d_2_5 d_2_7)))
(assert
 (not (and d_2_5 d_2_8)))
(assert
 (not (and d_2_5 d_2_9)))
(assert
 (not (and d_2_5 d_2_10)))
(assert
 (not (and d_2_5 d_2_11)))
(assert
 (not (and d_2_5 d_2_12)))
(assert
 (not (and d_2_5 d_2_13)))
(assert
 (not (and d_2_5 d_2_14)))
(assert
 (not (and d_2_5 d_2_15)))
(assert
 (not (and d_2_5 d_2_16)))
(assert
 (not (and d_2_5 d_2_17)))
(assert
 (not (and d_2_5 d_2_18)))
(assert
 (not (and d_2_5 d_2_19)))
(assert
 (not (and d_2_5 d_2_20)))
(assert
 (not (and d_2_5 d_2_21)))
(assert
 (not (and d_2_5 d_2_22)))
(assert
 (not (and d_2_5 d_2_23)))
(assert
 (not (and d_2_5 d_2_24)))
(assert
 (not (and d_2_6 d_2_7)))
(assert
 (not (and d_2_6 d_2_8)))
(assert
 (not (and d_2_6 d_2_9)))
(assert
 (not (and d_2_6 d_2_10)))
(assert
 (not (and d_2_6 d_2_11)))
(assert
 (not (and d_2_6 d_2_12)))
(assert
 (not (and d_2_6 d_2_13)))
(assert
 (not (and d_2_6 d_2_14)))
(assert
 (not (and d_2_6 d_2_15)))
(assert
 (not (and d_2_6 d_2_16)))
(assert
 (not (and d_2_6 d_2_17)))
(assert
 (not (and d_2_6 d_2_18)))
(assert
 (not (and d_2_6 d_2_19)))
(assert
 (not (and d_2_6 d_2_20)))
(assert
 (not (and d_2_6 d_2_21)))
(assert
 (not (and d_2_6 d_2_22)))
(assert
 (not (and d_2_6 d_2_23)))
(assert
 (not (and d_2_6 d_2_24)))
(assert
 (not (and d_2_7 d_2_8)))
(assert
 (not (and d_2_7 d_2_9)))
(assert
 (not (and d_2_7 d_2_10)))
(assert
 (not (and d_2_7 d_2_11)))
(assert
 (not (and d_2_7 d_2_12)))
(assert
 (not (and d_2_7 d_2_13)))
(assert
 (not (and d_2_7 d_2_14)))
(assert
 (not (and d_2_7 d_2_15)))
(assert
 (not (and d_2_7 d_2_16)))
(assert
 (not (and d_2_7 d_2_17)))
(assert
 (not (and d_2_7 d_2_18)))
(assert
 (not (and d_2_7 d_2_19)))
(assert
 (not (and d_2_7 d_2_20)))
(assert
 (not (and d_2_7 d_2_21)))
(assert
 (not (and d_2_7 d_2_22)))
(assert
 (not (and d_2_7 d_2_23)))
(assert
 (not (and d_2_7 d_2_24)))
(assert
 (not (and d_2_8 d_2_9)))
(assert
 (not (and d_2_8 d_2_10)))
(assert
 (not (and d_2_8 d_2_11)))
(assert
 (not (and d_2_8 d_2_12)))
(assert
 (not (and d_2_8 d_2_13)))
(assert
 (not (and d_2_8 d_2_14)))
(assert
 (not (and d_2_8 d_2_15)))
(assert
 (not (and d_2_8 d_2_16)))
(assert
 (not (and d_2_8 d_2_17)))
(assert
 (not (and d_2_8 d_2_18)))
(assert
 (not (and d_2_8 d_2_19)))
(assert
 (not (and d_2_8 d_2_20)))
(assert
 (not (and d_2_8 d_2_21)))
(assert
 (not (and d_2_8 d_2_22)))
(assert
 (not (and d_2_8 d_2_23)))
(assert
 (not (and d_2_8 d_2_24)))
(assert
 (not (and d_2_9 d_2_10)))
(assert
 (not (and d_2_9 d_2_11)))
(assert
 (not (and d_2_9 d_2_12)))
(assert
 (not (and d_2_9 d_2_13)))
(assert
 (not (and d_2_9 d_2_14)))
(assert
 (not (and d_2_9 d_2_15)))
(assert
 (not (and d_2_9 d_2_16)))
(assert
 (not (and d_2_9 d_2_17)))
(assert
 (not (and d_2_9 d_2_18)))
(assert
 (not (and d_2_9 d_2_19)))
(assert
 (not (and d_2_9 d_2_20)))
(assert
 (not (and d_2_9 d_2_21)))
(assert
 (not (and d_2_9 d_2_22)))
(assert
 (not (and d_2_9 d_2_23)))
(assert
 (not (and d_2_9 d_2_24)))
(assert
 (not (and d_2_10 d_2_11)))
(assert
 (not (and d_2_10 d_2_12)))
(assert
 (not (and d_2_10 d_2_13)))
(assert
 (not (and d_2_10 d_2_14)))
(assert
 (not (and d_2_10 d_2_15)))
(assert
 (not (and d_2_10 d_2_16)))
(assert
 (not (and d_2_10 d_2_17)))
(assert
 (not (and d_2_10 d_2_18)))
(assert
 (not (and d_2_10 d_2_19)))
(assert
 (not (and d_2_10 d_2_20)))
(assert
 (not (and d_2_10 d_2_21)))
(assert
 (not (and d_2_10 d_2_22)))
(assert
 (not (and d_2_10 d_2_23)))
(assert
 (not (and d_2_10 d_2_24)))
(assert
 (not (and d_2_11 d_2_12)))
(assert
 (not (and d_2_11 d_2_13)))
(assert
 (not (and d_2_11 d_2_14)))
(assert
 (not (and d_2_11 d_2_15)))
(assert
 (not (and d_2_11 d_2_16)))
(assert
 (not (and d_2_11 d_2_17)))
(assert
 (not (and d_2_11 d_2_18)))
(assert
 (not (and d_2_11 d_2_19)))
(assert
 (not (and d_2_11 d_2_20)))
(assert
 (not (and d_2_11 d_2_21)))
(assert
 (not (and d_2_11 d_2_22)))
(assert
 (not (and d_2_11 d_2_23)))
(assert
 (not (and d_2_11 d_2_24)))
(assert
 (not (and d_2_12 d_2_13)))
(assert
 (not (and d_2_12 d_2_14)))
(assert
 (not (and d_2_12 d_2_15)))
(assert
 (not (and d_2_12 d_2_16)))
(assert
 (not (and d_2_12 d_2_17)))
(assert
 (not (and d_2_12 d_2_18)))
(assert
 (not (and d_2_12 d_2_19)))
(assert
 (not (and d_2_12 d_2_20)))
(assert
 (not (and d_2_12 d_2_21)))
(assert
 (not (and d_2_12 d_2_22)))
(assert
 (not (and d_2_12 d_2_23)))
(assert
 (not (and d_2_12 d_2_24)))
(assert
 (not (and d_2_13 d_2_14)))
(assert
 (not (and d_2_13 d_2_15)))
(assert
 (not (and d_2_13 d_2_16)))
(assert
 (not (and d_2_13 d_2_17)))
(assert
 (not (and d_2_13 d_2_18)))
(assert
 (not (and d_2_13 d_2_19)))
(assert
 (not (and d_2_13 d_2_20)))
(assert
 (not (and d_2_13 d_2_21)))
(assert
 (not (and d_2_13 d_2_22)))
(assert
 (not (and d_2_13 d_2_23)))
(assert
 (not (and d_2_13 d_2_24)))
(assert
 (not (and d_2_14 d_2_15)))
(assert
 (not (and d_2_14 d_2_16)))
(assert
 (not (and d_2_14 d_2_17)))
(assert
 (not (and d_2_14 d_2_18)))
(assert
 (not (and d_2_14 d_2_19)))
(assert
 (not (and d_2_14 d_2_20)))
(assert
 (not (and d_2_14 d_2_21)))
(assert
 (not (and d_2_14 d_2_22)))
(assert
 (not (and d_2_14 d_2_23)))
(assert
 (not (and d_2_14 d_2_24)))
(assert
 (not (and d_2_15 d_2_16)))
(assert
 (not (and d_2_15 d_2_17)))
(assert
 (not (and d_2_15 d_2_18)))
(assert
 (not (and d_2_15 d_2_19)))
(assert
 (not (and d_2_15 d_2_20)))
(assert
 (not (and d_2_15 d_2_21)))
(assert
 (not (and d_2_15 d_2_22)))
(assert
 (not (and d_2_15 d_2_23)))
(assert
 (not (and d_2_15 d_2_24)))
(assert
 (not (and d_2_16 d_2_17)))
(assert
 (not (and d_2_16 d_2_18)))
(assert
 (not (and d_2_16 d_2_19)))
(assert
 (not (and d_2_16 d_2_20)))
(assert
 (not (and d_2_16 d_2_21)))
(assert
 (not (and d_2_16 d_2_22)))
(assert
 (not (and d_2_16 d_2_23)))
(assert
 (not (and d_2_16 d_2_24)))
(assert
 (not (and d_2_17 d_2_18)))
(assert
 (not (and d_2_17 d_2_19)))
(assert
 (not (and d_2_17 d_2_20)))
(assert
 (not (and d_2_17 d_2_21)))
(assert
 (not (and d_2_17 d_2_22)))
(assert
 (not (and d_2_17 d_2_23)))
(assert
 (not (and d_2_17 d_2_24)))
(assert
 (not (and d_2_18 d_2_19)))
(assert
 (not (and d_2_18 d_2_20)))
(assert
 (not (and d_2_18 d_2_21)))
(assert
 (not (and d_2_18 d_2_22)))
(assert
 (not (and d_2_18 d_2_23)))
(assert
 (not (and d_2_18 d_2_24)))
(assert
 (not (and d_2_19 d_2_20)))
(assert
 (not (and d_2_19 d_2_21)))
(assert
 (not (and d_2_19 d_2_22)))
(assert
 (not (and d_2_19 d_2_23)))
(assert
 (not (and d_2_19 d_2_24)))
(assert
 (not (and d_2_20 d_2_21)))
(assert
 (not (and d_2_20 d_2_22)))
(assert
 (not (and d_2_20 d_2_23)))
(assert
 (not (and d_2_20 d_2_24)))
(assert
 (not (and d_2_21 d_2_22)))
(assert
 (not (and d_2_21 d_2_23)))
(assert
 (not (and d_2_21 d_2_24)))
(assert
 (not (and d_2_22 d_2_23)))
(assert
 (not (and d_2_22 d_2_24)))
(assert
 (not (and d_2_23 d_2_24)))
(assert
 (let (($x4588 (or false d_3_0)))
 (let (($x4590 (or $x4588 d_3_1)))
 (let (($x4592 (or $x4590 d_3_2)))
 (let (($x4594 (or $x4592 d_3_3)))
 (let (($x4596 (or $x4594 d_3_4)))
 (let (($x4598 (or $x4596 d_3_5)))
 (let (($x4600 (or $x4598 d_3_6)))
 (let (($x4602 (or $x4600 d_3_7)))
 (let (($x4604 (or $x4602 d_3_8)))
 (let (($x4606 (or $x4604 d_3_9)))
 (let (($x4608 (or $x4606 d_3_10)))
 (let (($x4610 (or $x4608 d_3_11)))
 (let (($x4612 (or $x4610 d_3_12)))
 (let (($x4614 (or $x4612 d_3_13)))
 (let (($x4616 (or $x4614 d_3_14)))
 (let (($x4618 (or $x4616 d_3_15)))
 (let (($x4620 (or $x4618 d_3_16)))
 (let (($x4622 (or $x4620 d_3_17)))
 (let (($x4624 (or $x4622 d_3_18)))
 (let (($x4626 (or $x4624 d_3_19)))
 (let (($x4628 (or $x4626 d_3_20)))
 (let (($x4630 (or $x4628 d_3_21)))
 (let (($x4632 (or $x4630 d_3_22)))
 (let (($x4634 (or $x4632 d_3_23)))
 (or $x4634 d_3_24))))))))))))))))))))))))))
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
 (not (and d_3_0 d_3_7)))
(assert
 (not (and d_3_0 d_3_8)))
(assert
 (not (and d_3_0 d_3_9)))
(assert
 (not (and d_3_0 d_3_10)))
(assert
 (not (and d_3_0 d_3_11)))
(assert
 (not (and d_3_0 d_3_12)))
(assert
 (not (and d_3_0 d_3_13)))
(assert
 (not (and d_3_0 d_3_14)))
(assert
 (not (and d_3_0 d_3_15)))
(assert
 (not (and d_3_0 d_3_16)))
(assert
 (not (and d_3_0 d_3_17)))
(assert
 (not (and d_3_0 d_3_18)))
(assert
 (not (and d_3_0 d_3_19)))
(assert
 (not (and d_3_0 d_3_20)))
(assert
 (not (and d_3_0 d_3_21)))
(assert
 (not (and d_3_0 d_3_22)))
(assert
 (not (and d_3_0 d_3_23)))
(assert
 (not (and d_3_0 d_3_24)))
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
 (not (and d_3_1 d_3_7)))
(assert
 (not (and d_3_1 d_3_8)))
(assert
 (not (and d_3_1 d_3_9)))
(assert
 (not (and d_3_1 d_3_10)))
(assert
 (not (and d_3_1 d_3_11)))
(assert
 (not (and d_3_1 d_3_12)))
(assert
 (not (and d_3_1 d_3_13)))
(assert
 (not (and d_3_1 d_3_14)))
(assert
 (not (and d_3_1 d_3_15)))
(assert
 (not (and d_3_1 d_3_16)))
(assert
 (not (and d_3_1 d_3_17)))
(assert
 (not (and d_3_1 d_3_18)))
(assert
 (not (and d_3_1 d_3_19)))
(assert
 (not (and d_3_1 d_3_20)))
(assert
 (not (and d_3_1 d_3_21)))
(assert
 (not (and d_3_1 d_3_22)))
(assert
 (not (and d_3_1 d_3_23)))
(assert
 (not (and d_3_1 d_3_24)))
(assert
 (not (and d_3_2 d_3_3)))
(assert
 (not (and d_3_2 d_3_4)))
(assert
 (not (and d_3_2 d_3_5)))
(assert
 (not (and d_3_2 d_3_6)))
(assert
 (not (and d_3_2 d_3_7)))
(assert
 (not (and d_3_2 d_3_8)))
(assert
 (not (and d_3_2 d_3_9)))
(assert
 (not (and d_3_2 d_3_10)))
(assert
 (not (and d_3_2 d_3_11)))
(assert
 (not (and d_3_2 d_3_12)))
(assert
 (not (and d_3_2 d_3_13)))
(assert
 (not (and d_3_2 d_3_14)))
(assert
 (not (and d_3_2 d_3_15)))
(assert
 (not (and d_3_2 d_3_16)))
(assert
 (not (and d_3_2 d_3_17)))
(assert
 (not (and d_3_2 d_3_18)))
(assert
 (not (and d_3_2 d_3_19)))
(assert
 (not (and d_3_2 d_3_20)))
(assert
 (not (and d_3_2 d_3_21)))
(assert
 (not (and d_3_2 d_3_22)))
(assert
 (not (and d_3_2 d_3_23)))
(assert
 (not (and d_3_2 d_3_24)))
(assert
 (not (and d_3_3 d_3_4)))
(assert
 (not (and d_3_3 d_3_5)))
(assert
 (not (and d_3_3 d_3_6)))
(assert
 (not (and d_3_3 d_3_7)))
(assert
 (not (and d_3_3 d_3_8)))
(assert
 (not (and d_3_3 d_3_9)))
(assert
 (not (and d_3_3 d_3_10)))
(assert
 (not (and d_3_3 d_3_11)))
(assert
 (not (and d_3_3 d_3_12)))
(assert
 (not (and d_3_3 d_3_13)))
(assert
 (not (and d_3_3 d_3_14)))
(assert
 (not (and d_3_3 d_3_15)))
(assert
 (not (and d_3_3 d_3_16)))
(assert
 (not (and d_3_3 d_3_17)))
(assert
 (not (and d_3_3 d_3_18)))
(assert
 (not (and d_3_3 d_3_19)))
(assert
 (not (and d_3_3 d_3_20)))
(assert
 (not (and d_3_3 d_3_21)))
(assert
 (not (and d_3_3 d_3_22)))
(assert
 (not (and d_3_3 d_3_23)))
(assert
 (not (and d_3_3 d_3_24)))
(assert
 (not (and d_3_4 d_3_5)))
(assert
 (not (and d_3_4 d_3_6)))
(assert
 (not (and d_3_4 d_3_7)))
(assert
 (not (and d_3_4 d_3_8)))
(assert
 (not (and d_3_4 d_3_9)))
(assert
 (not (and d_3_4 d_3_10)))
(assert
 (not (and d_3_4 d_3_11)))
(assert
 (not (and d_3_4 d_3_12)))
(assert
 (not (and d_3_4 d_3_13)))
(assert
 (not (and d_3_4 d_3_14)))
(assert
 (not (and d_3_4 d_3_15)))
(assert
 (not (and d_3_4 d_3_16)))
(assert
 (not (and d_3_4 d_3_17)))
(assert
 (not (and d_3_4 d_3_18)))
(assert
 (not (and d_3_4 d_3_19)))
(assert
 (not (and d_3_4 d_3_20)))
(assert
 (not (and d_3_4 d_3_21)))
(assert
 (not (and d_3_4 d_3_22)))
(assert
 (not (and d_3_4 d_3_23)))
(assert
 (not (and d_3_4 d_3_24)))
(assert
 (not (and d_3_5 d_3_6)))
(assert
 (not (and d_3_5 d_3_7)))
(assert
 (not (and d_3_5 d_3_8)))
(assert
 (not (and d_3_5 d_3_9)))
(assert
 (not (and d_3_5 d_3_10)))
(assert
 (not (and d_3_5 d_3_11)))
(assert
 (not (and d_3_5 d_3_12)))
(assert
 (not (and d_3_5 d_3_13)))
(assert
 (not (and d_3_5 d_3_14)))
(assert
 (not (and d_3_5 d_3_15)))
(assert
 (not (and d_3_5 d_3_16)))
(assert
 (not (and d_3_5 d_3_17)))
(assert
 (not (and d_3_5 d_3_18)))
(assert
 (not (and d_3_5 d_3_19)))
(assert
 (not (and d_3_5 d_3_20)))
(assert
 (not (and d_3_5 d_3_21)))
(assert
 (not (and d_3_5 d_3_22)))
(assert
 (not (and d_3_5 d_3_23)))
(assert
 (not (and d_3_5 d_3_24)))
(assert
 (not (and d_3_6 d_3_7)))
(assert
 (not (and d_3_6 d_3_8)))
(assert
 (not (and d_3_6 d_3_9)))
(assert
 (not (and d_3_6 d_3_10)))
(assert
 (not (and d_3_6 d_3_11)))
(assert
 (not (and d_3_6 d_3_12)))
(assert
 (not (and d_3_6 d_3_13)))
(assert
 (not (and d_3_6 d_3_14)))
(assert
 (not (and d_3_6 d_3_15)))
(assert
 (not (and d_3_6 d_3_16)))
(assert
 (not (and d_3_6 d_3_17)))
(assert
 (not (and d_3_6 d_3_18)))
(assert
 (not (and d_3_6 d_3_19)))
(assert
 (not (and d_3_6 d_3_20)))
(assert
 (not (and d_3_6 d_3_21)))
(assert
 (not (and d_3_6 d_3_22)))
(assert
 (not (and d_3_6 d_3_23)))
(assert
 (not (and d_3_6 d_3_24)))
(assert
 (not (and d_3_7 d_3_8)))
(assert
 (not (and d_3_7 d_3_9)))
(assert
 (not (and d_3_7 d_3_10)))
(assert
 (not (and d_3_7 d_3_11)))
(assert
 (not (and d_3_7 d_3_12)))
(assert
 (not (and d_3_7 d_3_13)))
(assert
 (not (and d_3_7 d_3_14)))
(assert
 (not (and d_3_7 d_3_15)))
(assert
 (not (and d_3_7 d_3_16)))
(assert
 (not (and d_3_7 d_3_17)))
(assert
 (not (and d_3_7 d_3_18)))
(assert
 (not (and d_3_7 d_3_19)))
(assert
 (not (and d_3_7 d_3_20)))
(assert
 (not (and d_3_7 d_3_21)))
(assert
 (not (and d_3_7 d_3_22)))
(assert
 (not (and d_3_7 d_3_23)))
(assert
 (not (and d_3_7 d_3_24)))
(assert
 (not (and d_3_8 d_3_9)))
(assert
 (not (and d_3_8 d_3_10)))
(assert
 (not (and d_3_8 d_3_11)))
(assert
 (not (and d_3_8 d_3_12)))
(assert
 (not (and d_3_8 d_3_13)))
(assert
 (not (and d_3_8 d_3_14)))
(assert
 (not (and d_3_8 d_3_15)))
(assert
 (not (and d_3_8 d_3_16)))
(assert
 (not (and d_3_8 d_3_17)))
(assert
 (not (and d_3_8 d_3_18)))
(assert
 (not (and d_3_8 d_3_19)))
(assert
 (not (and d_3_8 d_3_20)))
(assert
 (not (and d_3_8 d_3_21)))
(assert
 (not (and d_3_8 d_3_22)))
(assert
 (not (and d_3_8 d_3_23)))
(assert
 (not (and d_3_8 d_3_24)))
(assert
 (not (and d_3_9 d_3_10)))
(assert
 (not (and d_3_9 d_3_11)))
(assert
 (not (and d_3_9 d_3_12)))
(assert
 (not (and d_3_9 d_3_13)))
(assert
 (not (and d_3_9 d_3_14)))
(assert
 (not (and d_3_9 d_3_15)))
(assert
 (not (and d_3_9 d_3_16)))
(assert
 (not (and d_3_9 d_3_17)))
(assert
 (not (and d_3_9 d_3_18)))
(assert
 (not (and d_3_9 d_3_19)))
(assert
 (not (and d_3_9 d_3_20)))
(assert
 (not (and d_3_9 d_3_21)))
(assert
 (not (and d_3_9 d_3_22)))
(assert
 (not (and d_3_9 d_3_23)))
(assert
 (not (and d_3_9 d_3_24)))
(assert
 (not (and d_3_10 d_3_11)))
(assert
 (not (and d_3_10 d_3_12)))
(assert
 (not (and d_3_10 d_3_13)))
(assert
 (not (and d_3_10 d_3_14)))
(assert
 (not (and d_3_10 d_3_15)))
(assert
 (not (and d_3_10 d_3_16)))
(assert
 (not (and d_3_10 d_3_17)))
(assert
 (not (and d_3_10 d_3_18)))
(assert
 (not (and d_3_10 d_3_19)))
(assert
 (not (and d_3_10 d_3_20)))
(assert
 (not (and d_3_10 d_3_21)))
(assert
 (not (and d_3_10 d_3_22)))
(assert
 (not (and d_3_10 d_3_23)))
(assert
 (not (and d_3_10 d_3_24)))
(assert
 (not (and d_3_11 d_3_12)))
(assert
 (not (and d_3_11 d_3_13)))
(assert
 (not (and d_3_11 d_3_14)))
(assert
 (not (and d_3_11 d_3_15)))
(assert
 (not (and d_3_11 d_3_16)))
(assert
 (not (and d_3_11 d_3_17)))
(assert
 (not (and d_3_11 d_3_18)))
(assert
 (not (and d_3_11 d_3_19)))
(assert
 (not (and d_3_11 d_3_20)))
(assert
 (not (and d_3_11 d_3_21)))
(assert
 (not (and d_3_11 d_3_22)))
(assert
 (not (and d_3_11 d_3_23)))
(assert
 (not (and d_3_11 d_3_24)))
(assert
 (not (and d_3_12 d_3_13)))
(assert
 (not (and d_3_12 d_3_14)))
(assert
 (not (and d_3_12 d_3_15)))
(assert
 (not (and d_3_12 d_3_16)))
(assert
 (not (and d_3_12 d_3_17)))
(assert
 (not (and d_3_12 d_3_18)))
(assert
 (not (and d_3_12 d_3_19)))
(assert
 (not (and d_3_12 d_3_20)))
(assert
 (not (and d_3_12 d_3_21)))
(assert
 (not (and d_3_12 d_3_22)))
(assert
 (not (and d_3_12 d_3_23)))
(assert
 (not (and d_3_12 d_3_24)))
(assert
 (not (and d_3_13 d_3_14)))
(assert
 (not (and d_3_13 d_3_15)))
(assert
 (not (and d_3_13 d_3_16)))
(assert
 (not (and d_3_13 d_3_17)))
(assert
 (not (and d_3_13 d_3_18)))
(assert
 (not (and d_3_13 d_3_19)))
(assert
 (not (and d_3_13 d_3_20)))
(assert
 (not (and d_3_13 d_3_21)))
(assert
 (not (and d_3_13 d_3_22)))
(assert
 (not (and d_3_13 d_3_23)))
(assert
 (not (and d_3_13 d_3_24)))
(assert
 (not (and d_3_14 d_3_15)))
(assert
 (not (and d_3_14 d_3_16)))
(assert
 (not (and d_3_14 d_3_17)))
(assert
 (not (and d_3_14 d_3_18)))
(assert
 (not (and d_3_14 d_3_19)))
(assert
 (not (and d_3_14 d_3_20)))
(assert
 (not (and d_3_14 d_3_21)))
(assert
 (not (and d_3_14 d_3_22)))
(assert
 (not (and d_3_14 d_3_23)))
(assert
 (not (and d_3_14 d_3_24)))
(assert
 (not (and d_3_15 d_3_16)))
(assert
 (not (and d_3_15 d_3_17)))
(assert
 (not (and d_3_15 d_3_18)))
(assert
 (not (and d_3_15 d_3_19)))
(assert
 (not (and d_3_15 d_3_20)))
(assert
 (not (and d_3_15 d_3_21)))
(assert
 (not (and d_3_15 d_3_22)))
(assert
 (not (and d_3_15 d_3_23)))
(assert
 (not (and d_3_15 d_3_24)))
(assert
 (not (and d_3_16 d_3_17)))
(assert
 (not (and d_3_16 d_3_18)))
(assert
 (not (and d_3_16 d_3_19)))
(assert
 (not (and d_3_16 d_3_20)))
(assert
 (not (and d_3_16 d_3_21)))
(assert
 (not (and d_3_16 d_3_22)))
(assert
 (not (and d_3_16 d_3_23)))
(assert
 (not (and d_3_16 d_3_24)))
(assert
 (not (and d_3_17 d_3_18)))
(assert
 (not (and d_3_17 d_3_19)))
(assert
 (not (and d_3_17 d_3_20)))
(assert
 (not (and d_3_17 d_3_21)))
(assert
 (not (and d_3_17 d_3_22)))
(assert
 (not (and d_3_17 d_3_23)))
(assert
 (not (and d_3_17 d_3_24)))
(assert
 (not (and d_3_18 d_3_19)))
(assert
 (not (and d_3_18 d_3_20)))
(assert
 (not (and d_3_18 d_3_21)))
(assert
 (not (and d_3_18 d_3_22)))
(assert
 (not (and d_3_18 d_3_23)))
(assert
 (not (and d_3_18 d_3_24)))
(assert
 (not (and d_3_19 d_3_20)))
(assert
 (not (and d_3_19 d_3_21)))
(assert
 (not (and d_3_19 d_3_22)))
(assert
 (not (and d_3_19 d_3_23)))
(assert
 (not (and d_3_19 d_3_24)))
(assert
 (not (and d_3_20 d_3_21)))
(assert
 (not (and d_3_20 d_3_22)))
(assert
 (not (and d_3_20 d_3_23)))
(assert
 (not (and d_3_20 d_3_24)))
(assert
 (not (and d_3_21 d_3_22)))
(assert
 (not (and d_3_21 d_3_23)))
(assert
 (not (and d_3_21 d_3_24)))
(assert
 (not (and d_3_22 d_3_23)))
(assert
 (not (and d_3_22 d_3_24)))
(assert
 (not (and d_3_23 d_3_24)))
(assert
 (let (($x23299 (and (distinct (+ 0 (ite c_0_0 0 1)) (+ 0 (ite d_0_0 0 1))) true)))
 (let (($x23314 (and d_3_24 in_walk8_3 in_walk7_3)))
 (let (($x23312 (and d_3_23 in_walk8_3 in_walk7_3)))
 (let (($x23310 (and d_3_22 in_walk8_3 in_walk7_3)))
 (let (($x23308 (and d_3_21 in_walk8_3 in_walk7_3)))
 (let (($x23306 (and d_3_20 in_walk8_3 in_walk7_3)))
 (let (($x23304 (and d_3_19 in_walk8_3 in_walk7_3)))
 (let (($x23302 (and d_3_18 in_walk8_3 in_walk7_3)))
 (let (($x23300 (and d_3_17 in_walk8_3 in_walk7_3)))
 (let (($x23298 (and d_3_16 in_walk8_3 in_walk7_3)))
 (let (($x23296 (and d_3_15 in_walk8_3 in_walk7_3)))
 (let (($x23294 (and d_3_14 in_walk8_3 in_walk7_3)))
 (let (($x23292 (and d_3_13 in_walk8_3 in_walk7_3)))
 (let (($x23290 (and d_3_12 in_walk8_3 in_walk7_3)))
 (let (($x23288 (and d_3_11 in_walk8_3 in_walk7_3)))
 (let (($x23286 (and d_3_10 in_walk8_3 in_walk7_3)))
 (let (($x23284 (and d_3_9 in_walk8_3 in_walk7_3)))
 (let (($x23282 (and d_3_8 in_walk8_3 in_walk7_3)))
 (let (($x23280 (and d_3_7 in_walk8_3 in_walk7_3)))
 (let (($x23278 (and d_3_6 in_walk8_3 in_walk7_3)))
 (let (($x23276 (and d_3_5 in_walk8_3 in_walk7_3)))
 (let (($x23274 (and d_3_4 in_walk8_3 in_walk7_3)))
 (let (($x23272 (and d_3_3 in_walk8_3 in_walk7_3)))
 (let (($x23270 (and d_3_2 in_walk8_3 in_walk7_3)))
 (let (($x23268 (and d_3_1 in_walk8_3 in_walk7_3)))
 (let (($x23267 (and d_3_0 in_walk8_3 in_walk7_3)))
 (let (($x23315 (or $x23267 $x23268 $x23270 $x23272 $x23274 $x23276 $x23278 $x23280 $x23282 $x23284 $x23286 $x23288 $x23290 $x23292 $x23294 $x23296 $x23298 $x23300 $x23302 $x23304 $x23306 $x23308 $x23310 $x23312 $x23314)))
 (let (($x23238 (and d_2_24 in_walk8_2 in_walk7_2)))
 (let (($x23236 (and d_2_23 in_walk8_2 in_walk7_2)))
 (let (($x23234 (and d_2_22 in_walk8_2 in_walk7_2)))
 (let (($x23232 (and d_2_21 in_walk8_2 in_walk7_2)))
 (let (($x23230 (and d_2_20 in_walk8_2 in_walk7_2)))
 (let (($x23228 (and d_2_19 in_walk8_2 in_walk7_2)))
 (let (($x23226 (and d_2_18 in_walk8_2 in_walk7_2)))
 (let (($x23224 (and d_2_17 in_walk8_2 in_walk7_2)))
 (let (($x23222 (and d_2_16 in_walk8_2 in_walk7_2)))
 (let (($x23220 (and d_2_15 in_walk8_2 in_walk7_2)))
 (let (($x23218 (and d_2_14 in_walk8_2 in_walk7_2)))
 (let (($x23216 (and d_2_13 in_walk8_2 in_walk7_2)))
 (let (($x23214 (and d_2_12 in_walk8_2 in_walk7_2)))
 (let (($x23212 (and d_2_11 in_walk8_2 in_walk7_2)))
 (let (($x23210 (and d_2_10 in_walk8_2 in_walk7_2)))
 (let (($x23208 (and d_2_9 in_walk8_2 in_walk7_2)))
 (let (($x23206 (and d_2_8 in_walk8_2 in_walk7_2)))
 (let (($x23204 (and d_2_7 in_walk8_2 in_walk7_2)))
 (let (($x23202 (and d_2_6 in_walk8_2 in_walk7_2)))
 (let (($x23200 (and d_2_5 in_walk8_2 in_walk7_2)))
 (let (($x23198 (and d_2_4 in_walk8_2 in_walk7_2)))
 (let (($x23196 (and d_2_3 in_walk8_2 in_walk7_2)))
 (let (($x23194 (and d_2_2 in_walk8_2 in_walk7_2)))
 (let (($x23192 (and d_2_1 in_walk8_2 in_walk7_2)))
 (let (($x23191 (and d_2_0 in_walk8_2 in_walk7_2)))
 (let (($x23239 (or $x23191 $x23192 $x23194 $x23196 $x23198 $x23200 $x23202 $x23204 $x23206 $x23208 $x23210 $x23212 $x23214 $x23216 $x23218 $x23220 $x23222 $x23224 $x23226 $x23228 $x23230 $x23232 $x23234 $x23236 $x23238)))
 (let (($x23162 (and d_1_24 in_walk8_1 in_walk7_1)))
 (let (($x23160 (and d_1_23 in_walk8_1 in_walk7_1)))
 (let (($x23158 (and d_1_22 in_walk8_1 in_walk7_1)))
 (let (($x23156 (and d_1_21 in_walk8_1 in_walk7_1)))
 (let (($x23154 (and d_1_20 in_walk8_1 in_walk7_1)))
 (let (($x23152 (and d_1_19 in_walk8_1 in_walk7_1)))
 (let (($x23150 (and d_1_18 in_walk8_1 in_walk7_1)))
 (let (($x23148 (and d_1_17 in_walk8_1 in_walk7_1)))
 (let (($x23146 (and d_1_16 in_walk8_1 in_walk7_1)))
 (let (($x23144 (and d_1_15 in_walk8_1 in_walk7_1)))
 (let (($x23142 (and d_1_14 in_walk8_1 in_walk7_1)))
 (let (($x23140 (and d_1_13 in_walk8_1 in_walk7_1)))
 (let (($x23138 (and d_1_12 in_walk8_1 in_walk7_1)))
 (let (($x23136 (and d_1_11 in_walk8_1 in_walk7_1)))
 (let (($x23134 (and d_1_10 in_walk8_1 in_walk7_1)))
 (let (($x23132 (and d_1_9 in_walk8_1 in_walk7_1)))
 (let (($x23130 (and d_1_8 in_walk8_1 in_walk7_1)))
 (let (($x23128 (and d_1_7 in_walk8_1 in_walk7_1)))
 (let (($x23126 (and d_1_6 in_walk8_1 in_walk7_1)))
 (let (($x23124 (and d_1_5 in_walk8_1 in_walk7_1)))
 (let (($x23122 (and d_1_4 in_walk8_1 in_walk7_1)))
 (let (($x23120 (and d_1_3 in_walk8_1 in_walk7_1)))
 (let (($x23118 (and d_1_2 in_walk8_1 in_walk7_1)))
 (let (($x23116 (and d_1_1 in_walk8_1 in_walk7_1)))
 (let (($x23115 (and d_1_0 in_walk8_1 in_walk7_1)))
 (let (($x23163 (or $x23115 $x23116 $x23118 $x23120 $x23122 $x23124 $x23126 $x23128 $x23130 $x23132 $x23134 $x23136 $x23138 $x23140 $x23142 $x23144 $x23146 $x23148 $x23150 $x23152 $x23154 $x23156 $x23158 $x23160 $x23162)))
 (let (($x23086 (and d_0_24 in_walk8_0 in_walk7_0)))
 (let (($x23084 (and d_0_23 in_walk8_0 in_walk7_0)))
 (let (($x23082 (and d_0_22 in_walk8_0 in_walk7_0)))
 (let (($x23080 (and d_0_21 in_walk8_0 in_walk7_0)))
 (let (($x23078 (and d_0_20 in_walk8_0 in_walk7_0)))
 (let (($x23076 (and d_0_19 in_walk8_0 in_walk7_0)))
 (let (($x23074 (and d_0_18 in_walk8_0 in_walk7_0)))
 (let (($x23072 (and d_0_17 in_walk8_0 in_walk7_0)))
 (let (($x23070 (and d_0_16 in_walk8_0 in_walk7_0)))
 (let (($x23068 (and d_0_15 in_walk8_0 in_walk7_0)))
 (let (($x23066 (and d_0_14 in_walk8_0 in_walk7_0)))
 (let (($x23064 (and d_0_13 in_walk8_0 in_walk7_0)))
 (let (($x23062 (and d_0_12 in_walk8_0 in_walk7_0)))
 (let (($x23060 (and d_0_11 in_walk8_0 in_walk7_0)))
 (let (($x23058 (and d_0_10 in_walk8_0 in_walk7_0)))
 (let (($x23056 (and d_0_9 in_walk8_0 in_walk7_0)))
 (let (($x23054 (and d_0_8 in_walk8_0 in_walk7_0)))
 (let (($x23052 (and d_0_7 in_walk8_0 in_walk7_0)))
 (let (($x23050 (and d_0_6 in_walk8_0 in_walk7_0)))
 (let (($x23048 (and d_0_5 in_walk8_0 in_walk7_0)))
 (let (($x23046 (and d_0_4 in_walk8_0 in_walk7_0)))
 (let (($x23044 (and d_0_3 in_walk8_0 in_walk7_0)))
 (let (($x23042 (and d_0_2 in_walk8_0 in_walk7_0)))
 (let (($x23040 (and d_0_1 in_walk8_0 in_walk7_0)))
 (let (($x23039 (and d_0_0 in_walk8_0 in_walk7_0)))
 (let (($x23087 (or $x23039 $x23040 $x23042 $x23044 $x23046 $x23048 $x23050 $x23052 $x23054 $x23056 $x23058 $x23060 $x23062 $x23064 $x23066 $x23068 $x23070 $x23072 $x23074 $x23076 $x23078 $x23080 $x23082 $x23084 $x23086)))
 (let (($x23037 (or false $x23087)))
 (let (($x23113 (or $x23037 $x23163)))
 (let (($x23189 (or $x23113 $x23239)))
 (let (($x16541 (not (or (or (or (or false d_0_16) d_1_16) d_2_16) d_3_16))))
 (let (($x16234 (not (or (or (or (or false d_0_15) d_1_15) d_2_15) d_3_15))))
 (let (($x23007 (and d_3_24 in_walk8_3 in_walk6_3)))
 (let (($x23005 (and d_3_23 in_walk8_3 in_walk6_3)))
 (let (($x23003 (and d_3_22 in_walk8_3 in_walk6_3)))
 (let (($x23001 (and d_3_21 in_walk8_3 in_walk6_3)))
 (let (($x22999 (and d_3_20 in_walk8_3 in_walk6_3)))
 (let (($x22997 (and d_3_19 in_walk8_3 in_walk6_3)))
 (let (($x22995 (and d_3_18 in_walk8_3 in_walk6_3)))
 (let (($x22993 (and d_3_17 in_walk8_3 in_walk6_3)))
 (let (($x22991 (and d_3_16 in_walk8_3 in_walk6_3)))
 (let (($x22989 (and d_3_15 in_walk8_3 in_walk6_3)))
 (let (($x22987 (and d_3_14 in_walk8_3 in_walk6_3)))
 (let (($x22985 (and d_3_13 in_walk8_3 in_walk6_3)))
 (let (($x22983 (and d_3_12 in_walk8_3 in_walk6_3)))
 (let (($x22981 (and d_3_11 in_walk8_3 in_walk6_3)))
 (let (($x22979 (and d_3_10 in_walk8_3 in_walk6_3)))
 (let (($x22977 (and d_3_9 in_walk8_3 in_walk6_3)))
 (let (($x22975 (and d_3_8 in_walk8_3 in_walk6_3)))
 (let (($x22973 (and d_3_7 in_walk8_3 in_walk6_3)))
 (let (($x22971 (and d_3_6 in_walk8_3 in_walk6_3)))
 (let (($x22969 (and d_3_5 in_walk8_3 in_walk6_3)))
 (let (($x22967 (and d_3_4 in_walk8_3 in_walk6_3)))
 (let (($x22965 (and d_3_3 in_walk8_3 in_walk6_3)))
 (let (($x22963 (and d_3_2 in_walk8_3 in_walk6_3)))
 (let (($x22961 (and d_3_1 in_walk8_3 in_walk6_3)))
 (let (($x22960 (and d_3_0 in_walk8_3 in_walk6_3)))
 (let (($x23008 (or $x22960 $x22961 $x22963 $x22965 $x22967 $x22969 $x22971 $x22973 $x22975 $x22977 $x22979 $x22981 $x22983 $x22985 $x22987 $x22989 $x22991 $x22993 $x22995 $x22997 $x22999 $x23001 $x23003 $x23005 $x23007)))
 (let (($x22931 (and d_2_24 in_walk8_2 in_walk6_2)))
 (let (($x22929 (and d_2_23 in_walk8_2 in_walk6_2)))
 (let (($x22927 (and d_2_22 in_walk8_2 in_walk6_2)))
 (let (($x22925 (and d_2_21 in_walk8_2 in_walk6_2)))
 (let (($x22923 (and d_2_20 in_walk8_2 in_walk6_2)))
 (let (($x22921 (and d_2_19 in_walk8_2 in_walk6_2)))
 (let (($x22919 (and d_2_18 in_walk8_2 in_walk6_2)))
 (let (($x22917 (and d_2_17 in_walk8_2 in_walk6_2)))
 (let (($x22915 (and d_2_16 in_walk8_2 in_walk6_2)))
 (let (($x22913 (and d_2_15 in_walk8_2 in_walk6_2)))
 (let (($x22911 (and d_2_14 in_walk8_2 in_walk6_2)))
 (let (($x22909 (and d_2_13 in_walk8_2 in_walk6_2)))
 (let (($x22907 (and d_2_12 in_walk8_2 in_walk6_2)))
 (let (($x22905 (and d_2_11 in_walk8_2 in_walk6_2)))
 (let (($x22903 (and d_2_10 in_walk8_2 in_walk6_2)))
 (let (($x22901 (and d_2_9 in_walk8_2 in_walk6_2)))
 (let (($x22899 (and d_2_8 in_walk8_2 in_walk6_2)))
 (let (($x22897 (and d_2_7 in_walk8_2 in_walk6_2)))
 (let (($x22895 (and d_2_6 in_walk8_2 in_walk6_2)))
 (let (($x22893 (and d_2_5 in_walk8_2 in_walk6_2)))
 (let (($x22891 (and d_2_4 in_walk8_2 in_walk6_2)))
 (let (($x22889 (and d_2_3 in_walk8_2 in_walk6_2)))
 (let (($x22887 (and d_2_2 in_walk8_2 in_walk6_2)))
 (let (($x22885 (and d_2_1 in_walk8_2 in_walk6_2)))
 (let (($x22884 (and d_2_0 in_walk8_2 in_walk6_2)))
 (let (($x22932 (or $x22884 $x22885 $x22887 $x22889 $x22891 $x22893 $x22895 $x22897 $x22899 $x22901 $x22903 $x22905 $x22907 $x22909 $x22911 $x22913 $x22915 $x22917 $x22919 $x22921 $x22923 $x22925 $x22927 $x22929 $x22931)))
 (let (($x22855 (and d_1_24 in_walk8_1 in_walk6_1)))
 (let (($x22853 (and d_1_23 in_walk8_1 in_walk6_1)))
 (let (($x22851 (and d_1_22 in_walk8_1 in_walk6_1)))
 (let (($x22849 (and d_1_21 in_walk8_1 in_walk6_1)))
 (let (($x22847 (and d_1_20 in_walk8_1 in_walk6_1)))
 (let (($x22845 (and d_1_19 in_walk8_1 in_walk6_1)))
 (let (($x22843 (and d_1_18 in_walk8_1 in_walk6_1)))
 (let (($x22841 (and d_1_17 in_walk8_1 in_walk6_1)))
 (let (($x22839 (and d_1_16 in_walk8_1 in_walk6_1)))
 (let (($x22837 (and d_1_15 in_walk8_1 in_walk6_1)))
 (let (($x22835 (and d_1_14 in_walk8_1 in_walk6_1)))
 (let (($x22833 (and d_1_13 in_walk8_1 in_walk6_1)))
 (let (($x22831 (and d_1_12 in_walk8_1 in_walk6_1)))
 (let (($x22829 (and d_1_11 in_walk8_1 in_walk6_1)))
 (let (($x22827 (and d_1_10 in_walk8_1 in_walk6_1)))
 (let (($x22825 (and d_1_9 in_walk8_1 in_walk6_1)))
 (let (($x22823 (and d_1_8 in_walk8_1 in_walk6_1)))
 (let (($x22821 (and d_1_7 in_walk8_1 in_walk6_1)))
 (let (($x22819 (and d_1_6 in_walk8_1 in_walk6_1)))
 (let (($x22817 (and d_1_5 in_walk8_1 in_walk6_1)))
 (let (($x22815 (and d_1_4 in_walk8_1 in_walk6_1)))
 (let (($x22813 (and d_1_3 in_walk8_1 in_walk6_1)))
 (let (($x22811 (and d_1_2 in_walk8_1 in_walk6_1)))
 (let (($x22809 (and d_1_1 in_walk8_1 in_walk6_1)))
 (let (($x22808 (and d_1_0 in_walk8_1 in_walk6_1)))
 (let (($x22856 (or $x22808 $x22809 $x22811 $x22813 $x22815 $x22817 $x22819 $x22821 $x22823 $x22825 $x22827 $x22829 $x22831 $x22833 $x22835 $x22837 $x22839 $x22841 $x22843 $x22845 $x22847 $x22849 $x22851 $x22853 $x22855)))
 (let (($x22779 (and d_0_24 in_walk8_0 in_walk6_0)))
 (let (($x22777 (and d_0_23 in_walk8_0 in_walk6_0)))
 (let (($x22775 (and d_0_22 in_walk8_0 in_walk6_0)))
 (let (($x22773 (and d_0_21 in_walk8_0 in_walk6_0)))
 (let (($x22771 (and d_0_20 in_walk8_0 in_walk6_0)))
 (let (($x22769 (and d_0_19 in_walk8_0 in_walk6_0)))
 (let (($x22767 (and d_0_18 in_walk8_0 in_walk6_0)))
 (let (($x22765 (and d_0_17 in_walk8_0 in_walk6_0)))
 (let (($x22763 (and d_0_16 in_walk8_0 in_walk6_0)))
 (let (($x22761 (and d_0_15 in_walk8_0 in_walk6_0)))
 (let (($x22759 (and d_0_14 in_walk8_0 in_walk6_0)))
 (let (($x22757 (and d_0_13 in_walk8_0 in_walk6_0)))
 (let (($x22755 (and d_0_12 in_walk8_0 in_walk6_0)))
 (let (($x22753 (and d_0_11 in_walk8_0 in_walk6_0)))
 (let (($x22751 (and d_0_10 in_walk8_0 in_walk6_0)))
 (let (($x22749 (and d_0_9 in_walk8_0 in_walk6_0)))
 (let (($x22747 (and d_0_8 in_walk8_0 in_walk6_0)))
 (let (($x22745 (and d_0_7 in_walk8_0 in_walk6_0)))
 (let (($x22743 (and d_0_6 in_walk8_0 in_walk6_0)))
 (let (($x22741 (and d_0_5 in_walk8_0 in_walk6_0)))
 (let (($x22739 (and d_0_4 in_walk8_0 in_walk6_0)))
 (let (($x22737 (and d_0_3 in_walk8_0 in_walk6_0)))
 (let (($x22735 (and d_0_2 in_walk8_0 in_walk6_0)))
 (let (($x22733 (and d_0_1 in_walk8_0 in_walk6_0)))
 (let (($x22732 (and d_0_0 in_walk8_0 in_walk6_0)))
 (let (($x22780 (or $x22732 $x22733 $x22735 $x22737 $x22739 $x22741 $x22743 $x22745 $x22747 $x22749 $x22751 $x22753 $x22755 $x22757 $x22759 $x22761 $x22763 $x22765 $x22767 $x22769 $x22771 $x22773 $x22775 $x22777 $x22779)))
 (let (($x22730 (or false $x22780)))
 (let (($x22806 (or $x22730 $x22856)))
 (let (($x22882 (or $x22806 $x22932)))
 (let (($x15887 (not (or (or (or (or false d_0_14) d_1_14) d_2_14) d_3_14))))
 (let (($x22700 (and d_3_24 in_walk7_3 in_walk6_3)))
 (let (($x22698 (and d_3_23 in_walk7_3 in_walk6_3)))
 (let (($x22696 (and d_3_22 in_walk7_3 in_walk6_3)))
 (let (($x22694 (and d_3_21 in_walk7_3 in_walk6_3)))
 (let (($x22692 (and d_3_20 in_walk7_3 in_walk6_3)))
 (let (($x22690 (and d_3_19 in_walk7_3 in_walk6_3)))
 (let (($x22688 (and d_3_18 in_walk7_3 in_walk6_3)))
 (let (($x22686 (and d_3_17 in_walk7_3 in_walk6_3)))
 (let (($x22684 (and d_3_16 in_walk7_3 in_walk6_3)))
 (let (($x22682 (and d_3_15 in_walk7_3 in_walk6_3)))
 (let (($x22680 (and d_3_14 in_walk7_3 in_walk6_3)))
 (let (($x22678 (and d_3_13 in_walk7_3 in_walk6_3)))
 (let (($x22676 (and d_3_12 in_walk7_3 in_walk6_3)))
 (let (($x22674 (and d_3_11 in_walk7_3 in_walk6_3)))
 (let (($x22672 (and d_3_10 in_walk7_3 in_walk6_3)))
 (let (($x22670 (and d_3_9 in_walk7_3 in_walk6_3)))
 (let (($x22668 (and d_3_8 in_walk7_3 in_walk6_3)))
 (let (($x22666 (and d_3_7 in_walk7_3 in_walk6_3)))
 (let (($x22664 (and d_3_6 in_walk7_3 in_walk6_3)))
 (let (($x22662 (and d_3_5 in_walk7_3 in_walk6_3)))
 (let (($x22660 (and d_3_4 in_walk7_3 in_walk6_3)))
 (let (($x22658 (and d_3_3 in_walk7_3 in_walk6_3)))
 (let (($x22656 (and d_3_2 in_walk7_3 in_walk6_3)))
 (let (($x22654 (and d_3_1 in_walk7_3 in_walk6_3)))
 (let (($x22653 (and d_3_0 in_walk7_3 in_walk6_3)))
 (let (($x22701 (or $x22653 $x22654 $x22656 $x22658 $x22660 $x22662 $x22664 $x22666 $x22668 $x22670 $x22672 $x22674 $x22676 $x22678 $x22680 $x22682 $x22684 $x22686 $x22688 $x22690 $x22692 $x22694 $x22696 $x22698 $x22700)))
 (let (($x22624 (and d_2_24 in_walk7_2 in_walk6_2)))
 (let (($x22622 (and d_2_23 in_walk7_2 in_walk6_2)))
 (let (($x22620 (and d_2_22 in_walk7_2 in_walk6_2)))
 (let (($x22618 (and d_2_21 in_walk7_2 in_walk6_2)))
 (let (($x22616 (and d_2_20 in_walk7_2 in_walk6_2)))
 (let (($x22614 (and d_2_19 in_walk7_2 in_walk6_2)))
 (let (($x22612 (and d_2_18 in_walk7_2 in_walk6_2)))
 (let (($x22610 (and d_2_17 in_walk7_2 in_walk6_2)))
 (let (($x22608 (and d_2_16 in_walk7_2 in_walk6_2)))
 (let (($x22606 (and d_2_15 in_walk7_2 in_walk6_2)))
 (let (($x22604 (and d_2_14 in_walk7_2 in_walk6_2)))
 (let (($x22602 (and d_2_13 in_walk7_2 in_walk6_2)))
 (let (($x22600 (and d_2_12 in_walk7_2 in_walk6_2)))
 (let (($x22598 (and d_2_11 in_walk7_2 in_walk6_2)))
 (let (($x22596 (and d_2_10 in_walk7_2 in_walk6_2)))
 (let (($x22594 (and d_2_9 in_walk7_2 in_walk6_2)))
 (let (($x22592 (and d_2_8 in_walk7_2 in_walk6_2)))
 (let (($x22590 (and d_2_7 in_walk7_2 in_walk6_2)))
 (let (($x22588 (and d_2_6 in_walk7_2 in_walk6_2)))
 (let (($x22586 (and d_2_5 in_walk7_2 in_walk6_2)))
 (let (($x22584 (and d_2_4 in_walk7_2 in_walk6_2)))
 (let (($x22582 (and d_2_3 in_walk7_2 in_walk6_2)))
 (let (($x22580 (and d_2_2 in_walk7_2 in_walk6_2)))
 (let (($x22578 (and d_2_1 in_walk7_2 in_walk6_2)))
 (let (($x22577 (and d_2_0 in_walk7_2 in_walk6_2)))
 (let (($x22625 (or $x22577 $x22578 $x22580 $x22582 $x22584 $x22586 $x22588 $x22590 $x22592 $x22594 $x22596 $x22598 $x22600 $x22602 $x22604 $x22606 $x22608 $x22610 $x22612 $x22614 $x22616 $x22618 $x22620 $x22622 $x22624)))
 (let (($x22548 (and d_1_24 in_walk7_1 in_walk6_1)))
 (let (($x22546 (and d_1_23 in_walk7_1 in_walk6_1)))
 (let (($x22544 (and d_1_22 in_walk7_1 in_walk6_1)))
 (let (($x22542 (and d_1_21 in_walk7_1 in_walk6_1)))
 (let (($x22540 (and d_1_20 in_walk7_1 in_walk6_1)))
 (let (($x22538 (and d_1_19 in_walk7_1 in_walk6_1)))
 (let (($x22536 (and d_1_18 in_walk7_1 in_walk6_1)))
 (let (($x22534 (and d_1_17 in_walk7_1 in_walk6_1)))
 (let (($x22532 (and d_1_16 in_walk7_1 in_walk6_1)))
 (let (($x22530 (and d_1_15 in_walk7_1 in_walk6_1)))
 (let (($x22528 (and d_1_14 in_walk7_1 in_walk6_1)))
 (let (($x22526 (and d_1_13 in_walk7_1 in_walk6_1)))
 (let (($x22524 (and d_1_12 in_walk7_1 in_walk6_1)))
 (let (($x22522 (and d_1_11 in_walk7_1 in_walk6_1)))
 (let (($x22520 (and d_1_10 in_walk7_1 in_walk6_1)))
 (let (($x22518 (and d_1_9 in_walk7_1 in_walk6_1)))
 (let (($x22516 (and d_1_8 in_walk7_1 in_walk6_1)))
 (let (($x22514 (and d_1_7 in_walk7_1 in_walk6_1)))
 (let (($x22512 (and d_1_6 in_walk7_1 in_walk6_1)))
 (let (($x22510 (and d_1_5 in_walk7_1 in_walk6_1)))
 (let (($x22508 (and d_1_4 in_walk7_1 in_walk6_1)))
 (let (($x22506 (and d_1_3 in_walk7_1 in_walk6_1)))
 (let (($x22504 (and d_1_2 in_walk7_1 in_walk6_1)))
 (let (($x22502 (and d_1_1 in_walk7_1 in_walk6_1)))
 (let (($x22501 (and d_1_0 in_walk7_1 in_walk6_1)))
 (let (($x22549 (or $x22501 $x22502 $x22504 $x22506 $x22508 $x22510 $x22512 $x22514 $x22516 $x22518 $x22520 $x22522 $x22524 $x22526 $x22528 $x22530 $x22532 $x22534 $x22536 $x22538 $x22540 $x22542 $x22544 $x22546 $x22548)))
 (let (($x22472 (and d_0_24 in_walk7_0 in_walk6_0)))
 (let (($x22470 (and d_0_23 in_walk7_0 in_walk6_0)))
 (let (($x22468 (and d_0_22 in_walk7_0 in_walk6_0)))
 (let (($x22466 (and d_0_21 in_walk7_0 in_walk6_0)))
 (let (($x22464 (and d_0_20 in_walk7_0 in_walk6_0)))
 (let (($x22462 (and d_0_19 in_walk7_0 in_walk6_0)))
 (let (($x22460 (and d_0_18 in_walk7_0 in_walk6_0)))
 (let (($x22458 (and d_0_17 in_walk7_0 in_walk6_0)))
 (let (($x22456 (and d_0_16 in_walk7_0 in_walk6_0)))
 (let (($x22454 (and d_0_15 in_walk7_0 in_walk6_0)))
 (let (($x22452 (and d_0_14 in_walk7_0 in_walk6_0)))
 (let (($x22450 (and d_0_13 in_walk7_0 in_walk6_0)))
 (let (($x22448 (and d_0_12 in_walk7_0 in_walk6_0)))
 (let (($x22446 (and d_0_11 in_walk7_0 in_walk6_0)))
 (let (($x22444 (and d_0_10 in_walk7_0 in_walk6_0)))
 (let (($x22442 (and d_0_9 in_walk7_0 in_walk6_0)))
 (let (($x22440 (and d_0_8 in_walk7_0 in_walk6_0)))
 (let (($x22438 (and d_0_7 in_walk7_0 in_walk6_0)))
 (let (($x22436 (and d_0_6 in_walk7_0 in_walk6_0)))
 (let (($x22434 (and d_0_5 in_walk7_0 in_walk6_0)))
 (let (($x22432 (and d_0_4 in_walk7_0 in_walk6_0)))
 (let (($x22430 (and d_0_3 in_walk7_0 in_walk6_0)))
 (let (($x22428 (and d_0_2 in_walk7_0 in_walk6_0)))
 (let (($x22426 (and d_0_1 in_walk7_0 in_walk6_0)))
 (let (($x22425 (and d_0_0 in_walk7_0 in_walk6_0)))
 (let (($x22473 (or $x22425 $x22426 $x22428 $x22430 $x22432 $x22434 $x22436 $x22438 $x22440 $x22442 $x22444 $x22446 $x22448 $x22450 $x22452 $x22454 $x22456 $x22458 $x22460 $x22462 $x22464 $x22466 $x22468 $x22470 $x22472)))
 (let (($x22423 (or false $x22473)))
 (let (($x22499 (or $x22423 $x22549)))
 (let (($x22575 (or $x22499 $x22625)))
 (let (($x22393 (and d_3_24 in_walk8_3 in_walk5_3)))
 (let (($x22391 (and d_3_23 in_walk8_3 in_walk5_3)))
 (let (($x22389 (and d_3_22 in_walk8_3 in_walk5_3)))
 (let (($x22387 (and d_3_21 in_walk8_3 in_walk5_3)))
 (let (($x22385 (and d_3_20 in_walk8_3 in_walk5_3)))
 (let (($x22383 (and d_3_19 in_walk8_3 in_walk5_3)))
 (let (($x22381 (and d_3_18 in_walk8_3 in_walk5_3)))
 (let (($x22379 (and d_3_17 in_walk8_3 in_walk5_3)))
 (let (($x22377 (and d_3_16 in_walk8_3 in_walk5_3)))
 (let (($x22375 (and d_3_15 in_walk8_3 in_walk5_3)))
 (let (($x22373 (and d_3_14 in_walk8_3 in_walk5_3)))
 (let (($x22371 (and d_3_13 in_walk8_3 in_walk5_3)))
 (let (($x22369 (and d_3_12 in_walk8_3 in_walk5_3)))
 (let (($x22367 (and d_3_11 in_walk8_3 in_walk5_3)))
 (let (($x22365 (and d_3_10 in_walk8_3 in_walk5_3)))
 (let (($x22363 (and d_3_9 in_walk8_3 in_walk5_3)))
 (let (($x22361 (and d_3_8 in_walk8_3 in_walk5_3)))
 (let (($x22359 (and d_3_7 in_walk8_3 in_walk5_3)))
 (let (($x22357 (and d_3_6 in_walk8_3 in_walk5_3)))
 (let (($x22355 (and d_3_5 in_walk8_3 in_walk5_3)))
 (let (($x22353 (and d_3_4 in_walk8_3 in_walk5_3)))
 (let (($x22351 (and d_3_3 in_walk8_3 in_walk5_3)))
 (let (($x22349 (and d_3_2 in_walk8_3 in_walk5_3)))
 (let (($x22347 (and d_3_1 in_walk8_3 in_walk5_3)))
 (let (($x22346 (and d_3_0 in_walk8_3 in_walk5_3)))
 (let (($x22394 (or $x22346 $x22347 $x22349 $x22351 $x22353 $x22355 $x22357 $x22359 $x22361 $x22363 $x22365 $x22367 $x22369 $x22371 $x22373 $x22375 $x22377 $x22379 $x22381 $x22383 $x22385 $x22387 $x22389 $x22391 $x22393)))
 (let (($x22317 (and d_2_24 in_walk8_2 in_walk5_2)))
 (let (($x22315 (and d_2_23 in_walk8_2 in_walk5_2)))
 (let (($x22313 (and d_2_22 in_walk8_2 in_walk5_2)))
 (let (($x22311 (and d_2_21 in_walk8_2 in_walk5_2)))
 (let (($x22309 (and d_2_20 in_walk8_2 in_walk5_2)))
 (let (($x22307 (and d_2_19 in_walk8_2 in_walk5_2)))
 (let (($x22305 (and d_2_18 in_walk8_2 in_walk5_2)))
 (let (($x22303 (and d_2_17 in_walk8_2 in_walk5_2)))
 (let (($x22301 (and d_2_16 in_walk8_2 in_walk5_2)))
 (let (($x22299 (and d_2_15 in_walk8_2 in_walk5_2)))
 (let (($x22297 (and d_2_14 in_walk8_2 in_walk5_2)))
 (let (($x22295 (and d_2_13 in_walk8_2 in_walk5_2)))
 (let (($x22293 (and d_2_12 in_walk8_2 in_walk5_2)))
 (let (($x22291 (and d_2_11 in_walk8_2 in_walk5_2)))
 (let (($x22289 (and d_2_10 in_walk8_2 in_walk5_2)))
 (let (($x22287 (and d_2_9 in_walk8_2 in_walk5_2)))
 (let (($x22285 (and d_2_8 in_walk8_2 in_walk5_2)))
 (let (($x22283 (and d_2_7 in_walk8_2 in_walk5_2)))
 (let (($x22281 (and d_2_6 in_walk8_2 in_walk5_2)))
 (let (($x22279 (and d_2_5 in_walk8_2 in_walk5_2)))
 (let (($x22277 (and d_2_4 in_walk8_2 in_walk5_2)))
 (let (($x22275 (and d_2_3 in_walk8_2 in_walk5_2)))
 (let (($x22273 (and d_2_2 in_walk8_2 in_walk5_2)))
 (let (($x22271 (and d_2_1 in_walk8_2 in_walk5_2)))
 (let (($x22270 (and d_2_0 in_walk8_2 in_walk5_2)))
 (let (($x22318 (or $x22270 $x22271 $x22273 $x22275 $x22277 $x22279 $x22281 $x22283 $x22285 $x22287 $x22289 $x22291 $x22293 $x22295 $x22297 $x22299 $x22301 $x22303 $x22305 $x22307 $x22309 $x22311 $x22313 $x22315 $x22317)))
 (let (($x22241 (and d_1_24 in_walk8_1 in_walk5_1)))
 (let (($x22239 (and d_1_23 in_walk8_1 in_walk5_1)))
 (let (($x22237 (and d_1_22 in_walk8_1 in_walk5_1)))
 (let (($x22235 (and d_1_21 in_walk8_1 in_walk5_1)))
 (let (($x22233 (and d_1_20 in_walk8_1 in_walk5_1)))
 (let (($x22231 (and d_1_19 in_walk8_1 in_walk5_1)))
 (let (($x22229 (and d_1_18 in_walk8_1 in_walk5_1)))
 (let (($x22227 (and d_1_17 in_walk8_1 in_walk5_1)))
 (let (($x22225 (and d_1_16 in_walk8_1 in_walk5_1)))
 (let (($x22223 (and d_1_15 in_walk8_1 in_walk5_1)))
 (let (($x22221 (and d_1_14 in_walk8_1 in_walk5_1)))
 (let (($x22219 (and d_1_13 in_walk8_1 in_walk5_1)))
 (let (($x22217 (and d_1_12 in_walk8_1 in_walk5_1)))
 (let (($x22215 (and d_1_11 in_walk8_1 in_walk5_1)))
 (let (($x22213 (and d_1_10 in_walk8_1 in_walk5_1)))
 (let (($x22211 (and d_1_9 in_walk8_1 in_walk5_1)))
 (let (($x22209 (and d_1_8 in_walk8_1 in_walk5_1)))
 (let (($x22207 (and d_1_7 in_walk8_1 in_walk5_1)))
 (let (($x22205 (and d_1_6 in_walk8_1 in_walk5_1)))
 (let (($x22203 (and d_1_5 in_walk8_1 in_walk5_1)))
 (let (($x22201 (and d_1_4 in_walk8_1 in_walk5_1)))
 (let (($x22199 (and d_1_3 in_walk8_1 in_walk5_1)))
 (let (($x22197 (and d_1_2 in_walk8_1 in_walk5_1)))
 (let (($x22195 (and d_1_1 in_walk8_1 in_walk5_1)))
 (let (($x22194 (and d_1_0 in_walk8_1 in_walk5_1)))
 (let (($x22242 (or $x22194 $x22195 $x22197 $x22199 $x22201 $x22203 $x22205 $x22207 $x22209 $x22211 $x22213 $x22215 $x22217 $x22219 $x22221 $x22223 $x22225 $x22227 $x22229 $x22231 $x22233 $x22235 $x22237 $x22239 $x22241)))
 (let (($x22165 (and d_0_24 in_walk8_0 in_walk5_0)))
 (let (($x22163 (and d_0_23 in_walk8_0 in_walk5_0)))
 (let (($x22161 (and d_0_22 in_walk8_0 in_walk5_0)))
 (let (($x22159 (and d_0_21 in_walk8_0 in_walk5_0)))
 (let (($x22157 (and d_0_20 in_walk8_0 in_walk5_0)))
 (let (($x22155 (and d_0_19 in_walk8_0 in_walk5_0)))
 (let (($x22153 (and d_0_18 in_walk8_0 in_walk5_0)))
 (let (($x22151 (and d_0_17 in_walk8_0 in_walk5_0)))
 (let (($x22149 (and d_0_16 in_walk8_0 in_walk5_0)))
 (let (($x22147 (and d_0_15 in_walk8_0 in_walk5_0)))
 (let (($x22145 (and d_0_14 in_walk8_0 in_walk5_0)))
 (let (($x22143 (and d_0_13 in_walk8_0 in_walk5_0)))
 (let (($x22141 (and d_0_12 in_walk8_0 in_walk5_0)))
 (let (($x22139 (and d_0_11 in_walk8_0 in_walk5_0)))
 (let (($x22137 (and d_0_10 in_walk8_0 in_walk5_0)))
 (let (($x22135 (and d_0_9 in_walk8_0 in_walk5_0)))
 (let (($x22133 (and d_0_8 in_walk8_0 in_walk5_0)))
 (let (($x22131 (and d_0_7 in_walk8_0 in_walk5_0)))
 (let (($x22129 (and d_0_6 in_walk8_0 in_walk5_0)))
 (let (($x22127 (and d_0_5 in_walk8_0 in_walk5_0)))
 (let (($x22125 (and d_0_4 in_walk8_0 in_walk5_0)))
 (let (($x22123 (and d_0_3 in_walk8_0 in_walk5_0)))
 (let (($x22121 (and d_0_2 in_walk8_0 in_walk5_0)))
 (let (($x22119 (and d_0_1 in_walk8_0 in_walk5_0)))
 (let (($x22118 (and d_0_0 in_walk8_0 in_walk5_0)))
 (let (($x22166 (or $x22118 $x22119 $x22121 $x22123 $x22125 $x22127 $x22129 $x22131 $x22133 $x22135 $x22137 $x22139 $x22141 $x22143 $x22145 $x22147 $x22149 $x22151 $x22153 $x22155 $x22157 $x22159 $x22161 $x22163 $x22165)))
 (let (($x22116 (or false $x22166)))
 (let (($x22192 (or $x22116 $x22242)))
 (let (($x22268 (or $x22192 $x22318)))
 (let (($x15572 (not (or (or (or (or false d_0_13) d_1_13) d_2_13) d_3_13))))
 (let (($x22086 (and d_3_24 in_walk7_3 in_walk5_3)))
 (let (($x22084 (and d_3_23 in_walk7_3 in_walk5_3)))
 (let (($x22082 (and d_3_22 in_walk7_3 in_walk5_3)))
 (let (($x22080 (and d_3_21 in_walk7_3 in_walk5_3)))
 (let (($x22078 (and d_3_20 in_walk7_3 in_walk5_3)))
 (let (($x22076 (and d_3_19 in_walk7_3 in_walk5_3)))
 (let (($x22074 (and d_3_18 in_walk7_3 in_walk5_3)))
 (let (($x22072 (and d_3_17 in_walk7_3 in_walk5_3)))
 (let (($x22070 (and d_3_16 in_walk7_3 in_walk5_3)))
 (let (($x22068 (and d_3_15 in_walk7_3 in_walk5_3)))
 (let (($x22066 (and d_3_14 in_walk7_3 in_walk5_3)))
 (let (($x22064 (and d_3_13 in_walk7_3 in_walk5_3)))
 (let (($x22062 (and d_3_12 in_walk7_3 in_walk5_3)))
 (let (($x22060 (and d_3_11 in_walk7_3 in_walk5_3)))
 (let (($x22058 (and d_3_10 in_walk7_3 in_walk5_3)))
 (let (($x22056 (and d_3_9 in_walk7_3 in_walk5_3)))
 (let (($x22054 (and d_3_8 in_walk7_3 in_walk5_3)))
 (let (($x22052 (and d_3_7 in_walk7_3 in_walk5_3)))
 (let (($x22050 (and d_3_6 in_walk7_3 in_walk5_3)))
 (let (($x22048 (and d_3_5 in_walk7_3 in_walk5_3)))
 (let (($x22046 (and d_3_4 in_walk7_3 in_walk5_3)))
 (let (($x22044 (and d_3_3 in_walk7_3 in_walk5_3)))
 (let (($x22042 (and d_3_2 in_walk7_3 in_walk5_3)))
 (let (($x22040 (and d_3_1 in_walk7_3 in_walk5_3)))
 (let (($x22039 (and d_3_0 in_walk7_3 in_walk5_3)))
 (let (($x22087 (or $x22039 $x22040 $x22042 $x22044 $x22046 $x22048 $x22050 $x22052 $x22054 $x22056 $x22058 $x22060 $x22062 $x22064 $x22066 $x22068 $x22070 $x22072 $x22074 $x22076 $x22078 $x22080 $x22082 $x22084 $x22086)))
 (let (($x22010 (and d_2_24 in_walk7_2 in_walk5_2)))
 (let (($x22008 (and d_2_23 in_walk7_2 in_walk5_2)))
 (let (($x22006 (and d_2_22 in_walk7_2 in_walk5_2)))
 (let (($x22004 (and d_2_21 in_walk7_2 in_walk5_2)))
 (let (($x22002 (and d_2_20 in_walk7_2 in_walk5_2)))
 (let (($x22000 (and d_2_19 in_walk7_2 in_walk5_2)))
 (let (($x21998 (and d_2_18 in_walk7_2 in_walk5_2)))
 (let (($x21996 (and d_2_17 in_walk7_2 in_walk5_2)))
 (let (($x21994 (and d_2_16 in_walk7_2 in_walk5_2)))
 (let (($x21992 (and d_2_15 in_walk7_2 in_walk5_2)))
 (let (($x21990 (and d_2_14 in_walk7_2 in_walk5_2)))
 (let (($x21988 (and d_2_13 in_walk7_2 in_walk5_2)))
 (let (($x21986 (and d_2_12 in_walk7_2 in_walk5_2)))
 (let (($x21984 (and d_2_11 in_walk7_2 in_walk5_2)))
 (let (($x21982 (and d_2_10 in_walk7_2 in_walk5_2)))
 (let (($x21980 (and d_2_9 in_walk7_2 in_walk5_2)))
 (let (($x21978 (and d_2_8 in_walk7_2 in_walk5_2)))
 (let (($x21976 (and d_2_7 in_walk7_2 in_walk5_2)))
 (let (($x21974 (and d_2_6 in_walk7_2 in_walk5_2)))
 (let (($x21972 (and d_2_5 in_walk7_2 in_walk5_2)))
 (let (($x21970 (and d_2_4 in_walk7_2 in_walk5_2)))
 (let (($x21968 (and d_2_3 in_walk7_2 in_walk5_2)))
 (let (($x21966 (and d_2_2 in_walk7_2 in_walk5_2)))
 (let (($x21964 (and d_2_1 in_walk7_2 in_walk5_2)))
 (let (($x21963 (and d_2_0 in_walk7_2 in_walk5_2)))
 (let (($x22011 (or $x21963 $x21964 $x21966 $x21968 $x21970 $x21972 $x21974 $x21976 $x21978 $x21980 $x21982 $x21984 $x21986 $x21988 $x21990 $x21992 $x21994 $x21996 $x21998 $x22000 $x22002 $x22004 $x22006 $x22008 $x22010)))
 (let (($x21934 (and d_1_24 in_walk7_1 in_walk5_1)))
 (let (($x21932 (and d_1_23 in_walk7_1 in_walk5_1)))
 (let (($x21930 (and d_1_22 in_walk7_1 in_walk5_1)))
 (let (($x21928 (and d_1_21 in_walk7_1 in_walk5_1)))
 (let (($x21926 (and d_1_20 in_walk7_1 in_walk5_1)))
 (let (($x21924 (and d_1_19 in_walk7_1 in_walk5_1)))
 (let (($x21922 (and d_1_18 in_walk7_1 in_walk5_1)))
 (let (($x21920 (and d_1_17 in_walk7_1 in_walk5_1)))
 (let (($x21918 (and d_1_16 in_walk7_1 in_walk5_1)))
 (let (($x21916 (and d_1_15 in_walk7_1 in_walk5_1)))
 (let (($x21914 (and d_1_14 in_walk7_1 in_walk5_1)))
 (let (($x21912 (and d_1_13 in_walk7_1 in_walk5_1)))
 (let (($x21910 (and d_1_12 in_walk7_1 in_walk5_1)))
 (let (($x21908 (and d_1_11 in_walk7_1 in_walk5_1)))
 (let (($x21906 (and d_1_10 in_walk7_1 in_walk5_1)))
 (let (($x21904 (and d_1_9 in_walk7_1 in_walk5_1)))
 (let (($x21902 (and d_1_8 in_walk7_1 in_walk5_1)))
 (let (($x21900 (and d_1_7 in_walk7_1 in_walk5_1)))
 (let (($x21898 (and d_1_6 in_walk7_1 in_walk5_1)))
 (let (($x21896 (and d_1_5 in_walk7_1 in_walk5_1)))
 (let (($x21894 (and d_1_4 in_walk7_1 in_walk5_1)))
 (let (($x21892 (and d_1_3 in_walk7_1 in_walk5_1)))
 (let (($x21890 (and d_1_2 in_walk7_1 in_walk5_1)))
 (let (($x21888 (and d_1_1 in_walk7_1 in_walk5_1)))
 (let (($x21887 (and d_1_0 in_walk7_1 in_walk5_1)))
 (let (($x21935 (or $x21887 $x21888 $x21890 $x21892 $x21894 $x21896 $x21898 $x21900 $x21902 $x21904 $x21906 $x21908 $x21910 $x21912 $x21914 $x21916 $x21918 $x21920 $x21922 $x21924 $x21926 $x21928 $x21930 $x21932 $x21934)))
 (let (($x21858 (and d_0_24 in_walk7_0 in_walk5_0)))
 (let (($x21856 (and d_0_23 in_walk7_0 in_walk5_0)))
 (let (($x21854 (and d_0_22 in_walk7_0 in_walk5_0)))
 (let (($x21852 (and d_0_21 in_walk7_0 in_walk5_0)))
 (let (($x21850 (and d_0_20 in_walk7_0 in_walk5_0)))
 (let (($x21848 (and d_0_19 in_walk7_0 in_walk5_0)))
 (let (($x21846 (and d_0_18 in_walk7_0 in_walk5_0)))
 (let (($x21844 (and d_0_17 in_walk7_0 in_walk5_0)))
 (let (($x21842 (and d_0_16 in_walk7_0 in_walk5_0)))
 (let (($x21840 (and d_0_15 in_walk7_0 in_walk5_0)))
 (let (($x21838 (and d_0_14 in_walk7_0 in_walk5_0)))
 (let (($x21836 (and d_0_13 in_walk7_0 in_walk5_0)))
 (let (($x21834 (and d_0_12 in_walk7_0 in_walk5_0)))
 (let (($x21832 (and d_0_11 in_walk7_0 in_walk5_0)))
 (let (($x21830 (and d_0_10 in_walk7_0 in_walk5_0)))
 (let (($x21828 (and d_0_9 in_walk7_0 in_walk5_0)))
 (let (($x21826 (and d_0_8 in_walk7_0 in_walk5_0)))
 (let (($x21824 (and d_0_7 in_walk7_0 in_walk5_0)))
 (let (($x21822 (and d_0_6 in_walk7_0 in_walk5_0)))
 (let (($x21820 (and d_0_5 in_walk7_0 in_walk5_0)))
 (let (($x21818 (and d_0_4 in_walk7_0 in_walk5_0)))
 (let (($x21816 (and d_0_3 in_walk7_0 in_walk5_0)))
 (let (($x21814 (and d_0_2 in_walk7_0 in_walk5_0)))
 (let (($x21812 (and d_0_1 in_walk7_0 in_walk5_0)))
 (let (($x21811 (and d_0_0 in_walk7_0 in_walk5_0)))
 (let (($x21859 (or $x21811 $x21812 $x21814 $x21816 $x21818 $x21820 $x21822 $x21824 $x21826 $x21828 $x21830 $x21832 $x21834 $x21836 $x21838 $x21840 $x21842 $x21844 $x21846 $x21848 $x21850 $x21852 $x21854 $x21856 $x21858)))
 (let (($x21809 (or false $x21859)))
 (let (($x21885 (or $x21809 $x21935)))
 (let (($x21961 (or $x21885 $x22011)))
 (let (($x21779 (and d_3_24 in_walk6_3 in_walk5_3)))
 (let (($x21777 (and d_3_23 in_walk6_3 in_walk5_3)))
 (let (($x21775 (and d_3_22 in_walk6_3 in_walk5_3)))
 (let (($x21773 (and d_3_21 in_walk6_3 in_walk5_3)))
 (let (($x21771 (and d_3_20 in_walk6_3 in_walk5_3)))
 (let (($x21769 (and d_3_19 in_walk6_3 in_walk5_3)))
 (let (($x21767 (and d_3_18 in_walk6_3 in_walk5_3)))
 (let (($x21765 (and d_3_17 in_walk6_3 in_walk5_3)))
 (let (($x21763 (and d_3_16 in_walk6_3 in_walk5_3)))
 (let (($x21761 (and d_3_15 in_walk6_3 in_walk5_3)))
 (let (($x21759 (and d_3_14 in_walk6_3 in_walk5_3)))
 (let (($x21757 (and d_3_13 in_walk6_3 in_walk5_3)))
 (let (($x21755 (and d_3_12 in_walk6_3 in_walk5_3)))
 (let (($x21753 (and d_3_11 in_walk6_3 in_walk5_3)))
 (let (($x21751 (and d_3_10 in_walk6_3 in_walk5_3)))
 (let (($x21749 (and d_3_9 in_walk6_3 in_walk5_3)))
 (let (($x21747 (and d_3_8 in_walk6_3 in_walk5_3)))
 (let (($x21745 (and d_3_7 in_walk6_3 in_walk5_3)))
 (let (($x21743 (and d_3_6 in_walk6_3 in_walk5_3)))
 (let (($x21741 (and d_3_5 in_walk6_3 in_walk5_3)))
 (let (($x21739 (and d_3_4 in_walk6_3 in_walk5_3)))
 (let (($x21737 (and d_3_3 in_walk6_3 in_walk5_3)))
 (let (($x21735 (and d_3_2 in_walk6_3 in_walk5_3)))
 (let (($x21733 (and d_3_1 in_walk6_3 in_walk5_3)))
 (let (($x21732 (and d_3_0 in_walk6_3 in_walk5_3)))
 (let (($x21780 (or $x21732 $x21733 $x21735 $x21737 $x21739 $x21741 $x21743 $x21745 $x21747 $x21749 $x21751 $x21753 $x21755 $x21757 $x21759 $x21761 $x21763 $x21765 $x21767 $x21769 $x21771 $x21773 $x21775 $x21777 $x21779)))
 (let (($x21703 (and d_2_24 in_walk6_2 in_walk5_2)))
 (let (($x21701 (and d_2_23 in_walk6_2 in_walk5_2)))
 (let (($x21699 (and d_2_22 in_walk6_2 in_walk5_2)))
 (let (($x21697 (and d_2_21 in_walk6_2 in_walk5_2)))
 (let (($x21695 (and d_2_20 in_walk6_2 in_walk5_2)))
 (let (($x21693 (and d_2_19 in_walk6_2 in_walk5_2)))
 (let (($x21691 (and d_2_18 in_walk6_2 in_walk5_2)))
 (let (($x21689 (and d_2_17 in_walk6_2 in_walk5_2)))
 (let (($x21687 (and d_2_16 in_walk6_2 in_walk5_2)))
 (let (($x21685 (and d_2_15 in_walk6_2 in_walk5_2)))
 (let (($x21683 (and d_2_14 in_walk6_2 in_walk5_2)))
 (let (($x21681 (and d_2_13 in_walk6_2 in_walk5_2)))
 (let (($x21679 (and d_2_12 in_walk6_2 in_walk5_2)))
 (let (($x21677 (and d_2_11 in_walk6_2 in_walk5_2)))
 (let (($x21675 (and d_2_10 in_walk6_2 in_walk5_2)))
 (let (($x21673 (and d_2_9 in_walk6_2 in_walk5_2)))
 (let (($x21671 (and d_2_8 in_walk6_2 in_walk5_2)))
 (let (($x21669 (and d_2_7 in_walk6_2 in_walk5_2)))
 (let (($x21667 (and d_2_6 in_walk6_2 in_walk5_2)))
 (let (($x21665 (and d_2_5 in_walk6_2 in_walk5_2)))
 (let (($x21663 (and d_2_4 in_walk6_2 in_walk5_2)))
 (let (($x21661 (and d_2_3 in_walk6_2 in_walk5_2)))
 (let (($x21659 (and d_2_2 in_walk6_2 in_walk5_2)))
 (let (($x21657 (and d_2_1 in_walk6_2 in_walk5_2)))
 (let (($x21656 (and d_2_0 in_walk6_2 in_walk5_2)))
 (let (($x21704 (or $x21656 $x21657 $x21659 $x21661 $x21663 $x21665 $x21667 $x21669 $x21671 $x21673 $x21675 $x21677 $x21679 $x21681 $x21683 $x21685 $x21687 $x21689 $x21691 $x21693 $x21695 $x21697 $x21699 $x21701 $x21703)))
 (let (($x21627 (and d_1_24 in_walk6_1 in_walk5_1)))
 (let (($x21625 (and d_1_23 in_walk6_1 in_walk5_1)))
 (let (($x21623 (and d_1_22 in_walk6_1 in_walk5_1)))
 (let (($x21621 (and d_1_21 in_walk6_1 in_walk5_1)))
 (let (($x21619 (and d_1_20 in_walk6_1 in_walk5_1)))
 (let (($x21617 (and d_1_19 in_walk6_1 in_walk5_1)))
 (let (($x21615 (and d_1_18 in_walk6_1 in_walk5_1)))
 (let (($x21613 (and d_1_17 in_walk6_1 in_walk5_1)))
 (let (($x21611 (and d_1_16 in_walk6_1 in_walk5_1)))
 (let (($x21609 (and d_1_15 in_walk6_1 in_walk5_1)))
 (let (($x21607 (and d_1_14 in_walk6_1 in_walk5_1)))
 (let (($x21605 (and d_1_13 in_walk6_1 in_walk5_1)))
 (let (($x21603 (and d_1_12 in_walk6_1 in_walk5_1)))
 (let (($x21601 (and d_1_11 in_walk6_1 in_walk5_1)))
 (let (($x21599 (and d_1_10 in_walk6_1 in_walk5_1)))
 (let (($x21597 (and d_1_9 in_walk6_1 in_walk5_1)))
 (let (($x21595 (and d_1_8 in_walk6_1 in_walk5_1)))
 (let (($x21593 (and d_1_7 in_walk6_1 in_walk5_1)))
 (let (($x21591 (and d_1_6 in_walk6_1 in_walk5_1)))
 (let (($x21589 (and d_1_5 in_walk6_1 in_walk5_1)))
 (let (($x21587 (and d_1_4 in_walk6_1 in_walk5_1)))
 (let (($x21585 (and d_1_3 in_walk6_1 in_walk5_1)))
 (let (($x21583 (and d_1_2 in_walk6_1 in_walk5_1)))
 (let (($x21581 (and d_1_1 in_walk6_1 in_walk5_1)))
 (let (($x21580 (and d_1_0 in_walk6_1 in_walk5_1)))
 (let (($x21628 (or $x21580 $x21581 $x21583 $x21585 $x21587 $x21589 $x21591 $x21593 $x21595 $x21597 $x21599 $x21601 $x21603 $x21605 $x21607 $x21609 $x21611 $x21613 $x21615 $x21617 $x21619 $x21621 $x21623 $x21625 $x21627)))
 (let (($x21551 (and d_0_24 in_walk6_0 in_walk5_0)))
 (let (($x21549 (and d_0_23 in_walk6_0 in_walk5_0)))
 (let (($x21547 (and d_0_22 in_walk6_0 in_walk5_0)))
 (let (($x21545 (and d_0_21 in_walk6_0 in_walk5_0)))
 (let (($x21543 (and d_0_20 in_walk6_0 in_walk5_0)))
 (let (($x21541 (and d_0_19 in_walk6_0 in_walk5_0)))
 (let (($x21539 (and d_0_18 in_walk6_0 in_walk5_0)))
 (let (($x21537 (and d_0_17 in_walk6_0 in_walk5_0)))
 (let (($x21535 (and d_0_16 in_walk6_0 in_walk5_0)))
 (let (($x21533 (and d_0_15 in_walk6_0 in_walk5_0)))
 (let (($x21531 (and d_0_14 in_walk6_0 in_walk5_0)))
 (let (($x21529 (and d_0_13 in_walk6_0 in_walk5_0)))
 (let (($x21527 (and d_0_12 in_walk6_0 in_walk5_0)))
 (let (($x21525 (and d_0_11 in_walk6_0 in_walk5_0)))
 (let (($x21523 (and d_0_10 in_walk6_0 in_walk5_0)))
 (let (($x21521 (and d_0_9 in_walk6_0 in_walk5_0)))
 (let (($x21519 (and d_0_8 in_walk6_0 in_walk5_0)))
 (let (($x21517 (and d_0_7 in_walk6_0 in_walk5_0)))
 (let (($x21515 (and d_0_6 in_walk6_0 in_walk5_0)))
 (let (($x21513 (and d_0_5 in_walk6_0 in_walk5_0)))
 (let (($x21511 (and d_0_4 in_walk6_0 in_walk5_0)))
 (let (($x21509 (and d_0_3 in_walk6_0 in_walk5_0)))
 (let (($x21507 (and d_0_2 in_walk6_0 in_walk5_0)))
 (let (($x21505 (and d_0_1 in_walk6_0 in_walk5_0)))
 (let (($x21504 (and d_0_0 in_walk6_0 in_walk5_0)))
 (let (($x21552 (or $x21504 $x21505 $x21507 $x21509 $x21511 $x21513 $x21515 $x21517 $x21519 $x21521 $x21523 $x21525 $x21527 $x21529 $x21531 $x21533 $x21535 $x21537 $x21539 $x21541 $x21543 $x21545 $x21547 $x21549 $x21551)))
 (let (($x21502 (or false $x21552)))
 (let (($x21578 (or $x21502 $x21628)))
 (let (($x21654 (or $x21578 $x21704)))
 (let (($x21472 (and d_3_24 in_walk8_3 in_walk4_3)))
 (let (($x21470 (and d_3_23 in_walk8_3 in_walk4_3)))
 (let (($x21468 (and d_3_22 in_walk8_3 in_walk4_3)))
 (let (($x21466 (and d_3_21 in_walk8_3 in_walk4_3)))
 (let (($x21464 (and d_3_20 in_walk8_3 in_walk4_3)))
 (let (($x21462 (and d_3_19 in_walk8_3 in_walk4_3)))
 (let (($x21460 (and d_3_18 in_walk8_3 in_walk4_3)))
 (let (($x21458 (and d_3_17 in_walk8_3 in_walk4_3)))
 (let (($x21456 (and d_3_16 in_walk8_3 in_walk4_3)))
 (let (($x21454 (and d_3_15 in_walk8_3 in_walk4_3)))
 (let (($x21452 (and d_3_14 in_walk8_3 in_walk4_3)))
 (let (($x21450 (and d_3_13 in_walk8_3 in_walk4_3)))
 (let (($x21448 (and d_3_12 in_walk8_3 in_walk4_3)))
 (let (($x21446 (and d_3_11 in_walk8_3 in_walk4_3)))
 (let (($x21444 (and d_3_10 in_walk8_3 in_walk4_3)))
 (let (($x21442 (and d_3_9 in_walk8_3 in_walk4_3)))
 (let (($x21440 (and d_3_8 in_walk8_3 in_walk4_3)))
 (let (($x21438 (and d_3_7 in_walk8_3 in_walk4_3)))
 (let (($x21436 (and d_3_6 in_walk8_3 in_walk4_3)))
 (let (($x21434 (and d_3_5 in_walk8_3 in_walk4_3)))
 (let (($x21432 (and d_3_4 in_walk8_3 in_walk4_3)))
 (let (($x21430 (and d_3_3 in_walk8_3 in_walk4_3)))
 (let (($x21428 (and d_3_2 in_walk8_3 in_walk4_3)))
 (let (($x21426 (and d_3_1 in_walk8_3 in_walk4_3)))
 (let (($x21425 (and d_3_0 in_walk8_3 in_walk4_3)))
 (let (($x21473 (or $x21425 $x21426 $x21428 $x21430 $x21432 $x21434 $x21436 $x21438 $x21440 $x21442 $x21444 $x21446 $x21448 $x21450 $x21452 $x21454 $x21456 $x21458 $x21460 $x21462 $x21464 $x21466 $x21468 $x21470 $x21472)))
 (let (($x21396 (and d_2_24 in_walk8_2 in_walk4_2)))
 (let (($x21394 (and d_2_23 in_walk8_2 in_walk4_2)))
 (let (($x21392 (and d_2_22 in_walk8_2 in_walk4_2)))
 (let (($x21390 (and d_2_21 in_walk8_2 in_walk4_2)))
 (let (($x21388 (and d_2_20 in_walk8_2 in_walk4_2)))
 (let (($x21386 (and d_2_19 in_walk8_2 in_walk4_2)))
 (let (($x21384 (and d_2_18 in_walk8_2 in_walk4_2)))
 (let (($x21382 (and d_2_17 in_walk8_2 in_walk4_2)))
 (let (($x21380 (and d_2_16 in_walk8_2 in_walk4_2)))
 (let (($x21378 (and d_2_15 in_walk8_2 in_walk4_2)))
 (let (($x21376 (and d_2_14 in_walk8_2 in_walk4_2)))
 (let (($x21374 (and d_2_13 in_walk8_2 in_walk4_2)))
 (let (($x21372 (and d_2_12 in_walk8_2 in_walk4_2)))
 (let (($x21370 (and d_2_11 in_walk8_2 in_walk4_2)))
 (let (($x21368 (and d_2_10 in_walk8_2 in_walk4_2)))
 (let (($x21366 (and d_2_9 in_walk8_2 in_walk4_2)))
 (let (($x21364 (and d_2_8 in_walk8_2 in_walk4_2)))
 (let (($x21362 (and d_2_7 in_walk8_2 in_walk4_2)))
 (let (($x21360 (and d_2_6 in_walk8_2 in_walk4_2)))
 (let (($x21358 (and d_2_5 in_walk8_2 in_walk4_2)))
 (let (($x21356 (and d_2_4 in_walk8_2 in_walk4_2)))
 (let (($x21354 (and d_2_3 in_walk8_2 in_walk4_2)))
 (let (($x21352 (and d_2_2 in_walk8_2 in_walk4_2)))
 (let (($x21350 (and d_2_1 in_walk8_2 in_walk4_2)))
 (let (($x21349 (and d_2_0 in_walk8_2 in_walk4_2)))
 (let (($x21397 (or $x21349 $x21350 $x21352 $x21354 $x21356 $x21358 $x21360 $x21362 $x21364 $x21366 $x21368 $x21370 $x21372 $x21374 $x21376 $x21378 $x21380 $x21382 $x21384 $x21386 $x21388 $x21390 $x21392 $x21394 $x21396)))
 (let (($x21320 (and d_1_24 in_walk8_1 in_walk4_1)))
 (let (($x21318 (and d_1_23 in_walk8_1 in_walk4_1)))
 (let (($x21316 (and d_1_22 in_walk8_1 in_walk4_1)))
 (let (($x21314 (and d_1_21 in_walk8_1 in_walk4_1)))
 (let (($x21312 (and d_1_20 in_walk8_1 in_walk4_1)))
 (let (($x21310 (and d_1_19 in_walk8_1 in_walk4_1)))
 (let (($x21308 (and d_1_18 in_walk8_1 in_walk4_1)))
 (let (($x21306 (and d_1_17 in_walk8_1 in_walk4_1)))
 (let (($x21304 (and d_1_16 in_walk8_1 in_walk4_1)))
 (let (($x21302 (and d_1_15 in_walk8_1 in_walk4_1)))
 (let (($x21300 (and d_1_14 in_walk8_1 in_walk4_1)))
 (let (($x21298 (and d_1_13 in_walk8_1 in_walk4_1)))
 (let (($x21296 (and d_1_12 in_walk8_1 in_walk4_1)))
 (let (($x21294 (and d_1_11 in_walk8_1 in_walk4_1)))
 (let (($x21292 (and d_1_10 in_walk8_1 in_walk4_1)))
 (let (($x21290 (and d_1_9 in_walk8_1 in_walk4_1)))
 (let (($x21288 (and d_1_8 in_walk8_1 in_walk4_1)))
 (let (($x21286 (and d_1_7 in_walk8_1 in_walk4_1)))
 (let (($x21284 (and d_1_6 in_walk8_1 in_walk4_1)))
 (let (($x21282 (and d_1_5 in_walk8_1 in_walk4_1)))
 (let (($x21280 (and d_1_4 in_walk8_1 in_walk4_1)))
 (let (($x21278 (and d_1_3 in_walk8_1 in_walk4_1)))
 (let (($x21276 (and d_1_2 in_walk8_1 in_walk4_1)))
 (let (($x21274 (and d_1_1 in_walk8_1 in_walk4_1)))
 (let (($x21273 (and d_1_0 in_walk8_1 in_walk4_1)))
 (let (($x21321 (or $x21273 $x21274 $x21276 $x21278 $x21280 $x21282 $x21284 $x21286 $x21288 $x21290 $x21292 $x21294 $x21296 $x21298 $x21300 $x21302 $x21304 $x21306 $x21308 $x21310 $x21312 $x21314 $x21316 $x21318 $x21320)))
 (let (($x21244 (and d_0_24 in_walk8_0 in_walk4_0)))
 (let (($x21242 (and d_0_23 in_walk8_0 in_walk4_0)))
 (let (($x21240 (and d_0_22 in_walk8_0 in_walk4_0)))
 (let (($x21238 (and d_0_21 in_walk8_0 in_walk4_0)))
 (let (($x21236 (and d_0_20 in_walk8_0 in_walk4_0)))
 (let (($x21234 (and d_0_19 in_walk8_0 in_walk4_0)))
 (let (($x21232 (and d_0_18 in_walk8_0 in_walk4_0)))
 (let (($x21230 (and d_0_17 in_walk8_0 in_walk4_0)))
 (let (($x21228 (and d_0_16 in_walk8_0 in_walk4_0)))
 (let (($x21226 (and d_0_15 in_walk8_0 in_walk4_0)))
 (let (($x21224 (and d_0_14 in_walk8_0 in_walk4_0)))
 (let (($x21222 (and d_0_13 in_walk8_0 in_walk4_0)))
 (let (($x21220 (and d_0_12 in_walk8_0 in_walk4_0)))
 (let (($x21218 (and d_0_11 in_walk8_0 in_walk4_0)))
 (let (($x21216 (and d_0_10 in_walk8_0 in_walk4_0)))
 (let (($x21214 (and d_0_9 in_walk8_0 in_walk4_0)))
 (let (($x21212 (and d_0_8 in_walk8_0 in_walk4_0)))
 (let (($x21210 (and d_0_7 in_walk8_0 in_walk4_0)))
 (let (($x21208 (and d_0_6 in_walk8_0 in_walk4_0)))
 (let (($x21206 (and d_0_5 in_walk8_0 in_walk4_0)))
 (let (($x21204 (and d_0_4 in_walk8_0 in_walk4_0)))
 (let (($x21202 (and d_0_3 in_walk8_0 in_walk4_0)))
 (let (($x21200 (and d_0_2 in_walk8_0 in_walk4_0)))
 (let (($x21198 (and d_0_1 in_walk8_0 in_walk4_0)))
 (let (($x21197 (and d_0_0 in_walk8_0 in_walk4_0)))
 (let (($x21245 (or $x21197 $x21198 $x21200 $x21202 $x21204 $x21206 $x21208 $x21210 $x21212 $x21214 $x21216 $x21218 $x21220 $x21222 $x21224 $x21226 $x21228 $x21230 $x21232 $x21234 $x21236 $x21238 $x21240 $x21242 $x21244)))
 (let (($x21195 (or false $x21245)))
 (let (($x21271 (or $x21195 $x21321)))
 (let (($x21347 (or $x21271 $x21397)))
 (let (($x15291 (not (or (or (or (or false d_0_12) d_1_12) d_2_12) d_3_12))))
 (let (($x21165 (and d_3_24 in_walk7_3 in_walk4_3)))
 (let (($x21163 (and d_3_23 in_walk7_3 in_walk4_3)))
 (let (($x21161 (and d_3_22 in_walk7_3 in_walk4_3)))
 (let (($x21159 (and d_3_21 in_walk7_3 in_walk4_3)))
 (let (($x21157 (and d_3_20 in_walk7_3 in_walk4_3)))
 (let (($x21155 (and d_3_19 in_walk7_3 in_walk4_3)))
 (let (($x21153 (and d_3_18 in_walk7_3 in_walk4_3)))
 (let (($x21151 (and d_3_17 in_walk7_3 in_walk4_3)))
 (let (($x21149 (and d_3_16 in_walk7_3 in_walk4_3)))
 (let (($x21147 (and d_3_15 in_walk7_3 in_walk4_3)))
 (let (($x21145 (and d_3_14 in_walk7_3 in_walk4_3)))
 (let (($x21143 (and d_3_13 in_walk7_3 in_walk4_3)))
 (let (($x21141 (and d_3_12 in_walk7_3 in_walk4_3)))
 (let (($x21139 (and d_3_11 in_walk7_3 in_walk4_3)))
 (let (($x21137 (and d_3_10 in_walk7_3 in_walk4_3)))
 (let (($x21135 (and d_3_9 in_walk7_3 in_walk4_3)))
 (let (($x21133 (and d_3_8 in_walk7_3 in_walk4_3)))
 (let (($x21131 (and d_3_7 in_walk7_3 in_walk4_3)))
 (let (($x21129 (and d_3_6 in_walk7_3 in_walk4_3)))
 (let (($x21127 (and d_3_5 in_walk7_3 in_walk4_3)))
 (let (($x21125 (and d_3_4 in_walk7_3 in_walk4_3)))
 (let (($x21123 (and d_3_3 in_walk7_3 in_walk4_3)))
 (let (($x21121 (and d_3_2 in_walk7_3 in_walk4_3)))
 (let (($x21119 (and d_3_1 in_walk7_3 in_walk4_3)))
 (let (($x21118 (and d_3_0 in_walk7_3 in_walk4_3)))
 (let (($x21166 (or $x21118 $x21119 $x21121 $x21123 $x21125 $x21127 $x21129 $x21131 $x21133 $x21135 $x21137 $x21139 $x21141 $x21143 $x21145 $x21147 $x21149 $x21151 $x21153 $x21155 $x21157 $x21159 $x21161 $x21163 $x21165)))
 (let (($x21089 (and d_2_24 in_walk7_2 in_walk4_2)))
 (let (($x21087 (and d_2_23 in_walk7_2 in_walk4_2)))
 (let (($x21085 (and d_2_22 in_walk7_2 in_walk4_2)))
 (let (($x21083 (and d_2_21 in_walk7_2 in_walk4_2)))
 (let (($x21081 (and d_2_20 in_walk7_2 in_walk4_2)))
 (let (($x21079 (and d_2_19 in_walk7_2 in_walk4_2)))
 (let (($x21077 (and d_2_18 in_walk7_2 in_walk4_2)))
 (let (($x21075 (and d_2_17 in_walk7_2 in_walk4_2)))
 (let (($x21073 (and d_2_16 in_walk7_2 in_walk4_2)))
 (let (($x21071 (and d_2_15 in_walk7_2 in_walk4_2)))
 (let (($x21069 (and d_2_14 in_walk7_2 in_walk4_2)))
 (let (($x21067 (and d_2_13 in_walk7_2 in_walk4_2)))
 (let (($x21065 (and d_2_12 in_walk7_2 in_walk4_2)))
 (let (($x21063 (and d_2_11 in_walk7_2 in_walk4_2)))
 (let (($x21061 (and d_2_10 in_walk7_2 in_walk4_2)))
 (let (($x21059 (and d_2_9 in_walk7_2 in_walk4_2)))
 (let (($x21057 (and d_2_8 in_walk7_2 in_walk4_2)))
 (let (($x21055 (and d_2_7 in_walk7_2 in_walk4_2)))
 (let (($x21053 (and d_2_6 in_walk7_2 in_walk4_2)))
 (let (($x21051 (and d_2_5 in_walk7_2 in_walk4_2)))
 (let (($x21049 (and d_2_4 in_walk7_2 in_walk4_2)))
 (let (($x21047 (and d_2_3 in_walk7_2 in_walk4_2)))
 (let (($x21045 (and d_2_2 in_walk7_2 in_walk4_2)))
 (let (($x21043 (and d_2_1 in_walk7_2 in_walk4_2)))
 (let (($x21042 (and d_2_0 in_walk7_2 in_walk4_2)))
 (let (($x21090 (or $x21042 $x21043 $x21045 $x21047 $x21049 $x21051 $x21053 $x21055 $x21057 $x21059 $x21061 $x21063 $x21065 $x21067 $x21069 $x21071 $x21073 $x21075 $x21077 $x21079 $x21081 $x21083 $x21085 $x21087 $x21089)))
 (let (($x21013 (and d_1_24 in_walk7_1 in_walk4_1)))
 (let (($x21011 (and d_1_23 in_walk7_1 in_walk4_1)))
 (let (($x21009 (and d_1_22 in_walk7_1 in_walk4_1)))
 (let (($x21007 (and d_1_21 in_walk7_1 in_walk4_1)))
 (let (($x21005 (and d_1_20 in_walk7_1 in_walk4_1)))
 (let (($x21003 (and d_1_19 in_walk7_1 in_walk4_1)))
 (let (($x21001 (and d_1_18 in_walk7_1 in_walk4_1)))
 (let (($x20999 (and d_1_17 in_walk7_1 in_walk4_1)))
 (let (($x20997 (and d_1_16 in_walk7_1 in_walk4_1)))
 (let (($x20995 (and d_1_15 in_walk7_1 in_walk4_1)))
 (let (($x20993 (and d_1_14 in_walk7_1 in_walk4_1)))
 (let (($x20991 (and d_1_13 in_walk7_1 in_walk4_1)))
 (let (($x20989 (and d_1_12 in_walk7_1 in_walk4_1)))
 (let (($x20987 (and d_1_11 in_walk7_1 in_walk4_1)))
 (let (($x20985 (and d_1_10 in_walk7_1 in_walk4_1)))
 (let (($x20983 (and d_1_9 in_walk7_1 in_walk4_1)))
 (let (($x20981 (and d_1_8 in_walk7_1 in_walk4_1)))
 (let (($x20979 (and d_1_7 in_walk7_1 in_walk4_1)))
 (let (($x20977 (and d_1_6 in_walk7_1 in_walk4_1)))
 (let (($x20975 (and d_1_5 in_walk7_1 in_walk4_1)))
 (let (($x20973 (and d_1_4 in_walk7_1 in_walk4_1)))
 (let (($x20971 (and d_1_3 in_walk7_1 in_walk4_1)))
 (let (($x20969 (and d_1_2 in_walk7_1 in_walk4_1)))
 (let (($x20967 (and d_1_1 in_walk7_1 in_walk4_1)))
 (let (($x20966 (and d_1_0 in_walk7_1 in_walk4_1)))
 (let (($x21014 (or $x20966 $x20967 $x20969 $x20971 $x20973 $x20975 $x20977 $x20979 $x20981 $x20983 $x20985 $x20987 $x20989 $x20991 $x20993 $x20995 $x20997 $x20999 $x21001 $x21003 $x21005 $x21007 $x21009 $x21011 $x21013)))
 (let (($x20937 (and d_0_24 in_walk7_0 in_walk4_0)))
 (let (($x20935 (and d_0_23 in_walk7_0 in_walk4_0)))
 (let (($x20933 (and d_0_22 in_walk7_0 in_walk4_0)))
 (let (($x20931 (and d_0_21 in_walk7_0 in_walk4_0)))
 (let (($x20929 (and d_0_20 in_walk7_0 in_walk4_0)))
 (let (($x20927 (and d_0_19 in_walk7_0 in_walk4_0)))
 (let (($x20925 (and d_0_18 in_walk7_0 in_walk4_0)))
 (let (($x20923 (and d_0_17 in_walk7_0 in_walk4_0)))
 (let (($x20921 (and d_0_16 in_walk7_0 in_walk4_0)))
 (let (($x20919 (and d_0_15 in_walk7_0 in_walk4_0)))
 (let (($x20917 (and d_0_14 in_walk7_0 in_walk4_0)))
 (let (($x20915 (and d_0_13 in_walk7_0 in_walk4_0)))
 (let (($x20913 (and d_0_12 in_walk7_0 in_walk4_0)))
 (let (($x20911 (and d_0_11 in_walk7_0 in_walk4_0)))
 (let (($x20909 (and d_0_10 in_walk7_0 in_walk4_0)))
 (let (($x20907 (and d_0_9 in_walk7_0 in_walk4_0)))
 (let (($x20905 (and d_0_8 in_walk7_0 in_walk4_0)))
 (let (($x20903 (and d_0_7 in_walk7_0 in_walk4_0)))
 (let (($x20901 (and d_0_6 in_walk7_0 in_walk4_0)))
 (let (($x20899 (and d_0_5 in_walk7_0 in_walk4_0)))
 (let (($x20897 (and d_0_4 in_walk7_0 in_walk4_0)))
 (let (($x20895 (and d_0_3 in_walk7_0 in_walk4_0)))
 (let (($x20893 (and d_0_2 in_walk7_0 in_walk4_0)))
 (let (($x20891 (and d_0_1 in_walk7_0 in_walk4_0)))
 (let (($x20890 (and d_0_0 in_walk7_0 in_walk4_0)))
 (let (($x20938 (or $x20890 $x20891 $x20893 $x20895 $x20897 $x20899 $x20901 $x20903 $x20905 $x20907 $x20909 $x20911 $x20913 $x20915 $x20917 $x20919 $x20921 $x20923 $x20925 $x20927 $x20929 $x20931 $x20933 $x20935 $x20937)))
 (let (($x20888 (or false $x20938)))
 (let (($x20964 (or $x20888 $x21014)))
 (let (($x21040 (or $x20964 $x21090)))
 (let (($x20858 (and d_3_24 in_walk6_3 in_walk4_3)))
 (let (($x20856 (and d_3_23 in_walk6_3 in_walk4_3)))
 (let (($x20854 (and d_3_22 in_walk6_3 in_walk4_3)))
 (let (($x20852 (and d_3_21 in_walk6_3 in_walk4_3)))
 (let (($x20850 (and d_3_20 in_walk6_3 in_walk4_3)))
 (let (($x20848 (and d_3_19 in_walk6_3 in_walk4_3)))
 (let (($x20846 (and d_3_18 in_walk6_3 in_walk4_3)))
 (let (($x20844 (and d_3_17 in_walk6_3 in_walk4_3)))
 (let (($x20842 (and d_3_16 in_walk6_3 in_walk4_3)))
 (let (($x20840 (and d_3_15 in_walk6_3 in_walk4_3)))
 (let (($x20838 (and d_3_14 in_walk6_3 in_walk4_3)))
 (let (($x20836 (and d_3_13 in_walk6_3 in_walk4_3)))
 (let (($x20834 (and d_3_12 in_walk6_3 in_walk4_3)))
 (let (($x20832 (and d_3_11 in_walk6_3 in_walk4_3)))
 (let (($x20830 (and d_3_10 in_walk6_3 in_walk4_3)))
 (let (($x20828 (and d_3_9 in_walk6_3 in_walk4_3)))
 (let (($x20826 (and d_3_8 in_walk6_3 in_walk4_3)))
 (let (($x20824 (and d_3_7 in_walk6_3 in_walk4_3)))
 (let (($x20822 (and d_3_6 in_walk6_3 in_walk4_3)))
 (let (($x20820 (and d_3_5 in_walk6_3 in_walk4_3)))
 (let (($x20818 (and d_3_4 in_walk6_3 in_walk4_3)))
 (let (($x20816 (and d_3_3 in_walk6_3 in_walk4_3)))
 (let (($x20814 (and d_3_2 in_walk6_3 in_walk4_3)))
 (let (($x20812 (and d_3_1 in_walk6_3 in_walk4_3)))
 (let (($x20811 (and d_3_0 in_walk6_3 in_walk4_3)))
 (let (($x20859 (or $x20811 $x20812 $x20814 $x20816 $x20818 $x20820 $x20822 $x20824 $x20826 $x20828 $x20830 $x20832 $x20834 $x20836 $x20838 $x20840 $x20842 $x20844 $x20846 $x20848 $x20850 $x20852 $x20854 $x20856 $x20858)))
 (let (($x20782 (and d_2_24 in_walk6_2 in_walk4_2)))
 (let (($x20780 (and d_2_23 in_walk6_2 in_walk4_2)))
 (let (($x20778 (and d_2_22 in_walk6_2 in_walk4_2)))
 (let (($x20776 (and d_2_21 in_walk6_2 in_walk4_2)))
 (let (($x20774 (and d_2_20 in_walk6_2 in_walk4_2)))
 (let (($x20772 (and d_2_19 in_walk6_2 in_walk4_2)))
 (let (($x20770 (and d_2_18 in_walk6_2 in_walk4_2)))
 (let (($x20768 (and d_2_17 in_walk6_2 in_walk4_2)))
 (let (($x20766 (and d_2_16 in_walk6_2 in_walk4_2)))
 (let (($x20764 (and d_2_15 in_walk6_2 in_walk4_2)))
 (let (($x20762 (and d_2_14 in_walk6_2 in_walk4_2)))
 (let (($x20760 (and d_2_13 in_walk6_2 in_walk4_2)))
 (let (($x20758 (and d_2_12 in_walk6_2 in_walk4_2)))
 (let (($x20756 (and d_2_11 in_walk6_2 in_walk4_2)))
 (let (($x20754 (and d_2_10 in_walk6_2 in_walk4_2)))
 (let (($x20752 (and d_2_9 in_walk6_2 in_walk4_2)))
 (let (($x20750 (and d_2_8 in_walk6_2 in_walk4_2)))
 (let (($x20748 (and d_2_7 in_walk6_2 in_walk4_2)))
 (let (($x20746 (and d_2_6 in_walk6_2 in_walk4_2)))
 (let (($x20744 (and d_2_5 in_walk6_2 in_walk4_2)))
 (let (($x20742 (and d_2_4 in_walk6_2 in_walk4_2)))
 (let (($x20740 (and d_2_3 in_walk6_2 in_walk4_2)))
 (let (($x20738 (and d_2_2 in_walk6_2 in_walk4_2)))
 (let (($x20736 (and d_2_1 in_walk6_2 in_walk4_2)))
 (let (($x20735 (and d_2_0 in_walk6_2 in_walk4_2)))
 (let (($x20783 (or $x20735 $x20736 $x20738 $x20740 $x20742 $x20744 $x20746 $x20748 $x20750 $x20752 $x20754 $x20756 $x20758 $x20760 $x20762 $x20764 $x20766 $x20768 $x20770 $x20772 $x20774 $x20776 $x20778 $x20780 $x20782)))
 (let (($x20706 (and d_1_24 in_walk6_1 in_walk4_1)))
 (let (($x20704 (and d_1_23 in_walk6_1 in_walk4_1)))
 (let (($x20702 (and d_1_22 in_walk6_1 in_walk4_1)))
 (let (($x20700 (and d_1_21 in_walk6_1 in_walk4_1)))
 (let (($x20698 (and d_1_20 in_walk6_1 in_walk4_1)))
 (let (($x20696 (and d_1_19 in_walk6_1 in_walk4_1)))
 (let (($x20694 (and d_1_18 in_walk6_1 in_walk4_1)))
 (let (($x20692 (and d_1_17 in_walk6_1 in_walk4_1)))
 (let (($x20690 (and d_1_16 in_walk6_1 in_walk4_1)))
 (let (($x20688 (and d_1_15 in_walk6_1 in_walk4_1)))
 (let (($x20686 (and d_1_14 in_walk6_1 in_walk4_1)))
 (let (($x20684 (and d_1_13 in_walk6_1 in_walk4_1)))
 (let (($x20682 (and d_1_12 in_walk6_1 in_walk4_1)))
 (let (($x20680 (and d_1_11 in_walk6_1 in_walk4_1)))
 (let (($x20678 (and d_1_10 in_walk6_1 in_walk4_1)))
 (let (($x20676 (and d_1_9 in_walk6_1 in_walk4_1)))
 (let (($x20674 (and d_1_8 in_walk6_1 in_walk4_1)))
 (let (($x20672 (and d_1_7 in_walk6_1 in_walk4_1)))
 (let (($x20670 (and d_1_6 in_walk6_1 in_walk4_1)))
 (let (($x20668 (and d_1_5 in_walk6_1 in_walk4_1)))
 (let (($x20666 (and d_1_4 in_walk6_1 in_walk4_1)))
 (let (($x20664 (and d_1_3 in_walk6_1 in_walk4_1)))
 (let (($x20662 (and d_1_2 in_walk6_1 in_walk4_1)))
 (let (($x20660 (and d_1_1 in_walk6_1 in_walk4_1)))
 (let (($x20659 (and d_1_0 in_walk6_1 in_walk4_1)))
 (let (($x20707 (or $x20659 $x20660 $x20662 $x20664 $x20666 $x20668 $x20670 $x20672 $x20674 $x20676 $x20678 $x20680 $x20682 $x20684 $x20686 $x20688 $x20690 $x20692 $x20694 $x20696 $x20698 $x20700 $x20702 $x20704 $x20706)))
 (let (($x20630 (and d_0_24 in_walk6_0 in_walk4_0)))
 (let (($x20628 (and d_0_23 in_walk6_0 in_walk4_0)))
 (let (($x20626 (and d_0_22 in_walk6_0 in_walk4_0)))
 (let (($x20624 (and d_0_21 in_walk6_0 in_walk4_0)))
 (let (($x20622 (and d_0_20 in_walk6_0 in_walk4_0)))
 (let (($x20620 (and d_0_19 in_walk6_0 in_walk4_0)))
 (let (($x20618 (and d_0_18 in_walk6_0 in_walk4_0)))
 (let (($x20616 (and d_0_17 in_walk6_0 in_walk4_0)))
 (let (($x20614 (and d_0_16 in_walk6_0 in_walk4_0)))
 (let (($x20612 (and d_0_15 in_walk6_0 in_walk4_0)))
 (let (($x20610 (and d_0_14 in_walk6_0 in_walk4_0)))
 (let (($x20608 (and d_0_13 in_walk6_0 in_walk4_0)))
 (let (($x20606 (and d_0_12 in_walk6_0 in_walk4_0)))
 (let (($x20604 (and d_0_11 in_walk6_0 in_walk4_0)))
 (let (($x20602 (and d_0_10 in_walk6_0 in_walk4_0)))
 (let (($x20600 (and d_0_9 in_walk6_0 in_walk4_0)))
 (let (($x20598 (and d_0_8 in_walk6_0 in_walk4_0)))
 (let (($x20596 (and d_0_7 in_walk6_0 in_walk4_0)))
 (let (($x20594 (and d_0_6 in_walk6_0 in_walk4_0)))
 (let (($x20592 (and d_0_5 in_walk6_0 in_walk4_0)))
 (let (($x20590 (and d_0_4 in_walk6_0 in_walk4_0)))
 (let (($x20588 (and d_0_3 in_walk6_0 in_walk4_0)))
 (let (($x20586 (and d_0_2 in_walk6_0 in_walk4_0)))
 (let (($x20584 (and d_0_1 in_walk6_0 in_walk4_0)))
 (let (($x20583 (and d_0_0 in_walk6_0 in_walk4_0)))
 (let (($x20631 (or $x20583 $x20584 $x20586 $x20588 $x20590 $x20592 $x20594 $x20596 $x20598 $x20600 $x20602 $x20604 $x20606 $x20608 $x20610 $x20612 $x20614 $x20616 $x20618 $x20620 $x20622 $x20624 $x20626 $x20628 $x20630)))
 (let (($x20581 (or false $x20631)))
 (let (($x20657 (or $x20581 $x20707)))
 (let (($x20733 (or $x20657 $x20783)))
 (let (($x20551 (and d_3_24 in_walk5_3 in_walk4_3)))
 (let (($x20549 (and d_3_23 in_walk5_3 in_walk4_3)))
 (let (($x20547 (and d_3_22 in_walk5_3 in_walk4_3)))
 (let (($x20545 (and d_3_21 in_walk5_3 in_walk4_3)))
 (let (($x20543 (and d_3_20 in_walk5_3 in_walk4_3)))
 (let (($x20541 (and d_3_19 in_walk5_3 in_walk4_3)))
 (let (($x20539 (and d_3_18 in_walk5_3 in_walk4_3)))
 (let (($x20537 (and d_3_17 in_walk5_3 in_walk4_3)))
 (let (($x20535 (and d_3_16 in_walk5_3 in_walk4_3)))
 (let (($x20533 (and d_3_15 in_walk5_3 in_walk4_3)))
 (let (($x20531 (and d_3_14 in_walk5_3 in_walk4_3)))
 (let (($x20529 (and d_3_13 in_walk5_3 in_walk4_3)))
 (let (($x20527 (and d_3_12 in_walk5_3 in_walk4_3)))
 (let (($x20525 (and d_3_11 in_walk5_3 in_walk4_3)))
 (let (($x20523 (and d_3_10 in_walk5_3 in_walk4_3)))
 (let (($x20521 (and d_3_9 in_walk5_3 in_walk4_3)))
 (let (($x20519 (and d_3_8 in_walk5_3 in_walk4_3)))
 (let (($x20517 (and d_3_7 in_walk5_3 in_walk4_3)))
 (let (($x20515 (and d_3_6 in_walk5_3 in_walk4_3)))
 (let (($x20513 (and d_3_5 in_walk5_3 in_walk4_3)))
 (let (($x20511 (and d_3_4 in_walk5_3 in_walk4_3)))
 (let (($x20509 (and d_3_3 in_walk5_3 in_walk4_3)))
 (let (($x20507 (and d_3_2 in_walk5_3 in_walk4_3)))
 (let (($x20505 (and d_3_1 in_walk5_3 in_walk4_3)))
 (let (($x20504 (and d_3_0 in_walk5_3 in_walk4_3)))
 (let (($x20552 (or $x20504 $x20505 $x20507 $x20509 $x20511 $x20513 $x20515 $x20517 $x20519 $x20521 $x20523 $x20525 $x20527 $x20529 $x20531 $x20533 $x20535 $x20537 $x20539 $x20541 $x20543 $x20545 $x20547 $x20549 $x20551)))
 (let (($x20475 (and d_2_24 in_walk5_2 in_walk4_2)))
 (let (($x20473 (and d_2_23 in_walk5_2 in_walk4_2)))
 (let (($x20471 (and d_2_22 in_walk5_2 in_walk4_2)))
 (let (($x20469 (and d_2_21 in_walk5_2 in_walk4_2)))
 (let (($x20467 (and d_2_20 in_walk5_2 in_walk4_2)))
 (let (($x20465 (and d_2_19 in_walk5_2 in_walk4_2)))
 (let (($x20463 (and d_2_18 in_walk5_2 in_walk4_2)))
 (let (($x20461 (and d_2_17 in_walk5_2 in_walk4_2)))
 (let (($x20459 (and d_2_16 in_walk5_2 in_walk4_2)))
 (let (($x20457 (and d_2_15 in_walk5_2 in_walk4_2)))
 (let (($x20455 (and d_2_14 in_walk5_2 in_walk4_2)))
 (let (($x20453 (and d_2_13 in_walk5_2 in_walk4_2)))
 (let (($x20451 (and d_2_12 in_walk5_2 in_walk4_2)))
 (let (($x20449 (and d_2_11 in_walk5_2 in_walk4_2)))
 (let (($x20447 (and d_2_10 in_walk5_2 in_walk4_2)))
 (let (($x20445 (and d_2_9 in_walk5_2 in_walk4_2)))
 (let (($x20443 (and d_2_8 in_walk5_2 in_walk4_2)))
 (let (($x20441 (and d_2_7 in_walk5_2 in_walk4_2)))
 (let (($x20439 (and d_2_6 in_walk5_2 in_walk4_2)))
 (let (($x20437 (and d_2_5 in_walk5_2 in_walk4_2)))
 (let (($x20435 (and d_2_4 in_walk5_2 in_walk4_2)))
 (let (($x20433 (and d_2_3 in_walk5_2 in_walk4_2)))
 (let (($x20431 (and d_2_2 in_walk5_2 in_walk4_2)))
 (let (($x20429 (and d_2_1 in_walk5_2 in_walk4_2)))
 (let (($x20428 (and d_2_0 in_walk5_2 in_walk4_2)))
 (let (($x20476 (or $x20428 $x20429 $x20431 $x20433 $x20435 $x20437 $x20439 $x20441 $x20443 $x20445 $x20447 $x20449 $x20451 $x20453 $x20455 $x20457 $x20459 $x20461 $x20463 $x20465 $x20467 $x20469 $x20471 $x20473 $x20475)))
 (let (($x20399 (and d_1_24 in_walk5_1 in_walk4_1)))
 (let (($x20397 (and d_1_23 in_walk5_1 in_walk4_1)))
 (let (($x20395 (and d_1_22 in_walk5_1 in_walk4_1)))
 (let (($x20393 (and d_1_21 in_walk5_1 in_walk4_1)))
 (let (($x20391 (and d_1_20 in_walk5_1 in_walk4_1)))
 (let (($x20389 (and d_1_19 in_walk5_1 in_walk4_1)))
 (let (($x20387 (and d_1_18 in_walk5_1 in_walk4_1)))
 (let (($x20385 (and d_1_17 in_walk5_1 in_walk4_1)))
 (let (($x20383 (and d_1_16 in_walk5_1 in_walk4_1)))
 (let (($x20381 (and d_1_15 in_walk5_1 in_walk4_1)))
 (let (($x20379 (and d_1_14 in_walk5_1 in_walk4_1)))
 (let (($x20377 (and d_1_13 in_walk5_1 in_walk4_1)))
 (let (($x20375 (and d_1_12 in_walk5_1 in_walk4_1)))
 (let (($x20373 (and d_1_11 in_walk5_1 in_walk4_1)))
 (let (($x20371 (and d_1_10 in_walk5_1 in_walk4_1)))
 (let (($x20369 (and d_1_9 in_walk5_1 in_walk4_1)))
 (let (($x20367 (and d_1_8 in_walk5_1 in_walk4_1)))
 (let (($x20365 (and d_1_7 in_walk5_1 in_walk4_1)))
 (let (($x20363 (and d_1_6 in_walk5_1 in_walk4_1)))
 (let (($x20361 (and d_1_5 in_walk5_1 in_walk4_1)))
 (let (($x20359 (and d_1_4 in_walk5_1 in_walk4_1)))
 (let (($x20357 (and d_1_3 in_walk5_1 in_walk4_1)))
 (let (($x20355 (and d_1_2 in_walk5_1 in_walk4_1)))
 (let (($x20353 (and d_1_1 in_walk5_1 in_walk4_1)))
 (let (($x20352 (and d_1_0 in_walk5_1 in_walk4_1)))
 (let (($x20400 (or $x20352 $x20353 $x20355 $x20357 $x20359 $x20361 $x20363 $x20365 $x20367 $x20369 $x20371 $x20373 $x20375 $x20377 $x20379 $x20381 $x20383 $x20385 $x20387 $x20389 $x20391 $x20393 $x20395 $x20397 $x20399)))
 (let (($x20323 (and d_0_24 in_walk5_0 in_walk4_0)))
 (let (($x20321 (and d_0_23 in_walk5_0 in_walk4_0)))
 (let (($x20319 (and d_0_22 in_walk5_0 in_walk4_0)))
 (let (($x20317 (and d_0_21 in_walk5_0 in_walk4_0)))
 (let (($x20315 (and d_0_20 in_walk5_0 in_walk4_0)))
 (let (($x20313 (and d_0_19 in_walk5_0 in_walk4_0)))
 (let (($x20311 (and d_0_18 in_walk5_0 in_walk4_0)))
 (let (($x20309 (and d_0_17 in_walk5_0 in_walk4_0)))
 (let (($x20307 (and d_0_16 in_walk5_0 in_walk4_0)))
 (let (($x20305 (and d_0_15 in_walk5_0 in_walk4_0)))
 (let (($x20303 (and d_0_14 in_walk5_0 in_walk4_0)))
 (let (($x20301 (and d_0_13 in_walk5_0 in_walk4_0)))
 (let (($x20299 (and d_0_12 in_walk5_0 in_walk4_0)))
 (let (($x20297 (and d_0_11 in_walk5_0 in_walk4_0)))
 (let (($x20295 (and d_0_10 in_walk5_0 in_walk4_0)))
 (let (($x20293 (and d_0_9 in_walk5_0 in_walk4_0)))
 (let (($x20291 (and d_0_8 in_walk5_0 in_walk4_0)))
 (let (($x20289 (and d_0_7 in_walk5_0 in_walk4_0)))
 (let (($x20287 (and d_0_6 in_walk5_0 in_walk4_0)))
 (let (($x20285 (and d_0_5 in_walk5_0 in_walk4_0)))
 (let (($x20283 (and d_0_4 in_walk5_0 in_walk4_0)))
 (let (($x20281 (and d_0_3 in_walk5_0 in_walk4_0)))
 (let (($x20279 (and d_0_2 in_walk5_0 in_walk4_0)))
 (let (($x20277 (and d_0_1 in_walk5_0 in_walk4_0)))
 (let (($x20276 (and d_0_0 in_walk5_0 in_walk4_0)))
 (let (($x20324 (or $x20276 $x20277 $x20279 $x20281 $x20283 $x20285 $x20287 $x20289 $x20291 $x20293 $x20295 $x20297 $x20299 $x20301 $x20303 $x20305 $x20307 $x20309 $x20311 $x20313 $x20315 $x20317 $x20319 $x20321 $x20323)))
 (let (($x20274 (or false $x20324)))
 (let (($x20350 (or $x20274 $x20400)))
 (let (($x20426 (or $x20350 $x20476)))
 (let (($x20244 (and d_3_24 in_walk8_3 in_walk3_3)))
 (let (($x20242 (and d_3_23 in_walk8_3 in_walk3_3)))
 (let (($x20240 (and d_3_22 in_walk8_3 in_walk3_3)))
 (let (($x20238 (and d_3_21 in_walk8_3 in_walk3_3)))
 (let (($x20236 (and d_3_20 in_walk8_3 in_walk3_3)))
 (let (($x20234 (and d_3_19 in_walk8_3 in_walk3_3)))
 (let (($x20232 (and d_3_18 in_walk8_3 in_walk3_3)))
 (let (($x20230 (and d_3_17 in_walk8_3 in_walk3_3)))
 (let (($x20228 (and d_3_16 in_walk8_3 in_walk3_3)))
 (let (($x20226 (and d_3_15 in_walk8_3 in_walk3_3)))
 (let (($x20224 (and d_3_14 in_walk8_3 in_walk3_3)))
 (let (($x20222 (and d_3_13 in_walk8_3 in_walk3_3)))
 (let (($x20220 (and d_3_12 in_walk8_3 in_walk3_3)))
 (let (($x20218 (and d_3_11 in_walk8_3 in_walk3_3)))
 (let (($x20216 (and d_3_10 in_walk8_3 in_walk3_3)))
 (let (($x20214 (and d_3_9 in_walk8_3 in_walk3_3)))
 (let (($x20212 (and d_3_8 in_walk8_3 in_walk3_3)))
 (let (($x20210 (and d_3_7 in_walk8_3 in_walk3_3)))
 (let (($x20208 (and d_3_6 in_walk8_3 in_walk3_3)))
 (let (($x20206 (and d_3_5 in_walk8_3 in_walk3_3)))
 (let (($x20204 (and d_3_4 in_walk8_3 in_walk3_3)))
 (let (($x20202 (and d_3_3 in_walk8_3 in_walk3_3)))
 (let (($x20200 (and d_3_2 in_walk8_3 in_walk3_3)))
 (let (($x20198 (and d_3_1 in_walk8_3 in_walk3_3)))
 (let (($x20197 (and d_3_0 in_walk8_3 in_walk3_3)))
 (let (($x20245 (or $x20197 $x20198 $x20200 $x20202 $x20204 $x20206 $x20208 $x20210 $x20212 $x20214 $x20216 $x20218 $x20220 $x20222 $x20224 $x20226 $x20228 $x20230 $x20232 $x20234 $x20236 $x20238 $x20240 $x20242 $x20244)))
 (let (($x20168 (and d_2_24 in_walk8_2 in_walk3_2)))
 (let (($x20166 (and d_2_23 in_walk8_2 in_walk3_2)))
 (let (($x20164 (and d_2_22 in_walk8_2 in_walk3_2)))
 (let (($x20162 (and d_2_21 in_walk8_2 in_walk3_2)))
 (let (($x20160 (and d_2_20 in_walk8_2 in_walk3_2)))
 (let (($x20158 (and d_2_19 in_walk8_2 in_walk3_2)))
 (let (($x20156 (and d_2_18 in_walk8_2 in_walk3_2)))
 (let (($x20154 (and d_2_17 in_walk8_2 in_walk3_2)))
 (let (($x20152 (and d_2_16 in_walk8_2 in_walk3_2)))
 (let (($x20150 (and d_2_15 in_walk8_2 in_walk3_2)))
 (let (($x20148 (and d_2_14 in_walk8_2 in_walk3_2)))
 (let (($x20146 (and d_2_13 in_walk8_2 in_walk3_2)))
 (let (($x20144 (and d_2_12 in_walk8_2 in_walk3_2)))
 (let (($x20142 (and d_2_11 in_walk8_2 in_walk3_2)))
 (let (($x20140 (and d_2_10 in_walk8_2 in_walk3_2)))
 (let (($x20138 (and d_2_9 in_walk8_2 in_walk3_2)))
 (let (($x20136 (and d_2_8 in_walk8_2 in_walk3_2)))
 (let (($x20134 (and d_2_7 in_walk8_2 in_walk3_2)))
 (let (($x20132 (and d_2_6 in_walk8_2 in_walk3_2)))
 (let (($x20130 (and d_2_5 in_walk8_2 in_walk3_2)))
 (let (($x20128 (and d_2_4 in_walk8_2 in_walk3_2)))
 (let (($x20126 (and d_2_3 in_walk8_2 in_walk3_2)))
 (let (($x20124 (and d_2_2 in_walk8_2 in_walk3_2)))
 (let (($x20122 (and d_2_1 in_walk8_2 in_walk3_2)))
 (let (($x20121 (and d_2_0 in_walk8_2 in_walk3_2)))
 (let (($x20169 (or $x20121 $x20122 $x20124 $x20126 $x20128 $x20130 $x20132 $x20134 $x20136 $x20138 $x20140 $x20142 $x20144 $x20146 $x20148 $x20150 $x20152 $x20154 $x20156 $x20158 $x20160 $x20162 $x20164 $x20166 $x20168)))
 (let (($x20092 (and d_1_24 in_walk8_1 in_walk3_1)))
 (let (($x20090 (and d_1_23 in_walk8_1 in_walk3_1)))
 (let (($x20088 (and d_1_22 in_walk8_1 in_walk3_1)))
 (let (($x20086 (and d_1_21 in_walk8_1 in_walk3_1)))
 (let (($x20084 (and d_1_20 in_walk8_1 in_walk3_1)))
 (let (($x20082 (and d_1_19 in_walk8_1 in_walk3_1)))
 (let (($x20080 (and d_1_18 in_walk8_1 in_walk3_1)))
 (let (($x20078 (and d_1_17 in_walk8_1 in_walk3_1)))
 (let (($x20076 (and d_1_16 in_walk8_1 in_walk3_1)))
 (let (($x20074 (and d_1_15 in_walk8_1 in_walk3_1)))
 (let (($x20072 (and d_1_14 in_walk8_1 in_walk3_1)))
 (let (($x20070 (and d_1_13 in_walk8_1 in_walk3_1)))
 (let (($x20068 (and d_1_12 in_walk8_1 in_walk3_1)))
 (let (($x20066 (and d_1_11 in_walk8_1 in_walk3_1)))
 (let (($x20064 (and d_1_10 in_walk8_1 in_walk3_1)))
 (let (($x20062 (and d_1_9 in_walk8_1 in_walk3_1)))
 (let (($x20060 (and d_1_8 in_walk8_1 in_walk3_1)))
 (let (($x20058 (and d_1_7 in_walk8_1 in_walk3_1)))
 (let (($x20056 (and d_1_6 in_walk8_1 in_walk3_1)))
 (let (($x20054 (and d_1_5 in_walk8_1 in_walk3_1)))
 (let (($x20052 (and d_1_4 in_walk8_1 in_walk3_1)))
 (let (($x20050 (and d_1_3 in_walk8_1 in_walk3_1)))
 (let (($x20048 (and d_1_2 in_walk8_1 in_walk3_1)))
 (let (($x20046 (and d_1_1 in_walk8_1 in_walk3_1)))
 (let (($x20045 (and d_1_0 in_walk8_1 in_walk3_1)))
 (let (($x20093 (or $x20045 $x20046 $x20048 $x20050 $x20052 $x20054 $x20056 $x20058 $x20060 $x20062 $x20064 $x20066 $x20068 $x20070 $x20072 $x20074 $x20076 $x20078 $x20080 $x20082 $x20084 $x20086 $x20088 $x20090 $x20092)))
 (let (($x20016 (and d_0_24 in_walk8_0 in_walk3_0)))
 (let (($x20014 (and d_0_23 in_walk8_0 in_walk3_0)))
 (let (($x20012 (and d_0_22 in_walk8_0 in_walk3_0)))
 (let (($x20010 (and d_0_21 in_walk8_0 in_walk3_0)))
 (let (($x20008 (and d_0_20 in_walk8_0 in_walk3_0)))
 (let (($x20006 (and d_0_19 in_walk8_0 in_walk3_0)))
 (let (($x20004 (and d_0_18 in_walk8_0 in_walk3_0)))
 (let (($x20002 (and d_0_17 in_walk8_0 in_walk3_0)))
 (let (($x20000 (and d_0_16 in_walk8_0 in_walk3_0)))
 (let (($x19998 (and d_0_15 in_walk8_0 in_walk3_0)))
 (let (($x19996 (and d_0_14 in_walk8_0 in_walk3_0)))
 (let (($x19994 (and d_0_13 in_walk8_0 in_walk3_0)))
 (let (($x19992 (and d_0_12 in_walk8_0 in_walk3_0)))
 (let (($x19990 (and d_0_11 in_walk8_0 in_walk3_0)))
 (let (($x19988 (and d_0_10 in_walk8_0 in_walk3_0)))
 (let (($x19986 (and d_0_9 in_walk8_0 in_walk3_0)))
 (let (($x19984 (and d_0_8 in_walk8_0 in_walk3_0)))
 (let (($x19982 (and d_0_7 in_walk8_0 in_walk3_0)))
 (let (($x19980 (and d_0_6 in_walk8_0 in_walk3_0)))
 (let (($x19978 (and d_0_5 in_walk8_0 in_walk3_0)))
 (let (($x19976 (and d_0_4 in_walk8_0 in_walk3_0)))
 (let (($x19974 (and d_0_3 in_walk8_0 in_walk3_0)))
 (let (($x19972 (and d_0_2 in_walk8_0 in_walk3_0)))
 (let (($x19970 (and d_0_1 in_walk8_0 in_walk3_0)))
 (let (($x19969 (and d_0_0 in_walk8_0 in_walk3_0)))
 (let (($x20017 (or $x19969 $x19970 $x19972 $x19974 $x19976 $x19978 $x19980 $x19982 $x19984 $x19986 $x19988 $x19990 $x19992 $x19994 $x19996 $x19998 $x20000 $x20002 $x20004 $x20006 $x20008 $x20010 $x20012 $x20014 $x20016)))
 (let (($x19967 (or false $x20017)))
 (let (($x20043 (or $x19967 $x20093)))
 (let (($x20119 (or $x20043 $x20169)))
 (let (($x14974 (not (or (or (or (or false d_0_11) d_1_11) d_2_11) d_3_11))))
 (let (($x19937 (and d_3_24 in_walk7_3 in_walk3_3)))
 (let (($x19935 (and d_3_23 in_walk7_3 in_walk3_3)))
 (let (($x19933 (and d_3_22 in_walk7_3 in_walk3_3)))
 (let (($x19931 (and d_3_21 in_walk7_3 in_walk3_3)))
 (let (($x19929 (and d_3_20 in_walk7_3 in_walk3_3)))
 (let (($x19927 (and d_3_19 in_walk7_3 in_walk3_3)))
 (let (($x19925 (and d_3_18 in_walk7_3 in_walk3_3)))
 (let (($x19923 (and d_3_17 in_walk7_3 in_walk3_3)))
 (let (($x19921 (and d_3_16 in_walk7_3 in_walk3_3)))
 (let (($x19919 (and d_3_15 in_walk7_3 in_walk3_3)))
 (let (($x19917 (and d_3_14 in_walk7_3 in_walk3_3)))
 (let (($x19915 (and d_3_13 in_walk7_3 in_walk3_3)))
 (let (($x19913 (and d_3_12 in_walk7_3 in_walk3_3)))
 (let (($x19911 (and d_3_11 in_walk7_3 in_walk3_3)))
 (let (($x19909 (and d_3_10 in_walk7_3 in_walk3_3)))
 (let (($x19907 (and d_3_9 in_walk7_3 in_walk3_3)))
 (let (($x19905 (and d_3_8 in_walk7_3 in_walk3_3)))
 (let (($x19903 (and d_3_7 in_walk7_3 in_walk3_3)))
 (let (($x19901 (and d_3_6 in_walk7_3 in_walk3_3)))
 (let (($x19899 (and d_3_5 in_walk7_3 in_walk3_3)))
 (let (($x19897 (and d_3_4 in_walk7_3 in_walk3_3)))
 (let (($x19895 (and d_3_3 in_walk7_3 in_walk3_3)))
 (let (($x19893 (and d_3_2 in_walk7_3 in_walk3_3)))
 (let (($x19891 (and d_3_1 in_walk7_3 in_walk3_3)))
 (let (($x19890 (and d_3_0 in_walk7_3 in_walk3_3)))
 (let (($x19938 (or $x19890 $x19891 $x19893 $x19895 $x19897 $x19899 $x19901 $x19903 $x19905 $x19907 $x19909 $x19911 $x19913 $x19915 $x19917 $x19919 $x19921 $x19923 $x19925 $x19927 $x19929 $x19931 $x19933 $x19935 $x19937)))
 (let (($x19861 (and d_2_24 in_walk7_2 in_walk3_2)))
 (let (($x19859 (and d_2_23 in_walk7_2 in_walk3_2)))
 (let (($x19857 (and d_2_22 in_walk7_2 in_walk3_2)))
 (let (($x19855 (and d_2_21 in_walk7_2 in_walk3_2)))
 (let (($x19853 (and d_2_20 in_walk7_2 in_walk3_2)))
 (let (($x19851 (and d_2_19 in_walk7_2 in_walk3_2)))
 (let (($x19849 (and d_2_18 in_walk7_2 in_walk3_2)))
 (let (($x19847 (and d_2_17 in_walk7_2 in_walk3_2)))
 (let (($x19845 (and d_2_16 in_walk7_2 in_walk3_2)))
 (let (($x19843 (and d_2_15 in_walk7_2 in_walk3_2)))
 (let (($x19841 (and d_2_14 in_walk7_2 in_walk3_2)))
 (let (($x19839 (and d_2_13 in_walk7_2 in_walk3_2)))
 (let (($x19837 (and d_2_12 in_walk7_2 in_walk3_2)))
 (let (($x19835 (and d_2_11 in_walk7_2 in_walk3_2)))
 (let (($x19833 (and d_2_10 in_walk7_2 in_walk3_2)))
 (let (($x19831 (and d_2_9 in_walk7_2 in_walk3_2)))
 (let (($x19829 (and d_2_8 in_walk7_2 in_walk3_2)))
 (let (($x19827 (and d_2_7 in_walk7_2 in_walk3_2)))
 (let (($x19825 (and d_2_6 in_walk7_2 in_walk3_2)))
 (let (($x19823 (and d_2_5 in_walk7_2 in_walk3_2)))
 (let (($x19821 (and d_2_4 in_walk7_2 in_walk3_2)))
 (let (($x19819 (and d_2_3 in_walk7_2 in_walk3_2)))
 (let (($x19817 (and d_2_2 in_walk7_2 in_walk3_2)))
 (let (($x19815 (and d_2_1 in_walk7_2 in_walk3_2)))
 (let (($x19814 (and d_2_0 in_walk7_2 in_walk3_2)))
 (let (($x19862 (or $x19814 $x19815 $x19817 $x19819 $x19821 $x19823 $x19825 $x19827 $x19829 $x19831 $x19833 $x19835 $x19837 $x19839 $x19841 $x19843 $x19845 $x19847 $x19849 $x19851 $x19853 $x19855 $x19857 $x19859 $x19861)))
 (let (($x19785 (and d_1_24 in_walk7_1 in_walk3_1)))
 (let (($x19783 (and d_1_23 in_walk7_1 in_walk3_1)))
 (let (($x19781 (and d_1_22 in_walk7_1 in_walk3_1)))
 (let (($x19779 (and d_1_21 in_walk7_1 in_walk3_1)))
 (let (($x19777 (and d_1_20 in_walk7_1 in_walk3_1)))
 (let (($x19775 (and d_1_19 in_walk7_1 in_walk3_1)))
 (let (($x19773 (and d_1_18 in_walk7_1 in_walk3_1)))
 (let (($x19771 (and d_1_17 in_walk7_1 in_walk3_1)))
 (let (($x19769 (and d_1_16 in_walk7_1 in_walk3_1)))
 (let (($x19767 (and d_1_15 in_walk7_1 in_walk3_1)))
 (let (($x19765 (and d_1_14 in_walk7_1 in_walk3_1)))
 (let (($x19763 (and d_1_13 in_walk7_1 in_walk3_1)))
 (let (($x19761 (and d_1_12 in_walk7_1 in_walk3_1)))
 (let (($x19759 (and d_1_11 in_walk7_1 in_walk3_1)))
 (let (($x19757 (and d_1_10 in_walk7_1 in_walk3_1)))
 (let (($x19755 (and d_1_9 in_walk7_1 in_walk3_1)))
 (let (($x19753 (and d_1_8 in_walk7_1 in_walk3_1)))
 (let (($x19751 (and d_1_7 in_walk7_1 in_walk3_1)))
 (let (($x19749 (and d_1_6 in_walk7_1 in_walk3_1)))
 (let (($x19747 (and d_1_5 in_walk7_1 in_walk3_1)))
 (let (($x19745 (and d_1_4 in_walk7_1 in_walk3_1)))
 (let (($x19743 (and d_1_3 in_walk7_1 in_walk3_1)))
 (let (($x19741 (and d_1_2 in_walk7_1 in_walk3_1)))
 (let (($x19739 (and d_1_1 in_walk7_1 in_walk3_1)))
 (let (($x19738 (and d_1_0 in_walk7_1 in_walk3_1)))
 (let (($x19786 (or $x19738 $x19739 $x19741 $x19743 $x19745 $x19747 $x19749 $x19751 $x19753 $x19755 $x19757 $x19759 $x19761 $x19763 $x19765 $x19767 $x19769 $x19771 $x19773 $x19775 $x19777 $x19779 $x19781 $x19783 $x19785)))
 (let (($x19709 (and d_0_24 in_walk7_0 in_walk3_0)))
 (let (($x19707 (and d_0_23 in_walk7_0 in_walk3_0)))
 (let (($x19705 (and d_0_22 in_walk7_0 in_walk3_0)))
 (let (($x19703 (and d_0_21 in_walk7_0 in_walk3_0)))
 (let (($x19701 (and d_0_20 in_walk7_0 in_walk3_0)))
 (let (($x19699 (and d_0_19 in_walk7_0 in_walk3_0)))
 (let (($x19697 (and d_0_18 in_walk7_0 in_walk3_0)))
 (let (($x19695 (and d_0_17 in_walk7_0 in_walk3_0)))
 (let (($x19693 (and d_0_16 in_walk7_0 in_walk3_0)))
 (let (($x19691 (and d_0_15 in_walk7_0 in_walk3_0)))
 (let (($x19689 (and d_0_14 in_walk7_0 in_walk3_0)))
 (let (($x19687 (and d_0_13 in_walk7_0 in_walk3_0)))
 (let (($x19685 (and d_0_12 in_walk7_0 in_walk3_0)))
 (let (($x19683 (and d_0_11 in_walk7_0 in_walk3_0)))
 (let (($x19681 (and d_0_10 in_walk7_0 in_walk3_0)))
 (let (($x19679 (and d_0_9 in_walk7_0 in_walk3_0)))
 (let (($x19677 (and d_0_8 in_walk7_0 in_walk3_0)))
 (let (($x19675 (and d_0_7 in_walk7_0 in_walk3_0)))
 (let (($x19673 (and d_0_6 in_walk7_0 in_walk3_0)))
 (let (($x19671 (and d_0_5 in_walk7_0 in_walk3_0)))
 (let (($x19669 (and d_0_4 in_walk7_0 in_walk3_0)))
 (let (($x19667 (and d_0_3 in_walk7_0 in_walk3_0)))
 (let (($x19665 (and d_0_2 in_walk7_0 in_walk3_0)))
 (let (($x19663 (and d_0_1 in_walk7_0 in_walk3_0)))
 (let (($x19662 (and d_0_0 in_walk7_0 in_walk3_0)))
 (let (($x19710 (or $x19662 $x19663 $x19665 $x19667 $x19669 $x19671 $x19673 $x19675 $x19677 $x19679 $x19681 $x19683 $x19685 $x19687 $x19689 $x19691 $x19693 $x19695 $x19697 $x19699 $x19701 $x19703 $x19705 $x19707 $x19709)))
 (let (($x19660 (or false $x19710)))
 (let (($x19736 (or $x19660 $x19786)))
 (let (($x19812 (or $x19736 $x19862)))
 (let (($x19630 (and d_3_24 in_walk6_3 in_walk3_3)))
 (let (($x19628 (and d_3_23 in_walk6_3 in_walk3_3)))
 (let (($x19626 (and d_3_22 in_walk6_3 in_walk3_3)))
 (let (($x19624 (and d_3_21 in_walk6_3 in_walk3_3)))
 (let (($x19622 (and d_3_20 in_walk6_3 in_walk3_3)))
 (let (($x19620 (and d_3_19 in_walk6_3 in_walk3_3)))
 (let (($x19618 (and d_3_18 in_walk6_3 in_walk3_3)))
 (let (($x19616 (and d_3_17 in_walk6_3 in_walk3_3)))
 (let (($x19614 (and d_3_16 in_walk6_3 in_walk3_3)))
 (let (($x19612 (and d_3_15 in_walk6_3 in_walk3_3)))
 (let (($x19610 (and d_3_14 in_walk6_3 in_walk3_3)))
 (let (($x19608 (and d_3_13 in_walk6_3 in_walk3_3)))
 (let (($x19606 (and d_3_12 in_walk6_3 in_walk3_3)))
 (let (($x19604 (and d_3_11 in_walk6_3 in_walk3_3)))
 (let (($x19602 (and d_3_10 in_walk6_3 in_walk3_3)))
 (let (($x19600 (and d_3_9 in_walk6_3 in_walk3_3)))
 (let (($x19598 (and d_3_8 in_walk6_3 in_walk3_3)))
 (let (($x19596 (and d_3_7 in_walk6_3 in_walk3_3)))
 (let (($x19594 (and d_3_6 in_walk6_3 in_walk3_3)))
 (let (($x19592 (and d_3_5 in_walk6_3 in_walk3_3)))
 (let (($x19590 (and d_3_4 in_walk6_3 in_walk3_3)))
 (let (($x19588 (and d_3_3 in_walk6_3 in_walk3_3)))
 (let (($x19586 (and d_3_2 in_walk6_3 in_walk3_3)))
 (let (($x19584 (and d_3_1 in_walk6_3 in_walk3_3)))
 (let (($x19583 (and d_3_0 in_walk6_3 in_walk3_3)))
 (let (($x19631 (or $x19583 $x19584 $x19586 $x19588 $x19590 $x19592 $x19594 $x19596 $x19598 $x19600 $x19602 $x19604 $x19606 $x19608 $x19610 $x19612 $x19614 $x19616 $x19618 $x19620 $x19622 $x19624 $x19626 $x19628 $x19630)))
 (let (($x19554 (and d_2_24 in_walk6_2 in_walk3_2)))
 (let (($x19552 (and d_2_23 in_walk6_2 in_walk3_2)))
 (let (($x19550 (and d_2_22 in_walk6_2 in_walk3_2)))
 (let (($x19548 (and d_2_21 in_walk6_2 in_walk3_2)))
 (let (($x19546 (and d_2_20 in_walk6_2 in_walk3_2)))
 (let (($x19544 (and d_2_19 in_walk6_2 in_walk3_2)))
 (let (($x19542 (and d_2_18 in_walk6_2 in_walk3_2)))
 (let (($x19540 (and d_2_17 in_walk6_2 in_walk3_2)))
 (let (($x19538 (and d_2_16 in_walk6_2 in_walk3_2)))
 (let (($x19536 (and d_2_15 in_walk6_2 in_walk3_2)))
 (let (($x19534 (and d_2_14 in_walk6_2 in_walk3_2)))
 (let (($x19532 (and d_2_13 in_walk6_2 in_walk3_2)))
 (let (($x19530 (and d_2_12 in_walk6_2 in_walk3_2)))
 (let (($x19528 (and d_2_11 in_walk6_2 in_walk3_2)))
 (let (($x19526 (and d_2_10 in_walk6_2 in_walk3_2)))
 (let (($x19524 (and d_2_9 in_walk6_2 in_walk3_2)))
 (let (($x19522 (and d_2_8 in_walk6_2 in_walk3_2)))
 (let (($x19520 (and d_2_7 in_walk6_2 in_walk3_2)))
 (let (($x19518 (and d_2_6 in_walk6_2 in_walk3_2)))
 (let (($x19516 (and d_2_5 in_walk6_2 in_walk3_2)))
 (let (($x19514 (and d_2_4 in_walk6_2 in_walk3_2)))
 (let (($x19512 (and d_2_3 in_walk6_2 in_walk3_2)))
 (let (($x19510 (and d_2_2 in_walk6_2 in_walk3_2)))
 (let (($x19508 (and d_2_1 in_walk6_2 in_walk3_2)))
 (let (($x19507 (and d_2_0 in_walk6_2 in_walk3_2)))
 (let (($x19555 (or $x19507 $x19508 $x19510 $x19512 $x19514 $x19516 $x19518 $x19520 $x19522 $x19524 $x19526 $x19528 $x19530 $x19532 $x19534 $x19536 $x19538 $x19540 $x19542 $x19544 $x19546 $x19548 $x19550 $x19552 $x19554)))
 (let (($x19478 (and d_1_24 in_walk6_1 in_walk3_1)))
 (let (($x19476 (and d_1_23 in_walk6_1 in_walk3_1)))
 (let (($x19474 (and d_1_22 in_walk6_1 in_walk3_1)))
 (let (($x19472 (and d_1_21 in_walk6_1 in_walk3_1)))
 (let (($x19470 (and d_1_20 in_walk6_1 in_walk3_1)))
 (let (($x19468 (and d_1_19 in_walk6_1 in_walk3_1)))
 (let (($x19466 (and d_1_18 in_walk6_1 in_walk3_1)))
 (let (($x19464 (and d_1_17 in_walk6_1 in_walk3_1)))
 (let (($x19462 (and d_1_16 in_walk6_1 in_walk3_1)))
 (let (($x19460 (and d_1_15 in_walk6_1 in_walk3_1)))
 (let (($x19458 (and d_1_14 in_walk6_1 in_walk3_1)))
 (let (($x19456 (and d_1_13 in_walk6_1 in_walk3_1)))
 (let (($x19454 (and d_1_12 in_walk6_1 in_walk3_1)))
 (let (($x19452 (and d_1_11 in_walk6_1 in_walk3_1)))
 (let (($x19450 (and d_1_10 in_walk6_1 in_walk3_1)))
 (let (($x19448 (and d_1_9 in_walk6_1 in_walk3_1)))
 (let (($x19446 (and d_1_8 in_walk6_1 in_walk3_1)))
 (let (($x19444 (and d_1_7 in_walk6_1 in_walk3_1)))
 (let (($x19442 (and d_1_6 in_walk6_1 in_walk3_1)))
 (let (($x19440 (and d_1_5 in_walk6_1 in_walk3_1)))
 (let (($x19438 (and d_1_4 in_walk6_1 in_walk3_1)))
 (let (($x19436 (and d_1_3 in_walk6_1 in_walk3_1)))
 (let (($x19434 (and d_1_2 in_walk6_1 in_walk3_1)))
 (let (($x19432 (and d_1_1 in_walk6_1 in_walk3_1)))
 (let (($x19431 (and d_1_0 in_walk6_1 in_walk3_1)))
 (let (($x19479 (or $x19431 $x19432 $x19434 $x19436 $x19438 $x19440 $x19442 $x19444 $x19446 $x19448 $x19450 $x19452 $x19454 $x19456 $x19458 $x19460 $x19462 $x19464 $x19466 $x19468 $x19470 $x19472 $x19474 $x19476 $x19478)))
 (let (($x19402 (and d_0_24 in_walk6_0 in_walk3_0)))
 (let (($x19400 (and d_0_23 in_walk6_0 in_walk3_0)))
 (let (($x19398 (and d_0_22 in_walk6_0 in_walk3_0)))
 (let (($x19396 (and d_0_21 in_walk6_0 in_walk3_0)))
 (let (($x19394 (and d_0_20 in_walk6_0 in_walk3_0)))
 (let (($x19392 (and d_0_19 in_walk6_0 in_walk3_0)))
 (let (($x19390 (and d_0_18 in_walk6_0 in_walk3_0)))
 (let (($x19388 (and d_0_17 in_walk6_0 in_walk3_0)))
 (let (($x19386 (and d_0_16 in_walk6_0 in_walk3_0)))
 (let (($x19384 (and d_0_15 in_walk6_0 in_walk3_0)))
 (let (($x19382 (and d_0_14 in_walk6_0 in_walk3_0)))
 (let (($x19380 (and d_0_13 in_walk6_0 in_walk3_0)))
 (let (($x19378 (and d_0_12 in_walk6_0 in_walk3_0)))
 (let (($x19376 (and d_0_11 in_walk6_0 in_walk3_0)))
 (let (($x19374 (and d_0_10 in_walk6_0 in_walk3_0)))
 (let (($x19372 (and d_0_9 in_walk6_0 in_walk3_0)))
 (let (($x19370 (and d_0_8 in_walk6_0 in_walk3_0)))
 (let (($x19368 (and d_0_7 in_walk6_0 in_walk3_0)))
 (let (($x19366 (and d_0_6 in_walk6_0 in_walk3_0)))
 (let (($x19364 (and d_0_5 in_walk6_0 in_walk3_0)))
 (let (($x19362 (and d_0_4 in_walk6_0 in_walk3_0)))
 (let (($x19360 (and d_0_3 in_walk6_0 in_walk3_0)))
 (let (($x19358 (and d_0_2 in_walk6_0 in_walk3_0)))
 (let (($x19356 (and d_0_1 in_walk6_0 in_walk3_0)))
 (let (($x19355 (and d_0_0 in_walk6_0 in_walk3_0)))
 (let (($x19403 (or $x19355 $x19356 $x19358 $x19360 $x19362 $x19364 $x19366 $x19368 $x19370 $x19372 $x19374 $x19376 $x19378 $x19380 $x19382 $x19384 $x19386 $x19388 $x19390 $x19392 $x19394 $x19396 $x19398 $x19400 $x19402)))
 (let (($x19353 (or false $x19403)))
 (let (($x19429 (or $x19353 $x19479)))
 (let (($x19505 (or $x19429 $x19555)))
 (let (($x19323 (and d_3_24 in_walk5_3 in_walk3_3)))
 (let (($x19321 (and d_3_23 in_walk5_3 in_walk3_3)))
 (let (($x19319 (and d_3_22 in_walk5_3 in_walk3_3)))
 (let (($x19317 (and d_3_21 in_walk5_3 in_walk3_3)))
 (let (($x19315 (and d_3_20 in_walk5_3 in_walk3_3)))
 (let (($x19313 (and d_3_19 in_walk5_3 in_walk3_3)))
 (let (($x19311 (and d_3_18 in_walk5_3 in_walk3_3)))
 (let (($x19309 (and d_3_17 in_walk5_3 in_walk3_3)))
 (let (($x19307 (and d_3_16 in_walk5_3 in_walk3_3)))
 (let (($x19305 (and d_3_15 in_walk5_3 in_walk3_3)))
 (let (($x19303 (and d_3_14 in_walk5_3 in_walk3_3)))
 (let (($x19301 (and d_3_13 in_walk5_3 in_walk3_3)))
 (let (($x19299 (and d_3_12 in_walk5_3 in_walk3_3)))
 (let (($x19297 (and d_3_11 in_walk5_3 in_walk3_3)))
 (let (($x19295 (and d_3_10 in_walk5_3 in_walk3_3)))
 (let (($x19293 (and d_3_9 in_walk5_3 in_walk3_3)))
 (let (($x19291 (and d_3_8 in_walk5_3 in_walk3_3)))
 (let (($x19289 (and d_3_7 in_walk5_3 in_walk3_3)))
 (let (($x19287 (and d_3_6 in_walk5_3 in_walk3_3)))
 (let (($x19285 (and d_3_5 in_walk5_3 in_walk3_3)))
 (let (($x19283 (and d_3_4 in_walk5_3 in_walk3_3)))
 (let (($x19281 (and d_3_3 in_walk5_3 in_walk3_3)))
 (let (($x19279 (and d_3_2 in_walk5_3 in_walk3_3)))
 (let (($x19277 (and d_3_1 in_walk5_3 in_walk3_3)))
 (let (($x19276 (and d_3_0 in_walk5_3 in_walk3_3)))
 (let (($x19324 (or $x19276 $x19277 $x19279 $x19281 $x19283 $x19285 $x19287 $x19289 $x19291 $x19293 $x19295 $x19297 $x19299 $x19301 $x19303 $x19305 $x19307 $x19309 $x19311 $x19313 $x19315 $x19317 $x19319 $x19321 $x19323)))
 (let (($x19247 (and d_2_24 in_walk5_2 in_walk3_2)))
 (let (($x19245 (and d_2_23 in_walk5_2 in_walk3_2)))
 (let (($x19243 (and d_2_22 in_walk5_2 in_walk3_2)))
 (let (($x19241 (and d_2_21 in_walk5_2 in_walk3_2)))
 (let (($x19239 (and d_2_20 in_walk5_2 in_walk3_2)))
 (let (($x19237 (and d_2_19 in_walk5_2 in_walk3_2)))
 (let (($x19235 (and d_2_18 in_walk5_2 in_walk3_2)))
 (let (($x19233 (and d_2_17 in_walk5_2 in_walk3_2)))
 (let (($x19231 (and d_2_16 in_walk5_2 in_walk3_2)))
 (let (($x19229 (and d_2_15 in_walk5_2 in_walk3_2)))
 (let (($x19227 (and d_2_14 in_walk5_2 in_walk3_2)))
 (let (($x19225 (and d_2_13 in_walk5_2 in_walk3_2)))
 (let (($x19223 (and d_2_12 in_walk5_2 in_walk3_2)))
 (let (($x19221 (and d_2_11 in_walk5_2 in_walk3_2)))
 (let (($x19219 (and d_2_10 in_walk5_2 in_walk3_2)))
 (let (($x19217 (and d_2_9 in_walk5_2 in_walk3_2)))
 (let (($x19215 (and d_2_8 in_walk5_2 in_walk3_2)))
 (let (($x19213 (and d_2_7 in_walk5_2 in_walk3_2)))
 (let (($x19211 (and d_2_6 in_walk5_2 in_walk3_2)))
 (let (($x19209 (and d_2_5 in_walk5_2 in_walk3_2)))
 (let (($x19207 (and d_2_4 in_walk5_2 in_walk3_2)))
 (let (($x19205 (and d_2_3 in_walk5_2 in_walk3_2)))
 (let (($x19203 (and d_2_2 in_walk5_2 in_walk3_2)))
 (let (($x19201 (and d_2_1 in_walk5_2 in_walk3_2)))
 (let (($x19200 (and d_2_0 in_walk5_2 in_walk3_2)))
 (let (($x19248 (or $x19200 $x19201 $x19203 $x19205 $x19207 $x19209 $x19211 $x19213 $x19215 $x19217 $x19219 $x19221 $x19223 $x19225 $x19227 $x19229 $x19231 $x19233 $x19235 $x19237 $x19239 $x19241 $x19243 $x19245 $x19247)))
 (let (($x19171 (and d_1_24 in_walk5_1 in_walk3_1)))
 (let (($x19169 (and d_1_23 in_walk5_1 in_walk3_1)))
 (let (($x19167 (and d_1_22 in_walk5_1 in_walk3_1)))
 (let (($x19165 (and d_1_21 in_walk5_1 in_walk3_1)))
 (let (($x19163 (and d_1_20 in_walk5_1 in_walk3_1)))
 (let (($x19161 (and d_1_19 in_walk5_1 in_walk3_1)))
 (let (($x19159 (and d_1_18 in_walk5_1 in_walk3_1)))
 (let (($x19157 (and d_1_17 in_walk5_1 in_walk3_1)))
 (let (($x19155 (and d_1_16 in_walk5_1 in_walk3_1)))
 (let (($x19153 (and d_1_15 in_walk5_1 in_walk3_1)))
 (let (($x19151 (and d_1_14 in_walk5_1 in_walk3_1)))
 (let (($x19149 (and d_1_13 in_walk5_1 in_walk3_1)))
 (let (($x19147 (and d_1_12 in_walk5_1 in_walk3_1)))
 (let (($x19145 (and d_1_11 in_walk5_1 in_walk3_1)))
 (let (($x19143 (and d_1_10 in_walk5_1 in_walk3_1)))
 (let (($x19141 (and d_1_9 in_walk5_1 in_walk3_1)))
 (let (($x19139 (and d_1_8 in_walk5_1 in_walk3_1)))
 (let (($x19137 (and d_1_7 in_walk5_1 in_walk3_1)))
 (let (($x19135 (and d_1_6 in_walk5_1 in_walk3_1)))
 (let (($x19133 (and d_1_5 in_walk5_1 in_walk3_1)))
 (let (($x19131 (and d_1_4 in_walk5_1 in_walk3_1)))
 (let (($x19129 (and d_1_3 in_walk5_1 in_walk3_1)))
 (let (($x19127 (and d_1_2 in_walk5_1 in_walk3_1)))
 (let (($x19125 (and d_1_1 in_walk5_1 in_walk3_1)))
 (let (($x19124 (and d_1_0 in_walk5_1 in_walk3_1)))
 (let (($x19172 (or $x19124 $x19125 $x19127 $x19129 $x19131 $x19133 $x19135 $x19137 $x19139 $x19141 $x19143 $x19145 $x19147 $x19149 $x19151 $x19153 $x19155 $x19157 $x19159 $x19161 $x19163 $x19165 $x19167 $x19169 $x19171)))
 (let (($x19095 (and d_0_24 in_walk5_0 in_walk3_0)))
 (let (($x19093 (and d_0_23 in_walk5_0 in_walk3_0)))
 (let (($x19091 (and d_0_22 in_walk5_0 in_walk3_0)))
 (let (($x19089 (and d_0_21 in_walk5_0 in_walk3_0)))
 (let (($x19087 (and d_0_20 in_walk5_0 in_walk3_0)))
 (let (($x19085 (and d_0_19 in_walk5_0 in_walk3_0)))
 (let (($x19083 (and d_0_18 in_walk5_0 in_walk3_0)))
 (let (($x19081 (and d_0_17 in_walk5_0 in_walk3_0)))
 (let (($x19079 (and d_0_16 in_walk5_0 in_walk3_0)))
 (let (($x19077 (and d_0_15 in_walk5_0 in_walk3_0)))
 (let (($x19075 (and d_0_14 in_walk5_0 in_walk3_0)))
 (let (($x19073 (and d_0_13 in_walk5_0 in_walk3_0)))
 (let (($x19071 (and d_0_12 in_walk5_0 in_walk3_0)))
 (let (($x19069 (and d_0_11 in_walk5_0 in_walk3_0)))
 (let (($x19067 (and d_0_10 in_walk5_0 in_walk3_0)))
 (let (($x19065 (and d_0_9 in_walk5_0 in_walk3_0)))
 (let (($x19063 (and d_0_8 in_walk5_0 in_walk3_0)))
 (let (($x19061 (and d_0_7 in_walk5_0 in_walk3_0)))
 (let (($x19059 (and d_0_6 in_walk5_0 in_walk3_0)))
 (let (($x19057 (and d_0_5 in_walk5_0 in_walk3_0)))
 (let (($x19055 (and d_0_4 in_walk5_0 in_walk3_0)))
 (let (($x19053 (and d_0_3 in_walk5_0 in_walk3_0)))
 (let (($x19051 (and d_0_2 in_walk5_0 in_walk3_0)))
 (let (($x19049 (and d_0_1 in_walk5_0 in_walk3_0)))
 (let (($x19048 (and d_0_0 in_walk5_0 in_walk3_0)))
 (let (($x19096 (or $x19048 $x19049 $x19051 $x19053 $x19055 $x19057 $x19059 $x19061 $x19063 $x19065 $x19067 $x19069 $x19071 $x19073 $x19075 $x19077 $x19079 $x19081 $x19083 $x19085 $x19087 $x19089 $x19091 $x19093 $x19095)))
 (let (($x19046 (or false $x19096)))
 (let (($x19122 (or $x19046 $x19172)))
 (let (($x19198 (or $x19122 $x19248)))
 (let (($x19016 (and d_3_24 in_walk4_3 in_walk3_3)))
 (let (($x19014 (and d_3_23 in_walk4_3 in_walk3_3)))
 (let (($x19012 (and d_3_22 in_walk4_3 in_walk3_3)))
 (let (($x19010 (and d_3_21 in_walk4_3 in_walk3_3)))
 (let (($x19008 (and d_3_20 in_walk4_3 in_walk3_3)))
 (let (($x19006 (and d_3_19 in_walk4_3 in_walk3_3)))
 (let (($x19004 (and d_3_18 in_walk4_3 in_walk3_3)))
 (let (($x19002 (and d_3_17 in_walk4_3 in_walk3_3)))
 (let (($x19000 (and d_3_16 in_walk4_3 in_walk3_3)))
 (let (($x18998 (and d_3_15 in_walk4_3 in_walk3_3)))
 (let (($x18996 (and d_3_14 in_walk4_3 in_walk3_3)))
 (let (($x18994 (and d_3_13 in_walk4_3 in_walk3_3)))
 (let (($x18992 (and d_3_12 in_walk4_3 in_walk3_3)))
 (let (($x18990 (and d_3_11 in_walk4_3 in_walk3_3)))
 (let (($x18988 (and d_3_10 in_walk4_3 in_walk3_3)))
 (let (($x18986 (and d_3_9 in_walk4_3 in_walk3_3)))
 (let (($x18984 (and d_3_8 in_walk4_3 in_walk3_3)))
 (let (($x18982 (and d_3_7 in_walk4_3 in_walk3_3)))
 (let (($x18980 (and d_3_6 in_walk4_3 in_walk3_3)))
 (let (($x18978 (and d_3_5 in_walk4_3 in_walk3_3)))
 (let (($x18976 (and d_3_4 in_walk4_3 in_walk3_3)))
 (let (($x18974 (and d_3_3 in_walk4_3 in_walk3_3)))
 (let (($x18972 (and d_3_2 in_walk4_3 in_walk3_3)))
 (let (($x18970 (and d_3_1 in_walk4_3 in_walk3_3)))
 (let (($x18969 (and d_3_0 in_walk4_3 in_walk3_3)))
 (let (($x19017 (or $x18969 $x18970 $x18972 $x18974 $x18976 $x18978 $x18980 $x18982 $x18984 $x18986 $x18988 $x18990 $x18992 $x18994 $x18996 $x18998 $x19000 $x19002 $x19004 $x19006 $x19008 $x19010 $x19012 $x19014 $x19016)))
 (let (($x18940 (and d_2_24 in_walk4_2 in_walk3_2)))
 (let (($x18938 (and d_2_23 in_walk4_2 in_walk3_2)))
 (let (($x18936 (and d_2_22 in_walk4_2 in_walk3_2)))
 (let (($x18934 (and d_2_21 in_walk4_2 in_walk3_2)))
 (let (($x18932 (and d_2_20 in_walk4_2 in_walk3_2)))
 (let (($x18930 (and d_2_19 in_walk4_2 in_walk3_2)))
 (let (($x18928 (and d_2_18 in_walk4_2 in_walk3_2)))
 (let (($x18926 (and d_2_17 in_walk4_2 in_walk3_2)))
 (let (($x18924 (and d_2_16 in_walk4_2 in_walk3_2)))
 (let (($x18922 (and d_2_15 in_walk4_2 in_walk3_2)))
 (let (($x18920 (and d_2_14 in_walk4_2 in_walk3_2)))
 (let (($x18918 (and d_2_13 in_walk4_2 in_walk3_2)))
 (let (($x18916 (and d_2_12 in_walk4_2 in_walk3_2)))
 (let (($x18914 (and d_2_11 in_walk4_2 in_walk3_2)))
 (let (($x18912 (and d_2_10 in_walk4_2 in_walk3_2)))
 (let (($x18910 (and d_2_9 in_walk4_2 in_walk3_2)))
 (let (($x18908 (and d_2_8 in_walk4_2 in_walk3_2)))
 (let (($x18906 (and d_2_7 in_walk4_2 in_walk3_2)))
 (let (($x18904 (and d_2_6 in_walk4_2 in_walk3_2)))
 (let (($x18902 (and d_2_5 in_walk4_2 in_walk3_2)))
 (let (($x18900 (and d_2_4 in_walk4_2 in_walk3_2)))
 (let (($x18898 (and d_2_3 in_walk4_2 in_walk3_2)))
 (let (($x18896 (and d_2_2 in_walk4_2 in_walk3_2)))
 (let (($x18894 (and d_2_1 in_walk4_2 in_walk3_2)))
 (let (($x18893 (and d_2_0 in_walk4_2 in_walk3_2)))
 (let (($x18941 (or $x18893 $x18894 $x18896 $x18898 $x18900 $x18902 $x18904 $x18906 $x18908 $x18910 $x18912 $x18914 $x18916 $x18918 $x18920 $x18922 $x18924 $x18926 $x18928 $x18930 $x18932 $x18934 $x18936 $x18938 $x18940)))
 (let (($x18864 (and d_1_24 in_walk4_1 in_walk3_1)))
 (let (($x18862 (and d_1_23 in_walk4_1 in_walk3_1)))
 (let (($x18860 (and d_1_22 in_walk4_1 in_walk3_1)))
 (let (($x18858 (and d_1_21 in_walk4_1 in_walk3_1)))
 (let (($x18856 (and d_1_20 in_walk4_1 in_walk3_1)))
 (let (($x18854 (and d_1_19 in_walk4_1 in_walk3_1)))
 (let (($x18852 (and d_1_18 in_walk4_1 in_walk3_1)))
 (let (($x18850 (and d_1_17 in_walk4_1 in_walk3_1)))
 (let (($x18848 (and d_1_16 in_walk4_1 in_walk3_1)))
 (let (($x18846 (and d_1_15 in_walk4_1 in_walk3_1)))
 (let (($x18844 (and d_1_14 in_walk4_1 in_walk3_1)))
 (let (($x18842 (and d_1_13 in_walk4_1 in_walk3_1)))
 (let (($x18840 (and d_1_12 in_walk4_1 in_walk3_1)))
 (let (($x18838 (and d_1_11 in_walk4_1 in_walk3_1)))
 (let (($x18836 (and d_1_10 in_walk4_1 in_walk3_1)))
 (let (($x18834 (and d_1_9 in_walk4_1 in_walk3_1)))
 (let (($x18832 (and d_1_8 in_walk4_1 in_walk3_1)))
 (let (($x18830 (and d_1_7 in_walk4_1 in_walk3_1)))
 (let (($x18828 (and d_1_6 in_walk4_1 in_walk3_1)))
 (let (($x18826 (and d_1_5 in_walk4_1 in_walk3_1)))
 (let (($x18824 (and d_1_4 in_walk4_1 in_walk3_1)))
 (let (($x18822 (and d_1_3 in_walk4_1 in_walk3_1)))
 (let (($x18820 (and d_1_2 in_walk4_1 in_walk3_1)))
 (let (($x18818 (and d_1_1 in_walk4_1 in_walk3_1)))
 (let (($x18817 (and d_1_0 in_walk4_1 in_walk3_1)))
 (let (($x18865 (or $x18817 $x18818 $x18820 $x18822 $x18824 $x18826 $x18828 $x18830 $x18832 $x18834 $x18836 $x18838 $x18840 $x18842 $x18844 $x18846 $x18848 $x18850 $x18852 $x18854 $x18856 $x18858 $x18860 $x18862 $x18864)))
 (let (($x18788 (and d_0_24 in_walk4_0 in_walk3_0)))
 (let (($x18786 (and d_0_23 in_walk4_0 in_walk3_0)))
 (let (($x18784 (and d_0_22 in_walk4_0 in_walk3_0)))
 (let (($x18782 (and d_0_21 in_walk4_0 in_walk3_0)))
 (let (($x18780 (and d_0_20 in_walk4_0 in_walk3_0)))
 (let (($x18778 (and d_0_19 in_walk4_0 in_walk3_0)))
 (let (($x18776 (and d_0_18 in_walk4_0 in_walk3_0)))
 (let (($x18774 (and d_0_17 in_walk4_0 in_walk3_0)))
 (let (($x18772 (and d_0_16 in_walk4_0 in_walk3_0)))
 (let (($x18770 (and d_0_15 in_walk4_0 in_walk3_0)))
 (let (($x18768 (and d_0_14 in_walk4_0 in_walk3_0)))
 (let (($x18766 (and d_0_13 in_walk4_0 in_walk3_0)))
 (let (($x18764 (and d_0_12 in_walk4_0 in_walk3_0)))
 (let (($x18762 (and d_0_11 in_walk4_0 in_walk3_0)))
 (let (($x18760 (and d_0_10 in_walk4_0 in_walk3_0)))
 (let (($x18758 (and d_0_9 in_walk4_0 in_walk3_0)))
 (let (($x18756 (and d_0_8 in_walk4_0 in_walk3_0)))
 (let (($x18754 (and d_0_7 in_walk4_0 in_walk3_0)))
 (let (($x18752 (and d_0_6 in_walk4_0 in_walk3_0)))
 (let (($x18750 (and d_0_5 in_walk4_0 in_walk3_0)))
 (let (($x18748 (and d_0_4 in_walk4_0 in_walk3_0)))
 (let (($x18746 (and d_0_3 in_walk4_0 in_walk3_0)))
 (let (($x18744 (and d_0_2 in_walk4_0 in_walk3_0)))
 (let (($x18742 (and d_0_1 in_walk4_0 in_walk3_0)))
 (let (($x18741 (and d_0_0 in_walk4_0 in_walk3_0)))
 (let (($x18789 (or $x18741 $x18742 $x18744 $x18746 $x18748 $x18750 $x18752 $x18754 $x18756 $x18758 $x18760 $x18762 $x18764 $x18766 $x18768 $x18770 $x18772 $x18774 $x18776 $x18778 $x18780 $x18782 $x18784 $x18786 $x18788)))
 (let (($x18739 (or false $x18789)))
 (let (($x18815 (or $x18739 $x18865)))
 (let (($x18891 (or $x18815 $x18941)))
 (let (($x18709 (and d_3_24 in_walk8_3 in_walk2_3)))
 (let (($x18707 (and d_3_23 in_walk8_3 in_walk2_3)))
 (let (($x18705 (and d_3_22 in_walk8_3 in_walk2_3)))
 (let (($x18703 (and d_3_21 in_walk8_3 in_walk2_3)))
 (let (($x18701 (and d_3_20 in_walk8_3 in_walk2_3)))
 (let (($x18699 (and d_3_19 in_walk8_3 in_walk2_3)))
 (let (($x18697 (and d_3_18 in_walk8_3 in_walk2_3)))
 (let (($x18695 (and d_3_17 in_walk8_3 in_walk2_3)))
 (let (($x18693 (and d_3_16 in_walk8_3 in_walk2_3)))
 (let (($x18691 (and d_3_15 in_walk8_3 in_walk2_3)))
 (let (($x18689 (and d_3_14 in_walk8_3 in_walk2_3)))
 (let (($x18687 (and d_3_13 in_walk8_3 in_walk2_3)))
 (let (($x18685 (and d_3_12 in_walk8_3 in_walk2_3)))
 (let (($x18683 (and d_3_11 in_walk8_3 in_walk2_3)))
 (let (($x18681 (and d_3_10 in_walk8_3 in_walk2_3)))
 (let (($x18679 (and d_3_9 in_walk8_3 in_walk2_3)))
 (let (($x18677 (and d_3_8 in_walk8_3 in_walk2_3)))
 (let (($x18675 (and d_3_7 in_walk8_3 in_walk2_3)))
 (let (($x18673 (and d_3_6 in_walk8_3 in_walk2_3)))
 (let (($x18671 (and d_3_5 in_walk8_3 in_walk2_3)))
 (let (($x18669 (and d_3_4 in_walk8_3 in_walk2_3)))
 (let (($x18667 (and d_3_3 in_walk8_3 in_walk2_3)))
 (let (($x18665 (and d_3_2 in_walk8_3 in_walk2_3)))
 (let (($x18663 (and d_3_1 in_walk8_3 in_walk2_3)))
 (let (($x18662 (and d_3_0 in_walk8_3 in_walk2_3)))
 (let (($x18710 (or $x18662 $x18663 $x18665 $x18667 $x18669 $x18671 $x18673 $x18675 $x18677 $x18679 $x18681 $x18683 $x18685 $x18687 $x18689 $x18691 $x18693 $x18695 $x18697 $x18699 $x18701 $x18703 $x18705 $x18707 $x18709)))
 (let (($x18633 (and d_2_24 in_walk8_2 in_walk2_2)))
 (let (($x18631 (and d_2_23 in_walk8_2 in_walk2_2)))
 (let (($x18629 (and d_2_22 in_walk8_2 in_walk2_2)))
 (let (($x18627 (and d_2_21 in_walk8_2 in_walk2_2)))
 (let (($x18625 (and d_2_20 in_walk8_2 in_walk2_2)))
 (let (($x18623 (and d_2_19 in_walk8_2 in_walk2_2)))
 (let (($x18621 (and d_2_18 in_walk8_2 in_walk2_2)))
 (let (($x18619 (and d_2_17 in_walk8_2 in_walk2_2)))
 (let (($x18617 (and d_2_16 in_walk8_2 in_walk2_2)))
 (let (($x18615 (and d_2_15 in_walk8_2 in_walk2_2)))
 (let (($x18613 (and d_2_14 in_walk8_2 in_walk2_2)))
 (let (($x18611 (and d_2_13 in_walk8_2 in_walk2_2)))
 (let (($x18609 (and d_2_12 in_walk8_2 in_walk2_2)))
 (let (($x18607 (and d_2_11 in_walk8_2 in_walk2_2)))
 (let (($x18605 (and d_2_10 in_walk8_2 in_walk2_2)))
 (let (($x18603 (and d_2_9 in_walk8_2 in_walk2_2)))
 (let (($x18601 (and d_2_8 in_walk8_2 in_walk2_2)))
 (let (($x18599 (and d_2_7 in_walk8_2 in_walk2_2)))
 (let (($x18597 (and d_2_6 in_walk8_2 in_walk2_2)))
 (let (($x18595 (and d_2_5 in_walk8_2 in_walk2_2)))
 (let (($x18593 (and d_2_4 in_walk8_2 in_walk2_2)))
 (let (($x18591 (and d_2_3 in_walk8_2 in_walk2_2)))
 (let (($x18589 (and d_2_2 in_walk8_2 in_walk2_2)))
 (let (($x18587 (and d_2_1 in_walk8_2 in_walk2_2)))
 (let (($x18586 (and d_2_0 in_walk8_2 in_walk2_2)))
 (let (($x18634 (or $x18586 $x18587 $x18589 $x18591 $x18593 $x18595 $x18597 $x18599 $x18601 $x18603 $x18605 $x18607 $x18609 $x18611 $x18613 $x18615 $x18617 $x18619 $x18621 $x18623 $x18625 $x18627 $x18629 $x18631 $x18633)))
 (let (($x18557 (and d_1_24 in_walk8_1 in_walk2_1)))
 (let (($x18555 (and d_1_23 in_walk8_1 in_walk2_1)))
 (let (($x18553 (and d_1_22 in_walk8_1 in_walk2_1)))
 (let (($x18551 (and d_1_21 in_walk8_1 in_walk2_1)))
 (let (($x18549 (and d_1_20 in_walk8_1 in_walk2_1)))
 (let (($x18547 (and d_1_19 in_walk8_1 in_walk2_1)))
 (let (($x18545 (and d_1_18 in_walk8_1 in_walk2_1)))
 (let (($x18543 (and d_1_17 in_walk8_1 in_walk2_1)))
 (let (($x18541 (and d_1_16 in_walk8_1 in_walk2_1)))
 (let (($x18539 (and d_1_15 in_walk8_1 in_walk2_1)))
 (let (($x18537 (and d_1_14 in_walk8_1 in_walk2_1)))
 (let (($x18535 (and d_1_13 in_walk8_1 in_walk2_1)))
 (let (($x18533 (and d_1_12 in_walk8_1 in_walk2_1)))
 (let (($x18531 (and d_1_11 in_walk8_1 in_walk2_1)))
 (let (($x18529 (and d_1_10 in_walk8_1 in_walk2_1)))
 (let (($x18527 (and d_1_9 in_walk8_1 in_walk2_1)))
 (let (($x18525 (and d_1_8 in_walk8_1 in_walk2_1)))
 (let (($x18523 (and d_1_7 in_walk8_1 in_walk2_1)))
 (let (($x18521 (and d_1_6 in_walk8_1 in_walk2_1)))
 (let (($x18519 (and d_1_5 in_walk8_1 in_walk2_1)))
 (let (($x18517 (and d_1_4 in_walk8_1 in_walk2_1)))
 (let (($x18515 (and d_1_3 in_walk8_1 in_walk2_1)))
 (let (($x18513 (and d_1_2 in_walk8_1 in_walk2_1)))
 (let (($x18511 (and d_1_1 in_walk8_1 in_walk2_1)))
 (let (($x18510 (and d_1_0 in_walk8_1 in_walk2_1)))
 (let (($x18558 (or $x18510 $x18511 $x18513 $x18515 $x18517 $x18519 $x18521 $x18523 $x18525 $x18527 $x18529 $x18531 $x18533 $x18535 $x18537 $x18539 $x18541 $x18543 $x18545 $x18547 $x18549 $x18551 $x18553 $x18555 $x18557)))
 (let (($x18481 (and d_0_24 in_walk8_0 in_walk2_0)))
 (let (($x18479 (and d_0_23 in_walk8_0 in_walk2_0)))
 (let (($x18477 (and d_0_22 in_walk8_0 in_walk2_0)))
 (let (($x18475 (and d_0_21 in_walk8_0 in_walk2_0)))
 (let (($x18473 (and d_0_20 in_walk8_0 in_walk2_0)))
 (let (($x18471 (and d_0_19 in_walk8_0 in_walk2_0)))
 (let (($x18469 (and d_0_18 in_walk8_0 in_walk2_0)))
 (let (($x18467 (and d_0_17 in_walk8_0 in_walk2_0)))
 (let (($x18465 (and d_0_16 in_walk8_0 in_walk2_0)))
 (let (($x18463 (and d_0_15 in_walk8_0 in_walk2_0)))
 (let (($x18461 (and d_0_14 in_walk8_0 in_walk2_0)))
 (let (($x18459 (and d_0_13 in_walk8_0 in_walk2_0)))
 (let (($x18457 (and d_0_12 in_walk8_0 in_walk2_0)))
 (let (($x18455 (and d_0_11 in_walk8_0 in_walk2_0)))
 (let (($x18453 (and d_0_10 in_walk8_0 in_walk2_0)))
 (let (($x18451 (and d_0_9 in_walk8_0 in_walk2_0)))
 (let (($x18449 (and d_0_8 in_walk8_0 in_walk2_0)))
 (let (($x18447 (and d_0_7 in_walk8_0 in_walk2_0)))
 (let (($x18445 (and d_0_6 in_walk8_0 in_walk2_0)))
 (let (($x18443 (and d_0_5 in_walk8_0 in_walk2_0)))
 (let (($x18441 (and d_0_4 in_walk8_0 in_walk2_0)))
 (let (($x18439 (and d_0_3 in_walk8_0 in_walk2_0)))
 (let (($x18437 (and d_0_2 in_walk8_0 in_walk2_0)))
 (let (($x18435 (and d_0_1 in_walk8_0 in_walk2_0)))
 (let (($x18434 (and d_0_0 in_walk8_0 in_walk2_0)))
 (let (($x18482 (or $x18434 $x18435 $x18437 $x18439 $x18441 $x18443 $x18445 $x18447 $x18449 $x18451 $x18453 $x18455 $x18457 $x18459 $x18461 $x18463 $x18465 $x18467 $x18469 $x18471 $x18473 $x18475 $x18477 $x18479 $x18481)))
 (let (($x18432 (or false $x18482)))
 (let (($x18508 (or $x18432 $x18558)))
 (let (($x18584 (or $x18508 $x18634)))
 (let (($x14651 (not (or (or (or (or false d_0_10) d_1_10) d_2_10) d_3_10))))
 (let (($x18402 (and d_3_24 in_walk7_3 in_walk2_3)))
 (let (($x18400 (and d_3_23 in_walk7_3 in_walk2_3)))
 (let (($x18398 (and d_3_22 in_walk7_3 in_walk2_3)))
 (let (($x18396 (and d_3_21 in_walk7_3 in_walk2_3)))
 (let (($x18394 (and d_3_20 in_walk7_3 in_walk2_3)))
 (let (($x18392 (and d_3_19 in_walk7_3 in_walk2_3)))
 (let (($x18390 (and d_3_18 in_walk7_3 in_walk2_3)))
 (let (($x18388 (and d_3_17 in_walk7_3 in_walk2_3)))
 (let (($x18386 (and d_3_16 in_walk7_3 in_walk2_3)))
 (let (($x18384 (and d_3_15 in_walk7_3 in_walk2_3)))
 (let (($x18382 (and d_3_14 in_walk7_3 in_walk2_3)))
 (let (($x18380 (and d_3_13 in_walk7_3 in_walk2_3)))
 (let (($x18378 (and d_3_12 in_walk7_3 in_walk2_3)))
 (let (($x18376 (and d_3_11 in_walk7_3 in_walk2_3)))
 (let (($x18374 (and d_3_10 in_walk7_3 in_walk2_3)))
 (let (($x18372 (and d_3_9 in_walk7_3 in_walk2_3)))
 (let (($x18370 (and d_3_8 in_walk7_3 in_walk2_3)))
 (let (($x18368 (and d_3_7 in_walk7_3 in_walk2_3)))
 (let (($x18366 (and d_3_6 in_walk7_3 in_walk2_3)))
 (let (($x18364 (and d_3_5 in_walk7_3 in_walk2_3)))
 (let (($x18362 (and d_3_4 in_walk7_3 in_walk2_3)))
 (let (($x18360 (and d_3_3 in_walk7_3 in_walk2_3)))
 (let (($x18358 (and d_3_2 in_walk7_3 in_walk2_3)))
 (let (($x18356 (and d_3_1 in_walk7_3 in_walk2_3)))
 (let (($x18355 (and d_3_0 in_walk7_3 in_walk2_3)))
 (let (($x18403 (or $x18355 $x18356 $x18358 $x18360 $x18362 $x18364 $x18366 $x18368 $x18370 $x18372 $x18374 $x18376 $x18378 $x18380 $x18382 $x18384 $x18386 $x18388 $x18390 $x18392 $x18394 $x18396 $x18398 $x18400 $x18402)))
 (let (($x18326 (and d_2_24 in_walk7_2 in_walk2_2)))
 (let (($x18324 (and d_2_23 in_walk7_2 in_walk2_2)))
 (let (($x18322 (and d_2_22 in_walk7_2 in_walk2_2)))
 (let (($x18320 (and d_2_21 in_walk7_2 in_walk2_2)))
 (let (($x18318 (and d_2_20 in_walk7_2 in_walk2_2)))
 (let (($x18316 (and d_2_19 in_walk7_2 in_walk2_2)))
 (let (($x18314 (and d_2_18 in_walk7_2 in_walk2_2)))
 (let (($x18312 (and d_2_17 in_walk7_2 in_walk2_2)))
 (let (($x18310 (and d_2_16 in_walk7_2 in_walk2_2)))
 (let (($x18308 (and d_2_15 in_walk7_2 in_walk2_2)))
 (let (($x18306 (and d_2_14 in_walk7_2 in_walk2_2)))
 (let (($x18304 (and d_2_13 in_walk7_2 in_walk2_2)))
 (let (($x18302 (and d_2_12 in_walk7_2 in_walk2_2)))
 (let (($x18300 (and d_2_11 in_walk7_2 in_walk2_2)))
 (let (($x18298 (and d_2_10 in_walk7_2 in_walk2_2)))
 (let (($x18296 (and d_2_9 in_walk7_2 in_walk2_2)))
 (let (($x18294 (and d_2_8 in_walk7_2 in_walk2_2)))
 (let (($x18292 (and d_2_7 in_walk7_2 in_walk2_2)))
 (let (($x18290 (and d_2_6 in_walk7_2 in_walk2_2)))
 (let (($x18288 (and d_2_5 in_walk7_2 in_walk2_2)))
 (let (($x18286 (and d_2_4 in_walk7_2 in_walk2_2)))
 (let (($x18284 (and d_2_3 in_walk7_2 in_walk2_2)))
 (let (($x18282 (and d_2_2 in_walk7_2 in_walk2_2)))
 (let (($x18280 (and d_2_1 in_walk7_2 in_walk2_2)))
 (let (($x18279 (and d_2_0 in_walk7_2 in_walk2_2)))
 (let (($x18327 (or $x18279 $x18280 $x18282 $x18284 $x18286 $x18288 $x18290 $x18292 $x18294 $x18296 $x18298 $x18300 $x18302 $x18304 $x18306 $x18308 $x18310 $x18312 $x18314 $x18316 $x18318 $x18320 $x18322 $x18324 $x18326)))
 (let (($x18250 (and d_1_24 in_walk7_1 in_walk2_1)))
 (let (($x18248 (and d_1_23 in_walk7_1 in_walk2_1)))
 (let (($x18246 (and d_1_22 in_walk7_1 in_walk2_1)))
 (let (($x18244 (and d_1_21 in_walk7_1 in_walk2_1)))
 (let (($x18242 (and d_1_20 in_walk7_1 in_walk2_1)))
 (let (($x18240 (and d_1_19 in_walk7_1 in_walk2_1)))
 (let (($x18238 (and d_1_18 in_walk7_1 in_walk2_1)))
 (let (($x18236 (and d_1_17 in_walk7_1 in_walk2_1)))
 (let (($x18234 (and d_1_16 in_walk7_1 in_walk2_1)))
 (let (($x18232 (and d_1_15 in_walk7_1 in_walk2_1)))
 (let (($x18230 (and d_1_14 in_walk7_1 in_walk2_1)))
 (let (($x18228 (and d_1_13 in_walk7_1 in_walk2_1)))
 (let (($x18226 (and d_1_12 in_walk7_1 in_walk2_1)))
 (let (($x18224 (and d_1_11 in_walk7_1 in_walk2_1)))
 (let (($x18222 (and d_1_10 in_walk7_1 in_walk2_1)))
 (let (($x18220 (and d_1_9 in_walk7_1 in_walk2_1)))
 (let (($x18218 (and d_1_8 in_walk7_1 in_walk2_1)))
 (let (($x18216 (and d_1_7 in_walk7_1 in_walk2_1)))
 (let (($x18214 (and d_1_6 in_walk7_1 in_walk2_1)))
 (let (($x18212 (and d_1_5 in_walk7_1 in_walk2_1)))
 (let (($x18210 (and d_1_4 in_walk7_1 in_walk2_1)))
 (let (($x18208 (and d_1_3 in_walk7_1 in_walk2_1)))
 (let (($x18206 (and d_1_2 in_walk7_1 in_walk2_1)))
 (let (($x18204 (and d_1_1 in_walk7_1 in_walk2_1)))
 (let (($x18203 (and d_1_0 in_walk7_1 in_walk2_1)))
 (let (($x18251 (or $x18203 $x18204 $x18206 $x18208 $x18210 $x18212 $x18214 $x18216 $x18218 $x18220 $x18222 $x18224 $x18226 $x18228 $x18230 $x18232 $x18234 $x18236 $x18238 $x18240 $x18242 $x18244 $x18246 $x18248 $x18250)))
 (let (($x18174 (and d_0_24 in_walk7_0 in_walk2_0)))
 (let (($x18172 (and d_0_23 in_walk7_0 in_walk2_0)))
 (let (($x18170 (and d_0_22 in_walk7_0 in_walk2_0)))
 (let (($x18168 (and d_0_21 in_walk7_0 in_walk2_0)))
 (let (($x18166 (and d_0_20 in_walk7_0 in_walk2_0)))
 (let (($x18164 (and d_0_19 in_walk7_0 in_walk2_0)))
 (let (($x18162 (and d_0_18 in_walk7_0 in_walk2_0)))
 (let (($x18160 (and d_0_17 in_walk7_0 in_walk2_0)))
 (let (($x18158 (and d_0_16 in_walk7_0 in_walk2_0)))
 (let (($x18156 (and d_0_15 in_walk7_0 in_walk2_0)))
 (let (($x18154 (and d_0_14 in_walk7_0 in_walk2_0)))
 (let (($x18152 (and d_0_13 in_walk7_0 in_walk2_0)))
 (let (($x18150 (and d_0_12 in_walk7_0 in_walk2_0)))
 (let (($x18148 (and d_0_11 in_walk7_0 in_walk2_0)))
 (let (($x18146 (and d_0_10 in_walk7_0 in_walk2_0)))
 (let (($x18144 (and d_0_9 in_walk7_0 in_walk2_0)))
 (let (($x18142 (and d_0_8 in_walk7_0 in_walk2_0)))
 (let (($x18140 (and d_0_7 in_walk7_0 in_walk2_0)))
 (let (($x18138 (and d_0_6 in_walk7_0 in_walk2_0)))
 (let (($x18136 (and d_0_5 in_walk7_0 in_walk2_0)))
 (let (($x18134 (and d_0_4 in_walk7_0 in_walk2_0)))
 (let (($x18132 (and d_0_3 in_walk7_0 in_walk2_0)))
 (let (($x18130 (and d_0_2 in_walk7_0 in_walk2_0)))
 (let (($x18128 (and d_0_1 in_walk7_0 in_walk2_0)))
 (let (($x18127 (and d_0_0 in_walk7_0 in_walk2_0)))
 (let (($x18175 (or $x18127 $x18128 $x18130 $x18132 $x18134 $x18136 $x18138 $x18140 $x18142 $x18144 $x18146 $x18148 $x18150 $x18152 $x18154 $x18156 $x18158 $x18160 $x18162 $x18164 $x18166 $x18168 $x18170 $x18172 $x18174)))
 (let (($x18125 (or false $x18175)))
 (let (($x18201 (or $x18125 $x18251)))
 (let (($x18277 (or $x18201 $x18327)))
 (let (($x18095 (and d_3_24 in_walk6_3 in_walk2_3)))
 (let (($x18093 (and d_3_23 in_walk6_3 in_walk2_3)))
 (let (($x18091 (and d_3_22 in_walk6_3 in_walk2_3)))
 (let (($x18089 (and d_3_21 in_walk6_3 in_walk2_3)))
 (let (($x18087 (and d_3_20 in_walk6_3 in_walk2_3)))
 (let (($x18085 (and d_3_19 in_walk6_3 in_walk2_3)))
 (let (($x18083 (and d_3_18 in_walk6_3 in_walk2_3)))
 (let (($x18081 (and d_3_17 in_walk6_3 in_walk2_3)))
 (let (($x18079 (and d_3_16 in_walk6_3 in_walk2_3)))
 (let (($x18077 (and d_3_15 in_walk6_3 in_walk2_3)))
 (let (($x18075 (and d_3_14 in_walk6_3 in_walk2_3)))
 (let (($x18073 (and d_3_13 in_walk6_3 in_walk2_3)))
 (let (($x18071 (and d_3_12 in_walk6_3 in_walk2_3)))
 (let (($x18069 (and d_3_11 in_walk6_3 in_walk2_3)))
 (let (($x18067 (and d_3_10 in_walk6_3 in_walk2_3)))
 (let (($x18065 (and d_3_9 in_walk6_3 in_walk2_3)))
 (let (($x18063 (and d_3_8 in_walk6_3 in_walk2_3)))
 (let (($x18061 (and d_3_7 in_walk6_3 in_walk2_3)))
 (let (($x18059 (and d_3_6 in_walk6_3 in_walk2_3)))
 (let (($x18057 (and d_3_5 in_walk6_3 in_walk2_3)))
 (let (($x18055 (and d_3_4 in_walk6_3 in_walk2_3)))
 (let (($x18053 (and d_3_3 in_walk6_3 in_walk2_3)))
 (let (($x18051 (and d_3_2 in_walk6_3 in_walk2_3)))
 (let (($x18049 (and d_3_1 in_walk6_3 in_walk2_3)))
 (let (($x18048 (and d_3_0 in_walk6_3 in_walk2_3)))
 (let (($x18096 (or $x18048 $x18049 $x18051 $x18053 $x18055 $x18057 $x18059 $x18061 $x18063 $x18065 $x18067 $x18069 $x18071 $x18073 $x18075 $x18077 $x18079 $x18081 $x18083 $x18085 $x18087 $x18089 $x18091 $x18093 $x18095)))
 (let (($x18019 (and d_2_24 in_walk6_2 in_walk2_2)))
 (let (($x18017 (and d_2_23 in_walk6_2 in_walk2_2)))
 (let (($x18015 (and d_2_22 in_walk6_2 in_walk2_2)))
 (let (($x18013 (and d_2_21 in_walk6_2 in_walk2_2)))
 (let (($x18011 (and d_2_20 in_walk6_2 in_walk2_2)))
 (let (($x18009 (and d_2_19 in_walk6_2 in_walk2_2)))
 (let (($x18007 (and d_2_18 in_walk6_2 in_walk2_2)))
 (let (($x18005 (and d_2_17 in_walk6_2 in_walk2_2)))
 (let (($x18003 (and d_2_16 in_walk6_2 in_walk2_2)))
 (let (($x18001 (and d_2_15 in_walk6_2 in_walk2_2)))
 (let (($x17999 (and d_2_14 in_walk6_2 in_walk2_2)))
 (let (($x17997 (and d_2_13 in_walk6_2 in_walk2_2)))
 (let (($x17995 (and d_2_12 in_walk6_2 in_walk2_2)))
 (let (($x17993 (and d_2_11 in_walk6_2 in_walk2_2)))
 (let (($x17991 (and d_2_10 in_walk6_2 in_walk2_2)))
 (let (($x17989 (and d_2_9 in_walk6_2 in_walk2_2)))
 (let (($x17987 (and d_2_8 in_walk6_2 in_walk2_2)))
 (let (($x17985 (and d_2_7 in_walk6_2 in_walk2_2)))
 (let (($x17983 (and d_2_6 in_walk6_2 in_walk2_2)))
 (let (($x17981 (and d_2_5 in_walk6_2 in_walk2_2)))
 (let (($x17979 (and d_2_4 in_walk6_2 in_walk2_2)))
 (let (($x17977 (and d_2_3 in_walk6_2 in_walk2_2)))
 (let (($x17975 (and d_2_2 in_walk6_2 in_walk2_2)))
 (let (($x17973 (and d_2_1 in_walk6_2 in_walk2_2)))
 (let (($x17972 (and d_2_0 in_walk6_2 in_walk2_2)))
 (let (($x18020 (or $x17972 $x17973 $x17975 $x17977 $x17979 $x17981 $x17983 $x17985 $x17987 $x17989 $x17991 $x17993 $x17995 $x17997 $x17999 $x18001 $x18003 $x18005 $x18007 $x18009 $x18011 $x18013 $x18015 $x18017 $x18019)))
 (let (($x17943 (and d_1_24 in_walk6_1 in_walk2_1)))
 (let (($x17941 (and d_1_23 in_walk6_1 in_walk2_1)))
 (let (($x17939 (and d_1_22 in_walk6_1 in_walk2_1)))
 (let (($x17937 (and d_1_21 in_walk6_1 in_walk2_1)))
 (let (($x17935 (and d_1_20 in_walk6_1 in_walk2_1)))
 (let (($x17933 (and d_1_19 in_walk6_1 in_walk2_1)))
 (let (($x17931 (and d_1_18 in_walk6_1 in_walk2_1)))
 (let (($x17929 (and d_1_17 in_walk6_1 in_walk2_1)))
 (let (($x17927 (and d_1_16 in_walk6_1 in_walk2_1)))
 (let (($x17925 (and d_1_15 in_walk6_1 in_walk2_1)))
 (let (($x17923 (and d_1_14 in_walk6_1 in_walk2_1)))
 (let (($x17921 (and d_1_13 in_walk6_1 in_walk2_1)))
 (let (($x17919 (and d_1_12 in_walk6_1 in_walk2_1)))
 (let (($x17917 (and d_1_11 in_walk6_1 in_walk2_1)))
 (let (($x17915 (and d_1_10 in_walk6_1 in_walk2_1)))
 (let (($x17913 (and d_1_9 in_walk6_1 in_walk2_1)))
 (let (($x17911 (and d_1_8 in_walk6_1 in_walk2_1)))
 (let (($x17909 (and d_1_7 in_walk6_1 in_walk2_1)))
 (let (($x17907 (and d_1_6 in_walk6_1 in_walk2_1)))
 (let (($x17905 (and d_1_5 in_walk6_1 in_walk2_1)))
 (let (($x17903 (and d_1_4 in_walk6_1 in_walk2_1)))
 (let (($x17901 (and d_1_3 in_walk6_1 in_walk2_1)))
 (let (($x17899 (and d_1_2 in_walk6_1 in_walk2_1)))
 (let (($x17897 (and d_1_1 in_walk6_1 in_walk2_1)))
 (let (($x17896 (and d_1_0 in_walk6_1 in_walk2_1)))
 (let (($x17944 (or $x17896 $x17897 $x17899 $x17901 $x17903 $x17905 $x17907 $x17909 $x17911 $x17913 $x17915 $x17917 $x17919 $x17921 $x17923 $x17925 $x17927 $x17929 $x17931 $x17933 $x17935 $x17937 $x17939 $x17941 $x17943)))
 (let (($x17867 (and d_0_24 in_walk6_0 in_walk2_0)))
 (let (($x17865 (and d_0_23 in_walk6_0 in_walk2_0)))
 (let (($x17863 (and d_0_22 in_walk6_0 in_walk2_0)))
 (let (($x17861 (and d_0_21 in_walk6_0 in_walk2_0)))
 (let (($x17859 (and d_0_20 in_walk6_0 in_walk2_0)))
 (let (($x17857 (and d_0_19 in_walk6_0 in_walk2_0)))
 (let (($x17855 (and d_0_18 in_walk6_0 in_walk2_0)))
 (let (($x17853 (and d_0_17 in_walk6_0 in_walk2_0)))
 (let (($x17851 (and d_0_16 in_walk6_0 in_walk2_0)))
 (let (($x17849 (and d_0_15 in_walk6_0 in_walk2_0)))
 (let (($x17847 (and d_0_14 in_walk6_0 in_walk2_0)))
 (let (($x17845 (and d_0_13 in_walk6_0 in_walk2_0)))
 (let (($x17843 (and d_0_12 in_walk6_0 in_walk2_0)))
 (let (($x17841 (and d_0_11 in_walk6_0 in_walk2_0)))
 (let (($x17839 (and d_0_10 in_walk6_0 in_walk2_0)))
 (let (($x17837 (and d_0_9 in_walk6_0 in_walk2_0)))
 (let (($x17835 (and d_0_8 in_walk6_0 in_walk2_0)))
 (let (($x17833 (and d_0_7 in_walk6_0 in_walk2_0)))
 (let (($x17831 (and d_0_6 in_walk6_0 in_walk2_0)))
 (let (($x17829 (and d_0_5 in_walk6_0 in_walk2_0)))
 (let (($x17827 (and d_0_4 in_walk6_0 in_walk2_0)))
 (let (($x17825 (and d_0_3 in_walk6_0 in_walk2_0)))
 (let (($x17823 (and d_0_2 in_walk6_0 in_walk2_0)))
 (let (($x17821 (and d_0_1 in_walk6_0 in_walk2_0)))
 (let (($x17820 (and d_0_0 in_walk6_0 in_walk2_0)))
 (let (($x17868 (or $x17820 $x17821 $x17823 $x17825 $x17827 $x17829 $x17831 $x17833 $x17835 $x17837 $x17839 $x17841 $x17843 $x17845 $x17847 $x17849 $x17851 $x17853 $x17855 $x17857 $x17859 $x17861 $x17863 $x17865 $x17867)))
 (let (($x17818 (or false $x17868)))
 (let (($x17894 (or $x17818 $x17944)))
 (let (($x17970 (or $x17894 $x18020)))
 (let (($x17788 (and d_3_24 in_walk5_3 in_walk2_3)))
 (let (($x17786 (and d_3_23 in_walk5_3 in_walk2_3)))
 (let (($x17784 (and d_3_22 in_walk5_3 in_walk2_3)))
 (let (($x17782 (and d_3_21 in_walk5_3 in_walk2_3)))
 (let (($x17780 (and d_3_20 in_walk5_3 in_walk2_3)))
 (let (($x17778 (and d_3_19 in_walk5_3 in_walk2_3)))
 (let (($x17776 (and d_3_18 in_walk5_3 in_walk2_3)))
 (let (($x17774 (and d_3_17 in_walk5_3 in_walk2_3)))
 (let (($x17772 (and d_3_16 in_walk5_3 in_walk2_3)))
 (let (($x17770 (and d_3_15 in_walk5_3 in_walk2_3)))
 (let (($x17768 (and d_3_14 in_walk5_3 in_walk2_3)))
 (let (($x17766 (and d_3_13 in_walk5_3 in_walk2_3)))
 (let (($x17764 (and d_3_12 in_walk5_3 in_walk2_3)))
 (let (($x17762 (and d_3_11 in_walk5_3 in_walk2_3)))
 (let (($x17760 (and d_3_10 in_walk5_3 in_walk2_3)))
 (let (($x17758 (and d_3_9 in_walk5_3 in_walk2_3)))
 (let (($x17756 (and d_3_8 in_walk5_3 in_walk2_3)))
 (let (($x17754 (and d_3_7 in_walk5_3 in_walk2_3)))
 (let (($x17752 (and d_3_6 in_walk5_3 in_walk2_3)))
 (let (($x17750 (and d_3_5 in_walk5_3 in_walk2_3)))
 (let (($x17748 (and d_3_4 in_walk5_3 in_walk2_3)))
 (let (($x17746 (and d_3_3 in_walk5_3 in_walk2_3)))
 (let (($x17744 (and d_3_2 in_walk5_3 in_walk2_3)))
 (let (($x17742 (and d_3_1 in_walk5_3 in_walk2_3)))
 (let (($x17741 (and d_3_0 in_walk5_3 in_walk2_3)))
 (let (($x17789 (or $x17741 $x17742 $x17744 $x17746 $x17748 $x17750 $x17752 $x17754 $x17756 $x17758 $x17760 $x17762 $x17764 $x17766 $x17768 $x17770 $x17772 $x17774 $x17776 $x17778 $x17780 $x17782 $x17784 $x17786 $x17788)))
 (let (($x17712 (and d_2_24 in_walk5_2 in_walk2_2)))
 (let (($x17710 (and d_2_23 in_walk5_2 in_walk2_2)))
 (let (($x17708 (and d_2_22 in_walk5_2 in_walk2_2)))
 (let (($x17706 (and d_2_21 in_walk5_2 in_walk2_2)))
 (let (($x17704 (and d_2_20 in_walk5_2 in_walk2_2)))
 (let (($x17702 (and d_2_19 in_walk5_2 in_walk2_2)))
 (let (($x17700 (and d_2_18 in_walk5_2 in_walk2_2)))
 (let (($x17698 (and d_2_17 in_walk5_2 in_walk2_2)))
 (let (($x17696 (and d_2_16 in_walk5_2 in_walk2_2)))
 (let (($x17694 (and d_2_15 in_walk5_2 in_walk2_2)))
 (let (($x17692 (and d_2_14 in_walk5_2 in_walk2_2)))
 (let (($x17690 (and d_2_13 in_walk5_2 in_walk2_2)))
 (let (($x17688 (and d_2_12 in_walk5_2 in_walk2_2)))
 (let (($x17686 (and d_2_11 in_walk5_2 in_walk2_2)))
 (let (($x17684 (and d_2_10 in_walk5_2 in_walk2_2)))
 (let (($x17682 (and d_2_9 in_walk5_2 in_walk2_2)))
 (let (($x17680 (and d_2_8 in_walk5_2 in_walk2_2)))
 (let (($x17678 (and d_2_7 in_walk5_2 in_walk2_2)))
 (let (($x17676 (and d_2_6 in_walk5_2 in_walk2_2)))
 (let (($x17674 (and d_2_5 in_walk5_2 in_walk2_2)))
 (let (($x17672 (and d_2_4 in_walk5_2 in_walk2_2)))
 (let (($x17670 (and d_2_3 in_walk5_2 in_walk2_2)))
 (let (($x17668 (and d_2_2 in_walk5_2 in_walk2_2)))
 (let (($x17666 (and d_2_1 in_walk5_2 in_walk2_2)))
 (let (($x17665 (and d_2_0 in_walk5_2 in_walk2_2)))
 (let (($x17713 (or $x17665 $x17666 $x17668 $x17670 $x17672 $x17674 $x17676 $x17678 $x17680 $x17682 $x17684 $x17686 $x17688 $x17690 $x17692 $x17694 $x17696 $x17698 $x17700 $x17702 $x17704 $x17706 $x17708 $x17710 $x17712)))
 (let (($x17636 (and d_1_24 in_walk5_1 in_walk2_1)))
 (let (($x17634 (and d_1_23 in_walk5_1 in_walk2_1)))
 (let (($x17632 (and d_1_22 in_walk5_1 in_walk2_1)))
 (let (($x17630 (and d_1_21 in_walk5_1 in_walk2_1)))
 (let (($x17628 (and d_1_20 in_walk5_1 in_walk2_1)))
 (let (($x17626 (and d_1_19 in_walk5_1 in_walk2_1)))
 (let (($x17624 (and d_1_18 in_walk5_1 in_walk2_1)))
 (let (($x17622 (and d_1_17 in_walk5_1 in_walk2_1)))
 (let (($x17620 (and d_1_16 in_walk5_1 in_walk2_1)))
 (let (($x17618 (and d_1_15 in_walk5_1 in_walk2_1)))
 (let (($x17616 (and d_1_14 in_walk5_1 in_walk2_1)))
 (let (($x17614 (and d_1_13 in_walk5_1 in_walk2_1)))
 (let (($x17612 (and d_1_12 in_walk5_1 in_walk2_1)))
 (let (($x17610 (and d_1_11 in_walk5_1 in_walk2_1)))
 (let (($x17608 (and d_1_10 in_walk5_1 in_walk2_1)))
 (let (($x17606 (and d_1_9 in_walk5_1 in_walk2_1)))
 (let (($x17604 (and d_1_8 in_walk5_1 in_walk2_1)))
 (let (($x17602 (and d_1_7 in_walk5_1 in_walk2_1)))
 (let (($x17600 (and d_1_6 in_walk5_1 in_walk2_1)))
 (let (($x17598 (and d_1_5 in_walk5_1 in_walk2_1)))
 (let (($x17596 (and d_1_4 in_walk5_1 in_walk2_1)))
 (let (($x17594 (and d_1_3 in_walk5_1 in_walk2_1)))
 (let (($x17592 (and d_1_2 in_walk5_1 in_walk2_1)))
 (let (($x17590 (and d_1_1 in_walk5_1 in_walk2_1)))
 (let (($x17589 (and d_1_0 in_walk5_1 in_walk2_1)))
 (let (($x17637 (or $x17589 $x17590 $x17592 $x17594 $x17596 $x17598 $x17600 $x17602 $x17604 $x17606 $x17608 $x17610 $x17612 $x17614 $x17616 $x17618 $x17620 $x17622 $x17624 $x17626 $x17628 $x17630 $x17632 $x17634 $x17636)))
 (let (($x17560 (and d_0_24 in_walk5_0 in_walk2_0)))
 (let (($x17558 (and d_0_23 in_walk5_0 in_walk2_0)))
 (let (($x17556 (and d_0_22 in_walk5_0 in_walk2_0)))
 (let (($x17554 (and d_0_21 in_walk5_0 in_walk2_0)))
 (let (($x17552 (and d_0_20 in_walk5_0 in_walk2_0)))
 (let (($x17550 (and d_0_19 in_walk5_0 in_walk2_0)))
 (let (($x17548 (and d_0_18 in_walk5_0 in_walk2_0)))
 (let (($x17546 (and d_0_17 in_walk5_0 in_walk2_0)))
 (let (($x17544 (and d_0_16 in_walk5_0 in_walk2_0)))
 (let (($x17542 (and d_0_15 in_walk5_0 in_walk2_0)))
 (let (($x17540 (and d_0_14 in_walk5_0 in_walk2_0)))
 (let (($x17538 (and d_0_13 in_walk5_0 in_walk2_0)))
 (let (($x17536 (and d_0_12 in_walk5_0 in_walk2_0)))
 (let (($x17534 (and d_0_11 in_walk5_0 in_walk2_0)))
 (let (($x17532 (and d_0_10 in_walk5_0 in_walk2_0)))
 (let (($x17530 (and d_0_9 in_walk5_0 in_walk2_0)))
 (let (($x17528 (and d_0_8 in_walk5_0 in_walk2_0)))
 (let (($x17526 (and d_0_7 in_walk5_0 in_walk2_0)))
 (let (($x17524 (and d_0_6 in_walk5_0 in_walk2_0)))
 (let (($x17522 (and d_0_5 in_walk5_0 in_walk2_0)))
 (let (($x17520 (and d_0_4 in_walk5_0 in_walk2_0)))
 (let (($x17518 (and d_0_3 in_walk5_0 in_walk2_0)))
 (let (($x17516 (and d_0_2 in_walk5_0 in_walk2_0)))
 (let (($x17514 (and d_0_1 in_walk5_0 in_walk2_0)))
 (let (($x17513 (and d_0_0 in_walk5_0 in_walk2_0)))
 (let (($x17561 (or $x17513 $x17514 $x17516 $x17518 $x17520 $x17522 $x17524 $x17526 $x17528 $x17530 $x17532 $x17534 $x17536 $x17538 $x17540 $x17542 $x17544 $x17546 $x17548 $x17550 $x17552 $x17554 $x17556 $x17558 $x17560)))
 (let (($x17511 (or false $x17561)))
 (let (($x17587 (or $x17511 $x17637)))
 (let (($x17663 (or $x17587 $x17713)))
 (let (($x17481 (and d_3_24 in_walk4_3 in_walk2_3)))
 (let (($x17479 (and d_3_23 in_walk4_3 in_walk2_3)))
 (let (($x17477 (and d_3_22 in_walk4_3 in_walk2_3)))
 (let (($x17475 (and d_3_21 in_walk4_3 in_walk2_3)))
 (let (($x17473 (and d_3_20 in_walk4_3 in_walk2_3)))
 (let (($x17471 (and d_3_19 in_walk4_3 in_walk2_3)))
 (let (($x17469 (and d_3_18 in_walk4_3 in_walk2_3)))
 (let (($x17467 (and d_3_17 in_walk4_3 in_walk2_3)))
 (let (($x17465 (and d_3_16 in_walk4_3 in_walk2_3)))
 (let (($x17463 (and d_3_15 in_walk4_3 in_walk2_3)))
 (let (($x17461 (and d_3_14 in_walk4_3 in_walk2_3)))
 (let (($x17459 (and d_3_13 in_walk4_3 in_walk2_3)))
 (let (($x17457 (and d_3_12 in_walk4_3 in_walk2_3)))
 (let (($x17455 (and d_3_11 in_walk4_3 in_walk2_3)))
 (let (($x17453 (and d_3_10 in_walk4_3 in_walk2_3)))
 (let (($x17451 (and d_3_9 in_walk4_3 in_walk2_3)))
 (let (($x17449 (and d_3_8 in_walk4_3 in_walk2_3)))
 (let (($x17447 (and d_3_7 in_walk4_3 in_walk2_3)))
 (let (($x17445 (and d_3_6 in_walk4_3 in_walk2_3)))
 (let (($x17443 (and d_3_5 in_walk4_3 in_walk2_3)))
 (let (($x17441 (and d_3_4 in_walk4_3 in_walk2_3)))
 (let (($x17439 (and d_3_3 in_walk4_3 in_walk2_3)))
 (let (($x17437 (and d_3_2 in_walk4_3 in_walk2_3)))
 (let (($x17435 (and d_3_1 in_walk4_3 in_walk2_3)))
 (let (($x17434 (and d_3_0 in_walk4_3 in_walk2_3)))
 (let (($x17482 (or $x17434 $x17435 $x17437 $x17439 $x17441 $x17443 $x17445 $x17447 $x17449 $x17451 $x17453 $x17455 $x17457 $x17459 $x17461 $x17463 $x17465 $x17467 $x17469 $x17471 $x17473 $x17475 $x17477 $x17479 $x17481)))
 (let (($x17405 (and d_2_24 in_walk4_2 in_walk2_2)))
 (let (($x17403 (and d_2_23 in_walk4_2 in_walk2_2)))
 (let (($x17401 (and d_2_22 in_walk4_2 in_walk2_2)))
 (let (($x17399 (and d_2_21 in_walk4_2 in_walk2_2)))
 (let (($x17397 (and d_2_20 in_walk4_2 in_walk2_2)))
 (let (($x17395 (and d_2_19 in_walk4_2 in_walk2_2)))
 (let (($x17393 (and d_2_18 in_walk4_2 in_walk2_2)))
 (let (($x17391 (and d_2_17 in_walk4_2 in_walk2_2)))
 (let (($x17389 (and d_2_16 in_walk4_2 in_walk2_2)))
 (let (($x17387 (and d_2_15 in_walk4_2 in_walk2_2)))
 (let (($x17385 (and d_2_14 in_walk4_2 in_walk2_2)))
 (let (($x17383 (and d_2_13 in_walk4_2 in_walk2_2)))
 (let (($x17381 (and d_2_12 in_walk4_2 in_walk2_2)))
 (let (($x17379 (and d_2_11 in_walk4_2 in_walk2_2)))
 (let (($x17377 (and d_2_10 in_walk4_2 in_walk2_2)))
 (let (($x17375 (and d_2_9 in_walk4_2 in_walk2_2)))
 (let (($x17373 (and d_2_8 in_walk4_2 in_walk2_2)))
 (let (($x17371 (and d_2_7 in_walk4_2 in_walk2_2)))
 (let (($x17369 (and d_2_6 in_walk4_2 in_walk2_2)))
 (let (($x17367 (and d_2_5 in_walk4_2 in_walk2_2)))
 (let (($x17365 (and d_2_4 in_walk4_2 in_walk2_2)))
 (let (($x17363 (and d_2_3 in_walk4_2 in_walk2_2)))
 (let (($x17361 (and d_2_2 in_walk4_2 in_walk2_2)))
 (let (($x17359 (and d_2_1 in_walk4_2 in_walk2_2)))
 (let (($x17358 (and d_2_0 in_walk4_2 in_walk2_2)))
 (let (($x17406 (or $x17358 $x17359 $x17361 $x17363 $x17365 $x17367 $x17369 $x17371 $x17373 $x17375 $x17377 $x17379 $x17381 $x17383 $x17385 $x17387 $x17389 $x17391 $x17393 $x17395 $x17397 $x17399 $x17401 $x17403 $x17405)))
 (let (($x17329 (and d_1_24 in_walk4_1 in_walk2_1)))
 (let (($x17327 (and d_1_23 in_walk4_1 in_walk2_1)))
 (let (($x17325 (and d_1_22 in_walk4_1 in_walk2_1)))
 (let (($x17323 (and d_1_21 in_walk4_1 in_walk2_1)))
 (let (($x17321 (and d_1_20 in_walk4_1 in_walk2_1)))
 (let (($x17319 (and d_1_19 in_walk4_1 in_walk2_1)))
 (let (($x17317 (and d_1_18 in_walk4_1 in_walk2_1)))
 (let (($x17315 (and d_1_17 in_walk4_1 in_walk2_1)))
 (let (($x17313 (and d_1_16 in_walk4_1 in_walk2_1)))
 (let (($x17311 (and d_1_15 in_walk4_1 in_walk2_1)))
 (let (($x17309 (and d_1_14 in_walk4_1 in_walk2_1)))
 (let (($x17307 (and d_1_13 in_walk4_1 in_walk2_1)))
 (let (($x17305 (and d_1_12 in_walk4_1 in_walk2_1)))
 (let (($x17303 (and d_1_11 in_walk4_1 in_walk2_1)))
 (let (($x17301 (and d_1_10 in_walk4_1 in_walk2_1)))
 (let (($x17299 (and d_1_9 in_walk4_1 in_walk2_1)))
 (let (($x17297 (and d_1_8 in_walk4_1 in_walk2_1)))
 (let (($x17295 (and d_1_7 in_walk4_1 in_walk2_1)))
 (let (($x17293 (and d_1_6 in_walk4_1 in_walk2_1)))
 (let (($x17291 (and d_1_5 in_walk4_1 in_walk2_1)))
 (let (($x17289 (and d_1_4 in_walk4_1 in_walk2_1)))
 (let (($x17287 (and d_1_3 in_walk4_1 in_walk2_1)))
 (let (($x17285 (and d_1_2 in_walk4_1 in_walk2_1)))
 (let (($x17283 (and d_1_1 in_walk4_1 in_walk2_1)))
 (let (($x17282 (and d_1_0 in_walk4_1 in_walk2_1)))
 (let (($x17330 (or $x17282 $x17283 $x17285 $x17287 $x17289 $x17291 $x17293 $x17295 $x17297 $x17299 $x17301 $x17303 $x17305 $x17307 $x17309 $x17311 $x17313 $x17315 $x17317 $x17319 $x17321 $x17323 $x17325 $x17327 $x17329)))
 (let (($x17253 (and d_0_24 in_walk4_0 in_walk2_0)))
 (let (($x17251 (and d_0_23 in_walk4_0 in_walk2_0)))
 (let (($x17249 (and d_0_22 in_walk4_0 in_walk2_0)))
 (let (($x17247 (and d_0_21 in_walk4_0 in_walk2_0)))
 (let (($x17245 (and d_0_20 in_walk4_0 in_walk2_0)))
 (let (($x17243 (and d_0_19 in_walk4_0 in_walk2_0)))
 (let (($x17241 (and d_0_18 in_walk4_0 in_walk2_0)))
 (let (($x17239 (and d_0_17 in_walk4_0 in_walk2_0)))
 (let (($x17237 (and d_0_16 in_walk4_0 in_walk2_0)))
 (let (($x17235 (and d_0_15 in_walk4_0 in_walk2_0)))
 (let (($x17233 (and d_0_14 in_walk4_0 in_walk2_0)))
 (let (($x17231 (and d_0_13 in_walk4_0 in_walk2_0)))
 (let (($x17229 (and d_0_12 in_walk4_0 in_walk2_0)))
 (let (($x17227 (and d_0_11 in_walk4_0 in_walk2_0)))
 (let (($x17225 (and d_0_10 in_walk4_0 in_walk2_0)))
 (let (($x17223 (and d_0_9 in_walk4_0 in_walk2_0)))
 (let (($x17221 (and d_0_8 in_walk4_0 in_walk2_0)))
 (let (($x17219 (and d_0_7 in_walk4_0 in_walk2_0)))
 (let (($x17217 (and d_0_6 in_walk4_0 in_walk2_0)))
 (let (($x17215 (and d_0_5 in_walk4_0 in_walk2_0)))
 (let (($x17213 (and d_0_4 in_walk4_0 in_walk2_0)))
 (let (($x17211 (and d_0_3 in_walk4_0 in_walk2_0)))
 (let (($x17209 (and d_0_2 in_walk4_0 in_walk2_0)))
 (let (($x17207 (and d_0_1 in_walk4_0 in_walk2_0)))
 (let (($x17206 (and d_0_0 in_walk4_0 in_walk2_0)))
 (let (($x17254 (or $x17206 $x17207 $x17209 $x17211 $x17213 $x17215 $x17217 $x17219 $x17221 $x17223 $x17225 $x17227 $x17229 $x17231 $x17233 $x17235 $x17237 $x17239 $x17241 $x17243 $x17245 $x17247 $x17249 $x17251 $x17253)))
 (let (($x17204 (or false $x17254)))
 (let (($x17280 (or $x17204 $x17330)))
 (let (($x17356 (or $x17280 $x17406)))
 (let (($x17174 (and d_3_24 in_walk3_3 in_walk2_3)))
 (let (($x17172 (and d_3_23 in_walk3_3 in_walk2_3)))
 (let (($x17170 (and d_3_22 in_walk3_3 in_walk2_3)))
 (let (($x17168 (and d_3_21 in_walk3_3 in_walk2_3)))
 (let (($x17166 (and d_3_20 in_walk3_3 in_walk2_3)))
 (let (($x17164 (and d_3_19 in_walk3_3 in_walk2_3)))
 (let (($x17162 (and d_3_18 in_walk3_3 in_walk2_3)))
 (let (($x17160 (and d_3_17 in_walk3_3 in_walk2_3)))
 (let (($x17158 (and d_3_16 in_walk3_3 in_walk2_3)))
 (let (($x17156 (and d_3_15 in_walk3_3 in_walk2_3)))
 (let (($x17154 (and d_3_14 in_walk3_3 in_walk2_3)))
 (let (($x17152 (and d_3_13 in_walk3_3 in_walk2_3)))
 (let (($x17150 (and d_3_12 in_walk3_3 in_walk2_3)))
 (let (($x17148 (and d_3_11 in_walk3_3 in_walk2_3)))
 (let (($x17146 (and d_3_10 in_walk3_3 in_walk2_3)))
 (let (($x17144 (and d_3_9 in_walk3_3 in_walk2_3)))
 (let (($x17142 (and d_3_8 in_walk3_3 in_walk2_3)))
 (let (($x17140 (and d_3_7 in_walk3_3 in_walk2_3)))
 (let (($x17138 (and d_3_6 in_walk3_3 in_walk2_3)))
 (let (($x17136 (and d_3_5 in_walk3_3 in_walk2_3)))
 (let (($x17134 (and d_3_4 in_walk3_3 in_walk2_3)))
 (let (($x17132 (and d_3_3 in_walk3_3 in_walk2_3)))
 (let (($x17130 (and d_3_2 in_walk3_3 in_walk2_3)))
 (let (($x17128 (and d_3_1 in_walk3_3 in_walk2_3)))
 (let (($x17127 (and d_3_0 in_walk3_3 in_walk2_3)))
 (let (($x17175 (or $x17127 $x17128 $x17130 $x17132 $x17134 $x17136 $x17138 $x17140 $x17142 $x17144 $x17146 $x17148 $x17150 $x17152 $x17154 $x17156 $x17158 $x17160 $x17162 $x17164 $x17166 $x17168 $x17170 $x17172 $x17174)))
 (let (($x17098 (and d_2_24 in_walk3_2 in_walk2_2)))
 (let (($x17096 (and d_2_23 in_walk3_2 in_walk2_2)))
 (let (($x17094 (and d_2_22 in_walk3_2 in_walk2_2)))
 (let (($x17092 (and d_2_21 in_walk3_2 in_walk2_2)))
 (let (($x17090 (and d_2_20 in_walk3_2 in_walk2_2)))
 (let (($x17088 (and d_2_19 in_walk3_2 in_walk2_2)))
 (let (($x17086 (and d_2_18 in_walk3_2 in_walk2_2)))
 (let (($x17084 (and d_2_17 in_walk3_2 in_walk2_2)))
 (let (($x17082 (and d_2_16 in_walk3_2 in_walk2_2)))
 (let (($x17080 (and d_2_15 in_walk3_2 in_walk2_2)))
 (let (($x17078 (and d_2_14 in_walk3_2 in_walk2_2)))
 (let (($x17076 (and d_2_13 in_walk3_2 in_walk2_2)))
 (let (($x17074 (and d_2_12 in_walk3_2 in_walk2_2)))
 (let (($x17072 (and d_2_11 in_walk3_2 in_walk2_2)))
 (let (($x17070 (and d_2_10 in_walk3_2 in_walk2_2)))
 (let (($x17068 (and d_2_9 in_walk3_2 in_walk2_2)))
 (let (($x17066 (and d_2_8 in_walk3_2 in_walk2_2)))
 (let (($x17064 (and d_2_7 in_walk3_2 in_walk2_2)))
 (let (($x17062 (and d_2_6 in_walk3_2 in_walk2_2)))
 (let (($x17060 (and d_2_5 in_walk3_2 in_walk2_2)))
 (let (($x17058 (and d_2_4 in_walk3_2 in_walk2_2)))
 (let (($x17056 (and d_2_3 in_walk3_2 in_walk2_2)))
 (let (($x17054 (and d_2_2 in_walk3_2 in_walk2_2)))
 (let (($x17052 (and d_2_1 in_walk3_2 in_walk2_2)))
 (let (($x17051 (and d_2_0 in_walk3_2 in_walk2_2)))
 (let (($x17099 (or $x17051 $x17052 $x17054 $x17056 $x17058 $x17060 $x17062 $x17064 $x17066 $x17068 $x17070 $x17072 $x17074 $x17076 $x17078 $x17080 $x17082 $x17084 $x17086 $x17088 $x17090 $x17092 $x17094 $x17096 $x17098)))
 (let (($x17022 (and d_1_24 in_walk3_1 in_walk2_1)))
 (let (($x17020 (and d_1_23 in_walk3_1 in_walk2_1)))
 (let (($x17018 (and d_1_22 in_walk3_1 in_walk2_1)))
 (let (($x17016 (and d_1_21 in_walk3_1 in_walk2_1)))
 (let (($x17014 (and d_1_20 in_walk3_1 in_walk2_1)))
 (let (($x17012 (and d_1_19 in_walk3_1 in_walk2_1)))
 (let (($x17010 (and d_1_18 in_walk3_1 in_walk2_1)))
 (let (($x17008 (and d_1_17 in_walk3_1 in_walk2_1)))
 (let (($x17006 (and d_1_16 in_walk3_1 in_walk2_1)))
 (let (($x17004 (and d_1_15 in_walk3_1 in_walk2_1)))
 (let (($x17002 (and d_1_14 in_walk3_1 in_walk2_1)))
 (let (($x17000 (and d_1_13 in_walk3_1 in_walk2_1)))
 (let (($x16998 (and d_1_12 in_walk3_1 in_walk2_1)))
 (let (($x16996 (and d_1_11 in_walk3_1 in_walk2_1)))
 (let (($x16994 (and d_1_10 in_walk3_1 in_walk2_1)))
 (let (($x16992 (and d_1_9 in_walk3_1 in_walk2_1)))
 (let (($x16990 (and d_1_8 in_walk3_1 in_walk2_1)))
 (let (($x16988 (and d_1_7 in_walk3_1 in_walk2_1)))
 (let (($x16986 (and d_1_6 in_walk3_1 in_walk2_1)))
 (let (($x16984 (and d_1_5 in_walk3_1 in_walk2_1)))
 (let (($x16982 (and d_1_4 in_walk3_1 in_walk2_1)))
 (let (($x16980 (and d_1_3 in_walk3_1 in_walk2_1)))
 (let (($x16978 (and d_1_2 in_walk3_1 in_walk2_1)))
 (let (($x16976 (and d_1_1 in_walk3_1 in_walk2_1)))
 (let (($x16975 (and d_1_0 in_walk3_1 in_walk2_1)))
 (let (($x17023 (or $x16975 $x16976 $x16978 $x16980 $x16982 $x16984 $x16986 $x16988 $x16990 $x16992 $x16994 $x16996 $x16998 $x17000 $x17002 $x17004 $x17006 $x17008 $x17010 $x17012 $x17014 $x17016 $x17018 $x17020 $x17022)))
 (let (($x16946 (and d_0_24 in_walk3_0 in_walk2_0)))
 (let (($x16944 (and d_0_23 in_walk3_0 in_walk2_0)))
 (let (($x16942 (and d_0_22 in_walk3_0 in_walk2_0)))
 (let (($x16940 (and d_0_21 in_walk3_0 in_walk2_0)))
 (let (($x16938 (and d_0_20 in_walk3_0 in_walk2_0)))
 (let (($x16936 (and d_0_19 in_walk3_0 in_walk2_0)))
 (let (($x16934 (and d_0_18 in_walk3_0 in_walk2_0)))
 (let (($x16932 (and d_0_17 in_walk3_0 in_walk2_0)))
 (let (($x16930 (and d_0_16 in_walk3_0 in_walk2_0)))
 (let (($x16928 (and d_0_15 in_walk3_0 in_walk2_0)))
 (let (($x16926 (and d_0_14 in_walk3_0 in_walk2_0)))
 (let (($x16924 (and d_0_13 in_walk3_0 in_walk2_0)))
 (let (($x16922 (and d_0_12 in_walk3_0 in_walk2_0)))
 (let (($x16920 (and d_0_11 in_walk3_0 in_walk2_0)))
 (let (($x16918 (and d_0_10 in_walk3_0 in_walk2_0)))
 (let (($x16916 (and d_0_9 in_walk3_0 in_walk2_0)))
 (let (($x16914 (and d_0_8 in_walk3_0 in_walk2_0)))
 (let (($x16912 (and d_0_7 in_walk3_0 in_walk2_0)))
 (let (($x16910 (and d_0_6 in_walk3_0 in_walk2_0)))
 (let (($x16908 (and d_0_5 in_walk3_0 in_walk2_0)))
 (let (($x16906 (and d_0_4 in_walk3_0 in_walk2_0)))
 (let (($x16904 (and d_0_3 in_walk3_0 in_walk2_0)))
 (let (($x16902 (and d_0_2 in_walk3_0 in_walk2_0)))
 (let (($x16900 (and d_0_1 in_walk3_0 in_walk2_0)))
 (let (($x16899 (and d_0_0 in_walk3_0 in_walk2_0)))
 (let (($x16947 (or $x16899 $x16900 $x16902 $x16904 $x16906 $x16908 $x16910 $x16912 $x16914 $x16916 $x16918 $x16920 $x16922 $x16924 $x16926 $x16928 $x16930 $x16932 $x16934 $x16936 $x16938 $x16940 $x16942 $x16944 $x16946)))
 (let (($x16897 (or false $x16947)))
 (let (($x16973 (or $x16897 $x17023)))
 (let (($x17049 (or $x16973 $x17099)))
 (let (($x16867 (and d_3_24 in_walk8_3 in_walk1_3)))
 (let (($x16865 (and d_3_23 in_walk8_3 in_walk1_3)))
 (let (($x16863 (and d_3_22 in_walk8_3 in_walk1_3)))
 (let (($x16861 (and d_3_21 in_walk8_3 in_walk1_3)))
 (let (($x16859 (and d_3_20 in_walk8_3 in_walk1_3)))
 (let (($x16857 (and d_3_19 in_walk8_3 in_walk1_3)))
 (let (($x16855 (and d_3_18 in_walk8_3 in_walk1_3)))
 (let (($x16853 (and d_3_17 in_walk8_3 in_walk1_3)))
 (let (($x16851 (and d_3_16 in_walk8_3 in_walk1_3)))
 (let (($x16849 (and d_3_15 in_walk8_3 in_walk1_3)))
 (let (($x16847 (and d_3_14 in_walk8_3 in_walk1_3)))
 (let (($x16845 (and d_3_13 in_walk8_3 in_walk1_3)))
 (let (($x16843 (and d_3_12 in_walk8_3 in_walk1_3)))
 (let (($x16841 (and d_3_11 in_walk8_3 in_walk1_3)))
 (let (($x16839 (and d_3_10 in_walk8_3 in_walk1_3)))
 (let (($x16837 (and d_3_9 in_walk8_3 in_walk1_3)))
 (let (($x16835 (and d_3_8 in_walk8_3 in_walk1_3)))
 (let (($x16833 (and d_3_7 in_walk8_3 in_walk1_3)))
 (let (($x16831 (and d_3_6 in_walk8_3 in_walk1_3)))
 (let (($x16829 (and d_3_5 in_walk8_3 in_walk1_3)))
 (let (($x16827 (and d_3_4 in_walk8_3 in_walk1_3)))
 (let (($x16825 (and d_3_3 in_walk8_3 in_walk1_3)))
 (let (($x16823 (and d_3_2 in_walk8_3 in_walk1_3)))
 (let (($x16821 (and d_3_1 in_walk8_3 in_walk1_3)))
 (let (($x16820 (and d_3_0 in_walk8_3 in_walk1_3)))
 (let (($x16868 (or $x16820 $x16821 $x16823 $x16825 $x16827 $x16829 $x16831 $x16833 $x16835 $x16837 $x16839 $x16841 $x16843 $x16845 $x16847 $x16849 $x16851 $x16853 $x16855 $x16857 $x16859 $x16861 $x16863 $x16865 $x16867)))
 (let (($x16791 (and d_2_24 in_walk8_2 in_walk1_2)))
 (let (($x16789 (and d_2_23 in_walk8_2 in_walk1_2)))
 (let (($x16787 (and d_2_22 in_walk8_2 in_walk1_2)))
 (let (($x16785 (and d_2_21 in_walk8_2 in_walk1_2)))
 (let (($x16783 (and d_2_20 in_walk8_2 in_walk1_2)))
 (let (($x16781 (and d_2_19 in_walk8_2 in_walk1_2)))
 (let (($x16779 (and d_2_18 in_walk8_2 in_walk1_2)))
 (let (($x16777 (and d_2_17 in_walk8_2 in_walk1_2)))
 (let (($x16775 (and d_2_16 in_walk8_2 in_walk1_2)))
 (let (($x16773 (and d_2_15 in_walk8_2 in_walk1_2)))
 (let (($x16771 (and d_2_14 in_walk8_2 in_walk1_2)))
 (let (($x16769 (and d_2_13 in_walk8_2 in_walk1_2)))
 (let (($x16767 (and d_2_12 in_walk8_2 in_walk1_2)))
 (let (($x16765 (and d_2_11 in_walk8_2 in_walk1_2)))
 (let (($x16763 (and d_2_10 in_walk8_2 in_walk1_2)))
 (let (($x16761 (and d_2_9 in_walk8_2 in_walk1_2)))
 (let (($x16759 (and d_2_8 in_walk8_2 in_walk1_2)))
 (let (($x16757 (and d_2_7 in_walk8_2 in_walk1_2)))
 (let (($x16755 (and d_2_6 in_walk8_2 in_walk1_2)))
 (let (($x16753 (and d_2_5 in_walk8_2 in_walk1_2)))
 (let (($x16751 (and d_2_4 in_walk8_2 in_walk1_2)))
 (let (($x16749 (and d_2_3 in_walk8_2 in_walk1_2)))
 (let (($x16747 (and d_2_2 in_walk8_2 in_walk1_2)))
 (let (($x16745 (and d_2_1 in_walk8_2 in_walk1_2)))
 (let (($x16744 (and d_2_0 in_walk8_2 in_walk1_2)))
 (let (($x16792 (or $x16744 $x16745 $x16747 $x16749 $x16751 $x16753 $x16755 $x16757 $x16759 $x16761 $x16763 $x16765 $x16767 $x16769 $x16771 $x16773 $x16775 $x16777 $x16779 $x16781 $x16783 $x16785 $x16787 $x16789 $x16791)))
 (let (($x16715 (and d_1_24 in_walk8_1 in_walk1_1)))
 (let (($x16713 (and d_1_23 in_walk8_1 in_walk1_1)))
 (let (($x16711 (and d_1_22 in_walk8_1 in_walk1_1)))
 (let (($x16709 (and d_1_21 in_walk8_1 in_walk1_1)))
 (let (($x16707 (and d_1_20 in_walk8_1 in_walk1_1)))
 (let (($x16705 (and d_1_19 in_walk8_1 in_walk1_1)))
 (let (($x16703 (and d_1_18 in_walk8_1 in_walk1_1)))
 (let (($x16701 (and d_1_17 in_walk8_1 in_walk1_1)))
 (let (($x16699 (and d_1_16 in_walk8_1 in_walk1_1)))
 (let (($x16697 (and d_1_15 in_walk8_1 in_walk1_1)))
 (let (($x16695 (and d_1_14 in_walk8_1 in_walk1_1)))
 (let (($x16693 (and d_1_13 in_walk8_1 in_walk1_1)))
 (let (($x16691 (and d_1_12 in_walk8_1 in_walk1_1)))
 (let (($x16689 (and d_1_11 in_walk8_1 in_walk1_1)))
 (let (($x16687 (and d_1_10 in_walk8_1 in_walk1_1)))
 (let (($x16685 (and d_1_9 in_walk8_1 in_walk1_1)))
 (let (($x16683 (and d_1_8 in_walk8_1 in_walk1_1)))
 (let (($x16681 (and d_1_7 in_walk8_1 in_walk1_1)))
 (let (($x16679 (and d_1_6 in_walk8_1 in_walk1_1)))
 (let (($x16677 (and d_1_5 in_walk8_1 in_walk1_1)))
 (let (($x16675 (and d_1_4 in_walk8_1 in_walk1_1)))
 (let (($x16673 (and d_1_3 in_walk8_1 in_walk1_1)))
 (let (($x16671 (and d_1_2 in_walk8_1 in_walk1_1)))
 (let (($x16669 (and d_1_1 in_walk8_1 in_walk1_1)))
 (let (($x16668 (and d_1_0 in_walk8_1 in_walk1_1)))
 (let (($x16716 (or $x16668 $x16669 $x16671 $x16673 $x16675 $x16677 $x16679 $x16681 $x16683 $x16685 $x16687 $x16689 $x16691 $x16693 $x16695 $x16697 $x16699 $x16701 $x16703 $x16705 $x16707 $x16709 $x16711 $x16713 $x16715)))
 (let (($x16639 (and d_0_24 in_walk8_0 in_walk1_0)))
 (let (($x16637 (and d_0_23 in_walk8_0 in_walk1_0)))
 (let (($x16635 (and d_0_22 in_walk8_0 in_walk1_0)))
 (let (($x16633 (and d_0_21 in_walk8_0 in_walk1_0)))
 (let (($x16631 (and d_0_20 in_walk8_0 in_walk1_0)))
 (let (($x16629 (and d_0_19 in_walk8_0 in_walk1_0)))
 (let (($x16627 (and d_0_18 in_walk8_0 in_walk1_0)))
 (let (($x16625 (and d_0_17 in_walk8_0 in_walk1_0)))
 (let (($x16623 (and d_0_16 in_walk8_0 in_walk1_0)))
 (let (($x16621 (and d_0_15 in_walk8_0 in_walk1_0)))
 (let (($x16619 (and d_0_14 in_walk8_0 in_walk1_0)))
 (let (($x16617 (and d_0_13 in_walk8_0 in_walk1_0)))
 (let (($x16615 (and d_0_12 in_walk8_0 in_walk1_0)))
 (let (($x16613 (and d_0_11 in_walk8_0 in_walk1_0)))
 (let (($x16611 (and d_0_10 in_walk8_0 in_walk1_0)))
 (let (($x16609 (and d_0_9 in_walk8_0 in_walk1_0)))
 (let (($x16607 (and d_0_8 in_walk8_0 in_walk1_0)))
 (let (($x16605 (and d_0_7 in_walk8_0 in_walk1_0)))
 (let (($x16603 (and d_0_6 in_walk8_0 in_walk1_0)))
 (let (($x16601 (and d_0_5 in_walk8_0 in_walk1_0)))
 (let (($x16599 (and d_0_4 in_walk8_0 in_walk1_0)))
 (let (($x16597 (and d_0_3 in_walk8_0 in_walk1_0)))
 (let (($x16595 (and d_0_2 in_walk8_0 in_walk1_0)))
 (let (($x16593 (and d_0_1 in_walk8_0 in_walk1_0)))
 (let (($x16592 (and d_0_0 in_walk8_0 in_walk1_0)))
 (let (($x16640 (or $x16592 $x16593 $x16595 $x16597 $x16599 $x16601 $x16603 $x16605 $x16607 $x16609 $x16611 $x16613 $x16615 $x16617 $x16619 $x16621 $x16623 $x16625 $x16627 $x16629 $x16631 $x16633 $x16635 $x16637 $x16639)))
 (let (($x16590 (or false $x16640)))
 (let (($x16666 (or $x16590 $x16716)))
 (let (($x16742 (or $x16666 $x16792)))
 (let (($x14643 (not (or (or (or (or false d_0_9) d_1_9) d_2_9) d_3_9))))
 (let (($x16552 (and d_3_24 in_walk7_3 in_walk1_3)))
 (let (($x16550 (and d_3_23 in_walk7_3 in_walk1_3)))
 (let (($x16548 (and d_3_22 in_walk7_3 in_walk1_3)))
 (let (($x16546 (and d_3_21 in_walk7_3 in_walk1_3)))
 (let (($x16544 (and d_3_20 in_walk7_3 in_walk1_3)))
 (let (($x16542 (and d_3_19 in_walk7_3 in_walk1_3)))
 (let (($x16540 (and d_3_18 in_walk7_3 in_walk1_3)))
 (let (($x16538 (and d_3_17 in_walk7_3 in_walk1_3)))
 (let (($x16536 (and d_3_16 in_walk7_3 in_walk1_3)))
 (let (($x16534 (and d_3_15 in_walk7_3 in_walk1_3)))
 (let (($x16532 (and d_3_14 in_walk7_3 in_walk1_3)))
 (let (($x16530 (and d_3_13 in_walk7_3 in_walk1_3)))
 (let (($x16528 (and d_3_12 in_walk7_3 in_walk1_3)))
 (let (($x16526 (and d_3_11 in_walk7_3 in_walk1_3)))
 (let (($x16524 (and d_3_10 in_walk7_3 in_walk1_3)))
 (let (($x16522 (and d_3_9 in_walk7_3 in_walk1_3)))
 (let (($x16520 (and d_3_8 in_walk7_3 in_walk1_3)))
 (let (($x16518 (and d_3_7 in_walk7_3 in_walk1_3)))
 (let (($x16516 (and d_3_6 in_walk7_3 in_walk1_3)))
 (let (($x16514 (and d_3_5 in_walk7_3 in_walk1_3)))
 (let (($x16512 (and d_3_4 in_walk7_3 in_walk1_3)))
 (let (($x16510 (and d_3_3 in_walk7_3 in_walk1_3)))
 (let (($x16508 (and d_3_2 in_walk7_3 in_walk1_3)))
 (let (($x16506 (and d_3_1 in_walk7_3 in_walk1_3)))
 (let (($x16505 (and d_3_0 in_walk7_3 in_walk1_3)))
 (let (($x16553 (or $x16505 $x16506 $x16508 $x16510 $x16512 $x16514 $x16516 $x16518 $x16520 $x16522 $x16524 $x16526 $x16528 $x16530 $x16532 $x16534 $x16536 $x16538 $x16540 $x16542 $x16544 $x16546 $x16548 $x16550 $x16552)))
 (let (($x16476 (and d_2_24 in_walk7_2 in_walk1_2)))
 (let (($x16474 (and d_2_23 in_walk7_2 in_walk1_2)))
 (let (($x16472 (and d_2_22 in_walk7_2 in_walk1_2)))
 (let (($x16470 (and d_2_21 in_walk7_2 in_walk1_2)))
 (let (($x16468 (and d_2_20 in_walk7_2 in_walk1_2)))
 (let (($x16466 (and d_2_19 in_walk7_2 in_walk1_2)))
 (let (($x16464 (and d_2_18 in_walk7_2 in_walk1_2)))
 (let (($x16462 (and d_2_17 in_walk7_2 in_walk1_2)))
 (let (($x16460 (and d_2_16 in_walk7_2 in_walk1_2)))
 (let (($x16458 (and d_2_15 in_walk7_2 in_walk1_2)))
 (let (($x16456 (and d_2_14 in_walk7_2 in_walk1_2)))
 (let (($x16454 (and d_2_13 in_walk7_2 in_walk1_2)))
 (let (($x16452 (and d_2_12 in_walk7_2 in_walk1_2)))
 (let (($x16450 (and d_2_11 in_walk7_2 in_walk1_2)))
 (let (($x16448 (and d_2_10 in_walk7_2 in_walk1_2)))
 (let (($x16446 (and d_2_9 in_walk7_2 in_walk1_2)))
 (let (($x16444 (and d_2_8 in_walk7_2 in_walk1_2)))
 (let (($x16442 (and d_2_7 in_walk7_2 in_walk1_2)))
 (let (($x16440 (and d_2_6 in_walk7_2 in_walk1_2)))
 (let (($x16438 (and d_2_5 in_walk7_2 in_walk1_2)))
 (let (($x16436 (and d_2_4 in_walk7_2 in_walk1_2)))
 (let (($x16434 (and d_2_3 in_walk7_2 in_walk1_2)))
 (let (($x16432 (and d_2_2 in_walk7_2 in_walk1_2)))
 (let (($x16430 (and d_2_1 in_walk7_2 in_walk1_2)))
 (let (($x16429 (and d_2_0 in_walk7_2 in_walk1_2)))
 (let (($x16477 (or $x16429 $x16430 $x16432 $x16434 $x16436 $x16438 $x16440 $x16442 $x16444 $x16446 $x16448 $x16450 $x16452 $x16454 $x16456 $x16458 $x16460 $x16462 $x16464 $x16466 $x16468 $x16470 $x16472 $x16474 $x16476)))
 (let (($x16400 (and d_1_24 in_walk7_1 in_walk1_1)))
 (let (($x16398 (and d_1_23 in_walk7_1 in_walk1_1)))
 (let (($x16396 (and d_1_22 in_walk7_1 in_walk1_1)))
 (let (($x16394 (and d_1_21 in_walk7_1 in_walk1_1)))
 (let (($x16392 (and d_1_20 in_walk7_1 in_walk1_1)))
 (let (($x16390 (and d_1_19 in_walk7_1 in_walk1_1)))
 (let (($x16388 (and d_1_18 in_walk7_1 in_walk1_1)))
 (let (($x16386 (and d_1_17 in_walk7_1 in_walk1_1)))
 (let (($x16384 (and d_1_16 in_walk7_1 in_walk1_1)))
 (let (($x16382 (and d_1_15 in_walk7_1 in_walk1_1)))
 (let (($x16380 (and d_1_14 in_walk7_1 in_walk1_1)))
 (let (($x16378 (and d_1_13 in_walk7_1 in_walk1_1)))
 (let (($x16376 (and d_1_12 in_walk7_1 in_walk1_1)))
 (let (($x16374 (and d_1_11 in_walk7_1 in_walk1_1)))
 (let (($x16372 (and d_1_10 in_walk7_1 in_walk1_1)))
 (let (($x16370 (and d_1_9 in_walk7_1 in_walk1_1)))
 (let (($x16368 (and d_1_8 in_walk7_1 in_walk1_1)))
 (let (($x16366 (and d_1_7 in_walk7_1 in_walk1_1)))
 (let (($x16364 (and d_1_6 in_walk7_1 in_walk1_1)))
 (let (($x16362 (and d_1_5 in_walk7_1 in_walk1_1)))
 (let (($x16360 (and d_1_4 in_walk7_1 in_walk1_1)))
 (let (($x16358 (and d_1_3 in_walk7_1 in_walk1_1)))
 (let (($x16356 (and d_1_2 in_walk7_1 in_walk1_1)))
 (let (($x16354 (and d_1_1 in_walk7_1 in_walk1_1)))
 (let (($x16353 (and d_1_0 in_walk7_1 in_walk1_1)))
 (let (($x16401 (or $x16353 $x16354 $x16356 $x16358 $x16360 $x16362 $x16364 $x16366 $x16368 $x16370 $x16372 $x16374 $x16376 $x16378 $x16380 $x16382 $x16384 $x16386 $x16388 $x16390 $x16392 $x16394 $x16396 $x16398 $x16400)))
 (let (($x16324 (and d_0_24 in_walk7_0 in_walk1_0)))
 (let (($x16322 (and d_0_23 in_walk7_0 in_walk1_0)))
 (let (($x16320 (and d_0_22 in_walk7_0 in_walk1_0)))
 (let (($x16318 (and d_0_21 in_walk7_0 in_walk1_0)))
 (let (($x16316 (and d_0_20 in_walk7_0 in_walk1_0)))
 (let (($x16314 (and d_0_19 in_walk7_0 in_walk1_0)))
 (let (($x16312 (and d_0_18 in_walk7_0 in_walk1_0)))
 (let (($x16310 (and d_0_17 in_walk7_0 in_walk1_0)))
 (let (($x16308 (and d_0_16 in_walk7_0 in_walk1_0)))
 (let (($x16306 (and d_0_15 in_walk7_0 in_walk1_0)))
 (let (($x16304 (and d_0_14 in_walk7_0 in_walk1_0)))
 (let (($x16302 (and d_0_13 in_walk7_0 in_walk1_0)))
 (let (($x16300 (and d_0_12 in_walk7_0 in_walk1_0)))
 (let (($x16298 (and d_0_11 in_walk7_0 in_walk1_0)))
 (let (($x16296 (and d_0_10 in_walk7_0 in_walk1_0)))
 (let (($x16294 (and d_0_9 in_walk7_0 in_walk1_0)))
 (let (($x16292 (and d_0_8 in_walk7_0 in_walk1_0)))
 (let (($x16290 (and d_0_7 in_walk7_0 in_walk1_0)))
 (let (($x16288 (and d_0_6 in_walk7_0 in_walk1_0)))
 (let (($x16286 (and d_0_5 in_walk7_0 in_walk1_0)))
 (let (($x16284 (and d_0_4 in_walk7_0 in_walk1_0)))
 (let (($x16282 (and d_0_3 in_walk7_0 in_walk1_0)))
 (let (($x16280 (and d_0_2 in_walk7_0 in_walk1_0)))
 (let (($x16278 (and d_0_1 in_walk7_0 in_walk1_0)))
 (let (($x16277 (and d_0_0 in_walk7_0 in_walk1_0)))
 (let (($x16325 (or $x16277 $x16278 $x16280 $x16282 $x16284 $x16286 $x16288 $x16290 $x16292 $x16294 $x16296 $x16298 $x16300 $x16302 $x16304 $x16306 $x16308 $x16310 $x16312 $x16314 $x16316 $x16318 $x16320 $x16322 $x16324)))
 (let (($x16275 (or false $x16325)))
 (let (($x16351 (or $x16275 $x16401)))
 (let (($x16427 (or $x16351 $x16477)))
 (let (($x16237 (and d_3_24 in_walk6_3 in_walk1_3)))
 (let (($x16235 (and d_3_23 in_walk6_3 in_walk1_3)))
 (let (($x16233 (and d_3_22 in_walk6_3 in_walk1_3)))
 (let (($x16231 (and d_3_21 in_walk6_3 in_walk1_3)))
 (let (($x16229 (and d_3_20 in_walk6_3 in_walk1_3)))
 (let (($x16227 (and d_3_19 in_walk6_3 in_walk1_3)))
 (let (($x16225 (and d_3_18 in_walk6_3 in_walk1_3)))
 (let (($x16223 (and d_3_17 in_walk6_3 in_walk1_3)))
 (let (($x16221 (and d_3_16 in_walk6_3 in_walk1_3)))
 (let (($x16219 (and d_3_15 in_walk6_3 in_walk1_3)))
 (let (($x16217 (and d_3_14 in_walk6_3 in_walk1_3)))
 (let (($x16215 (and d_3_13 in_walk6_3 in_walk1_3)))
 (let (($x16213 (and d_3_12 in_walk6_3 in_walk1_3)))
 (let (($x16211 (and d_3_11 in_walk6_3 in_walk1_3)))
 (let (($x16209 (and d_3_10 in_walk6_3 in_walk1_3)))
 (let (($x16207 (and d_3_9 in_walk6_3 in_walk1_3)))
 (let (($x16205 (and d_3_8 in_walk6_3 in_walk1_3)))
 (let (($x16203 (and d_3_7 in_walk6_3 in_walk1_3)))
 (let (($x16201 (and d_3_6 in_walk6_3 in_walk1_3)))
 (let (($x16199 (and d_3_5 in_walk6_3 in_walk1_3)))
 (let (($x16197 (and d_3_4 in_walk6_3 in_walk1_3)))
 (let (($x16195 (and d_3_3 in_walk6_3 in_walk1_3)))
 (let (($x16193 (and d_3_2 in_walk6_3 in_walk1_3)))
 (let (($x16191 (and d_3_1 in_walk6_3 in_walk1_3)))
 (let (($x16190 (and d_3_0 in_walk6_3 in_walk1_3)))
 (let (($x16238 (or $x16190 $x16191 $x16193 $x16195 $x16197 $x16199 $x16201 $x16203 $x16205 $x16207 $x16209 $x16211 $x16213 $x16215 $x16217 $x16219 $x16221 $x16223 $x16225 $x16227 $x16229 $x16231 $x16233 $x16235 $x16237)))
 (let (($x16161 (and d_2_24 in_walk6_2 in_walk1_2)))
 (let (($x16159 (and d_2_23 in_walk6_2 in_walk1_2)))
 (let (($x16157 (and d_2_22 in_walk6_2 in_walk1_2)))
 (let (($x16155 (and d_2_21 in_walk6_2 in_walk1_2)))
 (let (($x16153 (and d_2_20 in_walk6_2 in_walk1_2)))
 (let (($x16151 (and d_2_19 in_walk6_2 in_walk1_2)))
 (let (($x16149 (and d_2_18 in_walk6_2 in_walk1_2)))
 (let (($x16147 (and d_2_17 in_walk6_2 in_walk1_2)))
 (let (($x16145 (and d_2_16 in_walk6_2 in_walk1_2)))
 (let (($x16143 (and d_2_15 in_walk6_2 in_walk1_2)))
 (let (($x16141 (and d_2_14 in_walk6_2 in_walk1_2)))
 (let (($x16139 (and d_2_13 in_walk6_2 in_walk1_2)))
 (let (($x16137 (and d_2_12 in_walk6_2 in_walk1_2)))
 (let (($x16135 (and d_2_11 in_walk6_2 in_walk1_2)))
 (let (($x16133 (and d_2_10 in_walk6_2 in_walk1_2)))
 (let (($x16131 (and d_2_9 in_walk6_2 in_walk1_2)))
 (let (($x16129 (and d_2_8 in_walk6_2 in_walk1_2)))
 (let (($x16127 (and d_2_7 in_walk6_2 in_walk1_2)))
 (let (($x16125 (and d_2_6 in_walk6_2 in_walk1_2)))
 (let (($x16123 (and d_2_5 in_walk6_2 in_walk1_2)))
 (let (($x16121 (and d_2_4 in_walk6_2 in_walk1_2)))
 (let (($x16119 (and d_2_3 in_walk6_2 in_walk1_2)))
 (let (($x16117 (and d_2_2 in_walk6_2 in_walk1_2)))
 (let (($x16115 (and d_2_1 in_walk6_2 in_walk1_2)))
 (let (($x16114 (and d_2_0 in_walk6_2 in_walk1_2)))
 (let (($x16162 (or $x16114 $x16115 $x16117 $x16119 $x16121 $x16123 $x16125 $x16127 $x16129 $x16131 $x16133 $x16135 $x16137 $x16139 $x16141 $x16143 $x16145 $x16147 $x16149 $x16151 $x16153 $x16155 $x16157 $x16159 $x16161)))
 (let (($x16085 (and d_1_24 in_walk6_1 in_walk1_1)))
 (let (($x16083 (and d_1_23 in_walk6_1 in_walk1_1)))
 (let (($x16081 (and d_1_22 in_walk6_1 in_walk1_1)))
 (let (($x16079 (and d_1_21 in_walk6_1 in_walk1_1)))
 (let (($x16077 (and d_1_20 in_walk6_1 in_walk1_1)))
 (let (($x16075 (and d_1_19 in_walk6_1 in_walk1_1)))
 (let (($x16073 (and d_1_18 in_walk6_1 in_walk1_1)))
 (let (($x16071 (and d_1_17 in_walk6_1 in_walk1_1)))
 (let (($x16069 (and d_1_16 in_walk6_1 in_walk1_1)))
 (let (($x16067 (and d_1_15 in_walk6_1 in_walk1_1)))
 (let (($x16065 (and d_1_14 in_walk6_1 in_walk1_1)))
 (let (($x16063 (and d_1_13 in_walk6_1 in_walk1_1)))
 (let (($x16061 (and d_1_12 in_walk6_1 in_walk1_1)))
 (let (($x16059 (and d_1_11 in_walk6_1 in_walk1_1)))
 (let (($x16057 (and d_1_10 in_walk6_1 in_walk1_1)))
 (let (($x16055 (and d_1_9 in_walk6_1 in_walk1_1)))
 (let (($x16053 (and d_1_8 in_walk6_1 in_walk1_1)))
 (let (($x16051 (and d_1_7 in_walk6_1 in_walk1_1)))
 (let (($x16049 (and d_1_6 in_walk6_1 in_walk1_1)))
 (let (($x16047 (and d_1_5 in_walk6_1 in_walk1_1)))
 (let (($x16045 (and d_1_4 in_walk6_1 in_walk1_1)))
 (let (($x16043 (and d_1_3 in_walk6_1 in_walk1_1)))
 (let (($x16041 (and d_1_2 in_walk6_1 in_walk1_1)))
 (let (($x16039 (and d_1_1 in_walk6_1 in_walk1_1)))
 (let (($x16038 (and d_1_0 in_walk6_1 in_walk1_1)))
 (let (($x16086 (or $x16038 $x16039 $x16041 $x16043 $x16045 $x16047 $x16049 $x16051 $x16053 $x16055 $x16057 $x16059 $x16061 $x16063 $x16065 $x16067 $x16069 $x16071 $x16073 $x16075 $x16077 $x16079 $x16081 $x16083 $x16085)))
 (let (($x16009 (and d_0_24 in_walk6_0 in_walk1_0)))
 (let (($x16007 (and d_0_23 in_walk6_0 in_walk1_0)))
 (let (($x16005 (and d_0_22 in_walk6_0 in_walk1_0)))
 (let (($x16003 (and d_0_21 in_walk6_0 in_walk1_0)))
 (let (($x16001 (and d_0_20 in_walk6_0 in_walk1_0)))
 (let (($x15999 (and d_0_19 in_walk6_0 in_walk1_0)))
 (let (($x15997 (and d_0_18 in_walk6_0 in_walk1_0)))
 (let (($x15995 (and d_0_17 in_walk6_0 in_walk1_0)))
 (let (($x15993 (and d_0_16 in_walk6_0 in_walk1_0)))
 (let (($x15991 (and d_0_15 in_walk6_0 in_walk1_0)))
 (let (($x15989 (and d_0_14 in_walk6_0 in_walk1_0)))
 (let (($x15987 (and d_0_13 in_walk6_0 in_walk1_0)))
 (let (($x15985 (and d_0_12 in_walk6_0 in_walk1_0)))
 (let (($x15983 (and d_0_11 in_walk6_0 in_walk1_0)))
 (let (($x15981 (and d_0_10 in_walk6_0 in_walk1_0)))
 (let (($x15979 (and d_0_9 in_walk6_0 in_walk1_0)))
 (let (($x15977 (and d_0_8 in_walk6_0 in_walk1_0)))
 (let (($x15975 (and d_0_7 in_walk6_0 in_walk1_0)))
 (let (($x15973 (and d_0_6 in_walk6_0 in_walk1_0)))
 (let (($x15971 (and d_0_5 in_walk6_0 in_walk1_0)))
 (let (($x15969 (and d_0_4 in_walk6_0 in_walk1_0)))
 (let (($x15967 (and d_0_3 in_walk6_0 in_walk1_0)))
 (let (($x15965 (and d_0_2 in_walk6_0 in_walk1_0)))
 (let (($x15963 (and d_0_1 in_walk6_0 in_walk1_0)))
 (let (($x15962 (and d_0_0 in_walk6_0 in_walk1_0)))
 (let (($x16010 (or $x15962 $x15963 $x15965 $x15967 $x15969 $x15971 $x15973 $x15975 $x15977 $x15979 $x15981 $x15983 $x15985 $x15987 $x15989 $x15991 $x15993 $x15995 $x15997 $x15999 $x16001 $x16003 $x16005 $x16007 $x16009)))
 (let (($x15960 (or false $x16010)))
 (let (($x16036 (or $x15960 $x16086)))
 (let (($x16112 (or $x16036 $x16162)))
 (let (($x15922 (and d_3_24 in_walk5_3 in_walk1_3)))
 (let (($x15920 (and d_3_23 in_walk5_3 in_walk1_3)))
 (let (($x15918 (and d_3_22 in_walk5_3 in_walk1_3)))
 (let (($x15916 (and d_3_21 in_walk5_3 in_walk1_3)))
 (let (($x15914 (and d_3_20 in_walk5_3 in_walk1_3)))
 (let (($x15912 (and d_3_19 in_walk5_3 in_walk1_3)))
 (let (($x15910 (and d_3_18 in_walk5_3 in_walk1_3)))
 (let (($x15908 (and d_3_17 in_walk5_3 in_walk1_3)))
 (let (($x15906 (and d_3_16 in_walk5_3 in_walk1_3)))
 (let (($x15904 (and d_3_15 in_walk5_3 in_walk1_3)))
 (let (($x15902 (and d_3_14 in_walk5_3 in_walk1_3)))
 (let (($x15900 (and d_3_13 in_walk5_3 in_walk1_3)))
 (let (($x15898 (and d_3_12 in_walk5_3 in_walk1_3)))
 (let (($x15896 (and d_3_11 in_walk5_3 in_walk1_3)))
 (let (($x15894 (and d_3_10 in_walk5_3 in_walk1_3)))
 (let (($x15892 (and d_3_9 in_walk5_3 in_walk1_3)))
 (let (($x15890 (and d_3_8 in_walk5_3 in_walk1_3)))
 (let (($x15888 (and d_3_7 in_walk5_3 in_walk1_3)))
 (let (($x15886 (and d_3_6 in_walk5_3 in_walk1_3)))
 (let (($x15884 (and d_3_5 in_walk5_3 in_walk1_3)))
 (let (($x15882 (and d_3_4 in_walk5_3 in_walk1_3)))
 (let (($x15880 (and d_3_3 in_walk5_3 in_walk1_3)))
 (let (($x15878 (and d_3_2 in_walk5_3 in_walk1_3)))
 (let (($x15876 (and d_3_1 in_walk5_3 in_walk1_3)))
 (let (($x15875 (and d_3_0 in_walk5_3 in_walk1_3)))
 (let (($x15923 (or $x15875 $x15876 $x15878 $x15880 $x15882 $x15884 $x15886 $x15888 $x15890 $x15892 $x15894 $x15896 $x15898 $x15900 $x15902 $x15904 $x15906 $x15908 $x15910 $x15912 $x15914 $x15916 $x15918 $x15920 $x15922)))
 (let (($x15846 (and d_2_24 in_walk5_2 in_walk1_2)))
 (let (($x15844 (and d_2_23 in_walk5_2 in_walk1_2)))
 (let (($x15842 (and d_2_22 in_walk5_2 in_walk1_2)))
 (let (($x15840 (and d_2_21 in_walk5_2 in_walk1_2)))
 (let (($x15838 (and d_2_20 in_walk5_2 in_walk1_2)))
 (let (($x15836 (and d_2_19 in_walk5_2 in_walk1_2)))
 (let (($x15834 (and d_2_18 in_walk5_2 in_walk1_2)))
 (let (($x15832 (and d_2_17 in_walk5_2 in_walk1_2)))
 (let (($x15830 (and d_2_16 in_walk5_2 in_walk1_2)))
 (let (($x15828 (and d_2_15 in_walk5_2 in_walk1_2)))
 (let (($x15826 (and d_2_14 in_walk5_2 in_walk1_2)))
 (let (($x15824 (and d_2_13 in_walk5_2 in_walk1_2)))
 (let (($x15822 (and d_2_12 in_walk5_2 in_walk1_2)))
 (let (($x15820 (and d_2_11 in_walk5_2 in_walk1_2)))
 (let (($x15818 (and d_2_10 in_walk5_2 in_walk1_2)))
 (let (($x15816 (and d_2_9 in_walk5_2 in_walk1_2)))
 (let (($x15814 (and d_2_8 in_walk5_2 in_walk1_2)))
 (let (($x15812 (and d_2_7 in_walk5_2 in_walk1_2)))
 (let (($x15810 (and d_2_6 in_walk5_2 in_walk1_2)))
 (let (($x15808 (and d_2_5 in_walk5_2 in_walk1_2)))
 (let (($x15806 (and d_2_4 in_walk5_2 in_walk1_2)))
 (let (($x15804 (and d_2_3 in_walk5_2 in_walk1_2)))
 (let (($x15802 (and d_2_2 in_walk5_2 in_walk1_2)))
 (let (($x15800 (and d_2_1 in_walk5_2 in_walk1_2)))
 (let (($x15799 (and d_2_0 in_walk5_2 in_walk1_2)))
 (let (($x15847 (or $x15799 $x15800 $x15802 $x15804 $x15806 $x15808 $x15810 $x15812 $x15814 $x15816 $x15818 $x15820 $x15822 $x15824 $x15826 $x15828 $x15830 $x15832 $x15834 $x15836 $x15838 $x15840 $x15842 $x15844 $x15846)))
 (let (($x15770 (and d_1_24 in_walk5_1 in_walk1_1)))
 (let (($x15768 (and d_1_23 in_walk5_1 in_walk1_1)))
 (let (($x15766 (and d_1_22 in_walk5_1 in_walk1_1)))
 (let (($x15764 (and d_1_21 in_walk5_1 in_walk1_1)))
 (let (($x15762 (and d_1_20 in_walk5_1 in_walk1_1)))
 (let (($x15760 (and d_1_19 in_walk5_1 in_walk1_1)))
 (let (($x15758 (and d_1_18 in_walk5_1 in_walk1_1)))
 (let (($x15756 (and d_1_17 in_walk5_1 in_walk1_1)))
 (let (($x15754 (and d_1_16 in_walk5_1 in_walk1_1)))
 (let (($x15752 (and d_1_15 in_walk5_1 in_walk1_1)))
 (let (($x15750 (and d_1_14 in_walk5_1 in_walk1_1)))
 (let (($x15748 (and d_1_13 in_walk5_1 in_walk1_1)))
 (let (($x15746 (and d_1_12 in_walk5_1 in_walk1_1)))
 (let (($x15744 (and d_1_11 in_walk5_1 in_walk1_1)))
 (let (($x15742 (and d_1_10 in_walk5_1 in_walk1_1)))
 (let (($x15740 (and d_1_9 in_walk5_1 in_walk1_1)))
 (let (($x15738 (and d_1_8 in_walk5_1 in_walk1_1)))
 (let (($x15736 (and d_1_7 in_walk5_1 in_walk1_1)))
 (let (($x15734 (and d_1_6 in_walk5_1 in_walk1_1)))
 (let (($x15732 (and d_1_5 in_walk5_1 in_walk1_1)))
 (let (($x15730 (and d_1_4 in_walk5_1 in_walk1_1)))
 (let (($x15728 (and d_1_3 in_walk5_1 in_walk1_1)))
 (let (($x15726 (and d_1_2 in_walk5_1 in_walk1_1)))
 (let (($x15724 (and d_1_1 in_walk5_1 in_walk1_1)))
 (let (($x15723 (and d_1_0 in_walk5_1 in_walk1_1)))
 (let (($x15771 (or $x15723 $x15724 $x15726 $x15728 $x15730 $x15732 $x15734 $x15736 $x15738 $x15740 $x15742 $x15744 $x15746 $x15748 $x15750 $x15752 $x15754 $x15756 $x15758 $x15760 $x15762 $x15764 $x15766 $x15768 $x15770)))
 (let (($x15694 (and d_0_24 in_walk5_0 in_walk1_0)))
 (let (($x15692 (and d_0_23 in_walk5_0 in_walk1_0)))
 (let (($x15690 (and d_0_22 in_walk5_0 in_walk1_0)))
 (let (($x15688 (and d_0_21 in_walk5_0 in_walk1_0)))
 (let (($x15686 (and d_0_20 in_walk5_0 in_walk1_0)))
 (let (($x15684 (and d_0_19 in_walk5_0 in_walk1_0)))
 (let (($x15682 (and d_0_18 in_walk5_0 in_walk1_0)))
 (let (($x15680 (and d_0_17 in_walk5_0 in_walk1_0)))
 (let (($x15678 (and d_0_16 in_walk5_0 in_walk1_0)))
 (let (($x15676 (and d_0_15 in_walk5_0 in_walk1_0)))
 (let (($x15674 (and d_0_14 in_walk5_0 in_walk1_0)))
 (let (($x15672 (and d_0_13 in_walk5_0 in_walk1_0)))
 (let (($x15670 (and d_0_12 in_walk5_0 in_walk1_0)))
 (let (($x15668 (and d_0_11 in_walk5_0 in_walk1_0)))
 (let (($x15666 (and d_0_10 in_walk5_0 in_walk1_0)))
 (let (($x15664 (and d_0_9 in_walk5_0 in_walk1_0)))
 (let (($x15662 (and d_0_8 in_walk5_0 in_walk1_0)))
 (let (($x15660 (and d_0_7 in_walk5_0 in_walk1_0)))
 (let (($x15658 (and d_0_6 in_walk5_0 in_walk1_0)))
 (let (($x15656 (and d_0_5 in_walk5_0 in_walk1_0)))
 (let (($x15654 (and d_0_4 in_walk5_0 in_walk1_0)))
 (let (($x15652 (and d_0_3 in_walk5_0 in_walk1_0)))
 (let (($x15650 (and d_0_2 in_walk5_0 in_walk1_0)))
 (let (($x15648 (and d_0_1 in_walk5_0 in_walk1_0)))
 (let (($x15647 (and d_0_0 in_walk5_0 in_walk1_0)))
 (let (($x15695 (or $x15647 $x15648 $x15650 $x15652 $x15654 $x15656 $x15658 $x15660 $x15662 $x15664 $x15666 $x15668 $x15670 $x15672 $x15674 $x15676 $x15678 $x15680 $x15682 $x15684 $x15686 $x15688 $x15690 $x15692 $x15694)))
 (let (($x15645 (or false $x15695)))
 (let (($x15721 (or $x15645 $x15771)))
 (let (($x15797 (or $x15721 $x15847)))
 (let (($x15607 (and d_3_24 in_walk4_3 in_walk1_3)))
 (let (($x15605 (and d_3_23 in_walk4_3 in_walk1_3)))
 (let (($x15603 (and d_3_22 in_walk4_3 in_walk1_3)))
 (let (($x15601 (and d_3_21 in_walk4_3 in_walk1_3)))
 (let (($x15599 (and d_3_20 in_walk4_3 in_walk1_3)))
 (let (($x15597 (and d_3_19 in_walk4_3 in_walk1_3)))
 (let (($x15595 (and d_3_18 in_walk4_3 in_walk1_3)))
 (let (($x15593 (and d_3_17 in_walk4_3 in_walk1_3)))
 (let (($x15591 (and d_3_16 in_walk4_3 in_walk1_3)))
 (let (($x15589 (and d_3_15 in_walk4_3 in_walk1_3)))
 (let (($x15587 (and d_3_14 in_walk4_3 in_walk1_3)))
 (let (($x15585 (and d_3_13 in_walk4_3 in_walk1_3)))
 (let (($x15583 (and d_3_12 in_walk4_3 in_walk1_3)))
 (let (($x15581 (and d_3_11 in_walk4_3 in_walk1_3)))
 (let (($x15579 (and d_3_10 in_walk4_3 in_walk1_3)))
 (let (($x15577 (and d_3_9 in_walk4_3 in_walk1_3)))
 (let (($x15575 (and d_3_8 in_walk4_3 in_walk1_3)))
 (let (($x15573 (and d_3_7 in_walk4_3 in_walk1_3)))
 (let (($x15571 (and d_3_6 in_walk4_3 in_walk1_3)))
 (let (($x15569 (and d_3_5 in_walk4_3 in_walk1_3)))
 (let (($x15567 (and d_3_4 in_walk4_3 in_walk1_3)))
 (let (($x15565 (and d_3_3 in_walk4_3 in_walk1_3)))
 (let (($x15563 (and d_3_2 in_walk4_3 in_walk1_3)))
 (let (($x15561 (and d_3_1 in_walk4_3 in_walk1_3)))
 (let (($x15560 (and d_3_0 in_walk4_3 in_walk1_3)))
 (let (($x15608 (or $x15560 $x15561 $x15563 $x15565 $x15567 $x15569 $x15571 $x15573 $x15575 $x15577 $x15579 $x15581 $x15583 $x15585 $x15587 $x15589 $x15591 $x15593 $x15595 $x15597 $x15599 $x15601 $x15603 $x15605 $x15607)))
 (let (($x15531 (and d_2_24 in_walk4_2 in_walk1_2)))
 (let (($x15529 (and d_2_23 in_walk4_2 in_walk1_2)))
 (let (($x15527 (and d_2_22 in_walk4_2 in_walk1_2)))
 (let (($x15525 (and d_2_21 in_walk4_2 in_walk1_2)))
 (let (($x15523 (and d_2_20 in_walk4_2 in_walk1_2)))
 (let (($x15521 (and d_2_19 in_walk4_2 in_walk1_2)))
 (let (($x15519 (and d_2_18 in_walk4_2 in_walk1_2)))
 (let (($x15517 (and d_2_17 in_walk4_2 in_walk1_2)))
 (let (($x15515 (and d_2_16 in_walk4_2 in_walk1_2)))
 (let (($x15513 (and d_2_15 in_walk4_2 in_walk1_2)))
 (let (($x15511 (and d_2_14 in_walk4_2 in_walk1_2)))
 (let (($x15509 (and d_2_13 in_walk4_2 in_walk1_2)))
 (let (($x15507 (and d_2_12 in_walk4_2 in_walk1_2)))
 (let (($x15505 (and d_2_11 in_walk4_2 in_walk1_2)))
 (let (($x15503 (and d_2_10 in_walk4_2 in_walk1_2)))
 (let (($x15501 (and d_2_9 in_walk4_2 in_walk1_2)))
 (let (($x15499 (and d_2_8 in_walk4_2 in_walk1_2)))
 (let (($x15497 (and d_2_7 in_walk4_2 in_walk1_2)))
 (let (($x15495 (and d_2_6 in_walk4_2 in_walk1_2)))
 (let (($x15493 (and d_2_5 in_walk4_2 in_walk1_2)))
 (let (($x15491 (and d_2_4 in_walk4_2 in_walk1_2)))
 (let (($x15489 (and d_2_3 in_walk4_2 in_walk1_2)))
 (let (($x15487 (and d_2_2 in_walk4_2 in_walk1_2)))
 (let (($x15485 (and d_2_1 in_walk4_2 in_walk1_2)))
 (let (($x15484 (and d_2_0 in_walk4_2 in_walk1_2)))
 (let (($x15532 (or $x15484 $x15485 $x15487 $x15489 $x15491 $x15493 $x15495 $x15497 $x15499 $x15501 $x15503 $x15505 $x15507 $x15509 $x15511 $x15513 $x15515 $x15517 $x15519 $x15521 $x15523 $x15525 $x15527 $x15529 $x15531)))
 (let (($x15455 (and d_1_24 in_walk4_1 in_walk1_1)))
 (let (($x15453 (and d_1_23 in_walk4_1 in_walk1_1)))
 (let (($x15451 (and d_1_22 in_walk4_1 in_walk1_1)))
 (let (($x15449 (and d_1_21 in_walk4_1 in_walk1_1)))
 (let (($x15447 (and d_1_20 in_walk4_1 in_walk1_1)))
 (let (($x15445 (and d_1_19 in_walk4_1 in_walk1_1)))
 (let (($x15443 (and d_1_18 in_walk4_1 in_walk1_1)))
 (let (($x15441 (and d_1_17 in_walk4_1 in_walk1_1)))
 (let (($x15439 (and d_1_16 in_walk4_1 in_walk1_1)))
 (let (($x15437 (and d_1_15 in_walk4_1 in_walk1_1)))
 (let (($x15435 (and d_1_14 in_walk4_1 in_walk1_1)))
 (let (($x15433 (and d_1_13 in_walk4_1 in_walk1_1)))
 (let (($x15431 (and d_1_12 in_walk4_1 in_walk1_1)))
 (let (($x15429 (and d_1_11 in_walk4_1 in_walk1_1)))
 (let (($x15427 (and d_1_10 in_walk4_1 in_walk1_1)))
 (let (($x15425 (and d_1_9 in_walk4_1 in_walk1_1)))
 (let (($x15423 (and d_1_8 in_walk4_1 in_walk1_1)))
 (let (($x15421 (and d_1_7 in_walk4_1 in_walk1_1)))
 (let (($x15419 (and d_1_6 in_walk4_1 in_walk1_1)))
 (let (($x15417 (and d_1_5 in_walk4_1 in_walk1_1)))
 (let (($x15415 (and d_1_4 in_walk4_1 in_walk1_1)))
 (let (($x15413 (and d_1_3 in_walk4_1 in_walk1_1)))
 (let (($x15411 (and d_1_2 in_walk4_1 in_walk1_1)))
 (let (($x15409 (and d_1_1 in_walk4_1 in_walk1_1)))
 (let (($x15408 (and d_1_0 in_walk4_1 in_walk1_1)))
 (let (($x15456 (or $x15408 $x15409 $x15411 $x15413 $x15415 $x15417 $x15419 $x15421 $x15423 $x15425 $x15427 $x15429 $x15431 $x15433 $x15435 $x15437 $x15439 $x15441 $x15443 $x15445 $x15447 $x15449 $x15451 $x15453 $x15455)))
 (let (($x15379 (and d_0_24 in_walk4_0 in_walk1_0)))
 (let (($x15377 (and d_0_23 in_walk4_0 in_walk1_0)))
 (let (($x15375 (and d_0_22 in_walk4_0 in_walk1_0)))
 (let (($x15373 (and d_0_21 in_walk4_0 in_walk1_0)))
 (let (($x15371 (and d_0_20 in_walk4_0 in_walk1_0)))
 (let (($x15369 (and d_0_19 in_walk4_0 in_walk1_0)))
 (let (($x15367 (and d_0_18 in_walk4_0 in_walk1_0)))
 (let (($x15365 (and d_0_17 in_walk4_0 in_walk1_0)))
 (let (($x15363 (and d_0_16 in_walk4_0 in_walk1_0)))
 (let (($x15361 (and d_0_15 in_walk4_0 in_walk1_0)))
 (let (($x15359 (and d_0_14 in_walk4_0 in_walk1_0)))
 (let (($x15357 (and d_0_13 in_walk4_0 in_walk1_0)))
 (let (($x15355 (and d_0_12 in_walk4_0 in_walk1_0)))
 (let (($x15353 (and d_0_11 in_walk4_0 in_walk1_0)))
 (let (($x15351 (and d_0_10 in_walk4_0 in_walk1_0)))
 (let (($x15349 (and d_0_9 in_walk4_0 in_walk1_0)))
 (let (($x15347 (and d_0_8 in_walk4_0 in_walk1_0)))
 (let (($x15345 (and d_0_7 in_walk4_0 in_walk1_0)))
 (let (($x15343 (and d_0_6 in_walk4_0 in_walk1_0)))
 (let (($x15341 (and d_0_5 in_walk4_0 in_walk1_0)))
 (let (($x15339 (and d_0_4 in_walk4_0 in_walk1_0)))
 (let (($x15337 (and d_0_3 in_walk4_0 in_walk1_0)))
 (let (($x15335 (and d_0_2 in_walk4_0 in_walk1_0)))
 (let (($x15333 (and d_0_1 in_walk4_0 in_walk1_0)))
 (let (($x15332 (and d_0_0 in_walk4_0 in_walk1_0)))
 (let (($x15380 (or $x15332 $x15333 $x15335 $x15337 $x15339 $x15341 $x15343 $x15345 $x15347 $x15349 $x15351 $x15353 $x15355 $x15357 $x15359 $x15361 $x15363 $x15365 $x15367 $x15369 $x15371 $x15373 $x15375 $x15377 $x15379)))
 (let (($x15330 (or false $x15380)))
 (let (($x15406 (or $x15330 $x15456)))
 (let (($x15482 (or $x15406 $x15532)))
 (let (($x15292 (and d_3_24 in_walk3_3 in_walk1_3)))
 (let (($x15290 (and d_3_23 in_walk3_3 in_walk1_3)))
 (let (($x15288 (and d_3_22 in_walk3_3 in_walk1_3)))
 (let (($x15286 (and d_3_21 in_walk3_3 in_walk1_3)))
 (let (($x15284 (and d_3_20 in_walk3_3 in_walk1_3)))
 (let (($x15282 (and d_3_19 in_walk3_3 in_walk1_3)))
 (let (($x15280 (and d_3_18 in_walk3_3 in_walk1_3)))
 (let (($x15278 (and d_3_17 in_walk3_3 in_walk1_3)))
 (let (($x15276 (and d_3_16 in_walk3_3 in_walk1_3)))
 (let (($x15274 (and d_3_15 in_walk3_3 in_walk1_3)))
 (let (($x15272 (and d_3_14 in_walk3_3 in_walk1_3)))
 (let (($x15270 (and d_3_13 in_walk3_3 in_walk1_3)))
 (let (($x15268 (and d_3_12 in_walk3_3 in_walk1_3)))
 (let (($x15266 (and d_3_11 in_walk3_3 in_walk1_3)))
 (let (($x15264 (and d_3_10 in_walk3_3 in_walk1_3)))
 (let (($x15262 (and d_3_9 in_walk3_3 in_walk1_3)))
 (let (($x15260 (and d_3_8 in_walk3_3 in_walk1_3)))
 (let (($x15258 (and d_3_7 in_walk3_3 in_walk1_3)))
 (let (($x15256 (and d_3_6 in_walk3_3 in_walk1_3)))
 (let (($x15254 (and d_3_5 in_walk3_3 in_walk1_3)))
 (let (($x15252 (and d_3_4 in_walk3_3 in_walk1_3)))
 (let (($x15250 (and d_3_3 in_walk3_3 in_walk1_3)))
 (let (($x15248 (and d_3_2 in_walk3_3 in_walk1_3)))
 (let (($x15246 (and d_3_1 in_walk3_3 in_walk1_3)))
 (let (($x15245 (and d_3_0 in_walk3_3 in_walk1_3)))
 (let (($x15293 (or $x15245 $x15246 $x15248 $x15250 $x15252 $x15254 $x15256 $x15258 $x15260 $x15262 $x15264 $x15266 $x15268 $x15270 $x15272 $x15274 $x15276 $x15278 $x15280 $x15282 $x15284 $x15286 $x15288 $x15290 $x15292)))
 (let (($x15216 (and d_2_24 in_walk3_2 in_walk1_2)))
 (let (($x15214 (and d_2_23 in_walk3_2 in_walk1_2)))
 (let (($x15212 (and d_2_22 in_walk3_2 in_walk1_2)))
 (let (($x15210 (and d_2_21 in_walk3_2 in_walk1_2)))
 (let (($x15208 (and d_2_20 in_walk3_2 in_walk1_2)))
 (let (($x15206 (and d_2_19 in_walk3_2 in_walk1_2)))
 (let (($x15204 (and d_2_18 in_walk3_2 in_walk1_2)))
 (let (($x15202 (and d_2_17 in_walk3_2 in_walk1_2)))
 (let (($x15200 (and d_2_16 in_walk3_2 in_walk1_2)))
 (let (($x15198 (and d_2_15 in_walk3_2 in_walk1_2)))
 (let (($x15196 (and d_2_14 in_walk3_2 in_walk1_2)))
 (let (($x15194 (and d_2_13 in_walk3_2 in_walk1_2)))
 (let (($x15192 (and d_2_12 in_walk3_2 in_walk1_2)))
 (let (($x15190 (and d_2_11 in_walk3_2 in_walk1_2)))
 (let (($x15188 (and d_2_10 in_walk3_2 in_walk1_2)))
 (let (($x15186 (and d_2_9 in_walk3_2 in_walk1_2)))
 (let (($x15184 (and d_2_8 in_walk3_2 in_walk1_2)))
 (let (($x15182 (and d_2_7 in_walk3_2 in_walk1_2)))
 (let (($x15180 (and d_2_6 in_walk3_2 in_walk1_2)))
 (let (($x15178 (and d_2_5 in_walk3_2 in_walk1_2)))
 (let (($x15176 (and d_2_4 in_walk3_2 in_walk1_2)))
 (let (($x15174 (and d_2_3 in_walk3_2 in_walk1_2)))
 (let (($x15172 (and d_2_2 in_walk3_2 in_walk1_2)))
 (let (($x15170 (and d_2_1 in_walk3_2 in_walk1_2)))
 (let (($x15169 (and d_2_0 in_walk3_2 in_walk1_2)))
 (let (($x15217 (or $x15169 $x15170 $x15172 $x15174 $x15176 $x15178 $x15180 $x15182 $x15184 $x15186 $x15188 $x15190 $x15192 $x15194 $x15196 $x15198 $x15200 $x15202 $x15204 $x15206 $x15208 $x15210 $x15212 $x15214 $x15216)))
 (let (($x15140 (and d_1_24 in_walk3_1 in_walk1_1)))
 (let (($x15138 (and d_1_23 in_walk3_1 in_walk1_1)))
 (let (($x15136 (and d_1_22 in_walk3_1 in_walk1_1)))
 (let (($x15134 (and d_1_21 in_walk3_1 in_walk1_1)))
 (let (($x15132 (and d_1_20 in_walk3_1 in_walk1_1)))
 (let (($x15130 (and d_1_19 in_walk3_1 in_walk1_1)))
 (let (($x15128 (and d_1_18 in_walk3_1 in_walk1_1)))
 (let (($x15126 (and d_1_17 in_walk3_1 in_walk1_1)))
 (let (($x15124 (and d_1_16 in_walk3_1 in_walk1_1)))
 (let (($x15122 (and d_1_15 in_walk3_1 in_walk1_1)))
 (let (($x15120 (and d_1_14 in_walk3_1 in_walk1_1)))
 (let (($x15118 (and d_1_13 in_walk3_1 in_walk1_1)))
 (let (($x15116 (and d_1_12 in_walk3_1 in_walk1_1)))
 (let (($x15114 (and d_1_11 in_walk3_1 in_walk1_1)))
 (let (($x15112 (and d_1_10 in_walk3_1 in_walk1_1)))
 (let (($x15110 (and d_1_9 in_walk3_1 in_walk1_1)))
 (let (($x15108 (and d_1_8 in_walk3_1 in_walk1_1)))
 (let (($x15106 (and d_1_7 in_walk3_1 in_walk1_1)))
 (let (($x15104 (and d_1_6 in_walk3_1 in_walk1_1)))
 (let (($x15102 (and d_1_5 in_walk3_1 in_walk1_1)))
 (let (($x15100 (and d_1_4 in_walk3_1 in_walk1_1)))
 (let (($x15098 (and d_1_3 in_walk3_1 in_walk1_1)))
 (let (($x15096 (and d_1_2 in_walk3_1 in_walk1_1)))
 (let (($x15094 (and d_1_1 in_walk3_1 in_walk1_1)))
 (let (($x15093 (and d_1_0 in_walk3_1 in_walk1_1)))
 (let (($x15141 (or $x15093 $x15094 $x15096 $x15098 $x15100 $x15102 $x15104 $x15106 $x15108 $x15110 $x15112 $x15114 $x15116 $x15118 $x15120 $x15122 $x15124 $x15126 $x15128 $x15130 $x15132 $x15134 $x15136 $x15138 $x15140)))
 (let (($x15064 (and d_0_24 in_walk3_0 in_walk1_0)))
 (let (($x15062 (and d_0_23 in_walk3_0 in_walk1_0)))
 (let (($x15060 (and d_0_22 in_walk3_0 in_walk1_0)))
 (let (($x15058 (and d_0_21 in_walk3_0 in_walk1_0)))
 (let (($x15056 (and d_0_20 in_walk3_0 in_walk1_0)))
 (let (($x15054 (and d_0_19 in_walk3_0 in_walk1_0)))
 (let (($x15052 (and d_0_18 in_walk3_0 in_walk1_0)))
 (let (($x15050 (and d_0_17 in_walk3_0 in_walk1_0)))
 (let (($x15048 (and d_0_16 in_walk3_0 in_walk1_0)))
 (let (($x15046 (and d_0_15 in_walk3_0 in_walk1_0)))
 (let (($x15044 (and d_0_14 in_walk3_0 in_walk1_0)))
 (let (($x15042 (and d_0_13 in_walk3_0 in_walk1_0)))
 (let (($x15040 (and d_0_12 in_walk3_0 in_walk1_0)))
 (let (($x15038 (and d_0_11 in_walk3_0 in_walk1_0)))
 (let (($x15036 (and d_0_10 in_walk3_0 in_walk1_0)))
 (let (($x15034 (and d_0_9 in_walk3_0 in_walk1_0)))
 (let (($x15032 (and d_0_8 in_walk3_0 in_walk1_0)))
 (let (($x15030 (and d_0_7 in_walk3_0 in_walk1_0)))
 (let (($x15028 (and d_0_6 in_walk3_0 in_walk1_0)))
 (let (($x15026 (and d_0_5 in_walk3_0 in_walk1_0)))
 (let (($x15024 (and d_0_4 in_walk3_0 in_walk1_0)))
 (let (($x15022 (and d_0_3 in_walk3_0 in_walk1_0)))
 (let (($x15020 (and d_0_2 in_walk3_0 in_walk1_0)))
 (let (($x15018 (and d_0_1 in_walk3_0 in_walk1_0)))
 (let (($x15017 (and d_0_0 in_walk3_0 in_walk1_0)))
 (let (($x15065 (or $x15017 $x15018 $x15020 $x15022 $x15024 $x15026 $x15028 $x15030 $x15032 $x15034 $x15036 $x15038 $x15040 $x15042 $x15044 $x15046 $x15048 $x15050 $x15052 $x15054 $x15056 $x15058 $x15060 $x15062 $x15064)))
 (let (($x15015 (or false $x15065)))
 (let (($x15091 (or $x15015 $x15141)))
 (let (($x15167 (or $x15091 $x15217)))
 (let (($x14977 (and d_3_24 in_walk2_3 in_walk1_3)))
 (let (($x14975 (and d_3_23 in_walk2_3 in_walk1_3)))
 (let (($x14973 (and d_3_22 in_walk2_3 in_walk1_3)))
 (let (($x14971 (and d_3_21 in_walk2_3 in_walk1_3)))
 (let (($x14969 (and d_3_20 in_walk2_3 in_walk1_3)))
 (let (($x14967 (and d_3_19 in_walk2_3 in_walk1_3)))
 (let (($x14965 (and d_3_18 in_walk2_3 in_walk1_3)))
 (let (($x14963 (and d_3_17 in_walk2_3 in_walk1_3)))
 (let (($x14961 (and d_3_16 in_walk2_3 in_walk1_3)))
 (let (($x14959 (and d_3_15 in_walk2_3 in_walk1_3)))
 (let (($x14957 (and d_3_14 in_walk2_3 in_walk1_3)))
 (let (($x14955 (and d_3_13 in_walk2_3 in_walk1_3)))
 (let (($x14953 (and d_3_12 in_walk2_3 in_walk1_3)))
 (let (($x14951 (and d_3_11 in_walk2_3 in_walk1_3)))
 (let (($x14949 (and d_3_10 in_walk2_3 in_walk1_3)))
 (let (($x14947 (and d_3_9 in_walk2_3 in_walk1_3)))
 (let (($x14945 (and d_3_8 in_walk2_3 in_walk1_3)))
 (let (($x14943 (and d_3_7 in_walk2_3 in_walk1_3)))
 (let (($x14941 (and d_3_6 in_walk2_3 in_walk1_3)))
 (let (($x14939 (and d_3_5 in_walk2_3 in_walk1_3)))
 (let (($x14937 (and d_3_4 in_walk2_3 in_walk1_3)))
 (let (($x14935 (and d_3_3 in_walk2_3 in_walk1_3)))
 (let (($x14933 (and d_3_2 in_walk2_3 in_walk1_3)))
 (let (($x14931 (and d_3_1 in_walk2_3 in_walk1_3)))
 (let (($x14930 (and d_3_0 in_walk2_3 in_walk1_3)))
 (let (($x14978 (or $x14930 $x14931 $x14933 $x14935 $x14937 $x14939 $x14941 $x14943 $x14945 $x14947 $x14949 $x14951 $x14953 $x14955 $x14957 $x14959 $x14961 $x14963 $x14965 $x14967 $x14969 $x14971 $x14973 $x14975 $x14977)))
 (let (($x14901 (and d_2_24 in_walk2_2 in_walk1_2)))
 (let (($x14899 (and d_2_23 in_walk2_2 in_walk1_2)))
 (let (($x14897 (and d_2_22 in_walk2_2 in_walk1_2)))
 (let (($x14895 (and d_2_21 in_walk2_2 in_walk1_2)))
 (let (($x14893 (and d_2_20 in_walk2_2 in_walk1_2)))
 (let (($x14891 (and d_2_19 in_walk2_2 in_walk1_2)))
 (let (($x14889 (and d_2_18 in_walk2_2 in_walk1_2)))
 (let (($x14887 (and d_2_17 in_walk2_2 in_walk1_2)))
 (let (($x14885 (and d_2_16 in_walk2_2 in_walk1_2)))
 (let (($x14883 (and d_2_15 in_walk2_2 in_walk1_2)))
 (let (($x14881 (and d_2_14 in_walk2_2 in_walk1_2)))
 (let (($x14879 (and d_2_13 in_walk2_2 in_walk1_2)))
 (let (($x14877 (and d_2_12 in_walk2_2 in_walk1_2)))
 (let (($x14875 (and d_2_11 in_walk2_2 in_walk1_2)))
 (let (($x14873 (and d_2_10 in_walk2_2 in_walk1_2)))
 (let (($x14871 (and d_2_9 in_walk2_2 in_walk1_2)))
 (let (($x14869 (and d_2_8 in_walk2_2 in_walk1_2)))
 (let (($x14867 (and d_2_7 in_walk2_2 in_walk1_2)))
 (let (($x14865 (and d_2_6 in_walk2_2 in_walk1_2)))
 (let (($x14863 (and d_2_5 in_walk2_2 in_walk1_2)))
 (let (($x14861 (and d_2_4 in_walk2_2 in_walk1_2)))
 (let (($x14859 (and d_2_3 in_walk2_2 in_walk1_2)))
 (let (($x14857 (and d_2_2 in_walk2_2 in_walk1_2)))
 (let (($x14855 (and d_2_1 in_walk2_2 in_walk1_2)))
 (let (($x14854 (and d_2_0 in_walk2_2 in_walk1_2)))
 (let (($x14902 (or $x14854 $x14855 $x14857 $x14859 $x14861 $x14863 $x14865 $x14867 $x14869 $x14871 $x14873 $x14875 $x14877 $x14879 $x14881 $x14883 $x14885 $x14887 $x14889 $x14891 $x14893 $x14895 $x14897 $x14899 $x14901)))
 (let (($x14825 (and d_1_24 in_walk2_1 in_walk1_1)))
 (let (($x14823 (and d_1_23 in_walk2_1 in_walk1_1)))
 (let (($x14821 (and d_1_22 in_walk2_1 in_walk1_1)))
 (let (($x14819 (and d_1_21 in_walk2_1 in_walk1_1)))
 (let (($x14817 (and d_1_20 in_walk2_1 in_walk1_1)))
 (let (($x14815 (and d_1_19 in_walk2_1 in_walk1_1)))
 (let (($x14813 (and d_1_18 in_walk2_1 in_walk1_1)))
 (let (($x14811 (and d_1_17 in_walk2_1 in_walk1_1)))
 (let (($x14809 (and d_1_16 in_walk2_1 in_walk1_1)))
 (let (($x14807 (and d_1_15 in_walk2_1 in_walk1_1)))
 (let (($x14805 (and d_1_14 in_walk2_1 in_walk1_1)))
 (let (($x14803 (and d_1_13 in_walk2_1 in_walk1_1)))
 (let (($x14801 (and d_1_12 in_walk2_1 in_walk1_1)))
 (let (($x14799 (and d_1_11 in_walk2_1 in_walk1_1)))
 (let (($x14797 (and d_1_10 in_walk2_1 in_walk1_1)))
 (let (($x14795 (and d_1_9 in_walk2_1 in_walk1_1)))
 (let (($x14793 (and d_1_8 in_walk2_1 in_walk1_1)))
 (let (($x14791 (and d_1_7 in_walk2_1 in_walk1_1)))
 (let (($x14789 (and d_1_6 in_walk2_1 in_walk1_1)))
 (let (($x14787 (and d_1_5 in_walk2_1 in_walk1_1)))
 (let (($x14785 (and d_1_4 in_walk2_1 in_walk1_1)))
 (let (($x14783 (and d_1_3 in_walk2_1 in_walk1_1)))
 (let (($x14781 (and d_1_2 in_walk2_1 in_walk1_1)))
 (let (($x14779 (and d_1_1 in_walk2_1 in_walk1_1)))
 (let (($x14778 (and d_1_0 in_walk2_1 in_walk1_1)))
 (let (($x14826 (or $x14778 $x14779 $x14781 $x14783 $x14785 $x14787 $x14789 $x14791 $x14793 $x14795 $x14797 $x14799 $x14801 $x14803 $x14805 $x14807 $x14809 $x14811 $x14813 $x14815 $x14817 $x14819 $x14821 $x14823 $x14825)))
 (let (($x14749 (and d_0_24 in_walk2_0 in_walk1_0)))
 (let (($x14747 (and d_0_23 in_walk2_0 in_walk1_0)))
 (let (($x14745 (and d_0_22 in_walk2_0 in_walk1_0)))
 (let (($x14743 (and d_0_21 in_walk2_0 in_walk1_0)))
 (let (($x14741 (and d_0_20 in_walk2_0 in_walk1_0)))
 (let (($x14739 (and d_0_19 in_walk2_0 in_walk1_0)))
 (let (($x14737 (and d_0_18 in_walk2_0 in_walk1_0)))
 (let (($x14735 (and d_0_17 in_walk2_0 in_walk1_0)))
 (let (($x14733 (and d_0_16 in_walk2_0 in_walk1_0)))
 (let (($x14731 (and d_0_15 in_walk2_0 in_walk1_0)))
 (let (($x14729 (and d_0_14 in_walk2_0 in_walk1_0)))
 (let (($x14727 (and d_0_13 in_walk2_0 in_walk1_0)))
 (let (($x14725 (and d_0_12 in_walk2_0 in_walk1_0)))
 (let (($x14723 (and d_0_11 in_walk2_0 in_walk1_0)))
 (let (($x14721 (and d_0_10 in_walk2_0 in_walk1_0)))
 (let (($x14719 (and d_0_9 in_walk2_0 in_walk1_0)))
 (let (($x14717 (and d_0_8 in_walk2_0 in_walk1_0)))
 (let (($x14715 (and d_0_7 in_walk2_0 in_walk1_0)))
 (let (($x14713 (and d_0_6 in_walk2_0 in_walk1_0)))
 (let (($x14711 (and d_0_5 in_walk2_0 in_walk1_0)))
 (let (($x14709 (and d_0_4 in_walk2_0 in_walk1_0)))
 (let (($x14707 (and d_0_3 in_walk2_0 in_walk1_0)))
 (let (($x14705 (and d_0_2 in_walk2_0 in_walk1_0)))
 (let (($x14703 (and d_0_1 in_walk2_0 in_walk1_0)))
 (let (($x14702 (and d_0_0 in_walk2_0 in_walk1_0)))
 (let (($x14750 (or $x14702 $x14703 $x14705 $x14707 $x14709 $x14711 $x14713 $x14715 $x14717 $x14719 $x14721 $x14723 $x14725 $x14727 $x14729 $x14731 $x14733 $x14735 $x14737 $x14739 $x14741 $x14743 $x14745 $x14747 $x14749)))
 (let (($x14700 (or false $x14750)))
 (let (($x14776 (or $x14700 $x14826)))
 (let (($x14852 (or $x14776 $x14902)))
 (let (($x14627 (or d_2_16 d_2_24)))
 (let (($x14622 (or d_1_16 d_1_24)))
 (let (($x14617 (or d_0_16 d_0_24)))
 (let (($x14615 (or false $x14617)))
 (let (($x14620 (or $x14615 $x14622)))
 (let (($x14625 (or $x14620 $x14627)))
 (let (($x14631 (or (not (or (or (or (or false d_0_7) d_1_7) d_2_7) d_3_7)) (not (or $x14625 (or d_3_16 d_3_24))))))
 (let (($x14597 (or d_2_15 d_2_23)))
 (let (($x14592 (or d_1_15 d_1_23)))
 (let (($x14587 (or d_0_15 d_0_23)))
 (let (($x14585 (or false $x14587)))
 (let (($x14590 (or $x14585 $x14592)))
 (let (($x14595 (or $x14590 $x14597)))
 (let (($x14601 (or (not (or (or (or (or false d_0_6) d_1_6) d_2_6) d_3_6)) (not (or $x14595 (or d_3_15 d_3_23))))))
 (let (($x14567 (or d_2_14 d_2_22)))
 (let (($x14562 (or d_1_14 d_1_22)))
 (let (($x14557 (or d_0_14 d_0_22)))
 (let (($x14555 (or false $x14557)))
 (let (($x14560 (or $x14555 $x14562)))
 (let (($x14565 (or $x14560 $x14567)))
 (let (($x14571 (or (not (or (or (or (or false d_0_5) d_1_5) d_2_5) d_3_5)) (not (or $x14565 (or d_3_14 d_3_22))))))
 (let (($x14537 (or d_2_13 d_2_21)))
 (let (($x14532 (or d_1_13 d_1_21)))
 (let (($x14527 (or d_0_13 d_0_21)))
 (let (($x14525 (or false $x14527)))
 (let (($x14530 (or $x14525 $x14532)))
 (let (($x14535 (or $x14530 $x14537)))
 (let (($x14541 (or (not (or (or (or (or false d_0_4) d_1_4) d_2_4) d_3_4)) (not (or $x14535 (or d_3_13 d_3_21))))))
 (let (($x14507 (or d_2_12 d_2_20)))
 (let (($x14502 (or d_1_12 d_1_20)))
 (let (($x14497 (or d_0_12 d_0_20)))
 (let (($x14495 (or false $x14497)))
 (let (($x14500 (or $x14495 $x14502)))
 (let (($x14505 (or $x14500 $x14507)))
 (let (($x14511 (or (not (or (or (or (or false d_0_3) d_1_3) d_2_3) d_3_3)) (not (or $x14505 (or d_3_12 d_3_20))))))
 (let (($x14477 (or d_2_11 d_2_19)))
 (let (($x14472 (or d_1_11 d_1_19)))
 (let (($x14467 (or d_0_11 d_0_19)))
 (let (($x14465 (or false $x14467)))
 (let (($x14470 (or $x14465 $x14472)))
 (let (($x14475 (or $x14470 $x14477)))
 (let (($x14481 (or (not (or (or (or (or false d_0_2) d_1_2) d_2_2) d_3_2)) (not (or $x14475 (or d_3_11 d_3_19))))))
 (let (($x14447 (or d_2_10 d_2_18)))
 (let (($x14442 (or d_1_10 d_1_18)))
 (let (($x14437 (or d_0_10 d_0_18)))
 (let (($x14435 (or false $x14437)))
 (let (($x14440 (or $x14435 $x14442)))
 (let (($x14445 (or $x14440 $x14447)))
 (let (($x14451 (or (not (or (or (or (or false d_0_1) d_1_1) d_2_1) d_3_1)) (not (or $x14445 (or d_3_10 d_3_18))))))
 (let (($x14454 (and true $x14451)))
 (let (($x14484 (and $x14454 $x14481)))
 (let (($x14514 (and $x14484 $x14511)))
 (let (($x14544 (and $x14514 $x14541)))
 (let (($x14574 (and $x14544 $x14571)))
 (let (($x14604 (and $x14574 $x14601)))
 (let (($x14634 (and $x14604 $x14631)))
 (let (($x14972 (and $x14634 (or (or $x14643 $x14651) (not (or $x14852 $x14978))))))
 (let (($x15251 (and $x14972 (or (or $x14643 $x14974) (not (or $x15167 $x15293))))))
 (let (($x15604 (and $x15251 (or (or $x14643 $x15291) (not (or $x15482 $x15608))))))
 (let (($x15907 (and $x15604 (or (or $x14643 $x15572) (not (or $x15797 $x15923))))))
 (let (($x16228 (and $x15907 (or (or $x14643 $x15887) (not (or $x16112 $x16238))))))
 (let (($x16519 (and $x16228 (or (or $x14643 $x16234) (not (or $x16427 $x16553))))))
 (let (($x16834 (and $x16519 (or (or $x14643 $x16541) (not (or $x16742 $x16868))))))
 (let (($x17159 (and $x16834 (or (or $x14651 $x14974) (not (or $x17049 $x17175))))))
 (let (($x17444 (and $x17159 (or (or $x14651 $x15291) (not (or $x17356 $x17482))))))
 (let (($x17755 (and $x17444 (or (or $x14651 $x15572) (not (or $x17663 $x17789))))))
 (let (($x18060 (and $x17755 (or (or $x14651 $x15887) (not (or $x17970 $x18096))))))
 (let (($x18361 (and $x18060 (or (or $x14651 $x16234) (not (or $x18277 $x18403))))))
 (let (($x18676 (and $x18361 (or (or $x14651 $x16541) (not (or $x18584 $x18710))))))
 (let (($x19013 (and $x18676 (or (or $x14974 $x15291) (not (or $x18891 $x19017))))))
 (let (($x19308 (and $x19013 (or (or $x14974 $x15572) (not (or $x19198 $x19324))))))
 (let (($x19621 (and $x19308 (or (or $x14974 $x15887) (not (or $x19505 $x19631))))))
 (let (($x19904 (and $x19621 (or (or $x14974 $x16234) (not (or $x19812 $x19938))))))
 (let (($x20211 (and $x19904 (or (or $x14974 $x16541) (not (or $x20119 $x20245))))))
 (let (($x20518 (and $x20211 (or (or $x15291 $x15572) (not (or $x20426 $x20552))))))
 (let (($x20853 (and $x20518 (or (or $x15291 $x15887) (not (or $x20733 $x20859))))))
 (let (($x21142 (and $x20853 (or (or $x15291 $x16234) (not (or $x21040 $x21166))))))
 (let (($x21431 (and $x21142 (or (or $x15291 $x16541) (not (or $x21347 $x21473))))))
 (let (($x21776 (and $x21431 (or (or $x15572 $x15887) (not (or $x21654 $x21780))))))
 (let (($x22045 (and $x21776 (or (or $x15572 $x16234) (not (or $x21961 $x22087))))))
 (let (($x22370 (and $x22045 (or (or $x15572 $x16541) (not (or $x22268 $x22394))))))
 (let (($x22677 (and $x22370 (or (or $x15887 $x16234) (not (or $x22575 $x22701))))))
 (let (($x22966 (and $x22677 (or (or $x15887 $x16541) (not (or $x22882 $x23008))))))
 (let (($x23281 (and $x22966 (or (or $x16234 $x16541) (not (or $x23189 $x23315))))))
 (let (($x14421 (= c_3_24 d_3_24)))
 (let (($x14419 (= c_3_23 d_3_23)))
 (let (($x14417 (= c_3_22 d_3_22)))
 (let (($x14415 (= c_3_21 d_3_21)))
 (let (($x14413 (= c_3_20 d_3_20)))
 (let (($x14411 (= c_3_19 d_3_19)))
 (let (($x14409 (= c_3_18 d_3_18)))
 (let (($x14407 (= c_3_17 d_3_17)))
 (let (($x14405 (= c_3_16 d_3_16)))
 (let (($x14403 (= c_3_15 d_3_15)))
 (let (($x14401 (= c_3_14 d_3_14)))
 (let (($x14399 (= c_3_13 d_3_13)))
 (let (($x14397 (= c_3_12 d_3_12)))
 (let (($x14395 (= c_3_11 d_3_11)))
 (let (($x14393 (= c_3_10 d_3_10)))
 (let (($x14391 (= c_3_9 d_3_9)))
 (let (($x14389 (= c_3_8 d_3_8)))
 (let (($x14387 (= c_3_7 d_3_7)))
 (let (($x14385 (= c_3_6 d_3_6)))
 (let (($x14383 (= c_3_5 d_3_5)))
 (let (($x14381 (= c_3_4 d_3_4)))
 (let (($x14379 (= c_3_3 d_3_3)))
 (let (($x14377 (= c_3_2 d_3_2)))
 (let (($x14375 (= c_3_1 d_3_1)))
 (let (($x14373 (= c_3_0 d_3_0)))
 (let (($x14374 (and true $x14373)))
 (let (($x14376 (and $x14374 $x14375)))
 (let (($x14378 (and $x14376 $x14377)))
 (let (($x14380 (and $x14378 $x14379)))
 (let (($x14382 (and $x14380 $x14381)))
 (let (($x14384 (and $x14382 $x14383)))
 (let (($x14386 (and $x14384 $x14385)))
 (let (($x14388 (and $x14386 $x14387)))
 (let (($x14390 (and $x14388 $x14389)))
 (let (($x14392 (and $x14390 $x14391)))
 (let (($x14394 (and $x14392 $x14393)))
 (let (($x14396 (and $x14394 $x14395)))
 (let (($x14398 (and $x14396 $x14397)))
 (let (($x14400 (and $x14398 $x14399)))
 (let (($x14402 (and $x14400 $x14401)))
 (let (($x14404 (and $x14402 $x14403)))
 (let (($x14406 (and $x14404 $x14405)))
 (let (($x14408 (and $x14406 $x14407)))
 (let (($x14410 (and $x14408 $x14409)))
 (let (($x14412 (and $x14410 $x14411)))
 (let (($x14414 (and $x14412 $x14413)))
 (let (($x14416 (and $x14414 $x14415)))
 (let (($x14418 (and $x14416 $x14417)))
 (let (($x14420 (and $x14418 $x14419)))
 (let (($x14422 (and $x14420 $x14421)))
 (let (($x14370 (= c_2_24 d_2_24)))
 (let (($x14368 (= c_2_23 d_2_23)))
 (let (($x14366 (= c_2_22 d_2_22)))
 (let (($x14364 (= c_2_21 d_2_21)))
 (let (($x14362 (= c_2_20 d_2_20)))
 (let (($x14360 (= c_2_19 d_2_19)))
 (let (($x14358 (= c_2_18 d_2_18)))
 (let (($x14356 (= c_2_17 d_2_17)))
 (let (($x14354 (= c_2_16 d_2_16)))
 (let (($x14352 (= c_2_15 d_2_15)))
 (let (($x14350 (= c_2_14 d_2_14)))
 (let (($x14348 (= c_2_13 d_2_13)))
 (let (($x14346 (= c_2_12 d_2_12)))
 (let (($x14344 (= c_2_11 d_2_11)))
 (let (($x14342 (= c_2_10 d_2_10)))
 (let (($x14340 (= c_2_9 d_2_9)))
 (let (($x14338 (= c_2_8 d_2_8)))
 (let (($x14336 (= c_2_7 d_2_7)))
 (let (($x14334 (= c_2_6 d_2_6)))
 (let (($x14332 (= c_2_5 d_2_5)))
 (let (($x14330 (= c_2_4 d_2_4)))
 (let (($x14328 (= c_2_3 d_2_3)))
 (let (($x14326 (= c_2_2 d_2_2)))
 (let (($x14324 (= c_2_1 d_2_1)))
 (let (($x14322 (= c_2_0 d_2_0)))
 (let (($x14323 (and true $x14322)))
 (let (($x14325 (and $x14323 $x14324)))
 (let (($x14327 (and $x14325 $x14326)))
 (let (($x14329 (and $x14327 $x14328)))
 (let (($x14331 (and $x14329 $x14330)))
 (let (($x14333 (and $x14331 $x14332)))
 (let (($x14335 (and $x14333 $x14334)))
 (let (($x14337 (and $x14335 $x14336)))
 (let (($x14339 (and $x14337 $x14338)))
 (let (($x14341 (and $x14339 $x14340)))
 (let (($x14343 (and $x14341 $x14342)))
 (let (($x14345 (and $x14343 $x14344)))
 (let (($x14347 (and $x14345 $x14346)))
 (let (($x14349 (and $x14347 $x14348)))
 (let (($x14351 (and $x14349 $x14350)))
 (let (($x14353 (and $x14351 $x14352)))
 (let (($x14355 (and $x14353 $x14354)))
 (let (($x14357 (and $x14355 $x14356)))
 (let (($x14359 (and $x14357 $x14358)))
 (let (($x14361 (and $x14359 $x14360)))
 (let (($x14363 (and $x14361 $x14362)))
 (let (($x14365 (and $x14363 $x14364)))
 (let (($x14367 (and $x14365 $x14366)))
 (let (($x14369 (and $x14367 $x14368)))
 (let (($x14371 (and $x14369 $x14370)))
 (let (($x14319 (= c_1_24 d_1_24)))
 (let (($x14317 (= c_1_23 d_1_23)))
 (let (($x14315 (= c_1_22 d_1_22)))
 (let (($x14313 (= c_1_21 d_1_21)))
 (let (($x14311 (= c_1_20 d_1_20)))
 (let (($x14309 (= c_1_19 d_1_19)))
 (let (($x14307 (= c_1_18 d_1_18)))
 (let (($x14305 (= c_1_17 d_1_17)))
 (let (($x14303 (= c_1_16 d_1_16)))
 (let (($x14301 (= c_1_15 d_1_15)))
 (let (($x14299 (= c_1_14 d_1_14)))
 (let (($x14297 (= c_1_13 d_1_13)))
 (let (($x14295 (= c_1_12 d_1_12)))
 (let (($x14293 (= c_1_11 d_1_11)))
 (let (($x14291 (= c_1_10 d_1_10)))
 (let (($x14289 (= c_1_9 d_1_9)))
 (let (($x14287 (= c_1_8 d_1_8)))
 (let (($x14285 (= c_1_7 d_1_7)))
 (let (($x14283 (= c_1_6 d_1_6)))
 (let (($x14281 (= c_1_5 d_1_5)))
 (let (($x14279 (= c_1_4 d_1_4)))
 (let (($x14277 (= c_1_3 d_1_3)))
 (let (($x14275 (= c_1_2 d_1_2)))
 (let (($x14273 (= c_1_1 d_1_1)))
 (let (($x14271 (= c_1_0 d_1_0)))
 (let (($x14272 (and true $x14271)))
 (let (($x14274 (and $x14272 $x14273)))
 (let (($x14276 (and $x14274 $x14275)))
 (let (($x14278 (and $x14276 $x14277)))
 (let (($x14280 (and $x14278 $x14279)))
 (let (($x14282 (and $x14280 $x14281)))
 (let (($x14284 (and $x14282 $x14283)))
 (let (($x14286 (and $x14284 $x14285)))
 (let (($x14288 (and $x14286 $x14287)))
 (let (($x14290 (and $x14288 $x14289)))
 (let (($x14292 (and $x14290 $x14291)))
 (let (($x14294 (and $x14292 $x14293)))
 (let (($x14296 (and $x14294 $x14295)))
 (let (($x14298 (and $x14296 $x14297)))
 (let (($x14300 (and $x14298 $x14299)))
 (let (($x14302 (and $x14300 $x14301)))
 (let (($x14304 (and $x14302 $x14303)))
 (let (($x14306 (and $x14304 $x14305)))
 (let (($x14308 (and $x14306 $x14307)))
 (let (($x14310 (and $x14308 $x14309)))
 (let (($x14312 (and $x14310 $x14311)))
 (let (($x14314 (and $x14312 $x14313)))
 (let (($x14316 (and $x14314 $x14315)))
 (let (($x14318 (and $x14316 $x14317)))
 (let (($x14320 (and $x14318 $x14319)))
 (let (($x24170 (and true (=> c_0_0 d_0_24))))
 (let (($x24159 (and $x24170 (=> c_0_1 d_0_24))))
 (let (($x24185 (and $x24159 (=> c_0_2 d_0_24))))
 (let (($x24175 (and $x24185 (=> c_0_3 d_0_24))))
 (let (($x24162 (and $x24175 (=> c_0_4 d_0_24))))
 (let (($x24166 (and $x24162 (=> c_0_5 d_0_24))))
 (let (($x24164 (and $x24166 (=> c_0_6 d_0_24))))
 (let (($x24172 (and $x24164 (=> c_0_7 d_0_24))))
 (let (($x24168 (and $x24172 (=> c_0_8 d_0_24))))
 (let (($x24177 (and $x24168 (=> c_0_9 d_0_24))))
 (let (($x24183 (and $x24177 (=> c_0_10 d_0_24))))
 (let (($x24184 (and $x24183 (=> c_0_11 d_0_24))))
 (let (($x24187 (and $x24184 (=> c_0_12 d_0_24))))
 (let (($x24189 (and $x24187 (=> c_0_13 d_0_24))))
 (let (($x24191 (and $x24189 (=> c_0_14 d_0_24))))
 (let (($x24193 (and $x24191 (=> c_0_15 d_0_24))))
 (let (($x24195 (and $x24193 (=> c_0_16 d_0_24))))
 (let (($x24197 (and $x24195 (=> c_0_17 d_0_24))))
 (let (($x24199 (and $x24197 (=> c_0_18 d_0_24))))
 (let (($x24201 (and $x24199 (=> c_0_19 d_0_24))))
 (let (($x24203 (and $x24201 (=> c_0_20 d_0_24))))
 (let (($x24205 (and $x24203 (=> c_0_21 d_0_24))))
 (let (($x24207 (and $x24205 (=> c_0_22 d_0_24))))
 (let (($x24209 (and $x24207 (=> c_0_23 d_0_24))))
 (let (($x7378 (and true c_0_16)))
 (let (($x24212 (and $x7378 (and $x24209 (=> c_0_24 d_0_24)))))
 (let (($x24213 (and $x24212 $x14320)))
 (let (($x24214 (and $x24213 $x14371)))
 (let (($x14239 (and c_3_24 in_walk8_3 in_walk7_3)))
 (let (($x14237 (and c_3_23 in_walk8_3 in_walk7_3)))
 (let (($x14235 (and c_3_22 in_walk8_3 in_walk7_3)))
 (let (($x14233 (and c_3_21 in_walk8_3 in_walk7_3)))
 (let (($x14231 (and c_3_20 in_walk8_3 in_walk7_3)))
 (let (($x14229 (and c_3_19 in_walk8_3 in_walk7_3)))
 (let (($x14227 (and c_3_18 in_walk8_3 in_walk7_3)))
 (let (($x14225 (and c_3_17 in_walk8_3 in_walk7_3)))
 (let (($x14223 (and c_3_16 in_walk8_3 in_walk7_3)))
 (let (($x14221 (and c_3_15 in_walk8_3 in_walk7_3)))
 (let (($x14219 (and c_3_14 in_walk8_3 in_walk7_3)))
 (let (($x14217 (and c_3_13 in_walk8_3 in_walk7_3)))
 (let (($x14215 (and c_3_12 in_walk8_3 in_walk7_3)))
 (let (($x14213 (and c_3_11 in_walk8_3 in_walk7_3)))
 (let (($x14211 (and c_3_10 in_walk8_3 in_walk7_3)))
 (let (($x14209 (and c_3_9 in_walk8_3 in_walk7_3)))
 (let (($x14207 (and c_3_8 in_walk8_3 in_walk7_3)))
 (let (($x14205 (and c_3_7 in_walk8_3 in_walk7_3)))
 (let (($x14203 (and c_3_6 in_walk8_3 in_walk7_3)))
 (let (($x14201 (and c_3_5 in_walk8_3 in_walk7_3)))
 (let (($x14199 (and c_3_4 in_walk8_3 in_walk7_3)))
 (let (($x14197 (and c_3_3 in_walk8_3 in_walk7_3)))
 (let (($x14195 (and c_3_2 in_walk8_3 in_walk7_3)))
 (let (($x14193 (and c_3_1 in_walk8_3 in_walk7_3)))
 (let (($x14192 (and c_3_0 in_walk8_3 in_walk7_3)))
 (let (($x14240 (or $x14192 $x14193 $x14195 $x14197 $x14199 $x14201 $x14203 $x14205 $x14207 $x14209 $x14211 $x14213 $x14215 $x14217 $x14219 $x14221 $x14223 $x14225 $x14227 $x14229 $x14231 $x14233 $x14235 $x14237 $x14239)))
 (let (($x14162 (and c_2_24 in_walk8_2 in_walk7_2)))
 (let (($x14160 (and c_2_23 in_walk8_2 in_walk7_2)))
 (let (($x14158 (and c_2_22 in_walk8_2 in_walk7_2)))
 (let (($x14156 (and c_2_21 in_walk8_2 in_walk7_2)))
 (let (($x14154 (and c_2_20 in_walk8_2 in_walk7_2)))
 (let (($x14152 (and c_2_19 in_walk8_2 in_walk7_2)))
 (let (($x14150 (and c_2_18 in_walk8_2 in_walk7_2)))
 (let (($x14148 (and c_2_17 in_walk8_2 in_walk7_2)))
 (let (($x14146 (and c_2_16 in_walk8_2 in_walk7_2)))
 (let (($x14144 (and c_2_15 in_walk8_2 in_walk7_2)))
 (let (($x14142 (and c_2_14 in_walk8_2 in_walk7_2)))
 (let (($x14140 (and c_2_13 in_walk8_2 in_walk7_2)))
 (let (($x14138 (and c_2_12 in_walk8_2 in_walk7_2)))
 (let (($x14136 (and c_2_11 in_walk8_2 in_walk7_2)))
 (let (($x14134 (and c_2_10 in_walk8_2 in_walk7_2)))
 (let (($x14132 (and c_2_9 in_walk8_2 in_walk7_2)))
 (let (($x14130 (and c_2_8 in_walk8_2 in_walk7_2)))
 (let (($x14128 (and c_2_7 in_walk8_2 in_walk7_2)))
 (let (($x14126 (and c_2_6 in_walk8_2 in_walk7_2)))
 (let (($x14124 (and c_2_5 in_walk8_2 in_walk7_2)))
 (let (($x14122 (and c_2_4 in_walk8_2 in_walk7_2)))
 (let (($x14120 (and c_2_3 in_walk8_2 in_walk7_2)))
 (let (($x14118 (and c_2_2 in_walk8_2 in_walk7_2)))
 (let (($x14116 (and c_2_1 in_walk8_2 in_walk7_2)))
 (let (($x14115 (and c_2_0 in_walk8_2 in_walk7_2)))
 (let (($x14163 (or $x14115 $x14116 $x14118 $x14120 $x14122 $x14124 $x14126 $x14128 $x14130 $x14132 $x14134 $x14136 $x14138 $x14140 $x14142 $x14144 $x14146 $x14148 $x14150 $x14152 $x14154 $x14156 $x14158 $x14160 $x14162)))
 (let (($x14085 (and c_1_24 in_walk8_1 in_walk7_1)))
 (let (($x14083 (and c_1_23 in_walk8_1 in_walk7_1)))
 (let (($x14081 (and c_1_22 in_walk8_1 in_walk7_1)))
 (let (($x14079 (and c_1_21 in_walk8_1 in_walk7_1)))
 (let (($x14077 (and c_1_20 in_walk8_1 in_walk7_1)))
 (let (($x14075 (and c_1_19 in_walk8_1 in_walk7_1)))
 (let (($x14073 (and c_1_18 in_walk8_1 in_walk7_1)))
 (let (($x14071 (and c_1_17 in_walk8_1 in_walk7_1)))
 (let (($x14069 (and c_1_16 in_walk8_1 in_walk7_1)))
 (let (($x14067 (and c_1_15 in_walk8_1 in_walk7_1)))
 (let (($x14065 (and c_1_14 in_walk8_1 in_walk7_1)))
 (let (($x14063 (and c_1_13 in_walk8_1 in_walk7_1)))
 (let (($x14061 (and c_1_12 in_walk8_1 in_walk7_1)))
 (let (($x14059 (and c_1_11 in_walk8_1 in_walk7_1)))
 (let (($x14057 (and c_1_10 in_walk8_1 in_walk7_1)))
 (let (($x14055 (and c_1_9 in_walk8_1 in_walk7_1)))
 (let (($x14053 (and c_1_8 in_walk8_1 in_walk7_1)))
 (let (($x14051 (and c_1_7 in_walk8_1 in_walk7_1)))
 (let (($x14049 (and c_1_6 in_walk8_1 in_walk7_1)))
 (let (($x14047 (and c_1_5 in_walk8_1 in_walk7_1)))
 (let (($x14045 (and c_1_4 in_walk8_1 in_walk7_1)))
 (let (($x14043 (and c_1_3 in_walk8_1 in_walk7_1)))
 (let (($x14041 (and c_1_2 in_walk8_1 in_walk7_1)))
 (let (($x14039 (and c_1_1 in_walk8_1 in_walk7_1)))
 (let (($x14038 (and c_1_0 in_walk8_1 in_walk7_1)))
 (let (($x14086 (or $x14038 $x14039 $x14041 $x14043 $x14045 $x14047 $x14049 $x14051 $x14053 $x14055 $x14057 $x14059 $x14061 $x14063 $x14065 $x14067 $x14069 $x14071 $x14073 $x14075 $x14077 $x14079 $x14081 $x14083 $x14085)))
 (let (($x14008 (and c_0_24 in_walk8_0 in_walk7_0)))
 (let (($x14006 (and c_0_23 in_walk8_0 in_walk7_0)))
 (let (($x14004 (and c_0_22 in_walk8_0 in_walk7_0)))
 (let (($x14002 (and c_0_21 in_walk8_0 in_walk7_0)))
 (let (($x14000 (and c_0_20 in_walk8_0 in_walk7_0)))
 (let (($x13998 (and c_0_19 in_walk8_0 in_walk7_0)))
 (let (($x13996 (and c_0_18 in_walk8_0 in_walk7_0)))
 (let (($x13994 (and c_0_17 in_walk8_0 in_walk7_0)))
 (let (($x13992 (and c_0_16 in_walk8_0 in_walk7_0)))
 (let (($x13990 (and c_0_15 in_walk8_0 in_walk7_0)))
 (let (($x13988 (and c_0_14 in_walk8_0 in_walk7_0)))
 (let (($x13986 (and c_0_13 in_walk8_0 in_walk7_0)))
 (let (($x13984 (and c_0_12 in_walk8_0 in_walk7_0)))
 (let (($x13982 (and c_0_11 in_walk8_0 in_walk7_0)))
 (let (($x13980 (and c_0_10 in_walk8_0 in_walk7_0)))
 (let (($x13978 (and c_0_9 in_walk8_0 in_walk7_0)))
 (let (($x13976 (and c_0_8 in_walk8_0 in_walk7_0)))
 (let (($x13974 (and c_0_7 in_walk8_0 in_walk7_0)))
 (let (($x13972 (and c_0_6 in_walk8_0 in_walk7_0)))
 (let (($x13970 (and c_0_5 in_walk8_0 in_walk7_0)))
 (let (($x13968 (and c_0_4 in_walk8_0 in_walk7_0)))
 (let (($x13966 (and c_0_3 in_walk8_0 in_walk7_0)))
 (let (($x13964 (and c_0_2 in_walk8_0 in_walk7_0)))
 (let (($x13962 (and c_0_1 in_walk8_0 in_walk7_0)))
 (let (($x13961 (and c_0_0 in_walk8_0 in_walk7_0)))
 (let (($x14009 (or $x13961 $x13962 $x13964 $x13966 $x13968 $x13970 $x13972 $x13974 $x13976 $x13978 $x13980 $x13982 $x13984 $x13986 $x13988 $x13990 $x13992 $x13994 $x13996 $x13998 $x14000 $x14002 $x14004 $x14006 $x14008)))
 (let (($x13959 (or false $x14009)))
 (let (($x14036 (or $x13959 $x14086)))
 (let (($x14113 (or $x14036 $x14163)))
 (let (($x7352 (not (or (or (or (or false c_0_16) c_1_16) c_2_16) c_3_16))))
 (let (($x7037 (not (or (or (or (or false c_0_15) c_1_15) c_2_15) c_3_15))))
 (let (($x13928 (and c_3_24 in_walk8_3 in_walk6_3)))
 (let (($x13926 (and c_3_23 in_walk8_3 in_walk6_3)))
 (let (($x13924 (and c_3_22 in_walk8_3 in_walk6_3)))
 (let (($x13922 (and c_3_21 in_walk8_3 in_walk6_3)))
 (let (($x13920 (and c_3_20 in_walk8_3 in_walk6_3)))
 (let (($x13918 (and c_3_19 in_walk8_3 in_walk6_3)))
 (let (($x13916 (and c_3_18 in_walk8_3 in_walk6_3)))
 (let (($x13914 (and c_3_17 in_walk8_3 in_walk6_3)))
 (let (($x13912 (and c_3_16 in_walk8_3 in_walk6_3)))
 (let (($x13910 (and c_3_15 in_walk8_3 in_walk6_3)))
 (let (($x13908 (and c_3_14 in_walk8_3 in_walk6_3)))
 (let (($x13906 (and c_3_13 in_walk8_3 in_walk6_3)))
 (let (($x13904 (and c_3_12 in_walk8_3 in_walk6_3)))
 (let (($x13902 (and c_3_11 in_walk8_3 in_walk6_3)))
 (let (($x13900 (and c_3_10 in_walk8_3 in_walk6_3)))
 (let (($x13898 (and c_3_9 in_walk8_3 in_walk6_3)))
 (let (($x13896 (and c_3_8 in_walk8_3 in_walk6_3)))
 (let (($x13894 (and c_3_7 in_walk8_3 in_walk6_3)))
 (let (($x13892 (and c_3_6 in_walk8_3 in_walk6_3)))
 (let (($x13890 (and c_3_5 in_walk8_3 in_walk6_3)))
 (let (($x13888 (and c_3_4 in_walk8_3 in_walk6_3)))
 (let (($x13886 (and c_3_3 in_walk8_3 in_walk6_3)))
 (let (($x13884 (and c_3_2 in_walk8_3 in_walk6_3)))
 (let (($x13882 (and c_3_1 in_walk8_3 in_walk6_3)))
 (let (($x13881 (and c_3_0 in_walk8_3 in_walk6_3)))
 (let (($x13929 (or $x13881 $x13882 $x13884 $x13886 $x13888 $x13890 $x13892 $x13894 $x13896 $x13898 $x13900 $x13902 $x13904 $x13906 $x13908 $x13910 $x13912 $x13914 $x13916 $x13918 $x13920 $x13922 $x13924 $x13926 $x13928)))
 (let (($x13851 (and c_2_24 in_walk8_2 in_walk6_2)))
 (let (($x13849 (and c_2_23 in_walk8_2 in_walk6_2)))
 (let (($x13847 (and c_2_22 in_walk8_2 in_walk6_2)))
 (let (($x13845 (and c_2_21 in_walk8_2 in_walk6_2)))
 (let (($x13843 (and c_2_20 in_walk8_2 in_walk6_2)))
 (let (($x13841 (and c_2_19 in_walk8_2 in_walk6_2)))
 (let (($x13839 (and c_2_18 in_walk8_2 in_walk6_2)))
 (let (($x13837 (and c_2_17 in_walk8_2 in_walk6_2)))
 (let (($x13835 (and c_2_16 in_walk8_2 in_walk6_2)))
 (let (($x13833 (and c_2_15 in_walk8_2 in_walk6_2)))
 (let (($x13831 (and c_2_14 in_walk8_2 in_walk6_2)))
 (let (($x13829 (and c_2_13 in_walk8_2 in_walk6_2)))
 (let (($x13827 (and c_2_12 in_walk8_2 in_walk6_2)))
 (let (($x13825 (and c_2_11 in_walk8_2 in_walk6_2)))
 (let (($x13823 (and c_2_10 in_walk8_2 in_walk6_2)))
 (let (($x13821 (and c_2_9 in_walk8_2 in_walk6_2)))
 (let (($x13819 (and c_2_8 in_walk8_2 in_walk6_2)))
 (let (($x13817 (and c_2_7 in_walk8_2 in_walk6_2)))
 (let (($x13815 (and c_2_6 in_walk8_2 in_walk6_2)))
 (let (($x13813 (and c_2_5 in_walk8_2 in_walk6_2)))
 (let (($x13811 (and c_2_4 in_walk8_2 in_walk6_2)))
 (let (($x13809 (and c_2_3 in_walk8_2 in_walk6_2)))
 (let (($x13807 (and c_2_2 in_walk8_2 in_walk6_2)))
 (let (($x13805 (and c_2_1 in_walk8_2 in_walk6_2)))
 (let (($x13804 (and c_2_0 in_walk8_2 in_walk6_2)))
 (let (($x13852 (or $x13804 $x13805 $x13807 $x13809 $x13811 $x13813 $x13815 $x13817 $x13819 $x13821 $x13823 $x13825 $x13827 $x13829 $x13831 $x13833 $x13835 $x13837 $x13839 $x13841 $x13843 $x13845 $x13847 $x13849 $x13851)))
 (let (($x13774 (and c_1_24 in_walk8_1 in_walk6_1)))
 (let (($x13772 (and c_1_23 in_walk8_1 in_walk6_1)))
 (let (($x13770 (and c_1_22 in_walk8_1 in_walk6_1)))
 (let (($x13768 (and c_1_21 in_walk8_1 in_walk6_1)))
 (let (($x13766 (and c_1_20 in_walk8_1 in_walk6_1)))
 (let (($x13764 (and c_1_19 in_walk8_1 in_walk6_1)))
 (let (($x13762 (and c_1_18 in_walk8_1 in_walk6_1)))
 (let (($x13760 (and c_1_17 in_walk8_1 in_walk6_1)))
 (let (($x13758 (and c_1_16 in_walk8_1 in_walk6_1)))
 (let (($x13756 (and c_1_15 in_walk8_1 in_walk6_1)))
 (let (($x13754 (and c_1_14 in_walk8_1 in_walk6_1)))
 (let (($x13752 (and c_1_13 in_walk8_1 in_walk6_1)))
 (let (($x13750 (and c_1_12 in_walk8_1 in_walk6_1)))
 (let (($x13748 (and c_1_11 in_walk8_1 in_walk6_1)))
 (let (($x13746 (and c_1_10 in_walk8_1 in_walk6_1)))
 (let (($x13744 (and c_1_9 in_walk8_1 in_walk6_1)))
 (let (($x13742 (and c_1_8 in_walk8_1 in_walk6_1)))
 (let (($x13740 (and c_1_7 in_walk8_1 in_walk6_1)))
 (let (($x13738 (and c_1_6 in_walk8_1 in_walk6_1)))
 (let (($x13736 (and c_1_5 in_walk8_1 in_walk6_1)))
 (let (($x13734 (and c_1_4 in_walk8_1 in_walk6_1)))
 (let (($x13732 (and c_1_3 in_walk8_1 in_walk6_1)))
 (let (($x13730 (and c_1_2 in_walk8_1 in_walk6_1)))
 (let (($x13728 (and c_1_1 in_walk8_1 in_walk6_1)))
 (let (($x13727 (and c_1_0 in_walk8_1 in_walk6_1)))
 (let (($x13775 (or $x13727 $x13728 $x13730 $x13732 $x13734 $x13736 $x13738 $x13740 $x13742 $x13744 $x13746 $x13748 $x13750 $x13752 $x13754 $x13756 $x13758 $x13760 $x13762 $x13764 $x13766 $x13768 $x13770 $x13772 $x13774)))
 (let (($x13697 (and c_0_24 in_walk8_0 in_walk6_0)))
 (let (($x13695 (and c_0_23 in_walk8_0 in_walk6_0)))
 (let (($x13693 (and c_0_22 in_walk8_0 in_walk6_0)))
 (let (($x13691 (and c_0_21 in_walk8_0 in_walk6_0)))
 (let (($x13689 (and c_0_20 in_walk8_0 in_walk6_0)))
 (let (($x13687 (and c_0_19 in_walk8_0 in_walk6_0)))
 (let (($x13685 (and c_0_18 in_walk8_0 in_walk6_0)))
 (let (($x13683 (and c_0_17 in_walk8_0 in_walk6_0)))
 (let (($x13681 (and c_0_16 in_walk8_0 in_walk6_0)))
 (let (($x13679 (and c_0_15 in_walk8_0 in_walk6_0)))
 (let (($x13677 (and c_0_14 in_walk8_0 in_walk6_0)))
 (let (($x13675 (and c_0_13 in_walk8_0 in_walk6_0)))
 (let (($x13673 (and c_0_12 in_walk8_0 in_walk6_0)))
 (let (($x13671 (and c_0_11 in_walk8_0 in_walk6_0)))
 (let (($x13669 (and c_0_10 in_walk8_0 in_walk6_0)))
 (let (($x13667 (and c_0_9 in_walk8_0 in_walk6_0)))
 (let (($x13665 (and c_0_8 in_walk8_0 in_walk6_0)))
 (let (($x13663 (and c_0_7 in_walk8_0 in_walk6_0)))
 (let (($x13661 (and c_0_6 in_walk8_0 in_walk6_0)))
 (let (($x13659 (and c_0_5 in_walk8_0 in_walk6_0)))
 (let (($x13657 (and c_0_4 in_walk8_0 in_walk6_0)))
 (let (($x13655 (and c_0_3 in_walk8_0 in_walk6_0)))
 (let (($x13653 (and c_0_2 in_walk8_0 in_walk6_0)))
 (let (($x13651 (and c_0_1 in_walk8_0 in_walk6_0)))
 (let (($x13650 (and c_0_0 in_walk8_0 in_walk6_0)))
 (let (($x13698 (or $x13650 $x13651 $x13653 $x13655 $x13657 $x13659 $x13661 $x13663 $x13665 $x13667 $x13669 $x13671 $x13673 $x13675 $x13677 $x13679 $x13681 $x13683 $x13685 $x13687 $x13689 $x13691 $x13693 $x13695 $x13697)))
 (let (($x13648 (or false $x13698)))
 (let (($x13725 (or $x13648 $x13775)))
 (let (($x13802 (or $x13725 $x13852)))
 (let (($x6710 (not (or (or (or (or false c_0_14) c_1_14) c_2_14) c_3_14))))
 (let (($x13617 (and c_3_24 in_walk7_3 in_walk6_3)))
 (let (($x13615 (and c_3_23 in_walk7_3 in_walk6_3)))
 (let (($x13613 (and c_3_22 in_walk7_3 in_walk6_3)))
 (let (($x13611 (and c_3_21 in_walk7_3 in_walk6_3)))
 (let (($x13609 (and c_3_20 in_walk7_3 in_walk6_3)))
 (let (($x13607 (and c_3_19 in_walk7_3 in_walk6_3)))
 (let (($x13605 (and c_3_18 in_walk7_3 in_walk6_3)))
 (let (($x13603 (and c_3_17 in_walk7_3 in_walk6_3)))
 (let (($x13601 (and c_3_16 in_walk7_3 in_walk6_3)))
 (let (($x13599 (and c_3_15 in_walk7_3 in_walk6_3)))
 (let (($x13597 (and c_3_14 in_walk7_3 in_walk6_3)))
 (let (($x13595 (and c_3_13 in_walk7_3 in_walk6_3)))
 (let (($x13593 (and c_3_12 in_walk7_3 in_walk6_3)))
 (let (($x13591 (and c_3_11 in_walk7_3 in_walk6_3)))
 (let (($x13589 (and c_3_10 in_walk7_3 in_walk6_3)))
 (let (($x13587 (and c_3_9 in_walk7_3 in_walk6_3)))
 (let (($x13585 (and c_3_8 in_walk7_3 in_walk6_3)))
 (let (($x13583 (and c_3_7 in_walk7_3 in_walk6_3)))
 (let (($x13581 (and c_3_6 in_walk7_3 in_walk6_3)))
 (let (($x13579 (and c_3_5 in_walk7_3 in_walk6_3)))
 (let (($x13577 (and c_3_4 in_walk7_3 in_walk6_3)))
 (let (($x13575 (and c_3_3 in_walk7_3 in_walk6_3)))
 (let (($x13573 (and c_3_2 in_walk7_3 in_walk6_3)))
 (let (($x13571 (and c_3_1 in_walk7_3 in_walk6_3)))
 (let (($x13570 (and c_3_0 in_walk7_3 in_walk6_3)))
 (let (($x13618 (or $x13570 $x13571 $x13573 $x13575 $x13577 $x13579 $x13581 $x13583 $x13585 $x13587 $x13589 $x13591 $x13593 $x13595 $x13597 $x13599 $x13601 $x13603 $x13605 $x13607 $x13609 $x13611 $x13613 $x13615 $x13617)))
 (let (($x13540 (and c_2_24 in_walk7_2 in_walk6_2)))
 (let (($x13538 (and c_2_23 in_walk7_2 in_walk6_2)))
 (let (($x13536 (and c_2_22 in_walk7_2 in_walk6_2)))
 (let (($x13534 (and c_2_21 in_walk7_2 in_walk6_2)))
 (let (($x13532 (and c_2_20 in_walk7_2 in_walk6_2)))
 (let (($x13530 (and c_2_19 in_walk7_2 in_walk6_2)))
 (let (($x13528 (and c_2_18 in_walk7_2 in_walk6_2)))
 (let (($x13526 (and c_2_17 in_walk7_2 in_walk6_2)))
 (let (($x13524 (and c_2_16 in_walk7_2 in_walk6_2)))
 (let (($x13522 (and c_2_15 in_walk7_2 in_walk6_2)))
 (let (($x13520 (and c_2_14 in_walk7_2 in_walk6_2)))
 (let (($x13518 (and c_2_13 in_walk7_2 in_walk6_2)))
 (let (($x13516 (and c_2_12 in_walk7_2 in_walk6_2)))
 (let (($x13514 (and c_2_11 in_walk7_2 in_walk6_2)))
 (let (($x13512 (and c_2_10 in_walk7_2 in_walk6_2)))
 (let (($x13510 (and c_2_9 in_walk7_2 in_walk6_2)))
 (let (($x13508 (and c_2_8 in_walk7_2 in_walk6_2)))
 (let (($x13506 (and c_2_7 in_walk7_2 in_walk6_2)))
 (let (($x13504 (and c_2_6 in_walk7_2 in_walk6_2)))
 (let (($x13502 (and c_2_5 in_walk7_2 in_walk6_2)))
 (let (($x13500 (and c_2_4 in_walk7_2 in_walk6_2)))
 (let (($x13498 (and c_2_3 in_walk7_2 in_walk6_2)))
 (let (($x13496 (and c_2_2 in_walk7_2 in_walk6_2)))
 (let (($x13494 (and c_2_1 in_walk7_2 in_walk6_2)))
 (let (($x13493 (and c_2_0 in_walk7_2 in_walk6_2)))
 (let (($x13541 (or $x13493 $x13494 $x13496 $x13498 $x13500 $x13502 $x13504 $x13506 $x13508 $x13510 $x13512 $x13514 $x13516 $x13518 $x13520 $x13522 $x13524 $x13526 $x13528 $x13530 $x13532 $x13534 $x13536 $x13538 $x13540)))
 (let (($x13463 (and c_1_24 in_walk7_1 in_walk6_1)))
 (let (($x13461 (and c_1_23 in_walk7_1 in_walk6_1)))
 (let (($x13459 (and c_1_22 in_walk7_1 in_walk6_1)))
 (let (($x13457 (and c_1_21 in_walk7_1 in_walk6_1)))
 (let (($x13455 (and c_1_20 in_walk7_1 in_walk6_1)))
 (let (($x13453 (and c_1_19 in_walk7_1 in_walk6_1)))
 (let (($x13451 (and c_1_18 in_walk7_1 in_walk6_1)))
 (let (($x13449 (and c_1_17 in_walk7_1 in_walk6_1)))
 (let (($x13447 (and c_1_16 in_walk7_1 in_walk6_1)))
 (let (($x13445 (and c_1_15 in_walk7_1 in_walk6_1)))
 (let (($x13443 (and c_1_14 in_walk7_1 in_walk6_1)))
 (let (($x13441 (and c_1_13 in_walk7_1 in_walk6_1)))
 (let (($x13439 (and c_1_12 in_walk7_1 in_walk6_1)))
 (let (($x13437 (and c_1_11 in_walk7_1 in_walk6_1)))
 (let (($x13435 (and c_1_10 in_walk7_1 in_walk6_1)))
 (let (($x13433 (and c_1_9 in_walk7_1 in_walk6_1)))
 (let (($x13431 (and c_1_8 in_walk7_1 in_walk6_1)))
 (let (($x13429 (and c_1_7 in_walk7_1 in_walk6_1)))
 (let (($x13427 (and c_1_6 in_walk7_1 in_walk6_1)))
 (let (($x13425 (and c_1_5 in_walk7_1 in_walk6_1)))
 (let (($x13423 (and c_1_4 in_walk7_1 in_walk6_1)))
 (let (($x13421 (and c_1_3 in_walk7_1 in_walk6_1)))
 (let (($x13419 (and c_1_2 in_walk7_1 in_walk6_1)))
 (let (($x13417 (and c_1_1 in_walk7_1 in_walk6_1)))
 (let (($x13416 (and c_1_0 in_walk7_1 in_walk6_1)))
 (let (($x13464 (or $x13416 $x13417 $x13419 $x13421 $x13423 $x13425 $x13427 $x13429 $x13431 $x13433 $x13435 $x13437 $x13439 $x13441 $x13443 $x13445 $x13447 $x13449 $x13451 $x13453 $x13455 $x13457 $x13459 $x13461 $x13463)))
 (let (($x13386 (and c_0_24 in_walk7_0 in_walk6_0)))
 (let (($x13384 (and c_0_23 in_walk7_0 in_walk6_0)))
 (let (($x13382 (and c_0_22 in_walk7_0 in_walk6_0)))
 (let (($x13380 (and c_0_21 in_walk7_0 in_walk6_0)))
 (let (($x13378 (and c_0_20 in_walk7_0 in_walk6_0)))
 (let (($x13376 (and c_0_19 in_walk7_0 in_walk6_0)))
 (let (($x13374 (and c_0_18 in_walk7_0 in_walk6_0)))
 (let (($x13372 (and c_0_17 in_walk7_0 in_walk6_0)))
 (let (($x13370 (and c_0_16 in_walk7_0 in_walk6_0)))
 (let (($x13368 (and c_0_15 in_walk7_0 in_walk6_0)))
 (let (($x13366 (and c_0_14 in_walk7_0 in_walk6_0)))
 (let (($x13364 (and c_0_13 in_walk7_0 in_walk6_0)))
 (let (($x13362 (and c_0_12 in_walk7_0 in_walk6_0)))
 (let (($x13360 (and c_0_11 in_walk7_0 in_walk6_0)))
 (let (($x13358 (and c_0_10 in_walk7_0 in_walk6_0)))
 (let (($x13356 (and c_0_9 in_walk7_0 in_walk6_0)))
 (let (($x13354 (and c_0_8 in_walk7_0 in_walk6_0)))
 (let (($x13352 (and c_0_7 in_walk7_0 in_walk6_0)))
 (let (($x13350 (and c_0_6 in_walk7_0 in_walk6_0)))
 (let (($x13348 (and c_0_5 in_walk7_0 in_walk6_0)))
 (let (($x13346 (and c_0_4 in_walk7_0 in_walk6_0)))
 (let (($x13344 (and c_0_3 in_walk7_0 in_walk6_0)))
 (let (($x13342 (and c_0_2 in_walk7_0 in_walk6_0)))
 (let (($x13340 (and c_0_1 in_walk7_0 in_walk6_0)))
 (let (($x13339 (and c_0_0 in_walk7_0 in_walk6_0)))
 (let (($x13387 (or $x13339 $x13340 $x13342 $x13344 $x13346 $x13348 $x13350 $x13352 $x13354 $x13356 $x13358 $x13360 $x13362 $x13364 $x13366 $x13368 $x13370 $x13372 $x13374 $x13376 $x13378 $x13380 $x13382 $x13384 $x13386)))
 (let (($x13337 (or false $x13387)))
 (let (($x13414 (or $x13337 $x13464)))
 (let (($x13491 (or $x13414 $x13541)))
 (let (($x13306 (and c_3_24 in_walk8_3 in_walk5_3)))
 (let (($x13304 (and c_3_23 in_walk8_3 in_walk5_3)))
 (let (($x13302 (and c_3_22 in_walk8_3 in_walk5_3)))
 (let (($x13300 (and c_3_21 in_walk8_3 in_walk5_3)))
 (let (($x13298 (and c_3_20 in_walk8_3 in_walk5_3)))
 (let (($x13296 (and c_3_19 in_walk8_3 in_walk5_3)))
 (let (($x13294 (and c_3_18 in_walk8_3 in_walk5_3)))
 (let (($x13292 (and c_3_17 in_walk8_3 in_walk5_3)))
 (let (($x13290 (and c_3_16 in_walk8_3 in_walk5_3)))
 (let (($x13288 (and c_3_15 in_walk8_3 in_walk5_3)))
 (let (($x13286 (and c_3_14 in_walk8_3 in_walk5_3)))
 (let (($x13284 (and c_3_13 in_walk8_3 in_walk5_3)))
 (let (($x13282 (and c_3_12 in_walk8_3 in_walk5_3)))
 (let (($x13280 (and c_3_11 in_walk8_3 in_walk5_3)))
 (let (($x13278 (and c_3_10 in_walk8_3 in_walk5_3)))
 (let (($x13276 (and c_3_9 in_walk8_3 in_walk5_3)))
 (let (($x13274 (and c_3_8 in_walk8_3 in_walk5_3)))
 (let (($x13272 (and c_3_7 in_walk8_3 in_walk5_3)))
 (let (($x13270 (and c_3_6 in_walk8_3 in_walk5_3)))
 (let (($x13268 (and c_3_5 in_walk8_3 in_walk5_3)))
 (let (($x13266 (and c_3_4 in_walk8_3 in_walk5_3)))
 (let (($x13264 (and c_3_3 in_walk8_3 in_walk5_3)))
 (let (($x13262 (and c_3_2 in_walk8_3 in_walk5_3)))
 (let (($x13260 (and c_3_1 in_walk8_3 in_walk5_3)))
 (let (($x13259 (and c_3_0 in_walk8_3 in_walk5_3)))
 (let (($x13307 (or $x13259 $x13260 $x13262 $x13264 $x13266 $x13268 $x13270 $x13272 $x13274 $x13276 $x13278 $x13280 $x13282 $x13284 $x13286 $x13288 $x13290 $x13292 $x13294 $x13296 $x13298 $x13300 $x13302 $x13304 $x13306)))
 (let (($x13229 (and c_2_24 in_walk8_2 in_walk5_2)))
 (let (($x13227 (and c_2_23 in_walk8_2 in_walk5_2)))
 (let (($x13225 (and c_2_22 in_walk8_2 in_walk5_2)))
 (let (($x13223 (and c_2_21 in_walk8_2 in_walk5_2)))
 (let (($x13221 (and c_2_20 in_walk8_2 in_walk5_2)))
 (let (($x13219 (and c_2_19 in_walk8_2 in_walk5_2)))
 (let (($x13217 (and c_2_18 in_walk8_2 in_walk5_2)))
 (let (($x13215 (and c_2_17 in_walk8_2 in_walk5_2)))
 (let (($x13213 (and c_2_16 in_walk8_2 in_walk5_2)))
 (let (($x13211 (and c_2_15 in_walk8_2 in_walk5_2)))
 (let (($x13209 (and c_2_14 in_walk8_2 in_walk5_2)))
 (let (($x13207 (and c_2_13 in_walk8_2 in_walk5_2)))
 (let (($x13205 (and c_2_12 in_walk8_2 in_walk5_2)))
 (let (($x13203 (and c_2_11 in_walk8_2 in_walk5_2)))
 (let (($x13201 (and c_2_10 in_walk8_2 in_walk5_2)))
 (let (($x13199 (and c_2_9 in_walk8_2 in_walk5_2)))
 (let (($x13197 (and c_2_8 in_walk8_2 in_walk5_2)))
 (let (($x13195 (and c_2_7 in_walk8_2 in_walk5_2)))
 (let (($x13193 (and c_2_6 in_walk8_2 in_walk5_2)))
 (let (($x13191 (and c_2_5 in_walk8_2 in_walk5_2)))
 (let (($x13189 (and c_2_4 in_walk8_2 in_walk5_2)))
 (let (($x13187 (and c_2_3 in_walk8_2 in_walk5_2)))
 (let (($x13185 (and c_2_2 in_walk8_2 in_walk5_2)))
 (let (($x13183 (and c_2_1 in_walk8_2 in_walk5_2)))
 (let (($x13182 (and c_2_0 in_walk8_2 in_walk5_2)))
 (let (($x13230 (or $x13182 $x13183 $x13185 $x13187 $x13189 $x13191 $x13193 $x13195 $x13197 $x13199 $x13201 $x13203 $x13205 $x13207 $x13209 $x13211 $x13213 $x13215 $x13217 $x13219 $x13221 $x13223 $x13225 $x13227 $x13229)))
 (let (($x13152 (and c_1_24 in_walk8_1 in_walk5_1)))
 (let (($x13150 (and c_1_23 in_walk8_1 in_walk5_1)))
 (let (($x13148 (and c_1_22 in_walk8_1 in_walk5_1)))
 (let (($x13146 (and c_1_21 in_walk8_1 in_walk5_1)))
 (let (($x13144 (and c_1_20 in_walk8_1 in_walk5_1)))
 (let (($x13142 (and c_1_19 in_walk8_1 in_walk5_1)))
 (let (($x13140 (and c_1_18 in_walk8_1 in_walk5_1)))
 (let (($x13138 (and c_1_17 in_walk8_1 in_walk5_1)))
 (let (($x13136 (and c_1_16 in_walk8_1 in_walk5_1)))
 (let (($x13134 (and c_1_15 in_walk8_1 in_walk5_1)))
 (let (($x13132 (and c_1_14 in_walk8_1 in_walk5_1)))
 (let (($x13130 (and c_1_13 in_walk8_1 in_walk5_1)))
 (let (($x13128 (and c_1_12 in_walk8_1 in_walk5_1)))
 (let (($x13126 (and c_1_11 in_walk8_1 in_walk5_1)))
 (let (($x13124 (and c_1_10 in_walk8_1 in_walk5_1)))
 (let (($x13122 (and c_1_9 in_walk8_1 in_walk5_1)))
 (let (($x13120 (and c_1_8 in_walk8_1 in_walk5_1)))
 (let (($x13118 (and c_1_7 in_walk8_1 in_walk5_1)))
 (let (($x13116 (and c_1_6 in_walk8_1 in_walk5_1)))
 (let (($x13114 (and c_1_5 in_walk8_1 in_walk5_1)))
 (let (($x13112 (and c_1_4 in_walk8_1 in_walk5_1)))
 (let (($x13110 (and c_1_3 in_walk8_1 in_walk5_1)))
 (let (($x13108 (and c_1_2 in_walk8_1 in_walk5_1)))
 (let (($x13106 (and c_1_1 in_walk8_1 in_walk5_1)))
 (let (($x13105 (and c_1_0 in_walk8_1 in_walk5_1)))
 (let (($x13153 (or $x13105 $x13106 $x13108 $x13110 $x13112 $x13114 $x13116 $x13118 $x13120 $x13122 $x13124 $x13126 $x13128 $x13130 $x13132 $x13134 $x13136 $x13138 $x13140 $x13142 $x13144 $x13146 $x13148 $x13150 $x13152)))
 (let (($x13075 (and c_0_24 in_walk8_0 in_walk5_0)))
 (let (($x13073 (and c_0_23 in_walk8_0 in_walk5_0)))
 (let (($x13071 (and c_0_22 in_walk8_0 in_walk5_0)))
 (let (($x13069 (and c_0_21 in_walk8_0 in_walk5_0)))
 (let (($x13067 (and c_0_20 in_walk8_0 in_walk5_0)))
 (let (($x13065 (and c_0_19 in_walk8_0 in_walk5_0)))
 (let (($x13063 (and c_0_18 in_walk8_0 in_walk5_0)))
 (let (($x13061 (and c_0_17 in_walk8_0 in_walk5_0)))
 (let (($x13059 (and c_0_16 in_walk8_0 in_walk5_0)))
 (let (($x13057 (and c_0_15 in_walk8_0 in_walk5_0)))
 (let (($x13055 (and c_0_14 in_walk8_0 in_walk5_0)))
 (let (($x13053 (and c_0_13 in_walk8_0 in_walk5_0)))
 (let (($x13051 (and c_0_12 in_walk8_0 in_walk5_0)))
 (let (($x13049 (and c_0_11 in_walk8_0 in_walk5_0)))
 (let (($x13047 (and c_0_10 in_walk8_0 in_walk5_0)))
 (let (($x13045 (and c_0_9 in_walk8_0 in_walk5_0)))
 (let (($x13043 (and c_0_8 in_walk8_0 in_walk5_0)))
 (let (($x13041 (and c_0_7 in_walk8_0 in_walk5_0)))
 (let (($x13039 (and c_0_6 in_walk8_0 in_walk5_0)))
 (let (($x13037 (and c_0_5 in_walk8_0 in_walk5_0)))
 (let (($x13035 (and c_0_4 in_walk8_0 in_walk5_0)))
 (let (($x13033 (and c_0_3 in_walk8_0 in_walk5_0)))
 (let (($x13031 (and c_0_2 in_walk8_0 in_walk5_0)))
 (let (($x13029 (and c_0_1 in_walk8_0 in_walk5_0)))
 (let (($x13028 (and c_0_0 in_walk8_0 in_walk5_0)))
 (let (($x13076 (or $x13028 $x13029 $x13031 $x13033 $x13035 $x13037 $x13039 $x13041 $x13043 $x13045 $x13047 $x13049 $x13051 $x13053 $x13055 $x13057 $x13059 $x13061 $x13063 $x13065 $x13067 $x13069 $x13071 $x13073 $x13075)))
 (let (($x13026 (or false $x13076)))
 (let (($x13103 (or $x13026 $x13153)))
 (let (($x13180 (or $x13103 $x13230)))
 (let (($x6411 (not (or (or (or (or false c_0_13) c_1_13) c_2_13) c_3_13))))
 (let (($x12995 (and c_3_24 in_walk7_3 in_walk5_3)))
 (let (($x12993 (and c_3_23 in_walk7_3 in_walk5_3)))
 (let (($x12991 (and c_3_22 in_walk7_3 in_walk5_3)))
 (let (($x12989 (and c_3_21 in_walk7_3 in_walk5_3)))
 (let (($x12987 (and c_3_20 in_walk7_3 in_walk5_3)))
 (let (($x12985 (and c_3_19 in_walk7_3 in_walk5_3)))
 (let (($x12983 (and c_3_18 in_walk7_3 in_walk5_3)))
 (let (($x12981 (and c_3_17 in_walk7_3 in_walk5_3)))
 (let (($x12979 (and c_3_16 in_walk7_3 in_walk5_3)))
 (let (($x12977 (and c_3_15 in_walk7_3 in_walk5_3)))
 (let (($x12975 (and c_3_14 in_walk7_3 in_walk5_3)))
 (let (($x12973 (and c_3_13 in_walk7_3 in_walk5_3)))
 (let (($x12971 (and c_3_12 in_walk7_3 in_walk5_3)))
 (let (($x12969 (and c_3_11 in_walk7_3 in_walk5_3)))
 (let (($x12967 (and c_3_10 in_walk7_3 in_walk5_3)))
 (let (($x12965 (and c_3_9 in_walk7_3 in_walk5_3)))
 (let (($x12963 (and c_3_8 in_walk7_3 in_walk5_3)))
 (let (($x12961 (and c_3_7 in_walk7_3 in_walk5_3)))
 (let (($x12959 (and c_3_6 in_walk7_3 in_walk5_3)))
 (let (($x12957 (and c_3_5 in_walk7_3 in_walk5_3)))
 (let (($x12955 (and c_3_4 in_walk7_3 in_walk5_3)))
 (let (($x12953 (and c_3_3 in_walk7_3 in_walk5_3)))
 (let (($x12951 (and c_3_2 in_walk7_3 in_walk5_3)))
 (let (($x12949 (and c_3_1 in_walk7_3 in_walk5_3)))
 (let (($x12948 (and c_3_0 in_walk7_3 in_walk5_3)))
 (let (($x12996 (or $x12948 $x12949 $x12951 $x12953 $x12955 $x12957 $x12959 $x12961 $x12963 $x12965 $x12967 $x12969 $x12971 $x12973 $x12975 $x12977 $x12979 $x12981 $x12983 $x12985 $x12987 $x12989 $x12991 $x12993 $x12995)))
 (let (($x12918 (and c_2_24 in_walk7_2 in_walk5_2)))
 (let (($x12916 (and c_2_23 in_walk7_2 in_walk5_2)))
 (let (($x12914 (and c_2_22 in_walk7_2 in_walk5_2)))
 (let (($x12912 (and c_2_21 in_walk7_2 in_walk5_2)))
 (let (($x12910 (and c_2_20 in_walk7_2 in_walk5_2)))
 (let (($x12908 (and c_2_19 in_walk7_2 in_walk5_2)))
 (let (($x12906 (and c_2_18 in_walk7_2 in_walk5_2)))
 (let (($x12904 (and c_2_17 in_walk7_2 in_walk5_2)))
 (let (($x12902 (and c_2_16 in_walk7_2 in_walk5_2)))
 (let (($x12900 (and c_2_15 in_walk7_2 in_walk5_2)))
 (let (($x12898 (and c_2_14 in_walk7_2 in_walk5_2)))
 (let (($x12896 (and c_2_13 in_walk7_2 in_walk5_2)))
 (let (($x12894 (and c_2_12 in_walk7_2 in_walk5_2)))
 (let (($x12892 (and c_2_11 in_walk7_2 in_walk5_2)))
 (let (($x12890 (and c_2_10 in_walk7_2 in_walk5_2)))
 (let (($x12888 (and c_2_9 in_walk7_2 in_walk5_2)))
 (let (($x12886 (and c_2_8 in_walk7_2 in_walk5_2)))
 (let (($x12884 (and c_2_7 in_walk7_2 in_walk5_2)))
 (let (($x12882 (and c_2_6 in_walk7_2 in_walk5_2)))
 (let (($x12880 (and c_2_5 in_walk7_2 in_walk5_2)))
 (let (($x12878 (and c_2_4 in_walk7_2 in_walk5_2)))
 (let (($x12876 (and c_2_3 in_walk7_2 in_walk5_2)))
 (let (($x12874 (and c_2_2 in_walk7_2 in_walk5_2)))
 (let (($x12872 (and c_2_1 in_walk7_2 in_walk5_2)))
 (let (($x12871 (and c_2_0 in_walk7_2 in_walk5_2)))
 (let (($x12919 (or $x12871 $x12872 $x12874 $x12876 $x12878 $x12880 $x12882 $x12884 $x12886 $x12888 $x12890 $x12892 $x12894 $x12896 $x12898 $x12900 $x12902 $x12904 $x12906 $x12908 $x12910 $x12912 $x12914 $x12916 $x12918)))
 (let (($x12841 (and c_1_24 in_walk7_1 in_walk5_1)))
 (let (($x12839 (and c_1_23 in_walk7_1 in_walk5_1)))
 (let (($x12837 (and c_1_22 in_walk7_1 in_walk5_1)))
 (let (($x12835 (and c_1_21 in_walk7_1 in_walk5_1)))
 (let (($x12833 (and c_1_20 in_walk7_1 in_walk5_1)))
 (let (($x12831 (and c_1_19 in_walk7_1 in_walk5_1)))
 (let (($x12829 (and c_1_18 in_walk7_1 in_walk5_1)))
 (let (($x12827 (and c_1_17 in_walk7_1 in_walk5_1)))
 (let (($x12825 (and c_1_16 in_walk7_1 in_walk5_1)))
 (let (($x12823 (and c_1_15 in_walk7_1 in_walk5_1)))
 (let (($x12821 (and c_1_14 in_walk7_1 in_walk5_1)))
 (let (($x12819 (and c_1_13 in_walk7_1 in_walk5_1)))
 (let (($x12817 (and c_1_12 in_walk7_1 in_walk5_1)))
 (let (($x12815 (and c_1_11 in_walk7_1 in_walk5_1)))
 (let (($x12813 (and c_1_10 in_walk7_1 in_walk5_1)))
 (let (($x12811 (and c_1_9 in_walk7_1 in_walk5_1)))
 (let (($x12809 (and c_1_8 in_walk7_1 in_walk5_1)))
 (let (($x12807 (and c_1_7 in_walk7_1 in_walk5_1)))
 (let (($x12805 (and c_1_6 in_walk7_1 in_walk5_1)))
 (let (($x12803 (and c_1_5 in_walk7_1 in_walk5_1)))
 (let (($x12801 (and c_1_4 in_walk7_1 in_walk5_1)))
 (let (($x12799 (and c_1_3 in_walk7_1 in_walk5_1)))
 (let (($x12797 (and c_1_2 in_walk7_1 in_walk5_1)))
 (let (($x12795 (and c_1_1 in_walk7_1 in_walk5_1)))
 (let (($x12794 (and c_1_0 in_walk7_1 in_walk5_1)))
 (let (($x12842 (or $x12794 $x12795 $x12797 $x12799 $x12801 $x12803 $x12805 $x12807 $x12809 $x12811 $x12813 $x12815 $x12817 $x12819 $x12821 $x12823 $x12825 $x12827 $x12829 $x12831 $x12833 $x12835 $x12837 $x12839 $x12841)))
 (let (($x12764 (and c_0_24 in_walk7_0 in_walk5_0)))
 (let (($x12762 (and c_0_23 in_walk7_0 in_walk5_0)))
 (let (($x12760 (and c_0_22 in_walk7_0 in_walk5_0)))
 (let (($x12758 (and c_0_21 in_walk7_0 in_walk5_0)))
 (let (($x12756 (and c_0_20 in_walk7_0 in_walk5_0)))
 (let (($x12754 (and c_0_19 in_walk7_0 in_walk5_0)))
 (let (($x12752 (and c_0_18 in_walk7_0 in_walk5_0)))
 (let (($x12750 (and c_0_17 in_walk7_0 in_walk5_0)))
 (let (($x12748 (and c_0_16 in_walk7_0 in_walk5_0)))
 (let (($x12746 (and c_0_15 in_walk7_0 in_walk5_0)))
 (let (($x12744 (and c_0_14 in_walk7_0 in_walk5_0)))
 (let (($x12742 (and c_0_13 in_walk7_0 in_walk5_0)))
 (let (($x12740 (and c_0_12 in_walk7_0 in_walk5_0)))
 (let (($x12738 (and c_0_11 in_walk7_0 in_walk5_0)))
 (let (($x12736 (and c_0_10 in_walk7_0 in_walk5_0)))
 (let (($x12734 (and c_0_9 in_walk7_0 in_walk5_0)))
 (let (($x12732 (and c_0_8 in_walk7_0 in_walk5_0)))
 (let (($x12730 (and c_0_7 in_walk7_0 in_walk5_0)))
 (let (($x12728 (and c_0_6 in_walk7_0 in_walk5_0)))
 (let (($x12726 (and c_0_5 in_walk7_0 in_walk5_0)))
 (let (($x12724 (and c_0_4 in_walk7_0 in_walk5_0)))
 (let (($x12722 (and c_0_3 in_walk7_0 in_walk5_0)))
 (let (($x12720 (and c_0_2 in_walk7_0 in_walk5_0)))
 (let (($x12718 (and c_0_1 in_walk7_0 in_walk5_0)))
 (let (($x12717 (and c_0_0 in_walk7_0 in_walk5_0)))
 (let (($x12765 (or $x12717 $x12718 $x12720 $x12722 $x12724 $x12726 $x12728 $x12730 $x12732 $x12734 $x12736 $x12738 $x12740 $x12742 $x12744 $x12746 $x12748 $x12750 $x12752 $x12754 $x12756 $x12758 $x12760 $x12762 $x12764)))
 (let (($x12715 (or false $x12765)))
 (let (($x12792 (or $x12715 $x12842)))
 (let (($x12869 (or $x12792 $x12919)))
 (let (($x12684 (and c_3_24 in_walk6_3 in_walk5_3)))
 (let (($x12682 (and c_3_23 in_walk6_3 in_walk5_3)))
 (let (($x12680 (and c_3_22 in_walk6_3 in_walk5_3)))
 (let (($x12678 (and c_3_21 in_walk6_3 in_walk5_3)))
 (let (($x12676 (and c_3_20 in_walk6_3 in_walk5_3)))
 (let (($x12674 (and c_3_19 in_walk6_3 in_walk5_3)))
 (let (($x12672 (and c_3_18 in_walk6_3 in_walk5_3)))
 (let (($x12670 (and c_3_17 in_walk6_3 in_walk5_3)))
 (let (($x12668 (and c_3_16 in_walk6_3 in_walk5_3)))
 (let (($x12666 (and c_3_15 in_walk6_3 in_walk5_3)))
 (let (($x12664 (and c_3_14 in_walk6_3 in_walk5_3)))
 (let (($x12662 (and c_3_13 in_walk6_3 in_walk5_3)))
 (let (($x12660 (and c_3_12 in_walk6_3 in_walk5_3)))
 (let (($x12658 (and c_3_11 in_walk6_3 in_walk5_3)))
 (let (($x12656 (and c_3_10 in_walk6_3 in_walk5_3)))
 (let (($x12654 (and c_3_9 in_walk6_3 in_walk5_3)))
 (let (($x12652 (and c_3_8 in_walk6_3 in_walk5_3)))
 (let (($x12650 (and c_3_7 in_walk6_3 in_walk5_3)))
 (let (($x12648 (and c_3_6 in_walk6_3 in_walk5_3)))
 (let (($x12646 (and c_3_5 in_walk6_3 in_walk5_3)))
 (let (($x12644 (and c_3_4 in_walk6_3 in_walk5_3)))
 (let (($x12642 (and c_3_3 in_walk6_3 in_walk5_3)))
 (let (($x12640 (and c_3_2 in_walk6_3 in_walk5_3)))
 (let (($x12638 (and c_3_1 in_walk6_3 in_walk5_3)))
 (let (($x12637 (and c_3_0 in_walk6_3 in_walk5_3)))
 (let (($x12685 (or $x12637 $x12638 $x12640 $x12642 $x12644 $x12646 $x12648 $x12650 $x12652 $x12654 $x12656 $x12658 $x12660 $x12662 $x12664 $x12666 $x12668 $x12670 $x12672 $x12674 $x12676 $x12678 $x12680 $x12682 $x12684)))
 (let (($x12607 (and c_2_24 in_walk6_2 in_walk5_2)))
 (let (($x12605 (and c_2_23 in_walk6_2 in_walk5_2)))
 (let (($x12603 (and c_2_22 in_walk6_2 in_walk5_2)))
 (let (($x12601 (and c_2_21 in_walk6_2 in_walk5_2)))
 (let (($x12599 (and c_2_20 in_walk6_2 in_walk5_2)))
 (let (($x12597 (and c_2_19 in_walk6_2 in_walk5_2)))
 (let (($x12595 (and c_2_18 in_walk6_2 in_walk5_2)))
 (let (($x12593 (and c_2_17 in_walk6_2 in_walk5_2)))
 (let (($x12591 (and c_2_16 in_walk6_2 in_walk5_2)))
 (let (($x12589 (and c_2_15 in_walk6_2 in_walk5_2)))
 (let (($x12587 (and c_2_14 in_walk6_2 in_walk5_2)))
 (let (($x12585 (and c_2_13 in_walk6_2 in_walk5_2)))
 (let (($x12583 (and c_2_12 in_walk6_2 in_walk5_2)))
 (let (($x12581 (and c_2_11 in_walk6_2 in_walk5_2)))
 (let (($x12579 (and c_2_10 in_walk6_2 in_walk5_2)))
 (let (($x12577 (and c_2_9 in_walk6_2 in_walk5_2)))
 (let (($x12575 (and c_2_8 in_walk6_2 in_walk5_2)))
 (let (($x12573 (and c_2_7 in_walk6_2 in_walk5_2)))
 (let (($x12571 (and c_2_6 in_walk6_2 in_walk5_2)))
 (let (($x12569 (and c_2_5 in_walk6_2 in_walk5_2)))
 (let (($x12567 (and c_2_4 in_walk6_2 in_walk5_2)))
 (let (($x12565 (and c_2_3 in_walk6_2 in_walk5_2)))
 (let (($x12563 (and c_2_2 in_walk6_2 in_walk5_2)))
 (let (($x12561 (and c_2_1 in_walk6_2 in_walk5_2)))
 (let (($x12560 (and c_2_0 in_walk6_2 in_walk5_2)))
 (let (($x12608 (or $x12560 $x12561 $x12563 $x12565 $x12567 $x12569 $x12571 $x12573 $x12575 $x12577 $x12579 $x12581 $x12583 $x12585 $x12587 $x12589 $x12591 $x12593 $x12595 $x12597 $x12599 $x12601 $x12603 $x12605 $x12607)))
 (let (($x12530 (and c_1_24 in_walk6_1 in_walk5_1)))
 (let (($x12528 (and c_1_23 in_walk6_1 in_walk5_1)))
 (let (($x12526 (and c_1_22 in_walk6_1 in_walk5_1)))
 (let (($x12524 (and c_1_21 in_walk6_1 in_walk5_1)))
 (let (($x12522 (and c_1_20 in_walk6_1 in_walk5_1)))
 (let (($x12520 (and c_1_19 in_walk6_1 in_walk5_1)))
 (let (($x12518 (and c_1_18 in_walk6_1 in_walk5_1)))
 (let (($x12516 (and c_1_17 in_walk6_1 in_walk5_1)))
 (let (($x12514 (and c_1_16 in_walk6_1 in_walk5_1)))
 (let (($x12512 (and c_1_15 in_walk6_1 in_walk5_1)))
 (let (($x12510 (and c_1_14 in_walk6_1 in_walk5_1)))
 (let (($x12508 (and c_1_13 in_walk6_1 in_walk5_1)))
 (let (($x12506 (and c_1_12 in_walk6_1 in_walk5_1)))
 (let (($x12504 (and c_1_11 in_walk6_1 in_walk5_1)))
 (let (($x12502 (and c_1_10 in_walk6_1 in_walk5_1)))
 (let (($x12500 (and c_1_9 in_walk6_1 in_walk5_1)))
 (let (($x12498 (and c_1_8 in_walk6_1 in_walk5_1)))
 (let (($x12496 (and c_1_7 in_walk6_1 in_walk5_1)))
 (let (($x12494 (and c_1_6 in_walk6_1 in_walk5_1)))
 (let (($x12492 (and c_1_5 in_walk6_1 in_walk5_1)))
 (let (($x12490 (and c_1_4 in_walk6_1 in_walk5_1)))
 (let (($x12488 (and c_1_3 in_walk6_1 in_walk5_1)))
 (let (($x12486 (and c_1_2 in_walk6_1 in_walk5_1)))
 (let (($x12484 (and c_1_1 in_walk6_1 in_walk5_1)))
 (let (($x12483 (and c_1_0 in_walk6_1 in_walk5_1)))
 (let (($x12531 (or $x12483 $x12484 $x12486 $x12488 $x12490 $x12492 $x12494 $x12496 $x12498 $x12500 $x12502 $x12504 $x12506 $x12508 $x12510 $x12512 $x12514 $x12516 $x12518 $x12520 $x12522 $x12524 $x12526 $x12528 $x12530)))
 (let (($x12453 (and c_0_24 in_walk6_0 in_walk5_0)))
 (let (($x12451 (and c_0_23 in_walk6_0 in_walk5_0)))
 (let (($x12449 (and c_0_22 in_walk6_0 in_walk5_0)))
 (let (($x12447 (and c_0_21 in_walk6_0 in_walk5_0)))
 (let (($x12445 (and c_0_20 in_walk6_0 in_walk5_0)))
 (let (($x12443 (and c_0_19 in_walk6_0 in_walk5_0)))
 (let (($x12441 (and c_0_18 in_walk6_0 in_walk5_0)))
 (let (($x12439 (and c_0_17 in_walk6_0 in_walk5_0)))
 (let (($x12437 (and c_0_16 in_walk6_0 in_walk5_0)))
 (let (($x12435 (and c_0_15 in_walk6_0 in_walk5_0)))
 (let (($x12433 (and c_0_14 in_walk6_0 in_walk5_0)))
 (let (($x12431 (and c_0_13 in_walk6_0 in_walk5_0)))
 (let (($x12429 (and c_0_12 in_walk6_0 in_walk5_0)))
 (let (($x12427 (and c_0_11 in_walk6_0 in_walk5_0)))
 (let (($x12425 (and c_0_10 in_walk6_0 in_walk5_0)))
 (let (($x12423 (and c_0_9 in_walk6_0 in_walk5_0)))
 (let (($x12421 (and c_0_8 in_walk6_0 in_walk5_0)))
 (let (($x12419 (and c_0_7 in_walk6_0 in_walk5_0)))
 (let (($x12417 (and c_0_6 in_walk6_0 in_walk5_0)))
 (let (($x12415 (and c_0_5 in_walk6_0 in_walk5_0)))
 (let (($x12413 (and c_0_4 in_walk6_0 in_walk5_0)))
 (let (($x12411 (and c_0_3 in_walk6_0 in_walk5_0)))
 (let (($x12409 (and c_0_2 in_walk6_0 in_walk5_0)))
 (let (($x12407 (and c_0_1 in_walk6_0 in_walk5_0)))
 (let (($x12406 (and c_0_0 in_walk6_0 in_walk5_0)))
 (let (($x12454 (or $x12406 $x12407 $x12409 $x12411 $x12413 $x12415 $x12417 $x12419 $x12421 $x12423 $x12425 $x12427 $x12429 $x12431 $x12433 $x12435 $x12437 $x12439 $x12441 $x12443 $x12445 $x12447 $x12449 $x12451 $x12453)))
 (let (($x12404 (or false $x12454)))
 (let (($x12481 (or $x12404 $x12531)))
 (let (($x12558 (or $x12481 $x12608)))
 (let (($x12373 (and c_3_24 in_walk8_3 in_walk4_3)))
 (let (($x12371 (and c_3_23 in_walk8_3 in_walk4_3)))
 (let (($x12369 (and c_3_22 in_walk8_3 in_walk4_3)))
 (let (($x12367 (and c_3_21 in_walk8_3 in_walk4_3)))
 (let (($x12365 (and c_3_20 in_walk8_3 in_walk4_3)))
 (let (($x12363 (and c_3_19 in_walk8_3 in_walk4_3)))
 (let (($x12361 (and c_3_18 in_walk8_3 in_walk4_3)))
 (let (($x12359 (and c_3_17 in_walk8_3 in_walk4_3)))
 (let (($x12357 (and c_3_16 in_walk8_3 in_walk4_3)))
 (let (($x12355 (and c_3_15 in_walk8_3 in_walk4_3)))
 (let (($x12353 (and c_3_14 in_walk8_3 in_walk4_3)))
 (let (($x12351 (and c_3_13 in_walk8_3 in_walk4_3)))
 (let (($x12349 (and c_3_12 in_walk8_3 in_walk4_3)))
 (let (($x12347 (and c_3_11 in_walk8_3 in_walk4_3)))
 (let (($x12345 (and c_3_10 in_walk8_3 in_walk4_3)))
 (let (($x12343 (and c_3_9 in_walk8_3 in_walk4_3)))
 (let (($x12341 (and c_3_8 in_walk8_3 in_walk4_3)))
 (let (($x12339 (and c_3_7 in_walk8_3 in_walk4_3)))
 (let (($x12337 (and c_3_6 in_walk8_3 in_walk4_3)))
 (let (($x12335 (and c_3_5 in_walk8_3 in_walk4_3)))
 (let (($x12333 (and c_3_4 in_walk8_3 in_walk4_3)))
 (let (($x12331 (and c_3_3 in_walk8_3 in_walk4_3)))
 (let (($x12329 (and c_3_2 in_walk8_3 in_walk4_3)))
 (let (($x12327 (and c_3_1 in_walk8_3 in_walk4_3)))
 (let (($x12326 (and c_3_0 in_walk8_3 in_walk4_3)))
 (let (($x12374 (or $x12326 $x12327 $x12329 $x12331 $x12333 $x12335 $x12337 $x12339 $x12341 $x12343 $x12345 $x12347 $x12349 $x12351 $x12353 $x12355 $x12357 $x12359 $x12361 $x12363 $x12365 $x12367 $x12369 $x12371 $x12373)))
 (let (($x12296 (and c_2_24 in_walk8_2 in_walk4_2)))
 (let (($x12294 (and c_2_23 in_walk8_2 in_walk4_2)))
 (let (($x12292 (and c_2_22 in_walk8_2 in_walk4_2)))
 (let (($x12290 (and c_2_21 in_walk8_2 in_walk4_2)))
 (let (($x12288 (and c_2_20 in_walk8_2 in_walk4_2)))
 (let (($x12286 (and c_2_19 in_walk8_2 in_walk4_2)))
 (let (($x12284 (and c_2_18 in_walk8_2 in_walk4_2)))
 (let (($x12282 (and c_2_17 in_walk8_2 in_walk4_2)))
 (let (($x12280 (and c_2_16 in_walk8_2 in_walk4_2)))
 (let (($x12278 (and c_2_15 in_walk8_2 in_walk4_2)))
 (let (($x12276 (and c_2_14 in_walk8_2 in_walk4_2)))
 (let (($x12274 (and c_2_13 in_walk8_2 in_walk4_2)))
 (let (($x12272 (and c_2_12 in_walk8_2 in_walk4_2)))
 (let (($x12270 (and c_2_11 in_walk8_2 in_walk4_2)))
 (let (($x12268 (and c_2_10 in_walk8_2 in_walk4_2)))
 (let (($x12266 (and c_2_9 in_walk8_2 in_walk4_2)))
 (let (($x12264 (and c_2_8 in_walk8_2 in_walk4_2)))
 (let (($x12262 (and c_2_7 in_walk8_2 in_walk4_2)))
 (let (($x12260 (and c_2_6 in_walk8_2 in_walk4_2)))
 (let (($x12258 (and c_2_5 in_walk8_2 in_walk4_2)))
 (let (($x12256 (and c_2_4 in_walk8_2 in_walk4_2)))
 (let (($x12254 (and c_2_3 in_walk8_2 in_walk4_2)))
 (let (($x12252 (and c_2_2 in_walk8_2 in_walk4_2)))
 (let (($x12250 (and c_2_1 in_walk8_2 in_walk4_2)))
 (let (($x12249 (and c_2_0 in_walk8_2 in_walk4_2)))
 (let (($x12297 (or $x12249 $x12250 $x12252 $x12254 $x12256 $x12258 $x12260 $x12262 $x12264 $x12266 $x12268 $x12270 $x12272 $x12274 $x12276 $x12278 $x12280 $x12282 $x12284 $x12286 $x12288 $x12290 $x12292 $x12294 $x12296)))
 (let (($x12219 (and c_1_24 in_walk8_1 in_walk4_1)))
 (let (($x12217 (and c_1_23 in_walk8_1 in_walk4_1)))
 (let (($x12215 (and c_1_22 in_walk8_1 in_walk4_1)))
 (let (($x12213 (and c_1_21 in_walk8_1 in_walk4_1)))
 (let (($x12211 (and c_1_20 in_walk8_1 in_walk4_1)))
 (let (($x12209 (and c_1_19 in_walk8_1 in_walk4_1)))
 (let (($x12207 (and c_1_18 in_walk8_1 in_walk4_1)))
 (let (($x12205 (and c_1_17 in_walk8_1 in_walk4_1)))
 (let (($x12203 (and c_1_16 in_walk8_1 in_walk4_1)))
 (let (($x12201 (and c_1_15 in_walk8_1 in_walk4_1)))
 (let (($x12199 (and c_1_14 in_walk8_1 in_walk4_1)))
 (let (($x12197 (and c_1_13 in_walk8_1 in_walk4_1)))
 (let (($x12195 (and c_1_12 in_walk8_1 in_walk4_1)))
 (let (($x12193 (and c_1_11 in_walk8_1 in_walk4_1)))
 (let (($x12191 (and c_1_10 in_walk8_1 in_walk4_1)))
 (let (($x12189 (and c_1_9 in_walk8_1 in_walk4_1)))
 (let (($x12187 (and c_1_8 in_walk8_1 in_walk4_1)))
 (let (($x12185 (and c_1_7 in_walk8_1 in_walk4_1)))
 (let (($x12183 (and c_1_6 in_walk8_1 in_walk4_1)))
 (let (($x12181 (and c_1_5 in_walk8_1 in_walk4_1)))
 (let (($x12179 (and c_1_4 in_walk8_1 in_walk4_1)))
 (let (($x12177 (and c_1_3 in_walk8_1 in_walk4_1)))
 (let (($x12175 (and c_1_2 in_walk8_1 in_walk4_1)))
 (let (($x12173 (and c_1_1 in_walk8_1 in_walk4_1)))
 (let (($x12172 (and c_1_0 in_walk8_1 in_walk4_1)))
 (let (($x12220 (or $x12172 $x12173 $x12175 $x12177 $x12179 $x12181 $x12183 $x12185 $x12187 $x12189 $x12191 $x12193 $x12195 $x12197 $x12199 $x12201 $x12203 $x12205 $x12207 $x12209 $x12211 $x12213 $x12215 $x12217 $x12219)))
 (let (($x12142 (and c_0_24 in_walk8_0 in_walk4_0)))
 (let (($x12140 (and c_0_23 in_walk8_0 in_walk4_0)))
 (let (($x12138 (and c_0_22 in_walk8_0 in_walk4_0)))
 (let (($x12136 (and c_0_21 in_walk8_0 in_walk4_0)))
 (let (($x12134 (and c_0_20 in_walk8_0 in_walk4_0)))
 (let (($x12132 (and c_0_19 in_walk8_0 in_walk4_0)))
 (let (($x12130 (and c_0_18 in_walk8_0 in_walk4_0)))
 (let (($x12128 (and c_0_17 in_walk8_0 in_walk4_0)))
 (let (($x12126 (and c_0_16 in_walk8_0 in_walk4_0)))
 (let (($x12124 (and c_0_15 in_walk8_0 in_walk4_0)))
 (let (($x12122 (and c_0_14 in_walk8_0 in_walk4_0)))
 (let (($x12120 (and c_0_13 in_walk8_0 in_walk4_0)))
 (let (($x12118 (and c_0_12 in_walk8_0 in_walk4_0)))
 (let (($x12116 (and c_0_11 in_walk8_0 in_walk4_0)))
 (let (($x12114 (and c_0_10 in_walk8_0 in_walk4_0)))
 (let (($x12112 (and c_0_9 in_walk8_0 in_walk4_0)))
 (let (($x12110 (and c_0_8 in_walk8_0 in_walk4_0)))
 (let (($x12108 (and c_0_7 in_walk8_0 in_walk4_0)))
 (let (($x12106 (and c_0_6 in_walk8_0 in_walk4_0)))
 (let (($x12104 (and c_0_5 in_walk8_0 in_walk4_0)))
 (let (($x12102 (and c_0_4 in_walk8_0 in_walk4_0)))
 (let (($x12100 (and c_0_3 in_walk8_0 in_walk4_0)))
 (let (($x12098 (and c_0_2 in_walk8_0 in_walk4_0)))
 (let (($x12096 (and c_0_1 in_walk8_0 in_walk4_0)))
 (let (($x12095 (and c_0_0 in_walk8_0 in_walk4_0)))
 (let (($x12143 (or $x12095 $x12096 $x12098 $x12100 $x12102 $x12104 $x12106 $x12108 $x12110 $x12112 $x12114 $x12116 $x12118 $x12120 $x12122 $x12124 $x12126 $x12128 $x12130 $x12132 $x12134 $x12136 $x12138 $x12140 $x12142)))
 (let (($x12093 (or false $x12143)))
 (let (($x12170 (or $x12093 $x12220)))
 (let (($x12247 (or $x12170 $x12297)))
 (let (($x6096 (not (or (or (or (or false c_0_12) c_1_12) c_2_12) c_3_12))))
 (let (($x12062 (and c_3_24 in_walk7_3 in_walk4_3)))
 (let (($x12060 (and c_3_23 in_walk7_3 in_walk4_3)))
 (let (($x12058 (and c_3_22 in_walk7_3 in_walk4_3)))
 (let (($x12056 (and c_3_21 in_walk7_3 in_walk4_3)))
 (let (($x12054 (and c_3_20 in_walk7_3 in_walk4_3)))
 (let (($x12052 (and c_3_19 in_walk7_3 in_walk4_3)))
 (let (($x12050 (and c_3_18 in_walk7_3 in_walk4_3)))
 (let (($x12048 (and c_3_17 in_walk7_3 in_walk4_3)))
 (let (($x12046 (and c_3_16 in_walk7_3 in_walk4_3)))
 (let (($x12044 (and c_3_15 in_walk7_3 in_walk4_3)))
 (let (($x12042 (and c_3_14 in_walk7_3 in_walk4_3)))
 (let (($x12040 (and c_3_13 in_walk7_3 in_walk4_3)))
 (let (($x12038 (and c_3_12 in_walk7_3 in_walk4_3)))
 (let (($x12036 (and c_3_11 in_walk7_3 in_walk4_3)))
 (let (($x12034 (and c_3_10 in_walk7_3 in_walk4_3)))
 (let (($x12032 (and c_3_9 in_walk7_3 in_walk4_3)))
 (let (($x12030 (and c_3_8 in_walk7_3 in_walk4_3)))
 (let (($x12028 (and c_3_7 in_walk7_3 in_walk4_3)))
 (let (($x12026 (and c_3_6 in_walk7_3 in_walk4_3)))
 (let (($x12024 (and c_3_5 in_walk7_3 in_walk4_3)))
 (let (($x12022 (and c_3_4 in_walk7_3 in_walk4_3)))
 (let (($x12020 (and c_3_3 in_walk7_3 in_walk4_3)))
 (let (($x12018 (and c_3_2 in_walk7_3 in_walk4_3)))
 (let (($x12016 (and c_3_1 in_walk7_3 in_walk4_3)))
 (let (($x12015 (and c_3_0 in_walk7_3 in_walk4_3)))
 (let (($x12063 (or $x12015 $x12016 $x12018 $x12020 $x12022 $x12024 $x12026 $x12028 $x12030 $x12032 $x12034 $x12036 $x12038 $x12040 $x12042 $x12044 $x12046 $x12048 $x12050 $x12052 $x12054 $x12056 $x12058 $x12060 $x12062)))
 (let (($x11985 (and c_2_24 in_walk7_2 in_walk4_2)))
 (let (($x11983 (and c_2_23 in_walk7_2 in_walk4_2)))
 (let (($x11981 (and c_2_22 in_walk7_2 in_walk4_2)))
 (let (($x11979 (and c_2_21 in_walk7_2 in_walk4_2)))
 (let (($x11977 (and c_2_20 in_walk7_2 in_walk4_2)))
 (let (($x11975 (and c_2_19 in_walk7_2 in_walk4_2)))
 (let (($x11973 (and c_2_18 in_walk7_2 in_walk4_2)))
 (let (($x11971 (and c_2_17 in_walk7_2 in_walk4_2)))
 (let (($x11969 (and c_2_16 in_walk7_2 in_walk4_2)))
 (let (($x11967 (and c_2_15 in_walk7_2 in_walk4_2)))
 (let (($x11965 (and c_2_14 in_walk7_2 in_walk4_2)))
 (let (($x11963 (and c_2_13 in_walk7_2 in_walk4_2)))
 (let (($x11961 (and c_2_12 in_walk7_2 in_walk4_2)))
 (let (($x11959 (and c_2_11 in_walk7_2 in_walk4_2)))
 (let (($x11957 (and c_2_10 in_walk7_2 in_walk4_2)))
 (let (($x11955 (and c_2_9 in_walk7_2 in_walk4_2)))
 (let (($x11953 (and c_2_8 in_walk7_2 in_walk4_2)))
 (let (($x11951 (and c_2_7 in_walk7_2 in_walk4_2)))
 (let (($x11949 (and c_2_6 in_walk7_2 in_walk4_2)))
 (let (($x11947 (and c_2_5 in_walk7_2 in_walk4_2)))
 (let (($x11945 (and c_2_4 in_walk7_2 in_walk4_2)))
 (let (($x11943 (and c_2_3 in_walk7_2 in_walk4_2)))
 (let (($x11941 (and c_2_2 in_walk7_2 in_walk4_2)))
 (let (($x11939 (and c_2_1 in_walk7_2 in_walk4_2)))
 (let (($x11938 (and c_2_0 in_walk7_2 in_walk4_2)))
 (let (($x11986 (or $x11938 $x11939 $x11941 $x11943 $x11945 $x11947 $x11949 $x11951 $x11953 $x11955 $x11957 $x11959 $x11961 $x11963 $x11965 $x11967 $x11969 $x11971 $x11973 $x11975 $x11977 $x11979 $x11981 $x11983 $x11985)))
 (let (($x11908 (and c_1_24 in_walk7_1 in_walk4_1)))
 (let (($x11906 (and c_1_23 in_walk7_1 in_walk4_1)))
 (let (($x11904 (and c_1_22 in_walk7_1 in_walk4_1)))
 (let (($x11902 (and c_1_21 in_walk7_1 in_walk4_1)))
 (let (($x11900 (and c_1_20 in_walk7_1 in_walk4_1)))
 (let (($x11898 (and c_1_19 in_walk7_1 in_walk4_1)))
 (let (($x11896 (and c_1_18 in_walk7_1 in_walk4_1)))
 (let (($x11894 (and c_1_17 in_walk7_1 in_walk4_1)))
 (let (($x11892 (and c_1_16 in_walk7_1 in_walk4_1)))
 (let (($x11890 (and c_1_15 in_walk7_1 in_walk4_1)))
 (let (($x11888 (and c_1_14 in_walk7_1 in_walk4_1)))
 (let (($x11886 (and c_1_13 in_walk7_1 in_walk4_1)))
 (let (($x11884 (and c_1_12 in_walk7_1 in_walk4_1)))
 (let (($x11882 (and c_1_11 in_walk7_1 in_walk4_1)))
 (let (($x11880 (and c_1_10 in_walk7_1 in_walk4_1)))
 (let (($x11878 (and c_1_9 in_walk7_1 in_walk4_1)))
 (let (($x11876 (and c_1_8 in_walk7_1 in_walk4_1)))
 (let (($x11874 (and c_1_7 in_walk7_1 in_walk4_1)))
 (let (($x11872 (and c_1_6 in_walk7_1 in_walk4_1)))
 (let (($x11870 (and c_1_5 in_walk7_1 in_walk4_1)))
 (let (($x11868 (and c_1_4 in_walk7_1 in_walk4_1)))
 (let (($x11866 (and c_1_3 in_walk7_1 in_walk4_1)))
 (let (($x11864 (and c_1_2 in_walk7_1 in_walk4_1)))
 (let (($x11862 (and c_1_1 in_walk7_1 in_walk4_1)))
 (let (($x11861 (and c_1_0 in_walk7_1 in_walk4_1)))
 (let (($x11909 (or $x11861 $x11862 $x11864 $x11866 $x11868 $x11870 $x11872 $x11874 $x11876 $x11878 $x11880 $x11882 $x11884 $x11886 $x11888 $x11890 $x11892 $x11894 $x11896 $x11898 $x11900 $x11902 $x11904 $x11906 $x11908)))
 (let (($x11831 (and c_0_24 in_walk7_0 in_walk4_0)))
 (let (($x11829 (and c_0_23 in_walk7_0 in_walk4_0)))
 (let (($x11827 (and c_0_22 in_walk7_0 in_walk4_0)))
 (let (($x11825 (and c_0_21 in_walk7_0 in_walk4_0)))
 (let (($x11823 (and c_0_20 in_walk7_0 in_walk4_0)))
 (let (($x11821 (and c_0_19 in_walk7_0 in_walk4_0)))
 (let (($x11819 (and c_0_18 in_walk7_0 in_walk4_0)))
 (let (($x11817 (and c_0_17 in_walk7_0 in_walk4_0)))
 (let (($x11815 (and c_0_16 in_walk7_0 in_walk4_0)))
 (let (($x11813 (and c_0_15 in_walk7_0 in_walk4_0)))
 (let (($x11811 (and c_0_14 in_walk7_0 in_walk4_0)))
 (let (($x11809 (and c_0_13 in_walk7_0 in_walk4_0)))
 (let (($x11807 (and c_0_12 in_walk7_0 in_walk4_0)))
 (let (($x11805 (and c_0_11 in_walk7_0 in_walk4_0)))
 (let (($x11803 (and c_0_10 in_walk7_0 in_walk4_0)))
 (let (($x11801 (and c_0_9 in_walk7_0 in_walk4_0)))
 (let (($x11799 (and c_0_8 in_walk7_0 in_walk4_0)))
 (let (($x11797 (and c_0_7 in_walk7_0 in_walk4_0)))
 (let (($x11795 (and c_0_6 in_walk7_0 in_walk4_0)))
 (let (($x11793 (and c_0_5 in_walk7_0 in_walk4_0)))
 (let (($x11791 (and c_0_4 in_walk7_0 in_walk4_0)))
 (let (($x11789 (and c_0_3 in_walk7_0 in_walk4_0)))
 (let (($x11787 (and c_0_2 in_walk7_0 in_walk4_0)))
 (let (($x11785 (and c_0_1 in_walk7_0 in_walk4_0)))
 (let (($x11784 (and c_0_0 in_walk7_0 in_walk4_0)))
 (let (($x11832 (or $x11784 $x11785 $x11787 $x11789 $x11791 $x11793 $x11795 $x11797 $x11799 $x11801 $x11803 $x11805 $x11807 $x11809 $x11811 $x11813 $x11815 $x11817 $x11819 $x11821 $x11823 $x11825 $x11827 $x11829 $x11831)))
 (let (($x11782 (or false $x11832)))
 (let (($x11859 (or $x11782 $x11909)))
 (let (($x11936 (or $x11859 $x11986)))
 (let (($x11751 (and c_3_24 in_walk6_3 in_walk4_3)))
 (let (($x11749 (and c_3_23 in_walk6_3 in_walk4_3)))
 (let (($x11747 (and c_3_22 in_walk6_3 in_walk4_3)))
 (let (($x11745 (and c_3_21 in_walk6_3 in_walk4_3)))
 (let (($x11743 (and c_3_20 in_walk6_3 in_walk4_3)))
 (let (($x11741 (and c_3_19 in_walk6_3 in_walk4_3)))
 (let (($x11739 (and c_3_18 in_walk6_3 in_walk4_3)))
 (let (($x11737 (and c_3_17 in_walk6_3 in_walk4_3)))
 (let (($x11735 (and c_3_16 in_walk6_3 in_walk4_3)))
 (let (($x11733 (and c_3_15 in_walk6_3 in_walk4_3)))
 (let (($x11731 (and c_3_14 in_walk6_3 in_walk4_3)))
 (let (($x11729 (and c_3_13 in_walk6_3 in_walk4_3)))
 (let (($x11727 (and c_3_12 in_walk6_3 in_walk4_3)))
 (let (($x11725 (and c_3_11 in_walk6_3 in_walk4_3)))
 (let (($x11723 (and c_3_10 in_walk6_3 in_walk4_3)))
 (let (($x11721 (and c_3_9 in_walk6_3 in_walk4_3)))
 (let (($x11719 (and c_3_8 in_walk6_3 in_walk4_3)))
 (let (($x11717 (and c_3_7 in_walk6_3 in_walk4_3)))
 (let (($x11715 (and c_3_6 in_walk6_3 in_walk4_3)))
 (let (($x11713 (and c_3_5 in_walk6_3 in_walk4_3)))
 (let (($x11711 (and c_3_4 in_walk6_3 in_walk4_3)))
 (let (($x11709 (and c_3_3 in_walk6_3 in_walk4_3)))
 (let (($x11707 (and c_3_2 in_walk6_3 in_walk4_3)))
 (let (($x11705 (and c_3_1 in_walk6_3 in_walk4_3)))
 (let (($x11704 (and c_3_0 in_walk6_3 in_walk4_3)))
 (let (($x11752 (or $x11704 $x11705 $x11707 $x11709 $x11711 $x11713 $x11715 $x11717 $x11719 $x11721 $x11723 $x11725 $x11727 $x11729 $x11731 $x11733 $x11735 $x11737 $x11739 $x11741 $x11743 $x11745 $x11747 $x11749 $x11751)))
 (let (($x11674 (and c_2_24 in_walk6_2 in_walk4_2)))
 (let (($x11672 (and c_2_23 in_walk6_2 in_walk4_2)))
 (let (($x11670 (and c_2_22 in_walk6_2 in_walk4_2)))
 (let (($x11668 (and c_2_21 in_walk6_2 in_walk4_2)))
 (let (($x11666 (and c_2_20 in_walk6_2 in_walk4_2)))
 (let (($x11664 (and c_2_19 in_walk6_2 in_walk4_2)))
 (let (($x11662 (and c_2_18 in_walk6_2 in_walk4_2)))
 (let (($x11660 (and c_2_17 in_walk6_2 in_walk4_2)))
 (let (($x11658 (and c_2_16 in_walk6_2 in_walk4_2)))
 (let (($x11656 (and c_2_15 in_walk6_2 in_walk4_2)))
 (let (($x11654 (and c_2_14 in_walk6_2 in_walk4_2)))
 (let (($x11652 (and c_2_13 in_walk6_2 in_walk4_2)))
 (let (($x11650 (and c_2_12 in_walk6_2 in_walk4_2)))
 (let (($x11648 (and c_2_11 in_walk6_2 in_walk4_2)))
 (let (($x11646 (and c_2_10 in_walk6_2 in_walk4_2)))
 (let (($x11644 (and c_2_9 in_walk6_2 in_walk4_2)))
 (let (($x11642 (and c_2_8 in_walk6_2 in_walk4_2)))
 (let (($x11640 (and c_2_7 in_walk6_2 in_walk4_2)))
 (let (($x11638 (and c_2_6 in_walk6_2 in_walk4_2)))
 (let (($x11636 (and c_2_5 in_walk6_2 in_walk4_2)))
 (let (($x11634 (and c_2_4 in_walk6_2 in_walk4_2)))
 (let (($x11632 (and c_2_3 in_walk6_2 in_walk4_2)))
 (let (($x11630 (and c_2_2 in_walk6_2 in_walk4_2)))
 (let (($x11628 (and c_2_1 in_walk6_2 in_walk4_2)))
 (let (($x11627 (and c_2_0 in_walk6_2 in_walk4_2)))
 (let (($x11675 (or $x11627 $x11628 $x11630 $x11632 $x11634 $x11636 $x11638 $x11640 $x11642 $x11644 $x11646 $x11648 $x11650 $x11652 $x11654 $x11656 $x11658 $x11660 $x11662 $x11664 $x11666 $x11668 $x11670 $x11672 $x11674)))
 (let (($x11597 (and c_1_24 in_walk6_1 in_walk4_1)))
 (let (($x11595 (and c_1_23 in_walk6_1 in_walk4_1)))
 (let (($x11593 (and c_1_22 in_walk6_1 in_walk4_1)))
 (let (($x11591 (and c_1_21 in_walk6_1 in_walk4_1)))
 (let (($x11589 (and c_1_20 in_walk6_1 in_walk4_1)))
 (let (($x11587 (and c_1_19 in_walk6_1 in_walk4_1)))
 (let (($x11585 (and c_1_18 in_walk6_1 in_walk4_1)))
 (let (($x11583 (and c_1_17 in_walk6_1 in_walk4_1)))
 (let (($x11581 (and c_1_16 in_walk6_1 in_walk4_1)))
 (let (($x11579 (and c_1_15 in_walk6_1 in_walk4_1)))
 (let (($x11577 (and c_1_14 in_walk6_1 in_walk4_1)))
 (let (($x11575 (and c_1_13 in_walk6_1 in_walk4_1)))
 (let (($x11573 (and c_1_12 in_walk6_1 in_walk4_1)))
 (let (($x11571 (and c_1_11 in_walk6_1 in_walk4_1)))
 (let (($x11569 (and c_1_10 in_walk6_1 in_walk4_1)))
 (let (($x11567 (and c_1_9 in_walk6_1 in_walk4_1)))
 (let (($x11565 (and c_1_8 in_walk6_1 in_walk4_1)))
 (let (($x11563 (and c_1_7 in_walk6_1 in_walk4_1)))
 (let (($x11561 (and c_1_6 in_walk6_1 in_walk4_1)))
 (let (($x11559 (and c_1_5 in_walk6_1 in_walk4_1)))
 (let (($x11557 (and c_1_4 in_walk6_1 in_walk4_1)))
 (let (($x11555 (and c_1_3 in_walk6_1 in_walk4_1)))
 (let (($x11553 (and c_1_2 in_walk6_1 in_walk4_1)))
 (let (($x11551 (and c_1_1 in_walk6_1 in_walk4_1)))
 (let (($x11550 (and c_1_0 in_walk6_1 in_walk4_1)))
 (let (($x11598 (or $x11550 $x11551 $x11553 $x11555 $x11557 $x11559 $x11561 $x11563 $x11565 $x11567 $x11569 $x11571 $x11573 $x11575 $x11577 $x11579 $x11581 $x11583 $x11585 $x11587 $x11589 $x11591 $x11593 $x11595 $x11597)))
 (let (($x11520 (and c_0_24 in_walk6_0 in_walk4_0)))
 (let (($x11518 (and c_0_23 in_walk6_0 in_walk4_0)))
 (let (($x11516 (and c_0_22 in_walk6_0 in_walk4_0)))
 (let (($x11514 (and c_0_21 in_walk6_0 in_walk4_0)))
 (let (($x11512 (and c_0_20 in_walk6_0 in_walk4_0)))
 (let (($x11510 (and c_0_19 in_walk6_0 in_walk4_0)))
 (let (($x11508 (and c_0_18 in_walk6_0 in_walk4_0)))
 (let (($x11506 (and c_0_17 in_walk6_0 in_walk4_0)))
 (let (($x11504 (and c_0_16 in_walk6_0 in_walk4_0)))
 (let (($x11502 (and c_0_15 in_walk6_0 in_walk4_0)))
 (let (($x11500 (and c_0_14 in_walk6_0 in_walk4_0)))
 (let (($x11498 (and c_0_13 in_walk6_0 in_walk4_0)))
 (let (($x11496 (and c_0_12 in_walk6_0 in_walk4_0)))
 (let (($x11494 (and c_0_11 in_walk6_0 in_walk4_0)))
 (let (($x11492 (and c_0_10 in_walk6_0 in_walk4_0)))
 (let (($x11490 (and c_0_9 in_walk6_0 in_walk4_0)))
 (let (($x11488 (and c_0_8 in_walk6_0 in_walk4_0)))
 (let (($x11486 (and c_0_7 in_walk6_0 in_walk4_0)))
 (let (($x11484 (and c_0_6 in_walk6_0 in_walk4_0)))
 (let (($x11482 (and c_0_5 in_walk6_0 in_walk4_0)))
 (let (($x11480 (and c_0_4 in_walk6_0 in_walk4_0)))
 (let (($x11478 (and c_0_3 in_walk6_0 in_walk4_0)))
 (let (($x11476 (and c_0_2 in_walk6_0 in_walk4_0)))
 (let (($x11474 (and c_0_1 in_walk6_0 in_walk4_0)))
 (let (($x11473 (and c_0_0 in_walk6_0 in_walk4_0)))
 (let (($x11521 (or $x11473 $x11474 $x11476 $x11478 $x11480 $x11482 $x11484 $x11486 $x11488 $x11490 $x11492 $x11494 $x11496 $x11498 $x11500 $x11502 $x11504 $x11506 $x11508 $x11510 $x11512 $x11514 $x11516 $x11518 $x11520)))
 (let (($x11471 (or false $x11521)))
 (let (($x11548 (or $x11471 $x11598)))
 (let (($x11625 (or $x11548 $x11675)))
 (let (($x11440 (and c_3_24 in_walk5_3 in_walk4_3)))
 (let (($x11438 (and c_3_23 in_walk5_3 in_walk4_3)))
 (let (($x11436 (and c_3_22 in_walk5_3 in_walk4_3)))
 (let (($x11434 (and c_3_21 in_walk5_3 in_walk4_3)))
 (let (($x11432 (and c_3_20 in_walk5_3 in_walk4_3)))
 (let (($x11430 (and c_3_19 in_walk5_3 in_walk4_3)))
 (let (($x11428 (and c_3_18 in_walk5_3 in_walk4_3)))
 (let (($x11426 (and c_3_17 in_walk5_3 in_walk4_3)))
 (let (($x11424 (and c_3_16 in_walk5_3 in_walk4_3)))
 (let (($x11422 (and c_3_15 in_walk5_3 in_walk4_3)))
 (let (($x11420 (and c_3_14 in_walk5_3 in_walk4_3)))
 (let (($x11418 (and c_3_13 in_walk5_3 in_walk4_3)))
 (let (($x11416 (and c_3_12 in_walk5_3 in_walk4_3)))
 (let (($x11414 (and c_3_11 in_walk5_3 in_walk4_3)))
 (let (($x11412 (and c_3_10 in_walk5_3 in_walk4_3)))
 (let (($x11410 (and c_3_9 in_walk5_3 in_walk4_3)))
 (let (($x11408 (and c_3_8 in_walk5_3 in_walk4_3)))
 (let (($x11406 (and c_3_7 in_walk5_3 in_walk4_3)))
 (let (($x11404 (and c_3_6 in_walk5_3 in_walk4_3)))
 (let (($x11402 (and c_3_5 in_walk5_3 in_walk4_3)))
 (let (($x11400 (and c_3_4 in_walk5_3 in_walk4_3)))
 (let (($x11398 (and c_3_3 in_walk5_3 in_walk4_3)))
 (let (($x11396 (and c_3_2 in_walk5_3 in_walk4_3)))
 (let (($x11394 (and c_3_1 in_walk5_3 in_walk4_3)))
 (let (($x11393 (and c_3_0 in_walk5_3 in_walk4_3)))
 (let (($x11441 (or $x11393 $x11394 $x11396 $x11398 $x11400 $x11402 $x11404 $x11406 $x11408 $x11410 $x11412 $x11414 $x11416 $x11418 $x11420 $x11422 $x11424 $x11426 $x11428 $x11430 $x11432 $x11434 $x11436 $x11438 $x11440)))
 (let (($x11363 (and c_2_24 in_walk5_2 in_walk4_2)))
 (let (($x11361 (and c_2_23 in_walk5_2 in_walk4_2)))
 (let (($x11359 (and c_2_22 in_walk5_2 in_walk4_2)))
 (let (($x11357 (and c_2_21 in_walk5_2 in_walk4_2)))
 (let (($x11355 (and c_2_20 in_walk5_2 in_walk4_2)))
 (let (($x11353 (and c_2_19 in_walk5_2 in_walk4_2)))
 (let (($x11351 (and c_2_18 in_walk5_2 in_walk4_2)))
 (let (($x11349 (and c_2_17 in_walk5_2 in_walk4_2)))
 (let (($x11347 (and c_2_16 in_walk5_2 in_walk4_2)))
 (let (($x11345 (and c_2_15 in_walk5_2 in_walk4_2)))
 (let (($x11343 (and c_2_14 in_walk5_2 in_walk4_2)))
 (let (($x11341 (and c_2_13 in_walk5_2 in_walk4_2)))
 (let (($x11339 (and c_2_12 in_walk5_2 in_walk4_2)))
 (let (($x11337 (and c_2_11 in_walk5_2 in_walk4_2)))
 (let (($x11335 (and c_2_10 in_walk5_2 in_walk4_2)))
 (let (($x11333 (and c_2_9 in_walk5_2 in_walk4_2)))
 (let (($x11331 (and c_2_8 in_walk5_2 in_walk4_2)))
 (let (($x11329 (and c_2_7 in_walk5_2 in_walk4_2)))
 (let (($x11327 (and c_2_6 in_walk5_2 in_walk4_2)))
 (let (($x11325 (and c_2_5 in_walk5_2 in_walk4_2)))
 (let (($x11323 (and c_2_4 in_walk5_2 in_walk4_2)))
 (let (($x11321 (and c_2_3 in_walk5_2 in_walk4_2)))
 (let (($x11319 (and c_2_2 in_walk5_2 in_walk4_2)))
 (let (($x11317 (and c_2_1 in_walk5_2 in_walk4_2)))
 (let (($x11316 (and c_2_0 in_walk5_2 in_walk4_2)))
 (let (($x11364 (or $x11316 $x11317 $x11319 $x11321 $x11323 $x11325 $x11327 $x11329 $x11331 $x11333 $x11335 $x11337 $x11339 $x11341 $x11343 $x11345 $x11347 $x11349 $x11351 $x11353 $x11355 $x11357 $x11359 $x11361 $x11363)))
 (let (($x11286 (and c_1_24 in_walk5_1 in_walk4_1)))
 (let (($x11284 (and c_1_23 in_walk5_1 in_walk4_1)))
 (let (($x11282 (and c_1_22 in_walk5_1 in_walk4_1)))
 (let (($x11280 (and c_1_21 in_walk5_1 in_walk4_1)))
 (let (($x11278 (and c_1_20 in_walk5_1 in_walk4_1)))
 (let (($x11276 (and c_1_19 in_walk5_1 in_walk4_1)))
 (let (($x11274 (and c_1_18 in_walk5_1 in_walk4_1)))
 (let (($x11272 (and c_1_17 in_walk5_1 in_walk4_1)))
 (let (($x11270 (and c_1_16 in_walk5_1 in_walk4_1)))
 (let (($x11268 (and c_1_15 in_walk5_1 in_walk4_1)))
 (let (($x11266 (and c_1_14 in_walk5_1 in_walk4_1)))
 (let (($x11264 (and c_1_13 in_walk5_1 in_walk4_1)))
 (let (($x11262 (and c_1_12 in_walk5_1 in_walk4_1)))
 (let (($x11260 (and c_1_11 in_walk5_1 in_walk4_1)))
 (let (($x11258 (and c_1_10 in_walk5_1 in_walk4_1)))
 (let (($x11256 (and c_1_9 in_walk5_1 in_walk4_1)))
 (let (($x11254 (and c_1_8 in_walk5_1 in_walk4_1)))
 (let (($x11252 (and c_1_7 in_walk5_1 in_walk4_1)))
 (let (($x11250 (and c_1_6 in_walk5_1 in_walk4_1)))
 (let (($x11248 (and c_1_5 in_walk5_1 in_walk4_1)))
 (let (($x11246 (and c_1_4 in_walk5_1 in_walk4_1)))
 (let (($x11244 (and c_1_3 in_walk5_1 in_walk4_1)))
 (let (($x11242 (and c_1_2 in_walk5_1 in_walk4_1)))
 (let (($x11240 (and c_1_1 in_walk5_1 in_walk4_1)))
 (let (($x11239 (and c_1_0 in_walk5_1 in_walk4_1)))
 (let (($x11287 (or $x11239 $x11240 $x11242 $x11244 $x11246 $x11248 $x11250 $x11252 $x11254 $x11256 $x11258 $x11260 $x11262 $x11264 $x11266 $x11268 $x11270 $x11272 $x11274 $x11276 $x11278 $x11280 $x11282 $x11284 $x11286)))
 (let (($x11209 (and c_0_24 in_walk5_0 in_walk4_0)))
 (let (($x11207 (and c_0_23 in_walk5_0 in_walk4_0)))
 (let (($x11205 (and c_0_22 in_walk5_0 in_walk4_0)))
 (let (($x11203 (and c_0_21 in_walk5_0 in_walk4_0)))
 (let (($x11201 (and c_0_20 in_walk5_0 in_walk4_0)))
 (let (($x11199 (and c_0_19 in_walk5_0 in_walk4_0)))
 (let (($x11197 (and c_0_18 in_walk5_0 in_walk4_0)))
 (let (($x11195 (and c_0_17 in_walk5_0 in_walk4_0)))
 (let (($x11193 (and c_0_16 in_walk5_0 in_walk4_0)))
 (let (($x11191 (and c_0_15 in_walk5_0 in_walk4_0)))
 (let (($x11189 (and c_0_14 in_walk5_0 in_walk4_0)))
 (let (($x11187 (and c_0_13 in_walk5_0 in_walk4_0)))
 (let (($x11185 (and c_0_12 in_walk5_0 in_walk4_0)))
 (let (($x11183 (and c_0_11 in_walk5_0 in_walk4_0)))
 (let (($x11181 (and c_0_10 in_walk5_0 in_walk4_0)))
 (let (($x11179 (and c_0_9 in_walk5_0 in_walk4_0)))
 (let (($x11177 (and c_0_8 in_walk5_0 in_walk4_0)))
 (let (($x11175 (and c_0_7 in_walk5_0 in_walk4_0)))
 (let (($x11173 (and c_0_6 in_walk5_0 in_walk4_0)))
 (let (($x11171 (and c_0_5 in_walk5_0 in_walk4_0)))
 (let (($x11169 (and c_0_4 in_walk5_0 in_walk4_0)))
 (let (($x11167 (and c_0_3 in_walk5_0 in_walk4_0)))
 (let (($x11165 (and c_0_2 in_walk5_0 in_walk4_0)))
 (let (($x11163 (and c_0_1 in_walk5_0 in_walk4_0)))
 (let (($x11162 (and c_0_0 in_walk5_0 in_walk4_0)))
 (let (($x11210 (or $x11162 $x11163 $x11165 $x11167 $x11169 $x11171 $x11173 $x11175 $x11177 $x11179 $x11181 $x11183 $x11185 $x11187 $x11189 $x11191 $x11193 $x11195 $x11197 $x11199 $x11201 $x11203 $x11205 $x11207 $x11209)))
 (let (($x11160 (or false $x11210)))
 (let (($x11237 (or $x11160 $x11287)))
 (let (($x11314 (or $x11237 $x11364)))
 (let (($x11129 (and c_3_24 in_walk8_3 in_walk3_3)))
 (let (($x11127 (and c_3_23 in_walk8_3 in_walk3_3)))
 (let (($x11125 (and c_3_22 in_walk8_3 in_walk3_3)))
 (let (($x11123 (and c_3_21 in_walk8_3 in_walk3_3)))
 (let (($x11121 (and c_3_20 in_walk8_3 in_walk3_3)))
 (let (($x11119 (and c_3_19 in_walk8_3 in_walk3_3)))
 (let (($x11117 (and c_3_18 in_walk8_3 in_walk3_3)))
 (let (($x11115 (and c_3_17 in_walk8_3 in_walk3_3)))
 (let (($x11113 (and c_3_16 in_walk8_3 in_walk3_3)))
 (let (($x11111 (and c_3_15 in_walk8_3 in_walk3_3)))
 (let (($x11109 (and c_3_14 in_walk8_3 in_walk3_3)))
 (let (($x11107 (and c_3_13 in_walk8_3 in_walk3_3)))
 (let (($x11105 (and c_3_12 in_walk8_3 in_walk3_3)))
 (let (($x11103 (and c_3_11 in_walk8_3 in_walk3_3)))
 (let (($x11101 (and c_3_10 in_walk8_3 in_walk3_3)))
 (let (($x11099 (and c_3_9 in_walk8_3 in_walk3_3)))
 (let (($x11097 (and c_3_8 in_walk8_3 in_walk3_3)))
 (let (($x11095 (and c_3_7 in_walk8_3 in_walk3_3)))
 (let (($x11093 (and c_3_6 in_walk8_3 in_walk3_3)))
 (let (($x11091 (and c_3_5 in_walk8_3 in_walk3_3)))
 (let (($x11089 (and c_3_4 in_walk8_3 in_walk3_3)))
 (let (($x11087 (and c_3_3 in_walk8_3 in_walk3_3)))
 (let (($x11085 (and c_3_2 in_walk8_3 in_walk3_3)))
 (let (($x11083 (and c_3_1 in_walk8_3 in_walk3_3)))
 (let (($x11082 (and c_3_0 in_walk8_3 in_walk3_3)))
 (let (($x11130 (or $x11082 $x11083 $x11085 $x11087 $x11089 $x11091 $x11093 $x11095 $x11097 $x11099 $x11101 $x11103 $x11105 $x11107 $x11109 $x11111 $x11113 $x11115 $x11117 $x11119 $x11121 $x11123 $x11125 $x11127 $x11129)))
 (let (($x11052 (and c_2_24 in_walk8_2 in_walk3_2)))
 (let (($x11050 (and c_2_23 in_walk8_2 in_walk3_2)))
 (let (($x11048 (and c_2_22 in_walk8_2 in_walk3_2)))
 (let (($x11046 (and c_2_21 in_walk8_2 in_walk3_2)))
 (let (($x11044 (and c_2_20 in_walk8_2 in_walk3_2)))
 (let (($x11042 (and c_2_19 in_walk8_2 in_walk3_2)))
 (let (($x11040 (and c_2_18 in_walk8_2 in_walk3_2)))
 (let (($x11038 (and c_2_17 in_walk8_2 in_walk3_2)))
 (let (($x11036 (and c_2_16 in_walk8_2 in_walk3_2)))
 (let (($x11034 (and c_2_15 in_walk8_2 in_walk3_2)))
 (let (($x11032 (and c_2_14 in_walk8_2 in_walk3_2)))
 (let (($x11030 (and c_2_13 in_walk8_2 in_walk3_2)))
 (let (($x11028 (and c_2_12 in_walk8_2 in_walk3_2)))
 (let (($x11026 (and c_2_11 in_walk8_2 in_walk3_2)))
 (let (($x11024 (and c_2_10 in_walk8_2 in_walk3_2)))
 (let (($x11022 (and c_2_9 in_walk8_2 in_walk3_2)))
 (let (($x11020 (and c_2_8 in_walk8_2 in_walk3_2)))
 (let (($x11018 (and c_2_7 in_walk8_2 in_walk3_2)))
 (let (($x11016 (and c_2_6 in_walk8_2 in_walk3_2)))
 (let (($x11014 (and c_2_5 in_walk8_2 in_walk3_2)))
 (let (($x11012 (and c_2_4 in_walk8_2 in_walk3_2)))
 (let (($x11010 (and c_2_3 in_walk8_2 in_walk3_2)))
 (let (($x11008 (and c_2_2 in_walk8_2 in_walk3_2)))
 (let (($x11006 (and c_2_1 in_walk8_2 in_walk3_2)))
 (let (($x11005 (and c_2_0 in_walk8_2 in_walk3_2)))
 (let (($x11053 (or $x11005 $x11006 $x11008 $x11010 $x11012 $x11014 $x11016 $x11018 $x11020 $x11022 $x11024 $x11026 $x11028 $x11030 $x11032 $x11034 $x11036 $x11038 $x11040 $x11042 $x11044 $x11046 $x11048 $x11050 $x11052)))
 (let (($x10975 (and c_1_24 in_walk8_1 in_walk3_1)))
 (let (($x10973 (and c_1_23 in_walk8_1 in_walk3_1)))
 (let (($x10971 (and c_1_22 in_walk8_1 in_walk3_1)))
 (let (($x10969 (and c_1_21 in_walk8_1 in_walk3_1)))
 (let (($x10967 (and c_1_20 in_walk8_1 in_walk3_1)))
 (let (($x10965 (and c_1_19 in_walk8_1 in_walk3_1)))
 (let (($x10963 (and c_1_18 in_walk8_1 in_walk3_1)))
 (let (($x10961 (and c_1_17 in_walk8_1 in_walk3_1)))
 (let (($x10959 (and c_1_16 in_walk8_1 in_walk3_1)))
 (let (($x10957 (and c_1_15 in_walk8_1 in_walk3_1)))
 (let (($x10955 (and c_1_14 in_walk8_1 in_walk3_1)))
 (let (($x10953 (and c_1_13 in_walk8_1 in_walk3_1)))
 (let (($x10951 (and c_1_12 in_walk8_1 in_walk3_1)))
 (let (($x10949 (and c_1_11 in_walk8_1 in_walk3_1)))
 (let (($x10947 (and c_1_10 in_walk8_1 in_walk3_1)))
 (let (($x10945 (and c_1_9 in_walk8_1 in_walk3_1)))
 (let (($x10943 (and c_1_8 in_walk8_1 in_walk3_1)))
 (let (($x10941 (and c_1_7 in_walk8_1 in_walk3_1)))
 (let (($x10939 (and c_1_6 in_walk8_1 in_walk3_1)))
 (let (($x10937 (and c_1_5 in_walk8_1 in_walk3_1)))
 (let (($x10935 (and c_1_4 in_walk8_1 in_walk3_1)))
 (let (($x10933 (and c_1_3 in_walk8_1 in_walk3_1)))
 (let (($x10931 (and c_1_2 in_walk8_1 in_walk3_1)))
 (let (($x10929 (and c_1_1 in_walk8_1 in_walk3_1)))
 (let (($x10928 (and c_1_0 in_walk8_1 in_walk3_1)))
 (let (($x10976 (or $x10928 $x10929 $x10931 $x10933 $x10935 $x10937 $x10939 $x10941 $x10943 $x10945 $x10947 $x10949 $x10951 $x10953 $x10955 $x10957 $x10959 $x10961 $x10963 $x10965 $x10967 $x10969 $x10971 $x10973 $x10975)))
 (let (($x10898 (and c_0_24 in_walk8_0 in_walk3_0)))
 (let (($x10896 (and c_0_23 in_walk8_0 in_walk3_0)))
 (let (($x10894 (and c_0_22 in_walk8_0 in_walk3_0)))
 (let (($x10892 (and c_0_21 in_walk8_0 in_walk3_0)))
 (let (($x10890 (and c_0_20 in_walk8_0 in_walk3_0)))
 (let (($x10888 (and c_0_19 in_walk8_0 in_walk3_0)))
 (let (($x10886 (and c_0_18 in_walk8_0 in_walk3_0)))
 (let (($x10884 (and c_0_17 in_walk8_0 in_walk3_0)))
 (let (($x10882 (and c_0_16 in_walk8_0 in_walk3_0)))
 (let (($x10880 (and c_0_15 in_walk8_0 in_walk3_0)))
 (let (($x10878 (and c_0_14 in_walk8_0 in_walk3_0)))
 (let (($x10876 (and c_0_13 in_walk8_0 in_walk3_0)))
 (let (($x10874 (and c_0_12 in_walk8_0 in_walk3_0)))
 (let (($x10872 (and c_0_11 in_walk8_0 in_walk3_0)))
 (let (($x10870 (and c_0_10 in_walk8_0 in_walk3_0)))
 (let (($x10868 (and c_0_9 in_walk8_0 in_walk3_0)))
 (let (($x10866 (and c_0_8 in_walk8_0 in_walk3_0)))
 (let (($x10864 (and c_0_7 in_walk8_0 in_walk3_0)))
 (let (($x10862 (and c_0_6 in_walk8_0 in_walk3_0)))
 (let (($x10860 (and c_0_5 in_walk8_0 in_walk3_0)))
 (let (($x10858 (and c_0_4 in_walk8_0 in_walk3_0)))
 (let (($x10856 (and c_0_3 in_walk8_0 in_walk3_0)))
 (let (($x10854 (and c_0_2 in_walk8_0 in_walk3_0)))
 (let (($x10852 (and c_0_1 in_walk8_0 in_walk3_0)))
 (let (($x10851 (and c_0_0 in_walk8_0 in_walk3_0)))
 (let (($x10899 (or $x10851 $x10852 $x10854 $x10856 $x10858 $x10860 $x10862 $x10864 $x10866 $x10868 $x10870 $x10872 $x10874 $x10876 $x10878 $x10880 $x10882 $x10884 $x10886 $x10888 $x10890 $x10892 $x10894 $x10896 $x10898)))
 (let (($x10849 (or false $x10899)))
 (let (($x10926 (or $x10849 $x10976)))
 (let (($x11003 (or $x10926 $x11053)))
 (let (($x5777 (not (or (or (or (or false c_0_11) c_1_11) c_2_11) c_3_11))))
 (let (($x10818 (and c_3_24 in_walk7_3 in_walk3_3)))
 (let (($x10816 (and c_3_23 in_walk7_3 in_walk3_3)))
 (let (($x10814 (and c_3_22 in_walk7_3 in_walk3_3)))
 (let (($x10812 (and c_3_21 in_walk7_3 in_walk3_3)))
 (let (($x10810 (and c_3_20 in_walk7_3 in_walk3_3)))
 (let (($x10808 (and c_3_19 in_walk7_3 in_walk3_3)))
 (let (($x10806 (and c_3_18 in_walk7_3 in_walk3_3)))
 (let (($x10804 (and c_3_17 in_walk7_3 in_walk3_3)))
 (let (($x10802 (and c_3_16 in_walk7_3 in_walk3_3)))
 (let (($x10800 (and c_3_15 in_walk7_3 in_walk3_3)))
 (let (($x10798 (and c_3_14 in_walk7_3 in_walk3_3)))
 (let (($x10796 (and c_3_13 in_walk7_3 in_walk3_3)))
 (let (($x10794 (and c_3_12 in_walk7_3 in_walk3_3)))
 (let (($x10792 (and c_3_11 in_walk7_3 in_walk3_3)))
 (let (($x10790 (and c_3_10 in_walk7_3 in_walk3_3)))
 (let (($x10788 (and c_3_9 in_walk7_3 in_walk3_3)))
 (let (($x10786 (and c_3_8 in_walk7_3 in_walk3_3)))
 (let (($x10784 (and c_3_7 in_walk7_3 in_walk3_3)))
 (let (($x10782 (and c_3_6 in_walk7_3 in_walk3_3)))
 (let (($x10780 (and c_3_5 in_walk7_3 in_walk3_3)))
 (let (($x10778 (and c_3_4 in_walk7_3 in_walk3_3)))
 (let (($x10776 (and c_3_3 in_walk7_3 in_walk3_3)))
 (let (($x10774 (and c_3_2 in_walk7_3 in_walk3_3)))
 (let (($x10772 (and c_3_1 in_walk7_3 in_walk3_3)))
 (let (($x10771 (and c_3_0 in_walk7_3 in_walk3_3)))
 (let (($x10819 (or $x10771 $x10772 $x10774 $x10776 $x10778 $x10780 $x10782 $x10784 $x10786 $x10788 $x10790 $x10792 $x10794 $x10796 $x10798 $x10800 $x10802 $x10804 $x10806 $x10808 $x10810 $x10812 $x10814 $x10816 $x10818)))
 (let (($x10741 (and c_2_24 in_walk7_2 in_walk3_2)))
 (let (($x10739 (and c_2_23 in_walk7_2 in_walk3_2)))
 (let (($x10737 (and c_2_22 in_walk7_2 in_walk3_2)))
 (let (($x10735 (and c_2_21 in_walk7_2 in_walk3_2)))
 (let (($x10733 (and c_2_20 in_walk7_2 in_walk3_2)))
 (let (($x10731 (and c_2_19 in_walk7_2 in_walk3_2)))
 (let (($x10729 (and c_2_18 in_walk7_2 in_walk3_2)))
 (let (($x10727 (and c_2_17 in_walk7_2 in_walk3_2)))
 (let (($x10725 (and c_2_16 in_walk7_2 in_walk3_2)))
 (let (($x10723 (and c_2_15 in_walk7_2 in_walk3_2)))
 (let (($x10721 (and c_2_14 in_walk7_2 in_walk3_2)))
 (let (($x10719 (and c_2_13 in_walk7_2 in_walk3_2)))
 (let (($x10717 (and c_2_12 in_walk7_2 in_walk3_2)))
 (let (($x10715 (and c_2_11 in_walk7_2 in_walk3_2)))
 (let (($x10713 (and c_2_10 in_walk7_2 in_walk3_2)))
 (let (($x10711 (and c_2_9 in_walk7_2 in_walk3_2)))
 (let (($x10709 (and c_2_8 in_walk7_2 in_walk3_2)))
 (let (($x10707 (and c_2_7 in_walk7_2 in_walk3_2)))
 (let (($x10705 (and c_2_6 in_walk7_2 in_walk3_2)))
 (let (($x10703 (and c_2_5 in_walk7_2 in_walk3_2)))
 (let (($x10701 (and c_2_4 in_walk7_2 in_walk3_2)))
 (let (($x10699 (and c_2_3 in_walk7_2 in_walk3_2)))
 (let (($x10697 (and c_2_2 in_walk7_2 in_walk3_2)))
 (let (($x10695 (and c_2_1 in_walk7_2 in_walk3_2)))
 (let (($x10694 (and c_2_0 in_walk7_2 in_walk3_2)))
 (let (($x10742 (or $x10694 $x10695 $x10697 $x10699 $x10701 $x10703 $x10705 $x10707 $x10709 $x10711 $x10713 $x10715 $x10717 $x10719 $x10721 $x10723 $x10725 $x10727 $x10729 $x10731 $x10733 $x10735 $x10737 $x10739 $x10741)))
 (let (($x10664 (and c_1_24 in_walk7_1 in_walk3_1)))
 (let (($x10662 (and c_1_23 in_walk7_1 in_walk3_1)))
 (let (($x10660 (and c_1_22 in_walk7_1 in_walk3_1)))
 (let (($x10658 (and c_1_21 in_walk7_1 in_walk3_1)))
 (let (($x10656 (and c_1_20 in_walk7_1 in_walk3_1)))
 (let (($x10654 (and c_1_19 in_walk7_1 in_walk3_1)))
 (let (($x10652 (and c_1_18 in_walk7_1 in_walk3_1)))
 (let (($x10650 (and c_1_17 in_walk7_1 in_walk3_1)))
 (let (($x10648 (and c_1_16 in_walk7_1 in_walk3_1)))
 (let (($x10646 (and c_1_15 in_walk7_1 in_walk3_1)))
 (let (($x10644 (and c_1_14 in_walk7_1 in_walk3_1)))
 (let (($x10642 (and c_1_13 in_walk7_1 in_walk3_1)))
 (let (($x10640 (and c_1_12 in_walk7_1 in_walk3_1)))
 (let (($x10638 (and c_1_11 in_walk7_1 in_walk3_1)))
 (let (($x10636 (and c_1_10 in_walk7_1 in_walk3_1)))
 (let (($x10634 (and c_1_9 in_walk7_1 in_walk3_1)))
 (let (($x10632 (and c_1_8 in_walk7_1 in_walk3_1)))
 (let (($x10630 (and c_1_7 in_walk7_1 in_walk3_1)))
 (let (($x10628 (and c_1_6 in_walk7_1 in_walk3_1)))
 (let (($x10626 (and c_1_5 in_walk7_1 in_walk3_1)))
 (let (($x10624 (and c_1_4 in_walk7_1 in_walk3_1)))
 (let (($x10622 (and c_1_3 in_walk7_1 in_walk3_1)))
 (let (($x10620 (and c_1_2 in_walk7_1 in_walk3_1)))
 (let (($x10618 (and c_1_1 in_walk7_1 in_walk3_1)))
 (let (($x10617 (and c_1_0 in_walk7_1 in_walk3_1)))
 (let (($x10665 (or $x10617 $x10618 $x10620 $x10622 $x10624 $x10626 $x10628 $x10630 $x10632 $x10634 $x10636 $x10638 $x10640 $x10642 $x10644 $x10646 $x10648 $x10650 $x10652 $x10654 $x10656 $x10658 $x10660 $x10662 $x10664)))
 (let (($x10587 (and c_0_24 in_walk7_0 in_walk3_0)))
 (let (($x10585 (and c_0_23 in_walk7_0 in_walk3_0)))
 (let (($x10583 (and c_0_22 in_walk7_0 in_walk3_0)))
 (let (($x10581 (and c_0_21 in_walk7_0 in_walk3_0)))
 (let (($x10579 (and c_0_20 in_walk7_0 in_walk3_0)))
 (let (($x10577 (and c_0_19 in_walk7_0 in_walk3_0)))
 (let (($x10575 (and c_0_18 in_walk7_0 in_walk3_0)))
 (let (($x10573 (and c_0_17 in_walk7_0 in_walk3_0)))
 (let (($x10571 (and c_0_16 in_walk7_0 in_walk3_0)))
 (let (($x10569 (and c_0_15 in_walk7_0 in_walk3_0)))
 (let (($x10567 (and c_0_14 in_walk7_0 in_walk3_0)))
 (let (($x10565 (and c_0_13 in_walk7_0 in_walk3_0)))
 (let (($x10563 (and c_0_12 in_walk7_0 in_walk3_0)))
 (let (($x10561 (and c_0_11 in_walk7_0 in_walk3_0)))
 (let (($x10559 (and c_0_10 in_walk7_0 in_walk3_0)))
 (let (($x10557 (and c_0_9 in_walk7_0 in_walk3_0)))
 (let (($x10555 (and c_0_8 in_walk7_0 in_walk3_0)))
 (let (($x10553 (and c_0_7 in_walk7_0 in_walk3_0)))
 (let (($x10551 (and c_0_6 in_walk7_0 in_walk3_0)))
 (let (($x10549 (and c_0_5 in_walk7_0 in_walk3_0)))
 (let (($x10547 (and c_0_4 in_walk7_0 in_walk3_0)))
 (let (($x10545 (and c_0_3 in_walk7_0 in_walk3_0)))
 (let (($x10543 (and c_0_2 in_walk7_0 in_walk3_0)))
 (let (($x10541 (and c_0_1 in_walk7_0 in_walk3_0)))
 (let (($x10540 (and c_0_0 in_walk7_0 in_walk3_0)))
 (let (($x10588 (or $x10540 $x10541 $x10543 $x10545 $x10547 $x10549 $x10551 $x10553 $x10555 $x10557 $x10559 $x10561 $x10563 $x10565 $x10567 $x10569 $x10571 $x10573 $x10575 $x10577 $x10579 $x10581 $x10583 $x10585 $x10587)))
 (let (($x10538 (or false $x10588)))
 (let (($x10615 (or $x10538 $x10665)))
 (let (($x10692 (or $x10615 $x10742)))
 (let (($x10507 (and c_3_24 in_walk6_3 in_walk3_3)))
 (let (($x10505 (and c_3_23 in_walk6_3 in_walk3_3)))
 (let (($x10503 (and c_3_22 in_walk6_3 in_walk3_3)))
 (let (($x10501 (and c_3_21 in_walk6_3 in_walk3_3)))
 (let (($x10499 (and c_3_20 in_walk6_3 in_walk3_3)))
 (let (($x10497 (and c_3_19 in_walk6_3 in_walk3_3)))
 (let (($x10495 (and c_3_18 in_walk6_3 in_walk3_3)))
 (let (($x10493 (and c_3_17 in_walk6_3 in_walk3_3)))
 (let (($x10491 (and c_3_16 in_walk6_3 in_walk3_3)))
 (let (($x10489 (and c_3_15 in_walk6_3 in_walk3_3)))
 (let (($x10487 (and c_3_14 in_walk6_3 in_walk3_3)))
 (let (($x10485 (and c_3_13 in_walk6_3 in_walk3_3)))
 (let (($x10483 (and c_3_12 in_walk6_3 in_walk3_3)))
 (let (($x10481 (and c_3_11 in_walk6_3 in_walk3_3)))
 (let (($x10479 (and c_3_10 in_walk6_3 in_walk3_3)))
 (let (($x10477 (and c_3_9 in_walk6_3 in_walk3_3)))
 (let (($x10475 (and c_3_8 in_walk6_3 in_walk3_3)))
 (let (($x10473 (and c_3_7 in_walk6_3 in_walk3_3)))
 (let (($x10471 (and c_3_6 in_walk6_3 in_walk3_3)))
 (let (($x10469 (and c_3_5 in_walk6_3 in_walk3_3)))
 (let (($x10467 (and c_3_4 in_walk6_3 in_walk3_3)))
 (let (($x10465 (and c_3_3 in_walk6_3 in_walk3_3)))
 (let (($x10463 (and c_3_2 in_walk6_3 in_walk3_3)))
 (let (($x10461 (and c_3_1 in_walk6_3 in_walk3_3)))
 (let (($x10460 (and c_3_0 in_walk6_3 in_walk3_3)))
 (let (($x10508 (or $x10460 $x10461 $x10463 $x10465 $x10467 $x10469 $x10471 $x10473 $x10475 $x10477 $x10479 $x10481 $x10483 $x10485 $x10487 $x10489 $x10491 $x10493 $x10495 $x10497 $x10499 $x10501 $x10503 $x10505 $x10507)))
 (let (($x10430 (and c_2_24 in_walk6_2 in_walk3_2)))
 (let (($x10428 (and c_2_23 in_walk6_2 in_walk3_2)))
 (let (($x10426 (and c_2_22 in_walk6_2 in_walk3_2)))
 (let (($x10424 (and c_2_21 in_walk6_2 in_walk3_2)))
 (let (($x10422 (and c_2_20 in_walk6_2 in_walk3_2)))
 (let (($x10420 (and c_2_19 in_walk6_2 in_walk3_2)))
 (let (($x10418 (and c_2_18 in_walk6_2 in_walk3_2)))
 (let (($x10416 (and c_2_17 in_walk6_2 in_walk3_2)))
 (let (($x10414 (and c_2_16 in_walk6_2 in_walk3_2)))
 (let (($x10412 (and c_2_15 in_walk6_2 in_walk3_2)))
 (let (($x10410 (and c_2_14 in_walk6_2 in_walk3_2)))
 (let (($x10408 (and c_2_13 in_walk6_2 in_walk3_2)))
 (let (($x10406 (and c_2_12 in_walk6_2 in_walk3_2)))
 (let (($x10404 (and c_2_11 in_walk6_2 in_walk3_2)))
 (let (($x10402 (and c_2_10 in_walk6_2 in_walk3_2)))
 (let (($x10400 (and c_2_9 in_walk6_2 in_walk3_2)))
 (let (($x10398 (and c_2_8 in_walk6_2 in_walk3_2)))
 (let (($x10396 (and c_2_7 in_walk6_2 in_walk3_2)))
 (let (($x10394 (and c_2_6 in_walk6_2 in_walk3_2)))
 (let (($x10392 (and c_2_5 in_walk6_2 in_walk3_2)))
 (let (($x10390 (and c_2_4 in_walk6_2 in_walk3_2)))
 (let (($x10388 (and c_2_3 in_walk6_2 in_walk3_2)))
 (let (($x10386 (and c_2_2 in_walk6_2 in_walk3_2)))
 (let (($x10384 (and c_2_1 in_walk6_2 in_walk3_2)))
 (let (($x10383 (and c_2_0 in_walk6_2 in_walk3_2)))
 (let (($x10431 (or $x10383 $x10384 $x10386 $x10388 $x10390 $x10392 $x10394 $x10396 $x10398 $x10400 $x10402 $x10404 $x10406 $x10408 $x10410 $x10412 $x10414 $x10416 $x10418 $x10420 $x10422 $x10424 $x10426 $x10428 $x10430)))
 (let (($x10353 (and c_1_24 in_walk6_1 in_walk3_1)))
 (let (($x10351 (and c_1_23 in_walk6_1 in_walk3_1)))
 (let (($x10349 (and c_1_22 in_walk6_1 in_walk3_1)))
 (let (($x10347 (and c_1_21 in_walk6_1 in_walk3_1)))
 (let (($x10345 (and c_1_20 in_walk6_1 in_walk3_1)))
 (let (($x10343 (and c_1_19 in_walk6_1 in_walk3_1)))
 (let (($x10341 (and c_1_18 in_walk6_1 in_walk3_1)))
 (let (($x10339 (and c_1_17 in_walk6_1 in_walk3_1)))
 (let (($x10337 (and c_1_16 in_walk6_1 in_walk3_1)))
 (let (($x10335 (and c_1_15 in_walk6_1 in_walk3_1)))
 (let (($x10333 (and c_1_14 in_walk6_1 in_walk3_1)))
 (let (($x10331 (and c_1_13 in_walk6_1 in_walk3_1)))
 (let (($x10329 (and c_1_12 in_walk6_1 in_walk3_1)))
 (let (($x10327 (and c_1_11 in_walk6_1 in_walk3_1)))
 (let (($x10325 (and c_1_10 in_walk6_1 in_walk3_1)))
 (let (($x10323 (and c_1_9 in_walk6_1 in_walk3_1)))
 (let (($x10321 (and c_1_8 in_walk6_1 in_walk3_1)))
 (let (($x10319 (and c_1_7 in_walk6_1 in_walk3_1)))
 (let (($x10317 (and c_1_6 in_walk6_1 in_walk3_1)))
 (let (($x10315 (and c_1_5 in_walk6_1 in_walk3_1)))
 (let (($x10313 (and c_1_4 in_walk6_1 in_walk3_1)))
 (let (($x10311 (and c_1_3 in_walk6_1 in_walk3_1)))
 (let (($x10309 (and c_1_2 in_walk6_1 in_walk3_1)))
 (let (($x10307 (and c_1_1 in_walk6_1 in_walk3_1)))
 (let (($x10306 (and c_1_0 in_walk6_1 in_walk3_1)))
 (let (($x10354 (or $x10306 $x10307 $x10309 $x10311 $x10313 $x10315 $x10317 $x10319 $x10321 $x10323 $x10325 $x10327 $x10329 $x10331 $x10333 $x10335 $x10337 $x10339 $x10341 $x10343 $x10345 $x10347 $x10349 $x10351 $x10353)))
 (let (($x10276 (and c_0_24 in_walk6_0 in_walk3_0)))
 (let (($x10274 (and c_0_23 in_walk6_0 in_walk3_0)))
 (let (($x10272 (and c_0_22 in_walk6_0 in_walk3_0)))
 (let (($x10270 (and c_0_21 in_walk6_0 in_walk3_0)))
 (let (($x10268 (and c_0_20 in_walk6_0 in_walk3_0)))
 (let (($x10266 (and c_0_19 in_walk6_0 in_walk3_0)))
 (let (($x10264 (and c_0_18 in_walk6_0 in_walk3_0)))
 (let (($x10262 (and c_0_17 in_walk6_0 in_walk3_0)))
 (let (($x10260 (and c_0_16 in_walk6_0 in_walk3_0)))
 (let (($x10258 (and c_0_15 in_walk6_0 in_walk3_0)))
 (let (($x10256 (and c_0_14 in_walk6_0 in_walk3_0)))
 (let (($x10254 (and c_0_13 in_walk6_0 in_walk3_0)))
 (let (($x10252 (and c_0_12 in_walk6_0 in_walk3_0)))
 (let (($x10250 (and c_0_11 in_walk6_0 in_walk3_0)))
 (let (($x10248 (and c_0_10 in_walk6_0 in_walk3_0)))
 (let (($x10246 (and c_0_9 in_walk6_0 in_walk3_0)))
 (let (($x10244 (and c_0_8 in_walk6_0 in_walk3_0)))
 (let (($x10242 (and c_0_7 in_walk6_0 in_walk3_0)))
 (let (($x10240 (and c_0_6 in_walk6_0 in_walk3_0)))
 (let (($x10238 (and c_0_5 in_walk6_0 in_walk3_0)))
 (let (($x10236 (and c_0_4 in_walk6_0 in_walk3_0)))
 (let (($x10234 (and c_0_3 in_walk6_0 in_walk3_0)))
 (let (($x10232 (and c_0_2 in_walk6_0 in_walk3_0)))
 (let (($x10230 (and c_0_1 in_walk6_0 in_walk3_0)))
 (let (($x10229 (and c_0_0 in_walk6_0 in_walk3_0)))
 (let (($x10277 (or $x10229 $x10230 $x10232 $x10234 $x10236 $x10238 $x10240 $x10242 $x10244 $x10246 $x10248 $x10250 $x10252 $x10254 $x10256 $x10258 $x10260 $x10262 $x10264 $x10266 $x10268 $x10270 $x10272 $x10274 $x10276)))
 (let (($x10227 (or false $x10277)))
 (let (($x10304 (or $x10227 $x10354)))
 (let (($x10381 (or $x10304 $x10431)))
 (let (($x10196 (and c_3_24 in_walk5_3 in_walk3_3)))
 (let (($x10194 (and c_3_23 in_walk5_3 in_walk3_3)))
 (let (($x10192 (and c_3_22 in_walk5_3 in_walk3_3)))
 (let (($x10190 (and c_3_21 in_walk5_3 in_walk3_3)))
 (let (($x10188 (and c_3_20 in_walk5_3 in_walk3_3)))
 (let (($x10186 (and c_3_19 in_walk5_3 in_walk3_3)))
 (let (($x10184 (and c_3_18 in_walk5_3 in_walk3_3)))
 (let (($x10182 (and c_3_17 in_walk5_3 in_walk3_3)))
 (let (($x10180 (and c_3_16 in_walk5_3 in_walk3_3)))
 (let (($x10178 (and c_3_15 in_walk5_3 in_walk3_3)))
 (let (($x10176 (and c_3_14 in_walk5_3 in_walk3_3)))
 (let (($x10174 (and c_3_13 in_walk5_3 in_walk3_3)))
 (let (($x10172 (and c_3_12 in_walk5_3 in_walk3_3)))
 (let (($x10170 (and c_3_11 in_walk5_3 in_walk3_3)))
 (let (($x10168 (and c_3_10 in_walk5_3 in_walk3_3)))
 (let (($x10166 (and c_3_9 in_walk5_3 in_walk3_3)))
 (let (($x10164 (and c_3_8 in_walk5_3 in_walk3_3)))
 (let (($x10162 (and c_3_7 in_walk5_3 in_walk3_3)))
 (let (($x10160 (and c_3_6 in_walk5_3 in_walk3_3)))
 (let (($x10158 (and c_3_5 in_walk5_3 in_walk3_3)))
 (let (($x10156 (and c_3_4 in_walk5_3 in_walk3_3)))
 (let (($x10154 (and c_3_3 in_walk5_3 in_walk3_3)))
 (let (($x10152 (and c_3_2 in_walk5_3 in_walk3_3)))
 (let (($x10150 (and c_3_1 in_walk5_3 in_walk3_3)))
 (let (($x10149 (and c_3_0 in_walk5_3 in_walk3_3)))
 (let (($x10197 (or $x10149 $x10150 $x10152 $x10154 $x10156 $x10158 $x10160 $x10162 $x10164 $x10166 $x10168 $x10170 $x10172 $x10174 $x10176 $x10178 $x10180 $x10182 $x10184 $x10186 $x10188 $x10190 $x10192 $x10194 $x10196)))
 (let (($x10119 (and c_2_24 in_walk5_2 in_walk3_2)))
 (let (($x10117 (and c_2_23 in_walk5_2 in_walk3_2)))
 (let (($x10115 (and c_2_22 in_walk5_2 in_walk3_2)))
 (let (($x10113 (and c_2_21 in_walk5_2 in_walk3_2)))
 (let (($x10111 (and c_2_20 in_walk5_2 in_walk3_2)))
 (let (($x10109 (and c_2_19 in_walk5_2 in_walk3_2)))
 (let (($x10107 (and c_2_18 in_walk5_2 in_walk3_2)))
 (let (($x10105 (and c_2_17 in_walk5_2 in_walk3_2)))
 (let (($x10103 (and c_2_16 in_walk5_2 in_walk3_2)))
 (let (($x10101 (and c_2_15 in_walk5_2 in_walk3_2)))
 (let (($x10099 (and c_2_14 in_walk5_2 in_walk3_2)))
 (let (($x10097 (and c_2_13 in_walk5_2 in_walk3_2)))
 (let (($x10095 (and c_2_12 in_walk5_2 in_walk3_2)))
 (let (($x10093 (and c_2_11 in_walk5_2 in_walk3_2)))
 (let (($x10091 (and c_2_10 in_walk5_2 in_walk3_2)))
 (let (($x10089 (and c_2_9 in_walk5_2 in_walk3_2)))
 (let (($x10087 (and c_2_8 in_walk5_2 in_walk3_2)))
 (let (($x10085 (and c_2_7 in_walk5_2 in_walk3_2)))
 (let (($x10083 (and c_2_6 in_walk5_2 in_walk3_2)))
 (let (($x10081 (and c_2_5 in_walk5_2 in_walk3_2)))
 (let (($x10079 (and c_2_4 in_walk5_2 in_walk3_2)))
 (let (($x10077 (and c_2_3 in_walk5_2 in_walk3_2)))
 (let (($x10075 (and c_2_2 in_walk5_2 in_walk3_2)))
 (let (($x10073 (and c_2_1 in_walk5_2 in_walk3_2)))
 (let (($x10072 (and c_2_0 in_walk5_2 in_walk3_2)))
 (let (($x10120 (or $x10072 $x10073 $x10075 $x10077 $x10079 $x10081 $x10083 $x10085 $x10087 $x10089 $x10091 $x10093 $x10095 $x10097 $x10099 $x10101 $x10103 $x10105 $x10107 $x10109 $x10111 $x10113 $x10115 $x10117 $x10119)))
 (let (($x10042 (and c_1_24 in_walk5_1 in_walk3_1)))
 (let (($x10040 (and c_1_23 in_walk5_1 in_walk3_1)))
 (let (($x10038 (and c_1_22 in_walk5_1 in_walk3_1)))
 (let (($x10036 (and c_1_21 in_walk5_1 in_walk3_1)))
 (let (($x10034 (and c_1_20 in_walk5_1 in_walk3_1)))
 (let (($x10032 (and c_1_19 in_walk5_1 in_walk3_1)))
 (let (($x10030 (and c_1_18 in_walk5_1 in_walk3_1)))
 (let (($x10028 (and c_1_17 in_walk5_1 in_walk3_1)))
 (let (($x10026 (and c_1_16 in_walk5_1 in_walk3_1)))
 (let (($x10024 (and c_1_15 in_walk5_1 in_walk3_1)))
 (let (($x10022 (and c_1_14 in_walk5_1 in_walk3_1)))
 (let (($x10020 (and c_1_13 in_walk5_1 in_walk3_1)))
 (let (($x10018 (and c_1_12 in_walk5_1 in_walk3_1)))
 (let (($x10016 (and c_1_11 in_walk5_1 in_walk3_1)))
 (let (($x10014 (and c_1_10 in_walk5_1 in_walk3_1)))
 (let (($x10012 (and c_1_9 in_walk5_1 in_walk3_1)))
 (let (($x10010 (and c_1_8 in_walk5_1 in_walk3_1)))
 (let (($x10008 (and c_1_7 in_walk5_1 in_walk3_1)))
 (let (($x10006 (and c_1_6 in_walk5_1 in_walk3_1)))
 (let (($x10004 (and c_1_5 in_walk5_1 in_walk3_1)))
 (let (($x10002 (and c_1_4 in_walk5_1 in_walk3_1)))
 (let (($x10000 (and c_1_3 in_walk5_1 in_walk3_1)))
 (let (($x9998 (and c_1_2 in_walk5_1 in_walk3_1)))
 (let (($x9996 (and c_1_1 in_walk5_1 in_walk3_1)))
 (let (($x9995 (and c_1_0 in_walk5_1 in_walk3_1)))
 (let (($x10043 (or $x9995 $x9996 $x9998 $x10000 $x10002 $x10004 $x10006 $x10008 $x10010 $x10012 $x10014 $x10016 $x10018 $x10020 $x10022 $x10024 $x10026 $x10028 $x10030 $x10032 $x10034 $x10036 $x10038 $x10040 $x10042)))
 (let (($x9965 (and c_0_24 in_walk5_0 in_walk3_0)))
 (let (($x9963 (and c_0_23 in_walk5_0 in_walk3_0)))
 (let (($x9961 (and c_0_22 in_walk5_0 in_walk3_0)))
 (let (($x9959 (and c_0_21 in_walk5_0 in_walk3_0)))
 (let (($x9957 (and c_0_20 in_walk5_0 in_walk3_0)))
 (let (($x9955 (and c_0_19 in_walk5_0 in_walk3_0)))
 (let (($x9953 (and c_0_18 in_walk5_0 in_walk3_0)))
 (let (($x9951 (and c_0_17 in_walk5_0 in_walk3_0)))
 (let (($x9949 (and c_0_16 in_walk5_0 in_walk3_0)))
 (let (($x9947 (and c_0_15 in_walk5_0 in_walk3_0)))
 (let (($x9945 (and c_0_14 in_walk5_0 in_walk3_0)))
 (let (($x9943 (and c_0_13 in_walk5_0 in_walk3_0)))
 (let (($x9941 (and c_0_12 in_walk5_0 in_walk3_0)))
 (let (($x9939 (and c_0_11 in_walk5_0 in_walk3_0)))
 (let (($x9937 (and c_0_10 in_walk5_0 in_walk3_0)))
 (let (($x9935 (and c_0_9 in_walk5_0 in_walk3_0)))
 (let (($x9933 (and c_0_8 in_walk5_0 in_walk3_0)))
 (let (($x9931 (and c_0_7 in_walk5_0 in_walk3_0)))
 (let (($x9929 (and c_0_6 in_walk5_0 in_walk3_0)))
 (let (($x9927 (and c_0_5 in_walk5_0 in_walk3_0)))
 (let (($x9925 (and c_0_4 in_walk5_0 in_walk3_0)))
 (let (($x9923 (and c_0_3 in_walk5_0 in_walk3_0)))
 (let (($x9921 (and c_0_2 in_walk5_0 in_walk3_0)))
 (let (($x9919 (and c_0_1 in_walk5_0 in_walk3_0)))
 (let (($x9918 (and c_0_0 in_walk5_0 in_walk3_0)))
 (let (($x9966 (or $x9918 $x9919 $x9921 $x9923 $x9925 $x9927 $x9929 $x9931 $x9933 $x9935 $x9937 $x9939 $x9941 $x9943 $x9945 $x9947 $x9949 $x9951 $x9953 $x9955 $x9957 $x9959 $x9961 $x9963 $x9965)))
 (let (($x9916 (or false $x9966)))
 (let (($x9993 (or $x9916 $x10043)))
 (let (($x10070 (or $x9993 $x10120)))
 (let (($x9885 (and c_3_24 in_walk4_3 in_walk3_3)))
 (let (($x9883 (and c_3_23 in_walk4_3 in_walk3_3)))
 (let (($x9881 (and c_3_22 in_walk4_3 in_walk3_3)))
 (let (($x9879 (and c_3_21 in_walk4_3 in_walk3_3)))
 (let (($x9877 (and c_3_20 in_walk4_3 in_walk3_3)))
 (let (($x9875 (and c_3_19 in_walk4_3 in_walk3_3)))
 (let (($x9873 (and c_3_18 in_walk4_3 in_walk3_3)))
 (let (($x9871 (and c_3_17 in_walk4_3 in_walk3_3)))
 (let (($x9869 (and c_3_16 in_walk4_3 in_walk3_3)))
 (let (($x9867 (and c_3_15 in_walk4_3 in_walk3_3)))
 (let (($x9865 (and c_3_14 in_walk4_3 in_walk3_3)))
 (let (($x9863 (and c_3_13 in_walk4_3 in_walk3_3)))
 (let (($x9861 (and c_3_12 in_walk4_3 in_walk3_3)))
 (let (($x9859 (and c_3_11 in_walk4_3 in_walk3_3)))
 (let (($x9857 (and c_3_10 in_walk4_3 in_walk3_3)))
 (let (($x9855 (and c_3_9 in_walk4_3 in_walk3_3)))
 (let (($x9853 (and c_3_8 in_walk4_3 in_walk3_3)))
 (let (($x9851 (and c_3_7 in_walk4_3 in_walk3_3)))
 (let (($x9849 (and c_3_6 in_walk4_3 in_walk3_3)))
 (let (($x9847 (and c_3_5 in_walk4_3 in_walk3_3)))
 (let (($x9845 (and c_3_4 in_walk4_3 in_walk3_3)))
 (let (($x9843 (and c_3_3 in_walk4_3 in_walk3_3)))
 (let (($x9841 (and c_3_2 in_walk4_3 in_walk3_3)))
 (let (($x9839 (and c_3_1 in_walk4_3 in_walk3_3)))
 (let (($x9838 (and c_3_0 in_walk4_3 in_walk3_3)))
 (let (($x9886 (or $x9838 $x9839 $x9841 $x9843 $x9845 $x9847 $x9849 $x9851 $x9853 $x9855 $x9857 $x9859 $x9861 $x9863 $x9865 $x9867 $x9869 $x9871 $x9873 $x9875 $x9877 $x9879 $x9881 $x9883 $x9885)))
 (let (($x9808 (and c_2_24 in_walk4_2 in_walk3_2)))
 (let (($x9806 (and c_2_23 in_walk4_2 in_walk3_2)))
 (let (($x9804 (and c_2_22 in_walk4_2 in_walk3_2)))
 (let (($x9802 (and c_2_21 in_walk4_2 in_walk3_2)))
 (let (($x9800 (and c_2_20 in_walk4_2 in_walk3_2)))
 (let (($x9798 (and c_2_19 in_walk4_2 in_walk3_2)))
 (let (($x9796 (and c_2_18 in_walk4_2 in_walk3_2)))
 (let (($x9794 (and c_2_17 in_walk4_2 in_walk3_2)))
 (let (($x9792 (and c_2_16 in_walk4_2 in_walk3_2)))
 (let (($x9790 (and c_2_15 in_walk4_2 in_walk3_2)))
 (let (($x9788 (and c_2_14 in_walk4_2 in_walk3_2)))
 (let (($x9786 (and c_2_13 in_walk4_2 in_walk3_2)))
 (let (($x9784 (and c_2_12 in_walk4_2 in_walk3_2)))
 (let (($x9782 (and c_2_11 in_walk4_2 in_walk3_2)))
 (let (($x9780 (and c_2_10 in_walk4_2 in_walk3_2)))
 (let (($x9778 (and c_2_9 in_walk4_2 in_walk3_2)))
 (let (($x9776 (and c_2_8 in_walk4_2 in_walk3_2)))
 (let (($x9774 (and c_2_7 in_walk4_2 in_walk3_2)))
 (let (($x9772 (and c_2_6 in_walk4_2 in_walk3_2)))
 (let (($x9770 (and c_2_5 in_walk4_2 in_walk3_2)))
 (let (($x9768 (and c_2_4 in_walk4_2 in_walk3_2)))
 (let (($x9766 (and c_2_3 in_walk4_2 in_walk3_2)))
 (let (($x9764 (and c_2_2 in_walk4_2 in_walk3_2)))
 (let (($x9762 (and c_2_1 in_walk4_2 in_walk3_2)))
 (let (($x9761 (and c_2_0 in_walk4_2 in_walk3_2)))
 (let (($x9809 (or $x9761 $x9762 $x9764 $x9766 $x9768 $x9770 $x9772 $x9774 $x9776 $x9778 $x9780 $x9782 $x9784 $x9786 $x9788 $x9790 $x9792 $x9794 $x9796 $x9798 $x9800 $x9802 $x9804 $x9806 $x9808)))
 (let (($x9731 (and c_1_24 in_walk4_1 in_walk3_1)))
 (let (($x9729 (and c_1_23 in_walk4_1 in_walk3_1)))
 (let (($x9727 (and c_1_22 in_walk4_1 in_walk3_1)))
 (let (($x9725 (and c_1_21 in_walk4_1 in_walk3_1)))
 (let (($x9723 (and c_1_20 in_walk4_1 in_walk3_1)))
 (let (($x9721 (and c_1_19 in_walk4_1 in_walk3_1)))
 (let (($x9719 (and c_1_18 in_walk4_1 in_walk3_1)))
 (let (($x9717 (and c_1_17 in_walk4_1 in_walk3_1)))
 (let (($x9715 (and c_1_16 in_walk4_1 in_walk3_1)))
 (let (($x9713 (and c_1_15 in_walk4_1 in_walk3_1)))
 (let (($x9711 (and c_1_14 in_walk4_1 in_walk3_1)))
 (let (($x9709 (and c_1_13 in_walk4_1 in_walk3_1)))
 (let (($x9707 (and c_1_12 in_walk4_1 in_walk3_1)))
 (let (($x9705 (and c_1_11 in_walk4_1 in_walk3_1)))
 (let (($x9703 (and c_1_10 in_walk4_1 in_walk3_1)))
 (let (($x9701 (and c_1_9 in_walk4_1 in_walk3_1)))
 (let (($x9699 (and c_1_8 in_walk4_1 in_walk3_1)))
 (let (($x9697 (and c_1_7 in_walk4_1 in_walk3_1)))
 (let (($x9695 (and c_1_6 in_walk4_1 in_walk3_1)))
 (let (($x9693 (and c_1_5 in_walk4_1 in_walk3_1)))
 (let (($x9691 (and c_1_4 in_walk4_1 in_walk3_1)))
 (let (($x9689 (and c_1_3 in_walk4_1 in_walk3_1)))
 (let (($x9687 (and c_1_2 in_walk4_1 in_walk3_1)))
 (let (($x9685 (and c_1_1 in_walk4_1 in_walk3_1)))
 (let (($x9684 (and c_1_0 in_walk4_1 in_walk3_1)))
 (let (($x9732 (or $x9684 $x9685 $x9687 $x9689 $x9691 $x9693 $x9695 $x9697 $x9699 $x9701 $x9703 $x9705 $x9707 $x9709 $x9711 $x9713 $x9715 $x9717 $x9719 $x9721 $x9723 $x9725 $x9727 $x9729 $x9731)))
 (let (($x9654 (and c_0_24 in_walk4_0 in_walk3_0)))
 (let (($x9652 (and c_0_23 in_walk4_0 in_walk3_0)))
 (let (($x9650 (and c_0_22 in_walk4_0 in_walk3_0)))
 (let (($x9648 (and c_0_21 in_walk4_0 in_walk3_0)))
 (let (($x9646 (and c_0_20 in_walk4_0 in_walk3_0)))
 (let (($x9644 (and c_0_19 in_walk4_0 in_walk3_0)))
 (let (($x9642 (and c_0_18 in_walk4_0 in_walk3_0)))
 (let (($x9640 (and c_0_17 in_walk4_0 in_walk3_0)))
 (let (($x9638 (and c_0_16 in_walk4_0 in_walk3_0)))
 (let (($x9636 (and c_0_15 in_walk4_0 in_walk3_0)))
 (let (($x9634 (and c_0_14 in_walk4_0 in_walk3_0)))
 (let (($x9632 (and c_0_13 in_walk4_0 in_walk3_0)))
 (let (($x9630 (and c_0_12 in_walk4_0 in_walk3_0)))
 (let (($x9628 (and c_0_11 in_walk4_0 in_walk3_0)))
 (let (($x9626 (and c_0_10 in_walk4_0 in_walk3_0)))
 (let (($x9624 (and c_0_9 in_walk4_0 in_walk3_0)))
 (let (($x9622 (and c_0_8 in_walk4_0 in_walk3_0)))
 (let (($x9620 (and c_0_7 in_walk4_0 in_walk3_0)))
 (let (($x9618 (and c_0_6 in_walk4_0 in_walk3_0)))
 (let (($x9616 (and c_0_5 in_walk4_0 in_walk3_0)))
 (let (($x9614 (and c_0_4 in_walk4_0 in_walk3_0)))
 (let (($x9612 (and c_0_3 in_walk4_0 in_walk3_0)))
 (let (($x9610 (and c_0_2 in_walk4_0 in_walk3_0)))
 (let (($x9608 (and c_0_1 in_walk4_0 in_walk3_0)))
 (let (($x9607 (and c_0_0 in_walk4_0 in_walk3_0)))
 (let (($x9655 (or $x9607 $x9608 $x9610 $x9612 $x9614 $x9616 $x9618 $x9620 $x9622 $x9624 $x9626 $x9628 $x9630 $x9632 $x9634 $x9636 $x9638 $x9640 $x9642 $x9644 $x9646 $x9648 $x9650 $x9652 $x9654)))
 (let (($x9605 (or false $x9655)))
 (let (($x9682 (or $x9605 $x9732)))
 (let (($x9759 (or $x9682 $x9809)))
 (let (($x9574 (and c_3_24 in_walk8_3 in_walk2_3)))
 (let (($x9572 (and c_3_23 in_walk8_3 in_walk2_3)))
 (let (($x9570 (and c_3_22 in_walk8_3 in_walk2_3)))
 (let (($x9568 (and c_3_21 in_walk8_3 in_walk2_3)))
 (let (($x9566 (and c_3_20 in_walk8_3 in_walk2_3)))
 (let (($x9564 (and c_3_19 in_walk8_3 in_walk2_3)))
 (let (($x9562 (and c_3_18 in_walk8_3 in_walk2_3)))
 (let (($x9560 (and c_3_17 in_walk8_3 in_walk2_3)))
 (let (($x9558 (and c_3_16 in_walk8_3 in_walk2_3)))
 (let (($x9556 (and c_3_15 in_walk8_3 in_walk2_3)))
 (let (($x9554 (and c_3_14 in_walk8_3 in_walk2_3)))
 (let (($x9552 (and c_3_13 in_walk8_3 in_walk2_3)))
 (let (($x9550 (and c_3_12 in_walk8_3 in_walk2_3)))
 (let (($x9548 (and c_3_11 in_walk8_3 in_walk2_3)))
 (let (($x9546 (and c_3_10 in_walk8_3 in_walk2_3)))
 (let (($x9544 (and c_3_9 in_walk8_3 in_walk2_3)))
 (let (($x9542 (and c_3_8 in_walk8_3 in_walk2_3)))
 (let (($x9540 (and c_3_7 in_walk8_3 in_walk2_3)))
 (let (($x9538 (and c_3_6 in_walk8_3 in_walk2_3)))
 (let (($x9536 (and c_3_5 in_walk8_3 in_walk2_3)))
 (let (($x9534 (and c_3_4 in_walk8_3 in_walk2_3)))
 (let (($x9532 (and c_3_3 in_walk8_3 in_walk2_3)))
 (let (($x9530 (and c_3_2 in_walk8_3 in_walk2_3)))
 (let (($x9528 (and c_3_1 in_walk8_3 in_walk2_3)))
 (let (($x9527 (and c_3_0 in_walk8_3 in_walk2_3)))
 (let (($x9575 (or $x9527 $x9528 $x9530 $x9532 $x9534 $x9536 $x9538 $x9540 $x9542 $x9544 $x9546 $x9548 $x9550 $x9552 $x9554 $x9556 $x9558 $x9560 $x9562 $x9564 $x9566 $x9568 $x9570 $x9572 $x9574)))
 (let (($x9497 (and c_2_24 in_walk8_2 in_walk2_2)))
 (let (($x9495 (and c_2_23 in_walk8_2 in_walk2_2)))
 (let (($x9493 (and c_2_22 in_walk8_2 in_walk2_2)))
 (let (($x9491 (and c_2_21 in_walk8_2 in_walk2_2)))
 (let (($x9489 (and c_2_20 in_walk8_2 in_walk2_2)))
 (let (($x9487 (and c_2_19 in_walk8_2 in_walk2_2)))
 (let (($x9485 (and c_2_18 in_walk8_2 in_walk2_2)))
 (let (($x9483 (and c_2_17 in_walk8_2 in_walk2_2)))
 (let (($x9481 (and c_2_16 in_walk8_2 in_walk2_2)))
 (let (($x9479 (and c_2_15 in_walk8_2 in_walk2_2)))
 (let (($x9477 (and c_2_14 in_walk8_2 in_walk2_2)))
 (let (($x9475 (and c_2_13 in_walk8_2 in_walk2_2)))
 (let (($x9473 (and c_2_12 in_walk8_2 in_walk2_2)))
 (let (($x9471 (and c_2_11 in_walk8_2 in_walk2_2)))
 (let (($x9469 (and c_2_10 in_walk8_2 in_walk2_2)))
 (let (($x9467 (and c_2_9 in_walk8_2 in_walk2_2)))
 (let (($x9465 (and c_2_8 in_walk8_2 in_walk2_2)))
 (let (($x9463 (and c_2_7 in_walk8_2 in_walk2_2)))
 (let (($x9461 (and c_2_6 in_walk8_2 in_walk2_2)))
 (let (($x9459 (and c_2_5 in_walk8_2 in_walk2_2)))
 (let (($x9457 (and c_2_4 in_walk8_2 in_walk2_2)))
 (let (($x9455 (and c_2_3 in_walk8_2 in_walk2_2)))
 (let (($x9453 (and c_2_2 in_walk8_2 in_walk2_2)))
 (let (($x9451 (and c_2_1 in_walk8_2 in_walk2_2)))
 (let (($x9450 (and c_2_0 in_walk8_2 in_walk2_2)))
 (let (($x9498 (or $x9450 $x9451 $x9453 $x9455 $x9457 $x9459 $x9461 $x9463 $x9465 $x9467 $x9469 $x9471 $x9473 $x9475 $x9477 $x9479 $x9481 $x9483 $x9485 $x9487 $x9489 $x9491 $x9493 $x9495 $x9497)))
 (let (($x9420 (and c_1_24 in_walk8_1 in_walk2_1)))
 (let (($x9418 (and c_1_23 in_walk8_1 in_walk2_1)))
 (let (($x9416 (and c_1_22 in_walk8_1 in_walk2_1)))
 (let (($x9414 (and c_1_21 in_walk8_1 in_walk2_1)))
 (let (($x9412 (and c_1_20 in_walk8_1 in_walk2_1)))
 (let (($x9410 (and c_1_19 in_walk8_1 in_walk2_1)))
 (let (($x9408 (and c_1_18 in_walk8_1 in_walk2_1)))
 (let (($x9406 (and c_1_17 in_walk8_1 in_walk2_1)))
 (let (($x9404 (and c_1_16 in_walk8_1 in_walk2_1)))
 (let (($x9402 (and c_1_15 in_walk8_1 in_walk2_1)))
 (let (($x9400 (and c_1_14 in_walk8_1 in_walk2_1)))
 (let (($x9398 (and c_1_13 in_walk8_1 in_walk2_1)))
 (let (($x9396 (and c_1_12 in_walk8_1 in_walk2_1)))
 (let (($x9394 (and c_1_11 in_walk8_1 in_walk2_1)))
 (let (($x9392 (and c_1_10 in_walk8_1 in_walk2_1)))
 (let (($x9390 (and c_1_9 in_walk8_1 in_walk2_1)))
 (let (($x9388 (and c_1_8 in_walk8_1 in_walk2_1)))
 (let (($x9386 (and c_1_7 in_walk8_1 in_walk2_1)))
 (let (($x9384 (and c_1_6 in_walk8_1 in_walk2_1)))
 (let (($x9382 (and c_1_5 in_walk8_1 in_walk2_1)))
 (let (($x9380 (and c_1_4 in_walk8_1 in_walk2_1)))
 (let (($x9378 (and c_1_3 in_walk8_1 in_walk2_1)))
 (let (($x9376 (and c_1_2 in_walk8_1 in_walk2_1)))
 (let (($x9374 (and c_1_1 in_walk8_1 in_walk2_1)))
 (let (($x9373 (and c_1_0 in_walk8_1 in_walk2_1)))
 (let (($x9421 (or $x9373 $x9374 $x9376 $x9378 $x9380 $x9382 $x9384 $x9386 $x9388 $x9390 $x9392 $x9394 $x9396 $x9398 $x9400 $x9402 $x9404 $x9406 $x9408 $x9410 $x9412 $x9414 $x9416 $x9418 $x9420)))
 (let (($x9343 (and c_0_24 in_walk8_0 in_walk2_0)))
 (let (($x9341 (and c_0_23 in_walk8_0 in_walk2_0)))
 (let (($x9339 (and c_0_22 in_walk8_0 in_walk2_0)))
 (let (($x9337 (and c_0_21 in_walk8_0 in_walk2_0)))
 (let (($x9335 (and c_0_20 in_walk8_0 in_walk2_0)))
 (let (($x9333 (and c_0_19 in_walk8_0 in_walk2_0)))
 (let (($x9331 (and c_0_18 in_walk8_0 in_walk2_0)))
 (let (($x9329 (and c_0_17 in_walk8_0 in_walk2_0)))
 (let (($x9327 (and c_0_16 in_walk8_0 in_walk2_0)))
 (let (($x9325 (and c_0_15 in_walk8_0 in_walk2_0)))
 (let (($x9323 (and c_0_14 in_walk8_0 in_walk2_0)))
 (let (($x9321 (and c_0_13 in_walk8_0 in_walk2_0)))
 (let (($x9319 (and c_0_12 in_walk8_0 in_walk2_0)))
 (let (($x9317 (and c_0_11 in_walk8_0 in_walk2_0)))
 (let (($x9315 (and c_0_10 in_walk8_0 in_walk2_0)))
 (let (($x9313 (and c_0_9 in_walk8_0 in_walk2_0)))
 (let (($x9311 (and c_0_8 in_walk8_0 in_walk2_0)))
 (let (($x9309 (and c_0_7 in_walk8_0 in_walk2_0)))
 (let (($x9307 (and c_0_6 in_walk8_0 in_walk2_0)))
 (let (($x9305 (and c_0_5 in_walk8_0 in_walk2_0)))
 (let (($x9303 (and c_0_4 in_walk8_0 in_walk2_0)))
 (let (($x9301 (and c_0_3 in_walk8_0 in_walk2_0)))
 (let (($x9299 (and c_0_2 in_walk8_0 in_walk2_0)))
 (let (($x9297 (and c_0_1 in_walk8_0 in_walk2_0)))
 (let (($x9296 (and c_0_0 in_walk8_0 in_walk2_0)))
 (let (($x9344 (or $x9296 $x9297 $x9299 $x9301 $x9303 $x9305 $x9307 $x9309 $x9311 $x9313 $x9315 $x9317 $x9319 $x9321 $x9323 $x9325 $x9327 $x9329 $x9331 $x9333 $x9335 $x9337 $x9339 $x9341 $x9343)))
 (let (($x9294 (or false $x9344)))
 (let (($x9371 (or $x9294 $x9421)))
 (let (($x9448 (or $x9371 $x9498)))
 (let (($x5464 (not (or (or (or (or false c_0_10) c_1_10) c_2_10) c_3_10))))
 (let (($x9263 (and c_3_24 in_walk7_3 in_walk2_3)))
 (let (($x9261 (and c_3_23 in_walk7_3 in_walk2_3)))
 (let (($x9259 (and c_3_22 in_walk7_3 in_walk2_3)))
 (let (($x9257 (and c_3_21 in_walk7_3 in_walk2_3)))
 (let (($x9255 (and c_3_20 in_walk7_3 in_walk2_3)))
 (let (($x9253 (and c_3_19 in_walk7_3 in_walk2_3)))
 (let (($x9251 (and c_3_18 in_walk7_3 in_walk2_3)))
 (let (($x9249 (and c_3_17 in_walk7_3 in_walk2_3)))
 (let (($x9247 (and c_3_16 in_walk7_3 in_walk2_3)))
 (let (($x9245 (and c_3_15 in_walk7_3 in_walk2_3)))
 (let (($x9243 (and c_3_14 in_walk7_3 in_walk2_3)))
 (let (($x9241 (and c_3_13 in_walk7_3 in_walk2_3)))
 (let (($x9239 (and c_3_12 in_walk7_3 in_walk2_3)))
 (let (($x9237 (and c_3_11 in_walk7_3 in_walk2_3)))
 (let (($x9235 (and c_3_10 in_walk7_3 in_walk2_3)))
 (let (($x9233 (and c_3_9 in_walk7_3 in_walk2_3)))
 (let (($x9231 (and c_3_8 in_walk7_3 in_walk2_3)))
 (let (($x9229 (and c_3_7 in_walk7_3 in_walk2_3)))
 (let (($x9227 (and c_3_6 in_walk7_3 in_walk2_3)))
 (let (($x9225 (and c_3_5 in_walk7_3 in_walk2_3)))
 (let (($x9223 (and c_3_4 in_walk7_3 in_walk2_3)))
 (let (($x9221 (and c_3_3 in_walk7_3 in_walk2_3)))
 (let (($x9219 (and c_3_2 in_walk7_3 in_walk2_3)))
 (let (($x9217 (and c_3_1 in_walk7_3 in_walk2_3)))
 (let (($x9216 (and c_3_0 in_walk7_3 in_walk2_3)))
 (let (($x9264 (or $x9216 $x9217 $x9219 $x9221 $x9223 $x9225 $x9227 $x9229 $x9231 $x9233 $x9235 $x9237 $x9239 $x9241 $x9243 $x9245 $x9247 $x9249 $x9251 $x9253 $x9255 $x9257 $x9259 $x9261 $x9263)))
 (let (($x9186 (and c_2_24 in_walk7_2 in_walk2_2)))
 (let (($x9184 (and c_2_23 in_walk7_2 in_walk2_2)))
 (let (($x9182 (and c_2_22 in_walk7_2 in_walk2_2)))
 (let (($x9180 (and c_2_21 in_walk7_2 in_walk2_2)))
 (let (($x9178 (and c_2_20 in_walk7_2 in_walk2_2)))
 (let (($x9176 (and c_2_19 in_walk7_2 in_walk2_2)))
 (let (($x9174 (and c_2_18 in_walk7_2 in_walk2_2)))
 (let (($x9172 (and c_2_17 in_walk7_2 in_walk2_2)))
 (let (($x9170 (and c_2_16 in_walk7_2 in_walk2_2)))
 (let (($x9168 (and c_2_15 in_walk7_2 in_walk2_2)))
 (let (($x9166 (and c_2_14 in_walk7_2 in_walk2_2)))
 (let (($x9164 (and c_2_13 in_walk7_2 in_walk2_2)))
 (let (($x9162 (and c_2_12 in_walk7_2 in_walk2_2)))
 (let (($x9160 (and c_2_11 in_walk7_2 in_walk2_2)))
 (let (($x9158 (and c_2_10 in_walk7_2 in_walk2_2)))
 (let (($x9156 (and c_2_9 in_walk7_2 in_walk2_2)))
 (let (($x9154 (and c_2_8 in_walk7_2 in_walk2_2)))
 (let (($x9152 (and c_2_7 in_walk7_2 in_walk2_2)))
 (let (($x9150 (and c_2_6 in_walk7_2 in_walk2_2)))
 (let (($x9148 (and c_2_5 in_walk7_2 in_walk2_2)))
 (let (($x9146 (and c_2_4 in_walk7_2 in_walk2_2)))
 (let (($x9144 (and c_2_3 in_walk7_2 in_walk2_2)))
 (let (($x9142 (and c_2_2 in_walk7_2 in_walk2_2)))
 (let (($x9140 (and c_2_1 in_walk7_2 in_walk2_2)))
 (let (($x9139 (and c_2_0 in_walk7_2 in_walk2_2)))
 (let (($x9187 (or $x9139 $x9140 $x9142 $x9144 $x9146 $x9148 $x9150 $x9152 $x9154 $x9156 $x9158 $x9160 $x9162 $x9164 $x9166 $x9168 $x9170 $x9172 $x9174 $x9176 $x9178 $x9180 $x9182 $x9184 $x9186)))
 (let (($x9109 (and c_1_24 in_walk7_1 in_walk2_1)))
 (let (($x9107 (and c_1_23 in_walk7_1 in_walk2_1)))
 (let (($x9105 (and c_1_22 in_walk7_1 in_walk2_1)))
 (let (($x9103 (and c_1_21 in_walk7_1 in_walk2_1)))
 (let (($x9101 (and c_1_20 in_walk7_1 in_walk2_1)))
 (let (($x9099 (and c_1_19 in_walk7_1 in_walk2_1)))
 (let (($x9097 (and c_1_18 in_walk7_1 in_walk2_1)))
 (let (($x9095 (and c_1_17 in_walk7_1 in_walk2_1)))
 (let (($x9093 (and c_1_16 in_walk7_1 in_walk2_1)))
 (let (($x9091 (and c_1_15 in_walk7_1 in_walk2_1)))
 (let (($x9089 (and c_1_14 in_walk7_1 in_walk2_1)))
 (let (($x9087 (and c_1_13 in_walk7_1 in_walk2_1)))
 (let (($x9085 (and c_1_12 in_walk7_1 in_walk2_1)))
 (let (($x9083 (and c_1_11 in_walk7_1 in_walk2_1)))
 (let (($x9081 (and c_1_10 in_walk7_1 in_walk2_1)))
 (let (($x9079 (and c_1_9 in_walk7_1 in_walk2_1)))
 (let (($x9077 (and c_1_8 in_walk7_1 in_walk2_1)))
 (let (($x9075 (and c_1_7 in_walk7_1 in_walk2_1)))
 (let (($x9073 (and c_1_6 in_walk7_1 in_walk2_1)))
 (let (($x9071 (and c_1_5 in_walk7_1 in_walk2_1)))
 (let (($x9069 (and c_1_4 in_walk7_1 in_walk2_1)))
 (let (($x9067 (and c_1_3 in_walk7_1 in_walk2_1)))
 (let (($x9065 (and c_1_2 in_walk7_1 in_walk2_1)))
 (let (($x9063 (and c_1_1 in_walk7_1 in_walk2_1)))
 (let (($x9062 (and c_1_0 in_walk7_1 in_walk2_1)))
 (let (($x9110 (or $x9062 $x9063 $x9065 $x9067 $x9069 $x9071 $x9073 $x9075 $x9077 $x9079 $x9081 $x9083 $x9085 $x9087 $x9089 $x9091 $x9093 $x9095 $x9097 $x9099 $x9101 $x9103 $x9105 $x9107 $x9109)))
 (let (($x9032 (and c_0_24 in_walk7_0 in_walk2_0)))
 (let (($x9030 (and c_0_23 in_walk7_0 in_walk2_0)))
 (let (($x9028 (and c_0_22 in_walk7_0 in_walk2_0)))
 (let (($x9026 (and c_0_21 in_walk7_0 in_walk2_0)))
 (let (($x9024 (and c_0_20 in_walk7_0 in_walk2_0)))
 (let (($x9022 (and c_0_19 in_walk7_0 in_walk2_0)))
 (let (($x9020 (and c_0_18 in_walk7_0 in_walk2_0)))
 (let (($x9018 (and c_0_17 in_walk7_0 in_walk2_0)))
 (let (($x9016 (and c_0_16 in_walk7_0 in_walk2_0)))
 (let (($x9014 (and c_0_15 in_walk7_0 in_walk2_0)))
 (let (($x9012 (and c_0_14 in_walk7_0 in_walk2_0)))
 (let (($x9010 (and c_0_13 in_walk7_0 in_walk2_0)))
 (let (($x9008 (and c_0_12 in_walk7_0 in_walk2_0)))
 (let (($x9006 (and c_0_11 in_walk7_0 in_walk2_0)))
 (let (($x9004 (and c_0_10 in_walk7_0 in_walk2_0)))
 (let (($x9002 (and c_0_9 in_walk7_0 in_walk2_0)))
 (let (($x9000 (and c_0_8 in_walk7_0 in_walk2_0)))
 (let (($x8998 (and c_0_7 in_walk7_0 in_walk2_0)))
 (let (($x8996 (and c_0_6 in_walk7_0 in_walk2_0)))
 (let (($x8994 (and c_0_5 in_walk7_0 in_walk2_0)))
 (let (($x8992 (and c_0_4 in_walk7_0 in_walk2_0)))
 (let (($x8990 (and c_0_3 in_walk7_0 in_walk2_0)))
 (let (($x8988 (and c_0_2 in_walk7_0 in_walk2_0)))
 (let (($x8986 (and c_0_1 in_walk7_0 in_walk2_0)))
 (let (($x8985 (and c_0_0 in_walk7_0 in_walk2_0)))
 (let (($x9033 (or $x8985 $x8986 $x8988 $x8990 $x8992 $x8994 $x8996 $x8998 $x9000 $x9002 $x9004 $x9006 $x9008 $x9010 $x9012 $x9014 $x9016 $x9018 $x9020 $x9022 $x9024 $x9026 $x9028 $x9030 $x9032)))
 (let (($x8983 (or false $x9033)))
 (let (($x9060 (or $x8983 $x9110)))
 (let (($x9137 (or $x9060 $x9187)))
 (let (($x8952 (and c_3_24 in_walk6_3 in_walk2_3)))
 (let (($x8950 (and c_3_23 in_walk6_3 in_walk2_3)))
 (let (($x8948 (and c_3_22 in_walk6_3 in_walk2_3)))
 (let (($x8946 (and c_3_21 in_walk6_3 in_walk2_3)))
 (let (($x8944 (and c_3_20 in_walk6_3 in_walk2_3)))
 (let (($x8942 (and c_3_19 in_walk6_3 in_walk2_3)))
 (let (($x8940 (and c_3_18 in_walk6_3 in_walk2_3)))
 (let (($x8938 (and c_3_17 in_walk6_3 in_walk2_3)))
 (let (($x8936 (and c_3_16 in_walk6_3 in_walk2_3)))
 (let (($x8934 (and c_3_15 in_walk6_3 in_walk2_3)))
 (let (($x8932 (and c_3_14 in_walk6_3 in_walk2_3)))
 (let (($x8930 (and c_3_13 in_walk6_3 in_walk2_3)))
 (let (($x8928 (and c_3_12 in_walk6_3 in_walk2_3)))
 (let (($x8926 (and c_3_11 in_walk6_3 in_walk2_3)))
 (let (($x8924 (and c_3_10 in_walk6_3 in_walk2_3)))
 (let (($x8922 (and c_3_9 in_walk6_3 in_walk2_3)))
 (let (($x8920 (and c_3_8 in_walk6_3 in_walk2_3)))
 (let (($x8918 (and c_3_7 in_walk6_3 in_walk2_3)))
 (let (($x8916 (and c_3_6 in_walk6_3 in_walk2_3)))
 (let (($x8914 (and c_3_5 in_walk6_3 in_walk2_3)))
 (let (($x8912 (and c_3_4 in_walk6_3 in_walk2_3)))
 (let (($x8910 (and c_3_3 in_walk6_3 in_walk2_3)))
 (let (($x8908 (and c_3_2 in_walk6_3 in_walk2_3)))
 (let (($x8906 (and c_3_1 in_walk6_3 in_walk2_3)))
 (let (($x8905 (and c_3_0 in_walk6_3 in_walk2_3)))
 (let (($x8953 (or $x8905 $x8906 $x8908 $x8910 $x8912 $x8914 $x8916 $x8918 $x8920 $x8922 $x8924 $x8926 $x8928 $x8930 $x8932 $x8934 $x8936 $x8938 $x8940 $x8942 $x8944 $x8946 $x8948 $x8950 $x8952)))
 (let (($x8875 (and c_2_24 in_walk6_2 in_walk2_2)))
 (let (($x8873 (and c_2_23 in_walk6_2 in_walk2_2)))
 (let (($x8871 (and c_2_22 in_walk6_2 in_walk2_2)))
 (let (($x8869 (and c_2_21 in_walk6_2 in_walk2_2)))
 (let (($x8867 (and c_2_20 in_walk6_2 in_walk2_2)))
 (let (($x8865 (and c_2_19 in_walk6_2 in_walk2_2)))
 (let (($x8863 (and c_2_18 in_walk6_2 in_walk2_2)))
 (let (($x8861 (and c_2_17 in_walk6_2 in_walk2_2)))
 (let (($x8859 (and c_2_16 in_walk6_2 in_walk2_2)))
 (let (($x8857 (and c_2_15 in_walk6_2 in_walk2_2)))
 (let (($x8855 (and c_2_14 in_walk6_2 in_walk2_2)))
 (let (($x8853 (and c_2_13 in_walk6_2 in_walk2_2)))
 (let (($x8851 (and c_2_12 in_walk6_2 in_walk2_2)))
 (let (($x8849 (and c_2_11 in_walk6_2 in_walk2_2)))
 (let (($x8847 (and c_2_10 in_walk6_2 in_walk2_2)))
 (let (($x8845 (and c_2_9 in_walk6_2 in_walk2_2)))
 (let (($x8843 (and c_2_8 in_walk6_2 in_walk2_2)))
 (let (($x8841 (and c_2_7 in_walk6_2 in_walk2_2)))
 (let (($x8839 (and c_2_6 in_walk6_2 in_walk2_2)))
 (let (($x8837 (and c_2_5 in_walk6_2 in_walk2_2)))
 (let (($x8835 (and c_2_4 in_walk6_2 in_walk2_2)))
 (let (($x8833 (and c_2_3 in_walk6_2 in_walk2_2)))
 (let (($x8831 (and c_2_2 in_walk6_2 in_walk2_2)))
 (let (($x8829 (and c_2_1 in_walk6_2 in_walk2_2)))
 (let (($x8828 (and c_2_0 in_walk6_2 in_walk2_2)))
 (let (($x8876 (or $x8828 $x8829 $x8831 $x8833 $x8835 $x8837 $x8839 $x8841 $x8843 $x8845 $x8847 $x8849 $x8851 $x8853 $x8855 $x8857 $x8859 $x8861 $x8863 $x8865 $x8867 $x8869 $x8871 $x8873 $x8875)))
 (let (($x8798 (and c_1_24 in_walk6_1 in_walk2_1)))
 (let (($x8796 (and c_1_23 in_walk6_1 in_walk2_1)))
 (let (($x8794 (and c_1_22 in_walk6_1 in_walk2_1)))
 (let (($x8792 (and c_1_21 in_walk6_1 in_walk2_1)))
 (let (($x8790 (and c_1_20 in_walk6_1 in_walk2_1)))
 (let (($x8788 (and c_1_19 in_walk6_1 in_walk2_1)))
 (let (($x8786 (and c_1_18 in_walk6_1 in_walk2_1)))
 (let (($x8784 (and c_1_17 in_walk6_1 in_walk2_1)))
 (let (($x8782 (and c_1_16 in_walk6_1 in_walk2_1)))
 (let (($x8780 (and c_1_15 in_walk6_1 in_walk2_1)))
 (let (($x8778 (and c_1_14 in_walk6_1 in_walk2_1)))
 (let (($x8776 (and c_1_13 in_walk6_1 in_walk2_1)))
 (let (($x8774 (and c_1_12 in_walk6_1 in_walk2_1)))
 (let (($x8772 (and c_1_11 in_walk6_1 in_walk2_1)))
 (let (($x8770 (and c_1_10 in_walk6_1 in_walk2_1)))
 (let (($x8768 (and c_1_9 in_walk6_1 in_walk2_1)))
 (let (($x8766 (and c_1_8 in_walk6_1 in_walk2_1)))
 (let (($x8764 (and c_1_7 in_walk6_1 in_walk2_1)))
 (let (($x8762 (and c_1_6 in_walk6_1 in_walk2_1)))
 (let (($x8760 (and c_1_5 in_walk6_1 in_walk2_1)))
 (let (($x8758 (and c_1_4 in_walk6_1 in_walk2_1)))
 (let (($x8756 (and c_1_3 in_walk6_1 in_walk2_1)))
 (let (($x8754 (and c_1_2 in_walk6_1 in_walk2_1)))
 (let (($x8752 (and c_1_1 in_walk6_1 in_walk2_1)))
 (let (($x8751 (and c_1_0 in_walk6_1 in_walk2_1)))
 (let (($x8799 (or $x8751 $x8752 $x8754 $x8756 $x8758 $x8760 $x8762 $x8764 $x8766 $x8768 $x8770 $x8772 $x8774 $x8776 $x8778 $x8780 $x8782 $x8784 $x8786 $x8788 $x8790 $x8792 $x8794 $x8796 $x8798)))
 (let (($x8721 (and c_0_24 in_walk6_0 in_walk2_0)))
 (let (($x8719 (and c_0_23 in_walk6_0 in_walk2_0)))
 (let (($x8717 (and c_0_22 in_walk6_0 in_walk2_0)))
 (let (($x8715 (and c_0_21 in_walk6_0 in_walk2_0)))
 (let (($x8713 (and c_0_20 in_walk6_0 in_walk2_0)))
 (let (($x8711 (and c_0_19 in_walk6_0 in_walk2_0)))
 (let (($x8709 (and c_0_18 in_walk6_0 in_walk2_0)))
 (let (($x8707 (and c_0_17 in_walk6_0 in_walk2_0)))
 (let (($x8705 (and c_0_16 in_walk6_0 in_walk2_0)))
 (let (($x8703 (and c_0_15 in_walk6_0 in_walk2_0)))
 (let (($x8701 (and c_0_14 in_walk6_0 in_walk2_0)))
 (let (($x8699 (and c_0_13 in_walk6_0 in_walk2_0)))
 (let (($x8697 (and c_0_12 in_walk6_0 in_walk2_0)))
 (let (($x8695 (and c_0_11 in_walk6_0 in_walk2_0)))
 (let (($x8693 (and c_0_10 in_walk6_0 in_walk2_0)))
 (let (($x8691 (and c_0_9 in_walk6_0 in_walk2_0)))
 (let (($x8689 (and c_0_8 in_walk6_0 in_walk2_0)))
 (let (($x8687 (and c_0_7 in_walk6_0 in_walk2_0)))
 (let (($x8685 (and c_0_6 in_walk6_0 in_walk2_0)))
 (let (($x8683 (and c_0_5 in_walk6_0 in_walk2_0)))
 (let (($x8681 (and c_0_4 in_walk6_0 in_walk2_0)))
 (let (($x8679 (and c_0_3 in_walk6_0 in_walk2_0)))
 (let (($x8677 (and c_0_2 in_walk6_0 in_walk2_0)))
 (let (($x8675 (and c_0_1 in_walk6_0 in_walk2_0)))
 (let (($x8674 (and c_0_0 in_walk6_0 in_walk2_0)))
 (let (($x8722 (or $x8674 $x8675 $x8677 $x8679 $x8681 $x8683 $x8685 $x8687 $x8689 $x8691 $x8693 $x8695 $x8697 $x8699 $x8701 $x8703 $x8705 $x8707 $x8709 $x8711 $x8713 $x8715 $x8717 $x8719 $x8721)))
 (let (($x8672 (or false $x8722)))
 (let (($x8749 (or $x8672 $x8799)))
 (let (($x8826 (or $x8749 $x8876)))
 (let (($x8641 (and c_3_24 in_walk5_3 in_walk2_3)))
 (let (($x8639 (and c_3_23 in_walk5_3 in_walk2_3)))
 (let (($x8637 (and c_3_22 in_walk5_3 in_walk2_3)))
 (let (($x8635 (and c_3_21 in_walk5_3 in_walk2_3)))
 (let (($x8633 (and c_3_20 in_walk5_3 in_walk2_3)))
 (let (($x8631 (and c_3_19 in_walk5_3 in_walk2_3)))
 (let (($x8629 (and c_3_18 in_walk5_3 in_walk2_3)))
 (let (($x8627 (and c_3_17 in_walk5_3 in_walk2_3)))
 (let (($x8625 (and c_3_16 in_walk5_3 in_walk2_3)))
 (let (($x8623 (and c_3_15 in_walk5_3 in_walk2_3)))
 (let (($x8621 (and c_3_14 in_walk5_3 in_walk2_3)))
 (let (($x8619 (and c_3_13 in_walk5_3 in_walk2_3)))
 (let (($x8617 (and c_3_12 in_walk5_3 in_walk2_3)))
 (let (($x8615 (and c_3_11 in_walk5_3 in_walk2_3)))
 (let (($x8613 (and c_3_10 in_walk5_3 in_walk2_3)))
 (let (($x8611 (and c_3_9 in_walk5_3 in_walk2_3)))
 (let (($x8609 (and c_3_8 in_walk5_3 in_walk2_3)))
 (let (($x8607 (and c_3_7 in_walk5_3 in_walk2_3)))
 (let (($x8605 (and c_3_6 in_walk5_3 in_walk2_3)))
 (let (($x8603 (and c_3_5 in_walk5_3 in_walk2_3)))
 (let (($x8601 (and c_3_4 in_walk5_3 in_walk2_3)))
 (let (($x8599 (and c_3_3 in_walk5_3 in_walk2_3)))
 (let (($x8597 (and c_3_2 in_walk5_3 in_walk2_3)))
 (let (($x8595 (and c_3_1 in_walk5_3 in_walk2_3)))
 (let (($x8594 (and c_3_0 in_walk5_3 in_walk2_3)))
 (let (($x8642 (or $x8594 $x8595 $x8597 $x8599 $x8601 $x8603 $x8605 $x8607 $x8609 $x8611 $x8613 $x8615 $x8617 $x8619 $x8621 $x8623 $x8625 $x8627 $x8629 $x8631 $x8633 $x8635 $x8637 $x8639 $x8641)))
 (let (($x8564 (and c_2_24 in_walk5_2 in_walk2_2)))
 (let (($x8562 (and c_2_23 in_walk5_2 in_walk2_2)))
 (let (($x8560 (and c_2_22 in_walk5_2 in_walk2_2)))
 (let (($x8558 (and c_2_21 in_walk5_2 in_walk2_2)))
 (let (($x8556 (and c_2_20 in_walk5_2 in_walk2_2)))
 (let (($x8554 (and c_2_19 in_walk5_2 in_walk2_2)))
 (let (($x8552 (and c_2_18 in_walk5_2 in_walk2_2)))
 (let (($x8550 (and c_2_17 in_walk5_2 in_walk2_2)))
 (let (($x8548 (and c_2_16 in_walk5_2 in_walk2_2)))
 (let (($x8546 (and c_2_15 in_walk5_2 in_walk2_2)))
 (let (($x8544 (and c_2_14 in_walk5_2 in_walk2_2)))
 (let (($x8542 (and c_2_13 in_walk5_2 in_walk2_2)))
 (let (($x8540 (and c_2_12 in_walk5_2 in_walk2_2)))
 (let (($x8538 (and c_2_11 in_walk5_2 in_walk2_2)))
 (let (($x8536 (and c_2_10 in_walk5_2 in_walk2_2)))
 (let (($x8534 (and c_2_9 in_walk5_2 in_walk2_2)))
 (let (($x8532 (and c_2_8 in_walk5_2 in_walk2_2)))
 (let (($x8530 (and c_2_7 in_walk5_2 in_walk2_2)))
 (let (($x8528 (and c_2_6 in_walk5_2 in_walk2_2)))
 (let (($x8526 (and c_2_5 in_walk5_2 in_walk2_2)))
 (let (($x8524 (and c_2_4 in_walk5_2 in_walk2_2)))
 (let (($x8522 (and c_2_3 in_walk5_2 in_walk2_2)))
 (let (($x8520 (and c_2_2 in_walk5_2 in_walk2_2)))
 (let (($x8518 (and c_2_1 in_walk5_2 in_walk2_2)))
 (let (($x8517 (and c_2_0 in_walk5_2 in_walk2_2)))
 (let (($x8565 (or $x8517 $x8518 $x8520 $x8522 $x8524 $x8526 $x8528 $x8530 $x8532 $x8534 $x8536 $x8538 $x8540 $x8542 $x8544 $x8546 $x8548 $x8550 $x8552 $x8554 $x8556 $x8558 $x8560 $x8562 $x8564)))
 (let (($x8487 (and c_1_24 in_walk5_1 in_walk2_1)))
 (let (($x8485 (and c_1_23 in_walk5_1 in_walk2_1)))
 (let (($x8483 (and c_1_22 in_walk5_1 in_walk2_1)))
 (let (($x8481 (and c_1_21 in_walk5_1 in_walk2_1)))
 (let (($x8479 (and c_1_20 in_walk5_1 in_walk2_1)))
 (let (($x8477 (and c_1_19 in_walk5_1 in_walk2_1)))
 (let (($x8475 (and c_1_18 in_walk5_1 in_walk2_1)))
 (let (($x8473 (and c_1_17 in_walk5_1 in_walk2_1)))
 (let (($x8471 (and c_1_16 in_walk5_1 in_walk2_1)))
 (let (($x8469 (and c_1_15 in_walk5_1 in_walk2_1)))
 (let (($x8467 (and c_1_14 in_walk5_1 in_walk2_1)))
 (let (($x8465 (and c_1_13 in_walk5_1 in_walk2_1)))
 (let (($x8463 (and c_1_12 in_walk5_1 in_walk2_1)))
 (let (($x8461 (and c_1_11 in_walk5_1 in_walk2_1)))
 (let (($x8459 (and c_1_10 in_walk5_1 in_walk2_1)))
 (let (($x8457 (and c_1_9 in_walk5_1 in_walk2_1)))
 (let (($x8455 (and c_1_8 in_walk5_1 in_walk2_1)))
 (let (($x8453 (and c_1_7 in_walk5_1 in_walk2_1)))
 (let (($x8451 (and c_1_6 in_walk5_1 in_walk2_1)))
 (let (($x8449 (and c_1_5 in_walk5_1 in_walk2_1)))
 (let (($x8447 (and c_1_4 in_walk5_1 in_walk2_1)))
 (let (($x8445 (and c_1_3 in_walk5_1 in_walk2_1)))
 (let (($x8443 (and c_1_2 in_walk5_1 in_walk2_1)))
 (let (($x8441 (and c_1_1 in_walk5_1 in_walk2_1)))
 (let (($x8440 (and c_1_0 in_walk5_1 in_walk2_1)))
 (let (($x8488 (or $x8440 $x8441 $x8443 $x8445 $x8447 $x8449 $x8451 $x8453 $x8455 $x8457 $x8459 $x8461 $x8463 $x8465 $x8467 $x8469 $x8471 $x8473 $x8475 $x8477 $x8479 $x8481 $x8483 $x8485 $x8487)))
 (let (($x8410 (and c_0_24 in_walk5_0 in_walk2_0)))
 (let (($x8408 (and c_0_23 in_walk5_0 in_walk2_0)))
 (let (($x8406 (and c_0_22 in_walk5_0 in_walk2_0)))
 (let (($x8404 (and c_0_21 in_walk5_0 in_walk2_0)))
 (let (($x8402 (and c_0_20 in_walk5_0 in_walk2_0)))
 (let (($x8400 (and c_0_19 in_walk5_0 in_walk2_0)))
 (let (($x8398 (and c_0_18 in_walk5_0 in_walk2_0)))
 (let (($x8396 (and c_0_17 in_walk5_0 in_walk2_0)))
 (let (($x8394 (and c_0_16 in_walk5_0 in_walk2_0)))
 (let (($x8392 (and c_0_15 in_walk5_0 in_walk2_0)))
 (let (($x8390 (and c_0_14 in_walk5_0 in_walk2_0)))
 (let (($x8388 (and c_0_13 in_walk5_0 in_walk2_0)))
 (let (($x8386 (and c_0_12 in_walk5_0 in_walk2_0)))
 (let (($x8384 (and c_0_11 in_walk5_0 in_walk2_0)))
 (let (($x8382 (and c_0_10 in_walk5_0 in_walk2_0)))
 (let (($x8380 (and c_0_9 in_walk5_0 in_walk2_0)))
 (let (($x8378 (and c_0_8 in_walk5_0 in_walk2_0)))
 (let (($x8376 (and c_0_7 in_walk5_0 in_walk2_0)))
 (let (($x8374 (and c_0_6 in_walk5_0 in_walk2_0)))
 (let (($x8372 (and c_0_5 in_walk5_0 in_walk2_0)))
 (let (($x8370 (and c_0_4 in_walk5_0 in_walk2_0)))
 (let (($x8368 (and c_0_3 in_walk5_0 in_walk2_0)))
 (let (($x8366 (and c_0_2 in_walk5_0 in_walk2_0)))
 (let (($x8364 (and c_0_1 in_walk5_0 in_walk2_0)))
 (let (($x8363 (and c_0_0 in_walk5_0 in_walk2_0)))
 (let (($x8411 (or $x8363 $x8364 $x8366 $x8368 $x8370 $x8372 $x8374 $x8376 $x8378 $x8380 $x8382 $x8384 $x8386 $x8388 $x8390 $x8392 $x8394 $x8396 $x8398 $x8400 $x8402 $x8404 $x8406 $x8408 $x8410)))
 (let (($x8361 (or false $x8411)))
 (let (($x8438 (or $x8361 $x8488)))
 (let (($x8515 (or $x8438 $x8565)))
 (let (($x8330 (and c_3_24 in_walk4_3 in_walk2_3)))
 (let (($x8328 (and c_3_23 in_walk4_3 in_walk2_3)))
 (let (($x8326 (and c_3_22 in_walk4_3 in_walk2_3)))
 (let (($x8324 (and c_3_21 in_walk4_3 in_walk2_3)))
 (let (($x8322 (and c_3_20 in_walk4_3 in_walk2_3)))
 (let (($x8320 (and c_3_19 in_walk4_3 in_walk2_3)))
 (let (($x8318 (and c_3_18 in_walk4_3 in_walk2_3)))
 (let (($x8316 (and c_3_17 in_walk4_3 in_walk2_3)))
 (let (($x8314 (and c_3_16 in_walk4_3 in_walk2_3)))
 (let (($x8312 (and c_3_15 in_walk4_3 in_walk2_3)))
 (let (($x8310 (and c_3_14 in_walk4_3 in_walk2_3)))
 (let (($x8308 (and c_3_13 in_walk4_3 in_walk2_3)))
 (let (($x8306 (and c_3_12 in_walk4_3 in_walk2_3)))
 (let (($x8304 (and c_3_11 in_walk4_3 in_walk2_3)))
 (let (($x8302 (and c_3_10 in_walk4_3 in_walk2_3)))
 (let (($x8300 (and c_3_9 in_walk4_3 in_walk2_3)))
 (let (($x8298 (and c_3_8 in_walk4_3 in_walk2_3)))
 (let (($x8296 (and c_3_7 in_walk4_3 in_walk2_3)))
 (let (($x8294 (and c_3_6 in_walk4_3 in_walk2_3)))
 (let (($x8292 (and c_3_5 in_walk4_3 in_walk2_3)))
 (let (($x8290 (and c_3_4 in_walk4_3 in_walk2_3)))
 (let (($x8288 (and c_3_3 in_walk4_3 in_walk2_3)))
 (let (($x8286 (and c_3_2 in_walk4_3 in_walk2_3)))
 (let (($x8284 (and c_3_1 in_walk4_3 in_walk2_3)))
 (let (($x8283 (and c_3_0 in_walk4_3 in_walk2_3)))
 (let (($x8331 (or $x8283 $x8284 $x8286 $x8288 $x8290 $x8292 $x8294 $x8296 $x8298 $x8300 $x8302 $x8304 $x8306 $x8308 $x8310 $x8312 $x8314 $x8316 $x8318 $x8320 $x8322 $x8324 $x8326 $x8328 $x8330)))
 (let (($x8253 (and c_2_24 in_walk4_2 in_walk2_2)))
 (let (($x8251 (and c_2_23 in_walk4_2 in_walk2_2)))
 (let (($x8249 (and c_2_22 in_walk4_2 in_walk2_2)))
 (let (($x8247 (and c_2_21 in_walk4_2 in_walk2_2)))
 (let (($x8245 (and c_2_20 in_walk4_2 in_walk2_2)))
 (let (($x8243 (and c_2_19 in_walk4_2 in_walk2_2)))
 (let (($x8241 (and c_2_18 in_walk4_2 in_walk2_2)))
 (let (($x8239 (and c_2_17 in_walk4_2 in_walk2_2)))
 (let (($x8237 (and c_2_16 in_walk4_2 in_walk2_2)))
 (let (($x8235 (and c_2_15 in_walk4_2 in_walk2_2)))
 (let (($x8233 (and c_2_14 in_walk4_2 in_walk2_2)))
 (let (($x8231 (and c_2_13 in_walk4_2 in_walk2_2)))
 (let (($x8229 (and c_2_12 in_walk4_2 in_walk2_2)))
 (let (($x8227 (and c_2_11 in_walk4_2 in_walk2_2)))
 (let (($x8225 (and c_2_10 in_walk4_2 in_walk2_2)))
 (let (($x8223 (and c_2_9 in_walk4_2 in_walk2_2)))
 (let (($x8221 (and c_2_8 in_walk4_2 in_walk2_2)))
 (let (($x8219 (and c_2_7 in_walk4_2 in_walk2_2)))
 (let (($x8217 (and c_2_6 in_walk4_2 in_walk2_2)))
 (let (($x8215 (and c_2_5 in_walk4_2 in_walk2_2)))
 (let (($x8213 (and c_2_4 in_walk4_2 in_walk2_2)))
 (let (($x8211 (and c_2_3 in_walk4_2 in_walk2_2)))
 (let (($x8209 (and c_2_2 in_walk4_2 in_walk2_2)))
 (let (($x8207 (and c_2_1 in_walk4_2 in_walk2_2)))
 (let (($x8206 (and c_2_0 in_walk4_2 in_walk2_2)))
 (let (($x8254 (or $x8206 $x8207 $x8209 $x8211 $x8213 $x8215 $x8217 $x8219 $x8221 $x8223 $x8225 $x8227 $x8229 $x8231 $x8233 $x8235 $x8237 $x8239 $x8241 $x8243 $x8245 $x8247 $x8249 $x8251 $x8253)))
 (let (($x8176 (and c_1_24 in_walk4_1 in_walk2_1)))
 (let (($x8174 (and c_1_23 in_walk4_1 in_walk2_1)))
 (let (($x8172 (and c_1_22 in_walk4_1 in_walk2_1)))
 (let (($x8170 (and c_1_21 in_walk4_1 in_walk2_1)))
 (let (($x8168 (and c_1_20 in_walk4_1 in_walk2_1)))
 (let (($x8166 (and c_1_19 in_walk4_1 in_walk2_1)))
 (let (($x8164 (and c_1_18 in_walk4_1 in_walk2_1)))
 (let (($x8162 (and c_1_17 in_walk4_1 in_walk2_1)))
 (let (($x8160 (and c_1_16 in_walk4_1 in_walk2_1)))
 (let (($x8158 (and c_1_15 in_walk4_1 in_walk2_1)))
 (let (($x8156 (and c_1_14 in_walk4_1 in_walk2_1)))
 (let (($x8154 (and c_1_13 in_walk4_1 in_walk2_1)))
 (let (($x8152 (and c_1_12 in_walk4_1 in_walk2_1)))
 (let (($x8150 (and c_1_11 in_walk4_1 in_walk2_1)))
 (let (($x8148 (and c_1_10 in_walk4_1 in_walk2_1)))
 (let (($x8146 (and c_1_9 in_walk4_1 in_walk2_1)))
 (let (($x8144 (and c_1_8 in_walk4_1 in_walk2_1)))
 (let (($x8142 (and c_1_7 in_walk4_1 in_walk2_1)))
 (let (($x8140 (and c_1_6 in_walk4_1 in_walk2_1)))
 (let (($x8138 (and c_1_5 in_walk4_1 in_walk2_1)))
 (let (($x8136 (and c_1_4 in_walk4_1 in_walk2_1)))
 (let (($x8134 (and c_1_3 in_walk4_1 in_walk2_1)))
 (let (($x8132 (and c_1_2 in_walk4_1 in_walk2_1)))
 (let (($x8130 (and c_1_1 in_walk4_1 in_walk2_1)))
 (let (($x8129 (and c_1_0 in_walk4_1 in_walk2_1)))
 (let (($x8177 (or $x8129 $x8130 $x8132 $x8134 $x8136 $x8138 $x8140 $x8142 $x8144 $x8146 $x8148 $x8150 $x8152 $x8154 $x8156 $x8158 $x8160 $x8162 $x8164 $x8166 $x8168 $x8170 $x8172 $x8174 $x8176)))
 (let (($x8099 (and c_0_24 in_walk4_0 in_walk2_0)))
 (let (($x8097 (and c_0_23 in_walk4_0 in_walk2_0)))
 (let (($x8095 (and c_0_22 in_walk4_0 in_walk2_0)))
 (let (($x8093 (and c_0_21 in_walk4_0 in_walk2_0)))
 (let (($x8091 (and c_0_20 in_walk4_0 in_walk2_0)))
 (let (($x8089 (and c_0_19 in_walk4_0 in_walk2_0)))
 (let (($x8087 (and c_0_18 in_walk4_0 in_walk2_0)))
 (let (($x8085 (and c_0_17 in_walk4_0 in_walk2_0)))
 (let (($x8083 (and c_0_16 in_walk4_0 in_walk2_0)))
 (let (($x8081 (and c_0_15 in_walk4_0 in_walk2_0)))
 (let (($x8079 (and c_0_14 in_walk4_0 in_walk2_0)))
 (let (($x8077 (and c_0_13 in_walk4_0 in_walk2_0)))
 (let (($x8075 (and c_0_12 in_walk4_0 in_walk2_0)))
 (let (($x8073 (and c_0_11 in_walk4_0 in_walk2_0)))
 (let (($x8071 (and c_0_10 in_walk4_0 in_walk2_0)))
 (let (($x8069 (and c_0_9 in_walk4_0 in_walk2_0)))
 (let (($x8067 (and c_0_8 in_walk4_0 in_walk2_0)))
 (let (($x8065 (and c_0_7 in_walk4_0 in_walk2_0)))
 (let (($x8063 (and c_0_6 in_walk4_0 in_walk2_0)))
 (let (($x8061 (and c_0_5 in_walk4_0 in_walk2_0)))
 (let (($x8059 (and c_0_4 in_walk4_0 in_walk2_0)))
 (let (($x8057 (and c_0_3 in_walk4_0 in_walk2_0)))
 (let (($x8055 (and c_0_2 in_walk4_0 in_walk2_0)))
 (let (($x8053 (and c_0_1 in_walk4_0 in_walk2_0)))
 (let (($x8052 (and c_0_0 in_walk4_0 in_walk2_0)))
 (let (($x8100 (or $x8052 $x8053 $x8055 $x8057 $x8059 $x8061 $x8063 $x8065 $x8067 $x8069 $x8071 $x8073 $x8075 $x8077 $x8079 $x8081 $x8083 $x8085 $x8087 $x8089 $x8091 $x8093 $x8095 $x8097 $x8099)))
 (let (($x8050 (or false $x8100)))
 (let (($x8127 (or $x8050 $x8177)))
 (let (($x8204 (or $x8127 $x8254)))
 (let (($x8019 (and c_3_24 in_walk3_3 in_walk2_3)))
 (let (($x8017 (and c_3_23 in_walk3_3 in_walk2_3)))
 (let (($x8015 (and c_3_22 in_walk3_3 in_walk2_3)))
 (let (($x8013 (and c_3_21 in_walk3_3 in_walk2_3)))
 (let (($x8011 (and c_3_20 in_walk3_3 in_walk2_3)))
 (let (($x8009 (and c_3_19 in_walk3_3 in_walk2_3)))
 (let (($x8007 (and c_3_18 in_walk3_3 in_walk2_3)))
 (let (($x8005 (and c_3_17 in_walk3_3 in_walk2_3)))
 (let (($x8003 (and c_3_16 in_walk3_3 in_walk2_3)))
 (let (($x8001 (and c_3_15 in_walk3_3 in_walk2_3)))
 (let (($x7999 (and c_3_14 in_walk3_3 in_walk2_3)))
 (let (($x7997 (and c_3_13 in_walk3_3 in_walk2_3)))
 (let (($x7995 (and c_3_12 in_walk3_3 in_walk2_3)))
 (let (($x7993 (and c_3_11 in_walk3_3 in_walk2_3)))
 (let (($x7991 (and c_3_10 in_walk3_3 in_walk2_3)))
 (let (($x7989 (and c_3_9 in_walk3_3 in_walk2_3)))
 (let (($x7987 (and c_3_8 in_walk3_3 in_walk2_3)))
 (let (($x7985 (and c_3_7 in_walk3_3 in_walk2_3)))
 (let (($x7983 (and c_3_6 in_walk3_3 in_walk2_3)))
 (let (($x7981 (and c_3_5 in_walk3_3 in_walk2_3)))
 (let (($x7979 (and c_3_4 in_walk3_3 in_walk2_3)))
 (let (($x7977 (and c_3_3 in_walk3_3 in_walk2_3)))
 (let (($x7975 (and c_3_2 in_walk3_3 in_walk2_3)))
 (let (($x7973 (and c_3_1 in_walk3_3 in_walk2_3)))
 (let (($x7972 (and c_3_0 in_walk3_3 in_walk2_3)))
 (let (($x8020 (or $x7972 $x7973 $x7975 $x7977 $x7979 $x7981 $x7983 $x7985 $x7987 $x7989 $x7991 $x7993 $x7995 $x7997 $x7999 $x8001 $x8003 $x8005 $x8007 $x8009 $x8011 $x8013 $x8015 $x8017 $x8019)))
 (let (($x7942 (and c_2_24 in_walk3_2 in_walk2_2)))
 (let (($x7940 (and c_2_23 in_walk3_2 in_walk2_2)))
 (let (($x7938 (and c_2_22 in_walk3_2 in_walk2_2)))
 (let (($x7936 (and c_2_21 in_walk3_2 in_walk2_2)))
 (let (($x7934 (and c_2_20 in_walk3_2 in_walk2_2)))
 (let (($x7932 (and c_2_19 in_walk3_2 in_walk2_2)))
 (let (($x7930 (and c_2_18 in_walk3_2 in_walk2_2)))
 (let (($x7928 (and c_2_17 in_walk3_2 in_walk2_2)))
 (let (($x7926 (and c_2_16 in_walk3_2 in_walk2_2)))
 (let (($x7924 (and c_2_15 in_walk3_2 in_walk2_2)))
 (let (($x7922 (and c_2_14 in_walk3_2 in_walk2_2)))
 (let (($x7920 (and c_2_13 in_walk3_2 in_walk2_2)))
 (let (($x7918 (and c_2_12 in_walk3_2 in_walk2_2)))
 (let (($x7916 (and c_2_11 in_walk3_2 in_walk2_2)))
 (let (($x7914 (and c_2_10 in_walk3_2 in_walk2_2)))
 (let (($x7912 (and c_2_9 in_walk3_2 in_walk2_2)))
 (let (($x7910 (and c_2_8 in_walk3_2 in_walk2_2)))
 (let (($x7908 (and c_2_7 in_walk3_2 in_walk2_2)))
 (let (($x7906 (and c_2_6 in_walk3_2 in_walk2_2)))
 (let (($x7904 (and c_2_5 in_walk3_2 in_walk2_2)))
 (let (($x7902 (and c_2_4 in_walk3_2 in_walk2_2)))
 (let (($x7900 (and c_2_3 in_walk3_2 in_walk2_2)))
 (let (($x7898 (and c_2_2 in_walk3_2 in_walk2_2)))
 (let (($x7896 (and c_2_1 in_walk3_2 in_walk2_2)))
 (let (($x7895 (and c_2_0 in_walk3_2 in_walk2_2)))
 (let (($x7943 (or $x7895 $x7896 $x7898 $x7900 $x7902 $x7904 $x7906 $x7908 $x7910 $x7912 $x7914 $x7916 $x7918 $x7920 $x7922 $x7924 $x7926 $x7928 $x7930 $x7932 $x7934 $x7936 $x7938 $x7940 $x7942)))
 (let (($x7865 (and c_1_24 in_walk3_1 in_walk2_1)))
 (let (($x7863 (and c_1_23 in_walk3_1 in_walk2_1)))
 (let (($x7861 (and c_1_22 in_walk3_1 in_walk2_1)))
 (let (($x7859 (and c_1_21 in_walk3_1 in_walk2_1)))
 (let (($x7857 (and c_1_20 in_walk3_1 in_walk2_1)))
 (let (($x7855 (and c_1_19 in_walk3_1 in_walk2_1)))
 (let (($x7853 (and c_1_18 in_walk3_1 in_walk2_1)))
 (let (($x7851 (and c_1_17 in_walk3_1 in_walk2_1)))
 (let (($x7849 (and c_1_16 in_walk3_1 in_walk2_1)))
 (let (($x7847 (and c_1_15 in_walk3_1 in_walk2_1)))
 (let (($x7845 (and c_1_14 in_walk3_1 in_walk2_1)))
 (let (($x7843 (and c_1_13 in_walk3_1 in_walk2_1)))
 (let (($x7841 (and c_1_12 in_walk3_1 in_walk2_1)))
 (let (($x7839 (and c_1_11 in_walk3_1 in_walk2_1)))
 (let (($x7837 (and c_1_10 in_walk3_1 in_walk2_1)))
 (let (($x7835 (and c_1_9 in_walk3_1 in_walk2_1)))
 (let (($x7833 (and c_1_8 in_walk3_1 in_walk2_1)))
 (let (($x7831 (and c_1_7 in_walk3_1 in_walk2_1)))
 (let (($x7829 (and c_1_6 in_walk3_1 in_walk2_1)))
 (let (($x7827 (and c_1_5 in_walk3_1 in_walk2_1)))
 (let (($x7825 (and c_1_4 in_walk3_1 in_walk2_1)))
 (let (($x7823 (and c_1_3 in_walk3_1 in_walk2_1)))
 (let (($x7821 (and c_1_2 in_walk3_1 in_walk2_1)))
 (let (($x7819 (and c_1_1 in_walk3_1 in_walk2_1)))
 (let (($x7818 (and c_1_0 in_walk3_1 in_walk2_1)))
 (let (($x7866 (or $x7818 $x7819 $x7821 $x7823 $x7825 $x7827 $x7829 $x7831 $x7833 $x7835 $x7837 $x7839 $x7841 $x7843 $x7845 $x7847 $x7849 $x7851 $x7853 $x7855 $x7857 $x7859 $x7861 $x7863 $x7865)))
 (let (($x7788 (and c_0_24 in_walk3_0 in_walk2_0)))
 (let (($x7786 (and c_0_23 in_walk3_0 in_walk2_0)))
 (let (($x7784 (and c_0_22 in_walk3_0 in_walk2_0)))
 (let (($x7782 (and c_0_21 in_walk3_0 in_walk2_0)))
 (let (($x7780 (and c_0_20 in_walk3_0 in_walk2_0)))
 (let (($x7778 (and c_0_19 in_walk3_0 in_walk2_0)))
 (let (($x7776 (and c_0_18 in_walk3_0 in_walk2_0)))
 (let (($x7774 (and c_0_17 in_walk3_0 in_walk2_0)))
 (let (($x7772 (and c_0_16 in_walk3_0 in_walk2_0)))
 (let (($x7770 (and c_0_15 in_walk3_0 in_walk2_0)))
 (let (($x7768 (and c_0_14 in_walk3_0 in_walk2_0)))
 (let (($x7766 (and c_0_13 in_walk3_0 in_walk2_0)))
 (let (($x7764 (and c_0_12 in_walk3_0 in_walk2_0)))
 (let (($x7762 (and c_0_11 in_walk3_0 in_walk2_0)))
 (let (($x7760 (and c_0_10 in_walk3_0 in_walk2_0)))
 (let (($x7758 (and c_0_9 in_walk3_0 in_walk2_0)))
 (let (($x7756 (and c_0_8 in_walk3_0 in_walk2_0)))
 (let (($x7754 (and c_0_7 in_walk3_0 in_walk2_0)))
 (let (($x7752 (and c_0_6 in_walk3_0 in_walk2_0)))
 (let (($x7750 (and c_0_5 in_walk3_0 in_walk2_0)))
 (let (($x7748 (and c_0_4 in_walk3_0 in_walk2_0)))
 (let (($x7746 (and c_0_3 in_walk3_0 in_walk2_0)))
 (let (($x7744 (and c_0_2 in_walk3_0 in_walk2_0)))
 (let (($x7742 (and c_0_1 in_walk3_0 in_walk2_0)))
 (let (($x7741 (and c_0_0 in_walk3_0 in_walk2_0)))
 (let (($x7789 (or $x7741 $x7742 $x7744 $x7746 $x7748 $x7750 $x7752 $x7754 $x7756 $x7758 $x7760 $x7762 $x7764 $x7766 $x7768 $x7770 $x7772 $x7774 $x7776 $x7778 $x7780 $x7782 $x7784 $x7786 $x7788)))
 (let (($x7739 (or false $x7789)))
 (let (($x7816 (or $x7739 $x7866)))
 (let (($x7893 (or $x7816 $x7943)))
 (let (($x7708 (and c_3_24 in_walk8_3 in_walk1_3)))
 (let (($x7706 (and c_3_23 in_walk8_3 in_walk1_3)))
 (let (($x7704 (and c_3_22 in_walk8_3 in_walk1_3)))
 (let (($x7702 (and c_3_21 in_walk8_3 in_walk1_3)))
 (let (($x7700 (and c_3_20 in_walk8_3 in_walk1_3)))
 (let (($x7698 (and c_3_19 in_walk8_3 in_walk1_3)))
 (let (($x7696 (and c_3_18 in_walk8_3 in_walk1_3)))
 (let (($x7694 (and c_3_17 in_walk8_3 in_walk1_3)))
 (let (($x7692 (and c_3_16 in_walk8_3 in_walk1_3)))
 (let (($x7690 (and c_3_15 in_walk8_3 in_walk1_3)))
 (let (($x7688 (and c_3_14 in_walk8_3 in_walk1_3)))
 (let (($x7686 (and c_3_13 in_walk8_3 in_walk1_3)))
 (let (($x7684 (and c_3_12 in_walk8_3 in_walk1_3)))
 (let (($x7682 (and c_3_11 in_walk8_3 in_walk1_3)))
 (let (($x7680 (and c_3_10 in_walk8_3 in_walk1_3)))
 (let (($x7678 (and c_3_9 in_walk8_3 in_walk1_3)))
 (let (($x7676 (and c_3_8 in_walk8_3 in_walk1_3)))
 (let (($x7674 (and c_3_7 in_walk8_3 in_walk1_3)))
 (let (($x7672 (and c_3_6 in_walk8_3 in_walk1_3)))
 (let (($x7670 (and c_3_5 in_walk8_3 in_walk1_3)))
 (let (($x7668 (and c_3_4 in_walk8_3 in_walk1_3)))
 (let (($x7666 (and c_3_3 in_walk8_3 in_walk1_3)))
 (let (($x7664 (and c_3_2 in_walk8_3 in_walk1_3)))
 (let (($x7662 (and c_3_1 in_walk8_3 in_walk1_3)))
 (let (($x7661 (and c_3_0 in_walk8_3 in_walk1_3)))
 (let (($x7709 (or $x7661 $x7662 $x7664 $x7666 $x7668 $x7670 $x7672 $x7674 $x7676 $x7678 $x7680 $x7682 $x7684 $x7686 $x7688 $x7690 $x7692 $x7694 $x7696 $x7698 $x7700 $x7702 $x7704 $x7706 $x7708)))
 (let (($x7631 (and c_2_24 in_walk8_2 in_walk1_2)))
 (let (($x7629 (and c_2_23 in_walk8_2 in_walk1_2)))
 (let (($x7627 (and c_2_22 in_walk8_2 in_walk1_2)))
 (let (($x7625 (and c_2_21 in_walk8_2 in_walk1_2)))
 (let (($x7623 (and c_2_20 in_walk8_2 in_walk1_2)))
 (let (($x7621 (and c_2_19 in_walk8_2 in_walk1_2)))
 (let (($x7619 (and c_2_18 in_walk8_2 in_walk1_2)))
 (let (($x7617 (and c_2_17 in_walk8_2 in_walk1_2)))
 (let (($x7615 (and c_2_16 in_walk8_2 in_walk1_2)))
 (let (($x7613 (and c_2_15 in_walk8_2 in_walk1_2)))
 (let (($x7611 (and c_2_14 in_walk8_2 in_walk1_2)))
 (let (($x7609 (and c_2_13 in_walk8_2 in_walk1_2)))
 (let (($x7607 (and c_2_12 in_walk8_2 in_walk1_2)))
 (let (($x7605 (and c_2_11 in_walk8_2 in_walk1_2)))
 (let (($x7603 (and c_2_10 in_walk8_2 in_walk1_2)))
 (let (($x7601 (and c_2_9 in_walk8_2 in_walk1_2)))
 (let (($x7599 (and c_2_8 in_walk8_2 in_walk1_2)))
 (let (($x7597 (and c_2_7 in_walk8_2 in_walk1_2)))
 (let (($x7595 (and c_2_6 in_walk8_2 in_walk1_2)))
 (let (($x7593 (and c_2_5 in_walk8_2 in_walk1_2)))
 (let (($x7591 (and c_2_4 in_walk8_2 in_walk1_2)))
 (let (($x7589 (and c_2_3 in_walk8_2 in_walk1_2)))
 (let (($x7587 (and c_2_2 in_walk8_2 in_walk1_2)))
 (let (($x7585 (and c_2_1 in_walk8_2 in_walk1_2)))
 (let (($x7584 (and c_2_0 in_walk8_2 in_walk1_2)))
 (let (($x7632 (or $x7584 $x7585 $x7587 $x7589 $x7591 $x7593 $x7595 $x7597 $x7599 $x7601 $x7603 $x7605 $x7607 $x7609 $x7611 $x7613 $x7615 $x7617 $x7619 $x7621 $x7623 $x7625 $x7627 $x7629 $x7631)))
 (let (($x7554 (and c_1_24 in_walk8_1 in_walk1_1)))
 (let (($x7552 (and c_1_23 in_walk8_1 in_walk1_1)))
 (let (($x7550 (and c_1_22 in_walk8_1 in_walk1_1)))
 (let (($x7548 (and c_1_21 in_walk8_1 in_walk1_1)))
 (let (($x7546 (and c_1_20 in_walk8_1 in_walk1_1)))
 (let (($x7544 (and c_1_19 in_walk8_1 in_walk1_1)))
 (let (($x7542 (and c_1_18 in_walk8_1 in_walk1_1)))
 (let (($x7540 (and c_1_17 in_walk8_1 in_walk1_1)))
 (let (($x7538 (and c_1_16 in_walk8_1 in_walk1_1)))
 (let (($x7536 (and c_1_15 in_walk8_1 in_walk1_1)))
 (let (($x7534 (and c_1_14 in_walk8_1 in_walk1_1)))
 (let (($x7532 (and c_1_13 in_walk8_1 in_walk1_1)))
 (let (($x7530 (and c_1_12 in_walk8_1 in_walk1_1)))
 (let (($x7528 (and c_1_11 in_walk8_1 in_walk1_1)))
 (let (($x7526 (and c_1_10 in_walk8_1 in_walk1_1)))
 (let (($x7524 (and c_1_9 in_walk8_1 in_walk1_1)))
 (let (($x7522 (and c_1_8 in_walk8_1 in_walk1_1)))
 (let (($x7520 (and c_1_7 in_walk8_1 in_walk1_1)))
 (let (($x7518 (and c_1_6 in_walk8_1 in_walk1_1)))
 (let (($x7516 (and c_1_5 in_walk8_1 in_walk1_1)))
 (let (($x7514 (and c_1_4 in_walk8_1 in_walk1_1)))
 (let (($x7512 (and c_1_3 in_walk8_1 in_walk1_1)))
 (let (($x7510 (and c_1_2 in_walk8_1 in_walk1_1)))
 (let (($x7508 (and c_1_1 in_walk8_1 in_walk1_1)))
 (let (($x7507 (and c_1_0 in_walk8_1 in_walk1_1)))
 (let (($x7555 (or $x7507 $x7508 $x7510 $x7512 $x7514 $x7516 $x7518 $x7520 $x7522 $x7524 $x7526 $x7528 $x7530 $x7532 $x7534 $x7536 $x7538 $x7540 $x7542 $x7544 $x7546 $x7548 $x7550 $x7552 $x7554)))
 (let (($x7477 (and c_0_24 in_walk8_0 in_walk1_0)))
 (let (($x7475 (and c_0_23 in_walk8_0 in_walk1_0)))
 (let (($x7473 (and c_0_22 in_walk8_0 in_walk1_0)))
 (let (($x7471 (and c_0_21 in_walk8_0 in_walk1_0)))
 (let (($x7469 (and c_0_20 in_walk8_0 in_walk1_0)))
 (let (($x7467 (and c_0_19 in_walk8_0 in_walk1_0)))
 (let (($x7465 (and c_0_18 in_walk8_0 in_walk1_0)))
 (let (($x7463 (and c_0_17 in_walk8_0 in_walk1_0)))
 (let (($x7461 (and c_0_16 in_walk8_0 in_walk1_0)))
 (let (($x7459 (and c_0_15 in_walk8_0 in_walk1_0)))
 (let (($x7457 (and c_0_14 in_walk8_0 in_walk1_0)))
 (let (($x7455 (and c_0_13 in_walk8_0 in_walk1_0)))
 (let (($x7453 (and c_0_12 in_walk8_0 in_walk1_0)))
 (let (($x7451 (and c_0_11 in_walk8_0 in_walk1_0)))
 (let (($x7449 (and c_0_10 in_walk8_0 in_walk1_0)))
 (let (($x7447 (and c_0_9 in_walk8_0 in_walk1_0)))
 (let (($x7445 (and c_0_8 in_walk8_0 in_walk1_0)))
 (let (($x7443 (and c_0_7 in_walk8_0 in_walk1_0)))
 (let (($x7441 (and c_0_6 in_walk8_0 in_walk1_0)))
 (let (($x7439 (and c_0_5 in_walk8_0 in_walk1_0)))
 (let (($x7437 (and c_0_4 in_walk8_0 in_walk1_0)))
 (let (($x7435 (and c_0_3 in_walk8_0 in_walk1_0)))
 (let (($x7433 (and c_0_2 in_walk8_0 in_walk1_0)))
 (let (($x7431 (and c_0_1 in_walk8_0 in_walk1_0)))
 (let (($x7430 (and c_0_0 in_walk8_0 in_walk1_0)))
 (let (($x7478 (or $x7430 $x7431 $x7433 $x7435 $x7437 $x7439 $x7441 $x7443 $x7445 $x7447 $x7449 $x7451 $x7453 $x7455 $x7457 $x7459 $x7461 $x7463 $x7465 $x7467 $x7469 $x7471 $x7473 $x7475 $x7477)))
 (let (($x7428 (or false $x7478)))
 (let (($x7505 (or $x7428 $x7555)))
 (let (($x7582 (or $x7505 $x7632)))
 (let (($x5456 (not (or (or (or (or false c_0_9) c_1_9) c_2_9) c_3_9))))
 (let (($x7389 (and c_3_24 in_walk7_3 in_walk1_3)))
 (let (($x7387 (and c_3_23 in_walk7_3 in_walk1_3)))
 (let (($x7385 (and c_3_22 in_walk7_3 in_walk1_3)))
 (let (($x7383 (and c_3_21 in_walk7_3 in_walk1_3)))
 (let (($x7381 (and c_3_20 in_walk7_3 in_walk1_3)))
 (let (($x7379 (and c_3_19 in_walk7_3 in_walk1_3)))
 (let (($x7377 (and c_3_18 in_walk7_3 in_walk1_3)))
 (let (($x7375 (and c_3_17 in_walk7_3 in_walk1_3)))
 (let (($x7373 (and c_3_16 in_walk7_3 in_walk1_3)))
 (let (($x7371 (and c_3_15 in_walk7_3 in_walk1_3)))
 (let (($x7369 (and c_3_14 in_walk7_3 in_walk1_3)))
 (let (($x7367 (and c_3_13 in_walk7_3 in_walk1_3)))
 (let (($x7365 (and c_3_12 in_walk7_3 in_walk1_3)))
 (let (($x7363 (and c_3_11 in_walk7_3 in_walk1_3)))
 (let (($x7361 (and c_3_10 in_walk7_3 in_walk1_3)))
 (let (($x7359 (and c_3_9 in_walk7_3 in_walk1_3)))
 (let (($x7357 (and c_3_8 in_walk7_3 in_walk1_3)))
 (let (($x7355 (and c_3_7 in_walk7_3 in_walk1_3)))
 (let (($x7353 (and c_3_6 in_walk7_3 in_walk1_3)))
 (let (($x7351 (and c_3_5 in_walk7_3 in_walk1_3)))
 (let (($x7349 (and c_3_4 in_walk7_3 in_walk1_3)))
 (let (($x7347 (and c_3_3 in_walk7_3 in_walk1_3)))
 (let (($x7345 (and c_3_2 in_walk7_3 in_walk1_3)))
 (let (($x7343 (and c_3_1 in_walk7_3 in_walk1_3)))
 (let (($x7342 (and c_3_0 in_walk7_3 in_walk1_3)))
 (let (($x7390 (or $x7342 $x7343 $x7345 $x7347 $x7349 $x7351 $x7353 $x7355 $x7357 $x7359 $x7361 $x7363 $x7365 $x7367 $x7369 $x7371 $x7373 $x7375 $x7377 $x7379 $x7381 $x7383 $x7385 $x7387 $x7389)))
 (let (($x7312 (and c_2_24 in_walk7_2 in_walk1_2)))
 (let (($x7310 (and c_2_23 in_walk7_2 in_walk1_2)))
 (let (($x7308 (and c_2_22 in_walk7_2 in_walk1_2)))
 (let (($x7306 (and c_2_21 in_walk7_2 in_walk1_2)))
 (let (($x7304 (and c_2_20 in_walk7_2 in_walk1_2)))
 (let (($x7302 (and c_2_19 in_walk7_2 in_walk1_2)))
 (let (($x7300 (and c_2_18 in_walk7_2 in_walk1_2)))
 (let (($x7298 (and c_2_17 in_walk7_2 in_walk1_2)))
 (let (($x7296 (and c_2_16 in_walk7_2 in_walk1_2)))
 (let (($x7294 (and c_2_15 in_walk7_2 in_walk1_2)))
 (let (($x7292 (and c_2_14 in_walk7_2 in_walk1_2)))
 (let (($x7290 (and c_2_13 in_walk7_2 in_walk1_2)))
 (let (($x7288 (and c_2_12 in_walk7_2 in_walk1_2)))
 (let (($x7286 (and c_2_11 in_walk7_2 in_walk1_2)))
 (let (($x7284 (and c_2_10 in_walk7_2 in_walk1_2)))
 (let (($x7282 (and c_2_9 in_walk7_2 in_walk1_2)))
 (let (($x7280 (and c_2_8 in_walk7_2 in_walk1_2)))
 (let (($x7278 (and c_2_7 in_walk7_2 in_walk1_2)))
 (let (($x7276 (and c_2_6 in_walk7_2 in_walk1_2)))
 (let (($x7274 (and c_2_5 in_walk7_2 in_walk1_2)))
 (let (($x7272 (and c_2_4 in_walk7_2 in_walk1_2)))
 (let (($x7270 (and c_2_3 in_walk7_2 in_walk1_2)))
 (let (($x7268 (and c_2_2 in_walk7_2 in_walk1_2)))
 (let (($x7266 (and c_2_1 in_walk7_2 in_walk1_2)))
 (let (($x7265 (and c_2_0 in_walk7_2 in_walk1_2)))
 (let (($x7313 (or $x7265 $x7266 $x7268 $x7270 $x7272 $x7274 $x7276 $x7278 $x7280 $x7282 $x7284 $x7286 $x7288 $x7290 $x7292 $x7294 $x7296 $x7298 $x7300 $x7302 $x7304 $x7306 $x7308 $x7310 $x7312)))
 (let (($x7235 (and c_1_24 in_walk7_1 in_walk1_1)))
 (let (($x7233 (and c_1_23 in_walk7_1 in_walk1_1)))
 (let (($x7231 (and c_1_22 in_walk7_1 in_walk1_1)))
 (let (($x7229 (and c_1_21 in_walk7_1 in_walk1_1)))
 (let (($x7227 (and c_1_20 in_walk7_1 in_walk1_1)))
 (let (($x7225 (and c_1_19 in_walk7_1 in_walk1_1)))
 (let (($x7223 (and c_1_18 in_walk7_1 in_walk1_1)))
 (let (($x7221 (and c_1_17 in_walk7_1 in_walk1_1)))
 (let (($x7219 (and c_1_16 in_walk7_1 in_walk1_1)))
 (let (($x7217 (and c_1_15 in_walk7_1 in_walk1_1)))
 (let (($x7215 (and c_1_14 in_walk7_1 in_walk1_1)))
 (let (($x7213 (and c_1_13 in_walk7_1 in_walk1_1)))
 (let (($x7211 (and c_1_12 in_walk7_1 in_walk1_1)))
 (let (($x7209 (and c_1_11 in_walk7_1 in_walk1_1)))
 (let (($x7207 (and c_1_10 in_walk7_1 in_walk1_1)))
 (let (($x7205 (and c_1_9 in_walk7_1 in_walk1_1)))
 (let (($x7203 (and c_1_8 in_walk7_1 in_walk1_1)))
 (let (($x7201 (and c_1_7 in_walk7_1 in_walk1_1)))
 (let (($x7199 (and c_1_6 in_walk7_1 in_walk1_1)))
 (let (($x7197 (and c_1_5 in_walk7_1 in_walk1_1)))
 (let (($x7195 (and c_1_4 in_walk7_1 in_walk1_1)))
 (let (($x7193 (and c_1_3 in_walk7_1 in_walk1_1)))
 (let (($x7191 (and c_1_2 in_walk7_1 in_walk1_1)))
 (let (($x7189 (and c_1_1 in_walk7_1 in_walk1_1)))
 (let (($x7188 (and c_1_0 in_walk7_1 in_walk1_1)))
 (let (($x7236 (or $x7188 $x7189 $x7191 $x7193 $x7195 $x7197 $x7199 $x7201 $x7203 $x7205 $x7207 $x7209 $x7211 $x7213 $x7215 $x7217 $x7219 $x7221 $x7223 $x7225 $x7227 $x7229 $x7231 $x7233 $x7235)))
 (let (($x7158 (and c_0_24 in_walk7_0 in_walk1_0)))
 (let (($x7156 (and c_0_23 in_walk7_0 in_walk1_0)))
 (let (($x7154 (and c_0_22 in_walk7_0 in_walk1_0)))
 (let (($x7152 (and c_0_21 in_walk7_0 in_walk1_0)))
 (let (($x7150 (and c_0_20 in_walk7_0 in_walk1_0)))
 (let (($x7148 (and c_0_19 in_walk7_0 in_walk1_0)))
 (let (($x7146 (and c_0_18 in_walk7_0 in_walk1_0)))
 (let (($x7144 (and c_0_17 in_walk7_0 in_walk1_0)))
 (let (($x7142 (and c_0_16 in_walk7_0 in_walk1_0)))
 (let (($x7140 (and c_0_15 in_walk7_0 in_walk1_0)))
 (let (($x7138 (and c_0_14 in_walk7_0 in_walk1_0)))
 (let (($x7136 (and c_0_13 in_walk7_0 in_walk1_0)))
 (let (($x7134 (and c_0_12 in_walk7_0 in_walk1_0)))
 (let (($x7132 (and c_0_11 in_walk7_0 in_walk1_0)))
 (let (($x7130 (and c_0_10 in_walk7_0 in_walk1_0)))
 (let (($x7128 (and c_0_9 in_walk7_0 in_walk1_0)))
 (let (($x7126 (and c_0_8 in_walk7_0 in_walk1_0)))
 (let (($x7124 (and c_0_7 in_walk7_0 in_walk1_0)))
 (let (($x7122 (and c_0_6 in_walk7_0 in_walk1_0)))
 (let (($x7120 (and c_0_5 in_walk7_0 in_walk1_0)))
 (let (($x7118 (and c_0_4 in_walk7_0 in_walk1_0)))
 (let (($x7116 (and c_0_3 in_walk7_0 in_walk1_0)))
 (let (($x7114 (and c_0_2 in_walk7_0 in_walk1_0)))
 (let (($x7112 (and c_0_1 in_walk7_0 in_walk1_0)))
 (let (($x7111 (and c_0_0 in_walk7_0 in_walk1_0)))
 (let (($x7159 (or $x7111 $x7112 $x7114 $x7116 $x7118 $x7120 $x7122 $x7124 $x7126 $x7128 $x7130 $x7132 $x7134 $x7136 $x7138 $x7140 $x7142 $x7144 $x7146 $x7148 $x7150 $x7152 $x7154 $x7156 $x7158)))
 (let (($x7109 (or false $x7159)))
 (let (($x7186 (or $x7109 $x7236)))
 (let (($x7263 (or $x7186 $x7313)))
 (let (($x7070 (and c_3_24 in_walk6_3 in_walk1_3)))
 (let (($x7068 (and c_3_23 in_walk6_3 in_walk1_3)))
 (let (($x7066 (and c_3_22 in_walk6_3 in_walk1_3)))
 (let (($x7064 (and c_3_21 in_walk6_3 in_walk1_3)))
 (let (($x7062 (and c_3_20 in_walk6_3 in_walk1_3)))
 (let (($x7060 (and c_3_19 in_walk6_3 in_walk1_3)))
 (let (($x7058 (and c_3_18 in_walk6_3 in_walk1_3)))
 (let (($x7056 (and c_3_17 in_walk6_3 in_walk1_3)))
 (let (($x7054 (and c_3_16 in_walk6_3 in_walk1_3)))
 (let (($x7052 (and c_3_15 in_walk6_3 in_walk1_3)))
 (let (($x7050 (and c_3_14 in_walk6_3 in_walk1_3)))
 (let (($x7048 (and c_3_13 in_walk6_3 in_walk1_3)))
 (let (($x7046 (and c_3_12 in_walk6_3 in_walk1_3)))
 (let (($x7044 (and c_3_11 in_walk6_3 in_walk1_3)))
 (let (($x7042 (and c_3_10 in_walk6_3 in_walk1_3)))
 (let (($x7040 (and c_3_9 in_walk6_3 in_walk1_3)))
 (let (($x7038 (and c_3_8 in_walk6_3 in_walk1_3)))
 (let (($x7036 (and c_3_7 in_walk6_3 in_walk1_3)))
 (let (($x7034 (and c_3_6 in_walk6_3 in_walk1_3)))
 (let (($x7032 (and c_3_5 in_walk6_3 in_walk1_3)))
 (let (($x7030 (and c_3_4 in_walk6_3 in_walk1_3)))
 (let (($x7028 (and c_3_3 in_walk6_3 in_walk1_3)))
 (let (($x7026 (and c_3_2 in_walk6_3 in_walk1_3)))
 (let (($x7024 (and c_3_1 in_walk6_3 in_walk1_3)))
 (let (($x7023 (and c_3_0 in_walk6_3 in_walk1_3)))
 (let (($x7071 (or $x7023 $x7024 $x7026 $x7028 $x7030 $x7032 $x7034 $x7036 $x7038 $x7040 $x7042 $x7044 $x7046 $x7048 $x7050 $x7052 $x7054 $x7056 $x7058 $x7060 $x7062 $x7064 $x7066 $x7068 $x7070)))
 (let (($x6993 (and c_2_24 in_walk6_2 in_walk1_2)))
 (let (($x6991 (and c_2_23 in_walk6_2 in_walk1_2)))
 (let (($x6989 (and c_2_22 in_walk6_2 in_walk1_2)))
 (let (($x6987 (and c_2_21 in_walk6_2 in_walk1_2)))
 (let (($x6985 (and c_2_20 in_walk6_2 in_walk1_2)))
 (let (($x6983 (and c_2_19 in_walk6_2 in_walk1_2)))
 (let (($x6981 (and c_2_18 in_walk6_2 in_walk1_2)))
 (let (($x6979 (and c_2_17 in_walk6_2 in_walk1_2)))
 (let (($x6977 (and c_2_16 in_walk6_2 in_walk1_2)))
 (let (($x6975 (and c_2_15 in_walk6_2 in_walk1_2)))
 (let (($x6973 (and c_2_14 in_walk6_2 in_walk1_2)))
 (let (($x6971 (and c_2_13 in_walk6_2 in_walk1_2)))
 (let (($x6969 (and c_2_12 in_walk6_2 in_walk1_2)))
 (let (($x6967 (and c_2_11 in_walk6_2 in_walk1_2)))
 (let (($x6965 (and c_2_10 in_walk6_2 in_walk1_2)))
 (let (($x6963 (and c_2_9 in_walk6_2 in_walk1_2)))
 (let (($x6961 (and c_2_8 in_walk6_2 in_walk1_2)))
 (let (($x6959 (and c_2_7 in_walk6_2 in_walk1_2)))
 (let (($x6957 (and c_2_6 in_walk6_2 in_walk1_2)))
 (let (($x6955 (and c_2_5 in_walk6_2 in_walk1_2)))
 (let (($x6953 (and c_2_4 in_walk6_2 in_walk1_2)))
 (let (($x6951 (and c_2_3 in_walk6_2 in_walk1_2)))
 (let (($x6949 (and c_2_2 in_walk6_2 in_walk1_2)))
 (let (($x6947 (and c_2_1 in_walk6_2 in_walk1_2)))
 (let (($x6946 (and c_2_0 in_walk6_2 in_walk1_2)))
 (let (($x6994 (or $x6946 $x6947 $x6949 $x6951 $x6953 $x6955 $x6957 $x6959 $x6961 $x6963 $x6965 $x6967 $x6969 $x6971 $x6973 $x6975 $x6977 $x6979 $x6981 $x6983 $x6985 $x6987 $x6989 $x6991 $x6993)))
 (let (($x6916 (and c_1_24 in_walk6_1 in_walk1_1)))
 (let (($x6914 (and c_1_23 in_walk6_1 in_walk1_1)))
 (let (($x6912 (and c_1_22 in_walk6_1 in_walk1_1)))
 (let (($x6910 (and c_1_21 in_walk6_1 in_walk1_1)))
 (let (($x6908 (and c_1_20 in_walk6_1 in_walk1_1)))
 (let (($x6906 (and c_1_19 in_walk6_1 in_walk1_1)))
 (let (($x6904 (and c_1_18 in_walk6_1 in_walk1_1)))
 (let (($x6902 (and c_1_17 in_walk6_1 in_walk1_1)))
 (let (($x6900 (and c_1_16 in_walk6_1 in_walk1_1)))
 (let (($x6898 (and c_1_15 in_walk6_1 in_walk1_1)))
 (let (($x6896 (and c_1_14 in_walk6_1 in_walk1_1)))
 (let (($x6894 (and c_1_13 in_walk6_1 in_walk1_1)))
 (let (($x6892 (and c_1_12 in_walk6_1 in_walk1_1)))
 (let (($x6890 (and c_1_11 in_walk6_1 in_walk1_1)))
 (let (($x6888 (and c_1_10 in_walk6_1 in_walk1_1)))
 (let (($x6886 (and c_1_9 in_walk6_1 in_walk1_1)))
 (let (($x6884 (and c_1_8 in_walk6_1 in_walk1_1)))
 (let (($x6882 (and c_1_7 in_walk6_1 in_walk1_1)))
 (let (($x6880 (and c_1_6 in_walk6_1 in_walk1_1)))
 (let (($x6878 (and c_1_5 in_walk6_1 in_walk1_1)))
 (let (($x6876 (and c_1_4 in_walk6_1 in_walk1_1)))
 (let (($x6874 (and c_1_3 in_walk6_1 in_walk1_1)))
 (let (($x6872 (and c_1_2 in_walk6_1 in_walk1_1)))
 (let (($x6870 (and c_1_1 in_walk6_1 in_walk1_1)))
 (let (($x6869 (and c_1_0 in_walk6_1 in_walk1_1)))
 (let (($x6917 (or $x6869 $x6870 $x6872 $x6874 $x6876 $x6878 $x6880 $x6882 $x6884 $x6886 $x6888 $x6890 $x6892 $x6894 $x6896 $x6898 $x6900 $x6902 $x6904 $x6906 $x6908 $x6910 $x6912 $x6914 $x6916)))
 (let (($x6839 (and c_0_24 in_walk6_0 in_walk1_0)))
 (let (($x6837 (and c_0_23 in_walk6_0 in_walk1_0)))
 (let (($x6835 (and c_0_22 in_walk6_0 in_walk1_0)))
 (let (($x6833 (and c_0_21 in_walk6_0 in_walk1_0)))
 (let (($x6831 (and c_0_20 in_walk6_0 in_walk1_0)))
 (let (($x6829 (and c_0_19 in_walk6_0 in_walk1_0)))
 (let (($x6827 (and c_0_18 in_walk6_0 in_walk1_0)))
 (let (($x6825 (and c_0_17 in_walk6_0 in_walk1_0)))
 (let (($x6823 (and c_0_16 in_walk6_0 in_walk1_0)))
 (let (($x6821 (and c_0_15 in_walk6_0 in_walk1_0)))
 (let (($x6819 (and c_0_14 in_walk6_0 in_walk1_0)))
 (let (($x6817 (and c_0_13 in_walk6_0 in_walk1_0)))
 (let (($x6815 (and c_0_12 in_walk6_0 in_walk1_0)))
 (let (($x6813 (and c_0_11 in_walk6_0 in_walk1_0)))
 (let (($x6811 (and c_0_10 in_walk6_0 in_walk1_0)))
 (let (($x6809 (and c_0_9 in_walk6_0 in_walk1_0)))
 (let (($x6807 (and c_0_8 in_walk6_0 in_walk1_0)))
 (let (($x6805 (and c_0_7 in_walk6_0 in_walk1_0)))
 (let (($x6803 (and c_0_6 in_walk6_0 in_walk1_0)))
 (let (($x6801 (and c_0_5 in_walk6_0 in_walk1_0)))
 (let (($x6799 (and c_0_4 in_walk6_0 in_walk1_0)))
 (let (($x6797 (and c_0_3 in_walk6_0 in_walk1_0)))
 (let (($x6795 (and c_0_2 in_walk6_0 in_walk1_0)))
 (let (($x6793 (and c_0_1 in_walk6_0 in_walk1_0)))
 (let (($x6792 (and c_0_0 in_walk6_0 in_walk1_0)))
 (let (($x6840 (or $x6792 $x6793 $x6795 $x6797 $x6799 $x6801 $x6803 $x6805 $x6807 $x6809 $x6811 $x6813 $x6815 $x6817 $x6819 $x6821 $x6823 $x6825 $x6827 $x6829 $x6831 $x6833 $x6835 $x6837 $x6839)))
 (let (($x6790 (or false $x6840)))
 (let (($x6867 (or $x6790 $x6917)))
 (let (($x6944 (or $x6867 $x6994)))
 (let (($x6751 (and c_3_24 in_walk5_3 in_walk1_3)))
 (let (($x6749 (and c_3_23 in_walk5_3 in_walk1_3)))
 (let (($x6747 (and c_3_22 in_walk5_3 in_walk1_3)))
 (let (($x6745 (and c_3_21 in_walk5_3 in_walk1_3)))
 (let (($x6743 (and c_3_20 in_walk5_3 in_walk1_3)))
 (let (($x6741 (and c_3_19 in_walk5_3 in_walk1_3)))
 (let (($x6739 (and c_3_18 in_walk5_3 in_walk1_3)))
 (let (($x6737 (and c_3_17 in_walk5_3 in_walk1_3)))
 (let (($x6735 (and c_3_16 in_walk5_3 in_walk1_3)))
 (let (($x6733 (and c_3_15 in_walk5_3 in_walk1_3)))
 (let (($x6731 (and c_3_14 in_walk5_3 in_walk1_3)))
 (let (($x6729 (and c_3_13 in_walk5_3 in_walk1_3)))
 (let (($x6727 (and c_3_12 in_walk5_3 in_walk1_3)))
 (let (($x6725 (and c_3_11 in_walk5_3 in_walk1_3)))
 (let (($x6723 (and c_3_10 in_walk5_3 in_walk1_3)))
 (let (($x6721 (and c_3_9 in_walk5_3 in_walk1_3)))
 (let (($x6719 (and c_3_8 in_walk5_3 in_walk1_3)))
 (let (($x6717 (and c_3_7 in_walk5_3 in_walk1_3)))
 (let (($x6715 (and c_3_6 in_walk5_3 in_walk1_3)))
 (let (($x6713 (and c_3_5 in_walk5_3 in_walk1_3)))
 (let (($x6711 (and c_3_4 in_walk5_3 in_walk1_3)))
 (let (($x6709 (and c_3_3 in_walk5_3 in_walk1_3)))
 (let (($x6707 (and c_3_2 in_walk5_3 in_walk1_3)))
 (let (($x6705 (and c_3_1 in_walk5_3 in_walk1_3)))
 (let (($x6704 (and c_3_0 in_walk5_3 in_walk1_3)))
 (let (($x6752 (or $x6704 $x6705 $x6707 $x6709 $x6711 $x6713 $x6715 $x6717 $x6719 $x6721 $x6723 $x6725 $x6727 $x6729 $x6731 $x6733 $x6735 $x6737 $x6739 $x6741 $x6743 $x6745 $x6747 $x6749 $x6751)))
 (let (($x6674 (and c_2_24 in_walk5_2 in_walk1_2)))
 (let (($x6672 (and c_2_23 in_walk5_2 in_walk1_2)))
 (let (($x6670 (and c_2_22 in_walk5_2 in_walk1_2)))
 (let (($x6668 (and c_2_21 in_walk5_2 in_walk1_2)))
 (let (($x6666 (and c_2_20 in_walk5_2 in_walk1_2)))
 (let (($x6664 (and c_2_19 in_walk5_2 in_walk1_2)))
 (let (($x6662 (and c_2_18 in_walk5_2 in_walk1_2)))
 (let (($x6660 (and c_2_17 in_walk5_2 in_walk1_2)))
 (let (($x6658 (and c_2_16 in_walk5_2 in_walk1_2)))
 (let (($x6656 (and c_2_15 in_walk5_2 in_walk1_2)))
 (let (($x6654 (and c_2_14 in_walk5_2 in_walk1_2)))
 (let (($x6652 (and c_2_13 in_walk5_2 in_walk1_2)))
 (let (($x6650 (and c_2_12 in_walk5_2 in_walk1_2)))
 (let (($x6648 (and c_2_11 in_walk5_2 in_walk1_2)))
 (let (($x6646 (and c_2_10 in_walk5_2 in_walk1_2)))
 (let (($x6644 (and c_2_9 in_walk5_2 in_walk1_2)))
 (let (($x6642 (and c_2_8 in_walk5_2 in_walk1_2)))
 (let (($x6640 (and c_2_7 in_walk5_2 in_walk1_2)))
 (let (($x6638 (and c_2_6 in_walk5_2 in_walk1_2)))
 (let (($x6636 (and c_2_5 in_walk5_2 in_walk1_2)))
 (let (($x6634 (and c_2_4 in_walk5_2 in_walk1_2)))
 (let (($x6632 (and c_2_3 in_walk5_2 in_walk1_2)))
 (let (($x6630 (and c_2_2 in_walk5_2 in_walk1_2)))
 (let (($x6628 (and c_2_1 in_walk5_2 in_walk1_2)))
 (let (($x6627 (and c_2_0 in_walk5_2 in_walk1_2)))
 (let (($x6675 (or $x6627 $x6628 $x6630 $x6632 $x6634 $x6636 $x6638 $x6640 $x6642 $x6644 $x6646 $x6648 $x6650 $x6652 $x6654 $x6656 $x6658 $x6660 $x6662 $x6664 $x6666 $x6668 $x6670 $x6672 $x6674)))
 (let (($x6597 (and c_1_24 in_walk5_1 in_walk1_1)))
 (let (($x6595 (and c_1_23 in_walk5_1 in_walk1_1)))
 (let (($x6593 (and c_1_22 in_walk5_1 in_walk1_1)))
 (let (($x6591 (and c_1_21 in_walk5_1 in_walk1_1)))
 (let (($x6589 (and c_1_20 in_walk5_1 in_walk1_1)))
 (let (($x6587 (and c_1_19 in_walk5_1 in_walk1_1)))
 (let (($x6585 (and c_1_18 in_walk5_1 in_walk1_1)))
 (let (($x6583 (and c_1_17 in_walk5_1 in_walk1_1)))
 (let (($x6581 (and c_1_16 in_walk5_1 in_walk1_1)))
 (let (($x6579 (and c_1_15 in_walk5_1 in_walk1_1)))
 (let (($x6577 (and c_1_14 in_walk5_1 in_walk1_1)))
 (let (($x6575 (and c_1_13 in_walk5_1 in_walk1_1)))
 (let (($x6573 (and c_1_12 in_walk5_1 in_walk1_1)))
 (let (($x6571 (and c_1_11 in_walk5_1 in_walk1_1)))
 (let (($x6569 (and c_1_10 in_walk5_1 in_walk1_1)))
 (let (($x6567 (and c_1_9 in_walk5_1 in_walk1_1)))
 (let (($x6565 (and c_1_8 in_walk5_1 in_walk1_1)))
 (let (($x6563 (and c_1_7 in_walk5_1 in_walk1_1)))
 (let (($x6561 (and c_1_6 in_walk5_1 in_walk1_1)))
 (let (($x6559 (and c_1_5 in_walk5_1 in_walk1_1)))
 (let (($x6557 (and c_1_4 in_walk5_1 in_walk1_1)))
 (let (($x6555 (and c_1_3 in_walk5_1 in_walk1_1)))
 (let (($x6553 (and c_1_2 in_walk5_1 in_walk1_1)))
 (let (($x6551 (and c_1_1 in_walk5_1 in_walk1_1)))
 (let (($x6550 (and c_1_0 in_walk5_1 in_walk1_1)))
 (let (($x6598 (or $x6550 $x6551 $x6553 $x6555 $x6557 $x6559 $x6561 $x6563 $x6565 $x6567 $x6569 $x6571 $x6573 $x6575 $x6577 $x6579 $x6581 $x6583 $x6585 $x6587 $x6589 $x6591 $x6593 $x6595 $x6597)))
 (let (($x6520 (and c_0_24 in_walk5_0 in_walk1_0)))
 (let (($x6518 (and c_0_23 in_walk5_0 in_walk1_0)))
 (let (($x6516 (and c_0_22 in_walk5_0 in_walk1_0)))
 (let (($x6514 (and c_0_21 in_walk5_0 in_walk1_0)))
 (let (($x6512 (and c_0_20 in_walk5_0 in_walk1_0)))
 (let (($x6510 (and c_0_19 in_walk5_0 in_walk1_0)))
 (let (($x6508 (and c_0_18 in_walk5_0 in_walk1_0)))
 (let (($x6506 (and c_0_17 in_walk5_0 in_walk1_0)))
 (let (($x6504 (and c_0_16 in_walk5_0 in_walk1_0)))
 (let (($x6502 (and c_0_15 in_walk5_0 in_walk1_0)))
 (let (($x6500 (and c_0_14 in_walk5_0 in_walk1_0)))
 (let (($x6498 (and c_0_13 in_walk5_0 in_walk1_0)))
 (let (($x6496 (and c_0_12 in_walk5_0 in_walk1_0)))
 (let (($x6494 (and c_0_11 in_walk5_0 in_walk1_0)))
 (let (($x6492 (and c_0_10 in_walk5_0 in_walk1_0)))
 (let (($x6490 (and c_0_9 in_walk5_0 in_walk1_0)))
 (let (($x6488 (and c_0_8 in_walk5_0 in_walk1_0)))
 (let (($x6486 (and c_0_7 in_walk5_0 in_walk1_0)))
 (let (($x6484 (and c_0_6 in_walk5_0 in_walk1_0)))
 (let (($x6482 (and c_0_5 in_walk5_0 in_walk1_0)))
 (let (($x6480 (and c_0_4 in_walk5_0 in_walk1_0)))
 (let (($x6478 (and c_0_3 in_walk5_0 in_walk1_0)))
 (let (($x6476 (and c_0_2 in_walk5_0 in_walk1_0)))
 (let (($x6474 (and c_0_1 in_walk5_0 in_walk1_0)))
 (let (($x6473 (and c_0_0 in_walk5_0 in_walk1_0)))
 (let (($x6521 (or $x6473 $x6474 $x6476 $x6478 $x6480 $x6482 $x6484 $x6486 $x6488 $x6490 $x6492 $x6494 $x6496 $x6498 $x6500 $x6502 $x6504 $x6506 $x6508 $x6510 $x6512 $x6514 $x6516 $x6518 $x6520)))
 (let (($x6471 (or false $x6521)))
 (let (($x6548 (or $x6471 $x6598)))
 (let (($x6625 (or $x6548 $x6675)))
 (let (($x6432 (and c_3_24 in_walk4_3 in_walk1_3)))
 (let (($x6430 (and c_3_23 in_walk4_3 in_walk1_3)))
 (let (($x6428 (and c_3_22 in_walk4_3 in_walk1_3)))
 (let (($x6426 (and c_3_21 in_walk4_3 in_walk1_3)))
 (let (($x6424 (and c_3_20 in_walk4_3 in_walk1_3)))
 (let (($x6422 (and c_3_19 in_walk4_3 in_walk1_3)))
 (let (($x6420 (and c_3_18 in_walk4_3 in_walk1_3)))
 (let (($x6418 (and c_3_17 in_walk4_3 in_walk1_3)))
 (let (($x6416 (and c_3_16 in_walk4_3 in_walk1_3)))
 (let (($x6414 (and c_3_15 in_walk4_3 in_walk1_3)))
 (let (($x6412 (and c_3_14 in_walk4_3 in_walk1_3)))
 (let (($x6410 (and c_3_13 in_walk4_3 in_walk1_3)))
 (let (($x6408 (and c_3_12 in_walk4_3 in_walk1_3)))
 (let (($x6406 (and c_3_11 in_walk4_3 in_walk1_3)))
 (let (($x6404 (and c_3_10 in_walk4_3 in_walk1_3)))
 (let (($x6402 (and c_3_9 in_walk4_3 in_walk1_3)))
 (let (($x6400 (and c_3_8 in_walk4_3 in_walk1_3)))
 (let (($x6398 (and c_3_7 in_walk4_3 in_walk1_3)))
 (let (($x6396 (and c_3_6 in_walk4_3 in_walk1_3)))
 (let (($x6394 (and c_3_5 in_walk4_3 in_walk1_3)))
 (let (($x6392 (and c_3_4 in_walk4_3 in_walk1_3)))
 (let (($x6390 (and c_3_3 in_walk4_3 in_walk1_3)))
 (let (($x6388 (and c_3_2 in_walk4_3 in_walk1_3)))
 (let (($x6386 (and c_3_1 in_walk4_3 in_walk1_3)))
 (let (($x6385 (and c_3_0 in_walk4_3 in_walk1_3)))
 (let (($x6433 (or $x6385 $x6386 $x6388 $x6390 $x6392 $x6394 $x6396 $x6398 $x6400 $x6402 $x6404 $x6406 $x6408 $x6410 $x6412 $x6414 $x6416 $x6418 $x6420 $x6422 $x6424 $x6426 $x6428 $x6430 $x6432)))
 (let (($x6355 (and c_2_24 in_walk4_2 in_walk1_2)))
 (let (($x6353 (and c_2_23 in_walk4_2 in_walk1_2)))
 (let (($x6351 (and c_2_22 in_walk4_2 in_walk1_2)))
 (let (($x6349 (and c_2_21 in_walk4_2 in_walk1_2)))
 (let (($x6347 (and c_2_20 in_walk4_2 in_walk1_2)))
 (let (($x6345 (and c_2_19 in_walk4_2 in_walk1_2)))
 (let (($x6343 (and c_2_18 in_walk4_2 in_walk1_2)))
 (let (($x6341 (and c_2_17 in_walk4_2 in_walk1_2)))
 (let (($x6339 (and c_2_16 in_walk4_2 in_walk1_2)))
 (let (($x6337 (and c_2_15 in_walk4_2 in_walk1_2)))
 (let (($x6335 (and c_2_14 in_walk4_2 in_walk1_2)))
 (let (($x6333 (and c_2_13 in_walk4_2 in_walk1_2)))
 (let (($x6331 (and c_2_12 in_walk4_2 in_walk1_2)))
 (let (($x6329 (and c_2_11 in_walk4_2 in_walk1_2)))
 (let (($x6327 (and c_2_10 in_walk4_2 in_walk1_2)))
 (let (($x6325 (and c_2_9 in_walk4_2 in_walk1_2)))
 (let (($x6323 (and c_2_8 in_walk4_2 in_walk1_2)))
 (let (($x6321 (and c_2_7 in_walk4_2 in_walk1_2)))
 (let (($x6319 (and c_2_6 in_walk4_2 in_walk1_2)))
 (let (($x6317 (and c_2_5 in_walk4_2 in_walk1_2)))
 (let (($x6315 (and c_2_4 in_walk4_2 in_walk1_2)))
 (let (($x6313 (and c_2_3 in_walk4_2 in_walk1_2)))
 (let (($x6311 (and c_2_2 in_walk4_2 in_walk1_2)))
 (let (($x6309 (and c_2_1 in_walk4_2 in_walk1_2)))
 (let (($x6308 (and c_2_0 in_walk4_2 in_walk1_2)))
 (let (($x6356 (or $x6308 $x6309 $x6311 $x6313 $x6315 $x6317 $x6319 $x6321 $x6323 $x6325 $x6327 $x6329 $x6331 $x6333 $x6335 $x6337 $x6339 $x6341 $x6343 $x6345 $x6347 $x6349 $x6351 $x6353 $x6355)))
 (let (($x6278 (and c_1_24 in_walk4_1 in_walk1_1)))
 (let (($x6276 (and c_1_23 in_walk4_1 in_walk1_1)))
 (let (($x6274 (and c_1_22 in_walk4_1 in_walk1_1)))
 (let (($x6272 (and c_1_21 in_walk4_1 in_walk1_1)))
 (let (($x6270 (and c_1_20 in_walk4_1 in_walk1_1)))
 (let (($x6268 (and c_1_19 in_walk4_1 in_walk1_1)))
 (let (($x6266 (and c_1_18 in_walk4_1 in_walk1_1)))
 (let (($x6264 (and c_1_17 in_walk4_1 in_walk1_1)))
 (let (($x6262 (and c_1_16 in_walk4_1 in_walk1_1)))
 (let (($x6260 (and c_1_15 in_walk4_1 in_walk1_1)))
 (let (($x6258 (and c_1_14 in_walk4_1 in_walk1_1)))
 (let (($x6256 (and c_1_13 in_walk4_1 in_walk1_1)))
 (let (($x6254 (and c_1_12 in_walk4_1 in_walk1_1)))
 (let (($x6252 (and c_1_11 in_walk4_1 in_walk1_1)))
 (let (($x6250 (and c_1_10 in_walk4_1 in_walk1_1)))
 (let (($x6248 (and c_1_9 in_walk4_1 in_walk1_1)))
 (let (($x6246 (and c_1_8 in_walk4_1 in_walk1_1)))
 (let (($x6244 (and c_1_7 in_walk4_1 in_walk1_1)))
 (let (($x6242 (and c_1_6 in_walk4_1 in_walk1_1)))
 (let (($x6240 (and c_1_5 in_walk4_1 in_walk1_1)))
 (let (($x6238 (and c_1_4 in_walk4_1 in_walk1_1)))
 (let (($x6236 (and c_1_3 in_walk4_1 in_walk1_1)))
 (let (($x6234 (and c_1_2 in_walk4_1 in_walk1_1)))
 (let (($x6232 (and c_1_1 in_walk4_1 in_walk1_1)))
 (let (($x6231 (and c_1_0 in_walk4_1 in_walk1_1)))
 (let (($x6279 (or $x6231 $x6232 $x6234 $x6236 $x6238 $x6240 $x6242 $x6244 $x6246 $x6248 $x6250 $x6252 $x6254 $x6256 $x6258 $x6260 $x6262 $x6264 $x6266 $x6268 $x6270 $x6272 $x6274 $x6276 $x6278)))
 (let (($x6201 (and c_0_24 in_walk4_0 in_walk1_0)))
 (let (($x6199 (and c_0_23 in_walk4_0 in_walk1_0)))
 (let (($x6197 (and c_0_22 in_walk4_0 in_walk1_0)))
 (let (($x6195 (and c_0_21 in_walk4_0 in_walk1_0)))
 (let (($x6193 (and c_0_20 in_walk4_0 in_walk1_0)))
 (let (($x6191 (and c_0_19 in_walk4_0 in_walk1_0)))
 (let (($x6189 (and c_0_18 in_walk4_0 in_walk1_0)))
 (let (($x6187 (and c_0_17 in_walk4_0 in_walk1_0)))
 (let (($x6185 (and c_0_16 in_walk4_0 in_walk1_0)))
 (let (($x6183 (and c_0_15 in_walk4_0 in_walk1_0)))
 (let (($x6181 (and c_0_14 in_walk4_0 in_walk1_0)))
 (let (($x6179 (and c_0_13 in_walk4_0 in_walk1_0)))
 (let (($x6177 (and c_0_12 in_walk4_0 in_walk1_0)))
 (let (($x6175 (and c_0_11 in_walk4_0 in_walk1_0)))
 (let (($x6173 (and c_0_10 in_walk4_0 in_walk1_0)))
 (let (($x6171 (and c_0_9 in_walk4_0 in_walk1_0)))
 (let (($x6169 (and c_0_8 in_walk4_0 in_walk1_0)))
 (let (($x6167 (and c_0_7 in_walk4_0 in_walk1_0)))
 (let (($x6165 (and c_0_6 in_walk4_0 in_walk1_0)))
 (let (($x6163 (and c_0_5 in_walk4_0 in_walk1_0)))
 (let (($x6161 (and c_0_4 in_walk4_0 in_walk1_0)))
 (let (($x6159 (and c_0_3 in_walk4_0 in_walk1_0)))
 (let (($x6157 (and c_0_2 in_walk4_0 in_walk1_0)))
 (let (($x6155 (and c_0_1 in_walk4_0 in_walk1_0)))
 (let (($x6154 (and c_0_0 in_walk4_0 in_walk1_0)))
 (let (($x6202 (or $x6154 $x6155 $x6157 $x6159 $x6161 $x6163 $x6165 $x6167 $x6169 $x6171 $x6173 $x6175 $x6177 $x6179 $x6181 $x6183 $x6185 $x6187 $x6189 $x6191 $x6193 $x6195 $x6197 $x6199 $x6201)))
 (let (($x6152 (or false $x6202)))
 (let (($x6229 (or $x6152 $x6279)))
 (let (($x6306 (or $x6229 $x6356)))
 (let (($x6113 (and c_3_24 in_walk3_3 in_walk1_3)))
 (let (($x6111 (and c_3_23 in_walk3_3 in_walk1_3)))
 (let (($x6109 (and c_3_22 in_walk3_3 in_walk1_3)))
 (let (($x6107 (and c_3_21 in_walk3_3 in_walk1_3)))
 (let (($x6105 (and c_3_20 in_walk3_3 in_walk1_3)))
 (let (($x6103 (and c_3_19 in_walk3_3 in_walk1_3)))
 (let (($x6101 (and c_3_18 in_walk3_3 in_walk1_3)))
 (let (($x6099 (and c_3_17 in_walk3_3 in_walk1_3)))
 (let (($x6097 (and c_3_16 in_walk3_3 in_walk1_3)))
 (let (($x6095 (and c_3_15 in_walk3_3 in_walk1_3)))
 (let (($x6093 (and c_3_14 in_walk3_3 in_walk1_3)))
 (let (($x6091 (and c_3_13 in_walk3_3 in_walk1_3)))
 (let (($x6089 (and c_3_12 in_walk3_3 in_walk1_3)))
 (let (($x6087 (and c_3_11 in_walk3_3 in_walk1_3)))
 (let (($x6085 (and c_3_10 in_walk3_3 in_walk1_3)))
 (let (($x6083 (and c_3_9 in_walk3_3 in_walk1_3)))
 (let (($x6081 (and c_3_8 in_walk3_3 in_walk1_3)))
 (let (($x6079 (and c_3_7 in_walk3_3 in_walk1_3)))
 (let (($x6077 (and c_3_6 in_walk3_3 in_walk1_3)))
 (let (($x6075 (and c_3_5 in_walk3_3 in_walk1_3)))
 (let (($x6073 (and c_3_4 in_walk3_3 in_walk1_3)))
 (let (($x6071 (and c_3_3 in_walk3_3 in_walk1_3)))
 (let (($x6069 (and c_3_2 in_walk3_3 in_walk1_3)))
 (let (($x6067 (and c_3_1 in_walk3_3 in_walk1_3)))
 (let (($x6066 (and c_3_0 in_walk3_3 in_walk1_3)))
 (let (($x6114 (or $x6066 $x6067 $x6069 $x6071 $x6073 $x6075 $x6077 $x6079 $x6081 $x6083 $x6085 $x6087 $x6089 $x6091 $x6093 $x6095 $x6097 $x6099 $x6101 $x6103 $x6105 $x6107 $x6109 $x6111 $x6113)))
 (let (($x6036 (and c_2_24 in_walk3_2 in_walk1_2)))
 (let (($x6034 (and c_2_23 in_walk3_2 in_walk1_2)))
 (let (($x6032 (and c_2_22 in_walk3_2 in_walk1_2)))
 (let (($x6030 (and c_2_21 in_walk3_2 in_walk1_2)))
 (let (($x6028 (and c_2_20 in_walk3_2 in_walk1_2)))
 (let (($x6026 (and c_2_19 in_walk3_2 in_walk1_2)))
 (let (($x6024 (and c_2_18 in_walk3_2 in_walk1_2)))
 (let (($x6022 (and c_2_17 in_walk3_2 in_walk1_2)))
 (let (($x6020 (and c_2_16 in_walk3_2 in_walk1_2)))
 (let (($x6018 (and c_2_15 in_walk3_2 in_walk1_2)))
 (let (($x6016 (and c_2_14 in_walk3_2 in_walk1_2)))
 (let (($x6014 (and c_2_13 in_walk3_2 in_walk1_2)))
 (let (($x6012 (and c_2_12 in_walk3_2 in_walk1_2)))
 (let (($x6010 (and c_2_11 in_walk3_2 in_walk1_2)))
 (let (($x6008 (and c_2_10 in_walk3_2 in_walk1_2)))
 (let (($x6006 (and c_2_9 in_walk3_2 in_walk1_2)))
 (let (($x6004 (and c_2_8 in_walk3_2 in_walk1_2)))
 (let (($x6002 (and c_2_7 in_walk3_2 in_walk1_2)))
 (let (($x6000 (and c_2_6 in_walk3_2 in_walk1_2)))
 (let (($x5998 (and c_2_5 in_walk3_2 in_walk1_2)))
 (let (($x5996 (and c_2_4 in_walk3_2 in_walk1_2)))
 (let (($x5994 (and c_2_3 in_walk3_2 in_walk1_2)))
 (let (($x5992 (and c_2_2 in_walk3_2 in_walk1_2)))
 (let (($x5990 (and c_2_1 in_walk3_2 in_walk1_2)))
 (let (($x5989 (and c_2_0 in_walk3_2 in_walk1_2)))
 (let (($x6037 (or $x5989 $x5990 $x5992 $x5994 $x5996 $x5998 $x6000 $x6002 $x6004 $x6006 $x6008 $x6010 $x6012 $x6014 $x6016 $x6018 $x6020 $x6022 $x6024 $x6026 $x6028 $x6030 $x6032 $x6034 $x6036)))
 (let (($x5959 (and c_1_24 in_walk3_1 in_walk1_1)))
 (let (($x5957 (and c_1_23 in_walk3_1 in_walk1_1)))
 (let (($x5955 (and c_1_22 in_walk3_1 in_walk1_1)))
 (let (($x5953 (and c_1_21 in_walk3_1 in_walk1_1)))
 (let (($x5951 (and c_1_20 in_walk3_1 in_walk1_1)))
 (let (($x5949 (and c_1_19 in_walk3_1 in_walk1_1)))
 (let (($x5947 (and c_1_18 in_walk3_1 in_walk1_1)))
 (let (($x5945 (and c_1_17 in_walk3_1 in_walk1_1)))
 (let (($x5943 (and c_1_16 in_walk3_1 in_walk1_1)))
 (let (($x5941 (and c_1_15 in_walk3_1 in_walk1_1)))
 (let (($x5939 (and c_1_14 in_walk3_1 in_walk1_1)))
 (let (($x5937 (and c_1_13 in_walk3_1 in_walk1_1)))
 (let (($x5935 (and c_1_12 in_walk3_1 in_walk1_1)))
 (let (($x5933 (and c_1_11 in_walk3_1 in_walk1_1)))
 (let (($x5931 (and c_1_10 in_walk3_1 in_walk1_1)))
 (let (($x5929 (and c_1_9 in_walk3_1 in_walk1_1)))
 (let (($x5927 (and c_1_8 in_walk3_1 in_walk1_1)))
 (let (($x5925 (and c_1_7 in_walk3_1 in_walk1_1)))
 (let (($x5923 (and c_1_6 in_walk3_1 in_walk1_1)))
 (let (($x5921 (and c_1_5 in_walk3_1 in_walk1_1)))
 (let (($x5919 (and c_1_4 in_walk3_1 in_walk1_1)))
 (let (($x5917 (and c_1_3 in_walk3_1 in_walk1_1)))
 (let (($x5915 (and c_1_2 in_walk3_1 in_walk1_1)))
 (let (($x5913 (and c_1_1 in_walk3_1 in_walk1_1)))
 (let (($x5912 (and c_1_0 in_walk3_1 in_walk1_1)))
 (let (($x5960 (or $x5912 $x5913 $x5915 $x5917 $x5919 $x5921 $x5923 $x5925 $x5927 $x5929 $x5931 $x5933 $x5935 $x5937 $x5939 $x5941 $x5943 $x5945 $x5947 $x5949 $x5951 $x5953 $x5955 $x5957 $x5959)))
 (let (($x5882 (and c_0_24 in_walk3_0 in_walk1_0)))
 (let (($x5880 (and c_0_23 in_walk3_0 in_walk1_0)))
 (let (($x5878 (and c_0_22 in_walk3_0 in_walk1_0)))
 (let (($x5876 (and c_0_21 in_walk3_0 in_walk1_0)))
 (let (($x5874 (and c_0_20 in_walk3_0 in_walk1_0)))
 (let (($x5872 (and c_0_19 in_walk3_0 in_walk1_0)))
 (let (($x5870 (and c_0_18 in_walk3_0 in_walk1_0)))
 (let (($x5868 (and c_0_17 in_walk3_0 in_walk1_0)))
 (let (($x5866 (and c_0_16 in_walk3_0 in_walk1_0)))
 (let (($x5864 (and c_0_15 in_walk3_0 in_walk1_0)))
 (let (($x5862 (and c_0_14 in_walk3_0 in_walk1_0)))
 (let (($x5860 (and c_0_13 in_walk3_0 in_walk1_0)))
 (let (($x5858 (and c_0_12 in_walk3_0 in_walk1_0)))
 (let (($x5856 (and c_0_11 in_walk3_0 in_walk1_0)))
 (let (($x5854 (and c_0_10 in_walk3_0 in_walk1_0)))
 (let (($x5852 (and c_0_9 in_walk3_0 in_walk1_0)))
 (let (($x5850 (and c_0_8 in_walk3_0 in_walk1_0)))
 (let (($x5848 (and c_0_7 in_walk3_0 in_walk1_0)))
 (let (($x5846 (and c_0_6 in_walk3_0 in_walk1_0)))
 (let (($x5844 (and c_0_5 in_walk3_0 in_walk1_0)))
 (let (($x5842 (and c_0_4 in_walk3_0 in_walk1_0)))
 (let (($x5840 (and c_0_3 in_walk3_0 in_walk1_0)))
 (let (($x5838 (and c_0_2 in_walk3_0 in_walk1_0)))
 (let (($x5836 (and c_0_1 in_walk3_0 in_walk1_0)))
 (let (($x5835 (and c_0_0 in_walk3_0 in_walk1_0)))
 (let (($x5883 (or $x5835 $x5836 $x5838 $x5840 $x5842 $x5844 $x5846 $x5848 $x5850 $x5852 $x5854 $x5856 $x5858 $x5860 $x5862 $x5864 $x5866 $x5868 $x5870 $x5872 $x5874 $x5876 $x5878 $x5880 $x5882)))
 (let (($x5833 (or false $x5883)))
 (let (($x5910 (or $x5833 $x5960)))
 (let (($x5987 (or $x5910 $x6037)))
 (let (($x5794 (and c_3_24 in_walk2_3 in_walk1_3)))
 (let (($x5792 (and c_3_23 in_walk2_3 in_walk1_3)))
 (let (($x5790 (and c_3_22 in_walk2_3 in_walk1_3)))
 (let (($x5788 (and c_3_21 in_walk2_3 in_walk1_3)))
 (let (($x5786 (and c_3_20 in_walk2_3 in_walk1_3)))
 (let (($x5784 (and c_3_19 in_walk2_3 in_walk1_3)))
 (let (($x5782 (and c_3_18 in_walk2_3 in_walk1_3)))
 (let (($x5780 (and c_3_17 in_walk2_3 in_walk1_3)))
 (let (($x5778 (and c_3_16 in_walk2_3 in_walk1_3)))
 (let (($x5776 (and c_3_15 in_walk2_3 in_walk1_3)))
 (let (($x5774 (and c_3_14 in_walk2_3 in_walk1_3)))
 (let (($x5772 (and c_3_13 in_walk2_3 in_walk1_3)))
 (let (($x5770 (and c_3_12 in_walk2_3 in_walk1_3)))
 (let (($x5768 (and c_3_11 in_walk2_3 in_walk1_3)))
 (let (($x5766 (and c_3_10 in_walk2_3 in_walk1_3)))
 (let (($x5764 (and c_3_9 in_walk2_3 in_walk1_3)))
 (let (($x5762 (and c_3_8 in_walk2_3 in_walk1_3)))
 (let (($x5760 (and c_3_7 in_walk2_3 in_walk1_3)))
 (let (($x5758 (and c_3_6 in_walk2_3 in_walk1_3)))
 (let (($x5756 (and c_3_5 in_walk2_3 in_walk1_3)))
 (let (($x5754 (and c_3_4 in_walk2_3 in_walk1_3)))
 (let (($x5752 (and c_3_3 in_walk2_3 in_walk1_3)))
 (let (($x5750 (and c_3_2 in_walk2_3 in_walk1_3)))
 (let (($x5748 (and c_3_1 in_walk2_3 in_walk1_3)))
 (let (($x5747 (and c_3_0 in_walk2_3 in_walk1_3)))
 (let (($x5795 (or $x5747 $x5748 $x5750 $x5752 $x5754 $x5756 $x5758 $x5760 $x5762 $x5764 $x5766 $x5768 $x5770 $x5772 $x5774 $x5776 $x5778 $x5780 $x5782 $x5784 $x5786 $x5788 $x5790 $x5792 $x5794)))
 (let (($x5717 (and c_2_24 in_walk2_2 in_walk1_2)))
 (let (($x5715 (and c_2_23 in_walk2_2 in_walk1_2)))
 (let (($x5713 (and c_2_22 in_walk2_2 in_walk1_2)))
 (let (($x5711 (and c_2_21 in_walk2_2 in_walk1_2)))
 (let (($x5709 (and c_2_20 in_walk2_2 in_walk1_2)))
 (let (($x5707 (and c_2_19 in_walk2_2 in_walk1_2)))
 (let (($x5705 (and c_2_18 in_walk2_2 in_walk1_2)))
 (let (($x5703 (and c_2_17 in_walk2_2 in_walk1_2)))
 (let (($x5701 (and c_2_16 in_walk2_2 in_walk1_2)))
 (let (($x5699 (and c_2_15 in_walk2_2 in_walk1_2)))
 (let (($x5697 (and c_2_14 in_walk2_2 in_walk1_2)))
 (let (($x5695 (and c_2_13 in_walk2_2 in_walk1_2)))
 (let (($x5693 (and c_2_12 in_walk2_2 in_walk1_2)))
 (let (($x5691 (and c_2_11 in_walk2_2 in_walk1_2)))
 (let (($x5689 (and c_2_10 in_walk2_2 in_walk1_2)))
 (let (($x5687 (and c_2_9 in_walk2_2 in_walk1_2)))
 (let (($x5685 (and c_2_8 in_walk2_2 in_walk1_2)))
 (let (($x5683 (and c_2_7 in_walk2_2 in_walk1_2)))
 (let (($x5681 (and c_2_6 in_walk2_2 in_walk1_2)))
 (let (($x5679 (and c_2_5 in_walk2_2 in_walk1_2)))
 (let (($x5677 (and c_2_4 in_walk2_2 in_walk1_2)))
 (let (($x5675 (and c_2_3 in_walk2_2 in_walk1_2)))
 (let (($x5673 (and c_2_2 in_walk2_2 in_walk1_2)))
 (let (($x5671 (and c_2_1 in_walk2_2 in_walk1_2)))
 (let (($x5670 (and c_2_0 in_walk2_2 in_walk1_2)))
 (let (($x5718 (or $x5670 $x5671 $x5673 $x5675 $x5677 $x5679 $x5681 $x5683 $x5685 $x5687 $x5689 $x5691 $x5693 $x5695 $x5697 $x5699 $x5701 $x5703 $x5705 $x5707 $x5709 $x5711 $x5713 $x5715 $x5717)))
 (let (($x5640 (and c_1_24 in_walk2_1 in_walk1_1)))
 (let (($x5638 (and c_1_23 in_walk2_1 in_walk1_1)))
 (let (($x5636 (and c_1_22 in_walk2_1 in_walk1_1)))
 (let (($x5634 (and c_1_21 in_walk2_1 in_walk1_1)))
 (let (($x5632 (and c_1_20 in_walk2_1 in_walk1_1)))
 (let (($x5630 (and c_1_19 in_walk2_1 in_walk1_1)))
 (let (($x5628 (and c_1_18 in_walk2_1 in_walk1_1)))
 (let (($x5626 (and c_1_17 in_walk2_1 in_walk1_1)))
 (let (($x5624 (and c_1_16 in_walk2_1 in_walk1_1)))
 (let (($x5622 (and c_1_15 in_walk2_1 in_walk1_1)))
 (let (($x5620 (and c_1_14 in_walk2_1 in_walk1_1)))
 (let (($x5618 (and c_1_13 in_walk2_1 in_walk1_1)))
 (let (($x5616 (and c_1_12 in_walk2_1 in_walk1_1)))
 (let (($x5614 (and c_1_11 in_walk2_1 in_walk1_1)))
 (let (($x5612 (and c_1_10 in_walk2_1 in_walk1_1)))
 (let (($x5610 (and c_1_9 in_walk2_1 in_walk1_1)))
 (let (($x5608 (and c_1_8 in_walk2_1 in_walk1_1)))
 (let (($x5606 (and c_1_7 in_walk2_1 in_walk1_1)))
 (let (($x5604 (and c_1_6 in_walk2_1 in_walk1_1)))
 (let (($x5602 (and c_1_5 in_walk2_1 in_walk1_1)))
 (let (($x5600 (and c_1_4 in_walk2_1 in_walk1_1)))
 (let (($x5598 (and c_1_3 in_walk2_1 in_walk1_1)))
 (let (($x5596 (and c_1_2 in_walk2_1 in_walk1_1)))
 (let (($x5594 (and c_1_1 in_walk2_1 in_walk1_1)))
 (let (($x5593 (and c_1_0 in_walk2_1 in_walk1_1)))
 (let (($x5641 (or $x5593 $x5594 $x5596 $x5598 $x5600 $x5602 $x5604 $x5606 $x5608 $x5610 $x5612 $x5614 $x5616 $x5618 $x5620 $x5622 $x5624 $x5626 $x5628 $x5630 $x5632 $x5634 $x5636 $x5638 $x5640)))
 (let (($x5563 (and c_0_24 in_walk2_0 in_walk1_0)))
 (let (($x5561 (and c_0_23 in_walk2_0 in_walk1_0)))
 (let (($x5559 (and c_0_22 in_walk2_0 in_walk1_0)))
 (let (($x5557 (and c_0_21 in_walk2_0 in_walk1_0)))
 (let (($x5555 (and c_0_20 in_walk2_0 in_walk1_0)))
 (let (($x5553 (and c_0_19 in_walk2_0 in_walk1_0)))
 (let (($x5551 (and c_0_18 in_walk2_0 in_walk1_0)))
 (let (($x5549 (and c_0_17 in_walk2_0 in_walk1_0)))
 (let (($x5547 (and c_0_16 in_walk2_0 in_walk1_0)))
 (let (($x5545 (and c_0_15 in_walk2_0 in_walk1_0)))
 (let (($x5543 (and c_0_14 in_walk2_0 in_walk1_0)))
 (let (($x5541 (and c_0_13 in_walk2_0 in_walk1_0)))
 (let (($x5539 (and c_0_12 in_walk2_0 in_walk1_0)))
 (let (($x5537 (and c_0_11 in_walk2_0 in_walk1_0)))
 (let (($x5535 (and c_0_10 in_walk2_0 in_walk1_0)))
 (let (($x5533 (and c_0_9 in_walk2_0 in_walk1_0)))
 (let (($x5531 (and c_0_8 in_walk2_0 in_walk1_0)))
 (let (($x5529 (and c_0_7 in_walk2_0 in_walk1_0)))
 (let (($x5527 (and c_0_6 in_walk2_0 in_walk1_0)))
 (let (($x5525 (and c_0_5 in_walk2_0 in_walk1_0)))
 (let (($x5523 (and c_0_4 in_walk2_0 in_walk1_0)))
 (let (($x5521 (and c_0_3 in_walk2_0 in_walk1_0)))
 (let (($x5519 (and c_0_2 in_walk2_0 in_walk1_0)))
 (let (($x5517 (and c_0_1 in_walk2_0 in_walk1_0)))
 (let (($x5516 (and c_0_0 in_walk2_0 in_walk1_0)))
 (let (($x5564 (or $x5516 $x5517 $x5519 $x5521 $x5523 $x5525 $x5527 $x5529 $x5531 $x5533 $x5535 $x5537 $x5539 $x5541 $x5543 $x5545 $x5547 $x5549 $x5551 $x5553 $x5555 $x5557 $x5559 $x5561 $x5563)))
 (let (($x5514 (or false $x5564)))
 (let (($x5591 (or $x5514 $x5641)))
 (let (($x5668 (or $x5591 $x5718)))
 (let (($x5440 (or c_2_16 c_2_24)))
 (let (($x5435 (or c_1_16 c_1_24)))
 (let (($x5430 (or c_0_16 c_0_24)))
 (let (($x5428 (or false $x5430)))
 (let (($x5433 (or $x5428 $x5435)))
 (let (($x5438 (or $x5433 $x5440)))
 (let (($x5444 (or (not (or (or (or (or false c_0_7) c_1_7) c_2_7) c_3_7)) (not (or $x5438 (or c_3_16 c_3_24))))))
 (let (($x5410 (or c_2_15 c_2_23)))
 (let (($x5405 (or c_1_15 c_1_23)))
 (let (($x5400 (or c_0_15 c_0_23)))
 (let (($x5398 (or false $x5400)))
 (let (($x5403 (or $x5398 $x5405)))
 (let (($x5408 (or $x5403 $x5410)))
 (let (($x5414 (or (not (or (or (or (or false c_0_6) c_1_6) c_2_6) c_3_6)) (not (or $x5408 (or c_3_15 c_3_23))))))
 (let (($x5380 (or c_2_14 c_2_22)))
 (let (($x5375 (or c_1_14 c_1_22)))
 (let (($x5370 (or c_0_14 c_0_22)))
 (let (($x5368 (or false $x5370)))
 (let (($x5373 (or $x5368 $x5375)))
 (let (($x5378 (or $x5373 $x5380)))
 (let (($x5384 (or (not (or (or (or (or false c_0_5) c_1_5) c_2_5) c_3_5)) (not (or $x5378 (or c_3_14 c_3_22))))))
 (let (($x5350 (or c_2_13 c_2_21)))
 (let (($x5345 (or c_1_13 c_1_21)))
 (let (($x5340 (or c_0_13 c_0_21)))
 (let (($x5338 (or false $x5340)))
 (let (($x5343 (or $x5338 $x5345)))
 (let (($x5348 (or $x5343 $x5350)))
 (let (($x5354 (or (not (or (or (or (or false c_0_4) c_1_4) c_2_4) c_3_4)) (not (or $x5348 (or c_3_13 c_3_21))))))
 (let (($x5320 (or c_2_12 c_2_20)))
 (let (($x5315 (or c_1_12 c_1_20)))
 (let (($x5310 (or c_0_12 c_0_20)))
 (let (($x5308 (or false $x5310)))
 (let (($x5313 (or $x5308 $x5315)))
 (let (($x5318 (or $x5313 $x5320)))
 (let (($x5324 (or (not (or (or (or (or false c_0_3) c_1_3) c_2_3) c_3_3)) (not (or $x5318 (or c_3_12 c_3_20))))))
 (let (($x5290 (or c_2_11 c_2_19)))
 (let (($x5285 (or c_1_11 c_1_19)))
 (let (($x5280 (or c_0_11 c_0_19)))
 (let (($x5278 (or false $x5280)))
 (let (($x5283 (or $x5278 $x5285)))
 (let (($x5288 (or $x5283 $x5290)))
 (let (($x5294 (or (not (or (or (or (or false c_0_2) c_1_2) c_2_2) c_3_2)) (not (or $x5288 (or c_3_11 c_3_19))))))
 (let (($x5260 (or c_2_10 c_2_18)))
 (let (($x5255 (or c_1_10 c_1_18)))
 (let (($x5250 (or c_0_10 c_0_18)))
 (let (($x5248 (or false $x5250)))
 (let (($x5253 (or $x5248 $x5255)))
 (let (($x5258 (or $x5253 $x5260)))
 (let (($x5264 (or (not (or (or (or (or false c_0_1) c_1_1) c_2_1) c_3_1)) (not (or $x5258 (or c_3_10 c_3_18))))))
 (let (($x5267 (and true $x5264)))
 (let (($x5297 (and $x5267 $x5294)))
 (let (($x5327 (and $x5297 $x5324)))
 (let (($x5357 (and $x5327 $x5354)))
 (let (($x5387 (and $x5357 $x5384)))
 (let (($x5417 (and $x5387 $x5414)))
 (let (($x5447 (and $x5417 $x5444)))
 (let (($x5749 (and $x5447 (or (or $x5456 $x5464) (not (or $x5668 $x5795))))))
 (let (($x6088 (and $x5749 (or (or $x5456 $x5777) (not (or $x5987 $x6114))))))
 (let (($x6393 (and $x6088 (or (or $x5456 $x6096) (not (or $x6306 $x6433))))))
 (let (($x6740 (and $x6393 (or (or $x5456 $x6411) (not (or $x6625 $x6752))))))
 (let (($x7035 (and $x6740 (or (or $x5456 $x6710) (not (or $x6944 $x7071))))))
 (let (($x7356 (and $x7035 (or (or $x5456 $x7037) (not (or $x7263 $x7390))))))
 (let (($x7699 (and $x7356 (or (or $x5456 $x7352) (not (or $x7582 $x7709))))))
 (let (($x8008 (and $x7699 (or (or $x5464 $x5777) (not (or $x7893 $x8020))))))
 (let (($x8309 (and $x8008 (or (or $x5464 $x6096) (not (or $x8204 $x8331))))))
 (let (($x8608 (and $x8309 (or (or $x5464 $x6411) (not (or $x8515 $x8642))))))
 (let (($x8931 (and $x8608 (or (or $x5464 $x6710) (not (or $x8826 $x8953))))))
 (let (($x9238 (and $x8931 (or (or $x5464 $x7037) (not (or $x9137 $x9264))))))
 (let (($x9541 (and $x9238 (or (or $x5464 $x7352) (not (or $x9448 $x9575))))))
 (let (($x9846 (and $x9541 (or (or $x5777 $x6096) (not (or $x9759 $x9886))))))
 (let (($x10185 (and $x9846 (or (or $x5777 $x6411) (not (or $x10070 $x10197))))))
 (let (($x10472 (and $x10185 (or (or $x5777 $x6710) (not (or $x10381 $x10508))))))
 (let (($x10785 (and $x10472 (or (or $x5777 $x7037) (not (or $x10692 $x10819))))))
 (let (($x11120 (and $x10785 (or (or $x5777 $x7352) (not (or $x11003 $x11130))))))
 (let (($x11407 (and $x11120 (or (or $x6096 $x6411) (not (or $x11314 $x11441))))))
 (let (($x11710 (and $x11407 (or (or $x6096 $x6710) (not (or $x11625 $x11752))))))
 (let (($x12035 (and $x11710 (or (or $x6096 $x7037) (not (or $x11936 $x12063))))))
 (let (($x12348 (and $x12035 (or (or $x6096 $x7352) (not (or $x12247 $x12374))))))
 (let (($x12645 (and $x12348 (or (or $x6411 $x6710) (not (or $x12558 $x12685))))))
 (let (($x12970 (and $x12645 (or (or $x6411 $x7037) (not (or $x12869 $x12996))))))
 (let (($x13279 (and $x12970 (or (or $x6411 $x7352) (not (or $x13180 $x13307))))))
 (let (($x13590 (and $x13279 (or (or $x6710 $x7037) (not (or $x13491 $x13618))))))
 (let (($x13903 (and $x13590 (or (or $x6710 $x7352) (not (or $x13802 $x13929))))))
 (let (($x14230 (and $x13903 (or (or $x7037 $x7352) (not (or $x14113 $x14240))))))
 (let (($x24224 (= rule_instance 60)))
 (let (($x24109 (and true (=> c_0_0 d_0_23))))
 (let (($x24098 (and $x24109 (=> c_0_1 d_0_23))))
 (let (($x24124 (and $x24098 (=> c_0_2 d_0_23))))
 (let (($x24114 (and $x24124 (=> c_0_3 d_0_23))))
 (let (($x24101 (and $x24114 (=> c_0_4 d_0_23))))
 (let (($x24105 (and $x24101 (=> c_0_5 d_0_23))))
 (let (($x24103 (and $x24105 (=> c_0_6 d_0_23))))
 (let (($x24111 (and $x24103 (=> c_0_7 d_0_23))))
 (let (($x24107 (and $x24111 (=> c_0_8 d_0_23))))
 (let (($x24116 (and $x24107 (=> c_0_9 d_0_23))))
 (let (($x24122 (and $x24116 (=> c_0_10 d_0_23))))
 (let (($x24123 (and $x24122 (=> c_0_11 d_0_23))))
 (let (($x24126 (and $x24123 (=> c_0_12 d_0_23))))
 (let (($x24128 (and $x24126 (=> c_0_13 d_0_23))))
 (let (($x24130 (and $x24128 (=> c_0_14 d_0_23))))
 (let (($x24132 (and $x24130 (=> c_0_15 d_0_23))))
 (let (($x24134 (and $x24132 (=> c_0_16 d_0_23))))
 (let (($x24136 (and $x24134 (=> c_0_17 d_0_23))))
 (let (($x24138 (and $x24136 (=> c_0_18 d_0_23))))
 (let (($x24140 (and $x24138 (=> c_0_19 d_0_23))))
 (let (($x24142 (and $x24140 (=> c_0_20 d_0_23))))
 (let (($x24144 (and $x24142 (=> c_0_21 d_0_23))))
 (let (($x24146 (and $x24144 (=> c_0_22 d_0_23))))
 (let (($x24148 (and $x24146 (=> c_0_23 d_0_23))))
 (let (($x7059 (and true c_0_15)))
 (let (($x24151 (and $x7059 (and $x24148 (=> c_0_24 d_0_23)))))
 (let (($x24152 (and $x24151 $x14320)))
 (let (($x24153 (and $x24152 $x14371)))
 (let (($x24163 (= rule_instance 56)))
 (let (($x24048 (and true (=> c_0_0 d_0_22))))
 (let (($x24037 (and $x24048 (=> c_0_1 d_0_22))))
 (let (($x24063 (and $x24037 (=> c_0_2 d_0_22))))
 (let (($x24053 (and $x24063 (=> c_0_3 d_0_22))))
 (let (($x24040 (and $x24053 (=> c_0_4 d_0_22))))
 (let (($x24044 (and $x24040 (=> c_0_5 d_0_22))))
 (let (($x24042 (and $x24044 (=> c_0_6 d_0_22))))
 (let (($x24050 (and $x24042 (=> c_0_7 d_0_22))))
 (let (($x24046 (and $x24050 (=> c_0_8 d_0_22))))
 (let (($x24055 (and $x24046 (=> c_0_9 d_0_22))))
 (let (($x24061 (and $x24055 (=> c_0_10 d_0_22))))
 (let (($x24062 (and $x24061 (=> c_0_11 d_0_22))))
 (let (($x24065 (and $x24062 (=> c_0_12 d_0_22))))
 (let (($x24067 (and $x24065 (=> c_0_13 d_0_22))))
 (let (($x24069 (and $x24067 (=> c_0_14 d_0_22))))
 (let (($x24071 (and $x24069 (=> c_0_15 d_0_22))))
 (let (($x24073 (and $x24071 (=> c_0_16 d_0_22))))
 (let (($x24075 (and $x24073 (=> c_0_17 d_0_22))))
 (let (($x24077 (and $x24075 (=> c_0_18 d_0_22))))
 (let (($x24079 (and $x24077 (=> c_0_19 d_0_22))))
 (let (($x24081 (and $x24079 (=> c_0_20 d_0_22))))
 (let (($x24083 (and $x24081 (=> c_0_21 d_0_22))))
 (let (($x24085 (and $x24083 (=> c_0_22 d_0_22))))
 (let (($x24087 (and $x24085 (=> c_0_23 d_0_22))))
 (let (($x6718 (and true c_0_14)))
 (let (($x24090 (and $x6718 (and $x24087 (=> c_0_24 d_0_22)))))
 (let (($x24091 (and $x24090 $x14320)))
 (let (($x24092 (and $x24091 $x14371)))
 (let (($x24102 (= rule_instance 52)))
 (let (($x23987 (and true (=> c_0_0 d_0_21))))
 (let (($x23976 (and $x23987 (=> c_0_1 d_0_21))))
 (let (($x24002 (and $x23976 (=> c_0_2 d_0_21))))
 (let (($x23992 (and $x24002 (=> c_0_3 d_0_21))))
 (let (($x23979 (and $x23992 (=> c_0_4 d_0_21))))
 (let (($x23983 (and $x23979 (=> c_0_5 d_0_21))))
 (let (($x23981 (and $x23983 (=> c_0_6 d_0_21))))
 (let (($x23989 (and $x23981 (=> c_0_7 d_0_21))))
 (let (($x23985 (and $x23989 (=> c_0_8 d_0_21))))
 (let (($x23994 (and $x23985 (=> c_0_9 d_0_21))))
 (let (($x24000 (and $x23994 (=> c_0_10 d_0_21))))
 (let (($x24001 (and $x24000 (=> c_0_11 d_0_21))))
 (let (($x24004 (and $x24001 (=> c_0_12 d_0_21))))
 (let (($x24006 (and $x24004 (=> c_0_13 d_0_21))))
 (let (($x24008 (and $x24006 (=> c_0_14 d_0_21))))
 (let (($x24010 (and $x24008 (=> c_0_15 d_0_21))))
 (let (($x24012 (and $x24010 (=> c_0_16 d_0_21))))
 (let (($x24014 (and $x24012 (=> c_0_17 d_0_21))))
 (let (($x24016 (and $x24014 (=> c_0_18 d_0_21))))
 (let (($x24018 (and $x24016 (=> c_0_19 d_0_21))))
 (let (($x24020 (and $x24018 (=> c_0_20 d_0_21))))
 (let (($x24022 (and $x24020 (=> c_0_21 d_0_21))))
 (let (($x24024 (and $x24022 (=> c_0_22 d_0_21))))
 (let (($x24026 (and $x24024 (=> c_0_23 d_0_21))))
 (let (($x6429 (and true c_0_13)))
 (let (($x24029 (and $x6429 (and $x24026 (=> c_0_24 d_0_21)))))
 (let (($x24030 (and $x24029 $x14320)))
 (let (($x24031 (and $x24030 $x14371)))
 (let (($x24041 (= rule_instance 48)))
 (let (($x23926 (and true (=> c_0_0 d_0_20))))
 (let (($x23915 (and $x23926 (=> c_0_1 d_0_20))))
 (let (($x23941 (and $x23915 (=> c_0_2 d_0_20))))
 (let (($x23931 (and $x23941 (=> c_0_3 d_0_20))))
 (let (($x23918 (and $x23931 (=> c_0_4 d_0_20))))
 (let (($x23922 (and $x23918 (=> c_0_5 d_0_20))))
 (let (($x23920 (and $x23922 (=> c_0_6 d_0_20))))
 (let (($x23928 (and $x23920 (=> c_0_7 d_0_20))))
 (let (($x23924 (and $x23928 (=> c_0_8 d_0_20))))
 (let (($x23933 (and $x23924 (=> c_0_9 d_0_20))))
 (let (($x23939 (and $x23933 (=> c_0_10 d_0_20))))
 (let (($x23940 (and $x23939 (=> c_0_11 d_0_20))))
 (let (($x23943 (and $x23940 (=> c_0_12 d_0_20))))
 (let (($x23945 (and $x23943 (=> c_0_13 d_0_20))))
 (let (($x23947 (and $x23945 (=> c_0_14 d_0_20))))
 (let (($x23949 (and $x23947 (=> c_0_15 d_0_20))))
 (let (($x23951 (and $x23949 (=> c_0_16 d_0_20))))
 (let (($x23953 (and $x23951 (=> c_0_17 d_0_20))))
 (let (($x23955 (and $x23953 (=> c_0_18 d_0_20))))
 (let (($x23957 (and $x23955 (=> c_0_19 d_0_20))))
 (let (($x23959 (and $x23957 (=> c_0_20 d_0_20))))
 (let (($x23961 (and $x23959 (=> c_0_21 d_0_20))))
 (let (($x23963 (and $x23961 (=> c_0_22 d_0_20))))
 (let (($x23965 (and $x23963 (=> c_0_23 d_0_20))))
 (let (($x6070 (and true c_0_12)))
 (let (($x23968 (and $x6070 (and $x23965 (=> c_0_24 d_0_20)))))
 (let (($x23969 (and $x23968 $x14320)))
 (let (($x23970 (and $x23969 $x14371)))
 (let (($x23980 (= rule_instance 44)))
 (let (($x23865 (and true (=> c_0_0 d_0_19))))
 (let (($x23854 (and $x23865 (=> c_0_1 d_0_19))))
 (let (($x23880 (and $x23854 (=> c_0_2 d_0_19))))
 (let (($x23870 (and $x23880 (=> c_0_3 d_0_19))))
 (let (($x23857 (and $x23870 (=> c_0_4 d_0_19))))
 (let (($x23861 (and $x23857 (=> c_0_5 d_0_19))))
 (let (($x23859 (and $x23861 (=> c_0_6 d_0_19))))
 (let (($x23867 (and $x23859 (=> c_0_7 d_0_19))))
 (let (($x23863 (and $x23867 (=> c_0_8 d_0_19))))
 (let (($x23872 (and $x23863 (=> c_0_9 d_0_19))))
 (let (($x23878 (and $x23872 (=> c_0_10 d_0_19))))
 (let (($x23879 (and $x23878 (=> c_0_11 d_0_19))))
 (let (($x23882 (and $x23879 (=> c_0_12 d_0_19))))
 (let (($x23884 (and $x23882 (=> c_0_13 d_0_19))))
 (let (($x23886 (and $x23884 (=> c_0_14 d_0_19))))
 (let (($x23888 (and $x23886 (=> c_0_15 d_0_19))))
 (let (($x23890 (and $x23888 (=> c_0_16 d_0_19))))
 (let (($x23892 (and $x23890 (=> c_0_17 d_0_19))))
 (let (($x23894 (and $x23892 (=> c_0_18 d_0_19))))
 (let (($x23896 (and $x23894 (=> c_0_19 d_0_19))))
 (let (($x23898 (and $x23896 (=> c_0_20 d_0_19))))
 (let (($x23900 (and $x23898 (=> c_0_21 d_0_19))))
 (let (($x23902 (and $x23900 (=> c_0_22 d_0_19))))
 (let (($x23904 (and $x23902 (=> c_0_23 d_0_19))))
 (let (($x5761 (and true c_0_11)))
 (let (($x23907 (and $x5761 (and $x23904 (=> c_0_24 d_0_19)))))
 (let (($x23908 (and $x23907 $x14320)))
 (let (($x23909 (and $x23908 $x14371)))
 (let (($x23919 (= rule_instance 40)))
 (let (($x23804 (and true (=> c_0_0 d_0_18))))
 (let (($x23793 (and $x23804 (=> c_0_1 d_0_18))))
 (let (($x23819 (and $x23793 (=> c_0_2 d_0_18))))
 (let (($x23809 (and $x23819 (=> c_0_3 d_0_18))))
 (let (($x23796 (and $x23809 (=> c_0_4 d_0_18))))
 (let (($x23800 (and $x23796 (=> c_0_5 d_0_18))))
 (let (($x23798 (and $x23800 (=> c_0_6 d_0_18))))
 (let (($x23806 (and $x23798 (=> c_0_7 d_0_18))))
 (let (($x23802 (and $x23806 (=> c_0_8 d_0_18))))
 (let (($x23811 (and $x23802 (=> c_0_9 d_0_18))))
 (let (($x23817 (and $x23811 (=> c_0_10 d_0_18))))
 (let (($x23818 (and $x23817 (=> c_0_11 d_0_18))))
 (let (($x23821 (and $x23818 (=> c_0_12 d_0_18))))
 (let (($x23823 (and $x23821 (=> c_0_13 d_0_18))))
 (let (($x23825 (and $x23823 (=> c_0_14 d_0_18))))
 (let (($x23827 (and $x23825 (=> c_0_15 d_0_18))))
 (let (($x23829 (and $x23827 (=> c_0_16 d_0_18))))
 (let (($x23831 (and $x23829 (=> c_0_17 d_0_18))))
 (let (($x23833 (and $x23831 (=> c_0_18 d_0_18))))
 (let (($x23835 (and $x23833 (=> c_0_19 d_0_18))))
 (let (($x23837 (and $x23835 (=> c_0_20 d_0_18))))
 (let (($x23839 (and $x23837 (=> c_0_21 d_0_18))))
 (let (($x23841 (and $x23839 (=> c_0_22 d_0_18))))
 (let (($x23843 (and $x23841 (=> c_0_23 d_0_18))))
 (let (($x5457 (and true c_0_10)))
 (let (($x23846 (and $x5457 (and $x23843 (=> c_0_24 d_0_18)))))
 (let (($x23847 (and $x23846 $x14320)))
 (let (($x23848 (and $x23847 $x14371)))
 (let (($x23858 (= rule_instance 36)))
 (let (($x23743 (and true (=> c_0_0 d_0_17))))
 (let (($x23732 (and $x23743 (=> c_0_1 d_0_17))))
 (let (($x23758 (and $x23732 (=> c_0_2 d_0_17))))
 (let (($x23748 (and $x23758 (=> c_0_3 d_0_17))))
 (let (($x23735 (and $x23748 (=> c_0_4 d_0_17))))
 (let (($x23739 (and $x23735 (=> c_0_5 d_0_17))))
 (let (($x23737 (and $x23739 (=> c_0_6 d_0_17))))
 (let (($x23745 (and $x23737 (=> c_0_7 d_0_17))))
 (let (($x23741 (and $x23745 (=> c_0_8 d_0_17))))
 (let (($x23750 (and $x23741 (=> c_0_9 d_0_17))))
 (let (($x23756 (and $x23750 (=> c_0_10 d_0_17))))
 (let (($x23757 (and $x23756 (=> c_0_11 d_0_17))))
 (let (($x23760 (and $x23757 (=> c_0_12 d_0_17))))
 (let (($x23762 (and $x23760 (=> c_0_13 d_0_17))))
 (let (($x23764 (and $x23762 (=> c_0_14 d_0_17))))
 (let (($x23766 (and $x23764 (=> c_0_15 d_0_17))))
 (let (($x23768 (and $x23766 (=> c_0_16 d_0_17))))
 (let (($x23770 (and $x23768 (=> c_0_17 d_0_17))))
 (let (($x23772 (and $x23770 (=> c_0_18 d_0_17))))
 (let (($x23774 (and $x23772 (=> c_0_19 d_0_17))))
 (let (($x23776 (and $x23774 (=> c_0_20 d_0_17))))
 (let (($x23778 (and $x23776 (=> c_0_21 d_0_17))))
 (let (($x23780 (and $x23778 (=> c_0_22 d_0_17))))
 (let (($x23782 (and $x23780 (=> c_0_23 d_0_17))))
 (let (($x5449 (and true c_0_9)))
 (let (($x23785 (and $x5449 (and $x23782 (=> c_0_24 d_0_17)))))
 (let (($x23786 (and $x23785 $x14320)))
 (let (($x23787 (and $x23786 $x14371)))
 (let (($x23797 (= rule_instance 32)))
 (let (($x23693 (and true (=> c_0_0 d_0_16))))
 (let (($x23676 (and $x23693 (=> c_0_1 d_0_16))))
 (let (($x23690 (and $x23676 (=> c_0_2 d_0_16))))
 (let (($x23680 (and $x23690 (=> c_0_3 d_0_16))))
 (let (($x23687 (and $x23680 (=> c_0_4 d_0_16))))
 (let (($x23671 (and $x23687 (=> c_0_5 d_0_16))))
 (let (($x23669 (and $x23671 (=> c_0_6 d_0_16))))
 (let (($x23697 (and $x23669 (=> c_0_7 d_0_16))))
 (let (($x23689 (and $x23697 (=> c_0_8 d_0_16))))
 (let (($x23692 (and $x23689 (=> c_0_9 d_0_16))))
 (let (($x23684 (and $x23692 (=> c_0_10 d_0_16))))
 (let (($x23672 (and $x23684 (=> c_0_11 d_0_16))))
 (let (($x23699 (and $x23672 (=> c_0_12 d_0_16))))
 (let (($x23701 (and $x23699 (=> c_0_13 d_0_16))))
 (let (($x23703 (and $x23701 (=> c_0_14 d_0_16))))
 (let (($x23705 (and $x23703 (=> c_0_15 d_0_16))))
 (let (($x23707 (and $x23705 (=> c_0_16 d_0_16))))
 (let (($x23709 (and $x23707 (=> c_0_17 d_0_16))))
 (let (($x23711 (and $x23709 (=> c_0_18 d_0_16))))
 (let (($x23713 (and $x23711 (=> c_0_19 d_0_16))))
 (let (($x23715 (and $x23713 (=> c_0_20 d_0_16))))
 (let (($x23717 (and $x23715 (=> c_0_21 d_0_16))))
 (let (($x23719 (and $x23717 (=> c_0_22 d_0_16))))
 (let (($x23721 (and $x23719 (=> c_0_23 d_0_16))))
 (let (($x23685 (and true c_0_8)))
 (let (($x23724 (and $x23685 (and $x23721 (=> c_0_24 d_0_16)))))
 (let (($x23725 (and $x23724 $x14320)))
 (let (($x23726 (and $x23725 $x14371)))
 (let (($x23736 (= rule_instance 28)))
 (let (($x23620 (and true (=> c_0_0 d_0_15))))
 (let (($x23609 (and $x23620 (=> c_0_1 d_0_15))))
 (let (($x23635 (and $x23609 (=> c_0_2 d_0_15))))
 (let (($x23625 (and $x23635 (=> c_0_3 d_0_15))))
 (let (($x23612 (and $x23625 (=> c_0_4 d_0_15))))
 (let (($x23616 (and $x23612 (=> c_0_5 d_0_15))))
 (let (($x23614 (and $x23616 (=> c_0_6 d_0_15))))
 (let (($x23622 (and $x23614 (=> c_0_7 d_0_15))))
 (let (($x23618 (and $x23622 (=> c_0_8 d_0_15))))
 (let (($x23627 (and $x23618 (=> c_0_9 d_0_15))))
 (let (($x23633 (and $x23627 (=> c_0_10 d_0_15))))
 (let (($x23634 (and $x23633 (=> c_0_11 d_0_15))))
 (let (($x23637 (and $x23634 (=> c_0_12 d_0_15))))
 (let (($x23639 (and $x23637 (=> c_0_13 d_0_15))))
 (let (($x23641 (and $x23639 (=> c_0_14 d_0_15))))
 (let (($x23643 (and $x23641 (=> c_0_15 d_0_15))))
 (let (($x23645 (and $x23643 (=> c_0_16 d_0_15))))
 (let (($x23647 (and $x23645 (=> c_0_17 d_0_15))))
 (let (($x23649 (and $x23647 (=> c_0_18 d_0_15))))
 (let (($x23651 (and $x23649 (=> c_0_19 d_0_15))))
 (let (($x23653 (and $x23651 (=> c_0_20 d_0_15))))
 (let (($x23655 (and $x23653 (=> c_0_21 d_0_15))))
 (let (($x23657 (and $x23655 (=> c_0_22 d_0_15))))
 (let (($x23659 (and $x23657 (=> c_0_23 d_0_15))))
 (let (($x5419 (and true c_0_7)))
 (let (($x23662 (and $x5419 (and $x23659 (=> c_0_24 d_0_15)))))
 (let (($x23663 (and $x23662 $x14320)))
 (let (($x23664 (and $x23663 $x14371)))
 (let (($x23674 (= rule_instance 24)))
 (let (($x23559 (and true (=> c_0_0 d_0_14))))
 (let (($x23548 (and $x23559 (=> c_0_1 d_0_14))))
 (let (($x23574 (and $x23548 (=> c_0_2 d_0_14))))
 (let (($x23564 (and $x23574 (=> c_0_3 d_0_14))))
 (let (($x23551 (and $x23564 (=> c_0_4 d_0_14))))
 (let (($x23555 (and $x23551 (=> c_0_5 d_0_14))))
 (let (($x23553 (and $x23555 (=> c_0_6 d_0_14))))
 (let (($x23561 (and $x23553 (=> c_0_7 d_0_14))))
 (let (($x23557 (and $x23561 (=> c_0_8 d_0_14))))
 (let (($x23566 (and $x23557 (=> c_0_9 d_0_14))))
 (let (($x23572 (and $x23566 (=> c_0_10 d_0_14))))
 (let (($x23573 (and $x23572 (=> c_0_11 d_0_14))))
 (let (($x23576 (and $x23573 (=> c_0_12 d_0_14))))
 (let (($x23578 (and $x23576 (=> c_0_13 d_0_14))))
 (let (($x23580 (and $x23578 (=> c_0_14 d_0_14))))
 (let (($x23582 (and $x23580 (=> c_0_15 d_0_14))))
 (let (($x23584 (and $x23582 (=> c_0_16 d_0_14))))
 (let (($x23586 (and $x23584 (=> c_0_17 d_0_14))))
 (let (($x23588 (and $x23586 (=> c_0_18 d_0_14))))
 (let (($x23590 (and $x23588 (=> c_0_19 d_0_14))))
 (let (($x23592 (and $x23590 (=> c_0_20 d_0_14))))
 (let (($x23594 (and $x23592 (=> c_0_21 d_0_14))))
 (let (($x23596 (and $x23594 (=> c_0_22 d_0_14))))
 (let (($x23598 (and $x23596 (=> c_0_23 d_0_14))))
 (let (($x5389 (and true c_0_6)))
 (let (($x23601 (and $x5389 (and $x23598 (=> c_0_24 d_0_14)))))
 (let (($x23602 (and $x23601 $x14320)))
 (let (($x23603 (and $x23602 $x14371)))
 (let (($x23613 (= rule_instance 20)))
 (let (($x23498 (and true (=> c_0_0 d_0_13))))
 (let (($x23487 (and $x23498 (=> c_0_1 d_0_13))))
 (let (($x23513 (and $x23487 (=> c_0_2 d_0_13))))
 (let (($x23503 (and $x23513 (=> c_0_3 d_0_13))))
 (let (($x23490 (and $x23503 (=> c_0_4 d_0_13))))
 (let (($x23494 (and $x23490 (=> c_0_5 d_0_13))))
 (let (($x23492 (and $x23494 (=> c_0_6 d_0_13))))
 (let (($x23500 (and $x23492 (=> c_0_7 d_0_13))))
 (let (($x23496 (and $x23500 (=> c_0_8 d_0_13))))
 (let (($x23505 (and $x23496 (=> c_0_9 d_0_13))))
 (let (($x23511 (and $x23505 (=> c_0_10 d_0_13))))
 (let (($x23512 (and $x23511 (=> c_0_11 d_0_13))))
 (let (($x23515 (and $x23512 (=> c_0_12 d_0_13))))
 (let (($x23517 (and $x23515 (=> c_0_13 d_0_13))))
 (let (($x23519 (and $x23517 (=> c_0_14 d_0_13))))
 (let (($x23521 (and $x23519 (=> c_0_15 d_0_13))))
 (let (($x23523 (and $x23521 (=> c_0_16 d_0_13))))
 (let (($x23525 (and $x23523 (=> c_0_17 d_0_13))))
 (let (($x23527 (and $x23525 (=> c_0_18 d_0_13))))
 (let (($x23529 (and $x23527 (=> c_0_19 d_0_13))))
 (let (($x23531 (and $x23529 (=> c_0_20 d_0_13))))
 (let (($x23533 (and $x23531 (=> c_0_21 d_0_13))))
 (let (($x23535 (and $x23533 (=> c_0_22 d_0_13))))
 (let (($x23537 (and $x23535 (=> c_0_23 d_0_13))))
 (let (($x5359 (and true c_0_5)))
 (let (($x23540 (and $x5359 (and $x23537 (=> c_0_24 d_0_13)))))
 (let (($x23541 (and $x23540 $x14320)))
 (let (($x23542 (and $x23541 $x14371)))
 (let (($x23552 (= rule_instance 16)))
 (let (($x23437 (and true (=> c_0_0 d_0_12))))
 (let (($x23426 (and $x23437 (=> c_0_1 d_0_12))))
 (let (($x23452 (and $x23426 (=> c_0_2 d_0_12))))
 (let (($x23442 (and $x23452 (=> c_0_3 d_0_12))))
 (let (($x23429 (and $x23442 (=> c_0_4 d_0_12))))
 (let (($x23433 (and $x23429 (=> c_0_5 d_0_12))))
 (let (($x23431 (and $x23433 (=> c_0_6 d_0_12))))
 (let (($x23439 (and $x23431 (=> c_0_7 d_0_12))))
 (let (($x23435 (and $x23439 (=> c_0_8 d_0_12))))
 (let (($x23444 (and $x23435 (=> c_0_9 d_0_12))))
 (let (($x23450 (and $x23444 (=> c_0_10 d_0_12))))
 (let (($x23451 (and $x23450 (=> c_0_11 d_0_12))))
 (let (($x23454 (and $x23451 (=> c_0_12 d_0_12))))
 (let (($x23456 (and $x23454 (=> c_0_13 d_0_12))))
 (let (($x23458 (and $x23456 (=> c_0_14 d_0_12))))
 (let (($x23460 (and $x23458 (=> c_0_15 d_0_12))))
 (let (($x23462 (and $x23460 (=> c_0_16 d_0_12))))
 (let (($x23464 (and $x23462 (=> c_0_17 d_0_12))))
 (let (($x23466 (and $x23464 (=> c_0_18 d_0_12))))
 (let (($x23468 (and $x23466 (=> c_0_19 d_0_12))))
 (let (($x23470 (and $x23468 (=> c_0_20 d_0_12))))
 (let (($x23472 (and $x23470 (=> c_0_21 d_0_12))))
 (let (($x23474 (and $x23472 (=> c_0_22 d_0_12))))
 (let (($x23476 (and $x23474 (=> c_0_23 d_0_12))))
 (let (($x5329 (and true c_0_4)))
 (let (($x23479 (and $x5329 (and $x23476 (=> c_0_24 d_0_12)))))
 (let (($x23480 (and $x23479 $x14320)))
 (let (($x23481 (and $x23480 $x14371)))
 (let (($x23491 (= rule_instance 12)))
 (let (($x23376 (and true (=> c_0_0 d_0_11))))
 (let (($x23365 (and $x23376 (=> c_0_1 d_0_11))))
 (let (($x23391 (and $x23365 (=> c_0_2 d_0_11))))
 (let (($x23381 (and $x23391 (=> c_0_3 d_0_11))))
 (let (($x23368 (and $x23381 (=> c_0_4 d_0_11))))
 (let (($x23372 (and $x23368 (=> c_0_5 d_0_11))))
 (let (($x23370 (and $x23372 (=> c_0_6 d_0_11))))
 (let (($x23378 (and $x23370 (=> c_0_7 d_0_11))))
 (let (($x23374 (and $x23378 (=> c_0_8 d_0_11))))
 (let (($x23383 (and $x23374 (=> c_0_9 d_0_11))))
 (let (($x23389 (and $x23383 (=> c_0_10 d_0_11))))
 (let (($x23390 (and $x23389 (=> c_0_11 d_0_11))))
 (let (($x23393 (and $x23390 (=> c_0_12 d_0_11))))
 (let (($x23395 (and $x23393 (=> c_0_13 d_0_11))))
 (let (($x23397 (and $x23395 (=> c_0_14 d_0_11))))
 (let (($x23399 (and $x23397 (=> c_0_15 d_0_11))))
 (let (($x23401 (and $x23399 (=> c_0_16 d_0_11))))
 (let (($x23403 (and $x23401 (=> c_0_17 d_0_11))))
 (let (($x23405 (and $x23403 (=> c_0_18 d_0_11))))
 (let (($x23407 (and $x23405 (=> c_0_19 d_0_11))))
 (let (($x23409 (and $x23407 (=> c_0_20 d_0_11))))
 (let (($x23411 (and $x23409 (=> c_0_21 d_0_11))))
 (let (($x23413 (and $x23411 (=> c_0_22 d_0_11))))
 (let (($x23415 (and $x23413 (=> c_0_23 d_0_11))))
 (let (($x5299 (and true c_0_3)))
 (let (($x23418 (and $x5299 (and $x23415 (=> c_0_24 d_0_11)))))
 (let (($x23419 (and $x23418 $x14320)))
 (let (($x23420 (and $x23419 $x14371)))
 (let (($x23430 (= rule_instance 8)))
 (let (($x23275 (and true (=> c_0_0 d_0_10))))
 (let (($x23269 (and $x23275 (=> c_0_1 d_0_10))))
 (let (($x23330 (and $x23269 (=> c_0_2 d_0_10))))
 (let (($x23319 (and $x23330 (=> c_0_3 d_0_10))))
 (let (($x23318 (and $x23319 (=> c_0_4 d_0_10))))
 (let (($x23301 (and $x23318 (=> c_0_5 d_0_10))))
 (let (($x23271 (and $x23301 (=> c_0_6 d_0_10))))
 (let (($x23311 (and $x23271 (=> c_0_7 d_0_10))))
 (let (($x23324 (and $x23311 (=> c_0_8 d_0_10))))
 (let (($x23317 (and $x23324 (=> c_0_9 d_0_10))))
 (let (($x23328 (and $x23317 (=> c_0_10 d_0_10))))
 (let (($x23329 (and $x23328 (=> c_0_11 d_0_10))))
 (let (($x23332 (and $x23329 (=> c_0_12 d_0_10))))
 (let (($x23334 (and $x23332 (=> c_0_13 d_0_10))))
 (let (($x23336 (and $x23334 (=> c_0_14 d_0_10))))
 (let (($x23338 (and $x23336 (=> c_0_15 d_0_10))))
 (let (($x23340 (and $x23338 (=> c_0_16 d_0_10))))
 (let (($x23342 (and $x23340 (=> c_0_17 d_0_10))))
 (let (($x23344 (and $x23342 (=> c_0_18 d_0_10))))
 (let (($x23346 (and $x23344 (=> c_0_19 d_0_10))))
 (let (($x23348 (and $x23346 (=> c_0_20 d_0_10))))
 (let (($x23350 (and $x23348 (=> c_0_21 d_0_10))))
 (let (($x23352 (and $x23350 (=> c_0_22 d_0_10))))
 (let (($x23354 (and $x23352 (=> c_0_23 d_0_10))))
 (let (($x5269 (and true c_0_2)))
 (let (($x23357 (and $x5269 (and $x23354 (=> c_0_24 d_0_10)))))
 (let (($x23358 (and $x23357 $x14320)))
 (let (($x23359 (and $x23358 $x14371)))
 (let (($x23369 (= rule_instance 4)))
 (let (($x14202 (and true (=> c_0_0 d_0_9))))
 (let (($x14234 (and $x14202 (=> c_0_1 d_0_9))))
 (let (($x14220 (and $x14234 (=> c_0_2 d_0_9))))
 (let (($x14216 (and $x14220 (=> c_0_3 d_0_9))))
 (let (($x14196 (and $x14216 (=> c_0_4 d_0_9))))
 (let (($x14194 (and $x14196 (=> c_0_5 d_0_9))))
 (let (($x14208 (and $x14194 (=> c_0_6 d_0_9))))
 (let (($x14200 (and $x14208 (=> c_0_7 d_0_9))))
 (let (($x14236 (and $x14200 (=> c_0_8 d_0_9))))
 (let (($x14232 (and $x14236 (=> c_0_9 d_0_9))))
 (let (($x14241 (and $x14232 (=> c_0_10 d_0_9))))
 (let (($x14243 (and $x14241 (=> c_0_11 d_0_9))))
 (let (($x14245 (and $x14243 (=> c_0_12 d_0_9))))
 (let (($x14247 (and $x14245 (=> c_0_13 d_0_9))))
 (let (($x14249 (and $x14247 (=> c_0_14 d_0_9))))
 (let (($x14251 (and $x14249 (=> c_0_15 d_0_9))))
 (let (($x14253 (and $x14251 (=> c_0_16 d_0_9))))
 (let (($x14255 (and $x14253 (=> c_0_17 d_0_9))))
 (let (($x14257 (and $x14255 (=> c_0_18 d_0_9))))
 (let (($x14259 (and $x14257 (=> c_0_19 d_0_9))))
 (let (($x14261 (and $x14259 (=> c_0_20 d_0_9))))
 (let (($x14263 (and $x14261 (=> c_0_21 d_0_9))))
 (let (($x14265 (and $x14263 (=> c_0_22 d_0_9))))
 (let (($x14267 (and $x14265 (=> c_0_23 d_0_9))))
 (let (($x5239 (and true c_0_1)))
 (let (($x14270 (and $x5239 (and $x14267 (=> c_0_24 d_0_9)))))
 (let (($x14321 (and $x14270 $x14320)))
 (let (($x14372 (and $x14321 $x14371)))
 (let (($x23289 (= rule_instance 0)))
 (let (($x23291 (or false (and (and $x23289 (and (and $x14230 (and $x14372 $x14422)) $x23281)) $x23299))))
 (let (($x23377 (or $x23291 (and (and $x23369 (and (and $x14230 (and $x23359 $x14422)) $x23281)) $x23299))))
 (let (($x23438 (or $x23377 (and (and $x23430 (and (and $x14230 (and $x23420 $x14422)) $x23281)) $x23299))))
 (let (($x23499 (or $x23438 (and (and $x23491 (and (and $x14230 (and $x23481 $x14422)) $x23281)) $x23299))))
 (let (($x23560 (or $x23499 (and (and $x23552 (and (and $x14230 (and $x23542 $x14422)) $x23281)) $x23299))))
 (let (($x23621 (or $x23560 (and (and $x23613 (and (and $x14230 (and $x23603 $x14422)) $x23281)) $x23299))))
 (let (($x23682 (or $x23621 (and (and $x23674 (and (and $x14230 (and $x23664 $x14422)) $x23281)) $x23299))))
 (let (($x23744 (or $x23682 (and (and $x23736 (and (and $x14230 (and $x23726 $x14422)) $x23281)) $x23299))))
 (let (($x23805 (or $x23744 (and (and $x23797 (and (and $x14230 (and $x23787 $x14422)) $x23281)) $x23299))))
 (let (($x23866 (or $x23805 (and (and $x23858 (and (and $x14230 (and $x23848 $x14422)) $x23281)) $x23299))))
 (let (($x23927 (or $x23866 (and (and $x23919 (and (and $x14230 (and $x23909 $x14422)) $x23281)) $x23299))))
 (let (($x23988 (or $x23927 (and (and $x23980 (and (and $x14230 (and $x23970 $x14422)) $x23281)) $x23299))))
 (let (($x24049 (or $x23988 (and (and $x24041 (and (and $x14230 (and $x24031 $x14422)) $x23281)) $x23299))))
 (let (($x24110 (or $x24049 (and (and $x24102 (and (and $x14230 (and $x24092 $x14422)) $x23281)) $x23299))))
 (let (($x24171 (or $x24110 (and (and $x24163 (and (and $x14230 (and $x24153 $x14422)) $x23281)) $x23299))))
 (or $x24171 (and (and $x24224 (and (and $x14230 (and $x24214 $x14422)) $x23281)) $x23299)))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
