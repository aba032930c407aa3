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
 (let (($x3993 (>= rank_12 0)))
 (and $x3993 (< rank_12 6))))
(assert
 (let (($x3985 (>= rank_14 0)))
 (and $x3985 (< rank_14 6))))
(assert
 (let (($x3989 (>= rank_16 0)))
 (and $x3989 (< rank_16 6))))
(assert
 (let (($x3997 (>= rank_18 0)))
 (and $x3997 (< rank_18 6))))
(assert
 (let (($x4002 (>= rank_20 0)))
 (and $x4002 (< rank_20 6))))
(assert
 (let (($x4007 (>= rank_22 0)))
 (and $x4007 (< rank_22 6))))
(assert
 (let (($x4223 (>= rank_24 0)))
 (and $x4223 (< rank_24 6))))
(assert
 (let (($x4234 (>= rank_26 0)))
 (and $x4234 (< rank_26 6))))
(assert
 (let (($x4229 (>= rank_28 0)))
 (and $x4229 (< rank_28 6))))
(assert
 (let (($x4238 (>= rank_30 0)))
 (and $x4238 (< rank_30 6))))
(assert
 (let (($x4243 (>= rank_32 0)))
 (and $x4243 (< rank_32 6))))
(assert
 (let (($x4248 (>= rank_34 0)))
 (and $x4248 (< rank_34 6))))
(assert
 (let (($x4429 (>= rank_36 0)))
 (and $x4429 (< rank_36 6))))
(assert
 (let (($x4432 (>= rank_38 0)))
 (and $x4432 (< rank_38 6))))
(assert
 (let (($x4431 (>= rank_40 0)))
 (and $x4431 (< rank_40 6))))
(assert
 (let (($x4443 (>= rank_42 0)))
 (and $x4443 (< rank_42 6))))
(assert
 (let (($x4448 (>= rank_44 0)))
 (and $x4448 (< rank_44 6))))
(assert
 (let (($x4453 (>= rank_46 0)))
 (and $x4453 (< rank_46 6))))
(assert
 (let (($x4562 (>= rank_48 0)))
 (and $x4562 (< rank_48 6))))
(assert
 (let (($x4577 (>= rank_50 0)))
 (and $x4577 (< rank_50 6))))
(assert
 (let (($x4572 (>= rank_52 0)))
 (and $x4572 (< rank_52 6))))
(assert
 (let (($x4581 (>= rank_54 0)))
 (and $x4581 (< rank_54 6))))
(assert
 (let (($x4586 (>= rank_56 0)))
 (and $x4586 (< rank_56 6))))
(assert
 (let (($x4591 (>= rank_58 0)))
 (and $x4591 (< rank_58 6))))
(assert
 (let (($x4772 (>= rank_60 0)))
 (and $x4772 (< rank_60 6))))
(assert
 (let (($x4775 (>= rank_62 0)))
 (and $x4775 (< rank_62 6))))
(assert
 (let (($x4774 (>= rank_64 0)))
 (and $x4774 (< rank_64 6))))
(assert
 (let (($x4786 (>= rank_66 0)))
 (and $x4786 (< rank_66 6))))
(assert
 (let (($x4791 (>= rank_68 0)))
 (and $x4791 (< rank_68 6))))
(assert
 (let (($x4796 (>= rank_70 0)))
 (and $x4796 (< rank_70 6))))
(assert
 (let (($x4905 (>= rank_72 0)))
 (and $x4905 (< rank_72 6))))
(assert
 (let (($x4920 (>= rank_74 0)))
 (and $x4920 (< rank_74 6))))
(assert
 (let (($x4915 (>= rank_76 0)))
 (and $x4915 (< rank_76 6))))
(assert
 (let (($x4924 (>= rank_78 0)))
 (and $x4924 (< rank_78 6))))
(assert
 (let (($x4929 (>= rank_80 0)))
 (and $x4929 (< rank_80 6))))
(assert
 (let (($x4934 (>= rank_82 0)))
 (and $x4934 (< rank_82 6))))
(assert
 (let (($x5083 (>= rank_84 0)))
 (and $x5083 (< rank_84 6))))
(assert
 (let (($x5086 (>= rank_86 0)))
 (and $x5086 (< rank_86 6))))
(assert
 (let (($x5085 (>= rank_88 0)))
 (and $x5085 (< rank_88 6))))
(assert
 (let (($x5097 (>= rank_90 0)))
 (and $x5097 (< rank_90 6))))
(assert
 (let (($x5102 (>= rank_92 0)))
 (and $x5102 (< rank_92 6))))
(assert
 (let (($x5107 (>= rank_94 0)))
 (and $x5107 (< rank_94 6))))
(assert
 (let (($x5216 (>= rank_96 0)))
 (and $x5216 (< rank_96 6))))
(assert
 (let (($x5231 (>= rank_98 0)))
 (and $x5231 (< rank_98 6))))
(assert
 (let (($x5226 (>= rank_100 0)))
 (and $x5226 (< rank_100 6))))
(assert
 (let (($x5235 (>= rank_102 0)))
 (and $x5235 (< rank_102 6))))
(assert
 (let (($x5240 (>= rank_104 0)))
 (and $x5240 (< rank_104 6))))
(assert
 (let (($x5245 (>= rank_106 0)))
 (and $x5245 (< rank_106 6))))
(assert
 (let (($x5423 (>= rank_108 0)))
 (and $x5423 (< rank_108 6))))
(assert
 (let (($x5426 (>= rank_110 0)))
 (and $x5426 (< rank_110 6))))
(assert
 (let (($x5425 (>= rank_112 0)))
 (and $x5425 (< rank_112 6))))
(assert
 (let (($x5437 (>= rank_114 0)))
 (and $x5437 (< rank_114 6))))
(assert
 (let (($x5442 (>= rank_116 0)))
 (and $x5442 (< rank_116 6))))
(assert
 (let (($x5447 (>= rank_118 0)))
 (and $x5447 (< rank_118 6))))
