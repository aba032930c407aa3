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
 (let (($x4303 (>= rank_24 0)))
 (and $x4303 (< rank_24 6))))
(assert
 (let (($x4314 (>= rank_26 0)))
 (and $x4314 (< rank_26 6))))
(assert
 (let (($x4309 (>= rank_28 0)))
 (and $x4309 (< rank_28 6))))
(assert
 (let (($x4318 (>= rank_30 0)))
 (and $x4318 (< rank_30 6))))
(assert
 (let (($x4323 (>= rank_32 0)))
 (and $x4323 (< rank_32 6))))
(assert
 (let (($x4328 (>= rank_34 0)))
 (and $x4328 (< rank_34 6))))
(assert
 (let (($x4509 (>= rank_36 0)))
 (and $x4509 (< rank_36 6))))
(assert
 (let (($x4512 (>= rank_38 0)))
 (and $x4512 (< rank_38 6))))
(assert
 (let (($x4511 (>= rank_40 0)))
 (and $x4511 (< rank_40 6))))
(assert
 (let (($x4523 (>= rank_42 0)))
 (and $x4523 (< rank_42 6))))
(assert
 (let (($x4528 (>= rank_44 0)))
 (and $x4528 (< rank_44 6))))
(assert
 (let (($x4533 (>= rank_46 0)))
 (and $x4533 (< rank_46 6))))
(assert
 (let (($x4642 (>= rank_48 0)))
 (and $x4642 (< rank_48 6))))
(assert
 (let (($x4657 (>= rank_50 0)))
 (and $x4657 (< rank_50 6))))
(assert
 (let (($x4652 (>= rank_52 0)))
 (and $x4652 (< rank_52 6))))
(assert
 (let (($x4661 (>= rank_54 0)))
 (and $x4661 (< rank_54 6))))
(assert
 (let (($x4666 (>= rank_56 0)))
 (and $x4666 (< rank_56 6))))
(assert
 (let (($x4671 (>= rank_58 0)))
 (and $x4671 (< rank_58 6))))
(assert
 (let (($x4852 (>= rank_60 0)))
 (and $x4852 (< rank_60 6))))
(assert
 (let (($x4855 (>= rank_62 0)))
 (and $x4855 (< rank_62 6))))
(assert
 (let (($x4854 (>= rank_64 0)))
 (and $x4854 (< rank_64 6))))
(assert
 (let (($x4866 (>= rank_66 0)))
 (and $x4866 (< rank_66 6))))
(assert
 (let (($x4871 (>= rank_68 0)))
 (and $x4871 (< rank_68 6))))
(assert
 (let (($x4876 (>= rank_70 0)))
 (and $x4876 (< rank_70 6))))
(assert
 (let (($x4985 (>= rank_72 0)))
 (and $x4985 (< rank_72 6))))
(assert
 (let (($x5000 (>= rank_74 0)))
 (and $x5000 (< rank_74 6))))
(assert
 (let (($x4995 (>= rank_76 0)))
 (and $x4995 (< rank_76 6))))
(assert
 (let (($x5004 (>= rank_78 0)))
 (and $x5004 (< rank_78 6))))
(assert
 (let (($x5009 (>= rank_80 0)))
 (and $x5009 (< rank_80 6))))
(assert
 (let (($x5014 (>= rank_82 0)))
 (and $x5014 (< rank_82 6))))
(assert
 (let (($x5163 (>= rank_84 0)))
 (and $x5163 (< rank_84 6))))
(assert
 (let (($x5166 (>= rank_86 0)))
 (and $x5166 (< rank_86 6))))
(assert
 (let (($x5165 (>= rank_88 0)))
 (and $x5165 (< rank_88 6))))
(assert
 (let (($x5177 (>= rank_90 0)))
 (and $x5177 (< rank_90 6))))
(assert
 (let (($x5182 (>= rank_92 0)))
 (and $x5182 (< rank_92 6))))
(assert
 (let (($x5187 (>= rank_94 0)))
 (and $x5187 (< rank_94 6))))
(assert
 (let (($x5296 (>= rank_96 0)))
 (and $x5296 (< rank_96 6))))
(assert
 (let (($x5311 (>= rank_98 0)))
 (and $x5311 (< rank_98 6))))
(assert
 (let (($x5306 (>= rank_100 0)))
 (and $x5306 (< rank_100 6))))
(assert
 (let (($x5315 (>= rank_102 0)))
 (and $x5315 (< rank_102 6))))
(assert
 (let (($x5320 (>= rank_104 0)))
 (and $x5320 (< rank_104 6))))
(assert
 (let (($x5325 (>= rank_106 0)))
 (and $x5325 (< rank_106 6))))
(assert
 (let (($x5503 (>= rank_108 0)))
 (and $x5503 (< rank_108 6))))
(assert
 (let (($x5506 (>= rank_110 0)))
 (and $x5506 (< rank_110 6))))
(assert
 (let (($x5505 (>= rank_112 0)))
 (and $x5505 (< rank_112 6))))
(assert
 (let (($x5517 (>= rank_114 0)))
 (and $x5517 (< rank_114 6))))
(assert
 (let (($x5522 (>= rank_116 0)))
 (and $x5522 (< rank_116 6))))
(assert
 (let (($x5527 (>= rank_118 0)))
 (and $x5527 (< rank_118 6))))
