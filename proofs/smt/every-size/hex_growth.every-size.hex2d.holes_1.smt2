; holon proof obligation for every region: system hex_growth, lattice hex2d, property holes.1
; window: every rule shape with its first cell at the origin, and every point within 2 steps of its pattern, free (61 cells; proofs/README.md)
; expected: unsat (the property holds on every region of the lattice)
(set-logic ALL)
; 
(set-info :status unknown)
(declare-fun c_0_3 () Bool)
(declare-fun c_0_2 () Bool)
(declare-fun c_0_1 () Bool)
(declare-fun c_0_0 () Bool)
(declare-fun c_1_3 () Bool)
(declare-fun c_1_2 () Bool)
(declare-fun c_1_1 () Bool)
(declare-fun c_1_0 () Bool)
(declare-fun c_2_3 () Bool)
(declare-fun c_2_2 () Bool)
(declare-fun c_2_1 () Bool)
(declare-fun c_2_0 () Bool)
(declare-fun c_3_3 () Bool)
(declare-fun c_3_2 () Bool)
(declare-fun c_3_1 () Bool)
(declare-fun c_3_0 () Bool)
(declare-fun c_4_3 () Bool)
(declare-fun c_4_2 () Bool)
(declare-fun c_4_1 () Bool)
(declare-fun c_4_0 () Bool)
(declare-fun c_5_3 () Bool)
(declare-fun c_5_2 () Bool)
(declare-fun c_5_1 () Bool)
(declare-fun c_5_0 () Bool)
(declare-fun c_6_3 () Bool)
(declare-fun c_6_2 () Bool)
(declare-fun c_6_1 () Bool)
(declare-fun c_6_0 () Bool)
(declare-fun c_7_3 () Bool)
(declare-fun c_7_2 () Bool)
(declare-fun c_7_1 () Bool)
(declare-fun c_7_0 () Bool)
(declare-fun c_8_3 () Bool)
(declare-fun c_8_2 () Bool)
(declare-fun c_8_1 () Bool)
(declare-fun c_8_0 () Bool)
(declare-fun c_9_3 () Bool)
(declare-fun c_9_2 () Bool)
(declare-fun c_9_1 () Bool)
(declare-fun c_9_0 () Bool)
(declare-fun c_10_3 () Bool)
(declare-fun c_10_2 () Bool)
(declare-fun c_10_1 () Bool)
(declare-fun c_10_0 () Bool)
(declare-fun c_11_3 () Bool)
(declare-fun c_11_2 () Bool)
(declare-fun c_11_1 () Bool)
(declare-fun c_11_0 () Bool)
(declare-fun c_12_3 () Bool)
(declare-fun c_12_2 () Bool)
(declare-fun c_12_1 () Bool)
(declare-fun c_12_0 () Bool)
(declare-fun c_13_3 () Bool)
(declare-fun c_13_2 () Bool)
(declare-fun c_13_1 () Bool)
(declare-fun c_13_0 () Bool)
(declare-fun c_14_3 () Bool)
(declare-fun c_14_2 () Bool)
(declare-fun c_14_1 () Bool)
(declare-fun c_14_0 () Bool)
(declare-fun c_15_3 () Bool)
(declare-fun c_15_2 () Bool)
(declare-fun c_15_1 () Bool)
(declare-fun c_15_0 () Bool)
(declare-fun c_16_3 () Bool)
(declare-fun c_16_2 () Bool)
(declare-fun c_16_1 () Bool)
(declare-fun c_16_0 () Bool)
(declare-fun c_17_3 () Bool)
(declare-fun c_17_2 () Bool)
(declare-fun c_17_1 () Bool)
(declare-fun c_17_0 () Bool)
(declare-fun c_18_3 () Bool)
(declare-fun c_18_2 () Bool)
(declare-fun c_18_1 () Bool)
(declare-fun c_18_0 () Bool)
(declare-fun c_19_3 () Bool)
(declare-fun c_19_2 () Bool)
(declare-fun c_19_1 () Bool)
(declare-fun c_19_0 () Bool)
(declare-fun c_20_3 () Bool)
(declare-fun c_20_2 () Bool)
(declare-fun c_20_1 () Bool)
(declare-fun c_20_0 () Bool)
(declare-fun c_21_3 () Bool)
(declare-fun c_21_2 () Bool)
(declare-fun c_21_1 () Bool)
(declare-fun c_21_0 () Bool)
(declare-fun c_22_3 () Bool)
(declare-fun c_22_2 () Bool)
(declare-fun c_22_1 () Bool)
(declare-fun c_22_0 () Bool)
(declare-fun c_23_3 () Bool)
(declare-fun c_23_2 () Bool)
(declare-fun c_23_1 () Bool)
(declare-fun c_23_0 () Bool)
(declare-fun c_24_3 () Bool)
(declare-fun c_24_2 () Bool)
(declare-fun c_24_1 () Bool)
(declare-fun c_24_0 () Bool)
(declare-fun c_25_3 () Bool)
(declare-fun c_25_2 () Bool)
(declare-fun c_25_1 () Bool)
(declare-fun c_25_0 () Bool)
(declare-fun c_26_3 () Bool)
(declare-fun c_26_2 () Bool)
(declare-fun c_26_1 () Bool)
(declare-fun c_26_0 () Bool)
(declare-fun c_27_3 () Bool)
(declare-fun c_27_2 () Bool)
(declare-fun c_27_1 () Bool)
(declare-fun c_27_0 () Bool)
(declare-fun c_28_3 () Bool)
(declare-fun c_28_2 () Bool)
(declare-fun c_28_1 () Bool)
(declare-fun c_28_0 () Bool)
(declare-fun c_29_3 () Bool)
(declare-fun c_29_2 () Bool)
(declare-fun c_29_1 () Bool)
(declare-fun c_29_0 () Bool)
(declare-fun c_30_3 () Bool)
(declare-fun c_30_2 () Bool)
(declare-fun c_30_1 () Bool)
(declare-fun c_30_0 () Bool)
(declare-fun c_31_3 () Bool)
(declare-fun c_31_2 () Bool)
(declare-fun c_31_1 () Bool)
(declare-fun c_31_0 () Bool)
(declare-fun c_32_3 () Bool)
(declare-fun c_32_2 () Bool)
(declare-fun c_32_1 () Bool)
(declare-fun c_32_0 () Bool)
(declare-fun c_33_3 () Bool)
(declare-fun c_33_2 () Bool)
(declare-fun c_33_1 () Bool)
(declare-fun c_33_0 () Bool)
(declare-fun c_34_3 () Bool)
(declare-fun c_34_2 () Bool)
(declare-fun c_34_1 () Bool)
(declare-fun c_34_0 () Bool)
(declare-fun c_35_3 () Bool)
(declare-fun c_35_2 () Bool)
(declare-fun c_35_1 () Bool)
(declare-fun c_35_0 () Bool)
(declare-fun c_36_3 () Bool)
(declare-fun c_36_2 () Bool)
(declare-fun c_36_1 () Bool)
(declare-fun c_36_0 () Bool)
(declare-fun c_37_3 () Bool)
(declare-fun c_37_2 () Bool)
(declare-fun c_37_1 () Bool)
(declare-fun c_37_0 () Bool)
(declare-fun c_38_3 () Bool)
(declare-fun c_38_2 () Bool)
(declare-fun c_38_1 () Bool)
(declare-fun c_38_0 () Bool)
(declare-fun c_39_3 () Bool)
(declare-fun c_39_2 () Bool)
(declare-fun c_39_1 () Bool)
(declare-fun c_39_0 () Bool)
(declare-fun c_40_3 () Bool)
(declare-fun c_40_2 () Bool)
(declare-fun c_40_1 () Bool)
(declare-fun c_40_0 () Bool)
(declare-fun c_41_3 () Bool)
(declare-fun c_41_2 () Bool)
(declare-fun c_41_1 () Bool)
(declare-fun c_41_0 () Bool)
(declare-fun c_42_3 () Bool)
(declare-fun c_42_2 () Bool)
(declare-fun c_42_1 () Bool)
(declare-fun c_42_0 () Bool)
(declare-fun c_43_3 () Bool)
(declare-fun c_43_2 () Bool)
(declare-fun c_43_1 () Bool)
(declare-fun c_43_0 () Bool)
(declare-fun c_44_3 () Bool)
(declare-fun c_44_2 () Bool)
(declare-fun c_44_1 () Bool)
(declare-fun c_44_0 () Bool)
(declare-fun c_45_3 () Bool)
(declare-fun c_45_2 () Bool)
(declare-fun c_45_1 () Bool)
(declare-fun c_45_0 () Bool)
(declare-fun c_46_3 () Bool)
(declare-fun c_46_2 () Bool)
(declare-fun c_46_1 () Bool)
(declare-fun c_46_0 () Bool)
(declare-fun c_47_3 () Bool)
(declare-fun c_47_2 () Bool)
(declare-fun c_47_1 () Bool)
(declare-fun c_47_0 () Bool)
(declare-fun c_48_3 () Bool)
(declare-fun c_48_2 () Bool)
(declare-fun c_48_1 () Bool)
(declare-fun c_48_0 () Bool)
(declare-fun c_49_3 () Bool)
(declare-fun c_49_2 () Bool)
(declare-fun c_49_1 () Bool)
(declare-fun c_49_0 () Bool)
(declare-fun c_50_3 () Bool)
(declare-fun c_50_2 () Bool)
(declare-fun c_50_1 () Bool)
(declare-fun c_50_0 () Bool)
(declare-fun c_51_3 () Bool)
(declare-fun c_51_2 () Bool)
(declare-fun c_51_1 () Bool)
(declare-fun c_51_0 () Bool)
(declare-fun c_52_3 () Bool)
(declare-fun c_52_2 () Bool)
(declare-fun c_52_1 () Bool)
(declare-fun c_52_0 () Bool)
(declare-fun c_53_3 () Bool)
(declare-fun c_53_2 () Bool)
(declare-fun c_53_1 () Bool)
(declare-fun c_53_0 () Bool)
(declare-fun c_54_3 () Bool)
(declare-fun c_54_2 () Bool)
(declare-fun c_54_1 () Bool)
(declare-fun c_54_0 () Bool)
(declare-fun c_55_3 () Bool)
(declare-fun c_55_2 () Bool)
(declare-fun c_55_1 () Bool)
(declare-fun c_55_0 () Bool)
(declare-fun c_56_3 () Bool)
(declare-fun c_56_2 () Bool)
(declare-fun c_56_1 () Bool)
(declare-fun c_56_0 () Bool)
(declare-fun c_57_3 () Bool)
(declare-fun c_57_2 () Bool)
(declare-fun c_57_1 () Bool)
(declare-fun c_57_0 () Bool)
(declare-fun c_58_3 () Bool)
(declare-fun c_58_2 () Bool)
(declare-fun c_58_1 () Bool)
(declare-fun c_58_0 () Bool)
(declare-fun c_59_3 () Bool)
(declare-fun c_59_2 () Bool)
(declare-fun c_59_1 () Bool)
(declare-fun c_59_0 () Bool)
(declare-fun c_60_3 () Bool)
(declare-fun c_60_2 () Bool)
(declare-fun c_60_1 () Bool)
(declare-fun c_60_0 () Bool)
(declare-fun d_0_3 () Bool)
(declare-fun d_0_2 () Bool)
(declare-fun d_0_1 () Bool)
(declare-fun d_0_0 () Bool)
(declare-fun d_1_3 () Bool)
(declare-fun d_1_2 () Bool)
(declare-fun d_1_1 () Bool)
(declare-fun d_1_0 () Bool)
(declare-fun d_2_3 () Bool)
(declare-fun d_2_2 () Bool)
(declare-fun d_2_1 () Bool)
(declare-fun d_2_0 () Bool)
(declare-fun d_3_3 () Bool)
(declare-fun d_3_2 () Bool)
(declare-fun d_3_1 () Bool)
(declare-fun d_3_0 () Bool)
(declare-fun d_4_3 () Bool)
(declare-fun d_4_2 () Bool)
(declare-fun d_4_1 () Bool)
(declare-fun d_4_0 () Bool)
(declare-fun d_5_3 () Bool)
(declare-fun d_5_2 () Bool)
(declare-fun d_5_1 () Bool)
(declare-fun d_5_0 () Bool)
(declare-fun d_6_3 () Bool)
(declare-fun d_6_2 () Bool)
(declare-fun d_6_1 () Bool)
(declare-fun d_6_0 () Bool)
(declare-fun d_7_3 () Bool)
(declare-fun d_7_2 () Bool)
(declare-fun d_7_1 () Bool)
(declare-fun d_7_0 () Bool)
(declare-fun d_8_3 () Bool)
(declare-fun d_8_2 () Bool)
(declare-fun d_8_1 () Bool)
(declare-fun d_8_0 () Bool)
(declare-fun d_9_3 () Bool)
(declare-fun d_9_2 () Bool)
(declare-fun d_9_1 () Bool)
(declare-fun d_9_0 () Bool)
(declare-fun d_10_3 () Bool)
(declare-fun d_10_2 () Bool)
(declare-fun d_10_1 () Bool)
(declare-fun d_10_0 () Bool)
(declare-fun d_11_3 () Bool)
(declare-fun d_11_2 () Bool)
(declare-fun d_11_1 () Bool)
(declare-fun d_11_0 () Bool)
(declare-fun d_12_3 () Bool)
(declare-fun d_12_2 () Bool)
(declare-fun d_12_1 () Bool)
(declare-fun d_12_0 () Bool)
(declare-fun d_13_3 () Bool)
(declare-fun d_13_2 () Bool)
(declare-fun d_13_1 () Bool)
(declare-fun d_13_0 () Bool)
(declare-fun d_14_3 () Bool)
(declare-fun d_14_2 () Bool)
(declare-fun d_14_1 () Bool)
(declare-fun d_14_0 () Bool)
(declare-fun d_15_3 () Bool)
(declare-fun d_15_2 () Bool)
(declare-fun d_15_1 () Bool)
(declare-fun d_15_0 () Bool)
(declare-fun d_16_3 () Bool)
(declare-fun d_16_2 () Bool)
(declare-fun d_16_1 () Bool)
(declare-fun d_16_0 () Bool)
(declare-fun d_17_3 () Bool)
(declare-fun d_17_2 () Bool)
(declare-fun d_17_1 () Bool)
(declare-fun d_17_0 () Bool)
(declare-fun d_18_3 () Bool)
(declare-fun d_18_2 () Bool)
(declare-fun d_18_1 () Bool)
(declare-fun d_18_0 () Bool)
(declare-fun d_19_3 () Bool)
(declare-fun d_19_2 () Bool)
(declare-fun d_19_1 () Bool)
(declare-fun d_19_0 () Bool)
(declare-fun d_20_3 () Bool)
(declare-fun d_20_2 () Bool)
(declare-fun d_20_1 () Bool)
(declare-fun d_20_0 () Bool)
(declare-fun d_21_3 () Bool)
(declare-fun d_21_2 () Bool)
(declare-fun d_21_1 () Bool)
(declare-fun d_21_0 () Bool)
(declare-fun d_22_3 () Bool)
(declare-fun d_22_2 () Bool)
(declare-fun d_22_1 () Bool)
(declare-fun d_22_0 () Bool)
(declare-fun d_23_3 () Bool)
(declare-fun d_23_2 () Bool)
(declare-fun d_23_1 () Bool)
(declare-fun d_23_0 () Bool)
(declare-fun d_24_3 () Bool)
(declare-fun d_24_2 () Bool)
(declare-fun d_24_1 () Bool)
(declare-fun d_24_0 () Bool)
(declare-fun d_25_3 () Bool)
(declare-fun d_25_2 () Bool)
(declare-fun d_25_1 () Bool)
(declare-fun d_25_0 () Bool)
(declare-fun d_26_3 () Bool)
(declare-fun d_26_2 () Bool)
(declare-fun d_26_1 () Bool)
(declare-fun d_26_0 () Bool)
(declare-fun d_27_3 () Bool)
(declare-fun d_27_2 () Bool)
(declare-fun d_27_1 () Bool)
(declare-fun d_27_0 () Bool)
(declare-fun d_28_3 () Bool)
(declare-fun d_28_2 () Bool)
(declare-fun d_28_1 () Bool)
(declare-fun d_28_0 () Bool)
(declare-fun d_29_3 () Bool)
(declare-fun d_29_2 () Bool)
(declare-fun d_29_1 () Bool)
(declare-fun d_29_0 () Bool)
(declare-fun d_30_3 () Bool)
(declare-fun d_30_2 () Bool)
(declare-fun d_30_1 () Bool)
(declare-fun d_30_0 () Bool)
(declare-fun d_31_3 () Bool)
(declare-fun d_31_2 () Bool)
(declare-fun d_31_1 () Bool)
(declare-fun d_31_0 () Bool)
(declare-fun d_32_3 () Bool)
(declare-fun d_32_2 () Bool)
(declare-fun d_32_1 () Bool)
(declare-fun d_32_0 () Bool)
(declare-fun d_33_3 () Bool)
(declare-fun d_33_2 () Bool)
(declare-fun d_33_1 () Bool)
(declare-fun d_33_0 () Bool)
(declare-fun d_34_3 () Bool)
(declare-fun d_34_2 () Bool)
(declare-fun d_34_1 () Bool)
(declare-fun d_34_0 () Bool)
(declare-fun d_35_3 () Bool)
(declare-fun d_35_2 () Bool)
(declare-fun d_35_1 () Bool)
(declare-fun d_35_0 () Bool)
(declare-fun d_36_3 () Bool)
(declare-fun d_36_2 () Bool)
(declare-fun d_36_1 () Bool)
(declare-fun d_36_0 () Bool)
(declare-fun d_37_3 () Bool)
(declare-fun d_37_2 () Bool)
(declare-fun d_37_1 () Bool)
(declare-fun d_37_0 () Bool)
(declare-fun d_38_3 () Bool)
(declare-fun d_38_2 () Bool)
(declare-fun d_38_1 () Bool)
(declare-fun d_38_0 () Bool)
(declare-fun d_39_3 () Bool)
(declare-fun d_39_2 () Bool)
(declare-fun d_39_1 () Bool)
(declare-fun d_39_0 () Bool)
(declare-fun d_40_3 () Bool)
(declare-fun d_40_2 () Bool)
(declare-fun d_40_1 () Bool)
(declare-fun d_40_0 () Bool)
(declare-fun d_41_3 () Bool)
(declare-fun d_41_2 () Bool)
(declare-fun d_41_1 () Bool)
(declare-fun d_41_0 () Bool)
(declare-fun d_42_3 () Bool)
(declare-fun d_42_2 () Bool)
(declare-fun d_42_1 () Bool)
(declare-fun d_42_0 () Bool)
(declare-fun d_43_3 () Bool)
(declare-fun d_43_2 () Bool)
(declare-fun d_43_1 () Bool)
(declare-fun d_43_0 () Bool)
(declare-fun d_44_3 () Bool)
(declare-fun d_44_2 () Bool)
(declare-fun d_44_1 () Bool)
(declare-fun d_44_0 () Bool)
(declare-fun d_45_3 () Bool)
(declare-fun d_45_2 () Bool)
(declare-fun d_45_1 () Bool)
(declare-fun d_45_0 () Bool)
(declare-fun d_46_3 () Bool)
(declare-fun d_46_2 () Bool)
(declare-fun d_46_1 () Bool)
(declare-fun d_46_0 () Bool)
(declare-fun d_47_3 () Bool)
(declare-fun d_47_2 () Bool)
(declare-fun d_47_1 () Bool)
(declare-fun d_47_0 () Bool)
(declare-fun d_48_3 () Bool)
(declare-fun d_48_2 () Bool)
(declare-fun d_48_1 () Bool)
(declare-fun d_48_0 () Bool)
(declare-fun d_49_3 () Bool)
(declare-fun d_49_2 () Bool)
(declare-fun d_49_1 () Bool)
(declare-fun d_49_0 () Bool)
(declare-fun d_50_3 () Bool)
(declare-fun d_50_2 () Bool)
(declare-fun d_50_1 () Bool)
(declare-fun d_50_0 () Bool)
(declare-fun d_51_3 () Bool)
(declare-fun d_51_2 () Bool)
(declare-fun d_51_1 () Bool)
(declare-fun d_51_0 () Bool)
(declare-fun d_52_3 () Bool)
(declare-fun d_52_2 () Bool)
(declare-fun d_52_1 () Bool)
(declare-fun d_52_0 () Bool)
(declare-fun d_53_3 () Bool)
(declare-fun d_53_2 () Bool)
(declare-fun d_53_1 () Bool)
(declare-fun d_53_0 () Bool)
(declare-fun d_54_3 () Bool)
(declare-fun d_54_2 () Bool)
(declare-fun d_54_1 () Bool)
(declare-fun d_54_0 () Bool)
(declare-fun d_55_3 () Bool)
(declare-fun d_55_2 () Bool)
(declare-fun d_55_1 () Bool)
(declare-fun d_55_0 () Bool)
(declare-fun d_56_3 () Bool)
(declare-fun d_56_2 () Bool)
(declare-fun d_56_1 () Bool)
(declare-fun d_56_0 () Bool)
(declare-fun d_57_3 () Bool)
(declare-fun d_57_2 () Bool)
(declare-fun d_57_1 () Bool)
(declare-fun d_57_0 () Bool)
(declare-fun d_58_3 () Bool)
(declare-fun d_58_2 () Bool)
(declare-fun d_58_1 () Bool)
(declare-fun d_58_0 () Bool)
(declare-fun d_59_3 () Bool)
(declare-fun d_59_2 () Bool)
(declare-fun d_59_1 () Bool)
(declare-fun d_59_0 () Bool)
(declare-fun d_60_3 () Bool)
(declare-fun d_60_2 () Bool)
(declare-fun d_60_1 () Bool)
(declare-fun d_60_0 () Bool)
(declare-fun in_target_0 () Bool)
(declare-fun instance_0 () Bool)
(assert
 (let (($x67 (or false c_0_0)))
 (let (($x69 (or $x67 c_0_1)))
 (let (($x71 (or $x69 c_0_2)))
 (or $x71 c_0_3)))))
(assert
 (not (and c_0_0 c_0_1)))
(assert
 (not (and c_0_0 c_0_2)))
(assert
 (not (and c_0_0 c_0_3)))
(assert
 (not (and c_0_1 c_0_2)))
(assert
 (not (and c_0_1 c_0_3)))
(assert
 (not (and c_0_2 c_0_3)))
(assert
 (let (($x87 (or false c_1_0)))
 (let (($x89 (or $x87 c_1_1)))
 (let (($x91 (or $x89 c_1_2)))
 (or $x91 c_1_3)))))
(assert
 (not (and c_1_0 c_1_1)))
(assert
 (not (and c_1_0 c_1_2)))
(assert
 (not (and c_1_0 c_1_3)))
(assert
 (not (and c_1_1 c_1_2)))
(assert
 (not (and c_1_1 c_1_3)))
(assert
 (not (and c_1_2 c_1_3)))
(assert
 (let (($x107 (or false c_2_0)))
 (let (($x109 (or $x107 c_2_1)))
 (let (($x111 (or $x109 c_2_2)))
 (or $x111 c_2_3)))))
(assert
 (not (and c_2_0 c_2_1)))
(assert
 (not (and c_2_0 c_2_2)))
(assert
 (not (and c_2_0 c_2_3)))
(assert
 (not (and c_2_1 c_2_2)))
(assert
 (not (and c_2_1 c_2_3)))
(assert
 (not (and c_2_2 c_2_3)))
(assert
 (let (($x127 (or false c_3_0)))
 (let (($x129 (or $x127 c_3_1)))
 (let (($x131 (or $x129 c_3_2)))
 (or $x131 c_3_3)))))
(assert
 (not (and c_3_0 c_3_1)))
(assert
 (not (and c_3_0 c_3_2)))
(assert
 (not (and c_3_0 c_3_3)))
(assert
 (not (and c_3_1 c_3_2)))
(assert
 (not (and c_3_1 c_3_3)))
(assert
 (not (and c_3_2 c_3_3)))
(assert
 (let (($x147 (or false c_4_0)))
 (let (($x149 (or $x147 c_4_1)))
 (let (($x151 (or $x149 c_4_2)))
 (or $x151 c_4_3)))))
(assert
 (not (and c_4_0 c_4_1)))
(assert
 (not (and c_4_0 c_4_2)))
(assert
 (not (and c_4_0 c_4_3)))
(assert
 (not (and c_4_1 c_4_2)))
