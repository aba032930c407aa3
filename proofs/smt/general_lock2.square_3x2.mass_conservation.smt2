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
 (let (($x3371 (>= rank_0 0)))
 (and $x3371 (< rank_0 6))))
(assert
 (let (($x3367 (>= rank_2 0)))
 (and $x3367 (< rank_2 6))))
(assert
 (let (($x3374 (>= rank_4 0)))
 (and $x3374 (< rank_4 6))))
(assert
 (let (($x3379 (>= rank_6 0)))
 (and $x3379 (< rank_6 6))))
(assert
 (let (($x3384 (>= rank_8 0)))
 (and $x3384 (< rank_8 6))))
(assert
 (let (($x3389 (>= rank_10 0)))
 (and $x3389 (< rank_10 6))))
(assert
 (let (($x3813 (>= rank_12 0)))
 (and $x3813 (< rank_12 6))))
(assert
 (let (($x3809 (>= rank_14 0)))
 (and $x3809 (< rank_14 6))))
(assert
 (let (($x3816 (>= rank_16 0)))
 (and $x3816 (< rank_16 6))))
(assert
 (let (($x3824 (>= rank_18 0)))
 (and $x3824 (< rank_18 6))))
(assert
 (let (($x3829 (>= rank_20 0)))
 (and $x3829 (< rank_20 6))))
(assert
 (let (($x3834 (>= rank_22 0)))
 (and $x3834 (< rank_22 6))))
(assert
 (let (($x4105 (>= rank_24 0)))
 (and $x4105 (< rank_24 6))))
(assert
 (let (($x4100 (>= rank_26 0)))
 (and $x4100 (< rank_26 6))))
(assert
 (let (($x4108 (>= rank_28 0)))
 (and $x4108 (< rank_28 6))))
(assert
 (let (($x4112 (>= rank_30 0)))
 (and $x4112 (< rank_30 6))))
(assert
 (let (($x4117 (>= rank_32 0)))
 (and $x4117 (< rank_32 6))))
(assert
 (let (($x4122 (>= rank_34 0)))
 (and $x4122 (< rank_34 6))))
(assert
 (let (($x4303 (>= rank_36 0)))
 (and $x4303 (< rank_36 6))))
(assert
 (let (($x4305 (>= rank_38 0)))
 (and $x4305 (< rank_38 6))))
(assert
 (let (($x4309 (>= rank_40 0)))
 (and $x4309 (< rank_40 6))))
(assert
 (let (($x4317 (>= rank_42 0)))
 (and $x4317 (< rank_42 6))))
(assert
 (let (($x4322 (>= rank_44 0)))
 (and $x4322 (< rank_44 6))))
(assert
 (let (($x4327 (>= rank_46 0)))
 (and $x4327 (< rank_46 6))))
(assert
 (let (($x4448 (>= rank_48 0)))
 (and $x4448 (< rank_48 6))))
(assert
 (let (($x4440 (>= rank_50 0)))
 (and $x4440 (< rank_50 6))))
(assert
 (let (($x4451 (>= rank_52 0)))
 (and $x4451 (< rank_52 6))))
(assert
 (let (($x4455 (>= rank_54 0)))
 (and $x4455 (< rank_54 6))))
(assert
 (let (($x4460 (>= rank_56 0)))
 (and $x4460 (< rank_56 6))))
(assert
 (let (($x4465 (>= rank_58 0)))
 (and $x4465 (< rank_58 6))))
(assert
 (let (($x4646 (>= rank_60 0)))
 (and $x4646 (< rank_60 6))))
(assert
 (let (($x4648 (>= rank_62 0)))
 (and $x4648 (< rank_62 6))))
(assert
 (let (($x4652 (>= rank_64 0)))
 (and $x4652 (< rank_64 6))))
(assert
 (let (($x4660 (>= rank_66 0)))
 (and $x4660 (< rank_66 6))))
(assert
 (let (($x4665 (>= rank_68 0)))
 (and $x4665 (< rank_68 6))))
(assert
 (let (($x4670 (>= rank_70 0)))
 (and $x4670 (< rank_70 6))))
(assert
 (let (($x4791 (>= rank_72 0)))
 (and $x4791 (< rank_72 6))))
(assert
 (let (($x4783 (>= rank_74 0)))
 (and $x4783 (< rank_74 6))))
(assert
 (let (($x4794 (>= rank_76 0)))
 (and $x4794 (< rank_76 6))))
(assert
 (let (($x4798 (>= rank_78 0)))
 (and $x4798 (< rank_78 6))))
(assert
 (let (($x4803 (>= rank_80 0)))
 (and $x4803 (< rank_80 6))))
(assert
 (let (($x4808 (>= rank_82 0)))
 (and $x4808 (< rank_82 6))))
(assert
 (let (($x4957 (>= rank_84 0)))
 (and $x4957 (< rank_84 6))))
(assert
 (let (($x4959 (>= rank_86 0)))
 (and $x4959 (< rank_86 6))))
(assert
 (let (($x4963 (>= rank_88 0)))
 (and $x4963 (< rank_88 6))))
(assert
 (let (($x4971 (>= rank_90 0)))
 (and $x4971 (< rank_90 6))))
(assert
 (let (($x4976 (>= rank_92 0)))
 (and $x4976 (< rank_92 6))))
(assert
 (let (($x4981 (>= rank_94 0)))
 (and $x4981 (< rank_94 6))))
(assert
 (let (($x5102 (>= rank_96 0)))
 (and $x5102 (< rank_96 6))))
(assert
 (let (($x5094 (>= rank_98 0)))
 (and $x5094 (< rank_98 6))))
(assert
 (let (($x5105 (>= rank_100 0)))
 (and $x5105 (< rank_100 6))))
(assert
 (let (($x5109 (>= rank_102 0)))
 (and $x5109 (< rank_102 6))))
(assert
 (let (($x5114 (>= rank_104 0)))
 (and $x5114 (< rank_104 6))))
(assert
 (let (($x5119 (>= rank_106 0)))
 (and $x5119 (< rank_106 6))))
(assert
 (let (($x5297 (>= rank_108 0)))
 (and $x5297 (< rank_108 6))))
(assert
 (let (($x5299 (>= rank_110 0)))
 (and $x5299 (< rank_110 6))))
(assert
 (let (($x5303 (>= rank_112 0)))
 (and $x5303 (< rank_112 6))))
(assert
 (let (($x5311 (>= rank_114 0)))
 (and $x5311 (< rank_114 6))))
(assert
 (let (($x5316 (>= rank_116 0)))
 (and $x5316 (< rank_116 6))))
(assert
 (let (($x5321 (>= rank_118 0)))
 (and $x5321 (< rank_118 6))))
