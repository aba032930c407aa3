; holon proof obligation: system general_lock2, region square:3x2, property mass_conservation
; expected: unsat (the property holds for every configuration of the region)
(set-logic ALL)
; 
(set-info :status unknown)
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
(declare-fun d_4_15 () Bool)
(declare-fun d_4_14 () Bool)
(declare-fun d_4_13 () Bool)
(declare-fun d_4_12 () Bool)
(declare-fun d_4_11 () Bool)
(declare-fun d_4_10 () Bool)
(declare-fun d_4_9 () Bool)
(declare-fun d_4_8 () Bool)
(declare-fun d_4_7 () Bool)
(declare-fun d_4_6 () Bool)
(declare-fun d_4_5 () Bool)
(declare-fun d_4_4 () Bool)
(declare-fun d_4_3 () Bool)
(declare-fun d_4_2 () Bool)
(declare-fun d_4_1 () Bool)
(declare-fun d_4_0 () Bool)
(declare-fun d_5_15 () Bool)
(declare-fun d_5_14 () Bool)
(declare-fun d_5_13 () Bool)
(declare-fun d_5_12 () Bool)
(declare-fun d_5_11 () Bool)
(declare-fun d_5_10 () Bool)
(declare-fun d_5_9 () Bool)
(declare-fun d_5_8 () Bool)
(declare-fun d_5_7 () Bool)
(declare-fun d_5_6 () Bool)
(declare-fun d_5_5 () Bool)
(declare-fun d_5_4 () Bool)
(declare-fun d_5_3 () Bool)
(declare-fun d_5_2 () Bool)
(declare-fun d_5_1 () Bool)
(declare-fun d_5_0 () Bool)
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
(declare-fun rank_36 () Int)
(declare-fun rank_38 () Int)
(declare-fun rank_40 () Int)
(declare-fun rank_42 () Int)
(declare-fun rank_44 () Int)
(declare-fun rank_46 () Int)
(declare-fun rank_48 () Int)
(declare-fun rank_50 () Int)
(declare-fun rank_52 () Int)
(declare-fun rank_54 () Int)
(declare-fun rank_56 () Int)
(declare-fun rank_58 () Int)
(declare-fun rank_60 () Int)
(declare-fun rank_62 () Int)
(declare-fun rank_64 () Int)
(declare-fun rank_66 () Int)
(declare-fun rank_68 () Int)
(declare-fun rank_70 () Int)
(declare-fun rank_72 () Int)
(declare-fun rank_74 () Int)
(declare-fun rank_76 () Int)
(declare-fun rank_78 () Int)
(declare-fun rank_80 () Int)
(declare-fun rank_82 () Int)
(declare-fun rank_84 () Int)
(declare-fun rank_86 () Int)
(declare-fun rank_88 () Int)
(declare-fun rank_90 () Int)
(declare-fun rank_92 () Int)
(declare-fun rank_94 () Int)
(declare-fun rank_96 () Int)
(declare-fun rank_98 () Int)
(declare-fun rank_100 () Int)
(declare-fun rank_102 () Int)
(declare-fun rank_104 () Int)
(declare-fun rank_106 () Int)
(declare-fun rank_108 () Int)
(declare-fun rank_110 () Int)
(declare-fun rank_112 () Int)
(declare-fun rank_114 () Int)
(declare-fun rank_116 () Int)
(declare-fun rank_118 () Int)
(declare-fun root_119 () Bool)
(declare-fun root_117 () Bool)
(declare-fun root_115 () Bool)
(declare-fun root_113 () Bool)
(declare-fun root_111 () Bool)
(declare-fun root_109 () Bool)
(declare-fun root_107 () Bool)
(declare-fun root_105 () Bool)
(declare-fun root_103 () Bool)
(declare-fun root_101 () Bool)
(declare-fun root_99 () Bool)
(declare-fun root_97 () Bool)
(declare-fun rule_instance () Int)
(declare-fun root_95 () Bool)
(declare-fun root_93 () Bool)
(declare-fun root_91 () Bool)
(declare-fun root_89 () Bool)
(declare-fun root_87 () Bool)
(declare-fun root_85 () Bool)
(declare-fun root_83 () Bool)
(declare-fun root_81 () Bool)
(declare-fun root_79 () Bool)
(declare-fun root_77 () Bool)
(declare-fun root_75 () Bool)
(declare-fun root_73 () Bool)
(declare-fun root_71 () Bool)
(declare-fun root_69 () Bool)
(declare-fun root_67 () Bool)
(declare-fun root_65 () Bool)
(declare-fun root_63 () Bool)
(declare-fun root_61 () Bool)
(declare-fun root_59 () Bool)
(declare-fun root_57 () Bool)
(declare-fun root_55 () Bool)
(declare-fun root_53 () Bool)
(declare-fun root_51 () Bool)
(declare-fun root_49 () Bool)
(declare-fun root_47 () Bool)
(declare-fun root_45 () Bool)
(declare-fun root_43 () Bool)
(declare-fun root_41 () Bool)
(declare-fun root_39 () Bool)
(declare-fun root_37 () Bool)
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
 (let (($x6 (or false c_0_0)))
 (let (($x8 (or $x6 c_0_1)))
 (let (($x10 (or $x8 c_0_2)))
 (let (($x12 (or $x10 c_0_3)))
 (let (($x14 (or $x12 c_0_4)))
 (let (($x16 (or $x14 c_0_5)))
 (let (($x18 (or $x16 c_0_6)))
 (let (($x20 (or $x18 c_0_7)))
 (let (($x22 (or $x20 c_0_8)))
 (let (($x24 (or $x22 c_0_9)))
 (let (($x26 (or $x24 c_0_10)))
 (let (($x28 (or $x26 c_0_11)))
 (let (($x30 (or $x28 c_0_12)))
 (let (($x32 (or $x30 c_0_13)))
 (let (($x34 (or $x32 c_0_14)))
 (or $x34 c_0_15)))))))))))))))))
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
 (not (and c_0_11 c_0_12)))
(assert
 (not (and c_0_11 c_0_13)))
(assert
 (not (and c_0_11 c_0_14)))
(assert
 (not (and c_0_11 c_0_15)))
(assert
 (not (and c_0_12 c_0_13)))
(assert
 (not (and c_0_12 c_0_14)))
(assert
 (not (and c_0_12 c_0_15)))
(assert
 (not (and c_0_13 c_0_14)))
(assert
 (not (and c_0_13 c_0_15)))
(assert
 (not (and c_0_14 c_0_15)))
(assert
 (let (($x278 (or false c_1_0)))
 (let (($x280 (or $x278 c_1_1)))
 (let (($x282 (or $x280 c_1_2)))
 (let (($x284 (or $x282 c_1_3)))
 (let (($x286 (or $x284 c_1_4)))
 (let (($x288 (or $x286 c_1_5)))
 (let (($x290 (or $x288 c_1_6)))
 (let (($x292 (or $x290 c_1_7)))
 (let (($x294 (or $x292 c_1_8)))
 (let (($x296 (or $x294 c_1_9)))
 (let (($x298 (or $x296 c_1_10)))
 (let (($x300 (or $x298 c_1_11)))
 (let (($x302 (or $x300 c_1_12)))
 (let (($x304 (or $x302 c_1_13)))
 (let (($x306 (or $x304 c_1_14)))
 (or $x306 c_1_15)))))))))))))))))
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
 (not (and c_1_11 c_1_12)))
(assert
 (not (and c_1_11 c_1_13)))
(assert
 (not (and c_1_11 c_1_14)))
(assert
 (not (and c_1_11 c_1_15)))
(assert
 (not (and c_1_12 c_1_13)))
(assert
 (not (and c_1_12 c_1_14)))
(assert
 (not (and c_1_12 c_1_15)))
(assert
 (not (and c_1_13 c_1_14)))
(assert
 (not (and c_1_13 c_1_15)))
(assert
 (not (and c_1_14 c_1_15)))
(assert
 (let (($x550 (or false c_2_0)))
 (let (($x552 (or $x550 c_2_1)))
 (let (($x554 (or $x552 c_2_2)))
 (let (($x556 (or $x554 c_2_3)))
 (let (($x558 (or $x556 c_2_4)))
 (let (($x560 (or $x558 c_2_5)))
 (let (($x562 (or $x560 c_2_6)))
 (let (($x564 (or $x562 c_2_7)))
 (let (($x566 (or $x564 c_2_8)))
 (let (($x568 (or $x566 c_2_9)))
 (let (($x570 (or $x568 c_2_10)))
 (let (($x572 (or $x570 c_2_11)))
 (let (($x574 (or $x572 c_2_12)))
 (let (($x576 (or $x574 c_2_13)))
 (let (($x578 (or $x576 c_2_14)))
 (or $x578 c_2_15)))))))))))))))))
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
 (not (and c_2_11 c_2_12)))
(assert
 (not (and c_2_11 c_2_13)))
(assert
 (not (and c_2_11 c_2_14)))
(assert
 (not (and c_2_11 c_2_15)))
(assert
 (not (and c_2_12 c_2_13)))
(assert
 (not (and c_2_12 c_2_14)))
(assert
 (not (and c_2_12 c_2_15)))
(assert
 (not (and c_2_13 c_2_14)))
(assert
 (not (and c_2_13 c_2_15)))
(assert
 (not (and c_2_14 c_2_15)))
(assert
 (let (($x822 (or false c_3_0)))
 (let (($x824 (or $x822 c_3_1)))
 (let (($x826 (or $x824 c_3_2)))
 (let (($x828 (or $x826 c_3_3)))
 (let (($x830 (or $x828 c_3_4)))
 (let (($x832 (or $x830 c_3_5)))
 (let (($x834 (or $x832 c_3_6)))
 (let (($x836 (or $x834 c_3_7)))
 (let (($x838 (or $x836 c_3_8)))
 (let (($x840 (or $x838 c_3_9)))
 (let (($x842 (or $x840 c_3_10)))
 (let (($x844 (or $x842 c_3_11)))
 (let (($x846 (or $x844 c_3_12)))
 (let (($x848 (or $x846 c_3_13)))
 (let (($x850 (or $x848 c_3_14)))
 (or $x850 c_3_15)))))))))))))))))
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
 (not (and c_3_11 c_3_12)))
(assert
 (not (and c_3_11 c_3_13)))
(assert
 (not (and c_3_11 c_3_14)))
(assert
 (not (and c_3_11 c_3_15)))
(assert
 (not (and c_3_12 c_3_13)))
(assert
 (not (and c_3_12 c_3_14)))
(assert
 (not (and c_3_12 c_3_15)))
(assert
 (not (and c_3_13 c_3_14)))
(assert
 (not (and c_3_13 c_3_15)))
(assert
 (not (and c_3_14 c_3_15)))
(assert
 (let (($x1094 (or false c_4_0)))
 (let (($x1096 (or $x1094 c_4_1)))
 (let (($x1098 (or $x1096 c_4_2)))
 (let (($x1100 (or $x1098 c_4_3)))
 (let (($x1102 (or $x1100 c_4_4)))
 (let (($x1104 (or $x1102 c_4_5)))
 (let (($x1106 (or $x1104 c_4_6)))
 (let (($x1108 (or $x1106 c_4_7)))
 (let (($x1110 (or $x1108 c_4_8)))
 (let (($x1112 (or $x1110 c_4_9)))
 (let (($x1114 (or $x1112 c_4_10)))
 (let (($x1116 (or $x1114 c_4_11)))
 (let (($x1118 (or $x1116 c_4_12)))
 (let (($x1120 (or $x1118 c_4_13)))
 (let (($x1122 (or $x1120 c_4_14)))
 (or $x1122 c_4_15)))))))))))))))))
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
 (not (and c_4_11 c_4_12)))
(assert
 (not (and c_4_11 c_4_13)))
(assert
 (not (and c_4_11 c_4_14)))
(assert
 (not (and c_4_11 c_4_15)))
(assert
 (not (and c_4_12 c_4_13)))
(assert
 (not (and c_4_12 c_4_14)))
(assert
 (not (and c_4_12 c_4_15)))
(assert
 (not (and c_4_13 c_4_14)))
(assert
 (not (and c_4_13 c_4_15)))
(assert
 (not (and c_4_14 c_4_15)))
(assert
 (let (($x1366 (or false c_5_0)))
 (let (($x1368 (or $x1366 c_5_1)))
 (let (($x1370 (or $x1368 c_5_2)))
 (let (($x1372 (or $x1370 c_5_3)))
 (let (($x1374 (or $x1372 c_5_4)))
 (let (($x1376 (or $x1374 c_5_5)))
 (let (($x1378 (or $x1376 c_5_6)))
 (let (($x1380 (or $x1378 c_5_7)))
 (let (($x1382 (or $x1380 c_5_8)))
 (let (($x1384 (or $x1382 c_5_9)))
 (let (($x1386 (or $x1384 c_5_10)))
 (let (($x1388 (or $x1386 c_5_11)))
 (let (($x1390 (or $x1388 c_5_12)))
 (let (($x1392 (or $x1390 c_5_13)))
 (let (($x1394 (or $x1392 c_5_14)))
 (or $x1394 c_5_15)))))))))))))))))
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
 (not (and c_5_11 c_5_12)))
(assert
 (not (and c_5_11 c_5_13)))
(assert
 (not (and c_5_11 c_5_14)))
(assert
 (not (and c_5_11 c_5_15)))
(assert
 (not (and c_5_12 c_5_13)))
(assert
 (not (and c_5_12 c_5_14)))
(assert
 (not (and c_5_12 c_5_15)))
(assert
 (not (and c_5_13 c_5_14)))
(assert
 (not (and c_5_13 c_5_15)))
(assert
 (not (and c_5_14 c_5_15)))