(assert
 (not (and c_4_1 c_4_3)))
(assert
 (not (and c_4_2 c_4_3)))
(assert
 (let (($x167 (or false c_5_0)))
 (let (($x169 (or $x167 c_5_1)))
 (let (($x171 (or $x169 c_5_2)))
 (or $x171 c_5_3)))))
(assert
 (not (and c_5_0 c_5_1)))
(assert
 (not (and c_5_0 c_5_2)))
(assert
 (not (and c_5_0 c_5_3)))
(assert
 (not (and c_5_1 c_5_2)))
(assert
 (not (and c_5_1 c_5_3)))
(assert
 (not (and c_5_2 c_5_3)))
(assert
 (let (($x187 (or false c_6_0)))
 (let (($x189 (or $x187 c_6_1)))
 (let (($x191 (or $x189 c_6_2)))
 (or $x191 c_6_3)))))
(assert
 (not (and c_6_0 c_6_1)))
(assert
 (not (and c_6_0 c_6_2)))
(assert
 (not (and c_6_0 c_6_3)))
(assert
 (not (and c_6_1 c_6_2)))
(assert
 (not (and c_6_1 c_6_3)))
(assert
 (not (and c_6_2 c_6_3)))
(assert
 (let (($x207 (or false c_7_0)))
 (let (($x209 (or $x207 c_7_1)))
 (let (($x211 (or $x209 c_7_2)))
 (or $x211 c_7_3)))))
(assert
 (not (and c_7_0 c_7_1)))
(assert
 (not (and c_7_0 c_7_2)))
(assert
 (not (and c_7_0 c_7_3)))
(assert
 (not (and c_7_1 c_7_2)))
(assert
 (not (and c_7_1 c_7_3)))
(assert
 (not (and c_7_2 c_7_3)))
(assert
 (let (($x227 (or false c_8_0)))
 (let (($x229 (or $x227 c_8_1)))
 (let (($x231 (or $x229 c_8_2)))
 (or $x231 c_8_3)))))
(assert
 (not (and c_8_0 c_8_1)))
(assert
 (not (and c_8_0 c_8_2)))
(assert
 (not (and c_8_0 c_8_3)))
(assert
 (not (and c_8_1 c_8_2)))
(assert
 (not (and c_8_1 c_8_3)))
(assert
 (not (and c_8_2 c_8_3)))
(assert
 (let (($x247 (or false c_9_0)))
 (let (($x249 (or $x247 c_9_1)))
 (let (($x251 (or $x249 c_9_2)))
 (or $x251 c_9_3)))))
(assert
 (not (and c_9_0 c_9_1)))
(assert
 (not (and c_9_0 c_9_2)))
(assert
 (not (and c_9_0 c_9_3)))
(assert
 (not (and c_9_1 c_9_2)))
(assert
 (not (and c_9_1 c_9_3)))
(assert
 (not (and c_9_2 c_9_3)))
(assert
 (let (($x267 (or false c_10_0)))
 (let (($x269 (or $x267 c_10_1)))
 (let (($x271 (or $x269 c_10_2)))
 (or $x271 c_10_3)))))
(assert
 (not (and c_10_0 c_10_1)))
(assert
 (not (and c_10_0 c_10_2)))
(assert
 (not (and c_10_0 c_10_3)))
(assert
 (not (and c_10_1 c_10_2)))
(assert
 (not (and c_10_1 c_10_3)))
(assert
 (not (and c_10_2 c_10_3)))
(assert
 (let (($x287 (or false c_11_0)))
 (let (($x289 (or $x287 c_11_1)))
 (let (($x291 (or $x289 c_11_2)))
 (or $x291 c_11_3)))))
(assert
 (not (and c_11_0 c_11_1)))
(assert
 (not (and c_11_0 c_11_2)))
(assert
 (not (and c_11_0 c_11_3)))
(assert
 (not (and c_11_1 c_11_2)))
(assert
 (not (and c_11_1 c_11_3)))
(assert
 (not (and c_11_2 c_11_3)))
(assert
 (let (($x307 (or false c_12_0)))
 (let (($x309 (or $x307 c_12_1)))
 (let (($x311 (or $x309 c_12_2)))
 (or $x311 c_12_3)))))
(assert
 (not (and c_12_0 c_12_1)))
(assert
 (not (and c_12_0 c_12_2)))
(assert
 (not (and c_12_0 c_12_3)))
(assert
 (not (and c_12_1 c_12_2)))
(assert
 (not (and c_12_1 c_12_3)))
(assert
 (not (and c_12_2 c_12_3)))
(assert
 (let (($x327 (or false c_13_0)))
 (let (($x329 (or $x327 c_13_1)))
 (let (($x331 (or $x329 c_13_2)))
 (or $x331 c_13_3)))))
(assert
 (not (and c_13_0 c_13_1)))
(assert
 (not (and c_13_0 c_13_2)))
(assert
 (not (and c_13_0 c_13_3)))
(assert
 (not (and c_13_1 c_13_2)))
(assert
 (not (and c_13_1 c_13_3)))
(assert
 (not (and c_13_2 c_13_3)))
(assert
 (let (($x347 (or false c_14_0)))
 (let (($x349 (or $x347 c_14_1)))
 (let (($x351 (or $x349 c_14_2)))
 (or $x351 c_14_3)))))
(assert
 (not (and c_14_0 c_14_1)))
(assert
 (not (and c_14_0 c_14_2)))
(assert
 (not (and c_14_0 c_14_3)))
(assert
 (not (and c_14_1 c_14_2)))
(assert
 (not (and c_14_1 c_14_3)))
(assert
 (not (and c_14_2 c_14_3)))
(assert
 (let (($x367 (or false c_15_0)))
 (let (($x369 (or $x367 c_15_1)))
 (let (($x371 (or $x369 c_15_2)))
 (or $x371 c_15_3)))))
(assert
 (not (and c_15_0 c_15_1)))
(assert
 (not (and c_15_0 c_15_2)))
(assert
 (not (and c_15_0 c_15_3)))
(assert
 (not (and c_15_1 c_15_2)))
(assert
 (not (and c_15_1 c_15_3)))
(assert
 (not (and c_15_2 c_15_3)))
(assert
 (let (($x387 (or false c_16_0)))
 (let (($x389 (or $x387 c_16_1)))
 (let (($x391 (or $x389 c_16_2)))
 (or $x391 c_16_3)))))
(assert
 (not (and c_16_0 c_16_1)))
(assert
 (not (and c_16_0 c_16_2)))
(assert
 (not (and c_16_0 c_16_3)))
(assert
 (not (and c_16_1 c_16_2)))
(assert
 (not (and c_16_1 c_16_3)))
(assert
 (not (and c_16_2 c_16_3)))
(assert
 (let (($x407 (or false c_17_0)))
 (let (($x409 (or $x407 c_17_1)))
 (let (($x411 (or $x409 c_17_2)))
 (or $x411 c_17_3)))))
(assert
 (not (and c_17_0 c_17_1)))
(assert
 (not (and c_17_0 c_17_2)))
(assert
 (not (and c_17_0 c_17_3)))
(assert
 (not (and c_17_1 c_17_2)))
(assert
 (not (and c_17_1 c_17_3)))
(assert
 (not (and c_17_2 c_17_3)))
(assert
 (let (($x427 (or false c_18_0)))
 (let (($x429 (or $x427 c_18_1)))
 (let (($x431 (or $x429 c_18_2)))
 (or $x431 c_18_3)))))
(assert
 (not (and c_18_0 c_18_1)))
(assert
 (not (and c_18_0 c_18_2)))
(assert
 (not (and c_18_0 c_18_3)))
(assert
 (not (and c_18_1 c_18_2)))
(assert
 (not (and c_18_1 c_18_3)))
(assert
 (not (and c_18_2 c_18_3)))
(assert
 (let (($x447 (or false c_19_0)))
 (let (($x449 (or $x447 c_19_1)))
 (let (($x451 (or $x449 c_19_2)))
 (or $x451 c_19_3)))))
(assert
 (not (and c_19_0 c_19_1)))
(assert
 (not (and c_19_0 c_19_2)))
(assert
 (not (and c_19_0 c_19_3)))
(assert
 (not (and c_19_1 c_19_2)))
(assert
 (not (and c_19_1 c_19_3)))
(assert
 (not (and c_19_2 c_19_3)))
(assert
 (let (($x467 (or false c_20_0)))
 (let (($x469 (or $x467 c_20_1)))
 (let (($x471 (or $x469 c_20_2)))
 (or $x471 c_20_3)))))
(assert
 (not (and c_20_0 c_20_1)))
(assert
 (not (and c_20_0 c_20_2)))
(assert
 (not (and c_20_0 c_20_3)))
(assert
 (not (and c_20_1 c_20_2)))
(assert
 (not (and c_20_1 c_20_3)))
(assert
 (not (and c_20_2 c_20_3)))
(assert
 (let (($x487 (or false c_21_0)))
 (let (($x489 (or $x487 c_21_1)))
 (let (($x491 (or $x489 c_21_2)))
 (or $x491 c_21_3)))))
(assert
 (not (and c_21_0 c_21_1)))
(assert
 (not (and c_21_0 c_21_2)))
(assert
 (not (and c_21_0 c_21_3)))
(assert
 (not (and c_21_1 c_21_2)))
(assert
 (not (and c_21_1 c_21_3)))
(assert
 (not (and c_21_2 c_21_3)))
(assert
 (let (($x507 (or false c_22_0)))
 (let (($x509 (or $x507 c_22_1)))
 (let (($x511 (or $x509 c_22_2)))
 (or $x511 c_22_3)))))
(assert
 (not (and c_22_0 c_22_1)))
(assert
 (not (and c_22_0 c_22_2)))
(assert
 (not (and c_22_0 c_22_3)))
(assert
 (not (and c_22_1 c_22_2)))
(assert
 (not (and c_22_1 c_22_3)))
(assert
 (not (and c_22_2 c_22_3)))
(assert
 (let (($x527 (or false c_23_0)))
 (let (($x529 (or $x527 c_23_1)))
 (let (($x531 (or $x529 c_23_2)))
 (or $x531 c_23_3)))))
(assert
 (not (and c_23_0 c_23_1)))
(assert
 (not (and c_23_0 c_23_2)))
(assert
 (not (and c_23_0 c_23_3)))
(assert
 (not (and c_23_1 c_23_2)))
(assert
 (not (and c_23_1 c_23_3)))
(assert
 (not (and c_23_2 c_23_3)))
(assert
 (let (($x547 (or false c_24_0)))
 (let (($x549 (or $x547 c_24_1)))
 (let (($x551 (or $x549 c_24_2)))
 (or $x551 c_24_3)))))
(assert
 (not (and c_24_0 c_24_1)))
(assert
 (not (and c_24_0 c_24_2)))
(assert
 (not (and c_24_0 c_24_3)))
(assert
 (not (and c_24_1 c_24_2)))
(assert
 (not (and c_24_1 c_24_3)))
(assert
 (not (and c_24_2 c_24_3)))
(assert
 (let (($x567 (or false c_25_0)))
 (let (($x569 (or $x567 c_25_1)))
 (let (($x571 (or $x569 c_25_2)))
 (or $x571 c_25_3)))))
(assert
 (not (and c_25_0 c_25_1)))
(assert
 (not (and c_25_0 c_25_2)))
(assert
 (not (and c_25_0 c_25_3)))
(assert
 (not (and c_25_1 c_25_2)))
(assert
 (not (and c_25_1 c_25_3)))
(assert
 (not (and c_25_2 c_25_3)))
(assert
 (let (($x587 (or false c_26_0)))
 (let (($x589 (or $x587 c_26_1)))
 (let (($x591 (or $x589 c_26_2)))
 (or $x591 c_26_3)))))
(assert
 (not (and c_26_0 c_26_1)))
(assert
 (not (and c_26_0 c_26_2)))
(assert
 (not (and c_26_0 c_26_3)))
(assert
 (not (and c_26_1 c_26_2)))
(assert
 (not (and c_26_1 c_26_3)))
(assert
 (not (and c_26_2 c_26_3)))
(assert
 (let (($x607 (or false c_27_0)))
 (let (($x609 (or $x607 c_27_1)))
 (let (($x611 (or $x609 c_27_2)))
 (or $x611 c_27_3)))))
(assert
 (not (and c_27_0 c_27_1)))
(assert
 (not (and c_27_0 c_27_2)))
(assert
 (not (and c_27_0 c_27_3)))
(assert
 (not (and c_27_1 c_27_2)))
(assert
 (not (and c_27_1 c_27_3)))
(assert
 (not (and c_27_2 c_27_3)))
(assert
 (let (($x627 (or false c_28_0)))
 (let (($x629 (or $x627 c_28_1)))
 (let (($x631 (or $x629 c_28_2)))
 (or $x631 c_28_3)))))
(assert
 (not (and c_28_0 c_28_1)))
(assert
 (not (and c_28_0 c_28_2)))
(assert
 (not (and c_28_0 c_28_3)))
(assert
 (not (and c_28_1 c_28_2)))
(assert
 (not (and c_28_1 c_28_3)))
(assert
 (not (and c_28_2 c_28_3)))
(assert
 (let (($x647 (or false c_29_0)))
 (let (($x649 (or $x647 c_29_1)))
 (let (($x651 (or $x649 c_29_2)))
 (or $x651 c_29_3)))))
(assert
 (not (and c_29_0 c_29_1)))
(assert
 (not (and c_29_0 c_29_2)))
(assert
 (not (and c_29_0 c_29_3)))
(assert
 (not (and c_29_1 c_29_2)))
(assert
 (not (and c_29_1 c_29_3)))
(assert
 (not (and c_29_2 c_29_3)))
(assert
 (let (($x667 (or false c_30_0)))
 (let (($x669 (or $x667 c_30_1)))
 (let (($x671 (or $x669 c_30_2)))
 (or $x671 c_30_3)))))
(assert
 (not (and c_30_0 c_30_1)))
(assert
 (not (and c_30_0 c_30_2)))
(assert
 (not (and c_30_0 c_30_3)))
(assert
 (not (and c_30_1 c_30_2)))
(assert
 (not (and c_30_1 c_30_3)))
(assert
 (not (and c_30_2 c_30_3)))
(assert
 (let (($x687 (or false c_31_0)))
 (let (($x689 (or $x687 c_31_1)))
 (let (($x691 (or $x689 c_31_2)))
 (or $x691 c_31_3)))))
(assert
 (not (and c_31_0 c_31_1)))
(assert
 (not (and c_31_0 c_31_2)))
(assert
 (not (and c_31_0 c_31_3)))
(assert
 (not (and c_31_1 c_31_2)))
(assert
 (not (and c_31_1 c_31_3)))
(assert
 (not (and c_31_2 c_31_3)))
(assert
 (let (($x707 (or false c_32_0)))
 (let (($x709 (or $x707 c_32_1)))
 (let (($x711 (or $x709 c_32_2)))
 (or $x711 c_32_3)))))
(assert
 (not (and c_32_0 c_32_1)))
(assert
 (not (and c_32_0 c_32_2)))
(assert
 (not (and c_32_0 c_32_3)))
(assert
 (not (and c_32_1 c_32_2)))
(assert
 (not (and c_32_1 c_32_3)))
(assert
 (not (and c_32_2 c_32_3)))
(assert
 (let (($x727 (or false c_33_0)))
 (let (($x729 (or $x727 c_33_1)))
 (let (($x731 (or $x729 c_33_2)))
 (or $x731 c_33_3)))))
(assert
 (not (and c_33_0 c_33_1)))
(assert
 (not (and c_33_0 c_33_2)))
(assert
 (not (and c_33_0 c_33_3)))
(assert
 (not (and c_33_1 c_33_2)))
(assert
 (not (and c_33_1 c_33_3)))
(assert
 (not (and c_33_2 c_33_3)))
(assert
 (let (($x747 (or false c_34_0)))
 (let (($x749 (or $x747 c_34_1)))
 (let (($x751 (or $x749 c_34_2)))
 (or $x751 c_34_3)))))
(assert
 (not (and c_34_0 c_34_1)))
(assert
 (not (and c_34_0 c_34_2)))
(assert
 (not (and c_34_0 c_34_3)))
(assert
 (not (and c_34_1 c_34_2)))
(assert
 (not (and c_34_1 c_34_3)))
(assert
 (not (and c_34_2 c_34_3)))
(assert
 (let (($x767 (or false c_35_0)))
 (let (($x769 (or $x767 c_35_1)))
 (let (($x771 (or $x769 c_35_2)))
 (or $x771 c_35_3)))))
(assert
 (not (and c_35_0 c_35_1)))
(assert
 (not (and c_35_0 c_35_2)))
(assert
 (not (and c_35_0 c_35_3)))
(assert
 (not (and c_35_1 c_35_2)))
(assert
 (not (and c_35_1 c_35_3)))
(assert
 (not (and c_35_2 c_35_3)))
(assert
 (let (($x787 (or false c_36_0)))
 (let (($x789 (or $x787 c_36_1)))
 (let (($x791 (or $x789 c_36_2)))
 (or $x791 c_36_3)))))
(assert
 (not (and c_36_0 c_36_1)))
(assert
 (not (and c_36_0 c_36_2)))
(assert
 (not (and c_36_0 c_36_3)))
(assert
 (not (and c_36_1 c_36_2)))
(assert
 (not (and c_36_1 c_36_3)))
(assert
 (not (and c_36_2 c_36_3)))
(assert
 (let (($x807 (or false c_37_0)))
 (let (($x809 (or $x807 c_37_1)))
 (let (($x811 (or $x809 c_37_2)))
 (or $x811 c_37_3)))))
(assert
 (not (and c_37_0 c_37_1)))
(assert
 (not (and c_37_0 c_37_2)))
(assert
 (not (and c_37_0 c_37_3)))
(assert
 (not (and c_37_1 c_37_2)))
(assert
 (not (and c_37_1 c_37_3)))
(assert
 (not (and c_37_2 c_37_3)))
(assert
 (let (($x827 (or false c_38_0)))
 (let (($x829 (or $x827 c_38_1)))
 (let (($x831 (or $x829 c_38_2)))
 (or $x831 c_38_3)))))
(assert
 (not (and c_38_0 c_38_1)))
(assert
 (not (and c_38_0 c_38_2)))
(assert
 (not (and c_38_0 c_38_3)))
(assert
 (not (and c_38_1 c_38_2)))
(assert
 (not (and c_38_1 c_38_3)))
(assert
 (not (and c_38_2 c_38_3)))
(assert
 (let (($x847 (or false c_39_0)))
 (let (($x849 (or $x847 c_39_1)))
 (let (($x851 (or $x849 c_39_2)))
 (or $x851 c_39_3)))))
(assert
 (not (and c_39_0 c_39_1)))
(assert
 (not (and c_39_0 c_39_2)))
(assert
 (not (and c_39_0 c_39_3)))
(assert
 (not (and c_39_1 c_39_2)))
(assert
 (not (and c_39_1 c_39_3)))
(assert
 (not (and c_39_2 c_39_3)))
(assert
 (let (($x867 (or false c_40_0)))
 (let (($x869 (or $x867 c_40_1)))
 (let (($x871 (or $x869 c_40_2)))
 (or $x871 c_40_3)))))
(assert
 (not (and c_40_0 c_40_1)))
(assert
 (not (and c_40_0 c_40_2)))
(assert
 (not (and c_40_0 c_40_3)))
(assert
 (not (and c_40_1 c_40_2)))
(assert
 (not (and c_40_1 c_40_3)))
(assert
 (not (and c_40_2 c_40_3)))
(assert
 (let (($x887 (or false c_41_0)))
 (let (($x889 (or $x887 c_41_1)))
 (let (($x891 (or $x889 c_41_2)))
 (or $x891 c_41_3)))))
(assert
 (not (and c_41_0 c_41_1)))
(assert
 (not (and c_41_0 c_41_2)))
(assert
 (not (and c_41_0 c_41_3)))
(assert
 (not (and c_41_1 c_41_2)))
(assert
 (not (and c_41_1 c_41_3)))
(assert
 (not (and c_41_2 c_41_3)))
(assert
 (let (($x907 (or false c_42_0)))
 (let (($x909 (or $x907 c_42_1)))
 (let (($x911 (or $x909 c_42_2)))
 (or $x911 c_42_3)))))
(assert
 (not (and c_42_0 c_42_1)))
(assert
 (not (and c_42_0 c_42_2)))
(assert
 (not (and c_42_0 c_42_3)))
(assert
 (not (and c_42_1 c_42_2)))
(assert
 (not (and c_42_1 c_42_3)))
(assert
 (not (and c_42_2 c_42_3)))
(assert
 (let (($x927 (or false c_43_0)))
 (let (($x929 (or $x927 c_43_1)))
 (let (($x931 (or $x929 c_43_2)))
 (or $x931 c_43_3)))))
(assert
 (not (and c_43_0 c_43_1)))
(assert
 (not (and c_43_0 c_43_2)))
(assert
 (not (and c_43_0 c_43_3)))
(assert
 (not (and c_43_1 c_43_2)))
(assert
 (not (and c_43_1 c_43_3)))
(assert
 (not (and c_43_2 c_43_3)))
(assert
 (let (($x947 (or false c_44_0)))
 (let (($x949 (or $x947 c_44_1)))
 (let (($x951 (or $x949 c_44_2)))
 (or $x951 c_44_3)))))
(assert
 (not (and c_44_0 c_44_1)))
(assert
 (not (and c_44_0 c_44_2)))
(assert
 (not (and c_44_0 c_44_3)))
(assert
 (not (and c_44_1 c_44_2)))
(assert
 (not (and c_44_1 c_44_3)))
(assert
 (not (and c_44_2 c_44_3)))
(assert
 (let (($x967 (or false c_45_0)))
 (let (($x969 (or $x967 c_45_1)))
 (let (($x971 (or $x969 c_45_2)))
 (or $x971 c_45_3)))))
(assert
 (not (and c_45_0 c_45_1)))
(assert
 (not (and c_45_0 c_45_2)))
(assert
 (not (and c_45_0 c_45_3)))
(assert
 (not (and c_45_1 c_45_2)))
(assert
 (not (and c_45_1 c_45_3)))
(assert
 (not (and c_45_2 c_45_3)))
(assert
 (let (($x987 (or false c_46_0)))
 (let (($x989 (or $x987 c_46_1)))
 (let (($x991 (or $x989 c_46_2)))
 (or $x991 c_46_3)))))
(assert
 (not (and c_46_0 c_46_1)))
(assert
 (not (and c_46_0 c_46_2)))
(assert
 (not (and c_46_0 c_46_3)))
(assert
 (not (and c_46_1 c_46_2)))
(assert
 (not (and c_46_1 c_46_3)))
(assert
 (not (and c_46_2 c_46_3)))
(assert
 (let (($x1007 (or false c_47_0)))
 (let (($x1009 (or $x1007 c_47_1)))
 (let (($x1011 (or $x1009 c_47_2)))
 (or $x1011 c_47_3)))))
(assert
 (not (and c_47_0 c_47_1)))
(assert
 (not (and c_47_0 c_47_2)))
(assert
 (not (and c_47_0 c_47_3)))
(assert
 (not (and c_47_1 c_47_2)))
(assert
 (not (and c_47_1 c_47_3)))
(assert
 (not (and c_47_2 c_47_3)))
(assert
 (let (($x1027 (or false c_48_0)))
 (let (($x1029 (or $x1027 c_48_1)))
 (let (($x1031 (or $x1029 c_48_2)))
 (or $x1031 c_48_3)))))
(assert
 (not (and c_48_0 c_48_1)))
(assert
 (not (and c_48_0 c_48_2)))
(assert
 (not (and c_48_0 c_48_3)))
(assert
 (not (and c_48_1 c_48_2)))
(assert
 (not (and c_48_1 c_48_3)))
(assert
 (not (and c_48_2 c_48_3)))
(assert
 (let (($x1047 (or false c_49_0)))
 (let (($x1049 (or $x1047 c_49_1)))
 (let (($x1051 (or $x1049 c_49_2)))
 (or $x1051 c_49_3)))))
(assert
 (not (and c_49_0 c_49_1)))
(assert
 (not (and c_49_0 c_49_2)))
(assert
 (not (and c_49_0 c_49_3)))
(assert
 (not (and c_49_1 c_49_2)))
(assert
 (not (and c_49_1 c_49_3)))
(assert
 (not (and c_49_2 c_49_3)))
(assert
 (let (($x1067 (or false c_50_0)))
 (let (($x1069 (or $x1067 c_50_1)))
 (let (($x1071 (or $x1069 c_50_2)))
 (or $x1071 c_50_3)))))
