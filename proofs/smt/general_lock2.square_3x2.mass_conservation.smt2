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
 (let (($x3995 (>= rank_12 0)))
 (and $x3995 (< rank_12 6))))
(assert
 (let (($x3987 (>= rank_14 0)))
 (and $x3987 (< rank_14 6))))
(assert
 (let (($x3991 (>= rank_16 0)))
 (and $x3991 (< rank_16 6))))
(assert
 (let (($x3999 (>= rank_18 0)))
 (and $x3999 (< rank_18 6))))
(assert
 (let (($x4004 (>= rank_20 0)))
 (and $x4004 (< rank_20 6))))
(assert
 (let (($x4009 (>= rank_22 0)))
 (and $x4009 (< rank_22 6))))
(assert
 (let (($x4227 (>= rank_24 0)))
 (and $x4227 (< rank_24 6))))
(assert
 (let (($x4238 (>= rank_26 0)))
 (and $x4238 (< rank_26 6))))
(assert
 (let (($x4233 (>= rank_28 0)))
 (and $x4233 (< rank_28 6))))
(assert
 (let (($x4242 (>= rank_30 0)))
 (and $x4242 (< rank_30 6))))
(assert
 (let (($x4247 (>= rank_32 0)))
 (and $x4247 (< rank_32 6))))
(assert
 (let (($x4252 (>= rank_34 0)))
 (and $x4252 (< rank_34 6))))
(assert
 (let (($x4433 (>= rank_36 0)))
 (and $x4433 (< rank_36 6))))
(assert
 (let (($x4436 (>= rank_38 0)))
 (and $x4436 (< rank_38 6))))
(assert
 (let (($x4435 (>= rank_40 0)))
 (and $x4435 (< rank_40 6))))
(assert
 (let (($x4447 (>= rank_42 0)))
 (and $x4447 (< rank_42 6))))
(assert
 (let (($x4452 (>= rank_44 0)))
 (and $x4452 (< rank_44 6))))
(assert
 (let (($x4457 (>= rank_46 0)))
 (and $x4457 (< rank_46 6))))
(assert
 (let (($x4566 (>= rank_48 0)))
 (and $x4566 (< rank_48 6))))
(assert
 (let (($x4581 (>= rank_50 0)))
 (and $x4581 (< rank_50 6))))
(assert
 (let (($x4576 (>= rank_52 0)))
 (and $x4576 (< rank_52 6))))
(assert
 (let (($x4585 (>= rank_54 0)))
 (and $x4585 (< rank_54 6))))
(assert
 (let (($x4590 (>= rank_56 0)))
 (and $x4590 (< rank_56 6))))
(assert
 (let (($x4595 (>= rank_58 0)))
 (and $x4595 (< rank_58 6))))
(assert
 (let (($x4776 (>= rank_60 0)))
 (and $x4776 (< rank_60 6))))
(assert
 (let (($x4779 (>= rank_62 0)))
 (and $x4779 (< rank_62 6))))
(assert
 (let (($x4778 (>= rank_64 0)))
 (and $x4778 (< rank_64 6))))
(assert
 (let (($x4790 (>= rank_66 0)))
 (and $x4790 (< rank_66 6))))
(assert
 (let (($x4795 (>= rank_68 0)))
 (and $x4795 (< rank_68 6))))
(assert
 (let (($x4800 (>= rank_70 0)))
 (and $x4800 (< rank_70 6))))
(assert
 (let (($x4909 (>= rank_72 0)))
 (and $x4909 (< rank_72 6))))
(assert
 (let (($x4924 (>= rank_74 0)))
 (and $x4924 (< rank_74 6))))
(assert
 (let (($x4919 (>= rank_76 0)))
 (and $x4919 (< rank_76 6))))
(assert
 (let (($x4928 (>= rank_78 0)))
 (and $x4928 (< rank_78 6))))
(assert
 (let (($x4933 (>= rank_80 0)))
 (and $x4933 (< rank_80 6))))
(assert
 (let (($x4938 (>= rank_82 0)))
 (and $x4938 (< rank_82 6))))
(assert
 (let (($x5087 (>= rank_84 0)))
 (and $x5087 (< rank_84 6))))
(assert
 (let (($x5090 (>= rank_86 0)))
 (and $x5090 (< rank_86 6))))
(assert
 (let (($x5089 (>= rank_88 0)))
 (and $x5089 (< rank_88 6))))
(assert
 (let (($x5101 (>= rank_90 0)))
 (and $x5101 (< rank_90 6))))
(assert
 (let (($x5106 (>= rank_92 0)))
 (and $x5106 (< rank_92 6))))
(assert
 (let (($x5111 (>= rank_94 0)))
 (and $x5111 (< rank_94 6))))
(assert
 (let (($x5220 (>= rank_96 0)))
 (and $x5220 (< rank_96 6))))
(assert
 (let (($x5235 (>= rank_98 0)))
 (and $x5235 (< rank_98 6))))
(assert
 (let (($x5230 (>= rank_100 0)))
 (and $x5230 (< rank_100 6))))
(assert
 (let (($x5239 (>= rank_102 0)))
 (and $x5239 (< rank_102 6))))
(assert
 (let (($x5244 (>= rank_104 0)))
 (and $x5244 (< rank_104 6))))
(assert
 (let (($x5249 (>= rank_106 0)))
 (and $x5249 (< rank_106 6))))
(assert
 (let (($x5427 (>= rank_108 0)))
 (and $x5427 (< rank_108 6))))
(assert
 (let (($x5430 (>= rank_110 0)))
 (and $x5430 (< rank_110 6))))
(assert
 (let (($x5429 (>= rank_112 0)))
 (and $x5429 (< rank_112 6))))
(assert
 (let (($x5441 (>= rank_114 0)))
 (and $x5441 (< rank_114 6))))
(assert
 (let (($x5446 (>= rank_116 0)))
 (and $x5446 (< rank_116 6))))
(assert
 (let (($x5451 (>= rank_118 0)))
 (and $x5451 (< rank_118 6))))
