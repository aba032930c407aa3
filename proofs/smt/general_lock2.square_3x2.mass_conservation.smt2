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
 (let (($x3860 (>= rank_12 0)))
 (and $x3860 (< rank_12 6))))
(assert
 (let (($x3856 (>= rank_14 0)))
 (and $x3856 (< rank_14 6))))
(assert
 (let (($x3863 (>= rank_16 0)))
 (and $x3863 (< rank_16 6))))
(assert
 (let (($x3871 (>= rank_18 0)))
 (and $x3871 (< rank_18 6))))
(assert
 (let (($x3876 (>= rank_20 0)))
 (and $x3876 (< rank_20 6))))
(assert
 (let (($x3881 (>= rank_22 0)))
 (and $x3881 (< rank_22 6))))
(assert
 (let (($x4195 (>= rank_24 0)))
 (and $x4195 (< rank_24 6))))
(assert
 (let (($x4190 (>= rank_26 0)))
 (and $x4190 (< rank_26 6))))
(assert
 (let (($x4198 (>= rank_28 0)))
 (and $x4198 (< rank_28 6))))
(assert
 (let (($x4202 (>= rank_30 0)))
 (and $x4202 (< rank_30 6))))
(assert
 (let (($x4207 (>= rank_32 0)))
 (and $x4207 (< rank_32 6))))
(assert
 (let (($x4212 (>= rank_34 0)))
 (and $x4212 (< rank_34 6))))
(assert
 (let (($x4393 (>= rank_36 0)))
 (and $x4393 (< rank_36 6))))
(assert
 (let (($x4395 (>= rank_38 0)))
 (and $x4395 (< rank_38 6))))
(assert
 (let (($x4399 (>= rank_40 0)))
 (and $x4399 (< rank_40 6))))
(assert
 (let (($x4407 (>= rank_42 0)))
 (and $x4407 (< rank_42 6))))
(assert
 (let (($x4412 (>= rank_44 0)))
 (and $x4412 (< rank_44 6))))
(assert
 (let (($x4417 (>= rank_46 0)))
 (and $x4417 (< rank_46 6))))
(assert
 (let (($x4538 (>= rank_48 0)))
 (and $x4538 (< rank_48 6))))
(assert
 (let (($x4523 (>= rank_50 0)))
 (and $x4523 (< rank_50 6))))
(assert
 (let (($x4541 (>= rank_52 0)))
 (and $x4541 (< rank_52 6))))
(assert
 (let (($x4545 (>= rank_54 0)))
 (and $x4545 (< rank_54 6))))
(assert
 (let (($x4550 (>= rank_56 0)))
 (and $x4550 (< rank_56 6))))
(assert
 (let (($x4555 (>= rank_58 0)))
 (and $x4555 (< rank_58 6))))
(assert
 (let (($x4736 (>= rank_60 0)))
 (and $x4736 (< rank_60 6))))
(assert
 (let (($x4738 (>= rank_62 0)))
 (and $x4738 (< rank_62 6))))
(assert
 (let (($x4742 (>= rank_64 0)))
 (and $x4742 (< rank_64 6))))
(assert
 (let (($x4750 (>= rank_66 0)))
 (and $x4750 (< rank_66 6))))
(assert
 (let (($x4755 (>= rank_68 0)))
 (and $x4755 (< rank_68 6))))
(assert
 (let (($x4760 (>= rank_70 0)))
 (and $x4760 (< rank_70 6))))
(assert
 (let (($x4881 (>= rank_72 0)))
 (and $x4881 (< rank_72 6))))
(assert
 (let (($x4866 (>= rank_74 0)))
 (and $x4866 (< rank_74 6))))
(assert
 (let (($x4884 (>= rank_76 0)))
 (and $x4884 (< rank_76 6))))
(assert
 (let (($x4888 (>= rank_78 0)))
 (and $x4888 (< rank_78 6))))
(assert
 (let (($x4893 (>= rank_80 0)))
 (and $x4893 (< rank_80 6))))
(assert
 (let (($x4898 (>= rank_82 0)))
 (and $x4898 (< rank_82 6))))
(assert
 (let (($x5047 (>= rank_84 0)))
 (and $x5047 (< rank_84 6))))
(assert
 (let (($x5049 (>= rank_86 0)))
 (and $x5049 (< rank_86 6))))
(assert
 (let (($x5053 (>= rank_88 0)))
 (and $x5053 (< rank_88 6))))
(assert
 (let (($x5061 (>= rank_90 0)))
 (and $x5061 (< rank_90 6))))
(assert
 (let (($x5066 (>= rank_92 0)))
 (and $x5066 (< rank_92 6))))
(assert
 (let (($x5071 (>= rank_94 0)))
 (and $x5071 (< rank_94 6))))
(assert
 (let (($x5192 (>= rank_96 0)))
 (and $x5192 (< rank_96 6))))
(assert
 (let (($x5177 (>= rank_98 0)))
 (and $x5177 (< rank_98 6))))
(assert
 (let (($x5195 (>= rank_100 0)))
 (and $x5195 (< rank_100 6))))
(assert
 (let (($x5199 (>= rank_102 0)))
 (and $x5199 (< rank_102 6))))
(assert
 (let (($x5204 (>= rank_104 0)))
 (and $x5204 (< rank_104 6))))
(assert
 (let (($x5209 (>= rank_106 0)))
 (and $x5209 (< rank_106 6))))
(assert
 (let (($x5387 (>= rank_108 0)))
 (and $x5387 (< rank_108 6))))
(assert
 (let (($x5389 (>= rank_110 0)))
 (and $x5389 (< rank_110 6))))
(assert
 (let (($x5393 (>= rank_112 0)))
 (and $x5393 (< rank_112 6))))
(assert
 (let (($x5401 (>= rank_114 0)))
 (and $x5401 (< rank_114 6))))
(assert
 (let (($x5406 (>= rank_116 0)))
 (and $x5406 (< rank_116 6))))
(assert
 (let (($x5411 (>= rank_118 0)))
 (and $x5411 (< rank_118 6))))