(assert
 (not (and c_50_0 c_50_1)))
(assert
 (not (and c_50_0 c_50_2)))
(assert
 (not (and c_50_0 c_50_3)))
(assert
 (not (and c_50_1 c_50_2)))
(assert
 (not (and c_50_1 c_50_3)))
(assert
 (not (and c_50_2 c_50_3)))
(assert
 (let (($x1087 (or false c_51_0)))
 (let (($x1089 (or $x1087 c_51_1)))
 (let (($x1091 (or $x1089 c_51_2)))
 (or $x1091 c_51_3)))))
(assert
 (not (and c_51_0 c_51_1)))
(assert
 (not (and c_51_0 c_51_2)))
(assert
 (not (and c_51_0 c_51_3)))
(assert
 (not (and c_51_1 c_51_2)))
(assert
 (not (and c_51_1 c_51_3)))
(assert
 (not (and c_51_2 c_51_3)))
(assert
 (let (($x1107 (or false c_52_0)))
 (let (($x1109 (or $x1107 c_52_1)))
 (let (($x1111 (or $x1109 c_52_2)))
 (or $x1111 c_52_3)))))
(assert
 (not (and c_52_0 c_52_1)))
(assert
 (not (and c_52_0 c_52_2)))
(assert
 (not (and c_52_0 c_52_3)))
(assert
 (not (and c_52_1 c_52_2)))
(assert
 (not (and c_52_1 c_52_3)))
(assert
 (not (and c_52_2 c_52_3)))
(assert
 (let (($x1127 (or false c_53_0)))
 (let (($x1129 (or $x1127 c_53_1)))
 (let (($x1131 (or $x1129 c_53_2)))
 (or $x1131 c_53_3)))))
(assert
 (not (and c_53_0 c_53_1)))
(assert
 (not (and c_53_0 c_53_2)))
(assert
 (not (and c_53_0 c_53_3)))
(assert
 (not (and c_53_1 c_53_2)))
(assert
 (not (and c_53_1 c_53_3)))
(assert
 (not (and c_53_2 c_53_3)))
(assert
 (let (($x1147 (or false c_54_0)))
 (let (($x1149 (or $x1147 c_54_1)))
 (let (($x1151 (or $x1149 c_54_2)))
 (or $x1151 c_54_3)))))
(assert
 (not (and c_54_0 c_54_1)))
(assert
 (not (and c_54_0 c_54_2)))
(assert
 (not (and c_54_0 c_54_3)))
(assert
 (not (and c_54_1 c_54_2)))
(assert
 (not (and c_54_1 c_54_3)))
(assert
 (not (and c_54_2 c_54_3)))
(assert
 (let (($x1167 (or false c_55_0)))
 (let (($x1169 (or $x1167 c_55_1)))
 (let (($x1171 (or $x1169 c_55_2)))
 (or $x1171 c_55_3)))))
(assert
 (not (and c_55_0 c_55_1)))
(assert
 (not (and c_55_0 c_55_2)))
(assert
 (not (and c_55_0 c_55_3)))
(assert
 (not (and c_55_1 c_55_2)))
(assert
 (not (and c_55_1 c_55_3)))
(assert
 (not (and c_55_2 c_55_3)))
(assert
 (let (($x1187 (or false c_56_0)))
 (let (($x1189 (or $x1187 c_56_1)))
 (let (($x1191 (or $x1189 c_56_2)))
 (or $x1191 c_56_3)))))
(assert
 (not (and c_56_0 c_56_1)))
(assert
 (not (and c_56_0 c_56_2)))
(assert
 (not (and c_56_0 c_56_3)))
(assert
 (not (and c_56_1 c_56_2)))
(assert
 (not (and c_56_1 c_56_3)))
(assert
 (not (and c_56_2 c_56_3)))
(assert
 (let (($x1207 (or false c_57_0)))
 (let (($x1209 (or $x1207 c_57_1)))
 (let (($x1211 (or $x1209 c_57_2)))
 (or $x1211 c_57_3)))))
(assert
 (not (and c_57_0 c_57_1)))
(assert
 (not (and c_57_0 c_57_2)))
(assert
 (not (and c_57_0 c_57_3)))
(assert
 (not (and c_57_1 c_57_2)))
(assert
 (not (and c_57_1 c_57_3)))
(assert
 (not (and c_57_2 c_57_3)))
(assert
 (let (($x1227 (or false c_58_0)))
 (let (($x1229 (or $x1227 c_58_1)))
 (let (($x1231 (or $x1229 c_58_2)))
 (or $x1231 c_58_3)))))
(assert
 (not (and c_58_0 c_58_1)))
(assert
 (not (and c_58_0 c_58_2)))
(assert
 (not (and c_58_0 c_58_3)))
(assert
 (not (and c_58_1 c_58_2)))
(assert
 (not (and c_58_1 c_58_3)))
(assert
 (not (and c_58_2 c_58_3)))
(assert
 (let (($x1247 (or false c_59_0)))
 (let (($x1249 (or $x1247 c_59_1)))
 (let (($x1251 (or $x1249 c_59_2)))
 (or $x1251 c_59_3)))))
(assert
 (not (and c_59_0 c_59_1)))
(assert
 (not (and c_59_0 c_59_2)))
(assert
 (not (and c_59_0 c_59_3)))
(assert
 (not (and c_59_1 c_59_2)))
(assert
 (not (and c_59_1 c_59_3)))
(assert
 (not (and c_59_2 c_59_3)))
(assert
 (let (($x1267 (or false c_60_0)))
 (let (($x1269 (or $x1267 c_60_1)))
 (let (($x1271 (or $x1269 c_60_2)))
 (or $x1271 c_60_3)))))
(assert
 (not (and c_60_0 c_60_1)))
(assert
 (not (and c_60_0 c_60_2)))
(assert
 (not (and c_60_0 c_60_3)))
(assert
 (not (and c_60_1 c_60_2)))
(assert
 (not (and c_60_1 c_60_3)))
(assert
 (not (and c_60_2 c_60_3)))
(assert
 (let (($x1287 (or false d_0_0)))
 (let (($x1289 (or $x1287 d_0_1)))
 (let (($x1291 (or $x1289 d_0_2)))
 (or $x1291 d_0_3)))))
(assert
 (not (and d_0_0 d_0_1)))
(assert
 (not (and d_0_0 d_0_2)))
(assert
 (not (and d_0_0 d_0_3)))
(assert
 (not (and d_0_1 d_0_2)))
(assert
 (not (and d_0_1 d_0_3)))
(assert
 (not (and d_0_2 d_0_3)))
(assert
 (let (($x1307 (or false d_1_0)))
 (let (($x1309 (or $x1307 d_1_1)))
 (let (($x1311 (or $x1309 d_1_2)))
 (or $x1311 d_1_3)))))
(assert
 (not (and d_1_0 d_1_1)))
(assert
 (not (and d_1_0 d_1_2)))
(assert
 (not (and d_1_0 d_1_3)))
(assert
 (not (and d_1_1 d_1_2)))
(assert
 (not (and d_1_1 d_1_3)))
(assert
 (not (and d_1_2 d_1_3)))
(assert
 (let (($x1327 (or false d_2_0)))
 (let (($x1329 (or $x1327 d_2_1)))
 (let (($x1331 (or $x1329 d_2_2)))
 (or $x1331 d_2_3)))))
(assert
 (not (and d_2_0 d_2_1)))
(assert
 (not (and d_2_0 d_2_2)))
(assert
 (not (and d_2_0 d_2_3)))
(assert
 (not (and d_2_1 d_2_2)))
(assert
 (not (and d_2_1 d_2_3)))
(assert
 (not (and d_2_2 d_2_3)))
(assert
 (let (($x1347 (or false d_3_0)))
 (let (($x1349 (or $x1347 d_3_1)))
 (let (($x1351 (or $x1349 d_3_2)))
 (or $x1351 d_3_3)))))
(assert
 (not (and d_3_0 d_3_1)))
(assert
 (not (and d_3_0 d_3_2)))
(assert
 (not (and d_3_0 d_3_3)))
(assert
 (not (and d_3_1 d_3_2)))
(assert
 (not (and d_3_1 d_3_3)))
(assert
 (not (and d_3_2 d_3_3)))
(assert
 (let (($x1367 (or false d_4_0)))
 (let (($x1369 (or $x1367 d_4_1)))
 (let (($x1371 (or $x1369 d_4_2)))
 (or $x1371 d_4_3)))))
(assert
 (not (and d_4_0 d_4_1)))
(assert
 (not (and d_4_0 d_4_2)))
(assert
 (not (and d_4_0 d_4_3)))
(assert
 (not (and d_4_1 d_4_2)))
(assert
 (not (and d_4_1 d_4_3)))
(assert
 (not (and d_4_2 d_4_3)))
(assert
 (let (($x1387 (or false d_5_0)))
 (let (($x1389 (or $x1387 d_5_1)))
 (let (($x1391 (or $x1389 d_5_2)))
 (or $x1391 d_5_3)))))
(assert
 (not (and d_5_0 d_5_1)))
(assert
 (not (and d_5_0 d_5_2)))
(assert
 (not (and d_5_0 d_5_3)))
(assert
 (not (and d_5_1 d_5_2)))
(assert
 (not (and d_5_1 d_5_3)))
(assert
 (not (and d_5_2 d_5_3)))
(assert
 (let (($x1407 (or false d_6_0)))
 (let (($x1409 (or $x1407 d_6_1)))
 (let (($x1411 (or $x1409 d_6_2)))
 (or $x1411 d_6_3)))))
(assert
 (not (and d_6_0 d_6_1)))
(assert
 (not (and d_6_0 d_6_2)))
(assert
 (not (and d_6_0 d_6_3)))
(assert
 (not (and d_6_1 d_6_2)))
(assert
 (not (and d_6_1 d_6_3)))
(assert
 (not (and d_6_2 d_6_3)))
(assert
 (let (($x1427 (or false d_7_0)))
 (let (($x1429 (or $x1427 d_7_1)))
 (let (($x1431 (or $x1429 d_7_2)))
 (or $x1431 d_7_3)))))
(assert
 (not (and d_7_0 d_7_1)))
(assert
 (not (and d_7_0 d_7_2)))
(assert
 (not (and d_7_0 d_7_3)))
(assert
 (not (and d_7_1 d_7_2)))
(assert
 (not (and d_7_1 d_7_3)))
(assert
 (not (and d_7_2 d_7_3)))
(assert
 (let (($x1447 (or false d_8_0)))
 (let (($x1449 (or $x1447 d_8_1)))
 (let (($x1451 (or $x1449 d_8_2)))
 (or $x1451 d_8_3)))))
(assert
 (not (and d_8_0 d_8_1)))
(assert
 (not (and d_8_0 d_8_2)))
(assert
 (not (and d_8_0 d_8_3)))
(assert
 (not (and d_8_1 d_8_2)))
(assert
 (not (and d_8_1 d_8_3)))
(assert
 (not (and d_8_2 d_8_3)))
(assert
 (let (($x1467 (or false d_9_0)))
 (let (($x1469 (or $x1467 d_9_1)))
 (let (($x1471 (or $x1469 d_9_2)))
 (or $x1471 d_9_3)))))
(assert
 (not (and d_9_0 d_9_1)))
(assert
 (not (and d_9_0 d_9_2)))
(assert
 (not (and d_9_0 d_9_3)))
(assert
 (not (and d_9_1 d_9_2)))
(assert
 (not (and d_9_1 d_9_3)))
(assert
 (not (and d_9_2 d_9_3)))
(assert
 (let (($x1487 (or false d_10_0)))
 (let (($x1489 (or $x1487 d_10_1)))
 (let (($x1491 (or $x1489 d_10_2)))
 (or $x1491 d_10_3)))))
(assert
 (not (and d_10_0 d_10_1)))
(assert
 (not (and d_10_0 d_10_2)))
(assert
 (not (and d_10_0 d_10_3)))
(assert
 (not (and d_10_1 d_10_2)))
(assert
 (not (and d_10_1 d_10_3)))
(assert
 (not (and d_10_2 d_10_3)))
(assert
 (let (($x1507 (or false d_11_0)))
 (let (($x1509 (or $x1507 d_11_1)))
 (let (($x1511 (or $x1509 d_11_2)))
 (or $x1511 d_11_3)))))
(assert
 (not (and d_11_0 d_11_1)))
(assert
 (not (and d_11_0 d_11_2)))
(assert
 (not (and d_11_0 d_11_3)))
(assert
 (not (and d_11_1 d_11_2)))
(assert
 (not (and d_11_1 d_11_3)))
(assert
 (not (and d_11_2 d_11_3)))
(assert
 (let (($x1527 (or false d_12_0)))
 (let (($x1529 (or $x1527 d_12_1)))
 (let (($x1531 (or $x1529 d_12_2)))
 (or $x1531 d_12_3)))))
(assert
 (not (and d_12_0 d_12_1)))
(assert
 (not (and d_12_0 d_12_2)))
(assert
 (not (and d_12_0 d_12_3)))
(assert
 (not (and d_12_1 d_12_2)))
(assert
 (not (and d_12_1 d_12_3)))
(assert
 (not (and d_12_2 d_12_3)))
(assert
 (let (($x1547 (or false d_13_0)))
 (let (($x1549 (or $x1547 d_13_1)))
 (let (($x1551 (or $x1549 d_13_2)))
 (or $x1551 d_13_3)))))
(assert
 (not (and d_13_0 d_13_1)))
(assert
 (not (and d_13_0 d_13_2)))
(assert
 (not (and d_13_0 d_13_3)))
(assert
 (not (and d_13_1 d_13_2)))
(assert
 (not (and d_13_1 d_13_3)))
(assert
 (not (and d_13_2 d_13_3)))
(assert
 (let (($x1567 (or false d_14_0)))
 (let (($x1569 (or $x1567 d_14_1)))
 (let (($x1571 (or $x1569 d_14_2)))
 (or $x1571 d_14_3)))))
(assert
 (not (and d_14_0 d_14_1)))
(assert
 (not (and d_14_0 d_14_2)))
(assert
 (not (and d_14_0 d_14_3)))
(assert
 (not (and d_14_1 d_14_2)))
(assert
 (not (and d_14_1 d_14_3)))
(assert
 (not (and d_14_2 d_14_3)))
(assert
 (let (($x1587 (or false d_15_0)))
 (let (($x1589 (or $x1587 d_15_1)))
 (let (($x1591 (or $x1589 d_15_2)))
 (or $x1591 d_15_3)))))
(assert
 (not (and d_15_0 d_15_1)))
(assert
 (not (and d_15_0 d_15_2)))
(assert
 (not (and d_15_0 d_15_3)))
(assert
 (not (and d_15_1 d_15_2)))
(assert
 (not (and d_15_1 d_15_3)))
(assert
 (not (and d_15_2 d_15_3)))
(assert
 (let (($x1607 (or false d_16_0)))
 (let (($x1609 (or $x1607 d_16_1)))
 (let (($x1611 (or $x1609 d_16_2)))
 (or $x1611 d_16_3)))))
(assert
 (not (and d_16_0 d_16_1)))
(assert
 (not (and d_16_0 d_16_2)))
(assert
 (not (and d_16_0 d_16_3)))
(assert
 (not (and d_16_1 d_16_2)))
(assert
 (not (and d_16_1 d_16_3)))
(assert
 (not (and d_16_2 d_16_3)))
(assert
 (let (($x1627 (or false d_17_0)))
 (let (($x1629 (or $x1627 d_17_1)))
 (let (($x1631 (or $x1629 d_17_2)))
 (or $x1631 d_17_3)))))
(assert
 (not (and d_17_0 d_17_1)))
(assert
 (not (and d_17_0 d_17_2)))
(assert
 (not (and d_17_0 d_17_3)))
(assert
 (not (and d_17_1 d_17_2)))
(assert
 (not (and d_17_1 d_17_3)))
(assert
 (not (and d_17_2 d_17_3)))
(assert
 (let (($x1647 (or false d_18_0)))
 (let (($x1649 (or $x1647 d_18_1)))
 (let (($x1651 (or $x1649 d_18_2)))
 (or $x1651 d_18_3)))))
(assert
 (not (and d_18_0 d_18_1)))
(assert
 (not (and d_18_0 d_18_2)))
(assert
 (not (and d_18_0 d_18_3)))
(assert
 (not (and d_18_1 d_18_2)))
(assert
 (not (and d_18_1 d_18_3)))
(assert
 (not (and d_18_2 d_18_3)))
(assert
 (let (($x1667 (or false d_19_0)))
 (let (($x1669 (or $x1667 d_19_1)))
 (let (($x1671 (or $x1669 d_19_2)))
 (or $x1671 d_19_3)))))
(assert
 (not (and d_19_0 d_19_1)))
(assert
 (not (and d_19_0 d_19_2)))
(assert
 (not (and d_19_0 d_19_3)))
(assert
 (not (and d_19_1 d_19_2)))
(assert
 (not (and d_19_1 d_19_3)))
(assert
 (not (and d_19_2 d_19_3)))
(assert
 (let (($x1687 (or false d_20_0)))
 (let (($x1689 (or $x1687 d_20_1)))
 (let (($x1691 (or $x1689 d_20_2)))
 (or $x1691 d_20_3)))))
(assert
 (not (and d_20_0 d_20_1)))
(assert
 (not (and d_20_0 d_20_2)))
(assert
 (not (and d_20_0 d_20_3)))
(assert
 (not (and d_20_1 d_20_2)))
(assert
 (not (and d_20_1 d_20_3)))
(assert
 (not (and d_20_2 d_20_3)))
(assert
 (let (($x1707 (or false d_21_0)))
 (let (($x1709 (or $x1707 d_21_1)))
 (let (($x1711 (or $x1709 d_21_2)))
 (or $x1711 d_21_3)))))
(assert
 (not (and d_21_0 d_21_1)))
(assert
 (not (and d_21_0 d_21_2)))
(assert
 (not (and d_21_0 d_21_3)))
(assert
 (not (and d_21_1 d_21_2)))
(assert
 (not (and d_21_1 d_21_3)))
(assert
 (not (and d_21_2 d_21_3)))
(assert
 (let (($x1727 (or false d_22_0)))
 (let (($x1729 (or $x1727 d_22_1)))
 (let (($x1731 (or $x1729 d_22_2)))
 (or $x1731 d_22_3)))))
(assert
 (not (and d_22_0 d_22_1)))
(assert
 (not (and d_22_0 d_22_2)))
(assert
 (not (and d_22_0 d_22_3)))
(assert
 (not (and d_22_1 d_22_2)))
(assert
 (not (and d_22_1 d_22_3)))
(assert
 (not (and d_22_2 d_22_3)))
(assert
 (let (($x1747 (or false d_23_0)))
 (let (($x1749 (or $x1747 d_23_1)))
 (let (($x1751 (or $x1749 d_23_2)))
 (or $x1751 d_23_3)))))
(assert
 (not (and d_23_0 d_23_1)))
(assert
 (not (and d_23_0 d_23_2)))
(assert
 (not (and d_23_0 d_23_3)))
(assert
 (not (and d_23_1 d_23_2)))
(assert
 (not (and d_23_1 d_23_3)))
(assert
 (not (and d_23_2 d_23_3)))
(assert
 (let (($x1767 (or false d_24_0)))
 (let (($x1769 (or $x1767 d_24_1)))
 (let (($x1771 (or $x1769 d_24_2)))
 (or $x1771 d_24_3)))))
(assert
 (not (and d_24_0 d_24_1)))
(assert
 (not (and d_24_0 d_24_2)))
(assert
 (not (and d_24_0 d_24_3)))
(assert
 (not (and d_24_1 d_24_2)))
(assert
 (not (and d_24_1 d_24_3)))
(assert
 (not (and d_24_2 d_24_3)))
(assert
 (let (($x1787 (or false d_25_0)))
 (let (($x1789 (or $x1787 d_25_1)))
 (let (($x1791 (or $x1789 d_25_2)))
 (or $x1791 d_25_3)))))
(assert
 (not (and d_25_0 d_25_1)))
(assert
 (not (and d_25_0 d_25_2)))
(assert
 (not (and d_25_0 d_25_3)))
(assert
 (not (and d_25_1 d_25_2)))
(assert
 (not (and d_25_1 d_25_3)))
(assert
 (not (and d_25_2 d_25_3)))
(assert
 (let (($x1807 (or false d_26_0)))
 (let (($x1809 (or $x1807 d_26_1)))
 (let (($x1811 (or $x1809 d_26_2)))
 (or $x1811 d_26_3)))))
(assert
 (not (and d_26_0 d_26_1)))
(assert
 (not (and d_26_0 d_26_2)))
(assert
 (not (and d_26_0 d_26_3)))
(assert
 (not (and d_26_1 d_26_2)))
(assert
 (not (and d_26_1 d_26_3)))
(assert
 (not (and d_26_2 d_26_3)))
(assert
 (let (($x1827 (or false d_27_0)))
 (let (($x1829 (or $x1827 d_27_1)))
 (let (($x1831 (or $x1829 d_27_2)))
 (or $x1831 d_27_3)))))
(assert
 (not (and d_27_0 d_27_1)))
(assert
 (not (and d_27_0 d_27_2)))
(assert
 (not (and d_27_0 d_27_3)))
(assert
 (not (and d_27_1 d_27_2)))
(assert
 (not (and d_27_1 d_27_3)))
(assert
 (not (and d_27_2 d_27_3)))
(assert
 (let (($x1847 (or false d_28_0)))
 (let (($x1849 (or $x1847 d_28_1)))
 (let (($x1851 (or $x1849 d_28_2)))
 (or $x1851 d_28_3)))))
(assert
 (not (and d_28_0 d_28_1)))
(assert
 (not (and d_28_0 d_28_2)))
(assert
 (not (and d_28_0 d_28_3)))
(assert
 (not (and d_28_1 d_28_2)))
(assert
 (not (and d_28_1 d_28_3)))
(assert
 (not (and d_28_2 d_28_3)))
(assert
 (let (($x1867 (or false d_29_0)))
 (let (($x1869 (or $x1867 d_29_1)))
 (let (($x1871 (or $x1869 d_29_2)))
 (or $x1871 d_29_3)))))
(assert
 (not (and d_29_0 d_29_1)))
(assert
 (not (and d_29_0 d_29_2)))
(assert
 (not (and d_29_0 d_29_3)))
(assert
 (not (and d_29_1 d_29_2)))
(assert
 (not (and d_29_1 d_29_3)))
(assert
 (not (and d_29_2 d_29_3)))
(assert
 (let (($x1887 (or false d_30_0)))
 (let (($x1889 (or $x1887 d_30_1)))
 (let (($x1891 (or $x1889 d_30_2)))
 (or $x1891 d_30_3)))))
(assert
 (not (and d_30_0 d_30_1)))
(assert
 (not (and d_30_0 d_30_2)))
(assert
 (not (and d_30_0 d_30_3)))
(assert
 (not (and d_30_1 d_30_2)))
(assert
 (not (and d_30_1 d_30_3)))
(assert
 (not (and d_30_2 d_30_3)))
(assert
 (let (($x1907 (or false d_31_0)))
 (let (($x1909 (or $x1907 d_31_1)))
 (let (($x1911 (or $x1909 d_31_2)))
 (or $x1911 d_31_3)))))
(assert
 (not (and d_31_0 d_31_1)))
(assert
 (not (and d_31_0 d_31_2)))
(assert
 (not (and d_31_0 d_31_3)))
(assert
 (not (and d_31_1 d_31_2)))
(assert
 (not (and d_31_1 d_31_3)))
(assert
 (not (and d_31_2 d_31_3)))
(assert
 (let (($x1927 (or false d_32_0)))
 (let (($x1929 (or $x1927 d_32_1)))
 (let (($x1931 (or $x1929 d_32_2)))
 (or $x1931 d_32_3)))))
(assert
 (not (and d_32_0 d_32_1)))
(assert
 (not (and d_32_0 d_32_2)))
(assert
 (not (and d_32_0 d_32_3)))
(assert
 (not (and d_32_1 d_32_2)))
(assert
 (not (and d_32_1 d_32_3)))
(assert
 (not (and d_32_2 d_32_3)))
(assert
 (let (($x1947 (or false d_33_0)))
 (let (($x1949 (or $x1947 d_33_1)))
 (let (($x1951 (or $x1949 d_33_2)))
 (or $x1951 d_33_3)))))
(assert
 (not (and d_33_0 d_33_1)))