(assert
 (let (($x1638 (or false d_0_0)))
 (let (($x1640 (or $x1638 d_0_1)))
 (let (($x1642 (or $x1640 d_0_2)))
 (let (($x1644 (or $x1642 d_0_3)))
 (let (($x1646 (or $x1644 d_0_4)))
 (let (($x1648 (or $x1646 d_0_5)))
 (let (($x1650 (or $x1648 d_0_6)))
 (let (($x1652 (or $x1650 d_0_7)))
 (let (($x1654 (or $x1652 d_0_8)))
 (let (($x1656 (or $x1654 d_0_9)))
 (let (($x1658 (or $x1656 d_0_10)))
 (let (($x1660 (or $x1658 d_0_11)))
 (let (($x1662 (or $x1660 d_0_12)))
 (let (($x1664 (or $x1662 d_0_13)))
 (let (($x1666 (or $x1664 d_0_14)))
 (or $x1666 d_0_15)))))))))))))))))
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
 (not (and d_0_11 d_0_12)))
(assert
 (not (and d_0_11 d_0_13)))
(assert
 (not (and d_0_11 d_0_14)))
(assert
 (not (and d_0_11 d_0_15)))
(assert
 (not (and d_0_12 d_0_13)))
(assert
 (not (and d_0_12 d_0_14)))
(assert
 (not (and d_0_12 d_0_15)))
(assert
 (not (and d_0_13 d_0_14)))
(assert
 (not (and d_0_13 d_0_15)))
(assert
 (not (and d_0_14 d_0_15)))
(assert
 (let (($x1910 (or false d_1_0)))
 (let (($x1912 (or $x1910 d_1_1)))
 (let (($x1914 (or $x1912 d_1_2)))
 (let (($x1916 (or $x1914 d_1_3)))
 (let (($x1918 (or $x1916 d_1_4)))
 (let (($x1920 (or $x1918 d_1_5)))
 (let (($x1922 (or $x1920 d_1_6)))
 (let (($x1924 (or $x1922 d_1_7)))
 (let (($x1926 (or $x1924 d_1_8)))
 (let (($x1928 (or $x1926 d_1_9)))
 (let (($x1930 (or $x1928 d_1_10)))
 (let (($x1932 (or $x1930 d_1_11)))
 (let (($x1934 (or $x1932 d_1_12)))
 (let (($x1936 (or $x1934 d_1_13)))
 (let (($x1938 (or $x1936 d_1_14)))
 (or $x1938 d_1_15)))))))))))))))))
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
 (not (and d_1_11 d_1_12)))
(assert
 (not (and d_1_11 d_1_13)))
(assert
 (not (and d_1_11 d_1_14)))
(assert
 (not (and d_1_11 d_1_15)))
(assert
 (not (and d_1_12 d_1_13)))
(assert
 (not (and d_1_12 d_1_14)))
(assert
 (not (and d_1_12 d_1_15)))
(assert
 (not (and d_1_13 d_1_14)))
(assert
 (not (and d_1_13 d_1_15)))
(assert
 (not (and d_1_14 d_1_15)))
(assert
 (let (($x2182 (or false d_2_0)))
 (let (($x2184 (or $x2182 d_2_1)))
 (let (($x2186 (or $x2184 d_2_2)))
 (let (($x2188 (or $x2186 d_2_3)))
 (let (($x2190 (or $x2188 d_2_4)))
 (let (($x2192 (or $x2190 d_2_5)))
 (let (($x2194 (or $x2192 d_2_6)))
 (let (($x2196 (or $x2194 d_2_7)))
 (let (($x2198 (or $x2196 d_2_8)))
 (let (($x2200 (or $x2198 d_2_9)))
 (let (($x2202 (or $x2200 d_2_10)))
 (let (($x2204 (or $x2202 d_2_11)))
 (let (($x2206 (or $x2204 d_2_12)))
 (let (($x2208 (or $x2206 d_2_13)))
 (let (($x2210 (or $x2208 d_2_14)))
 (or $x2210 d_2_15)))))))))))))))))
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
 (not (and d_2_11 d_2_12)))
(assert
 (not (and d_2_11 d_2_13)))
(assert
 (not (and d_2_11 d_2_14)))
(assert
 (not (and d_2_11 d_2_15)))
(assert
 (not (and d_2_12 d_2_13)))
(assert
 (not (and d_2_12 d_2_14)))
(assert
 (not (and d_2_12 d_2_15)))
(assert
 (not (and d_2_13 d_2_14)))
(assert
 (not (and d_2_13 d_2_15)))
(assert
 (not (and d_2_14 d_2_15)))
(assert
 (let (($x2454 (or false d_3_0)))
 (let (($x2456 (or $x2454 d_3_1)))
 (let (($x2458 (or $x2456 d_3_2)))
 (let (($x2460 (or $x2458 d_3_3)))
 (let (($x2462 (or $x2460 d_3_4)))
 (let (($x2464 (or $x2462 d_3_5)))
 (let (($x2466 (or $x2464 d_3_6)))
 (let (($x2468 (or $x2466 d_3_7)))
 (let (($x2470 (or $x2468 d_3_8)))
 (let (($x2472 (or $x2470 d_3_9)))
 (let (($x2474 (or $x2472 d_3_10)))
 (let (($x2476 (or $x2474 d_3_11)))
 (let (($x2478 (or $x2476 d_3_12)))
 (let (($x2480 (or $x2478 d_3_13)))
 (let (($x2482 (or $x2480 d_3_14)))
 (or $x2482 d_3_15)))))))))))))))))
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
 (not (and d_3_11 d_3_12)))
(assert
 (not (and d_3_11 d_3_13)))
(assert
 (not (and d_3_11 d_3_14)))
(assert
 (not (and d_3_11 d_3_15)))
(assert
 (not (and d_3_12 d_3_13)))
(assert
 (not (and d_3_12 d_3_14)))
(assert
 (not (and d_3_12 d_3_15)))
(assert
 (not (and d_3_13 d_3_14)))
(assert
 (not (and d_3_13 d_3_15)))
(assert
 (not (and d_3_14 d_3_15)))
(assert
 (let (($x2726 (or false d_4_0)))
 (let (($x2728 (or $x2726 d_4_1)))
 (let (($x2730 (or $x2728 d_4_2)))
 (let (($x2732 (or $x2730 d_4_3)))
 (let (($x2734 (or $x2732 d_4_4)))
 (let (($x2736 (or $x2734 d_4_5)))
 (let (($x2738 (or $x2736 d_4_6)))
 (let (($x2740 (or $x2738 d_4_7)))
 (let (($x2742 (or $x2740 d_4_8)))
 (let (($x2744 (or $x2742 d_4_9)))
 (let (($x2746 (or $x2744 d_4_10)))
 (let (($x2748 (or $x2746 d_4_11)))
 (let (($x2750 (or $x2748 d_4_12)))
 (let (($x2752 (or $x2750 d_4_13)))
 (let (($x2754 (or $x2752 d_4_14)))
 (or $x2754 d_4_15)))))))))))))))))
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
 (not (and d_4_0 d_4_7)))
(assert
 (not (and d_4_0 d_4_8)))
(assert
 (not (and d_4_0 d_4_9)))
(assert
 (not (and d_4_0 d_4_10)))
(assert
 (not (and d_4_0 d_4_11)))
(assert
 (not (and d_4_0 d_4_12)))
(assert
 (not (and d_4_0 d_4_13)))
(assert
 (not (and d_4_0 d_4_14)))
(assert
 (not (and d_4_0 d_4_15)))
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
 (not (and d_4_1 d_4_7)))
(assert
 (not (and d_4_1 d_4_8)))
(assert
 (not (and d_4_1 d_4_9)))
(assert
 (not (and d_4_1 d_4_10)))
(assert
 (not (and d_4_1 d_4_11)))
(assert
 (not (and d_4_1 d_4_12)))
(assert
 (not (and d_4_1 d_4_13)))
(assert
 (not (and d_4_1 d_4_14)))
(assert
 (not (and d_4_1 d_4_15)))
(assert
 (not (and d_4_2 d_4_3)))
(assert
 (not (and d_4_2 d_4_4)))
(assert
 (not (and d_4_2 d_4_5)))
(assert
 (not (and d_4_2 d_4_6)))
(assert
 (not (and d_4_2 d_4_7)))
(assert
 (not (and d_4_2 d_4_8)))
(assert
 (not (and d_4_2 d_4_9)))
(assert
 (not (and d_4_2 d_4_10)))
(assert
 (not (and d_4_2 d_4_11)))
(assert
 (not (and d_4_2 d_4_12)))
(assert
 (not (and d_4_2 d_4_13)))
(assert
 (not (and d_4_2 d_4_14)))
(assert
 (not (and d_4_2 d_4_15)))
(assert
 (not (and d_4_3 d_4_4)))
(assert
 (not (and d_4_3 d_4_5)))
(assert
 (not (and d_4_3 d_4_6)))
(assert
 (not (and d_4_3 d_4_7)))
(assert
 (not (and d_4_3 d_4_8)))
(assert
 (not (and d_4_3 d_4_9)))
(assert
 (not (and d_4_3 d_4_10)))
(assert
 (not (and d_4_3 d_4_11)))
(assert
 (not (and d_4_3 d_4_12)))
(assert
 (not (and d_4_3 d_4_13)))
(assert
 (not (and d_4_3 d_4_14)))
(assert
 (not (and d_4_3 d_4_15)))
(assert
 (not (and d_4_4 d_4_5)))
(assert
 (not (and d_4_4 d_4_6)))
(assert
 (not (and d_4_4 d_4_7)))
(assert
 (not (and d_4_4 d_4_8)))
(assert
 (not (and d_4_4 d_4_9)))
(assert
 (not (and d_4_4 d_4_10)))
(assert
 (not (and d_4_4 d_4_11)))
(assert
 (not (and d_4_4 d_4_12)))
(assert
 (not (and d_4_4 d_4_13)))
(assert
 (not (and d_4_4 d_4_14)))
(assert
 (not (and d_4_4 d_4_15)))
(assert
 (not (and d_4_5 d_4_6)))
(assert
 (not (and d_4_5 d_4_7)))
(assert
 (not (and d_4_5 d_4_8)))
(assert
 (not (and d_4_5 d_4_9)))
(assert
 (not (and d_4_5 d_4_10)))
(assert
 (not (and d_4_5 d_4_11)))
(assert
 (not (and d_4_5 d_4_12)))
(assert
 (not (and d_4_5 d_4_13)))
(assert
 (not (and d_4_5 d_4_14)))
(assert
 (not (and d_4_5 d_4_15)))
(assert
 (not (and d_4_6 d_4_7)))
(assert
 (not (and d_4_6 d_4_8)))
(assert
 (not (and d_4_6 d_4_9)))
(assert
 (not (and d_4_6 d_4_10)))
(assert
 (not (and d_4_6 d_4_11)))
(assert
 (not (and d_4_6 d_4_12)))
(assert
 (not (and d_4_6 d_4_13)))
(assert
 (not (and d_4_6 d_4_14)))
(assert
 (not (and d_4_6 d_4_15)))
(assert
 (not (and d_4_7 d_4_8)))
(assert
 (not (and d_4_7 d_4_9)))
(assert
 (not (and d_4_7 d_4_10)))
(assert
 (not (and d_4_7 d_4_11)))
(assert
 (not (and d_4_7 d_4_12)))
(assert
 (not (and d_4_7 d_4_13)))
(assert
 (not (and d_4_7 d_4_14)))
(assert
 (not (and d_4_7 d_4_15)))
(assert
 (not (and d_4_8 d_4_9)))
(assert
 (not (and d_4_8 d_4_10)))
(assert
 (not (and d_4_8 d_4_11)))
(assert
 (not (and d_4_8 d_4_12)))
(assert
 (not (and d_4_8 d_4_13)))
(assert
 (not (and d_4_8 d_4_14)))
(assert
 (not (and d_4_8 d_4_15)))
(assert
 (not (and d_4_9 d_4_10)))
(assert
 (not (and d_4_9 d_4_11)))
(assert
 (not (and d_4_9 d_4_12)))
(assert
 (not (and d_4_9 d_4_13)))
(assert
 (not (and d_4_9 d_4_14)))
(assert
 (not (and d_4_9 d_4_15)))
(assert
 (not (and d_4_10 d_4_11)))
(assert
 (not (and d_4_10 d_4_12)))
(assert
 (not (and d_4_10 d_4_13)))
(assert
 (not (and d_4_10 d_4_14)))
(assert
 (not (and d_4_10 d_4_15)))
(assert
 (not (and d_4_11 d_4_12)))
(assert
 (not (and d_4_11 d_4_13)))
(assert
 (not (and d_4_11 d_4_14)))
(assert
 (not (and d_4_11 d_4_15)))
(assert
 (not (and d_4_12 d_4_13)))
(assert
 (not (and d_4_12 d_4_14)))
(assert
 (not (and d_4_12 d_4_15)))
(assert
 (not (and d_4_13 d_4_14)))
(assert
 (not (and d_4_13 d_4_15)))
(assert
 (not (and d_4_14 d_4_15)))
(assert
 (let (($x2998 (or false d_5_0)))
 (let (($x3000 (or $x2998 d_5_1)))
 (let (($x3002 (or $x3000 d_5_2)))
 (let (($x3004 (or $x3002 d_5_3)))
 (let (($x3006 (or $x3004 d_5_4)))
 (let (($x3008 (or $x3006 d_5_5)))
 (let (($x3010 (or $x3008 d_5_6)))
 (let (($x3012 (or $x3010 d_5_7)))
 (let (($x3014 (or $x3012 d_5_8)))
 (let (($x3016 (or $x3014 d_5_9)))
 (let (($x3018 (or $x3016 d_5_10)))
 (let (($x3020 (or $x3018 d_5_11)))
 (let (($x3022 (or $x3020 d_5_12)))
 (let (($x3024 (or $x3022 d_5_13)))
 (let (($x3026 (or $x3024 d_5_14)))
 (or $x3026 d_5_15)))))))))))))))))
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
 (not (and d_5_0 d_5_7)))