(assert
 (let ((?x4213 (ite (or (or (or (or d_1_6 d_1_7) d_1_8) d_1_9) d_1_10) 3 0)))
 (let ((?x4211 (ite (or (or (or (or d_1_1 d_1_2) d_1_3) d_1_4) d_1_5) 2 0)))
 (let ((?x4209 (ite (or (or (or (or d_1_11 d_1_12) d_1_13) d_1_14) d_1_15) 1 0)))
 (let ((?x4210 (+ 0 ?x4209)))
 (let ((?x4212 (+ ?x4210 ?x4211)))
 (let ((?x4175 (ite (or (or (or (or d_0_6 d_0_7) d_0_8) d_0_9) d_0_10) 3 0)))
 (let ((?x4173 (ite (or (or (or (or d_0_1 d_0_2) d_0_3) d_0_4) d_0_5) 2 0)))
 (let ((?x4171 (ite (or (or (or (or d_0_11 d_0_12) d_0_13) d_0_14) d_0_15) 1 0)))
 (let ((?x4172 (+ 0 ?x4171)))
 (let ((?x4174 (+ ?x4172 ?x4173)))
 (let ((?x4177 (+ 0 (+ ?x4174 ?x4175))))
 (let ((?x4194 (ite (or (or (or (or c_1_6 c_1_7) c_1_8) c_1_9) c_1_10) 3 0)))
 (let ((?x4192 (ite (or (or (or (or c_1_1 c_1_2) c_1_3) c_1_4) c_1_5) 2 0)))
 (let ((?x4190 (ite (or (or (or (or c_1_11 c_1_12) c_1_13) c_1_14) c_1_15) 1 0)))
 (let ((?x4191 (+ 0 ?x4190)))
 (let ((?x4193 (+ ?x4191 ?x4192)))
 (let ((?x4156 (ite (or (or (or (or c_0_6 c_0_7) c_0_8) c_0_9) c_0_10) 3 0)))
 (let ((?x4153 (ite (or (or (or (or c_0_1 c_0_2) c_0_3) c_0_4) c_0_5) 2 0)))
 (let ((?x4150 (ite (or (or (or (or c_0_11 c_0_12) c_0_13) c_0_14) c_0_15) 1 0)))
 (let ((?x4151 (+ 0 ?x4150)))
 (let ((?x4154 (+ ?x4151 ?x4153)))
 (let ((?x4158 (+ 0 (+ ?x4154 ?x4156))))
 (let (($x4218 (and (distinct (+ ?x4158 (+ ?x4193 ?x4194)) (+ ?x4177 (+ ?x4212 ?x4213))) true)))
 (let (($x3994 (or d_5_1 d_5_2 d_5_3 d_5_4 d_5_5 d_5_6 d_5_7 d_5_8 d_5_9 d_5_10 d_5_11 d_5_12 d_5_13 d_5_14 d_5_15)))
 (let ((?x4135 (ite $x3994 1 0)))
 (let (($x3965 (or d_4_1 d_4_2 d_4_3 d_4_4 d_4_5 d_4_6 d_4_7 d_4_8 d_4_9 d_4_10 d_4_11 d_4_12 d_4_13 d_4_14 d_4_15)))
 (let ((?x4133 (ite $x3965 1 0)))
 (let (($x3936 (or d_3_1 d_3_2 d_3_3 d_3_4 d_3_5 d_3_6 d_3_7 d_3_8 d_3_9 d_3_10 d_3_11 d_3_12 d_3_13 d_3_14 d_3_15)))
 (let ((?x4125 (ite $x3936 1 0)))
 (let (($x3907 (or d_2_1 d_2_2 d_2_3 d_2_4 d_2_5 d_2_6 d_2_7 d_2_8 d_2_9 d_2_10 d_2_11 d_2_12 d_2_13 d_2_14 d_2_15)))
 (let ((?x4132 (ite $x3907 1 0)))
 (let (($x3878 (or d_1_1 d_1_2 d_1_3 d_1_4 d_1_5 d_1_6 d_1_7 d_1_8 d_1_9 d_1_10 d_1_11 d_1_12 d_1_13 d_1_14 d_1_15)))
 (let ((?x4119 (ite $x3878 1 0)))
 (let (($x3849 (or d_0_1 d_0_2 d_0_3 d_0_4 d_0_5 d_0_6 d_0_7 d_0_8 d_0_9 d_0_10 d_0_11 d_0_12 d_0_13 d_0_14 d_0_15)))
 (let ((?x4117 (ite $x3849 1 0)))
 (let ((?x4118 (+ 0 ?x4117)))
 (let ((?x4127 (+ ?x4118 ?x4119)))
 (let ((?x4121 (+ ?x4127 ?x4132)))
 (let ((?x4131 (+ ?x4121 ?x4125)))
 (let ((?x4134 (+ ?x4131 ?x4133)))
 (let (($x4120 (>= (+ ?x4134 ?x4135) 1)))
 (let ((?x5532 (ite root_119 1 0)))
 (let ((?x5514 (ite root_117 1 0)))
 (let ((?x5499 (ite root_115 1 0)))
 (let ((?x5484 (ite root_113 1 0)))
 (let ((?x5466 (ite root_111 1 0)))
 (let ((?x5451 (ite root_109 1 0)))
 (let ((?x5452 (+ 0 ?x5451)))
 (let ((?x5467 (+ ?x5452 ?x5466)))
 (let ((?x5485 (+ ?x5467 ?x5484)))
 (let ((?x5500 (+ ?x5485 ?x5499)))
 (let ((?x5515 (+ ?x5500 ?x5514)))
 (let (($x5450 (or false root_109)))
 (let (($x5465 (or $x5450 root_111)))
 (let (($x5483 (or $x5465 root_113)))
 (let (($x5498 (or $x5483 root_115)))
 (let (($x5513 (or $x5498 root_117)))
 (let (($x4010 (or false $x3849)))
 (let (($x4026 (or $x4010 $x3878)))
 (let (($x4045 (or $x4026 $x3907)))
 (let (($x4061 (or $x4045 $x3936)))
 (let (($x4077 (or $x4061 $x3965)))
 (let (($x4096 (or $x4077 $x3994)))
 (let (($x5538 (or false (and $x3965 (< rank_116 rank_118)))))
 (let (($x5542 (not root_119)))
 (let (($x5543 (and $x3994 $x5542)))
 (let (($x5520 (or false (and $x3994 (< rank_118 rank_116)))))
 (let (($x5523 (or $x5520 (and $x3936 (< rank_114 rank_116)))))
 (let (($x5527 (not root_117)))
 (let (($x5528 (and $x3965 $x5527)))
 (let (($x5505 (or false (and $x3965 (< rank_116 rank_114)))))
 (let (($x5509 (not root_115)))
 (let (($x5510 (and $x3936 $x5509)))
 (let (($x5490 (or false (and $x3994 (< rank_118 rank_112)))))
 (let (($x5494 (not root_113)))
 (let (($x5495 (and $x3907 $x5494)))
 (let (($x5472 (or false (and $x3907 (< rank_112 rank_110)))))
 (let (($x5475 (or $x5472 (and $x3965 (< rank_116 rank_110)))))
 (let (($x5479 (not root_111)))
 (let (($x5480 (and $x3878 $x5479)))
 (let (($x5457 (or false (and $x3878 (< rank_110 rank_108)))))
 (let (($x5461 (not root_109)))
 (let (($x5462 (and $x3849 $x5461)))
 (let (($x5454 (and true (=> root_109 $x3849))))
 (let (($x5464 (and $x5454 (=> $x5462 (or $x5457 (and $x3936 (< rank_114 rank_108)))))))
 (let (($x5469 (and $x5464 (=> root_111 $x3878))))
 (let (($x5482 (and $x5469 (=> $x5480 (or $x5475 (and $x3849 (< rank_108 rank_110)))))))
 (let (($x5487 (and $x5482 (=> root_113 $x3907))))
 (let (($x5497 (and $x5487 (=> $x5495 (or $x5490 (and $x3878 (< rank_110 rank_112)))))))
 (let (($x5502 (and $x5497 (=> root_115 $x3936))))
 (let (($x5512 (and $x5502 (=> $x5510 (or $x5505 (and $x3849 (< rank_108 rank_114)))))))
 (let (($x5517 (and $x5512 (=> root_117 $x3965))))
 (let (($x5530 (and $x5517 (=> $x5528 (or $x5523 (and $x3878 (< rank_110 rank_116)))))))
 (let (($x5535 (and $x5530 (=> root_119 $x3994))))
 (let (($x5547 (and (and $x5535 (=> $x5543 (or $x5538 (and $x3907 (< rank_112 rank_118))))) (=> $x4096 (or $x5513 root_119)))))
 (let (($x5549 (and $x5547 (<= (+ ?x5515 ?x5532) 1))))
 (let (($x5550 (and true $x5549)))
 (let (($x3802 (= c_5_15 d_5_15)))
 (let (($x3800 (= c_5_14 d_5_14)))
 (let (($x3798 (= c_5_13 d_5_13)))
 (let (($x3796 (= c_5_12 d_5_12)))
 (let (($x3794 (= c_5_11 d_5_11)))
 (let (($x3792 (= c_5_10 d_5_10)))
 (let (($x3790 (= c_5_9 d_5_9)))
 (let (($x3788 (= c_5_8 d_5_8)))
 (let (($x3786 (= c_5_7 d_5_7)))
 (let (($x3784 (= c_5_6 d_5_6)))
 (let (($x3782 (= c_5_5 d_5_5)))
 (let (($x3780 (= c_5_4 d_5_4)))
 (let (($x3778 (= c_5_3 d_5_3)))
 (let (($x3776 (= c_5_2 d_5_2)))
 (let (($x3774 (= c_5_1 d_5_1)))
 (let (($x3772 (= c_5_0 d_5_0)))
 (let (($x3773 (and true $x3772)))
 (let (($x3775 (and $x3773 $x3774)))
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
 (let (($x3769 (= c_4_15 d_4_15)))
 (let (($x3767 (= c_4_14 d_4_14)))
 (let (($x3765 (= c_4_13 d_4_13)))
 (let (($x3763 (= c_4_12 d_4_12)))
 (let (($x3761 (= c_4_11 d_4_11)))
 (let (($x3759 (= c_4_10 d_4_10)))
 (let (($x3757 (= c_4_9 d_4_9)))
 (let (($x3755 (= c_4_8 d_4_8)))
 (let (($x3753 (= c_4_7 d_4_7)))
 (let (($x3751 (= c_4_6 d_4_6)))
 (let (($x3749 (= c_4_5 d_4_5)))
 (let (($x3747 (= c_4_4 d_4_4)))
 (let (($x3745 (= c_4_3 d_4_3)))
 (let (($x3743 (= c_4_2 d_4_2)))
 (let (($x3741 (= c_4_1 d_4_1)))
 (let (($x3739 (= c_4_0 d_4_0)))
 (let (($x3740 (and true $x3739)))
 (let (($x3742 (and $x3740 $x3741)))
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
 (let (($x3736 (= c_3_15 d_3_15)))
 (let (($x3734 (= c_3_14 d_3_14)))
 (let (($x3732 (= c_3_13 d_3_13)))
 (let (($x3730 (= c_3_12 d_3_12)))
 (let (($x3728 (= c_3_11 d_3_11)))
 (let (($x3726 (= c_3_10 d_3_10)))
 (let (($x3724 (= c_3_9 d_3_9)))
 (let (($x3722 (= c_3_8 d_3_8)))
 (let (($x3720 (= c_3_7 d_3_7)))
 (let (($x3718 (= c_3_6 d_3_6)))
 (let (($x3716 (= c_3_5 d_3_5)))
 (let (($x3714 (= c_3_4 d_3_4)))
 (let (($x3712 (= c_3_3 d_3_3)))
 (let (($x3710 (= c_3_2 d_3_2)))
 (let (($x3708 (= c_3_1 d_3_1)))
 (let (($x3706 (= c_3_0 d_3_0)))
 (let (($x3707 (and true $x3706)))
 (let (($x3709 (and $x3707 $x3708)))
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
 (let (($x3703 (= c_2_15 d_2_15)))
 (let (($x3701 (= c_2_14 d_2_14)))
 (let (($x3699 (= c_2_13 d_2_13)))
 (let (($x3697 (= c_2_12 d_2_12)))
 (let (($x3695 (= c_2_11 d_2_11)))
 (let (($x3693 (= c_2_10 d_2_10)))
 (let (($x3691 (= c_2_9 d_2_9)))
 (let (($x3689 (= c_2_8 d_2_8)))
 (let (($x3687 (= c_2_7 d_2_7)))
 (let (($x3685 (= c_2_6 d_2_6)))
 (let (($x3683 (= c_2_5 d_2_5)))
 (let (($x3681 (= c_2_4 d_2_4)))
 (let (($x3679 (= c_2_3 d_2_3)))
 (let (($x3677 (= c_2_2 d_2_2)))
 (let (($x3675 (= c_2_1 d_2_1)))
 (let (($x3673 (= c_2_0 d_2_0)))
 (let (($x3674 (and true $x3673)))
 (let (($x3676 (and $x3674 $x3675)))
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
 (let (($x5383 (and true (=> c_1_0 d_1_6))))
 (let (($x5385 (and $x5383 (=> c_1_1 d_1_6))))
 (let (($x5387 (and $x5385 (=> c_1_2 d_1_7))))
 (let (($x5389 (and $x5387 (=> c_1_3 d_1_8))))
 (let (($x5391 (and $x5389 (=> c_1_4 d_1_9))))
 (let (($x5393 (and $x5391 (=> c_1_5 d_1_10))))
 (let (($x5395 (and $x5393 (=> c_1_6 d_1_6))))
 (let (($x5397 (and $x5395 (=> c_1_7 d_1_7))))
 (let (($x5399 (and $x5397 (=> c_1_8 d_1_8))))
 (let (($x5401 (and $x5399 (=> c_1_9 d_1_9))))
 (let (($x5403 (and $x5401 (=> c_1_10 d_1_10))))
 (let (($x5405 (and $x5403 (=> c_1_11 d_1_6))))
 (let (($x5407 (and $x5405 (=> c_1_12 d_1_7))))
 (let (($x5409 (and $x5407 (=> c_1_13 d_1_8))))
 (let (($x5411 (and $x5409 (=> c_1_14 d_1_9))))
 (let (($x3631 (=> c_0_12 d_0_2)))
 (let (($x4720 (=> c_0_11 d_0_1)))
 (let (($x3621 (=> c_0_7 d_0_2)))
 (let (($x4710 (=> c_0_6 d_0_1)))
 (let (($x3611 (=> c_0_2 d_0_2)))
 (let (($x4699 (and true (=> c_0_0 d_0_1))))
 (let (($x4702 (and $x4699 (=> c_0_1 d_0_1))))
 (let (($x5356 (and $x4702 $x3611)))
 (let (($x5359 (and $x5356 (=> c_0_3 d_0_3))))
 (let (($x5351 (and $x5359 (=> c_0_4 d_0_4))))
 (let (($x5364 (and $x5351 (=> c_0_5 d_0_5))))
 (let (($x5365 (and $x5364 $x4710)))
 (let (($x5366 (and $x5365 $x3621)))
 (let (($x5368 (and $x5366 (=> c_0_8 d_0_3))))
 (let (($x5370 (and $x5368 (=> c_0_9 d_0_4))))
 (let (($x5372 (and $x5370 (=> c_0_10 d_0_5))))
 (let (($x5373 (and $x5372 $x4720)))
 (let (($x5374 (and $x5373 $x3631)))
 (let (($x5376 (and $x5374 (=> c_0_13 d_0_3))))
 (let (($x5378 (and $x5376 (=> c_0_14 d_0_4))))
 (let (($x5362 (or c_1_1 c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x5358 (or c_0_6 c_0_7 c_0_8 c_0_9 c_0_10)))
 (let (($x5360 (and true $x5358)))
 (let (($x5355 (and $x5360 $x5362)))
 (let (($x5381 (and $x5355 (and $x5378 (=> c_0_15 d_0_5)))))
 (let (($x5414 (and $x5381 (and $x5411 (=> c_1_15 d_1_10)))))
 (let (($x5415 (and $x5414 $x3704)))
 (let (($x5416 (and $x5415 $x3737)))
 (let (($x5417 (and $x5416 $x3770)))
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
 (let ((?x5330 (ite root_107 1 0)))
 (let ((?x5312 (ite root_105 1 0)))
 (let ((?x5297 (ite root_103 1 0)))
 (let ((?x5282 (ite root_101 1 0)))
 (let ((?x5264 (ite root_99 1 0)))
 (let ((?x5249 (ite root_97 1 0)))
 (let ((?x5250 (+ 0 ?x5249)))
 (let ((?x5265 (+ ?x5250 ?x5264)))
 (let ((?x5283 (+ ?x5265 ?x5282)))
 (let ((?x5298 (+ ?x5283 ?x5297)))
 (let ((?x5313 (+ ?x5298 ?x5312)))
 (let (($x5248 (or false root_97)))
 (let (($x5263 (or $x5248 root_99)))
 (let (($x5281 (or $x5263 root_101)))
 (let (($x5296 (or $x5281 root_103)))
 (let (($x5311 (or $x5296 root_105)))
 (let (($x3476 (or false $x3313)))
 (let (($x3493 (or $x3476 $x3342)))
 (let (($x3512 (or $x3493 $x3371)))
 (let (($x3528 (or $x3512 $x3400)))
 (let (($x3544 (or $x3528 $x3429)))
 (let (($x3563 (or $x3544 $x3458)))
 (let (($x5336 (or false (and $x3429 (< rank_104 rank_106)))))
 (let (($x5340 (not root_107)))
 (let (($x5341 (and $x3458 $x5340)))
 (let (($x5318 (or false (and $x3458 (< rank_106 rank_104)))))
 (let (($x5321 (or $x5318 (and $x3400 (< rank_102 rank_104)))))
 (let (($x5325 (not root_105)))
 (let (($x5326 (and $x3429 $x5325)))
 (let (($x5303 (or false (and $x3429 (< rank_104 rank_102)))))
 (let (($x5307 (not root_103)))
 (let (($x5308 (and $x3400 $x5307)))
 (let (($x5288 (or false (and $x3458 (< rank_106 rank_100)))))
 (let (($x5292 (not root_101)))
 (let (($x5293 (and $x3371 $x5292)))
 (let (($x5270 (or false (and $x3371 (< rank_100 rank_98)))))
 (let (($x5273 (or $x5270 (and $x3429 (< rank_104 rank_98)))))
 (let (($x5277 (not root_99)))
 (let (($x5278 (and $x3342 $x5277)))
 (let (($x5255 (or false (and $x3342 (< rank_98 rank_96)))))
 (let (($x5259 (not root_97)))
 (let (($x5260 (and $x3313 $x5259)))
 (let (($x5252 (and true (=> root_97 $x3313))))
 (let (($x5262 (and $x5252 (=> $x5260 (or $x5255 (and $x3400 (< rank_102 rank_96)))))))
 (let (($x5267 (and $x5262 (=> root_99 $x3342))))
 (let (($x5280 (and $x5267 (=> $x5278 (or $x5273 (and $x3313 (< rank_96 rank_98)))))))
 (let (($x5285 (and $x5280 (=> root_101 $x3371))))
 (let (($x5295 (and $x5285 (=> $x5293 (or $x5288 (and $x3342 (< rank_98 rank_100)))))))
 (let (($x5300 (and $x5295 (=> root_103 $x3400))))
 (let (($x5310 (and $x5300 (=> $x5308 (or $x5303 (and $x3313 (< rank_96 rank_102)))))))
 (let (($x5315 (and $x5310 (=> root_105 $x3429))))
 (let (($x5328 (and $x5315 (=> $x5326 (or $x5321 (and $x3342 (< rank_98 rank_104)))))))
 (let (($x5333 (and $x5328 (=> root_107 $x3458))))
 (let (($x5345 (and (and $x5333 (=> $x5341 (or $x5336 (and $x3371 (< rank_100 rank_106))))) (=> $x3563 (or $x5311 root_107)))))
 (let (($x5347 (and $x5345 (<= (+ ?x5313 ?x5330) 1))))
 (let (($x5348 (and true $x5347)))
 (let (($x5562 (= rule_instance 56)))
 (let (($x5555 (and $x5562 (and (and (and $x5348 $x3602) (and $x5417 $x3803)) (and $x5550 $x4120)))))
 (let ((?x5192 (ite root_95 1 0)))
 (let ((?x5174 (ite root_93 1 0)))
 (let ((?x5159 (ite root_91 1 0)))
 (let ((?x5144 (ite root_89 1 0)))
 (let ((?x5126 (ite root_87 1 0)))
 (let ((?x5111 (ite root_85 1 0)))
 (let ((?x5112 (+ 0 ?x5111)))
 (let ((?x5127 (+ ?x5112 ?x5126)))
 (let ((?x5145 (+ ?x5127 ?x5144)))
 (let ((?x5160 (+ ?x5145 ?x5159)))
 (let ((?x5175 (+ ?x5160 ?x5174)))
 (let (($x5110 (or false root_85)))
 (let (($x5125 (or $x5110 root_87)))
 (let (($x5143 (or $x5125 root_89)))
 (let (($x5158 (or $x5143 root_91)))
 (let (($x5173 (or $x5158 root_93)))
 (let (($x5198 (or false (and $x3965 (< rank_92 rank_94)))))
 (let (($x5202 (not root_95)))
 (let (($x5203 (and $x3994 $x5202)))
 (let (($x5180 (or false (and $x3994 (< rank_94 rank_92)))))
 (let (($x5183 (or $x5180 (and $x3936 (< rank_90 rank_92)))))
 (let (($x5187 (not root_93)))
 (let (($x5188 (and $x3965 $x5187)))
 (let (($x5165 (or false (and $x3965 (< rank_92 rank_90)))))
 (let (($x5169 (not root_91)))
 (let (($x5170 (and $x3936 $x5169)))
 (let (($x5150 (or false (and $x3994 (< rank_94 rank_88)))))
 (let (($x5154 (not root_89)))
 (let (($x5155 (and $x3907 $x5154)))
 (let (($x5132 (or false (and $x3907 (< rank_88 rank_86)))))
 (let (($x5135 (or $x5132 (and $x3965 (< rank_92 rank_86)))))
 (let (($x5139 (not root_87)))
 (let (($x5140 (and $x3878 $x5139)))
 (let (($x5117 (or false (and $x3878 (< rank_86 rank_84)))))
 (let (($x5121 (not root_85)))
 (let (($x5122 (and $x3849 $x5121)))
 (let (($x5114 (and true (=> root_85 $x3849))))
 (let (($x5124 (and $x5114 (=> $x5122 (or $x5117 (and $x3936 (< rank_90 rank_84)))))))
 (let (($x5129 (and $x5124 (=> root_87 $x3878))))
 (let (($x5142 (and $x5129 (=> $x5140 (or $x5135 (and $x3849 (< rank_84 rank_86)))))))
 (let (($x5147 (and $x5142 (=> root_89 $x3907))))
 (let (($x5157 (and $x5147 (=> $x5155 (or $x5150 (and $x3878 (< rank_86 rank_88)))))))
 (let (($x5162 (and $x5157 (=> root_91 $x3936))))
 (let (($x5172 (and $x5162 (=> $x5170 (or $x5165 (and $x3849 (< rank_84 rank_90)))))))
 (let (($x5177 (and $x5172 (=> root_93 $x3965))))
 (let (($x5190 (and $x5177 (=> $x5188 (or $x5183 (and $x3878 (< rank_86 rank_92)))))))
 (let (($x5195 (and $x5190 (=> root_95 $x3994))))
 (let (($x5207 (and (and $x5195 (=> $x5203 (or $x5198 (and $x3907 (< rank_88 rank_94))))) (=> $x4096 (or $x5173 root_95)))))
 (let (($x5209 (and $x5207 (<= (+ ?x5175 ?x5192) 1))))
 (let (($x5210 (and true $x5209)))
 (let (($x3641 (and true (=> c_1_0 d_1_14))))
 (let (($x3643 (and $x3641 (=> c_1_1 d_1_14))))
 (let (($x3645 (and $x3643 (=> c_1_2 d_1_14))))
 (let (($x3647 (and $x3645 (=> c_1_3 d_1_14))))
 (let (($x3649 (and $x3647 (=> c_1_4 d_1_14))))
 (let (($x3651 (and $x3649 (=> c_1_5 d_1_14))))
 (let (($x3653 (and $x3651 (=> c_1_6 d_1_14))))
 (let (($x3655 (and $x3653 (=> c_1_7 d_1_14))))
 (let (($x3657 (and $x3655 (=> c_1_8 d_1_14))))
 (let (($x3659 (and $x3657 (=> c_1_9 d_1_14))))
 (let (($x3661 (and $x3659 (=> c_1_10 d_1_14))))
 (let (($x3663 (and $x3661 (=> c_1_11 d_1_14))))
 (let (($x3665 (and $x3663 (=> c_1_12 d_1_14))))
 (let (($x3667 (and $x3665 (=> c_1_13 d_1_14))))
 (let (($x3669 (and $x3667 (=> c_1_14 d_1_14))))
 (let (($x3671 (and $x3669 (=> c_1_15 d_1_14))))
 (let (($x5042 (and true (=> c_0_0 d_0_7))))
 (let (($x5045 (and $x5042 (=> c_0_1 d_0_7))))
 (let (($x5047 (and $x5045 (=> c_0_2 d_0_7))))
 (let (($x5041 (and $x5047 (=> c_0_3 d_0_7))))
 (let (($x5050 (and $x5041 (=> c_0_4 d_0_7))))
 (let (($x5052 (and $x5050 (=> c_0_5 d_0_7))))
 (let (($x5054 (and $x5052 (=> c_0_6 d_0_7))))
 (let (($x5056 (and $x5054 (=> c_0_7 d_0_7))))
 (let (($x5058 (and $x5056 (=> c_0_8 d_0_7))))
 (let (($x5060 (and $x5058 (=> c_0_9 d_0_7))))
 (let (($x5062 (and $x5060 (=> c_0_10 d_0_7))))
 (let (($x5064 (and $x5062 (=> c_0_11 d_0_7))))
 (let (($x5066 (and $x5064 (=> c_0_12 d_0_7))))
 (let (($x5068 (and $x5066 (=> c_0_13 d_0_7))))
 (let (($x5070 (and $x5068 (=> c_0_14 d_0_7))))
 (let (($x5039 (and true c_0_1)))
 (let (($x5043 (and $x5039 c_1_1)))
 (let (($x5073 (and $x5043 (and $x5070 (=> c_0_15 d_0_7)))))
 (let (($x5074 (and $x5073 $x3671)))
 (let (($x5075 (and $x5074 $x3704)))
 (let (($x5076 (and $x5075 $x3737)))
 (let (($x5077 (and $x5076 $x3770)))
 (let ((?x5019 (ite root_83 1 0)))
 (let ((?x5001 (ite root_81 1 0)))
 (let ((?x4986 (ite root_79 1 0)))
 (let ((?x4971 (ite root_77 1 0)))
 (let ((?x4953 (ite root_75 1 0)))
 (let ((?x4938 (ite root_73 1 0)))
 (let ((?x4939 (+ 0 ?x4938)))
 (let ((?x4954 (+ ?x4939 ?x4953)))
 (let ((?x4972 (+ ?x4954 ?x4971)))
 (let ((?x4987 (+ ?x4972 ?x4986)))
 (let ((?x5002 (+ ?x4987 ?x5001)))
 (let (($x4937 (or false root_73)))
 (let (($x4952 (or $x4937 root_75)))
 (let (($x4970 (or $x4952 root_77)))
 (let (($x4985 (or $x4970 root_79)))
 (let (($x5000 (or $x4985 root_81)))
 (let (($x5025 (or false (and $x3429 (< rank_80 rank_82)))))
 (let (($x5029 (not root_83)))
 (let (($x5030 (and $x3458 $x5029)))
 (let (($x5007 (or false (and $x3458 (< rank_82 rank_80)))))
 (let (($x5010 (or $x5007 (and $x3400 (< rank_78 rank_80)))))
 (let (($x5014 (not root_81)))
 (let (($x5015 (and $x3429 $x5014)))
 (let (($x4992 (or false (and $x3429 (< rank_80 rank_78)))))
 (let (($x4996 (not root_79)))
 (let (($x4997 (and $x3400 $x4996)))
 (let (($x4977 (or false (and $x3458 (< rank_82 rank_76)))))
 (let (($x4981 (not root_77)))
 (let (($x4982 (and $x3371 $x4981)))
 (let (($x4959 (or false (and $x3371 (< rank_76 rank_74)))))
 (let (($x4962 (or $x4959 (and $x3429 (< rank_80 rank_74)))))
 (let (($x4966 (not root_75)))
 (let (($x4967 (and $x3342 $x4966)))
 (let (($x4944 (or false (and $x3342 (< rank_74 rank_72)))))
 (let (($x4948 (not root_73)))
 (let (($x4949 (and $x3313 $x4948)))
 (let (($x4941 (and true (=> root_73 $x3313))))
 (let (($x4951 (and $x4941 (=> $x4949 (or $x4944 (and $x3400 (< rank_78 rank_72)))))))
 (let (($x4956 (and $x4951 (=> root_75 $x3342))))
 (let (($x4969 (and $x4956 (=> $x4967 (or $x4962 (and $x3313 (< rank_72 rank_74)))))))
 (let (($x4974 (and $x4969 (=> root_77 $x3371))))
 (let (($x4984 (and $x4974 (=> $x4982 (or $x4977 (and $x3342 (< rank_74 rank_76)))))))
 (let (($x4989 (and $x4984 (=> root_79 $x3400))))
 (let (($x4999 (and $x4989 (=> $x4997 (or $x4992 (and $x3313 (< rank_72 rank_78)))))))
 (let (($x5004 (and $x4999 (=> root_81 $x3429))))
 (let (($x5017 (and $x5004 (=> $x5015 (or $x5010 (and $x3342 (< rank_74 rank_80)))))))
 (let (($x5022 (and $x5017 (=> root_83 $x3458))))
 (let (($x5034 (and (and $x5022 (=> $x5030 (or $x5025 (and $x3371 (< rank_76 rank_82))))) (=> $x3563 (or $x5000 root_83)))))
 (let (($x5036 (and $x5034 (<= (+ ?x5002 ?x5019) 1))))
 (let (($x5037 (and true $x5036)))
 (let (($x5222 (= rule_instance 42)))
 (let (($x5215 (and $x5222 (and (and (and $x5037 $x3602) (and $x5077 $x3803)) (and $x5210 $x4120)))))
 (let ((?x4881 (ite root_71 1 0)))
 (let ((?x4863 (ite root_69 1 0)))
 (let ((?x4848 (ite root_67 1 0)))
 (let ((?x4833 (ite root_65 1 0)))
 (let ((?x4815 (ite root_63 1 0)))
 (let ((?x4800 (ite root_61 1 0)))
 (let ((?x4801 (+ 0 ?x4800)))
 (let ((?x4816 (+ ?x4801 ?x4815)))
 (let ((?x4834 (+ ?x4816 ?x4833)))
 (let ((?x4849 (+ ?x4834 ?x4848)))
 (let ((?x4864 (+ ?x4849 ?x4863)))
 (let (($x4799 (or false root_61)))
 (let (($x4814 (or $x4799 root_63)))
 (let (($x4832 (or $x4814 root_65)))
 (let (($x4847 (or $x4832 root_67)))
 (let (($x4862 (or $x4847 root_69)))
 (let (($x4887 (or false (and $x3965 (< rank_68 rank_70)))))
 (let (($x4891 (not root_71)))
 (let (($x4892 (and $x3994 $x4891)))
 (let (($x4869 (or false (and $x3994 (< rank_70 rank_68)))))
 (let (($x4872 (or $x4869 (and $x3936 (< rank_66 rank_68)))))
 (let (($x4876 (not root_69)))
 (let (($x4877 (and $x3965 $x4876)))
 (let (($x4854 (or false (and $x3965 (< rank_68 rank_66)))))
 (let (($x4858 (not root_67)))
 (let (($x4859 (and $x3936 $x4858)))
 (let (($x4839 (or false (and $x3994 (< rank_70 rank_64)))))
 (let (($x4843 (not root_65)))
 (let (($x4844 (and $x3907 $x4843)))
 (let (($x4821 (or false (and $x3907 (< rank_64 rank_62)))))
 (let (($x4824 (or $x4821 (and $x3965 (< rank_68 rank_62)))))
 (let (($x4828 (not root_63)))
 (let (($x4829 (and $x3878 $x4828)))
 (let (($x4806 (or false (and $x3878 (< rank_62 rank_60)))))
 (let (($x4810 (not root_61)))
 (let (($x4811 (and $x3849 $x4810)))
 (let (($x4803 (and true (=> root_61 $x3849))))
 (let (($x4813 (and $x4803 (=> $x4811 (or $x4806 (and $x3936 (< rank_66 rank_60)))))))
 (let (($x4818 (and $x4813 (=> root_63 $x3878))))
 (let (($x4831 (and $x4818 (=> $x4829 (or $x4824 (and $x3849 (< rank_60 rank_62)))))))
 (let (($x4836 (and $x4831 (=> root_65 $x3907))))
 (let (($x4846 (and $x4836 (=> $x4844 (or $x4839 (and $x3878 (< rank_62 rank_64)))))))
 (let (($x4851 (and $x4846 (=> root_67 $x3936))))
 (let (($x4861 (and $x4851 (=> $x4859 (or $x4854 (and $x3849 (< rank_60 rank_66)))))))
 (let (($x4866 (and $x4861 (=> root_69 $x3965))))
 (let (($x4879 (and $x4866 (=> $x4877 (or $x4872 (and $x3878 (< rank_62 rank_68)))))))
 (let (($x4884 (and $x4879 (=> root_71 $x3994))))
 (let (($x4896 (and (and $x4884 (=> $x4892 (or $x4887 (and $x3907 (< rank_64 rank_70))))) (=> $x4096 (or $x4862 root_71)))))
 (let (($x4898 (and $x4896 (<= (+ ?x4864 ?x4881) 1))))
 (let (($x4899 (and true $x4898)))
 (let (($x4732 (and true (=> c_1_0 d_1_1))))
 (let (($x4734 (and $x4732 (=> c_1_1 d_1_1))))
 (let (($x4736 (and $x4734 (=> c_1_2 d_1_1))))
 (let (($x4738 (and $x4736 (=> c_1_3 d_1_1))))
 (let (($x4740 (and $x4738 (=> c_1_4 d_1_1))))
 (let (($x4742 (and $x4740 (=> c_1_5 d_1_1))))
 (let (($x4744 (and $x4742 (=> c_1_6 d_1_1))))
 (let (($x4746 (and $x4744 (=> c_1_7 d_1_1))))
 (let (($x4748 (and $x4746 (=> c_1_8 d_1_1))))
 (let (($x4750 (and $x4748 (=> c_1_9 d_1_1))))
 (let (($x4752 (and $x4750 (=> c_1_10 d_1_1))))
 (let (($x4754 (and $x4752 (=> c_1_11 d_1_1))))
 (let (($x4756 (and $x4754 (=> c_1_12 d_1_1))))
 (let (($x4758 (and $x4756 (=> c_1_13 d_1_1))))
 (let (($x4760 (and $x4758 (=> c_1_14 d_1_1))))
 (let (($x4704 (and $x4702 (=> c_0_2 d_0_1))))
 (let (($x4698 (and $x4704 (=> c_0_3 d_0_1))))
 (let (($x4707 (and $x4698 (=> c_0_4 d_0_1))))
 (let (($x4709 (and $x4707 (=> c_0_5 d_0_1))))
 (let (($x4711 (and $x4709 $x4710)))
 (let (($x4713 (and $x4711 (=> c_0_7 d_0_1))))
 (let (($x4715 (and $x4713 (=> c_0_8 d_0_1))))
 (let (($x4717 (and $x4715 (=> c_0_9 d_0_1))))
 (let (($x4719 (and $x4717 (=> c_0_10 d_0_1))))
 (let (($x4721 (and $x4719 $x4720)))
 (let (($x4723 (and $x4721 (=> c_0_12 d_0_1))))
 (let (($x4725 (and $x4723 (=> c_0_13 d_0_1))))
 (let (($x4727 (and $x4725 (=> c_0_14 d_0_1))))
 (let (($x4696 (and true c_0_7)))
 (let (($x4700 (and $x4696 c_1_14)))
 (let (($x4730 (and $x4700 (and $x4727 (=> c_0_15 d_0_1)))))
 (let (($x4763 (and $x4730 (and $x4760 (=> c_1_15 d_1_1)))))
 (let (($x4764 (and $x4763 $x3704)))
 (let (($x4765 (and $x4764 $x3737)))
 (let (($x4766 (and $x4765 $x3770)))
 (let ((?x4676 (ite root_59 1 0)))
 (let ((?x4658 (ite root_57 1 0)))
 (let ((?x4643 (ite root_55 1 0)))
 (let ((?x4628 (ite root_53 1 0)))
 (let ((?x4610 (ite root_51 1 0)))
 (let ((?x4595 (ite root_49 1 0)))
 (let ((?x4596 (+ 0 ?x4595)))
 (let ((?x4611 (+ ?x4596 ?x4610)))
 (let ((?x4629 (+ ?x4611 ?x4628)))
 (let ((?x4644 (+ ?x4629 ?x4643)))
 (let ((?x4659 (+ ?x4644 ?x4658)))
 (let (($x4594 (or false root_49)))
 (let (($x4609 (or $x4594 root_51)))
 (let (($x4627 (or $x4609 root_53)))
 (let (($x4642 (or $x4627 root_55)))
 (let (($x4657 (or $x4642 root_57)))
 (let (($x4682 (or false (and $x3429 (< rank_56 rank_58)))))
 (let (($x4686 (not root_59)))
 (let (($x4687 (and $x3458 $x4686)))
 (let (($x4664 (or false (and $x3458 (< rank_58 rank_56)))))
 (let (($x4667 (or $x4664 (and $x3400 (< rank_54 rank_56)))))
 (let (($x4671 (not root_57)))
 (let (($x4672 (and $x3429 $x4671)))
 (let (($x4649 (or false (and $x3429 (< rank_56 rank_54)))))
 (let (($x4653 (not root_55)))
 (let (($x4654 (and $x3400 $x4653)))
 (let (($x4634 (or false (and $x3458 (< rank_58 rank_52)))))
 (let (($x4638 (not root_53)))
 (let (($x4639 (and $x3371 $x4638)))
 (let (($x4616 (or false (and $x3371 (< rank_52 rank_50)))))
 (let (($x4619 (or $x4616 (and $x3429 (< rank_56 rank_50)))))
 (let (($x4623 (not root_51)))
 (let (($x4624 (and $x3342 $x4623)))
 (let (($x4601 (or false (and $x3342 (< rank_50 rank_48)))))
 (let (($x4605 (not root_49)))
 (let (($x4606 (and $x3313 $x4605)))
 (let (($x4598 (and true (=> root_49 $x3313))))
 (let (($x4608 (and $x4598 (=> $x4606 (or $x4601 (and $x3400 (< rank_54 rank_48)))))))
 (let (($x4613 (and $x4608 (=> root_51 $x3342))))
 (let (($x4626 (and $x4613 (=> $x4624 (or $x4619 (and $x3313 (< rank_48 rank_50)))))))
 (let (($x4631 (and $x4626 (=> root_53 $x3371))))
 (let (($x4641 (and $x4631 (=> $x4639 (or $x4634 (and $x3342 (< rank_50 rank_52)))))))
 (let (($x4646 (and $x4641 (=> root_55 $x3400))))
 (let (($x4656 (and $x4646 (=> $x4654 (or $x4649 (and $x3313 (< rank_48 rank_54)))))))
 (let (($x4661 (and $x4656 (=> root_57 $x3429))))
 (let (($x4674 (and $x4661 (=> $x4672 (or $x4667 (and $x3342 (< rank_50 rank_56)))))))
 (let (($x4679 (and $x4674 (=> root_59 $x3458))))
 (let (($x4691 (and (and $x4679 (=> $x4687 (or $x4682 (and $x3371 (< rank_52 rank_58))))) (=> $x3563 (or $x4657 root_59)))))
 (let (($x4693 (and $x4691 (<= (+ ?x4659 ?x4676) 1))))
 (let (($x4694 (and true $x4693)))
 (let (($x4911 (= rule_instance 28)))
 (let (($x4904 (and $x4911 (and (and (and $x4694 $x3602) (and $x4766 $x3803)) (and $x4899 $x4120)))))
 (let ((?x4538 (ite root_47 1 0)))
 (let ((?x4520 (ite root_45 1 0)))
 (let ((?x4505 (ite root_43 1 0)))
 (let ((?x4490 (ite root_41 1 0)))
 (let ((?x4472 (ite root_39 1 0)))
 (let ((?x4457 (ite root_37 1 0)))
 (let ((?x4458 (+ 0 ?x4457)))
 (let ((?x4473 (+ ?x4458 ?x4472)))
 (let ((?x4491 (+ ?x4473 ?x4490)))
 (let ((?x4506 (+ ?x4491 ?x4505)))
 (let ((?x4521 (+ ?x4506 ?x4520)))
 (let (($x4456 (or false root_37)))
 (let (($x4471 (or $x4456 root_39)))
 (let (($x4489 (or $x4471 root_41)))
 (let (($x4504 (or $x4489 root_43)))
 (let (($x4519 (or $x4504 root_45)))
 (let (($x4544 (or false (and $x3965 (< rank_44 rank_46)))))
 (let (($x4548 (not root_47)))
 (let (($x4549 (and $x3994 $x4548)))
 (let (($x4526 (or false (and $x3994 (< rank_46 rank_44)))))
 (let (($x4529 (or $x4526 (and $x3936 (< rank_42 rank_44)))))
 (let (($x4533 (not root_45)))
 (let (($x4534 (and $x3965 $x4533)))
 (let (($x4511 (or false (and $x3965 (< rank_44 rank_42)))))
 (let (($x4515 (not root_43)))
 (let (($x4516 (and $x3936 $x4515)))
 (let (($x4496 (or false (and $x3994 (< rank_46 rank_40)))))
 (let (($x4500 (not root_41)))
 (let (($x4501 (and $x3907 $x4500)))
 (let (($x4478 (or false (and $x3907 (< rank_40 rank_38)))))
 (let (($x4481 (or $x4478 (and $x3965 (< rank_44 rank_38)))))
 (let (($x4485 (not root_39)))
 (let (($x4486 (and $x3878 $x4485)))
 (let (($x4463 (or false (and $x3878 (< rank_38 rank_36)))))
 (let (($x4467 (not root_37)))
 (let (($x4468 (and $x3849 $x4467)))
 (let (($x4460 (and true (=> root_37 $x3849))))
 (let (($x4470 (and $x4460 (=> $x4468 (or $x4463 (and $x3936 (< rank_42 rank_36)))))))
 (let (($x4475 (and $x4470 (=> root_39 $x3878))))
 (let (($x4488 (and $x4475 (=> $x4486 (or $x4481 (and $x3849 (< rank_36 rank_38)))))))
 (let (($x4493 (and $x4488 (=> root_41 $x3907))))
 (let (($x4503 (and $x4493 (=> $x4501 (or $x4496 (and $x3878 (< rank_38 rank_40)))))))
 (let (($x4508 (and $x4503 (=> root_43 $x3936))))
 (let (($x4518 (and $x4508 (=> $x4516 (or $x4511 (and $x3849 (< rank_36 rank_42)))))))
 (let (($x4523 (and $x4518 (=> root_45 $x3965))))
 (let (($x4536 (and $x4523 (=> $x4534 (or $x4529 (and $x3878 (< rank_38 rank_44)))))))
 (let (($x4541 (and $x4536 (=> root_47 $x3994))))
 (let (($x4553 (and (and $x4541 (=> $x4549 (or $x4544 (and $x3907 (< rank_40 rank_46))))) (=> $x4096 (or $x4519 root_47)))))
 (let (($x4555 (and $x4553 (<= (+ ?x4521 ?x4538) 1))))
 (let (($x4556 (and true $x4555)))
 (let (($x4389 (and true (=> c_1_0 d_1_0))))
 (let (($x4391 (and $x4389 (=> c_1_1 d_1_0))))
 (let (($x4393 (and $x4391 (=> c_1_2 d_1_0))))
 (let (($x4395 (and $x4393 (=> c_1_3 d_1_0))))
 (let (($x4397 (and $x4395 (=> c_1_4 d_1_0))))
 (let (($x4399 (and $x4397 (=> c_1_5 d_1_0))))
 (let (($x4401 (and $x4399 (=> c_1_6 d_1_0))))
 (let (($x4403 (and $x4401 (=> c_1_7 d_1_0))))
 (let (($x4405 (and $x4403 (=> c_1_8 d_1_0))))
 (let (($x4407 (and $x4405 (=> c_1_9 d_1_0))))
 (let (($x4409 (and $x4407 (=> c_1_10 d_1_0))))
 (let (($x4411 (and $x4409 (=> c_1_11 d_1_0))))
 (let (($x4413 (and $x4411 (=> c_1_12 d_1_0))))
 (let (($x4415 (and $x4413 (=> c_1_13 d_1_0))))
 (let (($x4417 (and $x4415 (=> c_1_14 d_1_0))))
 (let (($x4356 (and true (=> c_0_0 d_0_6))))
 (let (($x4359 (and $x4356 (=> c_0_1 d_0_6))))
 (let (($x4361 (and $x4359 (=> c_0_2 d_0_6))))
 (let (($x4355 (and $x4361 (=> c_0_3 d_0_6))))
 (let (($x4364 (and $x4355 (=> c_0_4 d_0_6))))
 (let (($x4366 (and $x4364 (=> c_0_5 d_0_6))))
 (let (($x4368 (and $x4366 (=> c_0_6 d_0_6))))
 (let (($x4370 (and $x4368 (=> c_0_7 d_0_6))))
 (let (($x4372 (and $x4370 (=> c_0_8 d_0_6))))
 (let (($x4374 (and $x4372 (=> c_0_9 d_0_6))))
 (let (($x4376 (and $x4374 (=> c_0_10 d_0_6))))
 (let (($x4378 (and $x4376 (=> c_0_11 d_0_6))))
 (let (($x4380 (and $x4378 (=> c_0_12 d_0_6))))
 (let (($x4382 (and $x4380 (=> c_0_13 d_0_6))))
 (let (($x4384 (and $x4382 (=> c_0_14 d_0_6))))
 (let (($x4353 (and true c_0_2)))
 (let (($x4357 (and $x4353 c_1_14)))
 (let (($x4387 (and $x4357 (and $x4384 (=> c_0_15 d_0_6)))))
 (let (($x4420 (and $x4387 (and $x4417 (=> c_1_15 d_1_0)))))
 (let (($x4421 (and $x4420 $x3704)))
 (let (($x4422 (and $x4421 $x3737)))
 (let (($x4423 (and $x4422 $x3770)))
 (let ((?x4333 (ite root_35 1 0)))
 (let ((?x4315 (ite root_33 1 0)))
 (let ((?x4300 (ite root_31 1 0)))
 (let ((?x4285 (ite root_29 1 0)))
 (let ((?x4267 (ite root_27 1 0)))
 (let ((?x4252 (ite root_25 1 0)))
 (let ((?x4253 (+ 0 ?x4252)))
 (let ((?x4268 (+ ?x4253 ?x4267)))
 (let ((?x4286 (+ ?x4268 ?x4285)))
 (let ((?x4301 (+ ?x4286 ?x4300)))
 (let ((?x4316 (+ ?x4301 ?x4315)))
 (let (($x4251 (or false root_25)))
 (let (($x4266 (or $x4251 root_27)))
 (let (($x4284 (or $x4266 root_29)))
 (let (($x4299 (or $x4284 root_31)))
 (let (($x4314 (or $x4299 root_33)))
 (let (($x4339 (or false (and $x3429 (< rank_32 rank_34)))))
 (let (($x4343 (not root_35)))
 (let (($x4344 (and $x3458 $x4343)))
 (let (($x4321 (or false (and $x3458 (< rank_34 rank_32)))))
 (let (($x4324 (or $x4321 (and $x3400 (< rank_30 rank_32)))))
 (let (($x4328 (not root_33)))
 (let (($x4329 (and $x3429 $x4328)))
 (let (($x4306 (or false (and $x3429 (< rank_32 rank_30)))))
 (let (($x4310 (not root_31)))
 (let (($x4311 (and $x3400 $x4310)))
 (let (($x4291 (or false (and $x3458 (< rank_34 rank_28)))))
 (let (($x4295 (not root_29)))
 (let (($x4296 (and $x3371 $x4295)))
 (let (($x4273 (or false (and $x3371 (< rank_28 rank_26)))))
 (let (($x4276 (or $x4273 (and $x3429 (< rank_32 rank_26)))))
 (let (($x4280 (not root_27)))
 (let (($x4281 (and $x3342 $x4280)))
 (let (($x4258 (or false (and $x3342 (< rank_26 rank_24)))))
 (let (($x4262 (not root_25)))
 (let (($x4263 (and $x3313 $x4262)))
 (let (($x4255 (and true (=> root_25 $x3313))))
 (let (($x4265 (and $x4255 (=> $x4263 (or $x4258 (and $x3400 (< rank_30 rank_24)))))))
 (let (($x4270 (and $x4265 (=> root_27 $x3342))))
 (let (($x4283 (and $x4270 (=> $x4281 (or $x4276 (and $x3313 (< rank_24 rank_26)))))))
 (let (($x4288 (and $x4283 (=> root_29 $x3371))))
 (let (($x4298 (and $x4288 (=> $x4296 (or $x4291 (and $x3342 (< rank_26 rank_28)))))))
 (let (($x4303 (and $x4298 (=> root_31 $x3400))))
 (let (($x4313 (and $x4303 (=> $x4311 (or $x4306 (and $x3313 (< rank_24 rank_30)))))))
 (let (($x4318 (and $x4313 (=> root_33 $x3429))))
 (let (($x4331 (and $x4318 (=> $x4329 (or $x4324 (and $x3342 (< rank_26 rank_32)))))))
 (let (($x4336 (and $x4331 (=> root_35 $x3458))))
 (let (($x4348 (and (and $x4336 (=> $x4344 (or $x4339 (and $x3371 (< rank_28 rank_34))))) (=> $x3563 (or $x4314 root_35)))))
 (let (($x4350 (and $x4348 (<= (+ ?x4316 ?x4333) 1))))
 (let (($x4351 (and true $x4350)))
 (let (($x4568 (= rule_instance 14)))
 (let (($x4561 (and $x4568 (and (and (and $x4351 $x3602) (and $x4423 $x3803)) (and $x4556 $x4120)))))
 (let ((?x4098 (ite root_23 1 0)))
 (let ((?x4079 (ite root_21 1 0)))
 (let ((?x4063 (ite root_19 1 0)))
 (let ((?x4047 (ite root_17 1 0)))
 (let ((?x4028 (ite root_15 1 0)))
 (let ((?x4012 (ite root_13 1 0)))
 (let ((?x4013 (+ 0 ?x4012)))
 (let ((?x4029 (+ ?x4013 ?x4028)))
 (let ((?x4048 (+ ?x4029 ?x4047)))
 (let ((?x4064 (+ ?x4048 ?x4063)))
 (let ((?x4080 (+ ?x4064 ?x4079)))
 (let (($x4011 (or false root_13)))
 (let (($x4027 (or $x4011 root_15)))
 (let (($x4046 (or $x4027 root_17)))
 (let (($x4062 (or $x4046 root_19)))
 (let (($x4078 (or $x4062 root_21)))
 (let (($x4104 (or false (and $x3965 (< rank_20 rank_22)))))
 (let (($x4108 (not root_23)))
 (let (($x4109 (and $x3994 $x4108)))
 (let (($x4085 (or false (and $x3994 (< rank_22 rank_20)))))
 (let (($x4088 (or $x4085 (and $x3936 (< rank_18 rank_20)))))
 (let (($x4092 (not root_21)))
 (let (($x4093 (and $x3965 $x4092)))
 (let (($x4069 (or false (and $x3965 (< rank_20 rank_18)))))
 (let (($x4073 (not root_19)))
 (let (($x4074 (and $x3936 $x4073)))
 (let (($x4053 (or false (and $x3994 (< rank_22 rank_16)))))
 (let (($x4057 (not root_17)))
 (let (($x4058 (and $x3907 $x4057)))
 (let (($x4034 (or false (and $x3907 (< rank_16 rank_14)))))
 (let (($x4037 (or $x4034 (and $x3965 (< rank_20 rank_14)))))
 (let (($x4041 (not root_15)))
 (let (($x4042 (and $x3878 $x4041)))
 (let (($x4018 (or false (and $x3878 (< rank_14 rank_12)))))
 (let (($x4022 (not root_13)))
 (let (($x4023 (and $x3849 $x4022)))
 (let (($x4015 (and true (=> root_13 $x3849))))
 (let (($x4025 (and $x4015 (=> $x4023 (or $x4018 (and $x3936 (< rank_18 rank_12)))))))
 (let (($x4031 (and $x4025 (=> root_15 $x3878))))
 (let (($x4044 (and $x4031 (=> $x4042 (or $x4037 (and $x3849 (< rank_12 rank_14)))))))
 (let (($x4050 (and $x4044 (=> root_17 $x3907))))
 (let (($x4060 (and $x4050 (=> $x4058 (or $x4053 (and $x3878 (< rank_14 rank_16)))))))
 (let (($x4066 (and $x4060 (=> root_19 $x3936))))
 (let (($x4076 (and $x4066 (=> $x4074 (or $x4069 (and $x3849 (< rank_12 rank_18)))))))
 (let (($x4082 (and $x4076 (=> root_21 $x3965))))
 (let (($x4095 (and $x4082 (=> $x4093 (or $x4088 (and $x3878 (< rank_14 rank_20)))))))
 (let (($x4101 (and $x4095 (=> root_23 $x3994))))
 (let (($x4113 (and (and $x4101 (=> $x4109 (or $x4104 (and $x3907 (< rank_16 rank_22))))) (=> $x4096 (or $x4078 root_23)))))
 (let (($x4115 (and $x4113 (<= (+ ?x4080 ?x4098) 1))))
 (let (($x4116 (and true $x4115)))
 (let (($x3608 (and true (=> c_0_0 d_0_2))))
 (let (($x3592 (and $x3608 (=> c_0_1 d_0_2))))
 (let (($x3612 (and $x3592 $x3611)))
 (let (($x3614 (and $x3612 (=> c_0_3 d_0_2))))
 (let (($x3616 (and $x3614 (=> c_0_4 d_0_2))))
 (let (($x3618 (and $x3616 (=> c_0_5 d_0_2))))
 (let (($x3620 (and $x3618 (=> c_0_6 d_0_2))))
 (let (($x3622 (and $x3620 $x3621)))
 (let (($x3624 (and $x3622 (=> c_0_8 d_0_2))))
 (let (($x3626 (and $x3624 (=> c_0_9 d_0_2))))
 (let (($x3628 (and $x3626 (=> c_0_10 d_0_2))))
 (let (($x3630 (and $x3628 (=> c_0_11 d_0_2))))
 (let (($x3632 (and $x3630 $x3631)))
 (let (($x3634 (and $x3632 (=> c_0_13 d_0_2))))
 (let (($x3636 (and $x3634 (=> c_0_14 d_0_2))))
 (let (($x3605 (and true c_0_6)))
 (let (($x3600 (and $x3605 c_1_0)))
 (let (($x3639 (and $x3600 (and $x3636 (=> c_0_15 d_0_2)))))
 (let (($x3672 (and $x3639 $x3671)))
 (let (($x3705 (and $x3672 $x3704)))
 (let (($x3738 (and $x3705 $x3737)))
 (let (($x3771 (and $x3738 $x3770)))
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
 (let (($x4216 (= rule_instance 0)))
 (let (($x4217 (and $x4216 (and (and (and $x3583 $x3602) (and $x3771 $x3803)) (and $x4116 $x4120)))))
 (let (($x4220 (or false (and $x4217 $x4218))))
 (let (($x4563 (or $x4220 (and $x4561 $x4218))))
 (let (($x4906 (or $x4563 (and $x4904 $x4218))))
 (let (($x5217 (or $x4906 (and $x5215 $x4218))))
 (or $x5217 (and $x5555 $x4218))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