(assert
 (not (and d_33_0 d_33_2)))
(assert
 (not (and d_33_0 d_33_3)))
(assert
 (not (and d_33_1 d_33_2)))
(assert
 (not (and d_33_1 d_33_3)))
(assert
 (not (and d_33_2 d_33_3)))
(assert
 (let (($x1967 (or false d_34_0)))
 (let (($x1969 (or $x1967 d_34_1)))
 (let (($x1971 (or $x1969 d_34_2)))
 (or $x1971 d_34_3)))))
(assert
 (not (and d_34_0 d_34_1)))
(assert
 (not (and d_34_0 d_34_2)))
(assert
 (not (and d_34_0 d_34_3)))
(assert
 (not (and d_34_1 d_34_2)))
(assert
 (not (and d_34_1 d_34_3)))
(assert
 (not (and d_34_2 d_34_3)))
(assert
 (let (($x1987 (or false d_35_0)))
 (let (($x1989 (or $x1987 d_35_1)))
 (let (($x1991 (or $x1989 d_35_2)))
 (or $x1991 d_35_3)))))
(assert
 (not (and d_35_0 d_35_1)))
(assert
 (not (and d_35_0 d_35_2)))
(assert
 (not (and d_35_0 d_35_3)))
(assert
 (not (and d_35_1 d_35_2)))
(assert
 (not (and d_35_1 d_35_3)))
(assert
 (not (and d_35_2 d_35_3)))
(assert
 (let (($x2007 (or false d_36_0)))
 (let (($x2009 (or $x2007 d_36_1)))
 (let (($x2011 (or $x2009 d_36_2)))
 (or $x2011 d_36_3)))))
(assert
 (not (and d_36_0 d_36_1)))
(assert
 (not (and d_36_0 d_36_2)))
(assert
 (not (and d_36_0 d_36_3)))
(assert
 (not (and d_36_1 d_36_2)))
(assert
 (not (and d_36_1 d_36_3)))
(assert
 (not (and d_36_2 d_36_3)))
(assert
 (let (($x2027 (or false d_37_0)))
 (let (($x2029 (or $x2027 d_37_1)))
 (let (($x2031 (or $x2029 d_37_2)))
 (or $x2031 d_37_3)))))
(assert
 (not (and d_37_0 d_37_1)))
(assert
 (not (and d_37_0 d_37_2)))
(assert
 (not (and d_37_0 d_37_3)))
(assert
 (not (and d_37_1 d_37_2)))
(assert
 (not (and d_37_1 d_37_3)))
(assert
 (not (and d_37_2 d_37_3)))
(assert
 (let (($x2047 (or false d_38_0)))
 (let (($x2049 (or $x2047 d_38_1)))
 (let (($x2051 (or $x2049 d_38_2)))
 (or $x2051 d_38_3)))))
(assert
 (not (and d_38_0 d_38_1)))
(assert
 (not (and d_38_0 d_38_2)))
(assert
 (not (and d_38_0 d_38_3)))
(assert
 (not (and d_38_1 d_38_2)))
(assert
 (not (and d_38_1 d_38_3)))
(assert
 (not (and d_38_2 d_38_3)))
(assert
 (let (($x2067 (or false d_39_0)))
 (let (($x2069 (or $x2067 d_39_1)))
 (let (($x2071 (or $x2069 d_39_2)))
 (or $x2071 d_39_3)))))
(assert
 (not (and d_39_0 d_39_1)))
(assert
 (not (and d_39_0 d_39_2)))
(assert
 (not (and d_39_0 d_39_3)))
(assert
 (not (and d_39_1 d_39_2)))
(assert
 (not (and d_39_1 d_39_3)))
(assert
 (not (and d_39_2 d_39_3)))
(assert
 (let (($x2087 (or false d_40_0)))
 (let (($x2089 (or $x2087 d_40_1)))
 (let (($x2091 (or $x2089 d_40_2)))
 (or $x2091 d_40_3)))))
(assert
 (not (and d_40_0 d_40_1)))
(assert
 (not (and d_40_0 d_40_2)))
(assert
 (not (and d_40_0 d_40_3)))
(assert
 (not (and d_40_1 d_40_2)))
(assert
 (not (and d_40_1 d_40_3)))
(assert
 (not (and d_40_2 d_40_3)))
(assert
 (let (($x2107 (or false d_41_0)))
 (let (($x2109 (or $x2107 d_41_1)))
 (let (($x2111 (or $x2109 d_41_2)))
 (or $x2111 d_41_3)))))
(assert
 (not (and d_41_0 d_41_1)))
(assert
 (not (and d_41_0 d_41_2)))
(assert
 (not (and d_41_0 d_41_3)))
(assert
 (not (and d_41_1 d_41_2)))
(assert
 (not (and d_41_1 d_41_3)))
(assert
 (not (and d_41_2 d_41_3)))
(assert
 (let (($x2127 (or false d_42_0)))
 (let (($x2129 (or $x2127 d_42_1)))
 (let (($x2131 (or $x2129 d_42_2)))
 (or $x2131 d_42_3)))))
(assert
 (not (and d_42_0 d_42_1)))
(assert
 (not (and d_42_0 d_42_2)))
(assert
 (not (and d_42_0 d_42_3)))
(assert
 (not (and d_42_1 d_42_2)))
(assert
 (not (and d_42_1 d_42_3)))
(assert
 (not (and d_42_2 d_42_3)))
(assert
 (let (($x2147 (or false d_43_0)))
 (let (($x2149 (or $x2147 d_43_1)))
 (let (($x2151 (or $x2149 d_43_2)))
 (or $x2151 d_43_3)))))
(assert
 (not (and d_43_0 d_43_1)))
(assert
 (not (and d_43_0 d_43_2)))
(assert
 (not (and d_43_0 d_43_3)))
(assert
 (not (and d_43_1 d_43_2)))
(assert
 (not (and d_43_1 d_43_3)))
(assert
 (not (and d_43_2 d_43_3)))
(assert
 (let (($x2167 (or false d_44_0)))
 (let (($x2169 (or $x2167 d_44_1)))
 (let (($x2171 (or $x2169 d_44_2)))
 (or $x2171 d_44_3)))))
(assert
 (not (and d_44_0 d_44_1)))
(assert
 (not (and d_44_0 d_44_2)))
(assert
 (not (and d_44_0 d_44_3)))
(assert
 (not (and d_44_1 d_44_2)))
(assert
 (not (and d_44_1 d_44_3)))
(assert
 (not (and d_44_2 d_44_3)))
(assert
 (let (($x2187 (or false d_45_0)))
 (let (($x2189 (or $x2187 d_45_1)))
 (let (($x2191 (or $x2189 d_45_2)))
 (or $x2191 d_45_3)))))
(assert
 (not (and d_45_0 d_45_1)))
(assert
 (not (and d_45_0 d_45_2)))
(assert
 (not (and d_45_0 d_45_3)))
(assert
 (not (and d_45_1 d_45_2)))
(assert
 (not (and d_45_1 d_45_3)))
(assert
 (not (and d_45_2 d_45_3)))
(assert
 (let (($x2207 (or false d_46_0)))
 (let (($x2209 (or $x2207 d_46_1)))
 (let (($x2211 (or $x2209 d_46_2)))
 (or $x2211 d_46_3)))))
(assert
 (not (and d_46_0 d_46_1)))
(assert
 (not (and d_46_0 d_46_2)))
(assert
 (not (and d_46_0 d_46_3)))
(assert
 (not (and d_46_1 d_46_2)))
(assert
 (not (and d_46_1 d_46_3)))
(assert
 (not (and d_46_2 d_46_3)))
(assert
 (let (($x2227 (or false d_47_0)))
 (let (($x2229 (or $x2227 d_47_1)))
 (let (($x2231 (or $x2229 d_47_2)))
 (or $x2231 d_47_3)))))
(assert
 (not (and d_47_0 d_47_1)))
(assert
 (not (and d_47_0 d_47_2)))
(assert
 (not (and d_47_0 d_47_3)))
(assert
 (not (and d_47_1 d_47_2)))
(assert
 (not (and d_47_1 d_47_3)))
(assert
 (not (and d_47_2 d_47_3)))
(assert
 (let (($x2247 (or false d_48_0)))
 (let (($x2249 (or $x2247 d_48_1)))
 (let (($x2251 (or $x2249 d_48_2)))
 (or $x2251 d_48_3)))))
(assert
 (not (and d_48_0 d_48_1)))
(assert
 (not (and d_48_0 d_48_2)))
(assert
 (not (and d_48_0 d_48_3)))
(assert
 (not (and d_48_1 d_48_2)))
(assert
 (not (and d_48_1 d_48_3)))
(assert
 (not (and d_48_2 d_48_3)))
(assert
 (let (($x2267 (or false d_49_0)))
 (let (($x2269 (or $x2267 d_49_1)))
 (let (($x2271 (or $x2269 d_49_2)))
 (or $x2271 d_49_3)))))
(assert
 (not (and d_49_0 d_49_1)))
(assert
 (not (and d_49_0 d_49_2)))
(assert
 (not (and d_49_0 d_49_3)))
(assert
 (not (and d_49_1 d_49_2)))
(assert
 (not (and d_49_1 d_49_3)))
(assert
 (not (and d_49_2 d_49_3)))
(assert
 (let (($x2287 (or false d_50_0)))
 (let (($x2289 (or $x2287 d_50_1)))
 (let (($x2291 (or $x2289 d_50_2)))
 (or $x2291 d_50_3)))))
(assert
 (not (and d_50_0 d_50_1)))
(assert
 (not (and d_50_0 d_50_2)))
(assert
 (not (and d_50_0 d_50_3)))
(assert
 (not (and d_50_1 d_50_2)))
(assert
 (not (and d_50_1 d_50_3)))
(assert
 (not (and d_50_2 d_50_3)))
(assert
 (let (($x2307 (or false d_51_0)))
 (let (($x2309 (or $x2307 d_51_1)))
 (let (($x2311 (or $x2309 d_51_2)))
 (or $x2311 d_51_3)))))
(assert
 (not (and d_51_0 d_51_1)))
(assert
 (not (and d_51_0 d_51_2)))
(assert
 (not (and d_51_0 d_51_3)))
(assert
 (not (and d_51_1 d_51_2)))
(assert
 (not (and d_51_1 d_51_3)))
(assert
 (not (and d_51_2 d_51_3)))
(assert
 (let (($x2327 (or false d_52_0)))
 (let (($x2329 (or $x2327 d_52_1)))
 (let (($x2331 (or $x2329 d_52_2)))
 (or $x2331 d_52_3)))))
(assert
 (not (and d_52_0 d_52_1)))
(assert
 (not (and d_52_0 d_52_2)))
(assert
 (not (and d_52_0 d_52_3)))
(assert
 (not (and d_52_1 d_52_2)))
(assert
 (not (and d_52_1 d_52_3)))
(assert
 (not (and d_52_2 d_52_3)))
(assert
 (let (($x2347 (or false d_53_0)))
 (let (($x2349 (or $x2347 d_53_1)))
 (let (($x2351 (or $x2349 d_53_2)))
 (or $x2351 d_53_3)))))
(assert
 (not (and d_53_0 d_53_1)))
(assert
 (not (and d_53_0 d_53_2)))
(assert
 (not (and d_53_0 d_53_3)))
(assert
 (not (and d_53_1 d_53_2)))
(assert
 (not (and d_53_1 d_53_3)))
(assert
 (not (and d_53_2 d_53_3)))
(assert
 (let (($x2367 (or false d_54_0)))
 (let (($x2369 (or $x2367 d_54_1)))
 (let (($x2371 (or $x2369 d_54_2)))
 (or $x2371 d_54_3)))))
(assert
 (not (and d_54_0 d_54_1)))
(assert
 (not (and d_54_0 d_54_2)))
(assert
 (not (and d_54_0 d_54_3)))
(assert
 (not (and d_54_1 d_54_2)))
(assert
 (not (and d_54_1 d_54_3)))
(assert
 (not (and d_54_2 d_54_3)))
(assert
 (let (($x2387 (or false d_55_0)))
 (let (($x2389 (or $x2387 d_55_1)))
 (let (($x2391 (or $x2389 d_55_2)))
 (or $x2391 d_55_3)))))
(assert
 (not (and d_55_0 d_55_1)))
(assert
 (not (and d_55_0 d_55_2)))
(assert
 (not (and d_55_0 d_55_3)))
(assert
 (not (and d_55_1 d_55_2)))
(assert
 (not (and d_55_1 d_55_3)))
(assert
 (not (and d_55_2 d_55_3)))
(assert
 (let (($x2407 (or false d_56_0)))
 (let (($x2409 (or $x2407 d_56_1)))
 (let (($x2411 (or $x2409 d_56_2)))
 (or $x2411 d_56_3)))))
(assert
 (not (and d_56_0 d_56_1)))
(assert
 (not (and d_56_0 d_56_2)))
(assert
 (not (and d_56_0 d_56_3)))
(assert
 (not (and d_56_1 d_56_2)))
(assert
 (not (and d_56_1 d_56_3)))
(assert
 (not (and d_56_2 d_56_3)))
(assert
 (let (($x2427 (or false d_57_0)))
 (let (($x2429 (or $x2427 d_57_1)))
 (let (($x2431 (or $x2429 d_57_2)))
 (or $x2431 d_57_3)))))
(assert
 (not (and d_57_0 d_57_1)))
(assert
 (not (and d_57_0 d_57_2)))
(assert
 (not (and d_57_0 d_57_3)))
(assert
 (not (and d_57_1 d_57_2)))
(assert
 (not (and d_57_1 d_57_3)))
(assert
 (not (and d_57_2 d_57_3)))
(assert
 (let (($x2447 (or false d_58_0)))
 (let (($x2449 (or $x2447 d_58_1)))
 (let (($x2451 (or $x2449 d_58_2)))
 (or $x2451 d_58_3)))))
(assert
 (not (and d_58_0 d_58_1)))
(assert
 (not (and d_58_0 d_58_2)))
(assert
 (not (and d_58_0 d_58_3)))
(assert
 (not (and d_58_1 d_58_2)))
(assert
 (not (and d_58_1 d_58_3)))
(assert
 (not (and d_58_2 d_58_3)))
(assert
 (let (($x2467 (or false d_59_0)))
 (let (($x2469 (or $x2467 d_59_1)))
 (let (($x2471 (or $x2469 d_59_2)))
 (or $x2471 d_59_3)))))
(assert
 (not (and d_59_0 d_59_1)))
(assert
 (not (and d_59_0 d_59_2)))
(assert
 (not (and d_59_0 d_59_3)))
(assert
 (not (and d_59_1 d_59_2)))
(assert
 (not (and d_59_1 d_59_3)))
(assert
 (not (and d_59_2 d_59_3)))
(assert
 (let (($x2487 (or false d_60_0)))
 (let (($x2489 (or $x2487 d_60_1)))
 (let (($x2491 (or $x2489 d_60_2)))
 (or $x2491 d_60_3)))))
(assert
 (not (and d_60_0 d_60_1)))
(assert
 (not (and d_60_0 d_60_2)))
(assert
 (not (and d_60_0 d_60_3)))
(assert
 (not (and d_60_1 d_60_2)))
(assert
 (not (and d_60_1 d_60_3)))
(assert
 (not (and d_60_2 d_60_3)))