(assert
 (not (and d_5_0 d_5_8)))
(assert
 (not (and d_5_0 d_5_9)))
(assert
 (not (and d_5_0 d_5_10)))
(assert
 (not (and d_5_0 d_5_11)))
(assert
 (not (and d_5_0 d_5_12)))
(assert
 (not (and d_5_0 d_5_13)))
(assert
 (not (and d_5_0 d_5_14)))
(assert
 (not (and d_5_0 d_5_15)))
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
 (not (and d_5_1 d_5_7)))
(assert
 (not (and d_5_1 d_5_8)))
(assert
 (not (and d_5_1 d_5_9)))
(assert
 (not (and d_5_1 d_5_10)))
(assert
 (not (and d_5_1 d_5_11)))
(assert
 (not (and d_5_1 d_5_12)))
(assert
 (not (and d_5_1 d_5_13)))
(assert
 (not (and d_5_1 d_5_14)))
(assert
 (not (and d_5_1 d_5_15)))
(assert
 (not (and d_5_2 d_5_3)))
(assert
 (not (and d_5_2 d_5_4)))
(assert
 (not (and d_5_2 d_5_5)))
(assert
 (not (and d_5_2 d_5_6)))
(assert
 (not (and d_5_2 d_5_7)))
(assert
 (not (and d_5_2 d_5_8)))
(assert
 (not (and d_5_2 d_5_9)))
(assert
 (not (and d_5_2 d_5_10)))
(assert
 (not (and d_5_2 d_5_11)))
(assert
 (not (and d_5_2 d_5_12)))
(assert
 (not (and d_5_2 d_5_13)))
(assert
 (not (and d_5_2 d_5_14)))
(assert
 (not (and d_5_2 d_5_15)))
(assert
 (not (and d_5_3 d_5_4)))
(assert
 (not (and d_5_3 d_5_5)))
(assert
 (not (and d_5_3 d_5_6)))
(assert
 (not (and d_5_3 d_5_7)))
(assert
 (not (and d_5_3 d_5_8)))
(assert
 (not (and d_5_3 d_5_9)))
(assert
 (not (and d_5_3 d_5_10)))
(assert
 (not (and d_5_3 d_5_11)))
(assert
 (not (and d_5_3 d_5_12)))
(assert
 (not (and d_5_3 d_5_13)))
(assert
 (not (and d_5_3 d_5_14)))
(assert
 (not (and d_5_3 d_5_15)))
(assert
 (not (and d_5_4 d_5_5)))
(assert
 (not (and d_5_4 d_5_6)))
(assert
 (not (and d_5_4 d_5_7)))
(assert
 (not (and d_5_4 d_5_8)))
(assert
 (not (and d_5_4 d_5_9)))
(assert
 (not (and d_5_4 d_5_10)))
(assert
 (not (and d_5_4 d_5_11)))
(assert
 (not (and d_5_4 d_5_12)))
(assert
 (not (and d_5_4 d_5_13)))
(assert
 (not (and d_5_4 d_5_14)))
(assert
 (not (and d_5_4 d_5_15)))
(assert
 (not (and d_5_5 d_5_6)))
(assert
 (not (and d_5_5 d_5_7)))
(assert
 (not (and d_5_5 d_5_8)))
(assert
 (not (and d_5_5 d_5_9)))
(assert
 (not (and d_5_5 d_5_10)))
(assert
 (not (and d_5_5 d_5_11)))
(assert
 (not (and d_5_5 d_5_12)))
(assert
 (not (and d_5_5 d_5_13)))
(assert
 (not (and d_5_5 d_5_14)))
(assert
 (not (and d_5_5 d_5_15)))
(assert
 (not (and d_5_6 d_5_7)))
(assert
 (not (and d_5_6 d_5_8)))
(assert
 (not (and d_5_6 d_5_9)))
(assert
 (not (and d_5_6 d_5_10)))
(assert
 (not (and d_5_6 d_5_11)))
(assert
 (not (and d_5_6 d_5_12)))
(assert
 (not (and d_5_6 d_5_13)))
(assert
 (not (and d_5_6 d_5_14)))
(assert
 (not (and d_5_6 d_5_15)))
(assert
 (not (and d_5_7 d_5_8)))
(assert
 (not (and d_5_7 d_5_9)))
(assert
 (not (and d_5_7 d_5_10)))
(assert
 (not (and d_5_7 d_5_11)))
(assert
 (not (and d_5_7 d_5_12)))
(assert
 (not (and d_5_7 d_5_13)))
(assert
 (not (and d_5_7 d_5_14)))
(assert
 (not (and d_5_7 d_5_15)))
(assert
 (not (and d_5_8 d_5_9)))
(assert
 (not (and d_5_8 d_5_10)))
(assert
 (not (and d_5_8 d_5_11)))
(assert
 (not (and d_5_8 d_5_12)))
(assert
 (not (and d_5_8 d_5_13)))
(assert
 (not (and d_5_8 d_5_14)))
(assert
 (not (and d_5_8 d_5_15)))
(assert
 (not (and d_5_9 d_5_10)))
(assert
 (not (and d_5_9 d_5_11)))
(assert
 (not (and d_5_9 d_5_12)))
(assert
 (not (and d_5_9 d_5_13)))
(assert
 (not (and d_5_9 d_5_14)))
(assert
 (not (and d_5_9 d_5_15)))
(assert
 (not (and d_5_10 d_5_11)))
(assert
 (not (and d_5_10 d_5_12)))
(assert
 (not (and d_5_10 d_5_13)))
(assert
 (not (and d_5_10 d_5_14)))
(assert
 (not (and d_5_10 d_5_15)))
(assert
 (not (and d_5_11 d_5_12)))
(assert
 (not (and d_5_11 d_5_13)))
(assert
 (not (and d_5_11 d_5_14)))
(assert
 (not (and d_5_11 d_5_15)))
(assert
 (not (and d_5_12 d_5_13)))
(assert
 (not (and d_5_12 d_5_14)))
(assert
 (not (and d_5_12 d_5_15)))
(assert
 (not (and d_5_13 d_5_14)))
(assert
 (not (and d_5_13 d_5_15)))
(assert
 (not (and d_5_14 d_5_15)))
(assert
 (let (($x3450 (>= rank_0 0)))
 (and $x3450 (< rank_0 6))))
(assert
 (let (($x3445 (>= rank_2 0)))
 (and $x3445 (< rank_2 6))))
(assert
 (let (($x3447 (>= rank_4 0)))
 (and $x3447 (< rank_4 6))))
(assert
 (let (($x3463 (>= rank_6 0)))
 (and $x3463 (< rank_6 6))))
(assert
 (let (($x3468 (>= rank_8 0)))
 (and $x3468 (< rank_8 6))))
(assert
 (let (($x3473 (>= rank_10 0)))
 (and $x3473 (< rank_10 6))))
(assert
 (let (($x4035 (>= rank_12 0)))
 (and $x4035 (< rank_12 6))))
(assert
 (let (($x4027 (>= rank_14 0)))
 (and $x4027 (< rank_14 6))))
(assert
 (let (($x4031 (>= rank_16 0)))
 (and $x4031 (< rank_16 6))))
(assert
 (let (($x4039 (>= rank_18 0)))
 (and $x4039 (< rank_18 6))))
(assert
 (let (($x4044 (>= rank_20 0)))
 (and $x4044 (< rank_20 6))))
(assert
 (let (($x4049 (>= rank_22 0)))
 (and $x4049 (< rank_22 6))))
(assert
 (let (($x4356 (>= rank_24 0)))
 (and $x4356 (< rank_24 6))))
(assert
 (let (($x4360 (>= rank_26 0)))
 (and $x4360 (< rank_26 6))))
(assert
 (let (($x4358 (>= rank_28 0)))
 (and $x4358 (< rank_28 6))))
(assert
 (let (($x4370 (>= rank_30 0)))
 (and $x4370 (< rank_30 6))))
(assert
 (let (($x4375 (>= rank_32 0)))
 (and $x4375 (< rank_32 6))))
(assert
 (let (($x4380 (>= rank_34 0)))
 (and $x4380 (< rank_34 6))))
(assert
 (let (($x4562 (>= rank_36 0)))
 (and $x4562 (< rank_36 6))))
(assert
 (let (($x4565 (>= rank_38 0)))
 (and $x4565 (< rank_38 6))))
(assert
 (let (($x4564 (>= rank_40 0)))
 (and $x4564 (< rank_40 6))))
(assert
 (let (($x4575 (>= rank_42 0)))
 (and $x4575 (< rank_42 6))))
(assert
 (let (($x4580 (>= rank_44 0)))
 (and $x4580 (< rank_44 6))))
(assert
 (let (($x4585 (>= rank_46 0)))
 (and $x4585 (< rank_46 6))))
(assert
 (let (($x4701 (>= rank_48 0)))
 (and $x4701 (< rank_48 6))))
(assert
 (let (($x4702 (>= rank_50 0)))
 (and $x4702 (< rank_50 6))))
(assert
 (let (($x4697 (>= rank_52 0)))
 (and $x4697 (< rank_52 6))))
(assert
 (let (($x4713 (>= rank_54 0)))
 (and $x4713 (< rank_54 6))))
(assert
 (let (($x4718 (>= rank_56 0)))
 (and $x4718 (< rank_56 6))))
(assert
 (let (($x4723 (>= rank_58 0)))
 (and $x4723 (< rank_58 6))))
(assert
 (let (($x4905 (>= rank_60 0)))
 (and $x4905 (< rank_60 6))))
(assert
 (let (($x4908 (>= rank_62 0)))
 (and $x4908 (< rank_62 6))))
(assert
 (let (($x4907 (>= rank_64 0)))
 (and $x4907 (< rank_64 6))))
(assert
 (let (($x4918 (>= rank_66 0)))
 (and $x4918 (< rank_66 6))))
(assert
 (let (($x4923 (>= rank_68 0)))
 (and $x4923 (< rank_68 6))))
(assert
 (let (($x4928 (>= rank_70 0)))
 (and $x4928 (< rank_70 6))))
(assert
 (let (($x5044 (>= rank_72 0)))
 (and $x5044 (< rank_72 6))))
(assert
 (let (($x5045 (>= rank_74 0)))
 (and $x5045 (< rank_74 6))))
(assert
 (let (($x5040 (>= rank_76 0)))
 (and $x5040 (< rank_76 6))))
(assert
 (let (($x5056 (>= rank_78 0)))
 (and $x5056 (< rank_78 6))))
(assert
 (let (($x5061 (>= rank_80 0)))
 (and $x5061 (< rank_80 6))))
(assert
 (let (($x5066 (>= rank_82 0)))
 (and $x5066 (< rank_82 6))))
(assert
 (let (($x5216 (>= rank_84 0)))
 (and $x5216 (< rank_84 6))))
(assert
 (let (($x5219 (>= rank_86 0)))
 (and $x5219 (< rank_86 6))))
(assert
 (let (($x5218 (>= rank_88 0)))
 (and $x5218 (< rank_88 6))))
(assert
 (let (($x5229 (>= rank_90 0)))
 (and $x5229 (< rank_90 6))))
(assert
 (let (($x5234 (>= rank_92 0)))
 (and $x5234 (< rank_92 6))))
(assert
 (let (($x5239 (>= rank_94 0)))
 (and $x5239 (< rank_94 6))))
(assert
 (let (($x5355 (>= rank_96 0)))
 (and $x5355 (< rank_96 6))))
(assert
 (let (($x5356 (>= rank_98 0)))
 (and $x5356 (< rank_98 6))))
(assert
 (let (($x5351 (>= rank_100 0)))
 (and $x5351 (< rank_100 6))))
(assert
 (let (($x5367 (>= rank_102 0)))
 (and $x5367 (< rank_102 6))))
(assert
 (let (($x5372 (>= rank_104 0)))
 (and $x5372 (< rank_104 6))))
(assert
 (let (($x5377 (>= rank_106 0)))
 (and $x5377 (< rank_106 6))))
(assert
 (let (($x5556 (>= rank_108 0)))
 (and $x5556 (< rank_108 6))))
(assert
 (let (($x5559 (>= rank_110 0)))
 (and $x5559 (< rank_110 6))))
(assert
 (let (($x5558 (>= rank_112 0)))
 (and $x5558 (< rank_112 6))))
(assert
 (let (($x5569 (>= rank_114 0)))
 (and $x5569 (< rank_114 6))))
(assert
 (let (($x5574 (>= rank_116 0)))
 (and $x5574 (< rank_116 6))))
(assert
 (let (($x5579 (>= rank_118 0)))
 (and $x5579 (< rank_118 6))))