(assert
 (let ((?x4178 (ite d_1_15 1 0)))
 (let ((?x4174 (ite d_1_14 1 0)))
 (let ((?x4170 (ite d_1_13 1 0)))
 (let ((?x4166 (ite d_1_12 1 0)))
 (let ((?x4162 (ite d_1_11 1 0)))
 (let ((?x4158 (ite d_1_10 3 0)))
 (let ((?x4154 (ite d_1_9 3 0)))
 (let ((?x4150 (ite d_1_8 3 0)))
 (let ((?x4146 (ite d_1_7 3 0)))
 (let ((?x4142 (ite d_1_6 3 0)))
 (let ((?x4138 (ite d_1_5 2 0)))
 (let ((?x4134 (ite d_1_4 2 0)))
 (let ((?x4130 (ite d_1_3 2 0)))
 (let ((?x4126 (ite d_1_2 2 0)))
 (let ((?x4122 (ite d_1_1 2 0)))
 (let ((?x4114 (ite d_0_15 1 0)))
 (let ((?x4110 (ite d_0_14 1 0)))
 (let ((?x4106 (ite d_0_13 1 0)))
 (let ((?x4102 (ite d_0_12 1 0)))
 (let ((?x4098 (ite d_0_11 1 0)))
 (let ((?x4094 (ite d_0_10 3 0)))
 (let ((?x4090 (ite d_0_9 3 0)))
 (let ((?x4086 (ite d_0_8 3 0)))
 (let ((?x4082 (ite d_0_7 3 0)))
 (let ((?x4078 (ite d_0_6 3 0)))
 (let ((?x4073 (ite d_0_5 2 0)))
 (let ((?x4069 (ite d_0_4 2 0)))
 (let ((?x4065 (ite d_0_3 2 0)))
 (let ((?x4061 (ite d_0_2 2 0)))
 (let ((?x4057 (ite d_0_1 2 0)))
 (let ((?x4053 (+ 0 (ite d_0_0 0 0))))
 (let ((?x4058 (+ ?x4053 ?x4057)))
 (let ((?x4062 (+ ?x4058 ?x4061)))
 (let ((?x4066 (+ ?x4062 ?x4065)))
 (let ((?x4070 (+ ?x4066 ?x4069)))
 (let ((?x4074 (+ ?x4070 ?x4073)))
 (let ((?x4079 (+ ?x4074 ?x4078)))
 (let ((?x4083 (+ ?x4079 ?x4082)))
 (let ((?x4087 (+ ?x4083 ?x4086)))
 (let ((?x4091 (+ ?x4087 ?x4090)))
 (let ((?x4095 (+ ?x4091 ?x4094)))
 (let ((?x4099 (+ ?x4095 ?x4098)))
 (let ((?x4103 (+ ?x4099 ?x4102)))
 (let ((?x4107 (+ ?x4103 ?x4106)))
 (let ((?x4111 (+ ?x4107 ?x4110)))
 (let ((?x4115 (+ ?x4111 ?x4114)))
 (let ((?x4119 (+ ?x4115 (ite d_1_0 0 0))))
 (let ((?x4123 (+ ?x4119 ?x4122)))
 (let ((?x4127 (+ ?x4123 ?x4126)))
 (let ((?x4131 (+ ?x4127 ?x4130)))
 (let ((?x4135 (+ ?x4131 ?x4134)))
 (let ((?x4139 (+ ?x4135 ?x4138)))
 (let ((?x4143 (+ ?x4139 ?x4142)))
 (let ((?x4147 (+ ?x4143 ?x4146)))
 (let ((?x4151 (+ ?x4147 ?x4150)))
 (let ((?x4155 (+ ?x4151 ?x4154)))
 (let ((?x4159 (+ ?x4155 ?x4158)))
 (let ((?x4163 (+ ?x4159 ?x4162)))
 (let ((?x4167 (+ ?x4163 ?x4166)))
 (let ((?x4171 (+ ?x4167 ?x4170)))
 (let ((?x4175 (+ ?x4171 ?x4174)))
 (let ((?x4176 (ite c_1_15 1 0)))
 (let ((?x4172 (ite c_1_14 1 0)))
 (let ((?x4168 (ite c_1_13 1 0)))
 (let ((?x4164 (ite c_1_12 1 0)))
 (let ((?x4160 (ite c_1_11 1 0)))
 (let ((?x4156 (ite c_1_10 3 0)))
 (let ((?x4152 (ite c_1_9 3 0)))
 (let ((?x4148 (ite c_1_8 3 0)))
 (let ((?x4144 (ite c_1_7 3 0)))
 (let ((?x4140 (ite c_1_6 3 0)))
 (let ((?x4136 (ite c_1_5 2 0)))
 (let ((?x4132 (ite c_1_4 2 0)))
 (let ((?x4128 (ite c_1_3 2 0)))
 (let ((?x4124 (ite c_1_2 2 0)))
 (let ((?x4120 (ite c_1_1 2 0)))
 (let ((?x4112 (ite c_0_15 1 0)))
 (let ((?x4108 (ite c_0_14 1 0)))
 (let ((?x4104 (ite c_0_13 1 0)))
 (let ((?x4100 (ite c_0_12 1 0)))
 (let ((?x4096 (ite c_0_11 1 0)))
 (let ((?x4092 (ite c_0_10 3 0)))
 (let ((?x4088 (ite c_0_9 3 0)))
 (let ((?x4084 (ite c_0_8 3 0)))
 (let ((?x4080 (ite c_0_7 3 0)))
 (let ((?x4076 (ite c_0_6 3 0)))
 (let ((?x4071 (ite c_0_5 2 0)))
 (let ((?x4067 (ite c_0_4 2 0)))
 (let ((?x4063 (ite c_0_3 2 0)))
 (let ((?x4059 (ite c_0_2 2 0)))
 (let ((?x4055 (ite c_0_1 2 0)))
 (let ((?x4051 (+ 0 (ite c_0_0 0 0))))
 (let ((?x4056 (+ ?x4051 ?x4055)))
 (let ((?x4060 (+ ?x4056 ?x4059)))
 (let ((?x4064 (+ ?x4060 ?x4063)))
 (let ((?x4068 (+ ?x4064 ?x4067)))
 (let ((?x4072 (+ ?x4068 ?x4071)))
 (let ((?x4077 (+ ?x4072 ?x4076)))
 (let ((?x4081 (+ ?x4077 ?x4080)))
 (let ((?x4085 (+ ?x4081 ?x4084)))
 (let ((?x4089 (+ ?x4085 ?x4088)))
 (let ((?x4093 (+ ?x4089 ?x4092)))
 (let ((?x4097 (+ ?x4093 ?x4096)))
 (let ((?x4101 (+ ?x4097 ?x4100)))
 (let ((?x4105 (+ ?x4101 ?x4104)))
 (let ((?x4109 (+ ?x4105 ?x4108)))
 (let ((?x4113 (+ ?x4109 ?x4112)))
 (let ((?x4117 (+ ?x4113 (ite c_1_0 0 0))))
 (let ((?x4121 (+ ?x4117 ?x4120)))
 (let ((?x4125 (+ ?x4121 ?x4124)))
 (let ((?x4129 (+ ?x4125 ?x4128)))
 (let ((?x4133 (+ ?x4129 ?x4132)))
 (let ((?x4137 (+ ?x4133 ?x4136)))
 (let ((?x4141 (+ ?x4137 ?x4140)))
 (let ((?x4145 (+ ?x4141 ?x4144)))
 (let ((?x4149 (+ ?x4145 ?x4148)))
 (let ((?x4153 (+ ?x4149 ?x4152)))
 (let ((?x4157 (+ ?x4153 ?x4156)))
 (let ((?x4161 (+ ?x4157 ?x4160)))
 (let ((?x4165 (+ ?x4161 ?x4164)))
 (let ((?x4169 (+ ?x4165 ?x4168)))
 (let ((?x4173 (+ ?x4169 ?x4172)))
 (let (($x4182 (and (distinct (+ ?x4173 ?x4176) (+ ?x4175 ?x4178)) true)))
 (let (($x3867 (or d_5_1 d_5_2 d_5_3 d_5_4 d_5_5 d_5_6 d_5_7 d_5_8 d_5_9 d_5_10 d_5_11 d_5_12 d_5_13 d_5_14 d_5_15)))
 (let ((?x4011 (ite $x3867 1 0)))
 (let (($x3852 (or d_4_1 d_4_2 d_4_3 d_4_4 d_4_5 d_4_6 d_4_7 d_4_8 d_4_9 d_4_10 d_4_11 d_4_12 d_4_13 d_4_14 d_4_15)))
 (let ((?x3997 (ite $x3852 1 0)))
 (let (($x3837 (or d_3_1 d_3_2 d_3_3 d_3_4 d_3_5 d_3_6 d_3_7 d_3_8 d_3_9 d_3_10 d_3_11 d_3_12 d_3_13 d_3_14 d_3_15)))
 (let ((?x3994 (ite $x3837 1 0)))
 (let (($x3822 (or d_2_1 d_2_2 d_2_3 d_2_4 d_2_5 d_2_6 d_2_7 d_2_8 d_2_9 d_2_10 d_2_11 d_2_12 d_2_13 d_2_14 d_2_15)))
 (let ((?x3996 (ite $x3822 1 0)))
 (let (($x3807 (or d_1_1 d_1_2 d_1_3 d_1_4 d_1_5 d_1_6 d_1_7 d_1_8 d_1_9 d_1_10 d_1_11 d_1_12 d_1_13 d_1_14 d_1_15)))
 (let ((?x3993 (ite $x3807 1 0)))
 (let (($x3792 (or d_0_1 d_0_2 d_0_3 d_0_4 d_0_5 d_0_6 d_0_7 d_0_8 d_0_9 d_0_10 d_0_11 d_0_12 d_0_13 d_0_14 d_0_15)))
 (let ((?x3991 (ite $x3792 1 0)))
 (let ((?x4001 (+ 0 ?x3991)))
 (let ((?x3999 (+ ?x4001 ?x3993)))
 (let ((?x3992 (+ ?x3999 ?x3996)))
 (let ((?x4000 (+ ?x3992 ?x3994)))
 (let ((?x4002 (+ ?x4000 ?x3997)))
 (let (($x3998 (>= (+ ?x4002 ?x4011) 1)))
 (let ((?x5496 (ite root_119 1 0)))
 (let ((?x5478 (ite root_117 1 0)))
 (let ((?x5463 (ite root_115 1 0)))
 (let ((?x5448 (ite root_113 1 0)))
 (let ((?x5430 (ite root_111 1 0)))
 (let ((?x5415 (ite root_109 1 0)))
 (let ((?x5416 (+ 0 ?x5415)))
 (let ((?x5431 (+ ?x5416 ?x5430)))
 (let ((?x5449 (+ ?x5431 ?x5448)))
 (let ((?x5464 (+ ?x5449 ?x5463)))
 (let ((?x5479 (+ ?x5464 ?x5478)))
 (let (($x5414 (or false root_109)))
 (let (($x5429 (or $x5414 root_111)))
 (let (($x5447 (or $x5429 root_113)))
 (let (($x5462 (or $x5447 root_115)))
 (let (($x5477 (or $x5462 root_117)))
 (let (($x3884 (or false $x3792)))
 (let (($x3900 (or $x3884 $x3807)))
 (let (($x3919 (or $x3900 $x3822)))
 (let (($x3935 (or $x3919 $x3837)))
 (let (($x3951 (or $x3935 $x3852)))
 (let (($x3970 (or $x3951 $x3867)))
 (let (($x5502 (or false (and $x3852 (< rank_116 rank_118)))))
 (let (($x5506 (not root_119)))
 (let (($x5507 (and $x3867 $x5506)))
 (let (($x5484 (or false (and $x3867 (< rank_118 rank_116)))))
 (let (($x5487 (or $x5484 (and $x3837 (< rank_114 rank_116)))))
 (let (($x5491 (not root_117)))
 (let (($x5492 (and $x3852 $x5491)))
 (let (($x5469 (or false (and $x3852 (< rank_116 rank_114)))))
 (let (($x5473 (not root_115)))
 (let (($x5474 (and $x3837 $x5473)))
 (let (($x5454 (or false (and $x3867 (< rank_118 rank_112)))))
 (let (($x5458 (not root_113)))
 (let (($x5459 (and $x3822 $x5458)))
 (let (($x5436 (or false (and $x3822 (< rank_112 rank_110)))))
 (let (($x5439 (or $x5436 (and $x3852 (< rank_116 rank_110)))))
 (let (($x5443 (not root_111)))
 (let (($x5444 (and $x3807 $x5443)))
 (let (($x5421 (or false (and $x3807 (< rank_110 rank_108)))))
 (let (($x5425 (not root_109)))
 (let (($x5426 (and $x3792 $x5425)))
 (let (($x5418 (and true (=> root_109 $x3792))))
 (let (($x5428 (and $x5418 (=> $x5426 (or $x5421 (and $x3837 (< rank_114 rank_108)))))))
 (let (($x5433 (and $x5428 (=> root_111 $x3807))))
 (let (($x5446 (and $x5433 (=> $x5444 (or $x5439 (and $x3792 (< rank_108 rank_110)))))))
 (let (($x5451 (and $x5446 (=> root_113 $x3822))))
 (let (($x5461 (and $x5451 (=> $x5459 (or $x5454 (and $x3807 (< rank_110 rank_112)))))))
 (let (($x5466 (and $x5461 (=> root_115 $x3837))))
 (let (($x5476 (and $x5466 (=> $x5474 (or $x5469 (and $x3792 (< rank_108 rank_114)))))))
 (let (($x5481 (and $x5476 (=> root_117 $x3852))))
 (let (($x5494 (and $x5481 (=> $x5492 (or $x5487 (and $x3807 (< rank_110 rank_116)))))))
 (let (($x5499 (and $x5494 (=> root_119 $x3867))))
 (let (($x5511 (and (and $x5499 (=> $x5507 (or $x5502 (and $x3822 (< rank_112 rank_118))))) (=> $x3970 (or $x5477 root_119)))))
 (let (($x5513 (and $x5511 (<= (+ ?x5479 ?x5496) 1))))
 (let (($x5514 (and true $x5513)))
 (let (($x3760 (= c_5_15 d_5_15)))
 (let (($x3758 (= c_5_14 d_5_14)))
 (let (($x3756 (= c_5_13 d_5_13)))
 (let (($x3754 (= c_5_12 d_5_12)))
 (let (($x3752 (= c_5_11 d_5_11)))
 (let (($x3750 (= c_5_10 d_5_10)))
 (let (($x3748 (= c_5_9 d_5_9)))
 (let (($x3746 (= c_5_8 d_5_8)))
 (let (($x3744 (= c_5_7 d_5_7)))
 (let (($x3742 (= c_5_6 d_5_6)))
 (let (($x3740 (= c_5_5 d_5_5)))
 (let (($x3738 (= c_5_4 d_5_4)))
 (let (($x3736 (= c_5_3 d_5_3)))
 (let (($x3734 (= c_5_2 d_5_2)))
 (let (($x3732 (= c_5_1 d_5_1)))
 (let (($x3730 (= c_5_0 d_5_0)))
 (let (($x3731 (and true $x3730)))
 (let (($x3733 (and $x3731 $x3732)))
 (let (($x3735 (and $x3733 $x3734)))
 (let (($x3737 (and $x3735 $x3736)))
 (let (($x3739 (and $x3737 $x3738)))
 (let (($x3741 (and $x3739 $x3740)))
 (let (($x3743 (and $x3741 $x3742)))
 (let (($x3745 (and $x3743 $x3744)))
 (let (($x3747 (and $x3745 $x3746)))
 (let (($x3749 (and $x3747 $x3748)))
 (let (($x3751 (and $x3749 $x3750)))
 (let (($x3753 (and $x3751 $x3752)))
 (let (($x3755 (and $x3753 $x3754)))
 (let (($x3757 (and $x3755 $x3756)))
 (let (($x3759 (and $x3757 $x3758)))
 (let (($x3761 (and $x3759 $x3760)))
 (let (($x3727 (= c_4_15 d_4_15)))
 (let (($x3725 (= c_4_14 d_4_14)))
 (let (($x3723 (= c_4_13 d_4_13)))
 (let (($x3721 (= c_4_12 d_4_12)))
 (let (($x3719 (= c_4_11 d_4_11)))
 (let (($x3717 (= c_4_10 d_4_10)))
 (let (($x3715 (= c_4_9 d_4_9)))
 (let (($x3713 (= c_4_8 d_4_8)))
 (let (($x3711 (= c_4_7 d_4_7)))
 (let (($x3709 (= c_4_6 d_4_6)))
 (let (($x3707 (= c_4_5 d_4_5)))
 (let (($x3705 (= c_4_4 d_4_4)))
 (let (($x3703 (= c_4_3 d_4_3)))
 (let (($x3701 (= c_4_2 d_4_2)))
 (let (($x3699 (= c_4_1 d_4_1)))
 (let (($x3697 (= c_4_0 d_4_0)))
 (let (($x3698 (and true $x3697)))
 (let (($x3700 (and $x3698 $x3699)))
 (let (($x3702 (and $x3700 $x3701)))
 (let (($x3704 (and $x3702 $x3703)))
 (let (($x3706 (and $x3704 $x3705)))
 (let (($x3708 (and $x3706 $x3707)))
 (let (($x3710 (and $x3708 $x3709)))
 (let (($x3712 (and $x3710 $x3711)))
 (let (($x3714 (and $x3712 $x3713)))
 (let (($x3716 (and $x3714 $x3715)))
 (let (($x3718 (and $x3716 $x3717)))
 (let (($x3720 (and $x3718 $x3719)))
 (let (($x3722 (and $x3720 $x3721)))
 (let (($x3724 (and $x3722 $x3723)))
 (let (($x3726 (and $x3724 $x3725)))
 (let (($x3728 (and $x3726 $x3727)))
 (let (($x3694 (= c_3_15 d_3_15)))
 (let (($x3692 (= c_3_14 d_3_14)))
 (let (($x3690 (= c_3_13 d_3_13)))
 (let (($x3688 (= c_3_12 d_3_12)))
 (let (($x3686 (= c_3_11 d_3_11)))
 (let (($x3684 (= c_3_10 d_3_10)))
 (let (($x3682 (= c_3_9 d_3_9)))
 (let (($x3680 (= c_3_8 d_3_8)))
 (let (($x3678 (= c_3_7 d_3_7)))
 (let (($x3676 (= c_3_6 d_3_6)))
 (let (($x3674 (= c_3_5 d_3_5)))
 (let (($x3672 (= c_3_4 d_3_4)))
 (let (($x3670 (= c_3_3 d_3_3)))
 (let (($x3668 (= c_3_2 d_3_2)))
 (let (($x3666 (= c_3_1 d_3_1)))
 (let (($x3664 (= c_3_0 d_3_0)))
 (let (($x3665 (and true $x3664)))
 (let (($x3667 (and $x3665 $x3666)))
 (let (($x3669 (and $x3667 $x3668)))
 (let (($x3671 (and $x3669 $x3670)))
 (let (($x3673 (and $x3671 $x3672)))
 (let (($x3675 (and $x3673 $x3674)))
 (let (($x3677 (and $x3675 $x3676)))
 (let (($x3679 (and $x3677 $x3678)))
 (let (($x3681 (and $x3679 $x3680)))
 (let (($x3683 (and $x3681 $x3682)))
 (let (($x3685 (and $x3683 $x3684)))
 (let (($x3687 (and $x3685 $x3686)))
 (let (($x3689 (and $x3687 $x3688)))
 (let (($x3691 (and $x3689 $x3690)))
 (let (($x3693 (and $x3691 $x3692)))
 (let (($x3695 (and $x3693 $x3694)))
 (let (($x3661 (= c_2_15 d_2_15)))
 (let (($x3659 (= c_2_14 d_2_14)))
 (let (($x3657 (= c_2_13 d_2_13)))
 (let (($x3655 (= c_2_12 d_2_12)))
 (let (($x3653 (= c_2_11 d_2_11)))
 (let (($x3651 (= c_2_10 d_2_10)))
 (let (($x3649 (= c_2_9 d_2_9)))
 (let (($x3647 (= c_2_8 d_2_8)))
 (let (($x3645 (= c_2_7 d_2_7)))
 (let (($x3643 (= c_2_6 d_2_6)))
 (let (($x3641 (= c_2_5 d_2_5)))
 (let (($x3639 (= c_2_4 d_2_4)))
 (let (($x3637 (= c_2_3 d_2_3)))
 (let (($x3635 (= c_2_2 d_2_2)))
 (let (($x3633 (= c_2_1 d_2_1)))
 (let (($x3631 (= c_2_0 d_2_0)))
 (let (($x3632 (and true $x3631)))
 (let (($x3634 (and $x3632 $x3633)))
 (let (($x3636 (and $x3634 $x3635)))
 (let (($x3638 (and $x3636 $x3637)))
 (let (($x3640 (and $x3638 $x3639)))
 (let (($x3642 (and $x3640 $x3641)))
 (let (($x3644 (and $x3642 $x3643)))
 (let (($x3646 (and $x3644 $x3645)))
 (let (($x3648 (and $x3646 $x3647)))
 (let (($x3650 (and $x3648 $x3649)))
 (let (($x3652 (and $x3650 $x3651)))
 (let (($x3654 (and $x3652 $x3653)))
 (let (($x3656 (and $x3654 $x3655)))
 (let (($x3658 (and $x3656 $x3657)))
 (let (($x3660 (and $x3658 $x3659)))
 (let (($x3662 (and $x3660 $x3661)))
 (let (($x5347 (and true (=> c_1_0 d_1_6))))
 (let (($x5349 (and $x5347 (=> c_1_1 d_1_6))))
 (let (($x5351 (and $x5349 (=> c_1_2 d_1_7))))
 (let (($x5353 (and $x5351 (=> c_1_3 d_1_8))))
 (let (($x5355 (and $x5353 (=> c_1_4 d_1_9))))
 (let (($x5357 (and $x5355 (=> c_1_5 d_1_10))))
 (let (($x5359 (and $x5357 (=> c_1_6 d_1_6))))
 (let (($x5361 (and $x5359 (=> c_1_7 d_1_7))))
 (let (($x5363 (and $x5361 (=> c_1_8 d_1_8))))
 (let (($x5365 (and $x5363 (=> c_1_9 d_1_9))))
 (let (($x5367 (and $x5365 (=> c_1_10 d_1_10))))
 (let (($x5369 (and $x5367 (=> c_1_11 d_1_6))))
 (let (($x5371 (and $x5369 (=> c_1_12 d_1_7))))
 (let (($x5373 (and $x5371 (=> c_1_13 d_1_8))))
 (let (($x5375 (and $x5373 (=> c_1_14 d_1_9))))
 (let (($x3589 (=> c_0_12 d_0_2)))
 (let (($x4684 (=> c_0_11 d_0_1)))
 (let (($x3579 (=> c_0_7 d_0_2)))
 (let (($x4674 (=> c_0_6 d_0_1)))
 (let (($x3569 (=> c_0_2 d_0_2)))
 (let (($x4667 (and true (=> c_0_0 d_0_1))))
 (let (($x4665 (and $x4667 (=> c_0_1 d_0_1))))
 (let (($x5323 (and $x4665 $x3569)))
 (let (($x5320 (and $x5323 (=> c_0_3 d_0_3))))
 (let (($x5326 (and $x5320 (=> c_0_4 d_0_4))))
 (let (($x5328 (and $x5326 (=> c_0_5 d_0_5))))
 (let (($x5329 (and $x5328 $x4674)))
 (let (($x5330 (and $x5329 $x3579)))
 (let (($x5332 (and $x5330 (=> c_0_8 d_0_3))))
 (let (($x5334 (and $x5332 (=> c_0_9 d_0_4))))
 (let (($x5336 (and $x5334 (=> c_0_10 d_0_5))))
 (let (($x5337 (and $x5336 $x4684)))
 (let (($x5338 (and $x5337 $x3589)))
 (let (($x5340 (and $x5338 (=> c_0_13 d_0_3))))
 (let (($x5342 (and $x5340 (=> c_0_14 d_0_4))))
 (let (($x5324 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x5325 (or c_0_6 c_0_7 c_0_8 c_0_9 c_0_10)))
 (let (($x5314 (and true $x5325)))
 (let (($x5319 (and $x5314 $x5324)))
 (let (($x5345 (and $x5319 (and $x5342 (=> c_0_15 d_0_5)))))
 (let (($x5378 (and $x5345 (and $x5375 (=> c_1_15 d_1_10)))))
 (let (($x5379 (and $x5378 $x3662)))
 (let (($x5380 (and $x5379 $x3695)))
 (let (($x5381 (and $x5380 $x3728)))
 (let (($x3373 (or c_5_1 c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8 c_5_9 c_5_10 c_5_11 c_5_12 c_5_13 c_5_14 c_5_15)))
 (let ((?x3515 (ite $x3373 1 0)))
 (let (($x3358 (or c_4_1 c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8 c_4_9 c_4_10 c_4_11 c_4_12 c_4_13 c_4_14 c_4_15)))
 (let ((?x3509 (ite $x3358 1 0)))
 (let (($x3343 (or c_3_1 c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8 c_3_9 c_3_10 c_3_11 c_3_12 c_3_13 c_3_14 c_3_15)))
 (let ((?x3517 (ite $x3343 1 0)))
 (let (($x3328 (or c_2_1 c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8 c_2_9 c_2_10 c_2_11 c_2_12 c_2_13 c_2_14 c_2_15)))
 (let ((?x3514 (ite $x3328 1 0)))
 (let (($x3313 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8 c_1_9 c_1_10 c_1_11 c_1_12 c_1_13 c_1_14 c_1_15)))
 (let ((?x3510 (ite $x3313 1 0)))
 (let (($x3298 (or c_0_1 c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8 c_0_9 c_0_10 c_0_11 c_0_12 c_0_13 c_0_14 c_0_15)))
 (let ((?x3500 (ite $x3298 1 0)))
 (let ((?x3506 (+ 0 ?x3500)))
 (let ((?x3511 (+ ?x3506 ?x3510)))
 (let ((?x3504 (+ ?x3511 ?x3514)))
 (let ((?x3518 (+ ?x3504 ?x3517)))
 (let ((?x3513 (+ ?x3518 ?x3509)))
 (let (($x3512 (>= (+ ?x3513 ?x3515) 1)))
 (let ((?x5294 (ite root_107 1 0)))
 (let ((?x5276 (ite root_105 1 0)))
 (let ((?x5261 (ite root_103 1 0)))
 (let ((?x5246 (ite root_101 1 0)))
 (let ((?x5228 (ite root_99 1 0)))
 (let ((?x5213 (ite root_97 1 0)))
 (let ((?x5214 (+ 0 ?x5213)))
 (let ((?x5229 (+ ?x5214 ?x5228)))
 (let ((?x5247 (+ ?x5229 ?x5246)))
 (let ((?x5262 (+ ?x5247 ?x5261)))
 (let ((?x5277 (+ ?x5262 ?x5276)))
 (let (($x5212 (or false root_97)))
 (let (($x5227 (or $x5212 root_99)))
 (let (($x5245 (or $x5227 root_101)))
 (let (($x5260 (or $x5245 root_103)))
 (let (($x5275 (or $x5260 root_105)))
 (let (($x3392 (or false $x3298)))
 (let (($x3409 (or $x3392 $x3313)))
 (let (($x3428 (or $x3409 $x3328)))
 (let (($x3444 (or $x3428 $x3343)))
 (let (($x3460 (or $x3444 $x3358)))
 (let (($x3479 (or $x3460 $x3373)))
 (let (($x5300 (or false (and $x3358 (< rank_104 rank_106)))))
 (let (($x5304 (not root_107)))
 (let (($x5305 (and $x3373 $x5304)))
 (let (($x5282 (or false (and $x3373 (< rank_106 rank_104)))))
 (let (($x5285 (or $x5282 (and $x3343 (< rank_102 rank_104)))))
 (let (($x5289 (not root_105)))
 (let (($x5290 (and $x3358 $x5289)))
 (let (($x5267 (or false (and $x3358 (< rank_104 rank_102)))))
 (let (($x5271 (not root_103)))
 (let (($x5272 (and $x3343 $x5271)))
 (let (($x5252 (or false (and $x3373 (< rank_106 rank_100)))))
 (let (($x5256 (not root_101)))
 (let (($x5257 (and $x3328 $x5256)))
 (let (($x5234 (or false (and $x3328 (< rank_100 rank_98)))))
 (let (($x5237 (or $x5234 (and $x3358 (< rank_104 rank_98)))))
 (let (($x5241 (not root_99)))
 (let (($x5242 (and $x3313 $x5241)))
 (let (($x5219 (or false (and $x3313 (< rank_98 rank_96)))))
 (let (($x5223 (not root_97)))
 (let (($x5224 (and $x3298 $x5223)))
 (let (($x5216 (and true (=> root_97 $x3298))))
 (let (($x5226 (and $x5216 (=> $x5224 (or $x5219 (and $x3343 (< rank_102 rank_96)))))))
 (let (($x5231 (and $x5226 (=> root_99 $x3313))))
 (let (($x5244 (and $x5231 (=> $x5242 (or $x5237 (and $x3298 (< rank_96 rank_98)))))))
 (let (($x5249 (and $x5244 (=> root_101 $x3328))))
 (let (($x5259 (and $x5249 (=> $x5257 (or $x5252 (and $x3313 (< rank_98 rank_100)))))))
 (let (($x5264 (and $x5259 (=> root_103 $x3343))))
 (let (($x5274 (and $x5264 (=> $x5272 (or $x5267 (and $x3298 (< rank_96 rank_102)))))))
 (let (($x5279 (and $x5274 (=> root_105 $x3358))))
 (let (($x5292 (and $x5279 (=> $x5290 (or $x5285 (and $x3313 (< rank_98 rank_104)))))))
 (let (($x5297 (and $x5292 (=> root_107 $x3373))))
 (let (($x5309 (and (and $x5297 (=> $x5305 (or $x5300 (and $x3328 (< rank_100 rank_106))))) (=> $x3479 (or $x5275 root_107)))))
 (let (($x5311 (and $x5309 (<= (+ ?x5277 ?x5294) 1))))
 (let (($x5312 (and true $x5311)))
 (let (($x5522 (= rule_instance 56)))
 (let (($x5521 (and $x5522 (and (and (and $x5312 $x3512) (and $x5381 $x3761)) (and $x5514 $x3998)))))
 (let ((?x5156 (ite root_95 1 0)))
 (let ((?x5138 (ite root_93 1 0)))
 (let ((?x5123 (ite root_91 1 0)))
 (let ((?x5108 (ite root_89 1 0)))
 (let ((?x5090 (ite root_87 1 0)))
 (let ((?x5075 (ite root_85 1 0)))
 (let ((?x5076 (+ 0 ?x5075)))
 (let ((?x5091 (+ ?x5076 ?x5090)))
 (let ((?x5109 (+ ?x5091 ?x5108)))
 (let ((?x5124 (+ ?x5109 ?x5123)))
 (let ((?x5139 (+ ?x5124 ?x5138)))
 (let (($x5074 (or false root_85)))
 (let (($x5089 (or $x5074 root_87)))
 (let (($x5107 (or $x5089 root_89)))
 (let (($x5122 (or $x5107 root_91)))
 (let (($x5137 (or $x5122 root_93)))
 (let (($x5162 (or false (and $x3852 (< rank_92 rank_94)))))
 (let (($x5166 (not root_95)))
 (let (($x5167 (and $x3867 $x5166)))
 (let (($x5144 (or false (and $x3867 (< rank_94 rank_92)))))
 (let (($x5147 (or $x5144 (and $x3837 (< rank_90 rank_92)))))
 (let (($x5151 (not root_93)))
 (let (($x5152 (and $x3852 $x5151)))
 (let (($x5129 (or false (and $x3852 (< rank_92 rank_90)))))
 (let (($x5133 (not root_91)))
 (let (($x5134 (and $x3837 $x5133)))
 (let (($x5114 (or false (and $x3867 (< rank_94 rank_88)))))
 (let (($x5118 (not root_89)))
 (let (($x5119 (and $x3822 $x5118)))
 (let (($x5096 (or false (and $x3822 (< rank_88 rank_86)))))
 (let (($x5099 (or $x5096 (and $x3852 (< rank_92 rank_86)))))
 (let (($x5103 (not root_87)))
 (let (($x5104 (and $x3807 $x5103)))
 (let (($x5081 (or false (and $x3807 (< rank_86 rank_84)))))
 (let (($x5085 (not root_85)))
 (let (($x5086 (and $x3792 $x5085)))
 (let (($x5078 (and true (=> root_85 $x3792))))
 (let (($x5088 (and $x5078 (=> $x5086 (or $x5081 (and $x3837 (< rank_90 rank_84)))))))
 (let (($x5093 (and $x5088 (=> root_87 $x3807))))
 (let (($x5106 (and $x5093 (=> $x5104 (or $x5099 (and $x3792 (< rank_84 rank_86)))))))
 (let (($x5111 (and $x5106 (=> root_89 $x3822))))
 (let (($x5121 (and $x5111 (=> $x5119 (or $x5114 (and $x3807 (< rank_86 rank_88)))))))
 (let (($x5126 (and $x5121 (=> root_91 $x3837))))
 (let (($x5136 (and $x5126 (=> $x5134 (or $x5129 (and $x3792 (< rank_84 rank_90)))))))
 (let (($x5141 (and $x5136 (=> root_93 $x3852))))
 (let (($x5154 (and $x5141 (=> $x5152 (or $x5147 (and $x3807 (< rank_86 rank_92)))))))
 (let (($x5159 (and $x5154 (=> root_95 $x3867))))
 (let (($x5171 (and (and $x5159 (=> $x5167 (or $x5162 (and $x3822 (< rank_88 rank_94))))) (=> $x3970 (or $x5137 root_95)))))
 (let (($x5173 (and $x5171 (<= (+ ?x5139 ?x5156) 1))))
 (let (($x5174 (and true $x5173)))
 (let (($x3599 (and true (=> c_1_0 d_1_14))))
 (let (($x3601 (and $x3599 (=> c_1_1 d_1_14))))
 (let (($x3603 (and $x3601 (=> c_1_2 d_1_14))))
 (let (($x3605 (and $x3603 (=> c_1_3 d_1_14))))
 (let (($x3607 (and $x3605 (=> c_1_4 d_1_14))))
 (let (($x3609 (and $x3607 (=> c_1_5 d_1_14))))
 (let (($x3611 (and $x3609 (=> c_1_6 d_1_14))))
 (let (($x3613 (and $x3611 (=> c_1_7 d_1_14))))
 (let (($x3615 (and $x3613 (=> c_1_8 d_1_14))))
 (let (($x3617 (and $x3615 (=> c_1_9 d_1_14))))
 (let (($x3619 (and $x3617 (=> c_1_10 d_1_14))))
 (let (($x3621 (and $x3619 (=> c_1_11 d_1_14))))
 (let (($x3623 (and $x3621 (=> c_1_12 d_1_14))))
 (let (($x3625 (and $x3623 (=> c_1_13 d_1_14))))
 (let (($x3627 (and $x3625 (=> c_1_14 d_1_14))))
 (let (($x3629 (and $x3627 (=> c_1_15 d_1_14))))
 (let (($x5010 (and true (=> c_0_0 d_0_7))))
 (let (($x5008 (and $x5010 (=> c_0_1 d_0_7))))
 (let (($x5012 (and $x5008 (=> c_0_2 d_0_7))))
 (let (($x5013 (and $x5012 (=> c_0_3 d_0_7))))
 (let (($x5007 (and $x5013 (=> c_0_4 d_0_7))))
 (let (($x5016 (and $x5007 (=> c_0_5 d_0_7))))
 (let (($x5018 (and $x5016 (=> c_0_6 d_0_7))))
 (let (($x5020 (and $x5018 (=> c_0_7 d_0_7))))
 (let (($x5022 (and $x5020 (=> c_0_8 d_0_7))))
 (let (($x5024 (and $x5022 (=> c_0_9 d_0_7))))
 (let (($x5026 (and $x5024 (=> c_0_10 d_0_7))))
 (let (($x5028 (and $x5026 (=> c_0_11 d_0_7))))
 (let (($x5030 (and $x5028 (=> c_0_12 d_0_7))))
 (let (($x5032 (and $x5030 (=> c_0_13 d_0_7))))
 (let (($x5034 (and $x5032 (=> c_0_14 d_0_7))))
 (let (($x5011 (and true c_0_1)))
 (let (($x5004 (and $x5011 c_1_1)))
 (let (($x5037 (and $x5004 (and $x5034 (=> c_0_15 d_0_7)))))
 (let (($x5038 (and $x5037 $x3629)))
 (let (($x5039 (and $x5038 $x3662)))
 (let (($x5040 (and $x5039 $x3695)))
 (let (($x5041 (and $x5040 $x3728)))
 (let ((?x4983 (ite root_83 1 0)))
 (let ((?x4965 (ite root_81 1 0)))
 (let ((?x4950 (ite root_79 1 0)))
 (let ((?x4935 (ite root_77 1 0)))
 (let ((?x4917 (ite root_75 1 0)))
 (let ((?x4902 (ite root_73 1 0)))
 (let ((?x4903 (+ 0 ?x4902)))
 (let ((?x4918 (+ ?x4903 ?x4917)))
 (let ((?x4936 (+ ?x4918 ?x4935)))
 (let ((?x4951 (+ ?x4936 ?x4950)))
 (let ((?x4966 (+ ?x4951 ?x4965)))
 (let (($x4901 (or false root_73)))
 (let (($x4916 (or $x4901 root_75)))
 (let (($x4934 (or $x4916 root_77)))
 (let (($x4949 (or $x4934 root_79)))
 (let (($x4964 (or $x4949 root_81)))
 (let (($x4989 (or false (and $x3358 (< rank_80 rank_82)))))
 (let (($x4993 (not root_83)))
 (let (($x4994 (and $x3373 $x4993)))
 (let (($x4971 (or false (and $x3373 (< rank_82 rank_80)))))
 (let (($x4974 (or $x4971 (and $x3343 (< rank_78 rank_80)))))
 (let (($x4978 (not root_81)))
 (let (($x4979 (and $x3358 $x4978)))
 (let (($x4956 (or false (and $x3358 (< rank_80 rank_78)))))
 (let (($x4960 (not root_79)))
 (let (($x4961 (and $x3343 $x4960)))
 (let (($x4941 (or false (and $x3373 (< rank_82 rank_76)))))
 (let (($x4945 (not root_77)))
 (let (($x4946 (and $x3328 $x4945)))
 (let (($x4923 (or false (and $x3328 (< rank_76 rank_74)))))
 (let (($x4926 (or $x4923 (and $x3358 (< rank_80 rank_74)))))
 (let (($x4930 (not root_75)))
 (let (($x4931 (and $x3313 $x4930)))
 (let (($x4908 (or false (and $x3313 (< rank_74 rank_72)))))
 (let (($x4912 (not root_73)))
 (let (($x4913 (and $x3298 $x4912)))
 (let (($x4905 (and true (=> root_73 $x3298))))
 (let (($x4915 (and $x4905 (=> $x4913 (or $x4908 (and $x3343 (< rank_78 rank_72)))))))
 (let (($x4920 (and $x4915 (=> root_75 $x3313))))
 (let (($x4933 (and $x4920 (=> $x4931 (or $x4926 (and $x3298 (< rank_72 rank_74)))))))
 (let (($x4938 (and $x4933 (=> root_77 $x3328))))
 (let (($x4948 (and $x4938 (=> $x4946 (or $x4941 (and $x3313 (< rank_74 rank_76)))))))
 (let (($x4953 (and $x4948 (=> root_79 $x3343))))
 (let (($x4963 (and $x4953 (=> $x4961 (or $x4956 (and $x3298 (< rank_72 rank_78)))))))
 (let (($x4968 (and $x4963 (=> root_81 $x3358))))
 (let (($x4981 (and $x4968 (=> $x4979 (or $x4974 (and $x3313 (< rank_74 rank_80)))))))
 (let (($x4986 (and $x4981 (=> root_83 $x3373))))
 (let (($x4998 (and (and $x4986 (=> $x4994 (or $x4989 (and $x3328 (< rank_76 rank_82))))) (=> $x3479 (or $x4964 root_83)))))
 (let (($x5000 (and $x4998 (<= (+ ?x4966 ?x4983) 1))))
 (let (($x5001 (and true $x5000)))
 (let (($x5182 (= rule_instance 42)))
 (let (($x5181 (and $x5182 (and (and (and $x5001 $x3512) (and $x5041 $x3761)) (and $x5174 $x3998)))))
 (let ((?x4845 (ite root_71 1 0)))
 (let ((?x4827 (ite root_69 1 0)))
 (let ((?x4812 (ite root_67 1 0)))
 (let ((?x4797 (ite root_65 1 0)))
 (let ((?x4779 (ite root_63 1 0)))
 (let ((?x4764 (ite root_61 1 0)))
 (let ((?x4765 (+ 0 ?x4764)))
 (let ((?x4780 (+ ?x4765 ?x4779)))
 (let ((?x4798 (+ ?x4780 ?x4797)))
 (let ((?x4813 (+ ?x4798 ?x4812)))
 (let ((?x4828 (+ ?x4813 ?x4827)))
 (let (($x4763 (or false root_61)))
 (let (($x4778 (or $x4763 root_63)))
 (let (($x4796 (or $x4778 root_65)))
 (let (($x4811 (or $x4796 root_67)))
 (let (($x4826 (or $x4811 root_69)))
 (let (($x4851 (or false (and $x3852 (< rank_68 rank_70)))))
 (let (($x4855 (not root_71)))
 (let (($x4856 (and $x3867 $x4855)))
 (let (($x4833 (or false (and $x3867 (< rank_70 rank_68)))))
 (let (($x4836 (or $x4833 (and $x3837 (< rank_66 rank_68)))))
 (let (($x4840 (not root_69)))
 (let (($x4841 (and $x3852 $x4840)))
 (let (($x4818 (or false (and $x3852 (< rank_68 rank_66)))))
 (let (($x4822 (not root_67)))
 (let (($x4823 (and $x3837 $x4822)))
 (let (($x4803 (or false (and $x3867 (< rank_70 rank_64)))))
 (let (($x4807 (not root_65)))
 (let (($x4808 (and $x3822 $x4807)))
 (let (($x4785 (or false (and $x3822 (< rank_64 rank_62)))))
 (let (($x4788 (or $x4785 (and $x3852 (< rank_68 rank_62)))))
 (let (($x4792 (not root_63)))
 (let (($x4793 (and $x3807 $x4792)))
 (let (($x4770 (or false (and $x3807 (< rank_62 rank_60)))))
 (let (($x4774 (not root_61)))
 (let (($x4775 (and $x3792 $x4774)))
 (let (($x4767 (and true (=> root_61 $x3792))))
 (let (($x4777 (and $x4767 (=> $x4775 (or $x4770 (and $x3837 (< rank_66 rank_60)))))))
 (let (($x4782 (and $x4777 (=> root_63 $x3807))))
 (let (($x4795 (and $x4782 (=> $x4793 (or $x4788 (and $x3792 (< rank_60 rank_62)))))))
 (let (($x4800 (and $x4795 (=> root_65 $x3822))))
 (let (($x4810 (and $x4800 (=> $x4808 (or $x4803 (and $x3807 (< rank_62 rank_64)))))))
 (let (($x4815 (and $x4810 (=> root_67 $x3837))))
 (let (($x4825 (and $x4815 (=> $x4823 (or $x4818 (and $x3792 (< rank_60 rank_66)))))))
 (let (($x4830 (and $x4825 (=> root_69 $x3852))))
 (let (($x4843 (and $x4830 (=> $x4841 (or $x4836 (and $x3807 (< rank_62 rank_68)))))))
 (let (($x4848 (and $x4843 (=> root_71 $x3867))))
 (let (($x4860 (and (and $x4848 (=> $x4856 (or $x4851 (and $x3822 (< rank_64 rank_70))))) (=> $x3970 (or $x4826 root_71)))))
 (let (($x4862 (and $x4860 (<= (+ ?x4828 ?x4845) 1))))
 (let (($x4863 (and true $x4862)))
 (let (($x4696 (and true (=> c_1_0 d_1_1))))
 (let (($x4698 (and $x4696 (=> c_1_1 d_1_1))))
 (let (($x4700 (and $x4698 (=> c_1_2 d_1_1))))
 (let (($x4702 (and $x4700 (=> c_1_3 d_1_1))))
 (let (($x4704 (and $x4702 (=> c_1_4 d_1_1))))
 (let (($x4706 (and $x4704 (=> c_1_5 d_1_1))))
 (let (($x4708 (and $x4706 (=> c_1_6 d_1_1))))
 (let (($x4710 (and $x4708 (=> c_1_7 d_1_1))))
 (let (($x4712 (and $x4710 (=> c_1_8 d_1_1))))
 (let (($x4714 (and $x4712 (=> c_1_9 d_1_1))))
 (let (($x4716 (and $x4714 (=> c_1_10 d_1_1))))
 (let (($x4718 (and $x4716 (=> c_1_11 d_1_1))))
 (let (($x4720 (and $x4718 (=> c_1_12 d_1_1))))
 (let (($x4722 (and $x4720 (=> c_1_13 d_1_1))))
 (let (($x4724 (and $x4722 (=> c_1_14 d_1_1))))
 (let (($x4669 (and $x4665 (=> c_0_2 d_0_1))))
 (let (($x4670 (and $x4669 (=> c_0_3 d_0_1))))
 (let (($x4664 (and $x4670 (=> c_0_4 d_0_1))))
 (let (($x4673 (and $x4664 (=> c_0_5 d_0_1))))
 (let (($x4675 (and $x4673 $x4674)))
 (let (($x4677 (and $x4675 (=> c_0_7 d_0_1))))
 (let (($x4679 (and $x4677 (=> c_0_8 d_0_1))))
 (let (($x4681 (and $x4679 (=> c_0_9 d_0_1))))
 (let (($x4683 (and $x4681 (=> c_0_10 d_0_1))))
 (let (($x4685 (and $x4683 $x4684)))
 (let (($x4687 (and $x4685 (=> c_0_12 d_0_1))))
 (let (($x4689 (and $x4687 (=> c_0_13 d_0_1))))
 (let (($x4691 (and $x4689 (=> c_0_14 d_0_1))))
 (let (($x4668 (and true c_0_7)))
 (let (($x4661 (and $x4668 c_1_14)))
 (let (($x4694 (and $x4661 (and $x4691 (=> c_0_15 d_0_1)))))
 (let (($x4727 (and $x4694 (and $x4724 (=> c_1_15 d_1_1)))))
 (let (($x4728 (and $x4727 $x3662)))
 (let (($x4729 (and $x4728 $x3695)))
 (let (($x4730 (and $x4729 $x3728)))
 (let ((?x4640 (ite root_59 1 0)))
 (let ((?x4622 (ite root_57 1 0)))
 (let ((?x4607 (ite root_55 1 0)))
 (let ((?x4592 (ite root_53 1 0)))
 (let ((?x4574 (ite root_51 1 0)))
 (let ((?x4559 (ite root_49 1 0)))
 (let ((?x4560 (+ 0 ?x4559)))
 (let ((?x4575 (+ ?x4560 ?x4574)))
 (let ((?x4593 (+ ?x4575 ?x4592)))
 (let ((?x4608 (+ ?x4593 ?x4607)))
 (let ((?x4623 (+ ?x4608 ?x4622)))
 (let (($x4558 (or false root_49)))
 (let (($x4573 (or $x4558 root_51)))
 (let (($x4591 (or $x4573 root_53)))
 (let (($x4606 (or $x4591 root_55)))
 (let (($x4621 (or $x4606 root_57)))
 (let (($x4646 (or false (and $x3358 (< rank_56 rank_58)))))
 (let (($x4650 (not root_59)))
 (let (($x4651 (and $x3373 $x4650)))
 (let (($x4628 (or false (and $x3373 (< rank_58 rank_56)))))
 (let (($x4631 (or $x4628 (and $x3343 (< rank_54 rank_56)))))
 (let (($x4635 (not root_57)))
 (let (($x4636 (and $x3358 $x4635)))
 (let (($x4613 (or false (and $x3358 (< rank_56 rank_54)))))
 (let (($x4617 (not root_55)))
 (let (($x4618 (and $x3343 $x4617)))
 (let (($x4598 (or false (and $x3373 (< rank_58 rank_52)))))
 (let (($x4602 (not root_53)))
 (let (($x4603 (and $x3328 $x4602)))
 (let (($x4580 (or false (and $x3328 (< rank_52 rank_50)))))
 (let (($x4583 (or $x4580 (and $x3358 (< rank_56 rank_50)))))
 (let (($x4587 (not root_51)))
 (let (($x4588 (and $x3313 $x4587)))
 (let (($x4565 (or false (and $x3313 (< rank_50 rank_48)))))
 (let (($x4569 (not root_49)))
 (let (($x4570 (and $x3298 $x4569)))
 (let (($x4562 (and true (=> root_49 $x3298))))
 (let (($x4572 (and $x4562 (=> $x4570 (or $x4565 (and $x3343 (< rank_54 rank_48)))))))
 (let (($x4577 (and $x4572 (=> root_51 $x3313))))
 (let (($x4590 (and $x4577 (=> $x4588 (or $x4583 (and $x3298 (< rank_48 rank_50)))))))
 (let (($x4595 (and $x4590 (=> root_53 $x3328))))
 (let (($x4605 (and $x4595 (=> $x4603 (or $x4598 (and $x3313 (< rank_50 rank_52)))))))
 (let (($x4610 (and $x4605 (=> root_55 $x3343))))
 (let (($x4620 (and $x4610 (=> $x4618 (or $x4613 (and $x3298 (< rank_48 rank_54)))))))
 (let (($x4625 (and $x4620 (=> root_57 $x3358))))
 (let (($x4638 (and $x4625 (=> $x4636 (or $x4631 (and $x3313 (< rank_50 rank_56)))))))
 (let (($x4643 (and $x4638 (=> root_59 $x3373))))
 (let (($x4655 (and (and $x4643 (=> $x4651 (or $x4646 (and $x3328 (< rank_52 rank_58))))) (=> $x3479 (or $x4621 root_59)))))
 (let (($x4657 (and $x4655 (<= (+ ?x4623 ?x4640) 1))))
 (let (($x4658 (and true $x4657)))
 (let (($x4871 (= rule_instance 28)))
 (let (($x4870 (and $x4871 (and (and (and $x4658 $x3512) (and $x4730 $x3761)) (and $x4863 $x3998)))))
 (let ((?x4502 (ite root_47 1 0)))
 (let ((?x4484 (ite root_45 1 0)))
 (let ((?x4469 (ite root_43 1 0)))
 (let ((?x4454 (ite root_41 1 0)))
 (let ((?x4436 (ite root_39 1 0)))
 (let ((?x4421 (ite root_37 1 0)))
 (let ((?x4422 (+ 0 ?x4421)))
 (let ((?x4437 (+ ?x4422 ?x4436)))
 (let ((?x4455 (+ ?x4437 ?x4454)))
 (let ((?x4470 (+ ?x4455 ?x4469)))
 (let ((?x4485 (+ ?x4470 ?x4484)))
 (let (($x4420 (or false root_37)))
 (let (($x4435 (or $x4420 root_39)))
 (let (($x4453 (or $x4435 root_41)))
 (let (($x4468 (or $x4453 root_43)))
 (let (($x4483 (or $x4468 root_45)))
 (let (($x4508 (or false (and $x3852 (< rank_44 rank_46)))))
 (let (($x4512 (not root_47)))
 (let (($x4513 (and $x3867 $x4512)))
 (let (($x4490 (or false (and $x3867 (< rank_46 rank_44)))))
 (let (($x4493 (or $x4490 (and $x3837 (< rank_42 rank_44)))))
 (let (($x4497 (not root_45)))
 (let (($x4498 (and $x3852 $x4497)))
 (let (($x4475 (or false (and $x3852 (< rank_44 rank_42)))))
 (let (($x4479 (not root_43)))
 (let (($x4480 (and $x3837 $x4479)))
 (let (($x4460 (or false (and $x3867 (< rank_46 rank_40)))))
 (let (($x4464 (not root_41)))
 (let (($x4465 (and $x3822 $x4464)))
 (let (($x4442 (or false (and $x3822 (< rank_40 rank_38)))))
 (let (($x4445 (or $x4442 (and $x3852 (< rank_44 rank_38)))))
 (let (($x4449 (not root_39)))
 (let (($x4450 (and $x3807 $x4449)))
 (let (($x4427 (or false (and $x3807 (< rank_38 rank_36)))))
 (let (($x4431 (not root_37)))
 (let (($x4432 (and $x3792 $x4431)))
 (let (($x4424 (and true (=> root_37 $x3792))))
 (let (($x4434 (and $x4424 (=> $x4432 (or $x4427 (and $x3837 (< rank_42 rank_36)))))))
 (let (($x4439 (and $x4434 (=> root_39 $x3807))))
 (let (($x4452 (and $x4439 (=> $x4450 (or $x4445 (and $x3792 (< rank_36 rank_38)))))))
 (let (($x4457 (and $x4452 (=> root_41 $x3822))))
 (let (($x4467 (and $x4457 (=> $x4465 (or $x4460 (and $x3807 (< rank_38 rank_40)))))))
 (let (($x4472 (and $x4467 (=> root_43 $x3837))))
 (let (($x4482 (and $x4472 (=> $x4480 (or $x4475 (and $x3792 (< rank_36 rank_42)))))))
 (let (($x4487 (and $x4482 (=> root_45 $x3852))))
 (let (($x4500 (and $x4487 (=> $x4498 (or $x4493 (and $x3807 (< rank_38 rank_44)))))))
 (let (($x4505 (and $x4500 (=> root_47 $x3867))))
 (let (($x4517 (and (and $x4505 (=> $x4513 (or $x4508 (and $x3822 (< rank_40 rank_46))))) (=> $x3970 (or $x4483 root_47)))))
 (let (($x4519 (and $x4517 (<= (+ ?x4485 ?x4502) 1))))
 (let (($x4520 (and true $x4519)))
 (let (($x4353 (and true (=> c_1_0 d_1_0))))
 (let (($x4355 (and $x4353 (=> c_1_1 d_1_0))))
 (let (($x4357 (and $x4355 (=> c_1_2 d_1_0))))
 (let (($x4359 (and $x4357 (=> c_1_3 d_1_0))))
 (let (($x4361 (and $x4359 (=> c_1_4 d_1_0))))
 (let (($x4363 (and $x4361 (=> c_1_5 d_1_0))))
 (let (($x4365 (and $x4363 (=> c_1_6 d_1_0))))
 (let (($x4367 (and $x4365 (=> c_1_7 d_1_0))))
 (let (($x4369 (and $x4367 (=> c_1_8 d_1_0))))
 (let (($x4371 (and $x4369 (=> c_1_9 d_1_0))))
 (let (($x4373 (and $x4371 (=> c_1_10 d_1_0))))
 (let (($x4375 (and $x4373 (=> c_1_11 d_1_0))))
 (let (($x4377 (and $x4375 (=> c_1_12 d_1_0))))
 (let (($x4379 (and $x4377 (=> c_1_13 d_1_0))))
 (let (($x4381 (and $x4379 (=> c_1_14 d_1_0))))
 (let (($x4324 (and true (=> c_0_0 d_0_6))))
 (let (($x4322 (and $x4324 (=> c_0_1 d_0_6))))
 (let (($x4326 (and $x4322 (=> c_0_2 d_0_6))))
 (let (($x4327 (and $x4326 (=> c_0_3 d_0_6))))
 (let (($x4321 (and $x4327 (=> c_0_4 d_0_6))))
 (let (($x4330 (and $x4321 (=> c_0_5 d_0_6))))
 (let (($x4332 (and $x4330 (=> c_0_6 d_0_6))))
 (let (($x4334 (and $x4332 (=> c_0_7 d_0_6))))
 (let (($x4336 (and $x4334 (=> c_0_8 d_0_6))))
 (let (($x4338 (and $x4336 (=> c_0_9 d_0_6))))
 (let (($x4340 (and $x4338 (=> c_0_10 d_0_6))))
 (let (($x4342 (and $x4340 (=> c_0_11 d_0_6))))
 (let (($x4344 (and $x4342 (=> c_0_12 d_0_6))))
 (let (($x4346 (and $x4344 (=> c_0_13 d_0_6))))
 (let (($x4348 (and $x4346 (=> c_0_14 d_0_6))))
 (let (($x4325 (and true c_0_2)))
 (let (($x4318 (and $x4325 c_1_14)))
 (let (($x4351 (and $x4318 (and $x4348 (=> c_0_15 d_0_6)))))
 (let (($x4384 (and $x4351 (and $x4381 (=> c_1_15 d_1_0)))))
 (let (($x4385 (and $x4384 $x3662)))
 (let (($x4386 (and $x4385 $x3695)))
 (let (($x4387 (and $x4386 $x3728)))
 (let ((?x4297 (ite root_35 1 0)))
 (let ((?x4279 (ite root_33 1 0)))
 (let ((?x4264 (ite root_31 1 0)))
 (let ((?x4249 (ite root_29 1 0)))
 (let ((?x4231 (ite root_27 1 0)))
 (let ((?x4216 (ite root_25 1 0)))
 (let ((?x4217 (+ 0 ?x4216)))
 (let ((?x4232 (+ ?x4217 ?x4231)))
 (let ((?x4250 (+ ?x4232 ?x4249)))
 (let ((?x4265 (+ ?x4250 ?x4264)))
 (let ((?x4280 (+ ?x4265 ?x4279)))
 (let (($x4215 (or false root_25)))
 (let (($x4230 (or $x4215 root_27)))
 (let (($x4248 (or $x4230 root_29)))
 (let (($x4263 (or $x4248 root_31)))
 (let (($x4278 (or $x4263 root_33)))
 (let (($x4303 (or false (and $x3358 (< rank_32 rank_34)))))
 (let (($x4307 (not root_35)))
 (let (($x4308 (and $x3373 $x4307)))
 (let (($x4285 (or false (and $x3373 (< rank_34 rank_32)))))
 (let (($x4288 (or $x4285 (and $x3343 (< rank_30 rank_32)))))
 (let (($x4292 (not root_33)))
 (let (($x4293 (and $x3358 $x4292)))
 (let (($x4270 (or false (and $x3358 (< rank_32 rank_30)))))
 (let (($x4274 (not root_31)))
 (let (($x4275 (and $x3343 $x4274)))
 (let (($x4255 (or false (and $x3373 (< rank_34 rank_28)))))
 (let (($x4259 (not root_29)))
 (let (($x4260 (and $x3328 $x4259)))
 (let (($x4237 (or false (and $x3328 (< rank_28 rank_26)))))
 (let (($x4240 (or $x4237 (and $x3358 (< rank_32 rank_26)))))
 (let (($x4244 (not root_27)))
 (let (($x4245 (and $x3313 $x4244)))
 (let (($x4222 (or false (and $x3313 (< rank_26 rank_24)))))
 (let (($x4226 (not root_25)))
 (let (($x4227 (and $x3298 $x4226)))
 (let (($x4219 (and true (=> root_25 $x3298))))
 (let (($x4229 (and $x4219 (=> $x4227 (or $x4222 (and $x3343 (< rank_30 rank_24)))))))
 (let (($x4234 (and $x4229 (=> root_27 $x3313))))
 (let (($x4247 (and $x4234 (=> $x4245 (or $x4240 (and $x3298 (< rank_24 rank_26)))))))
 (let (($x4252 (and $x4247 (=> root_29 $x3328))))
 (let (($x4262 (and $x4252 (=> $x4260 (or $x4255 (and $x3313 (< rank_26 rank_28)))))))
 (let (($x4267 (and $x4262 (=> root_31 $x3343))))
 (let (($x4277 (and $x4267 (=> $x4275 (or $x4270 (and $x3298 (< rank_24 rank_30)))))))
 (let (($x4282 (and $x4277 (=> root_33 $x3358))))
 (let (($x4295 (and $x4282 (=> $x4293 (or $x4288 (and $x3313 (< rank_26 rank_32)))))))
 (let (($x4300 (and $x4295 (=> root_35 $x3373))))
 (let (($x4312 (and (and $x4300 (=> $x4308 (or $x4303 (and $x3328 (< rank_28 rank_34))))) (=> $x3479 (or $x4278 root_35)))))
 (let (($x4314 (and $x4312 (<= (+ ?x4280 ?x4297) 1))))
 (let (($x4315 (and true $x4314)))
 (let (($x4528 (= rule_instance 14)))
 (let (($x4527 (and $x4528 (and (and (and $x4315 $x3512) (and $x4387 $x3761)) (and $x4520 $x3998)))))
 (let ((?x3972 (ite root_23 1 0)))
 (let ((?x3953 (ite root_21 1 0)))
 (let ((?x3937 (ite root_19 1 0)))
 (let ((?x3921 (ite root_17 1 0)))
 (let ((?x3902 (ite root_15 1 0)))
 (let ((?x3886 (ite root_13 1 0)))
 (let ((?x3887 (+ 0 ?x3886)))
 (let ((?x3903 (+ ?x3887 ?x3902)))
 (let ((?x3922 (+ ?x3903 ?x3921)))
 (let ((?x3938 (+ ?x3922 ?x3937)))
 (let ((?x3954 (+ ?x3938 ?x3953)))
 (let (($x3885 (or false root_13)))
 (let (($x3901 (or $x3885 root_15)))
 (let (($x3920 (or $x3901 root_17)))
 (let (($x3936 (or $x3920 root_19)))
 (let (($x3952 (or $x3936 root_21)))
 (let (($x3978 (or false (and $x3852 (< rank_20 rank_22)))))
 (let (($x3982 (not root_23)))
 (let (($x3983 (and $x3867 $x3982)))
 (let (($x3959 (or false (and $x3867 (< rank_22 rank_20)))))
 (let (($x3962 (or $x3959 (and $x3837 (< rank_18 rank_20)))))
 (let (($x3966 (not root_21)))
 (let (($x3967 (and $x3852 $x3966)))
 (let (($x3943 (or false (and $x3852 (< rank_20 rank_18)))))
 (let (($x3947 (not root_19)))
 (let (($x3948 (and $x3837 $x3947)))
 (let (($x3927 (or false (and $x3867 (< rank_22 rank_16)))))
 (let (($x3931 (not root_17)))
 (let (($x3932 (and $x3822 $x3931)))
 (let (($x3908 (or false (and $x3822 (< rank_16 rank_14)))))
 (let (($x3911 (or $x3908 (and $x3852 (< rank_20 rank_14)))))
 (let (($x3915 (not root_15)))
 (let (($x3916 (and $x3807 $x3915)))
 (let (($x3892 (or false (and $x3807 (< rank_14 rank_12)))))
 (let (($x3896 (not root_13)))
 (let (($x3897 (and $x3792 $x3896)))
 (let (($x3889 (and true (=> root_13 $x3792))))
 (let (($x3899 (and $x3889 (=> $x3897 (or $x3892 (and $x3837 (< rank_18 rank_12)))))))
 (let (($x3905 (and $x3899 (=> root_15 $x3807))))
 (let (($x3918 (and $x3905 (=> $x3916 (or $x3911 (and $x3792 (< rank_12 rank_14)))))))
 (let (($x3924 (and $x3918 (=> root_17 $x3822))))
 (let (($x3934 (and $x3924 (=> $x3932 (or $x3927 (and $x3807 (< rank_14 rank_16)))))))
 (let (($x3940 (and $x3934 (=> root_19 $x3837))))
 (let (($x3950 (and $x3940 (=> $x3948 (or $x3943 (and $x3792 (< rank_12 rank_18)))))))
 (let (($x3956 (and $x3950 (=> root_21 $x3852))))
 (let (($x3969 (and $x3956 (=> $x3967 (or $x3962 (and $x3807 (< rank_14 rank_20)))))))
 (let (($x3975 (and $x3969 (=> root_23 $x3867))))
 (let (($x3987 (and (and $x3975 (=> $x3983 (or $x3978 (and $x3822 (< rank_16 rank_22))))) (=> $x3970 (or $x3952 root_23)))))
 (let (($x3989 (and $x3987 (<= (+ ?x3954 ?x3972) 1))))
 (let (($x3990 (and true $x3989)))
 (let (($x3566 (and true (=> c_0_0 d_0_2))))
 (let (($x3568 (and $x3566 (=> c_0_1 d_0_2))))
 (let (($x3570 (and $x3568 $x3569)))
 (let (($x3572 (and $x3570 (=> c_0_3 d_0_2))))
 (let (($x3574 (and $x3572 (=> c_0_4 d_0_2))))
 (let (($x3576 (and $x3574 (=> c_0_5 d_0_2))))
 (let (($x3578 (and $x3576 (=> c_0_6 d_0_2))))
 (let (($x3580 (and $x3578 $x3579)))
 (let (($x3582 (and $x3580 (=> c_0_8 d_0_2))))
 (let (($x3584 (and $x3582 (=> c_0_9 d_0_2))))
 (let (($x3586 (and $x3584 (=> c_0_10 d_0_2))))
 (let (($x3588 (and $x3586 (=> c_0_11 d_0_2))))
 (let (($x3590 (and $x3588 $x3589)))
 (let (($x3592 (and $x3590 (=> c_0_13 d_0_2))))
 (let (($x3594 (and $x3592 (=> c_0_14 d_0_2))))
 (let (($x3563 (and true c_0_6)))
 (let (($x3564 (and $x3563 c_1_0)))
 (let (($x3597 (and $x3564 (and $x3594 (=> c_0_15 d_0_2)))))
 (let (($x3630 (and $x3597 $x3629)))
 (let (($x3663 (and $x3630 $x3662)))
 (let (($x3696 (and $x3663 $x3695)))
 (let (($x3729 (and $x3696 $x3728)))
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
 (let (($x4180 (= rule_instance 0)))
 (let (($x4181 (and $x4180 (and (and (and $x3499 $x3512) (and $x3729 $x3761)) (and $x3990 $x3998)))))
 (let (($x4184 (or false (and $x4181 $x4182))))
 (let (($x4529 (or $x4184 (and $x4527 $x4182))))
 (let (($x4872 (or $x4529 (and $x4870 $x4182))))
 (let (($x5183 (or $x4872 (and $x5181 $x4182))))
 (or $x5183 (and $x5521 $x4182))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