(assert
 (let ((?x5212 (ite d_60_2 1 0)))
 (let ((?x5186 (ite d_58_2 1 0)))
 (let ((?x4946 (ite d_34_2 1 0)))
 (let ((?x4810 (ite d_17_2 1 0)))
 (let ((?x4954 (ite d_35_2 1 0)))
 (let ((?x5199 (ite d_59_2 1 0)))
 (let ((?x5207 (+ 0 ?x5199)))
 (let ((?x5208 (+ ?x5207 ?x4954)))
 (let ((?x5209 (+ ?x5208 ?x4810)))
 (let ((?x5210 (+ ?x5209 ?x4946)))
 (let ((?x5211 (+ ?x5210 ?x5186)))
 (let ((?x4960 (ite d_36_2 1 0)))
 (let ((?x4741 (ite d_18_2 1 0)))
 (let ((?x4825 (ite d_21_2 1 0)))
 (let ((?x5013 (ite d_41_2 1 0)))
 (let ((?x5194 (+ 0 ?x5013)))
 (let ((?x5195 (+ ?x5194 ?x4825)))
 (let ((?x5196 (+ ?x5195 ?x4741)))
 (let ((?x5197 (+ ?x5196 ?x4810)))
 (let ((?x5198 (+ ?x5197 ?x4960)))
 (let ((?x5173 (ite d_57_2 1 0)))
 (let ((?x4933 (ite d_33_2 1 0)))
 (let ((?x4797 (ite d_16_2 1 0)))
 (let ((?x5181 (+ 0 ?x4960)))
 (let ((?x5182 (+ ?x5181 ?x4810)))
 (let ((?x5183 (+ ?x5182 ?x4797)))
 (let ((?x5184 (+ ?x5183 ?x4933)))
 (let ((?x5185 (+ ?x5184 ?x5173)))
 (let ((?x5160 (ite d_56_2 1 0)))
 (let ((?x4931 (ite d_32_2 1 0)))
 (let ((?x4795 (ite d_15_2 1 0)))
 (let ((?x5168 (+ 0 ?x4946)))
 (let ((?x5169 (+ ?x5168 ?x4797)))
 (let ((?x5170 (+ ?x5169 ?x4795)))
 (let ((?x5171 (+ ?x5170 ?x4931)))
 (let ((?x5172 (+ ?x5171 ?x5160)))
 (let ((?x5158 (ite d_55_2 1 0)))
 (let ((?x5145 (ite d_54_2 1 0)))
 (let ((?x4918 (ite d_31_2 1 0)))
 (let ((?x5154 (+ 0 ?x4933)))
 (let ((?x5155 (+ ?x5154 ?x4795)))
 (let ((?x5156 (+ ?x5155 ?x4918)))
 (let ((?x5157 (+ ?x5156 ?x5145)))
 (let ((?x5159 (+ ?x5157 ?x5158)))
 (let ((?x5132 (ite d_53_2 1 0)))
 (let ((?x4905 (ite d_30_2 1 0)))
 (let ((?x4782 (ite d_14_2 1 0)))
 (let ((?x5141 (+ 0 ?x4795)))
 (let ((?x5142 (+ ?x5141 ?x4782)))
 (let ((?x5143 (+ ?x5142 ?x4905)))
 (let ((?x5144 (+ ?x5143 ?x5132)))
 (let ((?x5146 (+ ?x5144 ?x5145)))
 (let ((?x5119 (ite d_52_2 1 0)))
 (let ((?x4903 (ite d_29_2 1 0)))
 (let ((?x4780 (ite d_13_2 1 0)))
 (let ((?x5128 (+ 0 ?x4782)))
 (let ((?x5129 (+ ?x5128 ?x4780)))
 (let ((?x5130 (+ ?x5129 ?x4903)))
 (let ((?x5131 (+ ?x5130 ?x5119)))
 (let ((?x5133 (+ ?x5131 ?x5132)))
 (let ((?x5117 (ite d_51_2 1 0)))
 (let ((?x5104 (ite d_50_2 1 0)))
 (let ((?x4890 (ite d_28_2 1 0)))
 (let ((?x5114 (+ 0 ?x4780)))
 (let ((?x5115 (+ ?x5114 ?x4890)))
 (let ((?x5116 (+ ?x5115 ?x5104)))
 (let ((?x5118 (+ ?x5116 ?x5117)))
 (let ((?x5120 (+ ?x5118 ?x5119)))
 (let ((?x5091 (ite d_49_2 1 0)))
 (let ((?x4877 (ite d_27_2 1 0)))
 (let ((?x4767 (ite d_12_2 1 0)))
 (let ((?x5101 (+ 0 ?x4767)))
 (let ((?x5102 (+ ?x5101 ?x4877)))
 (let ((?x5103 (+ ?x5102 ?x5091)))
 (let ((?x5105 (+ ?x5103 ?x5104)))
 (let ((?x5106 (+ ?x5105 ?x4903)))
 (let ((?x5078 (ite d_48_2 1 0)))
 (let ((?x4875 (ite d_26_2 1 0)))
 (let ((?x4765 (ite d_11_2 1 0)))
 (let ((?x5088 (+ 0 ?x4765)))
 (let ((?x5089 (+ ?x5088 ?x4875)))
 (let ((?x5090 (+ ?x5089 ?x5078)))
 (let ((?x5092 (+ ?x5090 ?x5091)))
 (let ((?x5093 (+ ?x5092 ?x4890)))
 (let ((?x5076 (ite d_47_2 1 0)))
 (let ((?x5063 (ite d_46_2 1 0)))
 (let ((?x4862 (ite d_25_2 1 0)))
 (let ((?x5074 (+ 0 ?x4862)))
 (let ((?x5075 (+ ?x5074 ?x5063)))
 (let ((?x5077 (+ ?x5075 ?x5076)))
 (let ((?x5079 (+ ?x5077 ?x5078)))
 (let ((?x5080 (+ ?x5079 ?x4877)))
 (let ((?x4752 (ite d_10_2 1 0)))
 (let ((?x5050 (ite d_45_2 1 0)))
 (let ((?x4849 (ite d_24_2 1 0)))
 (let ((?x5061 (+ 0 ?x4849)))
 (let ((?x5062 (+ ?x5061 ?x5050)))
 (let ((?x5064 (+ ?x5062 ?x5063)))
 (let ((?x5065 (+ ?x5064 ?x4875)))
 (let ((?x5066 (+ ?x5065 ?x4765)))
 (let ((?x4750 (ite d_9_2 1 0)))
 (let ((?x5037 (ite d_44_2 1 0)))
 (let ((?x4847 (ite d_23_2 1 0)))
 (let ((?x5048 (+ 0 ?x4847)))
 (let ((?x5049 (+ ?x5048 ?x5037)))
 (let ((?x5051 (+ ?x5049 ?x5050)))
 (let ((?x5052 (+ ?x5051 ?x4862)))
 (let ((?x5053 (+ ?x5052 ?x4752)))
 (let ((?x4834 (ite d_22_2 1 0)))
 (let ((?x5035 (ite d_43_2 1 0)))
 (let ((?x5022 (ite d_42_2 1 0)))
 (let ((?x5034 (+ 0 ?x5022)))
 (let ((?x5036 (+ ?x5034 ?x5035)))
 (let ((?x5038 (+ ?x5036 ?x5037)))
 (let ((?x5039 (+ ?x5038 ?x4849)))
 (let ((?x5040 (+ ?x5039 ?x4750)))
 (let ((?x4820 (ite d_20_2 1 0)))
 (let ((?x4735 (ite d_8_2 1 0)))
 (let ((?x4996 (ite d_40_2 1 0)))
 (let ((?x5021 (+ 0 ?x4996)))
 (let ((?x5023 (+ ?x5021 ?x5022)))
 (let ((?x5024 (+ ?x5023 ?x4847)))
 (let ((?x5025 (+ ?x5024 ?x4750)))
 (let ((?x5026 (+ ?x5025 ?x4735)))
 (let ((?x4733 (ite d_7_2 1 0)))
 (let ((?x4818 (ite d_19_2 1 0)))
 (let ((?x4987 (ite d_39_2 1 0)))
 (let ((?x5008 (+ 0 ?x4987)))
 (let ((?x5009 (+ ?x5008 ?x4818)))
 (let ((?x5010 (+ ?x5009 ?x4733)))
 (let ((?x5011 (+ ?x5010 ?x4741)))
 (let ((?x5012 (+ ?x5011 ?x4954)))
 (let ((?x4982 (ite d_38_2 1 0)))
 (let ((?x4995 (+ 0 ?x4982)))
 (let ((?x4997 (+ ?x4995 ?x4996)))
 (let ((?x4998 (+ ?x4997 ?x4834)))
 (let ((?x4999 (+ ?x4998 ?x4735)))
 (let ((?x5000 (+ ?x4999 ?x4733)))
 (let ((?x4980 (ite d_37_2 1 0)))
 (let ((?x4981 (+ 0 ?x4980)))
 (let ((?x4983 (+ ?x4981 ?x4982)))
 (let ((?x4984 (+ ?x4983 ?x4820)))
 (let ((?x4985 (+ ?x4984 ?x4733)))
 (let ((?x4986 (+ ?x4985 ?x4825)))
 (let ((?x4725 (ite d_6_2 1 0)))
 (let ((?x4715 (ite d_1_2 1 0)))
 (let ((?x4968 (+ 0 ?x4825)))
 (let ((?x4969 (+ ?x4968 ?x4733)))
 (let ((?x4970 (+ ?x4969 ?x4715)))
 (let ((?x4971 (+ ?x4970 ?x4725)))
 (let ((?x4972 (+ ?x4971 ?x4810)))
 (let ((?x4962 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4954) ?x4741) ?x4725) ?x4797) ?x4946) ?x4960))))
 (let ((?x4723 (ite d_5_2 1 0)))
 (let ((?x4941 (+ 0 ?x4810)))
 (let ((?x4942 (+ ?x4941 ?x4725)))
 (let ((?x4943 (+ ?x4942 ?x4723)))
 (let ((?x4944 (+ ?x4943 ?x4795)))
 (let ((?x4945 (+ ?x4944 ?x4933)))
 (let ((?x4935 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4797) ?x4723) ?x4782) ?x4918) ?x4931) ?x4933))))
 (let ((?x4721 (ite d_4_2 1 0)))
 (let ((?x4914 (+ 0 ?x4723)))
 (let ((?x4915 (+ ?x4914 ?x4721)))
 (let ((?x4916 (+ ?x4915 ?x4780)))
 (let ((?x4917 (+ ?x4916 ?x4905)))
 (let ((?x4919 (+ ?x4917 ?x4918)))
 (let ((?x4908 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4721) ?x4767) ?x4890) ?x4903) ?x4905) ?x4782))))
 (let ((?x4719 (ite d_3_2 1 0)))
 (let ((?x4887 (+ 0 ?x4719)))
 (let ((?x4888 (+ ?x4887 ?x4765)))
 (let ((?x4889 (+ ?x4888 ?x4877)))
 (let ((?x4891 (+ ?x4889 ?x4890)))
 (let ((?x4892 (+ ?x4891 ?x4780)))
 (let ((?x4881 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4752) ?x4862) ?x4875) ?x4877) ?x4767) ?x4719))))
 (let ((?x4717 (ite d_2_2 1 0)))
 (let ((?x4860 (+ 0 ?x4750)))
 (let ((?x4861 (+ ?x4860 ?x4849)))
 (let ((?x4863 (+ ?x4861 ?x4862)))
 (let ((?x4864 (+ ?x4863 ?x4765)))
 (let ((?x4865 (+ ?x4864 ?x4719)))
 (let ((?x4854 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4834) ?x4847) ?x4849) ?x4752) ?x4717) ?x4735))))
 (let ((?x4840 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4820) ?x4834) ?x4750) ?x4717) ?x4715) ?x4733))))
 (let ((?x4827 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4818) ?x4820) ?x4735) ?x4715) ?x4741) ?x4825))))
 (let ((?x4738 (ite d_0_2 1 0)))
 (let ((?x4805 (+ 0 ?x4741)))
 (let ((?x4806 (+ ?x4805 ?x4715)))
 (let ((?x4807 (+ ?x4806 ?x4738)))
 (let ((?x4808 (+ ?x4807 ?x4723)))
 (let ((?x4809 (+ ?x4808 ?x4797)))
 (let ((?x4799 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4725) ?x4738) ?x4721) ?x4782) ?x4795) ?x4797))))
 (let ((?x4785 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4738) ?x4719) ?x4767) ?x4780) ?x4782) ?x4723))))
 (let ((?x4771 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4717) ?x4752) ?x4765) ?x4767) ?x4721) ?x4738))))
 (let ((?x4757 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4735) ?x4750) ?x4752) ?x4719) ?x4738) ?x4715))))
 (let ((?x4743 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4733) ?x4735) ?x4717) ?x4738) ?x4725) ?x4741))))
 (let ((?x4727 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4715) ?x4717) ?x4719) ?x4721) ?x4723) ?x4725))))
 (let (($x4732 (or false (not (=> d_0_3 (and d_0_3 (= ?x4727 6.0)))))))
 (let (($x4748 (or $x4732 (not (=> d_1_3 (and d_1_3 (= ?x4743 6.0)))))))
 (let (($x4762 (or $x4748 (not (=> d_2_3 (and d_2_3 (= ?x4757 6.0)))))))
 (let (($x4776 (or $x4762 (not (=> d_3_3 (and d_3_3 (= ?x4771 6.0)))))))
 (let (($x4790 (or $x4776 (not (=> d_4_3 (and d_4_3 (= ?x4785 6.0)))))))
 (let (($x4804 (or $x4790 (not (=> d_5_3 (and d_5_3 (= ?x4799 6.0)))))))
 (let (($x4817 (or $x4804 (not (=> d_6_3 (and d_6_3 (= (to_real (+ ?x4809 ?x4810)) 6.0)))))))
 (let (($x4832 (or $x4817 (not (=> d_7_3 (and d_7_3 (= ?x4827 6.0)))))))
 (let (($x4845 (or $x4832 (not (=> d_8_3 (and d_8_3 (= ?x4840 6.0)))))))
 (let (($x4859 (or $x4845 (not (=> d_9_3 (and d_9_3 (= ?x4854 6.0)))))))
 (let (($x4872 (or $x4859 (not (=> d_10_3 (and d_10_3 (= (to_real (+ ?x4865 ?x4717)) 6.0)))))))
 (let (($x4886 (or $x4872 (not (=> d_11_3 (and d_11_3 (= ?x4881 6.0)))))))
 (let (($x4899 (or $x4886 (not (=> d_12_3 (and d_12_3 (= (to_real (+ ?x4892 ?x4721)) 6.0)))))))
 (let (($x4913 (or $x4899 (not (=> d_13_3 (and d_13_3 (= ?x4908 6.0)))))))
 (let (($x4926 (or $x4913 (not (=> d_14_3 (and d_14_3 (= (to_real (+ ?x4919 ?x4795)) 6.0)))))))
 (let (($x4940 (or $x4926 (not (=> d_15_3 (and d_15_3 (= ?x4935 6.0)))))))
 (let (($x4953 (or $x4940 (not (=> d_16_3 (and d_16_3 (= (to_real (+ ?x4945 ?x4946)) 6.0)))))))
 (let (($x4967 (or $x4953 (not (=> d_17_3 (and d_17_3 (= ?x4962 6.0)))))))
 (let (($x4979 (or $x4967 (not (=> d_18_3 (and d_18_3 (= (to_real (+ ?x4972 ?x4954)) 6.0)))))))
 (let (($x4994 (or $x4979 (not (=> d_19_3 (and d_19_3 (= (to_real (+ ?x4986 ?x4987)) 6.0)))))))
 (let (($x5007 (or $x4994 (not (=> d_20_3 (and d_20_3 (= (to_real (+ ?x5000 ?x4818)) 6.0)))))))
 (let (($x5020 (or $x5007 (not (=> d_21_3 (and d_21_3 (= (to_real (+ ?x5012 ?x5013)) 6.0)))))))
 (let (($x5033 (or $x5020 (not (=> d_22_3 (and d_22_3 (= (to_real (+ ?x5026 ?x4820)) 6.0)))))))
 (let (($x5047 (or $x5033 (not (=> d_23_3 (and d_23_3 (= (to_real (+ ?x5040 ?x4834)) 6.0)))))))
 (let (($x5060 (or $x5047 (not (=> d_24_3 (and d_24_3 (= (to_real (+ ?x5053 ?x4750)) 6.0)))))))
 (let (($x5073 (or $x5060 (not (=> d_25_3 (and d_25_3 (= (to_real (+ ?x5066 ?x4752)) 6.0)))))))
 (let (($x5087 (or $x5073 (not (=> d_26_3 (and d_26_3 (= (to_real (+ ?x5080 ?x4765)) 6.0)))))))
 (let (($x5100 (or $x5087 (not (=> d_27_3 (and d_27_3 (= (to_real (+ ?x5093 ?x4767)) 6.0)))))))
 (let (($x5113 (or $x5100 (not (=> d_28_3 (and d_28_3 (= (to_real (+ ?x5106 ?x4780)) 6.0)))))))
 (let (($x5127 (or $x5113 (not (=> d_29_3 (and d_29_3 (= (to_real (+ ?x5120 ?x4905)) 6.0)))))))
 (let (($x5140 (or $x5127 (not (=> d_30_3 (and d_30_3 (= (to_real (+ ?x5133 ?x4918)) 6.0)))))))
 (let (($x5153 (or $x5140 (not (=> d_31_3 (and d_31_3 (= (to_real (+ ?x5146 ?x4931)) 6.0)))))))
 (let (($x5167 (or $x5153 (not (=> d_32_3 (and d_32_3 (= (to_real (+ ?x5159 ?x5160)) 6.0)))))))
 (let (($x5180 (or $x5167 (not (=> d_33_3 (and d_33_3 (= (to_real (+ ?x5172 ?x5173)) 6.0)))))))
 (let (($x5193 (or $x5180 (not (=> d_34_3 (and d_34_3 (= (to_real (+ ?x5185 ?x5186)) 6.0)))))))
 (let (($x5206 (or $x5193 (not (=> d_35_3 (and d_35_3 (= (to_real (+ ?x5198 ?x5199)) 6.0)))))))
 (let (($x5219 (or $x5206 (not (=> d_36_3 (and d_36_3 (= (to_real (+ ?x5211 ?x5212)) 6.0)))))))
 (let ((?x4707 (ite c_60_1 1 0)))
 (let ((?x4635 (ite c_58_1 1 0)))
 (let ((?x3969 (ite c_34_1 1 0)))
 (let ((?x2690 (ite c_17_1 1 0)))
 (let ((?x4002 (ite c_35_1 1 0)))
 (let ((?x4671 (ite c_59_1 1 0)))
 (let ((?x4702 (+ 0 ?x4671)))
 (let ((?x4703 (+ ?x4702 ?x4002)))
 (let ((?x4704 (+ ?x4703 ?x2690)))
 (let ((?x4705 (+ ?x4704 ?x3969)))
 (let ((?x4706 (+ ?x4705 ?x4635)))
 (let ((?x4684 (ite c_60_2 1 0)))
 (let ((?x4612 (ite c_58_2 1 0)))
 (let ((?x3946 (ite c_34_2 1 0)))
 (let ((?x3569 (ite c_17_2 1 0)))
 (let ((?x3977 (ite c_35_2 1 0)))
 (let ((?x4648 (ite c_59_2 1 0)))
 (let ((?x4679 (+ 0 ?x4648)))
 (let ((?x4680 (+ ?x4679 ?x3977)))
 (let ((?x4681 (+ ?x4680 ?x3569)))
 (let ((?x4682 (+ ?x4681 ?x3946)))
 (let ((?x4683 (+ ?x4682 ?x4612)))
 (let ((?x4686 (to_real (+ ?x4683 ?x4684))))
 (let ((?x4696 (ite c_60_3 1 0)))
 (let ((?x4624 (ite c_58_3 1 0)))
 (let ((?x3958 (ite c_34_3 1 0)))
 (let ((?x3581 (ite c_17_3 1 0)))
 (let ((?x3990 (ite c_35_3 1 0)))
 (let ((?x4660 (ite c_59_3 1 0)))
 (let ((?x4691 (+ 0 ?x4660)))
 (let ((?x4692 (+ ?x4691 ?x3990)))
 (let ((?x4693 (+ ?x4692 ?x3581)))
 (let ((?x4694 (+ ?x4693 ?x3958)))
 (let ((?x4695 (+ ?x4694 ?x4624)))
 (let (($x4711 (and (and (= (to_real (+ ?x4695 ?x4696)) 1.0) (= ?x4686 2.0)) (= (to_real (+ ?x4706 ?x4707)) 3.0))))
 (let ((?x4008 (ite c_36_1 1 0)))
 (let ((?x2692 (ite c_18_1 1 0)))
 (let ((?x3633 (ite c_21_1 1 0)))
 (let ((?x4155 (ite c_41_1 1 0)))
 (let ((?x4666 (+ 0 ?x4155)))
 (let ((?x4667 (+ ?x4666 ?x3633)))
 (let ((?x4668 (+ ?x4667 ?x2692)))
 (let ((?x4669 (+ ?x4668 ?x2690)))
 (let ((?x4670 (+ ?x4669 ?x4008)))
 (let ((?x3983 (ite c_36_2 1 0)))
 (let ((?x3384 (ite c_18_2 1 0)))
 (let ((?x3606 (ite c_21_2 1 0)))
 (let ((?x4132 (ite c_41_2 1 0)))
 (let ((?x4643 (+ 0 ?x4132)))
 (let ((?x4644 (+ ?x4643 ?x3606)))
 (let ((?x4645 (+ ?x4644 ?x3384)))
 (let ((?x4646 (+ ?x4645 ?x3569)))
 (let ((?x4647 (+ ?x4646 ?x3983)))
 (let ((?x4650 (to_real (+ ?x4647 ?x4648))))
 (let ((?x3996 (ite c_36_3 1 0)))
 (let ((?x3399 (ite c_18_3 1 0)))
 (let ((?x3620 (ite c_21_3 1 0)))
 (let ((?x4144 (ite c_41_3 1 0)))
 (let ((?x4655 (+ 0 ?x4144)))
 (let ((?x4656 (+ ?x4655 ?x3620)))
 (let ((?x4657 (+ ?x4656 ?x3399)))
 (let ((?x4658 (+ ?x4657 ?x3581)))
 (let ((?x4659 (+ ?x4658 ?x3996)))
 (let (($x4675 (and (and (= (to_real (+ ?x4659 ?x4660)) 1.0) (= ?x4650 2.0)) (= (to_real (+ ?x4670 ?x4671)) 3.0))))
 (let ((?x4599 (ite c_57_1 1 0)))
 (let ((?x3933 (ite c_33_1 1 0)))
 (let ((?x2688 (ite c_16_1 1 0)))
 (let ((?x4630 (+ 0 ?x4008)))
 (let ((?x4631 (+ ?x4630 ?x2690)))
 (let ((?x4632 (+ ?x4631 ?x2688)))
 (let ((?x4633 (+ ?x4632 ?x3933)))
 (let ((?x4634 (+ ?x4633 ?x4599)))
 (let ((?x4576 (ite c_57_2 1 0)))
 (let ((?x3908 (ite c_33_2 1 0)))
 (let ((?x3533 (ite c_16_2 1 0)))
 (let ((?x4607 (+ 0 ?x3983)))
 (let ((?x4608 (+ ?x4607 ?x3569)))
 (let ((?x4609 (+ ?x4608 ?x3533)))
 (let ((?x4610 (+ ?x4609 ?x3908)))
 (let ((?x4611 (+ ?x4610 ?x4576)))
 (let ((?x4614 (to_real (+ ?x4611 ?x4612))))
 (let ((?x4588 (ite c_57_3 1 0)))
 (let ((?x3921 (ite c_33_3 1 0)))
 (let ((?x3546 (ite c_16_3 1 0)))
 (let ((?x4619 (+ 0 ?x3996)))
 (let ((?x4620 (+ ?x4619 ?x3581)))
 (let ((?x4621 (+ ?x4620 ?x3546)))
 (let ((?x4622 (+ ?x4621 ?x3921)))
 (let ((?x4623 (+ ?x4622 ?x4588)))
 (let (($x4639 (and (and (= (to_real (+ ?x4623 ?x4624)) 1.0) (= ?x4614 2.0)) (= (to_real (+ ?x4634 ?x4635)) 3.0))))
 (let ((?x4563 (ite c_56_1 1 0)))
 (let ((?x3931 (ite c_32_1 1 0)))
 (let ((?x2686 (ite c_15_1 1 0)))
 (let ((?x4594 (+ 0 ?x3969)))
 (let ((?x4595 (+ ?x4594 ?x2688)))
 (let ((?x4596 (+ ?x4595 ?x2686)))
 (let ((?x4597 (+ ?x4596 ?x3931)))
 (let ((?x4598 (+ ?x4597 ?x4563)))
 (let ((?x4538 (ite c_56_2 1 0)))
 (let ((?x3906 (ite c_32_2 1 0)))
 (let ((?x3531 (ite c_15_2 1 0)))
 (let ((?x4571 (+ 0 ?x3946)))
 (let ((?x4572 (+ ?x4571 ?x3533)))
 (let ((?x4573 (+ ?x4572 ?x3531)))
 (let ((?x4574 (+ ?x4573 ?x3906)))
 (let ((?x4575 (+ ?x4574 ?x4538)))
 (let ((?x4578 (to_real (+ ?x4575 ?x4576))))
 (let ((?x4551 (ite c_56_3 1 0)))
 (let ((?x3919 (ite c_32_3 1 0)))
 (let ((?x3544 (ite c_15_3 1 0)))
 (let ((?x4583 (+ 0 ?x3958)))
 (let ((?x4584 (+ ?x4583 ?x3546)))
 (let ((?x4585 (+ ?x4584 ?x3544)))
 (let ((?x4586 (+ ?x4585 ?x3919)))
 (let ((?x4587 (+ ?x4586 ?x4551)))
 (let (($x4603 (and (and (= (to_real (+ ?x4587 ?x4588)) 1.0) (= ?x4578 2.0)) (= (to_real (+ ?x4598 ?x4599)) 3.0))))
 (let ((?x4561 (ite c_55_1 1 0)))
 (let ((?x4523 (ite c_54_1 1 0)))
 (let ((?x3893 (ite c_31_1 1 0)))
 (let ((?x4557 (+ 0 ?x3933)))
 (let ((?x4558 (+ ?x4557 ?x2686)))
 (let ((?x4559 (+ ?x4558 ?x3893)))
 (let ((?x4560 (+ ?x4559 ?x4523)))
 (let ((?x4562 (+ ?x4560 ?x4561)))
 (let ((?x4536 (ite c_55_2 1 0)))
 (let ((?x4500 (ite c_54_2 1 0)))
 (let ((?x3870 (ite c_31_2 1 0)))
 (let ((?x4532 (+ 0 ?x3908)))
 (let ((?x4533 (+ ?x4532 ?x3531)))
 (let ((?x4534 (+ ?x4533 ?x3870)))
 (let ((?x4535 (+ ?x4534 ?x4500)))
 (let ((?x4537 (+ ?x4535 ?x4536)))
 (let ((?x4540 (to_real (+ ?x4537 ?x4538))))
 (let ((?x4549 (ite c_55_3 1 0)))
 (let ((?x4512 (ite c_54_3 1 0)))
 (let ((?x3882 (ite c_31_3 1 0)))
 (let ((?x4545 (+ 0 ?x3921)))
 (let ((?x4546 (+ ?x4545 ?x3544)))
 (let ((?x4547 (+ ?x4546 ?x3882)))
 (let ((?x4548 (+ ?x4547 ?x4512)))
 (let ((?x4550 (+ ?x4548 ?x4549)))
 (let (($x4567 (and (and (= (to_real (+ ?x4550 ?x4551)) 1.0) (= ?x4540 2.0)) (= (to_real (+ ?x4562 ?x4563)) 3.0))))
 (let ((?x4487 (ite c_53_1 1 0)))
 (let ((?x3857 (ite c_30_1 1 0)))
 (let ((?x2684 (ite c_14_1 1 0)))
 (let ((?x4519 (+ 0 ?x2686)))
 (let ((?x4520 (+ ?x4519 ?x2684)))
 (let ((?x4521 (+ ?x4520 ?x3857)))
 (let ((?x4522 (+ ?x4521 ?x4487)))
 (let ((?x4524 (+ ?x4522 ?x4523)))
 (let ((?x4464 (ite c_53_2 1 0)))
 (let ((?x3832 (ite c_30_2 1 0)))
 (let ((?x3496 (ite c_14_2 1 0)))
 (let ((?x4496 (+ 0 ?x3531)))
 (let ((?x4497 (+ ?x4496 ?x3496)))
 (let ((?x4498 (+ ?x4497 ?x3832)))
 (let ((?x4499 (+ ?x4498 ?x4464)))
 (let ((?x4501 (+ ?x4499 ?x4500)))
 (let ((?x4503 (to_real (+ ?x4501 ?x3906))))
 (let ((?x4476 (ite c_53_3 1 0)))
 (let ((?x3845 (ite c_30_3 1 0)))
 (let ((?x3509 (ite c_14_3 1 0)))
 (let ((?x4508 (+ 0 ?x3544)))
 (let ((?x4509 (+ ?x4508 ?x3509)))
 (let ((?x4510 (+ ?x4509 ?x3845)))
 (let ((?x4511 (+ ?x4510 ?x4476)))
 (let ((?x4513 (+ ?x4511 ?x4512)))
 (let (($x4528 (and (and (= (to_real (+ ?x4513 ?x3919)) 1.0) (= ?x4503 2.0)) (= (to_real (+ ?x4524 ?x3931)) 3.0))))
 (let ((?x4451 (ite c_52_1 1 0)))
 (let ((?x3855 (ite c_29_1 1 0)))
 (let ((?x2682 (ite c_13_1 1 0)))
 (let ((?x4483 (+ 0 ?x2684)))
 (let ((?x4484 (+ ?x4483 ?x2682)))
 (let ((?x4485 (+ ?x4484 ?x3855)))
 (let ((?x4486 (+ ?x4485 ?x4451)))
 (let ((?x4488 (+ ?x4486 ?x4487)))
 (let ((?x4426 (ite c_52_2 1 0)))
 (let ((?x3830 (ite c_29_2 1 0)))
 (let ((?x3494 (ite c_13_2 1 0)))
 (let ((?x4460 (+ 0 ?x3496)))
 (let ((?x4461 (+ ?x4460 ?x3494)))
 (let ((?x4462 (+ ?x4461 ?x3830)))
 (let ((?x4463 (+ ?x4462 ?x4426)))
 (let ((?x4465 (+ ?x4463 ?x4464)))
 (let ((?x4467 (to_real (+ ?x4465 ?x3870))))
 (let ((?x4439 (ite c_52_3 1 0)))
 (let ((?x3843 (ite c_29_3 1 0)))
 (let ((?x3507 (ite c_13_3 1 0)))
 (let ((?x4472 (+ 0 ?x3509)))
 (let ((?x4473 (+ ?x4472 ?x3507)))
 (let ((?x4474 (+ ?x4473 ?x3843)))
 (let ((?x4475 (+ ?x4474 ?x4439)))
 (let ((?x4477 (+ ?x4475 ?x4476)))
 (let (($x4492 (and (and (= (to_real (+ ?x4477 ?x3882)) 1.0) (= ?x4467 2.0)) (= (to_real (+ ?x4488 ?x3893)) 3.0))))
 (let ((?x4449 (ite c_51_1 1 0)))
 (let ((?x4411 (ite c_50_1 1 0)))
 (let ((?x3817 (ite c_28_1 1 0)))
 (let ((?x4446 (+ 0 ?x2682)))
 (let ((?x4447 (+ ?x4446 ?x3817)))
 (let ((?x4448 (+ ?x4447 ?x4411)))
 (let ((?x4450 (+ ?x4448 ?x4449)))
 (let ((?x4452 (+ ?x4450 ?x4451)))
 (let ((?x4424 (ite c_51_2 1 0)))
 (let ((?x4388 (ite c_50_2 1 0)))
 (let ((?x3794 (ite c_28_2 1 0)))
 (let ((?x4421 (+ 0 ?x3494)))
 (let ((?x4422 (+ ?x4421 ?x3794)))
 (let ((?x4423 (+ ?x4422 ?x4388)))
 (let ((?x4425 (+ ?x4423 ?x4424)))
 (let ((?x4427 (+ ?x4425 ?x4426)))
 (let ((?x4429 (to_real (+ ?x4427 ?x3832))))
 (let ((?x4437 (ite c_51_3 1 0)))
 (let ((?x4400 (ite c_50_3 1 0)))
 (let ((?x3806 (ite c_28_3 1 0)))
 (let ((?x4434 (+ 0 ?x3507)))
 (let ((?x4435 (+ ?x4434 ?x3806)))
 (let ((?x4436 (+ ?x4435 ?x4400)))
 (let ((?x4438 (+ ?x4436 ?x4437)))
 (let ((?x4440 (+ ?x4438 ?x4439)))
 (let (($x4456 (and (and (= (to_real (+ ?x4440 ?x3845)) 1.0) (= ?x4429 2.0)) (= (to_real (+ ?x4452 ?x3857)) 3.0))))
 (let ((?x4375 (ite c_49_1 1 0)))
 (let ((?x3781 (ite c_27_1 1 0)))
 (let ((?x2680 (ite c_12_1 1 0)))
 (let ((?x4408 (+ 0 ?x2680)))
 (let ((?x4409 (+ ?x4408 ?x3781)))
 (let ((?x4410 (+ ?x4409 ?x4375)))
 (let ((?x4412 (+ ?x4410 ?x4411)))
 (let ((?x4413 (+ ?x4412 ?x3855)))
 (let ((?x4352 (ite c_49_2 1 0)))
 (let ((?x3756 (ite c_27_2 1 0)))
 (let ((?x3458 (ite c_12_2 1 0)))
 (let ((?x4385 (+ 0 ?x3458)))
 (let ((?x4386 (+ ?x4385 ?x3756)))
 (let ((?x4387 (+ ?x4386 ?x4352)))
 (let ((?x4389 (+ ?x4387 ?x4388)))
 (let ((?x4390 (+ ?x4389 ?x3830)))
 (let ((?x4392 (to_real (+ ?x4390 ?x3494))))
 (let ((?x4364 (ite c_49_3 1 0)))
 (let ((?x3769 (ite c_27_3 1 0)))
 (let ((?x3471 (ite c_12_3 1 0)))
 (let ((?x4397 (+ 0 ?x3471)))
 (let ((?x4398 (+ ?x4397 ?x3769)))
 (let ((?x4399 (+ ?x4398 ?x4364)))
 (let ((?x4401 (+ ?x4399 ?x4400)))
 (let ((?x4402 (+ ?x4401 ?x3843)))
 (let (($x4417 (and (and (= (to_real (+ ?x4402 ?x3507)) 1.0) (= ?x4392 2.0)) (= (to_real (+ ?x4413 ?x2682)) 3.0))))
 (let ((?x4339 (ite c_48_1 1 0)))
 (let ((?x3779 (ite c_26_1 1 0)))
 (let ((?x2678 (ite c_11_1 1 0)))
 (let ((?x4372 (+ 0 ?x2678)))
 (let ((?x4373 (+ ?x4372 ?x3779)))
 (let ((?x4374 (+ ?x4373 ?x4339)))
 (let ((?x4376 (+ ?x4374 ?x4375)))
 (let ((?x4377 (+ ?x4376 ?x3817)))
 (let ((?x4314 (ite c_48_2 1 0)))
 (let ((?x3754 (ite c_26_2 1 0)))
 (let ((?x3456 (ite c_11_2 1 0)))
 (let ((?x4349 (+ 0 ?x3456)))
 (let ((?x4350 (+ ?x4349 ?x3754)))
 (let ((?x4351 (+ ?x4350 ?x4314)))
 (let ((?x4353 (+ ?x4351 ?x4352)))
 (let ((?x4354 (+ ?x4353 ?x3794)))
 (let ((?x4356 (to_real (+ ?x4354 ?x3458))))
 (let ((?x4327 (ite c_48_3 1 0)))
 (let ((?x3767 (ite c_26_3 1 0)))
 (let ((?x3469 (ite c_11_3 1 0)))
 (let ((?x4361 (+ 0 ?x3469)))
 (let ((?x4362 (+ ?x4361 ?x3767)))
 (let ((?x4363 (+ ?x4362 ?x4327)))
 (let ((?x4365 (+ ?x4363 ?x4364)))
 (let ((?x4366 (+ ?x4365 ?x3806)))
 (let (($x4381 (and (and (= (to_real (+ ?x4366 ?x3471)) 1.0) (= ?x4356 2.0)) (= (to_real (+ ?x4377 ?x2680)) 3.0))))
 (let ((?x4337 (ite c_47_1 1 0)))
 (let ((?x4299 (ite c_46_1 1 0)))
 (let ((?x3741 (ite c_25_1 1 0)))
 (let ((?x4335 (+ 0 ?x3741)))
 (let ((?x4336 (+ ?x4335 ?x4299)))
 (let ((?x4338 (+ ?x4336 ?x4337)))
 (let ((?x4340 (+ ?x4338 ?x4339)))
 (let ((?x4341 (+ ?x4340 ?x3781)))
 (let ((?x4312 (ite c_47_2 1 0)))
 (let ((?x4276 (ite c_46_2 1 0)))
 (let ((?x3718 (ite c_25_2 1 0)))
 (let ((?x4310 (+ 0 ?x3718)))
 (let ((?x4311 (+ ?x4310 ?x4276)))
 (let ((?x4313 (+ ?x4311 ?x4312)))
 (let ((?x4315 (+ ?x4313 ?x4314)))
 (let ((?x4316 (+ ?x4315 ?x3756)))
 (let ((?x4318 (to_real (+ ?x4316 ?x3456))))
 (let ((?x4325 (ite c_47_3 1 0)))
 (let ((?x4288 (ite c_46_3 1 0)))
 (let ((?x3730 (ite c_25_3 1 0)))
 (let ((?x4323 (+ 0 ?x3730)))
 (let ((?x4324 (+ ?x4323 ?x4288)))
 (let ((?x4326 (+ ?x4324 ?x4325)))
 (let ((?x4328 (+ ?x4326 ?x4327)))
 (let ((?x4329 (+ ?x4328 ?x3769)))
 (let (($x4345 (and (and (= (to_real (+ ?x4329 ?x3469)) 1.0) (= ?x4318 2.0)) (= (to_real (+ ?x4341 ?x2678)) 3.0))))
 (let ((?x2676 (ite c_10_1 1 0)))
 (let ((?x4263 (ite c_45_1 1 0)))
 (let ((?x3705 (ite c_24_1 1 0)))
 (let ((?x4297 (+ 0 ?x3705)))
 (let ((?x4298 (+ ?x4297 ?x4263)))
 (let ((?x4300 (+ ?x4298 ?x4299)))
 (let ((?x4301 (+ ?x4300 ?x3779)))
 (let ((?x4302 (+ ?x4301 ?x2678)))
 (let ((?x3420 (ite c_10_2 1 0)))
 (let ((?x4240 (ite c_45_2 1 0)))
 (let ((?x3680 (ite c_24_2 1 0)))
 (let ((?x4274 (+ 0 ?x3680)))
 (let ((?x4275 (+ ?x4274 ?x4240)))
 (let ((?x4277 (+ ?x4275 ?x4276)))
 (let ((?x4278 (+ ?x4277 ?x3754)))
 (let ((?x4279 (+ ?x4278 ?x3456)))
 (let ((?x4281 (to_real (+ ?x4279 ?x3420))))
 (let ((?x3433 (ite c_10_3 1 0)))
 (let ((?x4252 (ite c_45_3 1 0)))
 (let ((?x3693 (ite c_24_3 1 0)))
 (let ((?x4286 (+ 0 ?x3693)))
 (let ((?x4287 (+ ?x4286 ?x4252)))
 (let ((?x4289 (+ ?x4287 ?x4288)))
 (let ((?x4290 (+ ?x4289 ?x3767)))
 (let ((?x4291 (+ ?x4290 ?x3469)))
 (let (($x4306 (and (and (= (to_real (+ ?x4291 ?x3433)) 1.0) (= ?x4281 2.0)) (= (to_real (+ ?x4302 ?x2676)) 3.0))))
 (let ((?x2674 (ite c_9_1 1 0)))
 (let ((?x4227 (ite c_44_1 1 0)))
 (let ((?x3703 (ite c_23_1 1 0)))
 (let ((?x4261 (+ 0 ?x3703)))
 (let ((?x4262 (+ ?x4261 ?x4227)))
 (let ((?x4264 (+ ?x4262 ?x4263)))
 (let ((?x4265 (+ ?x4264 ?x3741)))
 (let ((?x4266 (+ ?x4265 ?x2676)))
 (let ((?x3418 (ite c_9_2 1 0)))
 (let ((?x4202 (ite c_44_2 1 0)))
 (let ((?x3678 (ite c_23_2 1 0)))
 (let ((?x4238 (+ 0 ?x3678)))
 (let ((?x4239 (+ ?x4238 ?x4202)))
 (let ((?x4241 (+ ?x4239 ?x4240)))
 (let ((?x4242 (+ ?x4241 ?x3718)))
 (let ((?x4243 (+ ?x4242 ?x3420)))
 (let ((?x4245 (to_real (+ ?x4243 ?x3418))))
 (let ((?x3431 (ite c_9_3 1 0)))
 (let ((?x4215 (ite c_44_3 1 0)))
 (let ((?x3691 (ite c_23_3 1 0)))
 (let ((?x4250 (+ 0 ?x3691)))
 (let ((?x4251 (+ ?x4250 ?x4215)))
 (let ((?x4253 (+ ?x4251 ?x4252)))
 (let ((?x4254 (+ ?x4253 ?x3730)))
 (let ((?x4255 (+ ?x4254 ?x3433)))
 (let (($x4270 (and (and (= (to_real (+ ?x4255 ?x3431)) 1.0) (= ?x4245 2.0)) (= (to_real (+ ?x4266 ?x2674)) 3.0))))
 (let ((?x3665 (ite c_22_1 1 0)))
 (let ((?x4225 (ite c_43_1 1 0)))
 (let ((?x4187 (ite c_42_1 1 0)))
 (let ((?x4224 (+ 0 ?x4187)))
 (let ((?x4226 (+ ?x4224 ?x4225)))
 (let ((?x4228 (+ ?x4226 ?x4227)))
 (let ((?x4229 (+ ?x4228 ?x3705)))
 (let ((?x4230 (+ ?x4229 ?x2674)))
 (let ((?x3642 (ite c_22_2 1 0)))
 (let ((?x4200 (ite c_43_2 1 0)))
 (let ((?x4164 (ite c_42_2 1 0)))
 (let ((?x4199 (+ 0 ?x4164)))
 (let ((?x4201 (+ ?x4199 ?x4200)))
 (let ((?x4203 (+ ?x4201 ?x4202)))
 (let ((?x4204 (+ ?x4203 ?x3680)))
 (let ((?x4205 (+ ?x4204 ?x3418)))
 (let ((?x4207 (to_real (+ ?x4205 ?x3642))))
 (let ((?x3654 (ite c_22_3 1 0)))
 (let ((?x4213 (ite c_43_3 1 0)))
 (let ((?x4176 (ite c_42_3 1 0)))
 (let ((?x4212 (+ 0 ?x4176)))
 (let ((?x4214 (+ ?x4212 ?x4213)))
 (let ((?x4216 (+ ?x4214 ?x4215)))
 (let ((?x4217 (+ ?x4216 ?x3693)))
 (let ((?x4218 (+ ?x4217 ?x3431)))
 (let (($x4234 (and (and (= (to_real (+ ?x4218 ?x3654)) 1.0) (= ?x4207 2.0)) (= (to_real (+ ?x4230 ?x3665)) 3.0))))
 (let ((?x3628 (ite c_20_1 1 0)))
 (let ((?x2672 (ite c_8_1 1 0)))
 (let ((?x4115 (ite c_40_1 1 0)))
 (let ((?x4186 (+ 0 ?x4115)))
 (let ((?x4188 (+ ?x4186 ?x4187)))
 (let ((?x4189 (+ ?x4188 ?x3703)))
 (let ((?x4190 (+ ?x4189 ?x2674)))
 (let ((?x4191 (+ ?x4190 ?x2672)))
 (let ((?x3601 (ite c_20_2 1 0)))
 (let ((?x3378 (ite c_8_2 1 0)))
 (let ((?x4092 (ite c_40_2 1 0)))
 (let ((?x4163 (+ 0 ?x4092)))
 (let ((?x4165 (+ ?x4163 ?x4164)))
 (let ((?x4166 (+ ?x4165 ?x3678)))
 (let ((?x4167 (+ ?x4166 ?x3418)))
 (let ((?x4168 (+ ?x4167 ?x3378)))
 (let ((?x4170 (to_real (+ ?x4168 ?x3601))))
 (let ((?x3615 (ite c_20_3 1 0)))
 (let ((?x3393 (ite c_8_3 1 0)))
 (let ((?x4104 (ite c_40_3 1 0)))
 (let ((?x4175 (+ 0 ?x4104)))
 (let ((?x4177 (+ ?x4175 ?x4176)))
 (let ((?x4178 (+ ?x4177 ?x3691)))
 (let ((?x4179 (+ ?x4178 ?x3431)))
 (let ((?x4180 (+ ?x4179 ?x3393)))
 (let (($x4195 (and (and (= (to_real (+ ?x4180 ?x3615)) 1.0) (= ?x4170 2.0)) (= (to_real (+ ?x4191 ?x3628)) 3.0))))
 (let ((?x2670 (ite c_7_1 1 0)))
 (let ((?x3626 (ite c_19_1 1 0)))
 (let ((?x4083 (ite c_39_1 1 0)))
 (let ((?x4150 (+ 0 ?x4083)))
 (let ((?x4151 (+ ?x4150 ?x3626)))
 (let ((?x4152 (+ ?x4151 ?x2670)))
 (let ((?x4153 (+ ?x4152 ?x2692)))
 (let ((?x4154 (+ ?x4153 ?x4002)))
 (let ((?x3376 (ite c_7_2 1 0)))
 (let ((?x3599 (ite c_19_2 1 0)))
 (let ((?x4056 (ite c_39_2 1 0)))
 (let ((?x4127 (+ 0 ?x4056)))
 (let ((?x4128 (+ ?x4127 ?x3599)))
 (let ((?x4129 (+ ?x4128 ?x3376)))
 (let ((?x4130 (+ ?x4129 ?x3384)))
 (let ((?x4131 (+ ?x4130 ?x3977)))
 (let ((?x4134 (to_real (+ ?x4131 ?x4132))))
 (let ((?x3391 (ite c_7_3 1 0)))
 (let ((?x3613 (ite c_19_3 1 0)))
 (let ((?x4070 (ite c_39_3 1 0)))
 (let ((?x4139 (+ 0 ?x4070)))
 (let ((?x4140 (+ ?x4139 ?x3613)))
 (let ((?x4141 (+ ?x4140 ?x3391)))
 (let ((?x4142 (+ ?x4141 ?x3399)))
 (let ((?x4143 (+ ?x4142 ?x3990)))
 (let (($x4159 (and (and (= (to_real (+ ?x4143 ?x4144)) 1.0) (= ?x4134 2.0)) (= (to_real (+ ?x4154 ?x4155)) 3.0))))
 (let ((?x4078 (ite c_38_1 1 0)))
 (let ((?x4114 (+ 0 ?x4078)))
 (let ((?x4116 (+ ?x4114 ?x4115)))
 (let ((?x4117 (+ ?x4116 ?x3665)))
 (let ((?x4118 (+ ?x4117 ?x2672)))
 (let ((?x4119 (+ ?x4118 ?x2670)))
 (let ((?x4051 (ite c_38_2 1 0)))
 (let ((?x4091 (+ 0 ?x4051)))
 (let ((?x4093 (+ ?x4091 ?x4092)))
 (let ((?x4094 (+ ?x4093 ?x3642)))
 (let ((?x4095 (+ ?x4094 ?x3378)))
 (let ((?x4096 (+ ?x4095 ?x3376)))
 (let ((?x4098 (to_real (+ ?x4096 ?x3599))))
 (let ((?x4065 (ite c_38_3 1 0)))
 (let ((?x4103 (+ 0 ?x4065)))
 (let ((?x4105 (+ ?x4103 ?x4104)))
 (let ((?x4106 (+ ?x4105 ?x3654)))
 (let ((?x4107 (+ ?x4106 ?x3393)))
 (let ((?x4108 (+ ?x4107 ?x3391)))
 (let (($x4123 (and (and (= (to_real (+ ?x4108 ?x3613)) 1.0) (= ?x4098 2.0)) (= (to_real (+ ?x4119 ?x3626)) 3.0))))
 (let ((?x4076 (ite c_37_1 1 0)))
 (let ((?x4077 (+ 0 ?x4076)))
 (let ((?x4079 (+ ?x4077 ?x4078)))
 (let ((?x4080 (+ ?x4079 ?x3628)))
 (let ((?x4081 (+ ?x4080 ?x2670)))
 (let ((?x4082 (+ ?x4081 ?x3633)))
 (let ((?x4049 (ite c_37_2 1 0)))
 (let ((?x4050 (+ 0 ?x4049)))
 (let ((?x4052 (+ ?x4050 ?x4051)))
 (let ((?x4053 (+ ?x4052 ?x3601)))
 (let ((?x4054 (+ ?x4053 ?x3376)))
 (let ((?x4055 (+ ?x4054 ?x3606)))
 (let ((?x4058 (to_real (+ ?x4055 ?x4056))))
 (let ((?x4063 (ite c_37_3 1 0)))
 (let ((?x4064 (+ 0 ?x4063)))
 (let ((?x4066 (+ ?x4064 ?x4065)))
 (let ((?x4067 (+ ?x4066 ?x3615)))
 (let ((?x4068 (+ ?x4067 ?x3391)))
 (let ((?x4069 (+ ?x4068 ?x3620)))
 (let (($x4087 (and (and (= (to_real (+ ?x4069 ?x4070)) 1.0) (= ?x4058 2.0)) (= (to_real (+ ?x4082 ?x4083)) 3.0))))
 (let ((?x2668 (ite c_6_1 1 0)))
 (let ((?x2658 (ite c_1_1 1 0)))
 (let ((?x4037 (+ 0 ?x3633)))
 (let ((?x4038 (+ ?x4037 ?x2670)))
 (let ((?x4039 (+ ?x4038 ?x2658)))
 (let ((?x4040 (+ ?x4039 ?x2668)))
 (let ((?x4041 (+ ?x4040 ?x2690)))
 (let ((?x3338 (ite c_6_2 1 0)))
 (let ((?x3328 (ite c_1_2 1 0)))
 (let ((?x4016 (+ 0 ?x3606)))
 (let ((?x4017 (+ ?x4016 ?x3376)))
 (let ((?x4018 (+ ?x4017 ?x3328)))
 (let ((?x4019 (+ ?x4018 ?x3338)))
 (let ((?x4020 (+ ?x4019 ?x3569)))
 (let ((?x4022 (to_real (+ ?x4020 ?x3977))))
 (let ((?x3356 (ite c_6_3 1 0)))
 (let ((?x3346 (ite c_1_3 1 0)))
 (let ((?x4027 (+ 0 ?x3620)))
 (let ((?x4028 (+ ?x4027 ?x3391)))
 (let ((?x4029 (+ ?x4028 ?x3346)))
 (let ((?x4030 (+ ?x4029 ?x3356)))
 (let ((?x4031 (+ ?x4030 ?x3581)))
 (let (($x4045 (and (and (= (to_real (+ ?x4031 ?x3990)) 1.0) (= ?x4022 2.0)) (= (to_real (+ ?x4041 ?x4002)) 3.0))))
 (let ((?x4010 (to_real (+ (+ (+ (+ (+ (+ 0 ?x4002) ?x2692) ?x2668) ?x2688) ?x3969) ?x4008))))
 (let ((?x3985 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3977) ?x3384) ?x3338) ?x3533) ?x3946) ?x3983))))
 (let ((?x3998 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3990) ?x3399) ?x3356) ?x3546) ?x3958) ?x3996))))
 (let (($x4013 (and c_17_2 (and (and (= ?x3998 1.0) (= ?x3985 2.0)) (= ?x4010 3.0)))))
 (let ((?x2666 (ite c_5_1 1 0)))
 (let ((?x3964 (+ 0 ?x2690)))
 (let ((?x3965 (+ ?x3964 ?x2668)))
 (let ((?x3966 (+ ?x3965 ?x2666)))
 (let ((?x3967 (+ ?x3966 ?x2686)))
 (let ((?x3968 (+ ?x3967 ?x3933)))
 (let ((?x3336 (ite c_5_2 1 0)))
 (let ((?x3941 (+ 0 ?x3569)))
 (let ((?x3942 (+ ?x3941 ?x3338)))
 (let ((?x3943 (+ ?x3942 ?x3336)))
 (let ((?x3944 (+ ?x3943 ?x3531)))
 (let ((?x3945 (+ ?x3944 ?x3908)))
 (let ((?x3948 (to_real (+ ?x3945 ?x3946))))
 (let ((?x3354 (ite c_5_3 1 0)))
 (let ((?x3953 (+ 0 ?x3581)))
 (let ((?x3954 (+ ?x3953 ?x3356)))
 (let ((?x3955 (+ ?x3954 ?x3354)))
 (let ((?x3956 (+ ?x3955 ?x3544)))
 (let ((?x3957 (+ ?x3956 ?x3921)))
 (let (($x3973 (and (and (= (to_real (+ ?x3957 ?x3958)) 1.0) (= ?x3948 2.0)) (= (to_real (+ ?x3968 ?x3969)) 3.0))))
 (let ((?x3935 (to_real (+ (+ (+ (+ (+ (+ 0 ?x2688) ?x2666) ?x2684) ?x3893) ?x3931) ?x3933))))
 (let ((?x3910 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3533) ?x3336) ?x3496) ?x3870) ?x3906) ?x3908))))
 (let ((?x3923 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3546) ?x3354) ?x3509) ?x3882) ?x3919) ?x3921))))
 (let (($x3938 (and c_15_2 (and (and (= ?x3923 1.0) (= ?x3910 2.0)) (= ?x3935 3.0)))))
 (let ((?x2664 (ite c_4_1 1 0)))
 (let ((?x3889 (+ 0 ?x2666)))
 (let ((?x3890 (+ ?x3889 ?x2664)))
 (let ((?x3891 (+ ?x3890 ?x2682)))
 (let ((?x3892 (+ ?x3891 ?x3857)))
 (let ((?x3894 (+ ?x3892 ?x3893)))
 (let ((?x3334 (ite c_4_2 1 0)))
 (let ((?x3866 (+ 0 ?x3336)))
 (let ((?x3867 (+ ?x3866 ?x3334)))
 (let ((?x3868 (+ ?x3867 ?x3494)))
 (let ((?x3869 (+ ?x3868 ?x3832)))
 (let ((?x3871 (+ ?x3869 ?x3870)))
 (let ((?x3873 (to_real (+ ?x3871 ?x3531))))
 (let ((?x3352 (ite c_4_3 1 0)))
 (let ((?x3878 (+ 0 ?x3354)))
 (let ((?x3879 (+ ?x3878 ?x3352)))
 (let ((?x3880 (+ ?x3879 ?x3507)))
 (let ((?x3881 (+ ?x3880 ?x3845)))
 (let ((?x3883 (+ ?x3881 ?x3882)))
 (let (($x3898 (and (and (= (to_real (+ ?x3883 ?x3544)) 1.0) (= ?x3873 2.0)) (= (to_real (+ ?x3894 ?x2686)) 3.0))))
 (let ((?x3860 (to_real (+ (+ (+ (+ (+ (+ 0 ?x2664) ?x2680) ?x3817) ?x3855) ?x3857) ?x2684))))
 (let ((?x3835 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3334) ?x3458) ?x3794) ?x3830) ?x3832) ?x3496))))
 (let ((?x3848 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3352) ?x3471) ?x3806) ?x3843) ?x3845) ?x3509))))
 (let (($x3863 (and c_13_2 (and (and (= ?x3848 1.0) (= ?x3835 2.0)) (= ?x3860 3.0)))))
 (let ((?x2662 (ite c_3_1 1 0)))
 (let ((?x3814 (+ 0 ?x2662)))
 (let ((?x3815 (+ ?x3814 ?x2678)))
 (let ((?x3816 (+ ?x3815 ?x3781)))
 (let ((?x3818 (+ ?x3816 ?x3817)))
 (let ((?x3819 (+ ?x3818 ?x2682)))
 (let ((?x3332 (ite c_3_2 1 0)))
 (let ((?x3791 (+ 0 ?x3332)))
 (let ((?x3792 (+ ?x3791 ?x3456)))
 (let ((?x3793 (+ ?x3792 ?x3756)))
 (let ((?x3795 (+ ?x3793 ?x3794)))
 (let ((?x3796 (+ ?x3795 ?x3494)))
 (let ((?x3798 (to_real (+ ?x3796 ?x3334))))
 (let ((?x3350 (ite c_3_3 1 0)))
 (let ((?x3803 (+ 0 ?x3350)))
 (let ((?x3804 (+ ?x3803 ?x3469)))
 (let ((?x3805 (+ ?x3804 ?x3769)))
 (let ((?x3807 (+ ?x3805 ?x3806)))
 (let ((?x3808 (+ ?x3807 ?x3507)))
 (let (($x3823 (and (and (= (to_real (+ ?x3808 ?x3352)) 1.0) (= ?x3798 2.0)) (= (to_real (+ ?x3819 ?x2664)) 3.0))))
 (let ((?x3785 (to_real (+ (+ (+ (+ (+ (+ 0 ?x2676) ?x3741) ?x3779) ?x3781) ?x2680) ?x2662))))
 (let ((?x3760 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3420) ?x3718) ?x3754) ?x3756) ?x3458) ?x3332))))
 (let ((?x3773 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3433) ?x3730) ?x3767) ?x3769) ?x3471) ?x3350))))
 (let (($x3788 (and c_11_2 (and (and (= ?x3773 1.0) (= ?x3760 2.0)) (= ?x3785 3.0)))))
 (let ((?x2660 (ite c_2_1 1 0)))
 (let ((?x3739 (+ 0 ?x2674)))
 (let ((?x3740 (+ ?x3739 ?x3705)))
 (let ((?x3742 (+ ?x3740 ?x3741)))
 (let ((?x3743 (+ ?x3742 ?x2678)))
 (let ((?x3744 (+ ?x3743 ?x2662)))
 (let ((?x3330 (ite c_2_2 1 0)))
 (let ((?x3716 (+ 0 ?x3418)))
 (let ((?x3717 (+ ?x3716 ?x3680)))
 (let ((?x3719 (+ ?x3717 ?x3718)))
 (let ((?x3720 (+ ?x3719 ?x3456)))
 (let ((?x3721 (+ ?x3720 ?x3332)))
 (let ((?x3723 (to_real (+ ?x3721 ?x3330))))
 (let ((?x3348 (ite c_2_3 1 0)))
 (let ((?x3728 (+ 0 ?x3431)))
 (let ((?x3729 (+ ?x3728 ?x3693)))
 (let ((?x3731 (+ ?x3729 ?x3730)))
 (let ((?x3732 (+ ?x3731 ?x3469)))
 (let ((?x3733 (+ ?x3732 ?x3350)))
 (let (($x3748 (and (and (= (to_real (+ ?x3733 ?x3348)) 1.0) (= ?x3723 2.0)) (= (to_real (+ ?x3744 ?x2660)) 3.0))))
 (let ((?x3710 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3665) ?x3703) ?x3705) ?x2676) ?x2660) ?x2672))))
 (let ((?x3685 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3642) ?x3678) ?x3680) ?x3420) ?x3330) ?x3378))))
 (let ((?x3698 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3654) ?x3691) ?x3693) ?x3433) ?x3348) ?x3393))))
 (let (($x3713 (and c_9_2 (and (and (= ?x3698 1.0) (= ?x3685 2.0)) (= ?x3710 3.0)))))
 (let ((?x3671 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3628) ?x3665) ?x2674) ?x2660) ?x2658) ?x2670))))
 (let ((?x3648 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3601) ?x3642) ?x3418) ?x3330) ?x3328) ?x3376))))
 (let ((?x3660 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3615) ?x3654) ?x3431) ?x3348) ?x3346) ?x3391))))
 (let (($x3674 (and c_8_2 (and (and (= ?x3660 1.0) (= ?x3648 2.0)) (= ?x3671 3.0)))))
 (let ((?x3635 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3626) ?x3628) ?x2672) ?x2658) ?x2692) ?x3633))))
 (let ((?x3608 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3599) ?x3601) ?x3378) ?x3328) ?x3384) ?x3606))))
 (let ((?x3622 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3613) ?x3615) ?x3393) ?x3346) ?x3399) ?x3620))))
 (let (($x3638 (and c_7_2 (and (and (= ?x3622 1.0) (= ?x3608 2.0)) (= ?x3635 3.0)))))
 (let ((?x2656 (ite c_0_1 1 0)))
 (let ((?x3587 (+ 0 ?x2692)))
 (let ((?x3588 (+ ?x3587 ?x2658)))
 (let ((?x3589 (+ ?x3588 ?x2656)))
 (let ((?x3590 (+ ?x3589 ?x2666)))
 (let ((?x3591 (+ ?x3590 ?x2688)))
 (let ((?x3381 (ite c_0_2 1 0)))
 (let ((?x3564 (+ 0 ?x3384)))
 (let ((?x3565 (+ ?x3564 ?x3328)))
 (let ((?x3566 (+ ?x3565 ?x3381)))
 (let ((?x3567 (+ ?x3566 ?x3336)))
 (let ((?x3568 (+ ?x3567 ?x3533)))
 (let ((?x3571 (to_real (+ ?x3568 ?x3569))))
 (let ((?x3396 (ite c_0_3 1 0)))
 (let ((?x3576 (+ 0 ?x3399)))
 (let ((?x3577 (+ ?x3576 ?x3346)))
 (let ((?x3578 (+ ?x3577 ?x3396)))
 (let ((?x3579 (+ ?x3578 ?x3354)))
 (let ((?x3580 (+ ?x3579 ?x3546)))
 (let (($x3595 (and (and (= (to_real (+ ?x3580 ?x3581)) 1.0) (= ?x3571 2.0)) (= (to_real (+ ?x3591 ?x2690)) 3.0))))
 (let ((?x3558 (to_real (+ (+ (+ (+ (+ (+ 0 ?x2668) ?x2656) ?x2664) ?x2684) ?x2686) ?x2688))))
 (let ((?x3535 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3338) ?x3381) ?x3334) ?x3496) ?x3531) ?x3533))))
 (let ((?x3548 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3356) ?x3396) ?x3352) ?x3509) ?x3544) ?x3546))))
 (let (($x3561 (and c_5_2 (and (and (= ?x3548 1.0) (= ?x3535 2.0)) (= ?x3558 3.0)))))
 (let ((?x3521 (to_real (+ (+ (+ (+ (+ (+ 0 ?x2656) ?x2662) ?x2680) ?x2682) ?x2684) ?x2666))))
 (let ((?x3499 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3381) ?x3332) ?x3458) ?x3494) ?x3496) ?x3336))))
 (let ((?x3512 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3396) ?x3350) ?x3471) ?x3507) ?x3509) ?x3354))))
 (let (($x3524 (and c_4_2 (and (and (= ?x3512 1.0) (= ?x3499 2.0)) (= ?x3521 3.0)))))
 (let ((?x3485 (to_real (+ (+ (+ (+ (+ (+ 0 ?x2660) ?x2676) ?x2678) ?x2680) ?x2664) ?x2656))))
 (let ((?x3462 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3330) ?x3420) ?x3456) ?x3458) ?x3334) ?x3381))))
 (let ((?x3475 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3348) ?x3433) ?x3469) ?x3471) ?x3352) ?x3396))))
 (let (($x3488 (and c_3_2 (and (and (= ?x3475 1.0) (= ?x3462 2.0)) (= ?x3485 3.0)))))
 (let ((?x3448 (to_real (+ (+ (+ (+ (+ (+ 0 ?x2672) ?x2674) ?x2676) ?x2662) ?x2656) ?x2658))))
 (let ((?x3425 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3378) ?x3418) ?x3420) ?x3332) ?x3381) ?x3328))))
 (let ((?x3438 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3393) ?x3431) ?x3433) ?x3350) ?x3396) ?x3346))))
 (let (($x3451 (and c_2_2 (and (and (= ?x3438 1.0) (= ?x3425 2.0)) (= ?x3448 3.0)))))
 (let ((?x3411 (to_real (+ (+ (+ (+ (+ (+ 0 ?x2670) ?x2672) ?x2660) ?x2656) ?x2668) ?x2692))))
 (let ((?x3386 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3376) ?x3378) ?x3330) ?x3381) ?x3338) ?x3384))))
 (let ((?x3401 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3391) ?x3393) ?x3348) ?x3396) ?x3356) ?x3399))))
 (let (($x3414 (and c_1_2 (and (and (= ?x3401 1.0) (= ?x3386 2.0)) (= ?x3411 3.0)))))
 (let ((?x3370 (to_real (+ (+ (+ (+ (+ (+ 0 ?x2658) ?x2660) ?x2662) ?x2664) ?x2666) ?x2668))))
 (let ((?x3340 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3328) ?x3330) ?x3332) ?x3334) ?x3336) ?x3338))))
 (let ((?x3358 (to_real (+ (+ (+ (+ (+ (+ 0 ?x3346) ?x3348) ?x3350) ?x3352) ?x3354) ?x3356))))
 (let (($x3373 (and c_0_2 (and (and (= ?x3358 1.0) (= ?x3340 2.0)) (= ?x3370 3.0)))))
 (let (($x3324 (= c_60_3 d_60_3)))
 (let (($x3322 (= c_60_2 d_60_2)))
 (let (($x3320 (= c_60_1 d_60_1)))
 (let (($x3318 (= c_60_0 d_60_0)))
 (let (($x3319 (and true $x3318)))
 (let (($x3321 (and $x3319 $x3320)))
 (let (($x3323 (and $x3321 $x3322)))
 (let (($x3315 (= c_59_3 d_59_3)))
 (let (($x3313 (= c_59_2 d_59_2)))
 (let (($x3311 (= c_59_1 d_59_1)))
 (let (($x3309 (= c_59_0 d_59_0)))
 (let (($x3310 (and true $x3309)))
 (let (($x3312 (and $x3310 $x3311)))
 (let (($x3314 (and $x3312 $x3313)))
 (let (($x3306 (= c_58_3 d_58_3)))
 (let (($x3304 (= c_58_2 d_58_2)))
 (let (($x3302 (= c_58_1 d_58_1)))
 (let (($x3300 (= c_58_0 d_58_0)))
 (let (($x3301 (and true $x3300)))
 (let (($x3303 (and $x3301 $x3302)))
 (let (($x3305 (and $x3303 $x3304)))
 (let (($x3297 (= c_57_3 d_57_3)))
 (let (($x3295 (= c_57_2 d_57_2)))
 (let (($x3293 (= c_57_1 d_57_1)))
 (let (($x3291 (= c_57_0 d_57_0)))
 (let (($x3292 (and true $x3291)))
 (let (($x3294 (and $x3292 $x3293)))
 (let (($x3296 (and $x3294 $x3295)))
 (let (($x3288 (= c_56_3 d_56_3)))
 (let (($x3286 (= c_56_2 d_56_2)))
 (let (($x3284 (= c_56_1 d_56_1)))
 (let (($x3282 (= c_56_0 d_56_0)))
 (let (($x3283 (and true $x3282)))
 (let (($x3285 (and $x3283 $x3284)))
 (let (($x3287 (and $x3285 $x3286)))
 (let (($x3279 (= c_55_3 d_55_3)))
 (let (($x3277 (= c_55_2 d_55_2)))
 (let (($x3275 (= c_55_1 d_55_1)))
 (let (($x3273 (= c_55_0 d_55_0)))
 (let (($x3274 (and true $x3273)))
 (let (($x3276 (and $x3274 $x3275)))
 (let (($x3278 (and $x3276 $x3277)))
 (let (($x3270 (= c_54_3 d_54_3)))
 (let (($x3268 (= c_54_2 d_54_2)))
 (let (($x3266 (= c_54_1 d_54_1)))
 (let (($x3264 (= c_54_0 d_54_0)))
 (let (($x3265 (and true $x3264)))
 (let (($x3267 (and $x3265 $x3266)))
 (let (($x3269 (and $x3267 $x3268)))
 (let (($x3261 (= c_53_3 d_53_3)))
 (let (($x3259 (= c_53_2 d_53_2)))
 (let (($x3257 (= c_53_1 d_53_1)))
 (let (($x3255 (= c_53_0 d_53_0)))
 (let (($x3256 (and true $x3255)))
 (let (($x3258 (and $x3256 $x3257)))
 (let (($x3260 (and $x3258 $x3259)))
 (let (($x3252 (= c_52_3 d_52_3)))
 (let (($x3250 (= c_52_2 d_52_2)))
 (let (($x3248 (= c_52_1 d_52_1)))
 (let (($x3246 (= c_52_0 d_52_0)))
 (let (($x3247 (and true $x3246)))
 (let (($x3249 (and $x3247 $x3248)))
 (let (($x3251 (and $x3249 $x3250)))
 (let (($x3243 (= c_51_3 d_51_3)))
 (let (($x3241 (= c_51_2 d_51_2)))
 (let (($x3239 (= c_51_1 d_51_1)))
 (let (($x3237 (= c_51_0 d_51_0)))
 (let (($x3238 (and true $x3237)))
 (let (($x3240 (and $x3238 $x3239)))
 (let (($x3242 (and $x3240 $x3241)))
 (let (($x3234 (= c_50_3 d_50_3)))
 (let (($x3232 (= c_50_2 d_50_2)))
 (let (($x3230 (= c_50_1 d_50_1)))
 (let (($x3228 (= c_50_0 d_50_0)))
 (let (($x3229 (and true $x3228)))
 (let (($x3231 (and $x3229 $x3230)))
 (let (($x3233 (and $x3231 $x3232)))
 (let (($x3225 (= c_49_3 d_49_3)))
 (let (($x3223 (= c_49_2 d_49_2)))
 (let (($x3221 (= c_49_1 d_49_1)))
 (let (($x3219 (= c_49_0 d_49_0)))
 (let (($x3220 (and true $x3219)))
 (let (($x3222 (and $x3220 $x3221)))
 (let (($x3224 (and $x3222 $x3223)))
 (let (($x3216 (= c_48_3 d_48_3)))
 (let (($x3214 (= c_48_2 d_48_2)))
 (let (($x3212 (= c_48_1 d_48_1)))
 (let (($x3210 (= c_48_0 d_48_0)))
 (let (($x3211 (and true $x3210)))
 (let (($x3213 (and $x3211 $x3212)))
 (let (($x3215 (and $x3213 $x3214)))
 (let (($x3207 (= c_47_3 d_47_3)))
 (let (($x3205 (= c_47_2 d_47_2)))
 (let (($x3203 (= c_47_1 d_47_1)))
 (let (($x3201 (= c_47_0 d_47_0)))
 (let (($x3202 (and true $x3201)))
 (let (($x3204 (and $x3202 $x3203)))
 (let (($x3206 (and $x3204 $x3205)))
 (let (($x3198 (= c_46_3 d_46_3)))
 (let (($x3196 (= c_46_2 d_46_2)))
 (let (($x3194 (= c_46_1 d_46_1)))
 (let (($x3192 (= c_46_0 d_46_0)))
 (let (($x3193 (and true $x3192)))
 (let (($x3195 (and $x3193 $x3194)))
 (let (($x3197 (and $x3195 $x3196)))
 (let (($x3189 (= c_45_3 d_45_3)))
 (let (($x3187 (= c_45_2 d_45_2)))
 (let (($x3185 (= c_45_1 d_45_1)))
 (let (($x3183 (= c_45_0 d_45_0)))
 (let (($x3184 (and true $x3183)))
 (let (($x3186 (and $x3184 $x3185)))
 (let (($x3188 (and $x3186 $x3187)))
 (let (($x3180 (= c_44_3 d_44_3)))
 (let (($x3178 (= c_44_2 d_44_2)))
 (let (($x3176 (= c_44_1 d_44_1)))
 (let (($x3174 (= c_44_0 d_44_0)))
 (let (($x3175 (and true $x3174)))
 (let (($x3177 (and $x3175 $x3176)))
 (let (($x3179 (and $x3177 $x3178)))
 (let (($x3171 (= c_43_3 d_43_3)))
 (let (($x3169 (= c_43_2 d_43_2)))
 (let (($x3167 (= c_43_1 d_43_1)))
 (let (($x3165 (= c_43_0 d_43_0)))
 (let (($x3166 (and true $x3165)))
 (let (($x3168 (and $x3166 $x3167)))
 (let (($x3170 (and $x3168 $x3169)))
 (let (($x3162 (= c_42_3 d_42_3)))
 (let (($x3160 (= c_42_2 d_42_2)))
 (let (($x3158 (= c_42_1 d_42_1)))
 (let (($x3156 (= c_42_0 d_42_0)))
 (let (($x3157 (and true $x3156)))
 (let (($x3159 (and $x3157 $x3158)))
 (let (($x3161 (and $x3159 $x3160)))
 (let (($x3153 (= c_41_3 d_41_3)))
 (let (($x3151 (= c_41_2 d_41_2)))
 (let (($x3149 (= c_41_1 d_41_1)))
 (let (($x3147 (= c_41_0 d_41_0)))
 (let (($x3148 (and true $x3147)))
 (let (($x3150 (and $x3148 $x3149)))
 (let (($x3152 (and $x3150 $x3151)))
 (let (($x3144 (= c_40_3 d_40_3)))
 (let (($x3142 (= c_40_2 d_40_2)))
 (let (($x3140 (= c_40_1 d_40_1)))
 (let (($x3138 (= c_40_0 d_40_0)))
 (let (($x3139 (and true $x3138)))
 (let (($x3141 (and $x3139 $x3140)))
 (let (($x3143 (and $x3141 $x3142)))
 (let (($x3135 (= c_39_3 d_39_3)))
 (let (($x3133 (= c_39_2 d_39_2)))
 (let (($x3131 (= c_39_1 d_39_1)))
 (let (($x3129 (= c_39_0 d_39_0)))
 (let (($x3130 (and true $x3129)))
 (let (($x3132 (and $x3130 $x3131)))
 (let (($x3134 (and $x3132 $x3133)))
 (let (($x3126 (= c_38_3 d_38_3)))
 (let (($x3124 (= c_38_2 d_38_2)))
 (let (($x3122 (= c_38_1 d_38_1)))
 (let (($x3120 (= c_38_0 d_38_0)))
 (let (($x3121 (and true $x3120)))
 (let (($x3123 (and $x3121 $x3122)))
 (let (($x3125 (and $x3123 $x3124)))
 (let (($x3117 (= c_37_3 d_37_3)))
 (let (($x3115 (= c_37_2 d_37_2)))
 (let (($x3113 (= c_37_1 d_37_1)))
 (let (($x3111 (= c_37_0 d_37_0)))
 (let (($x3112 (and true $x3111)))
 (let (($x3114 (and $x3112 $x3113)))
 (let (($x3116 (and $x3114 $x3115)))
 (let (($x3108 (= c_36_3 d_36_3)))
 (let (($x3106 (= c_36_2 d_36_2)))
 (let (($x3104 (= c_36_1 d_36_1)))
 (let (($x3102 (= c_36_0 d_36_0)))
 (let (($x3103 (and true $x3102)))
 (let (($x3105 (and $x3103 $x3104)))
 (let (($x3107 (and $x3105 $x3106)))
 (let (($x3099 (= c_35_3 d_35_3)))
 (let (($x3097 (= c_35_2 d_35_2)))
 (let (($x3095 (= c_35_1 d_35_1)))
 (let (($x3093 (= c_35_0 d_35_0)))
 (let (($x3094 (and true $x3093)))
 (let (($x3096 (and $x3094 $x3095)))
 (let (($x3098 (and $x3096 $x3097)))
 (let (($x3090 (= c_34_3 d_34_3)))
 (let (($x3088 (= c_34_2 d_34_2)))
 (let (($x3086 (= c_34_1 d_34_1)))
 (let (($x3084 (= c_34_0 d_34_0)))
 (let (($x3085 (and true $x3084)))
 (let (($x3087 (and $x3085 $x3086)))
 (let (($x3089 (and $x3087 $x3088)))
 (let (($x3081 (= c_33_3 d_33_3)))
 (let (($x3079 (= c_33_2 d_33_2)))
 (let (($x3077 (= c_33_1 d_33_1)))
 (let (($x3075 (= c_33_0 d_33_0)))
 (let (($x3076 (and true $x3075)))
 (let (($x3078 (and $x3076 $x3077)))
 (let (($x3080 (and $x3078 $x3079)))
 (let (($x3072 (= c_32_3 d_32_3)))
 (let (($x3070 (= c_32_2 d_32_2)))
 (let (($x3068 (= c_32_1 d_32_1)))
 (let (($x3066 (= c_32_0 d_32_0)))
 (let (($x3067 (and true $x3066)))
 (let (($x3069 (and $x3067 $x3068)))
 (let (($x3071 (and $x3069 $x3070)))
 (let (($x3063 (= c_31_3 d_31_3)))
 (let (($x3061 (= c_31_2 d_31_2)))
 (let (($x3059 (= c_31_1 d_31_1)))
 (let (($x3057 (= c_31_0 d_31_0)))
 (let (($x3058 (and true $x3057)))
 (let (($x3060 (and $x3058 $x3059)))
 (let (($x3062 (and $x3060 $x3061)))
 (let (($x3054 (= c_30_3 d_30_3)))
 (let (($x3052 (= c_30_2 d_30_2)))
 (let (($x3050 (= c_30_1 d_30_1)))
 (let (($x3048 (= c_30_0 d_30_0)))
 (let (($x3049 (and true $x3048)))
 (let (($x3051 (and $x3049 $x3050)))
 (let (($x3053 (and $x3051 $x3052)))
 (let (($x3045 (= c_29_3 d_29_3)))
 (let (($x3043 (= c_29_2 d_29_2)))
 (let (($x3041 (= c_29_1 d_29_1)))
 (let (($x3039 (= c_29_0 d_29_0)))
 (let (($x3040 (and true $x3039)))
 (let (($x3042 (and $x3040 $x3041)))
 (let (($x3044 (and $x3042 $x3043)))
 (let (($x3036 (= c_28_3 d_28_3)))
 (let (($x3034 (= c_28_2 d_28_2)))
 (let (($x3032 (= c_28_1 d_28_1)))
 (let (($x3030 (= c_28_0 d_28_0)))
 (let (($x3031 (and true $x3030)))
 (let (($x3033 (and $x3031 $x3032)))
 (let (($x3035 (and $x3033 $x3034)))
 (let (($x3027 (= c_27_3 d_27_3)))
 (let (($x3025 (= c_27_2 d_27_2)))
 (let (($x3023 (= c_27_1 d_27_1)))
 (let (($x3021 (= c_27_0 d_27_0)))
 (let (($x3022 (and true $x3021)))
 (let (($x3024 (and $x3022 $x3023)))
 (let (($x3026 (and $x3024 $x3025)))
 (let (($x3018 (= c_26_3 d_26_3)))
 (let (($x3016 (= c_26_2 d_26_2)))
 (let (($x3014 (= c_26_1 d_26_1)))
 (let (($x3012 (= c_26_0 d_26_0)))
 (let (($x3013 (and true $x3012)))
 (let (($x3015 (and $x3013 $x3014)))
 (let (($x3017 (and $x3015 $x3016)))
 (let (($x3009 (= c_25_3 d_25_3)))
 (let (($x3007 (= c_25_2 d_25_2)))
 (let (($x3005 (= c_25_1 d_25_1)))
 (let (($x3003 (= c_25_0 d_25_0)))
 (let (($x3004 (and true $x3003)))
 (let (($x3006 (and $x3004 $x3005)))
 (let (($x3008 (and $x3006 $x3007)))
 (let (($x3000 (= c_24_3 d_24_3)))
 (let (($x2998 (= c_24_2 d_24_2)))
 (let (($x2996 (= c_24_1 d_24_1)))
 (let (($x2994 (= c_24_0 d_24_0)))
 (let (($x2995 (and true $x2994)))
 (let (($x2997 (and $x2995 $x2996)))
 (let (($x2999 (and $x2997 $x2998)))
 (let (($x2991 (= c_23_3 d_23_3)))
 (let (($x2989 (= c_23_2 d_23_2)))
 (let (($x2987 (= c_23_1 d_23_1)))
 (let (($x2985 (= c_23_0 d_23_0)))
 (let (($x2986 (and true $x2985)))
 (let (($x2988 (and $x2986 $x2987)))
 (let (($x2990 (and $x2988 $x2989)))
 (let (($x2982 (= c_22_3 d_22_3)))
 (let (($x2980 (= c_22_2 d_22_2)))
 (let (($x2978 (= c_22_1 d_22_1)))
 (let (($x2976 (= c_22_0 d_22_0)))
 (let (($x2977 (and true $x2976)))
 (let (($x2979 (and $x2977 $x2978)))
 (let (($x2981 (and $x2979 $x2980)))
 (let (($x2973 (= c_21_3 d_21_3)))
 (let (($x2971 (= c_21_2 d_21_2)))
 (let (($x2969 (= c_21_1 d_21_1)))
 (let (($x2967 (= c_21_0 d_21_0)))
 (let (($x2968 (and true $x2967)))
 (let (($x2970 (and $x2968 $x2969)))
 (let (($x2972 (and $x2970 $x2971)))
 (let (($x2964 (= c_20_3 d_20_3)))
 (let (($x2962 (= c_20_2 d_20_2)))
 (let (($x2960 (= c_20_1 d_20_1)))
 (let (($x2958 (= c_20_0 d_20_0)))
 (let (($x2959 (and true $x2958)))
 (let (($x2961 (and $x2959 $x2960)))
 (let (($x2963 (and $x2961 $x2962)))
 (let (($x2955 (= c_19_3 d_19_3)))
 (let (($x2953 (= c_19_2 d_19_2)))
 (let (($x2951 (= c_19_1 d_19_1)))
 (let (($x2949 (= c_19_0 d_19_0)))
 (let (($x2950 (and true $x2949)))
 (let (($x2952 (and $x2950 $x2951)))
 (let (($x2954 (and $x2952 $x2953)))
 (let (($x2941 (and true (=> c_18_0 d_18_1))))
 (let (($x2943 (and $x2941 (=> c_18_1 d_18_1))))
 (let (($x2945 (and $x2943 (=> c_18_2 d_18_1))))
 (let (($x2932 (and true (=> c_17_0 d_17_1))))
 (let (($x2934 (and $x2932 (=> c_17_1 d_17_1))))
 (let (($x2936 (and $x2934 (=> c_17_2 d_17_1))))
 (let (($x2923 (and true (=> c_16_0 d_16_1))))
 (let (($x2925 (and $x2923 (=> c_16_1 d_16_1))))
 (let (($x2927 (and $x2925 (=> c_16_2 d_16_1))))
 (let (($x2914 (and true (=> c_15_0 d_15_1))))
 (let (($x2916 (and $x2914 (=> c_15_1 d_15_1))))
 (let (($x2918 (and $x2916 (=> c_15_2 d_15_1))))
 (let (($x2905 (and true (=> c_14_0 d_14_1))))
 (let (($x2907 (and $x2905 (=> c_14_1 d_14_1))))
 (let (($x2909 (and $x2907 (=> c_14_2 d_14_1))))
 (let (($x2896 (and true (=> c_13_0 d_13_1))))
 (let (($x2898 (and $x2896 (=> c_13_1 d_13_1))))
 (let (($x2900 (and $x2898 (=> c_13_2 d_13_1))))
 (let (($x2887 (and true (=> c_12_0 d_12_1))))
 (let (($x2889 (and $x2887 (=> c_12_1 d_12_1))))
 (let (($x2891 (and $x2889 (=> c_12_2 d_12_1))))
 (let (($x2878 (and true (=> c_11_0 d_11_1))))
 (let (($x2880 (and $x2878 (=> c_11_1 d_11_1))))
 (let (($x2882 (and $x2880 (=> c_11_2 d_11_1))))
 (let (($x2869 (and true (=> c_10_0 d_10_1))))
 (let (($x2871 (and $x2869 (=> c_10_1 d_10_1))))
 (let (($x2873 (and $x2871 (=> c_10_2 d_10_1))))
 (let (($x2860 (and true (=> c_9_0 d_9_1))))
 (let (($x2862 (and $x2860 (=> c_9_1 d_9_1))))
 (let (($x2864 (and $x2862 (=> c_9_2 d_9_1))))
 (let (($x2851 (and true (=> c_8_0 d_8_1))))
 (let (($x2853 (and $x2851 (=> c_8_1 d_8_1))))
 (let (($x2855 (and $x2853 (=> c_8_2 d_8_1))))
 (let (($x2842 (and true (=> c_7_0 d_7_1))))
 (let (($x2844 (and $x2842 (=> c_7_1 d_7_1))))
 (let (($x2846 (and $x2844 (=> c_7_2 d_7_1))))
 (let (($x2833 (and true (=> c_6_0 d_6_2))))
 (let (($x2835 (and $x2833 (=> c_6_1 d_6_2))))
 (let (($x2837 (and $x2835 (=> c_6_2 d_6_2))))
 (let (($x2824 (and true (=> c_5_0 d_5_2))))
 (let (($x2826 (and $x2824 (=> c_5_1 d_5_2))))
 (let (($x2828 (and $x2826 (=> c_5_2 d_5_2))))
 (let (($x2815 (and true (=> c_4_0 d_4_2))))
 (let (($x2817 (and $x2815 (=> c_4_1 d_4_2))))
 (let (($x2819 (and $x2817 (=> c_4_2 d_4_2))))
 (let (($x2806 (and true (=> c_3_0 d_3_2))))
 (let (($x2808 (and $x2806 (=> c_3_1 d_3_2))))
 (let (($x2810 (and $x2808 (=> c_3_2 d_3_2))))
 (let (($x2797 (and true (=> c_2_0 d_2_2))))
 (let (($x2799 (and $x2797 (=> c_2_1 d_2_2))))
 (let (($x2801 (and $x2799 (=> c_2_2 d_2_2))))
 (let (($x2788 (and true (=> c_1_0 d_1_2))))
 (let (($x2790 (and $x2788 (=> c_1_1 d_1_2))))
 (let (($x2792 (and $x2790 (=> c_1_2 d_1_2))))
 (let (($x2779 (and true (=> c_0_0 d_0_3))))
 (let (($x2781 (and $x2779 (=> c_0_1 d_0_3))))
 (let (($x2783 (and $x2781 (=> c_0_2 d_0_3))))
 (let ((?x2771 (ite (or c_18_2 c_18_3) 1 0)))
 (let ((?x2769 (ite (or c_17_2 c_17_3) 1 0)))
 (let ((?x2767 (ite (or c_16_2 c_16_3) 1 0)))
 (let ((?x2765 (ite (or c_15_2 c_15_3) 1 0)))
 (let ((?x2763 (ite (or c_14_2 c_14_3) 1 0)))
 (let ((?x2761 (ite (or c_13_2 c_13_3) 1 0)))
 (let ((?x2759 (ite (or c_12_2 c_12_3) 1 0)))
 (let ((?x2757 (ite (or c_11_2 c_11_3) 1 0)))
 (let ((?x2755 (ite (or c_10_2 c_10_3) 1 0)))
 (let ((?x2753 (ite (or c_9_2 c_9_3) 1 0)))
 (let ((?x2751 (ite (or c_8_2 c_8_3) 1 0)))
 (let ((?x2749 (ite (or c_7_2 c_7_3) 1 0)))
 (let ((?x2747 (ite (or c_6_2 c_6_3) 1 0)))
 (let ((?x2745 (ite (or c_5_2 c_5_3) 1 0)))
 (let ((?x2743 (ite (or c_4_2 c_4_3) 1 0)))
 (let ((?x2741 (ite (or c_3_2 c_3_3) 1 0)))
 (let ((?x2739 (ite (or c_2_2 c_2_3) 1 0)))
 (let ((?x2737 (ite (or c_1_2 c_1_3) 1 0)))
 (let ((?x2733 (ite (or c_0_2 c_0_3) 1 0)))
 (let ((?x2735 (+ 0 ?x2733)))
 (let ((?x2738 (+ ?x2735 ?x2737)))
 (let ((?x2740 (+ ?x2738 ?x2739)))
 (let ((?x2742 (+ ?x2740 ?x2741)))
 (let ((?x2744 (+ ?x2742 ?x2743)))
 (let ((?x2746 (+ ?x2744 ?x2745)))
 (let ((?x2748 (+ ?x2746 ?x2747)))
 (let ((?x2750 (+ ?x2748 ?x2749)))
 (let ((?x2752 (+ ?x2750 ?x2751)))
 (let ((?x2754 (+ ?x2752 ?x2753)))
 (let ((?x2756 (+ ?x2754 ?x2755)))
 (let ((?x2758 (+ ?x2756 ?x2757)))
 (let ((?x2760 (+ ?x2758 ?x2759)))
 (let ((?x2762 (+ ?x2760 ?x2761)))
 (let ((?x2764 (+ ?x2762 ?x2763)))
 (let ((?x2766 (+ ?x2764 ?x2765)))
 (let ((?x2768 (+ ?x2766 ?x2767)))
 (let ((?x2770 (+ ?x2768 ?x2769)))
 (let ((?x2657 (+ 0 ?x2656)))
 (let ((?x2659 (+ ?x2657 ?x2658)))
 (let ((?x2661 (+ ?x2659 ?x2660)))
 (let ((?x2663 (+ ?x2661 ?x2662)))
 (let ((?x2665 (+ ?x2663 ?x2664)))
 (let ((?x2667 (+ ?x2665 ?x2666)))
 (let ((?x2669 (+ ?x2667 ?x2668)))
 (let ((?x2671 (+ ?x2669 ?x2670)))
 (let ((?x2673 (+ ?x2671 ?x2672)))
 (let ((?x2675 (+ ?x2673 ?x2674)))
 (let ((?x2677 (+ ?x2675 ?x2676)))
 (let ((?x2679 (+ ?x2677 ?x2678)))
 (let ((?x2681 (+ ?x2679 ?x2680)))
 (let ((?x2683 (+ ?x2681 ?x2682)))
 (let ((?x2685 (+ ?x2683 ?x2684)))
 (let ((?x2687 (+ ?x2685 ?x2686)))
 (let ((?x2689 (+ ?x2687 ?x2688)))
 (let ((?x2691 (+ ?x2689 ?x2690)))
 (let (($x2776 (and (= (to_real (+ ?x2691 ?x2692)) 12.0) (= (to_real (+ ?x2770 ?x2771)) 0.0))))
 (let (($x2655 (or c_18_0 c_18_1 c_18_2 c_18_3)))
 (let (($x2647 (or c_17_0 c_17_1 c_17_2 c_17_3)))
 (let (($x2639 (or c_16_0 c_16_1 c_16_2 c_16_3)))
 (let (($x2631 (or c_15_0 c_15_1 c_15_2 c_15_3)))
 (let (($x2623 (or c_14_0 c_14_1 c_14_2 c_14_3)))
 (let (($x2615 (or c_13_0 c_13_1 c_13_2 c_13_3)))
 (let (($x2607 (or c_12_0 c_12_1 c_12_2 c_12_3)))
 (let (($x2599 (or c_11_0 c_11_1 c_11_2 c_11_3)))
 (let (($x2591 (or c_10_0 c_10_1 c_10_2 c_10_3)))
 (let (($x2583 (or c_9_0 c_9_1 c_9_2 c_9_3)))
 (let (($x2575 (or c_8_0 c_8_1 c_8_2 c_8_3)))
 (let (($x2567 (or c_7_0 c_7_1 c_7_2 c_7_3)))
 (let (($x2559 (or c_6_0 c_6_1 c_6_2 c_6_3)))
 (let (($x2551 (or c_5_0 c_5_1 c_5_2 c_5_3)))
 (let (($x2543 (or c_4_0 c_4_1 c_4_2 c_4_3)))
 (let (($x2535 (or c_3_0 c_3_1 c_3_2 c_3_3)))
 (let (($x2527 (or c_2_0 c_2_1 c_2_2 c_2_3)))
 (let (($x2519 (or c_1_0 c_1_1 c_1_2 c_1_3)))
 (let (($x2511 (and c_0_1 in_target_0)))
 (let (($x2507 (and true $x2511)))
 (let (($x2515 (and $x2507 $x2519)))
 (let (($x2523 (and $x2515 $x2527)))
 (let (($x2531 (and $x2523 $x2535)))
 (let (($x2539 (and $x2531 $x2543)))
 (let (($x2547 (and $x2539 $x2551)))
 (let (($x2555 (and $x2547 $x2559)))
 (let (($x2563 (and $x2555 $x2567)))
 (let (($x2571 (and $x2563 $x2575)))
 (let (($x2579 (and $x2571 $x2583)))
 (let (($x2587 (and $x2579 $x2591)))
 (let (($x2595 (and $x2587 $x2599)))
 (let (($x2603 (and $x2595 $x2607)))
 (let (($x2611 (and $x2603 $x2615)))
 (let (($x2619 (and $x2611 $x2623)))
 (let (($x2627 (and $x2619 $x2631)))
 (let (($x2635 (and $x2627 $x2639)))
 (let (($x2643 (and $x2635 $x2647)))
 (let (($x2651 (and $x2643 $x2655)))
 (let (($x2777 (and $x2651 $x2776)))
 (let (($x2786 (and $x2777 (and $x2783 (=> c_0_3 d_0_3)))))
 (let (($x2795 (and $x2786 (and $x2792 (=> c_1_3 d_1_2)))))
 (let (($x2804 (and $x2795 (and $x2801 (=> c_2_3 d_2_2)))))
 (let (($x2813 (and $x2804 (and $x2810 (=> c_3_3 d_3_2)))))
 (let (($x2822 (and $x2813 (and $x2819 (=> c_4_3 d_4_2)))))
 (let (($x2831 (and $x2822 (and $x2828 (=> c_5_3 d_5_2)))))
 (let (($x2840 (and $x2831 (and $x2837 (=> c_6_3 d_6_2)))))
 (let (($x2849 (and $x2840 (and $x2846 (=> c_7_3 d_7_1)))))
 (let (($x2858 (and $x2849 (and $x2855 (=> c_8_3 d_8_1)))))
 (let (($x2867 (and $x2858 (and $x2864 (=> c_9_3 d_9_1)))))
 (let (($x2876 (and $x2867 (and $x2873 (=> c_10_3 d_10_1)))))
 (let (($x2885 (and $x2876 (and $x2882 (=> c_11_3 d_11_1)))))
 (let (($x2894 (and $x2885 (and $x2891 (=> c_12_3 d_12_1)))))
 (let (($x2903 (and $x2894 (and $x2900 (=> c_13_3 d_13_1)))))
 (let (($x2912 (and $x2903 (and $x2909 (=> c_14_3 d_14_1)))))
 (let (($x2921 (and $x2912 (and $x2918 (=> c_15_3 d_15_1)))))
 (let (($x2930 (and $x2921 (and $x2927 (=> c_16_3 d_16_1)))))
 (let (($x2939 (and $x2930 (and $x2936 (=> c_17_3 d_17_1)))))
 (let (($x2948 (and $x2939 (and $x2945 (=> c_18_3 d_18_1)))))
 (let (($x2957 (and $x2948 (and $x2954 $x2955))))
 (let (($x2966 (and $x2957 (and $x2963 $x2964))))
 (let (($x2975 (and $x2966 (and $x2972 $x2973))))
 (let (($x2984 (and $x2975 (and $x2981 $x2982))))
 (let (($x2993 (and $x2984 (and $x2990 $x2991))))
 (let (($x3002 (and $x2993 (and $x2999 $x3000))))
 (let (($x3011 (and $x3002 (and $x3008 $x3009))))
 (let (($x3020 (and $x3011 (and $x3017 $x3018))))
 (let (($x3029 (and $x3020 (and $x3026 $x3027))))
 (let (($x3038 (and $x3029 (and $x3035 $x3036))))
 (let (($x3047 (and $x3038 (and $x3044 $x3045))))
 (let (($x3056 (and $x3047 (and $x3053 $x3054))))
 (let (($x3065 (and $x3056 (and $x3062 $x3063))))
 (let (($x3074 (and $x3065 (and $x3071 $x3072))))
 (let (($x3083 (and $x3074 (and $x3080 $x3081))))
 (let (($x3092 (and $x3083 (and $x3089 $x3090))))
 (let (($x3101 (and $x3092 (and $x3098 $x3099))))
 (let (($x3110 (and $x3101 (and $x3107 $x3108))))
 (let (($x3119 (and $x3110 (and $x3116 $x3117))))
 (let (($x3128 (and $x3119 (and $x3125 $x3126))))
 (let (($x3137 (and $x3128 (and $x3134 $x3135))))
 (let (($x3146 (and $x3137 (and $x3143 $x3144))))
 (let (($x3155 (and $x3146 (and $x3152 $x3153))))
 (let (($x3164 (and $x3155 (and $x3161 $x3162))))
 (let (($x3173 (and $x3164 (and $x3170 $x3171))))
 (let (($x3182 (and $x3173 (and $x3179 $x3180))))
 (let (($x3191 (and $x3182 (and $x3188 $x3189))))
 (let (($x3200 (and $x3191 (and $x3197 $x3198))))
 (let (($x3209 (and $x3200 (and $x3206 $x3207))))
 (let (($x3218 (and $x3209 (and $x3215 $x3216))))
 (let (($x3227 (and $x3218 (and $x3224 $x3225))))
 (let (($x3236 (and $x3227 (and $x3233 $x3234))))
 (let (($x3245 (and $x3236 (and $x3242 $x3243))))
 (let (($x3254 (and $x3245 (and $x3251 $x3252))))
 (let (($x3263 (and $x3254 (and $x3260 $x3261))))
 (let (($x3272 (and $x3263 (and $x3269 $x3270))))
 (let (($x3281 (and $x3272 (and $x3278 $x3279))))
 (let (($x3290 (and $x3281 (and $x3287 $x3288))))
 (let (($x3299 (and $x3290 (and $x3296 $x3297))))
 (let (($x3308 (and $x3299 (and $x3305 $x3306))))
 (let (($x3317 (and $x3308 (and $x3314 $x3315))))
 (let (($x3326 (and $x3317 (and $x3323 $x3324))))
 (let (($x3344 (and $x3326 (=> c_0_3 (and c_0_3 (= ?x3340 6.0))))))
 (let (($x3375 (and $x3344 (=> c_0_2 $x3373))))
 (let (($x3390 (and $x3375 (=> c_1_3 (and c_1_3 (= ?x3386 6.0))))))
 (let (($x3416 (and $x3390 (=> c_1_2 $x3414))))
 (let (($x3429 (and $x3416 (=> c_2_3 (and c_2_3 (= ?x3425 6.0))))))
 (let (($x3453 (and $x3429 (=> c_2_2 $x3451))))
 (let (($x3466 (and $x3453 (=> c_3_3 (and c_3_3 (= ?x3462 6.0))))))
 (let (($x3490 (and $x3466 (=> c_3_2 $x3488))))
 (let (($x3503 (and $x3490 (=> c_4_3 (and c_4_3 (= ?x3499 6.0))))))
 (let (($x3526 (and $x3503 (=> c_4_2 $x3524))))
 (let (($x3539 (and $x3526 (=> c_5_3 (and c_5_3 (= ?x3535 6.0))))))
 (let (($x3563 (and $x3539 (=> c_5_2 $x3561))))
 (let (($x3575 (and $x3563 (=> c_6_3 (and c_6_3 (= ?x3571 6.0))))))
 (let (($x3598 (and $x3575 (=> c_6_2 (and c_6_2 $x3595)))))
 (let (($x3612 (and $x3598 (=> c_7_3 (and c_7_3 (= ?x3608 6.0))))))
 (let (($x3640 (and $x3612 (=> c_7_2 $x3638))))
 (let (($x3652 (and $x3640 (=> c_8_3 (and c_8_3 (= ?x3648 6.0))))))
 (let (($x3676 (and $x3652 (=> c_8_2 $x3674))))
 (let (($x3689 (and $x3676 (=> c_9_3 (and c_9_3 (= ?x3685 6.0))))))
 (let (($x3715 (and $x3689 (=> c_9_2 $x3713))))
 (let (($x3727 (and $x3715 (=> c_10_3 (and c_10_3 (= ?x3723 6.0))))))
 (let (($x3751 (and $x3727 (=> c_10_2 (and c_10_2 $x3748)))))
 (let (($x3764 (and $x3751 (=> c_11_3 (and c_11_3 (= ?x3760 6.0))))))
 (let (($x3790 (and $x3764 (=> c_11_2 $x3788))))
 (let (($x3802 (and $x3790 (=> c_12_3 (and c_12_3 (= ?x3798 6.0))))))
 (let (($x3826 (and $x3802 (=> c_12_2 (and c_12_2 $x3823)))))
 (let (($x3839 (and $x3826 (=> c_13_3 (and c_13_3 (= ?x3835 6.0))))))
 (let (($x3865 (and $x3839 (=> c_13_2 $x3863))))
 (let (($x3877 (and $x3865 (=> c_14_3 (and c_14_3 (= ?x3873 6.0))))))
 (let (($x3901 (and $x3877 (=> c_14_2 (and c_14_2 $x3898)))))
 (let (($x3914 (and $x3901 (=> c_15_3 (and c_15_3 (= ?x3910 6.0))))))
 (let (($x3940 (and $x3914 (=> c_15_2 $x3938))))
 (let (($x3952 (and $x3940 (=> c_16_3 (and c_16_3 (= ?x3948 6.0))))))
 (let (($x3976 (and $x3952 (=> c_16_2 (and c_16_2 $x3973)))))
 (let (($x3989 (and $x3976 (=> c_17_3 (and c_17_3 (= ?x3985 6.0))))))
 (let (($x4015 (and $x3989 (=> c_17_2 $x4013))))
 (let (($x4026 (and $x4015 (=> c_18_3 (and c_18_3 (= ?x4022 6.0))))))
 (let (($x4048 (and $x4026 (=> c_18_2 (and c_18_2 $x4045)))))
 (let (($x4062 (and $x4048 (=> c_19_3 (and c_19_3 (= ?x4058 6.0))))))
 (let (($x4090 (and $x4062 (=> c_19_2 (and c_19_2 $x4087)))))
 (let (($x4102 (and $x4090 (=> c_20_3 (and c_20_3 (= ?x4098 6.0))))))
 (let (($x4126 (and $x4102 (=> c_20_2 (and c_20_2 $x4123)))))
 (let (($x4138 (and $x4126 (=> c_21_3 (and c_21_3 (= ?x4134 6.0))))))
 (let (($x4162 (and $x4138 (=> c_21_2 (and c_21_2 $x4159)))))
 (let (($x4174 (and $x4162 (=> c_22_3 (and c_22_3 (= ?x4170 6.0))))))
 (let (($x4198 (and $x4174 (=> c_22_2 (and c_22_2 $x4195)))))
 (let (($x4211 (and $x4198 (=> c_23_3 (and c_23_3 (= ?x4207 6.0))))))
 (let (($x4237 (and $x4211 (=> c_23_2 (and c_23_2 $x4234)))))
 (let (($x4249 (and $x4237 (=> c_24_3 (and c_24_3 (= ?x4245 6.0))))))
 (let (($x4273 (and $x4249 (=> c_24_2 (and c_24_2 $x4270)))))
 (let (($x4285 (and $x4273 (=> c_25_3 (and c_25_3 (= ?x4281 6.0))))))
 (let (($x4309 (and $x4285 (=> c_25_2 (and c_25_2 $x4306)))))
 (let (($x4322 (and $x4309 (=> c_26_3 (and c_26_3 (= ?x4318 6.0))))))
 (let (($x4348 (and $x4322 (=> c_26_2 (and c_26_2 $x4345)))))
 (let (($x4360 (and $x4348 (=> c_27_3 (and c_27_3 (= ?x4356 6.0))))))
 (let (($x4384 (and $x4360 (=> c_27_2 (and c_27_2 $x4381)))))
 (let (($x4396 (and $x4384 (=> c_28_3 (and c_28_3 (= ?x4392 6.0))))))
 (let (($x4420 (and $x4396 (=> c_28_2 (and c_28_2 $x4417)))))
 (let (($x4433 (and $x4420 (=> c_29_3 (and c_29_3 (= ?x4429 6.0))))))
 (let (($x4459 (and $x4433 (=> c_29_2 (and c_29_2 $x4456)))))
 (let (($x4471 (and $x4459 (=> c_30_3 (and c_30_3 (= ?x4467 6.0))))))
 (let (($x4495 (and $x4471 (=> c_30_2 (and c_30_2 $x4492)))))
 (let (($x4507 (and $x4495 (=> c_31_3 (and c_31_3 (= ?x4503 6.0))))))
 (let (($x4531 (and $x4507 (=> c_31_2 (and c_31_2 $x4528)))))
 (let (($x4544 (and $x4531 (=> c_32_3 (and c_32_3 (= ?x4540 6.0))))))
 (let (($x4570 (and $x4544 (=> c_32_2 (and c_32_2 $x4567)))))
 (let (($x4582 (and $x4570 (=> c_33_3 (and c_33_3 (= ?x4578 6.0))))))
 (let (($x4606 (and $x4582 (=> c_33_2 (and c_33_2 $x4603)))))
 (let (($x4618 (and $x4606 (=> c_34_3 (and c_34_3 (= ?x4614 6.0))))))
 (let (($x4642 (and $x4618 (=> c_34_2 (and c_34_2 $x4639)))))
 (let (($x4654 (and $x4642 (=> c_35_3 (and c_35_3 (= ?x4650 6.0))))))
 (let (($x4678 (and $x4654 (=> c_35_2 (and c_35_2 $x4675)))))
 (let (($x4690 (and $x4678 (=> c_36_3 (and c_36_3 (= ?x4686 6.0))))))
 (let (($x5220 (and (and $x4690 (=> c_36_2 (and c_36_2 $x4711))) $x5219)))
 (=> instance_0 $x5220)))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(assert
 (or instance_0))
(check-sat)