(assert
 (let ((?x4346 (ite d_1_15 1 0)))
 (let ((?x4342 (ite d_1_14 1 0)))
 (let ((?x4338 (ite d_1_13 1 0)))
 (let ((?x4334 (ite d_1_12 1 0)))
 (let ((?x4330 (ite d_1_11 1 0)))
 (let ((?x4326 (ite d_1_10 3 0)))
 (let ((?x4322 (ite d_1_9 3 0)))
 (let ((?x4318 (ite d_1_8 3 0)))
 (let ((?x4314 (ite d_1_7 3 0)))
 (let ((?x4310 (ite d_1_6 3 0)))
 (let ((?x4306 (ite d_1_5 2 0)))
 (let ((?x4302 (ite d_1_4 2 0)))
 (let ((?x4298 (ite d_1_3 2 0)))
 (let ((?x4294 (ite d_1_2 2 0)))
 (let ((?x4290 (ite d_1_1 2 0)))
 (let ((?x4282 (ite d_0_15 1 0)))
 (let ((?x4278 (ite d_0_14 1 0)))
 (let ((?x4274 (ite d_0_13 1 0)))
 (let ((?x4270 (ite d_0_12 1 0)))
 (let ((?x4266 (ite d_0_11 1 0)))
 (let ((?x4262 (ite d_0_10 3 0)))
 (let ((?x4258 (ite d_0_9 3 0)))
 (let ((?x4254 (ite d_0_8 3 0)))
 (let ((?x4250 (ite d_0_7 3 0)))
 (let ((?x4246 (ite d_0_6 3 0)))
 (let ((?x4241 (ite d_0_5 2 0)))
 (let ((?x4237 (ite d_0_4 2 0)))
 (let ((?x4233 (ite d_0_3 2 0)))
 (let ((?x4229 (ite d_0_2 2 0)))
 (let ((?x4225 (ite d_0_1 2 0)))
 (let ((?x4221 (+ 0 (ite d_0_0 0 0))))
 (let ((?x4226 (+ ?x4221 ?x4225)))
 (let ((?x4230 (+ ?x4226 ?x4229)))
 (let ((?x4234 (+ ?x4230 ?x4233)))
 (let ((?x4238 (+ ?x4234 ?x4237)))
 (let ((?x4242 (+ ?x4238 ?x4241)))
 (let ((?x4247 (+ ?x4242 ?x4246)))
 (let ((?x4251 (+ ?x4247 ?x4250)))
 (let ((?x4255 (+ ?x4251 ?x4254)))
 (let ((?x4259 (+ ?x4255 ?x4258)))
 (let ((?x4263 (+ ?x4259 ?x4262)))
 (let ((?x4267 (+ ?x4263 ?x4266)))
 (let ((?x4271 (+ ?x4267 ?x4270)))
 (let ((?x4275 (+ ?x4271 ?x4274)))
 (let ((?x4279 (+ ?x4275 ?x4278)))
 (let ((?x4283 (+ ?x4279 ?x4282)))
 (let ((?x4287 (+ ?x4283 (ite d_1_0 0 0))))
 (let ((?x4291 (+ ?x4287 ?x4290)))
 (let ((?x4295 (+ ?x4291 ?x4294)))
 (let ((?x4299 (+ ?x4295 ?x4298)))
 (let ((?x4303 (+ ?x4299 ?x4302)))
 (let ((?x4307 (+ ?x4303 ?x4306)))
 (let ((?x4311 (+ ?x4307 ?x4310)))
 (let ((?x4315 (+ ?x4311 ?x4314)))
 (let ((?x4319 (+ ?x4315 ?x4318)))
 (let ((?x4323 (+ ?x4319 ?x4322)))
 (let ((?x4327 (+ ?x4323 ?x4326)))
 (let ((?x4331 (+ ?x4327 ?x4330)))
 (let ((?x4335 (+ ?x4331 ?x4334)))
 (let ((?x4339 (+ ?x4335 ?x4338)))
 (let ((?x4343 (+ ?x4339 ?x4342)))
 (let ((?x4344 (ite c_1_15 1 0)))
 (let ((?x4340 (ite c_1_14 1 0)))
 (let ((?x4336 (ite c_1_13 1 0)))
 (let ((?x4332 (ite c_1_12 1 0)))
 (let ((?x4328 (ite c_1_11 1 0)))
 (let ((?x4324 (ite c_1_10 3 0)))
 (let ((?x4320 (ite c_1_9 3 0)))
 (let ((?x4316 (ite c_1_8 3 0)))
 (let ((?x4312 (ite c_1_7 3 0)))
 (let ((?x4308 (ite c_1_6 3 0)))
 (let ((?x4304 (ite c_1_5 2 0)))
 (let ((?x4300 (ite c_1_4 2 0)))
 (let ((?x4296 (ite c_1_3 2 0)))
 (let ((?x4292 (ite c_1_2 2 0)))
 (let ((?x4288 (ite c_1_1 2 0)))
 (let ((?x4280 (ite c_0_15 1 0)))
 (let ((?x4276 (ite c_0_14 1 0)))
 (let ((?x4272 (ite c_0_13 1 0)))
 (let ((?x4268 (ite c_0_12 1 0)))
 (let ((?x4264 (ite c_0_11 1 0)))
 (let ((?x4260 (ite c_0_10 3 0)))
 (let ((?x4256 (ite c_0_9 3 0)))
 (let ((?x4252 (ite c_0_8 3 0)))
 (let ((?x4248 (ite c_0_7 3 0)))
 (let ((?x4244 (ite c_0_6 3 0)))
 (let ((?x4239 (ite c_0_5 2 0)))
 (let ((?x4235 (ite c_0_4 2 0)))
 (let ((?x4231 (ite c_0_3 2 0)))
 (let ((?x4227 (ite c_0_2 2 0)))
 (let ((?x4223 (ite c_0_1 2 0)))
 (let ((?x4219 (+ 0 (ite c_0_0 0 0))))
 (let ((?x4224 (+ ?x4219 ?x4223)))
 (let ((?x4228 (+ ?x4224 ?x4227)))
 (let ((?x4232 (+ ?x4228 ?x4231)))
 (let ((?x4236 (+ ?x4232 ?x4235)))
 (let ((?x4240 (+ ?x4236 ?x4239)))
 (let ((?x4245 (+ ?x4240 ?x4244)))
 (let ((?x4249 (+ ?x4245 ?x4248)))
 (let ((?x4253 (+ ?x4249 ?x4252)))
 (let ((?x4257 (+ ?x4253 ?x4256)))
 (let ((?x4261 (+ ?x4257 ?x4260)))
 (let ((?x4265 (+ ?x4261 ?x4264)))
 (let ((?x4269 (+ ?x4265 ?x4268)))
 (let ((?x4273 (+ ?x4269 ?x4272)))
 (let ((?x4277 (+ ?x4273 ?x4276)))
 (let ((?x4281 (+ ?x4277 ?x4280)))
 (let ((?x4285 (+ ?x4281 (ite c_1_0 0 0))))
 (let ((?x4289 (+ ?x4285 ?x4288)))
 (let ((?x4293 (+ ?x4289 ?x4292)))
 (let ((?x4297 (+ ?x4293 ?x4296)))
 (let ((?x4301 (+ ?x4297 ?x4300)))
 (let ((?x4305 (+ ?x4301 ?x4304)))
 (let ((?x4309 (+ ?x4305 ?x4308)))
 (let ((?x4313 (+ ?x4309 ?x4312)))
 (let ((?x4317 (+ ?x4313 ?x4316)))
 (let ((?x4321 (+ ?x4317 ?x4320)))
 (let ((?x4325 (+ ?x4321 ?x4324)))
 (let ((?x4329 (+ ?x4325 ?x4328)))
 (let ((?x4333 (+ ?x4329 ?x4332)))
 (let ((?x4337 (+ ?x4333 ?x4336)))
 (let ((?x4341 (+ ?x4337 ?x4340)))
 (let (($x4350 (and (distinct (+ ?x4341 ?x4344) (+ ?x4343 ?x4346)) true)))
 (let (($x4036 (or d_5_1 d_5_2 d_5_3 d_5_4 d_5_5 d_5_6 d_5_7 d_5_8 d_5_9 d_5_10 d_5_11 d_5_12 d_5_13 d_5_14 d_5_15)))
 (let ((?x4177 (ite $x4036 1 0)))
 (let (($x4007 (or d_4_1 d_4_2 d_4_3 d_4_4 d_4_5 d_4_6 d_4_7 d_4_8 d_4_9 d_4_10 d_4_11 d_4_12 d_4_13 d_4_14 d_4_15)))
 (let ((?x4175 (ite $x4007 1 0)))
 (let (($x3978 (or d_3_1 d_3_2 d_3_3 d_3_4 d_3_5 d_3_6 d_3_7 d_3_8 d_3_9 d_3_10 d_3_11 d_3_12 d_3_13 d_3_14 d_3_15)))
 (let ((?x4167 (ite $x3978 1 0)))
 (let (($x3949 (or d_2_1 d_2_2 d_2_3 d_2_4 d_2_5 d_2_6 d_2_7 d_2_8 d_2_9 d_2_10 d_2_11 d_2_12 d_2_13 d_2_14 d_2_15)))
 (let ((?x4174 (ite $x3949 1 0)))
 (let (($x3920 (or d_1_1 d_1_2 d_1_3 d_1_4 d_1_5 d_1_6 d_1_7 d_1_8 d_1_9 d_1_10 d_1_11 d_1_12 d_1_13 d_1_14 d_1_15)))
 (let ((?x4161 (ite $x3920 1 0)))
 (let (($x3891 (or d_0_1 d_0_2 d_0_3 d_0_4 d_0_5 d_0_6 d_0_7 d_0_8 d_0_9 d_0_10 d_0_11 d_0_12 d_0_13 d_0_14 d_0_15)))
 (let ((?x4159 (ite $x3891 1 0)))
 (let ((?x4160 (+ 0 ?x4159)))
 (let ((?x4169 (+ ?x4160 ?x4161)))
 (let ((?x4163 (+ ?x4169 ?x4174)))
 (let ((?x4173 (+ ?x4163 ?x4167)))
 (let ((?x4176 (+ ?x4173 ?x4175)))
 (let (($x4162 (>= (+ ?x4176 ?x4177) 1)))
 (let ((?x5664 (ite root_119 1 0)))
 (let ((?x5646 (ite root_117 1 0)))
 (let ((?x5631 (ite root_115 1 0)))
 (let ((?x5616 (ite root_113 1 0)))
 (let ((?x5598 (ite root_111 1 0)))
 (let ((?x5583 (ite root_109 1 0)))
 (let ((?x5584 (+ 0 ?x5583)))
 (let ((?x5599 (+ ?x5584 ?x5598)))
 (let ((?x5617 (+ ?x5599 ?x5616)))
 (let ((?x5632 (+ ?x5617 ?x5631)))
 (let ((?x5647 (+ ?x5632 ?x5646)))
 (let (($x5582 (or false root_109)))
 (let (($x5597 (or $x5582 root_111)))
 (let (($x5615 (or $x5597 root_113)))
 (let (($x5630 (or $x5615 root_115)))
 (let (($x5645 (or $x5630 root_117)))
 (let (($x4052 (or false $x3891)))
 (let (($x4068 (or $x4052 $x3920)))
 (let (($x4087 (or $x4068 $x3949)))
 (let (($x4103 (or $x4087 $x3978)))
 (let (($x4119 (or $x4103 $x4007)))
 (let (($x4138 (or $x4119 $x4036)))
 (let (($x5670 (or false (and $x4007 (< rank_116 rank_118)))))
 (let (($x5674 (not root_119)))
 (let (($x5675 (and $x4036 $x5674)))
 (let (($x5652 (or false (and $x4036 (< rank_118 rank_116)))))
 (let (($x5655 (or $x5652 (and $x3978 (< rank_114 rank_116)))))
 (let (($x5659 (not root_117)))
 (let (($x5660 (and $x4007 $x5659)))
 (let (($x5637 (or false (and $x4007 (< rank_116 rank_114)))))
 (let (($x5641 (not root_115)))
 (let (($x5642 (and $x3978 $x5641)))
 (let (($x5622 (or false (and $x4036 (< rank_118 rank_112)))))
 (let (($x5626 (not root_113)))
 (let (($x5627 (and $x3949 $x5626)))
 (let (($x5604 (or false (and $x3949 (< rank_112 rank_110)))))
 (let (($x5607 (or $x5604 (and $x4007 (< rank_116 rank_110)))))
 (let (($x5611 (not root_111)))
 (let (($x5612 (and $x3920 $x5611)))
 (let (($x5589 (or false (and $x3920 (< rank_110 rank_108)))))
 (let (($x5593 (not root_109)))
 (let (($x5594 (and $x3891 $x5593)))
 (let (($x5586 (and true (=> root_109 $x3891))))
 (let (($x5596 (and $x5586 (=> $x5594 (or $x5589 (and $x3978 (< rank_114 rank_108)))))))
 (let (($x5601 (and $x5596 (=> root_111 $x3920))))
 (let (($x5614 (and $x5601 (=> $x5612 (or $x5607 (and $x3891 (< rank_108 rank_110)))))))
 (let (($x5619 (and $x5614 (=> root_113 $x3949))))
 (let (($x5629 (and $x5619 (=> $x5627 (or $x5622 (and $x3920 (< rank_110 rank_112)))))))
 (let (($x5634 (and $x5629 (=> root_115 $x3978))))
 (let (($x5644 (and $x5634 (=> $x5642 (or $x5637 (and $x3891 (< rank_108 rank_114)))))))
 (let (($x5649 (and $x5644 (=> root_117 $x4007))))
 (let (($x5662 (and $x5649 (=> $x5660 (or $x5655 (and $x3920 (< rank_110 rank_116)))))))
 (let (($x5667 (and $x5662 (=> root_119 $x4036))))
 (let (($x5679 (and (and $x5667 (=> $x5675 (or $x5670 (and $x3949 (< rank_112 rank_118))))) (=> $x4138 (or $x5645 root_119)))))
 (let (($x5681 (and $x5679 (<= (+ ?x5647 ?x5664) 1))))
 (let (($x5682 (and true $x5681)))
 (let (($x3844 (= c_5_15 d_5_15)))
 (let (($x3842 (= c_5_14 d_5_14)))
 (let (($x3840 (= c_5_13 d_5_13)))
 (let (($x3838 (= c_5_12 d_5_12)))
 (let (($x3836 (= c_5_11 d_5_11)))
 (let (($x3834 (= c_5_10 d_5_10)))
 (let (($x3832 (= c_5_9 d_5_9)))
 (let (($x3830 (= c_5_8 d_5_8)))
 (let (($x3828 (= c_5_7 d_5_7)))
 (let (($x3826 (= c_5_6 d_5_6)))
 (let (($x3824 (= c_5_5 d_5_5)))
 (let (($x3822 (= c_5_4 d_5_4)))
 (let (($x3820 (= c_5_3 d_5_3)))
 (let (($x3818 (= c_5_2 d_5_2)))
 (let (($x3816 (= c_5_1 d_5_1)))
 (let (($x3814 (= c_5_0 d_5_0)))
 (let (($x3815 (and true $x3814)))
 (let (($x3817 (and $x3815 $x3816)))
 (let (($x3819 (and $x3817 $x3818)))
 (let (($x3821 (and $x3819 $x3820)))
 (let (($x3823 (and $x3821 $x3822)))
 (let (($x3825 (and $x3823 $x3824)))
 (let (($x3827 (and $x3825 $x3826)))
 (let (($x3829 (and $x3827 $x3828)))
 (let (($x3831 (and $x3829 $x3830)))
 (let (($x3833 (and $x3831 $x3832)))
 (let (($x3835 (and $x3833 $x3834)))
 (let (($x3837 (and $x3835 $x3836)))
 (let (($x3839 (and $x3837 $x3838)))
 (let (($x3841 (and $x3839 $x3840)))
 (let (($x3843 (and $x3841 $x3842)))
 (let (($x3845 (and $x3843 $x3844)))
 (let (($x3811 (= c_4_15 d_4_15)))
 (let (($x3809 (= c_4_14 d_4_14)))
 (let (($x3807 (= c_4_13 d_4_13)))
 (let (($x3805 (= c_4_12 d_4_12)))
 (let (($x3803 (= c_4_11 d_4_11)))
 (let (($x3801 (= c_4_10 d_4_10)))
 (let (($x3799 (= c_4_9 d_4_9)))
 (let (($x3797 (= c_4_8 d_4_8)))
 (let (($x3795 (= c_4_7 d_4_7)))
 (let (($x3793 (= c_4_6 d_4_6)))
 (let (($x3791 (= c_4_5 d_4_5)))
 (let (($x3789 (= c_4_4 d_4_4)))
 (let (($x3787 (= c_4_3 d_4_3)))
 (let (($x3785 (= c_4_2 d_4_2)))
 (let (($x3783 (= c_4_1 d_4_1)))
 (let (($x3781 (= c_4_0 d_4_0)))
 (let (($x3782 (and true $x3781)))
 (let (($x3784 (and $x3782 $x3783)))
 (let (($x3786 (and $x3784 $x3785)))
 (let (($x3788 (and $x3786 $x3787)))
 (let (($x3790 (and $x3788 $x3789)))
 (let (($x3792 (and $x3790 $x3791)))
 (let (($x3794 (and $x3792 $x3793)))
 (let (($x3796 (and $x3794 $x3795)))
 (let (($x3798 (and $x3796 $x3797)))
 (let (($x3800 (and $x3798 $x3799)))
 (let (($x3802 (and $x3800 $x3801)))
 (let (($x3804 (and $x3802 $x3803)))
 (let (($x3806 (and $x3804 $x3805)))
 (let (($x3808 (and $x3806 $x3807)))
 (let (($x3810 (and $x3808 $x3809)))
 (let (($x3812 (and $x3810 $x3811)))
 (let (($x3778 (= c_3_15 d_3_15)))
 (let (($x3776 (= c_3_14 d_3_14)))
 (let (($x3774 (= c_3_13 d_3_13)))
 (let (($x3772 (= c_3_12 d_3_12)))
 (let (($x3770 (= c_3_11 d_3_11)))
 (let (($x3768 (= c_3_10 d_3_10)))
 (let (($x3766 (= c_3_9 d_3_9)))
 (let (($x3764 (= c_3_8 d_3_8)))
 (let (($x3762 (= c_3_7 d_3_7)))
 (let (($x3760 (= c_3_6 d_3_6)))
 (let (($x3758 (= c_3_5 d_3_5)))
 (let (($x3756 (= c_3_4 d_3_4)))
 (let (($x3754 (= c_3_3 d_3_3)))
 (let (($x3752 (= c_3_2 d_3_2)))
 (let (($x3750 (= c_3_1 d_3_1)))
 (let (($x3748 (= c_3_0 d_3_0)))
 (let (($x3749 (and true $x3748)))
 (let (($x3751 (and $x3749 $x3750)))
 (let (($x3753 (and $x3751 $x3752)))
 (let (($x3755 (and $x3753 $x3754)))
 (let (($x3757 (and $x3755 $x3756)))
 (let (($x3759 (and $x3757 $x3758)))
 (let (($x3761 (and $x3759 $x3760)))
 (let (($x3763 (and $x3761 $x3762)))
 (let (($x3765 (and $x3763 $x3764)))
 (let (($x3767 (and $x3765 $x3766)))
 (let (($x3769 (and $x3767 $x3768)))
 (let (($x3771 (and $x3769 $x3770)))
 (let (($x3773 (and $x3771 $x3772)))
 (let (($x3775 (and $x3773 $x3774)))
 (let (($x3777 (and $x3775 $x3776)))
 (let (($x3779 (and $x3777 $x3778)))
 (let (($x3745 (= c_2_15 d_2_15)))
 (let (($x3743 (= c_2_14 d_2_14)))
 (let (($x3741 (= c_2_13 d_2_13)))
 (let (($x3739 (= c_2_12 d_2_12)))
 (let (($x3737 (= c_2_11 d_2_11)))
 (let (($x3735 (= c_2_10 d_2_10)))
 (let (($x3733 (= c_2_9 d_2_9)))
 (let (($x3731 (= c_2_8 d_2_8)))
 (let (($x3729 (= c_2_7 d_2_7)))
 (let (($x3727 (= c_2_6 d_2_6)))
 (let (($x3725 (= c_2_5 d_2_5)))
 (let (($x3723 (= c_2_4 d_2_4)))
 (let (($x3721 (= c_2_3 d_2_3)))
 (let (($x3719 (= c_2_2 d_2_2)))
 (let (($x3717 (= c_2_1 d_2_1)))
 (let (($x3715 (= c_2_0 d_2_0)))
 (let (($x3716 (and true $x3715)))
 (let (($x3718 (and $x3716 $x3717)))
 (let (($x3720 (and $x3718 $x3719)))
 (let (($x3722 (and $x3720 $x3721)))
 (let (($x3724 (and $x3722 $x3723)))
 (let (($x3726 (and $x3724 $x3725)))
 (let (($x3728 (and $x3726 $x3727)))
 (let (($x3730 (and $x3728 $x3729)))
 (let (($x3732 (and $x3730 $x3731)))
 (let (($x3734 (and $x3732 $x3733)))
 (let (($x3736 (and $x3734 $x3735)))
 (let (($x3738 (and $x3736 $x3737)))
 (let (($x3740 (and $x3738 $x3739)))
 (let (($x3742 (and $x3740 $x3741)))
 (let (($x3744 (and $x3742 $x3743)))
 (let (($x3746 (and $x3744 $x3745)))
 (let (($x5515 (and true (=> c_1_0 d_1_6))))
 (let (($x5517 (and $x5515 (=> c_1_1 d_1_6))))
 (let (($x5519 (and $x5517 (=> c_1_2 d_1_7))))
 (let (($x5521 (and $x5519 (=> c_1_3 d_1_8))))
 (let (($x5523 (and $x5521 (=> c_1_4 d_1_9))))
 (let (($x5525 (and $x5523 (=> c_1_5 d_1_10))))
 (let (($x5527 (and $x5525 (=> c_1_6 d_1_6))))
 (let (($x5529 (and $x5527 (=> c_1_7 d_1_7))))
 (let (($x5531 (and $x5529 (=> c_1_8 d_1_8))))
 (let (($x5533 (and $x5531 (=> c_1_9 d_1_9))))
 (let (($x5535 (and $x5533 (=> c_1_10 d_1_10))))
 (let (($x5537 (and $x5535 (=> c_1_11 d_1_6))))
 (let (($x5539 (and $x5537 (=> c_1_12 d_1_7))))
 (let (($x5541 (and $x5539 (=> c_1_13 d_1_8))))
 (let (($x5543 (and $x5541 (=> c_1_14 d_1_9))))
 (let (($x3673 (=> c_0_12 d_0_2)))
 (let (($x4852 (=> c_0_11 d_0_1)))
 (let (($x3663 (=> c_0_7 d_0_2)))
 (let (($x4842 (=> c_0_6 d_0_1)))
 (let (($x3653 (=> c_0_2 d_0_2)))
 (let (($x4838 (and true (=> c_0_0 d_0_1))))
 (let (($x4830 (and $x4838 (=> c_0_1 d_0_1))))
 (let (($x5484 (and $x4830 $x3653)))
 (let (($x5491 (and $x5484 (=> c_0_3 d_0_3))))
 (let (($x5494 (and $x5491 (=> c_0_4 d_0_4))))
 (let (($x5496 (and $x5494 (=> c_0_5 d_0_5))))
 (let (($x5497 (and $x5496 $x4842)))
 (let (($x5498 (and $x5497 $x3663)))
 (let (($x5500 (and $x5498 (=> c_0_8 d_0_3))))
 (let (($x5502 (and $x5500 (=> c_0_9 d_0_4))))
 (let (($x5504 (and $x5502 (=> c_0_10 d_0_5))))
 (let (($x5505 (and $x5504 $x4852)))
 (let (($x5506 (and $x5505 $x3673)))
 (let (($x5508 (and $x5506 (=> c_0_13 d_0_3))))
 (let (($x5510 (and $x5508 (=> c_0_14 d_0_4))))
 (let (($x5485 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x5489 (or c_0_6 c_0_7 c_0_8 c_0_9 c_0_10)))
 (let (($x5490 (and true $x5489)))
 (let (($x5495 (and $x5490 $x5485)))
 (let (($x5513 (and $x5495 (and $x5510 (=> c_0_15 d_0_5)))))
 (let (($x5546 (and $x5513 (and $x5543 (=> c_1_15 d_1_10)))))
 (let (($x5547 (and $x5546 $x3746)))
 (let (($x5548 (and $x5547 $x3779)))
 (let (($x5549 (and $x5548 $x3812)))
 (let (($x3458 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_13 c_5_14 c_5_15)))
 (let ((?x3599 (ite $x3458 1 0)))
 (let (($x3429 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_13 c_4_14 c_4_15)))
 (let ((?x3590 (ite $x3429 1 0)))
 (let (($x3400 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_13 c_3_14 c_3_15)))
 (let ((?x3589 (ite $x3400 1 0)))
 (let (($x3371 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_13 c_2_14 c_2_15)))
 (let ((?x3597 (ite $x3371 1 0)))
 (let (($x3342 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_13 c_1_14 c_1_15)))
 (let ((?x3587 (ite $x3342 1 0)))
 (let (($x3313 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_13 c_0_14 c_0_15)))
 (let ((?x3584 (ite $x3313 1 0)))
 (let ((?x3585 (+ 0 ?x3584)))
 (let ((?x3594 (+ ?x3585 ?x3587)))
 (let ((?x3588 (+ ?x3594 ?x3597)))
 (let ((?x3595 (+ ?x3588 ?x3589)))
 (let ((?x3586 (+ ?x3595 ?x3590)))
 (let (($x3602 (>= (+ ?x3586 ?x3599) 1)))
 (let ((?x5462 (ite root_107 1 0)))
 (let ((?x5444 (ite root_105 1 0)))
 (let ((?x5429 (ite root_103 1 0)))
 (let ((?x5414 (ite root_101 1 0)))
 (let ((?x5396 (ite root_99 1 0)))
 (let ((?x5381 (ite root_97 1 0)))
 (let ((?x5382 (+ 0 ?x5381)))
 (let ((?x5397 (+ ?x5382 ?x5396)))
 (let ((?x5415 (+ ?x5397 ?x5414)))
 (let ((?x5430 (+ ?x5415 ?x5429)))
 (let ((?x5445 (+ ?x5430 ?x5444)))
 (let (($x5380 (or false root_97)))
 (let (($x5395 (or $x5380 root_99)))
 (let (($x5413 (or $x5395 root_101)))
 (let (($x5428 (or $x5413 root_103)))
 (let (($x5443 (or $x5428 root_105)))
 (let (($x3476 (or false $x3313)))
 (let (($x3493 (or $x3476 $x3342)))
 (let (($x3512 (or $x3493 $x3371)))
 (let (($x3528 (or $x3512 $x3400)))
 (let (($x3544 (or $x3528 $x3429)))
 (let (($x3563 (or $x3544 $x3458)))
 (let (($x5468 (or false (and $x3429 (< rank_104 rank_106)))))
 (let (($x5472 (not root_107)))
 (let (($x5473 (and $x3458 $x5472)))
 (let (($x5450 (or false (and $x3458 (< rank_106 rank_104)))))
 (let (($x5453 (or $x5450 (and $x3400 (< rank_102 rank_104)))))
 (let (($x5457 (not root_105)))
 (let (($x5458 (and $x3429 $x5457)))
 (let (($x5435 (or false (and $x3429 (< rank_104 rank_102)))))
 (let (($x5439 (not root_103)))
 (let (($x5440 (and $x3400 $x5439)))
 (let (($x5420 (or false (and $x3458 (< rank_106 rank_100)))))
 (let (($x5424 (not root_101)))
 (let (($x5425 (and $x3371 $x5424)))
 (let (($x5402 (or false (and $x3371 (< rank_100 rank_98)))))
 (let (($x5405 (or $x5402 (and $x3429 (< rank_104 rank_98)))))
 (let (($x5409 (not root_99)))
 (let (($x5410 (and $x3342 $x5409)))
 (let (($x5387 (or false (and $x3342 (< rank_98 rank_96)))))
 (let (($x5391 (not root_97)))
 (let (($x5392 (and $x3313 $x5391)))
 (let (($x5384 (and true (=> root_97 $x3313))))
 (let (($x5394 (and $x5384 (=> $x5392 (or $x5387 (and $x3400 (< rank_102 rank_96)))))))
 (let (($x5399 (and $x5394 (=> root_99 $x3342))))
 (let (($x5412 (and $x5399 (=> $x5410 (or $x5405 (and $x3313 (< rank_96 rank_98)))))))
 (let (($x5417 (and $x5412 (=> root_101 $x3371))))
 (let (($x5427 (and $x5417 (=> $x5425 (or $x5420 (and $x3342 (< rank_98 rank_100)))))))
 (let (($x5432 (and $x5427 (=> root_103 $x3400))))
 (let (($x5442 (and $x5432 (=> $x5440 (or $x5435 (and $x3313 (< rank_96 rank_102)))))))
 (let (($x5447 (and $x5442 (=> root_105 $x3429))))
 (let (($x5460 (and $x5447 (=> $x5458 (or $x5453 (and $x3342 (< rank_98 rank_104)))))))
 (let (($x5465 (and $x5460 (=> root_107 $x3458))))
 (let (($x5477 (and (and $x5465 (=> $x5473 (or $x5468 (and $x3371 (< rank_100 rank_106))))) (=> $x3563 (or $x5443 root_107)))))
 (let (($x5479 (and $x5477 (<= (+ ?x5445 ?x5462) 1))))
 (let (($x5480 (and true $x5479)))
 (let (($x5697 (= rule_instance 56)))
 (let (($x5689 (and $x5697 (and (and (and $x5480 $x3602) (and $x5549 $x3845)) (and $x5682 $x4162)))))
 (let ((?x5324 (ite root_95 1 0)))
 (let ((?x5306 (ite root_93 1 0)))
 (let ((?x5291 (ite root_91 1 0)))
 (let ((?x5276 (ite root_89 1 0)))
 (let ((?x5258 (ite root_87 1 0)))
 (let ((?x5243 (ite root_85 1 0)))
 (let ((?x5244 (+ 0 ?x5243)))
 (let ((?x5259 (+ ?x5244 ?x5258)))
 (let ((?x5277 (+ ?x5259 ?x5276)))
 (let ((?x5292 (+ ?x5277 ?x5291)))
 (let ((?x5307 (+ ?x5292 ?x5306)))
 (let (($x5242 (or false root_85)))
 (let (($x5257 (or $x5242 root_87)))
 (let (($x5275 (or $x5257 root_89)))
 (let (($x5290 (or $x5275 root_91)))
 (let (($x5305 (or $x5290 root_93)))
 (let (($x5330 (or false (and $x4007 (< rank_92 rank_94)))))
 (let (($x5334 (not root_95)))
 (let (($x5335 (and $x4036 $x5334)))
 (let (($x5312 (or false (and $x4036 (< rank_94 rank_92)))))
 (let (($x5315 (or $x5312 (and $x3978 (< rank_90 rank_92)))))
 (let (($x5319 (not root_93)))
 (let (($x5320 (and $x4007 $x5319)))
 (let (($x5297 (or false (and $x4007 (< rank_92 rank_90)))))
 (let (($x5301 (not root_91)))
 (let (($x5302 (and $x3978 $x5301)))
 (let (($x5282 (or false (and $x4036 (< rank_94 rank_88)))))
 (let (($x5286 (not root_89)))
 (let (($x5287 (and $x3949 $x5286)))
 (let (($x5264 (or false (and $x3949 (< rank_88 rank_86)))))
 (let (($x5267 (or $x5264 (and $x4007 (< rank_92 rank_86)))))
 (let (($x5271 (not root_87)))
 (let (($x5272 (and $x3920 $x5271)))
 (let (($x5249 (or false (and $x3920 (< rank_86 rank_84)))))
 (let (($x5253 (not root_85)))
 (let (($x5254 (and $x3891 $x5253)))
 (let (($x5246 (and true (=> root_85 $x3891))))
 (let (($x5256 (and $x5246 (=> $x5254 (or $x5249 (and $x3978 (< rank_90 rank_84)))))))
 (let (($x5261 (and $x5256 (=> root_87 $x3920))))
 (let (($x5274 (and $x5261 (=> $x5272 (or $x5267 (and $x3891 (< rank_84 rank_86)))))))
 (let (($x5279 (and $x5274 (=> root_89 $x3949))))
 (let (($x5289 (and $x5279 (=> $x5287 (or $x5282 (and $x3920 (< rank_86 rank_88)))))))
 (let (($x5294 (and $x5289 (=> root_91 $x3978))))
 (let (($x5304 (and $x5294 (=> $x5302 (or $x5297 (and $x3891 (< rank_84 rank_90)))))))
 (let (($x5309 (and $x5304 (=> root_93 $x4007))))
 (let (($x5322 (and $x5309 (=> $x5320 (or $x5315 (and $x3920 (< rank_86 rank_92)))))))
 (let (($x5327 (and $x5322 (=> root_95 $x4036))))
 (let (($x5339 (and (and $x5327 (=> $x5335 (or $x5330 (and $x3949 (< rank_88 rank_94))))) (=> $x4138 (or $x5305 root_95)))))
 (let (($x5341 (and $x5339 (<= (+ ?x5307 ?x5324) 1))))
 (let (($x5342 (and true $x5341)))
 (let (($x3683 (and true (=> c_1_0 d_1_14))))
 (let (($x3685 (and $x3683 (=> c_1_1 d_1_14))))
 (let (($x3687 (and $x3685 (=> c_1_2 d_1_14))))
 (let (($x3689 (and $x3687 (=> c_1_3 d_1_14))))
 (let (($x3691 (and $x3689 (=> c_1_4 d_1_14))))
 (let (($x3693 (and $x3691 (=> c_1_5 d_1_14))))
 (let (($x3695 (and $x3693 (=> c_1_6 d_1_14))))
 (let (($x3697 (and $x3695 (=> c_1_7 d_1_14))))
 (let (($x3699 (and $x3697 (=> c_1_8 d_1_14))))
 (let (($x3701 (and $x3699 (=> c_1_9 d_1_14))))
 (let (($x3703 (and $x3701 (=> c_1_10 d_1_14))))
 (let (($x3705 (and $x3703 (=> c_1_11 d_1_14))))
 (let (($x3707 (and $x3705 (=> c_1_12 d_1_14))))
 (let (($x3709 (and $x3707 (=> c_1_13 d_1_14))))
 (let (($x3711 (and $x3709 (=> c_1_14 d_1_14))))
 (let (($x3713 (and $x3711 (=> c_1_15 d_1_14))))
 (let (($x5181 (and true (=> c_0_0 d_0_7))))
 (let (($x5173 (and $x5181 (=> c_0_1 d_0_7))))
 (let (($x5184 (and $x5173 (=> c_0_2 d_0_7))))
 (let (($x5174 (and $x5184 (=> c_0_3 d_0_7))))
 (let (($x5175 (and $x5174 (=> c_0_4 d_0_7))))
 (let (($x5182 (and $x5175 (=> c_0_5 d_0_7))))
 (let (($x5186 (and $x5182 (=> c_0_6 d_0_7))))
 (let (($x5188 (and $x5186 (=> c_0_7 d_0_7))))
 (let (($x5190 (and $x5188 (=> c_0_8 d_0_7))))
 (let (($x5192 (and $x5190 (=> c_0_9 d_0_7))))
 (let (($x5194 (and $x5192 (=> c_0_10 d_0_7))))
 (let (($x5196 (and $x5194 (=> c_0_11 d_0_7))))
 (let (($x5198 (and $x5196 (=> c_0_12 d_0_7))))
 (let (($x5200 (and $x5198 (=> c_0_13 d_0_7))))
 (let (($x5202 (and $x5200 (=> c_0_14 d_0_7))))
 (let (($x5171 (and true c_0_1)))
 (let (($x5177 (and $x5171 c_1_1)))
 (let (($x5205 (and $x5177 (and $x5202 (=> c_0_15 d_0_7)))))
 (let (($x5206 (and $x5205 $x3713)))
 (let (($x5207 (and $x5206 $x3746)))
 (let (($x5208 (and $x5207 $x3779)))
 (let (($x5209 (and $x5208 $x3812)))
 (let ((?x5151 (ite root_83 1 0)))
 (let ((?x5133 (ite root_81 1 0)))
 (let ((?x5118 (ite root_79 1 0)))
 (let ((?x5103 (ite root_77 1 0)))
 (let ((?x5085 (ite root_75 1 0)))
 (let ((?x5070 (ite root_73 1 0)))
 (let ((?x5071 (+ 0 ?x5070)))
 (let ((?x5086 (+ ?x5071 ?x5085)))
 (let ((?x5104 (+ ?x5086 ?x5103)))
 (let ((?x5119 (+ ?x5104 ?x5118)))
 (let ((?x5134 (+ ?x5119 ?x5133)))
 (let (($x5069 (or false root_73)))
 (let (($x5084 (or $x5069 root_75)))
 (let (($x5102 (or $x5084 root_77)))
 (let (($x5117 (or $x5102 root_79)))
 (let (($x5132 (or $x5117 root_81)))
 (let (($x5157 (or false (and $x3429 (< rank_80 rank_82)))))
 (let (($x5161 (not root_83)))
 (let (($x5162 (and $x3458 $x5161)))
 (let (($x5139 (or false (and $x3458 (< rank_82 rank_80)))))
 (let (($x5142 (or $x5139 (and $x3400 (< rank_78 rank_80)))))
 (let (($x5146 (not root_81)))
 (let (($x5147 (and $x3429 $x5146)))
 (let (($x5124 (or false (and $x3429 (< rank_80 rank_78)))))
 (let (($x5128 (not root_79)))
 (let (($x5129 (and $x3400 $x5128)))
 (let (($x5109 (or false (and $x3458 (< rank_82 rank_76)))))
 (let (($x5113 (not root_77)))
 (let (($x5114 (and $x3371 $x5113)))
 (let (($x5091 (or false (and $x3371 (< rank_76 rank_74)))))
 (let (($x5094 (or $x5091 (and $x3429 (< rank_80 rank_74)))))
 (let (($x5098 (not root_75)))
 (let (($x5099 (and $x3342 $x5098)))
 (let (($x5076 (or false (and $x3342 (< rank_74 rank_72)))))
 (let (($x5080 (not root_73)))
 (let (($x5081 (and $x3313 $x5080)))
 (let (($x5073 (and true (=> root_73 $x3313))))
 (let (($x5083 (and $x5073 (=> $x5081 (or $x5076 (and $x3400 (< rank_78 rank_72)))))))
 (let (($x5088 (and $x5083 (=> root_75 $x3342))))
 (let (($x5101 (and $x5088 (=> $x5099 (or $x5094 (and $x3313 (< rank_72 rank_74)))))))
 (let (($x5106 (and $x5101 (=> root_77 $x3371))))
 (let (($x5116 (and $x5106 (=> $x5114 (or $x5109 (and $x3342 (< rank_74 rank_76)))))))
 (let (($x5121 (and $x5116 (=> root_79 $x3400))))
 (let (($x5131 (and $x5121 (=> $x5129 (or $x5124 (and $x3313 (< rank_72 rank_78)))))))
 (let (($x5136 (and $x5131 (=> root_81 $x3429))))
 (let (($x5149 (and $x5136 (=> $x5147 (or $x5142 (and $x3342 (< rank_74 rank_80)))))))
 (let (($x5154 (and $x5149 (=> root_83 $x3458))))
 (let (($x5166 (and (and $x5154 (=> $x5162 (or $x5157 (and $x3371 (< rank_76 rank_82))))) (=> $x3563 (or $x5132 root_83)))))
 (let (($x5168 (and $x5166 (<= (+ ?x5134 ?x5151) 1))))
 (let (($x5169 (and true $x5168)))
 (let (($x5357 (= rule_instance 42)))
 (let (($x5349 (and $x5357 (and (and (and $x5169 $x3602) (and $x5209 $x3845)) (and $x5342 $x4162)))))
 (let ((?x5013 (ite root_71 1 0)))
 (let ((?x4995 (ite root_69 1 0)))
 (let ((?x4980 (ite root_67 1 0)))
 (let ((?x4965 (ite root_65 1 0)))
 (let ((?x4947 (ite root_63 1 0)))
 (let ((?x4932 (ite root_61 1 0)))
 (let ((?x4933 (+ 0 ?x4932)))
 (let ((?x4948 (+ ?x4933 ?x4947)))
 (let ((?x4966 (+ ?x4948 ?x4965)))
 (let ((?x4981 (+ ?x4966 ?x4980)))
 (let ((?x4996 (+ ?x4981 ?x4995)))
 (let (($x4931 (or false root_61)))
 (let (($x4946 (or $x4931 root_63)))
 (let (($x4964 (or $x4946 root_65)))
 (let (($x4979 (or $x4964 root_67)))
 (let (($x4994 (or $x4979 root_69)))
 (let (($x5019 (or false (and $x4007 (< rank_68 rank_70)))))
 (let (($x5023 (not root_71)))
 (let (($x5024 (and $x4036 $x5023)))
 (let (($x5001 (or false (and $x4036 (< rank_70 rank_68)))))
 (let (($x5004 (or $x5001 (and $x3978 (< rank_66 rank_68)))))
 (let (($x5008 (not root_69)))
 (let (($x5009 (and $x4007 $x5008)))
 (let (($x4986 (or false (and $x4007 (< rank_68 rank_66)))))
 (let (($x4990 (not root_67)))
 (let (($x4991 (and $x3978 $x4990)))
 (let (($x4971 (or false (and $x4036 (< rank_70 rank_64)))))
 (let (($x4975 (not root_65)))
 (let (($x4976 (and $x3949 $x4975)))
 (let (($x4953 (or false (and $x3949 (< rank_64 rank_62)))))
 (let (($x4956 (or $x4953 (and $x4007 (< rank_68 rank_62)))))
 (let (($x4960 (not root_63)))
 (let (($x4961 (and $x3920 $x4960)))
 (let (($x4938 (or false (and $x3920 (< rank_62 rank_60)))))
 (let (($x4942 (not root_61)))
 (let (($x4943 (and $x3891 $x4942)))
 (let (($x4935 (and true (=> root_61 $x3891))))
 (let (($x4945 (and $x4935 (=> $x4943 (or $x4938 (and $x3978 (< rank_66 rank_60)))))))
 (let (($x4950 (and $x4945 (=> root_63 $x3920))))
 (let (($x4963 (and $x4950 (=> $x4961 (or $x4956 (and $x3891 (< rank_60 rank_62)))))))
 (let (($x4968 (and $x4963 (=> root_65 $x3949))))
 (let (($x4978 (and $x4968 (=> $x4976 (or $x4971 (and $x3920 (< rank_62 rank_64)))))))
 (let (($x4983 (and $x4978 (=> root_67 $x3978))))
 (let (($x4993 (and $x4983 (=> $x4991 (or $x4986 (and $x3891 (< rank_60 rank_66)))))))
 (let (($x4998 (and $x4993 (=> root_69 $x4007))))
 (let (($x5011 (and $x4998 (=> $x5009 (or $x5004 (and $x3920 (< rank_62 rank_68)))))))
 (let (($x5016 (and $x5011 (=> root_71 $x4036))))
 (let (($x5028 (and (and $x5016 (=> $x5024 (or $x5019 (and $x3949 (< rank_64 rank_70))))) (=> $x4138 (or $x4994 root_71)))))
 (let (($x5030 (and $x5028 (<= (+ ?x4996 ?x5013) 1))))
 (let (($x5031 (and true $x5030)))
 (let (($x4864 (and true (=> c_1_0 d_1_1))))
 (let (($x4866 (and $x4864 (=> c_1_1 d_1_1))))
 (let (($x4868 (and $x4866 (=> c_1_2 d_1_1))))
 (let (($x4870 (and $x4868 (=> c_1_3 d_1_1))))
 (let (($x4872 (and $x4870 (=> c_1_4 d_1_1))))
 (let (($x4874 (and $x4872 (=> c_1_5 d_1_1))))
 (let (($x4876 (and $x4874 (=> c_1_6 d_1_1))))
 (let (($x4878 (and $x4876 (=> c_1_7 d_1_1))))
 (let (($x4880 (and $x4878 (=> c_1_8 d_1_1))))
 (let (($x4882 (and $x4880 (=> c_1_9 d_1_1))))
 (let (($x4884 (and $x4882 (=> c_1_10 d_1_1))))
 (let (($x4886 (and $x4884 (=> c_1_11 d_1_1))))
 (let (($x4888 (and $x4886 (=> c_1_12 d_1_1))))
 (let (($x4890 (and $x4888 (=> c_1_13 d_1_1))))
 (let (($x4892 (and $x4890 (=> c_1_14 d_1_1))))
 (let (($x4841 (and $x4830 (=> c_0_2 d_0_1))))
 (let (($x4831 (and $x4841 (=> c_0_3 d_0_1))))
 (let (($x4832 (and $x4831 (=> c_0_4 d_0_1))))
 (let (($x4839 (and $x4832 (=> c_0_5 d_0_1))))
 (let (($x4843 (and $x4839 $x4842)))
 (let (($x4845 (and $x4843 (=> c_0_7 d_0_1))))
 (let (($x4847 (and $x4845 (=> c_0_8 d_0_1))))
 (let (($x4849 (and $x4847 (=> c_0_9 d_0_1))))
 (let (($x4851 (and $x4849 (=> c_0_10 d_0_1))))
 (let (($x4853 (and $x4851 $x4852)))
 (let (($x4855 (and $x4853 (=> c_0_12 d_0_1))))
 (let (($x4857 (and $x4855 (=> c_0_13 d_0_1))))
 (let (($x4859 (and $x4857 (=> c_0_14 d_0_1))))
 (let (($x4828 (and true c_0_7)))
 (let (($x4834 (and $x4828 c_1_14)))
 (let (($x4862 (and $x4834 (and $x4859 (=> c_0_15 d_0_1)))))
 (let (($x4895 (and $x4862 (and $x4892 (=> c_1_15 d_1_1)))))
 (let (($x4896 (and $x4895 $x3746)))
 (let (($x4897 (and $x4896 $x3779)))
 (let (($x4898 (and $x4897 $x3812)))
 (let ((?x4808 (ite root_59 1 0)))
 (let ((?x4790 (ite root_57 1 0)))
 (let ((?x4775 (ite root_55 1 0)))
 (let ((?x4760 (ite root_53 1 0)))
 (let ((?x4742 (ite root_51 1 0)))
 (let ((?x4727 (ite root_49 1 0)))
 (let ((?x4728 (+ 0 ?x4727)))
 (let ((?x4743 (+ ?x4728 ?x4742)))
 (let ((?x4761 (+ ?x4743 ?x4760)))
 (let ((?x4776 (+ ?x4761 ?x4775)))
 (let ((?x4791 (+ ?x4776 ?x4790)))
 (let (($x4726 (or false root_49)))
 (let (($x4741 (or $x4726 root_51)))
 (let (($x4759 (or $x4741 root_53)))
 (let (($x4774 (or $x4759 root_55)))
 (let (($x4789 (or $x4774 root_57)))
 (let (($x4814 (or false (and $x3429 (< rank_56 rank_58)))))
 (let (($x4818 (not root_59)))
 (let (($x4819 (and $x3458 $x4818)))
 (let (($x4796 (or false (and $x3458 (< rank_58 rank_56)))))
 (let (($x4799 (or $x4796 (and $x3400 (< rank_54 rank_56)))))
 (let (($x4803 (not root_57)))
 (let (($x4804 (and $x3429 $x4803)))
 (let (($x4781 (or false (and $x3429 (< rank_56 rank_54)))))
 (let (($x4785 (not root_55)))
 (let (($x4786 (and $x3400 $x4785)))
 (let (($x4766 (or false (and $x3458 (< rank_58 rank_52)))))
 (let (($x4770 (not root_53)))
 (let (($x4771 (and $x3371 $x4770)))
 (let (($x4748 (or false (and $x3371 (< rank_52 rank_50)))))
 (let (($x4751 (or $x4748 (and $x3429 (< rank_56 rank_50)))))
 (let (($x4755 (not root_51)))
 (let (($x4756 (and $x3342 $x4755)))
 (let (($x4733 (or false (and $x3342 (< rank_50 rank_48)))))
 (let (($x4737 (not root_49)))
 (let (($x4738 (and $x3313 $x4737)))
 (let (($x4730 (and true (=> root_49 $x3313))))
 (let (($x4740 (and $x4730 (=> $x4738 (or $x4733 (and $x3400 (< rank_54 rank_48)))))))
 (let (($x4745 (and $x4740 (=> root_51 $x3342))))
 (let (($x4758 (and $x4745 (=> $x4756 (or $x4751 (and $x3313 (< rank_48 rank_50)))))))
 (let (($x4763 (and $x4758 (=> root_53 $x3371))))
 (let (($x4773 (and $x4763 (=> $x4771 (or $x4766 (and $x3342 (< rank_50 rank_52)))))))
 (let (($x4778 (and $x4773 (=> root_55 $x3400))))
 (let (($x4788 (and $x4778 (=> $x4786 (or $x4781 (and $x3313 (< rank_48 rank_54)))))))
 (let (($x4793 (and $x4788 (=> root_57 $x3429))))
 (let (($x4806 (and $x4793 (=> $x4804 (or $x4799 (and $x3342 (< rank_50 rank_56)))))))
 (let (($x4811 (and $x4806 (=> root_59 $x3458))))
 (let (($x4823 (and (and $x4811 (=> $x4819 (or $x4814 (and $x3371 (< rank_52 rank_58))))) (=> $x3563 (or $x4789 root_59)))))
 (let (($x4825 (and $x4823 (<= (+ ?x4791 ?x4808) 1))))
 (let (($x4826 (and true $x4825)))
 (let (($x5046 (= rule_instance 28)))
 (let (($x5038 (and $x5046 (and (and (and $x4826 $x3602) (and $x4898 $x3845)) (and $x5031 $x4162)))))
 (let ((?x4670 (ite root_47 1 0)))
 (let ((?x4652 (ite root_45 1 0)))
 (let ((?x4637 (ite root_43 1 0)))
 (let ((?x4622 (ite root_41 1 0)))
 (let ((?x4604 (ite root_39 1 0)))
 (let ((?x4589 (ite root_37 1 0)))
 (let ((?x4590 (+ 0 ?x4589)))
 (let ((?x4605 (+ ?x4590 ?x4604)))
 (let ((?x4623 (+ ?x4605 ?x4622)))
 (let ((?x4638 (+ ?x4623 ?x4637)))
 (let ((?x4653 (+ ?x4638 ?x4652)))
 (let (($x4588 (or false root_37)))
 (let (($x4603 (or $x4588 root_39)))
 (let (($x4621 (or $x4603 root_41)))
 (let (($x4636 (or $x4621 root_43)))
 (let (($x4651 (or $x4636 root_45)))
 (let (($x4676 (or false (and $x4007 (< rank_44 rank_46)))))
 (let (($x4680 (not root_47)))
 (let (($x4681 (and $x4036 $x4680)))
 (let (($x4658 (or false (and $x4036 (< rank_46 rank_44)))))
 (let (($x4661 (or $x4658 (and $x3978 (< rank_42 rank_44)))))
 (let (($x4665 (not root_45)))
 (let (($x4666 (and $x4007 $x4665)))
 (let (($x4643 (or false (and $x4007 (< rank_44 rank_42)))))
 (let (($x4647 (not root_43)))
 (let (($x4648 (and $x3978 $x4647)))
 (let (($x4628 (or false (and $x4036 (< rank_46 rank_40)))))
 (let (($x4632 (not root_41)))
 (let (($x4633 (and $x3949 $x4632)))
 (let (($x4610 (or false (and $x3949 (< rank_40 rank_38)))))
 (let (($x4613 (or $x4610 (and $x4007 (< rank_44 rank_38)))))
 (let (($x4617 (not root_39)))
 (let (($x4618 (and $x3920 $x4617)))
 (let (($x4595 (or false (and $x3920 (< rank_38 rank_36)))))
 (let (($x4599 (not root_37)))
 (let (($x4600 (and $x3891 $x4599)))
 (let (($x4592 (and true (=> root_37 $x3891))))
 (let (($x4602 (and $x4592 (=> $x4600 (or $x4595 (and $x3978 (< rank_42 rank_36)))))))
 (let (($x4607 (and $x4602 (=> root_39 $x3920))))
 (let (($x4620 (and $x4607 (=> $x4618 (or $x4613 (and $x3891 (< rank_36 rank_38)))))))
 (let (($x4625 (and $x4620 (=> root_41 $x3949))))
 (let (($x4635 (and $x4625 (=> $x4633 (or $x4628 (and $x3920 (< rank_38 rank_40)))))))
 (let (($x4640 (and $x4635 (=> root_43 $x3978))))
 (let (($x4650 (and $x4640 (=> $x4648 (or $x4643 (and $x3891 (< rank_36 rank_42)))))))
 (let (($x4655 (and $x4650 (=> root_45 $x4007))))
 (let (($x4668 (and $x4655 (=> $x4666 (or $x4661 (and $x3920 (< rank_38 rank_44)))))))
 (let (($x4673 (and $x4668 (=> root_47 $x4036))))
 (let (($x4685 (and (and $x4673 (=> $x4681 (or $x4676 (and $x3949 (< rank_40 rank_46))))) (=> $x4138 (or $x4651 root_47)))))
 (let (($x4687 (and $x4685 (<= (+ ?x4653 ?x4670) 1))))
 (let (($x4688 (and true $x4687)))
 (let (($x4521 (and true (=> c_1_0 d_1_0))))
 (let (($x4523 (and $x4521 (=> c_1_1 d_1_0))))
 (let (($x4525 (and $x4523 (=> c_1_2 d_1_0))))
 (let (($x4527 (and $x4525 (=> c_1_3 d_1_0))))
 (let (($x4529 (and $x4527 (=> c_1_4 d_1_0))))
 (let (($x4531 (and $x4529 (=> c_1_5 d_1_0))))
 (let (($x4533 (and $x4531 (=> c_1_6 d_1_0))))
 (let (($x4535 (and $x4533 (=> c_1_7 d_1_0))))
 (let (($x4537 (and $x4535 (=> c_1_8 d_1_0))))
 (let (($x4539 (and $x4537 (=> c_1_9 d_1_0))))
 (let (($x4541 (and $x4539 (=> c_1_10 d_1_0))))
 (let (($x4543 (and $x4541 (=> c_1_11 d_1_0))))
 (let (($x4545 (and $x4543 (=> c_1_12 d_1_0))))
 (let (($x4547 (and $x4545 (=> c_1_13 d_1_0))))
 (let (($x4549 (and $x4547 (=> c_1_14 d_1_0))))
 (let (($x4495 (and true (=> c_0_0 d_0_6))))
 (let (($x4487 (and $x4495 (=> c_0_1 d_0_6))))
 (let (($x4498 (and $x4487 (=> c_0_2 d_0_6))))
 (let (($x4488 (and $x4498 (=> c_0_3 d_0_6))))
 (let (($x4489 (and $x4488 (=> c_0_4 d_0_6))))
 (let (($x4496 (and $x4489 (=> c_0_5 d_0_6))))
 (let (($x4500 (and $x4496 (=> c_0_6 d_0_6))))
 (let (($x4502 (and $x4500 (=> c_0_7 d_0_6))))
 (let (($x4504 (and $x4502 (=> c_0_8 d_0_6))))
 (let (($x4506 (and $x4504 (=> c_0_9 d_0_6))))
 (let (($x4508 (and $x4506 (=> c_0_10 d_0_6))))
 (let (($x4510 (and $x4508 (=> c_0_11 d_0_6))))
 (let (($x4512 (and $x4510 (=> c_0_12 d_0_6))))
 (let (($x4514 (and $x4512 (=> c_0_13 d_0_6))))
 (let (($x4516 (and $x4514 (=> c_0_14 d_0_6))))
 (let (($x4485 (and true c_0_2)))
 (let (($x4491 (and $x4485 c_1_14)))
 (let (($x4519 (and $x4491 (and $x4516 (=> c_0_15 d_0_6)))))
 (let (($x4552 (and $x4519 (and $x4549 (=> c_1_15 d_1_0)))))
 (let (($x4553 (and $x4552 $x3746)))
 (let (($x4554 (and $x4553 $x3779)))
 (let (($x4555 (and $x4554 $x3812)))
 (let ((?x4465 (ite root_35 1 0)))
 (let ((?x4447 (ite root_33 1 0)))
 (let ((?x4432 (ite root_31 1 0)))
 (let ((?x4417 (ite root_29 1 0)))
 (let ((?x4399 (ite root_27 1 0)))
 (let ((?x4384 (ite root_25 1 0)))
 (let ((?x4385 (+ 0 ?x4384)))
 (let ((?x4400 (+ ?x4385 ?x4399)))
 (let ((?x4418 (+ ?x4400 ?x4417)))
 (let ((?x4433 (+ ?x4418 ?x4432)))
 (let ((?x4448 (+ ?x4433 ?x4447)))
 (let (($x4383 (or false root_25)))
 (let (($x4398 (or $x4383 root_27)))
 (let (($x4416 (or $x4398 root_29)))
 (let (($x4431 (or $x4416 root_31)))
 (let (($x4446 (or $x4431 root_33)))
 (let (($x4471 (or false (and $x3429 (< rank_32 rank_34)))))
 (let (($x4475 (not root_35)))
 (let (($x4476 (and $x3458 $x4475)))
 (let (($x4453 (or false (and $x3458 (< rank_34 rank_32)))))
 (let (($x4456 (or $x4453 (and $x3400 (< rank_30 rank_32)))))
 (let (($x4460 (not root_33)))
 (let (($x4461 (and $x3429 $x4460)))
 (let (($x4438 (or false (and $x3429 (< rank_32 rank_30)))))
 (let (($x4442 (not root_31)))
 (let (($x4443 (and $x3400 $x4442)))
 (let (($x4423 (or false (and $x3458 (< rank_34 rank_28)))))
 (let (($x4427 (not root_29)))
 (let (($x4428 (and $x3371 $x4427)))
 (let (($x4405 (or false (and $x3371 (< rank_28 rank_26)))))
 (let (($x4408 (or $x4405 (and $x3429 (< rank_32 rank_26)))))
 (let (($x4412 (not root_27)))
 (let (($x4413 (and $x3342 $x4412)))
 (let (($x4390 (or false (and $x3342 (< rank_26 rank_24)))))
 (let (($x4394 (not root_25)))
 (let (($x4395 (and $x3313 $x4394)))
 (let (($x4387 (and true (=> root_25 $x3313))))
 (let (($x4397 (and $x4387 (=> $x4395 (or $x4390 (and $x3400 (< rank_30 rank_24)))))))
 (let (($x4402 (and $x4397 (=> root_27 $x3342))))
 (let (($x4415 (and $x4402 (=> $x4413 (or $x4408 (and $x3313 (< rank_24 rank_26)))))))
 (let (($x4420 (and $x4415 (=> root_29 $x3371))))
 (let (($x4430 (and $x4420 (=> $x4428 (or $x4423 (and $x3342 (< rank_26 rank_28)))))))
 (let (($x4435 (and $x4430 (=> root_31 $x3400))))
 (let (($x4445 (and $x4435 (=> $x4443 (or $x4438 (and $x3313 (< rank_24 rank_30)))))))
 (let (($x4450 (and $x4445 (=> root_33 $x3429))))
 (let (($x4463 (and $x4450 (=> $x4461 (or $x4456 (and $x3342 (< rank_26 rank_32)))))))
 (let (($x4468 (and $x4463 (=> root_35 $x3458))))
 (let (($x4480 (and (and $x4468 (=> $x4476 (or $x4471 (and $x3371 (< rank_28 rank_34))))) (=> $x3563 (or $x4446 root_35)))))
 (let (($x4482 (and $x4480 (<= (+ ?x4448 ?x4465) 1))))
 (let (($x4483 (and true $x4482)))
 (let (($x4703 (= rule_instance 14)))
 (let (($x4695 (and $x4703 (and (and (and $x4483 $x3602) (and $x4555 $x3845)) (and $x4688 $x4162)))))
 (let ((?x4140 (ite root_23 1 0)))
 (let ((?x4121 (ite root_21 1 0)))
 (let ((?x4105 (ite root_19 1 0)))
 (let ((?x4089 (ite root_17 1 0)))
 (let ((?x4070 (ite root_15 1 0)))
 (let ((?x4054 (ite root_13 1 0)))
 (let ((?x4055 (+ 0 ?x4054)))
 (let ((?x4071 (+ ?x4055 ?x4070)))
 (let ((?x4090 (+ ?x4071 ?x4089)))
 (let ((?x4106 (+ ?x4090 ?x4105)))
 (let ((?x4122 (+ ?x4106 ?x4121)))
 (let (($x4053 (or false root_13)))
 (let (($x4069 (or $x4053 root_15)))
 (let (($x4088 (or $x4069 root_17)))
 (let (($x4104 (or $x4088 root_19)))
 (let (($x4120 (or $x4104 root_21)))
 (let (($x4146 (or false (and $x4007 (< rank_20 rank_22)))))
 (let (($x4150 (not root_23)))
 (let (($x4151 (and $x4036 $x4150)))
 (let (($x4127 (or false (and $x4036 (< rank_22 rank_20)))))
 (let (($x4130 (or $x4127 (and $x3978 (< rank_18 rank_20)))))
 (let (($x4134 (not root_21)))
 (let (($x4135 (and $x4007 $x4134)))
 (let (($x4111 (or false (and $x4007 (< rank_20 rank_18)))))
 (let (($x4115 (not root_19)))
 (let (($x4116 (and $x3978 $x4115)))
 (let (($x4095 (or false (and $x4036 (< rank_22 rank_16)))))
 (let (($x4099 (not root_17)))
 (let (($x4100 (and $x3949 $x4099)))
 (let (($x4076 (or false (and $x3949 (< rank_16 rank_14)))))
 (let (($x4079 (or $x4076 (and $x4007 (< rank_20 rank_14)))))
 (let (($x4083 (not root_15)))
 (let (($x4084 (and $x3920 $x4083)))
 (let (($x4060 (or false (and $x3920 (< rank_14 rank_12)))))
 (let (($x4064 (not root_13)))
 (let (($x4065 (and $x3891 $x4064)))
 (let (($x4057 (and true (=> root_13 $x3891))))
 (let (($x4067 (and $x4057 (=> $x4065 (or $x4060 (and $x3978 (< rank_18 rank_12)))))))
 (let (($x4073 (and $x4067 (=> root_15 $x3920))))
 (let (($x4086 (and $x4073 (=> $x4084 (or $x4079 (and $x3891 (< rank_12 rank_14)))))))
 (let (($x4092 (and $x4086 (=> root_17 $x3949))))
 (let (($x4102 (and $x4092 (=> $x4100 (or $x4095 (and $x3920 (< rank_14 rank_16)))))))
 (let (($x4108 (and $x4102 (=> root_19 $x3978))))
 (let (($x4118 (and $x4108 (=> $x4116 (or $x4111 (and $x3891 (< rank_12 rank_18)))))))
 (let (($x4124 (and $x4118 (=> root_21 $x4007))))
 (let (($x4137 (and $x4124 (=> $x4135 (or $x4130 (and $x3920 (< rank_14 rank_20)))))))
 (let (($x4143 (and $x4137 (=> root_23 $x4036))))
 (let (($x4155 (and (and $x4143 (=> $x4151 (or $x4146 (and $x3949 (< rank_16 rank_22))))) (=> $x4138 (or $x4120 root_23)))))
 (let (($x4157 (and $x4155 (<= (+ ?x4122 ?x4140) 1))))
 (let (($x4158 (and true $x4157)))
 (let (($x3650 (and true (=> c_0_0 d_0_2))))
 (let (($x3652 (and $x3650 (=> c_0_1 d_0_2))))
 (let (($x3654 (and $x3652 $x3653)))
 (let (($x3656 (and $x3654 (=> c_0_3 d_0_2))))
 (let (($x3658 (and $x3656 (=> c_0_4 d_0_2))))
 (let (($x3660 (and $x3658 (=> c_0_5 d_0_2))))
 (let (($x3662 (and $x3660 (=> c_0_6 d_0_2))))
 (let (($x3664 (and $x3662 $x3663)))
 (let (($x3666 (and $x3664 (=> c_0_8 d_0_2))))
 (let (($x3668 (and $x3666 (=> c_0_9 d_0_2))))
 (let (($x3670 (and $x3668 (=> c_0_10 d_0_2))))
 (let (($x3672 (and $x3670 (=> c_0_11 d_0_2))))
 (let (($x3674 (and $x3672 $x3673)))
 (let (($x3676 (and $x3674 (=> c_0_13 d_0_2))))
 (let (($x3678 (and $x3676 (=> c_0_14 d_0_2))))
 (let (($x3647 (and true c_0_6)))
 (let (($x3648 (and $x3647 c_1_0)))
 (let (($x3681 (and $x3648 (and $x3678 (=> c_0_15 d_0_2)))))
 (let (($x3714 (and $x3681 $x3713)))
 (let (($x3747 (and $x3714 $x3746)))
 (let (($x3780 (and $x3747 $x3779)))
 (let (($x3813 (and $x3780 $x3812)))
 (let ((?x3565 (ite root_11 1 0)))
 (let ((?x3546 (ite root_9 1 0)))
 (let ((?x3530 (ite root_7 1 0)))
 (let ((?x3514 (ite root_5 1 0)))
 (let ((?x3495 (ite root_3 1 0)))
 (let ((?x3479 (ite root_1 1 0)))
 (let ((?x3480 (+ 0 ?x3479)))
 (let ((?x3496 (+ ?x3480 ?x3495)))
 (let ((?x3515 (+ ?x3496 ?x3514)))
 (let ((?x3531 (+ ?x3515 ?x3530)))
 (let ((?x3547 (+ ?x3531 ?x3546)))
 (let (($x3477 (or false root_1)))
 (let (($x3494 (or $x3477 root_3)))
 (let (($x3513 (or $x3494 root_5)))
 (let (($x3529 (or $x3513 root_7)))
 (let (($x3545 (or $x3529 root_9)))
 (let (($x3571 (or false (and $x3429 (< rank_8 rank_10)))))
 (let (($x3575 (not root_11)))
 (let (($x3576 (and $x3458 $x3575)))
 (let (($x3552 (or false (and $x3458 (< rank_10 rank_8)))))
 (let (($x3555 (or $x3552 (and $x3400 (< rank_6 rank_8)))))
 (let (($x3559 (not root_9)))
 (let (($x3560 (and $x3429 $x3559)))
 (let (($x3536 (or false (and $x3429 (< rank_8 rank_6)))))
 (let (($x3540 (not root_7)))
 (let (($x3541 (and $x3400 $x3540)))
 (let (($x3520 (or false (and $x3458 (< rank_10 rank_4)))))
 (let (($x3524 (not root_5)))
 (let (($x3525 (and $x3371 $x3524)))
 (let (($x3501 (or false (and $x3371 (< rank_4 rank_2)))))
 (let (($x3504 (or $x3501 (and $x3429 (< rank_8 rank_2)))))
 (let (($x3508 (not root_3)))
 (let (($x3509 (and $x3342 $x3508)))
 (let (($x3485 (or false (and $x3342 (< rank_2 rank_0)))))
 (let (($x3489 (not root_1)))
 (let (($x3490 (and $x3313 $x3489)))
 (let (($x3482 (and true (=> root_1 $x3313))))
 (let (($x3492 (and $x3482 (=> $x3490 (or $x3485 (and $x3400 (< rank_6 rank_0)))))))
 (let (($x3498 (and $x3492 (=> root_3 $x3342))))
 (let (($x3511 (and $x3498 (=> $x3509 (or $x3504 (and $x3313 (< rank_0 rank_2)))))))
 (let (($x3517 (and $x3511 (=> root_5 $x3371))))
 (let (($x3527 (and $x3517 (=> $x3525 (or $x3520 (and $x3342 (< rank_2 rank_4)))))))
 (let (($x3533 (and $x3527 (=> root_7 $x3400))))
 (let (($x3543 (and $x3533 (=> $x3541 (or $x3536 (and $x3313 (< rank_0 rank_6)))))))
 (let (($x3549 (and $x3543 (=> root_9 $x3429))))
 (let (($x3562 (and $x3549 (=> $x3560 (or $x3555 (and $x3342 (< rank_2 rank_8)))))))
 (let (($x3568 (and $x3562 (=> root_11 $x3458))))
 (let (($x3580 (and (and $x3568 (=> $x3576 (or $x3571 (and $x3371 (< rank_4 rank_10))))) (=> $x3563 (or $x3545 root_11)))))
 (let (($x3582 (and $x3580 (<= (+ ?x3547 ?x3565) 1))))
 (let (($x3583 (and true $x3582)))
 (let (($x4348 (= rule_instance 0)))
 (let (($x4349 (and $x4348 (and (and (and $x3583 $x3602) (and $x3813 $x3845)) (and $x4158 $x4162)))))
 (let (($x4352 (or false (and $x4349 $x4350))))
 (let (($x4698 (or $x4352 (and $x4695 $x4350))))
 (let (($x5041 (or $x4698 (and $x5038 $x4350))))
 (let (($x5352 (or $x5041 (and $x5349 $x4350))))
 (or $x5352 (and $x5689 $x4350))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