(assert
 (let ((?x4088 (ite d_1_15 1 0)))
 (let ((?x4084 (ite d_1_14 1 0)))
 (let ((?x4080 (ite d_1_13 1 0)))
 (let ((?x4076 (ite d_1_12 1 0)))
 (let ((?x4072 (ite d_1_11 1 0)))
 (let ((?x4068 (ite d_1_10 3 0)))
 (let ((?x4064 (ite d_1_9 3 0)))
 (let ((?x4060 (ite d_1_8 3 0)))
 (let ((?x4056 (ite d_1_7 3 0)))
 (let ((?x4052 (ite d_1_6 3 0)))
 (let ((?x4048 (ite d_1_5 2 0)))
 (let ((?x4044 (ite d_1_4 2 0)))
 (let ((?x4040 (ite d_1_3 2 0)))
 (let ((?x4036 (ite d_1_2 2 0)))
 (let ((?x4032 (ite d_1_1 2 0)))
 (let ((?x4024 (ite d_0_15 1 0)))
 (let ((?x4020 (ite d_0_14 1 0)))
 (let ((?x4016 (ite d_0_13 1 0)))
 (let ((?x4012 (ite d_0_12 1 0)))
 (let ((?x4008 (ite d_0_11 1 0)))
 (let ((?x4004 (ite d_0_10 3 0)))
 (let ((?x4000 (ite d_0_9 3 0)))
 (let ((?x3996 (ite d_0_8 3 0)))
 (let ((?x3992 (ite d_0_7 3 0)))
 (let ((?x3988 (ite d_0_6 3 0)))
 (let ((?x3983 (ite d_0_5 2 0)))
 (let ((?x3979 (ite d_0_4 2 0)))
 (let ((?x3975 (ite d_0_3 2 0)))
 (let ((?x3971 (ite d_0_2 2 0)))
 (let ((?x3952 (ite d_0_1 2 0)))
 (let ((?x3958 (+ 0 (ite d_0_0 0 0))))
 (let ((?x3968 (+ ?x3958 ?x3952)))
 (let ((?x3972 (+ ?x3968 ?x3971)))
 (let ((?x3976 (+ ?x3972 ?x3975)))
 (let ((?x3980 (+ ?x3976 ?x3979)))
 (let ((?x3984 (+ ?x3980 ?x3983)))
 (let ((?x3989 (+ ?x3984 ?x3988)))
 (let ((?x3993 (+ ?x3989 ?x3992)))
 (let ((?x3997 (+ ?x3993 ?x3996)))
 (let ((?x4001 (+ ?x3997 ?x4000)))
 (let ((?x4005 (+ ?x4001 ?x4004)))
 (let ((?x4009 (+ ?x4005 ?x4008)))
 (let ((?x4013 (+ ?x4009 ?x4012)))
 (let ((?x4017 (+ ?x4013 ?x4016)))
 (let ((?x4021 (+ ?x4017 ?x4020)))
 (let ((?x4025 (+ ?x4021 ?x4024)))
 (let ((?x4029 (+ ?x4025 (ite d_1_0 0 0))))
 (let ((?x4033 (+ ?x4029 ?x4032)))
 (let ((?x4037 (+ ?x4033 ?x4036)))
 (let ((?x4041 (+ ?x4037 ?x4040)))
 (let ((?x4045 (+ ?x4041 ?x4044)))
 (let ((?x4049 (+ ?x4045 ?x4048)))
 (let ((?x4053 (+ ?x4049 ?x4052)))
 (let ((?x4057 (+ ?x4053 ?x4056)))
 (let ((?x4061 (+ ?x4057 ?x4060)))
 (let ((?x4065 (+ ?x4061 ?x4064)))
 (let ((?x4069 (+ ?x4065 ?x4068)))
 (let ((?x4073 (+ ?x4069 ?x4072)))
 (let ((?x4077 (+ ?x4073 ?x4076)))
 (let ((?x4081 (+ ?x4077 ?x4080)))
 (let ((?x4085 (+ ?x4081 ?x4084)))
 (let ((?x4086 (ite c_1_15 1 0)))
 (let ((?x4082 (ite c_1_14 1 0)))
 (let ((?x4078 (ite c_1_13 1 0)))
 (let ((?x4074 (ite c_1_12 1 0)))
 (let ((?x4070 (ite c_1_11 1 0)))
 (let ((?x4066 (ite c_1_10 3 0)))
 (let ((?x4062 (ite c_1_9 3 0)))
 (let ((?x4058 (ite c_1_8 3 0)))
 (let ((?x4054 (ite c_1_7 3 0)))
 (let ((?x4050 (ite c_1_6 3 0)))
 (let ((?x4046 (ite c_1_5 2 0)))
 (let ((?x4042 (ite c_1_4 2 0)))
 (let ((?x4038 (ite c_1_3 2 0)))
 (let ((?x4034 (ite c_1_2 2 0)))
 (let ((?x4030 (ite c_1_1 2 0)))
 (let ((?x4022 (ite c_0_15 1 0)))
 (let ((?x4018 (ite c_0_14 1 0)))
 (let ((?x4014 (ite c_0_13 1 0)))
 (let ((?x4010 (ite c_0_12 1 0)))
 (let ((?x4006 (ite c_0_11 1 0)))
 (let ((?x4002 (ite c_0_10 3 0)))
 (let ((?x3998 (ite c_0_9 3 0)))
 (let ((?x3994 (ite c_0_8 3 0)))
 (let ((?x3990 (ite c_0_7 3 0)))
 (let ((?x3986 (ite c_0_6 3 0)))
 (let ((?x3981 (ite c_0_5 2 0)))
 (let ((?x3977 (ite c_0_4 2 0)))
 (let ((?x3973 (ite c_0_3 2 0)))
 (let ((?x3969 (ite c_0_2 2 0)))
 (let ((?x3966 (ite c_0_1 2 0)))
 (let ((?x3962 (+ 0 (ite c_0_0 0 0))))
 (let ((?x3955 (+ ?x3962 ?x3966)))
 (let ((?x3970 (+ ?x3955 ?x3969)))
 (let ((?x3974 (+ ?x3970 ?x3973)))
 (let ((?x3978 (+ ?x3974 ?x3977)))
 (let ((?x3982 (+ ?x3978 ?x3981)))
 (let ((?x3987 (+ ?x3982 ?x3986)))
 (let ((?x3991 (+ ?x3987 ?x3990)))
 (let ((?x3995 (+ ?x3991 ?x3994)))
 (let ((?x3999 (+ ?x3995 ?x3998)))
 (let ((?x4003 (+ ?x3999 ?x4002)))
 (let ((?x4007 (+ ?x4003 ?x4006)))
 (let ((?x4011 (+ ?x4007 ?x4010)))
 (let ((?x4015 (+ ?x4011 ?x4014)))
 (let ((?x4019 (+ ?x4015 ?x4018)))
 (let ((?x4023 (+ ?x4019 ?x4022)))
 (let ((?x4027 (+ ?x4023 (ite c_1_0 0 0))))
 (let ((?x4031 (+ ?x4027 ?x4030)))
 (let ((?x4035 (+ ?x4031 ?x4034)))
 (let ((?x4039 (+ ?x4035 ?x4038)))
 (let ((?x4043 (+ ?x4039 ?x4042)))
 (let ((?x4047 (+ ?x4043 ?x4046)))
 (let ((?x4051 (+ ?x4047 ?x4050)))
 (let ((?x4055 (+ ?x4051 ?x4054)))
 (let ((?x4059 (+ ?x4055 ?x4058)))
 (let ((?x4063 (+ ?x4059 ?x4062)))
 (let ((?x4067 (+ ?x4063 ?x4066)))
 (let ((?x4071 (+ ?x4067 ?x4070)))
 (let ((?x4075 (+ ?x4071 ?x4074)))
 (let ((?x4079 (+ ?x4075 ?x4078)))
 (let ((?x4083 (+ ?x4079 ?x4082)))
 (let (($x4092 (and (distinct (+ ?x4083 ?x4086) (+ ?x4085 ?x4088)) true)))
 (let (($x3820 (or d_5_1 d_5_2 d_5_3 d_5_4 d_5_5 d_5_6 d_5_7 d_5_8 d_5_9 d_5_10 d_5_11 d_5_12 d_5_13 d_5_14 d_5_15)))
 (let ((?x3950 (ite $x3820 1 0)))
 (let (($x3805 (or d_4_1 d_4_2 d_4_3 d_4_4 d_4_5 d_4_6 d_4_7 d_4_8 d_4_9 d_4_10 d_4_11 d_4_12 d_4_13 d_4_14 d_4_15)))
 (let ((?x3956 (ite $x3805 1 0)))
 (let (($x3790 (or d_3_1 d_3_2 d_3_3 d_3_4 d_3_5 d_3_6 d_3_7 d_3_8 d_3_9 d_3_10 d_3_11 d_3_12 d_3_13 d_3_14 d_3_15)))
 (let ((?x3957 (ite $x3790 1 0)))
 (let (($x3775 (or d_2_1 d_2_2 d_2_3 d_2_4 d_2_5 d_2_6 d_2_7 d_2_8 d_2_9 d_2_10 d_2_11 d_2_12 d_2_13 d_2_14 d_2_15)))
 (let ((?x3945 (ite $x3775 1 0)))
 (let (($x3760 (or d_1_1 d_1_2 d_1_3 d_1_4 d_1_5 d_1_6 d_1_7 d_1_8 d_1_9 d_1_10 d_1_11 d_1_12 d_1_13 d_1_14 d_1_15)))
 (let ((?x3946 (ite $x3760 1 0)))
 (let (($x3745 (or d_0_1 d_0_2 d_0_3 d_0_4 d_0_5 d_0_6 d_0_7 d_0_8 d_0_9 d_0_10 d_0_11 d_0_12 d_0_13 d_0_14 d_0_15)))
 (let ((?x3944 (ite $x3745 1 0)))
 (let ((?x3954 (+ 0 ?x3944)))
 (let ((?x3947 (+ ?x3954 ?x3946)))
 (let ((?x3961 (+ ?x3947 ?x3945)))
 (let ((?x3959 (+ ?x3961 ?x3957)))
 (let ((?x3949 (+ ?x3959 ?x3956)))
 (let (($x3965 (>= (to_real (+ ?x3949 ?x3950)) 1.0)))
 (let ((?x5406 (ite root_119 1 0)))
 (let ((?x5388 (ite root_117 1 0)))
 (let ((?x5373 (ite root_115 1 0)))
 (let ((?x5358 (ite root_113 1 0)))
 (let ((?x5340 (ite root_111 1 0)))
 (let ((?x5325 (ite root_109 1 0)))
 (let ((?x5326 (+ 0 ?x5325)))
 (let ((?x5341 (+ ?x5326 ?x5340)))
 (let ((?x5359 (+ ?x5341 ?x5358)))
 (let ((?x5374 (+ ?x5359 ?x5373)))
 (let ((?x5389 (+ ?x5374 ?x5388)))
 (let (($x5324 (or false root_109)))
 (let (($x5339 (or $x5324 root_111)))
 (let (($x5357 (or $x5339 root_113)))
 (let (($x5372 (or $x5357 root_115)))
 (let (($x5387 (or $x5372 root_117)))
 (let (($x3837 (or false $x3745)))
 (let (($x3853 (or $x3837 $x3760)))
 (let (($x3872 (or $x3853 $x3775)))
 (let (($x3888 (or $x3872 $x3790)))
 (let (($x3904 (or $x3888 $x3805)))
 (let (($x3923 (or $x3904 $x3820)))
 (let (($x5412 (or false (and $x3805 (< rank_116 rank_118)))))
 (let (($x5416 (not root_119)))
 (let (($x5417 (and $x3820 $x5416)))
 (let (($x5394 (or false (and $x3820 (< rank_118 rank_116)))))
 (let (($x5397 (or $x5394 (and $x3790 (< rank_114 rank_116)))))
 (let (($x5401 (not root_117)))
 (let (($x5402 (and $x3805 $x5401)))
 (let (($x5379 (or false (and $x3805 (< rank_116 rank_114)))))
 (let (($x5383 (not root_115)))
 (let (($x5384 (and $x3790 $x5383)))
 (let (($x5364 (or false (and $x3820 (< rank_118 rank_112)))))
 (let (($x5368 (not root_113)))
 (let (($x5369 (and $x3775 $x5368)))
 (let (($x5346 (or false (and $x3775 (< rank_112 rank_110)))))
 (let (($x5349 (or $x5346 (and $x3805 (< rank_116 rank_110)))))
 (let (($x5353 (not root_111)))
 (let (($x5354 (and $x3760 $x5353)))
 (let (($x5331 (or false (and $x3760 (< rank_110 rank_108)))))
 (let (($x5335 (not root_109)))
 (let (($x5336 (and $x3745 $x5335)))
 (let (($x5328 (and true (=> root_109 $x3745))))
 (let (($x5338 (and $x5328 (=> $x5336 (or $x5331 (and $x3790 (< rank_114 rank_108)))))))
 (let (($x5343 (and $x5338 (=> root_111 $x3760))))
 (let (($x5356 (and $x5343 (=> $x5354 (or $x5349 (and $x3745 (< rank_108 rank_110)))))))
 (let (($x5361 (and $x5356 (=> root_113 $x3775))))
 (let (($x5371 (and $x5361 (=> $x5369 (or $x5364 (and $x3760 (< rank_110 rank_112)))))))
 (let (($x5376 (and $x5371 (=> root_115 $x3790))))
 (let (($x5386 (and $x5376 (=> $x5384 (or $x5379 (and $x3745 (< rank_108 rank_114)))))))
 (let (($x5391 (and $x5386 (=> root_117 $x3805))))
 (let (($x5404 (and $x5391 (=> $x5402 (or $x5397 (and $x3760 (< rank_110 rank_116)))))))
 (let (($x5409 (and $x5404 (=> root_119 $x3820))))
 (let (($x5421 (and (and $x5409 (=> $x5417 (or $x5412 (and $x3775 (< rank_112 rank_118))))) (=> $x3923 (or $x5387 root_119)))))
 (let (($x5423 (and $x5421 (<= (+ ?x5389 ?x5406) 1))))
 (let (($x5424 (and true $x5423)))
 (let (($x3713 (= c_5_15 d_5_15)))
 (let (($x3711 (= c_5_14 d_5_14)))
 (let (($x3709 (= c_5_13 d_5_13)))
 (let (($x3707 (= c_5_12 d_5_12)))
 (let (($x3705 (= c_5_11 d_5_11)))
 (let (($x3703 (= c_5_10 d_5_10)))
 (let (($x3701 (= c_5_9 d_5_9)))
 (let (($x3699 (= c_5_8 d_5_8)))
 (let (($x3697 (= c_5_7 d_5_7)))
 (let (($x3695 (= c_5_6 d_5_6)))
 (let (($x3693 (= c_5_5 d_5_5)))
 (let (($x3691 (= c_5_4 d_5_4)))
 (let (($x3689 (= c_5_3 d_5_3)))
 (let (($x3687 (= c_5_2 d_5_2)))
 (let (($x3685 (= c_5_1 d_5_1)))
 (let (($x3683 (= c_5_0 d_5_0)))
 (let (($x3684 (and true $x3683)))
 (let (($x3686 (and $x3684 $x3685)))
 (let (($x3688 (and $x3686 $x3687)))
 (let (($x3690 (and $x3688 $x3689)))
 (let (($x3692 (and $x3690 $x3691)))
 (let (($x3694 (and $x3692 $x3693)))
 (let (($x3696 (and $x3694 $x3695)))
 (let (($x3698 (and $x3696 $x3697)))
 (let (($x3700 (and $x3698 $x3699)))
 (let (($x3702 (and $x3700 $x3701)))
 (let (($x3704 (and $x3702 $x3703)))
 (let (($x3706 (and $x3704 $x3705)))
 (let (($x3708 (and $x3706 $x3707)))
 (let (($x3710 (and $x3708 $x3709)))
 (let (($x3712 (and $x3710 $x3711)))
 (let (($x3714 (and $x3712 $x3713)))
 (let (($x3680 (= c_4_15 d_4_15)))
 (let (($x3678 (= c_4_14 d_4_14)))
 (let (($x3676 (= c_4_13 d_4_13)))
 (let (($x3674 (= c_4_12 d_4_12)))
 (let (($x3672 (= c_4_11 d_4_11)))
 (let (($x3670 (= c_4_10 d_4_10)))
 (let (($x3668 (= c_4_9 d_4_9)))
 (let (($x3666 (= c_4_8 d_4_8)))
 (let (($x3664 (= c_4_7 d_4_7)))
 (let (($x3662 (= c_4_6 d_4_6)))
 (let (($x3660 (= c_4_5 d_4_5)))
 (let (($x3658 (= c_4_4 d_4_4)))
 (let (($x3656 (= c_4_3 d_4_3)))
 (let (($x3654 (= c_4_2 d_4_2)))
 (let (($x3652 (= c_4_1 d_4_1)))
 (let (($x3650 (= c_4_0 d_4_0)))
 (let (($x3651 (and true $x3650)))
 (let (($x3653 (and $x3651 $x3652)))
 (let (($x3655 (and $x3653 $x3654)))
 (let (($x3657 (and $x3655 $x3656)))
 (let (($x3659 (and $x3657 $x3658)))
 (let (($x3661 (and $x3659 $x3660)))
 (let (($x3663 (and $x3661 $x3662)))
 (let (($x3665 (and $x3663 $x3664)))
 (let (($x3667 (and $x3665 $x3666)))
 (let (($x3669 (and $x3667 $x3668)))
 (let (($x3671 (and $x3669 $x3670)))
 (let (($x3673 (and $x3671 $x3672)))
 (let (($x3675 (and $x3673 $x3674)))
 (let (($x3677 (and $x3675 $x3676)))
 (let (($x3679 (and $x3677 $x3678)))
 (let (($x3681 (and $x3679 $x3680)))
 (let (($x3647 (= c_3_15 d_3_15)))
 (let (($x3645 (= c_3_14 d_3_14)))
 (let (($x3643 (= c_3_13 d_3_13)))
 (let (($x3641 (= c_3_12 d_3_12)))
 (let (($x3639 (= c_3_11 d_3_11)))
 (let (($x3637 (= c_3_10 d_3_10)))
 (let (($x3635 (= c_3_9 d_3_9)))
 (let (($x3633 (= c_3_8 d_3_8)))
 (let (($x3631 (= c_3_7 d_3_7)))
 (let (($x3629 (= c_3_6 d_3_6)))
 (let (($x3627 (= c_3_5 d_3_5)))
 (let (($x3625 (= c_3_4 d_3_4)))
 (let (($x3623 (= c_3_3 d_3_3)))
 (let (($x3621 (= c_3_2 d_3_2)))
 (let (($x3619 (= c_3_1 d_3_1)))
 (let (($x3617 (= c_3_0 d_3_0)))
 (let (($x3618 (and true $x3617)))
 (let (($x3620 (and $x3618 $x3619)))
 (let (($x3622 (and $x3620 $x3621)))
 (let (($x3624 (and $x3622 $x3623)))
 (let (($x3626 (and $x3624 $x3625)))
 (let (($x3628 (and $x3626 $x3627)))
 (let (($x3630 (and $x3628 $x3629)))
 (let (($x3632 (and $x3630 $x3631)))
 (let (($x3634 (and $x3632 $x3633)))
 (let (($x3636 (and $x3634 $x3635)))
 (let (($x3638 (and $x3636 $x3637)))
 (let (($x3640 (and $x3638 $x3639)))
 (let (($x3642 (and $x3640 $x3641)))
 (let (($x3644 (and $x3642 $x3643)))
 (let (($x3646 (and $x3644 $x3645)))
 (let (($x3648 (and $x3646 $x3647)))
 (let (($x3614 (= c_2_15 d_2_15)))
 (let (($x3612 (= c_2_14 d_2_14)))
 (let (($x3610 (= c_2_13 d_2_13)))
 (let (($x3608 (= c_2_12 d_2_12)))
 (let (($x3606 (= c_2_11 d_2_11)))
 (let (($x3604 (= c_2_10 d_2_10)))
 (let (($x3602 (= c_2_9 d_2_9)))
 (let (($x3600 (= c_2_8 d_2_8)))
 (let (($x3598 (= c_2_7 d_2_7)))
 (let (($x3596 (= c_2_6 d_2_6)))
 (let (($x3594 (= c_2_5 d_2_5)))
 (let (($x3592 (= c_2_4 d_2_4)))
 (let (($x3590 (= c_2_3 d_2_3)))
 (let (($x3588 (= c_2_2 d_2_2)))
 (let (($x3586 (= c_2_1 d_2_1)))
 (let (($x3584 (= c_2_0 d_2_0)))
 (let (($x3585 (and true $x3584)))
 (let (($x3587 (and $x3585 $x3586)))
 (let (($x3589 (and $x3587 $x3588)))
 (let (($x3591 (and $x3589 $x3590)))
 (let (($x3593 (and $x3591 $x3592)))
 (let (($x3595 (and $x3593 $x3594)))
 (let (($x3597 (and $x3595 $x3596)))
 (let (($x3599 (and $x3597 $x3598)))
 (let (($x3601 (and $x3599 $x3600)))
 (let (($x3603 (and $x3601 $x3602)))
 (let (($x3605 (and $x3603 $x3604)))
 (let (($x3607 (and $x3605 $x3606)))
 (let (($x3609 (and $x3607 $x3608)))
 (let (($x3611 (and $x3609 $x3610)))
 (let (($x3613 (and $x3611 $x3612)))
 (let (($x3615 (and $x3613 $x3614)))
 (let (($x5257 (and true (=> c_1_0 d_1_6))))
 (let (($x5259 (and $x5257 (=> c_1_1 d_1_6))))
 (let (($x5261 (and $x5259 (=> c_1_2 d_1_7))))
 (let (($x5263 (and $x5261 (=> c_1_3 d_1_8))))
 (let (($x5265 (and $x5263 (=> c_1_4 d_1_9))))
 (let (($x5267 (and $x5265 (=> c_1_5 d_1_10))))
 (let (($x5269 (and $x5267 (=> c_1_6 d_1_6))))
 (let (($x5271 (and $x5269 (=> c_1_7 d_1_7))))
 (let (($x5273 (and $x5271 (=> c_1_8 d_1_8))))
 (let (($x5275 (and $x5273 (=> c_1_9 d_1_9))))
 (let (($x5277 (and $x5275 (=> c_1_10 d_1_10))))
 (let (($x5279 (and $x5277 (=> c_1_11 d_1_6))))
 (let (($x5281 (and $x5279 (=> c_1_12 d_1_7))))
 (let (($x5283 (and $x5281 (=> c_1_13 d_1_8))))
 (let (($x5285 (and $x5283 (=> c_1_14 d_1_9))))
 (let (($x3542 (=> c_0_12 d_0_2)))
 (let (($x4594 (=> c_0_11 d_0_1)))
 (let (($x3532 (=> c_0_7 d_0_2)))
 (let (($x4584 (=> c_0_6 d_0_1)))
 (let (($x3519 (=> c_0_2 d_0_2)))
 (let (($x4575 (and true (=> c_0_0 d_0_1))))
 (let (($x4571 (and $x4575 (=> c_0_1 d_0_1))))
 (let (($x5231 (and $x4571 $x3519)))
 (let (($x5234 (and $x5231 (=> c_0_3 d_0_3))))
 (let (($x5224 (and $x5234 (=> c_0_4 d_0_4))))
 (let (($x5238 (and $x5224 (=> c_0_5 d_0_5))))
 (let (($x5239 (and $x5238 $x4584)))
 (let (($x5240 (and $x5239 $x3532)))
 (let (($x5242 (and $x5240 (=> c_0_8 d_0_3))))
 (let (($x5244 (and $x5242 (=> c_0_9 d_0_4))))
 (let (($x5246 (and $x5244 (=> c_0_10 d_0_5))))
 (let (($x5247 (and $x5246 $x4594)))
 (let (($x5248 (and $x5247 $x3542)))
 (let (($x5250 (and $x5248 (=> c_0_13 d_0_3))))
 (let (($x5252 (and $x5250 (=> c_0_14 d_0_4))))
 (let (($x5226 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x5235 (or c_0_6 c_0_7 c_0_8 c_0_9 c_0_10)))
 (let (($x5230 (and true $x5235)))
 (let (($x5225 (and $x5230 $x5226)))
 (let (($x5255 (and $x5225 (and $x5252 (=> c_0_15 d_0_5)))))
 (let (($x5288 (and $x5255 (and $x5285 (=> c_1_15 d_1_10)))))
 (let (($x5289 (and $x5288 $x3615)))
 (let (($x5290 (and $x5289 $x3648)))
 (let (($x5291 (and $x5290 $x3681)))
 (let (($x3373 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_13 c_5_14 c_5_15)))
 (let ((?x3516 (ite $x3373 1 0)))
 (let (($x3358 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_13 c_4_14 c_4_15)))
 (let ((?x3514 (ite $x3358 1 0)))
 (let (($x3343 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_13 c_3_14 c_3_15)))
 (let ((?x3518 (ite $x3343 1 0)))
 (let (($x3328 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_13 c_2_14 c_2_15)))
 (let ((?x3503 (ite $x3328 1 0)))
 (let (($x3313 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_13 c_1_14 c_1_15)))
 (let ((?x3511 (ite $x3313 1 0)))
 (let (($x3298 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_13 c_0_14 c_0_15)))
 (let ((?x3501 (ite $x3298 1 0)))
 (let ((?x3507 (+ 0 ?x3501)))
 (let ((?x3513 (+ ?x3507 ?x3511)))
 (let ((?x3509 (+ ?x3513 ?x3503)))
 (let ((?x3502 (+ ?x3509 ?x3518)))
 (let ((?x3510 (+ ?x3502 ?x3514)))
 (let (($x3523 (>= (to_real (+ ?x3510 ?x3516)) 1.0)))
 (let ((?x5204 (ite root_107 1 0)))
 (let ((?x5186 (ite root_105 1 0)))
 (let ((?x5171 (ite root_103 1 0)))
 (let ((?x5156 (ite root_101 1 0)))
 (let ((?x5138 (ite root_99 1 0)))
 (let ((?x5123 (ite root_97 1 0)))
 (let ((?x5124 (+ 0 ?x5123)))
 (let ((?x5139 (+ ?x5124 ?x5138)))
 (let ((?x5157 (+ ?x5139 ?x5156)))
 (let ((?x5172 (+ ?x5157 ?x5171)))
 (let ((?x5187 (+ ?x5172 ?x5186)))
 (let (($x5122 (or false root_97)))
 (let (($x5137 (or $x5122 root_99)))
 (let (($x5155 (or $x5137 root_101)))
 (let (($x5170 (or $x5155 root_103)))
 (let (($x5185 (or $x5170 root_105)))
 (let (($x3392 (or false $x3298)))
 (let (($x3409 (or $x3392 $x3313)))
 (let (($x3428 (or $x3409 $x3328)))
 (let (($x3444 (or $x3428 $x3343)))
 (let (($x3460 (or $x3444 $x3358)))
 (let (($x3479 (or $x3460 $x3373)))
 (let (($x5210 (or false (and $x3358 (< rank_104 rank_106)))))
 (let (($x5214 (not root_107)))
 (let (($x5215 (and $x3373 $x5214)))
 (let (($x5192 (or false (and $x3373 (< rank_106 rank_104)))))
 (let (($x5195 (or $x5192 (and $x3343 (< rank_102 rank_104)))))
 (let (($x5199 (not root_105)))
 (let (($x5200 (and $x3358 $x5199)))
 (let (($x5177 (or false (and $x3358 (< rank_104 rank_102)))))
 (let (($x5181 (not root_103)))
 (let (($x5182 (and $x3343 $x5181)))
 (let (($x5162 (or false (and $x3373 (< rank_106 rank_100)))))
 (let (($x5166 (not root_101)))
 (let (($x5167 (and $x3328 $x5166)))
 (let (($x5144 (or false (and $x3328 (< rank_100 rank_98)))))
 (let (($x5147 (or $x5144 (and $x3358 (< rank_104 rank_98)))))
 (let (($x5151 (not root_99)))
 (let (($x5152 (and $x3313 $x5151)))
 (let (($x5129 (or false (and $x3313 (< rank_98 rank_96)))))
 (let (($x5133 (not root_97)))
 (let (($x5134 (and $x3298 $x5133)))
 (let (($x5126 (and true (=> root_97 $x3298))))
 (let (($x5136 (and $x5126 (=> $x5134 (or $x5129 (and $x3343 (< rank_102 rank_96)))))))
 (let (($x5141 (and $x5136 (=> root_99 $x3313))))
 (let (($x5154 (and $x5141 (=> $x5152 (or $x5147 (and $x3298 (< rank_96 rank_98)))))))
 (let (($x5159 (and $x5154 (=> root_101 $x3328))))
 (let (($x5169 (and $x5159 (=> $x5167 (or $x5162 (and $x3313 (< rank_98 rank_100)))))))
 (let (($x5174 (and $x5169 (=> root_103 $x3343))))
 (let (($x5184 (and $x5174 (=> $x5182 (or $x5177 (and $x3298 (< rank_96 rank_102)))))))
 (let (($x5189 (and $x5184 (=> root_105 $x3358))))
 (let (($x5202 (and $x5189 (=> $x5200 (or $x5195 (and $x3313 (< rank_98 rank_104)))))))
 (let (($x5207 (and $x5202 (=> root_107 $x3373))))
 (let (($x5219 (and (and $x5207 (=> $x5215 (or $x5210 (and $x3328 (< rank_100 rank_106))))) (=> $x3479 (or $x5185 root_107)))))
 (let (($x5221 (and $x5219 (<= (+ ?x5187 ?x5204) 1))))
 (let (($x5222 (and true $x5221)))
 (let (($x5437 (= rule_instance 56)))
 (let (($x5436 (and $x5437 (and (and (and $x5222 $x3523) (and $x5291 $x3714)) (and $x5424 $x3965)))))
 (let ((?x5066 (ite root_95 1 0)))
 (let ((?x5048 (ite root_93 1 0)))
 (let ((?x5033 (ite root_91 1 0)))
 (let ((?x5018 (ite root_89 1 0)))
 (let ((?x5000 (ite root_87 1 0)))
 (let ((?x4985 (ite root_85 1 0)))
 (let ((?x4986 (+ 0 ?x4985)))
 (let ((?x5001 (+ ?x4986 ?x5000)))
 (let ((?x5019 (+ ?x5001 ?x5018)))
 (let ((?x5034 (+ ?x5019 ?x5033)))
 (let ((?x5049 (+ ?x5034 ?x5048)))
 (let (($x4984 (or false root_85)))
 (let (($x4999 (or $x4984 root_87)))
 (let (($x5017 (or $x4999 root_89)))
 (let (($x5032 (or $x5017 root_91)))
 (let (($x5047 (or $x5032 root_93)))
 (let (($x5072 (or false (and $x3805 (< rank_92 rank_94)))))
 (let (($x5076 (not root_95)))
 (let (($x5077 (and $x3820 $x5076)))
 (let (($x5054 (or false (and $x3820 (< rank_94 rank_92)))))
 (let (($x5057 (or $x5054 (and $x3790 (< rank_90 rank_92)))))
 (let (($x5061 (not root_93)))
 (let (($x5062 (and $x3805 $x5061)))
 (let (($x5039 (or false (and $x3805 (< rank_92 rank_90)))))
 (let (($x5043 (not root_91)))
 (let (($x5044 (and $x3790 $x5043)))
 (let (($x5024 (or false (and $x3820 (< rank_94 rank_88)))))
 (let (($x5028 (not root_89)))
 (let (($x5029 (and $x3775 $x5028)))
 (let (($x5006 (or false (and $x3775 (< rank_88 rank_86)))))
 (let (($x5009 (or $x5006 (and $x3805 (< rank_92 rank_86)))))
 (let (($x5013 (not root_87)))
 (let (($x5014 (and $x3760 $x5013)))
 (let (($x4991 (or false (and $x3760 (< rank_86 rank_84)))))
 (let (($x4995 (not root_85)))
 (let (($x4996 (and $x3745 $x4995)))
 (let (($x4988 (and true (=> root_85 $x3745))))
 (let (($x4998 (and $x4988 (=> $x4996 (or $x4991 (and $x3790 (< rank_90 rank_84)))))))
 (let (($x5003 (and $x4998 (=> root_87 $x3760))))
 (let (($x5016 (and $x5003 (=> $x5014 (or $x5009 (and $x3745 (< rank_84 rank_86)))))))
 (let (($x5021 (and $x5016 (=> root_89 $x3775))))
 (let (($x5031 (and $x5021 (=> $x5029 (or $x5024 (and $x3760 (< rank_86 rank_88)))))))
 (let (($x5036 (and $x5031 (=> root_91 $x3790))))
 (let (($x5046 (and $x5036 (=> $x5044 (or $x5039 (and $x3745 (< rank_84 rank_90)))))))
 (let (($x5051 (and $x5046 (=> root_93 $x3805))))
 (let (($x5064 (and $x5051 (=> $x5062 (or $x5057 (and $x3760 (< rank_86 rank_92)))))))
 (let (($x5069 (and $x5064 (=> root_95 $x3820))))
 (let (($x5081 (and (and $x5069 (=> $x5077 (or $x5072 (and $x3775 (< rank_88 rank_94))))) (=> $x3923 (or $x5047 root_95)))))
 (let (($x5083 (and $x5081 (<= (+ ?x5049 ?x5066) 1))))
 (let (($x5084 (and true $x5083)))
 (let (($x3552 (and true (=> c_1_0 d_1_14))))
 (let (($x3554 (and $x3552 (=> c_1_1 d_1_14))))
 (let (($x3556 (and $x3554 (=> c_1_2 d_1_14))))
 (let (($x3558 (and $x3556 (=> c_1_3 d_1_14))))
 (let (($x3560 (and $x3558 (=> c_1_4 d_1_14))))
 (let (($x3562 (and $x3560 (=> c_1_5 d_1_14))))
 (let (($x3564 (and $x3562 (=> c_1_6 d_1_14))))
 (let (($x3566 (and $x3564 (=> c_1_7 d_1_14))))
 (let (($x3568 (and $x3566 (=> c_1_8 d_1_14))))
 (let (($x3570 (and $x3568 (=> c_1_9 d_1_14))))
 (let (($x3572 (and $x3570 (=> c_1_10 d_1_14))))
 (let (($x3574 (and $x3572 (=> c_1_11 d_1_14))))
 (let (($x3576 (and $x3574 (=> c_1_12 d_1_14))))
 (let (($x3578 (and $x3576 (=> c_1_13 d_1_14))))
 (let (($x3580 (and $x3578 (=> c_1_14 d_1_14))))
 (let (($x3582 (and $x3580 (=> c_1_15 d_1_14))))
 (let (($x4918 (and true (=> c_0_0 d_0_7))))
 (let (($x4914 (and $x4918 (=> c_0_1 d_0_7))))
 (let (($x4920 (and $x4914 (=> c_0_2 d_0_7))))
 (let (($x4915 (and $x4920 (=> c_0_3 d_0_7))))
 (let (($x4925 (and $x4915 (=> c_0_4 d_0_7))))
 (let (($x4926 (and $x4925 (=> c_0_5 d_0_7))))
 (let (($x4928 (and $x4926 (=> c_0_6 d_0_7))))
 (let (($x4930 (and $x4928 (=> c_0_7 d_0_7))))
 (let (($x4932 (and $x4930 (=> c_0_8 d_0_7))))
 (let (($x4934 (and $x4932 (=> c_0_9 d_0_7))))
 (let (($x4936 (and $x4934 (=> c_0_10 d_0_7))))
 (let (($x4938 (and $x4936 (=> c_0_11 d_0_7))))
 (let (($x4940 (and $x4938 (=> c_0_12 d_0_7))))
 (let (($x4942 (and $x4940 (=> c_0_13 d_0_7))))
 (let (($x4944 (and $x4942 (=> c_0_14 d_0_7))))
 (let (($x4921 (and true c_0_1)))
 (let (($x4922 (and $x4921 c_1_1)))
 (let (($x4947 (and $x4922 (and $x4944 (=> c_0_15 d_0_7)))))
 (let (($x4948 (and $x4947 $x3582)))
 (let (($x4949 (and $x4948 $x3615)))
 (let (($x4950 (and $x4949 $x3648)))
 (let (($x4951 (and $x4950 $x3681)))
 (let ((?x4893 (ite root_83 1 0)))
 (let ((?x4875 (ite root_81 1 0)))
 (let ((?x4860 (ite root_79 1 0)))
 (let ((?x4845 (ite root_77 1 0)))
 (let ((?x4827 (ite root_75 1 0)))
 (let ((?x4812 (ite root_73 1 0)))
 (let ((?x4813 (+ 0 ?x4812)))
 (let ((?x4828 (+ ?x4813 ?x4827)))
 (let ((?x4846 (+ ?x4828 ?x4845)))
 (let ((?x4861 (+ ?x4846 ?x4860)))
 (let ((?x4876 (+ ?x4861 ?x4875)))
 (let (($x4811 (or false root_73)))
 (let (($x4826 (or $x4811 root_75)))
 (let (($x4844 (or $x4826 root_77)))
 (let (($x4859 (or $x4844 root_79)))
 (let (($x4874 (or $x4859 root_81)))
 (let (($x4899 (or false (and $x3358 (< rank_80 rank_82)))))
 (let (($x4903 (not root_83)))
 (let (($x4904 (and $x3373 $x4903)))
 (let (($x4881 (or false (and $x3373 (< rank_82 rank_80)))))
 (let (($x4884 (or $x4881 (and $x3343 (< rank_78 rank_80)))))
 (let (($x4888 (not root_81)))
 (let (($x4889 (and $x3358 $x4888)))
 (let (($x4866 (or false (and $x3358 (< rank_80 rank_78)))))
 (let (($x4870 (not root_79)))
 (let (($x4871 (and $x3343 $x4870)))
 (let (($x4851 (or false (and $x3373 (< rank_82 rank_76)))))
 (let (($x4855 (not root_77)))
 (let (($x4856 (and $x3328 $x4855)))
 (let (($x4833 (or false (and $x3328 (< rank_76 rank_74)))))
 (let (($x4836 (or $x4833 (and $x3358 (< rank_80 rank_74)))))
 (let (($x4840 (not root_75)))
 (let (($x4841 (and $x3313 $x4840)))
 (let (($x4818 (or false (and $x3313 (< rank_74 rank_72)))))
 (let (($x4822 (not root_73)))
 (let (($x4823 (and $x3298 $x4822)))
 (let (($x4815 (and true (=> root_73 $x3298))))
 (let (($x4825 (and $x4815 (=> $x4823 (or $x4818 (and $x3343 (< rank_78 rank_72)))))))
 (let (($x4830 (and $x4825 (=> root_75 $x3313))))
 (let (($x4843 (and $x4830 (=> $x4841 (or $x4836 (and $x3298 (< rank_72 rank_74)))))))
 (let (($x4848 (and $x4843 (=> root_77 $x3328))))
 (let (($x4858 (and $x4848 (=> $x4856 (or $x4851 (and $x3313 (< rank_74 rank_76)))))))
 (let (($x4863 (and $x4858 (=> root_79 $x3343))))
 (let (($x4873 (and $x4863 (=> $x4871 (or $x4866 (and $x3298 (< rank_72 rank_78)))))))
 (let (($x4878 (and $x4873 (=> root_81 $x3358))))
 (let (($x4891 (and $x4878 (=> $x4889 (or $x4884 (and $x3313 (< rank_74 rank_80)))))))
 (let (($x4896 (and $x4891 (=> root_83 $x3373))))
 (let (($x4908 (and (and $x4896 (=> $x4904 (or $x4899 (and $x3328 (< rank_76 rank_82))))) (=> $x3479 (or $x4874 root_83)))))
 (let (($x4910 (and $x4908 (<= (+ ?x4876 ?x4893) 1))))
 (let (($x4911 (and true $x4910)))
 (let (($x5097 (= rule_instance 42)))
 (let (($x5096 (and $x5097 (and (and (and $x4911 $x3523) (and $x4951 $x3714)) (and $x5084 $x3965)))))
 (let ((?x4755 (ite root_71 1 0)))
 (let ((?x4737 (ite root_69 1 0)))
 (let ((?x4722 (ite root_67 1 0)))
 (let ((?x4707 (ite root_65 1 0)))
 (let ((?x4689 (ite root_63 1 0)))
 (let ((?x4674 (ite root_61 1 0)))
 (let ((?x4675 (+ 0 ?x4674)))
 (let ((?x4690 (+ ?x4675 ?x4689)))
 (let ((?x4708 (+ ?x4690 ?x4707)))
 (let ((?x4723 (+ ?x4708 ?x4722)))
 (let ((?x4738 (+ ?x4723 ?x4737)))
 (let (($x4673 (or false root_61)))
 (let (($x4688 (or $x4673 root_63)))
 (let (($x4706 (or $x4688 root_65)))
 (let (($x4721 (or $x4706 root_67)))
 (let (($x4736 (or $x4721 root_69)))
 (let (($x4761 (or false (and $x3805 (< rank_68 rank_70)))))
 (let (($x4765 (not root_71)))
 (let (($x4766 (and $x3820 $x4765)))
 (let (($x4743 (or false (and $x3820 (< rank_70 rank_68)))))
 (let (($x4746 (or $x4743 (and $x3790 (< rank_66 rank_68)))))
 (let (($x4750 (not root_69)))
 (let (($x4751 (and $x3805 $x4750)))
 (let (($x4728 (or false (and $x3805 (< rank_68 rank_66)))))
 (let (($x4732 (not root_67)))
 (let (($x4733 (and $x3790 $x4732)))
 (let (($x4713 (or false (and $x3820 (< rank_70 rank_64)))))
 (let (($x4717 (not root_65)))
 (let (($x4718 (and $x3775 $x4717)))
 (let (($x4695 (or false (and $x3775 (< rank_64 rank_62)))))
 (let (($x4698 (or $x4695 (and $x3805 (< rank_68 rank_62)))))
 (let (($x4702 (not root_63)))
 (let (($x4703 (and $x3760 $x4702)))
 (let (($x4680 (or false (and $x3760 (< rank_62 rank_60)))))
 (let (($x4684 (not root_61)))
 (let (($x4685 (and $x3745 $x4684)))
 (let (($x4677 (and true (=> root_61 $x3745))))
 (let (($x4687 (and $x4677 (=> $x4685 (or $x4680 (and $x3790 (< rank_66 rank_60)))))))
 (let (($x4692 (and $x4687 (=> root_63 $x3760))))
 (let (($x4705 (and $x4692 (=> $x4703 (or $x4698 (and $x3745 (< rank_60 rank_62)))))))
 (let (($x4710 (and $x4705 (=> root_65 $x3775))))
 (let (($x4720 (and $x4710 (=> $x4718 (or $x4713 (and $x3760 (< rank_62 rank_64)))))))
 (let (($x4725 (and $x4720 (=> root_67 $x3790))))
 (let (($x4735 (and $x4725 (=> $x4733 (or $x4728 (and $x3745 (< rank_60 rank_66)))))))
 (let (($x4740 (and $x4735 (=> root_69 $x3805))))
 (let (($x4753 (and $x4740 (=> $x4751 (or $x4746 (and $x3760 (< rank_62 rank_68)))))))
 (let (($x4758 (and $x4753 (=> root_71 $x3820))))
 (let (($x4770 (and (and $x4758 (=> $x4766 (or $x4761 (and $x3775 (< rank_64 rank_70))))) (=> $x3923 (or $x4736 root_71)))))
 (let (($x4772 (and $x4770 (<= (+ ?x4738 ?x4755) 1))))
 (let (($x4773 (and true $x4772)))
 (let (($x4606 (and true (=> c_1_0 d_1_1))))
 (let (($x4608 (and $x4606 (=> c_1_1 d_1_1))))
 (let (($x4610 (and $x4608 (=> c_1_2 d_1_1))))
 (let (($x4612 (and $x4610 (=> c_1_3 d_1_1))))
 (let (($x4614 (and $x4612 (=> c_1_4 d_1_1))))
 (let (($x4616 (and $x4614 (=> c_1_5 d_1_1))))
 (let (($x4618 (and $x4616 (=> c_1_6 d_1_1))))
 (let (($x4620 (and $x4618 (=> c_1_7 d_1_1))))
 (let (($x4622 (and $x4620 (=> c_1_8 d_1_1))))
 (let (($x4624 (and $x4622 (=> c_1_9 d_1_1))))
 (let (($x4626 (and $x4624 (=> c_1_10 d_1_1))))
 (let (($x4628 (and $x4626 (=> c_1_11 d_1_1))))
 (let (($x4630 (and $x4628 (=> c_1_12 d_1_1))))
 (let (($x4632 (and $x4630 (=> c_1_13 d_1_1))))
 (let (($x4634 (and $x4632 (=> c_1_14 d_1_1))))
 (let (($x4577 (and $x4571 (=> c_0_2 d_0_1))))
 (let (($x4572 (and $x4577 (=> c_0_3 d_0_1))))
 (let (($x4582 (and $x4572 (=> c_0_4 d_0_1))))
 (let (($x4583 (and $x4582 (=> c_0_5 d_0_1))))
 (let (($x4585 (and $x4583 $x4584)))
 (let (($x4587 (and $x4585 (=> c_0_7 d_0_1))))
 (let (($x4589 (and $x4587 (=> c_0_8 d_0_1))))
 (let (($x4591 (and $x4589 (=> c_0_9 d_0_1))))
 (let (($x4593 (and $x4591 (=> c_0_10 d_0_1))))
 (let (($x4595 (and $x4593 $x4594)))
 (let (($x4597 (and $x4595 (=> c_0_12 d_0_1))))
 (let (($x4599 (and $x4597 (=> c_0_13 d_0_1))))
 (let (($x4601 (and $x4599 (=> c_0_14 d_0_1))))
 (let (($x4578 (and true c_0_7)))
 (let (($x4579 (and $x4578 c_1_14)))
 (let (($x4604 (and $x4579 (and $x4601 (=> c_0_15 d_0_1)))))
 (let (($x4637 (and $x4604 (and $x4634 (=> c_1_15 d_1_1)))))
 (let (($x4638 (and $x4637 $x3615)))
 (let (($x4639 (and $x4638 $x3648)))
 (let (($x4640 (and $x4639 $x3681)))
 (let ((?x4550 (ite root_59 1 0)))
 (let ((?x4532 (ite root_57 1 0)))
 (let ((?x4517 (ite root_55 1 0)))
 (let ((?x4502 (ite root_53 1 0)))
 (let ((?x4484 (ite root_51 1 0)))
 (let ((?x4469 (ite root_49 1 0)))
 (let ((?x4470 (+ 0 ?x4469)))
 (let ((?x4485 (+ ?x4470 ?x4484)))
 (let ((?x4503 (+ ?x4485 ?x4502)))
 (let ((?x4518 (+ ?x4503 ?x4517)))
 (let ((?x4533 (+ ?x4518 ?x4532)))
 (let (($x4468 (or false root_49)))
 (let (($x4483 (or $x4468 root_51)))
 (let (($x4501 (or $x4483 root_53)))
 (let (($x4516 (or $x4501 root_55)))
 (let (($x4531 (or $x4516 root_57)))
 (let (($x4556 (or false (and $x3358 (< rank_56 rank_58)))))
 (let (($x4560 (not root_59)))
 (let (($x4561 (and $x3373 $x4560)))
 (let (($x4538 (or false (and $x3373 (< rank_58 rank_56)))))
 (let (($x4541 (or $x4538 (and $x3343 (< rank_54 rank_56)))))
 (let (($x4545 (not root_57)))
 (let (($x4546 (and $x3358 $x4545)))
 (let (($x4523 (or false (and $x3358 (< rank_56 rank_54)))))
 (let (($x4527 (not root_55)))
 (let (($x4528 (and $x3343 $x4527)))
 (let (($x4508 (or false (and $x3373 (< rank_58 rank_52)))))
 (let (($x4512 (not root_53)))
 (let (($x4513 (and $x3328 $x4512)))
 (let (($x4490 (or false (and $x3328 (< rank_52 rank_50)))))
 (let (($x4493 (or $x4490 (and $x3358 (< rank_56 rank_50)))))
 (let (($x4497 (not root_51)))
 (let (($x4498 (and $x3313 $x4497)))
 (let (($x4475 (or false (and $x3313 (< rank_50 rank_48)))))
 (let (($x4479 (not root_49)))
 (let (($x4480 (and $x3298 $x4479)))
 (let (($x4472 (and true (=> root_49 $x3298))))
 (let (($x4482 (and $x4472 (=> $x4480 (or $x4475 (and $x3343 (< rank_54 rank_48)))))))
 (let (($x4487 (and $x4482 (=> root_51 $x3313))))
 (let (($x4500 (and $x4487 (=> $x4498 (or $x4493 (and $x3298 (< rank_48 rank_50)))))))
 (let (($x4505 (and $x4500 (=> root_53 $x3328))))
 (let (($x4515 (and $x4505 (=> $x4513 (or $x4508 (and $x3313 (< rank_50 rank_52)))))))
 (let (($x4520 (and $x4515 (=> root_55 $x3343))))
 (let (($x4530 (and $x4520 (=> $x4528 (or $x4523 (and $x3298 (< rank_48 rank_54)))))))
 (let (($x4535 (and $x4530 (=> root_57 $x3358))))
 (let (($x4548 (and $x4535 (=> $x4546 (or $x4541 (and $x3313 (< rank_50 rank_56)))))))
 (let (($x4553 (and $x4548 (=> root_59 $x3373))))
 (let (($x4565 (and (and $x4553 (=> $x4561 (or $x4556 (and $x3328 (< rank_52 rank_58))))) (=> $x3479 (or $x4531 root_59)))))
 (let (($x4567 (and $x4565 (<= (+ ?x4533 ?x4550) 1))))
 (let (($x4568 (and true $x4567)))
 (let (($x4786 (= rule_instance 28)))
 (let (($x4785 (and $x4786 (and (and (and $x4568 $x3523) (and $x4640 $x3714)) (and $x4773 $x3965)))))
 (let ((?x4412 (ite root_47 1 0)))
 (let ((?x4394 (ite root_45 1 0)))
 (let ((?x4379 (ite root_43 1 0)))
 (let ((?x4364 (ite root_41 1 0)))
 (let ((?x4346 (ite root_39 1 0)))
 (let ((?x4331 (ite root_37 1 0)))
 (let ((?x4332 (+ 0 ?x4331)))
 (let ((?x4347 (+ ?x4332 ?x4346)))
 (let ((?x4365 (+ ?x4347 ?x4364)))
 (let ((?x4380 (+ ?x4365 ?x4379)))
 (let ((?x4395 (+ ?x4380 ?x4394)))
 (let (($x4330 (or false root_37)))
 (let (($x4345 (or $x4330 root_39)))
 (let (($x4363 (or $x4345 root_41)))
 (let (($x4378 (or $x4363 root_43)))
 (let (($x4393 (or $x4378 root_45)))
 (let (($x4418 (or false (and $x3805 (< rank_44 rank_46)))))
 (let (($x4422 (not root_47)))
 (let (($x4423 (and $x3820 $x4422)))
 (let (($x4400 (or false (and $x3820 (< rank_46 rank_44)))))
 (let (($x4403 (or $x4400 (and $x3790 (< rank_42 rank_44)))))
 (let (($x4407 (not root_45)))
 (let (($x4408 (and $x3805 $x4407)))
 (let (($x4385 (or false (and $x3805 (< rank_44 rank_42)))))
 (let (($x4389 (not root_43)))
 (let (($x4390 (and $x3790 $x4389)))
 (let (($x4370 (or false (and $x3820 (< rank_46 rank_40)))))
 (let (($x4374 (not root_41)))
 (let (($x4375 (and $x3775 $x4374)))
 (let (($x4352 (or false (and $x3775 (< rank_40 rank_38)))))
 (let (($x4355 (or $x4352 (and $x3805 (< rank_44 rank_38)))))
 (let (($x4359 (not root_39)))
 (let (($x4360 (and $x3760 $x4359)))
 (let (($x4337 (or false (and $x3760 (< rank_38 rank_36)))))
 (let (($x4341 (not root_37)))
 (let (($x4342 (and $x3745 $x4341)))
 (let (($x4334 (and true (=> root_37 $x3745))))
 (let (($x4344 (and $x4334 (=> $x4342 (or $x4337 (and $x3790 (< rank_42 rank_36)))))))
 (let (($x4349 (and $x4344 (=> root_39 $x3760))))
 (let (($x4362 (and $x4349 (=> $x4360 (or $x4355 (and $x3745 (< rank_36 rank_38)))))))
 (let (($x4367 (and $x4362 (=> root_41 $x3775))))
 (let (($x4377 (and $x4367 (=> $x4375 (or $x4370 (and $x3760 (< rank_38 rank_40)))))))
 (let (($x4382 (and $x4377 (=> root_43 $x3790))))
 (let (($x4392 (and $x4382 (=> $x4390 (or $x4385 (and $x3745 (< rank_36 rank_42)))))))
 (let (($x4397 (and $x4392 (=> root_45 $x3805))))
 (let (($x4410 (and $x4397 (=> $x4408 (or $x4403 (and $x3760 (< rank_38 rank_44)))))))
 (let (($x4415 (and $x4410 (=> root_47 $x3820))))
 (let (($x4427 (and (and $x4415 (=> $x4423 (or $x4418 (and $x3775 (< rank_40 rank_46))))) (=> $x3923 (or $x4393 root_47)))))
 (let (($x4429 (and $x4427 (<= (+ ?x4395 ?x4412) 1))))
 (let (($x4430 (and true $x4429)))
 (let (($x4263 (and true (=> c_1_0 d_1_0))))
 (let (($x4265 (and $x4263 (=> c_1_1 d_1_0))))
 (let (($x4267 (and $x4265 (=> c_1_2 d_1_0))))
 (let (($x4269 (and $x4267 (=> c_1_3 d_1_0))))
 (let (($x4271 (and $x4269 (=> c_1_4 d_1_0))))
 (let (($x4273 (and $x4271 (=> c_1_5 d_1_0))))
 (let (($x4275 (and $x4273 (=> c_1_6 d_1_0))))
 (let (($x4277 (and $x4275 (=> c_1_7 d_1_0))))
 (let (($x4279 (and $x4277 (=> c_1_8 d_1_0))))
 (let (($x4281 (and $x4279 (=> c_1_9 d_1_0))))
 (let (($x4283 (and $x4281 (=> c_1_10 d_1_0))))
 (let (($x4285 (and $x4283 (=> c_1_11 d_1_0))))
 (let (($x4287 (and $x4285 (=> c_1_12 d_1_0))))
 (let (($x4289 (and $x4287 (=> c_1_13 d_1_0))))
 (let (($x4291 (and $x4289 (=> c_1_14 d_1_0))))
 (let (($x4232 (and true (=> c_0_0 d_0_6))))
 (let (($x4228 (and $x4232 (=> c_0_1 d_0_6))))
 (let (($x4234 (and $x4228 (=> c_0_2 d_0_6))))
 (let (($x4229 (and $x4234 (=> c_0_3 d_0_6))))
 (let (($x4239 (and $x4229 (=> c_0_4 d_0_6))))
 (let (($x4240 (and $x4239 (=> c_0_5 d_0_6))))
 (let (($x4242 (and $x4240 (=> c_0_6 d_0_6))))
 (let (($x4244 (and $x4242 (=> c_0_7 d_0_6))))
 (let (($x4246 (and $x4244 (=> c_0_8 d_0_6))))
 (let (($x4248 (and $x4246 (=> c_0_9 d_0_6))))
 (let (($x4250 (and $x4248 (=> c_0_10 d_0_6))))
 (let (($x4252 (and $x4250 (=> c_0_11 d_0_6))))
 (let (($x4254 (and $x4252 (=> c_0_12 d_0_6))))
 (let (($x4256 (and $x4254 (=> c_0_13 d_0_6))))
 (let (($x4258 (and $x4256 (=> c_0_14 d_0_6))))
 (let (($x4235 (and true c_0_2)))
 (let (($x4236 (and $x4235 c_1_14)))
 (let (($x4261 (and $x4236 (and $x4258 (=> c_0_15 d_0_6)))))
 (let (($x4294 (and $x4261 (and $x4291 (=> c_1_15 d_1_0)))))
 (let (($x4295 (and $x4294 $x3615)))
 (let (($x4296 (and $x4295 $x3648)))
 (let (($x4297 (and $x4296 $x3681)))
 (let ((?x4207 (ite root_35 1 0)))
 (let ((?x4189 (ite root_33 1 0)))
 (let ((?x4174 (ite root_31 1 0)))
 (let ((?x4159 (ite root_29 1 0)))
 (let ((?x4141 (ite root_27 1 0)))
 (let ((?x4126 (ite root_25 1 0)))
 (let ((?x4127 (+ 0 ?x4126)))
 (let ((?x4142 (+ ?x4127 ?x4141)))
 (let ((?x4160 (+ ?x4142 ?x4159)))
 (let ((?x4175 (+ ?x4160 ?x4174)))
 (let ((?x4190 (+ ?x4175 ?x4189)))
 (let (($x4125 (or false root_25)))
 (let (($x4140 (or $x4125 root_27)))
 (let (($x4158 (or $x4140 root_29)))
 (let (($x4173 (or $x4158 root_31)))
 (let (($x4188 (or $x4173 root_33)))
 (let (($x4213 (or false (and $x3358 (< rank_32 rank_34)))))
 (let (($x4217 (not root_35)))
 (let (($x4218 (and $x3373 $x4217)))
 (let (($x4195 (or false (and $x3373 (< rank_34 rank_32)))))
 (let (($x4198 (or $x4195 (and $x3343 (< rank_30 rank_32)))))
 (let (($x4202 (not root_33)))
 (let (($x4203 (and $x3358 $x4202)))
 (let (($x4180 (or false (and $x3358 (< rank_32 rank_30)))))
 (let (($x4184 (not root_31)))
 (let (($x4185 (and $x3343 $x4184)))
 (let (($x4165 (or false (and $x3373 (< rank_34 rank_28)))))
 (let (($x4169 (not root_29)))
 (let (($x4170 (and $x3328 $x4169)))
 (let (($x4147 (or false (and $x3328 (< rank_28 rank_26)))))
 (let (($x4150 (or $x4147 (and $x3358 (< rank_32 rank_26)))))
 (let (($x4154 (not root_27)))
 (let (($x4155 (and $x3313 $x4154)))
 (let (($x4132 (or false (and $x3313 (< rank_26 rank_24)))))
 (let (($x4136 (not root_25)))
 (let (($x4137 (and $x3298 $x4136)))
 (let (($x4129 (and true (=> root_25 $x3298))))
 (let (($x4139 (and $x4129 (=> $x4137 (or $x4132 (and $x3343 (< rank_30 rank_24)))))))
 (let (($x4144 (and $x4139 (=> root_27 $x3313))))
 (let (($x4157 (and $x4144 (=> $x4155 (or $x4150 (and $x3298 (< rank_24 rank_26)))))))
 (let (($x4162 (and $x4157 (=> root_29 $x3328))))
 (let (($x4172 (and $x4162 (=> $x4170 (or $x4165 (and $x3313 (< rank_26 rank_28)))))))
 (let (($x4177 (and $x4172 (=> root_31 $x3343))))
 (let (($x4187 (and $x4177 (=> $x4185 (or $x4180 (and $x3298 (< rank_24 rank_30)))))))
 (let (($x4192 (and $x4187 (=> root_33 $x3358))))
 (let (($x4205 (and $x4192 (=> $x4203 (or $x4198 (and $x3313 (< rank_26 rank_32)))))))
 (let (($x4210 (and $x4205 (=> root_35 $x3373))))
 (let (($x4222 (and (and $x4210 (=> $x4218 (or $x4213 (and $x3328 (< rank_28 rank_34))))) (=> $x3479 (or $x4188 root_35)))))
 (let (($x4224 (and $x4222 (<= (+ ?x4190 ?x4207) 1))))
 (let (($x4225 (and true $x4224)))
 (let (($x4443 (= rule_instance 14)))
 (let (($x4442 (and $x4443 (and (and (and $x4225 $x3523) (and $x4297 $x3714)) (and $x4430 $x3965)))))
 (let ((?x3925 (ite root_23 1 0)))
 (let ((?x3906 (ite root_21 1 0)))
 (let ((?x3890 (ite root_19 1 0)))
 (let ((?x3874 (ite root_17 1 0)))
 (let ((?x3855 (ite root_15 1 0)))
 (let ((?x3839 (ite root_13 1 0)))
 (let ((?x3840 (+ 0 ?x3839)))
 (let ((?x3856 (+ ?x3840 ?x3855)))
 (let ((?x3875 (+ ?x3856 ?x3874)))
 (let ((?x3891 (+ ?x3875 ?x3890)))
 (let ((?x3907 (+ ?x3891 ?x3906)))
 (let (($x3838 (or false root_13)))
 (let (($x3854 (or $x3838 root_15)))
 (let (($x3873 (or $x3854 root_17)))
 (let (($x3889 (or $x3873 root_19)))
 (let (($x3905 (or $x3889 root_21)))
 (let (($x3931 (or false (and $x3805 (< rank_20 rank_22)))))
 (let (($x3935 (not root_23)))
 (let (($x3936 (and $x3820 $x3935)))
 (let (($x3912 (or false (and $x3820 (< rank_22 rank_20)))))
 (let (($x3915 (or $x3912 (and $x3790 (< rank_18 rank_20)))))
 (let (($x3919 (not root_21)))
 (let (($x3920 (and $x3805 $x3919)))
 (let (($x3896 (or false (and $x3805 (< rank_20 rank_18)))))
 (let (($x3900 (not root_19)))
 (let (($x3901 (and $x3790 $x3900)))
 (let (($x3880 (or false (and $x3820 (< rank_22 rank_16)))))
 (let (($x3884 (not root_17)))
 (let (($x3885 (and $x3775 $x3884)))
 (let (($x3861 (or false (and $x3775 (< rank_16 rank_14)))))
 (let (($x3864 (or $x3861 (and $x3805 (< rank_20 rank_14)))))
 (let (($x3868 (not root_15)))
 (let (($x3869 (and $x3760 $x3868)))
 (let (($x3845 (or false (and $x3760 (< rank_14 rank_12)))))
 (let (($x3849 (not root_13)))
 (let (($x3850 (and $x3745 $x3849)))
 (let (($x3842 (and true (=> root_13 $x3745))))
 (let (($x3852 (and $x3842 (=> $x3850 (or $x3845 (and $x3790 (< rank_18 rank_12)))))))
 (let (($x3858 (and $x3852 (=> root_15 $x3760))))
 (let (($x3871 (and $x3858 (=> $x3869 (or $x3864 (and $x3745 (< rank_12 rank_14)))))))
 (let (($x3877 (and $x3871 (=> root_17 $x3775))))
 (let (($x3887 (and $x3877 (=> $x3885 (or $x3880 (and $x3760 (< rank_14 rank_16)))))))
 (let (($x3893 (and $x3887 (=> root_19 $x3790))))
 (let (($x3903 (and $x3893 (=> $x3901 (or $x3896 (and $x3745 (< rank_12 rank_18)))))))
 (let (($x3909 (and $x3903 (=> root_21 $x3805))))
 (let (($x3922 (and $x3909 (=> $x3920 (or $x3915 (and $x3760 (< rank_14 rank_20)))))))
 (let (($x3928 (and $x3922 (=> root_23 $x3820))))
 (let (($x3940 (and (and $x3928 (=> $x3936 (or $x3931 (and $x3775 (< rank_16 rank_22))))) (=> $x3923 (or $x3905 root_23)))))
 (let (($x3942 (and $x3940 (<= (+ ?x3907 ?x3925) 1))))
 (let (($x3943 (and true $x3942)))
 (let (($x3520 (and true (=> c_0_0 d_0_2))))
 (let (($x3505 (and $x3520 (=> c_0_1 d_0_2))))
 (let (($x3524 (and $x3505 $x3519)))
 (let (($x3525 (and $x3524 (=> c_0_3 d_0_2))))
 (let (($x3527 (and $x3525 (=> c_0_4 d_0_2))))
 (let (($x3529 (and $x3527 (=> c_0_5 d_0_2))))
 (let (($x3531 (and $x3529 (=> c_0_6 d_0_2))))
 (let (($x3533 (and $x3531 $x3532)))
 (let (($x3535 (and $x3533 (=> c_0_8 d_0_2))))
 (let (($x3537 (and $x3535 (=> c_0_9 d_0_2))))
 (let (($x3539 (and $x3537 (=> c_0_10 d_0_2))))
 (let (($x3541 (and $x3539 (=> c_0_11 d_0_2))))
 (let (($x3543 (and $x3541 $x3542)))
 (let (($x3545 (and $x3543 (=> c_0_13 d_0_2))))
 (let (($x3547 (and $x3545 (=> c_0_14 d_0_2))))
 (let (($x3506 (and true c_0_6)))
 (let (($x3522 (and $x3506 c_1_0)))
 (let (($x3550 (and $x3522 (and $x3547 (=> c_0_15 d_0_2)))))
 (let (($x3583 (and $x3550 $x3582)))
 (let (($x3616 (and $x3583 $x3615)))
 (let (($x3649 (and $x3616 $x3648)))
 (let (($x3682 (and $x3649 $x3681)))
 (let ((?x3481 (ite root_11 1 0)))
 (let ((?x3462 (ite root_9 1 0)))
 (let ((?x3446 (ite root_7 1 0)))
 (let ((?x3430 (ite root_5 1 0)))
 (let ((?x3411 (ite root_3 1 0)))
 (let ((?x3395 (ite root_1 1 0)))
 (let ((?x3396 (+ 0 ?x3395)))
 (let ((?x3412 (+ ?x3396 ?x3411)))
 (let ((?x3431 (+ ?x3412 ?x3430)))
 (let ((?x3447 (+ ?x3431 ?x3446)))
 (let ((?x3463 (+ ?x3447 ?x3462)))
 (let (($x3393 (or false root_1)))
 (let (($x3410 (or $x3393 root_3)))
 (let (($x3429 (or $x3410 root_5)))
 (let (($x3445 (or $x3429 root_7)))
 (let (($x3461 (or $x3445 root_9)))
 (let (($x3487 (or false (and $x3358 (< rank_8 rank_10)))))
 (let (($x3491 (not root_11)))
 (let (($x3492 (and $x3373 $x3491)))
 (let (($x3468 (or false (and $x3373 (< rank_10 rank_8)))))
 (let (($x3471 (or $x3468 (and $x3343 (< rank_6 rank_8)))))
 (let (($x3475 (not root_9)))
 (let (($x3476 (and $x3358 $x3475)))
 (let (($x3452 (or false (and $x3358 (< rank_8 rank_6)))))
 (let (($x3456 (not root_7)))
 (let (($x3457 (and $x3343 $x3456)))
 (let (($x3436 (or false (and $x3373 (< rank_10 rank_4)))))
 (let (($x3440 (not root_5)))
 (let (($x3441 (and $x3328 $x3440)))
 (let (($x3417 (or false (and $x3328 (< rank_4 rank_2)))))
 (let (($x3420 (or $x3417 (and $x3358 (< rank_8 rank_2)))))
 (let (($x3424 (not root_3)))
 (let (($x3425 (and $x3313 $x3424)))
 (let (($x3401 (or false (and $x3313 (< rank_2 rank_0)))))
 (let (($x3405 (not root_1)))
 (let (($x3406 (and $x3298 $x3405)))
 (let (($x3398 (and true (=> root_1 $x3298))))
 (let (($x3408 (and $x3398 (=> $x3406 (or $x3401 (and $x3343 (< rank_6 rank_0)))))))
 (let (($x3414 (and $x3408 (=> root_3 $x3313))))
 (let (($x3427 (and $x3414 (=> $x3425 (or $x3420 (and $x3298 (< rank_0 rank_2)))))))
 (let (($x3433 (and $x3427 (=> root_5 $x3328))))
 (let (($x3443 (and $x3433 (=> $x3441 (or $x3436 (and $x3313 (< rank_2 rank_4)))))))
 (let (($x3449 (and $x3443 (=> root_7 $x3343))))
 (let (($x3459 (and $x3449 (=> $x3457 (or $x3452 (and $x3298 (< rank_0 rank_6)))))))
 (let (($x3465 (and $x3459 (=> root_9 $x3358))))
 (let (($x3478 (and $x3465 (=> $x3476 (or $x3471 (and $x3313 (< rank_2 rank_8)))))))
 (let (($x3484 (and $x3478 (=> root_11 $x3373))))
 (let (($x3496 (and (and $x3484 (=> $x3492 (or $x3487 (and $x3328 (< rank_4 rank_10))))) (=> $x3479 (or $x3461 root_11)))))
 (let (($x3498 (and $x3496 (<= (+ ?x3463 ?x3481) 1))))
 (let (($x3499 (and true $x3498)))
 (let (($x4090 (= rule_instance 0)))
 (let (($x4091 (and $x4090 (and (and (and $x3499 $x3523) (and $x3682 $x3714)) (and $x3943 $x3965)))))
 (let (($x4094 (or false (and $x4091 $x4092))))
 (let (($x4438 (or $x4094 (and $x4442 $x4092))))
 (let (($x4781 (or $x4438 (and $x4785 $x4092))))
 (let (($x5092 (or $x4781 (and $x5096 $x4092))))
 (or $x5092 (and $x5436 $x4092))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