(assert
 (let ((?x4217 (ite (or (or (or (or d_1_6 d_1_7) d_1_8) d_1_9) d_1_10) 3 0)))
 (let ((?x4215 (ite (or (or (or (or d_1_1 d_1_2) d_1_3) d_1_4) d_1_5) 2 0)))
 (let ((?x4213 (ite (or (or (or (or d_1_11 d_1_12) d_1_13) d_1_14) d_1_15) 1 0)))
 (let ((?x4214 (+ 0 ?x4213)))
 (let ((?x4216 (+ ?x4214 ?x4215)))
 (let ((?x4179 (ite (or (or (or (or d_0_6 d_0_7) d_0_8) d_0_9) d_0_10) 3 0)))
 (let ((?x4177 (ite (or (or (or (or d_0_1 d_0_2) d_0_3) d_0_4) d_0_5) 2 0)))
 (let ((?x4175 (ite (or (or (or (or d_0_11 d_0_12) d_0_13) d_0_14) d_0_15) 1 0)))
 (let ((?x4176 (+ 0 ?x4175)))
 (let ((?x4178 (+ ?x4176 ?x4177)))
 (let ((?x4181 (+ 0 (+ ?x4178 ?x4179))))
 (let ((?x4198 (ite (or (or (or (or c_1_6 c_1_7) c_1_8) c_1_9) c_1_10) 3 0)))
 (let ((?x4196 (ite (or (or (or (or c_1_1 c_1_2) c_1_3) c_1_4) c_1_5) 2 0)))
 (let ((?x4194 (ite (or (or (or (or c_1_11 c_1_12) c_1_13) c_1_14) c_1_15) 1 0)))
 (let ((?x4195 (+ 0 ?x4194)))
 (let ((?x4197 (+ ?x4195 ?x4196)))
 (let ((?x4160 (ite (or (or (or (or c_0_6 c_0_7) c_0_8) c_0_9) c_0_10) 3 0)))
 (let ((?x4157 (ite (or (or (or (or c_0_1 c_0_2) c_0_3) c_0_4) c_0_5) 2 0)))
 (let ((?x4154 (ite (or (or (or (or c_0_11 c_0_12) c_0_13) c_0_14) c_0_15) 1 0)))
 (let ((?x4155 (+ 0 ?x4154)))
 (let ((?x4158 (+ ?x4155 ?x4157)))
 (let ((?x4162 (+ 0 (+ ?x4158 ?x4160))))
 (let (($x4222 (and (distinct (+ ?x4162 (+ ?x4197 ?x4198)) (+ ?x4181 (+ ?x4216 ?x4217))) true)))
 (let (($x3996 (or d_5_1 d_5_2 d_5_3 d_5_4 d_5_5 d_5_6 d_5_7 d_5_8 d_5_9 d_5_10 d_5_11 d_5_12 d_5_13 d_5_14 d_5_15)))
 (let ((?x4137 (ite $x3996 1 0)))
 (let (($x3967 (or d_4_1 d_4_2 d_4_3 d_4_4 d_4_5 d_4_6 d_4_7 d_4_8 d_4_9 d_4_10 d_4_11 d_4_12 d_4_13 d_4_14 d_4_15)))
 (let ((?x4135 (ite $x3967 1 0)))
 (let (($x3938 (or d_3_1 d_3_2 d_3_3 d_3_4 d_3_5 d_3_6 d_3_7 d_3_8 d_3_9 d_3_10 d_3_11 d_3_12 d_3_13 d_3_14 d_3_15)))
 (let ((?x4127 (ite $x3938 1 0)))
 (let (($x3909 (or d_2_1 d_2_2 d_2_3 d_2_4 d_2_5 d_2_6 d_2_7 d_2_8 d_2_9 d_2_10 d_2_11 d_2_12 d_2_13 d_2_14 d_2_15)))
 (let ((?x4134 (ite $x3909 1 0)))
 (let (($x3880 (or d_1_1 d_1_2 d_1_3 d_1_4 d_1_5 d_1_6 d_1_7 d_1_8 d_1_9 d_1_10 d_1_11 d_1_12 d_1_13 d_1_14 d_1_15)))
 (let ((?x4121 (ite $x3880 1 0)))
 (let (($x3851 (or d_0_1 d_0_2 d_0_3 d_0_4 d_0_5 d_0_6 d_0_7 d_0_8 d_0_9 d_0_10 d_0_11 d_0_12 d_0_13 d_0_14 d_0_15)))
 (let ((?x4119 (ite $x3851 1 0)))
 (let ((?x4120 (+ 0 ?x4119)))
 (let ((?x4129 (+ ?x4120 ?x4121)))
 (let ((?x4123 (+ ?x4129 ?x4134)))
 (let ((?x4133 (+ ?x4123 ?x4127)))
 (let ((?x4136 (+ ?x4133 ?x4135)))
 (let (($x4122 (>= (+ ?x4136 ?x4137) 1)))
 (let ((?x5536 (ite root_119 1 0)))
 (let ((?x5518 (ite root_117 1 0)))
 (let ((?x5503 (ite root_115 1 0)))
 (let ((?x5488 (ite root_113 1 0)))
 (let ((?x5470 (ite root_111 1 0)))
 (let ((?x5455 (ite root_109 1 0)))
 (let ((?x5456 (+ 0 ?x5455)))
 (let ((?x5471 (+ ?x5456 ?x5470)))
 (let ((?x5489 (+ ?x5471 ?x5488)))
 (let ((?x5504 (+ ?x5489 ?x5503)))
 (let ((?x5519 (+ ?x5504 ?x5518)))
 (let (($x5454 (or false root_109)))
 (let (($x5469 (or $x5454 root_111)))
 (let (($x5487 (or $x5469 root_113)))
 (let (($x5502 (or $x5487 root_115)))
 (let (($x5517 (or $x5502 root_117)))
 (let (($x4012 (or false $x3851)))
 (let (($x4028 (or $x4012 $x3880)))
 (let (($x4047 (or $x4028 $x3909)))
 (let (($x4063 (or $x4047 $x3938)))
 (let (($x4079 (or $x4063 $x3967)))
 (let (($x4098 (or $x4079 $x3996)))
 (let (($x5542 (or false (and $x3967 (< rank_116 rank_118)))))
 (let (($x5546 (not root_119)))
 (let (($x5547 (and $x3996 $x5546)))
 (let (($x5524 (or false (and $x3996 (< rank_118 rank_116)))))
 (let (($x5527 (or $x5524 (and $x3938 (< rank_114 rank_116)))))
 (let (($x5531 (not root_117)))
 (let (($x5532 (and $x3967 $x5531)))
 (let (($x5509 (or false (and $x3967 (< rank_116 rank_114)))))
 (let (($x5513 (not root_115)))
 (let (($x5514 (and $x3938 $x5513)))
 (let (($x5494 (or false (and $x3996 (< rank_118 rank_112)))))
 (let (($x5498 (not root_113)))
 (let (($x5499 (and $x3909 $x5498)))
 (let (($x5476 (or false (and $x3909 (< rank_112 rank_110)))))
 (let (($x5479 (or $x5476 (and $x3967 (< rank_116 rank_110)))))
 (let (($x5483 (not root_111)))
 (let (($x5484 (and $x3880 $x5483)))
 (let (($x5461 (or false (and $x3880 (< rank_110 rank_108)))))
 (let (($x5465 (not root_109)))
 (let (($x5466 (and $x3851 $x5465)))
 (let (($x5458 (and true (=> root_109 $x3851))))
 (let (($x5468 (and $x5458 (=> $x5466 (or $x5461 (and $x3938 (< rank_114 rank_108)))))))
 (let (($x5473 (and $x5468 (=> root_111 $x3880))))
 (let (($x5486 (and $x5473 (=> $x5484 (or $x5479 (and $x3851 (< rank_108 rank_110)))))))
 (let (($x5491 (and $x5486 (=> root_113 $x3909))))
 (let (($x5501 (and $x5491 (=> $x5499 (or $x5494 (and $x3880 (< rank_110 rank_112)))))))
 (let (($x5506 (and $x5501 (=> root_115 $x3938))))
 (let (($x5516 (and $x5506 (=> $x5514 (or $x5509 (and $x3851 (< rank_108 rank_114)))))))
 (let (($x5521 (and $x5516 (=> root_117 $x3967))))
 (let (($x5534 (and $x5521 (=> $x5532 (or $x5527 (and $x3880 (< rank_110 rank_116)))))))
 (let (($x5539 (and $x5534 (=> root_119 $x3996))))
 (let (($x5551 (and (and $x5539 (=> $x5547 (or $x5542 (and $x3909 (< rank_112 rank_118))))) (=> $x4098 (or $x5517 root_119)))))
 (let (($x5553 (and $x5551 (<= (+ ?x5519 ?x5536) 1))))
 (let (($x5554 (and true $x5553)))
 (let (($x3804 (= c_5_15 d_5_15)))
 (let (($x3802 (= c_5_14 d_5_14)))
 (let (($x3800 (= c_5_13 d_5_13)))
 (let (($x3798 (= c_5_12 d_5_12)))
 (let (($x3796 (= c_5_11 d_5_11)))
 (let (($x3794 (= c_5_10 d_5_10)))
 (let (($x3792 (= c_5_9 d_5_9)))
 (let (($x3790 (= c_5_8 d_5_8)))
 (let (($x3788 (= c_5_7 d_5_7)))
 (let (($x3786 (= c_5_6 d_5_6)))
 (let (($x3784 (= c_5_5 d_5_5)))
 (let (($x3782 (= c_5_4 d_5_4)))
 (let (($x3780 (= c_5_3 d_5_3)))
 (let (($x3778 (= c_5_2 d_5_2)))
 (let (($x3776 (= c_5_1 d_5_1)))
 (let (($x3774 (= c_5_0 d_5_0)))
 (let (($x3775 (and true $x3774)))
 (let (($x3777 (and $x3775 $x3776)))
 (let (($x3779 (and $x3777 $x3778)))
 (let (($x3781 (and $x3779 $x3780)))
 (let (($x3783 (and $x3781 $x3782)))
 (let (($x3785 (and $x3783 $x3784)))
 (let (($x3787 (and $x3785 $x3786)))
 (let (($x3789 (and $x3787 $x3788)))
 (let (($x3791 (and $x3789 $x3790)))
 (let (($x3793 (and $x3791 $x3792)))
 (let (($x3795 (and $x3793 $x3794)))
 (let (($x3797 (and $x3795 $x3796)))
 (let (($x3799 (and $x3797 $x3798)))
 (let (($x3801 (and $x3799 $x3800)))
 (let (($x3803 (and $x3801 $x3802)))
 (let (($x3805 (and $x3803 $x3804)))
 (let (($x3771 (= c_4_15 d_4_15)))
 (let (($x3769 (= c_4_14 d_4_14)))
 (let (($x3767 (= c_4_13 d_4_13)))
 (let (($x3765 (= c_4_12 d_4_12)))
 (let (($x3763 (= c_4_11 d_4_11)))
 (let (($x3761 (= c_4_10 d_4_10)))
 (let (($x3759 (= c_4_9 d_4_9)))
 (let (($x3757 (= c_4_8 d_4_8)))
 (let (($x3755 (= c_4_7 d_4_7)))
 (let (($x3753 (= c_4_6 d_4_6)))
 (let (($x3751 (= c_4_5 d_4_5)))
 (let (($x3749 (= c_4_4 d_4_4)))
 (let (($x3747 (= c_4_3 d_4_3)))
 (let (($x3745 (= c_4_2 d_4_2)))
 (let (($x3743 (= c_4_1 d_4_1)))
 (let (($x3741 (= c_4_0 d_4_0)))
 (let (($x3742 (and true $x3741)))
 (let (($x3744 (and $x3742 $x3743)))
 (let (($x3746 (and $x3744 $x3745)))
 (let (($x3748 (and $x3746 $x3747)))
 (let (($x3750 (and $x3748 $x3749)))
 (let (($x3752 (and $x3750 $x3751)))
 (let (($x3754 (and $x3752 $x3753)))
 (let (($x3756 (and $x3754 $x3755)))
 (let (($x3758 (and $x3756 $x3757)))
 (let (($x3760 (and $x3758 $x3759)))
 (let (($x3762 (and $x3760 $x3761)))
 (let (($x3764 (and $x3762 $x3763)))
 (let (($x3766 (and $x3764 $x3765)))
 (let (($x3768 (and $x3766 $x3767)))
 (let (($x3770 (and $x3768 $x3769)))
 (let (($x3772 (and $x3770 $x3771)))
 (let (($x3738 (= c_3_15 d_3_15)))
 (let (($x3736 (= c_3_14 d_3_14)))
 (let (($x3734 (= c_3_13 d_3_13)))
 (let (($x3732 (= c_3_12 d_3_12)))
 (let (($x3730 (= c_3_11 d_3_11)))
 (let (($x3728 (= c_3_10 d_3_10)))
 (let (($x3726 (= c_3_9 d_3_9)))
 (let (($x3724 (= c_3_8 d_3_8)))
 (let (($x3722 (= c_3_7 d_3_7)))
 (let (($x3720 (= c_3_6 d_3_6)))
 (let (($x3718 (= c_3_5 d_3_5)))
 (let (($x3716 (= c_3_4 d_3_4)))
 (let (($x3714 (= c_3_3 d_3_3)))
 (let (($x3712 (= c_3_2 d_3_2)))
 (let (($x3710 (= c_3_1 d_3_1)))
 (let (($x3708 (= c_3_0 d_3_0)))
 (let (($x3709 (and true $x3708)))
 (let (($x3711 (and $x3709 $x3710)))
 (let (($x3713 (and $x3711 $x3712)))
 (let (($x3715 (and $x3713 $x3714)))
 (let (($x3717 (and $x3715 $x3716)))
 (let (($x3719 (and $x3717 $x3718)))
 (let (($x3721 (and $x3719 $x3720)))
 (let (($x3723 (and $x3721 $x3722)))
 (let (($x3725 (and $x3723 $x3724)))
 (let (($x3727 (and $x3725 $x3726)))
 (let (($x3729 (and $x3727 $x3728)))
 (let (($x3731 (and $x3729 $x3730)))
 (let (($x3733 (and $x3731 $x3732)))
 (let (($x3735 (and $x3733 $x3734)))
 (let (($x3737 (and $x3735 $x3736)))
 (let (($x3739 (and $x3737 $x3738)))
 (let (($x3705 (= c_2_15 d_2_15)))
 (let (($x3703 (= c_2_14 d_2_14)))
 (let (($x3701 (= c_2_13 d_2_13)))
 (let (($x3699 (= c_2_12 d_2_12)))
 (let (($x3697 (= c_2_11 d_2_11)))
 (let (($x3695 (= c_2_10 d_2_10)))
 (let (($x3693 (= c_2_9 d_2_9)))
 (let (($x3691 (= c_2_8 d_2_8)))
 (let (($x3689 (= c_2_7 d_2_7)))
 (let (($x3687 (= c_2_6 d_2_6)))
 (let (($x3685 (= c_2_5 d_2_5)))
 (let (($x3683 (= c_2_4 d_2_4)))
 (let (($x3681 (= c_2_3 d_2_3)))
 (let (($x3679 (= c_2_2 d_2_2)))
 (let (($x3677 (= c_2_1 d_2_1)))
 (let (($x3675 (= c_2_0 d_2_0)))
 (let (($x3676 (and true $x3675)))
 (let (($x3678 (and $x3676 $x3677)))
 (let (($x3680 (and $x3678 $x3679)))
 (let (($x3682 (and $x3680 $x3681)))
 (let (($x3684 (and $x3682 $x3683)))
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
 (let (($x5387 (and true (=> c_1_0 d_1_6))))
 (let (($x5389 (and $x5387 (=> c_1_1 d_1_6))))
 (let (($x5391 (and $x5389 (=> c_1_2 d_1_7))))
 (let (($x5393 (and $x5391 (=> c_1_3 d_1_8))))
 (let (($x5395 (and $x5393 (=> c_1_4 d_1_9))))
 (let (($x5397 (and $x5395 (=> c_1_5 d_1_10))))
 (let (($x5399 (and $x5397 (=> c_1_6 d_1_6))))
 (let (($x5401 (and $x5399 (=> c_1_7 d_1_7))))
 (let (($x5403 (and $x5401 (=> c_1_8 d_1_8))))
 (let (($x5405 (and $x5403 (=> c_1_9 d_1_9))))
 (let (($x5407 (and $x5405 (=> c_1_10 d_1_10))))
 (let (($x5409 (and $x5407 (=> c_1_11 d_1_6))))
 (let (($x5411 (and $x5409 (=> c_1_12 d_1_7))))
 (let (($x5413 (and $x5411 (=> c_1_13 d_1_8))))
 (let (($x5415 (and $x5413 (=> c_1_14 d_1_9))))
 (let (($x3633 (=> c_0_12 d_0_2)))
 (let (($x4724 (=> c_0_11 d_0_1)))
 (let (($x3623 (=> c_0_7 d_0_2)))
 (let (($x4714 (=> c_0_6 d_0_1)))
 (let (($x3613 (=> c_0_2 d_0_2)))
 (let (($x4703 (and true (=> c_0_0 d_0_1))))
 (let (($x4706 (and $x4703 (=> c_0_1 d_0_1))))
 (let (($x5360 (and $x4706 $x3613)))
 (let (($x5363 (and $x5360 (=> c_0_3 d_0_3))))
 (let (($x5355 (and $x5363 (=> c_0_4 d_0_4))))
 (let (($x5368 (and $x5355 (=> c_0_5 d_0_5))))
 (let (($x5369 (and $x5368 $x4714)))
 (let (($x5370 (and $x5369 $x3623)))
 (let (($x5372 (and $x5370 (=> c_0_8 d_0_3))))
 (let (($x5374 (and $x5372 (=> c_0_9 d_0_4))))
 (let (($x5376 (and $x5374 (=> c_0_10 d_0_5))))
 (let (($x5377 (and $x5376 $x4724)))
 (let (($x5378 (and $x5377 $x3633)))
 (let (($x5380 (and $x5378 (=> c_0_13 d_0_3))))
 (let (($x5382 (and $x5380 (=> c_0_14 d_0_4))))
 (let (($x5366 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x5362 (or c_0_6 c_0_7 c_0_8 c_0_9 c_0_10)))
 (let (($x5364 (and true $x5362)))
 (let (($x5359 (and $x5364 $x5366)))
 (let (($x5385 (and $x5359 (and $x5382 (=> c_0_15 d_0_5)))))
 (let (($x5418 (and $x5385 (and $x5415 (=> c_1_15 d_1_10)))))
 (let (($x5419 (and $x5418 $x3706)))
 (let (($x5420 (and $x5419 $x3739)))
 (let (($x5421 (and $x5420 $x3772)))
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
 (let ((?x5334 (ite root_107 1 0)))
 (let ((?x5316 (ite root_105 1 0)))
 (let ((?x5301 (ite root_103 1 0)))
 (let ((?x5286 (ite root_101 1 0)))
 (let ((?x5268 (ite root_99 1 0)))
 (let ((?x5253 (ite root_97 1 0)))
 (let ((?x5254 (+ 0 ?x5253)))
 (let ((?x5269 (+ ?x5254 ?x5268)))
 (let ((?x5287 (+ ?x5269 ?x5286)))
 (let ((?x5302 (+ ?x5287 ?x5301)))
 (let ((?x5317 (+ ?x5302 ?x5316)))
 (let (($x5252 (or false root_97)))
 (let (($x5267 (or $x5252 root_99)))
 (let (($x5285 (or $x5267 root_101)))
 (let (($x5300 (or $x5285 root_103)))
 (let (($x5315 (or $x5300 root_105)))
 (let (($x3476 (or false $x3313)))
 (let (($x3493 (or $x3476 $x3342)))
 (let (($x3512 (or $x3493 $x3371)))
 (let (($x3528 (or $x3512 $x3400)))
 (let (($x3544 (or $x3528 $x3429)))
 (let (($x3563 (or $x3544 $x3458)))
 (let (($x5340 (or false (and $x3429 (< rank_104 rank_106)))))
 (let (($x5344 (not root_107)))
 (let (($x5345 (and $x3458 $x5344)))
 (let (($x5322 (or false (and $x3458 (< rank_106 rank_104)))))
 (let (($x5325 (or $x5322 (and $x3400 (< rank_102 rank_104)))))
 (let (($x5329 (not root_105)))
 (let (($x5330 (and $x3429 $x5329)))
 (let (($x5307 (or false (and $x3429 (< rank_104 rank_102)))))
 (let (($x5311 (not root_103)))
 (let (($x5312 (and $x3400 $x5311)))
 (let (($x5292 (or false (and $x3458 (< rank_106 rank_100)))))
 (let (($x5296 (not root_101)))
 (let (($x5297 (and $x3371 $x5296)))
 (let (($x5274 (or false (and $x3371 (< rank_100 rank_98)))))
 (let (($x5277 (or $x5274 (and $x3429 (< rank_104 rank_98)))))
 (let (($x5281 (not root_99)))
 (let (($x5282 (and $x3342 $x5281)))
 (let (($x5259 (or false (and $x3342 (< rank_98 rank_96)))))
 (let (($x5263 (not root_97)))
 (let (($x5264 (and $x3313 $x5263)))
 (let (($x5256 (and true (=> root_97 $x3313))))
 (let (($x5266 (and $x5256 (=> $x5264 (or $x5259 (and $x3400 (< rank_102 rank_96)))))))
 (let (($x5271 (and $x5266 (=> root_99 $x3342))))
 (let (($x5284 (and $x5271 (=> $x5282 (or $x5277 (and $x3313 (< rank_96 rank_98)))))))
 (let (($x5289 (and $x5284 (=> root_101 $x3371))))
 (let (($x5299 (and $x5289 (=> $x5297 (or $x5292 (and $x3342 (< rank_98 rank_100)))))))
 (let (($x5304 (and $x5299 (=> root_103 $x3400))))
 (let (($x5314 (and $x5304 (=> $x5312 (or $x5307 (and $x3313 (< rank_96 rank_102)))))))
 (let (($x5319 (and $x5314 (=> root_105 $x3429))))
 (let (($x5332 (and $x5319 (=> $x5330 (or $x5325 (and $x3342 (< rank_98 rank_104)))))))
 (let (($x5337 (and $x5332 (=> root_107 $x3458))))
 (let (($x5349 (and (and $x5337 (=> $x5345 (or $x5340 (and $x3371 (< rank_100 rank_106))))) (=> $x3563 (or $x5315 root_107)))))
 (let (($x5351 (and $x5349 (<= (+ ?x5317 ?x5334) 1))))
 (let (($x5352 (and true $x5351)))
 (let (($x5566 (= rule_instance 56)))
 (let (($x5559 (and $x5566 (and (and (and $x5352 $x3602) (and $x5421 $x3805)) (and $x5554 $x4122)))))
 (let ((?x5196 (ite root_95 1 0)))
 (let ((?x5178 (ite root_93 1 0)))
 (let ((?x5163 (ite root_91 1 0)))
 (let ((?x5148 (ite root_89 1 0)))
 (let ((?x5130 (ite root_87 1 0)))
 (let ((?x5115 (ite root_85 1 0)))
 (let ((?x5116 (+ 0 ?x5115)))
 (let ((?x5131 (+ ?x5116 ?x5130)))
 (let ((?x5149 (+ ?x5131 ?x5148)))
 (let ((?x5164 (+ ?x5149 ?x5163)))
 (let ((?x5179 (+ ?x5164 ?x5178)))
 (let (($x5114 (or false root_85)))
 (let (($x5129 (or $x5114 root_87)))
 (let (($x5147 (or $x5129 root_89)))
 (let (($x5162 (or $x5147 root_91)))
 (let (($x5177 (or $x5162 root_93)))
 (let (($x5202 (or false (and $x3967 (< rank_92 rank_94)))))
 (let (($x5206 (not root_95)))
 (let (($x5207 (and $x3996 $x5206)))
 (let (($x5184 (or false (and $x3996 (< rank_94 rank_92)))))
 (let (($x5187 (or $x5184 (and $x3938 (< rank_90 rank_92)))))
 (let (($x5191 (not root_93)))
 (let (($x5192 (and $x3967 $x5191)))
 (let (($x5169 (or false (and $x3967 (< rank_92 rank_90)))))
 (let (($x5173 (not root_91)))
 (let (($x5174 (and $x3938 $x5173)))
 (let (($x5154 (or false (and $x3996 (< rank_94 rank_88)))))
 (let (($x5158 (not root_89)))
 (let (($x5159 (and $x3909 $x5158)))
 (let (($x5136 (or false (and $x3909 (< rank_88 rank_86)))))
 (let (($x5139 (or $x5136 (and $x3967 (< rank_92 rank_86)))))
 (let (($x5143 (not root_87)))
 (let (($x5144 (and $x3880 $x5143)))
 (let (($x5121 (or false (and $x3880 (< rank_86 rank_84)))))
 (let (($x5125 (not root_85)))
 (let (($x5126 (and $x3851 $x5125)))
 (let (($x5118 (and true (=> root_85 $x3851))))
 (let (($x5128 (and $x5118 (=> $x5126 (or $x5121 (and $x3938 (< rank_90 rank_84)))))))
 (let (($x5133 (and $x5128 (=> root_87 $x3880))))
 (let (($x5146 (and $x5133 (=> $x5144 (or $x5139 (and $x3851 (< rank_84 rank_86)))))))
 (let (($x5151 (and $x5146 (=> root_89 $x3909))))
 (let (($x5161 (and $x5151 (=> $x5159 (or $x5154 (and $x3880 (< rank_86 rank_88)))))))
 (let (($x5166 (and $x5161 (=> root_91 $x3938))))
 (let (($x5176 (and $x5166 (=> $x5174 (or $x5169 (and $x3851 (< rank_84 rank_90)))))))
 (let (($x5181 (and $x5176 (=> root_93 $x3967))))
 (let (($x5194 (and $x5181 (=> $x5192 (or $x5187 (and $x3880 (< rank_86 rank_92)))))))
 (let (($x5199 (and $x5194 (=> root_95 $x3996))))
 (let (($x5211 (and (and $x5199 (=> $x5207 (or $x5202 (and $x3909 (< rank_88 rank_94))))) (=> $x4098 (or $x5177 root_95)))))
 (let (($x5213 (and $x5211 (<= (+ ?x5179 ?x5196) 1))))
 (let (($x5214 (and true $x5213)))
 (let (($x3643 (and true (=> c_1_0 d_1_14))))
 (let (($x3645 (and $x3643 (=> c_1_1 d_1_14))))
 (let (($x3647 (and $x3645 (=> c_1_2 d_1_14))))
 (let (($x3649 (and $x3647 (=> c_1_3 d_1_14))))
 (let (($x3651 (and $x3649 (=> c_1_4 d_1_14))))
 (let (($x3653 (and $x3651 (=> c_1_5 d_1_14))))
 (let (($x3655 (and $x3653 (=> c_1_6 d_1_14))))
 (let (($x3657 (and $x3655 (=> c_1_7 d_1_14))))
 (let (($x3659 (and $x3657 (=> c_1_8 d_1_14))))
 (let (($x3661 (and $x3659 (=> c_1_9 d_1_14))))
 (let (($x3663 (and $x3661 (=> c_1_10 d_1_14))))
 (let (($x3665 (and $x3663 (=> c_1_11 d_1_14))))
 (let (($x3667 (and $x3665 (=> c_1_12 d_1_14))))
 (let (($x3669 (and $x3667 (=> c_1_13 d_1_14))))
 (let (($x3671 (and $x3669 (=> c_1_14 d_1_14))))
 (let (($x3673 (and $x3671 (=> c_1_15 d_1_14))))
 (let (($x5046 (and true (=> c_0_0 d_0_7))))
 (let (($x5049 (and $x5046 (=> c_0_1 d_0_7))))
 (let (($x5051 (and $x5049 (=> c_0_2 d_0_7))))
 (let (($x5045 (and $x5051 (=> c_0_3 d_0_7))))
 (let (($x5054 (and $x5045 (=> c_0_4 d_0_7))))
 (let (($x5056 (and $x5054 (=> c_0_5 d_0_7))))
 (let (($x5058 (and $x5056 (=> c_0_6 d_0_7))))
 (let (($x5060 (and $x5058 (=> c_0_7 d_0_7))))
 (let (($x5062 (and $x5060 (=> c_0_8 d_0_7))))
 (let (($x5064 (and $x5062 (=> c_0_9 d_0_7))))
 (let (($x5066 (and $x5064 (=> c_0_10 d_0_7))))
 (let (($x5068 (and $x5066 (=> c_0_11 d_0_7))))
 (let (($x5070 (and $x5068 (=> c_0_12 d_0_7))))
 (let (($x5072 (and $x5070 (=> c_0_13 d_0_7))))
 (let (($x5074 (and $x5072 (=> c_0_14 d_0_7))))
 (let (($x5043 (and true c_0_1)))
 (let (($x5047 (and $x5043 c_1_1)))
 (let (($x5077 (and $x5047 (and $x5074 (=> c_0_15 d_0_7)))))
 (let (($x5078 (and $x5077 $x3673)))
 (let (($x5079 (and $x5078 $x3706)))
 (let (($x5080 (and $x5079 $x3739)))
 (let (($x5081 (and $x5080 $x3772)))
 (let ((?x5023 (ite root_83 1 0)))
 (let ((?x5005 (ite root_81 1 0)))
 (let ((?x4990 (ite root_79 1 0)))
 (let ((?x4975 (ite root_77 1 0)))
 (let ((?x4957 (ite root_75 1 0)))
 (let ((?x4942 (ite root_73 1 0)))
 (let ((?x4943 (+ 0 ?x4942)))
 (let ((?x4958 (+ ?x4943 ?x4957)))
 (let ((?x4976 (+ ?x4958 ?x4975)))
 (let ((?x4991 (+ ?x4976 ?x4990)))
 (let ((?x5006 (+ ?x4991 ?x5005)))
 (let (($x4941 (or false root_73)))
 (let (($x4956 (or $x4941 root_75)))
 (let (($x4974 (or $x4956 root_77)))
 (let (($x4989 (or $x4974 root_79)))
 (let (($x5004 (or $x4989 root_81)))
 (let (($x5029 (or false (and $x3429 (< rank_80 rank_82)))))
 (let (($x5033 (not root_83)))
 (let (($x5034 (and $x3458 $x5033)))
 (let (($x5011 (or false (and $x3458 (< rank_82 rank_80)))))
 (let (($x5014 (or $x5011 (and $x3400 (< rank_78 rank_80)))))
 (let (($x5018 (not root_81)))
 (let (($x5019 (and $x3429 $x5018)))
 (let (($x4996 (or false (and $x3429 (< rank_80 rank_78)))))
 (let (($x5000 (not root_79)))
 (let (($x5001 (and $x3400 $x5000)))
 (let (($x4981 (or false (and $x3458 (< rank_82 rank_76)))))
 (let (($x4985 (not root_77)))
 (let (($x4986 (and $x3371 $x4985)))
 (let (($x4963 (or false (and $x3371 (< rank_76 rank_74)))))
 (let (($x4966 (or $x4963 (and $x3429 (< rank_80 rank_74)))))
 (let (($x4970 (not root_75)))
 (let (($x4971 (and $x3342 $x4970)))
 (let (($x4948 (or false (and $x3342 (< rank_74 rank_72)))))
 (let (($x4952 (not root_73)))
 (let (($x4953 (and $x3313 $x4952)))
 (let (($x4945 (and true (=> root_73 $x3313))))
 (let (($x4955 (and $x4945 (=> $x4953 (or $x4948 (and $x3400 (< rank_78 rank_72)))))))
 (let (($x4960 (and $x4955 (=> root_75 $x3342))))
 (let (($x4973 (and $x4960 (=> $x4971 (or $x4966 (and $x3313 (< rank_72 rank_74)))))))
 (let (($x4978 (and $x4973 (=> root_77 $x3371))))
 (let (($x4988 (and $x4978 (=> $x4986 (or $x4981 (and $x3342 (< rank_74 rank_76)))))))
 (let (($x4993 (and $x4988 (=> root_79 $x3400))))
 (let (($x5003 (and $x4993 (=> $x5001 (or $x4996 (and $x3313 (< rank_72 rank_78)))))))
 (let (($x5008 (and $x5003 (=> root_81 $x3429))))
 (let (($x5021 (and $x5008 (=> $x5019 (or $x5014 (and $x3342 (< rank_74 rank_80)))))))
 (let (($x5026 (and $x5021 (=> root_83 $x3458))))
 (let (($x5038 (and (and $x5026 (=> $x5034 (or $x5029 (and $x3371 (< rank_76 rank_82))))) (=> $x3563 (or $x5004 root_83)))))
 (let (($x5040 (and $x5038 (<= (+ ?x5006 ?x5023) 1))))
 (let (($x5041 (and true $x5040)))
 (let (($x5226 (= rule_instance 42)))
 (let (($x5219 (and $x5226 (and (and (and $x5041 $x3602) (and $x5081 $x3805)) (and $x5214 $x4122)))))
 (let ((?x4885 (ite root_71 1 0)))
 (let ((?x4867 (ite root_69 1 0)))
 (let ((?x4852 (ite root_67 1 0)))
 (let ((?x4837 (ite root_65 1 0)))
 (let ((?x4819 (ite root_63 1 0)))
 (let ((?x4804 (ite root_61 1 0)))
 (let ((?x4805 (+ 0 ?x4804)))
 (let ((?x4820 (+ ?x4805 ?x4819)))
 (let ((?x4838 (+ ?x4820 ?x4837)))
 (let ((?x4853 (+ ?x4838 ?x4852)))
 (let ((?x4868 (+ ?x4853 ?x4867)))
 (let (($x4803 (or false root_61)))
 (let (($x4818 (or $x4803 root_63)))
 (let (($x4836 (or $x4818 root_65)))
 (let (($x4851 (or $x4836 root_67)))
 (let (($x4866 (or $x4851 root_69)))
 (let (($x4891 (or false (and $x3967 (< rank_68 rank_70)))))
 (let (($x4895 (not root_71)))
 (let (($x4896 (and $x3996 $x4895)))
 (let (($x4873 (or false (and $x3996 (< rank_70 rank_68)))))
 (let (($x4876 (or $x4873 (and $x3938 (< rank_66 rank_68)))))
 (let (($x4880 (not root_69)))
 (let (($x4881 (and $x3967 $x4880)))
 (let (($x4858 (or false (and $x3967 (< rank_68 rank_66)))))
 (let (($x4862 (not root_67)))
 (let (($x4863 (and $x3938 $x4862)))
 (let (($x4843 (or false (and $x3996 (< rank_70 rank_64)))))
 (let (($x4847 (not root_65)))
 (let (($x4848 (and $x3909 $x4847)))
 (let (($x4825 (or false (and $x3909 (< rank_64 rank_62)))))
 (let (($x4828 (or $x4825 (and $x3967 (< rank_68 rank_62)))))
 (let (($x4832 (not root_63)))
 (let (($x4833 (and $x3880 $x4832)))
 (let (($x4810 (or false (and $x3880 (< rank_62 rank_60)))))
 (let (($x4814 (not root_61)))
 (let (($x4815 (and $x3851 $x4814)))
 (let (($x4807 (and true (=> root_61 $x3851))))
 (let (($x4817 (and $x4807 (=> $x4815 (or $x4810 (and $x3938 (< rank_66 rank_60)))))))
 (let (($x4822 (and $x4817 (=> root_63 $x3880))))
 (let (($x4835 (and $x4822 (=> $x4833 (or $x4828 (and $x3851 (< rank_60 rank_62)))))))
 (let (($x4840 (and $x4835 (=> root_65 $x3909))))
 (let (($x4850 (and $x4840 (=> $x4848 (or $x4843 (and $x3880 (< rank_62 rank_64)))))))
 (let (($x4855 (and $x4850 (=> root_67 $x3938))))
 (let (($x4865 (and $x4855 (=> $x4863 (or $x4858 (and $x3851 (< rank_60 rank_66)))))))
 (let (($x4870 (and $x4865 (=> root_69 $x3967))))
 (let (($x4883 (and $x4870 (=> $x4881 (or $x4876 (and $x3880 (< rank_62 rank_68)))))))
 (let (($x4888 (and $x4883 (=> root_71 $x3996))))
 (let (($x4900 (and (and $x4888 (=> $x4896 (or $x4891 (and $x3909 (< rank_64 rank_70))))) (=> $x4098 (or $x4866 root_71)))))
 (let (($x4902 (and $x4900 (<= (+ ?x4868 ?x4885) 1))))
 (let (($x4903 (and true $x4902)))
 (let (($x4736 (and true (=> c_1_0 d_1_1))))
 (let (($x4738 (and $x4736 (=> c_1_1 d_1_1))))
 (let (($x4740 (and $x4738 (=> c_1_2 d_1_1))))
 (let (($x4742 (and $x4740 (=> c_1_3 d_1_1))))
 (let (($x4744 (and $x4742 (=> c_1_4 d_1_1))))
 (let (($x4746 (and $x4744 (=> c_1_5 d_1_1))))
 (let (($x4748 (and $x4746 (=> c_1_6 d_1_1))))
 (let (($x4750 (and $x4748 (=> c_1_7 d_1_1))))
 (let (($x4752 (and $x4750 (=> c_1_8 d_1_1))))
 (let (($x4754 (and $x4752 (=> c_1_9 d_1_1))))
 (let (($x4756 (and $x4754 (=> c_1_10 d_1_1))))
 (let (($x4758 (and $x4756 (=> c_1_11 d_1_1))))
 (let (($x4760 (and $x4758 (=> c_1_12 d_1_1))))
 (let (($x4762 (and $x4760 (=> c_1_13 d_1_1))))
 (let (($x4764 (and $x4762 (=> c_1_14 d_1_1))))
 (let (($x4708 (and $x4706 (=> c_0_2 d_0_1))))
 (let (($x4702 (and $x4708 (=> c_0_3 d_0_1))))
 (let (($x4711 (and $x4702 (=> c_0_4 d_0_1))))
 (let (($x4713 (and $x4711 (=> c_0_5 d_0_1))))
 (let (($x4715 (and $x4713 $x4714)))
 (let (($x4717 (and $x4715 (=> c_0_7 d_0_1))))
 (let (($x4719 (and $x4717 (=> c_0_8 d_0_1))))
 (let (($x4721 (and $x4719 (=> c_0_9 d_0_1))))
 (let (($x4723 (and $x4721 (=> c_0_10 d_0_1))))
 (let (($x4725 (and $x4723 $x4724)))
 (let (($x4727 (and $x4725 (=> c_0_12 d_0_1))))
 (let (($x4729 (and $x4727 (=> c_0_13 d_0_1))))
 (let (($x4731 (and $x4729 (=> c_0_14 d_0_1))))
 (let (($x4700 (and true c_0_7)))
 (let (($x4704 (and $x4700 c_1_14)))
 (let (($x4734 (and $x4704 (and $x4731 (=> c_0_15 d_0_1)))))
 (let (($x4767 (and $x4734 (and $x4764 (=> c_1_15 d_1_1)))))
 (let (($x4768 (and $x4767 $x3706)))
 (let (($x4769 (and $x4768 $x3739)))
 (let (($x4770 (and $x4769 $x3772)))
 (let ((?x4680 (ite root_59 1 0)))
 (let ((?x4662 (ite root_57 1 0)))
 (let ((?x4647 (ite root_55 1 0)))
 (let ((?x4632 (ite root_53 1 0)))
 (let ((?x4614 (ite root_51 1 0)))
 (let ((?x4599 (ite root_49 1 0)))
 (let ((?x4600 (+ 0 ?x4599)))
 (let ((?x4615 (+ ?x4600 ?x4614)))
 (let ((?x4633 (+ ?x4615 ?x4632)))
 (let ((?x4648 (+ ?x4633 ?x4647)))
 (let ((?x4663 (+ ?x4648 ?x4662)))
 (let (($x4598 (or false root_49)))
 (let (($x4613 (or $x4598 root_51)))
 (let (($x4631 (or $x4613 root_53)))
 (let (($x4646 (or $x4631 root_55)))
 (let (($x4661 (or $x4646 root_57)))
 (let (($x4686 (or false (and $x3429 (< rank_56 rank_58)))))
 (let (($x4690 (not root_59)))
 (let (($x4691 (and $x3458 $x4690)))
 (let (($x4668 (or false (and $x3458 (< rank_58 rank_56)))))
 (let (($x4671 (or $x4668 (and $x3400 (< rank_54 rank_56)))))
 (let (($x4675 (not root_57)))
 (let (($x4676 (and $x3429 $x4675)))
 (let (($x4653 (or false (and $x3429 (< rank_56 rank_54)))))
 (let (($x4657 (not root_55)))
 (let (($x4658 (and $x3400 $x4657)))
 (let (($x4638 (or false (and $x3458 (< rank_58 rank_52)))))
 (let (($x4642 (not root_53)))
 (let (($x4643 (and $x3371 $x4642)))
 (let (($x4620 (or false (and $x3371 (< rank_52 rank_50)))))
 (let (($x4623 (or $x4620 (and $x3429 (< rank_56 rank_50)))))
 (let (($x4627 (not root_51)))
 (let (($x4628 (and $x3342 $x4627)))
 (let (($x4605 (or false (and $x3342 (< rank_50 rank_48)))))
 (let (($x4609 (not root_49)))
 (let (($x4610 (and $x3313 $x4609)))
 (let (($x4602 (and true (=> root_49 $x3313))))
 (let (($x4612 (and $x4602 (=> $x4610 (or $x4605 (and $x3400 (< rank_54 rank_48)))))))
 (let (($x4617 (and $x4612 (=> root_51 $x3342))))
 (let (($x4630 (and $x4617 (=> $x4628 (or $x4623 (and $x3313 (< rank_48 rank_50)))))))
 (let (($x4635 (and $x4630 (=> root_53 $x3371))))
 (let (($x4645 (and $x4635 (=> $x4643 (or $x4638 (and $x3342 (< rank_50 rank_52)))))))
 (let (($x4650 (and $x4645 (=> root_55 $x3400))))
 (let (($x4660 (and $x4650 (=> $x4658 (or $x4653 (and $x3313 (< rank_48 rank_54)))))))
 (let (($x4665 (and $x4660 (=> root_57 $x3429))))
 (let (($x4678 (and $x4665 (=> $x4676 (or $x4671 (and $x3342 (< rank_50 rank_56)))))))
 (let (($x4683 (and $x4678 (=> root_59 $x3458))))
 (let (($x4695 (and (and $x4683 (=> $x4691 (or $x4686 (and $x3371 (< rank_52 rank_58))))) (=> $x3563 (or $x4661 root_59)))))
 (let (($x4697 (and $x4695 (<= (+ ?x4663 ?x4680) 1))))
 (let (($x4698 (and true $x4697)))
 (let (($x4915 (= rule_instance 28)))
 (let (($x4908 (and $x4915 (and (and (and $x4698 $x3602) (and $x4770 $x3805)) (and $x4903 $x4122)))))
 (let ((?x4542 (ite root_47 1 0)))
 (let ((?x4524 (ite root_45 1 0)))
 (let ((?x4509 (ite root_43 1 0)))
 (let ((?x4494 (ite root_41 1 0)))
 (let ((?x4476 (ite root_39 1 0)))
 (let ((?x4461 (ite root_37 1 0)))
 (let ((?x4462 (+ 0 ?x4461)))
 (let ((?x4477 (+ ?x4462 ?x4476)))
 (let ((?x4495 (+ ?x4477 ?x4494)))
 (let ((?x4510 (+ ?x4495 ?x4509)))
 (let ((?x4525 (+ ?x4510 ?x4524)))
 (let (($x4460 (or false root_37)))
 (let (($x4475 (or $x4460 root_39)))
 (let (($x4493 (or $x4475 root_41)))
 (let (($x4508 (or $x4493 root_43)))
 (let (($x4523 (or $x4508 root_45)))
 (let (($x4548 (or false (and $x3967 (< rank_44 rank_46)))))
 (let (($x4552 (not root_47)))
 (let (($x4553 (and $x3996 $x4552)))
 (let (($x4530 (or false (and $x3996 (< rank_46 rank_44)))))
 (let (($x4533 (or $x4530 (and $x3938 (< rank_42 rank_44)))))
 (let (($x4537 (not root_45)))
 (let (($x4538 (and $x3967 $x4537)))
 (let (($x4515 (or false (and $x3967 (< rank_44 rank_42)))))
 (let (($x4519 (not root_43)))
 (let (($x4520 (and $x3938 $x4519)))
 (let (($x4500 (or false (and $x3996 (< rank_46 rank_40)))))
 (let (($x4504 (not root_41)))
 (let (($x4505 (and $x3909 $x4504)))
 (let (($x4482 (or false (and $x3909 (< rank_40 rank_38)))))
 (let (($x4485 (or $x4482 (and $x3967 (< rank_44 rank_38)))))
 (let (($x4489 (not root_39)))
 (let (($x4490 (and $x3880 $x4489)))
 (let (($x4467 (or false (and $x3880 (< rank_38 rank_36)))))
 (let (($x4471 (not root_37)))
 (let (($x4472 (and $x3851 $x4471)))
 (let (($x4464 (and true (=> root_37 $x3851))))
 (let (($x4474 (and $x4464 (=> $x4472 (or $x4467 (and $x3938 (< rank_42 rank_36)))))))
 (let (($x4479 (and $x4474 (=> root_39 $x3880))))
 (let (($x4492 (and $x4479 (=> $x4490 (or $x4485 (and $x3851 (< rank_36 rank_38)))))))
 (let (($x4497 (and $x4492 (=> root_41 $x3909))))
 (let (($x4507 (and $x4497 (=> $x4505 (or $x4500 (and $x3880 (< rank_38 rank_40)))))))
 (let (($x4512 (and $x4507 (=> root_43 $x3938))))
 (let (($x4522 (and $x4512 (=> $x4520 (or $x4515 (and $x3851 (< rank_36 rank_42)))))))
 (let (($x4527 (and $x4522 (=> root_45 $x3967))))
 (let (($x4540 (and $x4527 (=> $x4538 (or $x4533 (and $x3880 (< rank_38 rank_44)))))))
 (let (($x4545 (and $x4540 (=> root_47 $x3996))))
 (let (($x4557 (and (and $x4545 (=> $x4553 (or $x4548 (and $x3909 (< rank_40 rank_46))))) (=> $x4098 (or $x4523 root_47)))))
 (let (($x4559 (and $x4557 (<= (+ ?x4525 ?x4542) 1))))
 (let (($x4560 (and true $x4559)))
 (let (($x4393 (and true (=> c_1_0 d_1_0))))
 (let (($x4395 (and $x4393 (=> c_1_1 d_1_0))))
 (let (($x4397 (and $x4395 (=> c_1_2 d_1_0))))
 (let (($x4399 (and $x4397 (=> c_1_3 d_1_0))))
 (let (($x4401 (and $x4399 (=> c_1_4 d_1_0))))
 (let (($x4403 (and $x4401 (=> c_1_5 d_1_0))))
 (let (($x4405 (and $x4403 (=> c_1_6 d_1_0))))
 (let (($x4407 (and $x4405 (=> c_1_7 d_1_0))))
 (let (($x4409 (and $x4407 (=> c_1_8 d_1_0))))
 (let (($x4411 (and $x4409 (=> c_1_9 d_1_0))))
 (let (($x4413 (and $x4411 (=> c_1_10 d_1_0))))
 (let (($x4415 (and $x4413 (=> c_1_11 d_1_0))))
 (let (($x4417 (and $x4415 (=> c_1_12 d_1_0))))
 (let (($x4419 (and $x4417 (=> c_1_13 d_1_0))))
 (let (($x4421 (and $x4419 (=> c_1_14 d_1_0))))
 (let (($x4360 (and true (=> c_0_0 d_0_6))))
 (let (($x4363 (and $x4360 (=> c_0_1 d_0_6))))
 (let (($x4365 (and $x4363 (=> c_0_2 d_0_6))))
 (let (($x4359 (and $x4365 (=> c_0_3 d_0_6))))
 (let (($x4368 (and $x4359 (=> c_0_4 d_0_6))))
 (let (($x4370 (and $x4368 (=> c_0_5 d_0_6))))
 (let (($x4372 (and $x4370 (=> c_0_6 d_0_6))))
 (let (($x4374 (and $x4372 (=> c_0_7 d_0_6))))
 (let (($x4376 (and $x4374 (=> c_0_8 d_0_6))))
 (let (($x4378 (and $x4376 (=> c_0_9 d_0_6))))
 (let (($x4380 (and $x4378 (=> c_0_10 d_0_6))))
 (let (($x4382 (and $x4380 (=> c_0_11 d_0_6))))
 (let (($x4384 (and $x4382 (=> c_0_12 d_0_6))))
 (let (($x4386 (and $x4384 (=> c_0_13 d_0_6))))
 (let (($x4388 (and $x4386 (=> c_0_14 d_0_6))))
 (let (($x4357 (and true c_0_2)))
 (let (($x4361 (and $x4357 c_1_14)))
 (let (($x4391 (and $x4361 (and $x4388 (=> c_0_15 d_0_6)))))
 (let (($x4424 (and $x4391 (and $x4421 (=> c_1_15 d_1_0)))))
 (let (($x4425 (and $x4424 $x3706)))
 (let (($x4426 (and $x4425 $x3739)))
 (let (($x4427 (and $x4426 $x3772)))
 (let ((?x4337 (ite root_35 1 0)))
 (let ((?x4319 (ite root_33 1 0)))
 (let ((?x4304 (ite root_31 1 0)))
 (let ((?x4289 (ite root_29 1 0)))
 (let ((?x4271 (ite root_27 1 0)))
 (let ((?x4256 (ite root_25 1 0)))
 (let ((?x4257 (+ 0 ?x4256)))
 (let ((?x4272 (+ ?x4257 ?x4271)))
 (let ((?x4290 (+ ?x4272 ?x4289)))
 (let ((?x4305 (+ ?x4290 ?x4304)))
 (let ((?x4320 (+ ?x4305 ?x4319)))
 (let (($x4255 (or false root_25)))
 (let (($x4270 (or $x4255 root_27)))
 (let (($x4288 (or $x4270 root_29)))
 (let (($x4303 (or $x4288 root_31)))
 (let (($x4318 (or $x4303 root_33)))
 (let (($x4343 (or false (and $x3429 (< rank_32 rank_34)))))
 (let (($x4347 (not root_35)))
 (let (($x4348 (and $x3458 $x4347)))
 (let (($x4325 (or false (and $x3458 (< rank_34 rank_32)))))
 (let (($x4328 (or $x4325 (and $x3400 (< rank_30 rank_32)))))
 (let (($x4332 (not root_33)))
 (let (($x4333 (and $x3429 $x4332)))
 (let (($x4310 (or false (and $x3429 (< rank_32 rank_30)))))
 (let (($x4314 (not root_31)))
 (let (($x4315 (and $x3400 $x4314)))
 (let (($x4295 (or false (and $x3458 (< rank_34 rank_28)))))
 (let (($x4299 (not root_29)))
 (let (($x4300 (and $x3371 $x4299)))
 (let (($x4277 (or false (and $x3371 (< rank_28 rank_26)))))
 (let (($x4280 (or $x4277 (and $x3429 (< rank_32 rank_26)))))
 (let (($x4284 (not root_27)))
 (let (($x4285 (and $x3342 $x4284)))
 (let (($x4262 (or false (and $x3342 (< rank_26 rank_24)))))
 (let (($x4266 (not root_25)))
 (let (($x4267 (and $x3313 $x4266)))
 (let (($x4259 (and true (=> root_25 $x3313))))
 (let (($x4269 (and $x4259 (=> $x4267 (or $x4262 (and $x3400 (< rank_30 rank_24)))))))
 (let (($x4274 (and $x4269 (=> root_27 $x3342))))
 (let (($x4287 (and $x4274 (=> $x4285 (or $x4280 (and $x3313 (< rank_24 rank_26)))))))
 (let (($x4292 (and $x4287 (=> root_29 $x3371))))
 (let (($x4302 (and $x4292 (=> $x4300 (or $x4295 (and $x3342 (< rank_26 rank_28)))))))
 (let (($x4307 (and $x4302 (=> root_31 $x3400))))
 (let (($x4317 (and $x4307 (=> $x4315 (or $x4310 (and $x3313 (< rank_24 rank_30)))))))
 (let (($x4322 (and $x4317 (=> root_33 $x3429))))
 (let (($x4335 (and $x4322 (=> $x4333 (or $x4328 (and $x3342 (< rank_26 rank_32)))))))
 (let (($x4340 (and $x4335 (=> root_35 $x3458))))
 (let (($x4352 (and (and $x4340 (=> $x4348 (or $x4343 (and $x3371 (< rank_28 rank_34))))) (=> $x3563 (or $x4318 root_35)))))
 (let (($x4354 (and $x4352 (<= (+ ?x4320 ?x4337) 1))))
 (let (($x4355 (and true $x4354)))
 (let (($x4572 (= rule_instance 14)))
 (let (($x4565 (and $x4572 (and (and (and $x4355 $x3602) (and $x4427 $x3805)) (and $x4560 $x4122)))))
 (let ((?x4100 (ite root_23 1 0)))
 (let ((?x4081 (ite root_21 1 0)))
 (let ((?x4065 (ite root_19 1 0)))
 (let ((?x4049 (ite root_17 1 0)))
 (let ((?x4030 (ite root_15 1 0)))
 (let ((?x4014 (ite root_13 1 0)))
 (let ((?x4015 (+ 0 ?x4014)))
 (let ((?x4031 (+ ?x4015 ?x4030)))
 (let ((?x4050 (+ ?x4031 ?x4049)))
 (let ((?x4066 (+ ?x4050 ?x4065)))
 (let ((?x4082 (+ ?x4066 ?x4081)))
 (let (($x4013 (or false root_13)))
 (let (($x4029 (or $x4013 root_15)))
 (let (($x4048 (or $x4029 root_17)))
 (let (($x4064 (or $x4048 root_19)))
 (let (($x4080 (or $x4064 root_21)))
 (let (($x4106 (or false (and $x3967 (< rank_20 rank_22)))))
 (let (($x4110 (not root_23)))
 (let (($x4111 (and $x3996 $x4110)))
 (let (($x4087 (or false (and $x3996 (< rank_22 rank_20)))))
 (let (($x4090 (or $x4087 (and $x3938 (< rank_18 rank_20)))))
 (let (($x4094 (not root_21)))
 (let (($x4095 (and $x3967 $x4094)))
 (let (($x4071 (or false (and $x3967 (< rank_20 rank_18)))))
 (let (($x4075 (not root_19)))
 (let (($x4076 (and $x3938 $x4075)))
 (let (($x4055 (or false (and $x3996 (< rank_22 rank_16)))))
 (let (($x4059 (not root_17)))
 (let (($x4060 (and $x3909 $x4059)))
 (let (($x4036 (or false (and $x3909 (< rank_16 rank_14)))))
 (let (($x4039 (or $x4036 (and $x3967 (< rank_20 rank_14)))))
 (let (($x4043 (not root_15)))
 (let (($x4044 (and $x3880 $x4043)))
 (let (($x4020 (or false (and $x3880 (< rank_14 rank_12)))))
 (let (($x4024 (not root_13)))
 (let (($x4025 (and $x3851 $x4024)))
 (let (($x4017 (and true (=> root_13 $x3851))))
 (let (($x4027 (and $x4017 (=> $x4025 (or $x4020 (and $x3938 (< rank_18 rank_12)))))))
 (let (($x4033 (and $x4027 (=> root_15 $x3880))))
 (let (($x4046 (and $x4033 (=> $x4044 (or $x4039 (and $x3851 (< rank_12 rank_14)))))))
 (let (($x4052 (and $x4046 (=> root_17 $x3909))))
 (let (($x4062 (and $x4052 (=> $x4060 (or $x4055 (and $x3880 (< rank_14 rank_16)))))))
 (let (($x4068 (and $x4062 (=> root_19 $x3938))))
 (let (($x4078 (and $x4068 (=> $x4076 (or $x4071 (and $x3851 (< rank_12 rank_18)))))))
 (let (($x4084 (and $x4078 (=> root_21 $x3967))))
 (let (($x4097 (and $x4084 (=> $x4095 (or $x4090 (and $x3880 (< rank_14 rank_20)))))))
 (let (($x4103 (and $x4097 (=> root_23 $x3996))))
 (let (($x4115 (and (and $x4103 (=> $x4111 (or $x4106 (and $x3909 (< rank_16 rank_22))))) (=> $x4098 (or $x4080 root_23)))))
 (let (($x4117 (and $x4115 (<= (+ ?x4082 ?x4100) 1))))
 (let (($x4118 (and true $x4117)))
 (let (($x3592 (and true (=> c_0_0 d_0_2))))
 (let (($x3612 (and $x3592 (=> c_0_1 d_0_2))))
 (let (($x3614 (and $x3612 $x3613)))
 (let (($x3616 (and $x3614 (=> c_0_3 d_0_2))))
 (let (($x3618 (and $x3616 (=> c_0_4 d_0_2))))
 (let (($x3620 (and $x3618 (=> c_0_5 d_0_2))))
 (let (($x3622 (and $x3620 (=> c_0_6 d_0_2))))
 (let (($x3624 (and $x3622 $x3623)))
 (let (($x3626 (and $x3624 (=> c_0_8 d_0_2))))
 (let (($x3628 (and $x3626 (=> c_0_9 d_0_2))))
 (let (($x3630 (and $x3628 (=> c_0_10 d_0_2))))
 (let (($x3632 (and $x3630 (=> c_0_11 d_0_2))))
 (let (($x3634 (and $x3632 $x3633)))
 (let (($x3636 (and $x3634 (=> c_0_13 d_0_2))))
 (let (($x3638 (and $x3636 (=> c_0_14 d_0_2))))
 (let (($x3603 (and true c_0_6)))
 (let (($x3608 (and $x3603 c_1_0)))
 (let (($x3641 (and $x3608 (and $x3638 (=> c_0_15 d_0_2)))))
 (let (($x3674 (and $x3641 $x3673)))
 (let (($x3707 (and $x3674 $x3706)))
 (let (($x3740 (and $x3707 $x3739)))
 (let (($x3773 (and $x3740 $x3772)))
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
 (let (($x4220 (= rule_instance 0)))
 (let (($x4221 (and $x4220 (and (and (and $x3583 $x3602) (and $x3773 $x3805)) (and $x4118 $x4122)))))
 (let (($x4224 (or false (and $x4221 $x4222))))
 (let (($x4567 (or $x4224 (and $x4565 $x4222))))
 (let (($x4910 (or $x4567 (and $x4908 $x4222))))
 (let (($x5221 (or $x4910 (and $x5219 $x4222))))
 (or $x5221 (and $x5559 $x4222))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