(assert
 (let ((?x4293 (ite (or (or (or (or d_1_6 d_1_7) d_1_8) d_1_9) d_1_10) 3 0)))
 (let ((?x4291 (ite (or (or (or (or d_1_1 d_1_2) d_1_3) d_1_4) d_1_5) 2 0)))
 (let ((?x4289 (ite (or (or (or (or d_1_11 d_1_12) d_1_13) d_1_14) d_1_15) 1 0)))
 (let ((?x4290 (+ 0 ?x4289)))
 (let ((?x4292 (+ ?x4290 ?x4291)))
 (let ((?x4255 (ite (or (or (or (or d_0_6 d_0_7) d_0_8) d_0_9) d_0_10) 3 0)))
 (let ((?x4253 (ite (or (or (or (or d_0_1 d_0_2) d_0_3) d_0_4) d_0_5) 2 0)))
 (let ((?x4251 (ite (or (or (or (or d_0_11 d_0_12) d_0_13) d_0_14) d_0_15) 1 0)))
 (let ((?x4252 (+ 0 ?x4251)))
 (let ((?x4254 (+ ?x4252 ?x4253)))
 (let ((?x4257 (+ 0 (+ ?x4254 ?x4255))))
 (let ((?x4274 (ite (or (or (or (or c_1_6 c_1_7) c_1_8) c_1_9) c_1_10) 3 0)))
 (let ((?x4272 (ite (or (or (or (or c_1_1 c_1_2) c_1_3) c_1_4) c_1_5) 2 0)))
 (let ((?x4270 (ite (or (or (or (or c_1_11 c_1_12) c_1_13) c_1_14) c_1_15) 1 0)))
 (let ((?x4271 (+ 0 ?x4270)))
 (let ((?x4273 (+ ?x4271 ?x4272)))
 (let ((?x4236 (ite (or (or (or (or c_0_6 c_0_7) c_0_8) c_0_9) c_0_10) 3 0)))
 (let ((?x4233 (ite (or (or (or (or c_0_1 c_0_2) c_0_3) c_0_4) c_0_5) 2 0)))
 (let ((?x4230 (ite (or (or (or (or c_0_11 c_0_12) c_0_13) c_0_14) c_0_15) 1 0)))
 (let ((?x4231 (+ 0 ?x4230)))
 (let ((?x4234 (+ ?x4231 ?x4233)))
 (let ((?x4238 (+ 0 (+ ?x4234 ?x4236))))
 (let (($x4298 (and (distinct (+ ?x4238 (+ ?x4273 ?x4274)) (+ ?x4257 (+ ?x4292 ?x4293))) true)))
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
 (let ((?x5612 (ite root_119 1 0)))
 (let ((?x5594 (ite root_117 1 0)))
 (let ((?x5579 (ite root_115 1 0)))
 (let ((?x5564 (ite root_113 1 0)))
 (let ((?x5546 (ite root_111 1 0)))
 (let ((?x5531 (ite root_109 1 0)))
 (let ((?x5532 (+ 0 ?x5531)))
 (let ((?x5547 (+ ?x5532 ?x5546)))
 (let ((?x5565 (+ ?x5547 ?x5564)))
 (let ((?x5580 (+ ?x5565 ?x5579)))
 (let ((?x5595 (+ ?x5580 ?x5594)))
 (let (($x5530 (or false root_109)))
 (let (($x5545 (or $x5530 root_111)))
 (let (($x5563 (or $x5545 root_113)))
 (let (($x5578 (or $x5563 root_115)))
 (let (($x5593 (or $x5578 root_117)))
 (let (($x4052 (or false $x3891)))
 (let (($x4068 (or $x4052 $x3920)))
 (let (($x4087 (or $x4068 $x3949)))
 (let (($x4103 (or $x4087 $x3978)))
 (let (($x4119 (or $x4103 $x4007)))
 (let (($x4138 (or $x4119 $x4036)))
 (let (($x5618 (or false (and $x4007 (< rank_116 rank_118)))))
 (let (($x5622 (not root_119)))
 (let (($x5623 (and $x4036 $x5622)))
 (let (($x5600 (or false (and $x4036 (< rank_118 rank_116)))))
 (let (($x5603 (or $x5600 (and $x3978 (< rank_114 rank_116)))))
 (let (($x5607 (not root_117)))
 (let (($x5608 (and $x4007 $x5607)))
 (let (($x5585 (or false (and $x4007 (< rank_116 rank_114)))))
 (let (($x5589 (not root_115)))
 (let (($x5590 (and $x3978 $x5589)))
 (let (($x5570 (or false (and $x4036 (< rank_118 rank_112)))))
 (let (($x5574 (not root_113)))
 (let (($x5575 (and $x3949 $x5574)))
 (let (($x5552 (or false (and $x3949 (< rank_112 rank_110)))))
 (let (($x5555 (or $x5552 (and $x4007 (< rank_116 rank_110)))))
 (let (($x5559 (not root_111)))
 (let (($x5560 (and $x3920 $x5559)))
 (let (($x5537 (or false (and $x3920 (< rank_110 rank_108)))))
 (let (($x5541 (not root_109)))
 (let (($x5542 (and $x3891 $x5541)))
 (let (($x5534 (and true (=> root_109 $x3891))))
 (let (($x5544 (and $x5534 (=> $x5542 (or $x5537 (and $x3978 (< rank_114 rank_108)))))))
 (let (($x5549 (and $x5544 (=> root_111 $x3920))))
 (let (($x5562 (and $x5549 (=> $x5560 (or $x5555 (and $x3891 (< rank_108 rank_110)))))))
 (let (($x5567 (and $x5562 (=> root_113 $x3949))))
 (let (($x5577 (and $x5567 (=> $x5575 (or $x5570 (and $x3920 (< rank_110 rank_112)))))))
 (let (($x5582 (and $x5577 (=> root_115 $x3978))))
 (let (($x5592 (and $x5582 (=> $x5590 (or $x5585 (and $x3891 (< rank_108 rank_114)))))))
 (let (($x5597 (and $x5592 (=> root_117 $x4007))))
 (let (($x5610 (and $x5597 (=> $x5608 (or $x5603 (and $x3920 (< rank_110 rank_116)))))))
 (let (($x5615 (and $x5610 (=> root_119 $x4036))))
 (let (($x5627 (and (and $x5615 (=> $x5623 (or $x5618 (and $x3949 (< rank_112 rank_118))))) (=> $x4138 (or $x5593 root_119)))))
 (let (($x5629 (and $x5627 (<= (+ ?x5595 ?x5612) 1))))
 (let (($x5630 (and true $x5629)))
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
 (let (($x5463 (and true (=> c_1_0 d_1_6))))
 (let (($x5465 (and $x5463 (=> c_1_1 d_1_6))))
 (let (($x5467 (and $x5465 (=> c_1_2 d_1_7))))
 (let (($x5469 (and $x5467 (=> c_1_3 d_1_8))))
 (let (($x5471 (and $x5469 (=> c_1_4 d_1_9))))
 (let (($x5473 (and $x5471 (=> c_1_5 d_1_10))))
 (let (($x5475 (and $x5473 (=> c_1_6 d_1_6))))
 (let (($x5477 (and $x5475 (=> c_1_7 d_1_7))))
 (let (($x5479 (and $x5477 (=> c_1_8 d_1_8))))
 (let (($x5481 (and $x5479 (=> c_1_9 d_1_9))))
 (let (($x5483 (and $x5481 (=> c_1_10 d_1_10))))
 (let (($x5485 (and $x5483 (=> c_1_11 d_1_6))))
 (let (($x5487 (and $x5485 (=> c_1_12 d_1_7))))
 (let (($x5489 (and $x5487 (=> c_1_13 d_1_8))))
 (let (($x5491 (and $x5489 (=> c_1_14 d_1_9))))
 (let (($x3673 (=> c_0_12 d_0_2)))
 (let (($x4800 (=> c_0_11 d_0_1)))
 (let (($x3663 (=> c_0_7 d_0_2)))
 (let (($x4790 (=> c_0_6 d_0_1)))
 (let (($x3653 (=> c_0_2 d_0_2)))
 (let (($x4779 (and true (=> c_0_0 d_0_1))))
 (let (($x4782 (and $x4779 (=> c_0_1 d_0_1))))
 (let (($x5436 (and $x4782 $x3653)))
 (let (($x5439 (and $x5436 (=> c_0_3 d_0_3))))
 (let (($x5431 (and $x5439 (=> c_0_4 d_0_4))))
 (let (($x5444 (and $x5431 (=> c_0_5 d_0_5))))
 (let (($x5445 (and $x5444 $x4790)))
 (let (($x5446 (and $x5445 $x3663)))
 (let (($x5448 (and $x5446 (=> c_0_8 d_0_3))))
 (let (($x5450 (and $x5448 (=> c_0_9 d_0_4))))
 (let (($x5452 (and $x5450 (=> c_0_10 d_0_5))))
 (let (($x5453 (and $x5452 $x4800)))
 (let (($x5454 (and $x5453 $x3673)))
 (let (($x5456 (and $x5454 (=> c_0_13 d_0_3))))
 (let (($x5458 (and $x5456 (=> c_0_14 d_0_4))))
 (let (($x5442 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x5438 (or c_0_6 c_0_7 c_0_8 c_0_9 c_0_10)))
 (let (($x5440 (and true $x5438)))
 (let (($x5435 (and $x5440 $x5442)))
 (let (($x5461 (and $x5435 (and $x5458 (=> c_0_15 d_0_5)))))
 (let (($x5494 (and $x5461 (and $x5491 (=> c_1_15 d_1_10)))))
 (let (($x5495 (and $x5494 $x3746)))
 (let (($x5496 (and $x5495 $x3779)))
 (let (($x5497 (and $x5496 $x3812)))
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
 (let ((?x5410 (ite root_107 1 0)))
 (let ((?x5392 (ite root_105 1 0)))
 (let ((?x5377 (ite root_103 1 0)))
 (let ((?x5362 (ite root_101 1 0)))
 (let ((?x5344 (ite root_99 1 0)))
 (let ((?x5329 (ite root_97 1 0)))
 (let ((?x5330 (+ 0 ?x5329)))
 (let ((?x5345 (+ ?x5330 ?x5344)))
 (let ((?x5363 (+ ?x5345 ?x5362)))
 (let ((?x5378 (+ ?x5363 ?x5377)))
 (let ((?x5393 (+ ?x5378 ?x5392)))
 (let (($x5328 (or false root_97)))
 (let (($x5343 (or $x5328 root_99)))
 (let (($x5361 (or $x5343 root_101)))
 (let (($x5376 (or $x5361 root_103)))
 (let (($x5391 (or $x5376 root_105)))
 (let (($x3476 (or false $x3313)))
 (let (($x3493 (or $x3476 $x3342)))
 (let (($x3512 (or $x3493 $x3371)))
 (let (($x3528 (or $x3512 $x3400)))
 (let (($x3544 (or $x3528 $x3429)))
 (let (($x3563 (or $x3544 $x3458)))
 (let (($x5416 (or false (and $x3429 (< rank_104 rank_106)))))
 (let (($x5420 (not root_107)))
 (let (($x5421 (and $x3458 $x5420)))
 (let (($x5398 (or false (and $x3458 (< rank_106 rank_104)))))
 (let (($x5401 (or $x5398 (and $x3400 (< rank_102 rank_104)))))
 (let (($x5405 (not root_105)))
 (let (($x5406 (and $x3429 $x5405)))
 (let (($x5383 (or false (and $x3429 (< rank_104 rank_102)))))
 (let (($x5387 (not root_103)))
 (let (($x5388 (and $x3400 $x5387)))
 (let (($x5368 (or false (and $x3458 (< rank_106 rank_100)))))
 (let (($x5372 (not root_101)))
 (let (($x5373 (and $x3371 $x5372)))
 (let (($x5350 (or false (and $x3371 (< rank_100 rank_98)))))
 (let (($x5353 (or $x5350 (and $x3429 (< rank_104 rank_98)))))
 (let (($x5357 (not root_99)))
 (let (($x5358 (and $x3342 $x5357)))
 (let (($x5335 (or false (and $x3342 (< rank_98 rank_96)))))
 (let (($x5339 (not root_97)))
 (let (($x5340 (and $x3313 $x5339)))
 (let (($x5332 (and true (=> root_97 $x3313))))
 (let (($x5342 (and $x5332 (=> $x5340 (or $x5335 (and $x3400 (< rank_102 rank_96)))))))
 (let (($x5347 (and $x5342 (=> root_99 $x3342))))
 (let (($x5360 (and $x5347 (=> $x5358 (or $x5353 (and $x3313 (< rank_96 rank_98)))))))
 (let (($x5365 (and $x5360 (=> root_101 $x3371))))
 (let (($x5375 (and $x5365 (=> $x5373 (or $x5368 (and $x3342 (< rank_98 rank_100)))))))
 (let (($x5380 (and $x5375 (=> root_103 $x3400))))
 (let (($x5390 (and $x5380 (=> $x5388 (or $x5383 (and $x3313 (< rank_96 rank_102)))))))
 (let (($x5395 (and $x5390 (=> root_105 $x3429))))
 (let (($x5408 (and $x5395 (=> $x5406 (or $x5401 (and $x3342 (< rank_98 rank_104)))))))
 (let (($x5413 (and $x5408 (=> root_107 $x3458))))
 (let (($x5425 (and (and $x5413 (=> $x5421 (or $x5416 (and $x3371 (< rank_100 rank_106))))) (=> $x3563 (or $x5391 root_107)))))
 (let (($x5427 (and $x5425 (<= (+ ?x5393 ?x5410) 1))))
 (let (($x5428 (and true $x5427)))
 (let (($x5642 (= rule_instance 56)))
 (let (($x5635 (and $x5642 (and (and (and $x5428 $x3602) (and $x5497 $x3845)) (and $x5630 $x4162)))))
 (let ((?x5272 (ite root_95 1 0)))
 (let ((?x5254 (ite root_93 1 0)))
 (let ((?x5239 (ite root_91 1 0)))
 (let ((?x5224 (ite root_89 1 0)))
 (let ((?x5206 (ite root_87 1 0)))
 (let ((?x5191 (ite root_85 1 0)))
 (let ((?x5192 (+ 0 ?x5191)))
 (let ((?x5207 (+ ?x5192 ?x5206)))
 (let ((?x5225 (+ ?x5207 ?x5224)))
 (let ((?x5240 (+ ?x5225 ?x5239)))
 (let ((?x5255 (+ ?x5240 ?x5254)))
 (let (($x5190 (or false root_85)))
 (let (($x5205 (or $x5190 root_87)))
 (let (($x5223 (or $x5205 root_89)))
 (let (($x5238 (or $x5223 root_91)))
 (let (($x5253 (or $x5238 root_93)))
 (let (($x5278 (or false (and $x4007 (< rank_92 rank_94)))))
 (let (($x5282 (not root_95)))
 (let (($x5283 (and $x4036 $x5282)))
 (let (($x5260 (or false (and $x4036 (< rank_94 rank_92)))))
 (let (($x5263 (or $x5260 (and $x3978 (< rank_90 rank_92)))))
 (let (($x5267 (not root_93)))
 (let (($x5268 (and $x4007 $x5267)))
 (let (($x5245 (or false (and $x4007 (< rank_92 rank_90)))))
 (let (($x5249 (not root_91)))
 (let (($x5250 (and $x3978 $x5249)))
 (let (($x5230 (or false (and $x4036 (< rank_94 rank_88)))))
 (let (($x5234 (not root_89)))
 (let (($x5235 (and $x3949 $x5234)))
 (let (($x5212 (or false (and $x3949 (< rank_88 rank_86)))))
 (let (($x5215 (or $x5212 (and $x4007 (< rank_92 rank_86)))))
 (let (($x5219 (not root_87)))
 (let (($x5220 (and $x3920 $x5219)))
 (let (($x5197 (or false (and $x3920 (< rank_86 rank_84)))))
 (let (($x5201 (not root_85)))
 (let (($x5202 (and $x3891 $x5201)))
 (let (($x5194 (and true (=> root_85 $x3891))))
 (let (($x5204 (and $x5194 (=> $x5202 (or $x5197 (and $x3978 (< rank_90 rank_84)))))))
 (let (($x5209 (and $x5204 (=> root_87 $x3920))))
 (let (($x5222 (and $x5209 (=> $x5220 (or $x5215 (and $x3891 (< rank_84 rank_86)))))))
 (let (($x5227 (and $x5222 (=> root_89 $x3949))))
 (let (($x5237 (and $x5227 (=> $x5235 (or $x5230 (and $x3920 (< rank_86 rank_88)))))))
 (let (($x5242 (and $x5237 (=> root_91 $x3978))))
 (let (($x5252 (and $x5242 (=> $x5250 (or $x5245 (and $x3891 (< rank_84 rank_90)))))))
 (let (($x5257 (and $x5252 (=> root_93 $x4007))))
 (let (($x5270 (and $x5257 (=> $x5268 (or $x5263 (and $x3920 (< rank_86 rank_92)))))))
 (let (($x5275 (and $x5270 (=> root_95 $x4036))))
 (let (($x5287 (and (and $x5275 (=> $x5283 (or $x5278 (and $x3949 (< rank_88 rank_94))))) (=> $x4138 (or $x5253 root_95)))))
 (let (($x5289 (and $x5287 (<= (+ ?x5255 ?x5272) 1))))
 (let (($x5290 (and true $x5289)))
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
 (let (($x5122 (and true (=> c_0_0 d_0_7))))
 (let (($x5125 (and $x5122 (=> c_0_1 d_0_7))))
 (let (($x5127 (and $x5125 (=> c_0_2 d_0_7))))
 (let (($x5121 (and $x5127 (=> c_0_3 d_0_7))))
 (let (($x5130 (and $x5121 (=> c_0_4 d_0_7))))
 (let (($x5132 (and $x5130 (=> c_0_5 d_0_7))))
 (let (($x5134 (and $x5132 (=> c_0_6 d_0_7))))
 (let (($x5136 (and $x5134 (=> c_0_7 d_0_7))))
 (let (($x5138 (and $x5136 (=> c_0_8 d_0_7))))
 (let (($x5140 (and $x5138 (=> c_0_9 d_0_7))))
 (let (($x5142 (and $x5140 (=> c_0_10 d_0_7))))
 (let (($x5144 (and $x5142 (=> c_0_11 d_0_7))))
 (let (($x5146 (and $x5144 (=> c_0_12 d_0_7))))
 (let (($x5148 (and $x5146 (=> c_0_13 d_0_7))))
 (let (($x5150 (and $x5148 (=> c_0_14 d_0_7))))
 (let (($x5119 (and true c_0_1)))
 (let (($x5123 (and $x5119 c_1_1)))
 (let (($x5153 (and $x5123 (and $x5150 (=> c_0_15 d_0_7)))))
 (let (($x5154 (and $x5153 $x3713)))
 (let (($x5155 (and $x5154 $x3746)))
 (let (($x5156 (and $x5155 $x3779)))
 (let (($x5157 (and $x5156 $x3812)))
 (let ((?x5099 (ite root_83 1 0)))
 (let ((?x5081 (ite root_81 1 0)))
 (let ((?x5066 (ite root_79 1 0)))
 (let ((?x5051 (ite root_77 1 0)))
 (let ((?x5033 (ite root_75 1 0)))
 (let ((?x5018 (ite root_73 1 0)))
 (let ((?x5019 (+ 0 ?x5018)))
 (let ((?x5034 (+ ?x5019 ?x5033)))
 (let ((?x5052 (+ ?x5034 ?x5051)))
 (let ((?x5067 (+ ?x5052 ?x5066)))
 (let ((?x5082 (+ ?x5067 ?x5081)))
 (let (($x5017 (or false root_73)))
 (let (($x5032 (or $x5017 root_75)))
 (let (($x5050 (or $x5032 root_77)))
 (let (($x5065 (or $x5050 root_79)))
 (let (($x5080 (or $x5065 root_81)))
 (let (($x5105 (or false (and $x3429 (< rank_80 rank_82)))))
 (let (($x5109 (not root_83)))
 (let (($x5110 (and $x3458 $x5109)))
 (let (($x5087 (or false (and $x3458 (< rank_82 rank_80)))))
 (let (($x5090 (or $x5087 (and $x3400 (< rank_78 rank_80)))))
 (let (($x5094 (not root_81)))
 (let (($x5095 (and $x3429 $x5094)))
 (let (($x5072 (or false (and $x3429 (< rank_80 rank_78)))))
 (let (($x5076 (not root_79)))
 (let (($x5077 (and $x3400 $x5076)))
 (let (($x5057 (or false (and $x3458 (< rank_82 rank_76)))))
 (let (($x5061 (not root_77)))
 (let (($x5062 (and $x3371 $x5061)))
 (let (($x5039 (or false (and $x3371 (< rank_76 rank_74)))))
 (let (($x5042 (or $x5039 (and $x3429 (< rank_80 rank_74)))))
 (let (($x5046 (not root_75)))
 (let (($x5047 (and $x3342 $x5046)))
 (let (($x5024 (or false (and $x3342 (< rank_74 rank_72)))))
 (let (($x5028 (not root_73)))
 (let (($x5029 (and $x3313 $x5028)))
 (let (($x5021 (and true (=> root_73 $x3313))))
 (let (($x5031 (and $x5021 (=> $x5029 (or $x5024 (and $x3400 (< rank_78 rank_72)))))))
 (let (($x5036 (and $x5031 (=> root_75 $x3342))))
 (let (($x5049 (and $x5036 (=> $x5047 (or $x5042 (and $x3313 (< rank_72 rank_74)))))))
 (let (($x5054 (and $x5049 (=> root_77 $x3371))))
 (let (($x5064 (and $x5054 (=> $x5062 (or $x5057 (and $x3342 (< rank_74 rank_76)))))))
 (let (($x5069 (and $x5064 (=> root_79 $x3400))))
 (let (($x5079 (and $x5069 (=> $x5077 (or $x5072 (and $x3313 (< rank_72 rank_78)))))))
 (let (($x5084 (and $x5079 (=> root_81 $x3429))))
 (let (($x5097 (and $x5084 (=> $x5095 (or $x5090 (and $x3342 (< rank_74 rank_80)))))))
 (let (($x5102 (and $x5097 (=> root_83 $x3458))))
 (let (($x5114 (and (and $x5102 (=> $x5110 (or $x5105 (and $x3371 (< rank_76 rank_82))))) (=> $x3563 (or $x5080 root_83)))))
 (let (($x5116 (and $x5114 (<= (+ ?x5082 ?x5099) 1))))
 (let (($x5117 (and true $x5116)))
 (let (($x5302 (= rule_instance 42)))
 (let (($x5295 (and $x5302 (and (and (and $x5117 $x3602) (and $x5157 $x3845)) (and $x5290 $x4162)))))
 (let ((?x4961 (ite root_71 1 0)))
 (let ((?x4943 (ite root_69 1 0)))
 (let ((?x4928 (ite root_67 1 0)))
 (let ((?x4913 (ite root_65 1 0)))
 (let ((?x4895 (ite root_63 1 0)))
 (let ((?x4880 (ite root_61 1 0)))
 (let ((?x4881 (+ 0 ?x4880)))
 (let ((?x4896 (+ ?x4881 ?x4895)))
 (let ((?x4914 (+ ?x4896 ?x4913)))
 (let ((?x4929 (+ ?x4914 ?x4928)))
 (let ((?x4944 (+ ?x4929 ?x4943)))
 (let (($x4879 (or false root_61)))
 (let (($x4894 (or $x4879 root_63)))
 (let (($x4912 (or $x4894 root_65)))
 (let (($x4927 (or $x4912 root_67)))
 (let (($x4942 (or $x4927 root_69)))
 (let (($x4967 (or false (and $x4007 (< rank_68 rank_70)))))
 (let (($x4971 (not root_71)))
 (let (($x4972 (and $x4036 $x4971)))
 (let (($x4949 (or false (and $x4036 (< rank_70 rank_68)))))
 (let (($x4952 (or $x4949 (and $x3978 (< rank_66 rank_68)))))
 (let (($x4956 (not root_69)))
 (let (($x4957 (and $x4007 $x4956)))
 (let (($x4934 (or false (and $x4007 (< rank_68 rank_66)))))
 (let (($x4938 (not root_67)))
 (let (($x4939 (and $x3978 $x4938)))
 (let (($x4919 (or false (and $x4036 (< rank_70 rank_64)))))
 (let (($x4923 (not root_65)))
 (let (($x4924 (and $x3949 $x4923)))
 (let (($x4901 (or false (and $x3949 (< rank_64 rank_62)))))
 (let (($x4904 (or $x4901 (and $x4007 (< rank_68 rank_62)))))
 (let (($x4908 (not root_63)))
 (let (($x4909 (and $x3920 $x4908)))
 (let (($x4886 (or false (and $x3920 (< rank_62 rank_60)))))
 (let (($x4890 (not root_61)))
 (let (($x4891 (and $x3891 $x4890)))
 (let (($x4883 (and true (=> root_61 $x3891))))
 (let (($x4893 (and $x4883 (=> $x4891 (or $x4886 (and $x3978 (< rank_66 rank_60)))))))
 (let (($x4898 (and $x4893 (=> root_63 $x3920))))
 (let (($x4911 (and $x4898 (=> $x4909 (or $x4904 (and $x3891 (< rank_60 rank_62)))))))
 (let (($x4916 (and $x4911 (=> root_65 $x3949))))
 (let (($x4926 (and $x4916 (=> $x4924 (or $x4919 (and $x3920 (< rank_62 rank_64)))))))
 (let (($x4931 (and $x4926 (=> root_67 $x3978))))
 (let (($x4941 (and $x4931 (=> $x4939 (or $x4934 (and $x3891 (< rank_60 rank_66)))))))
 (let (($x4946 (and $x4941 (=> root_69 $x4007))))
 (let (($x4959 (and $x4946 (=> $x4957 (or $x4952 (and $x3920 (< rank_62 rank_68)))))))
 (let (($x4964 (and $x4959 (=> root_71 $x4036))))
 (let (($x4976 (and (and $x4964 (=> $x4972 (or $x4967 (and $x3949 (< rank_64 rank_70))))) (=> $x4138 (or $x4942 root_71)))))
 (let (($x4978 (and $x4976 (<= (+ ?x4944 ?x4961) 1))))
 (let (($x4979 (and true $x4978)))
 (let (($x4812 (and true (=> c_1_0 d_1_1))))
 (let (($x4814 (and $x4812 (=> c_1_1 d_1_1))))
 (let (($x4816 (and $x4814 (=> c_1_2 d_1_1))))
 (let (($x4818 (and $x4816 (=> c_1_3 d_1_1))))
 (let (($x4820 (and $x4818 (=> c_1_4 d_1_1))))
 (let (($x4822 (and $x4820 (=> c_1_5 d_1_1))))
 (let (($x4824 (and $x4822 (=> c_1_6 d_1_1))))
 (let (($x4826 (and $x4824 (=> c_1_7 d_1_1))))
 (let (($x4828 (and $x4826 (=> c_1_8 d_1_1))))
 (let (($x4830 (and $x4828 (=> c_1_9 d_1_1))))
 (let (($x4832 (and $x4830 (=> c_1_10 d_1_1))))
 (let (($x4834 (and $x4832 (=> c_1_11 d_1_1))))
 (let (($x4836 (and $x4834 (=> c_1_12 d_1_1))))
 (let (($x4838 (and $x4836 (=> c_1_13 d_1_1))))
 (let (($x4840 (and $x4838 (=> c_1_14 d_1_1))))
 (let (($x4784 (and $x4782 (=> c_0_2 d_0_1))))
 (let (($x4778 (and $x4784 (=> c_0_3 d_0_1))))
 (let (($x4787 (and $x4778 (=> c_0_4 d_0_1))))
 (let (($x4789 (and $x4787 (=> c_0_5 d_0_1))))
 (let (($x4791 (and $x4789 $x4790)))
 (let (($x4793 (and $x4791 (=> c_0_7 d_0_1))))
 (let (($x4795 (and $x4793 (=> c_0_8 d_0_1))))
 (let (($x4797 (and $x4795 (=> c_0_9 d_0_1))))
 (let (($x4799 (and $x4797 (=> c_0_10 d_0_1))))
 (let (($x4801 (and $x4799 $x4800)))
 (let (($x4803 (and $x4801 (=> c_0_12 d_0_1))))
 (let (($x4805 (and $x4803 (=> c_0_13 d_0_1))))
 (let (($x4807 (and $x4805 (=> c_0_14 d_0_1))))
 (let (($x4776 (and true c_0_7)))
 (let (($x4780 (and $x4776 c_1_14)))
 (let (($x4810 (and $x4780 (and $x4807 (=> c_0_15 d_0_1)))))
 (let (($x4843 (and $x4810 (and $x4840 (=> c_1_15 d_1_1)))))
 (let (($x4844 (and $x4843 $x3746)))
 (let (($x4845 (and $x4844 $x3779)))
 (let (($x4846 (and $x4845 $x3812)))
 (let ((?x4756 (ite root_59 1 0)))
 (let ((?x4738 (ite root_57 1 0)))
 (let ((?x4723 (ite root_55 1 0)))
 (let ((?x4708 (ite root_53 1 0)))
 (let ((?x4690 (ite root_51 1 0)))
 (let ((?x4675 (ite root_49 1 0)))
 (let ((?x4676 (+ 0 ?x4675)))
 (let ((?x4691 (+ ?x4676 ?x4690)))
 (let ((?x4709 (+ ?x4691 ?x4708)))
 (let ((?x4724 (+ ?x4709 ?x4723)))
 (let ((?x4739 (+ ?x4724 ?x4738)))
 (let (($x4674 (or false root_49)))
 (let (($x4689 (or $x4674 root_51)))
 (let (($x4707 (or $x4689 root_53)))
 (let (($x4722 (or $x4707 root_55)))
 (let (($x4737 (or $x4722 root_57)))
 (let (($x4762 (or false (and $x3429 (< rank_56 rank_58)))))
 (let (($x4766 (not root_59)))
 (let (($x4767 (and $x3458 $x4766)))
 (let (($x4744 (or false (and $x3458 (< rank_58 rank_56)))))
 (let (($x4747 (or $x4744 (and $x3400 (< rank_54 rank_56)))))
 (let (($x4751 (not root_57)))
 (let (($x4752 (and $x3429 $x4751)))
 (let (($x4729 (or false (and $x3429 (< rank_56 rank_54)))))
 (let (($x4733 (not root_55)))
 (let (($x4734 (and $x3400 $x4733)))
 (let (($x4714 (or false (and $x3458 (< rank_58 rank_52)))))
 (let (($x4718 (not root_53)))
 (let (($x4719 (and $x3371 $x4718)))
 (let (($x4696 (or false (and $x3371 (< rank_52 rank_50)))))
 (let (($x4699 (or $x4696 (and $x3429 (< rank_56 rank_50)))))
 (let (($x4703 (not root_51)))
 (let (($x4704 (and $x3342 $x4703)))
 (let (($x4681 (or false (and $x3342 (< rank_50 rank_48)))))
 (let (($x4685 (not root_49)))
 (let (($x4686 (and $x3313 $x4685)))
 (let (($x4678 (and true (=> root_49 $x3313))))
 (let (($x4688 (and $x4678 (=> $x4686 (or $x4681 (and $x3400 (< rank_54 rank_48)))))))
 (let (($x4693 (and $x4688 (=> root_51 $x3342))))
 (let (($x4706 (and $x4693 (=> $x4704 (or $x4699 (and $x3313 (< rank_48 rank_50)))))))
 (let (($x4711 (and $x4706 (=> root_53 $x3371))))
 (let (($x4721 (and $x4711 (=> $x4719 (or $x4714 (and $x3342 (< rank_50 rank_52)))))))
 (let (($x4726 (and $x4721 (=> root_55 $x3400))))
 (let (($x4736 (and $x4726 (=> $x4734 (or $x4729 (and $x3313 (< rank_48 rank_54)))))))
 (let (($x4741 (and $x4736 (=> root_57 $x3429))))
 (let (($x4754 (and $x4741 (=> $x4752 (or $x4747 (and $x3342 (< rank_50 rank_56)))))))
 (let (($x4759 (and $x4754 (=> root_59 $x3458))))
 (let (($x4771 (and (and $x4759 (=> $x4767 (or $x4762 (and $x3371 (< rank_52 rank_58))))) (=> $x3563 (or $x4737 root_59)))))
 (let (($x4773 (and $x4771 (<= (+ ?x4739 ?x4756) 1))))
 (let (($x4774 (and true $x4773)))
 (let (($x4991 (= rule_instance 28)))
 (let (($x4984 (and $x4991 (and (and (and $x4774 $x3602) (and $x4846 $x3845)) (and $x4979 $x4162)))))
 (let ((?x4618 (ite root_47 1 0)))
 (let ((?x4600 (ite root_45 1 0)))
 (let ((?x4585 (ite root_43 1 0)))
 (let ((?x4570 (ite root_41 1 0)))
 (let ((?x4552 (ite root_39 1 0)))
 (let ((?x4537 (ite root_37 1 0)))
 (let ((?x4538 (+ 0 ?x4537)))
 (let ((?x4553 (+ ?x4538 ?x4552)))
 (let ((?x4571 (+ ?x4553 ?x4570)))
 (let ((?x4586 (+ ?x4571 ?x4585)))
 (let ((?x4601 (+ ?x4586 ?x4600)))
 (let (($x4536 (or false root_37)))
 (let (($x4551 (or $x4536 root_39)))
 (let (($x4569 (or $x4551 root_41)))
 (let (($x4584 (or $x4569 root_43)))
 (let (($x4599 (or $x4584 root_45)))
 (let (($x4624 (or false (and $x4007 (< rank_44 rank_46)))))
 (let (($x4628 (not root_47)))
 (let (($x4629 (and $x4036 $x4628)))
 (let (($x4606 (or false (and $x4036 (< rank_46 rank_44)))))
 (let (($x4609 (or $x4606 (and $x3978 (< rank_42 rank_44)))))
 (let (($x4613 (not root_45)))
 (let (($x4614 (and $x4007 $x4613)))
 (let (($x4591 (or false (and $x4007 (< rank_44 rank_42)))))
 (let (($x4595 (not root_43)))
 (let (($x4596 (and $x3978 $x4595)))
 (let (($x4576 (or false (and $x4036 (< rank_46 rank_40)))))
 (let (($x4580 (not root_41)))
 (let (($x4581 (and $x3949 $x4580)))
 (let (($x4558 (or false (and $x3949 (< rank_40 rank_38)))))
 (let (($x4561 (or $x4558 (and $x4007 (< rank_44 rank_38)))))
 (let (($x4565 (not root_39)))
 (let (($x4566 (and $x3920 $x4565)))
 (let (($x4543 (or false (and $x3920 (< rank_38 rank_36)))))
 (let (($x4547 (not root_37)))
 (let (($x4548 (and $x3891 $x4547)))
 (let (($x4540 (and true (=> root_37 $x3891))))
 (let (($x4550 (and $x4540 (=> $x4548 (or $x4543 (and $x3978 (< rank_42 rank_36)))))))
 (let (($x4555 (and $x4550 (=> root_39 $x3920))))
 (let (($x4568 (and $x4555 (=> $x4566 (or $x4561 (and $x3891 (< rank_36 rank_38)))))))
 (let (($x4573 (and $x4568 (=> root_41 $x3949))))
 (let (($x4583 (and $x4573 (=> $x4581 (or $x4576 (and $x3920 (< rank_38 rank_40)))))))
 (let (($x4588 (and $x4583 (=> root_43 $x3978))))
 (let (($x4598 (and $x4588 (=> $x4596 (or $x4591 (and $x3891 (< rank_36 rank_42)))))))
 (let (($x4603 (and $x4598 (=> root_45 $x4007))))
 (let (($x4616 (and $x4603 (=> $x4614 (or $x4609 (and $x3920 (< rank_38 rank_44)))))))
 (let (($x4621 (and $x4616 (=> root_47 $x4036))))
 (let (($x4633 (and (and $x4621 (=> $x4629 (or $x4624 (and $x3949 (< rank_40 rank_46))))) (=> $x4138 (or $x4599 root_47)))))
 (let (($x4635 (and $x4633 (<= (+ ?x4601 ?x4618) 1))))
 (let (($x4636 (and true $x4635)))
 (let (($x4469 (and true (=> c_1_0 d_1_0))))
 (let (($x4471 (and $x4469 (=> c_1_1 d_1_0))))
 (let (($x4473 (and $x4471 (=> c_1_2 d_1_0))))
 (let (($x4475 (and $x4473 (=> c_1_3 d_1_0))))
 (let (($x4477 (and $x4475 (=> c_1_4 d_1_0))))
 (let (($x4479 (and $x4477 (=> c_1_5 d_1_0))))
 (let (($x4481 (and $x4479 (=> c_1_6 d_1_0))))
 (let (($x4483 (and $x4481 (=> c_1_7 d_1_0))))
 (let (($x4485 (and $x4483 (=> c_1_8 d_1_0))))
 (let (($x4487 (and $x4485 (=> c_1_9 d_1_0))))
 (let (($x4489 (and $x4487 (=> c_1_10 d_1_0))))
 (let (($x4491 (and $x4489 (=> c_1_11 d_1_0))))
 (let (($x4493 (and $x4491 (=> c_1_12 d_1_0))))
 (let (($x4495 (and $x4493 (=> c_1_13 d_1_0))))
 (let (($x4497 (and $x4495 (=> c_1_14 d_1_0))))
 (let (($x4436 (and true (=> c_0_0 d_0_6))))
 (let (($x4439 (and $x4436 (=> c_0_1 d_0_6))))
 (let (($x4441 (and $x4439 (=> c_0_2 d_0_6))))
 (let (($x4435 (and $x4441 (=> c_0_3 d_0_6))))
 (let (($x4444 (and $x4435 (=> c_0_4 d_0_6))))
 (let (($x4446 (and $x4444 (=> c_0_5 d_0_6))))
 (let (($x4448 (and $x4446 (=> c_0_6 d_0_6))))
 (let (($x4450 (and $x4448 (=> c_0_7 d_0_6))))
 (let (($x4452 (and $x4450 (=> c_0_8 d_0_6))))
 (let (($x4454 (and $x4452 (=> c_0_9 d_0_6))))
 (let (($x4456 (and $x4454 (=> c_0_10 d_0_6))))
 (let (($x4458 (and $x4456 (=> c_0_11 d_0_6))))
 (let (($x4460 (and $x4458 (=> c_0_12 d_0_6))))
 (let (($x4462 (and $x4460 (=> c_0_13 d_0_6))))
 (let (($x4464 (and $x4462 (=> c_0_14 d_0_6))))
 (let (($x4433 (and true c_0_2)))
 (let (($x4437 (and $x4433 c_1_14)))
 (let (($x4467 (and $x4437 (and $x4464 (=> c_0_15 d_0_6)))))
 (let (($x4500 (and $x4467 (and $x4497 (=> c_1_15 d_1_0)))))
 (let (($x4501 (and $x4500 $x3746)))
 (let (($x4502 (and $x4501 $x3779)))
 (let (($x4503 (and $x4502 $x3812)))
 (let ((?x4413 (ite root_35 1 0)))
 (let ((?x4395 (ite root_33 1 0)))
 (let ((?x4380 (ite root_31 1 0)))
 (let ((?x4365 (ite root_29 1 0)))
 (let ((?x4347 (ite root_27 1 0)))
 (let ((?x4332 (ite root_25 1 0)))
 (let ((?x4333 (+ 0 ?x4332)))
 (let ((?x4348 (+ ?x4333 ?x4347)))
 (let ((?x4366 (+ ?x4348 ?x4365)))
 (let ((?x4381 (+ ?x4366 ?x4380)))
 (let ((?x4396 (+ ?x4381 ?x4395)))
 (let (($x4331 (or false root_25)))
 (let (($x4346 (or $x4331 root_27)))
 (let (($x4364 (or $x4346 root_29)))
 (let (($x4379 (or $x4364 root_31)))
 (let (($x4394 (or $x4379 root_33)))
 (let (($x4419 (or false (and $x3429 (< rank_32 rank_34)))))
 (let (($x4423 (not root_35)))
 (let (($x4424 (and $x3458 $x4423)))
 (let (($x4401 (or false (and $x3458 (< rank_34 rank_32)))))
 (let (($x4404 (or $x4401 (and $x3400 (< rank_30 rank_32)))))
 (let (($x4408 (not root_33)))
 (let (($x4409 (and $x3429 $x4408)))
 (let (($x4386 (or false (and $x3429 (< rank_32 rank_30)))))
 (let (($x4390 (not root_31)))
 (let (($x4391 (and $x3400 $x4390)))
 (let (($x4371 (or false (and $x3458 (< rank_34 rank_28)))))
 (let (($x4375 (not root_29)))
 (let (($x4376 (and $x3371 $x4375)))
 (let (($x4353 (or false (and $x3371 (< rank_28 rank_26)))))
 (let (($x4356 (or $x4353 (and $x3429 (< rank_32 rank_26)))))
 (let (($x4360 (not root_27)))
 (let (($x4361 (and $x3342 $x4360)))
 (let (($x4338 (or false (and $x3342 (< rank_26 rank_24)))))
 (let (($x4342 (not root_25)))
 (let (($x4343 (and $x3313 $x4342)))
 (let (($x4335 (and true (=> root_25 $x3313))))
 (let (($x4345 (and $x4335 (=> $x4343 (or $x4338 (and $x3400 (< rank_30 rank_24)))))))
 (let (($x4350 (and $x4345 (=> root_27 $x3342))))
 (let (($x4363 (and $x4350 (=> $x4361 (or $x4356 (and $x3313 (< rank_24 rank_26)))))))
 (let (($x4368 (and $x4363 (=> root_29 $x3371))))
 (let (($x4378 (and $x4368 (=> $x4376 (or $x4371 (and $x3342 (< rank_26 rank_28)))))))
 (let (($x4383 (and $x4378 (=> root_31 $x3400))))
 (let (($x4393 (and $x4383 (=> $x4391 (or $x4386 (and $x3313 (< rank_24 rank_30)))))))
 (let (($x4398 (and $x4393 (=> root_33 $x3429))))
 (let (($x4411 (and $x4398 (=> $x4409 (or $x4404 (and $x3342 (< rank_26 rank_32)))))))
 (let (($x4416 (and $x4411 (=> root_35 $x3458))))
 (let (($x4428 (and (and $x4416 (=> $x4424 (or $x4419 (and $x3371 (< rank_28 rank_34))))) (=> $x3563 (or $x4394 root_35)))))
 (let (($x4430 (and $x4428 (<= (+ ?x4396 ?x4413) 1))))
 (let (($x4431 (and true $x4430)))
 (let (($x4648 (= rule_instance 14)))
 (let (($x4641 (and $x4648 (and (and (and $x4431 $x3602) (and $x4503 $x3845)) (and $x4636 $x4162)))))
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
 (let (($x4296 (= rule_instance 0)))
 (let (($x4297 (and $x4296 (and (and (and $x3583 $x3602) (and $x3813 $x3845)) (and $x4158 $x4162)))))
 (let (($x4300 (or false (and $x4297 $x4298))))
 (let (($x4643 (or $x4300 (and $x4641 $x4298))))
 (let (($x4986 (or $x4643 (and $x4984 $x4298))))
 (let (($x5297 (or $x4986 (and $x5295 $x4298))))
 (or $x5297 (and $x5635 $x4298))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
