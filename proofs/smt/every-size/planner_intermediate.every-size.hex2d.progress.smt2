; holon proof obligation for every region: system planner_intermediate, lattice hex2d, property progress
; window: every rule shape with its first cell at the origin, and every point within 4 steps of its pattern, free (91 cells; proofs/README.md)
; expected: unsat (the property holds on every region of the lattice)
(set-logic ALL)
; 
(set-info :status unknown)
(declare-fun c_0_8 () Bool)
(declare-fun c_0_7 () Bool)
(declare-fun c_0_6 () Bool)
(declare-fun c_0_5 () Bool)
(declare-fun c_0_4 () Bool)
(declare-fun c_0_3 () Bool)
(declare-fun c_0_2 () Bool)
(declare-fun c_0_1 () Bool)
(declare-fun c_0_0 () Bool)
(declare-fun c_1_8 () Bool)
(declare-fun c_1_7 () Bool)
(declare-fun c_1_6 () Bool)
(declare-fun c_1_5 () Bool)
(declare-fun c_1_4 () Bool)
(declare-fun c_1_3 () Bool)
(declare-fun c_1_2 () Bool)
(declare-fun c_1_1 () Bool)
(declare-fun c_1_0 () Bool)
(declare-fun c_2_8 () Bool)
(declare-fun c_2_7 () Bool)
(declare-fun c_2_6 () Bool)
(declare-fun c_2_5 () Bool)
(declare-fun c_2_4 () Bool)
(declare-fun c_2_3 () Bool)
(declare-fun c_2_2 () Bool)
(declare-fun c_2_1 () Bool)
(declare-fun c_2_0 () Bool)
(declare-fun c_3_8 () Bool)
(declare-fun c_3_7 () Bool)
(declare-fun c_3_6 () Bool)
(declare-fun c_3_5 () Bool)
(declare-fun c_3_4 () Bool)
(declare-fun c_3_3 () Bool)
(declare-fun c_3_2 () Bool)
(declare-fun c_3_1 () Bool)
(declare-fun c_3_0 () Bool)
(declare-fun c_4_8 () Bool)
(declare-fun c_4_7 () Bool)
(declare-fun c_4_6 () Bool)
(declare-fun c_4_5 () Bool)
(declare-fun c_4_4 () Bool)
(declare-fun c_4_3 () Bool)
(declare-fun c_4_2 () Bool)
(declare-fun c_4_1 () Bool)
(declare-fun c_4_0 () Bool)
(declare-fun c_5_8 () Bool)
(declare-fun c_5_7 () Bool)
(declare-fun c_5_6 () Bool)
(declare-fun c_5_5 () Bool)
(declare-fun c_5_4 () Bool)
(declare-fun c_5_3 () Bool)
(declare-fun c_5_2 () Bool)
(declare-fun c_5_1 () Bool)
(declare-fun c_5_0 () Bool)
(declare-fun c_6_8 () Bool)
(declare-fun c_6_7 () Bool)
(declare-fun c_6_6 () Bool)
(declare-fun c_6_5 () Bool)
(declare-fun c_6_4 () Bool)
(declare-fun c_6_3 () Bool)
(declare-fun c_6_2 () Bool)
(declare-fun c_6_1 () Bool)
(declare-fun c_6_0 () Bool)
(declare-fun c_7_8 () Bool)
(declare-fun c_7_7 () Bool)
(declare-fun c_7_6 () Bool)
(declare-fun c_7_5 () Bool)
(declare-fun c_7_4 () Bool)
(declare-fun c_7_3 () Bool)
(declare-fun c_7_2 () Bool)
(declare-fun c_7_1 () Bool)
(declare-fun c_7_0 () Bool)
(declare-fun c_8_8 () Bool)
(declare-fun c_8_7 () Bool)
(declare-fun c_8_6 () Bool)
(declare-fun c_8_5 () Bool)
(declare-fun c_8_4 () Bool)
(declare-fun c_8_3 () Bool)
(declare-fun c_8_2 () Bool)
(declare-fun c_8_1 () Bool)
(declare-fun c_8_0 () Bool)
(declare-fun c_9_8 () Bool)
(declare-fun c_9_7 () Bool)
(declare-fun c_9_6 () Bool)
(declare-fun c_9_5 () Bool)
(declare-fun c_9_4 () Bool)
(declare-fun c_9_3 () Bool)
(declare-fun c_9_2 () Bool)
(declare-fun c_9_1 () Bool)
(declare-fun c_9_0 () Bool)
(declare-fun c_10_8 () Bool)
(declare-fun c_10_7 () Bool)
(declare-fun c_10_6 () Bool)
(declare-fun c_10_5 () Bool)
(declare-fun c_10_4 () Bool)
(declare-fun c_10_3 () Bool)
(declare-fun c_10_2 () Bool)
(declare-fun c_10_1 () Bool)
(declare-fun c_10_0 () Bool)
(declare-fun c_11_8 () Bool)
(declare-fun c_11_7 () Bool)
(declare-fun c_11_6 () Bool)
(declare-fun c_11_5 () Bool)
(declare-fun c_11_4 () Bool)
(declare-fun c_11_3 () Bool)
(declare-fun c_11_2 () Bool)
(declare-fun c_11_1 () Bool)
(declare-fun c_11_0 () Bool)
(declare-fun c_12_8 () Bool)
(declare-fun c_12_7 () Bool)
(declare-fun c_12_6 () Bool)
(declare-fun c_12_5 () Bool)
(declare-fun c_12_4 () Bool)
(declare-fun c_12_3 () Bool)
(declare-fun c_12_2 () Bool)
(declare-fun c_12_1 () Bool)
(declare-fun c_12_0 () Bool)
(declare-fun c_13_8 () Bool)
(declare-fun c_13_7 () Bool)
(declare-fun c_13_6 () Bool)
(declare-fun c_13_5 () Bool)
(declare-fun c_13_4 () Bool)
(declare-fun c_13_3 () Bool)
(declare-fun c_13_2 () Bool)
(declare-fun c_13_1 () Bool)
(declare-fun c_13_0 () Bool)
(declare-fun c_14_8 () Bool)
(declare-fun c_14_7 () Bool)
(declare-fun c_14_6 () Bool)
(declare-fun c_14_5 () Bool)
(declare-fun c_14_4 () Bool)
(declare-fun c_14_3 () Bool)
(declare-fun c_14_2 () Bool)
(declare-fun c_14_1 () Bool)
(declare-fun c_14_0 () Bool)
(declare-fun c_15_8 () Bool)
(declare-fun c_15_7 () Bool)
(declare-fun c_15_6 () Bool)
(declare-fun c_15_5 () Bool)
(declare-fun c_15_4 () Bool)
(declare-fun c_15_3 () Bool)
(declare-fun c_15_2 () Bool)
(declare-fun c_15_1 () Bool)
(declare-fun c_15_0 () Bool)
(declare-fun c_16_8 () Bool)
(declare-fun c_16_7 () Bool)
(declare-fun c_16_6 () Bool)
(declare-fun c_16_5 () Bool)
(declare-fun c_16_4 () Bool)
(declare-fun c_16_3 () Bool)
(declare-fun c_16_2 () Bool)
(declare-fun c_16_1 () Bool)
(declare-fun c_16_0 () Bool)
(declare-fun c_17_8 () Bool)
(declare-fun c_17_7 () Bool)
(declare-fun c_17_6 () Bool)
(declare-fun c_17_5 () Bool)
(declare-fun c_17_4 () Bool)
(declare-fun c_17_3 () Bool)
(declare-fun c_17_2 () Bool)
(declare-fun c_17_1 () Bool)
(declare-fun c_17_0 () Bool)
(declare-fun c_18_8 () Bool)
(declare-fun c_18_7 () Bool)
(declare-fun c_18_6 () Bool)
(declare-fun c_18_5 () Bool)
(declare-fun c_18_4 () Bool)
(declare-fun c_18_3 () Bool)
(declare-fun c_18_2 () Bool)
(declare-fun c_18_1 () Bool)
(declare-fun c_18_0 () Bool)
(declare-fun c_19_8 () Bool)
(declare-fun c_19_7 () Bool)
(declare-fun c_19_6 () Bool)
(declare-fun c_19_5 () Bool)
(declare-fun c_19_4 () Bool)
(declare-fun c_19_3 () Bool)
(declare-fun c_19_2 () Bool)
(declare-fun c_19_1 () Bool)
(declare-fun c_19_0 () Bool)
(declare-fun c_20_8 () Bool)
(declare-fun c_20_7 () Bool)
(declare-fun c_20_6 () Bool)
(declare-fun c_20_5 () Bool)
(declare-fun c_20_4 () Bool)
(declare-fun c_20_3 () Bool)
(declare-fun c_20_2 () Bool)
(declare-fun c_20_1 () Bool)
(declare-fun c_20_0 () Bool)
(declare-fun c_21_8 () Bool)
(declare-fun c_21_7 () Bool)
(declare-fun c_21_6 () Bool)
(declare-fun c_21_5 () Bool)
(declare-fun c_21_4 () Bool)
(declare-fun c_21_3 () Bool)
(declare-fun c_21_2 () Bool)
(declare-fun c_21_1 () Bool)
(declare-fun c_21_0 () Bool)
(declare-fun c_22_8 () Bool)
(declare-fun c_22_7 () Bool)
(declare-fun c_22_6 () Bool)
(declare-fun c_22_5 () Bool)
(declare-fun c_22_4 () Bool)
(declare-fun c_22_3 () Bool)
(declare-fun c_22_2 () Bool)
(declare-fun c_22_1 () Bool)
(declare-fun c_22_0 () Bool)
(declare-fun c_23_8 () Bool)
(declare-fun c_23_7 () Bool)
(declare-fun c_23_6 () Bool)
(declare-fun c_23_5 () Bool)
(declare-fun c_23_4 () Bool)
(declare-fun c_23_3 () Bool)
(declare-fun c_23_2 () Bool)
(declare-fun c_23_1 () Bool)
(declare-fun c_23_0 () Bool)
(declare-fun c_24_8 () Bool)
(declare-fun c_24_7 () Bool)
(declare-fun c_24_6 () Bool)
(declare-fun c_24_5 () Bool)
(declare-fun c_24_4 () Bool)
(declare-fun c_24_3 () Bool)
(declare-fun c_24_2 () Bool)
(declare-fun c_24_1 () Bool)
(declare-fun c_24_0 () Bool)
(declare-fun c_25_8 () Bool)
(declare-fun c_25_7 () Bool)
(declare-fun c_25_6 () Bool)
(declare-fun c_25_5 () Bool)
(declare-fun c_25_4 () Bool)
(declare-fun c_25_3 () Bool)
(declare-fun c_25_2 () Bool)
(declare-fun c_25_1 () Bool)
(declare-fun c_25_0 () Bool)
(declare-fun c_26_8 () Bool)
(declare-fun c_26_7 () Bool)
(declare-fun c_26_6 () Bool)
(declare-fun c_26_5 () Bool)
(declare-fun c_26_4 () Bool)
(declare-fun c_26_3 () Bool)
(declare-fun c_26_2 () Bool)
(declare-fun c_26_1 () Bool)
(declare-fun c_26_0 () Bool)
(declare-fun c_27_8 () Bool)
(declare-fun c_27_7 () Bool)
(declare-fun c_27_6 () Bool)
(declare-fun c_27_5 () Bool)
(declare-fun c_27_4 () Bool)
(declare-fun c_27_3 () Bool)
(declare-fun c_27_2 () Bool)
(declare-fun c_27_1 () Bool)
(declare-fun c_27_0 () Bool)
(declare-fun c_28_8 () Bool)
(declare-fun c_28_7 () Bool)
(declare-fun c_28_6 () Bool)
(declare-fun c_28_5 () Bool)
(declare-fun c_28_4 () Bool)
(declare-fun c_28_3 () Bool)
(declare-fun c_28_2 () Bool)
(declare-fun c_28_1 () Bool)
(declare-fun c_28_0 () Bool)
(declare-fun c_29_8 () Bool)
(declare-fun c_29_7 () Bool)
(declare-fun c_29_6 () Bool)
(declare-fun c_29_5 () Bool)
(declare-fun c_29_4 () Bool)
(declare-fun c_29_3 () Bool)
(declare-fun c_29_2 () Bool)
(declare-fun c_29_1 () Bool)
(declare-fun c_29_0 () Bool)
(declare-fun c_30_8 () Bool)
(declare-fun c_30_7 () Bool)
(declare-fun c_30_6 () Bool)
(declare-fun c_30_5 () Bool)
(declare-fun c_30_4 () Bool)
(declare-fun c_30_3 () Bool)
(declare-fun c_30_2 () Bool)
(declare-fun c_30_1 () Bool)
(declare-fun c_30_0 () Bool)
(declare-fun c_31_8 () Bool)
(declare-fun c_31_7 () Bool)
(declare-fun c_31_6 () Bool)
(declare-fun c_31_5 () Bool)
(declare-fun c_31_4 () Bool)
(declare-fun c_31_3 () Bool)
(declare-fun c_31_2 () Bool)
(declare-fun c_31_1 () Bool)
(declare-fun c_31_0 () Bool)
(declare-fun c_32_8 () Bool)
(declare-fun c_32_7 () Bool)
(declare-fun c_32_6 () Bool)
(declare-fun c_32_5 () Bool)
(declare-fun c_32_4 () Bool)
(declare-fun c_32_3 () Bool)
(declare-fun c_32_2 () Bool)
(declare-fun c_32_1 () Bool)
(declare-fun c_32_0 () Bool)
(declare-fun c_33_8 () Bool)
(declare-fun c_33_7 () Bool)
(declare-fun c_33_6 () Bool)
(declare-fun c_33_5 () Bool)
(declare-fun c_33_4 () Bool)
(declare-fun c_33_3 () Bool)
(declare-fun c_33_2 () Bool)
(declare-fun c_33_1 () Bool)
(declare-fun c_33_0 () Bool)
(declare-fun c_34_8 () Bool)
(declare-fun c_34_7 () Bool)
(declare-fun c_34_6 () Bool)
(declare-fun c_34_5 () Bool)
(declare-fun c_34_4 () Bool)
(declare-fun c_34_3 () Bool)
(declare-fun c_34_2 () Bool)
(declare-fun c_34_1 () Bool)
(declare-fun c_34_0 () Bool)
(declare-fun c_35_8 () Bool)
(declare-fun c_35_7 () Bool)
(declare-fun c_35_6 () Bool)
(declare-fun c_35_5 () Bool)
(declare-fun c_35_4 () Bool)
(declare-fun c_35_3 () Bool)
(declare-fun c_35_2 () Bool)
(declare-fun c_35_1 () Bool)
(declare-fun c_35_0 () Bool)
(declare-fun c_36_8 () Bool)
(declare-fun c_36_7 () Bool)
(declare-fun c_36_6 () Bool)
(declare-fun c_36_5 () Bool)
(declare-fun c_36_4 () Bool)
(declare-fun c_36_3 () Bool)
(declare-fun c_36_2 () Bool)
(declare-fun c_36_1 () Bool)
(declare-fun c_36_0 () Bool)
(declare-fun c_37_8 () Bool)
(declare-fun c_37_7 () Bool)
(declare-fun c_37_6 () Bool)
(declare-fun c_37_5 () Bool)
(declare-fun c_37_4 () Bool)
(declare-fun c_37_3 () Bool)
(declare-fun c_37_2 () Bool)
(declare-fun c_37_1 () Bool)
(declare-fun c_37_0 () Bool)
(declare-fun c_38_8 () Bool)
(declare-fun c_38_7 () Bool)
(declare-fun c_38_6 () Bool)
(declare-fun c_38_5 () Bool)
(declare-fun c_38_4 () Bool)
(declare-fun c_38_3 () Bool)
(declare-fun c_38_2 () Bool)
(declare-fun c_38_1 () Bool)
(declare-fun c_38_0 () Bool)
(declare-fun c_39_8 () Bool)
(declare-fun c_39_7 () Bool)
(declare-fun c_39_6 () Bool)
(declare-fun c_39_5 () Bool)
(declare-fun c_39_4 () Bool)
(declare-fun c_39_3 () Bool)
(declare-fun c_39_2 () Bool)
(declare-fun c_39_1 () Bool)
(declare-fun c_39_0 () Bool)
(declare-fun c_40_8 () Bool)
(declare-fun c_40_7 () Bool)
(declare-fun c_40_6 () Bool)
(declare-fun c_40_5 () Bool)
(declare-fun c_40_4 () Bool)
(declare-fun c_40_3 () Bool)
(declare-fun c_40_2 () Bool)
(declare-fun c_40_1 () Bool)
(declare-fun c_40_0 () Bool)
(declare-fun c_41_8 () Bool)
(declare-fun c_41_7 () Bool)
(declare-fun c_41_6 () Bool)
(declare-fun c_41_5 () Bool)
(declare-fun c_41_4 () Bool)
(declare-fun c_41_3 () Bool)
(declare-fun c_41_2 () Bool)
(declare-fun c_41_1 () Bool)
(declare-fun c_41_0 () Bool)
(declare-fun c_42_8 () Bool)
(declare-fun c_42_7 () Bool)
(declare-fun c_42_6 () Bool)
(declare-fun c_42_5 () Bool)
(declare-fun c_42_4 () Bool)
(declare-fun c_42_3 () Bool)
(declare-fun c_42_2 () Bool)
(declare-fun c_42_1 () Bool)
(declare-fun c_42_0 () Bool)
(declare-fun c_43_8 () Bool)
(declare-fun c_43_7 () Bool)
(declare-fun c_43_6 () Bool)
(declare-fun c_43_5 () Bool)
(declare-fun c_43_4 () Bool)
(declare-fun c_43_3 () Bool)
(declare-fun c_43_2 () Bool)
(declare-fun c_43_1 () Bool)
(declare-fun c_43_0 () Bool)
(declare-fun c_44_8 () Bool)
(declare-fun c_44_7 () Bool)
(declare-fun c_44_6 () Bool)
(declare-fun c_44_5 () Bool)
(declare-fun c_44_4 () Bool)
(declare-fun c_44_3 () Bool)
(declare-fun c_44_2 () Bool)
(declare-fun c_44_1 () Bool)
(declare-fun c_44_0 () Bool)
(declare-fun c_45_8 () Bool)
(declare-fun c_45_7 () Bool)
(declare-fun c_45_6 () Bool)
(declare-fun c_45_5 () Bool)
(declare-fun c_45_4 () Bool)
(declare-fun c_45_3 () Bool)
(declare-fun c_45_2 () Bool)
(declare-fun c_45_1 () Bool)
(declare-fun c_45_0 () Bool)
(declare-fun c_46_8 () Bool)
(declare-fun c_46_7 () Bool)
(declare-fun c_46_6 () Bool)
(declare-fun c_46_5 () Bool)
(declare-fun c_46_4 () Bool)
(declare-fun c_46_3 () Bool)
(declare-fun c_46_2 () Bool)
(declare-fun c_46_1 () Bool)
(declare-fun c_46_0 () Bool)
(declare-fun c_47_8 () Bool)
(declare-fun c_47_7 () Bool)
(declare-fun c_47_6 () Bool)
(declare-fun c_47_5 () Bool)
(declare-fun c_47_4 () Bool)
(declare-fun c_47_3 () Bool)
(declare-fun c_47_2 () Bool)
(declare-fun c_47_1 () Bool)
(declare-fun c_47_0 () Bool)
(declare-fun c_48_8 () Bool)
(declare-fun c_48_7 () Bool)
(declare-fun c_48_6 () Bool)
(declare-fun c_48_5 () Bool)
(declare-fun c_48_4 () Bool)
(declare-fun c_48_3 () Bool)
(declare-fun c_48_2 () Bool)
(declare-fun c_48_1 () Bool)
(declare-fun c_48_0 () Bool)
(declare-fun c_49_8 () Bool)
(declare-fun c_49_7 () Bool)
(declare-fun c_49_6 () Bool)
(declare-fun c_49_5 () Bool)
(declare-fun c_49_4 () Bool)
(declare-fun c_49_3 () Bool)
(declare-fun c_49_2 () Bool)
(declare-fun c_49_1 () Bool)
(declare-fun c_49_0 () Bool)
(declare-fun c_50_8 () Bool)
(declare-fun c_50_7 () Bool)
(declare-fun c_50_6 () Bool)
(declare-fun c_50_5 () Bool)
(declare-fun c_50_4 () Bool)
(declare-fun c_50_3 () Bool)
(declare-fun c_50_2 () Bool)
(declare-fun c_50_1 () Bool)
(declare-fun c_50_0 () Bool)
(declare-fun c_51_8 () Bool)
(declare-fun c_51_7 () Bool)
(declare-fun c_51_6 () Bool)
(declare-fun c_51_5 () Bool)
(declare-fun c_51_4 () Bool)
(declare-fun c_51_3 () Bool)
(declare-fun c_51_2 () Bool)
(declare-fun c_51_1 () Bool)
(declare-fun c_51_0 () Bool)
(declare-fun c_52_8 () Bool)
(declare-fun c_52_7 () Bool)
(declare-fun c_52_6 () Bool)
(declare-fun c_52_5 () Bool)
(declare-fun c_52_4 () Bool)
(declare-fun c_52_3 () Bool)
(declare-fun c_52_2 () Bool)
(declare-fun c_52_1 () Bool)
(declare-fun c_52_0 () Bool)
(declare-fun c_53_8 () Bool)
(declare-fun c_53_7 () Bool)
(declare-fun c_53_6 () Bool)
(declare-fun c_53_5 () Bool)
(declare-fun c_53_4 () Bool)
(declare-fun c_53_3 () Bool)
(declare-fun c_53_2 () Bool)
(declare-fun c_53_1 () Bool)
(declare-fun c_53_0 () Bool)
(declare-fun c_54_8 () Bool)
(declare-fun c_54_7 () Bool)
(declare-fun c_54_6 () Bool)
(declare-fun c_54_5 () Bool)
(declare-fun c_54_4 () Bool)
(declare-fun c_54_3 () Bool)
(declare-fun c_54_2 () Bool)
(declare-fun c_54_1 () Bool)
(declare-fun c_54_0 () Bool)
(declare-fun c_55_8 () Bool)
(declare-fun c_55_7 () Bool)
(declare-fun c_55_6 () Bool)
(declare-fun c_55_5 () Bool)
(declare-fun c_55_4 () Bool)
(declare-fun c_55_3 () Bool)
(declare-fun c_55_2 () Bool)
(declare-fun c_55_1 () Bool)
(declare-fun c_55_0 () Bool)
(declare-fun c_56_8 () Bool)
(declare-fun c_56_7 () Bool)
(declare-fun c_56_6 () Bool)
(declare-fun c_56_5 () Bool)
(declare-fun c_56_4 () Bool)
(declare-fun c_56_3 () Bool)
(declare-fun c_56_2 () Bool)
(declare-fun c_56_1 () Bool)
(declare-fun c_56_0 () Bool)
(declare-fun c_57_8 () Bool)
(declare-fun c_57_7 () Bool)
(declare-fun c_57_6 () Bool)
(declare-fun c_57_5 () Bool)
(declare-fun c_57_4 () Bool)
(declare-fun c_57_3 () Bool)
(declare-fun c_57_2 () Bool)
(declare-fun c_57_1 () Bool)
(declare-fun c_57_0 () Bool)
(declare-fun c_58_8 () Bool)
(declare-fun c_58_7 () Bool)
(declare-fun c_58_6 () Bool)
(declare-fun c_58_5 () Bool)
(declare-fun c_58_4 () Bool)
(declare-fun c_58_3 () Bool)
(declare-fun c_58_2 () Bool)
(declare-fun c_58_1 () Bool)
(declare-fun c_58_0 () Bool)
(declare-fun c_59_8 () Bool)
(declare-fun c_59_7 () Bool)
(declare-fun c_59_6 () Bool)
(declare-fun c_59_5 () Bool)
(declare-fun c_59_4 () Bool)
(declare-fun c_59_3 () Bool)
(declare-fun c_59_2 () Bool)
(declare-fun c_59_1 () Bool)
(declare-fun c_59_0 () Bool)
(declare-fun c_60_8 () Bool)
(declare-fun c_60_7 () Bool)
(declare-fun c_60_6 () Bool)
(declare-fun c_60_5 () Bool)
(declare-fun c_60_4 () Bool)
(declare-fun c_60_3 () Bool)
(declare-fun c_60_2 () Bool)
(declare-fun c_60_1 () Bool)
(declare-fun c_60_0 () Bool)
(declare-fun c_61_8 () Bool)
(declare-fun c_61_7 () Bool)
(declare-fun c_61_6 () Bool)
(declare-fun c_61_5 () Bool)
(declare-fun c_61_4 () Bool)
(declare-fun c_61_3 () Bool)
(declare-fun c_61_2 () Bool)
(declare-fun c_61_1 () Bool)
(declare-fun c_61_0 () Bool)
(declare-fun c_62_8 () Bool)
(declare-fun c_62_7 () Bool)
(declare-fun c_62_6 () Bool)
(declare-fun c_62_5 () Bool)
(declare-fun c_62_4 () Bool)
(declare-fun c_62_3 () Bool)
(declare-fun c_62_2 () Bool)
(declare-fun c_62_1 () Bool)
(declare-fun c_62_0 () Bool)
(declare-fun c_63_8 () Bool)
(declare-fun c_63_7 () Bool)
(declare-fun c_63_6 () Bool)
(declare-fun c_63_5 () Bool)
(declare-fun c_63_4 () Bool)
(declare-fun c_63_3 () Bool)
(declare-fun c_63_2 () Bool)
(declare-fun c_63_1 () Bool)
(declare-fun c_63_0 () Bool)
(declare-fun c_64_8 () Bool)
(declare-fun c_64_7 () Bool)
(declare-fun c_64_6 () Bool)
(declare-fun c_64_5 () Bool)
(declare-fun c_64_4 () Bool)
(declare-fun c_64_3 () Bool)
(declare-fun c_64_2 () Bool)
(declare-fun c_64_1 () Bool)
(declare-fun c_64_0 () Bool)
(declare-fun c_65_8 () Bool)
(declare-fun c_65_7 () Bool)
(declare-fun c_65_6 () Bool)
(declare-fun c_65_5 () Bool)
(declare-fun c_65_4 () Bool)
(declare-fun c_65_3 () Bool)
(declare-fun c_65_2 () Bool)
(declare-fun c_65_1 () Bool)
(declare-fun c_65_0 () Bool)
(declare-fun c_66_8 () Bool)
(declare-fun c_66_7 () Bool)
(declare-fun c_66_6 () Bool)
(declare-fun c_66_5 () Bool)
(declare-fun c_66_4 () Bool)
(declare-fun c_66_3 () Bool)
(declare-fun c_66_2 () Bool)
(declare-fun c_66_1 () Bool)
(declare-fun c_66_0 () Bool)
(declare-fun c_67_8 () Bool)
(declare-fun c_67_7 () Bool)
(declare-fun c_67_6 () Bool)
(declare-fun c_67_5 () Bool)
(declare-fun c_67_4 () Bool)
(declare-fun c_67_3 () Bool)
(declare-fun c_67_2 () Bool)
(declare-fun c_67_1 () Bool)
(declare-fun c_67_0 () Bool)
(declare-fun c_68_8 () Bool)
(declare-fun c_68_7 () Bool)
(declare-fun c_68_6 () Bool)
(declare-fun c_68_5 () Bool)
(declare-fun c_68_4 () Bool)
(declare-fun c_68_3 () Bool)
(declare-fun c_68_2 () Bool)
(declare-fun c_68_1 () Bool)
(declare-fun c_68_0 () Bool)
(declare-fun c_69_8 () Bool)
(declare-fun c_69_7 () Bool)
(declare-fun c_69_6 () Bool)
(declare-fun c_69_5 () Bool)
(declare-fun c_69_4 () Bool)
(declare-fun c_69_3 () Bool)
(declare-fun c_69_2 () Bool)
(declare-fun c_69_1 () Bool)
(declare-fun c_69_0 () Bool)
(declare-fun c_70_8 () Bool)
(declare-fun c_70_7 () Bool)
(declare-fun c_70_6 () Bool)
(declare-fun c_70_5 () Bool)
(declare-fun c_70_4 () Bool)
(declare-fun c_70_3 () Bool)
(declare-fun c_70_2 () Bool)
(declare-fun c_70_1 () Bool)
(declare-fun c_70_0 () Bool)
(declare-fun c_71_8 () Bool)
(declare-fun c_71_7 () Bool)
(declare-fun c_71_6 () Bool)
(declare-fun c_71_5 () Bool)
(declare-fun c_71_4 () Bool)
(declare-fun c_71_3 () Bool)
(declare-fun c_71_2 () Bool)
(declare-fun c_71_1 () Bool)
(declare-fun c_71_0 () Bool)
(declare-fun c_72_8 () Bool)
(declare-fun c_72_7 () Bool)
(declare-fun c_72_6 () Bool)
(declare-fun c_72_5 () Bool)
(declare-fun c_72_4 () Bool)
(declare-fun c_72_3 () Bool)
(declare-fun c_72_2 () Bool)
(declare-fun c_72_1 () Bool)
(declare-fun c_72_0 () Bool)
(declare-fun c_73_8 () Bool)
(declare-fun c_73_7 () Bool)
(declare-fun c_73_6 () Bool)
(declare-fun c_73_5 () Bool)
(declare-fun c_73_4 () Bool)
(declare-fun c_73_3 () Bool)
(declare-fun c_73_2 () Bool)
(declare-fun c_73_1 () Bool)
(declare-fun c_73_0 () Bool)
(declare-fun c_74_8 () Bool)
(declare-fun c_74_7 () Bool)
(declare-fun c_74_6 () Bool)
(declare-fun c_74_5 () Bool)
(declare-fun c_74_4 () Bool)
(declare-fun c_74_3 () Bool)
(declare-fun c_74_2 () Bool)
(declare-fun c_74_1 () Bool)
(declare-fun c_74_0 () Bool)
(declare-fun c_75_8 () Bool)
(declare-fun c_75_7 () Bool)
(declare-fun c_75_6 () Bool)
(declare-fun c_75_5 () Bool)
(declare-fun c_75_4 () Bool)
(declare-fun c_75_3 () Bool)
(declare-fun c_75_2 () Bool)
(declare-fun c_75_1 () Bool)
(declare-fun c_75_0 () Bool)
(declare-fun c_76_8 () Bool)
(declare-fun c_76_7 () Bool)
(declare-fun c_76_6 () Bool)
(declare-fun c_76_5 () Bool)
(declare-fun c_76_4 () Bool)
(declare-fun c_76_3 () Bool)
(declare-fun c_76_2 () Bool)
(declare-fun c_76_1 () Bool)
(declare-fun c_76_0 () Bool)
(declare-fun c_77_8 () Bool)
(declare-fun c_77_7 () Bool)
(declare-fun c_77_6 () Bool)
(declare-fun c_77_5 () Bool)
(declare-fun c_77_4 () Bool)
(declare-fun c_77_3 () Bool)
(declare-fun c_77_2 () Bool)
(declare-fun c_77_1 () Bool)
(declare-fun c_77_0 () Bool)
(declare-fun c_78_8 () Bool)
(declare-fun c_78_7 () Bool)
(declare-fun c_78_6 () Bool)
(declare-fun c_78_5 () Bool)
(declare-fun c_78_4 () Bool)
(declare-fun c_78_3 () Bool)
(declare-fun c_78_2 () Bool)
(declare-fun c_78_1 () Bool)
(declare-fun c_78_0 () Bool)
(declare-fun c_79_8 () Bool)
(declare-fun c_79_7 () Bool)
(declare-fun c_79_6 () Bool)
(declare-fun c_79_5 () Bool)
(declare-fun c_79_4 () Bool)
(declare-fun c_79_3 () Bool)
(declare-fun c_79_2 () Bool)
(declare-fun c_79_1 () Bool)
(declare-fun c_79_0 () Bool)
(declare-fun c_80_8 () Bool)
(declare-fun c_80_7 () Bool)
(declare-fun c_80_6 () Bool)
(declare-fun c_80_5 () Bool)
(declare-fun c_80_4 () Bool)
(declare-fun c_80_3 () Bool)
(declare-fun c_80_2 () Bool)
(declare-fun c_80_1 () Bool)
(declare-fun c_80_0 () Bool)
(declare-fun c_81_8 () Bool)
(declare-fun c_81_7 () Bool)
(declare-fun c_81_6 () Bool)
(declare-fun c_81_5 () Bool)
(declare-fun c_81_4 () Bool)
(declare-fun c_81_3 () Bool)
(declare-fun c_81_2 () Bool)
(declare-fun c_81_1 () Bool)
(declare-fun c_81_0 () Bool)
(declare-fun c_82_8 () Bool)
(declare-fun c_82_7 () Bool)
(declare-fun c_82_6 () Bool)
(declare-fun c_82_5 () Bool)
(declare-fun c_82_4 () Bool)
(declare-fun c_82_3 () Bool)
(declare-fun c_82_2 () Bool)
(declare-fun c_82_1 () Bool)
(declare-fun c_82_0 () Bool)
(declare-fun c_83_8 () Bool)
(declare-fun c_83_7 () Bool)
(declare-fun c_83_6 () Bool)
(declare-fun c_83_5 () Bool)
(declare-fun c_83_4 () Bool)
(declare-fun c_83_3 () Bool)
(declare-fun c_83_2 () Bool)
(declare-fun c_83_1 () Bool)
(declare-fun c_83_0 () Bool)
(declare-fun c_84_8 () Bool)
(declare-fun c_84_7 () Bool)
(declare-fun c_84_6 () Bool)
(declare-fun c_84_5 () Bool)
(declare-fun c_84_4 () Bool)
(declare-fun c_84_3 () Bool)
(declare-fun c_84_2 () Bool)
(declare-fun c_84_1 () Bool)
(declare-fun c_84_0 () Bool)
(declare-fun c_85_8 () Bool)
(declare-fun c_85_7 () Bool)
(declare-fun c_85_6 () Bool)
(declare-fun c_85_5 () Bool)
(declare-fun c_85_4 () Bool)
(declare-fun c_85_3 () Bool)
(declare-fun c_85_2 () Bool)
(declare-fun c_85_1 () Bool)
(declare-fun c_85_0 () Bool)
(declare-fun c_86_8 () Bool)
(declare-fun c_86_7 () Bool)
(declare-fun c_86_6 () Bool)
(declare-fun c_86_5 () Bool)
(declare-fun c_86_4 () Bool)
(declare-fun c_86_3 () Bool)
(declare-fun c_86_2 () Bool)
(declare-fun c_86_1 () Bool)
(declare-fun c_86_0 () Bool)
(declare-fun c_87_8 () Bool)
(declare-fun c_87_7 () Bool)
(declare-fun c_87_6 () Bool)
(declare-fun c_87_5 () Bool)
(declare-fun c_87_4 () Bool)
(declare-fun c_87_3 () Bool)
(declare-fun c_87_2 () Bool)
(declare-fun c_87_1 () Bool)
(declare-fun c_87_0 () Bool)
(declare-fun c_88_8 () Bool)
(declare-fun c_88_7 () Bool)
(declare-fun c_88_6 () Bool)
(declare-fun c_88_5 () Bool)
(declare-fun c_88_4 () Bool)
(declare-fun c_88_3 () Bool)
(declare-fun c_88_2 () Bool)
(declare-fun c_88_1 () Bool)
(declare-fun c_88_0 () Bool)
(declare-fun c_89_8 () Bool)
(declare-fun c_89_7 () Bool)
(declare-fun c_89_6 () Bool)
(declare-fun c_89_5 () Bool)
(declare-fun c_89_4 () Bool)
(declare-fun c_89_3 () Bool)
(declare-fun c_89_2 () Bool)
(declare-fun c_89_1 () Bool)
(declare-fun c_89_0 () Bool)
(declare-fun c_90_8 () Bool)
(declare-fun c_90_7 () Bool)
(declare-fun c_90_6 () Bool)
(declare-fun c_90_5 () Bool)
(declare-fun c_90_4 () Bool)
(declare-fun c_90_3 () Bool)
(declare-fun c_90_2 () Bool)
(declare-fun c_90_1 () Bool)
(declare-fun c_90_0 () Bool)
(declare-fun d_0_8 () Bool)
(declare-fun d_0_7 () Bool)
(declare-fun d_0_6 () Bool)
(declare-fun d_0_5 () Bool)
(declare-fun d_0_4 () Bool)
(declare-fun d_0_3 () Bool)
(declare-fun d_0_2 () Bool)
(declare-fun d_0_1 () Bool)
(declare-fun d_0_0 () Bool)
(declare-fun d_1_8 () Bool)
(declare-fun d_1_7 () Bool)
(declare-fun d_1_6 () Bool)
(declare-fun d_1_5 () Bool)
(declare-fun d_1_4 () Bool)
(declare-fun d_1_3 () Bool)
(declare-fun d_1_2 () Bool)
(declare-fun d_1_1 () Bool)
(declare-fun d_1_0 () Bool)
(declare-fun d_2_8 () Bool)
(declare-fun d_2_7 () Bool)
(declare-fun d_2_6 () Bool)
(declare-fun d_2_5 () Bool)
(declare-fun d_2_4 () Bool)
(declare-fun d_2_3 () Bool)
(declare-fun d_2_2 () Bool)
(declare-fun d_2_1 () Bool)
(declare-fun d_2_0 () Bool)
(declare-fun d_3_8 () Bool)
(declare-fun d_3_7 () Bool)
(declare-fun d_3_6 () Bool)
(declare-fun d_3_5 () Bool)
(declare-fun d_3_4 () Bool)
(declare-fun d_3_3 () Bool)
(declare-fun d_3_2 () Bool)
(declare-fun d_3_1 () Bool)
(declare-fun d_3_0 () Bool)
(declare-fun d_4_8 () Bool)
(declare-fun d_4_7 () Bool)
(declare-fun d_4_6 () Bool)
(declare-fun d_4_5 () Bool)
(declare-fun d_4_4 () Bool)
(declare-fun d_4_3 () Bool)
(declare-fun d_4_2 () Bool)
(declare-fun d_4_1 () Bool)
(declare-fun d_4_0 () Bool)
(declare-fun d_5_8 () Bool)
(declare-fun d_5_7 () Bool)
(declare-fun d_5_6 () Bool)
(declare-fun d_5_5 () Bool)
(declare-fun d_5_4 () Bool)
(declare-fun d_5_3 () Bool)
(declare-fun d_5_2 () Bool)
(declare-fun d_5_1 () Bool)
(declare-fun d_5_0 () Bool)
(declare-fun d_6_8 () Bool)
(declare-fun d_6_7 () Bool)
(declare-fun d_6_6 () Bool)
(declare-fun d_6_5 () Bool)
(declare-fun d_6_4 () Bool)
(declare-fun d_6_3 () Bool)
(declare-fun d_6_2 () Bool)
(declare-fun d_6_1 () Bool)
(declare-fun d_6_0 () Bool)
(declare-fun d_7_8 () Bool)
(declare-fun d_7_7 () Bool)
(declare-fun d_7_6 () Bool)
(declare-fun d_7_5 () Bool)
(declare-fun d_7_4 () Bool)
(declare-fun d_7_3 () Bool)
(declare-fun d_7_2 () Bool)
(declare-fun d_7_1 () Bool)
(declare-fun d_7_0 () Bool)
(declare-fun d_8_8 () Bool)
(declare-fun d_8_7 () Bool)
(declare-fun d_8_6 () Bool)
(declare-fun d_8_5 () Bool)
(declare-fun d_8_4 () Bool)
(declare-fun d_8_3 () Bool)
(declare-fun d_8_2 () Bool)
(declare-fun d_8_1 () Bool)
(declare-fun d_8_0 () Bool)
(declare-fun d_9_8 () Bool)
(declare-fun d_9_7 () Bool)
(declare-fun d_9_6 () Bool)
(declare-fun d_9_5 () Bool)
(declare-fun d_9_4 () Bool)
(declare-fun d_9_3 () Bool)
(declare-fun d_9_2 () Bool)
(declare-fun d_9_1 () Bool)
(declare-fun d_9_0 () Bool)
(declare-fun d_10_8 () Bool)
(declare-fun d_10_7 () Bool)
(declare-fun d_10_6 () Bool)
(declare-fun d_10_5 () Bool)
(declare-fun d_10_4 () Bool)
(declare-fun d_10_3 () Bool)
(declare-fun d_10_2 () Bool)
(declare-fun d_10_1 () Bool)
(declare-fun d_10_0 () Bool)
(declare-fun d_11_8 () Bool)
(declare-fun d_11_7 () Bool)
(declare-fun d_11_6 () Bool)
(declare-fun d_11_5 () Bool)
(declare-fun d_11_4 () Bool)
(declare-fun d_11_3 () Bool)
(declare-fun d_11_2 () Bool)
(declare-fun d_11_1 () Bool)
(declare-fun d_11_0 () Bool)
(declare-fun d_12_8 () Bool)
(declare-fun d_12_7 () Bool)
(declare-fun d_12_6 () Bool)
(declare-fun d_12_5 () Bool)
(declare-fun d_12_4 () Bool)
(declare-fun d_12_3 () Bool)
(declare-fun d_12_2 () Bool)
(declare-fun d_12_1 () Bool)
(declare-fun d_12_0 () Bool)
(declare-fun d_13_8 () Bool)
(declare-fun d_13_7 () Bool)
(declare-fun d_13_6 () Bool)
(declare-fun d_13_5 () Bool)
(declare-fun d_13_4 () Bool)
(declare-fun d_13_3 () Bool)
(declare-fun d_13_2 () Bool)
(declare-fun d_13_1 () Bool)
(declare-fun d_13_0 () Bool)
(declare-fun d_14_8 () Bool)
(declare-fun d_14_7 () Bool)
(declare-fun d_14_6 () Bool)
(declare-fun d_14_5 () Bool)
(declare-fun d_14_4 () Bool)
(declare-fun d_14_3 () Bool)
(declare-fun d_14_2 () Bool)
(declare-fun d_14_1 () Bool)
(declare-fun d_14_0 () Bool)
(declare-fun d_15_8 () Bool)
(declare-fun d_15_7 () Bool)
(declare-fun d_15_6 () Bool)
(declare-fun d_15_5 () Bool)
(declare-fun d_15_4 () Bool)
(declare-fun d_15_3 () Bool)
(declare-fun d_15_2 () Bool)
(declare-fun d_15_1 () Bool)
(declare-fun d_15_0 () Bool)
(declare-fun d_16_8 () Bool)
(declare-fun d_16_7 () Bool)
(declare-fun d_16_6 () Bool)
(declare-fun d_16_5 () Bool)
(declare-fun d_16_4 () Bool)
(declare-fun d_16_3 () Bool)
(declare-fun d_16_2 () Bool)
(declare-fun d_16_1 () Bool)
(declare-fun d_16_0 () Bool)
(declare-fun d_17_8 () Bool)
(declare-fun d_17_7 () Bool)
(declare-fun d_17_6 () Bool)
(declare-fun d_17_5 () Bool)
(declare-fun d_17_4 () Bool)
(declare-fun d_17_3 () Bool)
(declare-fun d_17_2 () Bool)
(declare-fun d_17_1 () Bool)
(declare-fun d_17_0 () Bool)
(declare-fun d_18_8 () Bool)
(declare-fun d_18_7 () Bool)
(declare-fun d_18_6 () Bool)
(declare-fun d_18_5 () Bool)
(declare-fun d_18_4 () Bool)
(declare-fun d_18_3 () Bool)
(declare-fun d_18_2 () Bool)
(declare-fun d_18_1 () Bool)
(declare-fun d_18_0 () Bool)
(declare-fun d_19_8 () Bool)
(declare-fun d_19_7 () Bool)
(declare-fun d_19_6 () Bool)
(declare-fun d_19_5 () Bool)
(declare-fun d_19_4 () Bool)
(declare-fun d_19_3 () Bool)
(declare-fun d_19_2 () Bool)
(declare-fun d_19_1 () Bool)
(declare-fun d_19_0 () Bool)
(declare-fun d_20_8 () Bool)
(declare-fun d_20_7 () Bool)
(declare-fun d_20_6 () Bool)
(declare-fun d_20_5 () Bool)
(declare-fun d_20_4 () Bool)
(declare-fun d_20_3 () Bool)
(declare-fun d_20_2 () Bool)
(declare-fun d_20_1 () Bool)
(declare-fun d_20_0 () Bool)
(declare-fun d_21_8 () Bool)
(declare-fun d_21_7 () Bool)
(declare-fun d_21_6 () Bool)
(declare-fun d_21_5 () Bool)
(declare-fun d_21_4 () Bool)
(declare-fun d_21_3 () Bool)
(declare-fun d_21_2 () Bool)
(declare-fun d_21_1 () Bool)
(declare-fun d_21_0 () Bool)
(declare-fun d_22_8 () Bool)
(declare-fun d_22_7 () Bool)
(declare-fun d_22_6 () Bool)
(declare-fun d_22_5 () Bool)
(declare-fun d_22_4 () Bool)
(declare-fun d_22_3 () Bool)
(declare-fun d_22_2 () Bool)
(declare-fun d_22_1 () Bool)
(declare-fun d_22_0 () Bool)
(declare-fun d_23_8 () Bool)
(declare-fun d_23_7 () Bool)
(declare-fun d_23_6 () Bool)
(declare-fun d_23_5 () Bool)
(declare-fun d_23_4 () Bool)
(declare-fun d_23_3 () Bool)
(declare-fun d_23_2 () Bool)
(declare-fun d_23_1 () Bool)
(declare-fun d_23_0 () Bool)
(declare-fun d_24_8 () Bool)
(declare-fun d_24_7 () Bool)
(declare-fun d_24_6 () Bool)
(declare-fun d_24_5 () Bool)
(declare-fun d_24_4 () Bool)
(declare-fun d_24_3 () Bool)
(declare-fun d_24_2 () Bool)
(declare-fun d_24_1 () Bool)
(declare-fun d_24_0 () Bool)
(declare-fun d_25_8 () Bool)
(declare-fun d_25_7 () Bool)
(declare-fun d_25_6 () Bool)
(declare-fun d_25_5 () Bool)
(declare-fun d_25_4 () Bool)
(declare-fun d_25_3 () Bool)
(declare-fun d_25_2 () Bool)
(declare-fun d_25_1 () Bool)
(declare-fun d_25_0 () Bool)
(declare-fun d_26_8 () Bool)
(declare-fun d_26_7 () Bool)
(declare-fun d_26_6 () Bool)
(declare-fun d_26_5 () Bool)
(declare-fun d_26_4 () Bool)
(declare-fun d_26_3 () Bool)
(declare-fun d_26_2 () Bool)
(declare-fun d_26_1 () Bool)
(declare-fun d_26_0 () Bool)
(declare-fun d_27_8 () Bool)
(declare-fun d_27_7 () Bool)
(declare-fun d_27_6 () Bool)
(declare-fun d_27_5 () Bool)
(declare-fun d_27_4 () Bool)
(declare-fun d_27_3 () Bool)
(declare-fun d_27_2 () Bool)
(declare-fun d_27_1 () Bool)
(declare-fun d_27_0 () Bool)
(declare-fun d_28_8 () Bool)
(declare-fun d_28_7 () Bool)
(declare-fun d_28_6 () Bool)
(declare-fun d_28_5 () Bool)
(declare-fun d_28_4 () Bool)
(declare-fun d_28_3 () Bool)
(declare-fun d_28_2 () Bool)
(declare-fun d_28_1 () Bool)
(declare-fun d_28_0 () Bool)
(declare-fun d_29_8 () Bool)
(declare-fun d_29_7 () Bool)
(declare-fun d_29_6 () Bool)
(declare-fun d_29_5 () Bool)
(declare-fun d_29_4 () Bool)
(declare-fun d_29_3 () Bool)
(declare-fun d_29_2 () Bool)
(declare-fun d_29_1 () Bool)
(declare-fun d_29_0 () Bool)
(declare-fun d_30_8 () Bool)
(declare-fun d_30_7 () Bool)
(declare-fun d_30_6 () Bool)
(declare-fun d_30_5 () Bool)
(declare-fun d_30_4 () Bool)
(declare-fun d_30_3 () Bool)
(declare-fun d_30_2 () Bool)
(declare-fun d_30_1 () Bool)
(declare-fun d_30_0 () Bool)
(declare-fun d_31_8 () Bool)
(declare-fun d_31_7 () Bool)
(declare-fun d_31_6 () Bool)
(declare-fun d_31_5 () Bool)
(declare-fun d_31_4 () Bool)
(declare-fun d_31_3 () Bool)
(declare-fun d_31_2 () Bool)
(declare-fun d_31_1 () Bool)
(declare-fun d_31_0 () Bool)
(declare-fun d_32_8 () Bool)
(declare-fun d_32_7 () Bool)
(declare-fun d_32_6 () Bool)
(declare-fun d_32_5 () Bool)
(declare-fun d_32_4 () Bool)
(declare-fun d_32_3 () Bool)
(declare-fun d_32_2 () Bool)
(declare-fun d_32_1 () Bool)
(declare-fun d_32_0 () Bool)
(declare-fun d_33_8 () Bool)
(declare-fun d_33_7 () Bool)
(declare-fun d_33_6 () Bool)
(declare-fun d_33_5 () Bool)
(declare-fun d_33_4 () Bool)
(declare-fun d_33_3 () Bool)
(declare-fun d_33_2 () Bool)
(declare-fun d_33_1 () Bool)
(declare-fun d_33_0 () Bool)
(declare-fun d_34_8 () Bool)
(declare-fun d_34_7 () Bool)
(declare-fun d_34_6 () Bool)
(declare-fun d_34_5 () Bool)
(declare-fun d_34_4 () Bool)
(declare-fun d_34_3 () Bool)
(declare-fun d_34_2 () Bool)
(declare-fun d_34_1 () Bool)
(declare-fun d_34_0 () Bool)
(declare-fun d_35_8 () Bool)
(declare-fun d_35_7 () Bool)
(declare-fun d_35_6 () Bool)
(declare-fun d_35_5 () Bool)
(declare-fun d_35_4 () Bool)
(declare-fun d_35_3 () Bool)
(declare-fun d_35_2 () Bool)
(declare-fun d_35_1 () Bool)
(declare-fun d_35_0 () Bool)
(declare-fun d_36_8 () Bool)
(declare-fun d_36_7 () Bool)
(declare-fun d_36_6 () Bool)
(declare-fun d_36_5 () Bool)
(declare-fun d_36_4 () Bool)
(declare-fun d_36_3 () Bool)
(declare-fun d_36_2 () Bool)
(declare-fun d_36_1 () Bool)
(declare-fun d_36_0 () Bool)
(declare-fun d_37_8 () Bool)
(declare-fun d_37_7 () Bool)
(declare-fun d_37_6 () Bool)
(declare-fun d_37_5 () Bool)
(declare-fun d_37_4 () Bool)
(declare-fun d_37_3 () Bool)
(declare-fun d_37_2 () Bool)
(declare-fun d_37_1 () Bool)
(declare-fun d_37_0 () Bool)
(declare-fun d_38_8 () Bool)
(declare-fun d_38_7 () Bool)
(declare-fun d_38_6 () Bool)
(declare-fun d_38_5 () Bool)
(declare-fun d_38_4 () Bool)
(declare-fun d_38_3 () Bool)
(declare-fun d_38_2 () Bool)
(declare-fun d_38_1 () Bool)
(declare-fun d_38_0 () Bool)
(declare-fun d_39_8 () Bool)
(declare-fun d_39_7 () Bool)
(declare-fun d_39_6 () Bool)
(declare-fun d_39_5 () Bool)
(declare-fun d_39_4 () Bool)
(declare-fun d_39_3 () Bool)
(declare-fun d_39_2 () Bool)
(declare-fun d_39_1 () Bool)
(declare-fun d_39_0 () Bool)
(declare-fun d_40_8 () Bool)
(declare-fun d_40_7 () Bool)
(declare-fun d_40_6 () Bool)
(declare-fun d_40_5 () Bool)
(declare-fun d_40_4 () Bool)
(declare-fun d_40_3 () Bool)
(declare-fun d_40_2 () Bool)
(declare-fun d_40_1 () Bool)
(declare-fun d_40_0 () Bool)
(declare-fun d_41_8 () Bool)
(declare-fun d_41_7 () Bool)
(declare-fun d_41_6 () Bool)
(declare-fun d_41_5 () Bool)
(declare-fun d_41_4 () Bool)
(declare-fun d_41_3 () Bool)
(declare-fun d_41_2 () Bool)
(declare-fun d_41_1 () Bool)
(declare-fun d_41_0 () Bool)
(declare-fun d_42_8 () Bool)
(declare-fun d_42_7 () Bool)
(declare-fun d_42_6 () Bool)
(declare-fun d_42_5 () Bool)
(declare-fun d_42_4 () Bool)
(declare-fun d_42_3 () Bool)
(declare-fun d_42_2 () Bool)
(declare-fun d_42_1 () Bool)
(declare-fun d_42_0 () Bool)
(declare-fun d_43_8 () Bool)
(declare-fun d_43_7 () Bool)
(declare-fun d_43_6 () Bool)
(declare-fun d_43_5 () Bool)
(declare-fun d_43_4 () Bool)
(declare-fun d_43_3 () Bool)
(declare-fun d_43_2 () Bool)
(declare-fun d_43_1 () Bool)
(declare-fun d_43_0 () Bool)
(declare-fun d_44_8 () Bool)
(declare-fun d_44_7 () Bool)
(declare-fun d_44_6 () Bool)
(declare-fun d_44_5 () Bool)
(declare-fun d_44_4 () Bool)
(declare-fun d_44_3 () Bool)
(declare-fun d_44_2 () Bool)
(declare-fun d_44_1 () Bool)
(declare-fun d_44_0 () Bool)
(declare-fun d_45_8 () Bool)
(declare-fun d_45_7 () Bool)
(declare-fun d_45_6 () Bool)
(declare-fun d_45_5 () Bool)
(declare-fun d_45_4 () Bool)
(declare-fun d_45_3 () Bool)
(declare-fun d_45_2 () Bool)
(declare-fun d_45_1 () Bool)
(declare-fun d_45_0 () Bool)
(declare-fun d_46_8 () Bool)
(declare-fun d_46_7 () Bool)
(declare-fun d_46_6 () Bool)
(declare-fun d_46_5 () Bool)
(declare-fun d_46_4 () Bool)
(declare-fun d_46_3 () Bool)
(declare-fun d_46_2 () Bool)
(declare-fun d_46_1 () Bool)
(declare-fun d_46_0 () Bool)
(declare-fun d_47_8 () Bool)
(declare-fun d_47_7 () Bool)
(declare-fun d_47_6 () Bool)
(declare-fun d_47_5 () Bool)
(declare-fun d_47_4 () Bool)
(declare-fun d_47_3 () Bool)
(declare-fun d_47_2 () Bool)
(declare-fun d_47_1 () Bool)
(declare-fun d_47_0 () Bool)
(declare-fun d_48_8 () Bool)
(declare-fun d_48_7 () Bool)
(declare-fun d_48_6 () Bool)
(declare-fun d_48_5 () Bool)
(declare-fun d_48_4 () Bool)
(declare-fun d_48_3 () Bool)
(declare-fun d_48_2 () Bool)
(declare-fun d_48_1 () Bool)
(declare-fun d_48_0 () Bool)
(declare-fun d_49_8 () Bool)
(declare-fun d_49_7 () Bool)
(declare-fun d_49_6 () Bool)
(declare-fun d_49_5 () Bool)
(declare-fun d_49_4 () Bool)
(declare-fun d_49_3 () Bool)
(declare-fun d_49_2 () Bool)
(declare-fun d_49_1 () Bool)
(declare-fun d_49_0 () Bool)
(declare-fun d_50_8 () Bool)
(declare-fun d_50_7 () Bool)
(declare-fun d_50_6 () Bool)
(declare-fun d_50_5 () Bool)
(declare-fun d_50_4 () Bool)
(declare-fun d_50_3 () Bool)
(declare-fun d_50_2 () Bool)
(declare-fun d_50_1 () Bool)
(declare-fun d_50_0 () Bool)
(declare-fun d_51_8 () Bool)
(declare-fun d_51_7 () Bool)
(declare-fun d_51_6 () Bool)
(declare-fun d_51_5 () Bool)
(declare-fun d_51_4 () Bool)
(declare-fun d_51_3 () Bool)
(declare-fun d_51_2 () Bool)
(declare-fun d_51_1 () Bool)
(declare-fun d_51_0 () Bool)
(declare-fun d_52_8 () Bool)
(declare-fun d_52_7 () Bool)
(declare-fun d_52_6 () Bool)
(declare-fun d_52_5 () Bool)
(declare-fun d_52_4 () Bool)
(declare-fun d_52_3 () Bool)
(declare-fun d_52_2 () Bool)
(declare-fun d_52_1 () Bool)
(declare-fun d_52_0 () Bool)
(declare-fun d_53_8 () Bool)
(declare-fun d_53_7 () Bool)
(declare-fun d_53_6 () Bool)
(declare-fun d_53_5 () Bool)
(declare-fun d_53_4 () Bool)
(declare-fun d_53_3 () Bool)
(declare-fun d_53_2 () Bool)
(declare-fun d_53_1 () Bool)
(declare-fun d_53_0 () Bool)
(declare-fun d_54_8 () Bool)
(declare-fun d_54_7 () Bool)
(declare-fun d_54_6 () Bool)
(declare-fun d_54_5 () Bool)
(declare-fun d_54_4 () Bool)
(declare-fun d_54_3 () Bool)
(declare-fun d_54_2 () Bool)
(declare-fun d_54_1 () Bool)
(declare-fun d_54_0 () Bool)
(declare-fun d_55_8 () Bool)
(declare-fun d_55_7 () Bool)
(declare-fun d_55_6 () Bool)
(declare-fun d_55_5 () Bool)
(declare-fun d_55_4 () Bool)
(declare-fun d_55_3 () Bool)
(declare-fun d_55_2 () Bool)
(declare-fun d_55_1 () Bool)
(declare-fun d_55_0 () Bool)
(declare-fun d_56_8 () Bool)
(declare-fun d_56_7 () Bool)
(declare-fun d_56_6 () Bool)
(declare-fun d_56_5 () Bool)
(declare-fun d_56_4 () Bool)
(declare-fun d_56_3 () Bool)
(declare-fun d_56_2 () Bool)
(declare-fun d_56_1 () Bool)
(declare-fun d_56_0 () Bool)
(declare-fun d_57_8 () Bool)
(declare-fun d_57_7 () Bool)
(declare-fun d_57_6 () Bool)
(declare-fun d_57_5 () Bool)
(declare-fun d_57_4 () Bool)
(declare-fun d_57_3 () Bool)
(declare-fun d_57_2 () Bool)
(declare-fun d_57_1 () Bool)
(declare-fun d_57_0 () Bool)
(declare-fun d_58_8 () Bool)
(declare-fun d_58_7 () Bool)
(declare-fun d_58_6 () Bool)
(declare-fun d_58_5 () Bool)
(declare-fun d_58_4 () Bool)
(declare-fun d_58_3 () Bool)
(declare-fun d_58_2 () Bool)
(declare-fun d_58_1 () Bool)
(declare-fun d_58_0 () Bool)
(declare-fun d_59_8 () Bool)
(declare-fun d_59_7 () Bool)
(declare-fun d_59_6 () Bool)
(declare-fun d_59_5 () Bool)
(declare-fun d_59_4 () Bool)
(declare-fun d_59_3 () Bool)
(declare-fun d_59_2 () Bool)
(declare-fun d_59_1 () Bool)
(declare-fun d_59_0 () Bool)
(declare-fun d_60_8 () Bool)
(declare-fun d_60_7 () Bool)
(declare-fun d_60_6 () Bool)
(declare-fun d_60_5 () Bool)
(declare-fun d_60_4 () Bool)
(declare-fun d_60_3 () Bool)
(declare-fun d_60_2 () Bool)
(declare-fun d_60_1 () Bool)
(declare-fun d_60_0 () Bool)
(declare-fun d_61_8 () Bool)
(declare-fun d_61_7 () Bool)
(declare-fun d_61_6 () Bool)
(declare-fun d_61_5 () Bool)
(declare-fun d_61_4 () Bool)
(declare-fun d_61_3 () Bool)
(declare-fun d_61_2 () Bool)
(declare-fun d_61_1 () Bool)
(declare-fun d_61_0 () Bool)
(declare-fun d_62_8 () Bool)
(declare-fun d_62_7 () Bool)
(declare-fun d_62_6 () Bool)
(declare-fun d_62_5 () Bool)
(declare-fun d_62_4 () Bool)
(declare-fun d_62_3 () Bool)
(declare-fun d_62_2 () Bool)
(declare-fun d_62_1 () Bool)
(declare-fun d_62_0 () Bool)
(declare-fun d_63_8 () Bool)
(declare-fun d_63_7 () Bool)
(declare-fun d_63_6 () Bool)
(declare-fun d_63_5 () Bool)
(declare-fun d_63_4 () Bool)
(declare-fun d_63_3 () Bool)
(declare-fun d_63_2 () Bool)
(declare-fun d_63_1 () Bool)
(declare-fun d_63_0 () Bool)
(declare-fun d_64_8 () Bool)
(declare-fun d_64_7 () Bool)
(declare-fun d_64_6 () Bool)
(declare-fun d_64_5 () Bool)
(declare-fun d_64_4 () Bool)
(declare-fun d_64_3 () Bool)
(declare-fun d_64_2 () Bool)
(declare-fun d_64_1 () Bool)
(declare-fun d_64_0 () Bool)
(declare-fun d_65_8 () Bool)
(declare-fun d_65_7 () Bool)
(declare-fun d_65_6 () Bool)
(declare-fun d_65_5 () Bool)
(declare-fun d_65_4 () Bool)
(declare-fun d_65_3 () Bool)
(declare-fun d_65_2 () Bool)
(declare-fun d_65_1 () Bool)
(declare-fun d_65_0 () Bool)
(declare-fun d_66_8 () Bool)
(declare-fun d_66_7 () Bool)
(declare-fun d_66_6 () Bool)
(declare-fun d_66_5 () Bool)
(declare-fun d_66_4 () Bool)
(declare-fun d_66_3 () Bool)
(declare-fun d_66_2 () Bool)
(declare-fun d_66_1 () Bool)
(declare-fun d_66_0 () Bool)
(declare-fun d_67_8 () Bool)
(declare-fun d_67_7 () Bool)
(declare-fun d_67_6 () Bool)
(declare-fun d_67_5 () Bool)
(declare-fun d_67_4 () Bool)
(declare-fun d_67_3 () Bool)
(declare-fun d_67_2 () Bool)
(declare-fun d_67_1 () Bool)
(declare-fun d_67_0 () Bool)
(declare-fun d_68_8 () Bool)
(declare-fun d_68_7 () Bool)
(declare-fun d_68_6 () Bool)
(declare-fun d_68_5 () Bool)
(declare-fun d_68_4 () Bool)
(declare-fun d_68_3 () Bool)
(declare-fun d_68_2 () Bool)
(declare-fun d_68_1 () Bool)
(declare-fun d_68_0 () Bool)
(declare-fun d_69_8 () Bool)
(declare-fun d_69_7 () Bool)
(declare-fun d_69_6 () Bool)
(declare-fun d_69_5 () Bool)
(declare-fun d_69_4 () Bool)
(declare-fun d_69_3 () Bool)
(declare-fun d_69_2 () Bool)
(declare-fun d_69_1 () Bool)
(declare-fun d_69_0 () Bool)
(declare-fun d_70_8 () Bool)
(declare-fun d_70_7 () Bool)
(declare-fun d_70_6 () Bool)
(declare-fun d_70_5 () Bool)
(declare-fun d_70_4 () Bool)
(declare-fun d_70_3 () Bool)
(declare-fun d_70_2 () Bool)
(declare-fun d_70_1 () Bool)
(declare-fun d_70_0 () Bool)
(declare-fun d_71_8 () Bool)
(declare-fun d_71_7 () Bool)
(declare-fun d_71_6 () Bool)
(declare-fun d_71_5 () Bool)
(declare-fun d_71_4 () Bool)
(declare-fun d_71_3 () Bool)
(declare-fun d_71_2 () Bool)
(declare-fun d_71_1 () Bool)
(declare-fun d_71_0 () Bool)
(declare-fun d_72_8 () Bool)
(declare-fun d_72_7 () Bool)
(declare-fun d_72_6 () Bool)
(declare-fun d_72_5 () Bool)
(declare-fun d_72_4 () Bool)
(declare-fun d_72_3 () Bool)
(declare-fun d_72_2 () Bool)
(declare-fun d_72_1 () Bool)
(declare-fun d_72_0 () Bool)
(declare-fun d_73_8 () Bool)
(declare-fun d_73_7 () Bool)
(declare-fun d_73_6 () Bool)
(declare-fun d_73_5 () Bool)
(declare-fun d_73_4 () Bool)
(declare-fun d_73_3 () Bool)
(declare-fun d_73_2 () Bool)
(declare-fun d_73_1 () Bool)
(declare-fun d_73_0 () Bool)
(declare-fun d_74_8 () Bool)
(declare-fun d_74_7 () Bool)
(declare-fun d_74_6 () Bool)
(declare-fun d_74_5 () Bool)
(declare-fun d_74_4 () Bool)
(declare-fun d_74_3 () Bool)
(declare-fun d_74_2 () Bool)
(declare-fun d_74_1 () Bool)
(declare-fun d_74_0 () Bool)
(declare-fun d_75_8 () Bool)
(declare-fun d_75_7 () Bool)
(declare-fun d_75_6 () Bool)
(declare-fun d_75_5 () Bool)
(declare-fun d_75_4 () Bool)
(declare-fun d_75_3 () Bool)
(declare-fun d_75_2 () Bool)
(declare-fun d_75_1 () Bool)
(declare-fun d_75_0 () Bool)
(declare-fun d_76_8 () Bool)
(declare-fun d_76_7 () Bool)
(declare-fun d_76_6 () Bool)
(declare-fun d_76_5 () Bool)
(declare-fun d_76_4 () Bool)
(declare-fun d_76_3 () Bool)
(declare-fun d_76_2 () Bool)
(declare-fun d_76_1 () Bool)
(declare-fun d_76_0 () Bool)
(declare-fun d_77_8 () Bool)
(declare-fun d_77_7 () Bool)
(declare-fun d_77_6 () Bool)
(declare-fun d_77_5 () Bool)
(declare-fun d_77_4 () Bool)
(declare-fun d_77_3 () Bool)
(declare-fun d_77_2 () Bool)
(declare-fun d_77_1 () Bool)
(declare-fun d_77_0 () Bool)
(declare-fun d_78_8 () Bool)
(declare-fun d_78_7 () Bool)
(declare-fun d_78_6 () Bool)
(declare-fun d_78_5 () Bool)
(declare-fun d_78_4 () Bool)
(declare-fun d_78_3 () Bool)
(declare-fun d_78_2 () Bool)
(declare-fun d_78_1 () Bool)
(declare-fun d_78_0 () Bool)
(declare-fun d_79_8 () Bool)
(declare-fun d_79_7 () Bool)
(declare-fun d_79_6 () Bool)
(declare-fun d_79_5 () Bool)
(declare-fun d_79_4 () Bool)
(declare-fun d_79_3 () Bool)
(declare-fun d_79_2 () Bool)
(declare-fun d_79_1 () Bool)
(declare-fun d_79_0 () Bool)
(declare-fun d_80_8 () Bool)
(declare-fun d_80_7 () Bool)
(declare-fun d_80_6 () Bool)
(declare-fun d_80_5 () Bool)
(declare-fun d_80_4 () Bool)
(declare-fun d_80_3 () Bool)
(declare-fun d_80_2 () Bool)
(declare-fun d_80_1 () Bool)
(declare-fun d_80_0 () Bool)
(declare-fun d_81_8 () Bool)
(declare-fun d_81_7 () Bool)
(declare-fun d_81_6 () Bool)
(declare-fun d_81_5 () Bool)
(declare-fun d_81_4 () Bool)
(declare-fun d_81_3 () Bool)
(declare-fun d_81_2 () Bool)
(declare-fun d_81_1 () Bool)
(declare-fun d_81_0 () Bool)
(declare-fun d_82_8 () Bool)
(declare-fun d_82_7 () Bool)
(declare-fun d_82_6 () Bool)
(declare-fun d_82_5 () Bool)
(declare-fun d_82_4 () Bool)
(declare-fun d_82_3 () Bool)
(declare-fun d_82_2 () Bool)
(declare-fun d_82_1 () Bool)
(declare-fun d_82_0 () Bool)
(declare-fun d_83_8 () Bool)
(declare-fun d_83_7 () Bool)
(declare-fun d_83_6 () Bool)
(declare-fun d_83_5 () Bool)
(declare-fun d_83_4 () Bool)
(declare-fun d_83_3 () Bool)
(declare-fun d_83_2 () Bool)
(declare-fun d_83_1 () Bool)
(declare-fun d_83_0 () Bool)
(declare-fun d_84_8 () Bool)
(declare-fun d_84_7 () Bool)
(declare-fun d_84_6 () Bool)
(declare-fun d_84_5 () Bool)
(declare-fun d_84_4 () Bool)
(declare-fun d_84_3 () Bool)
(declare-fun d_84_2 () Bool)
(declare-fun d_84_1 () Bool)
(declare-fun d_84_0 () Bool)
(declare-fun d_85_8 () Bool)
(declare-fun d_85_7 () Bool)
(declare-fun d_85_6 () Bool)
(declare-fun d_85_5 () Bool)
(declare-fun d_85_4 () Bool)
(declare-fun d_85_3 () Bool)
(declare-fun d_85_2 () Bool)
(declare-fun d_85_1 () Bool)
(declare-fun d_85_0 () Bool)
(declare-fun d_86_8 () Bool)
(declare-fun d_86_7 () Bool)
(declare-fun d_86_6 () Bool)
(declare-fun d_86_5 () Bool)
(declare-fun d_86_4 () Bool)
(declare-fun d_86_3 () Bool)
(declare-fun d_86_2 () Bool)
(declare-fun d_86_1 () Bool)
(declare-fun d_86_0 () Bool)
(declare-fun d_87_8 () Bool)
(declare-fun d_87_7 () Bool)
(declare-fun d_87_6 () Bool)
(declare-fun d_87_5 () Bool)
(declare-fun d_87_4 () Bool)
(declare-fun d_87_3 () Bool)
(declare-fun d_87_2 () Bool)
(declare-fun d_87_1 () Bool)
(declare-fun d_87_0 () Bool)
(declare-fun d_88_8 () Bool)
(declare-fun d_88_7 () Bool)
(declare-fun d_88_6 () Bool)
(declare-fun d_88_5 () Bool)
(declare-fun d_88_4 () Bool)
(declare-fun d_88_3 () Bool)
(declare-fun d_88_2 () Bool)
(declare-fun d_88_1 () Bool)
(declare-fun d_88_0 () Bool)
(declare-fun d_89_8 () Bool)
(declare-fun d_89_7 () Bool)
(declare-fun d_89_6 () Bool)
(declare-fun d_89_5 () Bool)
(declare-fun d_89_4 () Bool)
(declare-fun d_89_3 () Bool)
(declare-fun d_89_2 () Bool)
(declare-fun d_89_1 () Bool)
(declare-fun d_89_0 () Bool)
(declare-fun d_90_8 () Bool)
(declare-fun d_90_7 () Bool)
(declare-fun d_90_6 () Bool)
(declare-fun d_90_5 () Bool)
(declare-fun d_90_4 () Bool)
(declare-fun d_90_3 () Bool)
(declare-fun d_90_2 () Bool)
(declare-fun d_90_1 () Bool)
(declare-fun d_90_0 () Bool)
(declare-fun in_target_0 () Bool)
(declare-fun in_target_6 () Bool)
(declare-fun in_region_6 () Bool)
(declare-fun ghost_2_0 () Int)
(declare-fun ghost_2_6 () Int)
(declare-fun ghost_1_0 () Int)
(declare-fun ghost_1_6 () Int)
(declare-fun in_target_5 () Bool)
(declare-fun in_region_5 () Bool)
(declare-fun ghost_2_5 () Int)
(declare-fun ghost_1_5 () Int)
(declare-fun in_target_4 () Bool)
(declare-fun in_region_4 () Bool)
(declare-fun ghost_2_4 () Int)
(declare-fun ghost_1_4 () Int)
(declare-fun in_target_3 () Bool)
(declare-fun in_region_3 () Bool)
(declare-fun ghost_2_3 () Int)
(declare-fun ghost_1_3 () Int)
(declare-fun in_target_2 () Bool)
(declare-fun in_region_2 () Bool)
(declare-fun ghost_2_2 () Int)
(declare-fun ghost_1_2 () Int)
(declare-fun in_target_1 () Bool)
(declare-fun in_region_1 () Bool)
(declare-fun ghost_2_1 () Int)
(declare-fun ghost_1_1 () Int)
(declare-fun in_region_0 () Bool)
(declare-fun in_region_13 () Bool)
(declare-fun in_region_12 () Bool)
(declare-fun in_region_11 () Bool)
(declare-fun in_target_18 () Bool)
(declare-fun in_region_18 () Bool)
(declare-fun in_target_17 () Bool)
(declare-fun in_region_17 () Bool)
(declare-fun in_target_9 () Bool)
(declare-fun in_region_9 () Bool)
(declare-fun in_region_10 () Bool)
(declare-fun in_region_8 () Bool)
(declare-fun in_target_16 () Bool)
(declare-fun in_region_16 () Bool)
(declare-fun in_target_15 () Bool)
(declare-fun in_region_15 () Bool)
(declare-fun in_region_7 () Bool)
(declare-fun in_target_14 () Bool)
(declare-fun in_region_14 () Bool)
(declare-fun in_target_13 () Bool)
(declare-fun in_target_12 () Bool)
(declare-fun in_target_11 () Bool)
(declare-fun in_target_10 () Bool)
(declare-fun in_target_8 () Bool)
(declare-fun in_target_7 () Bool)
(declare-fun ghost_2_60 () Int)
(declare-fun ghost_2_90 () Int)
(declare-fun in_target_90 () Bool)
(declare-fun ghost_2_89 () Int)
(declare-fun in_target_89 () Bool)
(declare-fun ghost_2_59 () Int)
(declare-fun in_target_59 () Bool)
(declare-fun ghost_2_36 () Int)
(declare-fun in_target_36 () Bool)
(declare-fun ghost_2_43 () Int)
(declare-fun in_target_43 () Bool)
(declare-fun ghost_2_69 () Int)
(declare-fun in_target_69 () Bool)
(declare-fun in_target_60 () Bool)
(declare-fun ghost_2_88 () Int)
(declare-fun in_target_88 () Bool)
(declare-fun ghost_2_58 () Int)
(declare-fun in_target_58 () Bool)
(declare-fun ghost_2_35 () Int)
(declare-fun in_target_35 () Bool)
(declare-fun ghost_2_87 () Int)
(declare-fun in_target_87 () Bool)
(declare-fun ghost_2_57 () Int)
(declare-fun in_target_57 () Bool)
(declare-fun ghost_2_34 () Int)
(declare-fun in_target_34 () Bool)
(declare-fun ghost_2_86 () Int)
(declare-fun in_target_86 () Bool)
(declare-fun ghost_2_56 () Int)
(declare-fun in_target_56 () Bool)
(declare-fun ghost_2_33 () Int)
(declare-fun in_target_33 () Bool)
(declare-fun ghost_2_85 () Int)
(declare-fun in_target_85 () Bool)
(declare-fun ghost_2_84 () Int)
(declare-fun in_target_84 () Bool)
(declare-fun ghost_2_55 () Int)
(declare-fun in_target_55 () Bool)
(declare-fun ghost_2_83 () Int)
(declare-fun in_target_83 () Bool)
(declare-fun ghost_2_54 () Int)
(declare-fun in_target_54 () Bool)
(declare-fun ghost_2_32 () Int)
(declare-fun in_target_32 () Bool)
(declare-fun ghost_2_82 () Int)
(declare-fun in_target_82 () Bool)
(declare-fun ghost_2_53 () Int)
(declare-fun in_target_53 () Bool)
(declare-fun ghost_2_31 () Int)
(declare-fun in_target_31 () Bool)
(declare-fun ghost_2_81 () Int)
(declare-fun in_target_81 () Bool)
(declare-fun ghost_2_52 () Int)
(declare-fun in_target_52 () Bool)
(declare-fun ghost_2_30 () Int)
(declare-fun in_target_30 () Bool)
(declare-fun ghost_2_80 () Int)
(declare-fun in_target_80 () Bool)
(declare-fun ghost_2_79 () Int)
(declare-fun in_target_79 () Bool)
(declare-fun ghost_2_51 () Int)
(declare-fun in_target_51 () Bool)
(declare-fun ghost_2_78 () Int)
(declare-fun in_target_78 () Bool)
(declare-fun ghost_2_50 () Int)
(declare-fun in_target_50 () Bool)
(declare-fun ghost_2_29 () Int)
(declare-fun in_target_29 () Bool)
(declare-fun ghost_2_77 () Int)
(declare-fun in_target_77 () Bool)
(declare-fun ghost_2_49 () Int)
(declare-fun in_target_49 () Bool)
(declare-fun ghost_2_28 () Int)
(declare-fun in_target_28 () Bool)
(declare-fun ghost_2_76 () Int)
(declare-fun in_target_76 () Bool)
(declare-fun ghost_2_48 () Int)
(declare-fun in_target_48 () Bool)
(declare-fun ghost_2_27 () Int)
(declare-fun in_target_27 () Bool)
(declare-fun ghost_2_75 () Int)
(declare-fun in_target_75 () Bool)
(declare-fun ghost_2_74 () Int)
(declare-fun in_target_74 () Bool)
(declare-fun ghost_2_47 () Int)
(declare-fun in_target_47 () Bool)
(declare-fun ghost_2_26 () Int)
(declare-fun in_target_26 () Bool)
(declare-fun ghost_2_73 () Int)
(declare-fun in_target_73 () Bool)
(declare-fun ghost_2_46 () Int)
(declare-fun in_target_46 () Bool)
(declare-fun ghost_2_25 () Int)
(declare-fun in_target_25 () Bool)
(declare-fun ghost_2_72 () Int)
(declare-fun in_target_72 () Bool)
(declare-fun ghost_2_45 () Int)
(declare-fun in_target_45 () Bool)
(declare-fun ghost_2_24 () Int)
(declare-fun in_target_24 () Bool)
(declare-fun ghost_2_71 () Int)
(declare-fun in_target_71 () Bool)
(declare-fun ghost_2_44 () Int)
(declare-fun in_target_44 () Bool)
(declare-fun ghost_2_42 () Int)
(declare-fun in_target_42 () Bool)
(declare-fun ghost_2_70 () Int)
(declare-fun in_target_70 () Bool)
(declare-fun ghost_2_68 () Int)
(declare-fun in_target_68 () Bool)
(declare-fun ghost_2_23 () Int)
(declare-fun in_target_23 () Bool)
(declare-fun ghost_2_41 () Int)
(declare-fun in_target_41 () Bool)
(declare-fun ghost_2_67 () Int)
(declare-fun in_target_67 () Bool)
(declare-fun ghost_2_40 () Int)
(declare-fun in_target_40 () Bool)
(declare-fun ghost_2_22 () Int)
(declare-fun in_target_22 () Bool)
(declare-fun ghost_2_66 () Int)
(declare-fun in_target_66 () Bool)
(declare-fun ghost_2_21 () Int)
(declare-fun in_target_21 () Bool)
(declare-fun ghost_2_39 () Int)
(declare-fun in_target_39 () Bool)
(declare-fun ghost_2_65 () Int)
(declare-fun in_target_65 () Bool)
(declare-fun ghost_2_38 () Int)
(declare-fun in_target_38 () Bool)
(declare-fun ghost_2_20 () Int)
(declare-fun in_target_20 () Bool)
(declare-fun ghost_2_64 () Int)
(declare-fun in_target_64 () Bool)
(declare-fun ghost_2_19 () Int)
(declare-fun in_target_19 () Bool)
(declare-fun ghost_2_37 () Int)
(declare-fun in_target_37 () Bool)
(declare-fun ghost_2_63 () Int)
(declare-fun in_target_63 () Bool)
(declare-fun ghost_2_62 () Int)
(declare-fun in_target_62 () Bool)
(declare-fun ghost_2_61 () Int)
(declare-fun in_target_61 () Bool)
(declare-fun ghost_2_18 () Int)
(declare-fun ghost_2_17 () Int)
(declare-fun ghost_2_16 () Int)
(declare-fun ghost_2_15 () Int)
(declare-fun ghost_2_14 () Int)
(declare-fun ghost_2_13 () Int)
(declare-fun ghost_2_12 () Int)
(declare-fun ghost_2_11 () Int)
(declare-fun ghost_2_10 () Int)
(declare-fun ghost_2_9 () Int)
(declare-fun ghost_2_8 () Int)
(declare-fun ghost_2_7 () Int)
(declare-fun ghost_1_60 () Int)
(declare-fun ghost_1_90 () Int)
(declare-fun ghost_1_89 () Int)
(declare-fun ghost_1_59 () Int)
(declare-fun ghost_1_36 () Int)
(declare-fun ghost_1_43 () Int)
(declare-fun ghost_1_69 () Int)
(declare-fun ghost_1_88 () Int)
(declare-fun ghost_1_58 () Int)
(declare-fun ghost_1_35 () Int)
(declare-fun ghost_1_87 () Int)
(declare-fun ghost_1_57 () Int)
(declare-fun ghost_1_34 () Int)
(declare-fun ghost_1_86 () Int)
(declare-fun ghost_1_56 () Int)
(declare-fun ghost_1_33 () Int)
(declare-fun ghost_1_85 () Int)
(declare-fun ghost_1_84 () Int)
(declare-fun ghost_1_55 () Int)
(declare-fun ghost_1_83 () Int)
(declare-fun ghost_1_54 () Int)
(declare-fun ghost_1_32 () Int)
(declare-fun ghost_1_82 () Int)
(declare-fun ghost_1_53 () Int)
(declare-fun ghost_1_31 () Int)
(declare-fun ghost_1_81 () Int)
(declare-fun ghost_1_52 () Int)
(declare-fun ghost_1_30 () Int)
(declare-fun ghost_1_80 () Int)
(declare-fun ghost_1_79 () Int)
(declare-fun ghost_1_51 () Int)
(declare-fun ghost_1_78 () Int)
(declare-fun ghost_1_50 () Int)
(declare-fun ghost_1_29 () Int)
(declare-fun ghost_1_77 () Int)
(declare-fun ghost_1_49 () Int)
(declare-fun ghost_1_28 () Int)
(declare-fun ghost_1_76 () Int)
(declare-fun ghost_1_48 () Int)
(declare-fun ghost_1_27 () Int)
(declare-fun ghost_1_75 () Int)
(declare-fun ghost_1_74 () Int)
(declare-fun ghost_1_47 () Int)
(declare-fun ghost_1_26 () Int)
(declare-fun ghost_1_73 () Int)
(declare-fun ghost_1_46 () Int)
(declare-fun ghost_1_25 () Int)
(declare-fun ghost_1_72 () Int)
(declare-fun ghost_1_45 () Int)
(declare-fun ghost_1_24 () Int)
(declare-fun ghost_1_71 () Int)
(declare-fun ghost_1_44 () Int)
(declare-fun ghost_1_42 () Int)
(declare-fun ghost_1_70 () Int)
(declare-fun ghost_1_68 () Int)
(declare-fun ghost_1_23 () Int)
(declare-fun ghost_1_41 () Int)
(declare-fun ghost_1_67 () Int)
(declare-fun ghost_1_40 () Int)
(declare-fun ghost_1_22 () Int)
(declare-fun ghost_1_66 () Int)
(declare-fun ghost_1_21 () Int)
(declare-fun ghost_1_39 () Int)
(declare-fun ghost_1_65 () Int)
(declare-fun ghost_1_38 () Int)
(declare-fun ghost_1_20 () Int)
(declare-fun ghost_1_64 () Int)
(declare-fun ghost_1_19 () Int)
(declare-fun ghost_1_37 () Int)
(declare-fun ghost_1_63 () Int)
(declare-fun ghost_1_62 () Int)
(declare-fun ghost_1_61 () Int)
(declare-fun ghost_1_18 () Int)
(declare-fun ghost_1_17 () Int)
(declare-fun ghost_1_16 () Int)
(declare-fun ghost_1_15 () Int)
(declare-fun ghost_1_14 () Int)
(declare-fun ghost_1_13 () Int)
(declare-fun ghost_1_12 () Int)
(declare-fun ghost_1_11 () Int)
(declare-fun ghost_1_10 () Int)
(declare-fun ghost_1_9 () Int)
(declare-fun ghost_1_8 () Int)
(declare-fun ghost_1_7 () Int)
(declare-fun in_region_90 () Bool)
(declare-fun in_region_89 () Bool)
(declare-fun in_region_88 () Bool)
(declare-fun in_region_87 () Bool)
(declare-fun in_region_86 () Bool)
(declare-fun in_region_85 () Bool)
(declare-fun in_region_84 () Bool)
(declare-fun in_region_83 () Bool)
(declare-fun in_region_82 () Bool)
(declare-fun in_region_81 () Bool)
(declare-fun in_region_80 () Bool)
(declare-fun in_region_79 () Bool)
(declare-fun in_region_78 () Bool)
(declare-fun in_region_77 () Bool)
(declare-fun in_region_76 () Bool)
(declare-fun in_region_75 () Bool)
(declare-fun in_region_74 () Bool)
(declare-fun in_region_73 () Bool)
(declare-fun in_region_72 () Bool)
(declare-fun in_region_71 () Bool)
(declare-fun in_region_70 () Bool)
(declare-fun in_region_69 () Bool)
(declare-fun in_region_68 () Bool)
(declare-fun in_region_67 () Bool)
(declare-fun in_region_66 () Bool)
(declare-fun in_region_65 () Bool)
(declare-fun in_region_64 () Bool)
(declare-fun in_region_63 () Bool)
(declare-fun in_region_62 () Bool)
(declare-fun in_region_61 () Bool)
(declare-fun in_region_60 () Bool)
(declare-fun in_region_59 () Bool)
(declare-fun in_region_58 () Bool)
(declare-fun in_region_57 () Bool)
(declare-fun in_region_56 () Bool)
(declare-fun in_region_55 () Bool)
(declare-fun in_region_54 () Bool)
(declare-fun in_region_53 () Bool)
(declare-fun in_region_52 () Bool)
(declare-fun in_region_51 () Bool)
(declare-fun in_region_50 () Bool)
(declare-fun in_region_49 () Bool)
(declare-fun in_region_48 () Bool)
(declare-fun in_region_47 () Bool)
(declare-fun in_region_46 () Bool)
(declare-fun in_region_45 () Bool)
(declare-fun in_region_44 () Bool)
(declare-fun in_region_43 () Bool)
(declare-fun in_region_42 () Bool)
(declare-fun in_region_41 () Bool)
(declare-fun in_region_40 () Bool)
(declare-fun in_region_39 () Bool)
(declare-fun in_region_38 () Bool)
(declare-fun in_region_37 () Bool)
(declare-fun in_region_36 () Bool)
(declare-fun in_region_35 () Bool)
(declare-fun in_region_34 () Bool)
(declare-fun in_region_33 () Bool)
(declare-fun in_region_32 () Bool)
(declare-fun in_region_31 () Bool)
(declare-fun in_region_30 () Bool)
(declare-fun in_region_29 () Bool)
(declare-fun in_region_28 () Bool)
(declare-fun in_region_27 () Bool)
(declare-fun in_region_26 () Bool)
(declare-fun in_region_25 () Bool)
(declare-fun in_region_24 () Bool)
(declare-fun in_region_23 () Bool)
(declare-fun in_region_22 () Bool)
(declare-fun in_region_21 () Bool)
(declare-fun in_region_20 () Bool)
(declare-fun in_region_19 () Bool)
(declare-fun instance_0 () Bool)
(assert
 (let (($x97 (or false c_0_0)))
 (let (($x99 (or $x97 c_0_1)))
 (let (($x101 (or $x99 c_0_2)))
 (let (($x103 (or $x101 c_0_3)))
 (let (($x105 (or $x103 c_0_4)))
 (let (($x107 (or $x105 c_0_5)))
 (let (($x109 (or $x107 c_0_6)))
 (let (($x111 (or $x109 c_0_7)))
 (or $x111 c_0_8))))))))))
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
 (not (and c_0_4 c_0_5)))
(assert
 (not (and c_0_4 c_0_6)))
(assert
 (not (and c_0_4 c_0_7)))
(assert
 (not (and c_0_4 c_0_8)))
(assert
 (not (and c_0_5 c_0_6)))
(assert
 (not (and c_0_5 c_0_7)))
(assert
 (not (and c_0_5 c_0_8)))
(assert
 (not (and c_0_6 c_0_7)))
(assert
 (not (and c_0_6 c_0_8)))
(assert
 (not (and c_0_7 c_0_8)))
(assert
 (let (($x187 (or false c_1_0)))
 (let (($x189 (or $x187 c_1_1)))
 (let (($x191 (or $x189 c_1_2)))
 (let (($x193 (or $x191 c_1_3)))
 (let (($x195 (or $x193 c_1_4)))
 (let (($x197 (or $x195 c_1_5)))
 (let (($x199 (or $x197 c_1_6)))
 (let (($x201 (or $x199 c_1_7)))
 (or $x201 c_1_8))))))))))
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
 (not (and c_1_4 c_1_5)))
(assert
 (not (and c_1_4 c_1_6)))
(assert
 (not (and c_1_4 c_1_7)))
(assert
 (not (and c_1_4 c_1_8)))
(assert
 (not (and c_1_5 c_1_6)))
(assert
 (not (and c_1_5 c_1_7)))
(assert
 (not (and c_1_5 c_1_8)))
(assert
 (not (and c_1_6 c_1_7)))
(assert
 (not (and c_1_6 c_1_8)))
(assert
 (not (and c_1_7 c_1_8)))
(assert
 (let (($x277 (or false c_2_0)))
 (let (($x279 (or $x277 c_2_1)))
 (let (($x281 (or $x279 c_2_2)))
 (let (($x283 (or $x281 c_2_3)))
 (let (($x285 (or $x283 c_2_4)))
 (let (($x287 (or $x285 c_2_5)))
 (let (($x289 (or $x287 c_2_6)))
 (let (($x291 (or $x289 c_2_7)))
 (or $x291 c_2_8))))))))))
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
 (not (and c_2_4 c_2_5)))
(assert
 (not (and c_2_4 c_2_6)))
(assert
 (not (and c_2_4 c_2_7)))
(assert
 (not (and c_2_4 c_2_8)))
(assert
 (not (and c_2_5 c_2_6)))
(assert
 (not (and c_2_5 c_2_7)))
(assert
 (not (and c_2_5 c_2_8)))
(assert
 (not (and c_2_6 c_2_7)))
(assert
 (not (and c_2_6 c_2_8)))
(assert
 (not (and c_2_7 c_2_8)))
(assert
 (let (($x367 (or false c_3_0)))
 (let (($x369 (or $x367 c_3_1)))
 (let (($x371 (or $x369 c_3_2)))
 (let (($x373 (or $x371 c_3_3)))
 (let (($x375 (or $x373 c_3_4)))
 (let (($x377 (or $x375 c_3_5)))
 (let (($x379 (or $x377 c_3_6)))
 (let (($x381 (or $x379 c_3_7)))
 (or $x381 c_3_8))))))))))
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
 (not (and c_3_4 c_3_5)))
(assert
 (not (and c_3_4 c_3_6)))
(assert
 (not (and c_3_4 c_3_7)))
(assert
 (not (and c_3_4 c_3_8)))
(assert
 (not (and c_3_5 c_3_6)))
(assert
 (not (and c_3_5 c_3_7)))
(assert
 (not (and c_3_5 c_3_8)))
(assert
 (not (and c_3_6 c_3_7)))
(assert
 (not (and c_3_6 c_3_8)))
(assert
 (not (and c_3_7 c_3_8)))
(assert
 (let (($x457 (or false c_4_0)))
 (let (($x459 (or $x457 c_4_1)))
 (let (($x461 (or $x459 c_4_2)))
 (let (($x463 (or $x461 c_4_3)))
 (let (($x465 (or $x463 c_4_4)))
 (let (($x467 (or $x465 c_4_5)))
 (let (($x469 (or $x467 c_4_6)))
 (let (($x471 (or $x469 c_4_7)))
 (or $x471 c_4_8))))))))))
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
 (not (and c_4_4 c_4_5)))
(assert
 (not (and c_4_4 c_4_6)))
(assert
 (not (and c_4_4 c_4_7)))
(assert
 (not (and c_4_4 c_4_8)))
(assert
 (not (and c_4_5 c_4_6)))
(assert
 (not (and c_4_5 c_4_7)))
(assert
 (not (and c_4_5 c_4_8)))
(assert
 (not (and c_4_6 c_4_7)))
(assert
 (not (and c_4_6 c_4_8)))
(assert
 (not (and c_4_7 c_4_8)))
(assert
 (let (($x547 (or false c_5_0)))
 (let (($x549 (or $x547 c_5_1)))
 (let (($x551 (or $x549 c_5_2)))
 (let (($x553 (or $x551 c_5_3)))
 (let (($x555 (or $x553 c_5_4)))
 (let (($x557 (or $x555 c_5_5)))
 (let (($x559 (or $x557 c_5_6)))
 (let (($x561 (or $x559 c_5_7)))
 (or $x561 c_5_8))))))))))
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
 (not (and c_5_4 c_5_5)))
(assert
 (not (and c_5_4 c_5_6)))
(assert
 (not (and c_5_4 c_5_7)))
(assert
 (not (and c_5_4 c_5_8)))
(assert
 (not (and c_5_5 c_5_6)))
(assert
 (not (and c_5_5 c_5_7)))
(assert
 (not (and c_5_5 c_5_8)))
(assert
 (not (and c_5_6 c_5_7)))
(assert
 (not (and c_5_6 c_5_8)))
(assert
 (not (and c_5_7 c_5_8)))
(assert
 (let (($x637 (or false c_6_0)))
 (let (($x639 (or $x637 c_6_1)))
 (let (($x641 (or $x639 c_6_2)))
 (let (($x643 (or $x641 c_6_3)))
 (let (($x645 (or $x643 c_6_4)))
 (let (($x647 (or $x645 c_6_5)))
 (let (($x649 (or $x647 c_6_6)))
 (let (($x651 (or $x649 c_6_7)))
 (or $x651 c_6_8))))))))))
(assert
 (not (and c_6_0 c_6_1)))
(assert
 (not (and c_6_0 c_6_2)))
(assert
 (not (and c_6_0 c_6_3)))
(assert
 (not (and c_6_0 c_6_4)))
(assert
 (not (and c_6_0 c_6_5)))
(assert
 (not (and c_6_0 c_6_6)))
(assert
 (not (and c_6_0 c_6_7)))
(assert
 (not (and c_6_0 c_6_8)))
(assert
 (not (and c_6_1 c_6_2)))
(assert
 (not (and c_6_1 c_6_3)))
(assert
 (not (and c_6_1 c_6_4)))
(assert
 (not (and c_6_1 c_6_5)))
(assert
 (not (and c_6_1 c_6_6)))
(assert
 (not (and c_6_1 c_6_7)))
(assert
 (not (and c_6_1 c_6_8)))
(assert
 (not (and c_6_2 c_6_3)))
(assert
 (not (and c_6_2 c_6_4)))
(assert
 (not (and c_6_2 c_6_5)))
(assert
 (not (and c_6_2 c_6_6)))
(assert
 (not (and c_6_2 c_6_7)))
(assert
 (not (and c_6_2 c_6_8)))
(assert
 (not (and c_6_3 c_6_4)))
(assert
 (not (and c_6_3 c_6_5)))
(assert
 (not (and c_6_3 c_6_6)))
(assert
 (not (and c_6_3 c_6_7)))
(assert
 (not (and c_6_3 c_6_8)))
(assert
 (not (and c_6_4 c_6_5)))
(assert
 (not (and c_6_4 c_6_6)))
(assert
 (not (and c_6_4 c_6_7)))
(assert
 (not (and c_6_4 c_6_8)))
(assert
 (not (and c_6_5 c_6_6)))
(assert
 (not (and c_6_5 c_6_7)))
(assert
 (not (and c_6_5 c_6_8)))
(assert
 (not (and c_6_6 c_6_7)))
(assert
 (not (and c_6_6 c_6_8)))
(assert
 (not (and c_6_7 c_6_8)))
(assert
 (let (($x727 (or false c_7_0)))
 (let (($x729 (or $x727 c_7_1)))
 (let (($x731 (or $x729 c_7_2)))
 (let (($x733 (or $x731 c_7_3)))
 (let (($x735 (or $x733 c_7_4)))
 (let (($x737 (or $x735 c_7_5)))
 (let (($x739 (or $x737 c_7_6)))
 (let (($x741 (or $x739 c_7_7)))
 (or $x741 c_7_8))))))))))
(assert
 (not (and c_7_0 c_7_1)))
(assert
 (not (and c_7_0 c_7_2)))
(assert
 (not (and c_7_0 c_7_3)))
(assert
 (not (and c_7_0 c_7_4)))
(assert
 (not (and c_7_0 c_7_5)))
(assert
 (not (and c_7_0 c_7_6)))
(assert
 (not (and c_7_0 c_7_7)))
(assert
 (not (and c_7_0 c_7_8)))
(assert
 (not (and c_7_1 c_7_2)))
(assert
 (not (and c_7_1 c_7_3)))
(assert
 (not (and c_7_1 c_7_4)))
(assert
 (not (and c_7_1 c_7_5)))
(assert
 (not (and c_7_1 c_7_6)))
(assert
 (not (and c_7_1 c_7_7)))
(assert
 (not (and c_7_1 c_7_8)))
(assert
 (not (and c_7_2 c_7_3)))
(assert
 (not (and c_7_2 c_7_4)))
(assert
 (not (and c_7_2 c_7_5)))
(assert
 (not (and c_7_2 c_7_6)))
(assert
 (not (and c_7_2 c_7_7)))
(assert
 (not (and c_7_2 c_7_8)))
(assert
 (not (and c_7_3 c_7_4)))
(assert
 (not (and c_7_3 c_7_5)))
(assert
 (not (and c_7_3 c_7_6)))
(assert
 (not (and c_7_3 c_7_7)))
(assert
 (not (and c_7_3 c_7_8)))
(assert
 (not (and c_7_4 c_7_5)))
(assert
 (not (and c_7_4 c_7_6)))
(assert
 (not (and c_7_4 c_7_7)))
(assert
 (not (and c_7_4 c_7_8)))
(assert
 (not (and c_7_5 c_7_6)))
(assert
 (not (and c_7_5 c_7_7)))
(assert
 (not (and c_7_5 c_7_8)))
(assert
 (not (and c_7_6 c_7_7)))
(assert
 (not (and c_7_6 c_7_8)))
(assert
 (not (and c_7_7 c_7_8)))
(assert
 (let (($x817 (or false c_8_0)))
 (let (($x819 (or $x817 c_8_1)))
 (let (($x821 (or $x819 c_8_2)))
 (let (($x823 (or $x821 c_8_3)))
 (let (($x825 (or $x823 c_8_4)))
 (let (($x827 (or $x825 c_8_5)))
 (let (($x829 (or $x827 c_8_6)))
 (let (($x831 (or $x829 c_8_7)))
 (or $x831 c_8_8))))))))))
(assert
 (not (and c_8_0 c_8_1)))
(assert
 (not (and c_8_0 c_8_2)))
(assert
 (not (and c_8_0 c_8_3)))
(assert
 (not (and c_8_0 c_8_4)))
(assert
 (not (and c_8_0 c_8_5)))
(assert
 (not (and c_8_0 c_8_6)))
(assert
 (not (and c_8_0 c_8_7)))
(assert
 (not (and c_8_0 c_8_8)))
(assert
 (not (and c_8_1 c_8_2)))
(assert
 (not (and c_8_1 c_8_3)))
(assert
 (not (and c_8_1 c_8_4)))
(assert
 (not (and c_8_1 c_8_5)))
(assert
 (not (and c_8_1 c_8_6)))
(assert
 (not (and c_8_1 c_8_7)))
(assert
 (not (and c_8_1 c_8_8)))
(assert
 (not (and c_8_2 c_8_3)))
(assert
 (not (and c_8_2 c_8_4)))
(assert
 (not (and c_8_2 c_8_5)))
(assert
 (not (and c_8_2 c_8_6)))
(assert
 (not (and c_8_2 c_8_7)))
(assert
 (not (and c_8_2 c_8_8)))
(assert
 (not (and c_8_3 c_8_4)))
(assert
 (not (and c_8_3 c_8_5)))
(assert
 (not (and c_8_3 c_8_6)))
(assert
 (not (and c_8_3 c_8_7)))
(assert
 (not (and c_8_3 c_8_8)))
(assert
 (not (and c_8_4 c_8_5)))
(assert
 (not (and c_8_4 c_8_6)))
(assert
 (not (and c_8_4 c_8_7)))
(assert
 (not (and c_8_4 c_8_8)))
(assert
 (not (and c_8_5 c_8_6)))
(assert
 (not (and c_8_5 c_8_7)))
(assert
 (not (and c_8_5 c_8_8)))
(assert
 (not (and c_8_6 c_8_7)))
(assert
 (not (and c_8_6 c_8_8)))
(assert
 (not (and c_8_7 c_8_8)))
(assert
 (let (($x907 (or false c_9_0)))
 (let (($x909 (or $x907 c_9_1)))
 (let (($x911 (or $x909 c_9_2)))
 (let (($x913 (or $x911 c_9_3)))
 (let (($x915 (or $x913 c_9_4)))
 (let (($x917 (or $x915 c_9_5)))
 (let (($x919 (or $x917 c_9_6)))
 (let (($x921 (or $x919 c_9_7)))
 (or $x921 c_9_8))))))))))
(assert
 (not (and c_9_0 c_9_1)))
(assert
 (not (and c_9_0 c_9_2)))
(assert
 (not (and c_9_0 c_9_3)))
(assert
 (not (and c_9_0 c_9_4)))
(assert
 (not (and c_9_0 c_9_5)))
(assert
 (not (and c_9_0 c_9_6)))
(assert
 (not (and c_9_0 c_9_7)))
(assert
 (not (and c_9_0 c_9_8)))
(assert
 (not (and c_9_1 c_9_2)))
(assert
 (not (and c_9_1 c_9_3)))
(assert
 (not (and c_9_1 c_9_4)))
(assert
 (not (and c_9_1 c_9_5)))
(assert
 (not (and c_9_1 c_9_6)))
(assert
 (not (and c_9_1 c_9_7)))
(assert
 (not (and c_9_1 c_9_8)))
(assert
 (not (and c_9_2 c_9_3)))
(assert
 (not (and c_9_2 c_9_4)))
(assert
 (not (and c_9_2 c_9_5)))
(assert
 (not (and c_9_2 c_9_6)))
(assert
 (not (and c_9_2 c_9_7)))
(assert
 (not (and c_9_2 c_9_8)))
(assert
 (not (and c_9_3 c_9_4)))
(assert
 (not (and c_9_3 c_9_5)))
(assert
 (not (and c_9_3 c_9_6)))
(assert
 (not (and c_9_3 c_9_7)))
(assert
 (not (and c_9_3 c_9_8)))
(assert
 (not (and c_9_4 c_9_5)))
(assert
 (not (and c_9_4 c_9_6)))
(assert
 (not (and c_9_4 c_9_7)))
(assert
 (not (and c_9_4 c_9_8)))
(assert
 (not (and c_9_5 c_9_6)))
(assert
 (not (and c_9_5 c_9_7)))
(assert
 (not (and c_9_5 c_9_8)))
(assert
 (not (and c_9_6 c_9_7)))
(assert
 (not (and c_9_6 c_9_8)))
(assert
 (not (and c_9_7 c_9_8)))
(assert
 (let (($x997 (or false c_10_0)))
 (let (($x999 (or $x997 c_10_1)))
 (let (($x1001 (or $x999 c_10_2)))
 (let (($x1003 (or $x1001 c_10_3)))
 (let (($x1005 (or $x1003 c_10_4)))
 (let (($x1007 (or $x1005 c_10_5)))
 (let (($x1009 (or $x1007 c_10_6)))
 (let (($x1011 (or $x1009 c_10_7)))
 (or $x1011 c_10_8))))))))))
(assert
 (not (and c_10_0 c_10_1)))
(assert
 (not (and c_10_0 c_10_2)))
(assert
 (not (and c_10_0 c_10_3)))
(assert
 (not (and c_10_0 c_10_4)))
(assert
 (not (and c_10_0 c_10_5)))
(assert
 (not (and c_10_0 c_10_6)))
(assert
 (not (and c_10_0 c_10_7)))
(assert
 (not (and c_10_0 c_10_8)))
(assert
 (not (and c_10_1 c_10_2)))
(assert
 (not (and c_10_1 c_10_3)))
(assert
 (not (and c_10_1 c_10_4)))
(assert
 (not (and c_10_1 c_10_5)))
(assert
 (not (and c_10_1 c_10_6)))
(assert
 (not (and c_10_1 c_10_7)))
(assert
 (not (and c_10_1 c_10_8)))
(assert
 (not (and c_10_2 c_10_3)))
(assert
 (not (and c_10_2 c_10_4)))
(assert
 (not (and c_10_2 c_10_5)))
(assert
 (not (and c_10_2 c_10_6)))
(assert
 (not (and c_10_2 c_10_7)))
(assert
 (not (and c_10_2 c_10_8)))
(assert
 (not (and c_10_3 c_10_4)))
(assert
 (not (and c_10_3 c_10_5)))
(assert
 (not (and c_10_3 c_10_6)))
(assert
 (not (and c_10_3 c_10_7)))
(assert
 (not (and c_10_3 c_10_8)))
(assert
 (not (and c_10_4 c_10_5)))
(assert
 (not (and c_10_4 c_10_6)))
(assert
 (not (and c_10_4 c_10_7)))
(assert
 (not (and c_10_4 c_10_8)))
(assert
 (not (and c_10_5 c_10_6)))
(assert
 (not (and c_10_5 c_10_7)))
(assert
 (not (and c_10_5 c_10_8)))
(assert
 (not (and c_10_6 c_10_7)))
(assert
 (not (and c_10_6 c_10_8)))
(assert
 (not (and c_10_7 c_10_8)))
(assert
 (let (($x1087 (or false c_11_0)))
 (let (($x1089 (or $x1087 c_11_1)))
 (let (($x1091 (or $x1089 c_11_2)))
 (let (($x1093 (or $x1091 c_11_3)))
 (let (($x1095 (or $x1093 c_11_4)))
 (let (($x1097 (or $x1095 c_11_5)))
 (let (($x1099 (or $x1097 c_11_6)))
 (let (($x1101 (or $x1099 c_11_7)))
 (or $x1101 c_11_8))))))))))
(assert
 (not (and c_11_0 c_11_1)))
(assert
 (not (and c_11_0 c_11_2)))
(assert
 (not (and c_11_0 c_11_3)))
(assert
 (not (and c_11_0 c_11_4)))
(assert
 (not (and c_11_0 c_11_5)))
(assert
 (not (and c_11_0 c_11_6)))
(assert
 (not (and c_11_0 c_11_7)))
(assert
 (not (and c_11_0 c_11_8)))
(assert
 (not (and c_11_1 c_11_2)))
(assert
 (not (and c_11_1 c_11_3)))
(assert
 (not (and c_11_1 c_11_4)))
(assert
 (not (and c_11_1 c_11_5)))
(assert
 (not (and c_11_1 c_11_6)))
(assert
 (not (and c_11_1 c_11_7)))
(assert
 (not (and c_11_1 c_11_8)))
(assert
 (not (and c_11_2 c_11_3)))
(assert
 (not (and c_11_2 c_11_4)))
(assert
 (not (and c_11_2 c_11_5)))
(assert
 (not (and c_11_2 c_11_6)))
(assert
 (not (and c_11_2 c_11_7)))
(assert
 (not (and c_11_2 c_11_8)))
(assert
 (not (and c_11_3 c_11_4)))
(assert
 (not (and c_11_3 c_11_5)))
(assert
 (not (and c_11_3 c_11_6)))
(assert
 (not (and c_11_3 c_11_7)))
(assert
 (not (and c_11_3 c_11_8)))
(assert
 (not (and c_11_4 c_11_5)))
(assert
 (not (and c_11_4 c_11_6)))
(assert
 (not (and c_11_4 c_11_7)))
(assert
 (not (and c_11_4 c_11_8)))
(assert
 (not (and c_11_5 c_11_6)))
(assert
 (not (and c_11_5 c_11_7)))
(assert
 (not (and c_11_5 c_11_8)))
(assert
 (not (and c_11_6 c_11_7)))
(assert
 (not (and c_11_6 c_11_8)))
(assert
 (not (and c_11_7 c_11_8)))
(assert
 (let (($x1177 (or false c_12_0)))
 (let (($x1179 (or $x1177 c_12_1)))
 (let (($x1181 (or $x1179 c_12_2)))
 (let (($x1183 (or $x1181 c_12_3)))
 (let (($x1185 (or $x1183 c_12_4)))
 (let (($x1187 (or $x1185 c_12_5)))
 (let (($x1189 (or $x1187 c_12_6)))
 (let (($x1191 (or $x1189 c_12_7)))
 (or $x1191 c_12_8))))))))))
(assert
 (not (and c_12_0 c_12_1)))
(assert
 (not (and c_12_0 c_12_2)))
(assert
 (not (and c_12_0 c_12_3)))
(assert
 (not (and c_12_0 c_12_4)))
(assert
 (not (and c_12_0 c_12_5)))
(assert
 (not (and c_12_0 c_12_6)))
(assert
 (not (and c_12_0 c_12_7)))
(assert
 (not (and c_12_0 c_12_8)))
(assert
 (not (and c_12_1 c_12_2)))
(assert
 (not (and c_12_1 c_12_3)))
(assert
 (not (and c_12_1 c_12_4)))
(assert
 (not (and c_12_1 c_12_5)))
(assert
 (not (and c_12_1 c_12_6)))
(assert
 (not (and c_12_1 c_12_7)))
(assert
 (not (and c_12_1 c_12_8)))
(assert
 (not (and c_12_2 c_12_3)))
(assert
 (not (and c_12_2 c_12_4)))
(assert
 (not (and c_12_2 c_12_5)))
(assert
 (not (and c_12_2 c_12_6)))
(assert
 (not (and c_12_2 c_12_7)))
(assert
 (not (and c_12_2 c_12_8)))
(assert
 (not (and c_12_3 c_12_4)))
(assert
 (not (and c_12_3 c_12_5)))
(assert
 (not (and c_12_3 c_12_6)))
(assert
 (not (and c_12_3 c_12_7)))
(assert
 (not (and c_12_3 c_12_8)))
(assert
 (not (and c_12_4 c_12_5)))
(assert
 (not (and c_12_4 c_12_6)))
(assert
 (not (and c_12_4 c_12_7)))
(assert
 (not (and c_12_4 c_12_8)))
(assert
 (not (and c_12_5 c_12_6)))
(assert
 (not (and c_12_5 c_12_7)))
(assert
 (not (and c_12_5 c_12_8)))
(assert
 (not (and c_12_6 c_12_7)))
(assert
 (not (and c_12_6 c_12_8)))
(assert
 (not (and c_12_7 c_12_8)))
(assert
 (let (($x1267 (or false c_13_0)))
 (let (($x1269 (or $x1267 c_13_1)))
 (let (($x1271 (or $x1269 c_13_2)))
 (let (($x1273 (or $x1271 c_13_3)))
 (let (($x1275 (or $x1273 c_13_4)))
 (let (($x1277 (or $x1275 c_13_5)))
 (let (($x1279 (or $x1277 c_13_6)))
 (let (($x1281 (or $x1279 c_13_7)))
 (or $x1281 c_13_8))))))))))
(assert
 (not (and c_13_0 c_13_1)))
(assert
 (not (and c_13_0 c_13_2)))
(assert
 (not (and c_13_0 c_13_3)))
(assert
 (not (and c_13_0 c_13_4)))
(assert
 (not (and c_13_0 c_13_5)))
(assert
 (not (and c_13_0 c_13_6)))
(assert
 (not (and c_13_0 c_13_7)))
(assert
 (not (and c_13_0 c_13_8)))
(assert
 (not (and c_13_1 c_13_2)))
(assert
 (not (and c_13_1 c_13_3)))
(assert
 (not (and c_13_1 c_13_4)))
(assert
 (not (and c_13_1 c_13_5)))
(assert
 (not (and c_13_1 c_13_6)))
(assert
 (not (and c_13_1 c_13_7)))
(assert
 (not (and c_13_1 c_13_8)))
(assert
 (not (and c_13_2 c_13_3)))
(assert
 (not (and c_13_2 c_13_4)))
(assert
 (not (and c_13_2 c_13_5)))
(assert
 (not (and c_13_2 c_13_6)))
(assert
 (not (and c_13_2 c_13_7)))
(assert
 (not (and c_13_2 c_13_8)))
(assert
 (not (and c_13_3 c_13_4)))
(assert
 (not (and c_13_3 c_13_5)))
(assert
 (not (and c_13_3 c_13_6)))
(assert
 (not (and c_13_3 c_13_7)))
(assert
 (not (and c_13_3 c_13_8)))
(assert
 (not (and c_13_4 c_13_5)))
(assert
 (not (and c_13_4 c_13_6)))
(assert
 (not (and c_13_4 c_13_7)))
(assert
 (not (and c_13_4 c_13_8)))
(assert
 (not (and c_13_5 c_13_6)))
(assert
 (not (and c_13_5 c_13_7)))
(assert
 (not (and c_13_5 c_13_8)))
(assert
 (not (and c_13_6 c_13_7)))
(assert
 (not (and c_13_6 c_13_8)))
(assert
 (not (and c_13_7 c_13_8)))
(assert
 (let (($x1357 (or false c_14_0)))
 (let (($x1359 (or $x1357 c_14_1)))
 (let (($x1361 (or $x1359 c_14_2)))
 (let (($x1363 (or $x1361 c_14_3)))
 (let (($x1365 (or $x1363 c_14_4)))
 (let (($x1367 (or $x1365 c_14_5)))
 (let (($x1369 (or $x1367 c_14_6)))
 (let (($x1371 (or $x1369 c_14_7)))
 (or $x1371 c_14_8))))))))))
(assert
 (not (and c_14_0 c_14_1)))
(assert
 (not (and c_14_0 c_14_2)))
(assert
 (not (and c_14_0 c_14_3)))
(assert
 (not (and c_14_0 c_14_4)))
(assert
 (not (and c_14_0 c_14_5)))
(assert
 (not (and c_14_0 c_14_6)))
(assert
 (not (and c_14_0 c_14_7)))
(assert
 (not (and c_14_0 c_14_8)))
(assert
 (not (and c_14_1 c_14_2)))
(assert
 (not (and c_14_1 c_14_3)))
(assert
 (not (and c_14_1 c_14_4)))
(assert
 (not (and c_14_1 c_14_5)))
(assert
 (not (and c_14_1 c_14_6)))
(assert
 (not (and c_14_1 c_14_7)))
(assert
 (not (and c_14_1 c_14_8)))
(assert
 (not (and c_14_2 c_14_3)))
(assert
 (not (and c_14_2 c_14_4)))
(assert
 (not (and c_14_2 c_14_5)))
(assert
 (not (and c_14_2 c_14_6)))
(assert
 (not (and c_14_2 c_14_7)))
(assert
 (not (and c_14_2 c_14_8)))
(assert
 (not (and c_14_3 c_14_4)))
(assert
 (not (and c_14_3 c_14_5)))
(assert
 (not (and c_14_3 c_14_6)))
(assert
 (not (and c_14_3 c_14_7)))
(assert
 (not (and c_14_3 c_14_8)))
(assert
 (not (and c_14_4 c_14_5)))
(assert
 (not (and c_14_4 c_14_6)))
(assert
 (not (and c_14_4 c_14_7)))
(assert
 (not (and c_14_4 c_14_8)))
(assert
 (not (and c_14_5 c_14_6)))
(assert
 (not (and c_14_5 c_14_7)))
(assert
 (not (and c_14_5 c_14_8)))
(assert
 (not (and c_14_6 c_14_7)))
(assert
 (not (and c_14_6 c_14_8)))
(assert
 (not (and c_14_7 c_14_8)))
(assert
 (let (($x1447 (or false c_15_0)))
 (let (($x1449 (or $x1447 c_15_1)))
 (let (($x1451 (or $x1449 c_15_2)))
 (let (($x1453 (or $x1451 c_15_3)))
 (let (($x1455 (or $x1453 c_15_4)))
 (let (($x1457 (or $x1455 c_15_5)))
 (let (($x1459 (or $x1457 c_15_6)))
 (let (($x1461 (or $x1459 c_15_7)))
 (or $x1461 c_15_8))))))))))
(assert
 (not (and c_15_0 c_15_1)))
(assert
 (not (and c_15_0 c_15_2)))
(assert
 (not (and c_15_0 c_15_3)))
(assert
 (not (and c_15_0 c_15_4)))
(assert
 (not (and c_15_0 c_15_5)))
(assert
 (not (and c_15_0 c_15_6)))
(assert
 (not (and c_15_0 c_15_7)))
(assert
 (not (and c_15_0 c_15_8)))
(assert
 (not (and c_15_1 c_15_2)))
(assert
 (not (and c_15_1 c_15_3)))
(assert
 (not (and c_15_1 c_15_4)))
(assert
 (not (and c_15_1 c_15_5)))
(assert
 (not (and c_15_1 c_15_6)))
(assert
 (not (and c_15_1 c_15_7)))
(assert
 (not (and c_15_1 c_15_8)))
(assert
 (not (and c_15_2 c_15_3)))
(assert
 (not (and c_15_2 c_15_4)))
(assert
 (not (and c_15_2 c_15_5)))
(assert
 (not (and c_15_2 c_15_6)))
(assert
 (not (and c_15_2 c_15_7)))
(assert
 (not (and c_15_2 c_15_8)))
(assert
 (not (and c_15_3 c_15_4)))
(assert
 (not (and c_15_3 c_15_5)))
(assert
 (not (and c_15_3 c_15_6)))
(assert
 (not (and c_15_3 c_15_7)))
(assert
 (not (and c_15_3 c_15_8)))
(assert
 (not (and c_15_4 c_15_5)))
(assert
 (not (and c_15_4 c_15_6)))
(assert
 (not (and c_15_4 c_15_7)))
(assert
 (not (and c_15_4 c_15_8)))
(assert
 (not (and c_15_5 c_15_6)))
(assert
 (not (and c_15_5 c_15_7)))
(assert
 (not (and c_15_5 c_15_8)))
(assert
 (not (and c_15_6 c_15_7)))
(assert
 (not (and c_15_6 c_15_8)))
(assert
 (not (and c_15_7 c_15_8)))
(assert
 (let (($x1537 (or false c_16_0)))
 (let (($x1539 (or $x1537 c_16_1)))
 (let (($x1541 (or $x1539 c_16_2)))
 (let (($x1543 (or $x1541 c_16_3)))
 (let (($x1545 (or $x1543 c_16_4)))
 (let (($x1547 (or $x1545 c_16_5)))
 (let (($x1549 (or $x1547 c_16_6)))
 (let (($x1551 (or $x1549 c_16_7)))
 (or $x1551 c_16_8))))))))))
(assert
 (not (and c_16_0 c_16_1)))
(assert
 (not (and c_16_0 c_16_2)))
(assert
 (not (and c_16_0 c_16_3)))
(assert
 (not (and c_16_0 c_16_4)))
(assert
 (not (and c_16_0 c_16_5)))
(assert
 (not (and c_16_0 c_16_6)))
(assert
 (not (and c_16_0 c_16_7)))
(assert
 (not (and c_16_0 c_16_8)))
(assert
 (not (and c_16_1 c_16_2)))
(assert
 (not (and c_16_1 c_16_3)))
(assert
 (not (and c_16_1 c_16_4)))
(assert
 (not (and c_16_1 c_16_5)))
(assert
 (not (and c_16_1 c_16_6)))
(assert
 (not (and c_16_1 c_16_7)))
(assert
 (not (and c_16_1 c_16_8)))
(assert
 (not (and c_16_2 c_16_3)))
(assert
 (not (and c_16_2 c_16_4)))
(assert
 (not (and c_16_2 c_16_5)))
(assert
 (not (and c_16_2 c_16_6)))
(assert
 (not (and c_16_2 c_16_7)))
(assert
 (not (and c_16_2 c_16_8)))
(assert
 (not (and c_16_3 c_16_4)))
(assert
 (not (and c_16_3 c_16_5)))
(assert
 (not (and c_16_3 c_16_6)))
(assert
 (not (and c_16_3 c_16_7)))
(assert
 (not (and c_16_3 c_16_8)))
(assert
 (not (and c_16_4 c_16_5)))
(assert
 (not (and c_16_4 c_16_6)))
(assert
 (not (and c_16_4 c_16_7)))
(assert
 (not (and c_16_4 c_16_8)))
(assert
 (not (and c_16_5 c_16_6)))
(assert
 (not (and c_16_5 c_16_7)))
(assert
 (not (and c_16_5 c_16_8)))
(assert
 (not (and c_16_6 c_16_7)))
(assert
 (not (and c_16_6 c_16_8)))
(assert
 (not (and c_16_7 c_16_8)))
(assert
 (let (($x1627 (or false c_17_0)))
 (let (($x1629 (or $x1627 c_17_1)))
 (let (($x1631 (or $x1629 c_17_2)))
 (let (($x1633 (or $x1631 c_17_3)))
 (let (($x1635 (or $x1633 c_17_4)))
 (let (($x1637 (or $x1635 c_17_5)))
 (let (($x1639 (or $x1637 c_17_6)))
 (let (($x1641 (or $x1639 c_17_7)))
 (or $x1641 c_17_8))))))))))
(assert
 (not (and c_17_0 c_17_1)))
(assert
 (not (and c_17_0 c_17_2)))
(assert
 (not (and c_17_0 c_17_3)))
(assert
 (not (and c_17_0 c_17_4)))
(assert
 (not (and c_17_0 c_17_5)))
(assert
 (not (and c_17_0 c_17_6)))
(assert
 (not (and c_17_0 c_17_7)))
(assert
 (not (and c_17_0 c_17_8)))
(assert
 (not (and c_17_1 c_17_2)))
(assert
 (not (and c_17_1 c_17_3)))
(assert
 (not (and c_17_1 c_17_4)))
(assert
 (not (and c_17_1 c_17_5)))
(assert
 (not (and c_17_1 c_17_6)))
(assert
 (not (and c_17_1 c_17_7)))
(assert
 (not (and c_17_1 c_17_8)))
(assert
 (not (and c_17_2 c_17_3)))
(assert
 (not (and c_17_2 c_17_4)))
(assert
 (not (and c_17_2 c_17_5)))
(assert
 (not (and c_17_2 c_17_6)))
(assert
 (not (and c_17_2 c_17_7)))
(assert
 (not (and c_17_2 c_17_8)))
(assert
 (not (and c_17_3 c_17_4)))
(assert
 (not (and c_17_3 c_17_5)))
(assert
 (not (and c_17_3 c_17_6)))
(assert
 (not (and c_17_3 c_17_7)))
(assert
 (not (and c_17_3 c_17_8)))
(assert
 (not (and c_17_4 c_17_5)))
(assert
 (not (and c_17_4 c_17_6)))
(assert
 (not (and c_17_4 c_17_7)))
(assert
 (not (and c_17_4 c_17_8)))
(assert
 (not (and c_17_5 c_17_6)))
(assert
 (not (and c_17_5 c_17_7)))
(assert
 (not (and c_17_5 c_17_8)))
(assert
 (not (and c_17_6 c_17_7)))
(assert
 (not (and c_17_6 c_17_8)))
(assert
 (not (and c_17_7 c_17_8)))
(assert
 (let (($x1717 (or false c_18_0)))
 (let (($x1719 (or $x1717 c_18_1)))
 (let (($x1721 (or $x1719 c_18_2)))
 (let (($x1723 (or $x1721 c_18_3)))
 (let (($x1725 (or $x1723 c_18_4)))
 (let (($x1727 (or $x1725 c_18_5)))
 (let (($x1729 (or $x1727 c_18_6)))
 (let (($x1731 (or $x1729 c_18_7)))
 (or $x1731 c_18_8))))))))))
(assert
 (not (and c_18_0 c_18_1)))
(assert
 (not (and c_18_0 c_18_2)))
(assert
 (not (and c_18_0 c_18_3)))
(assert
 (not (and c_18_0 c_18_4)))
(assert
 (not (and c_18_0 c_18_5)))
(assert
 (not (and c_18_0 c_18_6)))
(assert
 (not (and c_18_0 c_18_7)))
(assert
 (not (and c_18_0 c_18_8)))
(assert
 (not (and c_18_1 c_18_2)))
(assert
 (not (and c_18_1 c_18_3)))
(assert
 (not (and c_18_1 c_18_4)))
(assert
 (not (and c_18_1 c_18_5)))
(assert
 (not (and c_18_1 c_18_6)))
(assert
 (not (and c_18_1 c_18_7)))
(assert
 (not (and c_18_1 c_18_8)))
(assert
 (not (and c_18_2 c_18_3)))
(assert
 (not (and c_18_2 c_18_4)))
(assert
 (not (and c_18_2 c_18_5)))
(assert
 (not (and c_18_2 c_18_6)))
(assert
 (not (and c_18_2 c_18_7)))
(assert
 (not (and c_18_2 c_18_8)))
(assert
 (not (and c_18_3 c_18_4)))
(assert
 (not (and c_18_3 c_18_5)))
(assert
 (not (and c_18_3 c_18_6)))
(assert
 (not (and c_18_3 c_18_7)))
(assert
 (not (and c_18_3 c_18_8)))
(assert
 (not (and c_18_4 c_18_5)))
(assert
 (not (and c_18_4 c_18_6)))
(assert
 (not (and c_18_4 c_18_7)))
(assert
 (not (and c_18_4 c_18_8)))
(assert
 (not (and c_18_5 c_18_6)))
(assert
 (not (and c_18_5 c_18_7)))
(assert
 (not (and c_18_5 c_18_8)))
(assert
 (not (and c_18_6 c_18_7)))
(assert
 (not (and c_18_6 c_18_8)))
(assert
 (not (and c_18_7 c_18_8)))
(assert
 (let (($x1807 (or false c_19_0)))
 (let (($x1809 (or $x1807 c_19_1)))
 (let (($x1811 (or $x1809 c_19_2)))
 (let (($x1813 (or $x1811 c_19_3)))
 (let (($x1815 (or $x1813 c_19_4)))
 (let (($x1817 (or $x1815 c_19_5)))
 (let (($x1819 (or $x1817 c_19_6)))
 (let (($x1821 (or $x1819 c_19_7)))
 (or $x1821 c_19_8))))))))))
(assert
 (not (and c_19_0 c_19_1)))
(assert
 (not (and c_19_0 c_19_2)))
(assert
 (not (and c_19_0 c_19_3)))
(assert
 (not (and c_19_0 c_19_4)))
(assert
 (not (and c_19_0 c_19_5)))
(assert
 (not (and c_19_0 c_19_6)))
(assert
 (not (and c_19_0 c_19_7)))
(assert
 (not (and c_19_0 c_19_8)))
(assert
 (not (and c_19_1 c_19_2)))
(assert
 (not (and c_19_1 c_19_3)))
(assert
 (not (and c_19_1 c_19_4)))
(assert
 (not (and c_19_1 c_19_5)))
(assert
 (not (and c_19_1 c_19_6)))
(assert
 (not (and c_19_1 c_19_7)))
(assert
 (not (and c_19_1 c_19_8)))
(assert
 (not (and c_19_2 c_19_3)))
(assert
 (not (and c_19_2 c_19_4)))
(assert
 (not (and c_19_2 c_19_5)))
(assert
 (not (and c_19_2 c_19_6)))
(assert
 (not (and c_19_2 c_19_7)))
(assert
 (not (and c_19_2 c_19_8)))
(assert
 (not (and c_19_3 c_19_4)))
(assert
 (not (and c_19_3 c_19_5)))
(assert
 (not (and c_19_3 c_19_6)))
(assert
 (not (and c_19_3 c_19_7)))
(assert
 (not (and c_19_3 c_19_8)))
(assert
 (not (and c_19_4 c_19_5)))
(assert
 (not (and c_19_4 c_19_6)))
(assert
 (not (and c_19_4 c_19_7)))
(assert
 (not (and c_19_4 c_19_8)))
(assert
 (not (and c_19_5 c_19_6)))
(assert
 (not (and c_19_5 c_19_7)))
(assert
 (not (and c_19_5 c_19_8)))
(assert
 (not (and c_19_6 c_19_7)))
(assert
 (not (and c_19_6 c_19_8)))
(assert
 (not (and c_19_7 c_19_8)))
(assert
 (let (($x1897 (or false c_20_0)))
 (let (($x1899 (or $x1897 c_20_1)))
 (let (($x1901 (or $x1899 c_20_2)))
 (let (($x1903 (or $x1901 c_20_3)))
 (let (($x1905 (or $x1903 c_20_4)))
 (let (($x1907 (or $x1905 c_20_5)))
 (let (($x1909 (or $x1907 c_20_6)))
 (let (($x1911 (or $x1909 c_20_7)))
 (or $x1911 c_20_8))))))))))
(assert
 (not (and c_20_0 c_20_1)))
(assert
 (not (and c_20_0 c_20_2)))
(assert
 (not (and c_20_0 c_20_3)))
(assert
 (not (and c_20_0 c_20_4)))
(assert
 (not (and c_20_0 c_20_5)))
(assert
 (not (and c_20_0 c_20_6)))
(assert
 (not (and c_20_0 c_20_7)))
(assert
 (not (and c_20_0 c_20_8)))
(assert
 (not (and c_20_1 c_20_2)))
(assert
 (not (and c_20_1 c_20_3)))
(assert
 (not (and c_20_1 c_20_4)))
(assert
 (not (and c_20_1 c_20_5)))
(assert
 (not (and c_20_1 c_20_6)))
(assert
 (not (and c_20_1 c_20_7)))
(assert
 (not (and c_20_1 c_20_8)))
(assert
 (not (and c_20_2 c_20_3)))
(assert
 (not (and c_20_2 c_20_4)))
(assert
 (not (and c_20_2 c_20_5)))
(assert
 (not (and c_20_2 c_20_6)))
(assert
 (not (and c_20_2 c_20_7)))
(assert
 (not (and c_20_2 c_20_8)))
(assert
 (not (and c_20_3 c_20_4)))
(assert
 (not (and c_20_3 c_20_5)))
(assert
 (not (and c_20_3 c_20_6)))
(assert
 (not (and c_20_3 c_20_7)))
(assert
 (not (and c_20_3 c_20_8)))
(assert
 (not (and c_20_4 c_20_5)))
(assert
 (not (and c_20_4 c_20_6)))
(assert
 (not (and c_20_4 c_20_7)))
(assert
 (not (and c_20_4 c_20_8)))
(assert
 (not (and c_20_5 c_20_6)))
(assert
 (not (and c_20_5 c_20_7)))
(assert
 (not (and c_20_5 c_20_8)))
(assert
 (not (and c_20_6 c_20_7)))
(assert
 (not (and c_20_6 c_20_8)))
(assert
 (not (and c_20_7 c_20_8)))
(assert
 (let (($x1987 (or false c_21_0)))
 (let (($x1989 (or $x1987 c_21_1)))
 (let (($x1991 (or $x1989 c_21_2)))
 (let (($x1993 (or $x1991 c_21_3)))
 (let (($x1995 (or $x1993 c_21_4)))
 (let (($x1997 (or $x1995 c_21_5)))
 (let (($x1999 (or $x1997 c_21_6)))
 (let (($x2001 (or $x1999 c_21_7)))
 (or $x2001 c_21_8))))))))))
(assert
 (not (and c_21_0 c_21_1)))
(assert
 (not (and c_21_0 c_21_2)))
(assert
 (not (and c_21_0 c_21_3)))
(assert
 (not (and c_21_0 c_21_4)))
(assert
 (not (and c_21_0 c_21_5)))
(assert
 (not (and c_21_0 c_21_6)))
(assert
 (not (and c_21_0 c_21_7)))
(assert
 (not (and c_21_0 c_21_8)))
(assert
 (not (and c_21_1 c_21_2)))
(assert
 (not (and c_21_1 c_21_3)))
(assert
 (not (and c_21_1 c_21_4)))
(assert
 (not (and c_21_1 c_21_5)))
(assert
 (not (and c_21_1 c_21_6)))
(assert
 (not (and c_21_1 c_21_7)))
(assert
 (not (and c_21_1 c_21_8)))
(assert
 (not (and c_21_2 c_21_3)))
(assert
 (not (and c_21_2 c_21_4)))
(assert
 (not (and c_21_2 c_21_5)))
(assert
 (not (and c_21_2 c_21_6)))
(assert
 (not (and c_21_2 c_21_7)))
(assert
 (not (and c_21_2 c_21_8)))
(assert
 (not (and c_21_3 c_21_4)))
(assert
 (not (and c_21_3 c_21_5)))
(assert
 (not (and c_21_3 c_21_6)))
(assert
 (not (and c_21_3 c_21_7)))
(assert
 (not (and c_21_3 c_21_8)))
(assert
 (not (and c_21_4 c_21_5)))
(assert
 (not (and c_21_4 c_21_6)))
(assert
 (not (and c_21_4 c_21_7)))
(assert
 (not (and c_21_4 c_21_8)))
(assert
 (not (and c_21_5 c_21_6)))
(assert
 (not (and c_21_5 c_21_7)))
(assert
 (not (and c_21_5 c_21_8)))
(assert
 (not (and c_21_6 c_21_7)))
(assert
 (not (and c_21_6 c_21_8)))
(assert
 (not (and c_21_7 c_21_8)))
(assert
 (let (($x2077 (or false c_22_0)))
 (let (($x2079 (or $x2077 c_22_1)))
 (let (($x2081 (or $x2079 c_22_2)))
 (let (($x2083 (or $x2081 c_22_3)))
 (let (($x2085 (or $x2083 c_22_4)))
 (let (($x2087 (or $x2085 c_22_5)))
 (let (($x2089 (or $x2087 c_22_6)))
 (let (($x2091 (or $x2089 c_22_7)))
 (or $x2091 c_22_8))))))))))
(assert
 (not (and c_22_0 c_22_1)))
(assert
 (not (and c_22_0 c_22_2)))
(assert
 (not (and c_22_0 c_22_3)))
(assert
 (not (and c_22_0 c_22_4)))
(assert
 (not (and c_22_0 c_22_5)))
(assert
 (not (and c_22_0 c_22_6)))
(assert
 (not (and c_22_0 c_22_7)))
(assert
 (not (and c_22_0 c_22_8)))
(assert
 (not (and c_22_1 c_22_2)))
(assert
 (not (and c_22_1 c_22_3)))
(assert
 (not (and c_22_1 c_22_4)))
(assert
 (not (and c_22_1 c_22_5)))
(assert
 (not (and c_22_1 c_22_6)))
(assert
 (not (and c_22_1 c_22_7)))
(assert
 (not (and c_22_1 c_22_8)))
(assert
 (not (and c_22_2 c_22_3)))
(assert
 (not (and c_22_2 c_22_4)))
(assert
 (not (and c_22_2 c_22_5)))
(assert
 (not (and c_22_2 c_22_6)))
(assert
 (not (and c_22_2 c_22_7)))
(assert
 (not (and c_22_2 c_22_8)))
(assert
 (not (and c_22_3 c_22_4)))
(assert
 (not (and c_22_3 c_22_5)))
(assert
 (not (and c_22_3 c_22_6)))
(assert
 (not (and c_22_3 c_22_7)))
(assert
 (not (and c_22_3 c_22_8)))
(assert
 (not (and c_22_4 c_22_5)))
(assert
 (not (and c_22_4 c_22_6)))
(assert
 (not (and c_22_4 c_22_7)))
(assert
 (not (and c_22_4 c_22_8)))
(assert
 (not (and c_22_5 c_22_6)))
(assert
 (not (and c_22_5 c_22_7)))
(assert
 (not (and c_22_5 c_22_8)))
(assert
 (not (and c_22_6 c_22_7)))
(assert
 (not (and c_22_6 c_22_8)))
(assert
 (not (and c_22_7 c_22_8)))
(assert
 (let (($x2167 (or false c_23_0)))
 (let (($x2169 (or $x2167 c_23_1)))
 (let (($x2171 (or $x2169 c_23_2)))
 (let (($x2173 (or $x2171 c_23_3)))
 (let (($x2175 (or $x2173 c_23_4)))
 (let (($x2177 (or $x2175 c_23_5)))
 (let (($x2179 (or $x2177 c_23_6)))
 (let (($x2181 (or $x2179 c_23_7)))
 (or $x2181 c_23_8))))))))))
(assert
 (not (and c_23_0 c_23_1)))
(assert
 (not (and c_23_0 c_23_2)))
(assert
 (not (and c_23_0 c_23_3)))
(assert
 (not (and c_23_0 c_23_4)))
(assert
 (not (and c_23_0 c_23_5)))
(assert
 (not (and c_23_0 c_23_6)))
(assert
 (not (and c_23_0 c_23_7)))
(assert
 (not (and c_23_0 c_23_8)))
(assert
 (not (and c_23_1 c_23_2)))
(assert
 (not (and c_23_1 c_23_3)))
(assert
 (not (and c_23_1 c_23_4)))
(assert
 (not (and c_23_1 c_23_5)))
(assert
 (not (and c_23_1 c_23_6)))
(assert
 (not (and c_23_1 c_23_7)))
(assert
 (not (and c_23_1 c_23_8)))
(assert
 (not (and c_23_2 c_23_3)))
(assert
 (not (and c_23_2 c_23_4)))
(assert
 (not (and c_23_2 c_23_5)))
(assert
 (not (and c_23_2 c_23_6)))
(assert
 (not (and c_23_2 c_23_7)))
(assert
 (not (and c_23_2 c_23_8)))
(assert
 (not (and c_23_3 c_23_4)))
(assert
 (not (and c_23_3 c_23_5)))
(assert
 (not (and c_23_3 c_23_6)))
(assert
 (not (and c_23_3 c_23_7)))
(assert
 (not (and c_23_3 c_23_8)))
(assert
 (not (and c_23_4 c_23_5)))
(assert
 (not (and c_23_4 c_23_6)))
(assert
 (not (and c_23_4 c_23_7)))
(assert
 (not (and c_23_4 c_23_8)))
(assert
 (not (and c_23_5 c_23_6)))
(assert
 (not (and c_23_5 c_23_7)))
(assert
 (not (and c_23_5 c_23_8)))
(assert
 (not (and c_23_6 c_23_7)))
(assert
 (not (and c_23_6 c_23_8)))
(assert
 (not (and c_23_7 c_23_8)))
(assert
 (let (($x2257 (or false c_24_0)))
 (let (($x2259 (or $x2257 c_24_1)))
 (let (($x2261 (or $x2259 c_24_2)))
 (let (($x2263 (or $x2261 c_24_3)))
 (let (($x2265 (or $x2263 c_24_4)))
 (let (($x2267 (or $x2265 c_24_5)))
 (let (($x2269 (or $x2267 c_24_6)))
 (let (($x2271 (or $x2269 c_24_7)))
 (or $x2271 c_24_8))))))))))
(assert
 (not (and c_24_0 c_24_1)))
(assert
 (not (and c_24_0 c_24_2)))
(assert
 (not (and c_24_0 c_24_3)))
(assert
 (not (and c_24_0 c_24_4)))
(assert
 (not (and c_24_0 c_24_5)))
(assert
 (not (and c_24_0 c_24_6)))
(assert
 (not (and c_24_0 c_24_7)))
(assert
 (not (and c_24_0 c_24_8)))
(assert
 (not (and c_24_1 c_24_2)))
(assert
 (not (and c_24_1 c_24_3)))
(assert
 (not (and c_24_1 c_24_4)))
(assert
 (not (and c_24_1 c_24_5)))
(assert
 (not (and c_24_1 c_24_6)))
(assert
 (not (and c_24_1 c_24_7)))
(assert
 (not (and c_24_1 c_24_8)))
(assert
 (not (and c_24_2 c_24_3)))
(assert
 (not (and c_24_2 c_24_4)))
(assert
 (not (and c_24_2 c_24_5)))
(assert
 (not (and c_24_2 c_24_6)))
(assert
 (not (and c_24_2 c_24_7)))
(assert
 (not (and c_24_2 c_24_8)))
(assert
 (not (and c_24_3 c_24_4)))
(assert
 (not (and c_24_3 c_24_5)))
(assert
 (not (and c_24_3 c_24_6)))
(assert
 (not (and c_24_3 c_24_7)))
(assert
 (not (and c_24_3 c_24_8)))
(assert
 (not (and c_24_4 c_24_5)))
(assert
 (not (and c_24_4 c_24_6)))
(assert
 (not (and c_24_4 c_24_7)))
(assert
 (not (and c_24_4 c_24_8)))
(assert
 (not (and c_24_5 c_24_6)))
(assert
 (not (and c_24_5 c_24_7)))
(assert
 (not (and c_24_5 c_24_8)))
(assert
 (not (and c_24_6 c_24_7)))
(assert
 (not (and c_24_6 c_24_8)))
(assert
 (not (and c_24_7 c_24_8)))
(assert
 (let (($x2347 (or false c_25_0)))
 (let (($x2349 (or $x2347 c_25_1)))
 (let (($x2351 (or $x2349 c_25_2)))
 (let (($x2353 (or $x2351 c_25_3)))
 (let (($x2355 (or $x2353 c_25_4)))
 (let (($x2357 (or $x2355 c_25_5)))
 (let (($x2359 (or $x2357 c_25_6)))
 (let (($x2361 (or $x2359 c_25_7)))
 (or $x2361 c_25_8))))))))))
(assert
 (not (and c_25_0 c_25_1)))
(assert
 (not (and c_25_0 c_25_2)))
(assert
 (not (and c_25_0 c_25_3)))
(assert
 (not (and c_25_0 c_25_4)))
(assert
 (not (and c_25_0 c_25_5)))
(assert
 (not (and c_25_0 c_25_6)))
(assert
 (not (and c_25_0 c_25_7)))
(assert
 (not (and c_25_0 c_25_8)))
(assert
 (not (and c_25_1 c_25_2)))
(assert
 (not (and c_25_1 c_25_3)))
(assert
 (not (and c_25_1 c_25_4)))
(assert
 (not (and c_25_1 c_25_5)))
(assert
 (not (and c_25_1 c_25_6)))
(assert
 (not (and c_25_1 c_25_7)))
(assert
 (not (and c_25_1 c_25_8)))
(assert
 (not (and c_25_2 c_25_3)))
(assert
 (not (and c_25_2 c_25_4)))
(assert
 (not (and c_25_2 c_25_5)))
(assert
 (not (and c_25_2 c_25_6)))
(assert
 (not (and c_25_2 c_25_7)))
(assert
 (not (and c_25_2 c_25_8)))
(assert
 (not (and c_25_3 c_25_4)))
(assert
 (not (and c_25_3 c_25_5)))
(assert
 (not (and c_25_3 c_25_6)))
(assert
 (not (and c_25_3 c_25_7)))
(assert
 (not (and c_25_3 c_25_8)))
(assert
 (not (and c_25_4 c_25_5)))
(assert
 (not (and c_25_4 c_25_6)))
(assert
 (not (and c_25_4 c_25_7)))
(assert
 (not (and c_25_4 c_25_8)))
(assert
 (not (and c_25_5 c_25_6)))
(assert
 (not (and c_25_5 c_25_7)))
(assert
 (not (and c_25_5 c_25_8)))
(assert
 (not (and c_25_6 c_25_7)))
(assert
 (not (and c_25_6 c_25_8)))
(assert
 (not (and c_25_7 c_25_8)))
(assert
 (let (($x2437 (or false c_26_0)))
 (let (($x2439 (or $x2437 c_26_1)))
 (let (($x2441 (or $x2439 c_26_2)))
 (let (($x2443 (or $x2441 c_26_3)))
 (let (($x2445 (or $x2443 c_26_4)))
 (let (($x2447 (or $x2445 c_26_5)))
 (let (($x2449 (or $x2447 c_26_6)))
 (let (($x2451 (or $x2449 c_26_7)))
 (or $x2451 c_26_8))))))))))
(assert
 (not (and c_26_0 c_26_1)))
(assert
 (not (and c_26_0 c_26_2)))
(assert
 (not (and c_26_0 c_26_3)))
(assert
 (not (and c_26_0 c_26_4)))
(assert
 (not (and c_26_0 c_26_5)))
(assert
 (not (and c_26_0 c_26_6)))
(assert
 (not (and c_26_0 c_26_7)))
(assert
 (not (and c_26_0 c_26_8)))
(assert
 (not (and c_26_1 c_26_2)))
(assert
 (not (and c_26_1 c_26_3)))
(assert
 (not (and c_26_1 c_26_4)))
(assert
 (not (and c_26_1 c_26_5)))
(assert
 (not (and c_26_1 c_26_6)))
(assert
 (not (and c_26_1 c_26_7)))
(assert
 (not (and c_26_1 c_26_8)))
(assert
 (not (and c_26_2 c_26_3)))
(assert
 (not (and c_26_2 c_26_4)))
(assert
 (not (and c_26_2 c_26_5)))
(assert
 (not (and c_26_2 c_26_6)))
(assert
 (not (and c_26_2 c_26_7)))
(assert
 (not (and c_26_2 c_26_8)))
(assert
 (not (and c_26_3 c_26_4)))
(assert
 (not (and c_26_3 c_26_5)))
(assert
 (not (and c_26_3 c_26_6)))
(assert
 (not (and c_26_3 c_26_7)))
(assert
 (not (and c_26_3 c_26_8)))
(assert
 (not (and c_26_4 c_26_5)))
(assert
 (not (and c_26_4 c_26_6)))
(assert
 (not (and c_26_4 c_26_7)))
(assert
 (not (and c_26_4 c_26_8)))
(assert
 (not (and c_26_5 c_26_6)))
(assert
 (not (and c_26_5 c_26_7)))
(assert
 (not (and c_26_5 c_26_8)))
(assert
 (not (and c_26_6 c_26_7)))
(assert
 (not (and c_26_6 c_26_8)))
(assert
 (not (and c_26_7 c_26_8)))
(assert
 (let (($x2527 (or false c_27_0)))
 (let (($x2529 (or $x2527 c_27_1)))
 (let (($x2531 (or $x2529 c_27_2)))
 (let (($x2533 (or $x2531 c_27_3)))
 (let (($x2535 (or $x2533 c_27_4)))
 (let (($x2537 (or $x2535 c_27_5)))
 (let (($x2539 (or $x2537 c_27_6)))
 (let (($x2541 (or $x2539 c_27_7)))
 (or $x2541 c_27_8))))))))))
(assert
 (not (and c_27_0 c_27_1)))
(assert
 (not (and c_27_0 c_27_2)))
(assert
 (not (and c_27_0 c_27_3)))
(assert
 (not (and c_27_0 c_27_4)))
(assert
 (not (and c_27_0 c_27_5)))
(assert
 (not (and c_27_0 c_27_6)))
(assert
 (not (and c_27_0 c_27_7)))
(assert
 (not (and c_27_0 c_27_8)))
(assert
 (not (and c_27_1 c_27_2)))
(assert
 (not (and c_27_1 c_27_3)))
(assert
 (not (and c_27_1 c_27_4)))
(assert
 (not (and c_27_1 c_27_5)))
(assert
 (not (and c_27_1 c_27_6)))
(assert
 (not (and c_27_1 c_27_7)))
(assert
 (not (and c_27_1 c_27_8)))
(assert
 (not (and c_27_2 c_27_3)))
(assert
 (not (and c_27_2 c_27_4)))
(assert
 (not (and c_27_2 c_27_5)))
(assert
 (not (and c_27_2 c_27_6)))
(assert
 (not (and c_27_2 c_27_7)))
(assert
 (not (and c_27_2 c_27_8)))
(assert
 (not (and c_27_3 c_27_4)))
(assert
 (not (and c_27_3 c_27_5)))
(assert
 (not (and c_27_3 c_27_6)))
(assert
 (not (and c_27_3 c_27_7)))
(assert
 (not (and c_27_3 c_27_8)))
(assert
 (not (and c_27_4 c_27_5)))
(assert
 (not (and c_27_4 c_27_6)))
(assert
 (not (and c_27_4 c_27_7)))
(assert
 (not (and c_27_4 c_27_8)))
(assert
 (not (and c_27_5 c_27_6)))
(assert
 (not (and c_27_5 c_27_7)))
(assert
 (not (and c_27_5 c_27_8)))
(assert
 (not (and c_27_6 c_27_7)))
(assert
 (not (and c_27_6 c_27_8)))
(assert
 (not (and c_27_7 c_27_8)))
(assert
 (let (($x2617 (or false c_28_0)))
 (let (($x2619 (or $x2617 c_28_1)))
 (let (($x2621 (or $x2619 c_28_2)))
 (let (($x2623 (or $x2621 c_28_3)))
 (let (($x2625 (or $x2623 c_28_4)))
 (let (($x2627 (or $x2625 c_28_5)))
 (let (($x2629 (or $x2627 c_28_6)))
 (let (($x2631 (or $x2629 c_28_7)))
 (or $x2631 c_28_8))))))))))
(assert
 (not (and c_28_0 c_28_1)))
(assert
 (not (and c_28_0 c_28_2)))
(assert
 (not (and c_28_0 c_28_3)))
(assert
 (not (and c_28_0 c_28_4)))
(assert
 (not (and c_28_0 c_28_5)))
(assert
 (not (and c_28_0 c_28_6)))
(assert
 (not (and c_28_0 c_28_7)))
(assert
 (not (and c_28_0 c_28_8)))
(assert
 (not (and c_28_1 c_28_2)))
(assert
 (not (and c_28_1 c_28_3)))
(assert
 (not (and c_28_1 c_28_4)))
(assert
 (not (and c_28_1 c_28_5)))
(assert
 (not (and c_28_1 c_28_6)))
(assert
 (not (and c_28_1 c_28_7)))
(assert
 (not (and c_28_1 c_28_8)))
(assert
 (not (and c_28_2 c_28_3)))
(assert
 (not (and c_28_2 c_28_4)))
(assert
 (not (and c_28_2 c_28_5)))
(assert
 (not (and c_28_2 c_28_6)))
(assert
 (not (and c_28_2 c_28_7)))
(assert
 (not (and c_28_2 c_28_8)))
(assert
 (not (and c_28_3 c_28_4)))
(assert
 (not (and c_28_3 c_28_5)))
(assert
 (not (and c_28_3 c_28_6)))
(assert
 (not (and c_28_3 c_28_7)))
(assert
 (not (and c_28_3 c_28_8)))
(assert
 (not (and c_28_4 c_28_5)))
(assert
 (not (and c_28_4 c_28_6)))
(assert
 (not (and c_28_4 c_28_7)))
(assert
 (not (and c_28_4 c_28_8)))
(assert
 (not (and c_28_5 c_28_6)))
(assert
 (not (and c_28_5 c_28_7)))
(assert
 (not (and c_28_5 c_28_8)))
(assert
 (not (and c_28_6 c_28_7)))
(assert
 (not (and c_28_6 c_28_8)))
(assert
 (not (and c_28_7 c_28_8)))
(assert
 (let (($x2707 (or false c_29_0)))
 (let (($x2709 (or $x2707 c_29_1)))
 (let (($x2711 (or $x2709 c_29_2)))
 (let (($x2713 (or $x2711 c_29_3)))
 (let (($x2715 (or $x2713 c_29_4)))
 (let (($x2717 (or $x2715 c_29_5)))
 (let (($x2719 (or $x2717 c_29_6)))
 (let (($x2721 (or $x2719 c_29_7)))
 (or $x2721 c_29_8))))))))))
(assert
 (not (and c_29_0 c_29_1)))
(assert
 (not (and c_29_0 c_29_2)))
(assert
 (not (and c_29_0 c_29_3)))
(assert
 (not (and c_29_0 c_29_4)))
(assert
 (not (and c_29_0 c_29_5)))
(assert
 (not (and c_29_0 c_29_6)))
(assert
 (not (and c_29_0 c_29_7)))
(assert
 (not (and c_29_0 c_29_8)))
(assert
 (not (and c_29_1 c_29_2)))
(assert
 (not (and c_29_1 c_29_3)))
(assert
 (not (and c_29_1 c_29_4)))
(assert
 (not (and c_29_1 c_29_5)))
(assert
 (not (and c_29_1 c_29_6)))
(assert
 (not (and c_29_1 c_29_7)))
(assert
 (not (and c_29_1 c_29_8)))
(assert
 (not (and c_29_2 c_29_3)))
(assert
 (not (and c_29_2 c_29_4)))
(assert
 (not (and c_29_2 c_29_5)))
(assert
 (not (and c_29_2 c_29_6)))
(assert
 (not (and c_29_2 c_29_7)))
(assert
 (not (and c_29_2 c_29_8)))
(assert
 (not (and c_29_3 c_29_4)))
(assert
 (not (and c_29_3 c_29_5)))
(assert
 (not (and c_29_3 c_29_6)))
(assert
 (not (and c_29_3 c_29_7)))
(assert
 (not (and c_29_3 c_29_8)))
(assert
 (not (and c_29_4 c_29_5)))
(assert
 (not (and c_29_4 c_29_6)))
(assert
 (not (and c_29_4 c_29_7)))
(assert
 (not (and c_29_4 c_29_8)))
(assert
 (not (and c_29_5 c_29_6)))
(assert
 (not (and c_29_5 c_29_7)))
(assert
 (not (and c_29_5 c_29_8)))
(assert
 (not (and c_29_6 c_29_7)))
(assert
 (not (and c_29_6 c_29_8)))
(assert
 (not (and c_29_7 c_29_8)))
(assert
 (let (($x2797 (or false c_30_0)))
 (let (($x2799 (or $x2797 c_30_1)))
 (let (($x2801 (or $x2799 c_30_2)))
 (let (($x2803 (or $x2801 c_30_3)))
 (let (($x2805 (or $x2803 c_30_4)))
 (let (($x2807 (or $x2805 c_30_5)))
 (let (($x2809 (or $x2807 c_30_6)))
 (let (($x2811 (or $x2809 c_30_7)))
 (or $x2811 c_30_8))))))))))
(assert
 (not (and c_30_0 c_30_1)))
(assert
 (not (and c_30_0 c_30_2)))
(assert
 (not (and c_30_0 c_30_3)))
(assert
 (not (and c_30_0 c_30_4)))
(assert
 (not (and c_30_0 c_30_5)))
(assert
 (not (and c_30_0 c_30_6)))
(assert
 (not (and c_30_0 c_30_7)))
(assert
 (not (and c_30_0 c_30_8)))
(assert
 (not (and c_30_1 c_30_2)))
(assert
 (not (and c_30_1 c_30_3)))
(assert
 (not (and c_30_1 c_30_4)))
(assert
 (not (and c_30_1 c_30_5)))
(assert
 (not (and c_30_1 c_30_6)))
(assert
 (not (and c_30_1 c_30_7)))
(assert
 (not (and c_30_1 c_30_8)))
(assert
 (not (and c_30_2 c_30_3)))
(assert
 (not (and c_30_2 c_30_4)))
(assert
 (not (and c_30_2 c_30_5)))
(assert
 (not (and c_30_2 c_30_6)))
(assert
 (not (and c_30_2 c_30_7)))
(assert
 (not (and c_30_2 c_30_8)))
(assert
 (not (and c_30_3 c_30_4)))
(assert
 (not (and c_30_3 c_30_5)))
(assert
 (not (and c_30_3 c_30_6)))
(assert
 (not (and c_30_3 c_30_7)))
(assert
 (not (and c_30_3 c_30_8)))
(assert
 (not (and c_30_4 c_30_5)))
(assert
 (not (and c_30_4 c_30_6)))
(assert
 (not (and c_30_4 c_30_7)))
(assert
 (not (and c_30_4 c_30_8)))
(assert
 (not (and c_30_5 c_30_6)))
(assert
 (not (and c_30_5 c_30_7)))
(assert
 (not (and c_30_5 c_30_8)))
(assert
 (not (and c_30_6 c_30_7)))
(assert
 (not (and c_30_6 c_30_8)))
(assert
 (not (and c_30_7 c_30_8)))
(assert
 (let (($x2887 (or false c_31_0)))
 (let (($x2889 (or $x2887 c_31_1)))
 (let (($x2891 (or $x2889 c_31_2)))
 (let (($x2893 (or $x2891 c_31_3)))
 (let (($x2895 (or $x2893 c_31_4)))
 (let (($x2897 (or $x2895 c_31_5)))
 (let (($x2899 (or $x2897 c_31_6)))
 (let (($x2901 (or $x2899 c_31_7)))
 (or $x2901 c_31_8))))))))))
(assert
 (not (and c_31_0 c_31_1)))
(assert
 (not (and c_31_0 c_31_2)))
(assert
 (not (and c_31_0 c_31_3)))
(assert
 (not (and c_31_0 c_31_4)))
(assert
 (not (and c_31_0 c_31_5)))
(assert
 (not (and c_31_0 c_31_6)))
(assert
 (not (and c_31_0 c_31_7)))
(assert
 (not (and c_31_0 c_31_8)))
(assert
 (not (and c_31_1 c_31_2)))
(assert
 (not (and c_31_1 c_31_3)))
(assert
 (not (and c_31_1 c_31_4)))
(assert
 (not (and c_31_1 c_31_5)))
(assert
 (not (and c_31_1 c_31_6)))
(assert
 (not (and c_31_1 c_31_7)))
(assert
 (not (and c_31_1 c_31_8)))
(assert
 (not (and c_31_2 c_31_3)))
(assert
 (not (and c_31_2 c_31_4)))
(assert
 (not (and c_31_2 c_31_5)))
(assert
 (not (and c_31_2 c_31_6)))
(assert
 (not (and c_31_2 c_31_7)))
(assert
 (not (and c_31_2 c_31_8)))
(assert
 (not (and c_31_3 c_31_4)))
(assert
 (not (and c_31_3 c_31_5)))
(assert
 (not (and c_31_3 c_31_6)))
(assert
 (not (and c_31_3 c_31_7)))
(assert
 (not (and c_31_3 c_31_8)))
(assert
 (not (and c_31_4 c_31_5)))
(assert
 (not (and c_31_4 c_31_6)))
(assert
 (not (and c_31_4 c_31_7)))
(assert
 (not (and c_31_4 c_31_8)))
(assert
 (not (and c_31_5 c_31_6)))
(assert
 (not (and c_31_5 c_31_7)))
(assert
 (not (and c_31_5 c_31_8)))
(assert
 (not (and c_31_6 c_31_7)))
(assert
 (not (and c_31_6 c_31_8)))
(assert
 (not (and c_31_7 c_31_8)))
(assert
 (let (($x2977 (or false c_32_0)))
 (let (($x2979 (or $x2977 c_32_1)))
 (let (($x2981 (or $x2979 c_32_2)))
 (let (($x2983 (or $x2981 c_32_3)))
 (let (($x2985 (or $x2983 c_32_4)))
 (let (($x2987 (or $x2985 c_32_5)))
 (let (($x2989 (or $x2987 c_32_6)))
 (let (($x2991 (or $x2989 c_32_7)))
 (or $x2991 c_32_8))))))))))
(assert
 (not (and c_32_0 c_32_1)))
(assert
 (not (and c_32_0 c_32_2)))
(assert
 (not (and c_32_0 c_32_3)))
(assert
 (not (and c_32_0 c_32_4)))
(assert
 (not (and c_32_0 c_32_5)))
(assert
 (not (and c_32_0 c_32_6)))
(assert
 (not (and c_32_0 c_32_7)))
(assert
 (not (and c_32_0 c_32_8)))
(assert
 (not (and c_32_1 c_32_2)))
(assert
 (not (and c_32_1 c_32_3)))
(assert
 (not (and c_32_1 c_32_4)))
(assert
 (not (and c_32_1 c_32_5)))
(assert
 (not (and c_32_1 c_32_6)))
(assert
 (not (and c_32_1 c_32_7)))
(assert
 (not (and c_32_1 c_32_8)))
(assert
 (not (and c_32_2 c_32_3)))
(assert
 (not (and c_32_2 c_32_4)))
(assert
 (not (and c_32_2 c_32_5)))
(assert
 (not (and c_32_2 c_32_6)))
(assert
 (not (and c_32_2 c_32_7)))
(assert
 (not (and c_32_2 c_32_8)))
(assert
 (not (and c_32_3 c_32_4)))
(assert
 (not (and c_32_3 c_32_5)))
(assert
 (not (and c_32_3 c_32_6)))
(assert
 (not (and c_32_3 c_32_7)))
(assert
 (not (and c_32_3 c_32_8)))
(assert
 (not (and c_32_4 c_32_5)))
(assert
 (not (and c_32_4 c_32_6)))
(assert
 (not (and c_32_4 c_32_7)))
(assert
 (not (and c_32_4 c_32_8)))
(assert
 (not (and c_32_5 c_32_6)))
(assert
 (not (and c_32_5 c_32_7)))
(assert
 (not (and c_32_5 c_32_8)))
(assert
 (not (and c_32_6 c_32_7)))
(assert
 (not (and c_32_6 c_32_8)))
(assert
 (not (and c_32_7 c_32_8)))
(assert
 (let (($x3067 (or false c_33_0)))
 (let (($x3069 (or $x3067 c_33_1)))
 (let (($x3071 (or $x3069 c_33_2)))
 (let (($x3073 (or $x3071 c_33_3)))
 (let (($x3075 (or $x3073 c_33_4)))
 (let (($x3077 (or $x3075 c_33_5)))
 (let (($x3079 (or $x3077 c_33_6)))
 (let (($x3081 (or $x3079 c_33_7)))
 (or $x3081 c_33_8))))))))))
(assert
 (not (and c_33_0 c_33_1)))
(assert
 (not (and c_33_0 c_33_2)))
(assert
 (not (and c_33_0 c_33_3)))
(assert
 (not (and c_33_0 c_33_4)))
(assert
 (not (and c_33_0 c_33_5)))
(assert
 (not (and c_33_0 c_33_6)))
(assert
 (not (and c_33_0 c_33_7)))
(assert
 (not (and c_33_0 c_33_8)))
(assert
 (not (and c_33_1 c_33_2)))
(assert
 (not (and c_33_1 c_33_3)))
(assert
 (not (and c_33_1 c_33_4)))
(assert
 (not (and c_33_1 c_33_5)))
(assert
 (not (and c_33_1 c_33_6)))
(assert
 (not (and c_33_1 c_33_7)))
(assert
 (not (and c_33_1 c_33_8)))
(assert
 (not (and c_33_2 c_33_3)))
(assert
 (not (and c_33_2 c_33_4)))
(assert
 (not (and c_33_2 c_33_5)))
(assert
 (not (and c_33_2 c_33_6)))
(assert
 (not (and c_33_2 c_33_7)))
(assert
 (not (and c_33_2 c_33_8)))
(assert
 (not (and c_33_3 c_33_4)))
(assert
 (not (and c_33_3 c_33_5)))
(assert
 (not (and c_33_3 c_33_6)))
(assert
 (not (and c_33_3 c_33_7)))
(assert
 (not (and c_33_3 c_33_8)))
(assert
 (not (and c_33_4 c_33_5)))
(assert
 (not (and c_33_4 c_33_6)))
(assert
 (not (and c_33_4 c_33_7)))
(assert
 (not (and c_33_4 c_33_8)))
(assert
 (not (and c_33_5 c_33_6)))
(assert
 (not (and c_33_5 c_33_7)))
(assert
 (not (and c_33_5 c_33_8)))
(assert
 (not (and c_33_6 c_33_7)))
(assert
 (not (and c_33_6 c_33_8)))
(assert
 (not (and c_33_7 c_33_8)))
(assert
 (let (($x3157 (or false c_34_0)))
 (let (($x3159 (or $x3157 c_34_1)))
 (let (($x3161 (or $x3159 c_34_2)))
 (let (($x3163 (or $x3161 c_34_3)))
 (let (($x3165 (or $x3163 c_34_4)))
 (let (($x3167 (or $x3165 c_34_5)))
 (let (($x3169 (or $x3167 c_34_6)))
 (let (($x3171 (or $x3169 c_34_7)))
 (or $x3171 c_34_8))))))))))
(assert
 (not (and c_34_0 c_34_1)))
(assert
 (not (and c_34_0 c_34_2)))
(assert
 (not (and c_34_0 c_34_3)))
(assert
 (not (and c_34_0 c_34_4)))
(assert
 (not (and c_34_0 c_34_5)))
(assert
 (not (and c_34_0 c_34_6)))
(assert
 (not (and c_34_0 c_34_7)))
(assert
 (not (and c_34_0 c_34_8)))
(assert
 (not (and c_34_1 c_34_2)))
(assert
 (not (and c_34_1 c_34_3)))
(assert
 (not (and c_34_1 c_34_4)))
(assert
 (not (and c_34_1 c_34_5)))
(assert
 (not (and c_34_1 c_34_6)))
(assert
 (not (and c_34_1 c_34_7)))
(assert
 (not (and c_34_1 c_34_8)))
(assert
 (not (and c_34_2 c_34_3)))
(assert
 (not (and c_34_2 c_34_4)))
(assert
 (not (and c_34_2 c_34_5)))
(assert
 (not (and c_34_2 c_34_6)))
(assert
 (not (and c_34_2 c_34_7)))
(assert
 (not (and c_34_2 c_34_8)))
(assert
 (not (and c_34_3 c_34_4)))
(assert
 (not (and c_34_3 c_34_5)))
(assert
 (not (and c_34_3 c_34_6)))
(assert
 (not (and c_34_3 c_34_7)))
(assert
 (not (and c_34_3 c_34_8)))
(assert
 (not (and c_34_4 c_34_5)))
(assert
 (not (and c_34_4 c_34_6)))
(assert
 (not (and c_34_4 c_34_7)))
(assert
 (not (and c_34_4 c_34_8)))
(assert
 (not (and c_34_5 c_34_6)))
(assert
 (not (and c_34_5 c_34_7)))
(assert
 (not (and c_34_5 c_34_8)))
(assert
 (not (and c_34_6 c_34_7)))
(assert
 (not (and c_34_6 c_34_8)))
(assert
 (not (and c_34_7 c_34_8)))
(assert
 (let (($x3247 (or false c_35_0)))
 (let (($x3249 (or $x3247 c_35_1)))
 (let (($x3251 (or $x3249 c_35_2)))
 (let (($x3253 (or $x3251 c_35_3)))
 (let (($x3255 (or $x3253 c_35_4)))
 (let (($x3257 (or $x3255 c_35_5)))
 (let (($x3259 (or $x3257 c_35_6)))
 (let (($x3261 (or $x3259 c_35_7)))
 (or $x3261 c_35_8))))))))))
(assert
 (not (and c_35_0 c_35_1)))
(assert
 (not (and c_35_0 c_35_2)))
(assert
 (not (and c_35_0 c_35_3)))
(assert
 (not (and c_35_0 c_35_4)))
(assert
 (not (and c_35_0 c_35_5)))
(assert
 (not (and c_35_0 c_35_6)))
(assert
 (not (and c_35_0 c_35_7)))
(assert
 (not (and c_35_0 c_35_8)))
(assert
 (not (and c_35_1 c_35_2)))
(assert
 (not (and c_35_1 c_35_3)))
(assert
 (not (and c_35_1 c_35_4)))
(assert
 (not (and c_35_1 c_35_5)))
(assert
 (not (and c_35_1 c_35_6)))
(assert
 (not (and c_35_1 c_35_7)))
(assert
 (not (and c_35_1 c_35_8)))
(assert
 (not (and c_35_2 c_35_3)))
(assert
 (not (and c_35_2 c_35_4)))
(assert
 (not (and c_35_2 c_35_5)))
(assert
 (not (and c_35_2 c_35_6)))
(assert
 (not (and c_35_2 c_35_7)))
(assert
 (not (and c_35_2 c_35_8)))
(assert
 (not (and c_35_3 c_35_4)))
(assert
 (not (and c_35_3 c_35_5)))
(assert
 (not (and c_35_3 c_35_6)))
(assert
 (not (and c_35_3 c_35_7)))
(assert
 (not (and c_35_3 c_35_8)))
(assert
 (not (and c_35_4 c_35_5)))
(assert
 (not (and c_35_4 c_35_6)))
(assert
 (not (and c_35_4 c_35_7)))
(assert
 (not (and c_35_4 c_35_8)))
(assert
 (not (and c_35_5 c_35_6)))
(assert
 (not (and c_35_5 c_35_7)))
(assert
 (not (and c_35_5 c_35_8)))
(assert
 (not (and c_35_6 c_35_7)))
(assert
 (not (and c_35_6 c_35_8)))
(assert
 (not (and c_35_7 c_35_8)))
(assert
 (let (($x3337 (or false c_36_0)))
 (let (($x3339 (or $x3337 c_36_1)))
 (let (($x3341 (or $x3339 c_36_2)))
 (let (($x3343 (or $x3341 c_36_3)))
 (let (($x3345 (or $x3343 c_36_4)))
 (let (($x3347 (or $x3345 c_36_5)))
 (let (($x3349 (or $x3347 c_36_6)))
 (let (($x3351 (or $x3349 c_36_7)))
 (or $x3351 c_36_8))))))))))
(assert
 (not (and c_36_0 c_36_1)))
(assert
 (not (and c_36_0 c_36_2)))
(assert
 (not (and c_36_0 c_36_3)))
(assert
 (not (and c_36_0 c_36_4)))
(assert
 (not (and c_36_0 c_36_5)))
(assert
 (not (and c_36_0 c_36_6)))
(assert
 (not (and c_36_0 c_36_7)))
(assert
 (not (and c_36_0 c_36_8)))
(assert
 (not (and c_36_1 c_36_2)))
(assert
 (not (and c_36_1 c_36_3)))
(assert
 (not (and c_36_1 c_36_4)))
(assert
 (not (and c_36_1 c_36_5)))
(assert
 (not (and c_36_1 c_36_6)))
(assert
 (not (and c_36_1 c_36_7)))
(assert
 (not (and c_36_1 c_36_8)))
(assert
 (not (and c_36_2 c_36_3)))
(assert
 (not (and c_36_2 c_36_4)))
(assert
 (not (and c_36_2 c_36_5)))
(assert
 (not (and c_36_2 c_36_6)))
(assert
 (not (and c_36_2 c_36_7)))
(assert
 (not (and c_36_2 c_36_8)))
(assert
 (not (and c_36_3 c_36_4)))
(assert
 (not (and c_36_3 c_36_5)))
(assert
 (not (and c_36_3 c_36_6)))
(assert
 (not (and c_36_3 c_36_7)))
(assert
 (not (and c_36_3 c_36_8)))
(assert
 (not (and c_36_4 c_36_5)))
(assert
 (not (and c_36_4 c_36_6)))
(assert
 (not (and c_36_4 c_36_7)))
(assert
 (not (and c_36_4 c_36_8)))
(assert
 (not (and c_36_5 c_36_6)))
(assert
 (not (and c_36_5 c_36_7)))
(assert
 (not (and c_36_5 c_36_8)))
(assert
 (not (and c_36_6 c_36_7)))
(assert
 (not (and c_36_6 c_36_8)))
(assert
 (not (and c_36_7 c_36_8)))
(assert
 (let (($x3427 (or false c_37_0)))
 (let (($x3429 (or $x3427 c_37_1)))
 (let (($x3431 (or $x3429 c_37_2)))
 (let (($x3433 (or $x3431 c_37_3)))
 (let (($x3435 (or $x3433 c_37_4)))
 (let (($x3437 (or $x3435 c_37_5)))
 (let (($x3439 (or $x3437 c_37_6)))
 (let (($x3441 (or $x3439 c_37_7)))
 (or $x3441 c_37_8))))))))))
(assert
 (not (and c_37_0 c_37_1)))
(assert
 (not (and c_37_0 c_37_2)))
(assert
 (not (and c_37_0 c_37_3)))
(assert
 (not (and c_37_0 c_37_4)))
(assert
 (not (and c_37_0 c_37_5)))
(assert
 (not (and c_37_0 c_37_6)))
(assert
 (not (and c_37_0 c_37_7)))
(assert
 (not (and c_37_0 c_37_8)))
(assert
 (not (and c_37_1 c_37_2)))
(assert
 (not (and c_37_1 c_37_3)))
(assert
 (not (and c_37_1 c_37_4)))
(assert
 (not (and c_37_1 c_37_5)))
(assert
 (not (and c_37_1 c_37_6)))
(assert
 (not (and c_37_1 c_37_7)))
(assert
 (not (and c_37_1 c_37_8)))
(assert
 (not (and c_37_2 c_37_3)))
(assert
 (not (and c_37_2 c_37_4)))
(assert
 (not (and c_37_2 c_37_5)))
(assert
 (not (and c_37_2 c_37_6)))
(assert
 (not (and c_37_2 c_37_7)))
(assert
 (not (and c_37_2 c_37_8)))
(assert
 (not (and c_37_3 c_37_4)))
(assert
 (not (and c_37_3 c_37_5)))
(assert
 (not (and c_37_3 c_37_6)))
(assert
 (not (and c_37_3 c_37_7)))
(assert
 (not (and c_37_3 c_37_8)))
(assert
 (not (and c_37_4 c_37_5)))
(assert
 (not (and c_37_4 c_37_6)))
(assert
 (not (and c_37_4 c_37_7)))
(assert
 (not (and c_37_4 c_37_8)))
(assert
 (not (and c_37_5 c_37_6)))
(assert
 (not (and c_37_5 c_37_7)))
(assert
 (not (and c_37_5 c_37_8)))
(assert
 (not (and c_37_6 c_37_7)))
(assert
 (not (and c_37_6 c_37_8)))
(assert
 (not (and c_37_7 c_37_8)))
(assert
 (let (($x3517 (or false c_38_0)))
 (let (($x3519 (or $x3517 c_38_1)))
 (let (($x3521 (or $x3519 c_38_2)))
 (let (($x3523 (or $x3521 c_38_3)))
 (let (($x3525 (or $x3523 c_38_4)))
 (let (($x3527 (or $x3525 c_38_5)))
 (let (($x3529 (or $x3527 c_38_6)))
 (let (($x3531 (or $x3529 c_38_7)))
 (or $x3531 c_38_8))))))))))
(assert
 (not (and c_38_0 c_38_1)))
(assert
 (not (and c_38_0 c_38_2)))
(assert
 (not (and c_38_0 c_38_3)))
(assert
 (not (and c_38_0 c_38_4)))
(assert
 (not (and c_38_0 c_38_5)))
(assert
 (not (and c_38_0 c_38_6)))
(assert
 (not (and c_38_0 c_38_7)))
(assert
 (not (and c_38_0 c_38_8)))
(assert
 (not (and c_38_1 c_38_2)))
(assert
 (not (and c_38_1 c_38_3)))
(assert
 (not (and c_38_1 c_38_4)))
(assert
 (not (and c_38_1 c_38_5)))
(assert
 (not (and c_38_1 c_38_6)))
(assert
 (not (and c_38_1 c_38_7)))
(assert
 (not (and c_38_1 c_38_8)))
(assert
 (not (and c_38_2 c_38_3)))
(assert
 (not (and c_38_2 c_38_4)))
(assert
 (not (and c_38_2 c_38_5)))
(assert
 (not (and c_38_2 c_38_6)))
(assert
 (not (and c_38_2 c_38_7)))
(assert
 (not (and c_38_2 c_38_8)))
(assert
 (not (and c_38_3 c_38_4)))
(assert
 (not (and c_38_3 c_38_5)))
(assert
 (not (and c_38_3 c_38_6)))
(assert
 (not (and c_38_3 c_38_7)))
(assert
 (not (and c_38_3 c_38_8)))
(assert
 (not (and c_38_4 c_38_5)))
(assert
 (not (and c_38_4 c_38_6)))
(assert
 (not (and c_38_4 c_38_7)))
(assert
 (not (and c_38_4 c_38_8)))
(assert
 (not (and c_38_5 c_38_6)))
(assert
 (not (and c_38_5 c_38_7)))
(assert
 (not (and c_38_5 c_38_8)))
(assert
 (not (and c_38_6 c_38_7)))
(assert
 (not (and c_38_6 c_38_8)))
(assert
 (not (and c_38_7 c_38_8)))
(assert
 (let (($x3607 (or false c_39_0)))
 (let (($x3609 (or $x3607 c_39_1)))
 (let (($x3611 (or $x3609 c_39_2)))
 (let (($x3613 (or $x3611 c_39_3)))
 (let (($x3615 (or $x3613 c_39_4)))
 (let (($x3617 (or $x3615 c_39_5)))
 (let (($x3619 (or $x3617 c_39_6)))
 (let (($x3621 (or $x3619 c_39_7)))
 (or $x3621 c_39_8))))))))))
(assert
 (not (and c_39_0 c_39_1)))
(assert
 (not (and c_39_0 c_39_2)))
(assert
 (not (and c_39_0 c_39_3)))
(assert
 (not (and c_39_0 c_39_4)))
(assert
 (not (and c_39_0 c_39_5)))
(assert
 (not (and c_39_0 c_39_6)))
(assert
 (not (and c_39_0 c_39_7)))
(assert
 (not (and c_39_0 c_39_8)))
(assert
 (not (and c_39_1 c_39_2)))
(assert
 (not (and c_39_1 c_39_3)))
(assert
 (not (and c_39_1 c_39_4)))
(assert
 (not (and c_39_1 c_39_5)))
(assert
 (not (and c_39_1 c_39_6)))
(assert
 (not (and c_39_1 c_39_7)))
(assert
 (not (and c_39_1 c_39_8)))
(assert
 (not (and c_39_2 c_39_3)))
(assert
 (not (and c_39_2 c_39_4)))
(assert
 (not (and c_39_2 c_39_5)))
(assert
 (not (and c_39_2 c_39_6)))
(assert
 (not (and c_39_2 c_39_7)))
(assert
 (not (and c_39_2 c_39_8)))
(assert
 (not (and c_39_3 c_39_4)))
(assert
 (not (and c_39_3 c_39_5)))
(assert
 (not (and c_39_3 c_39_6)))
(assert
 (not (and c_39_3 c_39_7)))
(assert
 (not (and c_39_3 c_39_8)))
(assert
 (not (and c_39_4 c_39_5)))
(assert
 (not (and c_39_4 c_39_6)))
(assert
 (not (and c_39_4 c_39_7)))
(assert
 (not (and c_39_4 c_39_8)))
(assert
 (not (and c_39_5 c_39_6)))
(assert
 (not (and c_39_5 c_39_7)))
(assert
 (not (and c_39_5 c_39_8)))
(assert
 (not (and c_39_6 c_39_7)))
(assert
 (not (and c_39_6 c_39_8)))
(assert
 (not (and c_39_7 c_39_8)))
(assert
 (let (($x3697 (or false c_40_0)))
 (let (($x3699 (or $x3697 c_40_1)))
 (let (($x3701 (or $x3699 c_40_2)))
 (let (($x3703 (or $x3701 c_40_3)))
 (let (($x3705 (or $x3703 c_40_4)))
 (let (($x3707 (or $x3705 c_40_5)))
 (let (($x3709 (or $x3707 c_40_6)))
 (let (($x3711 (or $x3709 c_40_7)))
 (or $x3711 c_40_8))))))))))
(assert
 (not (and c_40_0 c_40_1)))
(assert
 (not (and c_40_0 c_40_2)))
(assert
 (not (and c_40_0 c_40_3)))
(assert
 (not (and c_40_0 c_40_4)))
(assert
 (not (and c_40_0 c_40_5)))
(assert
 (not (and c_40_0 c_40_6)))
(assert
 (not (and c_40_0 c_40_7)))
(assert
 (not (and c_40_0 c_40_8)))
(assert
 (not (and c_40_1 c_40_2)))
(assert
 (not (and c_40_1 c_40_3)))
(assert
 (not (and c_40_1 c_40_4)))
(assert
 (not (and c_40_1 c_40_5)))
(assert
 (not (and c_40_1 c_40_6)))
(assert
 (not (and c_40_1 c_40_7)))
(assert
 (not (and c_40_1 c_40_8)))
(assert
 (not (and c_40_2 c_40_3)))
(assert
 (not (and c_40_2 c_40_4)))
(assert
 (not (and c_40_2 c_40_5)))
(assert
 (not (and c_40_2 c_40_6)))
(assert
 (not (and c_40_2 c_40_7)))
(assert
 (not (and c_40_2 c_40_8)))
(assert
 (not (and c_40_3 c_40_4)))
(assert
 (not (and c_40_3 c_40_5)))
(assert
 (not (and c_40_3 c_40_6)))
(assert
 (not (and c_40_3 c_40_7)))
(assert
 (not (and c_40_3 c_40_8)))
(assert
 (not (and c_40_4 c_40_5)))
(assert
 (not (and c_40_4 c_40_6)))
(assert
 (not (and c_40_4 c_40_7)))
(assert
 (not (and c_40_4 c_40_8)))
(assert
 (not (and c_40_5 c_40_6)))
(assert
 (not (and c_40_5 c_40_7)))
(assert
 (not (and c_40_5 c_40_8)))
(assert
 (not (and c_40_6 c_40_7)))
(assert
 (not (and c_40_6 c_40_8)))
(assert
 (not (and c_40_7 c_40_8)))
(assert
 (let (($x3787 (or false c_41_0)))
 (let (($x3789 (or $x3787 c_41_1)))
 (let (($x3791 (or $x3789 c_41_2)))
 (let (($x3793 (or $x3791 c_41_3)))
 (let (($x3795 (or $x3793 c_41_4)))
 (let (($x3797 (or $x3795 c_41_5)))
 (let (($x3799 (or $x3797 c_41_6)))
 (let (($x3801 (or $x3799 c_41_7)))
 (or $x3801 c_41_8))))))))))
(assert
 (not (and c_41_0 c_41_1)))
(assert
 (not (and c_41_0 c_41_2)))
(assert
 (not (and c_41_0 c_41_3)))
(assert
 (not (and c_41_0 c_41_4)))
(assert
 (not (and c_41_0 c_41_5)))
(assert
 (not (and c_41_0 c_41_6)))
(assert
 (not (and c_41_0 c_41_7)))
(assert
 (not (and c_41_0 c_41_8)))
(assert
 (not (and c_41_1 c_41_2)))
(assert
 (not (and c_41_1 c_41_3)))
(assert
 (not (and c_41_1 c_41_4)))
(assert
 (not (and c_41_1 c_41_5)))
(assert
 (not (and c_41_1 c_41_6)))
(assert
 (not (and c_41_1 c_41_7)))
(assert
 (not (and c_41_1 c_41_8)))
(assert
 (not (and c_41_2 c_41_3)))
(assert
 (not (and c_41_2 c_41_4)))
(assert
 (not (and c_41_2 c_41_5)))
(assert
 (not (and c_41_2 c_41_6)))
(assert
 (not (and c_41_2 c_41_7)))
(assert
 (not (and c_41_2 c_41_8)))
(assert
 (not (and c_41_3 c_41_4)))
(assert
 (not (and c_41_3 c_41_5)))
(assert
 (not (and c_41_3 c_41_6)))
(assert
 (not (and c_41_3 c_41_7)))
(assert
 (not (and c_41_3 c_41_8)))
(assert
 (not (and c_41_4 c_41_5)))
(assert
 (not (and c_41_4 c_41_6)))
(assert
 (not (and c_41_4 c_41_7)))
(assert
 (not (and c_41_4 c_41_8)))
(assert
 (not (and c_41_5 c_41_6)))
(assert
 (not (and c_41_5 c_41_7)))
(assert
 (not (and c_41_5 c_41_8)))
(assert
 (not (and c_41_6 c_41_7)))
(assert
 (not (and c_41_6 c_41_8)))
(assert
 (not (and c_41_7 c_41_8)))
(assert
 (let (($x3877 (or false c_42_0)))
 (let (($x3879 (or $x3877 c_42_1)))
 (let (($x3881 (or $x3879 c_42_2)))
 (let (($x3883 (or $x3881 c_42_3)))
 (let (($x3885 (or $x3883 c_42_4)))
 (let (($x3887 (or $x3885 c_42_5)))
 (let (($x3889 (or $x3887 c_42_6)))
 (let (($x3891 (or $x3889 c_42_7)))
 (or $x3891 c_42_8))))))))))
(assert
 (not (and c_42_0 c_42_1)))
(assert
 (not (and c_42_0 c_42_2)))
(assert
 (not (and c_42_0 c_42_3)))
(assert
 (not (and c_42_0 c_42_4)))
(assert
 (not (and c_42_0 c_42_5)))
(assert
 (not (and c_42_0 c_42_6)))
(assert
 (not (and c_42_0 c_42_7)))
(assert
 (not (and c_42_0 c_42_8)))
(assert
 (not (and c_42_1 c_42_2)))
(assert
 (not (and c_42_1 c_42_3)))
(assert
 (not (and c_42_1 c_42_4)))
(assert
 (not (and c_42_1 c_42_5)))
(assert
 (not (and c_42_1 c_42_6)))
(assert
 (not (and c_42_1 c_42_7)))
(assert
 (not (and c_42_1 c_42_8)))
(assert
 (not (and c_42_2 c_42_3)))
(assert
 (not (and c_42_2 c_42_4)))
(assert
 (not (and c_42_2 c_42_5)))
(assert
 (not (and c_42_2 c_42_6)))
(assert
 (not (and c_42_2 c_42_7)))
(assert
 (not (and c_42_2 c_42_8)))
(assert
 (not (and c_42_3 c_42_4)))
(assert
 (not (and c_42_3 c_42_5)))
(assert
 (not (and c_42_3 c_42_6)))
(assert
 (not (and c_42_3 c_42_7)))
(assert
 (not (and c_42_3 c_42_8)))
(assert
 (not (and c_42_4 c_42_5)))
(assert
 (not (and c_42_4 c_42_6)))
(assert
 (not (and c_42_4 c_42_7)))
(assert
 (not (and c_42_4 c_42_8)))
(assert
 (not (and c_42_5 c_42_6)))
(assert
 (not (and c_42_5 c_42_7)))
(assert
 (not (and c_42_5 c_42_8)))
(assert
 (not (and c_42_6 c_42_7)))
(assert
 (not (and c_42_6 c_42_8)))
(assert
 (not (and c_42_7 c_42_8)))
(assert
 (let (($x3967 (or false c_43_0)))
 (let (($x3969 (or $x3967 c_43_1)))
 (let (($x3971 (or $x3969 c_43_2)))
 (let (($x3973 (or $x3971 c_43_3)))
 (let (($x3975 (or $x3973 c_43_4)))
 (let (($x3977 (or $x3975 c_43_5)))
 (let (($x3979 (or $x3977 c_43_6)))
 (let (($x3981 (or $x3979 c_43_7)))
 (or $x3981 c_43_8))))))))))
(assert
 (not (and c_43_0 c_43_1)))
(assert
 (not (and c_43_0 c_43_2)))
(assert
 (not (and c_43_0 c_43_3)))
(assert
 (not (and c_43_0 c_43_4)))
(assert
 (not (and c_43_0 c_43_5)))
(assert
 (not (and c_43_0 c_43_6)))
(assert
 (not (and c_43_0 c_43_7)))
(assert
 (not (and c_43_0 c_43_8)))
(assert
 (not (and c_43_1 c_43_2)))
(assert
 (not (and c_43_1 c_43_3)))
(assert
 (not (and c_43_1 c_43_4)))
(assert
 (not (and c_43_1 c_43_5)))
(assert
 (not (and c_43_1 c_43_6)))
(assert
 (not (and c_43_1 c_43_7)))
(assert
 (not (and c_43_1 c_43_8)))
(assert
 (not (and c_43_2 c_43_3)))
(assert
 (not (and c_43_2 c_43_4)))
(assert
 (not (and c_43_2 c_43_5)))
(assert
 (not (and c_43_2 c_43_6)))
(assert
 (not (and c_43_2 c_43_7)))
(assert
 (not (and c_43_2 c_43_8)))
(assert
 (not (and c_43_3 c_43_4)))
(assert
 (not (and c_43_3 c_43_5)))
(assert
 (not (and c_43_3 c_43_6)))
(assert
 (not (and c_43_3 c_43_7)))
(assert
 (not (and c_43_3 c_43_8)))
(assert
 (not (and c_43_4 c_43_5)))
(assert
 (not (and c_43_4 c_43_6)))
(assert
 (not (and c_43_4 c_43_7)))
(assert
 (not (and c_43_4 c_43_8)))
(assert
 (not (and c_43_5 c_43_6)))
(assert
 (not (and c_43_5 c_43_7)))
(assert
 (not (and c_43_5 c_43_8)))
(assert
 (not (and c_43_6 c_43_7)))
(assert
 (not (and c_43_6 c_43_8)))
(assert
 (not (and c_43_7 c_43_8)))
(assert
 (let (($x4057 (or false c_44_0)))
 (let (($x4059 (or $x4057 c_44_1)))
 (let (($x4061 (or $x4059 c_44_2)))
 (let (($x4063 (or $x4061 c_44_3)))
 (let (($x4065 (or $x4063 c_44_4)))
 (let (($x4067 (or $x4065 c_44_5)))
 (let (($x4069 (or $x4067 c_44_6)))
 (let (($x4071 (or $x4069 c_44_7)))
 (or $x4071 c_44_8))))))))))
(assert
 (not (and c_44_0 c_44_1)))
(assert
 (not (and c_44_0 c_44_2)))
(assert
 (not (and c_44_0 c_44_3)))
(assert
 (not (and c_44_0 c_44_4)))
(assert
 (not (and c_44_0 c_44_5)))
(assert
 (not (and c_44_0 c_44_6)))
(assert
 (not (and c_44_0 c_44_7)))
(assert
 (not (and c_44_0 c_44_8)))
(assert
 (not (and c_44_1 c_44_2)))
(assert
 (not (and c_44_1 c_44_3)))
(assert
 (not (and c_44_1 c_44_4)))
(assert
 (not (and c_44_1 c_44_5)))
(assert
 (not (and c_44_1 c_44_6)))
(assert
 (not (and c_44_1 c_44_7)))
(assert
 (not (and c_44_1 c_44_8)))
(assert
 (not (and c_44_2 c_44_3)))
(assert
 (not (and c_44_2 c_44_4)))
(assert
 (not (and c_44_2 c_44_5)))
(assert
 (not (and c_44_2 c_44_6)))
(assert
 (not (and c_44_2 c_44_7)))
(assert
 (not (and c_44_2 c_44_8)))
(assert
 (not (and c_44_3 c_44_4)))
(assert
 (not (and c_44_3 c_44_5)))
(assert
 (not (and c_44_3 c_44_6)))
(assert
 (not (and c_44_3 c_44_7)))
(assert
 (not (and c_44_3 c_44_8)))
(assert
 (not (and c_44_4 c_44_5)))
(assert
 (not (and c_44_4 c_44_6)))
(assert
 (not (and c_44_4 c_44_7)))
(assert
 (not (and c_44_4 c_44_8)))
(assert
 (not (and c_44_5 c_44_6)))
(assert
 (not (and c_44_5 c_44_7)))
(assert
 (not (and c_44_5 c_44_8)))
(assert
 (not (and c_44_6 c_44_7)))
(assert
 (not (and c_44_6 c_44_8)))
(assert
 (not (and c_44_7 c_44_8)))
(assert
 (let (($x4147 (or false c_45_0)))
 (let (($x4149 (or $x4147 c_45_1)))
 (let (($x4151 (or $x4149 c_45_2)))
 (let (($x4153 (or $x4151 c_45_3)))
 (let (($x4155 (or $x4153 c_45_4)))
 (let (($x4157 (or $x4155 c_45_5)))
 (let (($x4159 (or $x4157 c_45_6)))
 (let (($x4161 (or $x4159 c_45_7)))
 (or $x4161 c_45_8))))))))))
(assert
 (not (and c_45_0 c_45_1)))
(assert
 (not (and c_45_0 c_45_2)))
(assert
 (not (and c_45_0 c_45_3)))
(assert
 (not (and c_45_0 c_45_4)))
(assert
 (not (and c_45_0 c_45_5)))
(assert
 (not (and c_45_0 c_45_6)))
(assert
 (not (and c_45_0 c_45_7)))
(assert
 (not (and c_45_0 c_45_8)))
(assert
 (not (and c_45_1 c_45_2)))
(assert
 (not (and c_45_1 c_45_3)))
(assert
 (not (and c_45_1 c_45_4)))
(assert
 (not (and c_45_1 c_45_5)))
(assert
 (not (and c_45_1 c_45_6)))
(assert
 (not (and c_45_1 c_45_7)))
(assert
 (not (and c_45_1 c_45_8)))
(assert
 (not (and c_45_2 c_45_3)))
(assert
 (not (and c_45_2 c_45_4)))
(assert
 (not (and c_45_2 c_45_5)))
(assert
 (not (and c_45_2 c_45_6)))
(assert
 (not (and c_45_2 c_45_7)))
(assert
 (not (and c_45_2 c_45_8)))
(assert
 (not (and c_45_3 c_45_4)))
(assert
 (not (and c_45_3 c_45_5)))
(assert
 (not (and c_45_3 c_45_6)))
(assert
 (not (and c_45_3 c_45_7)))
(assert
 (not (and c_45_3 c_45_8)))
(assert
 (not (and c_45_4 c_45_5)))
(assert
 (not (and c_45_4 c_45_6)))
(assert
 (not (and c_45_4 c_45_7)))
(assert
 (not (and c_45_4 c_45_8)))
(assert
 (not (and c_45_5 c_45_6)))
(assert
 (not (and c_45_5 c_45_7)))
(assert
 (not (and c_45_5 c_45_8)))
(assert
 (not (and c_45_6 c_45_7)))
(assert
 (not (and c_45_6 c_45_8)))
(assert
 (not (and c_45_7 c_45_8)))
(assert
 (let (($x4237 (or false c_46_0)))
 (let (($x4239 (or $x4237 c_46_1)))
 (let (($x4241 (or $x4239 c_46_2)))
 (let (($x4243 (or $x4241 c_46_3)))
 (let (($x4245 (or $x4243 c_46_4)))
 (let (($x4247 (or $x4245 c_46_5)))
 (let (($x4249 (or $x4247 c_46_6)))
 (let (($x4251 (or $x4249 c_46_7)))
 (or $x4251 c_46_8))))))))))
(assert
 (not (and c_46_0 c_46_1)))
(assert
 (not (and c_46_0 c_46_2)))
(assert
 (not (and c_46_0 c_46_3)))
(assert
 (not (and c_46_0 c_46_4)))
(assert
 (not (and c_46_0 c_46_5)))
(assert
 (not (and c_46_0 c_46_6)))
(assert
 (not (and c_46_0 c_46_7)))
(assert
 (not (and c_46_0 c_46_8)))
(assert
 (not (and c_46_1 c_46_2)))
(assert
 (not (and c_46_1 c_46_3)))
(assert
 (not (and c_46_1 c_46_4)))
(assert
 (not (and c_46_1 c_46_5)))
(assert
 (not (and c_46_1 c_46_6)))
(assert
 (not (and c_46_1 c_46_7)))
(assert
 (not (and c_46_1 c_46_8)))
(assert
 (not (and c_46_2 c_46_3)))
(assert
 (not (and c_46_2 c_46_4)))
(assert
 (not (and c_46_2 c_46_5)))
(assert
 (not (and c_46_2 c_46_6)))
(assert
 (not (and c_46_2 c_46_7)))
(assert
 (not (and c_46_2 c_46_8)))
(assert
 (not (and c_46_3 c_46_4)))
(assert
 (not (and c_46_3 c_46_5)))
(assert
 (not (and c_46_3 c_46_6)))
(assert
 (not (and c_46_3 c_46_7)))
(assert
 (not (and c_46_3 c_46_8)))
(assert
 (not (and c_46_4 c_46_5)))
(assert
 (not (and c_46_4 c_46_6)))
(assert
 (not (and c_46_4 c_46_7)))
(assert
 (not (and c_46_4 c_46_8)))
(assert
 (not (and c_46_5 c_46_6)))
(assert
 (not (and c_46_5 c_46_7)))
(assert
 (not (and c_46_5 c_46_8)))
(assert
 (not (and c_46_6 c_46_7)))
(assert
 (not (and c_46_6 c_46_8)))
(assert
 (not (and c_46_7 c_46_8)))
(assert
 (let (($x4327 (or false c_47_0)))
 (let (($x4329 (or $x4327 c_47_1)))
 (let (($x4331 (or $x4329 c_47_2)))
 (let (($x4333 (or $x4331 c_47_3)))
 (let (($x4335 (or $x4333 c_47_4)))
 (let (($x4337 (or $x4335 c_47_5)))
 (let (($x4339 (or $x4337 c_47_6)))
 (let (($x4341 (or $x4339 c_47_7)))
 (or $x4341 c_47_8))))))))))
(assert
 (not (and c_47_0 c_47_1)))
(assert
 (not (and c_47_0 c_47_2)))
(assert
 (not (and c_47_0 c_47_3)))
(assert
 (not (and c_47_0 c_47_4)))
(assert
 (not (and c_47_0 c_47_5)))
(assert
 (not (and c_47_0 c_47_6)))
(assert
 (not (and c_47_0 c_47_7)))
(assert
 (not (and c_47_0 c_47_8)))
(assert
 (not (and c_47_1 c_47_2)))
(assert
 (not (and c_47_1 c_47_3)))
(assert
 (not (and c_47_1 c_47_4)))
(assert
 (not (and c_47_1 c_47_5)))
(assert
 (not (and c_47_1 c_47_6)))
(assert
 (not (and c_47_1 c_47_7)))
(assert
 (not (and c_47_1 c_47_8)))
(assert
 (not (and c_47_2 c_47_3)))
(assert
 (not (and c_47_2 c_47_4)))
(assert
 (not (and c_47_2 c_47_5)))
(assert
 (not (and c_47_2 c_47_6)))
(assert
 (not (and c_47_2 c_47_7)))
(assert
 (not (and c_47_2 c_47_8)))
(assert
 (not (and c_47_3 c_47_4)))
(assert
 (not (and c_47_3 c_47_5)))
(assert
 (not (and c_47_3 c_47_6)))
(assert
 (not (and c_47_3 c_47_7)))
(assert
 (not (and c_47_3 c_47_8)))
(assert
 (not (and c_47_4 c_47_5)))
(assert
 (not (and c_47_4 c_47_6)))
(assert
 (not (and c_47_4 c_47_7)))
(assert
 (not (and c_47_4 c_47_8)))
(assert
 (not (and c_47_5 c_47_6)))
(assert
 (not (and c_47_5 c_47_7)))
(assert
 (not (and c_47_5 c_47_8)))
(assert
 (not (and c_47_6 c_47_7)))
(assert
 (not (and c_47_6 c_47_8)))
(assert
 (not (and c_47_7 c_47_8)))
(assert
 (let (($x4417 (or false c_48_0)))
 (let (($x4419 (or $x4417 c_48_1)))
 (let (($x4421 (or $x4419 c_48_2)))
 (let (($x4423 (or $x4421 c_48_3)))
 (let (($x4425 (or $x4423 c_48_4)))
 (let (($x4427 (or $x4425 c_48_5)))
 (let (($x4429 (or $x4427 c_48_6)))
 (let (($x4431 (or $x4429 c_48_7)))
 (or $x4431 c_48_8))))))))))
(assert
 (not (and c_48_0 c_48_1)))
(assert
 (not (and c_48_0 c_48_2)))
(assert
 (not (and c_48_0 c_48_3)))
(assert
 (not (and c_48_0 c_48_4)))
(assert
 (not (and c_48_0 c_48_5)))
(assert
 (not (and c_48_0 c_48_6)))
(assert
 (not (and c_48_0 c_48_7)))
(assert
 (not (and c_48_0 c_48_8)))
(assert
 (not (and c_48_1 c_48_2)))
(assert
 (not (and c_48_1 c_48_3)))
(assert
 (not (and c_48_1 c_48_4)))
(assert
 (not (and c_48_1 c_48_5)))
(assert
 (not (and c_48_1 c_48_6)))
(assert
 (not (and c_48_1 c_48_7)))
(assert
 (not (and c_48_1 c_48_8)))
(assert
 (not (and c_48_2 c_48_3)))
(assert
 (not (and c_48_2 c_48_4)))
(assert
 (not (and c_48_2 c_48_5)))
(assert
 (not (and c_48_2 c_48_6)))
(assert
 (not (and c_48_2 c_48_7)))
(assert
 (not (and c_48_2 c_48_8)))
(assert
 (not (and c_48_3 c_48_4)))
(assert
 (not (and c_48_3 c_48_5)))
(assert
 (not (and c_48_3 c_48_6)))
(assert
 (not (and c_48_3 c_48_7)))
(assert
 (not (and c_48_3 c_48_8)))
(assert
 (not (and c_48_4 c_48_5)))
(assert
 (not (and c_48_4 c_48_6)))
(assert
 (not (and c_48_4 c_48_7)))
(assert
 (not (and c_48_4 c_48_8)))
(assert
 (not (and c_48_5 c_48_6)))
(assert
 (not (and c_48_5 c_48_7)))
(assert
 (not (and c_48_5 c_48_8)))
(assert
 (not (and c_48_6 c_48_7)))
(assert
 (not (and c_48_6 c_48_8)))
(assert
 (not (and c_48_7 c_48_8)))
(assert
 (let (($x4507 (or false c_49_0)))
 (let (($x4509 (or $x4507 c_49_1)))
 (let (($x4511 (or $x4509 c_49_2)))
 (let (($x4513 (or $x4511 c_49_3)))
 (let (($x4515 (or $x4513 c_49_4)))
 (let (($x4517 (or $x4515 c_49_5)))
 (let (($x4519 (or $x4517 c_49_6)))
 (let (($x4521 (or $x4519 c_49_7)))
 (or $x4521 c_49_8))))))))))
(assert
 (not (and c_49_0 c_49_1)))
(assert
 (not (and c_49_0 c_49_2)))
(assert
 (not (and c_49_0 c_49_3)))
(assert
 (not (and c_49_0 c_49_4)))
(assert
 (not (and c_49_0 c_49_5)))
(assert
 (not (and c_49_0 c_49_6)))
(assert
 (not (and c_49_0 c_49_7)))
(assert
 (not (and c_49_0 c_49_8)))
(assert
 (not (and c_49_1 c_49_2)))
(assert
 (not (and c_49_1 c_49_3)))
(assert
 (not (and c_49_1 c_49_4)))
(assert
 (not (and c_49_1 c_49_5)))
(assert
 (not (and c_49_1 c_49_6)))
(assert
 (not (and c_49_1 c_49_7)))
(assert
 (not (and c_49_1 c_49_8)))
(assert
 (not (and c_49_2 c_49_3)))
(assert
 (not (and c_49_2 c_49_4)))
(assert
 (not (and c_49_2 c_49_5)))
(assert
 (not (and c_49_2 c_49_6)))
(assert
 (not (and c_49_2 c_49_7)))
(assert
 (not (and c_49_2 c_49_8)))
(assert
 (not (and c_49_3 c_49_4)))
(assert
 (not (and c_49_3 c_49_5)))
(assert
 (not (and c_49_3 c_49_6)))
(assert
 (not (and c_49_3 c_49_7)))
(assert
 (not (and c_49_3 c_49_8)))
(assert
 (not (and c_49_4 c_49_5)))
(assert
 (not (and c_49_4 c_49_6)))
(assert
 (not (and c_49_4 c_49_7)))
(assert
 (not (and c_49_4 c_49_8)))
(assert
 (not (and c_49_5 c_49_6)))
(assert
 (not (and c_49_5 c_49_7)))
(assert
 (not (and c_49_5 c_49_8)))
(assert
 (not (and c_49_6 c_49_7)))
(assert
 (not (and c_49_6 c_49_8)))
(assert
 (not (and c_49_7 c_49_8)))
(assert
 (let (($x4597 (or false c_50_0)))
 (let (($x4599 (or $x4597 c_50_1)))
 (let (($x4601 (or $x4599 c_50_2)))
 (let (($x4603 (or $x4601 c_50_3)))
 (let (($x4605 (or $x4603 c_50_4)))
 (let (($x4607 (or $x4605 c_50_5)))
 (let (($x4609 (or $x4607 c_50_6)))
 (let (($x4611 (or $x4609 c_50_7)))
 (or $x4611 c_50_8))))))))))
(assert
 (not (and c_50_0 c_50_1)))
(assert
 (not (and c_50_0 c_50_2)))
(assert
 (not (and c_50_0 c_50_3)))
(assert
 (not (and c_50_0 c_50_4)))
(assert
 (not (and c_50_0 c_50_5)))
(assert
 (not (and c_50_0 c_50_6)))
(assert
 (not (and c_50_0 c_50_7)))
(assert
 (not (and c_50_0 c_50_8)))
(assert
 (not (and c_50_1 c_50_2)))
(assert
 (not (and c_50_1 c_50_3)))
(assert
 (not (and c_50_1 c_50_4)))
(assert
 (not (and c_50_1 c_50_5)))
(assert
 (not (and c_50_1 c_50_6)))
(assert
 (not (and c_50_1 c_50_7)))
(assert
 (not (and c_50_1 c_50_8)))
(assert
 (not (and c_50_2 c_50_3)))
(assert
 (not (and c_50_2 c_50_4)))
(assert
 (not (and c_50_2 c_50_5)))
(assert
 (not (and c_50_2 c_50_6)))
(assert
 (not (and c_50_2 c_50_7)))
(assert
 (not (and c_50_2 c_50_8)))
(assert
 (not (and c_50_3 c_50_4)))
(assert
 (not (and c_50_3 c_50_5)))
(assert
 (not (and c_50_3 c_50_6)))
(assert
 (not (and c_50_3 c_50_7)))
(assert
 (not (and c_50_3 c_50_8)))
(assert
 (not (and c_50_4 c_50_5)))
(assert
 (not (and c_50_4 c_50_6)))
(assert
 (not (and c_50_4 c_50_7)))
(assert
 (not (and c_50_4 c_50_8)))
(assert
 (not (and c_50_5 c_50_6)))
(assert
 (not (and c_50_5 c_50_7)))
(assert
 (not (and c_50_5 c_50_8)))
(assert
 (not (and c_50_6 c_50_7)))
(assert
 (not (and c_50_6 c_50_8)))
(assert
 (not (and c_50_7 c_50_8)))
(assert
 (let (($x4687 (or false c_51_0)))
 (let (($x4689 (or $x4687 c_51_1)))
 (let (($x4691 (or $x4689 c_51_2)))
 (let (($x4693 (or $x4691 c_51_3)))
 (let (($x4695 (or $x4693 c_51_4)))
 (let (($x4697 (or $x4695 c_51_5)))
 (let (($x4699 (or $x4697 c_51_6)))
 (let (($x4701 (or $x4699 c_51_7)))
 (or $x4701 c_51_8))))))))))
(assert
 (not (and c_51_0 c_51_1)))
(assert
 (not (and c_51_0 c_51_2)))
(assert
 (not (and c_51_0 c_51_3)))
(assert
 (not (and c_51_0 c_51_4)))
(assert
 (not (and c_51_0 c_51_5)))
(assert
 (not (and c_51_0 c_51_6)))
(assert
 (not (and c_51_0 c_51_7)))
(assert
 (not (and c_51_0 c_51_8)))
(assert
 (not (and c_51_1 c_51_2)))
(assert
 (not (and c_51_1 c_51_3)))
(assert
 (not (and c_51_1 c_51_4)))
(assert
 (not (and c_51_1 c_51_5)))
(assert
 (not (and c_51_1 c_51_6)))
(assert
 (not (and c_51_1 c_51_7)))
(assert
 (not (and c_51_1 c_51_8)))
(assert
 (not (and c_51_2 c_51_3)))
(assert
 (not (and c_51_2 c_51_4)))
(assert
 (not (and c_51_2 c_51_5)))
(assert
 (not (and c_51_2 c_51_6)))
(assert
 (not (and c_51_2 c_51_7)))
(assert
 (not (and c_51_2 c_51_8)))
(assert
 (not (and c_51_3 c_51_4)))
(assert
 (not (and c_51_3 c_51_5)))
(assert
 (not (and c_51_3 c_51_6)))
(assert
 (not (and c_51_3 c_51_7)))
(assert
 (not (and c_51_3 c_51_8)))
(assert
 (not (and c_51_4 c_51_5)))
(assert
 (not (and c_51_4 c_51_6)))
(assert
 (not (and c_51_4 c_51_7)))
(assert
 (not (and c_51_4 c_51_8)))
(assert
 (not (and c_51_5 c_51_6)))
(assert
 (not (and c_51_5 c_51_7)))
(assert
 (not (and c_51_5 c_51_8)))
(assert
 (not (and c_51_6 c_51_7)))
(assert
 (not (and c_51_6 c_51_8)))
(assert
 (not (and c_51_7 c_51_8)))
(assert
 (let (($x4777 (or false c_52_0)))
 (let (($x4779 (or $x4777 c_52_1)))
 (let (($x4781 (or $x4779 c_52_2)))
 (let (($x4783 (or $x4781 c_52_3)))
 (let (($x4785 (or $x4783 c_52_4)))
 (let (($x4787 (or $x4785 c_52_5)))
 (let (($x4789 (or $x4787 c_52_6)))
 (let (($x4791 (or $x4789 c_52_7)))
 (or $x4791 c_52_8))))))))))
(assert
 (not (and c_52_0 c_52_1)))
(assert
 (not (and c_52_0 c_52_2)))
(assert
 (not (and c_52_0 c_52_3)))
(assert
 (not (and c_52_0 c_52_4)))
(assert
 (not (and c_52_0 c_52_5)))
(assert
 (not (and c_52_0 c_52_6)))
(assert
 (not (and c_52_0 c_52_7)))
(assert
 (not (and c_52_0 c_52_8)))
(assert
 (not (and c_52_1 c_52_2)))
(assert
 (not (and c_52_1 c_52_3)))
(assert
 (not (and c_52_1 c_52_4)))
(assert
 (not (and c_52_1 c_52_5)))
(assert
 (not (and c_52_1 c_52_6)))
(assert
 (not (and c_52_1 c_52_7)))
(assert
 (not (and c_52_1 c_52_8)))
(assert
 (not (and c_52_2 c_52_3)))
(assert
 (not (and c_52_2 c_52_4)))
(assert
 (not (and c_52_2 c_52_5)))
(assert
 (not (and c_52_2 c_52_6)))
(assert
 (not (and c_52_2 c_52_7)))
(assert
 (not (and c_52_2 c_52_8)))
(assert
 (not (and c_52_3 c_52_4)))
(assert
 (not (and c_52_3 c_52_5)))
(assert
 (not (and c_52_3 c_52_6)))
(assert
 (not (and c_52_3 c_52_7)))
(assert
 (not (and c_52_3 c_52_8)))
(assert
 (not (and c_52_4 c_52_5)))
(assert
 (not (and c_52_4 c_52_6)))
(assert
 (not (and c_52_4 c_52_7)))
(assert
 (not (and c_52_4 c_52_8)))
(assert
 (not (and c_52_5 c_52_6)))
(assert
 (not (and c_52_5 c_52_7)))
(assert
 (not (and c_52_5 c_52_8)))
(assert
 (not (and c_52_6 c_52_7)))
(assert
 (not (and c_52_6 c_52_8)))
(assert
 (not (and c_52_7 c_52_8)))
(assert
 (let (($x4867 (or false c_53_0)))
 (let (($x4869 (or $x4867 c_53_1)))
 (let (($x4871 (or $x4869 c_53_2)))
 (let (($x4873 (or $x4871 c_53_3)))
 (let (($x4875 (or $x4873 c_53_4)))
 (let (($x4877 (or $x4875 c_53_5)))
 (let (($x4879 (or $x4877 c_53_6)))
 (let (($x4881 (or $x4879 c_53_7)))
 (or $x4881 c_53_8))))))))))
(assert
 (not (and c_53_0 c_53_1)))
(assert
 (not (and c_53_0 c_53_2)))
(assert
 (not (and c_53_0 c_53_3)))
(assert
 (not (and c_53_0 c_53_4)))
(assert
 (not (and c_53_0 c_53_5)))
(assert
 (not (and c_53_0 c_53_6)))
(assert
 (not (and c_53_0 c_53_7)))
(assert
 (not (and c_53_0 c_53_8)))
(assert
 (not (and c_53_1 c_53_2)))
(assert
 (not (and c_53_1 c_53_3)))
(assert
 (not (and c_53_1 c_53_4)))
(assert
 (not (and c_53_1 c_53_5)))
(assert
 (not (and c_53_1 c_53_6)))
(assert
 (not (and c_53_1 c_53_7)))
(assert
 (not (and c_53_1 c_53_8)))
(assert
 (not (and c_53_2 c_53_3)))
(assert
 (not (and c_53_2 c_53_4)))
(assert
 (not (and c_53_2 c_53_5)))
(assert
 (not (and c_53_2 c_53_6)))
(assert
 (not (and c_53_2 c_53_7)))
(assert
 (not (and c_53_2 c_53_8)))
(assert
 (not (and c_53_3 c_53_4)))
(assert
 (not (and c_53_3 c_53_5)))
(assert
 (not (and c_53_3 c_53_6)))
(assert
 (not (and c_53_3 c_53_7)))
(assert
 (not (and c_53_3 c_53_8)))
(assert
 (not (and c_53_4 c_53_5)))
(assert
 (not (and c_53_4 c_53_6)))
(assert
 (not (and c_53_4 c_53_7)))
(assert
 (not (and c_53_4 c_53_8)))
(assert
 (not (and c_53_5 c_53_6)))
(assert
 (not (and c_53_5 c_53_7)))
(assert
 (not (and c_53_5 c_53_8)))
(assert
 (not (and c_53_6 c_53_7)))
(assert
 (not (and c_53_6 c_53_8)))
(assert
 (not (and c_53_7 c_53_8)))
(assert
 (let (($x4957 (or false c_54_0)))
 (let (($x4959 (or $x4957 c_54_1)))
 (let (($x4961 (or $x4959 c_54_2)))
 (let (($x4963 (or $x4961 c_54_3)))
 (let (($x4965 (or $x4963 c_54_4)))
 (let (($x4967 (or $x4965 c_54_5)))
 (let (($x4969 (or $x4967 c_54_6)))
 (let (($x4971 (or $x4969 c_54_7)))
 (or $x4971 c_54_8))))))))))
(assert
 (not (and c_54_0 c_54_1)))
(assert
 (not (and c_54_0 c_54_2)))
(assert
 (not (and c_54_0 c_54_3)))
(assert
 (not (and c_54_0 c_54_4)))
(assert
 (not (and c_54_0 c_54_5)))
(assert
 (not (and c_54_0 c_54_6)))
(assert
 (not (and c_54_0 c_54_7)))
(assert
 (not (and c_54_0 c_54_8)))
(assert
 (not (and c_54_1 c_54_2)))
(assert
 (not (and c_54_1 c_54_3)))
(assert
 (not (and c_54_1 c_54_4)))
(assert
 (not (and c_54_1 c_54_5)))
(assert
 (not (and c_54_1 c_54_6)))
(assert
 (not (and c_54_1 c_54_7)))
(assert
 (not (and c_54_1 c_54_8)))
(assert
 (not (and c_54_2 c_54_3)))
(assert
 (not (and c_54_2 c_54_4)))
(assert
 (not (and c_54_2 c_54_5)))
(assert
 (not (and c_54_2 c_54_6)))
(assert
 (not (and c_54_2 c_54_7)))
(assert
 (not (and c_54_2 c_54_8)))
(assert
 (not (and c_54_3 c_54_4)))
(assert
 (not (and c_54_3 c_54_5)))
(assert
 (not (and c_54_3 c_54_6)))
(assert
 (not (and c_54_3 c_54_7)))
(assert
 (not (and c_54_3 c_54_8)))
(assert
 (not (and c_54_4 c_54_5)))
(assert
 (not (and c_54_4 c_54_6)))
(assert
 (not (and c_54_4 c_54_7)))
(assert
 (not (and c_54_4 c_54_8)))
(assert
 (not (and c_54_5 c_54_6)))
(assert
 (not (and c_54_5 c_54_7)))
(assert
 (not (and c_54_5 c_54_8)))
(assert
 (not (and c_54_6 c_54_7)))
(assert
 (not (and c_54_6 c_54_8)))
(assert
 (not (and c_54_7 c_54_8)))
(assert
 (let (($x5047 (or false c_55_0)))
 (let (($x5049 (or $x5047 c_55_1)))
 (let (($x5051 (or $x5049 c_55_2)))
 (let (($x5053 (or $x5051 c_55_3)))
 (let (($x5055 (or $x5053 c_55_4)))
 (let (($x5057 (or $x5055 c_55_5)))
 (let (($x5059 (or $x5057 c_55_6)))
 (let (($x5061 (or $x5059 c_55_7)))
 (or $x5061 c_55_8))))))))))
(assert
 (not (and c_55_0 c_55_1)))
(assert
 (not (and c_55_0 c_55_2)))
(assert
 (not (and c_55_0 c_55_3)))
(assert
 (not (and c_55_0 c_55_4)))
(assert
 (not (and c_55_0 c_55_5)))
(assert
 (not (and c_55_0 c_55_6)))
(assert
 (not (and c_55_0 c_55_7)))
(assert
 (not (and c_55_0 c_55_8)))
(assert
 (not (and c_55_1 c_55_2)))
(assert
 (not (and c_55_1 c_55_3)))
(assert
 (not (and c_55_1 c_55_4)))
(assert
 (not (and c_55_1 c_55_5)))
(assert
 (not (and c_55_1 c_55_6)))
(assert
 (not (and c_55_1 c_55_7)))
(assert
 (not (and c_55_1 c_55_8)))
(assert
 (not (and c_55_2 c_55_3)))
(assert
 (not (and c_55_2 c_55_4)))
(assert
 (not (and c_55_2 c_55_5)))
(assert
 (not (and c_55_2 c_55_6)))
(assert
 (not (and c_55_2 c_55_7)))
(assert
 (not (and c_55_2 c_55_8)))
(assert
 (not (and c_55_3 c_55_4)))
(assert
 (not (and c_55_3 c_55_5)))
(assert
 (not (and c_55_3 c_55_6)))
(assert
 (not (and c_55_3 c_55_7)))
(assert
 (not (and c_55_3 c_55_8)))
(assert
 (not (and c_55_4 c_55_5)))
(assert
 (not (and c_55_4 c_55_6)))
(assert
 (not (and c_55_4 c_55_7)))
(assert
 (not (and c_55_4 c_55_8)))
(assert
 (not (and c_55_5 c_55_6)))
(assert
 (not (and c_55_5 c_55_7)))
(assert
 (not (and c_55_5 c_55_8)))
(assert
 (not (and c_55_6 c_55_7)))
(assert
 (not (and c_55_6 c_55_8)))
(assert
 (not (and c_55_7 c_55_8)))
(assert
 (let (($x5137 (or false c_56_0)))
 (let (($x5139 (or $x5137 c_56_1)))
 (let (($x5141 (or $x5139 c_56_2)))
 (let (($x5143 (or $x5141 c_56_3)))
 (let (($x5145 (or $x5143 c_56_4)))
 (let (($x5147 (or $x5145 c_56_5)))
 (let (($x5149 (or $x5147 c_56_6)))
 (let (($x5151 (or $x5149 c_56_7)))
 (or $x5151 c_56_8))))))))))
(assert
 (not (and c_56_0 c_56_1)))
(assert
 (not (and c_56_0 c_56_2)))
(assert
 (not (and c_56_0 c_56_3)))
(assert
 (not (and c_56_0 c_56_4)))
(assert
 (not (and c_56_0 c_56_5)))
(assert
 (not (and c_56_0 c_56_6)))
(assert
 (not (and c_56_0 c_56_7)))
(assert
 (not (and c_56_0 c_56_8)))
(assert
 (not (and c_56_1 c_56_2)))
(assert
 (not (and c_56_1 c_56_3)))
(assert
 (not (and c_56_1 c_56_4)))
(assert
 (not (and c_56_1 c_56_5)))
(assert
 (not (and c_56_1 c_56_6)))
(assert
 (not (and c_56_1 c_56_7)))
(assert
 (not (and c_56_1 c_56_8)))
(assert
 (not (and c_56_2 c_56_3)))
(assert
 (not (and c_56_2 c_56_4)))
(assert
 (not (and c_56_2 c_56_5)))
(assert
 (not (and c_56_2 c_56_6)))
(assert
 (not (and c_56_2 c_56_7)))
(assert
 (not (and c_56_2 c_56_8)))
(assert
 (not (and c_56_3 c_56_4)))
(assert
 (not (and c_56_3 c_56_5)))
(assert
 (not (and c_56_3 c_56_6)))
(assert
 (not (and c_56_3 c_56_7)))
(assert
 (not (and c_56_3 c_56_8)))
(assert
 (not (and c_56_4 c_56_5)))
(assert
 (not (and c_56_4 c_56_6)))
(assert
 (not (and c_56_4 c_56_7)))
(assert
 (not (and c_56_4 c_56_8)))
(assert
 (not (and c_56_5 c_56_6)))
(assert
 (not (and c_56_5 c_56_7)))
(assert
 (not (and c_56_5 c_56_8)))
(assert
 (not (and c_56_6 c_56_7)))
(assert
 (not (and c_56_6 c_56_8)))
(assert
 (not (and c_56_7 c_56_8)))
(assert
 (let (($x5227 (or false c_57_0)))
 (let (($x5229 (or $x5227 c_57_1)))
 (let (($x5231 (or $x5229 c_57_2)))
 (let (($x5233 (or $x5231 c_57_3)))
 (let (($x5235 (or $x5233 c_57_4)))
 (let (($x5237 (or $x5235 c_57_5)))
 (let (($x5239 (or $x5237 c_57_6)))
 (let (($x5241 (or $x5239 c_57_7)))
 (or $x5241 c_57_8))))))))))
(assert
 (not (and c_57_0 c_57_1)))
(assert
 (not (and c_57_0 c_57_2)))
(assert
 (not (and c_57_0 c_57_3)))
(assert
 (not (and c_57_0 c_57_4)))
(assert
 (not (and c_57_0 c_57_5)))
(assert
 (not (and c_57_0 c_57_6)))
(assert
 (not (and c_57_0 c_57_7)))
(assert
 (not (and c_57_0 c_57_8)))
(assert
 (not (and c_57_1 c_57_2)))
(assert
 (not (and c_57_1 c_57_3)))
(assert
 (not (and c_57_1 c_57_4)))
(assert
 (not (and c_57_1 c_57_5)))
(assert
 (not (and c_57_1 c_57_6)))
(assert
 (not (and c_57_1 c_57_7)))
(assert
 (not (and c_57_1 c_57_8)))
(assert
 (not (and c_57_2 c_57_3)))
(assert
 (not (and c_57_2 c_57_4)))
(assert
 (not (and c_57_2 c_57_5)))
(assert
 (not (and c_57_2 c_57_6)))
(assert
 (not (and c_57_2 c_57_7)))
(assert
 (not (and c_57_2 c_57_8)))
(assert
 (not (and c_57_3 c_57_4)))
(assert
 (not (and c_57_3 c_57_5)))
(assert
 (not (and c_57_3 c_57_6)))
(assert
 (not (and c_57_3 c_57_7)))
(assert
 (not (and c_57_3 c_57_8)))
(assert
 (not (and c_57_4 c_57_5)))
(assert
 (not (and c_57_4 c_57_6)))
(assert
 (not (and c_57_4 c_57_7)))
(assert
 (not (and c_57_4 c_57_8)))
(assert
 (not (and c_57_5 c_57_6)))
(assert
 (not (and c_57_5 c_57_7)))
(assert
 (not (and c_57_5 c_57_8)))
(assert
 (not (and c_57_6 c_57_7)))
(assert
 (not (and c_57_6 c_57_8)))
(assert
 (not (and c_57_7 c_57_8)))
(assert
 (let (($x5317 (or false c_58_0)))
 (let (($x5319 (or $x5317 c_58_1)))
 (let (($x5321 (or $x5319 c_58_2)))
 (let (($x5323 (or $x5321 c_58_3)))
 (let (($x5325 (or $x5323 c_58_4)))
 (let (($x5327 (or $x5325 c_58_5)))
 (let (($x5329 (or $x5327 c_58_6)))
 (let (($x5331 (or $x5329 c_58_7)))
 (or $x5331 c_58_8))))))))))
(assert
 (not (and c_58_0 c_58_1)))
(assert
 (not (and c_58_0 c_58_2)))
(assert
 (not (and c_58_0 c_58_3)))
(assert
 (not (and c_58_0 c_58_4)))
(assert
 (not (and c_58_0 c_58_5)))
(assert
 (not (and c_58_0 c_58_6)))
(assert
 (not (and c_58_0 c_58_7)))
(assert
 (not (and c_58_0 c_58_8)))
(assert
 (not (and c_58_1 c_58_2)))
(assert
 (not (and c_58_1 c_58_3)))
(assert
 (not (and c_58_1 c_58_4)))
(assert
 (not (and c_58_1 c_58_5)))
(assert
 (not (and c_58_1 c_58_6)))
(assert
 (not (and c_58_1 c_58_7)))
(assert
 (not (and c_58_1 c_58_8)))
(assert
 (not (and c_58_2 c_58_3)))
(assert
 (not (and c_58_2 c_58_4)))
(assert
 (not (and c_58_2 c_58_5)))
(assert
 (not (and c_58_2 c_58_6)))
(assert
 (not (and c_58_2 c_58_7)))
(assert
 (not (and c_58_2 c_58_8)))
(assert
 (not (and c_58_3 c_58_4)))
(assert
 (not (and c_58_3 c_58_5)))
(assert
 (not (and c_58_3 c_58_6)))
(assert
 (not (and c_58_3 c_58_7)))
(assert
 (not (and c_58_3 c_58_8)))
(assert
 (not (and c_58_4 c_58_5)))
(assert
 (not (and c_58_4 c_58_6)))
(assert
 (not (and c_58_4 c_58_7)))
(assert
 (not (and c_58_4 c_58_8)))
(assert
 (not (and c_58_5 c_58_6)))
(assert
 (not (and c_58_5 c_58_7)))
(assert
 (not (and c_58_5 c_58_8)))
(assert
 (not (and c_58_6 c_58_7)))
(assert
 (not (and c_58_6 c_58_8)))
(assert
 (not (and c_58_7 c_58_8)))
(assert
 (let (($x5407 (or false c_59_0)))
 (let (($x5409 (or $x5407 c_59_1)))
 (let (($x5411 (or $x5409 c_59_2)))
 (let (($x5413 (or $x5411 c_59_3)))
 (let (($x5415 (or $x5413 c_59_4)))
 (let (($x5417 (or $x5415 c_59_5)))
 (let (($x5419 (or $x5417 c_59_6)))
 (let (($x5421 (or $x5419 c_59_7)))
 (or $x5421 c_59_8))))))))))
(assert
 (not (and c_59_0 c_59_1)))
(assert
 (not (and c_59_0 c_59_2)))
(assert
 (not (and c_59_0 c_59_3)))
(assert
 (not (and c_59_0 c_59_4)))
(assert
 (not (and c_59_0 c_59_5)))
(assert
 (not (and c_59_0 c_59_6)))
(assert
 (not (and c_59_0 c_59_7)))
(assert
 (not (and c_59_0 c_59_8)))
(assert
 (not (and c_59_1 c_59_2)))
(assert
 (not (and c_59_1 c_59_3)))
(assert
 (not (and c_59_1 c_59_4)))
(assert
 (not (and c_59_1 c_59_5)))
(assert
 (not (and c_59_1 c_59_6)))
(assert
 (not (and c_59_1 c_59_7)))
(assert
 (not (and c_59_1 c_59_8)))
(assert
 (not (and c_59_2 c_59_3)))
(assert
 (not (and c_59_2 c_59_4)))
(assert
 (not (and c_59_2 c_59_5)))
(assert
 (not (and c_59_2 c_59_6)))
(assert
 (not (and c_59_2 c_59_7)))
(assert
 (not (and c_59_2 c_59_8)))
(assert
 (not (and c_59_3 c_59_4)))
(assert
 (not (and c_59_3 c_59_5)))
(assert
 (not (and c_59_3 c_59_6)))
(assert
 (not (and c_59_3 c_59_7)))
(assert
 (not (and c_59_3 c_59_8)))
(assert
 (not (and c_59_4 c_59_5)))
(assert
 (not (and c_59_4 c_59_6)))
(assert
 (not (and c_59_4 c_59_7)))
(assert
 (not (and c_59_4 c_59_8)))
(assert
 (not (and c_59_5 c_59_6)))
(assert
 (not (and c_59_5 c_59_7)))
(assert
 (not (and c_59_5 c_59_8)))
(assert
 (not (and c_59_6 c_59_7)))
(assert
 (not (and c_59_6 c_59_8)))
(assert
 (not (and c_59_7 c_59_8)))
(assert
 (let (($x5497 (or false c_60_0)))
 (let (($x5499 (or $x5497 c_60_1)))
 (let (($x5501 (or $x5499 c_60_2)))
 (let (($x5503 (or $x5501 c_60_3)))
 (let (($x5505 (or $x5503 c_60_4)))
 (let (($x5507 (or $x5505 c_60_5)))
 (let (($x5509 (or $x5507 c_60_6)))
 (let (($x5511 (or $x5509 c_60_7)))
 (or $x5511 c_60_8))))))))))
(assert
 (not (and c_60_0 c_60_1)))
(assert
 (not (and c_60_0 c_60_2)))
(assert
 (not (and c_60_0 c_60_3)))
(assert
 (not (and c_60_0 c_60_4)))
(assert
 (not (and c_60_0 c_60_5)))
(assert
 (not (and c_60_0 c_60_6)))
(assert
 (not (and c_60_0 c_60_7)))
(assert
 (not (and c_60_0 c_60_8)))
(assert
 (not (and c_60_1 c_60_2)))
(assert
 (not (and c_60_1 c_60_3)))
(assert
 (not (and c_60_1 c_60_4)))
(assert
 (not (and c_60_1 c_60_5)))
(assert
 (not (and c_60_1 c_60_6)))
(assert
 (not (and c_60_1 c_60_7)))
(assert
 (not (and c_60_1 c_60_8)))
(assert
 (not (and c_60_2 c_60_3)))
(assert
 (not (and c_60_2 c_60_4)))
(assert
 (not (and c_60_2 c_60_5)))
(assert
 (not (and c_60_2 c_60_6)))
(assert
 (not (and c_60_2 c_60_7)))
(assert
 (not (and c_60_2 c_60_8)))
(assert
 (not (and c_60_3 c_60_4)))
(assert
 (not (and c_60_3 c_60_5)))
(assert
 (not (and c_60_3 c_60_6)))
(assert
 (not (and c_60_3 c_60_7)))
(assert
 (not (and c_60_3 c_60_8)))
(assert
 (not (and c_60_4 c_60_5)))
(assert
 (not (and c_60_4 c_60_6)))
(assert
 (not (and c_60_4 c_60_7)))
(assert
 (not (and c_60_4 c_60_8)))
(assert
 (not (and c_60_5 c_60_6)))
(assert
 (not (and c_60_5 c_60_7)))
(assert
 (not (and c_60_5 c_60_8)))
(assert
 (not (and c_60_6 c_60_7)))
(assert
 (not (and c_60_6 c_60_8)))
(assert
 (not (and c_60_7 c_60_8)))
(assert
 (let (($x5587 (or false c_61_0)))
 (let (($x5589 (or $x5587 c_61_1)))
 (let (($x5591 (or $x5589 c_61_2)))
 (let (($x5593 (or $x5591 c_61_3)))
 (let (($x5595 (or $x5593 c_61_4)))
 (let (($x5597 (or $x5595 c_61_5)))
 (let (($x5599 (or $x5597 c_61_6)))
 (let (($x5601 (or $x5599 c_61_7)))
 (or $x5601 c_61_8))))))))))
(assert
 (not (and c_61_0 c_61_1)))
(assert
 (not (and c_61_0 c_61_2)))
(assert
 (not (and c_61_0 c_61_3)))
(assert
 (not (and c_61_0 c_61_4)))
(assert
 (not (and c_61_0 c_61_5)))
(assert
 (not (and c_61_0 c_61_6)))
(assert
 (not (and c_61_0 c_61_7)))
(assert
 (not (and c_61_0 c_61_8)))
(assert
 (not (and c_61_1 c_61_2)))
(assert
 (not (and c_61_1 c_61_3)))
(assert
 (not (and c_61_1 c_61_4)))
(assert
 (not (and c_61_1 c_61_5)))
(assert
 (not (and c_61_1 c_61_6)))
(assert
 (not (and c_61_1 c_61_7)))
(assert
 (not (and c_61_1 c_61_8)))
(assert
 (not (and c_61_2 c_61_3)))
(assert
 (not (and c_61_2 c_61_4)))
(assert
 (not (and c_61_2 c_61_5)))
(assert
 (not (and c_61_2 c_61_6)))
(assert
 (not (and c_61_2 c_61_7)))
(assert
 (not (and c_61_2 c_61_8)))
(assert
 (not (and c_61_3 c_61_4)))
(assert
 (not (and c_61_3 c_61_5)))
(assert
 (not (and c_61_3 c_61_6)))
(assert
 (not (and c_61_3 c_61_7)))
(assert
 (not (and c_61_3 c_61_8)))
(assert
 (not (and c_61_4 c_61_5)))
(assert
 (not (and c_61_4 c_61_6)))
(assert
 (not (and c_61_4 c_61_7)))
(assert
 (not (and c_61_4 c_61_8)))
(assert
 (not (and c_61_5 c_61_6)))
(assert
 (not (and c_61_5 c_61_7)))
(assert
 (not (and c_61_5 c_61_8)))
(assert
 (not (and c_61_6 c_61_7)))
(assert
 (not (and c_61_6 c_61_8)))
(assert
 (not (and c_61_7 c_61_8)))
(assert
 (let (($x5677 (or false c_62_0)))
 (let (($x5679 (or $x5677 c_62_1)))
 (let (($x5681 (or $x5679 c_62_2)))
 (let (($x5683 (or $x5681 c_62_3)))
 (let (($x5685 (or $x5683 c_62_4)))
 (let (($x5687 (or $x5685 c_62_5)))
 (let (($x5689 (or $x5687 c_62_6)))
 (let (($x5691 (or $x5689 c_62_7)))
 (or $x5691 c_62_8))))))))))
(assert
 (not (and c_62_0 c_62_1)))
(assert
 (not (and c_62_0 c_62_2)))
(assert
 (not (and c_62_0 c_62_3)))
(assert
 (not (and c_62_0 c_62_4)))
(assert
 (not (and c_62_0 c_62_5)))
(assert
 (not (and c_62_0 c_62_6)))
(assert
 (not (and c_62_0 c_62_7)))
(assert
 (not (and c_62_0 c_62_8)))
(assert
 (not (and c_62_1 c_62_2)))
(assert
 (not (and c_62_1 c_62_3)))
(assert
 (not (and c_62_1 c_62_4)))
(assert
 (not (and c_62_1 c_62_5)))
(assert
 (not (and c_62_1 c_62_6)))
(assert
 (not (and c_62_1 c_62_7)))
(assert
 (not (and c_62_1 c_62_8)))
(assert
 (not (and c_62_2 c_62_3)))
(assert
 (not (and c_62_2 c_62_4)))
(assert
 (not (and c_62_2 c_62_5)))
(assert
 (not (and c_62_2 c_62_6)))
(assert
 (not (and c_62_2 c_62_7)))
(assert
 (not (and c_62_2 c_62_8)))
(assert
 (not (and c_62_3 c_62_4)))
(assert
 (not (and c_62_3 c_62_5)))
(assert
 (not (and c_62_3 c_62_6)))
(assert
 (not (and c_62_3 c_62_7)))
(assert
 (not (and c_62_3 c_62_8)))
(assert
 (not (and c_62_4 c_62_5)))
(assert
 (not (and c_62_4 c_62_6)))
(assert
 (not (and c_62_4 c_62_7)))
(assert
 (not (and c_62_4 c_62_8)))
(assert
 (not (and c_62_5 c_62_6)))
(assert
 (not (and c_62_5 c_62_7)))
(assert
 (not (and c_62_5 c_62_8)))
(assert
 (not (and c_62_6 c_62_7)))
(assert
 (not (and c_62_6 c_62_8)))
(assert
 (not (and c_62_7 c_62_8)))
(assert
 (let (($x5767 (or false c_63_0)))
 (let (($x5769 (or $x5767 c_63_1)))
 (let (($x5771 (or $x5769 c_63_2)))
 (let (($x5773 (or $x5771 c_63_3)))
 (let (($x5775 (or $x5773 c_63_4)))
 (let (($x5777 (or $x5775 c_63_5)))
 (let (($x5779 (or $x5777 c_63_6)))
 (let (($x5781 (or $x5779 c_63_7)))
 (or $x5781 c_63_8))))))))))
(assert
 (not (and c_63_0 c_63_1)))
(assert
 (not (and c_63_0 c_63_2)))
(assert
 (not (and c_63_0 c_63_3)))
(assert
 (not (and c_63_0 c_63_4)))
(assert
 (not (and c_63_0 c_63_5)))
(assert
 (not (and c_63_0 c_63_6)))
(assert
 (not (and c_63_0 c_63_7)))
(assert
 (not (and c_63_0 c_63_8)))
(assert
 (not (and c_63_1 c_63_2)))
(assert
 (not (and c_63_1 c_63_3)))
(assert
 (not (and c_63_1 c_63_4)))
(assert
 (not (and c_63_1 c_63_5)))
(assert
 (not (and c_63_1 c_63_6)))
(assert
 (not (and c_63_1 c_63_7)))
(assert
 (not (and c_63_1 c_63_8)))
(assert
 (not (and c_63_2 c_63_3)))
(assert
 (not (and c_63_2 c_63_4)))
(assert
 (not (and c_63_2 c_63_5)))
(assert
 (not (and c_63_2 c_63_6)))
(assert
 (not (and c_63_2 c_63_7)))
(assert
 (not (and c_63_2 c_63_8)))
(assert
 (not (and c_63_3 c_63_4)))
(assert
 (not (and c_63_3 c_63_5)))
(assert
 (not (and c_63_3 c_63_6)))
(assert
 (not (and c_63_3 c_63_7)))
(assert
 (not (and c_63_3 c_63_8)))
(assert
 (not (and c_63_4 c_63_5)))
(assert
 (not (and c_63_4 c_63_6)))
(assert
 (not (and c_63_4 c_63_7)))
(assert
 (not (and c_63_4 c_63_8)))
(assert
 (not (and c_63_5 c_63_6)))
(assert
 (not (and c_63_5 c_63_7)))
(assert
 (not (and c_63_5 c_63_8)))
(assert
 (not (and c_63_6 c_63_7)))
(assert
 (not (and c_63_6 c_63_8)))
(assert
 (not (and c_63_7 c_63_8)))
(assert
 (let (($x5857 (or false c_64_0)))
 (let (($x5859 (or $x5857 c_64_1)))
 (let (($x5861 (or $x5859 c_64_2)))
 (let (($x5863 (or $x5861 c_64_3)))
 (let (($x5865 (or $x5863 c_64_4)))
 (let (($x5867 (or $x5865 c_64_5)))
 (let (($x5869 (or $x5867 c_64_6)))
 (let (($x5871 (or $x5869 c_64_7)))
 (or $x5871 c_64_8))))))))))
(assert
 (not (and c_64_0 c_64_1)))
(assert
 (not (and c_64_0 c_64_2)))
(assert
 (not (and c_64_0 c_64_3)))
(assert
 (not (and c_64_0 c_64_4)))
(assert
 (not (and c_64_0 c_64_5)))
(assert
 (not (and c_64_0 c_64_6)))
(assert
 (not (and c_64_0 c_64_7)))
(assert
 (not (and c_64_0 c_64_8)))
(assert
 (not (and c_64_1 c_64_2)))
(assert
 (not (and c_64_1 c_64_3)))
(assert
 (not (and c_64_1 c_64_4)))
(assert
 (not (and c_64_1 c_64_5)))
(assert
 (not (and c_64_1 c_64_6)))
(assert
 (not (and c_64_1 c_64_7)))
(assert
 (not (and c_64_1 c_64_8)))
(assert
 (not (and c_64_2 c_64_3)))
(assert
 (not (and c_64_2 c_64_4)))
(assert
 (not (and c_64_2 c_64_5)))
(assert
 (not (and c_64_2 c_64_6)))
(assert
 (not (and c_64_2 c_64_7)))
(assert
 (not (and c_64_2 c_64_8)))
(assert
 (not (and c_64_3 c_64_4)))
(assert
 (not (and c_64_3 c_64_5)))
(assert
 (not (and c_64_3 c_64_6)))
(assert
 (not (and c_64_3 c_64_7)))
(assert
 (not (and c_64_3 c_64_8)))
(assert
 (not (and c_64_4 c_64_5)))
(assert
 (not (and c_64_4 c_64_6)))
(assert
 (not (and c_64_4 c_64_7)))
(assert
 (not (and c_64_4 c_64_8)))
(assert
 (not (and c_64_5 c_64_6)))
(assert
 (not (and c_64_5 c_64_7)))
(assert
 (not (and c_64_5 c_64_8)))
(assert
 (not (and c_64_6 c_64_7)))
(assert
 (not (and c_64_6 c_64_8)))
(assert
 (not (and c_64_7 c_64_8)))
(assert
 (let (($x5947 (or false c_65_0)))
 (let (($x5949 (or $x5947 c_65_1)))
 (let (($x5951 (or $x5949 c_65_2)))
 (let (($x5953 (or $x5951 c_65_3)))
 (let (($x5955 (or $x5953 c_65_4)))
 (let (($x5957 (or $x5955 c_65_5)))
 (let (($x5959 (or $x5957 c_65_6)))
 (let (($x5961 (or $x5959 c_65_7)))
 (or $x5961 c_65_8))))))))))
(assert
 (not (and c_65_0 c_65_1)))
(assert
 (not (and c_65_0 c_65_2)))
(assert
 (not (and c_65_0 c_65_3)))
(assert
 (not (and c_65_0 c_65_4)))
(assert
 (not (and c_65_0 c_65_5)))
(assert
 (not (and c_65_0 c_65_6)))
(assert
 (not (and c_65_0 c_65_7)))
(assert
 (not (and c_65_0 c_65_8)))
(assert
 (not (and c_65_1 c_65_2)))
(assert
 (not (and c_65_1 c_65_3)))
(assert
 (not (and c_65_1 c_65_4)))
(assert
 (not (and c_65_1 c_65_5)))
(assert
 (not (and c_65_1 c_65_6)))
(assert
 (not (and c_65_1 c_65_7)))
(assert
 (not (and c_65_1 c_65_8)))
(assert
 (not (and c_65_2 c_65_3)))
(assert
 (not (and c_65_2 c_65_4)))
(assert
 (not (and c_65_2 c_65_5)))
(assert
 (not (and c_65_2 c_65_6)))
(assert
 (not (and c_65_2 c_65_7)))
(assert
 (not (and c_65_2 c_65_8)))
(assert
 (not (and c_65_3 c_65_4)))
(assert
 (not (and c_65_3 c_65_5)))
(assert
 (not (and c_65_3 c_65_6)))
(assert
 (not (and c_65_3 c_65_7)))
(assert
 (not (and c_65_3 c_65_8)))
(assert
 (not (and c_65_4 c_65_5)))
(assert
 (not (and c_65_4 c_65_6)))
(assert
 (not (and c_65_4 c_65_7)))
(assert
 (not (and c_65_4 c_65_8)))
(assert
 (not (and c_65_5 c_65_6)))
(assert
 (not (and c_65_5 c_65_7)))
(assert
 (not (and c_65_5 c_65_8)))
(assert
 (not (and c_65_6 c_65_7)))
(assert
 (not (and c_65_6 c_65_8)))
(assert
 (not (and c_65_7 c_65_8)))
(assert
 (let (($x6037 (or false c_66_0)))
 (let (($x6039 (or $x6037 c_66_1)))
 (let (($x6041 (or $x6039 c_66_2)))
 (let (($x6043 (or $x6041 c_66_3)))
 (let (($x6045 (or $x6043 c_66_4)))
 (let (($x6047 (or $x6045 c_66_5)))
 (let (($x6049 (or $x6047 c_66_6)))
 (let (($x6051 (or $x6049 c_66_7)))
 (or $x6051 c_66_8))))))))))
(assert
 (not (and c_66_0 c_66_1)))
(assert
 (not (and c_66_0 c_66_2)))
(assert
 (not (and c_66_0 c_66_3)))
(assert
 (not (and c_66_0 c_66_4)))
(assert
 (not (and c_66_0 c_66_5)))
(assert
 (not (and c_66_0 c_66_6)))
(assert
 (not (and c_66_0 c_66_7)))
(assert
 (not (and c_66_0 c_66_8)))
(assert
 (not (and c_66_1 c_66_2)))
(assert
 (not (and c_66_1 c_66_3)))
(assert
 (not (and c_66_1 c_66_4)))
(assert
 (not (and c_66_1 c_66_5)))
(assert
 (not (and c_66_1 c_66_6)))
(assert
 (not (and c_66_1 c_66_7)))
(assert
 (not (and c_66_1 c_66_8)))
(assert
 (not (and c_66_2 c_66_3)))
(assert
 (not (and c_66_2 c_66_4)))
(assert
 (not (and c_66_2 c_66_5)))
(assert
 (not (and c_66_2 c_66_6)))
(assert
 (not (and c_66_2 c_66_7)))
(assert
 (not (and c_66_2 c_66_8)))
(assert
 (not (and c_66_3 c_66_4)))
(assert
 (not (and c_66_3 c_66_5)))
(assert
 (not (and c_66_3 c_66_6)))
(assert
 (not (and c_66_3 c_66_7)))
(assert
 (not (and c_66_3 c_66_8)))
(assert
 (not (and c_66_4 c_66_5)))
(assert
 (not (and c_66_4 c_66_6)))
(assert
 (not (and c_66_4 c_66_7)))
(assert
 (not (and c_66_4 c_66_8)))
(assert
 (not (and c_66_5 c_66_6)))
(assert
 (not (and c_66_5 c_66_7)))
(assert
 (not (and c_66_5 c_66_8)))
(assert
 (not (and c_66_6 c_66_7)))
(assert
 (not (and c_66_6 c_66_8)))
(assert
 (not (and c_66_7 c_66_8)))
(assert
 (let (($x6127 (or false c_67_0)))
 (let (($x6129 (or $x6127 c_67_1)))
 (let (($x6131 (or $x6129 c_67_2)))
 (let (($x6133 (or $x6131 c_67_3)))
 (let (($x6135 (or $x6133 c_67_4)))
 (let (($x6137 (or $x6135 c_67_5)))
 (let (($x6139 (or $x6137 c_67_6)))
 (let (($x6141 (or $x6139 c_67_7)))
 (or $x6141 c_67_8))))))))))
(assert
 (not (and c_67_0 c_67_1)))
(assert
 (not (and c_67_0 c_67_2)))
(assert
 (not (and c_67_0 c_67_3)))
(assert
 (not (and c_67_0 c_67_4)))
(assert
 (not (and c_67_0 c_67_5)))
(assert
 (not (and c_67_0 c_67_6)))
(assert
 (not (and c_67_0 c_67_7)))
(assert
 (not (and c_67_0 c_67_8)))
(assert
 (not (and c_67_1 c_67_2)))
(assert
 (not (and c_67_1 c_67_3)))
(assert
 (not (and c_67_1 c_67_4)))
(assert
 (not (and c_67_1 c_67_5)))
(assert
 (not (and c_67_1 c_67_6)))
(assert
 (not (and c_67_1 c_67_7)))
(assert
 (not (and c_67_1 c_67_8)))
(assert
 (not (and c_67_2 c_67_3)))
(assert
 (not (and c_67_2 c_67_4)))
(assert
 (not (and c_67_2 c_67_5)))
(assert
 (not (and c_67_2 c_67_6)))
(assert
 (not (and c_67_2 c_67_7)))
(assert
 (not (and c_67_2 c_67_8)))
(assert
 (not (and c_67_3 c_67_4)))
(assert
 (not (and c_67_3 c_67_5)))
(assert
 (not (and c_67_3 c_67_6)))
(assert
 (not (and c_67_3 c_67_7)))
(assert
 (not (and c_67_3 c_67_8)))
(assert
 (not (and c_67_4 c_67_5)))
(assert
 (not (and c_67_4 c_67_6)))
(assert
 (not (and c_67_4 c_67_7)))
(assert
 (not (and c_67_4 c_67_8)))
(assert
 (not (and c_67_5 c_67_6)))
(assert
 (not (and c_67_5 c_67_7)))
(assert
 (not (and c_67_5 c_67_8)))
(assert
 (not (and c_67_6 c_67_7)))
(assert
 (not (and c_67_6 c_67_8)))
(assert
 (not (and c_67_7 c_67_8)))
(assert
 (let (($x6217 (or false c_68_0)))
 (let (($x6219 (or $x6217 c_68_1)))
 (let (($x6221 (or $x6219 c_68_2)))
 (let (($x6223 (or $x6221 c_68_3)))
 (let (($x6225 (or $x6223 c_68_4)))
 (let (($x6227 (or $x6225 c_68_5)))
 (let (($x6229 (or $x6227 c_68_6)))
 (let (($x6231 (or $x6229 c_68_7)))
 (or $x6231 c_68_8))))))))))
(assert
 (not (and c_68_0 c_68_1)))
(assert
 (not (and c_68_0 c_68_2)))
(assert
 (not (and c_68_0 c_68_3)))
(assert
 (not (and c_68_0 c_68_4)))
(assert
 (not (and c_68_0 c_68_5)))
(assert
 (not (and c_68_0 c_68_6)))
(assert
 (not (and c_68_0 c_68_7)))
(assert
 (not (and c_68_0 c_68_8)))
(assert
 (not (and c_68_1 c_68_2)))
(assert
 (not (and c_68_1 c_68_3)))
(assert
 (not (and c_68_1 c_68_4)))
(assert
 (not (and c_68_1 c_68_5)))
(assert
 (not (and c_68_1 c_68_6)))
(assert
 (not (and c_68_1 c_68_7)))
(assert
 (not (and c_68_1 c_68_8)))
(assert
 (not (and c_68_2 c_68_3)))
(assert
 (not (and c_68_2 c_68_4)))
(assert
 (not (and c_68_2 c_68_5)))
(assert
 (not (and c_68_2 c_68_6)))
(assert
 (not (and c_68_2 c_68_7)))
(assert
 (not (and c_68_2 c_68_8)))
(assert
 (not (and c_68_3 c_68_4)))
(assert
 (not (and c_68_3 c_68_5)))
(assert
 (not (and c_68_3 c_68_6)))
(assert
 (not (and c_68_3 c_68_7)))
(assert
 (not (and c_68_3 c_68_8)))
(assert
 (not (and c_68_4 c_68_5)))
(assert
 (not (and c_68_4 c_68_6)))
(assert
 (not (and c_68_4 c_68_7)))
(assert
 (not (and c_68_4 c_68_8)))
(assert
 (not (and c_68_5 c_68_6)))
(assert
 (not (and c_68_5 c_68_7)))
(assert
 (not (and c_68_5 c_68_8)))
(assert
 (not (and c_68_6 c_68_7)))
(assert
 (not (and c_68_6 c_68_8)))
(assert
 (not (and c_68_7 c_68_8)))
(assert
 (let (($x6307 (or false c_69_0)))
 (let (($x6309 (or $x6307 c_69_1)))
 (let (($x6311 (or $x6309 c_69_2)))
 (let (($x6313 (or $x6311 c_69_3)))
 (let (($x6315 (or $x6313 c_69_4)))
 (let (($x6317 (or $x6315 c_69_5)))
 (let (($x6319 (or $x6317 c_69_6)))
 (let (($x6321 (or $x6319 c_69_7)))
 (or $x6321 c_69_8))))))))))
(assert
 (not (and c_69_0 c_69_1)))
(assert
 (not (and c_69_0 c_69_2)))
(assert
 (not (and c_69_0 c_69_3)))
(assert
 (not (and c_69_0 c_69_4)))
(assert
 (not (and c_69_0 c_69_5)))
(assert
 (not (and c_69_0 c_69_6)))
(assert
 (not (and c_69_0 c_69_7)))
(assert
 (not (and c_69_0 c_69_8)))
(assert
 (not (and c_69_1 c_69_2)))
(assert
 (not (and c_69_1 c_69_3)))
(assert
 (not (and c_69_1 c_69_4)))
(assert
 (not (and c_69_1 c_69_5)))
(assert
 (not (and c_69_1 c_69_6)))
(assert
 (not (and c_69_1 c_69_7)))
(assert
 (not (and c_69_1 c_69_8)))
(assert
 (not (and c_69_2 c_69_3)))
(assert
 (not (and c_69_2 c_69_4)))
(assert
 (not (and c_69_2 c_69_5)))
(assert
 (not (and c_69_2 c_69_6)))
(assert
 (not (and c_69_2 c_69_7)))
(assert
 (not (and c_69_2 c_69_8)))
(assert
 (not (and c_69_3 c_69_4)))
(assert
 (not (and c_69_3 c_69_5)))
(assert
 (not (and c_69_3 c_69_6)))
(assert
 (not (and c_69_3 c_69_7)))
(assert
 (not (and c_69_3 c_69_8)))
(assert
 (not (and c_69_4 c_69_5)))
(assert
 (not (and c_69_4 c_69_6)))
(assert
 (not (and c_69_4 c_69_7)))
(assert
 (not (and c_69_4 c_69_8)))
(assert
 (not (and c_69_5 c_69_6)))
(assert
 (not (and c_69_5 c_69_7)))
(assert
 (not (and c_69_5 c_69_8)))
(assert
 (not (and c_69_6 c_69_7)))
(assert
 (not (and c_69_6 c_69_8)))
(assert
 (not (and c_69_7 c_69_8)))
(assert
 (let (($x6397 (or false c_70_0)))
 (let (($x6399 (or $x6397 c_70_1)))
 (let (($x6401 (or $x6399 c_70_2)))
 (let (($x6403 (or $x6401 c_70_3)))
 (let (($x6405 (or $x6403 c_70_4)))
 (let (($x6407 (or $x6405 c_70_5)))
 (let (($x6409 (or $x6407 c_70_6)))
 (let (($x6411 (or $x6409 c_70_7)))
 (or $x6411 c_70_8))))))))))
(assert
 (not (and c_70_0 c_70_1)))
(assert
 (not (and c_70_0 c_70_2)))
(assert
 (not (and c_70_0 c_70_3)))
(assert
 (not (and c_70_0 c_70_4)))
(assert
 (not (and c_70_0 c_70_5)))
(assert
 (not (and c_70_0 c_70_6)))
(assert
 (not (and c_70_0 c_70_7)))
(assert
 (not (and c_70_0 c_70_8)))
(assert
 (not (and c_70_1 c_70_2)))
(assert
 (not (and c_70_1 c_70_3)))
(assert
 (not (and c_70_1 c_70_4)))
(assert
 (not (and c_70_1 c_70_5)))
(assert
 (not (and c_70_1 c_70_6)))
(assert
 (not (and c_70_1 c_70_7)))
(assert
 (not (and c_70_1 c_70_8)))
(assert
 (not (and c_70_2 c_70_3)))
(assert
 (not (and c_70_2 c_70_4)))
(assert
 (not (and c_70_2 c_70_5)))
(assert
 (not (and c_70_2 c_70_6)))
(assert
 (not (and c_70_2 c_70_7)))
(assert
 (not (and c_70_2 c_70_8)))
(assert
 (not (and c_70_3 c_70_4)))
(assert
 (not (and c_70_3 c_70_5)))
(assert
 (not (and c_70_3 c_70_6)))
(assert
 (not (and c_70_3 c_70_7)))
(assert
 (not (and c_70_3 c_70_8)))
(assert
 (not (and c_70_4 c_70_5)))
(assert
 (not (and c_70_4 c_70_6)))
(assert
 (not (and c_70_4 c_70_7)))
(assert
 (not (and c_70_4 c_70_8)))
(assert
 (not (and c_70_5 c_70_6)))
(assert
 (not (and c_70_5 c_70_7)))
(assert
 (not (and c_70_5 c_70_8)))
(assert
 (not (and c_70_6 c_70_7)))
(assert
 (not (and c_70_6 c_70_8)))
(assert
 (not (and c_70_7 c_70_8)))
(assert
 (let (($x6487 (or false c_71_0)))
 (let (($x6489 (or $x6487 c_71_1)))
 (let (($x6491 (or $x6489 c_71_2)))
 (let (($x6493 (or $x6491 c_71_3)))
 (let (($x6495 (or $x6493 c_71_4)))
 (let (($x6497 (or $x6495 c_71_5)))
 (let (($x6499 (or $x6497 c_71_6)))
 (let (($x6501 (or $x6499 c_71_7)))
 (or $x6501 c_71_8))))))))))
(assert
 (not (and c_71_0 c_71_1)))
(assert
 (not (and c_71_0 c_71_2)))
(assert
 (not (and c_71_0 c_71_3)))
(assert
 (not (and c_71_0 c_71_4)))
(assert
 (not (and c_71_0 c_71_5)))
(assert
 (not (and c_71_0 c_71_6)))
(assert
 (not (and c_71_0 c_71_7)))
(assert
 (not (and c_71_0 c_71_8)))
(assert
 (not (and c_71_1 c_71_2)))
(assert
 (not (and c_71_1 c_71_3)))
(assert
 (not (and c_71_1 c_71_4)))
(assert
 (not (and c_71_1 c_71_5)))
(assert
 (not (and c_71_1 c_71_6)))
(assert
 (not (and c_71_1 c_71_7)))
(assert
 (not (and c_71_1 c_71_8)))
(assert
 (not (and c_71_2 c_71_3)))
(assert
 (not (and c_71_2 c_71_4)))
(assert
 (not (and c_71_2 c_71_5)))
(assert
 (not (and c_71_2 c_71_6)))
(assert
 (not (and c_71_2 c_71_7)))
(assert
 (not (and c_71_2 c_71_8)))
(assert
 (not (and c_71_3 c_71_4)))
(assert
 (not (and c_71_3 c_71_5)))
(assert
 (not (and c_71_3 c_71_6)))
(assert
 (not (and c_71_3 c_71_7)))
(assert
 (not (and c_71_3 c_71_8)))
(assert
 (not (and c_71_4 c_71_5)))
(assert
 (not (and c_71_4 c_71_6)))
(assert
 (not (and c_71_4 c_71_7)))
(assert
 (not (and c_71_4 c_71_8)))
(assert
 (not (and c_71_5 c_71_6)))
(assert
 (not (and c_71_5 c_71_7)))
(assert
 (not (and c_71_5 c_71_8)))
(assert
 (not (and c_71_6 c_71_7)))
(assert
 (not (and c_71_6 c_71_8)))
(assert
 (not (and c_71_7 c_71_8)))
(assert
 (let (($x6577 (or false c_72_0)))
 (let (($x6579 (or $x6577 c_72_1)))
 (let (($x6581 (or $x6579 c_72_2)))
 (let (($x6583 (or $x6581 c_72_3)))
 (let (($x6585 (or $x6583 c_72_4)))
 (let (($x6587 (or $x6585 c_72_5)))
 (let (($x6589 (or $x6587 c_72_6)))
 (let (($x6591 (or $x6589 c_72_7)))
 (or $x6591 c_72_8))))))))))
(assert
 (not (and c_72_0 c_72_1)))
(assert
 (not (and c_72_0 c_72_2)))
(assert
 (not (and c_72_0 c_72_3)))
(assert
 (not (and c_72_0 c_72_4)))
(assert
 (not (and c_72_0 c_72_5)))
(assert
 (not (and c_72_0 c_72_6)))
(assert
 (not (and c_72_0 c_72_7)))
(assert
 (not (and c_72_0 c_72_8)))
(assert
 (not (and c_72_1 c_72_2)))
(assert
 (not (and c_72_1 c_72_3)))
(assert
 (not (and c_72_1 c_72_4)))
(assert
 (not (and c_72_1 c_72_5)))
(assert
 (not (and c_72_1 c_72_6)))
(assert
 (not (and c_72_1 c_72_7)))
(assert
 (not (and c_72_1 c_72_8)))
(assert
 (not (and c_72_2 c_72_3)))
(assert
 (not (and c_72_2 c_72_4)))
(assert
 (not (and c_72_2 c_72_5)))
(assert
 (not (and c_72_2 c_72_6)))
(assert
 (not (and c_72_2 c_72_7)))
(assert
 (not (and c_72_2 c_72_8)))
(assert
 (not (and c_72_3 c_72_4)))
(assert
 (not (and c_72_3 c_72_5)))
(assert
 (not (and c_72_3 c_72_6)))
(assert
 (not (and c_72_3 c_72_7)))
(assert
 (not (and c_72_3 c_72_8)))
(assert
 (not (and c_72_4 c_72_5)))
(assert
 (not (and c_72_4 c_72_6)))
(assert
 (not (and c_72_4 c_72_7)))
(assert
 (not (and c_72_4 c_72_8)))
(assert
 (not (and c_72_5 c_72_6)))
(assert
 (not (and c_72_5 c_72_7)))
(assert
 (not (and c_72_5 c_72_8)))
(assert
 (not (and c_72_6 c_72_7)))
(assert
 (not (and c_72_6 c_72_8)))
(assert
 (not (and c_72_7 c_72_8)))
(assert
 (let (($x6667 (or false c_73_0)))
 (let (($x6669 (or $x6667 c_73_1)))
 (let (($x6671 (or $x6669 c_73_2)))
 (let (($x6673 (or $x6671 c_73_3)))
 (let (($x6675 (or $x6673 c_73_4)))
 (let (($x6677 (or $x6675 c_73_5)))
 (let (($x6679 (or $x6677 c_73_6)))
 (let (($x6681 (or $x6679 c_73_7)))
 (or $x6681 c_73_8))))))))))
(assert
 (not (and c_73_0 c_73_1)))
(assert
 (not (and c_73_0 c_73_2)))
(assert
 (not (and c_73_0 c_73_3)))
(assert
 (not (and c_73_0 c_73_4)))
(assert
 (not (and c_73_0 c_73_5)))
(assert
 (not (and c_73_0 c_73_6)))
(assert
 (not (and c_73_0 c_73_7)))
(assert
 (not (and c_73_0 c_73_8)))
(assert
 (not (and c_73_1 c_73_2)))
(assert
 (not (and c_73_1 c_73_3)))
(assert
 (not (and c_73_1 c_73_4)))
(assert
 (not (and c_73_1 c_73_5)))
(assert
 (not (and c_73_1 c_73_6)))
(assert
 (not (and c_73_1 c_73_7)))
(assert
 (not (and c_73_1 c_73_8)))
(assert
 (not (and c_73_2 c_73_3)))
(assert
 (not (and c_73_2 c_73_4)))
(assert
 (not (and c_73_2 c_73_5)))
(assert
 (not (and c_73_2 c_73_6)))
(assert
 (not (and c_73_2 c_73_7)))
(assert
 (not (and c_73_2 c_73_8)))
(assert
 (not (and c_73_3 c_73_4)))
(assert
 (not (and c_73_3 c_73_5)))
(assert
 (not (and c_73_3 c_73_6)))
(assert
 (not (and c_73_3 c_73_7)))
(assert
 (not (and c_73_3 c_73_8)))
(assert
 (not (and c_73_4 c_73_5)))
(assert
 (not (and c_73_4 c_73_6)))
(assert
 (not (and c_73_4 c_73_7)))
(assert
 (not (and c_73_4 c_73_8)))
(assert
 (not (and c_73_5 c_73_6)))
(assert
 (not (and c_73_5 c_73_7)))
(assert
 (not (and c_73_5 c_73_8)))
(assert
 (not (and c_73_6 c_73_7)))
(assert
 (not (and c_73_6 c_73_8)))
(assert
 (not (and c_73_7 c_73_8)))
(assert
 (let (($x6757 (or false c_74_0)))
 (let (($x6759 (or $x6757 c_74_1)))
 (let (($x6761 (or $x6759 c_74_2)))
 (let (($x6763 (or $x6761 c_74_3)))
 (let (($x6765 (or $x6763 c_74_4)))
 (let (($x6767 (or $x6765 c_74_5)))
 (let (($x6769 (or $x6767 c_74_6)))
 (let (($x6771 (or $x6769 c_74_7)))
 (or $x6771 c_74_8))))))))))
(assert
 (not (and c_74_0 c_74_1)))
(assert
 (not (and c_74_0 c_74_2)))
(assert
 (not (and c_74_0 c_74_3)))
(assert
 (not (and c_74_0 c_74_4)))
(assert
 (not (and c_74_0 c_74_5)))
(assert
 (not (and c_74_0 c_74_6)))
(assert
 (not (and c_74_0 c_74_7)))
(assert
 (not (and c_74_0 c_74_8)))
(assert
 (not (and c_74_1 c_74_2)))
(assert
 (not (and c_74_1 c_74_3)))
(assert
 (not (and c_74_1 c_74_4)))
(assert
 (not (and c_74_1 c_74_5)))
(assert
 (not (and c_74_1 c_74_6)))
(assert
 (not (and c_74_1 c_74_7)))
(assert
 (not (and c_74_1 c_74_8)))
(assert
 (not (and c_74_2 c_74_3)))
(assert
 (not (and c_74_2 c_74_4)))
(assert
 (not (and c_74_2 c_74_5)))
(assert
 (not (and c_74_2 c_74_6)))
(assert
 (not (and c_74_2 c_74_7)))
(assert
 (not (and c_74_2 c_74_8)))
(assert
 (not (and c_74_3 c_74_4)))
(assert
 (not (and c_74_3 c_74_5)))
(assert
 (not (and c_74_3 c_74_6)))
(assert
 (not (and c_74_3 c_74_7)))
(assert
 (not (and c_74_3 c_74_8)))
(assert
 (not (and c_74_4 c_74_5)))
(assert
 (not (and c_74_4 c_74_6)))
(assert
 (not (and c_74_4 c_74_7)))
(assert
 (not (and c_74_4 c_74_8)))
(assert
 (not (and c_74_5 c_74_6)))
(assert
 (not (and c_74_5 c_74_7)))
(assert
 (not (and c_74_5 c_74_8)))
(assert
 (not (and c_74_6 c_74_7)))
(assert
 (not (and c_74_6 c_74_8)))
(assert
 (not (and c_74_7 c_74_8)))
(assert
 (let (($x6847 (or false c_75_0)))
 (let (($x6849 (or $x6847 c_75_1)))
 (let (($x6851 (or $x6849 c_75_2)))
 (let (($x6853 (or $x6851 c_75_3)))
 (let (($x6855 (or $x6853 c_75_4)))
 (let (($x6857 (or $x6855 c_75_5)))
 (let (($x6859 (or $x6857 c_75_6)))
 (let (($x6861 (or $x6859 c_75_7)))
 (or $x6861 c_75_8))))))))))
(assert
 (not (and c_75_0 c_75_1)))
(assert
 (not (and c_75_0 c_75_2)))
(assert
 (not (and c_75_0 c_75_3)))
(assert
 (not (and c_75_0 c_75_4)))
(assert
 (not (and c_75_0 c_75_5)))
(assert
 (not (and c_75_0 c_75_6)))
(assert
 (not (and c_75_0 c_75_7)))
(assert
 (not (and c_75_0 c_75_8)))
(assert
 (not (and c_75_1 c_75_2)))
(assert
 (not (and c_75_1 c_75_3)))
(assert
 (not (and c_75_1 c_75_4)))
(assert
 (not (and c_75_1 c_75_5)))
(assert
 (not (and c_75_1 c_75_6)))
(assert
 (not (and c_75_1 c_75_7)))
(assert
 (not (and c_75_1 c_75_8)))
(assert
 (not (and c_75_2 c_75_3)))
(assert
 (not (and c_75_2 c_75_4)))
(assert
 (not (and c_75_2 c_75_5)))
(assert
 (not (and c_75_2 c_75_6)))
(assert
 (not (and c_75_2 c_75_7)))
(assert
 (not (and c_75_2 c_75_8)))
(assert
 (not (and c_75_3 c_75_4)))
(assert
 (not (and c_75_3 c_75_5)))
(assert
 (not (and c_75_3 c_75_6)))
(assert
 (not (and c_75_3 c_75_7)))
(assert
 (not (and c_75_3 c_75_8)))
(assert
 (not (and c_75_4 c_75_5)))
(assert
 (not (and c_75_4 c_75_6)))
(assert
 (not (and c_75_4 c_75_7)))
(assert
 (not (and c_75_4 c_75_8)))
(assert
 (not (and c_75_5 c_75_6)))
(assert
 (not (and c_75_5 c_75_7)))
(assert
 (not (and c_75_5 c_75_8)))
(assert
 (not (and c_75_6 c_75_7)))
(assert
 (not (and c_75_6 c_75_8)))
(assert
 (not (and c_75_7 c_75_8)))
(assert
 (let (($x6937 (or false c_76_0)))
 (let (($x6939 (or $x6937 c_76_1)))
 (let (($x6941 (or $x6939 c_76_2)))
 (let (($x6943 (or $x6941 c_76_3)))
 (let (($x6945 (or $x6943 c_76_4)))
 (let (($x6947 (or $x6945 c_76_5)))
 (let (($x6949 (or $x6947 c_76_6)))
 (let (($x6951 (or $x6949 c_76_7)))
 (or $x6951 c_76_8))))))))))
(assert
 (not (and c_76_0 c_76_1)))
(assert
 (not (and c_76_0 c_76_2)))
(assert
 (not (and c_76_0 c_76_3)))
(assert
 (not (and c_76_0 c_76_4)))
(assert
 (not (and c_76_0 c_76_5)))
(assert
 (not (and c_76_0 c_76_6)))
(assert
 (not (and c_76_0 c_76_7)))
(assert
 (not (and c_76_0 c_76_8)))
(assert
 (not (and c_76_1 c_76_2)))
(assert
 (not (and c_76_1 c_76_3)))
(assert
 (not (and c_76_1 c_76_4)))
(assert
 (not (and c_76_1 c_76_5)))
(assert
 (not (and c_76_1 c_76_6)))
(assert
 (not (and c_76_1 c_76_7)))
(assert
 (not (and c_76_1 c_76_8)))
(assert
 (not (and c_76_2 c_76_3)))
(assert
 (not (and c_76_2 c_76_4)))
(assert
 (not (and c_76_2 c_76_5)))
(assert
 (not (and c_76_2 c_76_6)))
(assert
 (not (and c_76_2 c_76_7)))
(assert
 (not (and c_76_2 c_76_8)))
(assert
 (not (and c_76_3 c_76_4)))
(assert
 (not (and c_76_3 c_76_5)))
(assert
 (not (and c_76_3 c_76_6)))
(assert
 (not (and c_76_3 c_76_7)))
(assert
 (not (and c_76_3 c_76_8)))
(assert
 (not (and c_76_4 c_76_5)))
(assert
 (not (and c_76_4 c_76_6)))
(assert
 (not (and c_76_4 c_76_7)))
(assert
 (not (and c_76_4 c_76_8)))
(assert
 (not (and c_76_5 c_76_6)))
(assert
 (not (and c_76_5 c_76_7)))
(assert
 (not (and c_76_5 c_76_8)))
(assert
 (not (and c_76_6 c_76_7)))
(assert
 (not (and c_76_6 c_76_8)))
(assert
 (not (and c_76_7 c_76_8)))
(assert
 (let (($x7027 (or false c_77_0)))
 (let (($x7029 (or $x7027 c_77_1)))
 (let (($x7031 (or $x7029 c_77_2)))
 (let (($x7033 (or $x7031 c_77_3)))
 (let (($x7035 (or $x7033 c_77_4)))
 (let (($x7037 (or $x7035 c_77_5)))
 (let (($x7039 (or $x7037 c_77_6)))
 (let (($x7041 (or $x7039 c_77_7)))
 (or $x7041 c_77_8))))))))))
(assert
 (not (and c_77_0 c_77_1)))
(assert
 (not (and c_77_0 c_77_2)))
(assert
 (not (and c_77_0 c_77_3)))
(assert
 (not (and c_77_0 c_77_4)))
(assert
 (not (and c_77_0 c_77_5)))
(assert
 (not (and c_77_0 c_77_6)))
(assert
 (not (and c_77_0 c_77_7)))
(assert
 (not (and c_77_0 c_77_8)))
(assert
 (not (and c_77_1 c_77_2)))
(assert
 (not (and c_77_1 c_77_3)))
(assert
 (not (and c_77_1 c_77_4)))
(assert
 (not (and c_77_1 c_77_5)))
(assert
 (not (and c_77_1 c_77_6)))
(assert
 (not (and c_77_1 c_77_7)))
(assert
 (not (and c_77_1 c_77_8)))
(assert
 (not (and c_77_2 c_77_3)))
(assert
 (not (and c_77_2 c_77_4)))
(assert
 (not (and c_77_2 c_77_5)))
(assert
 (not (and c_77_2 c_77_6)))
(assert
 (not (and c_77_2 c_77_7)))
(assert
 (not (and c_77_2 c_77_8)))
(assert
 (not (and c_77_3 c_77_4)))
(assert
 (not (and c_77_3 c_77_5)))
(assert
 (not (and c_77_3 c_77_6)))
(assert
 (not (and c_77_3 c_77_7)))
(assert
 (not (and c_77_3 c_77_8)))
(assert
 (not (and c_77_4 c_77_5)))
(assert
 (not (and c_77_4 c_77_6)))
(assert
 (not (and c_77_4 c_77_7)))
(assert
 (not (and c_77_4 c_77_8)))
(assert
 (not (and c_77_5 c_77_6)))
(assert
 (not (and c_77_5 c_77_7)))
(assert
 (not (and c_77_5 c_77_8)))
(assert
 (not (and c_77_6 c_77_7)))
(assert
 (not (and c_77_6 c_77_8)))
(assert
 (not (and c_77_7 c_77_8)))
(assert
 (let (($x7117 (or false c_78_0)))
 (let (($x7119 (or $x7117 c_78_1)))
 (let (($x7121 (or $x7119 c_78_2)))
 (let (($x7123 (or $x7121 c_78_3)))
 (let (($x7125 (or $x7123 c_78_4)))
 (let (($x7127 (or $x7125 c_78_5)))
 (let (($x7129 (or $x7127 c_78_6)))
 (let (($x7131 (or $x7129 c_78_7)))
 (or $x7131 c_78_8))))))))))
(assert
 (not (and c_78_0 c_78_1)))
(assert
 (not (and c_78_0 c_78_2)))
(assert
 (not (and c_78_0 c_78_3)))
(assert
 (not (and c_78_0 c_78_4)))
(assert
 (not (and c_78_0 c_78_5)))
(assert
 (not (and c_78_0 c_78_6)))
(assert
 (not (and c_78_0 c_78_7)))
(assert
 (not (and c_78_0 c_78_8)))
(assert
 (not (and c_78_1 c_78_2)))
(assert
 (not (and c_78_1 c_78_3)))
(assert
 (not (and c_78_1 c_78_4)))
(assert
 (not (and c_78_1 c_78_5)))
(assert
 (not (and c_78_1 c_78_6)))
(assert
 (not (and c_78_1 c_78_7)))
(assert
 (not (and c_78_1 c_78_8)))
(assert
 (not (and c_78_2 c_78_3)))
(assert
 (not (and c_78_2 c_78_4)))
(assert
 (not (and c_78_2 c_78_5)))
(assert
 (not (and c_78_2 c_78_6)))
(assert
 (not (and c_78_2 c_78_7)))
(assert
 (not (and c_78_2 c_78_8)))
(assert
 (not (and c_78_3 c_78_4)))
(assert
 (not (and c_78_3 c_78_5)))
(assert
 (not (and c_78_3 c_78_6)))
(assert
 (not (and c_78_3 c_78_7)))
(assert
 (not (and c_78_3 c_78_8)))
(assert
 (not (and c_78_4 c_78_5)))
(assert
 (not (and c_78_4 c_78_6)))
(assert
 (not (and c_78_4 c_78_7)))
(assert
 (not (and c_78_4 c_78_8)))
(assert
 (not (and c_78_5 c_78_6)))
(assert
 (not (and c_78_5 c_78_7)))
(assert
 (not (and c_78_5 c_78_8)))
(assert
 (not (and c_78_6 c_78_7)))
(assert
 (not (and c_78_6 c_78_8)))
(assert
 (not (and c_78_7 c_78_8)))
(assert
 (let (($x7207 (or false c_79_0)))
 (let (($x7209 (or $x7207 c_79_1)))
 (let (($x7211 (or $x7209 c_79_2)))
 (let (($x7213 (or $x7211 c_79_3)))
 (let (($x7215 (or $x7213 c_79_4)))
 (let (($x7217 (or $x7215 c_79_5)))
 (let (($x7219 (or $x7217 c_79_6)))
 (let (($x7221 (or $x7219 c_79_7)))
 (or $x7221 c_79_8))))))))))
(assert
 (not (and c_79_0 c_79_1)))
(assert
 (not (and c_79_0 c_79_2)))
(assert
 (not (and c_79_0 c_79_3)))
(assert
 (not (and c_79_0 c_79_4)))
(assert
 (not (and c_79_0 c_79_5)))
(assert
 (not (and c_79_0 c_79_6)))
(assert
 (not (and c_79_0 c_79_7)))
(assert
 (not (and c_79_0 c_79_8)))
(assert
 (not (and c_79_1 c_79_2)))
(assert
 (not (and c_79_1 c_79_3)))
(assert
 (not (and c_79_1 c_79_4)))
(assert
 (not (and c_79_1 c_79_5)))
(assert
 (not (and c_79_1 c_79_6)))
(assert
 (not (and c_79_1 c_79_7)))
(assert
 (not (and c_79_1 c_79_8)))
(assert
 (not (and c_79_2 c_79_3)))
(assert
 (not (and c_79_2 c_79_4)))
(assert
 (not (and c_79_2 c_79_5)))
(assert
 (not (and c_79_2 c_79_6)))
(assert
 (not (and c_79_2 c_79_7)))
(assert
 (not (and c_79_2 c_79_8)))
(assert
 (not (and c_79_3 c_79_4)))
(assert
 (not (and c_79_3 c_79_5)))
(assert
 (not (and c_79_3 c_79_6)))
(assert
 (not (and c_79_3 c_79_7)))
(assert
 (not (and c_79_3 c_79_8)))
(assert
 (not (and c_79_4 c_79_5)))
(assert
 (not (and c_79_4 c_79_6)))
(assert
 (not (and c_79_4 c_79_7)))
(assert
 (not (and c_79_4 c_79_8)))
(assert
 (not (and c_79_5 c_79_6)))
(assert
 (not (and c_79_5 c_79_7)))
(assert
 (not (and c_79_5 c_79_8)))
(assert
 (not (and c_79_6 c_79_7)))
(assert
 (not (and c_79_6 c_79_8)))
(assert
 (not (and c_79_7 c_79_8)))
(assert
 (let (($x7297 (or false c_80_0)))
 (let (($x7299 (or $x7297 c_80_1)))
 (let (($x7301 (or $x7299 c_80_2)))
 (let (($x7303 (or $x7301 c_80_3)))
 (let (($x7305 (or $x7303 c_80_4)))
 (let (($x7307 (or $x7305 c_80_5)))
 (let (($x7309 (or $x7307 c_80_6)))
 (let (($x7311 (or $x7309 c_80_7)))
 (or $x7311 c_80_8))))))))))
(assert
 (not (and c_80_0 c_80_1)))
(assert
 (not (and c_80_0 c_80_2)))
(assert
 (not (and c_80_0 c_80_3)))
(assert
 (not (and c_80_0 c_80_4)))
(assert
 (not (and c_80_0 c_80_5)))
(assert
 (not (and c_80_0 c_80_6)))
(assert
 (not (and c_80_0 c_80_7)))
(assert
 (not (and c_80_0 c_80_8)))
(assert
 (not (and c_80_1 c_80_2)))
(assert
 (not (and c_80_1 c_80_3)))
(assert
 (not (and c_80_1 c_80_4)))
(assert
 (not (and c_80_1 c_80_5)))
(assert
 (not (and c_80_1 c_80_6)))
(assert
 (not (and c_80_1 c_80_7)))
(assert
 (not (and c_80_1 c_80_8)))
(assert
 (not (and c_80_2 c_80_3)))
(assert
 (not (and c_80_2 c_80_4)))
(assert
 (not (and c_80_2 c_80_5)))
(assert
 (not (and c_80_2 c_80_6)))
(assert
 (not (and c_80_2 c_80_7)))
(assert
 (not (and c_80_2 c_80_8)))
(assert
 (not (and c_80_3 c_80_4)))
(assert
 (not (and c_80_3 c_80_5)))
(assert
 (not (and c_80_3 c_80_6)))
(assert
 (not (and c_80_3 c_80_7)))
(assert
 (not (and c_80_3 c_80_8)))
(assert
 (not (and c_80_4 c_80_5)))
(assert
 (not (and c_80_4 c_80_6)))
(assert
 (not (and c_80_4 c_80_7)))
(assert
 (not (and c_80_4 c_80_8)))
(assert
 (not (and c_80_5 c_80_6)))
(assert
 (not (and c_80_5 c_80_7)))
(assert
 (not (and c_80_5 c_80_8)))
(assert
 (not (and c_80_6 c_80_7)))
(assert
 (not (and c_80_6 c_80_8)))
(assert
 (not (and c_80_7 c_80_8)))
(assert
 (let (($x7387 (or false c_81_0)))
 (let (($x7389 (or $x7387 c_81_1)))
 (let (($x7391 (or $x7389 c_81_2)))
 (let (($x7393 (or $x7391 c_81_3)))
 (let (($x7395 (or $x7393 c_81_4)))
 (let (($x7397 (or $x7395 c_81_5)))
 (let (($x7399 (or $x7397 c_81_6)))
 (let (($x7401 (or $x7399 c_81_7)))
 (or $x7401 c_81_8))))))))))
(assert
 (not (and c_81_0 c_81_1)))
(assert
 (not (and c_81_0 c_81_2)))
(assert
 (not (and c_81_0 c_81_3)))
(assert
 (not (and c_81_0 c_81_4)))
(assert
 (not (and c_81_0 c_81_5)))
(assert
 (not (and c_81_0 c_81_6)))
(assert
 (not (and c_81_0 c_81_7)))
(assert
 (not (and c_81_0 c_81_8)))
(assert
 (not (and c_81_1 c_81_2)))
(assert
 (not (and c_81_1 c_81_3)))
(assert
 (not (and c_81_1 c_81_4)))
(assert
 (not (and c_81_1 c_81_5)))
(assert
 (not (and c_81_1 c_81_6)))
(assert
 (not (and c_81_1 c_81_7)))
(assert
 (not (and c_81_1 c_81_8)))
(assert
 (not (and c_81_2 c_81_3)))
(assert
 (not (and c_81_2 c_81_4)))
(assert
 (not (and c_81_2 c_81_5)))
(assert
 (not (and c_81_2 c_81_6)))
(assert
 (not (and c_81_2 c_81_7)))
(assert
 (not (and c_81_2 c_81_8)))
(assert
 (not (and c_81_3 c_81_4)))
(assert
 (not (and c_81_3 c_81_5)))
(assert
 (not (and c_81_3 c_81_6)))
(assert
 (not (and c_81_3 c_81_7)))
(assert
 (not (and c_81_3 c_81_8)))
(assert
 (not (and c_81_4 c_81_5)))
(assert
 (not (and c_81_4 c_81_6)))
(assert
 (not (and c_81_4 c_81_7)))
(assert
 (not (and c_81_4 c_81_8)))
(assert
 (not (and c_81_5 c_81_6)))
(assert
 (not (and c_81_5 c_81_7)))
(assert
 (not (and c_81_5 c_81_8)))
(assert
 (not (and c_81_6 c_81_7)))
(assert
 (not (and c_81_6 c_81_8)))
(assert
 (not (and c_81_7 c_81_8)))
(assert
 (let (($x7477 (or false c_82_0)))
 (let (($x7479 (or $x7477 c_82_1)))
 (let (($x7481 (or $x7479 c_82_2)))
 (let (($x7483 (or $x7481 c_82_3)))
 (let (($x7485 (or $x7483 c_82_4)))
 (let (($x7487 (or $x7485 c_82_5)))
 (let (($x7489 (or $x7487 c_82_6)))
 (let (($x7491 (or $x7489 c_82_7)))
 (or $x7491 c_82_8))))))))))
(assert
 (not (and c_82_0 c_82_1)))
(assert
 (not (and c_82_0 c_82_2)))
(assert
 (not (and c_82_0 c_82_3)))
(assert
 (not (and c_82_0 c_82_4)))
(assert
 (not (and c_82_0 c_82_5)))
(assert
 (not (and c_82_0 c_82_6)))
(assert
 (not (and c_82_0 c_82_7)))
(assert
 (not (and c_82_0 c_82_8)))
(assert
 (not (and c_82_1 c_82_2)))
(assert
 (not (and c_82_1 c_82_3)))
(assert
 (not (and c_82_1 c_82_4)))
(assert
 (not (and c_82_1 c_82_5)))
(assert
 (not (and c_82_1 c_82_6)))
(assert
 (not (and c_82_1 c_82_7)))
(assert
 (not (and c_82_1 c_82_8)))
(assert
 (not (and c_82_2 c_82_3)))
(assert
 (not (and c_82_2 c_82_4)))
(assert
 (not (and c_82_2 c_82_5)))
(assert
 (not (and c_82_2 c_82_6)))
(assert
 (not (and c_82_2 c_82_7)))
(assert
 (not (and c_82_2 c_82_8)))
(assert
 (not (and c_82_3 c_82_4)))
(assert
 (not (and c_82_3 c_82_5)))
(assert
 (not (and c_82_3 c_82_6)))
(assert
 (not (and c_82_3 c_82_7)))
(assert
 (not (and c_82_3 c_82_8)))
(assert
 (not (and c_82_4 c_82_5)))
(assert
 (not (and c_82_4 c_82_6)))
(assert
 (not (and c_82_4 c_82_7)))
(assert
 (not (and c_82_4 c_82_8)))
(assert
 (not (and c_82_5 c_82_6)))
(assert
 (not (and c_82_5 c_82_7)))
(assert
 (not (and c_82_5 c_82_8)))
(assert
 (not (and c_82_6 c_82_7)))
(assert
 (not (and c_82_6 c_82_8)))
(assert
 (not (and c_82_7 c_82_8)))
(assert
 (let (($x7567 (or false c_83_0)))
 (let (($x7569 (or $x7567 c_83_1)))
 (let (($x7571 (or $x7569 c_83_2)))
 (let (($x7573 (or $x7571 c_83_3)))
 (let (($x7575 (or $x7573 c_83_4)))
 (let (($x7577 (or $x7575 c_83_5)))
 (let (($x7579 (or $x7577 c_83_6)))
 (let (($x7581 (or $x7579 c_83_7)))
 (or $x7581 c_83_8))))))))))
(assert
 (not (and c_83_0 c_83_1)))
(assert
 (not (and c_83_0 c_83_2)))
(assert
 (not (and c_83_0 c_83_3)))
(assert
 (not (and c_83_0 c_83_4)))
(assert
 (not (and c_83_0 c_83_5)))
(assert
 (not (and c_83_0 c_83_6)))
(assert
 (not (and c_83_0 c_83_7)))
(assert
 (not (and c_83_0 c_83_8)))
(assert
 (not (and c_83_1 c_83_2)))
(assert
 (not (and c_83_1 c_83_3)))
(assert
 (not (and c_83_1 c_83_4)))
(assert
 (not (and c_83_1 c_83_5)))
(assert
 (not (and c_83_1 c_83_6)))
(assert
 (not (and c_83_1 c_83_7)))
(assert
 (not (and c_83_1 c_83_8)))
(assert
 (not (and c_83_2 c_83_3)))
(assert
 (not (and c_83_2 c_83_4)))
(assert
 (not (and c_83_2 c_83_5)))
(assert
 (not (and c_83_2 c_83_6)))
(assert
 (not (and c_83_2 c_83_7)))
(assert
 (not (and c_83_2 c_83_8)))
(assert
 (not (and c_83_3 c_83_4)))
(assert
 (not (and c_83_3 c_83_5)))
(assert
 (not (and c_83_3 c_83_6)))
(assert
 (not (and c_83_3 c_83_7)))
(assert
 (not (and c_83_3 c_83_8)))
(assert
 (not (and c_83_4 c_83_5)))
(assert
 (not (and c_83_4 c_83_6)))
(assert
 (not (and c_83_4 c_83_7)))
(assert
 (not (and c_83_4 c_83_8)))
(assert
 (not (and c_83_5 c_83_6)))
(assert
 (not (and c_83_5 c_83_7)))
(assert
 (not (and c_83_5 c_83_8)))
(assert
 (not (and c_83_6 c_83_7)))
(assert
 (not (and c_83_6 c_83_8)))
(assert
 (not (and c_83_7 c_83_8)))
(assert
 (let (($x7657 (or false c_84_0)))
 (let (($x7659 (or $x7657 c_84_1)))
 (let (($x7661 (or $x7659 c_84_2)))
 (let (($x7663 (or $x7661 c_84_3)))
 (let (($x7665 (or $x7663 c_84_4)))
 (let (($x7667 (or $x7665 c_84_5)))
 (let (($x7669 (or $x7667 c_84_6)))
 (let (($x7671 (or $x7669 c_84_7)))
 (or $x7671 c_84_8))))))))))
(assert
 (not (and c_84_0 c_84_1)))
(assert
 (not (and c_84_0 c_84_2)))
(assert
 (not (and c_84_0 c_84_3)))
(assert
 (not (and c_84_0 c_84_4)))
(assert
 (not (and c_84_0 c_84_5)))
(assert
 (not (and c_84_0 c_84_6)))
(assert
 (not (and c_84_0 c_84_7)))
(assert
 (not (and c_84_0 c_84_8)))
(assert
 (not (and c_84_1 c_84_2)))
(assert
 (not (and c_84_1 c_84_3)))
(assert
 (not (and c_84_1 c_84_4)))
(assert
 (not (and c_84_1 c_84_5)))
(assert
 (not (and c_84_1 c_84_6)))
(assert
 (not (and c_84_1 c_84_7)))
(assert
 (not (and c_84_1 c_84_8)))
(assert
 (not (and c_84_2 c_84_3)))
(assert
 (not (and c_84_2 c_84_4)))
(assert
 (not (and c_84_2 c_84_5)))
(assert
 (not (and c_84_2 c_84_6)))
(assert
 (not (and c_84_2 c_84_7)))
(assert
 (not (and c_84_2 c_84_8)))
(assert
 (not (and c_84_3 c_84_4)))
(assert
 (not (and c_84_3 c_84_5)))
(assert
 (not (and c_84_3 c_84_6)))
(assert
 (not (and c_84_3 c_84_7)))
(assert
 (not (and c_84_3 c_84_8)))
(assert
 (not (and c_84_4 c_84_5)))
(assert
 (not (and c_84_4 c_84_6)))
(assert
 (not (and c_84_4 c_84_7)))
(assert
 (not (and c_84_4 c_84_8)))
(assert
 (not (and c_84_5 c_84_6)))
(assert
 (not (and c_84_5 c_84_7)))
(assert
 (not (and c_84_5 c_84_8)))
(assert
 (not (and c_84_6 c_84_7)))
(assert
 (not (and c_84_6 c_84_8)))
(assert
 (not (and c_84_7 c_84_8)))
(assert
 (let (($x7747 (or false c_85_0)))
 (let (($x7749 (or $x7747 c_85_1)))
 (let (($x7751 (or $x7749 c_85_2)))
 (let (($x7753 (or $x7751 c_85_3)))
 (let (($x7755 (or $x7753 c_85_4)))
 (let (($x7757 (or $x7755 c_85_5)))
 (let (($x7759 (or $x7757 c_85_6)))
 (let (($x7761 (or $x7759 c_85_7)))
 (or $x7761 c_85_8))))))))))
(assert
 (not (and c_85_0 c_85_1)))
(assert
 (not (and c_85_0 c_85_2)))
(assert
 (not (and c_85_0 c_85_3)))
(assert
 (not (and c_85_0 c_85_4)))
(assert
 (not (and c_85_0 c_85_5)))
(assert
 (not (and c_85_0 c_85_6)))
(assert
 (not (and c_85_0 c_85_7)))
(assert
 (not (and c_85_0 c_85_8)))
(assert
 (not (and c_85_1 c_85_2)))
(assert
 (not (and c_85_1 c_85_3)))
(assert
 (not (and c_85_1 c_85_4)))
(assert
 (not (and c_85_1 c_85_5)))
(assert
 (not (and c_85_1 c_85_6)))
(assert
 (not (and c_85_1 c_85_7)))
(assert
 (not (and c_85_1 c_85_8)))
(assert
 (not (and c_85_2 c_85_3)))
(assert
 (not (and c_85_2 c_85_4)))
(assert
 (not (and c_85_2 c_85_5)))
(assert
 (not (and c_85_2 c_85_6)))
(assert
 (not (and c_85_2 c_85_7)))
(assert
 (not (and c_85_2 c_85_8)))
(assert
 (not (and c_85_3 c_85_4)))
(assert
 (not (and c_85_3 c_85_5)))
(assert
 (not (and c_85_3 c_85_6)))
(assert
 (not (and c_85_3 c_85_7)))
(assert
 (not (and c_85_3 c_85_8)))
(assert
 (not (and c_85_4 c_85_5)))
(assert
 (not (and c_85_4 c_85_6)))
(assert
 (not (and c_85_4 c_85_7)))
(assert
 (not (and c_85_4 c_85_8)))
(assert
 (not (and c_85_5 c_85_6)))
(assert
 (not (and c_85_5 c_85_7)))
(assert
 (not (and c_85_5 c_85_8)))
(assert
 (not (and c_85_6 c_85_7)))
(assert
 (not (and c_85_6 c_85_8)))
(assert
 (not (and c_85_7 c_85_8)))
(assert
 (let (($x7837 (or false c_86_0)))
 (let (($x7839 (or $x7837 c_86_1)))
 (let (($x7841 (or $x7839 c_86_2)))
 (let (($x7843 (or $x7841 c_86_3)))
 (let (($x7845 (or $x7843 c_86_4)))
 (let (($x7847 (or $x7845 c_86_5)))
 (let (($x7849 (or $x7847 c_86_6)))
 (let (($x7851 (or $x7849 c_86_7)))
 (or $x7851 c_86_8))))))))))
(assert
 (not (and c_86_0 c_86_1)))
(assert
 (not (and c_86_0 c_86_2)))
(assert
 (not (and c_86_0 c_86_3)))
(assert
 (not (and c_86_0 c_86_4)))
(assert
 (not (and c_86_0 c_86_5)))
(assert
 (not (and c_86_0 c_86_6)))
(assert
 (not (and c_86_0 c_86_7)))
(assert
 (not (and c_86_0 c_86_8)))
(assert
 (not (and c_86_1 c_86_2)))
(assert
 (not (and c_86_1 c_86_3)))
(assert
 (not (and c_86_1 c_86_4)))
(assert
 (not (and c_86_1 c_86_5)))
(assert
 (not (and c_86_1 c_86_6)))
(assert
 (not (and c_86_1 c_86_7)))
(assert
 (not (and c_86_1 c_86_8)))
(assert
 (not (and c_86_2 c_86_3)))
(assert
 (not (and c_86_2 c_86_4)))
(assert
 (not (and c_86_2 c_86_5)))
(assert
 (not (and c_86_2 c_86_6)))
(assert
 (not (and c_86_2 c_86_7)))
(assert
 (not (and c_86_2 c_86_8)))
(assert
 (not (and c_86_3 c_86_4)))
(assert
 (not (and c_86_3 c_86_5)))
(assert
 (not (and c_86_3 c_86_6)))
(assert
 (not (and c_86_3 c_86_7)))
(assert
 (not (and c_86_3 c_86_8)))
(assert
 (not (and c_86_4 c_86_5)))
(assert
 (not (and c_86_4 c_86_6)))
(assert
 (not (and c_86_4 c_86_7)))
(assert
 (not (and c_86_4 c_86_8)))
(assert
 (not (and c_86_5 c_86_6)))
(assert
 (not (and c_86_5 c_86_7)))
(assert
 (not (and c_86_5 c_86_8)))
(assert
 (not (and c_86_6 c_86_7)))
(assert
 (not (and c_86_6 c_86_8)))
(assert
 (not (and c_86_7 c_86_8)))
(assert
 (let (($x7927 (or false c_87_0)))
 (let (($x7929 (or $x7927 c_87_1)))
 (let (($x7931 (or $x7929 c_87_2)))
 (let (($x7933 (or $x7931 c_87_3)))
 (let (($x7935 (or $x7933 c_87_4)))
 (let (($x7937 (or $x7935 c_87_5)))
 (let (($x7939 (or $x7937 c_87_6)))
 (let (($x7941 (or $x7939 c_87_7)))
 (or $x7941 c_87_8))))))))))
(assert
 (not (and c_87_0 c_87_1)))
(assert
 (not (and c_87_0 c_87_2)))
(assert
 (not (and c_87_0 c_87_3)))
(assert
 (not (and c_87_0 c_87_4)))
(assert
 (not (and c_87_0 c_87_5)))
(assert
 (not (and c_87_0 c_87_6)))
(assert
 (not (and c_87_0 c_87_7)))
(assert
 (not (and c_87_0 c_87_8)))
(assert
 (not (and c_87_1 c_87_2)))
(assert
 (not (and c_87_1 c_87_3)))
(assert
 (not (and c_87_1 c_87_4)))
(assert
 (not (and c_87_1 c_87_5)))
(assert
 (not (and c_87_1 c_87_6)))
(assert
 (not (and c_87_1 c_87_7)))
(assert
 (not (and c_87_1 c_87_8)))
(assert
 (not (and c_87_2 c_87_3)))
(assert
 (not (and c_87_2 c_87_4)))
(assert
 (not (and c_87_2 c_87_5)))
(assert
 (not (and c_87_2 c_87_6)))
(assert
 (not (and c_87_2 c_87_7)))
(assert
 (not (and c_87_2 c_87_8)))
(assert
 (not (and c_87_3 c_87_4)))
(assert
 (not (and c_87_3 c_87_5)))
(assert
 (not (and c_87_3 c_87_6)))
(assert
 (not (and c_87_3 c_87_7)))
(assert
 (not (and c_87_3 c_87_8)))
(assert
 (not (and c_87_4 c_87_5)))
(assert
 (not (and c_87_4 c_87_6)))
(assert
 (not (and c_87_4 c_87_7)))
(assert
 (not (and c_87_4 c_87_8)))
(assert
 (not (and c_87_5 c_87_6)))
(assert
 (not (and c_87_5 c_87_7)))
(assert
 (not (and c_87_5 c_87_8)))
(assert
 (not (and c_87_6 c_87_7)))
(assert
 (not (and c_87_6 c_87_8)))
(assert
 (not (and c_87_7 c_87_8)))
(assert
 (let (($x8017 (or false c_88_0)))
 (let (($x8019 (or $x8017 c_88_1)))
 (let (($x8021 (or $x8019 c_88_2)))
 (let (($x8023 (or $x8021 c_88_3)))
 (let (($x8025 (or $x8023 c_88_4)))
 (let (($x8027 (or $x8025 c_88_5)))
 (let (($x8029 (or $x8027 c_88_6)))
 (let (($x8031 (or $x8029 c_88_7)))
 (or $x8031 c_88_8))))))))))
(assert
 (not (and c_88_0 c_88_1)))
(assert
 (not (and c_88_0 c_88_2)))
(assert
 (not (and c_88_0 c_88_3)))
(assert
 (not (and c_88_0 c_88_4)))
(assert
 (not (and c_88_0 c_88_5)))
(assert
 (not (and c_88_0 c_88_6)))
(assert
 (not (and c_88_0 c_88_7)))
(assert
 (not (and c_88_0 c_88_8)))
(assert
 (not (and c_88_1 c_88_2)))
(assert
 (not (and c_88_1 c_88_3)))
(assert
 (not (and c_88_1 c_88_4)))
(assert
 (not (and c_88_1 c_88_5)))
(assert
 (not (and c_88_1 c_88_6)))
(assert
 (not (and c_88_1 c_88_7)))
(assert
 (not (and c_88_1 c_88_8)))
(assert
 (not (and c_88_2 c_88_3)))
(assert
 (not (and c_88_2 c_88_4)))
(assert
 (not (and c_88_2 c_88_5)))
(assert
 (not (and c_88_2 c_88_6)))
(assert
 (not (and c_88_2 c_88_7)))
(assert
 (not (and c_88_2 c_88_8)))
(assert
 (not (and c_88_3 c_88_4)))
(assert
 (not (and c_88_3 c_88_5)))
(assert
 (not (and c_88_3 c_88_6)))
(assert
 (not (and c_88_3 c_88_7)))
(assert
 (not (and c_88_3 c_88_8)))
(assert
 (not (and c_88_4 c_88_5)))
(assert
 (not (and c_88_4 c_88_6)))
(assert
 (not (and c_88_4 c_88_7)))
(assert
 (not (and c_88_4 c_88_8)))
(assert
 (not (and c_88_5 c_88_6)))
(assert
 (not (and c_88_5 c_88_7)))
(assert
 (not (and c_88_5 c_88_8)))
(assert
 (not (and c_88_6 c_88_7)))
(assert
 (not (and c_88_6 c_88_8)))
(assert
 (not (and c_88_7 c_88_8)))
(assert
 (let (($x8107 (or false c_89_0)))
 (let (($x8109 (or $x8107 c_89_1)))
 (let (($x8111 (or $x8109 c_89_2)))
 (let (($x8113 (or $x8111 c_89_3)))
 (let (($x8115 (or $x8113 c_89_4)))
 (let (($x8117 (or $x8115 c_89_5)))
 (let (($x8119 (or $x8117 c_89_6)))
 (let (($x8121 (or $x8119 c_89_7)))
 (or $x8121 c_89_8))))))))))
(assert
 (not (and c_89_0 c_89_1)))
(assert
 (not (and c_89_0 c_89_2)))
(assert
 (not (and c_89_0 c_89_3)))
(assert
 (not (and c_89_0 c_89_4)))
(assert
 (not (and c_89_0 c_89_5)))
(assert
 (not (and c_89_0 c_89_6)))
(assert
 (not (and c_89_0 c_89_7)))
(assert
 (not (and c_89_0 c_89_8)))
(assert
 (not (and c_89_1 c_89_2)))
(assert
 (not (and c_89_1 c_89_3)))
(assert
 (not (and c_89_1 c_89_4)))
(assert
 (not (and c_89_1 c_89_5)))
(assert
 (not (and c_89_1 c_89_6)))
(assert
 (not (and c_89_1 c_89_7)))
(assert
 (not (and c_89_1 c_89_8)))
(assert
 (not (and c_89_2 c_89_3)))
(assert
 (not (and c_89_2 c_89_4)))
(assert
 (not (and c_89_2 c_89_5)))
(assert
 (not (and c_89_2 c_89_6)))
(assert
 (not (and c_89_2 c_89_7)))
(assert
 (not (and c_89_2 c_89_8)))
(assert
 (not (and c_89_3 c_89_4)))
(assert
 (not (and c_89_3 c_89_5)))
(assert
 (not (and c_89_3 c_89_6)))
(assert
 (not (and c_89_3 c_89_7)))
(assert
 (not (and c_89_3 c_89_8)))
(assert
 (not (and c_89_4 c_89_5)))
(assert
 (not (and c_89_4 c_89_6)))
(assert
 (not (and c_89_4 c_89_7)))
(assert
 (not (and c_89_4 c_89_8)))
(assert
 (not (and c_89_5 c_89_6)))
(assert
 (not (and c_89_5 c_89_7)))
(assert
 (not (and c_89_5 c_89_8)))
(assert
 (not (and c_89_6 c_89_7)))
(assert
 (not (and c_89_6 c_89_8)))
(assert
 (not (and c_89_7 c_89_8)))
(assert
 (let (($x8197 (or false c_90_0)))
 (let (($x8199 (or $x8197 c_90_1)))
 (let (($x8201 (or $x8199 c_90_2)))
 (let (($x8203 (or $x8201 c_90_3)))
 (let (($x8205 (or $x8203 c_90_4)))
 (let (($x8207 (or $x8205 c_90_5)))
 (let (($x8209 (or $x8207 c_90_6)))
 (let (($x8211 (or $x8209 c_90_7)))
 (or $x8211 c_90_8))))))))))
(assert
 (not (and c_90_0 c_90_1)))
(assert
 (not (and c_90_0 c_90_2)))
(assert
 (not (and c_90_0 c_90_3)))
(assert
 (not (and c_90_0 c_90_4)))
(assert
 (not (and c_90_0 c_90_5)))
(assert
 (not (and c_90_0 c_90_6)))
(assert
 (not (and c_90_0 c_90_7)))
(assert
 (not (and c_90_0 c_90_8)))
(assert
 (not (and c_90_1 c_90_2)))
(assert
 (not (and c_90_1 c_90_3)))
(assert
 (not (and c_90_1 c_90_4)))
(assert
 (not (and c_90_1 c_90_5)))
(assert
 (not (and c_90_1 c_90_6)))
(assert
 (not (and c_90_1 c_90_7)))
(assert
 (not (and c_90_1 c_90_8)))
(assert
 (not (and c_90_2 c_90_3)))
(assert
 (not (and c_90_2 c_90_4)))
(assert
 (not (and c_90_2 c_90_5)))
(assert
 (not (and c_90_2 c_90_6)))
(assert
 (not (and c_90_2 c_90_7)))
(assert
 (not (and c_90_2 c_90_8)))
(assert
 (not (and c_90_3 c_90_4)))
(assert
 (not (and c_90_3 c_90_5)))
(assert
 (not (and c_90_3 c_90_6)))
(assert
 (not (and c_90_3 c_90_7)))
(assert
 (not (and c_90_3 c_90_8)))
(assert
 (not (and c_90_4 c_90_5)))
(assert
 (not (and c_90_4 c_90_6)))
(assert
 (not (and c_90_4 c_90_7)))
(assert
 (not (and c_90_4 c_90_8)))
(assert
 (not (and c_90_5 c_90_6)))
(assert
 (not (and c_90_5 c_90_7)))
(assert
 (not (and c_90_5 c_90_8)))
(assert
 (not (and c_90_6 c_90_7)))
(assert
 (not (and c_90_6 c_90_8)))
(assert
 (not (and c_90_7 c_90_8)))
(assert
 (let (($x8287 (or false d_0_0)))
 (let (($x8289 (or $x8287 d_0_1)))
 (let (($x8291 (or $x8289 d_0_2)))
 (let (($x8293 (or $x8291 d_0_3)))
 (let (($x8295 (or $x8293 d_0_4)))
 (let (($x8297 (or $x8295 d_0_5)))
 (let (($x8299 (or $x8297 d_0_6)))
 (let (($x8301 (or $x8299 d_0_7)))
 (or $x8301 d_0_8))))))))))
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
 (not (and d_0_4 d_0_5)))
(assert
 (not (and d_0_4 d_0_6)))
(assert
 (not (and d_0_4 d_0_7)))
(assert
 (not (and d_0_4 d_0_8)))
(assert
 (not (and d_0_5 d_0_6)))
(assert
 (not (and d_0_5 d_0_7)))
(assert
 (not (and d_0_5 d_0_8)))
(assert
 (not (and d_0_6 d_0_7)))
(assert
 (not (and d_0_6 d_0_8)))
(assert
 (not (and d_0_7 d_0_8)))
(assert
 (let (($x8377 (or false d_1_0)))
 (let (($x8379 (or $x8377 d_1_1)))
 (let (($x8381 (or $x8379 d_1_2)))
 (let (($x8383 (or $x8381 d_1_3)))
 (let (($x8385 (or $x8383 d_1_4)))
 (let (($x8387 (or $x8385 d_1_5)))
 (let (($x8389 (or $x8387 d_1_6)))
 (let (($x8391 (or $x8389 d_1_7)))
 (or $x8391 d_1_8))))))))))
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
 (not (and d_1_4 d_1_5)))
(assert
 (not (and d_1_4 d_1_6)))
(assert
 (not (and d_1_4 d_1_7)))
(assert
 (not (and d_1_4 d_1_8)))
(assert
 (not (and d_1_5 d_1_6)))
(assert
 (not (and d_1_5 d_1_7)))
(assert
 (not (and d_1_5 d_1_8)))
(assert
 (not (and d_1_6 d_1_7)))
(assert
 (not (and d_1_6 d_1_8)))
(assert
 (not (and d_1_7 d_1_8)))
(assert
 (let (($x8467 (or false d_2_0)))
 (let (($x8469 (or $x8467 d_2_1)))
 (let (($x8471 (or $x8469 d_2_2)))
 (let (($x8473 (or $x8471 d_2_3)))
 (let (($x8475 (or $x8473 d_2_4)))
 (let (($x8477 (or $x8475 d_2_5)))
 (let (($x8479 (or $x8477 d_2_6)))
 (let (($x8481 (or $x8479 d_2_7)))
 (or $x8481 d_2_8))))))))))
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
 (not (and d_2_4 d_2_5)))
(assert
 (not (and d_2_4 d_2_6)))
(assert
 (not (and d_2_4 d_2_7)))
(assert
 (not (and d_2_4 d_2_8)))
(assert
 (not (and d_2_5 d_2_6)))
(assert
 (not (and d_2_5 d_2_7)))
(assert
 (not (and d_2_5 d_2_8)))
(assert
 (not (and d_2_6 d_2_7)))
(assert
 (not (and d_2_6 d_2_8)))
(assert
 (not (and d_2_7 d_2_8)))
(assert
 (let (($x8557 (or false d_3_0)))
 (let (($x8559 (or $x8557 d_3_1)))
 (let (($x8561 (or $x8559 d_3_2)))
 (let (($x8563 (or $x8561 d_3_3)))
 (let (($x8565 (or $x8563 d_3_4)))
 (let (($x8567 (or $x8565 d_3_5)))
 (let (($x8569 (or $x8567 d_3_6)))
 (let (($x8571 (or $x8569 d_3_7)))
 (or $x8571 d_3_8))))))))))
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
 (not (and d_3_4 d_3_5)))
(assert
 (not (and d_3_4 d_3_6)))
(assert
 (not (and d_3_4 d_3_7)))
(assert
 (not (and d_3_4 d_3_8)))
(assert
 (not (and d_3_5 d_3_6)))
(assert
 (not (and d_3_5 d_3_7)))
(assert
 (not (and d_3_5 d_3_8)))
(assert
 (not (and d_3_6 d_3_7)))
(assert
 (not (and d_3_6 d_3_8)))
(assert
 (not (and d_3_7 d_3_8)))
(assert
 (let (($x8647 (or false d_4_0)))
 (let (($x8649 (or $x8647 d_4_1)))
 (let (($x8651 (or $x8649 d_4_2)))
 (let (($x8653 (or $x8651 d_4_3)))
 (let (($x8655 (or $x8653 d_4_4)))
 (let (($x8657 (or $x8655 d_4_5)))
 (let (($x8659 (or $x8657 d_4_6)))
 (let (($x8661 (or $x8659 d_4_7)))
 (or $x8661 d_4_8))))))))))
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
 (not (and d_4_4 d_4_5)))
(assert
 (not (and d_4_4 d_4_6)))
(assert
 (not (and d_4_4 d_4_7)))
(assert
 (not (and d_4_4 d_4_8)))
(assert
 (not (and d_4_5 d_4_6)))
(assert
 (not (and d_4_5 d_4_7)))
(assert
 (not (and d_4_5 d_4_8)))
(assert
 (not (and d_4_6 d_4_7)))
(assert
 (not (and d_4_6 d_4_8)))
(assert
 (not (and d_4_7 d_4_8)))
(assert
 (let (($x8737 (or false d_5_0)))
 (let (($x8739 (or $x8737 d_5_1)))
 (let (($x8741 (or $x8739 d_5_2)))
 (let (($x8743 (or $x8741 d_5_3)))
 (let (($x8745 (or $x8743 d_5_4)))
 (let (($x8747 (or $x8745 d_5_5)))
 (let (($x8749 (or $x8747 d_5_6)))
 (let (($x8751 (or $x8749 d_5_7)))
 (or $x8751 d_5_8))))))))))
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
 (not (and d_5_4 d_5_5)))
(assert
 (not (and d_5_4 d_5_6)))
(assert
 (not (and d_5_4 d_5_7)))
(assert
 (not (and d_5_4 d_5_8)))
(assert
 (not (and d_5_5 d_5_6)))
(assert
 (not (and d_5_5 d_5_7)))
(assert
 (not (and d_5_5 d_5_8)))
(assert
 (not (and d_5_6 d_5_7)))
(assert
 (not (and d_5_6 d_5_8)))
(assert
 (not (and d_5_7 d_5_8)))
(assert
 (let (($x8827 (or false d_6_0)))
 (let (($x8829 (or $x8827 d_6_1)))
 (let (($x8831 (or $x8829 d_6_2)))
 (let (($x8833 (or $x8831 d_6_3)))
 (let (($x8835 (or $x8833 d_6_4)))
 (let (($x8837 (or $x8835 d_6_5)))
 (let (($x8839 (or $x8837 d_6_6)))
 (let (($x8841 (or $x8839 d_6_7)))
 (or $x8841 d_6_8))))))))))
(assert
 (not (and d_6_0 d_6_1)))
(assert
 (not (and d_6_0 d_6_2)))
(assert
 (not (and d_6_0 d_6_3)))
(assert
 (not (and d_6_0 d_6_4)))
(assert
 (not (and d_6_0 d_6_5)))
(assert
 (not (and d_6_0 d_6_6)))
(assert
 (not (and d_6_0 d_6_7)))
(assert
 (not (and d_6_0 d_6_8)))
(assert
 (not (and d_6_1 d_6_2)))
(assert
 (not (and d_6_1 d_6_3)))
(assert
 (not (and d_6_1 d_6_4)))
(assert
 (not (and d_6_1 d_6_5)))
(assert
 (not (and d_6_1 d_6_6)))
(assert
 (not (and d_6_1 d_6_7)))
(assert
 (not (and d_6_1 d_6_8)))
(assert
 (not (and d_6_2 d_6_3)))
(assert
 (not (and d_6_2 d_6_4)))
(assert
 (not (and d_6_2 d_6_5)))
(assert
 (not (and d_6_2 d_6_6)))
(assert
 (not (and d_6_2 d_6_7)))
(assert
 (not (and d_6_2 d_6_8)))
(assert
 (not (and d_6_3 d_6_4)))
(assert
 (not (and d_6_3 d_6_5)))
(assert
 (not (and d_6_3 d_6_6)))
(assert
 (not (and d_6_3 d_6_7)))
(assert
 (not (and d_6_3 d_6_8)))
(assert
 (not (and d_6_4 d_6_5)))
(assert
 (not (and d_6_4 d_6_6)))
(assert
 (not (and d_6_4 d_6_7)))
(assert
 (not (and d_6_4 d_6_8)))
(assert
 (not (and d_6_5 d_6_6)))
(assert
 (not (and d_6_5 d_6_7)))
(assert
 (not (and d_6_5 d_6_8)))
(assert
 (not (and d_6_6 d_6_7)))
(assert
 (not (and d_6_6 d_6_8)))
(assert
 (not (and d_6_7 d_6_8)))
(assert
 (let (($x8917 (or false d_7_0)))
 (let (($x8919 (or $x8917 d_7_1)))
 (let (($x8921 (or $x8919 d_7_2)))
 (let (($x8923 (or $x8921 d_7_3)))
 (let (($x8925 (or $x8923 d_7_4)))
 (let (($x8927 (or $x8925 d_7_5)))
 (let (($x8929 (or $x8927 d_7_6)))
 (let (($x8931 (or $x8929 d_7_7)))
 (or $x8931 d_7_8))))))))))
(assert
 (not (and d_7_0 d_7_1)))
(assert
 (not (and d_7_0 d_7_2)))
(assert
 (not (and d_7_0 d_7_3)))
(assert
 (not (and d_7_0 d_7_4)))
(assert
 (not (and d_7_0 d_7_5)))
(assert
 (not (and d_7_0 d_7_6)))
(assert
 (not (and d_7_0 d_7_7)))
(assert
 (not (and d_7_0 d_7_8)))
(assert
 (not (and d_7_1 d_7_2)))
(assert
 (not (and d_7_1 d_7_3)))
(assert
 (not (and d_7_1 d_7_4)))
(assert
 (not (and d_7_1 d_7_5)))
(assert
 (not (and d_7_1 d_7_6)))
(assert
 (not (and d_7_1 d_7_7)))
(assert
 (not (and d_7_1 d_7_8)))
(assert
 (not (and d_7_2 d_7_3)))
(assert
 (not (and d_7_2 d_7_4)))
(assert
 (not (and d_7_2 d_7_5)))
(assert
 (not (and d_7_2 d_7_6)))
(assert
 (not (and d_7_2 d_7_7)))
(assert
 (not (and d_7_2 d_7_8)))
(assert
 (not (and d_7_3 d_7_4)))
(assert
 (not (and d_7_3 d_7_5)))
(assert
 (not (and d_7_3 d_7_6)))
(assert
 (not (and d_7_3 d_7_7)))
(assert
 (not (and d_7_3 d_7_8)))
(assert
 (not (and d_7_4 d_7_5)))
(assert
 (not (and d_7_4 d_7_6)))
(assert
 (not (and d_7_4 d_7_7)))
(assert
 (not (and d_7_4 d_7_8)))
(assert
 (not (and d_7_5 d_7_6)))
(assert
 (not (and d_7_5 d_7_7)))
(assert
 (not (and d_7_5 d_7_8)))
(assert
 (not (and d_7_6 d_7_7)))
(assert
 (not (and d_7_6 d_7_8)))
(assert
 (not (and d_7_7 d_7_8)))
(assert
 (let (($x9007 (or false d_8_0)))
 (let (($x9009 (or $x9007 d_8_1)))
 (let (($x9011 (or $x9009 d_8_2)))
 (let (($x9013 (or $x9011 d_8_3)))
 (let (($x9015 (or $x9013 d_8_4)))
 (let (($x9017 (or $x9015 d_8_5)))
 (let (($x9019 (or $x9017 d_8_6)))
 (let (($x9021 (or $x9019 d_8_7)))
 (or $x9021 d_8_8))))))))))
(assert
 (not (and d_8_0 d_8_1)))
(assert
 (not (and d_8_0 d_8_2)))
(assert
 (not (and d_8_0 d_8_3)))
(assert
 (not (and d_8_0 d_8_4)))
(assert
 (not (and d_8_0 d_8_5)))
(assert
 (not (and d_8_0 d_8_6)))
(assert
 (not (and d_8_0 d_8_7)))
(assert
 (not (and d_8_0 d_8_8)))
(assert
 (not (and d_8_1 d_8_2)))
(assert
 (not (and d_8_1 d_8_3)))
(assert
 (not (and d_8_1 d_8_4)))
(assert
 (not (and d_8_1 d_8_5)))
(assert
 (not (and d_8_1 d_8_6)))
(assert
 (not (and d_8_1 d_8_7)))
(assert
 (not (and d_8_1 d_8_8)))
(assert
 (not (and d_8_2 d_8_3)))
(assert
 (not (and d_8_2 d_8_4)))
(assert
 (not (and d_8_2 d_8_5)))
(assert
 (not (and d_8_2 d_8_6)))
(assert
 (not (and d_8_2 d_8_7)))
(assert
 (not (and d_8_2 d_8_8)))
(assert
 (not (and d_8_3 d_8_4)))
(assert
 (not (and d_8_3 d_8_5)))
(assert
 (not (and d_8_3 d_8_6)))
(assert
 (not (and d_8_3 d_8_7)))
(assert
 (not (and d_8_3 d_8_8)))
(assert
 (not (and d_8_4 d_8_5)))
(assert
 (not (and d_8_4 d_8_6)))
(assert
 (not (and d_8_4 d_8_7)))
(assert
 (not (and d_8_4 d_8_8)))
(assert
 (not (and d_8_5 d_8_6)))
(assert
 (not (and d_8_5 d_8_7)))
(assert
 (not (and d_8_5 d_8_8)))
(assert
 (not (and d_8_6 d_8_7)))
(assert
 (not (and d_8_6 d_8_8)))
(assert
 (not (and d_8_7 d_8_8)))
(assert
 (let (($x9097 (or false d_9_0)))
 (let (($x9099 (or $x9097 d_9_1)))
 (let (($x9101 (or $x9099 d_9_2)))
 (let (($x9103 (or $x9101 d_9_3)))
 (let (($x9105 (or $x9103 d_9_4)))
 (let (($x9107 (or $x9105 d_9_5)))
 (let (($x9109 (or $x9107 d_9_6)))
 (let (($x9111 (or $x9109 d_9_7)))
 (or $x9111 d_9_8))))))))))
(assert
 (not (and d_9_0 d_9_1)))
(assert
 (not (and d_9_0 d_9_2)))
(assert
 (not (and d_9_0 d_9_3)))
(assert
 (not (and d_9_0 d_9_4)))
(assert
 (not (and d_9_0 d_9_5)))
(assert
 (not (and d_9_0 d_9_6)))
(assert
 (not (and d_9_0 d_9_7)))
(assert
 (not (and d_9_0 d_9_8)))
(assert
 (not (and d_9_1 d_9_2)))
(assert
 (not (and d_9_1 d_9_3)))
(assert
 (not (and d_9_1 d_9_4)))
(assert
 (not (and d_9_1 d_9_5)))
(assert
 (not (and d_9_1 d_9_6)))
(assert
 (not (and d_9_1 d_9_7)))
(assert
 (not (and d_9_1 d_9_8)))
(assert
 (not (and d_9_2 d_9_3)))
(assert
 (not (and d_9_2 d_9_4)))
(assert
 (not (and d_9_2 d_9_5)))
(assert
 (not (and d_9_2 d_9_6)))
(assert
 (not (and d_9_2 d_9_7)))
(assert
 (not (and d_9_2 d_9_8)))
(assert
 (not (and d_9_3 d_9_4)))
(assert
 (not (and d_9_3 d_9_5)))
(assert
 (not (and d_9_3 d_9_6)))
(assert
 (not (and d_9_3 d_9_7)))
(assert
 (not (and d_9_3 d_9_8)))
(assert
 (not (and d_9_4 d_9_5)))
(assert
 (not (and d_9_4 d_9_6)))
(assert
 (not (and d_9_4 d_9_7)))
(assert
 (not (and d_9_4 d_9_8)))
(assert
 (not (and d_9_5 d_9_6)))
(assert
 (not (and d_9_5 d_9_7)))
(assert
 (not (and d_9_5 d_9_8)))
(assert
 (not (and d_9_6 d_9_7)))
(assert
 (not (and d_9_6 d_9_8)))
(assert
 (not (and d_9_7 d_9_8)))
(assert
 (let (($x9187 (or false d_10_0)))
 (let (($x9189 (or $x9187 d_10_1)))
 (let (($x9191 (or $x9189 d_10_2)))
 (let (($x9193 (or $x9191 d_10_3)))
 (let (($x9195 (or $x9193 d_10_4)))
 (let (($x9197 (or $x9195 d_10_5)))
 (let (($x9199 (or $x9197 d_10_6)))
 (let (($x9201 (or $x9199 d_10_7)))
 (or $x9201 d_10_8))))))))))
(assert
 (not (and d_10_0 d_10_1)))
(assert
 (not (and d_10_0 d_10_2)))
(assert
 (not (and d_10_0 d_10_3)))
(assert
 (not (and d_10_0 d_10_4)))
(assert
 (not (and d_10_0 d_10_5)))
(assert
 (not (and d_10_0 d_10_6)))
(assert
 (not (and d_10_0 d_10_7)))
(assert
 (not (and d_10_0 d_10_8)))
(assert
 (not (and d_10_1 d_10_2)))
(assert
 (not (and d_10_1 d_10_3)))
(assert
 (not (and d_10_1 d_10_4)))
(assert
 (not (and d_10_1 d_10_5)))
(assert
 (not (and d_10_1 d_10_6)))
(assert
 (not (and d_10_1 d_10_7)))
(assert
 (not (and d_10_1 d_10_8)))
(assert
 (not (and d_10_2 d_10_3)))
(assert
 (not (and d_10_2 d_10_4)))
(assert
 (not (and d_10_2 d_10_5)))
(assert
 (not (and d_10_2 d_10_6)))
(assert
 (not (and d_10_2 d_10_7)))
(assert
 (not (and d_10_2 d_10_8)))
(assert
 (not (and d_10_3 d_10_4)))
(assert
 (not (and d_10_3 d_10_5)))
(assert
 (not (and d_10_3 d_10_6)))
(assert
 (not (and d_10_3 d_10_7)))
(assert
 (not (and d_10_3 d_10_8)))
(assert
 (not (and d_10_4 d_10_5)))
(assert
 (not (and d_10_4 d_10_6)))
(assert
 (not (and d_10_4 d_10_7)))
(assert
 (not (and d_10_4 d_10_8)))
(assert
 (not (and d_10_5 d_10_6)))
(assert
 (not (and d_10_5 d_10_7)))
(assert
 (not (and d_10_5 d_10_8)))
(assert
 (not (and d_10_6 d_10_7)))
(assert
 (not (and d_10_6 d_10_8)))
(assert
 (not (and d_10_7 d_10_8)))
(assert
 (let (($x9277 (or false d_11_0)))
 (let (($x9279 (or $x9277 d_11_1)))
 (let (($x9281 (or $x9279 d_11_2)))
 (let (($x9283 (or $x9281 d_11_3)))
 (let (($x9285 (or $x9283 d_11_4)))
 (let (($x9287 (or $x9285 d_11_5)))
 (let (($x9289 (or $x9287 d_11_6)))
 (let (($x9291 (or $x9289 d_11_7)))
 (or $x9291 d_11_8))))))))))
(assert
 (not (and d_11_0 d_11_1)))
(assert
 (not (and d_11_0 d_11_2)))
(assert
 (not (and d_11_0 d_11_3)))
(assert
 (not (and d_11_0 d_11_4)))
(assert
 (not (and d_11_0 d_11_5)))
(assert
 (not (and d_11_0 d_11_6)))
(assert
 (not (and d_11_0 d_11_7)))
(assert
 (not (and d_11_0 d_11_8)))
(assert
 (not (and d_11_1 d_11_2)))
(assert
 (not (and d_11_1 d_11_3)))
(assert
 (not (and d_11_1 d_11_4)))
(assert
 (not (and d_11_1 d_11_5)))
(assert
 (not (and d_11_1 d_11_6)))
(assert
 (not (and d_11_1 d_11_7)))
(assert
 (not (and d_11_1 d_11_8)))
(assert
 (not (and d_11_2 d_11_3)))
(assert
 (not (and d_11_2 d_11_4)))
(assert
 (not (and d_11_2 d_11_5)))
(assert
 (not (and d_11_2 d_11_6)))
(assert
 (not (and d_11_2 d_11_7)))
(assert
 (not (and d_11_2 d_11_8)))
(assert
 (not (and d_11_3 d_11_4)))
(assert
 (not (and d_11_3 d_11_5)))
(assert
 (not (and d_11_3 d_11_6)))
(assert
 (not (and d_11_3 d_11_7)))
(assert
 (not (and d_11_3 d_11_8)))
(assert
 (not (and d_11_4 d_11_5)))
(assert
 (not (and d_11_4 d_11_6)))
(assert
 (not (and d_11_4 d_11_7)))
(assert
 (not (and d_11_4 d_11_8)))
(assert
 (not (and d_11_5 d_11_6)))
(assert
 (not (and d_11_5 d_11_7)))
(assert
 (not (and d_11_5 d_11_8)))
(assert
 (not (and d_11_6 d_11_7)))
(assert
 (not (and d_11_6 d_11_8)))
(assert
 (not (and d_11_7 d_11_8)))
(assert
 (let (($x9367 (or false d_12_0)))
 (let (($x9369 (or $x9367 d_12_1)))
 (let (($x9371 (or $x9369 d_12_2)))
 (let (($x9373 (or $x9371 d_12_3)))
 (let (($x9375 (or $x9373 d_12_4)))
 (let (($x9377 (or $x9375 d_12_5)))
 (let (($x9379 (or $x9377 d_12_6)))
 (let (($x9381 (or $x9379 d_12_7)))
 (or $x9381 d_12_8))))))))))
(assert
 (not (and d_12_0 d_12_1)))
(assert
 (not (and d_12_0 d_12_2)))
(assert
 (not (and d_12_0 d_12_3)))
(assert
 (not (and d_12_0 d_12_4)))
(assert
 (not (and d_12_0 d_12_5)))
(assert
 (not (and d_12_0 d_12_6)))
(assert
 (not (and d_12_0 d_12_7)))
(assert
 (not (and d_12_0 d_12_8)))
(assert
 (not (and d_12_1 d_12_2)))
(assert
 (not (and d_12_1 d_12_3)))
(assert
 (not (and d_12_1 d_12_4)))
(assert
 (not (and d_12_1 d_12_5)))
(assert
 (not (and d_12_1 d_12_6)))
(assert
 (not (and d_12_1 d_12_7)))
(assert
 (not (and d_12_1 d_12_8)))
(assert
 (not (and d_12_2 d_12_3)))
(assert
 (not (and d_12_2 d_12_4)))
(assert
 (not (and d_12_2 d_12_5)))
(assert
 (not (and d_12_2 d_12_6)))
(assert
 (not (and d_12_2 d_12_7)))
(assert
 (not (and d_12_2 d_12_8)))
(assert
 (not (and d_12_3 d_12_4)))
(assert
 (not (and d_12_3 d_12_5)))
(assert
 (not (and d_12_3 d_12_6)))
(assert
 (not (and d_12_3 d_12_7)))
(assert
 (not (and d_12_3 d_12_8)))
(assert
 (not (and d_12_4 d_12_5)))
(assert
 (not (and d_12_4 d_12_6)))
(assert
 (not (and d_12_4 d_12_7)))
(assert
 (not (and d_12_4 d_12_8)))
(assert
 (not (and d_12_5 d_12_6)))
(assert
 (not (and d_12_5 d_12_7)))
(assert
 (not (and d_12_5 d_12_8)))
(assert
 (not (and d_12_6 d_12_7)))
(assert
 (not (and d_12_6 d_12_8)))
(assert
 (not (and d_12_7 d_12_8)))
(assert
 (let (($x9457 (or false d_13_0)))
 (let (($x9459 (or $x9457 d_13_1)))
 (let (($x9461 (or $x9459 d_13_2)))
 (let (($x9463 (or $x9461 d_13_3)))
 (let (($x9465 (or $x9463 d_13_4)))
 (let (($x9467 (or $x9465 d_13_5)))
 (let (($x9469 (or $x9467 d_13_6)))
 (let (($x9471 (or $x9469 d_13_7)))
 (or $x9471 d_13_8))))))))))
(assert
 (not (and d_13_0 d_13_1)))
(assert
 (not (and d_13_0 d_13_2)))
(assert
 (not (and d_13_0 d_13_3)))
(assert
 (not (and d_13_0 d_13_4)))
(assert
 (not (and d_13_0 d_13_5)))
(assert
 (not (and d_13_0 d_13_6)))
(assert
 (not (and d_13_0 d_13_7)))
(assert
 (not (and d_13_0 d_13_8)))
(assert
 (not (and d_13_1 d_13_2)))
(assert
 (not (and d_13_1 d_13_3)))
(assert
 (not (and d_13_1 d_13_4)))
(assert
 (not (and d_13_1 d_13_5)))
(assert
 (not (and d_13_1 d_13_6)))
(assert
 (not (and d_13_1 d_13_7)))
(assert
 (not (and d_13_1 d_13_8)))
(assert
 (not (and d_13_2 d_13_3)))
(assert
 (not (and d_13_2 d_13_4)))
(assert
 (not (and d_13_2 d_13_5)))
(assert
 (not (and d_13_2 d_13_6)))
(assert
 (not (and d_13_2 d_13_7)))
(assert
 (not (and d_13_2 d_13_8)))
(assert
 (not (and d_13_3 d_13_4)))
(assert
 (not (and d_13_3 d_13_5)))
(assert
 (not (and d_13_3 d_13_6)))
(assert
 (not (and d_13_3 d_13_7)))
(assert
 (not (and d_13_3 d_13_8)))
(assert
 (not (and d_13_4 d_13_5)))
(assert
 (not (and d_13_4 d_13_6)))
(assert
 (not (and d_13_4 d_13_7)))
(assert
 (not (and d_13_4 d_13_8)))
(assert
 (not (and d_13_5 d_13_6)))
(assert
 (not (and d_13_5 d_13_7)))
(assert
 (not (and d_13_5 d_13_8)))
(assert
 (not (and d_13_6 d_13_7)))
(assert
 (not (and d_13_6 d_13_8)))
(assert
 (not (and d_13_7 d_13_8)))
(assert
 (let (($x9547 (or false d_14_0)))
 (let (($x9549 (or $x9547 d_14_1)))
 (let (($x9551 (or $x9549 d_14_2)))
 (let (($x9553 (or $x9551 d_14_3)))
 (let (($x9555 (or $x9553 d_14_4)))
 (let (($x9557 (or $x9555 d_14_5)))
 (let (($x9559 (or $x9557 d_14_6)))
 (let (($x9561 (or $x9559 d_14_7)))
 (or $x9561 d_14_8))))))))))
(assert
 (not (and d_14_0 d_14_1)))
(assert
 (not (and d_14_0 d_14_2)))
(assert
 (not (and d_14_0 d_14_3)))
(assert
 (not (and d_14_0 d_14_4)))
(assert
 (not (and d_14_0 d_14_5)))
(assert
 (not (and d_14_0 d_14_6)))
(assert
 (not (and d_14_0 d_14_7)))
(assert
 (not (and d_14_0 d_14_8)))
(assert
 (not (and d_14_1 d_14_2)))
(assert
 (not (and d_14_1 d_14_3)))
(assert
 (not (and d_14_1 d_14_4)))
(assert
 (not (and d_14_1 d_14_5)))
(assert
 (not (and d_14_1 d_14_6)))
(assert
 (not (and d_14_1 d_14_7)))
(assert
 (not (and d_14_1 d_14_8)))
(assert
 (not (and d_14_2 d_14_3)))
(assert
 (not (and d_14_2 d_14_4)))
(assert
 (not (and d_14_2 d_14_5)))
(assert
 (not (and d_14_2 d_14_6)))
(assert
 (not (and d_14_2 d_14_7)))
(assert
 (not (and d_14_2 d_14_8)))
(assert
 (not (and d_14_3 d_14_4)))
(assert
 (not (and d_14_3 d_14_5)))
(assert
 (not (and d_14_3 d_14_6)))
(assert
 (not (and d_14_3 d_14_7)))
(assert
 (not (and d_14_3 d_14_8)))
(assert
 (not (and d_14_4 d_14_5)))
(assert
 (not (and d_14_4 d_14_6)))
(assert
 (not (and d_14_4 d_14_7)))
(assert
 (not (and d_14_4 d_14_8)))
(assert
 (not (and d_14_5 d_14_6)))
(assert
 (not (and d_14_5 d_14_7)))
(assert
 (not (and d_14_5 d_14_8)))
(assert
 (not (and d_14_6 d_14_7)))
(assert
 (not (and d_14_6 d_14_8)))
(assert
 (not (and d_14_7 d_14_8)))
(assert
 (let (($x9637 (or false d_15_0)))
 (let (($x9639 (or $x9637 d_15_1)))
 (let (($x9641 (or $x9639 d_15_2)))
 (let (($x9643 (or $x9641 d_15_3)))
 (let (($x9645 (or $x9643 d_15_4)))
 (let (($x9647 (or $x9645 d_15_5)))
 (let (($x9649 (or $x9647 d_15_6)))
 (let (($x9651 (or $x9649 d_15_7)))
 (or $x9651 d_15_8))))))))))
(assert
 (not (and d_15_0 d_15_1)))
(assert
 (not (and d_15_0 d_15_2)))
(assert
 (not (and d_15_0 d_15_3)))
(assert
 (not (and d_15_0 d_15_4)))
(assert
 (not (and d_15_0 d_15_5)))
(assert
 (not (and d_15_0 d_15_6)))
(assert
 (not (and d_15_0 d_15_7)))
(assert
 (not (and d_15_0 d_15_8)))
(assert
 (not (and d_15_1 d_15_2)))
(assert
 (not (and d_15_1 d_15_3)))
(assert
 (not (and d_15_1 d_15_4)))
(assert
 (not (and d_15_1 d_15_5)))
(assert
 (not (and d_15_1 d_15_6)))
(assert
 (not (and d_15_1 d_15_7)))
(assert
 (not (and d_15_1 d_15_8)))
(assert
 (not (and d_15_2 d_15_3)))
(assert
 (not (and d_15_2 d_15_4)))
(assert
 (not (and d_15_2 d_15_5)))
(assert
 (not (and d_15_2 d_15_6)))
(assert
 (not (and d_15_2 d_15_7)))
(assert
 (not (and d_15_2 d_15_8)))
(assert
 (not (and d_15_3 d_15_4)))
(assert
 (not (and d_15_3 d_15_5)))
(assert
 (not (and d_15_3 d_15_6)))
(assert
 (not (and d_15_3 d_15_7)))
(assert
 (not (and d_15_3 d_15_8)))
(assert
 (not (and d_15_4 d_15_5)))
(assert
 (not (and d_15_4 d_15_6)))
(assert
 (not (and d_15_4 d_15_7)))
(assert
 (not (and d_15_4 d_15_8)))
(assert
 (not (and d_15_5 d_15_6)))
(assert
 (not (and d_15_5 d_15_7)))
(assert
 (not (and d_15_5 d_15_8)))
(assert
 (not (and d_15_6 d_15_7)))
(assert
 (not (and d_15_6 d_15_8)))
(assert
 (not (and d_15_7 d_15_8)))
(assert
 (let (($x9727 (or false d_16_0)))
 (let (($x9729 (or $x9727 d_16_1)))
 (let (($x9731 (or $x9729 d_16_2)))
 (let (($x9733 (or $x9731 d_16_3)))
 (let (($x9735 (or $x9733 d_16_4)))
 (let (($x9737 (or $x9735 d_16_5)))
 (let (($x9739 (or $x9737 d_16_6)))
 (let (($x9741 (or $x9739 d_16_7)))
 (or $x9741 d_16_8))))))))))
(assert
 (not (and d_16_0 d_16_1)))
(assert
 (not (and d_16_0 d_16_2)))
(assert
 (not (and d_16_0 d_16_3)))
(assert
 (not (and d_16_0 d_16_4)))
(assert
 (not (and d_16_0 d_16_5)))
(assert
 (not (and d_16_0 d_16_6)))
(assert
 (not (and d_16_0 d_16_7)))
(assert
 (not (and d_16_0 d_16_8)))
(assert
 (not (and d_16_1 d_16_2)))
(assert
 (not (and d_16_1 d_16_3)))
(assert
 (not (and d_16_1 d_16_4)))
(assert
 (not (and d_16_1 d_16_5)))
(assert
 (not (and d_16_1 d_16_6)))
(assert
 (not (and d_16_1 d_16_7)))
(assert
 (not (and d_16_1 d_16_8)))
(assert
 (not (and d_16_2 d_16_3)))
(assert
 (not (and d_16_2 d_16_4)))
(assert
 (not (and d_16_2 d_16_5)))
(assert
 (not (and d_16_2 d_16_6)))
(assert
 (not (and d_16_2 d_16_7)))
(assert
 (not (and d_16_2 d_16_8)))
(assert
 (not (and d_16_3 d_16_4)))
(assert
 (not (and d_16_3 d_16_5)))
(assert
 (not (and d_16_3 d_16_6)))
(assert
 (not (and d_16_3 d_16_7)))
(assert
 (not (and d_16_3 d_16_8)))
(assert
 (not (and d_16_4 d_16_5)))
(assert
 (not (and d_16_4 d_16_6)))
(assert
 (not (and d_16_4 d_16_7)))
(assert
 (not (and d_16_4 d_16_8)))
(assert
 (not (and d_16_5 d_16_6)))
(assert
 (not (and d_16_5 d_16_7)))
(assert
 (not (and d_16_5 d_16_8)))
(assert
 (not (and d_16_6 d_16_7)))
(assert
 (not (and d_16_6 d_16_8)))
(assert
 (not (and d_16_7 d_16_8)))
(assert
 (let (($x9817 (or false d_17_0)))
 (let (($x9819 (or $x9817 d_17_1)))
 (let (($x9821 (or $x9819 d_17_2)))
 (let (($x9823 (or $x9821 d_17_3)))
 (let (($x9825 (or $x9823 d_17_4)))
 (let (($x9827 (or $x9825 d_17_5)))
 (let (($x9829 (or $x9827 d_17_6)))
 (let (($x9831 (or $x9829 d_17_7)))
 (or $x9831 d_17_8))))))))))
(assert
 (not (and d_17_0 d_17_1)))
(assert
 (not (and d_17_0 d_17_2)))
(assert
 (not (and d_17_0 d_17_3)))
(assert
 (not (and d_17_0 d_17_4)))
(assert
 (not (and d_17_0 d_17_5)))
(assert
 (not (and d_17_0 d_17_6)))
(assert
 (not (and d_17_0 d_17_7)))
(assert
 (not (and d_17_0 d_17_8)))
(assert
 (not (and d_17_1 d_17_2)))
(assert
 (not (and d_17_1 d_17_3)))
(assert
 (not (and d_17_1 d_17_4)))
(assert
 (not (and d_17_1 d_17_5)))
(assert
 (not (and d_17_1 d_17_6)))
(assert
 (not (and d_17_1 d_17_7)))
(assert
 (not (and d_17_1 d_17_8)))
(assert
 (not (and d_17_2 d_17_3)))
(assert
 (not (and d_17_2 d_17_4)))
(assert
 (not (and d_17_2 d_17_5)))
(assert
 (not (and d_17_2 d_17_6)))
(assert
 (not (and d_17_2 d_17_7)))
(assert
 (not (and d_17_2 d_17_8)))
(assert
 (not (and d_17_3 d_17_4)))
(assert
 (not (and d_17_3 d_17_5)))
(assert
 (not (and d_17_3 d_17_6)))
(assert
 (not (and d_17_3 d_17_7)))
(assert
 (not (and d_17_3 d_17_8)))
(assert
 (not (and d_17_4 d_17_5)))
(assert
 (not (and d_17_4 d_17_6)))
(assert
 (not (and d_17_4 d_17_7)))
(assert
 (not (and d_17_4 d_17_8)))
(assert
 (not (and d_17_5 d_17_6)))
(assert
 (not (and d_17_5 d_17_7)))
(assert
 (not (and d_17_5 d_17_8)))
(assert
 (not (and d_17_6 d_17_7)))
(assert
 (not (and d_17_6 d_17_8)))
(assert
 (not (and d_17_7 d_17_8)))
(assert
 (let (($x9907 (or false d_18_0)))
 (let (($x9909 (or $x9907 d_18_1)))
 (let (($x9911 (or $x9909 d_18_2)))
 (let (($x9913 (or $x9911 d_18_3)))
 (let (($x9915 (or $x9913 d_18_4)))
 (let (($x9917 (or $x9915 d_18_5)))
 (let (($x9919 (or $x9917 d_18_6)))
 (let (($x9921 (or $x9919 d_18_7)))
 (or $x9921 d_18_8))))))))))
(assert
 (not (and d_18_0 d_18_1)))
(assert
 (not (and d_18_0 d_18_2)))
(assert
 (not (and d_18_0 d_18_3)))
(assert
 (not (and d_18_0 d_18_4)))
(assert
 (not (and d_18_0 d_18_5)))
(assert
 (not (and d_18_0 d_18_6)))
(assert
 (not (and d_18_0 d_18_7)))
(assert
 (not (and d_18_0 d_18_8)))
(assert
 (not (and d_18_1 d_18_2)))
(assert
 (not (and d_18_1 d_18_3)))
(assert
 (not (and d_18_1 d_18_4)))
(assert
 (not (and d_18_1 d_18_5)))
(assert
 (not (and d_18_1 d_18_6)))
(assert
 (not (and d_18_1 d_18_7)))
(assert
 (not (and d_18_1 d_18_8)))
(assert
 (not (and d_18_2 d_18_3)))
(assert
 (not (and d_18_2 d_18_4)))
(assert
 (not (and d_18_2 d_18_5)))
(assert
 (not (and d_18_2 d_18_6)))
(assert
 (not (and d_18_2 d_18_7)))
(assert
 (not (and d_18_2 d_18_8)))
(assert
 (not (and d_18_3 d_18_4)))
(assert
 (not (and d_18_3 d_18_5)))
(assert
 (not (and d_18_3 d_18_6)))
(assert
 (not (and d_18_3 d_18_7)))
(assert
 (not (and d_18_3 d_18_8)))
(assert
 (not (and d_18_4 d_18_5)))
(assert
 (not (and d_18_4 d_18_6)))
(assert
 (not (and d_18_4 d_18_7)))
(assert
 (not (and d_18_4 d_18_8)))
(assert
 (not (and d_18_5 d_18_6)))
(assert
 (not (and d_18_5 d_18_7)))
(assert
 (not (and d_18_5 d_18_8)))
(assert
 (not (and d_18_6 d_18_7)))
(assert
 (not (and d_18_6 d_18_8)))
(assert
 (not (and d_18_7 d_18_8)))
(assert
 (let (($x9997 (or false d_19_0)))
 (let (($x9999 (or $x9997 d_19_1)))
 (let (($x10001 (or $x9999 d_19_2)))
 (let (($x10003 (or $x10001 d_19_3)))
 (let (($x10005 (or $x10003 d_19_4)))
 (let (($x10007 (or $x10005 d_19_5)))
 (let (($x10009 (or $x10007 d_19_6)))
 (let (($x10011 (or $x10009 d_19_7)))
 (or $x10011 d_19_8))))))))))
(assert
 (not (and d_19_0 d_19_1)))
(assert
 (not (and d_19_0 d_19_2)))
(assert
 (not (and d_19_0 d_19_3)))
(assert
 (not (and d_19_0 d_19_4)))
(assert
 (not (and d_19_0 d_19_5)))
(assert
 (not (and d_19_0 d_19_6)))
(assert
 (not (and d_19_0 d_19_7)))
(assert
 (not (and d_19_0 d_19_8)))
(assert
 (not (and d_19_1 d_19_2)))
(assert
 (not (and d_19_1 d_19_3)))
(assert
 (not (and d_19_1 d_19_4)))
(assert
 (not (and d_19_1 d_19_5)))
(assert
 (not (and d_19_1 d_19_6)))
(assert
 (not (and d_19_1 d_19_7)))
(assert
 (not (and d_19_1 d_19_8)))
(assert
 (not (and d_19_2 d_19_3)))
(assert
 (not (and d_19_2 d_19_4)))
(assert
 (not (and d_19_2 d_19_5)))
(assert
 (not (and d_19_2 d_19_6)))
(assert
 (not (and d_19_2 d_19_7)))
(assert
 (not (and d_19_2 d_19_8)))
(assert
 (not (and d_19_3 d_19_4)))
(assert
 (not (and d_19_3 d_19_5)))
(assert
 (not (and d_19_3 d_19_6)))
(assert
 (not (and d_19_3 d_19_7)))
(assert
 (not (and d_19_3 d_19_8)))
(assert
 (not (and d_19_4 d_19_5)))
(assert
 (not (and d_19_4 d_19_6)))
(assert
 (not (and d_19_4 d_19_7)))
(assert
 (not (and d_19_4 d_19_8)))
(assert
 (not (and d_19_5 d_19_6)))
(assert
 (not (and d_19_5 d_19_7)))
(assert
 (not (and d_19_5 d_19_8)))
(assert
 (not (and d_19_6 d_19_7)))
(assert
 (not (and d_19_6 d_19_8)))
(assert
 (not (and d_19_7 d_19_8)))
(assert
 (let (($x10087 (or false d_20_0)))
 (let (($x10089 (or $x10087 d_20_1)))
 (let (($x10091 (or $x10089 d_20_2)))
 (let (($x10093 (or $x10091 d_20_3)))
 (let (($x10095 (or $x10093 d_20_4)))
 (let (($x10097 (or $x10095 d_20_5)))
 (let (($x10099 (or $x10097 d_20_6)))
 (let (($x10101 (or $x10099 d_20_7)))
 (or $x10101 d_20_8))))))))))
(assert
 (not (and d_20_0 d_20_1)))
(assert
 (not (and d_20_0 d_20_2)))
(assert
 (not (and d_20_0 d_20_3)))
(assert
 (not (and d_20_0 d_20_4)))
(assert
 (not (and d_20_0 d_20_5)))
(assert
 (not (and d_20_0 d_20_6)))
(assert
 (not (and d_20_0 d_20_7)))
(assert
 (not (and d_20_0 d_20_8)))
(assert
 (not (and d_20_1 d_20_2)))
(assert
 (not (and d_20_1 d_20_3)))
(assert
 (not (and d_20_1 d_20_4)))
(assert
 (not (and d_20_1 d_20_5)))
(assert
 (not (and d_20_1 d_20_6)))
(assert
 (not (and d_20_1 d_20_7)))
(assert
 (not (and d_20_1 d_20_8)))
(assert
 (not (and d_20_2 d_20_3)))
(assert
 (not (and d_20_2 d_20_4)))
(assert
 (not (and d_20_2 d_20_5)))
(assert
 (not (and d_20_2 d_20_6)))
(assert
 (not (and d_20_2 d_20_7)))
(assert
 (not (and d_20_2 d_20_8)))
(assert
 (not (and d_20_3 d_20_4)))
(assert
 (not (and d_20_3 d_20_5)))
(assert
 (not (and d_20_3 d_20_6)))
(assert
 (not (and d_20_3 d_20_7)))
(assert
 (not (and d_20_3 d_20_8)))
(assert
 (not (and d_20_4 d_20_5)))
(assert
 (not (and d_20_4 d_20_6)))
(assert
 (not (and d_20_4 d_20_7)))
(assert
 (not (and d_20_4 d_20_8)))
(assert
 (not (and d_20_5 d_20_6)))
(assert
 (not (and d_20_5 d_20_7)))
(assert
 (not (and d_20_5 d_20_8)))
(assert
 (not (and d_20_6 d_20_7)))
(assert
 (not (and d_20_6 d_20_8)))
(assert
 (not (and d_20_7 d_20_8)))
(assert
 (let (($x10177 (or false d_21_0)))
 (let (($x10179 (or $x10177 d_21_1)))
 (let (($x10181 (or $x10179 d_21_2)))
 (let (($x10183 (or $x10181 d_21_3)))
 (let (($x10185 (or $x10183 d_21_4)))
 (let (($x10187 (or $x10185 d_21_5)))
 (let (($x10189 (or $x10187 d_21_6)))
 (let (($x10191 (or $x10189 d_21_7)))
 (or $x10191 d_21_8))))))))))
(assert
 (not (and d_21_0 d_21_1)))
(assert
 (not (and d_21_0 d_21_2)))
(assert
 (not (and d_21_0 d_21_3)))
(assert
 (not (and d_21_0 d_21_4)))
(assert
 (not (and d_21_0 d_21_5)))
(assert
 (not (and d_21_0 d_21_6)))
(assert
 (not (and d_21_0 d_21_7)))
(assert
 (not (and d_21_0 d_21_8)))
(assert
 (not (and d_21_1 d_21_2)))
(assert
 (not (and d_21_1 d_21_3)))
(assert
 (not (and d_21_1 d_21_4)))
(assert
 (not (and d_21_1 d_21_5)))
(assert
 (not (and d_21_1 d_21_6)))
(assert
 (not (and d_21_1 d_21_7)))
(assert
 (not (and d_21_1 d_21_8)))
(assert
 (not (and d_21_2 d_21_3)))
(assert
 (not (and d_21_2 d_21_4)))
(assert
 (not (and d_21_2 d_21_5)))
(assert
 (not (and d_21_2 d_21_6)))
(assert
 (not (and d_21_2 d_21_7)))
(assert
 (not (and d_21_2 d_21_8)))
(assert
 (not (and d_21_3 d_21_4)))
(assert
 (not (and d_21_3 d_21_5)))
(assert
 (not (and d_21_3 d_21_6)))
(assert
 (not (and d_21_3 d_21_7)))
(assert
 (not (and d_21_3 d_21_8)))
(assert
 (not (and d_21_4 d_21_5)))
(assert
 (not (and d_21_4 d_21_6)))
(assert
 (not (and d_21_4 d_21_7)))
(assert
 (not (and d_21_4 d_21_8)))
(assert
 (not (and d_21_5 d_21_6)))
(assert
 (not (and d_21_5 d_21_7)))
(assert
 (not (and d_21_5 d_21_8)))
(assert
 (not (and d_21_6 d_21_7)))
(assert
 (not (and d_21_6 d_21_8)))
(assert
 (not (and d_21_7 d_21_8)))
(assert
 (let (($x10267 (or false d_22_0)))
 (let (($x10269 (or $x10267 d_22_1)))
 (let (($x10271 (or $x10269 d_22_2)))
 (let (($x10273 (or $x10271 d_22_3)))
 (let (($x10275 (or $x10273 d_22_4)))
 (let (($x10277 (or $x10275 d_22_5)))
 (let (($x10279 (or $x10277 d_22_6)))
 (let (($x10281 (or $x10279 d_22_7)))
 (or $x10281 d_22_8))))))))))
(assert
 (not (and d_22_0 d_22_1)))
(assert
 (not (and d_22_0 d_22_2)))
(assert
 (not (and d_22_0 d_22_3)))
(assert
 (not (and d_22_0 d_22_4)))
(assert
 (not (and d_22_0 d_22_5)))
(assert
 (not (and d_22_0 d_22_6)))
(assert
 (not (and d_22_0 d_22_7)))
(assert
 (not (and d_22_0 d_22_8)))
(assert
 (not (and d_22_1 d_22_2)))
(assert
 (not (and d_22_1 d_22_3)))
(assert
 (not (and d_22_1 d_22_4)))
(assert
 (not (and d_22_1 d_22_5)))
(assert
 (not (and d_22_1 d_22_6)))
(assert
 (not (and d_22_1 d_22_7)))
(assert
 (not (and d_22_1 d_22_8)))
(assert
 (not (and d_22_2 d_22_3)))
(assert
 (not (and d_22_2 d_22_4)))
(assert
 (not (and d_22_2 d_22_5)))
(assert
 (not (and d_22_2 d_22_6)))
(assert
 (not (and d_22_2 d_22_7)))
(assert
 (not (and d_22_2 d_22_8)))
(assert
 (not (and d_22_3 d_22_4)))
(assert
 (not (and d_22_3 d_22_5)))
(assert
 (not (and d_22_3 d_22_6)))
(assert
 (not (and d_22_3 d_22_7)))
(assert
 (not (and d_22_3 d_22_8)))
(assert
 (not (and d_22_4 d_22_5)))
(assert
 (not (and d_22_4 d_22_6)))
(assert
 (not (and d_22_4 d_22_7)))
(assert
 (not (and d_22_4 d_22_8)))
(assert
 (not (and d_22_5 d_22_6)))
(assert
 (not (and d_22_5 d_22_7)))
(assert
 (not (and d_22_5 d_22_8)))
(assert
 (not (and d_22_6 d_22_7)))
(assert
 (not (and d_22_6 d_22_8)))
(assert
 (not (and d_22_7 d_22_8)))
(assert
 (let (($x10357 (or false d_23_0)))
 (let (($x10359 (or $x10357 d_23_1)))
 (let (($x10361 (or $x10359 d_23_2)))
 (let (($x10363 (or $x10361 d_23_3)))
 (let (($x10365 (or $x10363 d_23_4)))
 (let (($x10367 (or $x10365 d_23_5)))
 (let (($x10369 (or $x10367 d_23_6)))
 (let (($x10371 (or $x10369 d_23_7)))
 (or $x10371 d_23_8))))))))))
(assert
 (not (and d_23_0 d_23_1)))
(assert
 (not (and d_23_0 d_23_2)))
(assert
 (not (and d_23_0 d_23_3)))
(assert
 (not (and d_23_0 d_23_4)))
(assert
 (not (and d_23_0 d_23_5)))
(assert
 (not (and d_23_0 d_23_6)))
(assert
 (not (and d_23_0 d_23_7)))
(assert
 (not (and d_23_0 d_23_8)))
(assert
 (not (and d_23_1 d_23_2)))
(assert
 (not (and d_23_1 d_23_3)))
(assert
 (not (and d_23_1 d_23_4)))
(assert
 (not (and d_23_1 d_23_5)))
(assert
 (not (and d_23_1 d_23_6)))
(assert
 (not (and d_23_1 d_23_7)))
(assert
 (not (and d_23_1 d_23_8)))
(assert
 (not (and d_23_2 d_23_3)))
(assert
 (not (and d_23_2 d_23_4)))
(assert
 (not (and d_23_2 d_23_5)))
(assert
 (not (and d_23_2 d_23_6)))
(assert
 (not (and d_23_2 d_23_7)))
(assert
 (not (and d_23_2 d_23_8)))
(assert
 (not (and d_23_3 d_23_4)))
(assert
 (not (and d_23_3 d_23_5)))
(assert
 (not (and d_23_3 d_23_6)))
(assert
 (not (and d_23_3 d_23_7)))
(assert
 (not (and d_23_3 d_23_8)))
(assert
 (not (and d_23_4 d_23_5)))
(assert
 (not (and d_23_4 d_23_6)))
(assert
 (not (and d_23_4 d_23_7)))
(assert
 (not (and d_23_4 d_23_8)))
(assert
 (not (and d_23_5 d_23_6)))
(assert
 (not (and d_23_5 d_23_7)))
(assert
 (not (and d_23_5 d_23_8)))
(assert
 (not (and d_23_6 d_23_7)))
(assert
 (not (and d_23_6 d_23_8)))
(assert
 (not (and d_23_7 d_23_8)))
(assert
 (let (($x10447 (or false d_24_0)))
 (let (($x10449 (or $x10447 d_24_1)))
 (let (($x10451 (or $x10449 d_24_2)))
 (let (($x10453 (or $x10451 d_24_3)))
 (let (($x10455 (or $x10453 d_24_4)))
 (let (($x10457 (or $x10455 d_24_5)))
 (let (($x10459 (or $x10457 d_24_6)))
 (let (($x10461 (or $x10459 d_24_7)))
 (or $x10461 d_24_8))))))))))
(assert
 (not (and d_24_0 d_24_1)))
(assert
 (not (and d_24_0 d_24_2)))
(assert
 (not (and d_24_0 d_24_3)))
(assert
 (not (and d_24_0 d_24_4)))
(assert
 (not (and d_24_0 d_24_5)))
(assert
 (not (and d_24_0 d_24_6)))
(assert
 (not (and d_24_0 d_24_7)))
(assert
 (not (and d_24_0 d_24_8)))
(assert
 (not (and d_24_1 d_24_2)))
(assert
 (not (and d_24_1 d_24_3)))
(assert
 (not (and d_24_1 d_24_4)))
(assert
 (not (and d_24_1 d_24_5)))
(assert
 (not (and d_24_1 d_24_6)))
(assert
 (not (and d_24_1 d_24_7)))
(assert
 (not (and d_24_1 d_24_8)))
(assert
 (not (and d_24_2 d_24_3)))
(assert
 (not (and d_24_2 d_24_4)))
(assert
 (not (and d_24_2 d_24_5)))
(assert
 (not (and d_24_2 d_24_6)))
(assert
 (not (and d_24_2 d_24_7)))
(assert
 (not (and d_24_2 d_24_8)))
(assert
 (not (and d_24_3 d_24_4)))
(assert
 (not (and d_24_3 d_24_5)))
(assert
 (not (and d_24_3 d_24_6)))
(assert
 (not (and d_24_3 d_24_7)))
(assert
 (not (and d_24_3 d_24_8)))
(assert
 (not (and d_24_4 d_24_5)))
(assert
 (not (and d_24_4 d_24_6)))
(assert
 (not (and d_24_4 d_24_7)))
(assert
 (not (and d_24_4 d_24_8)))
(assert
 (not (and d_24_5 d_24_6)))
(assert
 (not (and d_24_5 d_24_7)))
(assert
 (not (and d_24_5 d_24_8)))
(assert
 (not (and d_24_6 d_24_7)))
(assert
 (not (and d_24_6 d_24_8)))
(assert
 (not (and d_24_7 d_24_8)))
(assert
 (let (($x10537 (or false d_25_0)))
 (let (($x10539 (or $x10537 d_25_1)))
 (let (($x10541 (or $x10539 d_25_2)))
 (let (($x10543 (or $x10541 d_25_3)))
 (let (($x10545 (or $x10543 d_25_4)))
 (let (($x10547 (or $x10545 d_25_5)))
 (let (($x10549 (or $x10547 d_25_6)))
 (let (($x10551 (or $x10549 d_25_7)))
 (or $x10551 d_25_8))))))))))
(assert
 (not (and d_25_0 d_25_1)))
(assert
 (not (and d_25_0 d_25_2)))
(assert
 (not (and d_25_0 d_25_3)))
(assert
 (not (and d_25_0 d_25_4)))
(assert
 (not (and d_25_0 d_25_5)))
(assert
 (not (and d_25_0 d_25_6)))
(assert
 (not (and d_25_0 d_25_7)))
(assert
 (not (and d_25_0 d_25_8)))
(assert
 (not (and d_25_1 d_25_2)))
(assert
 (not (and d_25_1 d_25_3)))
(assert
 (not (and d_25_1 d_25_4)))
(assert
 (not (and d_25_1 d_25_5)))
(assert
 (not (and d_25_1 d_25_6)))
(assert
 (not (and d_25_1 d_25_7)))
(assert
 (not (and d_25_1 d_25_8)))
(assert
 (not (and d_25_2 d_25_3)))
(assert
 (not (and d_25_2 d_25_4)))
(assert
 (not (and d_25_2 d_25_5)))
(assert
 (not (and d_25_2 d_25_6)))
(assert
 (not (and d_25_2 d_25_7)))
(assert
 (not (and d_25_2 d_25_8)))
(assert
 (not (and d_25_3 d_25_4)))
(assert
 (not (and d_25_3 d_25_5)))
(assert
 (not (and d_25_3 d_25_6)))
(assert
 (not (and d_25_3 d_25_7)))
(assert
 (not (and d_25_3 d_25_8)))
(assert
 (not (and d_25_4 d_25_5)))
(assert
 (not (and d_25_4 d_25_6)))
(assert
 (not (and d_25_4 d_25_7)))
(assert
 (not (and d_25_4 d_25_8)))
(assert
 (not (and d_25_5 d_25_6)))
(assert
 (not (and d_25_5 d_25_7)))
(assert
 (not (and d_25_5 d_25_8)))
(assert
 (not (and d_25_6 d_25_7)))
(assert
 (not (and d_25_6 d_25_8)))
(assert
 (not (and d_25_7 d_25_8)))
(assert
 (let (($x10627 (or false d_26_0)))
 (let (($x10629 (or $x10627 d_26_1)))
 (let (($x10631 (or $x10629 d_26_2)))
 (let (($x10633 (or $x10631 d_26_3)))
 (let (($x10635 (or $x10633 d_26_4)))
 (let (($x10637 (or $x10635 d_26_5)))
 (let (($x10639 (or $x10637 d_26_6)))
 (let (($x10641 (or $x10639 d_26_7)))
 (or $x10641 d_26_8))))))))))
(assert
 (not (and d_26_0 d_26_1)))
(assert
 (not (and d_26_0 d_26_2)))
(assert
 (not (and d_26_0 d_26_3)))
(assert
 (not (and d_26_0 d_26_4)))
(assert
 (not (and d_26_0 d_26_5)))
(assert
 (not (and d_26_0 d_26_6)))
(assert
 (not (and d_26_0 d_26_7)))
(assert
 (not (and d_26_0 d_26_8)))
(assert
 (not (and d_26_1 d_26_2)))
(assert
 (not (and d_26_1 d_26_3)))
(assert
 (not (and d_26_1 d_26_4)))
(assert
 (not (and d_26_1 d_26_5)))
(assert
 (not (and d_26_1 d_26_6)))
(assert
 (not (and d_26_1 d_26_7)))
(assert
 (not (and d_26_1 d_26_8)))
(assert
 (not (and d_26_2 d_26_3)))
(assert
 (not (and d_26_2 d_26_4)))
(assert
 (not (and d_26_2 d_26_5)))
(assert
 (not (and d_26_2 d_26_6)))
(assert
 (not (and d_26_2 d_26_7)))
(assert
 (not (and d_26_2 d_26_8)))
(assert
 (not (and d_26_3 d_26_4)))
(assert
 (not (and d_26_3 d_26_5)))
(assert
 (not (and d_26_3 d_26_6)))
(assert
 (not (and d_26_3 d_26_7)))
(assert
 (not (and d_26_3 d_26_8)))
(assert
 (not (and d_26_4 d_26_5)))
(assert
 (not (and d_26_4 d_26_6)))
(assert
 (not (and d_26_4 d_26_7)))
(assert
 (not (and d_26_4 d_26_8)))
(assert
 (not (and d_26_5 d_26_6)))
(assert
 (not (and d_26_5 d_26_7)))
(assert
 (not (and d_26_5 d_26_8)))
(assert
 (not (and d_26_6 d_26_7)))
(assert
 (not (and d_26_6 d_26_8)))
(assert
 (not (and d_26_7 d_26_8)))
(assert
 (let (($x10717 (or false d_27_0)))
 (let (($x10719 (or $x10717 d_27_1)))
 (let (($x10721 (or $x10719 d_27_2)))
 (let (($x10723 (or $x10721 d_27_3)))
 (let (($x10725 (or $x10723 d_27_4)))
 (let (($x10727 (or $x10725 d_27_5)))
 (let (($x10729 (or $x10727 d_27_6)))
 (let (($x10731 (or $x10729 d_27_7)))
 (or $x10731 d_27_8))))))))))
(assert
 (not (and d_27_0 d_27_1)))
(assert
 (not (and d_27_0 d_27_2)))
(assert
 (not (and d_27_0 d_27_3)))
(assert
 (not (and d_27_0 d_27_4)))
(assert
 (not (and d_27_0 d_27_5)))
(assert
 (not (and d_27_0 d_27_6)))
(assert
 (not (and d_27_0 d_27_7)))
(assert
 (not (and d_27_0 d_27_8)))
(assert
 (not (and d_27_1 d_27_2)))
(assert
 (not (and d_27_1 d_27_3)))
(assert
 (not (and d_27_1 d_27_4)))
(assert
 (not (and d_27_1 d_27_5)))
(assert
 (not (and d_27_1 d_27_6)))
(assert
 (not (and d_27_1 d_27_7)))
(assert
 (not (and d_27_1 d_27_8)))
(assert
 (not (and d_27_2 d_27_3)))
(assert
 (not (and d_27_2 d_27_4)))
(assert
 (not (and d_27_2 d_27_5)))
(assert
 (not (and d_27_2 d_27_6)))
(assert
 (not (and d_27_2 d_27_7)))
(assert
 (not (and d_27_2 d_27_8)))
(assert
 (not (and d_27_3 d_27_4)))
(assert
 (not (and d_27_3 d_27_5)))
(assert
 (not (and d_27_3 d_27_6)))
(assert
 (not (and d_27_3 d_27_7)))
(assert
 (not (and d_27_3 d_27_8)))
(assert
 (not (and d_27_4 d_27_5)))
(assert
 (not (and d_27_4 d_27_6)))
(assert
 (not (and d_27_4 d_27_7)))
(assert
 (not (and d_27_4 d_27_8)))
(assert
 (not (and d_27_5 d_27_6)))
(assert
 (not (and d_27_5 d_27_7)))
(assert
 (not (and d_27_5 d_27_8)))
(assert
 (not (and d_27_6 d_27_7)))
(assert
 (not (and d_27_6 d_27_8)))
(assert
 (not (and d_27_7 d_27_8)))
(assert
 (let (($x10807 (or false d_28_0)))
 (let (($x10809 (or $x10807 d_28_1)))
 (let (($x10811 (or $x10809 d_28_2)))
 (let (($x10813 (or $x10811 d_28_3)))
 (let (($x10815 (or $x10813 d_28_4)))
 (let (($x10817 (or $x10815 d_28_5)))
 (let (($x10819 (or $x10817 d_28_6)))
 (let (($x10821 (or $x10819 d_28_7)))
 (or $x10821 d_28_8))))))))))
(assert
 (not (and d_28_0 d_28_1)))
(assert
 (not (and d_28_0 d_28_2)))
(assert
 (not (and d_28_0 d_28_3)))
(assert
 (not (and d_28_0 d_28_4)))
(assert
 (not (and d_28_0 d_28_5)))
(assert
 (not (and d_28_0 d_28_6)))
(assert
 (not (and d_28_0 d_28_7)))
(assert
 (not (and d_28_0 d_28_8)))
(assert
 (not (and d_28_1 d_28_2)))
(assert
 (not (and d_28_1 d_28_3)))
(assert
 (not (and d_28_1 d_28_4)))
(assert
 (not (and d_28_1 d_28_5)))
(assert
 (not (and d_28_1 d_28_6)))
(assert
 (not (and d_28_1 d_28_7)))
(assert
 (not (and d_28_1 d_28_8)))
(assert
 (not (and d_28_2 d_28_3)))
(assert
 (not (and d_28_2 d_28_4)))
(assert
 (not (and d_28_2 d_28_5)))
(assert
 (not (and d_28_2 d_28_6)))
(assert
 (not (and d_28_2 d_28_7)))
(assert
 (not (and d_28_2 d_28_8)))
(assert
 (not (and d_28_3 d_28_4)))
(assert
 (not (and d_28_3 d_28_5)))
(assert
 (not (and d_28_3 d_28_6)))
(assert
 (not (and d_28_3 d_28_7)))
(assert
 (not (and d_28_3 d_28_8)))
(assert
 (not (and d_28_4 d_28_5)))
(assert
 (not (and d_28_4 d_28_6)))
(assert
 (not (and d_28_4 d_28_7)))
(assert
 (not (and d_28_4 d_28_8)))
(assert
 (not (and d_28_5 d_28_6)))
(assert
 (not (and d_28_5 d_28_7)))
(assert
 (not (and d_28_5 d_28_8)))
(assert
 (not (and d_28_6 d_28_7)))
(assert
 (not (and d_28_6 d_28_8)))
(assert
 (not (and d_28_7 d_28_8)))
(assert
 (let (($x10897 (or false d_29_0)))
 (let (($x10899 (or $x10897 d_29_1)))
 (let (($x10901 (or $x10899 d_29_2)))
 (let (($x10903 (or $x10901 d_29_3)))
 (let (($x10905 (or $x10903 d_29_4)))
 (let (($x10907 (or $x10905 d_29_5)))
 (let (($x10909 (or $x10907 d_29_6)))
 (let (($x10911 (or $x10909 d_29_7)))
 (or $x10911 d_29_8))))))))))
(assert
 (not (and d_29_0 d_29_1)))
(assert
 (not (and d_29_0 d_29_2)))
(assert
 (not (and d_29_0 d_29_3)))
(assert
 (not (and d_29_0 d_29_4)))
(assert
 (not (and d_29_0 d_29_5)))
(assert
 (not (and d_29_0 d_29_6)))
(assert
 (not (and d_29_0 d_29_7)))
(assert
 (not (and d_29_0 d_29_8)))
(assert
 (not (and d_29_1 d_29_2)))
(assert
 (not (and d_29_1 d_29_3)))
(assert
 (not (and d_29_1 d_29_4)))
(assert
 (not (and d_29_1 d_29_5)))
(assert
 (not (and d_29_1 d_29_6)))
(assert
 (not (and d_29_1 d_29_7)))
(assert
 (not (and d_29_1 d_29_8)))
(assert
 (not (and d_29_2 d_29_3)))
(assert
 (not (and d_29_2 d_29_4)))
(assert
 (not (and d_29_2 d_29_5)))
(assert
 (not (and d_29_2 d_29_6)))
(assert
 (not (and d_29_2 d_29_7)))
(assert
 (not (and d_29_2 d_29_8)))
(assert
 (not (and d_29_3 d_29_4)))
(assert
 (not (and d_29_3 d_29_5)))
(assert
 (not (and d_29_3 d_29_6)))
(assert
 (not (and d_29_3 d_29_7)))
(assert
 (not (and d_29_3 d_29_8)))
(assert
 (not (and d_29_4 d_29_5)))
(assert
 (not (and d_29_4 d_29_6)))
(assert
 (not (and d_29_4 d_29_7)))
(assert
 (not (and d_29_4 d_29_8)))
(assert
 (not (and d_29_5 d_29_6)))
(assert
 (not (and d_29_5 d_29_7)))
(assert
 (not (and d_29_5 d_29_8)))
(assert
 (not (and d_29_6 d_29_7)))
(assert
 (not (and d_29_6 d_29_8)))
(assert
 (not (and d_29_7 d_29_8)))
(assert
 (let (($x10987 (or false d_30_0)))
 (let (($x10989 (or $x10987 d_30_1)))
 (let (($x10991 (or $x10989 d_30_2)))
 (let (($x10993 (or $x10991 d_30_3)))
 (let (($x10995 (or $x10993 d_30_4)))
 (let (($x10997 (or $x10995 d_30_5)))
 (let (($x10999 (or $x10997 d_30_6)))
 (let (($x11001 (or $x10999 d_30_7)))
 (or $x11001 d_30_8))))))))))
(assert
 (not (and d_30_0 d_30_1)))
(assert
 (not (and d_30_0 d_30_2)))
(assert
 (not (and d_30_0 d_30_3)))
(assert
 (not (and d_30_0 d_30_4)))
(assert
 (not (and d_30_0 d_30_5)))
(assert
 (not (and d_30_0 d_30_6)))
(assert
 (not (and d_30_0 d_30_7)))
(assert
 (not (and d_30_0 d_30_8)))
(assert
 (not (and d_30_1 d_30_2)))
(assert
 (not (and d_30_1 d_30_3)))
(assert
 (not (and d_30_1 d_30_4)))
(assert
 (not (and d_30_1 d_30_5)))
(assert
 (not (and d_30_1 d_30_6)))
(assert
 (not (and d_30_1 d_30_7)))
(assert
 (not (and d_30_1 d_30_8)))
(assert
 (not (and d_30_2 d_30_3)))
(assert
 (not (and d_30_2 d_30_4)))
(assert
 (not (and d_30_2 d_30_5)))
(assert
 (not (and d_30_2 d_30_6)))
(assert
 (not (and d_30_2 d_30_7)))
(assert
 (not (and d_30_2 d_30_8)))
(assert
 (not (and d_30_3 d_30_4)))
(assert
 (not (and d_30_3 d_30_5)))
(assert
 (not (and d_30_3 d_30_6)))
(assert
 (not (and d_30_3 d_30_7)))
(assert
 (not (and d_30_3 d_30_8)))
(assert
 (not (and d_30_4 d_30_5)))
(assert
 (not (and d_30_4 d_30_6)))
(assert
 (not (and d_30_4 d_30_7)))
(assert
 (not (and d_30_4 d_30_8)))
(assert
 (not (and d_30_5 d_30_6)))
(assert
 (not (and d_30_5 d_30_7)))
(assert
 (not (and d_30_5 d_30_8)))
(assert
 (not (and d_30_6 d_30_7)))
(assert
 (not (and d_30_6 d_30_8)))
(assert
 (not (and d_30_7 d_30_8)))
(assert
 (let (($x11077 (or false d_31_0)))
 (let (($x11079 (or $x11077 d_31_1)))
 (let (($x11081 (or $x11079 d_31_2)))
 (let (($x11083 (or $x11081 d_31_3)))
 (let (($x11085 (or $x11083 d_31_4)))
 (let (($x11087 (or $x11085 d_31_5)))
 (let (($x11089 (or $x11087 d_31_6)))
 (let (($x11091 (or $x11089 d_31_7)))
 (or $x11091 d_31_8))))))))))
(assert
 (not (and d_31_0 d_31_1)))
(assert
 (not (and d_31_0 d_31_2)))
(assert
 (not (and d_31_0 d_31_3)))
(assert
 (not (and d_31_0 d_31_4)))
(assert
 (not (and d_31_0 d_31_5)))
(assert
 (not (and d_31_0 d_31_6)))
(assert
 (not (and d_31_0 d_31_7)))
(assert
 (not (and d_31_0 d_31_8)))
(assert
 (not (and d_31_1 d_31_2)))
(assert
 (not (and d_31_1 d_31_3)))
(assert
 (not (and d_31_1 d_31_4)))
(assert
 (not (and d_31_1 d_31_5)))
(assert
 (not (and d_31_1 d_31_6)))
(assert
 (not (and d_31_1 d_31_7)))
(assert
 (not (and d_31_1 d_31_8)))
(assert
 (not (and d_31_2 d_31_3)))
(assert
 (not (and d_31_2 d_31_4)))
(assert
 (not (and d_31_2 d_31_5)))
(assert
 (not (and d_31_2 d_31_6)))
(assert
 (not (and d_31_2 d_31_7)))
(assert
 (not (and d_31_2 d_31_8)))
(assert
 (not (and d_31_3 d_31_4)))
(assert
 (not (and d_31_3 d_31_5)))
(assert
 (not (and d_31_3 d_31_6)))
(assert
 (not (and d_31_3 d_31_7)))
(assert
 (not (and d_31_3 d_31_8)))
(assert
 (not (and d_31_4 d_31_5)))
(assert
 (not (and d_31_4 d_31_6)))
(assert
 (not (and d_31_4 d_31_7)))
(assert
 (not (and d_31_4 d_31_8)))
(assert
 (not (and d_31_5 d_31_6)))
(assert
 (not (and d_31_5 d_31_7)))
(assert
 (not (and d_31_5 d_31_8)))
(assert
 (not (and d_31_6 d_31_7)))
(assert
 (not (and d_31_6 d_31_8)))
(assert
 (not (and d_31_7 d_31_8)))
(assert
 (let (($x11167 (or false d_32_0)))
 (let (($x11169 (or $x11167 d_32_1)))
 (let (($x11171 (or $x11169 d_32_2)))
 (let (($x11173 (or $x11171 d_32_3)))
 (let (($x11175 (or $x11173 d_32_4)))
 (let (($x11177 (or $x11175 d_32_5)))
 (let (($x11179 (or $x11177 d_32_6)))
 (let (($x11181 (or $x11179 d_32_7)))
 (or $x11181 d_32_8))))))))))
(assert
 (not (and d_32_0 d_32_1)))
(assert
 (not (and d_32_0 d_32_2)))
(assert
 (not (and d_32_0 d_32_3)))
(assert
 (not (and d_32_0 d_32_4)))
(assert
 (not (and d_32_0 d_32_5)))
(assert
 (not (and d_32_0 d_32_6)))
(assert
 (not (and d_32_0 d_32_7)))
(assert
 (not (and d_32_0 d_32_8)))
(assert
 (not (and d_32_1 d_32_2)))
(assert
 (not (and d_32_1 d_32_3)))
(assert
 (not (and d_32_1 d_32_4)))
(assert
 (not (and d_32_1 d_32_5)))
(assert
 (not (and d_32_1 d_32_6)))
(assert
 (not (and d_32_1 d_32_7)))
(assert
 (not (and d_32_1 d_32_8)))
(assert
 (not (and d_32_2 d_32_3)))
(assert
 (not (and d_32_2 d_32_4)))
(assert
 (not (and d_32_2 d_32_5)))
(assert
 (not (and d_32_2 d_32_6)))
(assert
 (not (and d_32_2 d_32_7)))
(assert
 (not (and d_32_2 d_32_8)))
(assert
 (not (and d_32_3 d_32_4)))
(assert
 (not (and d_32_3 d_32_5)))
(assert
 (not (and d_32_3 d_32_6)))
(assert
 (not (and d_32_3 d_32_7)))
(assert
 (not (and d_32_3 d_32_8)))
(assert
 (not (and d_32_4 d_32_5)))
(assert
 (not (and d_32_4 d_32_6)))
(assert
 (not (and d_32_4 d_32_7)))
(assert
 (not (and d_32_4 d_32_8)))
(assert
 (not (and d_32_5 d_32_6)))
(assert
 (not (and d_32_5 d_32_7)))
(assert
 (not (and d_32_5 d_32_8)))
(assert
 (not (and d_32_6 d_32_7)))
(assert
 (not (and d_32_6 d_32_8)))
(assert
 (not (and d_32_7 d_32_8)))
(assert
 (let (($x11257 (or false d_33_0)))
 (let (($x11259 (or $x11257 d_33_1)))
 (let (($x11261 (or $x11259 d_33_2)))
 (let (($x11263 (or $x11261 d_33_3)))
 (let (($x11265 (or $x11263 d_33_4)))
 (let (($x11267 (or $x11265 d_33_5)))
 (let (($x11269 (or $x11267 d_33_6)))
 (let (($x11271 (or $x11269 d_33_7)))
 (or $x11271 d_33_8))))))))))
(assert
 (not (and d_33_0 d_33_1)))
(assert
 (not (and d_33_0 d_33_2)))
(assert
 (not (and d_33_0 d_33_3)))
(assert
 (not (and d_33_0 d_33_4)))
(assert
 (not (and d_33_0 d_33_5)))
(assert
 (not (and d_33_0 d_33_6)))
(assert
 (not (and d_33_0 d_33_7)))
(assert
 (not (and d_33_0 d_33_8)))
(assert
 (not (and d_33_1 d_33_2)))
(assert
 (not (and d_33_1 d_33_3)))
(assert
 (not (and d_33_1 d_33_4)))
(assert
 (not (and d_33_1 d_33_5)))
(assert
 (not (and d_33_1 d_33_6)))
(assert
 (not (and d_33_1 d_33_7)))
(assert
 (not (and d_33_1 d_33_8)))
(assert
 (not (and d_33_2 d_33_3)))
(assert
 (not (and d_33_2 d_33_4)))
(assert
 (not (and d_33_2 d_33_5)))
(assert
 (not (and d_33_2 d_33_6)))
(assert
 (not (and d_33_2 d_33_7)))
(assert
 (not (and d_33_2 d_33_8)))
(assert
 (not (and d_33_3 d_33_4)))
(assert
 (not (and d_33_3 d_33_5)))
(assert
 (not (and d_33_3 d_33_6)))
(assert
 (not (and d_33_3 d_33_7)))
(assert
 (not (and d_33_3 d_33_8)))
(assert
 (not (and d_33_4 d_33_5)))
(assert
 (not (and d_33_4 d_33_6)))
(assert
 (not (and d_33_4 d_33_7)))
(assert
 (not (and d_33_4 d_33_8)))
(assert
 (not (and d_33_5 d_33_6)))
(assert
 (not (and d_33_5 d_33_7)))
(assert
 (not (and d_33_5 d_33_8)))
(assert
 (not (and d_33_6 d_33_7)))
(assert
 (not (and d_33_6 d_33_8)))
(assert
 (not (and d_33_7 d_33_8)))
(assert
 (let (($x11347 (or false d_34_0)))
 (let (($x11349 (or $x11347 d_34_1)))
 (let (($x11351 (or $x11349 d_34_2)))
 (let (($x11353 (or $x11351 d_34_3)))
 (let (($x11355 (or $x11353 d_34_4)))
 (let (($x11357 (or $x11355 d_34_5)))
 (let (($x11359 (or $x11357 d_34_6)))
 (let (($x11361 (or $x11359 d_34_7)))
 (or $x11361 d_34_8))))))))))
(assert
 (not (and d_34_0 d_34_1)))
(assert
 (not (and d_34_0 d_34_2)))
(assert
 (not (and d_34_0 d_34_3)))
(assert
 (not (and d_34_0 d_34_4)))
(assert
 (not (and d_34_0 d_34_5)))
(assert
 (not (and d_34_0 d_34_6)))
(assert
 (not (and d_34_0 d_34_7)))
(assert
 (not (and d_34_0 d_34_8)))
(assert
 (not (and d_34_1 d_34_2)))
(assert
 (not (and d_34_1 d_34_3)))
(assert
 (not (and d_34_1 d_34_4)))
(assert
 (not (and d_34_1 d_34_5)))
(assert
 (not (and d_34_1 d_34_6)))
(assert
 (not (and d_34_1 d_34_7)))
(assert
 (not (and d_34_1 d_34_8)))
(assert
 (not (and d_34_2 d_34_3)))
(assert
 (not (and d_34_2 d_34_4)))
(assert
 (not (and d_34_2 d_34_5)))
(assert
 (not (and d_34_2 d_34_6)))
(assert
 (not (and d_34_2 d_34_7)))
(assert
 (not (and d_34_2 d_34_8)))
(assert
 (not (and d_34_3 d_34_4)))
(assert
 (not (and d_34_3 d_34_5)))
(assert
 (not (and d_34_3 d_34_6)))
(assert
 (not (and d_34_3 d_34_7)))
(assert
 (not (and d_34_3 d_34_8)))
(assert
 (not (and d_34_4 d_34_5)))
(assert
 (not (and d_34_4 d_34_6)))
(assert
 (not (and d_34_4 d_34_7)))
(assert
 (not (and d_34_4 d_34_8)))
(assert
 (not (and d_34_5 d_34_6)))
(assert
 (not (and d_34_5 d_34_7)))
(assert
 (not (and d_34_5 d_34_8)))
(assert
 (not (and d_34_6 d_34_7)))
(assert
 (not (and d_34_6 d_34_8)))
(assert
 (not (and d_34_7 d_34_8)))
(assert
 (let (($x11437 (or false d_35_0)))
 (let (($x11439 (or $x11437 d_35_1)))
 (let (($x11441 (or $x11439 d_35_2)))
 (let (($x11443 (or $x11441 d_35_3)))
 (let (($x11445 (or $x11443 d_35_4)))
 (let (($x11447 (or $x11445 d_35_5)))
 (let (($x11449 (or $x11447 d_35_6)))
 (let (($x11451 (or $x11449 d_35_7)))
 (or $x11451 d_35_8))))))))))
(assert
 (not (and d_35_0 d_35_1)))
(assert
 (not (and d_35_0 d_35_2)))
(assert
 (not (and d_35_0 d_35_3)))
(assert
 (not (and d_35_0 d_35_4)))
(assert
 (not (and d_35_0 d_35_5)))
(assert
 (not (and d_35_0 d_35_6)))
(assert
 (not (and d_35_0 d_35_7)))
(assert
 (not (and d_35_0 d_35_8)))
(assert
 (not (and d_35_1 d_35_2)))
(assert
 (not (and d_35_1 d_35_3)))
(assert
 (not (and d_35_1 d_35_4)))
(assert
 (not (and d_35_1 d_35_5)))
(assert
 (not (and d_35_1 d_35_6)))
(assert
 (not (and d_35_1 d_35_7)))
(assert
 (not (and d_35_1 d_35_8)))
(assert
 (not (and d_35_2 d_35_3)))
(assert
 (not (and d_35_2 d_35_4)))
(assert
 (not (and d_35_2 d_35_5)))
(assert
 (not (and d_35_2 d_35_6)))
(assert
 (not (and d_35_2 d_35_7)))
(assert
 (not (and d_35_2 d_35_8)))
(assert
 (not (and d_35_3 d_35_4)))
(assert
 (not (and d_35_3 d_35_5)))
(assert
 (not (and d_35_3 d_35_6)))
(assert
 (not (and d_35_3 d_35_7)))
(assert
 (not (and d_35_3 d_35_8)))
(assert
 (not (and d_35_4 d_35_5)))
(assert
 (not (and d_35_4 d_35_6)))
(assert
 (not (and d_35_4 d_35_7)))
(assert
 (not (and d_35_4 d_35_8)))
(assert
 (not (and d_35_5 d_35_6)))
(assert
 (not (and d_35_5 d_35_7)))
(assert
 (not (and d_35_5 d_35_8)))
(assert
 (not (and d_35_6 d_35_7)))
(assert
 (not (and d_35_6 d_35_8)))
(assert
 (not (and d_35_7 d_35_8)))
(assert
 (let (($x11527 (or false d_36_0)))
 (let (($x11529 (or $x11527 d_36_1)))
 (let (($x11531 (or $x11529 d_36_2)))
 (let (($x11533 (or $x11531 d_36_3)))
 (let (($x11535 (or $x11533 d_36_4)))
 (let (($x11537 (or $x11535 d_36_5)))
 (let (($x11539 (or $x11537 d_36_6)))
 (let (($x11541 (or $x11539 d_36_7)))
 (or $x11541 d_36_8))))))))))
(assert
 (not (and d_36_0 d_36_1)))
(assert
 (not (and d_36_0 d_36_2)))
(assert
 (not (and d_36_0 d_36_3)))
(assert
 (not (and d_36_0 d_36_4)))
(assert
 (not (and d_36_0 d_36_5)))
(assert
 (not (and d_36_0 d_36_6)))
(assert
 (not (and d_36_0 d_36_7)))
(assert
 (not (and d_36_0 d_36_8)))
(assert
 (not (and d_36_1 d_36_2)))
(assert
 (not (and d_36_1 d_36_3)))
(assert
 (not (and d_36_1 d_36_4)))
(assert
 (not (and d_36_1 d_36_5)))
(assert
 (not (and d_36_1 d_36_6)))
(assert
 (not (and d_36_1 d_36_7)))
(assert
 (not (and d_36_1 d_36_8)))
(assert
 (not (and d_36_2 d_36_3)))
(assert
 (not (and d_36_2 d_36_4)))
(assert
 (not (and d_36_2 d_36_5)))
(assert
 (not (and d_36_2 d_36_6)))
(assert
 (not (and d_36_2 d_36_7)))
(assert
 (not (and d_36_2 d_36_8)))
(assert
 (not (and d_36_3 d_36_4)))
(assert
 (not (and d_36_3 d_36_5)))
(assert
 (not (and d_36_3 d_36_6)))
(assert
 (not (and d_36_3 d_36_7)))
(assert
 (not (and d_36_3 d_36_8)))
(assert
 (not (and d_36_4 d_36_5)))
(assert
 (not (and d_36_4 d_36_6)))
(assert
 (not (and d_36_4 d_36_7)))
(assert
 (not (and d_36_4 d_36_8)))
(assert
 (not (and d_36_5 d_36_6)))
(assert
 (not (and d_36_5 d_36_7)))
(assert
 (not (and d_36_5 d_36_8)))
(assert
 (not (and d_36_6 d_36_7)))
(assert
 (not (and d_36_6 d_36_8)))
(assert
 (not (and d_36_7 d_36_8)))
(assert
 (let (($x11617 (or false d_37_0)))
 (let (($x11619 (or $x11617 d_37_1)))
 (let (($x11621 (or $x11619 d_37_2)))
 (let (($x11623 (or $x11621 d_37_3)))
 (let (($x11625 (or $x11623 d_37_4)))
 (let (($x11627 (or $x11625 d_37_5)))
 (let (($x11629 (or $x11627 d_37_6)))
 (let (($x11631 (or $x11629 d_37_7)))
 (or $x11631 d_37_8))))))))))
(assert
 (not (and d_37_0 d_37_1)))
(assert
 (not (and d_37_0 d_37_2)))
(assert
 (not (and d_37_0 d_37_3)))
(assert
 (not (and d_37_0 d_37_4)))
(assert
 (not (and d_37_0 d_37_5)))
(assert
 (not (and d_37_0 d_37_6)))
(assert
 (not (and d_37_0 d_37_7)))
(assert
 (not (and d_37_0 d_37_8)))
(assert
 (not (and d_37_1 d_37_2)))
(assert
 (not (and d_37_1 d_37_3)))
(assert
 (not (and d_37_1 d_37_4)))
(assert
 (not (and d_37_1 d_37_5)))
(assert
 (not (and d_37_1 d_37_6)))
(assert
 (not (and d_37_1 d_37_7)))
(assert
 (not (and d_37_1 d_37_8)))
(assert
 (not (and d_37_2 d_37_3)))
(assert
 (not (and d_37_2 d_37_4)))
(assert
 (not (and d_37_2 d_37_5)))
(assert
 (not (and d_37_2 d_37_6)))
(assert
 (not (and d_37_2 d_37_7)))
(assert
 (not (and d_37_2 d_37_8)))
(assert
 (not (and d_37_3 d_37_4)))
(assert
 (not (and d_37_3 d_37_5)))
(assert
 (not (and d_37_3 d_37_6)))
(assert
 (not (and d_37_3 d_37_7)))
(assert
 (not (and d_37_3 d_37_8)))
(assert
 (not (and d_37_4 d_37_5)))
(assert
 (not (and d_37_4 d_37_6)))
(assert
 (not (and d_37_4 d_37_7)))
(assert
 (not (and d_37_4 d_37_8)))
(assert
 (not (and d_37_5 d_37_6)))
(assert
 (not (and d_37_5 d_37_7)))
(assert
 (not (and d_37_5 d_37_8)))
(assert
 (not (and d_37_6 d_37_7)))
(assert
 (not (and d_37_6 d_37_8)))
(assert
 (not (and d_37_7 d_37_8)))
(assert
 (let (($x11707 (or false d_38_0)))
 (let (($x11709 (or $x11707 d_38_1)))
 (let (($x11711 (or $x11709 d_38_2)))
 (let (($x11713 (or $x11711 d_38_3)))
 (let (($x11715 (or $x11713 d_38_4)))
 (let (($x11717 (or $x11715 d_38_5)))
 (let (($x11719 (or $x11717 d_38_6)))
 (let (($x11721 (or $x11719 d_38_7)))
 (or $x11721 d_38_8))))))))))
(assert
 (not (and d_38_0 d_38_1)))
(assert
 (not (and d_38_0 d_38_2)))
(assert
 (not (and d_38_0 d_38_3)))
(assert
 (not (and d_38_0 d_38_4)))
(assert
 (not (and d_38_0 d_38_5)))
(assert
 (not (and d_38_0 d_38_6)))
(assert
 (not (and d_38_0 d_38_7)))
(assert
 (not (and d_38_0 d_38_8)))
(assert
 (not (and d_38_1 d_38_2)))
(assert
 (not (and d_38_1 d_38_3)))
(assert
 (not (and d_38_1 d_38_4)))
(assert
 (not (and d_38_1 d_38_5)))
(assert
 (not (and d_38_1 d_38_6)))
(assert
 (not (and d_38_1 d_38_7)))
(assert
 (not (and d_38_1 d_38_8)))
(assert
 (not (and d_38_2 d_38_3)))
(assert
 (not (and d_38_2 d_38_4)))
(assert
 (not (and d_38_2 d_38_5)))
(assert
 (not (and d_38_2 d_38_6)))
(assert
 (not (and d_38_2 d_38_7)))
(assert
 (not (and d_38_2 d_38_8)))
(assert
 (not (and d_38_3 d_38_4)))
(assert
 (not (and d_38_3 d_38_5)))
(assert
 (not (and d_38_3 d_38_6)))
(assert
 (not (and d_38_3 d_38_7)))
(assert
 (not (and d_38_3 d_38_8)))
(assert
 (not (and d_38_4 d_38_5)))
(assert
 (not (and d_38_4 d_38_6)))
(assert
 (not (and d_38_4 d_38_7)))
(assert
 (not (and d_38_4 d_38_8)))
(assert
 (not (and d_38_5 d_38_6)))
(assert
 (not (and d_38_5 d_38_7)))
(assert
 (not (and d_38_5 d_38_8)))
(assert
 (not (and d_38_6 d_38_7)))
(assert
 (not (and d_38_6 d_38_8)))
(assert
 (not (and d_38_7 d_38_8)))
(assert
 (let (($x11797 (or false d_39_0)))
 (let (($x11799 (or $x11797 d_39_1)))
 (let (($x11801 (or $x11799 d_39_2)))
 (let (($x11803 (or $x11801 d_39_3)))
 (let (($x11805 (or $x11803 d_39_4)))
 (let (($x11807 (or $x11805 d_39_5)))
 (let (($x11809 (or $x11807 d_39_6)))
 (let (($x11811 (or $x11809 d_39_7)))
 (or $x11811 d_39_8))))))))))
(assert
 (not (and d_39_0 d_39_1)))
(assert
 (not (and d_39_0 d_39_2)))
(assert
 (not (and d_39_0 d_39_3)))
(assert
 (not (and d_39_0 d_39_4)))
(assert
 (not (and d_39_0 d_39_5)))
(assert
 (not (and d_39_0 d_39_6)))
(assert
 (not (and d_39_0 d_39_7)))
(assert
 (not (and d_39_0 d_39_8)))
(assert
 (not (and d_39_1 d_39_2)))
(assert
 (not (and d_39_1 d_39_3)))
(assert
 (not (and d_39_1 d_39_4)))
(assert
 (not (and d_39_1 d_39_5)))
(assert
 (not (and d_39_1 d_39_6)))
(assert
 (not (and d_39_1 d_39_7)))
(assert
 (not (and d_39_1 d_39_8)))
(assert
 (not (and d_39_2 d_39_3)))
(assert
 (not (and d_39_2 d_39_4)))
(assert
 (not (and d_39_2 d_39_5)))
(assert
 (not (and d_39_2 d_39_6)))
(assert
 (not (and d_39_2 d_39_7)))
(assert
 (not (and d_39_2 d_39_8)))
(assert
 (not (and d_39_3 d_39_4)))
(assert
 (not (and d_39_3 d_39_5)))
(assert
 (not (and d_39_3 d_39_6)))
(assert
 (not (and d_39_3 d_39_7)))
(assert
 (not (and d_39_3 d_39_8)))
(assert
 (not (and d_39_4 d_39_5)))
(assert
 (not (and d_39_4 d_39_6)))
(assert
 (not (and d_39_4 d_39_7)))
(assert
 (not (and d_39_4 d_39_8)))
(assert
 (not (and d_39_5 d_39_6)))
(assert
 (not (and d_39_5 d_39_7)))
(assert
 (not (and d_39_5 d_39_8)))
(assert
 (not (and d_39_6 d_39_7)))
(assert
 (not (and d_39_6 d_39_8)))
(assert
 (not (and d_39_7 d_39_8)))
(assert
 (let (($x11887 (or false d_40_0)))
 (let (($x11889 (or $x11887 d_40_1)))
 (let (($x11891 (or $x11889 d_40_2)))
 (let (($x11893 (or $x11891 d_40_3)))
 (let (($x11895 (or $x11893 d_40_4)))
 (let (($x11897 (or $x11895 d_40_5)))
 (let (($x11899 (or $x11897 d_40_6)))
 (let (($x11901 (or $x11899 d_40_7)))
 (or $x11901 d_40_8))))))))))
(assert
 (not (and d_40_0 d_40_1)))
(assert
 (not (and d_40_0 d_40_2)))
(assert
 (not (and d_40_0 d_40_3)))
(assert
 (not (and d_40_0 d_40_4)))
(assert
 (not (and d_40_0 d_40_5)))
(assert
 (not (and d_40_0 d_40_6)))
(assert
 (not (and d_40_0 d_40_7)))
(assert
 (not (and d_40_0 d_40_8)))
(assert
 (not (and d_40_1 d_40_2)))
(assert
 (not (and d_40_1 d_40_3)))
(assert
 (not (and d_40_1 d_40_4)))
(assert
 (not (and d_40_1 d_40_5)))
(assert
 (not (and d_40_1 d_40_6)))
(assert
 (not (and d_40_1 d_40_7)))
(assert
 (not (and d_40_1 d_40_8)))
(assert
 (not (and d_40_2 d_40_3)))
(assert
 (not (and d_40_2 d_40_4)))
(assert
 (not (and d_40_2 d_40_5)))
(assert
 (not (and d_40_2 d_40_6)))
(assert
 (not (and d_40_2 d_40_7)))
(assert
 (not (and d_40_2 d_40_8)))
(assert
 (not (and d_40_3 d_40_4)))
(assert
 (not (and d_40_3 d_40_5)))
(assert
 (not (and d_40_3 d_40_6)))
(assert
 (not (and d_40_3 d_40_7)))
(assert
 (not (and d_40_3 d_40_8)))
(assert
 (not (and d_40_4 d_40_5)))
(assert
 (not (and d_40_4 d_40_6)))
(assert
 (not (and d_40_4 d_40_7)))
(assert
 (not (and d_40_4 d_40_8)))
(assert
 (not (and d_40_5 d_40_6)))
(assert
 (not (and d_40_5 d_40_7)))
(assert
 (not (and d_40_5 d_40_8)))
(assert
 (not (and d_40_6 d_40_7)))
(assert
 (not (and d_40_6 d_40_8)))
(assert
 (not (and d_40_7 d_40_8)))
(assert
 (let (($x11977 (or false d_41_0)))
 (let (($x11979 (or $x11977 d_41_1)))
 (let (($x11981 (or $x11979 d_41_2)))
 (let (($x11983 (or $x11981 d_41_3)))
 (let (($x11985 (or $x11983 d_41_4)))
 (let (($x11987 (or $x11985 d_41_5)))
 (let (($x11989 (or $x11987 d_41_6)))
 (let (($x11991 (or $x11989 d_41_7)))
 (or $x11991 d_41_8))))))))))
(assert
 (not (and d_41_0 d_41_1)))
(assert
 (not (and d_41_0 d_41_2)))
(assert
 (not (and d_41_0 d_41_3)))
(assert
 (not (and d_41_0 d_41_4)))
(assert
 (not (and d_41_0 d_41_5)))
(assert
 (not (and d_41_0 d_41_6)))
(assert
 (not (and d_41_0 d_41_7)))
(assert
 (not (and d_41_0 d_41_8)))
(assert
 (not (and d_41_1 d_41_2)))
(assert
 (not (and d_41_1 d_41_3)))
(assert
 (not (and d_41_1 d_41_4)))
(assert
 (not (and d_41_1 d_41_5)))
(assert
 (not (and d_41_1 d_41_6)))
(assert
 (not (and d_41_1 d_41_7)))
(assert
 (not (and d_41_1 d_41_8)))
(assert
 (not (and d_41_2 d_41_3)))
(assert
 (not (and d_41_2 d_41_4)))
(assert
 (not (and d_41_2 d_41_5)))
(assert
 (not (and d_41_2 d_41_6)))
(assert
 (not (and d_41_2 d_41_7)))
(assert
 (not (and d_41_2 d_41_8)))
(assert
 (not (and d_41_3 d_41_4)))
(assert
 (not (and d_41_3 d_41_5)))
(assert
 (not (and d_41_3 d_41_6)))
(assert
 (not (and d_41_3 d_41_7)))
(assert
 (not (and d_41_3 d_41_8)))
(assert
 (not (and d_41_4 d_41_5)))
(assert
 (not (and d_41_4 d_41_6)))
(assert
 (not (and d_41_4 d_41_7)))
(assert
 (not (and d_41_4 d_41_8)))
(assert
 (not (and d_41_5 d_41_6)))
(assert
 (not (and d_41_5 d_41_7)))
(assert
 (not (and d_41_5 d_41_8)))
(assert
 (not (and d_41_6 d_41_7)))
(assert
 (not (and d_41_6 d_41_8)))
(assert
 (not (and d_41_7 d_41_8)))
(assert
 (let (($x12067 (or false d_42_0)))
 (let (($x12069 (or $x12067 d_42_1)))
 (let (($x12071 (or $x12069 d_42_2)))
 (let (($x12073 (or $x12071 d_42_3)))
 (let (($x12075 (or $x12073 d_42_4)))
 (let (($x12077 (or $x12075 d_42_5)))
 (let (($x12079 (or $x12077 d_42_6)))
 (let (($x12081 (or $x12079 d_42_7)))
 (or $x12081 d_42_8))))))))))
(assert
 (not (and d_42_0 d_42_1)))
(assert
 (not (and d_42_0 d_42_2)))
(assert
 (not (and d_42_0 d_42_3)))
(assert
 (not (and d_42_0 d_42_4)))
(assert
 (not (and d_42_0 d_42_5)))
(assert
 (not (and d_42_0 d_42_6)))
(assert
 (not (and d_42_0 d_42_7)))
(assert
 (not (and d_42_0 d_42_8)))
(assert
 (not (and d_42_1 d_42_2)))
(assert
 (not (and d_42_1 d_42_3)))
(assert
 (not (and d_42_1 d_42_4)))
(assert
 (not (and d_42_1 d_42_5)))
(assert
 (not (and d_42_1 d_42_6)))
(assert
 (not (and d_42_1 d_42_7)))
(assert
 (not (and d_42_1 d_42_8)))
(assert
 (not (and d_42_2 d_42_3)))
(assert
 (not (and d_42_2 d_42_4)))
(assert
 (not (and d_42_2 d_42_5)))
(assert
 (not (and d_42_2 d_42_6)))
(assert
 (not (and d_42_2 d_42_7)))
(assert
 (not (and d_42_2 d_42_8)))
(assert
 (not (and d_42_3 d_42_4)))
(assert
 (not (and d_42_3 d_42_5)))
(assert
 (not (and d_42_3 d_42_6)))
(assert
 (not (and d_42_3 d_42_7)))
(assert
 (not (and d_42_3 d_42_8)))
(assert
 (not (and d_42_4 d_42_5)))
(assert
 (not (and d_42_4 d_42_6)))
(assert
 (not (and d_42_4 d_42_7)))
(assert
 (not (and d_42_4 d_42_8)))
(assert
 (not (and d_42_5 d_42_6)))
(assert
 (not (and d_42_5 d_42_7)))
(assert
 (not (and d_42_5 d_42_8)))
(assert
 (not (and d_42_6 d_42_7)))
(assert
 (not (and d_42_6 d_42_8)))
(assert
 (not (and d_42_7 d_42_8)))
(assert
 (let (($x12157 (or false d_43_0)))
 (let (($x12159 (or $x12157 d_43_1)))
 (let (($x12161 (or $x12159 d_43_2)))
 (let (($x12163 (or $x12161 d_43_3)))
 (let (($x12165 (or $x12163 d_43_4)))
 (let (($x12167 (or $x12165 d_43_5)))
 (let (($x12169 (or $x12167 d_43_6)))
 (let (($x12171 (or $x12169 d_43_7)))
 (or $x12171 d_43_8))))))))))
(assert
 (not (and d_43_0 d_43_1)))
(assert
 (not (and d_43_0 d_43_2)))
(assert
 (not (and d_43_0 d_43_3)))
(assert
 (not (and d_43_0 d_43_4)))
(assert
 (not (and d_43_0 d_43_5)))
(assert
 (not (and d_43_0 d_43_6)))
(assert
 (not (and d_43_0 d_43_7)))
(assert
 (not (and d_43_0 d_43_8)))
(assert
 (not (and d_43_1 d_43_2)))
(assert
 (not (and d_43_1 d_43_3)))
(assert
 (not (and d_43_1 d_43_4)))
(assert
 (not (and d_43_1 d_43_5)))
(assert
 (not (and d_43_1 d_43_6)))
(assert
 (not (and d_43_1 d_43_7)))
(assert
 (not (and d_43_1 d_43_8)))
(assert
 (not (and d_43_2 d_43_3)))
(assert
 (not (and d_43_2 d_43_4)))
(assert
 (not (and d_43_2 d_43_5)))
(assert
 (not (and d_43_2 d_43_6)))
(assert
 (not (and d_43_2 d_43_7)))
(assert
 (not (and d_43_2 d_43_8)))
(assert
 (not (and d_43_3 d_43_4)))
(assert
 (not (and d_43_3 d_43_5)))
(assert
 (not (and d_43_3 d_43_6)))
(assert
 (not (and d_43_3 d_43_7)))
(assert
 (not (and d_43_3 d_43_8)))
(assert
 (not (and d_43_4 d_43_5)))
(assert
 (not (and d_43_4 d_43_6)))
(assert
 (not (and d_43_4 d_43_7)))
(assert
 (not (and d_43_4 d_43_8)))
(assert
 (not (and d_43_5 d_43_6)))
(assert
 (not (and d_43_5 d_43_7)))
(assert
 (not (and d_43_5 d_43_8)))
(assert
 (not (and d_43_6 d_43_7)))
(assert
 (not (and d_43_6 d_43_8)))
(assert
 (not (and d_43_7 d_43_8)))
(assert
 (let (($x12247 (or false d_44_0)))
 (let (($x12249 (or $x12247 d_44_1)))
 (let (($x12251 (or $x12249 d_44_2)))
 (let (($x12253 (or $x12251 d_44_3)))
 (let (($x12255 (or $x12253 d_44_4)))
 (let (($x12257 (or $x12255 d_44_5)))
 (let (($x12259 (or $x12257 d_44_6)))
 (let (($x12261 (or $x12259 d_44_7)))
 (or $x12261 d_44_8))))))))))
(assert
 (not (and d_44_0 d_44_1)))
(assert
 (not (and d_44_0 d_44_2)))
(assert
 (not (and d_44_0 d_44_3)))
(assert
 (not (and d_44_0 d_44_4)))
(assert
 (not (and d_44_0 d_44_5)))
(assert
 (not (and d_44_0 d_44_6)))
(assert
 (not (and d_44_0 d_44_7)))
(assert
 (not (and d_44_0 d_44_8)))
(assert
 (not (and d_44_1 d_44_2)))
(assert
 (not (and d_44_1 d_44_3)))
(assert
 (not (and d_44_1 d_44_4)))
(assert
 (not (and d_44_1 d_44_5)))
(assert
 (not (and d_44_1 d_44_6)))
(assert
 (not (and d_44_1 d_44_7)))
(assert
 (not (and d_44_1 d_44_8)))
(assert
 (not (and d_44_2 d_44_3)))
(assert
 (not (and d_44_2 d_44_4)))
(assert
 (not (and d_44_2 d_44_5)))
(assert
 (not (and d_44_2 d_44_6)))
(assert
 (not (and d_44_2 d_44_7)))
(assert
 (not (and d_44_2 d_44_8)))
(assert
 (not (and d_44_3 d_44_4)))
(assert
 (not (and d_44_3 d_44_5)))
(assert
 (not (and d_44_3 d_44_6)))
(assert
 (not (and d_44_3 d_44_7)))
(assert
 (not (and d_44_3 d_44_8)))
(assert
 (not (and d_44_4 d_44_5)))
(assert
 (not (and d_44_4 d_44_6)))
(assert
 (not (and d_44_4 d_44_7)))
(assert
 (not (and d_44_4 d_44_8)))
(assert
 (not (and d_44_5 d_44_6)))
(assert
 (not (and d_44_5 d_44_7)))
(assert
 (not (and d_44_5 d_44_8)))
(assert
 (not (and d_44_6 d_44_7)))
(assert
 (not (and d_44_6 d_44_8)))
(assert
 (not (and d_44_7 d_44_8)))
(assert
 (let (($x12337 (or false d_45_0)))
 (let (($x12339 (or $x12337 d_45_1)))
 (let (($x12341 (or $x12339 d_45_2)))
 (let (($x12343 (or $x12341 d_45_3)))
 (let (($x12345 (or $x12343 d_45_4)))
 (let (($x12347 (or $x12345 d_45_5)))
 (let (($x12349 (or $x12347 d_45_6)))
 (let (($x12351 (or $x12349 d_45_7)))
 (or $x12351 d_45_8))))))))))
(assert
 (not (and d_45_0 d_45_1)))
(assert
 (not (and d_45_0 d_45_2)))
(assert
 (not (and d_45_0 d_45_3)))
(assert
 (not (and d_45_0 d_45_4)))
(assert
 (not (and d_45_0 d_45_5)))
(assert
 (not (and d_45_0 d_45_6)))
(assert
 (not (and d_45_0 d_45_7)))
(assert
 (not (and d_45_0 d_45_8)))
(assert
 (not (and d_45_1 d_45_2)))
(assert
 (not (and d_45_1 d_45_3)))
(assert
 (not (and d_45_1 d_45_4)))
(assert
 (not (and d_45_1 d_45_5)))
(assert
 (not (and d_45_1 d_45_6)))
(assert
 (not (and d_45_1 d_45_7)))
(assert
 (not (and d_45_1 d_45_8)))
(assert
 (not (and d_45_2 d_45_3)))
(assert
 (not (and d_45_2 d_45_4)))
(assert
 (not (and d_45_2 d_45_5)))
(assert
 (not (and d_45_2 d_45_6)))
(assert
 (not (and d_45_2 d_45_7)))
(assert
 (not (and d_45_2 d_45_8)))
(assert
 (not (and d_45_3 d_45_4)))
(assert
 (not (and d_45_3 d_45_5)))
(assert
 (not (and d_45_3 d_45_6)))
(assert
 (not (and d_45_3 d_45_7)))
(assert
 (not (and d_45_3 d_45_8)))
(assert
 (not (and d_45_4 d_45_5)))
(assert
 (not (and d_45_4 d_45_6)))
(assert
 (not (and d_45_4 d_45_7)))
(assert
 (not (and d_45_4 d_45_8)))
(assert
 (not (and d_45_5 d_45_6)))
(assert
 (not (and d_45_5 d_45_7)))
(assert
 (not (and d_45_5 d_45_8)))
(assert
 (not (and d_45_6 d_45_7)))
(assert
 (not (and d_45_6 d_45_8)))
(assert
 (not (and d_45_7 d_45_8)))
(assert
 (let (($x12427 (or false d_46_0)))
 (let (($x12429 (or $x12427 d_46_1)))
 (let (($x12431 (or $x12429 d_46_2)))
 (let (($x12433 (or $x12431 d_46_3)))
 (let (($x12435 (or $x12433 d_46_4)))
 (let (($x12437 (or $x12435 d_46_5)))
 (let (($x12439 (or $x12437 d_46_6)))
 (let (($x12441 (or $x12439 d_46_7)))
 (or $x12441 d_46_8))))))))))
(assert
 (not (and d_46_0 d_46_1)))
(assert
 (not (and d_46_0 d_46_2)))
(assert
 (not (and d_46_0 d_46_3)))
(assert
 (not (and d_46_0 d_46_4)))
(assert
 (not (and d_46_0 d_46_5)))
(assert
 (not (and d_46_0 d_46_6)))
(assert
 (not (and d_46_0 d_46_7)))
(assert
 (not (and d_46_0 d_46_8)))
(assert
 (not (and d_46_1 d_46_2)))
(assert
 (not (and d_46_1 d_46_3)))
(assert
 (not (and d_46_1 d_46_4)))
(assert
 (not (and d_46_1 d_46_5)))
(assert
 (not (and d_46_1 d_46_6)))
(assert
 (not (and d_46_1 d_46_7)))
(assert
 (not (and d_46_1 d_46_8)))
(assert
 (not (and d_46_2 d_46_3)))
(assert
 (not (and d_46_2 d_46_4)))
(assert
 (not (and d_46_2 d_46_5)))
(assert
 (not (and d_46_2 d_46_6)))
(assert
 (not (and d_46_2 d_46_7)))
(assert
 (not (and d_46_2 d_46_8)))
(assert
 (not (and d_46_3 d_46_4)))
(assert
 (not (and d_46_3 d_46_5)))
(assert
 (not (and d_46_3 d_46_6)))
(assert
 (not (and d_46_3 d_46_7)))
(assert
 (not (and d_46_3 d_46_8)))
(assert
 (not (and d_46_4 d_46_5)))
(assert
 (not (and d_46_4 d_46_6)))
(assert
 (not (and d_46_4 d_46_7)))
(assert
 (not (and d_46_4 d_46_8)))
(assert
 (not (and d_46_5 d_46_6)))
(assert
 (not (and d_46_5 d_46_7)))
(assert
 (not (and d_46_5 d_46_8)))
(assert
 (not (and d_46_6 d_46_7)))
(assert
 (not (and d_46_6 d_46_8)))
(assert
 (not (and d_46_7 d_46_8)))
(assert
 (let (($x12517 (or false d_47_0)))
 (let (($x12519 (or $x12517 d_47_1)))
 (let (($x12521 (or $x12519 d_47_2)))
 (let (($x12523 (or $x12521 d_47_3)))
 (let (($x12525 (or $x12523 d_47_4)))
 (let (($x12527 (or $x12525 d_47_5)))
 (let (($x12529 (or $x12527 d_47_6)))
 (let (($x12531 (or $x12529 d_47_7)))
 (or $x12531 d_47_8))))))))))
(assert
 (not (and d_47_0 d_47_1)))
(assert
 (not (and d_47_0 d_47_2)))
(assert
 (not (and d_47_0 d_47_3)))
(assert
 (not (and d_47_0 d_47_4)))
(assert
 (not (and d_47_0 d_47_5)))
(assert
 (not (and d_47_0 d_47_6)))
(assert
 (not (and d_47_0 d_47_7)))
(assert
 (not (and d_47_0 d_47_8)))
(assert
 (not (and d_47_1 d_47_2)))
(assert
 (not (and d_47_1 d_47_3)))
(assert
 (not (and d_47_1 d_47_4)))
(assert
 (not (and d_47_1 d_47_5)))
(assert
 (not (and d_47_1 d_47_6)))
(assert
 (not (and d_47_1 d_47_7)))
(assert
 (not (and d_47_1 d_47_8)))
(assert
 (not (and d_47_2 d_47_3)))
(assert
 (not (and d_47_2 d_47_4)))
(assert
 (not (and d_47_2 d_47_5)))
(assert
 (not (and d_47_2 d_47_6)))
(assert
 (not (and d_47_2 d_47_7)))
(assert
 (not (and d_47_2 d_47_8)))
(assert
 (not (and d_47_3 d_47_4)))
(assert
 (not (and d_47_3 d_47_5)))
(assert
 (not (and d_47_3 d_47_6)))
(assert
 (not (and d_47_3 d_47_7)))
(assert
 (not (and d_47_3 d_47_8)))
(assert
 (not (and d_47_4 d_47_5)))
(assert
 (not (and d_47_4 d_47_6)))
(assert
 (not (and d_47_4 d_47_7)))
(assert
 (not (and d_47_4 d_47_8)))
(assert
 (not (and d_47_5 d_47_6)))
(assert
 (not (and d_47_5 d_47_7)))
(assert
 (not (and d_47_5 d_47_8)))
(assert
 (not (and d_47_6 d_47_7)))
(assert
 (not (and d_47_6 d_47_8)))
(assert
 (not (and d_47_7 d_47_8)))
(assert
 (let (($x12607 (or false d_48_0)))
 (let (($x12609 (or $x12607 d_48_1)))
 (let (($x12611 (or $x12609 d_48_2)))
 (let (($x12613 (or $x12611 d_48_3)))
 (let (($x12615 (or $x12613 d_48_4)))
 (let (($x12617 (or $x12615 d_48_5)))
 (let (($x12619 (or $x12617 d_48_6)))
 (let (($x12621 (or $x12619 d_48_7)))
 (or $x12621 d_48_8))))))))))
(assert
 (not (and d_48_0 d_48_1)))
(assert
 (not (and d_48_0 d_48_2)))
(assert
 (not (and d_48_0 d_48_3)))
(assert
 (not (and d_48_0 d_48_4)))
(assert
 (not (and d_48_0 d_48_5)))
(assert
 (not (and d_48_0 d_48_6)))
(assert
 (not (and d_48_0 d_48_7)))
(assert
 (not (and d_48_0 d_48_8)))
(assert
 (not (and d_48_1 d_48_2)))
(assert
 (not (and d_48_1 d_48_3)))
(assert
 (not (and d_48_1 d_48_4)))
(assert
 (not (and d_48_1 d_48_5)))
(assert
 (not (and d_48_1 d_48_6)))
(assert
 (not (and d_48_1 d_48_7)))
(assert
 (not (and d_48_1 d_48_8)))
(assert
 (not (and d_48_2 d_48_3)))
(assert
 (not (and d_48_2 d_48_4)))
(assert
 (not (and d_48_2 d_48_5)))
(assert
 (not (and d_48_2 d_48_6)))
(assert
 (not (and d_48_2 d_48_7)))
(assert
 (not (and d_48_2 d_48_8)))
(assert
 (not (and d_48_3 d_48_4)))
(assert
 (not (and d_48_3 d_48_5)))
(assert
 (not (and d_48_3 d_48_6)))
(assert
 (not (and d_48_3 d_48_7)))
(assert
 (not (and d_48_3 d_48_8)))
(assert
 (not (and d_48_4 d_48_5)))
(assert
 (not (and d_48_4 d_48_6)))
(assert
 (not (and d_48_4 d_48_7)))
(assert
 (not (and d_48_4 d_48_8)))
(assert
 (not (and d_48_5 d_48_6)))
(assert
 (not (and d_48_5 d_48_7)))
(assert
 (not (and d_48_5 d_48_8)))
(assert
 (not (and d_48_6 d_48_7)))
(assert
 (not (and d_48_6 d_48_8)))
(assert
 (not (and d_48_7 d_48_8)))
(assert
 (let (($x12697 (or false d_49_0)))
 (let (($x12699 (or $x12697 d_49_1)))
 (let (($x12701 (or $x12699 d_49_2)))
 (let (($x12703 (or $x12701 d_49_3)))
 (let (($x12705 (or $x12703 d_49_4)))
 (let (($x12707 (or $x12705 d_49_5)))
 (let (($x12709 (or $x12707 d_49_6)))
 (let (($x12711 (or $x12709 d_49_7)))
 (or $x12711 d_49_8))))))))))
(assert
 (not (and d_49_0 d_49_1)))
(assert
 (not (and d_49_0 d_49_2)))
(assert
 (not (and d_49_0 d_49_3)))
(assert
 (not (and d_49_0 d_49_4)))
(assert
 (not (and d_49_0 d_49_5)))
(assert
 (not (and d_49_0 d_49_6)))
(assert
 (not (and d_49_0 d_49_7)))
(assert
 (not (and d_49_0 d_49_8)))
(assert
 (not (and d_49_1 d_49_2)))
(assert
 (not (and d_49_1 d_49_3)))
(assert
 (not (and d_49_1 d_49_4)))
(assert
 (not (and d_49_1 d_49_5)))
(assert
 (not (and d_49_1 d_49_6)))
(assert
 (not (and d_49_1 d_49_7)))
(assert
 (not (and d_49_1 d_49_8)))
(assert
 (not (and d_49_2 d_49_3)))
(assert
 (not (and d_49_2 d_49_4)))
(assert
 (not (and d_49_2 d_49_5)))
(assert
 (not (and d_49_2 d_49_6)))
(assert
 (not (and d_49_2 d_49_7)))
(assert
 (not (and d_49_2 d_49_8)))
(assert
 (not (and d_49_3 d_49_4)))
(assert
 (not (and d_49_3 d_49_5)))
(assert
 (not (and d_49_3 d_49_6)))
(assert
 (not (and d_49_3 d_49_7)))
(assert
 (not (and d_49_3 d_49_8)))
(assert
 (not (and d_49_4 d_49_5)))
(assert
 (not (and d_49_4 d_49_6)))
(assert
 (not (and d_49_4 d_49_7)))
(assert
 (not (and d_49_4 d_49_8)))
(assert
 (not (and d_49_5 d_49_6)))
(assert
 (not (and d_49_5 d_49_7)))
(assert
 (not (and d_49_5 d_49_8)))
(assert
 (not (and d_49_6 d_49_7)))
(assert
 (not (and d_49_6 d_49_8)))
(assert
 (not (and d_49_7 d_49_8)))
(assert
 (let (($x12787 (or false d_50_0)))
 (let (($x12789 (or $x12787 d_50_1)))
 (let (($x12791 (or $x12789 d_50_2)))
 (let (($x12793 (or $x12791 d_50_3)))
 (let (($x12795 (or $x12793 d_50_4)))
 (let (($x12797 (or $x12795 d_50_5)))
 (let (($x12799 (or $x12797 d_50_6)))
 (let (($x12801 (or $x12799 d_50_7)))
 (or $x12801 d_50_8))))))))))
(assert
 (not (and d_50_0 d_50_1)))
(assert
 (not (and d_50_0 d_50_2)))
(assert
 (not (and d_50_0 d_50_3)))
(assert
 (not (and d_50_0 d_50_4)))
(assert
 (not (and d_50_0 d_50_5)))
(assert
 (not (and d_50_0 d_50_6)))
(assert
 (not (and d_50_0 d_50_7)))
(assert
 (not (and d_50_0 d_50_8)))
(assert
 (not (and d_50_1 d_50_2)))
(assert
 (not (and d_50_1 d_50_3)))
(assert
 (not (and d_50_1 d_50_4)))
(assert
 (not (and d_50_1 d_50_5)))
(assert
 (not (and d_50_1 d_50_6)))
(assert
 (not (and d_50_1 d_50_7)))
(assert
 (not (and d_50_1 d_50_8)))
(assert
 (not (and d_50_2 d_50_3)))
(assert
 (not (and d_50_2 d_50_4)))
(assert
 (not (and d_50_2 d_50_5)))
(assert
 (not (and d_50_2 d_50_6)))
(assert
 (not (and d_50_2 d_50_7)))
(assert
 (not (and d_50_2 d_50_8)))
(assert
 (not (and d_50_3 d_50_4)))
(assert
 (not (and d_50_3 d_50_5)))
(assert
 (not (and d_50_3 d_50_6)))
(assert
 (not (and d_50_3 d_50_7)))
(assert
 (not (and d_50_3 d_50_8)))
(assert
 (not (and d_50_4 d_50_5)))
(assert
 (not (and d_50_4 d_50_6)))
(assert
 (not (and d_50_4 d_50_7)))
(assert
 (not (and d_50_4 d_50_8)))
(assert
 (not (and d_50_5 d_50_6)))
(assert
 (not (and d_50_5 d_50_7)))
(assert
 (not (and d_50_5 d_50_8)))
(assert
 (not (and d_50_6 d_50_7)))
(assert
 (not (and d_50_6 d_50_8)))
(assert
 (not (and d_50_7 d_50_8)))
(assert
 (let (($x12877 (or false d_51_0)))
 (let (($x12879 (or $x12877 d_51_1)))
 (let (($x12881 (or $x12879 d_51_2)))
 (let (($x12883 (or $x12881 d_51_3)))
 (let (($x12885 (or $x12883 d_51_4)))
 (let (($x12887 (or $x12885 d_51_5)))
 (let (($x12889 (or $x12887 d_51_6)))
 (let (($x12891 (or $x12889 d_51_7)))
 (or $x12891 d_51_8))))))))))
(assert
 (not (and d_51_0 d_51_1)))
(assert
 (not (and d_51_0 d_51_2)))
(assert
 (not (and d_51_0 d_51_3)))
(assert
 (not (and d_51_0 d_51_4)))
(assert
 (not (and d_51_0 d_51_5)))
(assert
 (not (and d_51_0 d_51_6)))
(assert
 (not (and d_51_0 d_51_7)))
(assert
 (not (and d_51_0 d_51_8)))
(assert
 (not (and d_51_1 d_51_2)))
(assert
 (not (and d_51_1 d_51_3)))
(assert
 (not (and d_51_1 d_51_4)))
(assert
 (not (and d_51_1 d_51_5)))
(assert
 (not (and d_51_1 d_51_6)))
(assert
 (not (and d_51_1 d_51_7)))
(assert
 (not (and d_51_1 d_51_8)))
(assert
 (not (and d_51_2 d_51_3)))
(assert
 (not (and d_51_2 d_51_4)))
(assert
 (not (and d_51_2 d_51_5)))
(assert
 (not (and d_51_2 d_51_6)))
(assert
 (not (and d_51_2 d_51_7)))
(assert
 (not (and d_51_2 d_51_8)))
(assert
 (not (and d_51_3 d_51_4)))
(assert
 (not (and d_51_3 d_51_5)))
(assert
 (not (and d_51_3 d_51_6)))
(assert
 (not (and d_51_3 d_51_7)))
(assert
 (not (and d_51_3 d_51_8)))
(assert
 (not (and d_51_4 d_51_5)))
(assert
 (not (and d_51_4 d_51_6)))
(assert
 (not (and d_51_4 d_51_7)))
(assert
 (not (and d_51_4 d_51_8)))
(assert
 (not (and d_51_5 d_51_6)))
(assert
 (not (and d_51_5 d_51_7)))
(assert
 (not (and d_51_5 d_51_8)))
(assert
 (not (and d_51_6 d_51_7)))
(assert
 (not (and d_51_6 d_51_8)))
(assert
 (not (and d_51_7 d_51_8)))
(assert
 (let (($x12967 (or false d_52_0)))
 (let (($x12969 (or $x12967 d_52_1)))
 (let (($x12971 (or $x12969 d_52_2)))
 (let (($x12973 (or $x12971 d_52_3)))
 (let (($x12975 (or $x12973 d_52_4)))
 (let (($x12977 (or $x12975 d_52_5)))
 (let (($x12979 (or $x12977 d_52_6)))
 (let (($x12981 (or $x12979 d_52_7)))
 (or $x12981 d_52_8))))))))))
(assert
 (not (and d_52_0 d_52_1)))
(assert
 (not (and d_52_0 d_52_2)))
(assert
 (not (and d_52_0 d_52_3)))
(assert
 (not (and d_52_0 d_52_4)))
(assert
 (not (and d_52_0 d_52_5)))
(assert
 (not (and d_52_0 d_52_6)))
(assert
 (not (and d_52_0 d_52_7)))
(assert
 (not (and d_52_0 d_52_8)))
(assert
 (not (and d_52_1 d_52_2)))
(assert
 (not (and d_52_1 d_52_3)))
(assert
 (not (and d_52_1 d_52_4)))
(assert
 (not (and d_52_1 d_52_5)))
(assert
 (not (and d_52_1 d_52_6)))
(assert
 (not (and d_52_1 d_52_7)))
(assert
 (not (and d_52_1 d_52_8)))
(assert
 (not (and d_52_2 d_52_3)))
(assert
 (not (and d_52_2 d_52_4)))
(assert
 (not (and d_52_2 d_52_5)))
(assert
 (not (and d_52_2 d_52_6)))
(assert
 (not (and d_52_2 d_52_7)))
(assert
 (not (and d_52_2 d_52_8)))
(assert
 (not (and d_52_3 d_52_4)))
(assert
 (not (and d_52_3 d_52_5)))
(assert
 (not (and d_52_3 d_52_6)))
(assert
 (not (and d_52_3 d_52_7)))
(assert
 (not (and d_52_3 d_52_8)))
(assert
 (not (and d_52_4 d_52_5)))
(assert
 (not (and d_52_4 d_52_6)))
(assert
 (not (and d_52_4 d_52_7)))
(assert
 (not (and d_52_4 d_52_8)))
(assert
 (not (and d_52_5 d_52_6)))
(assert
 (not (and d_52_5 d_52_7)))
(assert
 (not (and d_52_5 d_52_8)))
(assert
 (not (and d_52_6 d_52_7)))
(assert
 (not (and d_52_6 d_52_8)))
(assert
 (not (and d_52_7 d_52_8)))
(assert
 (let (($x13057 (or false d_53_0)))
 (let (($x13059 (or $x13057 d_53_1)))
 (let (($x13061 (or $x13059 d_53_2)))
 (let (($x13063 (or $x13061 d_53_3)))
 (let (($x13065 (or $x13063 d_53_4)))
 (let (($x13067 (or $x13065 d_53_5)))
 (let (($x13069 (or $x13067 d_53_6)))
 (let (($x13071 (or $x13069 d_53_7)))
 (or $x13071 d_53_8))))))))))
(assert
 (not (and d_53_0 d_53_1)))
(assert
 (not (and d_53_0 d_53_2)))
(assert
 (not (and d_53_0 d_53_3)))
(assert
 (not (and d_53_0 d_53_4)))
(assert
 (not (and d_53_0 d_53_5)))
(assert
 (not (and d_53_0 d_53_6)))
(assert
 (not (and d_53_0 d_53_7)))
(assert
 (not (and d_53_0 d_53_8)))
(assert
 (not (and d_53_1 d_53_2)))
(assert
 (not (and d_53_1 d_53_3)))
(assert
 (not (and d_53_1 d_53_4)))
(assert
 (not (and d_53_1 d_53_5)))
(assert
 (not (and d_53_1 d_53_6)))
(assert
 (not (and d_53_1 d_53_7)))
(assert
 (not (and d_53_1 d_53_8)))
(assert
 (not (and d_53_2 d_53_3)))
(assert
 (not (and d_53_2 d_53_4)))
(assert
 (not (and d_53_2 d_53_5)))
(assert
 (not (and d_53_2 d_53_6)))
(assert
 (not (and d_53_2 d_53_7)))
(assert
 (not (and d_53_2 d_53_8)))
(assert
 (not (and d_53_3 d_53_4)))
(assert
 (not (and d_53_3 d_53_5)))
(assert
 (not (and d_53_3 d_53_6)))
(assert
 (not (and d_53_3 d_53_7)))
(assert
 (not (and d_53_3 d_53_8)))
(assert
 (not (and d_53_4 d_53_5)))
(assert
 (not (and d_53_4 d_53_6)))
(assert
 (not (and d_53_4 d_53_7)))
(assert
 (not (and d_53_4 d_53_8)))
(assert
 (not (and d_53_5 d_53_6)))
(assert
 (not (and d_53_5 d_53_7)))
(assert
 (not (and d_53_5 d_53_8)))
(assert
 (not (and d_53_6 d_53_7)))
(assert
 (not (and d_53_6 d_53_8)))
(assert
 (not (and d_53_7 d_53_8)))
(assert
 (let (($x13147 (or false d_54_0)))
 (let (($x13149 (or $x13147 d_54_1)))
 (let (($x13151 (or $x13149 d_54_2)))
 (let (($x13153 (or $x13151 d_54_3)))
 (let (($x13155 (or $x13153 d_54_4)))
 (let (($x13157 (or $x13155 d_54_5)))
 (let (($x13159 (or $x13157 d_54_6)))
 (let (($x13161 (or $x13159 d_54_7)))
 (or $x13161 d_54_8))))))))))
(assert
 (not (and d_54_0 d_54_1)))
(assert
 (not (and d_54_0 d_54_2)))
(assert
 (not (and d_54_0 d_54_3)))
(assert
 (not (and d_54_0 d_54_4)))
(assert
 (not (and d_54_0 d_54_5)))
(assert
 (not (and d_54_0 d_54_6)))
(assert
 (not (and d_54_0 d_54_7)))
(assert
 (not (and d_54_0 d_54_8)))
(assert
 (not (and d_54_1 d_54_2)))
(assert
 (not (and d_54_1 d_54_3)))
(assert
 (not (and d_54_1 d_54_4)))
(assert
 (not (and d_54_1 d_54_5)))
(assert
 (not (and d_54_1 d_54_6)))
(assert
 (not (and d_54_1 d_54_7)))
(assert
 (not (and d_54_1 d_54_8)))
(assert
 (not (and d_54_2 d_54_3)))
(assert
 (not (and d_54_2 d_54_4)))
(assert
 (not (and d_54_2 d_54_5)))
(assert
 (not (and d_54_2 d_54_6)))
(assert
 (not (and d_54_2 d_54_7)))
(assert
 (not (and d_54_2 d_54_8)))
(assert
 (not (and d_54_3 d_54_4)))
(assert
 (not (and d_54_3 d_54_5)))
(assert
 (not (and d_54_3 d_54_6)))
(assert
 (not (and d_54_3 d_54_7)))
(assert
 (not (and d_54_3 d_54_8)))
(assert
 (not (and d_54_4 d_54_5)))
(assert
 (not (and d_54_4 d_54_6)))
(assert
 (not (and d_54_4 d_54_7)))
(assert
 (not (and d_54_4 d_54_8)))
(assert
 (not (and d_54_5 d_54_6)))
(assert
 (not (and d_54_5 d_54_7)))
(assert
 (not (and d_54_5 d_54_8)))
(assert
 (not (and d_54_6 d_54_7)))
(assert
 (not (and d_54_6 d_54_8)))
(assert
 (not (and d_54_7 d_54_8)))
(assert
 (let (($x13237 (or false d_55_0)))
 (let (($x13239 (or $x13237 d_55_1)))
 (let (($x13241 (or $x13239 d_55_2)))
 (let (($x13243 (or $x13241 d_55_3)))
 (let (($x13245 (or $x13243 d_55_4)))
 (let (($x13247 (or $x13245 d_55_5)))
 (let (($x13249 (or $x13247 d_55_6)))
 (let (($x13251 (or $x13249 d_55_7)))
 (or $x13251 d_55_8))))))))))
(assert
 (not (and d_55_0 d_55_1)))
(assert
 (not (and d_55_0 d_55_2)))
(assert
 (not (and d_55_0 d_55_3)))
(assert
 (not (and d_55_0 d_55_4)))
(assert
 (not (and d_55_0 d_55_5)))
(assert
 (not (and d_55_0 d_55_6)))
(assert
 (not (and d_55_0 d_55_7)))
(assert
 (not (and d_55_0 d_55_8)))
(assert
 (not (and d_55_1 d_55_2)))
(assert
 (not (and d_55_1 d_55_3)))
(assert
 (not (and d_55_1 d_55_4)))
(assert
 (not (and d_55_1 d_55_5)))
(assert
 (not (and d_55_1 d_55_6)))
(assert
 (not (and d_55_1 d_55_7)))
(assert
 (not (and d_55_1 d_55_8)))
(assert
 (not (and d_55_2 d_55_3)))
(assert
 (not (and d_55_2 d_55_4)))
(assert
 (not (and d_55_2 d_55_5)))
(assert
 (not (and d_55_2 d_55_6)))
(assert
 (not (and d_55_2 d_55_7)))
(assert
 (not (and d_55_2 d_55_8)))
(assert
 (not (and d_55_3 d_55_4)))
(assert
 (not (and d_55_3 d_55_5)))
(assert
 (not (and d_55_3 d_55_6)))
(assert
 (not (and d_55_3 d_55_7)))
(assert
 (not (and d_55_3 d_55_8)))
(assert
 (not (and d_55_4 d_55_5)))
(assert
 (not (and d_55_4 d_55_6)))
(assert
 (not (and d_55_4 d_55_7)))
(assert
 (not (and d_55_4 d_55_8)))
(assert
 (not (and d_55_5 d_55_6)))
(assert
 (not (and d_55_5 d_55_7)))
(assert
 (not (and d_55_5 d_55_8)))
(assert
 (not (and d_55_6 d_55_7)))
(assert
 (not (and d_55_6 d_55_8)))
(assert
 (not (and d_55_7 d_55_8)))
(assert
 (let (($x13327 (or false d_56_0)))
 (let (($x13329 (or $x13327 d_56_1)))
 (let (($x13331 (or $x13329 d_56_2)))
 (let (($x13333 (or $x13331 d_56_3)))
 (let (($x13335 (or $x13333 d_56_4)))
 (let (($x13337 (or $x13335 d_56_5)))
 (let (($x13339 (or $x13337 d_56_6)))
 (let (($x13341 (or $x13339 d_56_7)))
 (or $x13341 d_56_8))))))))))
(assert
 (not (and d_56_0 d_56_1)))
(assert
 (not (and d_56_0 d_56_2)))
(assert
 (not (and d_56_0 d_56_3)))
(assert
 (not (and d_56_0 d_56_4)))
(assert
 (not (and d_56_0 d_56_5)))
(assert
 (not (and d_56_0 d_56_6)))
(assert
 (not (and d_56_0 d_56_7)))
(assert
 (not (and d_56_0 d_56_8)))
(assert
 (not (and d_56_1 d_56_2)))
(assert
 (not (and d_56_1 d_56_3)))
(assert
 (not (and d_56_1 d_56_4)))
(assert
 (not (and d_56_1 d_56_5)))
(assert
 (not (and d_56_1 d_56_6)))
(assert
 (not (and d_56_1 d_56_7)))
(assert
 (not (and d_56_1 d_56_8)))
(assert
 (not (and d_56_2 d_56_3)))
(assert
 (not (and d_56_2 d_56_4)))
(assert
 (not (and d_56_2 d_56_5)))
(assert
 (not (and d_56_2 d_56_6)))
(assert
 (not (and d_56_2 d_56_7)))
(assert
 (not (and d_56_2 d_56_8)))
(assert
 (not (and d_56_3 d_56_4)))
(assert
 (not (and d_56_3 d_56_5)))
(assert
 (not (and d_56_3 d_56_6)))
(assert
 (not (and d_56_3 d_56_7)))
(assert
 (not (and d_56_3 d_56_8)))
(assert
 (not (and d_56_4 d_56_5)))
(assert
 (not (and d_56_4 d_56_6)))
(assert
 (not (and d_56_4 d_56_7)))
(assert
 (not (and d_56_4 d_56_8)))
(assert
 (not (and d_56_5 d_56_6)))
(assert
 (not (and d_56_5 d_56_7)))
(assert
 (not (and d_56_5 d_56_8)))
(assert
 (not (and d_56_6 d_56_7)))
(assert
 (not (and d_56_6 d_56_8)))
(assert
 (not (and d_56_7 d_56_8)))
(assert
 (let (($x13417 (or false d_57_0)))
 (let (($x13419 (or $x13417 d_57_1)))
 (let (($x13421 (or $x13419 d_57_2)))
 (let (($x13423 (or $x13421 d_57_3)))
 (let (($x13425 (or $x13423 d_57_4)))
 (let (($x13427 (or $x13425 d_57_5)))
 (let (($x13429 (or $x13427 d_57_6)))
 (let (($x13431 (or $x13429 d_57_7)))
 (or $x13431 d_57_8))))))))))
(assert
 (not (and d_57_0 d_57_1)))
(assert
 (not (and d_57_0 d_57_2)))
(assert
 (not (and d_57_0 d_57_3)))
(assert
 (not (and d_57_0 d_57_4)))
(assert
 (not (and d_57_0 d_57_5)))
(assert
 (not (and d_57_0 d_57_6)))
(assert
 (not (and d_57_0 d_57_7)))
(assert
 (not (and d_57_0 d_57_8)))
(assert
 (not (and d_57_1 d_57_2)))
(assert
 (not (and d_57_1 d_57_3)))
(assert
 (not (and d_57_1 d_57_4)))
(assert
 (not (and d_57_1 d_57_5)))
(assert
 (not (and d_57_1 d_57_6)))
(assert
 (not (and d_57_1 d_57_7)))
(assert
 (not (and d_57_1 d_57_8)))
(assert
 (not (and d_57_2 d_57_3)))
(assert
 (not (and d_57_2 d_57_4)))
(assert
 (not (and d_57_2 d_57_5)))
(assert
 (not (and d_57_2 d_57_6)))
(assert
 (not (and d_57_2 d_57_7)))
(assert
 (not (and d_57_2 d_57_8)))
(assert
 (not (and d_57_3 d_57_4)))
(assert
 (not (and d_57_3 d_57_5)))
(assert
 (not (and d_57_3 d_57_6)))
(assert
 (not (and d_57_3 d_57_7)))
(assert
 (not (and d_57_3 d_57_8)))
(assert
 (not (and d_57_4 d_57_5)))
(assert
 (not (and d_57_4 d_57_6)))
(assert
 (not (and d_57_4 d_57_7)))
(assert
 (not (and d_57_4 d_57_8)))
(assert
 (not (and d_57_5 d_57_6)))
(assert
 (not (and d_57_5 d_57_7)))
(assert
 (not (and d_57_5 d_57_8)))
(assert
 (not (and d_57_6 d_57_7)))
(assert
 (not (and d_57_6 d_57_8)))
(assert
 (not (and d_57_7 d_57_8)))
(assert
 (let (($x13507 (or false d_58_0)))
 (let (($x13509 (or $x13507 d_58_1)))
 (let (($x13511 (or $x13509 d_58_2)))
 (let (($x13513 (or $x13511 d_58_3)))
 (let (($x13515 (or $x13513 d_58_4)))
 (let (($x13517 (or $x13515 d_58_5)))
 (let (($x13519 (or $x13517 d_58_6)))
 (let (($x13521 (or $x13519 d_58_7)))
 (or $x13521 d_58_8))))))))))
(assert
 (not (and d_58_0 d_58_1)))
(assert
 (not (and d_58_0 d_58_2)))
(assert
 (not (and d_58_0 d_58_3)))
(assert
 (not (and d_58_0 d_58_4)))
(assert
 (not (and d_58_0 d_58_5)))
(assert
 (not (and d_58_0 d_58_6)))
(assert
 (not (and d_58_0 d_58_7)))
(assert
 (not (and d_58_0 d_58_8)))
(assert
 (not (and d_58_1 d_58_2)))
(assert
 (not (and d_58_1 d_58_3)))
(assert
 (not (and d_58_1 d_58_4)))
(assert
 (not (and d_58_1 d_58_5)))
(assert
 (not (and d_58_1 d_58_6)))
(assert
 (not (and d_58_1 d_58_7)))
(assert
 (not (and d_58_1 d_58_8)))
(assert
 (not (and d_58_2 d_58_3)))
(assert
 (not (and d_58_2 d_58_4)))
(assert
 (not (and d_58_2 d_58_5)))
(assert
 (not (and d_58_2 d_58_6)))
(assert
 (not (and d_58_2 d_58_7)))
(assert
 (not (and d_58_2 d_58_8)))
(assert
 (not (and d_58_3 d_58_4)))
(assert
 (not (and d_58_3 d_58_5)))
(assert
 (not (and d_58_3 d_58_6)))
(assert
 (not (and d_58_3 d_58_7)))
(assert
 (not (and d_58_3 d_58_8)))
(assert
 (not (and d_58_4 d_58_5)))
(assert
 (not (and d_58_4 d_58_6)))
(assert
 (not (and d_58_4 d_58_7)))
(assert
 (not (and d_58_4 d_58_8)))
(assert
 (not (and d_58_5 d_58_6)))
(assert
 (not (and d_58_5 d_58_7)))
(assert
 (not (and d_58_5 d_58_8)))
(assert
 (not (and d_58_6 d_58_7)))
(assert
 (not (and d_58_6 d_58_8)))
(assert
 (not (and d_58_7 d_58_8)))
(assert
 (let (($x13597 (or false d_59_0)))
 (let (($x13599 (or $x13597 d_59_1)))
 (let (($x13601 (or $x13599 d_59_2)))
 (let (($x13603 (or $x13601 d_59_3)))
 (let (($x13605 (or $x13603 d_59_4)))
 (let (($x13607 (or $x13605 d_59_5)))
 (let (($x13609 (or $x13607 d_59_6)))
 (let (($x13611 (or $x13609 d_59_7)))
 (or $x13611 d_59_8))))))))))
(assert
 (not (and d_59_0 d_59_1)))
(assert
 (not (and d_59_0 d_59_2)))
(assert
 (not (and d_59_0 d_59_3)))
(assert
 (not (and d_59_0 d_59_4)))
(assert
 (not (and d_59_0 d_59_5)))
(assert
 (not (and d_59_0 d_59_6)))
(assert
 (not (and d_59_0 d_59_7)))
(assert
 (not (and d_59_0 d_59_8)))
(assert
 (not (and d_59_1 d_59_2)))
(assert
 (not (and d_59_1 d_59_3)))
(assert
 (not (and d_59_1 d_59_4)))
(assert
 (not (and d_59_1 d_59_5)))
(assert
 (not (and d_59_1 d_59_6)))
(assert
 (not (and d_59_1 d_59_7)))
(assert
 (not (and d_59_1 d_59_8)))
(assert
 (not (and d_59_2 d_59_3)))
(assert
 (not (and d_59_2 d_59_4)))
(assert
 (not (and d_59_2 d_59_5)))
(assert
 (not (and d_59_2 d_59_6)))
(assert
 (not (and d_59_2 d_59_7)))
(assert
 (not (and d_59_2 d_59_8)))
(assert
 (not (and d_59_3 d_59_4)))
(assert
 (not (and d_59_3 d_59_5)))
(assert
 (not (and d_59_3 d_59_6)))
(assert
 (not (and d_59_3 d_59_7)))
(assert
 (not (and d_59_3 d_59_8)))
(assert
 (not (and d_59_4 d_59_5)))
(assert
 (not (and d_59_4 d_59_6)))
(assert
 (not (and d_59_4 d_59_7)))
(assert
 (not (and d_59_4 d_59_8)))
(assert
 (not (and d_59_5 d_59_6)))
(assert
 (not (and d_59_5 d_59_7)))
(assert
 (not (and d_59_5 d_59_8)))
(assert
 (not (and d_59_6 d_59_7)))
(assert
 (not (and d_59_6 d_59_8)))
(assert
 (not (and d_59_7 d_59_8)))
(assert
 (let (($x13687 (or false d_60_0)))
 (let (($x13689 (or $x13687 d_60_1)))
 (let (($x13691 (or $x13689 d_60_2)))
 (let (($x13693 (or $x13691 d_60_3)))
 (let (($x13695 (or $x13693 d_60_4)))
 (let (($x13697 (or $x13695 d_60_5)))
 (let (($x13699 (or $x13697 d_60_6)))
 (let (($x13701 (or $x13699 d_60_7)))
 (or $x13701 d_60_8))))))))))
(assert
 (not (and d_60_0 d_60_1)))
(assert
 (not (and d_60_0 d_60_2)))
(assert
 (not (and d_60_0 d_60_3)))
(assert
 (not (and d_60_0 d_60_4)))
(assert
 (not (and d_60_0 d_60_5)))
(assert
 (not (and d_60_0 d_60_6)))
(assert
 (not (and d_60_0 d_60_7)))
(assert
 (not (and d_60_0 d_60_8)))
(assert
 (not (and d_60_1 d_60_2)))
(assert
 (not (and d_60_1 d_60_3)))
(assert
 (not (and d_60_1 d_60_4)))
(assert
 (not (and d_60_1 d_60_5)))
(assert
 (not (and d_60_1 d_60_6)))
(assert
 (not (and d_60_1 d_60_7)))
(assert
 (not (and d_60_1 d_60_8)))
(assert
 (not (and d_60_2 d_60_3)))
(assert
 (not (and d_60_2 d_60_4)))
(assert
 (not (and d_60_2 d_60_5)))
(assert
 (not (and d_60_2 d_60_6)))
(assert
 (not (and d_60_2 d_60_7)))
(assert
 (not (and d_60_2 d_60_8)))
(assert
 (not (and d_60_3 d_60_4)))
(assert
 (not (and d_60_3 d_60_5)))
(assert
 (not (and d_60_3 d_60_6)))
(assert
 (not (and d_60_3 d_60_7)))
(assert
 (not (and d_60_3 d_60_8)))
(assert
 (not (and d_60_4 d_60_5)))
(assert
 (not (and d_60_4 d_60_6)))
(assert
 (not (and d_60_4 d_60_7)))
(assert
 (not (and d_60_4 d_60_8)))
(assert
 (not (and d_60_5 d_60_6)))
(assert
 (not (and d_60_5 d_60_7)))
(assert
 (not (and d_60_5 d_60_8)))
(assert
 (not (and d_60_6 d_60_7)))
(assert
 (not (and d_60_6 d_60_8)))
(assert
 (not (and d_60_7 d_60_8)))
(assert
 (let (($x13777 (or false d_61_0)))
 (let (($x13779 (or $x13777 d_61_1)))
 (let (($x13781 (or $x13779 d_61_2)))
 (let (($x13783 (or $x13781 d_61_3)))
 (let (($x13785 (or $x13783 d_61_4)))
 (let (($x13787 (or $x13785 d_61_5)))
 (let (($x13789 (or $x13787 d_61_6)))
 (let (($x13791 (or $x13789 d_61_7)))
 (or $x13791 d_61_8))))))))))
(assert
 (not (and d_61_0 d_61_1)))
(assert
 (not (and d_61_0 d_61_2)))
(assert
 (not (and d_61_0 d_61_3)))
(assert
 (not (and d_61_0 d_61_4)))
(assert
 (not (and d_61_0 d_61_5)))
(assert
 (not (and d_61_0 d_61_6)))
(assert
 (not (and d_61_0 d_61_7)))
(assert
 (not (and d_61_0 d_61_8)))
(assert
 (not (and d_61_1 d_61_2)))
(assert
 (not (and d_61_1 d_61_3)))
(assert
 (not (and d_61_1 d_61_4)))
(assert
 (not (and d_61_1 d_61_5)))
(assert
 (not (and d_61_1 d_61_6)))
(assert
 (not (and d_61_1 d_61_7)))
(assert
 (not (and d_61_1 d_61_8)))
(assert
 (not (and d_61_2 d_61_3)))
(assert
 (not (and d_61_2 d_61_4)))
(assert
 (not (and d_61_2 d_61_5)))
(assert
 (not (and d_61_2 d_61_6)))
(assert
 (not (and d_61_2 d_61_7)))
(assert
 (not (and d_61_2 d_61_8)))
(assert
 (not (and d_61_3 d_61_4)))
(assert
 (not (and d_61_3 d_61_5)))
(assert
 (not (and d_61_3 d_61_6)))
(assert
 (not (and d_61_3 d_61_7)))
(assert
 (not (and d_61_3 d_61_8)))
(assert
 (not (and d_61_4 d_61_5)))
(assert
 (not (and d_61_4 d_61_6)))
(assert
 (not (and d_61_4 d_61_7)))
(assert
 (not (and d_61_4 d_61_8)))
(assert
 (not (and d_61_5 d_61_6)))
(assert
 (not (and d_61_5 d_61_7)))
(assert
 (not (and d_61_5 d_61_8)))
(assert
 (not (and d_61_6 d_61_7)))
(assert
 (not (and d_61_6 d_61_8)))
(assert
 (not (and d_61_7 d_61_8)))
(assert
 (let (($x13867 (or false d_62_0)))
 (let (($x13869 (or $x13867 d_62_1)))
 (let (($x13871 (or $x13869 d_62_2)))
 (let (($x13873 (or $x13871 d_62_3)))
 (let (($x13875 (or $x13873 d_62_4)))
 (let (($x13877 (or $x13875 d_62_5)))
 (let (($x13879 (or $x13877 d_62_6)))
 (let (($x13881 (or $x13879 d_62_7)))
 (or $x13881 d_62_8))))))))))
(assert
 (not (and d_62_0 d_62_1)))
(assert
 (not (and d_62_0 d_62_2)))
(assert
 (not (and d_62_0 d_62_3)))
(assert
 (not (and d_62_0 d_62_4)))
(assert
 (not (and d_62_0 d_62_5)))
(assert
 (not (and d_62_0 d_62_6)))
(assert
 (not (and d_62_0 d_62_7)))
(assert
 (not (and d_62_0 d_62_8)))
(assert
 (not (and d_62_1 d_62_2)))
(assert
 (not (and d_62_1 d_62_3)))
(assert
 (not (and d_62_1 d_62_4)))
(assert
 (not (and d_62_1 d_62_5)))
(assert
 (not (and d_62_1 d_62_6)))
(assert
 (not (and d_62_1 d_62_7)))
(assert
 (not (and d_62_1 d_62_8)))
(assert
 (not (and d_62_2 d_62_3)))
(assert
 (not (and d_62_2 d_62_4)))
(assert
 (not (and d_62_2 d_62_5)))
(assert
 (not (and d_62_2 d_62_6)))
(assert
 (not (and d_62_2 d_62_7)))
(assert
 (not (and d_62_2 d_62_8)))
(assert
 (not (and d_62_3 d_62_4)))
(assert
 (not (and d_62_3 d_62_5)))
(assert
 (not (and d_62_3 d_62_6)))
(assert
 (not (and d_62_3 d_62_7)))
(assert
 (not (and d_62_3 d_62_8)))
(assert
 (not (and d_62_4 d_62_5)))
(assert
 (not (and d_62_4 d_62_6)))
(assert
 (not (and d_62_4 d_62_7)))
(assert
 (not (and d_62_4 d_62_8)))
(assert
 (not (and d_62_5 d_62_6)))
(assert
 (not (and d_62_5 d_62_7)))
(assert
 (not (and d_62_5 d_62_8)))
(assert
 (not (and d_62_6 d_62_7)))
(assert
 (not (and d_62_6 d_62_8)))
(assert
 (not (and d_62_7 d_62_8)))
(assert
 (let (($x13957 (or false d_63_0)))
 (let (($x13959 (or $x13957 d_63_1)))
 (let (($x13961 (or $x13959 d_63_2)))
 (let (($x13963 (or $x13961 d_63_3)))
 (let (($x13965 (or $x13963 d_63_4)))
 (let (($x13967 (or $x13965 d_63_5)))
 (let (($x13969 (or $x13967 d_63_6)))
 (let (($x13971 (or $x13969 d_63_7)))
 (or $x13971 d_63_8))))))))))
(assert
 (not (and d_63_0 d_63_1)))
(assert
 (not (and d_63_0 d_63_2)))
(assert
 (not (and d_63_0 d_63_3)))
(assert
 (not (and d_63_0 d_63_4)))
(assert
 (not (and d_63_0 d_63_5)))
(assert
 (not (and d_63_0 d_63_6)))
(assert
 (not (and d_63_0 d_63_7)))
(assert
 (not (and d_63_0 d_63_8)))
(assert
 (not (and d_63_1 d_63_2)))
(assert
 (not (and d_63_1 d_63_3)))
(assert
 (not (and d_63_1 d_63_4)))
(assert
 (not (and d_63_1 d_63_5)))
(assert
 (not (and d_63_1 d_63_6)))
(assert
 (not (and d_63_1 d_63_7)))
(assert
 (not (and d_63_1 d_63_8)))
(assert
 (not (and d_63_2 d_63_3)))
(assert
 (not (and d_63_2 d_63_4)))
(assert
 (not (and d_63_2 d_63_5)))
(assert
 (not (and d_63_2 d_63_6)))
(assert
 (not (and d_63_2 d_63_7)))
(assert
 (not (and d_63_2 d_63_8)))
(assert
 (not (and d_63_3 d_63_4)))
(assert
 (not (and d_63_3 d_63_5)))
(assert
 (not (and d_63_3 d_63_6)))
(assert
 (not (and d_63_3 d_63_7)))
(assert
 (not (and d_63_3 d_63_8)))
(assert
 (not (and d_63_4 d_63_5)))
(assert
 (not (and d_63_4 d_63_6)))
(assert
 (not (and d_63_4 d_63_7)))
(assert
 (not (and d_63_4 d_63_8)))
(assert
 (not (and d_63_5 d_63_6)))
(assert
 (not (and d_63_5 d_63_7)))
(assert
 (not (and d_63_5 d_63_8)))
(assert
 (not (and d_63_6 d_63_7)))
(assert
 (not (and d_63_6 d_63_8)))
(assert
 (not (and d_63_7 d_63_8)))
(assert
 (let (($x14047 (or false d_64_0)))
 (let (($x14049 (or $x14047 d_64_1)))
 (let (($x14051 (or $x14049 d_64_2)))
 (let (($x14053 (or $x14051 d_64_3)))
 (let (($x14055 (or $x14053 d_64_4)))
 (let (($x14057 (or $x14055 d_64_5)))
 (let (($x14059 (or $x14057 d_64_6)))
 (let (($x14061 (or $x14059 d_64_7)))
 (or $x14061 d_64_8))))))))))
(assert
 (not (and d_64_0 d_64_1)))
(assert
 (not (and d_64_0 d_64_2)))
(assert
 (not (and d_64_0 d_64_3)))
(assert
 (not (and d_64_0 d_64_4)))
(assert
 (not (and d_64_0 d_64_5)))
(assert
 (not (and d_64_0 d_64_6)))
(assert
 (not (and d_64_0 d_64_7)))
(assert
 (not (and d_64_0 d_64_8)))
(assert
 (not (and d_64_1 d_64_2)))
(assert
 (not (and d_64_1 d_64_3)))
(assert
 (not (and d_64_1 d_64_4)))
(assert
 (not (and d_64_1 d_64_5)))
(assert
 (not (and d_64_1 d_64_6)))
(assert
 (not (and d_64_1 d_64_7)))
(assert
 (not (and d_64_1 d_64_8)))
(assert
 (not (and d_64_2 d_64_3)))
(assert
 (not (and d_64_2 d_64_4)))
(assert
 (not (and d_64_2 d_64_5)))
(assert
 (not (and d_64_2 d_64_6)))
(assert
 (not (and d_64_2 d_64_7)))
(assert
 (not (and d_64_2 d_64_8)))
(assert
 (not (and d_64_3 d_64_4)))
(assert
 (not (and d_64_3 d_64_5)))
(assert
 (not (and d_64_3 d_64_6)))
(assert
 (not (and d_64_3 d_64_7)))
(assert
 (not (and d_64_3 d_64_8)))
(assert
 (not (and d_64_4 d_64_5)))
(assert
 (not (and d_64_4 d_64_6)))
(assert
 (not (and d_64_4 d_64_7)))
(assert
 (not (and d_64_4 d_64_8)))
(assert
 (not (and d_64_5 d_64_6)))
(assert
 (not (and d_64_5 d_64_7)))
(assert
 (not (and d_64_5 d_64_8)))
(assert
 (not (and d_64_6 d_64_7)))
(assert
 (not (and d_64_6 d_64_8)))
(assert
 (not (and d_64_7 d_64_8)))
(assert
 (let (($x14137 (or false d_65_0)))
 (let (($x14139 (or $x14137 d_65_1)))
 (let (($x14141 (or $x14139 d_65_2)))
 (let (($x14143 (or $x14141 d_65_3)))
 (let (($x14145 (or $x14143 d_65_4)))
 (let (($x14147 (or $x14145 d_65_5)))
 (let (($x14149 (or $x14147 d_65_6)))
 (let (($x14151 (or $x14149 d_65_7)))
 (or $x14151 d_65_8))))))))))
(assert
 (not (and d_65_0 d_65_1)))
(assert
 (not (and d_65_0 d_65_2)))
(assert
 (not (and d_65_0 d_65_3)))
(assert
 (not (and d_65_0 d_65_4)))
(assert
 (not (and d_65_0 d_65_5)))
(assert
 (not (and d_65_0 d_65_6)))
(assert
 (not (and d_65_0 d_65_7)))
(assert
 (not (and d_65_0 d_65_8)))
(assert
 (not (and d_65_1 d_65_2)))
(assert
 (not (and d_65_1 d_65_3)))
(assert
 (not (and d_65_1 d_65_4)))
(assert
 (not (and d_65_1 d_65_5)))
(assert
 (not (and d_65_1 d_65_6)))
(assert
 (not (and d_65_1 d_65_7)))
(assert
 (not (and d_65_1 d_65_8)))
(assert
 (not (and d_65_2 d_65_3)))
(assert
 (not (and d_65_2 d_65_4)))
(assert
 (not (and d_65_2 d_65_5)))
(assert
 (not (and d_65_2 d_65_6)))
(assert
 (not (and d_65_2 d_65_7)))
(assert
 (not (and d_65_2 d_65_8)))
(assert
 (not (and d_65_3 d_65_4)))
(assert
 (not (and d_65_3 d_65_5)))
(assert
 (not (and d_65_3 d_65_6)))
(assert
 (not (and d_65_3 d_65_7)))
(assert
 (not (and d_65_3 d_65_8)))
(assert
 (not (and d_65_4 d_65_5)))
(assert
 (not (and d_65_4 d_65_6)))
(assert
 (not (and d_65_4 d_65_7)))
(assert
 (not (and d_65_4 d_65_8)))
(assert
 (not (and d_65_5 d_65_6)))
(assert
 (not (and d_65_5 d_65_7)))
(assert
 (not (and d_65_5 d_65_8)))
(assert
 (not (and d_65_6 d_65_7)))
(assert
 (not (and d_65_6 d_65_8)))
(assert
 (not (and d_65_7 d_65_8)))
(assert
 (let (($x14227 (or false d_66_0)))
 (let (($x14229 (or $x14227 d_66_1)))
 (let (($x14231 (or $x14229 d_66_2)))
 (let (($x14233 (or $x14231 d_66_3)))
 (let (($x14235 (or $x14233 d_66_4)))
 (let (($x14237 (or $x14235 d_66_5)))
 (let (($x14239 (or $x14237 d_66_6)))
 (let (($x14241 (or $x14239 d_66_7)))
 (or $x14241 d_66_8))))))))))
(assert
 (not (and d_66_0 d_66_1)))
(assert
 (not (and d_66_0 d_66_2)))
(assert
 (not (and d_66_0 d_66_3)))
(assert
 (not (and d_66_0 d_66_4)))
(assert
 (not (and d_66_0 d_66_5)))
(assert
 (not (and d_66_0 d_66_6)))
(assert
 (not (and d_66_0 d_66_7)))
(assert
 (not (and d_66_0 d_66_8)))
(assert
 (not (and d_66_1 d_66_2)))
(assert
 (not (and d_66_1 d_66_3)))
(assert
 (not (and d_66_1 d_66_4)))
(assert
 (not (and d_66_1 d_66_5)))
(assert
 (not (and d_66_1 d_66_6)))
(assert
 (not (and d_66_1 d_66_7)))
(assert
 (not (and d_66_1 d_66_8)))
(assert
 (not (and d_66_2 d_66_3)))
(assert
 (not (and d_66_2 d_66_4)))
(assert
 (not (and d_66_2 d_66_5)))
(assert
 (not (and d_66_2 d_66_6)))
(assert
 (not (and d_66_2 d_66_7)))
(assert
 (not (and d_66_2 d_66_8)))
(assert
 (not (and d_66_3 d_66_4)))
(assert
 (not (and d_66_3 d_66_5)))
(assert
 (not (and d_66_3 d_66_6)))
(assert
 (not (and d_66_3 d_66_7)))
(assert
 (not (and d_66_3 d_66_8)))
(assert
 (not (and d_66_4 d_66_5)))
(assert
 (not (and d_66_4 d_66_6)))
(assert
 (not (and d_66_4 d_66_7)))
(assert
 (not (and d_66_4 d_66_8)))
(assert
 (not (and d_66_5 d_66_6)))
(assert
 (not (and d_66_5 d_66_7)))
(assert
 (not (and d_66_5 d_66_8)))
(assert
 (not (and d_66_6 d_66_7)))
(assert
 (not (and d_66_6 d_66_8)))
(assert
 (not (and d_66_7 d_66_8)))
(assert
 (let (($x14317 (or false d_67_0)))
 (let (($x14319 (or $x14317 d_67_1)))
 (let (($x14321 (or $x14319 d_67_2)))
 (let (($x14323 (or $x14321 d_67_3)))
 (let (($x14325 (or $x14323 d_67_4)))
 (let (($x14327 (or $x14325 d_67_5)))
 (let (($x14329 (or $x14327 d_67_6)))
 (let (($x14331 (or $x14329 d_67_7)))
 (or $x14331 d_67_8))))))))))
(assert
 (not (and d_67_0 d_67_1)))
(assert
 (not (and d_67_0 d_67_2)))
(assert
 (not (and d_67_0 d_67_3)))
(assert
 (not (and d_67_0 d_67_4)))
(assert
 (not (and d_67_0 d_67_5)))
(assert
 (not (and d_67_0 d_67_6)))
(assert
 (not (and d_67_0 d_67_7)))
(assert
 (not (and d_67_0 d_67_8)))
(assert
 (not (and d_67_1 d_67_2)))
(assert
 (not (and d_67_1 d_67_3)))
(assert
 (not (and d_67_1 d_67_4)))
(assert
 (not (and d_67_1 d_67_5)))
(assert
 (not (and d_67_1 d_67_6)))
(assert
 (not (and d_67_1 d_67_7)))
(assert
 (not (and d_67_1 d_67_8)))
(assert
 (not (and d_67_2 d_67_3)))
(assert
 (not (and d_67_2 d_67_4)))
(assert
 (not (and d_67_2 d_67_5)))
(assert
 (not (and d_67_2 d_67_6)))
(assert
 (not (and d_67_2 d_67_7)))
(assert
 (not (and d_67_2 d_67_8)))
(assert
 (not (and d_67_3 d_67_4)))
(assert
 (not (and d_67_3 d_67_5)))
(assert
 (not (and d_67_3 d_67_6)))
(assert
 (not (and d_67_3 d_67_7)))
(assert
 (not (and d_67_3 d_67_8)))
(assert
 (not (and d_67_4 d_67_5)))
(assert
 (not (and d_67_4 d_67_6)))
(assert
 (not (and d_67_4 d_67_7)))
(assert
 (not (and d_67_4 d_67_8)))
(assert
 (not (and d_67_5 d_67_6)))
(assert
 (not (and d_67_5 d_67_7)))
(assert
 (not (and d_67_5 d_67_8)))
(assert
 (not (and d_67_6 d_67_7)))
(assert
 (not (and d_67_6 d_67_8)))
(assert
 (not (and d_67_7 d_67_8)))
(assert
 (let (($x14407 (or false d_68_0)))
 (let (($x14409 (or $x14407 d_68_1)))
 (let (($x14411 (or $x14409 d_68_2)))
 (let (($x14413 (or $x14411 d_68_3)))
 (let (($x14415 (or $x14413 d_68_4)))
 (let (($x14417 (or $x14415 d_68_5)))
 (let (($x14419 (or $x14417 d_68_6)))
 (let (($x14421 (or $x14419 d_68_7)))
 (or $x14421 d_68_8))))))))))
(assert
 (not (and d_68_0 d_68_1)))
(assert
 (not (and d_68_0 d_68_2)))
(assert
 (not (and d_68_0 d_68_3)))
(assert
 (not (and d_68_0 d_68_4)))
(assert
 (not (and d_68_0 d_68_5)))
(assert
 (not (and d_68_0 d_68_6)))
(assert
 (not (and d_68_0 d_68_7)))
(assert
 (not (and d_68_0 d_68_8)))
(assert
 (not (and d_68_1 d_68_2)))
(assert
 (not (and d_68_1 d_68_3)))
(assert
 (not (and d_68_1 d_68_4)))
(assert
 (not (and d_68_1 d_68_5)))
(assert
 (not (and d_68_1 d_68_6)))
(assert
 (not (and d_68_1 d_68_7)))
(assert
 (not (and d_68_1 d_68_8)))
(assert
 (not (and d_68_2 d_68_3)))
(assert
 (not (and d_68_2 d_68_4)))
(assert
 (not (and d_68_2 d_68_5)))
(assert
 (not (and d_68_2 d_68_6)))
(assert
 (not (and d_68_2 d_68_7)))
(assert
 (not (and d_68_2 d_68_8)))
(assert
 (not (and d_68_3 d_68_4)))
(assert
 (not (and d_68_3 d_68_5)))
(assert
 (not (and d_68_3 d_68_6)))
(assert
 (not (and d_68_3 d_68_7)))
(assert
 (not (and d_68_3 d_68_8)))
(assert
 (not (and d_68_4 d_68_5)))
(assert
 (not (and d_68_4 d_68_6)))
(assert
 (not (and d_68_4 d_68_7)))
(assert
 (not (and d_68_4 d_68_8)))
(assert
 (not (and d_68_5 d_68_6)))
(assert
 (not (and d_68_5 d_68_7)))
(assert
 (not (and d_68_5 d_68_8)))
(assert
 (not (and d_68_6 d_68_7)))
(assert
 (not (and d_68_6 d_68_8)))
(assert
 (not (and d_68_7 d_68_8)))
(assert
 (let (($x14497 (or false d_69_0)))
 (let (($x14499 (or $x14497 d_69_1)))
 (let (($x14501 (or $x14499 d_69_2)))
 (let (($x14503 (or $x14501 d_69_3)))
 (let (($x14505 (or $x14503 d_69_4)))
 (let (($x14507 (or $x14505 d_69_5)))
 (let (($x14509 (or $x14507 d_69_6)))
 (let (($x14511 (or $x14509 d_69_7)))
 (or $x14511 d_69_8))))))))))
(assert
 (not (and d_69_0 d_69_1)))
(assert
 (not (and d_69_0 d_69_2)))
(assert
 (not (and d_69_0 d_69_3)))
(assert
 (not (and d_69_0 d_69_4)))
(assert
 (not (and d_69_0 d_69_5)))
(assert
 (not (and d_69_0 d_69_6)))
(assert
 (not (and d_69_0 d_69_7)))
(assert
 (not (and d_69_0 d_69_8)))
(assert
 (not (and d_69_1 d_69_2)))
(assert
 (not (and d_69_1 d_69_3)))
(assert
 (not (and d_69_1 d_69_4)))
(assert
 (not (and d_69_1 d_69_5)))
(assert
 (not (and d_69_1 d_69_6)))
(assert
 (not (and d_69_1 d_69_7)))
(assert
 (not (and d_69_1 d_69_8)))
(assert
 (not (and d_69_2 d_69_3)))
(assert
 (not (and d_69_2 d_69_4)))
(assert
 (not (and d_69_2 d_69_5)))
(assert
 (not (and d_69_2 d_69_6)))
(assert
 (not (and d_69_2 d_69_7)))
(assert
 (not (and d_69_2 d_69_8)))
(assert
 (not (and d_69_3 d_69_4)))
(assert
 (not (and d_69_3 d_69_5)))
(assert
 (not (and d_69_3 d_69_6)))
(assert
 (not (and d_69_3 d_69_7)))
(assert
 (not (and d_69_3 d_69_8)))
(assert
 (not (and d_69_4 d_69_5)))
(assert
 (not (and d_69_4 d_69_6)))
(assert
 (not (and d_69_4 d_69_7)))
(assert
 (not (and d_69_4 d_69_8)))
(assert
 (not (and d_69_5 d_69_6)))
(assert
 (not (and d_69_5 d_69_7)))
(assert
 (not (and d_69_5 d_69_8)))
(assert
 (not (and d_69_6 d_69_7)))
(assert
 (not (and d_69_6 d_69_8)))
(assert
 (not (and d_69_7 d_69_8)))
(assert
 (let (($x14587 (or false d_70_0)))
 (let (($x14589 (or $x14587 d_70_1)))
 (let (($x14591 (or $x14589 d_70_2)))
 (let (($x14593 (or $x14591 d_70_3)))
 (let (($x14595 (or $x14593 d_70_4)))
 (let (($x14597 (or $x14595 d_70_5)))
 (let (($x14599 (or $x14597 d_70_6)))
 (let (($x14601 (or $x14599 d_70_7)))
 (or $x14601 d_70_8))))))))))
(assert
 (not (and d_70_0 d_70_1)))
(assert
 (not (and d_70_0 d_70_2)))
(assert
 (not (and d_70_0 d_70_3)))
(assert
 (not (and d_70_0 d_70_4)))
(assert
 (not (and d_70_0 d_70_5)))
(assert
 (not (and d_70_0 d_70_6)))
(assert
 (not (and d_70_0 d_70_7)))
(assert
 (not (and d_70_0 d_70_8)))
(assert
 (not (and d_70_1 d_70_2)))
(assert
 (not (and d_70_1 d_70_3)))
(assert
 (not (and d_70_1 d_70_4)))
(assert
 (not (and d_70_1 d_70_5)))
(assert
 (not (and d_70_1 d_70_6)))
(assert
 (not (and d_70_1 d_70_7)))
(assert
 (not (and d_70_1 d_70_8)))
(assert
 (not (and d_70_2 d_70_3)))
(assert
 (not (and d_70_2 d_70_4)))
(assert
 (not (and d_70_2 d_70_5)))
(assert
 (not (and d_70_2 d_70_6)))
(assert
 (not (and d_70_2 d_70_7)))
(assert
 (not (and d_70_2 d_70_8)))
(assert
 (not (and d_70_3 d_70_4)))
(assert
 (not (and d_70_3 d_70_5)))
(assert
 (not (and d_70_3 d_70_6)))
(assert
 (not (and d_70_3 d_70_7)))
(assert
 (not (and d_70_3 d_70_8)))
(assert
 (not (and d_70_4 d_70_5)))
(assert
 (not (and d_70_4 d_70_6)))
(assert
 (not (and d_70_4 d_70_7)))
(assert
 (not (and d_70_4 d_70_8)))
(assert
 (not (and d_70_5 d_70_6)))
(assert
 (not (and d_70_5 d_70_7)))
(assert
 (not (and d_70_5 d_70_8)))
(assert
 (not (and d_70_6 d_70_7)))
(assert
 (not (and d_70_6 d_70_8)))
(assert
 (not (and d_70_7 d_70_8)))
(assert
 (let (($x14677 (or false d_71_0)))
 (let (($x14679 (or $x14677 d_71_1)))
 (let (($x14681 (or $x14679 d_71_2)))
 (let (($x14683 (or $x14681 d_71_3)))
 (let (($x14685 (or $x14683 d_71_4)))
 (let (($x14687 (or $x14685 d_71_5)))
 (let (($x14689 (or $x14687 d_71_6)))
 (let (($x14691 (or $x14689 d_71_7)))
 (or $x14691 d_71_8))))))))))
(assert
 (not (and d_71_0 d_71_1)))
(assert
 (not (and d_71_0 d_71_2)))
(assert
 (not (and d_71_0 d_71_3)))
(assert
 (not (and d_71_0 d_71_4)))
(assert
 (not (and d_71_0 d_71_5)))
(assert
 (not (and d_71_0 d_71_6)))
(assert
 (not (and d_71_0 d_71_7)))
(assert
 (not (and d_71_0 d_71_8)))
(assert
 (not (and d_71_1 d_71_2)))
(assert
 (not (and d_71_1 d_71_3)))
(assert
 (not (and d_71_1 d_71_4)))
(assert
 (not (and d_71_1 d_71_5)))
(assert
 (not (and d_71_1 d_71_6)))
(assert
 (not (and d_71_1 d_71_7)))
(assert
 (not (and d_71_1 d_71_8)))
(assert
 (not (and d_71_2 d_71_3)))
(assert
 (not (and d_71_2 d_71_4)))
(assert
 (not (and d_71_2 d_71_5)))
(assert
 (not (and d_71_2 d_71_6)))
(assert
 (not (and d_71_2 d_71_7)))
(assert
 (not (and d_71_2 d_71_8)))
(assert
 (not (and d_71_3 d_71_4)))
(assert
 (not (and d_71_3 d_71_5)))
(assert
 (not (and d_71_3 d_71_6)))
(assert
 (not (and d_71_3 d_71_7)))
(assert
 (not (and d_71_3 d_71_8)))
(assert
 (not (and d_71_4 d_71_5)))
(assert
 (not (and d_71_4 d_71_6)))
(assert
 (not (and d_71_4 d_71_7)))
(assert
 (not (and d_71_4 d_71_8)))
(assert
 (not (and d_71_5 d_71_6)))
(assert
 (not (and d_71_5 d_71_7)))
(assert
 (not (and d_71_5 d_71_8)))
(assert
 (not (and d_71_6 d_71_7)))
(assert
 (not (and d_71_6 d_71_8)))
(assert
 (not (and d_71_7 d_71_8)))
(assert
 (let (($x14767 (or false d_72_0)))
 (let (($x14769 (or $x14767 d_72_1)))
 (let (($x14771 (or $x14769 d_72_2)))
 (let (($x14773 (or $x14771 d_72_3)))
 (let (($x14775 (or $x14773 d_72_4)))
 (let (($x14777 (or $x14775 d_72_5)))
 (let (($x14779 (or $x14777 d_72_6)))
 (let (($x14781 (or $x14779 d_72_7)))
 (or $x14781 d_72_8))))))))))
(assert
 (not (and d_72_0 d_72_1)))
(assert
 (not (and d_72_0 d_72_2)))
(assert
 (not (and d_72_0 d_72_3)))
(assert
 (not (and d_72_0 d_72_4)))
(assert
 (not (and d_72_0 d_72_5)))
(assert
 (not (and d_72_0 d_72_6)))
(assert
 (not (and d_72_0 d_72_7)))
(assert
 (not (and d_72_0 d_72_8)))
(assert
 (not (and d_72_1 d_72_2)))
(assert
 (not (and d_72_1 d_72_3)))
(assert
 (not (and d_72_1 d_72_4)))
(assert
 (not (and d_72_1 d_72_5)))
(assert
 (not (and d_72_1 d_72_6)))
(assert
 (not (and d_72_1 d_72_7)))
(assert
 (not (and d_72_1 d_72_8)))
(assert
 (not (and d_72_2 d_72_3)))
(assert
 (not (and d_72_2 d_72_4)))
(assert
 (not (and d_72_2 d_72_5)))
(assert
 (not (and d_72_2 d_72_6)))
(assert
 (not (and d_72_2 d_72_7)))
(assert
 (not (and d_72_2 d_72_8)))
(assert
 (not (and d_72_3 d_72_4)))
(assert
 (not (and d_72_3 d_72_5)))
(assert
 (not (and d_72_3 d_72_6)))
(assert
 (not (and d_72_3 d_72_7)))
(assert
 (not (and d_72_3 d_72_8)))
(assert
 (not (and d_72_4 d_72_5)))
(assert
 (not (and d_72_4 d_72_6)))
(assert
 (not (and d_72_4 d_72_7)))
(assert
 (not (and d_72_4 d_72_8)))
(assert
 (not (and d_72_5 d_72_6)))
(assert
 (not (and d_72_5 d_72_7)))
(assert
 (not (and d_72_5 d_72_8)))
(assert
 (not (and d_72_6 d_72_7)))
(assert
 (not (and d_72_6 d_72_8)))
(assert
 (not (and d_72_7 d_72_8)))
(assert
 (let (($x14857 (or false d_73_0)))
 (let (($x14859 (or $x14857 d_73_1)))
 (let (($x14861 (or $x14859 d_73_2)))
 (let (($x14863 (or $x14861 d_73_3)))
 (let (($x14865 (or $x14863 d_73_4)))
 (let (($x14867 (or $x14865 d_73_5)))
 (let (($x14869 (or $x14867 d_73_6)))
 (let (($x14871 (or $x14869 d_73_7)))
 (or $x14871 d_73_8))))))))))
(assert
 (not (and d_73_0 d_73_1)))
(assert
 (not (and d_73_0 d_73_2)))
(assert
 (not (and d_73_0 d_73_3)))
(assert
 (not (and d_73_0 d_73_4)))
(assert
 (not (and d_73_0 d_73_5)))
(assert
 (not (and d_73_0 d_73_6)))
(assert
 (not (and d_73_0 d_73_7)))
(assert
 (not (and d_73_0 d_73_8)))
(assert
 (not (and d_73_1 d_73_2)))
(assert
 (not (and d_73_1 d_73_3)))
(assert
 (not (and d_73_1 d_73_4)))
(assert
 (not (and d_73_1 d_73_5)))
(assert
 (not (and d_73_1 d_73_6)))
(assert
 (not (and d_73_1 d_73_7)))
(assert
 (not (and d_73_1 d_73_8)))
(assert
 (not (and d_73_2 d_73_3)))
(assert
 (not (and d_73_2 d_73_4)))
(assert
 (not (and d_73_2 d_73_5)))
(assert
 (not (and d_73_2 d_73_6)))
(assert
 (not (and d_73_2 d_73_7)))
(assert
 (not (and d_73_2 d_73_8)))
(assert
 (not (and d_73_3 d_73_4)))
(assert
 (not (and d_73_3 d_73_5)))
(assert
 (not (and d_73_3 d_73_6)))
(assert
 (not (and d_73_3 d_73_7)))
(assert
 (not (and d_73_3 d_73_8)))
(assert
 (not (and d_73_4 d_73_5)))
(assert
 (not (and d_73_4 d_73_6)))
(assert
 (not (and d_73_4 d_73_7)))
(assert
 (not (and d_73_4 d_73_8)))
(assert
 (not (and d_73_5 d_73_6)))
(assert
 (not (and d_73_5 d_73_7)))
(assert
 (not (and d_73_5 d_73_8)))
(assert
 (not (and d_73_6 d_73_7)))
(assert
 (not (and d_73_6 d_73_8)))
(assert
 (not (and d_73_7 d_73_8)))
(assert
 (let (($x14947 (or false d_74_0)))
 (let (($x14949 (or $x14947 d_74_1)))
 (let (($x14951 (or $x14949 d_74_2)))
 (let (($x14953 (or $x14951 d_74_3)))
 (let (($x14955 (or $x14953 d_74_4)))
 (let (($x14957 (or $x14955 d_74_5)))
 (let (($x14959 (or $x14957 d_74_6)))
 (let (($x14961 (or $x14959 d_74_7)))
 (or $x14961 d_74_8))))))))))
(assert
 (not (and d_74_0 d_74_1)))
(assert
 (not (and d_74_0 d_74_2)))
(assert
 (not (and d_74_0 d_74_3)))
(assert
 (not (and d_74_0 d_74_4)))
(assert
 (not (and d_74_0 d_74_5)))
(assert
 (not (and d_74_0 d_74_6)))
(assert
 (not (and d_74_0 d_74_7)))
(assert
 (not (and d_74_0 d_74_8)))
(assert
 (not (and d_74_1 d_74_2)))
(assert
 (not (and d_74_1 d_74_3)))
(assert
 (not (and d_74_1 d_74_4)))
(assert
 (not (and d_74_1 d_74_5)))
(assert
 (not (and d_74_1 d_74_6)))
(assert
 (not (and d_74_1 d_74_7)))
(assert
 (not (and d_74_1 d_74_8)))
(assert
 (not (and d_74_2 d_74_3)))
(assert
 (not (and d_74_2 d_74_4)))
(assert
 (not (and d_74_2 d_74_5)))
(assert
 (not (and d_74_2 d_74_6)))
(assert
 (not (and d_74_2 d_74_7)))
(assert
 (not (and d_74_2 d_74_8)))
(assert
 (not (and d_74_3 d_74_4)))
(assert
 (not (and d_74_3 d_74_5)))
(assert
 (not (and d_74_3 d_74_6)))
(assert
 (not (and d_74_3 d_74_7)))
(assert
 (not (and d_74_3 d_74_8)))
(assert
 (not (and d_74_4 d_74_5)))
(assert
 (not (and d_74_4 d_74_6)))
(assert
 (not (and d_74_4 d_74_7)))
(assert
 (not (and d_74_4 d_74_8)))
(assert
 (not (and d_74_5 d_74_6)))
(assert
 (not (and d_74_5 d_74_7)))
(assert
 (not (and d_74_5 d_74_8)))
(assert
 (not (and d_74_6 d_74_7)))
(assert
 (not (and d_74_6 d_74_8)))
(assert
 (not (and d_74_7 d_74_8)))
(assert
 (let (($x15037 (or false d_75_0)))
 (let (($x15039 (or $x15037 d_75_1)))
 (let (($x15041 (or $x15039 d_75_2)))
 (let (($x15043 (or $x15041 d_75_3)))
 (let (($x15045 (or $x15043 d_75_4)))
 (let (($x15047 (or $x15045 d_75_5)))
 (let (($x15049 (or $x15047 d_75_6)))
 (let (($x15051 (or $x15049 d_75_7)))
 (or $x15051 d_75_8))))))))))
(assert
 (not (and d_75_0 d_75_1)))
(assert
 (not (and d_75_0 d_75_2)))
(assert
 (not (and d_75_0 d_75_3)))
(assert
 (not (and d_75_0 d_75_4)))
(assert
 (not (and d_75_0 d_75_5)))
(assert
 (not (and d_75_0 d_75_6)))
(assert
 (not (and d_75_0 d_75_7)))
(assert
 (not (and d_75_0 d_75_8)))
(assert
 (not (and d_75_1 d_75_2)))
(assert
 (not (and d_75_1 d_75_3)))
(assert
 (not (and d_75_1 d_75_4)))
(assert
 (not (and d_75_1 d_75_5)))
(assert
 (not (and d_75_1 d_75_6)))
(assert
 (not (and d_75_1 d_75_7)))
(assert
 (not (and d_75_1 d_75_8)))
(assert
 (not (and d_75_2 d_75_3)))
(assert
 (not (and d_75_2 d_75_4)))
(assert
 (not (and d_75_2 d_75_5)))
(assert
 (not (and d_75_2 d_75_6)))
(assert
 (not (and d_75_2 d_75_7)))
(assert
 (not (and d_75_2 d_75_8)))
(assert
 (not (and d_75_3 d_75_4)))
(assert
 (not (and d_75_3 d_75_5)))
(assert
 (not (and d_75_3 d_75_6)))
(assert
 (not (and d_75_3 d_75_7)))
(assert
 (not (and d_75_3 d_75_8)))
(assert
 (not (and d_75_4 d_75_5)))
(assert
 (not (and d_75_4 d_75_6)))
(assert
 (not (and d_75_4 d_75_7)))
(assert
 (not (and d_75_4 d_75_8)))
(assert
 (not (and d_75_5 d_75_6)))
(assert
 (not (and d_75_5 d_75_7)))
(assert
 (not (and d_75_5 d_75_8)))
(assert
 (not (and d_75_6 d_75_7)))
(assert
 (not (and d_75_6 d_75_8)))
(assert
 (not (and d_75_7 d_75_8)))
(assert
 (let (($x15127 (or false d_76_0)))
 (let (($x15129 (or $x15127 d_76_1)))
 (let (($x15131 (or $x15129 d_76_2)))
 (let (($x15133 (or $x15131 d_76_3)))
 (let (($x15135 (or $x15133 d_76_4)))
 (let (($x15137 (or $x15135 d_76_5)))
 (let (($x15139 (or $x15137 d_76_6)))
 (let (($x15141 (or $x15139 d_76_7)))
 (or $x15141 d_76_8))))))))))
(assert
 (not (and d_76_0 d_76_1)))
(assert
 (not (and d_76_0 d_76_2)))
(assert
 (not (and d_76_0 d_76_3)))
(assert
 (not (and d_76_0 d_76_4)))
(assert
 (not (and d_76_0 d_76_5)))
(assert
 (not (and d_76_0 d_76_6)))
(assert
 (not (and d_76_0 d_76_7)))
(assert
 (not (and d_76_0 d_76_8)))
(assert
 (not (and d_76_1 d_76_2)))
(assert
 (not (and d_76_1 d_76_3)))
(assert
 (not (and d_76_1 d_76_4)))
(assert
 (not (and d_76_1 d_76_5)))
(assert
 (not (and d_76_1 d_76_6)))
(assert
 (not (and d_76_1 d_76_7)))
(assert
 (not (and d_76_1 d_76_8)))
(assert
 (not (and d_76_2 d_76_3)))
(assert
 (not (and d_76_2 d_76_4)))
(assert
 (not (and d_76_2 d_76_5)))
(assert
 (not (and d_76_2 d_76_6)))
(assert
 (not (and d_76_2 d_76_7)))
(assert
 (not (and d_76_2 d_76_8)))
(assert
 (not (and d_76_3 d_76_4)))
(assert
 (not (and d_76_3 d_76_5)))
(assert
 (not (and d_76_3 d_76_6)))
(assert
 (not (and d_76_3 d_76_7)))
(assert
 (not (and d_76_3 d_76_8)))
(assert
 (not (and d_76_4 d_76_5)))
(assert
 (not (and d_76_4 d_76_6)))
(assert
 (not (and d_76_4 d_76_7)))
(assert
 (not (and d_76_4 d_76_8)))
(assert
 (not (and d_76_5 d_76_6)))
(assert
 (not (and d_76_5 d_76_7)))
(assert
 (not (and d_76_5 d_76_8)))
(assert
 (not (and d_76_6 d_76_7)))
(assert
 (not (and d_76_6 d_76_8)))
(assert
 (not (and d_76_7 d_76_8)))
(assert
 (let (($x15217 (or false d_77_0)))
 (let (($x15219 (or $x15217 d_77_1)))
 (let (($x15221 (or $x15219 d_77_2)))
 (let (($x15223 (or $x15221 d_77_3)))
 (let (($x15225 (or $x15223 d_77_4)))
 (let (($x15227 (or $x15225 d_77_5)))
 (let (($x15229 (or $x15227 d_77_6)))
 (let (($x15231 (or $x15229 d_77_7)))
 (or $x15231 d_77_8))))))))))
(assert
 (not (and d_77_0 d_77_1)))
(assert
 (not (and d_77_0 d_77_2)))
(assert
 (not (and d_77_0 d_77_3)))
(assert
 (not (and d_77_0 d_77_4)))
(assert
 (not (and d_77_0 d_77_5)))
(assert
 (not (and d_77_0 d_77_6)))
(assert
 (not (and d_77_0 d_77_7)))
(assert
 (not (and d_77_0 d_77_8)))
(assert
 (not (and d_77_1 d_77_2)))
(assert
 (not (and d_77_1 d_77_3)))
(assert
 (not (and d_77_1 d_77_4)))
(assert
 (not (and d_77_1 d_77_5)))
(assert
 (not (and d_77_1 d_77_6)))
(assert
 (not (and d_77_1 d_77_7)))
(assert
 (not (and d_77_1 d_77_8)))
(assert
 (not (and d_77_2 d_77_3)))
(assert
 (not (and d_77_2 d_77_4)))
(assert
 (not (and d_77_2 d_77_5)))
(assert
 (not (and d_77_2 d_77_6)))
(assert
 (not (and d_77_2 d_77_7)))
(assert
 (not (and d_77_2 d_77_8)))
(assert
 (not (and d_77_3 d_77_4)))
(assert
 (not (and d_77_3 d_77_5)))
(assert
 (not (and d_77_3 d_77_6)))
(assert
 (not (and d_77_3 d_77_7)))
(assert
 (not (and d_77_3 d_77_8)))
(assert
 (not (and d_77_4 d_77_5)))
(assert
 (not (and d_77_4 d_77_6)))
(assert
 (not (and d_77_4 d_77_7)))
(assert
 (not (and d_77_4 d_77_8)))
(assert
 (not (and d_77_5 d_77_6)))
(assert
 (not (and d_77_5 d_77_7)))
(assert
 (not (and d_77_5 d_77_8)))
(assert
 (not (and d_77_6 d_77_7)))
(assert
 (not (and d_77_6 d_77_8)))
(assert
 (not (and d_77_7 d_77_8)))
(assert
 (let (($x15307 (or false d_78_0)))
 (let (($x15309 (or $x15307 d_78_1)))
 (let (($x15311 (or $x15309 d_78_2)))
 (let (($x15313 (or $x15311 d_78_3)))
 (let (($x15315 (or $x15313 d_78_4)))
 (let (($x15317 (or $x15315 d_78_5)))
 (let (($x15319 (or $x15317 d_78_6)))
 (let (($x15321 (or $x15319 d_78_7)))
 (or $x15321 d_78_8))))))))))
(assert
 (not (and d_78_0 d_78_1)))
(assert
 (not (and d_78_0 d_78_2)))
(assert
 (not (and d_78_0 d_78_3)))
(assert
 (not (and d_78_0 d_78_4)))
(assert
 (not (and d_78_0 d_78_5)))
(assert
 (not (and d_78_0 d_78_6)))
(assert
 (not (and d_78_0 d_78_7)))
(assert
 (not (and d_78_0 d_78_8)))
(assert
 (not (and d_78_1 d_78_2)))
(assert
 (not (and d_78_1 d_78_3)))
(assert
 (not (and d_78_1 d_78_4)))
(assert
 (not (and d_78_1 d_78_5)))
(assert
 (not (and d_78_1 d_78_6)))
(assert
 (not (and d_78_1 d_78_7)))
(assert
 (not (and d_78_1 d_78_8)))
(assert
 (not (and d_78_2 d_78_3)))
(assert
 (not (and d_78_2 d_78_4)))
(assert
 (not (and d_78_2 d_78_5)))
(assert
 (not (and d_78_2 d_78_6)))
(assert
 (not (and d_78_2 d_78_7)))
(assert
 (not (and d_78_2 d_78_8)))
(assert
 (not (and d_78_3 d_78_4)))
(assert
 (not (and d_78_3 d_78_5)))
(assert
 (not (and d_78_3 d_78_6)))
(assert
 (not (and d_78_3 d_78_7)))
(assert
 (not (and d_78_3 d_78_8)))
(assert
 (not (and d_78_4 d_78_5)))
(assert
 (not (and d_78_4 d_78_6)))
(assert
 (not (and d_78_4 d_78_7)))
(assert
 (not (and d_78_4 d_78_8)))
(assert
 (not (and d_78_5 d_78_6)))
(assert
 (not (and d_78_5 d_78_7)))
(assert
 (not (and d_78_5 d_78_8)))
(assert
 (not (and d_78_6 d_78_7)))
(assert
 (not (and d_78_6 d_78_8)))
(assert
 (not (and d_78_7 d_78_8)))
(assert
 (let (($x15397 (or false d_79_0)))
 (let (($x15399 (or $x15397 d_79_1)))
 (let (($x15401 (or $x15399 d_79_2)))
 (let (($x15403 (or $x15401 d_79_3)))
 (let (($x15405 (or $x15403 d_79_4)))
 (let (($x15407 (or $x15405 d_79_5)))
 (let (($x15409 (or $x15407 d_79_6)))
 (let (($x15411 (or $x15409 d_79_7)))
 (or $x15411 d_79_8))))))))))
(assert
 (not (and d_79_0 d_79_1)))
(assert
 (not (and d_79_0 d_79_2)))
(assert
 (not (and d_79_0 d_79_3)))
(assert
 (not (and d_79_0 d_79_4)))
(assert
 (not (and d_79_0 d_79_5)))
(assert
 (not (and d_79_0 d_79_6)))
(assert
 (not (and d_79_0 d_79_7)))
(assert
 (not (and d_79_0 d_79_8)))
(assert
 (not (and d_79_1 d_79_2)))
(assert
 (not (and d_79_1 d_79_3)))
(assert
 (not (and d_79_1 d_79_4)))
(assert
 (not (and d_79_1 d_79_5)))
(assert
 (not (and d_79_1 d_79_6)))
(assert
 (not (and d_79_1 d_79_7)))
(assert
 (not (and d_79_1 d_79_8)))
(assert
 (not (and d_79_2 d_79_3)))
(assert
 (not (and d_79_2 d_79_4)))
(assert
 (not (and d_79_2 d_79_5)))
(assert
 (not (and d_79_2 d_79_6)))
(assert
 (not (and d_79_2 d_79_7)))
(assert
 (not (and d_79_2 d_79_8)))
(assert
 (not (and d_79_3 d_79_4)))
(assert
 (not (and d_79_3 d_79_5)))
(assert
 (not (and d_79_3 d_79_6)))
(assert
 (not (and d_79_3 d_79_7)))
(assert
 (not (and d_79_3 d_79_8)))
(assert
 (not (and d_79_4 d_79_5)))
(assert
 (not (and d_79_4 d_79_6)))
(assert
 (not (and d_79_4 d_79_7)))
(assert
 (not (and d_79_4 d_79_8)))
(assert
 (not (and d_79_5 d_79_6)))
(assert
 (not (and d_79_5 d_79_7)))
(assert
 (not (and d_79_5 d_79_8)))
(assert
 (not (and d_79_6 d_79_7)))
(assert
 (not (and d_79_6 d_79_8)))
(assert
 (not (and d_79_7 d_79_8)))
(assert
 (let (($x15487 (or false d_80_0)))
 (let (($x15489 (or $x15487 d_80_1)))
 (let (($x15491 (or $x15489 d_80_2)))
 (let (($x15493 (or $x15491 d_80_3)))
 (let (($x15495 (or $x15493 d_80_4)))
 (let (($x15497 (or $x15495 d_80_5)))
 (let (($x15499 (or $x15497 d_80_6)))
 (let (($x15501 (or $x15499 d_80_7)))
 (or $x15501 d_80_8))))))))))
(assert
 (not (and d_80_0 d_80_1)))
(assert
 (not (and d_80_0 d_80_2)))
(assert
 (not (and d_80_0 d_80_3)))
(assert
 (not (and d_80_0 d_80_4)))
(assert
 (not (and d_80_0 d_80_5)))
(assert
 (not (and d_80_0 d_80_6)))
(assert
 (not (and d_80_0 d_80_7)))
(assert
 (not (and d_80_0 d_80_8)))
(assert
 (not (and d_80_1 d_80_2)))
(assert
 (not (and d_80_1 d_80_3)))
(assert
 (not (and d_80_1 d_80_4)))
(assert
 (not (and d_80_1 d_80_5)))
(assert
 (not (and d_80_1 d_80_6)))
(assert
 (not (and d_80_1 d_80_7)))
(assert
 (not (and d_80_1 d_80_8)))
(assert
 (not (and d_80_2 d_80_3)))
(assert
 (not (and d_80_2 d_80_4)))
(assert
 (not (and d_80_2 d_80_5)))
(assert
 (not (and d_80_2 d_80_6)))
(assert
 (not (and d_80_2 d_80_7)))
(assert
 (not (and d_80_2 d_80_8)))
(assert
 (not (and d_80_3 d_80_4)))
(assert
 (not (and d_80_3 d_80_5)))
(assert
 (not (and d_80_3 d_80_6)))
(assert
 (not (and d_80_3 d_80_7)))
(assert
 (not (and d_80_3 d_80_8)))
(assert
 (not (and d_80_4 d_80_5)))
(assert
 (not (and d_80_4 d_80_6)))
(assert
 (not (and d_80_4 d_80_7)))
(assert
 (not (and d_80_4 d_80_8)))
(assert
 (not (and d_80_5 d_80_6)))
(assert
 (not (and d_80_5 d_80_7)))
(assert
 (not (and d_80_5 d_80_8)))
(assert
 (not (and d_80_6 d_80_7)))
(assert
 (not (and d_80_6 d_80_8)))
(assert
 (not (and d_80_7 d_80_8)))
(assert
 (let (($x15577 (or false d_81_0)))
 (let (($x15579 (or $x15577 d_81_1)))
 (let (($x15581 (or $x15579 d_81_2)))
 (let (($x15583 (or $x15581 d_81_3)))
 (let (($x15585 (or $x15583 d_81_4)))
 (let (($x15587 (or $x15585 d_81_5)))
 (let (($x15589 (or $x15587 d_81_6)))
 (let (($x15591 (or $x15589 d_81_7)))
 (or $x15591 d_81_8))))))))))
(assert
 (not (and d_81_0 d_81_1)))
(assert
 (not (and d_81_0 d_81_2)))
(assert
 (not (and d_81_0 d_81_3)))
(assert
 (not (and d_81_0 d_81_4)))
(assert
 (not (and d_81_0 d_81_5)))
(assert
 (not (and d_81_0 d_81_6)))
(assert
 (not (and d_81_0 d_81_7)))
(assert
 (not (and d_81_0 d_81_8)))
(assert
 (not (and d_81_1 d_81_2)))
(assert
 (not (and d_81_1 d_81_3)))
(assert
 (not (and d_81_1 d_81_4)))
(assert
 (not (and d_81_1 d_81_5)))
(assert
 (not (and d_81_1 d_81_6)))
(assert
 (not (and d_81_1 d_81_7)))
(assert
 (not (and d_81_1 d_81_8)))
(assert
 (not (and d_81_2 d_81_3)))
(assert
 (not (and d_81_2 d_81_4)))
(assert
 (not (and d_81_2 d_81_5)))
(assert
 (not (and d_81_2 d_81_6)))
(assert
 (not (and d_81_2 d_81_7)))
(assert
 (not (and d_81_2 d_81_8)))
(assert
 (not (and d_81_3 d_81_4)))
(assert
 (not (and d_81_3 d_81_5)))
(assert
 (not (and d_81_3 d_81_6)))
(assert
 (not (and d_81_3 d_81_7)))
(assert
 (not (and d_81_3 d_81_8)))
(assert
 (not (and d_81_4 d_81_5)))
(assert
 (not (and d_81_4 d_81_6)))
(assert
 (not (and d_81_4 d_81_7)))
(assert
 (not (and d_81_4 d_81_8)))
(assert
 (not (and d_81_5 d_81_6)))
(assert
 (not (and d_81_5 d_81_7)))
(assert
 (not (and d_81_5 d_81_8)))
(assert
 (not (and d_81_6 d_81_7)))
(assert
 (not (and d_81_6 d_81_8)))
(assert
 (not (and d_81_7 d_81_8)))
(assert
 (let (($x15667 (or false d_82_0)))
 (let (($x15669 (or $x15667 d_82_1)))
 (let (($x15671 (or $x15669 d_82_2)))
 (let (($x15673 (or $x15671 d_82_3)))
 (let (($x15675 (or $x15673 d_82_4)))
 (let (($x15677 (or $x15675 d_82_5)))
 (let (($x15679 (or $x15677 d_82_6)))
 (let (($x15681 (or $x15679 d_82_7)))
 (or $x15681 d_82_8))))))))))
(assert
 (not (and d_82_0 d_82_1)))
(assert
 (not (and d_82_0 d_82_2)))
(assert
 (not (and d_82_0 d_82_3)))
(assert
 (not (and d_82_0 d_82_4)))
(assert
 (not (and d_82_0 d_82_5)))
(assert
 (not (and d_82_0 d_82_6)))
(assert
 (not (and d_82_0 d_82_7)))
(assert
 (not (and d_82_0 d_82_8)))
(assert
 (not (and d_82_1 d_82_2)))
(assert
 (not (and d_82_1 d_82_3)))
(assert
 (not (and d_82_1 d_82_4)))
(assert
 (not (and d_82_1 d_82_5)))
(assert
 (not (and d_82_1 d_82_6)))
(assert
 (not (and d_82_1 d_82_7)))
(assert
 (not (and d_82_1 d_82_8)))
(assert
 (not (and d_82_2 d_82_3)))
(assert
 (not (and d_82_2 d_82_4)))
(assert
 (not (and d_82_2 d_82_5)))
(assert
 (not (and d_82_2 d_82_6)))
(assert
 (not (and d_82_2 d_82_7)))
(assert
 (not (and d_82_2 d_82_8)))
(assert
 (not (and d_82_3 d_82_4)))
(assert
 (not (and d_82_3 d_82_5)))
(assert
 (not (and d_82_3 d_82_6)))
(assert
 (not (and d_82_3 d_82_7)))
(assert
 (not (and d_82_3 d_82_8)))
(assert
 (not (and d_82_4 d_82_5)))
(assert
 (not (and d_82_4 d_82_6)))
(assert
 (not (and d_82_4 d_82_7)))
(assert
 (not (and d_82_4 d_82_8)))
(assert
 (not (and d_82_5 d_82_6)))
(assert
 (not (and d_82_5 d_82_7)))
(assert
 (not (and d_82_5 d_82_8)))
(assert
 (not (and d_82_6 d_82_7)))
(assert
 (not (and d_82_6 d_82_8)))
(assert
 (not (and d_82_7 d_82_8)))
(assert
 (let (($x15757 (or false d_83_0)))
 (let (($x15759 (or $x15757 d_83_1)))
 (let (($x15761 (or $x15759 d_83_2)))
 (let (($x15763 (or $x15761 d_83_3)))
 (let (($x15765 (or $x15763 d_83_4)))
 (let (($x15767 (or $x15765 d_83_5)))
 (let (($x15769 (or $x15767 d_83_6)))
 (let (($x15771 (or $x15769 d_83_7)))
 (or $x15771 d_83_8))))))))))
(assert
 (not (and d_83_0 d_83_1)))
(assert
 (not (and d_83_0 d_83_2)))
(assert
 (not (and d_83_0 d_83_3)))
(assert
 (not (and d_83_0 d_83_4)))
(assert
 (not (and d_83_0 d_83_5)))
(assert
 (not (and d_83_0 d_83_6)))
(assert
 (not (and d_83_0 d_83_7)))
(assert
 (not (and d_83_0 d_83_8)))
(assert
 (not (and d_83_1 d_83_2)))
(assert
 (not (and d_83_1 d_83_3)))
(assert
 (not (and d_83_1 d_83_4)))
(assert
 (not (and d_83_1 d_83_5)))
(assert
 (not (and d_83_1 d_83_6)))
(assert
 (not (and d_83_1 d_83_7)))
(assert
 (not (and d_83_1 d_83_8)))
(assert
 (not (and d_83_2 d_83_3)))
(assert
 (not (and d_83_2 d_83_4)))
(assert
 (not (and d_83_2 d_83_5)))
(assert
 (not (and d_83_2 d_83_6)))
(assert
 (not (and d_83_2 d_83_7)))
(assert
 (not (and d_83_2 d_83_8)))
(assert
 (not (and d_83_3 d_83_4)))
(assert
 (not (and d_83_3 d_83_5)))
(assert
 (not (and d_83_3 d_83_6)))
(assert
 (not (and d_83_3 d_83_7)))
(assert
 (not (and d_83_3 d_83_8)))
(assert
 (not (and d_83_4 d_83_5)))
(assert
 (not (and d_83_4 d_83_6)))
(assert
 (not (and d_83_4 d_83_7)))
(assert
 (not (and d_83_4 d_83_8)))
(assert
 (not (and d_83_5 d_83_6)))
(assert
 (not (and d_83_5 d_83_7)))
(assert
 (not (and d_83_5 d_83_8)))
(assert
 (not (and d_83_6 d_83_7)))
(assert
 (not (and d_83_6 d_83_8)))
(assert
 (not (and d_83_7 d_83_8)))
(assert
 (let (($x15847 (or false d_84_0)))
 (let (($x15849 (or $x15847 d_84_1)))
 (let (($x15851 (or $x15849 d_84_2)))
 (let (($x15853 (or $x15851 d_84_3)))
 (let (($x15855 (or $x15853 d_84_4)))
 (let (($x15857 (or $x15855 d_84_5)))
 (let (($x15859 (or $x15857 d_84_6)))
 (let (($x15861 (or $x15859 d_84_7)))
 (or $x15861 d_84_8))))))))))
(assert
 (not (and d_84_0 d_84_1)))
(assert
 (not (and d_84_0 d_84_2)))
(assert
 (not (and d_84_0 d_84_3)))
(assert
 (not (and d_84_0 d_84_4)))
(assert
 (not (and d_84_0 d_84_5)))
(assert
 (not (and d_84_0 d_84_6)))
(assert
 (not (and d_84_0 d_84_7)))
(assert
 (not (and d_84_0 d_84_8)))
(assert
 (not (and d_84_1 d_84_2)))
(assert
 (not (and d_84_1 d_84_3)))
(assert
 (not (and d_84_1 d_84_4)))
(assert
 (not (and d_84_1 d_84_5)))
(assert
 (not (and d_84_1 d_84_6)))
(assert
 (not (and d_84_1 d_84_7)))
(assert
 (not (and d_84_1 d_84_8)))
(assert
 (not (and d_84_2 d_84_3)))
(assert
 (not (and d_84_2 d_84_4)))
(assert
 (not (and d_84_2 d_84_5)))
(assert
 (not (and d_84_2 d_84_6)))
(assert
 (not (and d_84_2 d_84_7)))
(assert
 (not (and d_84_2 d_84_8)))
(assert
 (not (and d_84_3 d_84_4)))
(assert
 (not (and d_84_3 d_84_5)))
(assert
 (not (and d_84_3 d_84_6)))
(assert
 (not (and d_84_3 d_84_7)))
(assert
 (not (and d_84_3 d_84_8)))
(assert
 (not (and d_84_4 d_84_5)))
(assert
 (not (and d_84_4 d_84_6)))
(assert
 (not (and d_84_4 d_84_7)))
(assert
 (not (and d_84_4 d_84_8)))
(assert
 (not (and d_84_5 d_84_6)))
(assert
 (not (and d_84_5 d_84_7)))
(assert
 (not (and d_84_5 d_84_8)))
(assert
 (not (and d_84_6 d_84_7)))
(assert
 (not (and d_84_6 d_84_8)))
(assert
 (not (and d_84_7 d_84_8)))
(assert
 (let (($x15937 (or false d_85_0)))
 (let (($x15939 (or $x15937 d_85_1)))
 (let (($x15941 (or $x15939 d_85_2)))
 (let (($x15943 (or $x15941 d_85_3)))
 (let (($x15945 (or $x15943 d_85_4)))
 (let (($x15947 (or $x15945 d_85_5)))
 (let (($x15949 (or $x15947 d_85_6)))
 (let (($x15951 (or $x15949 d_85_7)))
 (or $x15951 d_85_8))))))))))
(assert
 (not (and d_85_0 d_85_1)))
(assert
 (not (and d_85_0 d_85_2)))
(assert
 (not (and d_85_0 d_85_3)))
(assert
 (not (and d_85_0 d_85_4)))
(assert
 (not (and d_85_0 d_85_5)))
(assert
 (not (and d_85_0 d_85_6)))
(assert
 (not (and d_85_0 d_85_7)))
(assert
 (not (and d_85_0 d_85_8)))
(assert
 (not (and d_85_1 d_85_2)))
(assert
 (not (and d_85_1 d_85_3)))
(assert
 (not (and d_85_1 d_85_4)))
(assert
 (not (and d_85_1 d_85_5)))
(assert
 (not (and d_85_1 d_85_6)))
(assert
 (not (and d_85_1 d_85_7)))
(assert
 (not (and d_85_1 d_85_8)))
(assert
 (not (and d_85_2 d_85_3)))
(assert
 (not (and d_85_2 d_85_4)))
(assert
 (not (and d_85_2 d_85_5)))
(assert
 (not (and d_85_2 d_85_6)))
(assert
 (not (and d_85_2 d_85_7)))
(assert
 (not (and d_85_2 d_85_8)))
(assert
 (not (and d_85_3 d_85_4)))
(assert
 (not (and d_85_3 d_85_5)))
(assert
 (not (and d_85_3 d_85_6)))
(assert
 (not (and d_85_3 d_85_7)))
(assert
 (not (and d_85_3 d_85_8)))
(assert
 (not (and d_85_4 d_85_5)))
(assert
 (not (and d_85_4 d_85_6)))
(assert
 (not (and d_85_4 d_85_7)))
(assert
 (not (and d_85_4 d_85_8)))
(assert
 (not (and d_85_5 d_85_6)))
(assert
 (not (and d_85_5 d_85_7)))
(assert
 (not (and d_85_5 d_85_8)))
(assert
 (not (and d_85_6 d_85_7)))
(assert
 (not (and d_85_6 d_85_8)))
(assert
 (not (and d_85_7 d_85_8)))
(assert
 (let (($x16027 (or false d_86_0)))
 (let (($x16029 (or $x16027 d_86_1)))
 (let (($x16031 (or $x16029 d_86_2)))
 (let (($x16033 (or $x16031 d_86_3)))
 (let (($x16035 (or $x16033 d_86_4)))
 (let (($x16037 (or $x16035 d_86_5)))
 (let (($x16039 (or $x16037 d_86_6)))
 (let (($x16041 (or $x16039 d_86_7)))
 (or $x16041 d_86_8))))))))))
(assert
 (not (and d_86_0 d_86_1)))
(assert
 (not (and d_86_0 d_86_2)))
(assert
 (not (and d_86_0 d_86_3)))
(assert
 (not (and d_86_0 d_86_4)))
(assert
 (not (and d_86_0 d_86_5)))
(assert
 (not (and d_86_0 d_86_6)))
(assert
 (not (and d_86_0 d_86_7)))
(assert
 (not (and d_86_0 d_86_8)))
(assert
 (not (and d_86_1 d_86_2)))
(assert
 (not (and d_86_1 d_86_3)))
(assert
 (not (and d_86_1 d_86_4)))
(assert
 (not (and d_86_1 d_86_5)))
(assert
 (not (and d_86_1 d_86_6)))
(assert
 (not (and d_86_1 d_86_7)))
(assert
 (not (and d_86_1 d_86_8)))
(assert
 (not (and d_86_2 d_86_3)))
(assert
 (not (and d_86_2 d_86_4)))
(assert
 (not (and d_86_2 d_86_5)))
(assert
 (not (and d_86_2 d_86_6)))
(assert
 (not (and d_86_2 d_86_7)))
(assert
 (not (and d_86_2 d_86_8)))
(assert
 (not (and d_86_3 d_86_4)))
(assert
 (not (and d_86_3 d_86_5)))
(assert
 (not (and d_86_3 d_86_6)))
(assert
 (not (and d_86_3 d_86_7)))
(assert
 (not (and d_86_3 d_86_8)))
(assert
 (not (and d_86_4 d_86_5)))
(assert
 (not (and d_86_4 d_86_6)))
(assert
 (not (and d_86_4 d_86_7)))
(assert
 (not (and d_86_4 d_86_8)))
(assert
 (not (and d_86_5 d_86_6)))
(assert
 (not (and d_86_5 d_86_7)))
(assert
 (not (and d_86_5 d_86_8)))
(assert
 (not (and d_86_6 d_86_7)))
(assert
 (not (and d_86_6 d_86_8)))
(assert
 (not (and d_86_7 d_86_8)))
(assert
 (let (($x16117 (or false d_87_0)))
 (let (($x16119 (or $x16117 d_87_1)))
 (let (($x16121 (or $x16119 d_87_2)))
 (let (($x16123 (or $x16121 d_87_3)))
 (let (($x16125 (or $x16123 d_87_4)))
 (let (($x16127 (or $x16125 d_87_5)))
 (let (($x16129 (or $x16127 d_87_6)))
 (let (($x16131 (or $x16129 d_87_7)))
 (or $x16131 d_87_8))))))))))
(assert
 (not (and d_87_0 d_87_1)))
(assert
 (not (and d_87_0 d_87_2)))
(assert
 (not (and d_87_0 d_87_3)))
(assert
 (not (and d_87_0 d_87_4)))
(assert
 (not (and d_87_0 d_87_5)))
(assert
 (not (and d_87_0 d_87_6)))
(assert
 (not (and d_87_0 d_87_7)))
(assert
 (not (and d_87_0 d_87_8)))
(assert
 (not (and d_87_1 d_87_2)))
(assert
 (not (and d_87_1 d_87_3)))
(assert
 (not (and d_87_1 d_87_4)))
(assert
 (not (and d_87_1 d_87_5)))
(assert
 (not (and d_87_1 d_87_6)))
(assert
 (not (and d_87_1 d_87_7)))
(assert
 (not (and d_87_1 d_87_8)))
(assert
 (not (and d_87_2 d_87_3)))
(assert
 (not (and d_87_2 d_87_4)))
(assert
 (not (and d_87_2 d_87_5)))
(assert
 (not (and d_87_2 d_87_6)))
(assert
 (not (and d_87_2 d_87_7)))
(assert
 (not (and d_87_2 d_87_8)))
(assert
 (not (and d_87_3 d_87_4)))
(assert
 (not (and d_87_3 d_87_5)))
(assert
 (not (and d_87_3 d_87_6)))
(assert
 (not (and d_87_3 d_87_7)))
(assert
 (not (and d_87_3 d_87_8)))
(assert
 (not (and d_87_4 d_87_5)))
(assert
 (not (and d_87_4 d_87_6)))
(assert
 (not (and d_87_4 d_87_7)))
(assert
 (not (and d_87_4 d_87_8)))
(assert
 (not (and d_87_5 d_87_6)))
(assert
 (not (and d_87_5 d_87_7)))
(assert
 (not (and d_87_5 d_87_8)))
(assert
 (not (and d_87_6 d_87_7)))
(assert
 (not (and d_87_6 d_87_8)))
(assert
 (not (and d_87_7 d_87_8)))
(assert
 (let (($x16207 (or false d_88_0)))
 (let (($x16209 (or $x16207 d_88_1)))
 (let (($x16211 (or $x16209 d_88_2)))
 (let (($x16213 (or $x16211 d_88_3)))
 (let (($x16215 (or $x16213 d_88_4)))
 (let (($x16217 (or $x16215 d_88_5)))
 (let (($x16219 (or $x16217 d_88_6)))
 (let (($x16221 (or $x16219 d_88_7)))
 (or $x16221 d_88_8))))))))))
(assert
 (not (and d_88_0 d_88_1)))
(assert
 (not (and d_88_0 d_88_2)))
(assert
 (not (and d_88_0 d_88_3)))
(assert
 (not (and d_88_0 d_88_4)))
(assert
 (not (and d_88_0 d_88_5)))
(assert
 (not (and d_88_0 d_88_6)))
(assert
 (not (and d_88_0 d_88_7)))
(assert
 (not (and d_88_0 d_88_8)))
(assert
 (not (and d_88_1 d_88_2)))
(assert
 (not (and d_88_1 d_88_3)))
(assert
 (not (and d_88_1 d_88_4)))
(assert
 (not (and d_88_1 d_88_5)))
(assert
 (not (and d_88_1 d_88_6)))
(assert
 (not (and d_88_1 d_88_7)))
(assert
 (not (and d_88_1 d_88_8)))
(assert
 (not (and d_88_2 d_88_3)))
(assert
 (not (and d_88_2 d_88_4)))
(assert
 (not (and d_88_2 d_88_5)))
(assert
 (not (and d_88_2 d_88_6)))
(assert
 (not (and d_88_2 d_88_7)))
(assert
 (not (and d_88_2 d_88_8)))
(assert
 (not (and d_88_3 d_88_4)))
(assert
 (not (and d_88_3 d_88_5)))
(assert
 (not (and d_88_3 d_88_6)))
(assert
 (not (and d_88_3 d_88_7)))
(assert
 (not (and d_88_3 d_88_8)))
(assert
 (not (and d_88_4 d_88_5)))
(assert
 (not (and d_88_4 d_88_6)))
(assert
 (not (and d_88_4 d_88_7)))
(assert
 (not (and d_88_4 d_88_8)))
(assert
 (not (and d_88_5 d_88_6)))
(assert
 (not (and d_88_5 d_88_7)))
(assert
 (not (and d_88_5 d_88_8)))
(assert
 (not (and d_88_6 d_88_7)))
(assert
 (not (and d_88_6 d_88_8)))
(assert
 (not (and d_88_7 d_88_8)))
(assert
 (let (($x16297 (or false d_89_0)))
 (let (($x16299 (or $x16297 d_89_1)))
 (let (($x16301 (or $x16299 d_89_2)))
 (let (($x16303 (or $x16301 d_89_3)))
 (let (($x16305 (or $x16303 d_89_4)))
 (let (($x16307 (or $x16305 d_89_5)))
 (let (($x16309 (or $x16307 d_89_6)))
 (let (($x16311 (or $x16309 d_89_7)))
 (or $x16311 d_89_8))))))))))
(assert
 (not (and d_89_0 d_89_1)))
(assert
 (not (and d_89_0 d_89_2)))
(assert
 (not (and d_89_0 d_89_3)))
(assert
 (not (and d_89_0 d_89_4)))
(assert
 (not (and d_89_0 d_89_5)))
(assert
 (not (and d_89_0 d_89_6)))
(assert
 (not (and d_89_0 d_89_7)))
(assert
 (not (and d_89_0 d_89_8)))
(assert
 (not (and d_89_1 d_89_2)))
(assert
 (not (and d_89_1 d_89_3)))
(assert
 (not (and d_89_1 d_89_4)))
(assert
 (not (and d_89_1 d_89_5)))
(assert
 (not (and d_89_1 d_89_6)))
(assert
 (not (and d_89_1 d_89_7)))
(assert
 (not (and d_89_1 d_89_8)))
(assert
 (not (and d_89_2 d_89_3)))
(assert
 (not (and d_89_2 d_89_4)))
(assert
 (not (and d_89_2 d_89_5)))
(assert
 (not (and d_89_2 d_89_6)))
(assert
 (not (and d_89_2 d_89_7)))
(assert
 (not (and d_89_2 d_89_8)))
(assert
 (not (and d_89_3 d_89_4)))
(assert
 (not (and d_89_3 d_89_5)))
(assert
 (not (and d_89_3 d_89_6)))
(assert
 (not (and d_89_3 d_89_7)))
(assert
 (not (and d_89_3 d_89_8)))
(assert
 (not (and d_89_4 d_89_5)))
(assert
 (not (and d_89_4 d_89_6)))
(assert
 (not (and d_89_4 d_89_7)))
(assert
 (not (and d_89_4 d_89_8)))
(assert
 (not (and d_89_5 d_89_6)))
(assert
 (not (and d_89_5 d_89_7)))
(assert
 (not (and d_89_5 d_89_8)))
(assert
 (not (and d_89_6 d_89_7)))
(assert
 (not (and d_89_6 d_89_8)))
(assert
 (not (and d_89_7 d_89_8)))
(assert
 (let (($x16387 (or false d_90_0)))
 (let (($x16389 (or $x16387 d_90_1)))
 (let (($x16391 (or $x16389 d_90_2)))
 (let (($x16393 (or $x16391 d_90_3)))
 (let (($x16395 (or $x16393 d_90_4)))
 (let (($x16397 (or $x16395 d_90_5)))
 (let (($x16399 (or $x16397 d_90_6)))
 (let (($x16401 (or $x16399 d_90_7)))
 (or $x16401 d_90_8))))))))))
(assert
 (not (and d_90_0 d_90_1)))
(assert
 (not (and d_90_0 d_90_2)))
(assert
 (not (and d_90_0 d_90_3)))
(assert
 (not (and d_90_0 d_90_4)))
(assert
 (not (and d_90_0 d_90_5)))
(assert
 (not (and d_90_0 d_90_6)))
(assert
 (not (and d_90_0 d_90_7)))
(assert
 (not (and d_90_0 d_90_8)))
(assert
 (not (and d_90_1 d_90_2)))
(assert
 (not (and d_90_1 d_90_3)))
(assert
 (not (and d_90_1 d_90_4)))
(assert
 (not (and d_90_1 d_90_5)))
(assert
 (not (and d_90_1 d_90_6)))
(assert
 (not (and d_90_1 d_90_7)))
(assert
 (not (and d_90_1 d_90_8)))
(assert
 (not (and d_90_2 d_90_3)))
(assert
 (not (and d_90_2 d_90_4)))
(assert
 (not (and d_90_2 d_90_5)))
(assert
 (not (and d_90_2 d_90_6)))
(assert
 (not (and d_90_2 d_90_7)))
(assert
 (not (and d_90_2 d_90_8)))
(assert
 (not (and d_90_3 d_90_4)))
(assert
 (not (and d_90_3 d_90_5)))
(assert
 (not (and d_90_3 d_90_6)))
(assert
 (not (and d_90_3 d_90_7)))
(assert
 (not (and d_90_3 d_90_8)))
(assert
 (not (and d_90_4 d_90_5)))
(assert
 (not (and d_90_4 d_90_6)))
(assert
 (not (and d_90_4 d_90_7)))
(assert
 (not (and d_90_4 d_90_8)))
(assert
 (not (and d_90_5 d_90_6)))
(assert
 (not (and d_90_5 d_90_7)))
(assert
 (not (and d_90_5 d_90_8)))
(assert
 (not (and d_90_6 d_90_7)))
(assert
 (not (and d_90_6 d_90_8)))
(assert
 (not (and d_90_7 d_90_8)))
(assert
 (let (($x22207 (and c_0_8 in_target_0)))
 (let (($x22205 (and c_0_7 in_target_0)))
 (let (($x22203 (and c_0_6 in_target_0)))
 (let (($x22201 (and c_0_5 in_target_0)))
 (let (($x22199 (and c_0_4 in_target_0)))
 (let (($x22197 (and c_0_3 in_target_0)))
 (let (($x22195 (and c_0_2 in_target_0)))
 (let (($x22193 (and c_0_1 in_target_0)))
 (let (($x22192 (and c_0_0 in_target_0)))
 (let (($x22208 (or $x22192 $x22193 $x22195 $x22197 $x22199 $x22201 $x22203 $x22205 $x22207)))
 (let (($x22190 (not $x22208)))
 (let (($x22191 (and c_0_8 $x22190)))
 (let (($x27636 (not c_6_1)))
 (let (($x17324 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_7)))
 (let (($x27623 (not $x17324)))
 (let (($x22508 (and c_6_8 in_target_6)))
 (let (($x22506 (and c_6_7 in_target_6)))
 (let (($x22504 (and c_6_6 in_target_6)))
 (let (($x22502 (and c_6_5 in_target_6)))
 (let (($x22500 (and c_6_4 in_target_6)))
 (let (($x22498 (and c_6_3 in_target_6)))
 (let (($x22496 (and c_6_2 in_target_6)))
 (let (($x22494 (and c_6_1 in_target_6)))
 (let (($x22493 (and c_6_0 in_target_6)))
 (let (($x22509 (or $x22493 $x22494 $x22496 $x22498 $x22500 $x22502 $x22504 $x22506 $x22508)))
 (let (($x27628 (and $x22509 $x27623)))
 (let (($x27637 (and $x27628 $x27636)))
 (let (($x27619 (and c_6_1 $x27623)))
 (let (($x27621 (or false $x17324)))
 (let (($x27630 (or $x27621 $x27619)))
 (let (($x27438 (not c_0_1)))
 (let (($x17338 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7)))
 (let (($x27440 (not $x17338)))
 (let (($x27421 (and true $x27440)))
 (let (($x27435 (and $x27421 $x27438)))
 (let (($x27433 (and $x27435 $x22190)))
 (let (($x27607 (not (or (and c_6_0 (not in_target_6)) $x22508))))
 (let (($x27613 (and in_region_6 $x27607)))
 (let (($x27638 (and (and $x27613 (and (and $x22208 $x27440) $x27438)) (or $x27630 (and $x27637 (< ghost_2_6 ghost_2_0))))))
 (let (($x27626 (and (and $x27613 (and c_0_1 $x27440)) (or $x27621 (and $x27619 (< ghost_1_6 ghost_1_0))))))
 (let (($x27604 (not c_5_1)))
 (let (($x17310 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7)))
 (let (($x27587 (not $x17310)))
 (let (($x22473 (and c_5_8 in_target_5)))
 (let (($x22471 (and c_5_7 in_target_5)))
 (let (($x22469 (and c_5_6 in_target_5)))
 (let (($x22467 (and c_5_5 in_target_5)))
 (let (($x22465 (and c_5_4 in_target_5)))
 (let (($x22463 (and c_5_3 in_target_5)))
 (let (($x22461 (and c_5_2 in_target_5)))
 (let (($x22459 (and c_5_1 in_target_5)))
 (let (($x22458 (and c_5_0 in_target_5)))
 (let (($x22474 (or $x22458 $x22459 $x22461 $x22463 $x22465 $x22467 $x22469 $x22471 $x22473)))
 (let (($x27596 (and $x22474 $x27587)))
 (let (($x27603 (and $x27596 $x27604)))
 (let (($x27590 (and c_5_1 $x27587)))
 (let (($x27586 (or false $x17310)))
 (let (($x27595 (or $x27586 $x27590)))
 (let (($x27579 (not (or (and c_5_0 (not in_target_5)) $x22473))))
 (let (($x27578 (and in_region_5 $x27579)))
 (let (($x27598 (and (and $x27578 (and (and $x22208 $x27440) $x27438)) (or $x27595 (and $x27603 (< ghost_2_5 ghost_2_0))))))
 (let (($x27593 (and (and $x27578 (and c_0_1 $x27440)) (or $x27586 (and $x27590 (< ghost_1_5 ghost_1_0))))))
 (let (($x27565 (not c_4_1)))
 (let (($x17296 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7)))
 (let (($x27557 (not $x17296)))
 (let (($x22438 (and c_4_8 in_target_4)))
 (let (($x22436 (and c_4_7 in_target_4)))
 (let (($x22434 (and c_4_6 in_target_4)))
 (let (($x22432 (and c_4_5 in_target_4)))
 (let (($x22430 (and c_4_4 in_target_4)))
 (let (($x22428 (and c_4_3 in_target_4)))
 (let (($x22426 (and c_4_2 in_target_4)))
 (let (($x22424 (and c_4_1 in_target_4)))
 (let (($x22423 (and c_4_0 in_target_4)))
 (let (($x22439 (or $x22423 $x22424 $x22426 $x22428 $x22430 $x22432 $x22434 $x22436 $x22438)))
 (let (($x27563 (and $x22439 $x27557)))
 (let (($x27567 (and $x27563 $x27565)))
 (let (($x27556 (and c_4_1 $x27557)))
 (let (($x27555 (or false $x17296)))
 (let (($x27564 (or $x27555 $x27556)))
 (let (($x27547 (not (or (and c_4_0 (not in_target_4)) $x22438))))
 (let (($x27543 (and in_region_4 $x27547)))
 (let (($x27569 (and (and $x27543 (and (and $x22208 $x27440) $x27438)) (or $x27564 (and $x27567 (< ghost_2_4 ghost_2_0))))))
 (let (($x27560 (and (and $x27543 (and c_0_1 $x27440)) (or $x27555 (and $x27556 (< ghost_1_4 ghost_1_0))))))
 (let (($x27530 (not c_3_1)))
 (let (($x17282 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7)))
 (let (($x27524 (not $x17282)))
 (let (($x22403 (and c_3_8 in_target_3)))
 (let (($x22401 (and c_3_7 in_target_3)))
 (let (($x22399 (and c_3_6 in_target_3)))
 (let (($x22397 (and c_3_5 in_target_3)))
 (let (($x22395 (and c_3_4 in_target_3)))
 (let (($x22393 (and c_3_3 in_target_3)))
 (let (($x22391 (and c_3_2 in_target_3)))
 (let (($x22389 (and c_3_1 in_target_3)))
 (let (($x22388 (and c_3_0 in_target_3)))
 (let (($x22404 (or $x22388 $x22389 $x22391 $x22393 $x22395 $x22397 $x22399 $x22401 $x22403)))
 (let (($x27533 (and $x22404 $x27524)))
 (let (($x27537 (and $x27533 $x27530)))
 (let (($x27521 (and c_3_1 $x27524)))
 (let (($x27522 (or false $x17282)))
 (let (($x27531 (or $x27522 $x27521)))
 (let (($x27514 (not (or (and c_3_0 (not in_target_3)) $x22403))))
 (let (($x27509 (and in_region_3 $x27514)))
 (let (($x27539 (and (and $x27509 (and (and $x22208 $x27440) $x27438)) (or $x27531 (and $x27537 (< ghost_2_3 ghost_2_0))))))
 (let (($x27527 (and (and $x27509 (and c_0_1 $x27440)) (or $x27522 (and $x27521 (< ghost_1_3 ghost_1_0))))))
 (let (($x27497 (not c_2_1)))
 (let (($x17268 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7)))
 (let (($x27491 (not $x17268)))
 (let (($x22368 (and c_2_8 in_target_2)))
 (let (($x22366 (and c_2_7 in_target_2)))
 (let (($x22364 (and c_2_6 in_target_2)))
 (let (($x22362 (and c_2_5 in_target_2)))
 (let (($x22360 (and c_2_4 in_target_2)))
 (let (($x22358 (and c_2_3 in_target_2)))
 (let (($x22356 (and c_2_2 in_target_2)))
 (let (($x22354 (and c_2_1 in_target_2)))
 (let (($x22353 (and c_2_0 in_target_2)))
 (let (($x22369 (or $x22353 $x22354 $x22356 $x22358 $x22360 $x22362 $x22364 $x22366 $x22368)))
 (let (($x27505 (and $x22369 $x27491)))
 (let (($x27504 (and $x27505 $x27497)))
 (let (($x27488 (and c_2_1 $x27491)))
 (let (($x27489 (or false $x17268)))
 (let (($x27498 (or $x27489 $x27488)))
 (let (($x27478 (not (or (and c_2_0 (not in_target_2)) $x22368))))
 (let (($x27479 (and in_region_2 $x27478)))
 (let (($x27506 (and (and $x27479 (and (and $x22208 $x27440) $x27438)) (or $x27498 (and $x27504 (< ghost_2_2 ghost_2_0))))))
 (let (($x27494 (and (and $x27479 (and c_0_1 $x27440)) (or $x27489 (and $x27488 (< ghost_1_2 ghost_1_0))))))
 (let (($x27466 (not c_1_1)))
 (let (($x17254 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7)))
 (let (($x27456 (not $x17254)))
 (let (($x22332 (and c_1_8 in_target_1)))
 (let (($x22330 (and c_1_7 in_target_1)))
 (let (($x22328 (and c_1_6 in_target_1)))
 (let (($x22326 (and c_1_5 in_target_1)))
 (let (($x22324 (and c_1_4 in_target_1)))
 (let (($x22322 (and c_1_3 in_target_1)))
 (let (($x22320 (and c_1_2 in_target_1)))
 (let (($x22318 (and c_1_1 in_target_1)))
 (let (($x22317 (and c_1_0 in_target_1)))
 (let (($x22333 (or $x22317 $x22318 $x22320 $x22322 $x22324 $x22326 $x22328 $x22330 $x22332)))
 (let (($x27473 (and $x22333 $x27456)))
 (let (($x27467 (and $x27473 $x27466)))
 (let (($x27457 (and c_1_1 $x27456)))
 (let (($x27453 (or false $x17254)))
 (let (($x27463 (or $x27453 $x27457)))
 (let (($x27442 (not (or (and c_1_0 (not in_target_1)) $x22332))))
 (let (($x27445 (and in_region_1 $x27442)))
 (let (($x27468 (and (and $x27445 (and (and $x22208 $x27440) $x27438)) (or $x27463 (and $x27467 (< ghost_2_1 ghost_2_0))))))
 (let (($x27459 (and (and $x27445 (and c_0_1 $x27440)) (or $x27453 (and $x27457 (< ghost_1_1 ghost_1_0))))))
 (let (($x27443 (or false (and (and $x27445 $x17338) (or false (and $x17254 c_1_5))))))
 (let (($x27460 (or $x27443 $x27459)))
 (let (($x27471 (or $x27460 $x27468)))
 (let (($x27472 (or $x27471 (and (and $x27445 $x27433) (or $x27463 $x27467)))))
 (let (($x27486 (or $x27472 (and (and $x27479 $x17338) (or false (and $x17268 c_2_6))))))
 (let (($x27495 (or $x27486 $x27494)))
 (let (($x27502 (or $x27495 $x27506)))
 (let (($x27513 (or $x27502 (and (and $x27479 $x27433) (or $x27498 $x27504)))))
 (let (($x27519 (or $x27513 (and (and $x27509 $x17338) (or false (and $x17282 c_3_7))))))
 (let (($x27528 (or $x27519 $x27527)))
 (let (($x27534 (or $x27528 $x27539)))
 (let (($x27546 (or $x27534 (and (and $x27509 $x27433) (or $x27531 $x27537)))))
 (let (($x27550 (or $x27546 (and (and $x27543 $x17338) (or false (and $x17296 c_4_2))))))
 (let (($x27561 (or $x27550 $x27560)))
 (let (($x27566 (or $x27561 $x27569)))
 (let (($x27573 (or $x27566 (and (and $x27543 $x27433) (or $x27564 $x27567)))))
 (let (($x27585 (or $x27573 (and (and $x27578 $x17338) (or false (and $x17310 c_5_3))))))
 (let (($x27594 (or $x27585 $x27593)))
 (let (($x27605 (or $x27594 $x27598)))
 (let (($x27612 (or $x27605 (and (and $x27578 $x27433) (or $x27595 $x27603)))))
 (let (($x27615 (or $x27612 (and (and $x27613 $x17338) (or false (and $x17324 c_6_4))))))
 (let (($x27627 (or $x27615 $x27626)))
 (let (($x27633 (or $x27627 $x27638)))
 (let ((?x29058 (ite c_18_4 1 0)))
 (let ((?x29056 (ite c_17_3 1 0)))
 (let ((?x29054 (ite c_5_2 1 0)))
 (let ((?x29052 (ite c_0_7 1 0)))
 (let ((?x29050 (ite c_1_6 1 0)))
 (let ((?x29048 (ite c_9_5 1 0)))
 (let ((?x29049 (+ 0 ?x29048)))
 (let ((?x29051 (+ ?x29049 ?x29050)))
 (let ((?x29053 (+ ?x29051 ?x29052)))
 (let ((?x29055 (+ ?x29053 ?x29054)))
 (let ((?x29057 (+ ?x29055 ?x29056)))
 (let ((?x29044 (ite c_18_1 1 0)))
 (let ((?x29017 (ite c_17_1 1 0)))
 (let ((?x28872 (ite c_5_1 1 0)))
 (let ((?x28902 (ite c_0_1 1 0)))
 (let ((?x28864 (ite c_1_1 1 0)))
 (let ((?x28905 (ite c_9_1 1 0)))
 (let ((?x29041 (+ 0 ?x28905)))
 (let ((?x29040 (+ ?x29041 ?x28864)))
 (let ((?x29042 (+ ?x29040 ?x28902)))
 (let ((?x29039 (+ ?x29042 ?x28872)))
 (let ((?x29043 (+ ?x29039 ?x29017)))
 (let (($x29062 (and (= (to_real (+ ?x29043 ?x29044)) 0.0) (= (to_real (+ ?x29057 ?x29058)) 0.0))))
 (let (($x28511 (and true $x17324)))
 (let (($x27678 (and true in_region_6)))
 (let ((?x29031 (ite c_17_4 1 0)))
 (let ((?x29029 (ite c_16_3 1 0)))
 (let ((?x29027 (ite c_15_2 1 0)))
 (let ((?x29025 (ite c_4_7 1 0)))
 (let ((?x29023 (ite c_0_6 1 0)))
 (let ((?x29021 (ite c_6_5 1 0)))
 (let ((?x29022 (+ 0 ?x29021)))
 (let ((?x29024 (+ ?x29022 ?x29023)))
 (let ((?x29026 (+ ?x29024 ?x29025)))
 (let ((?x29028 (+ ?x29026 ?x29027)))
 (let ((?x29030 (+ ?x29028 ?x29029)))
 (let ((?x29015 (ite c_16_1 1 0)))
 (let ((?x28988 (ite c_15_1 1 0)))
 (let ((?x28870 (ite c_4_1 1 0)))
 (let ((?x28874 (ite c_6_1 1 0)))
 (let ((?x29011 (+ 0 ?x28874)))
 (let ((?x29013 (+ ?x29011 ?x28902)))
 (let ((?x29012 (+ ?x29013 ?x28870)))
 (let ((?x29014 (+ ?x29012 ?x28988)))
 (let ((?x29016 (+ ?x29014 ?x29015)))
 (let (($x29035 (and (= (to_real (+ ?x29016 ?x29017)) 0.0) (= (to_real (+ ?x29030 ?x29031)) 0.0))))
 (let (($x28505 (and true $x17310)))
 (let (($x27672 (and true in_region_5)))
 (let ((?x29003 (ite c_5_4 1 0)))
 (let ((?x29001 (ite c_15_3 1 0)))
 (let ((?x28999 (ite c_14_2 1 0)))
 (let ((?x28997 (ite c_13_7 1 0)))
 (let ((?x28995 (ite c_3_6 1 0)))
 (let ((?x28993 (ite c_0_5 1 0)))
 (let ((?x28994 (+ 0 ?x28993)))
 (let ((?x28996 (+ ?x28994 ?x28995)))
 (let ((?x28998 (+ ?x28996 ?x28997)))
 (let ((?x29000 (+ ?x28998 ?x28999)))
 (let ((?x29002 (+ ?x29000 ?x29001)))
 (let ((?x28984 (ite c_14_1 1 0)))
 (let ((?x28959 (ite c_13_1 1 0)))
 (let ((?x28868 (ite c_3_1 1 0)))
 (let ((?x28985 (+ 0 ?x28902)))
 (let ((?x28983 (+ ?x28985 ?x28868)))
 (let ((?x28986 (+ ?x28983 ?x28959)))
 (let ((?x28987 (+ ?x28986 ?x28984)))
 (let ((?x28989 (+ ?x28987 ?x28988)))
 (let (($x29007 (and (= (to_real (+ ?x28989 ?x28872)) 0.0) (= (to_real (+ ?x29002 ?x29003)) 0.0))))
 (let (($x28503 (and true $x17296)))
 (let (($x27666 (and true in_region_4)))
 (let ((?x28975 (ite c_0_4 1 0)))
 (let ((?x28973 (ite c_4_3 1 0)))
 (let ((?x28971 (ite c_13_2 1 0)))
 (let ((?x28969 (ite c_12_7 1 0)))
 (let ((?x28967 (ite c_11_6 1 0)))
 (let ((?x28965 (ite c_2_5 1 0)))
 (let ((?x28966 (+ 0 ?x28965)))
 (let ((?x28968 (+ ?x28966 ?x28967)))
 (let ((?x28970 (+ ?x28968 ?x28969)))
 (let ((?x28972 (+ ?x28970 ?x28971)))
 (let ((?x28974 (+ ?x28972 ?x28973)))
 (let ((?x28956 (ite c_12_1 1 0)))
 (let ((?x28930 (ite c_11_1 1 0)))
 (let ((?x28866 (ite c_2_1 1 0)))
 (let ((?x28957 (+ 0 ?x28866)))
 (let ((?x28955 (+ ?x28957 ?x28930)))
 (let ((?x28958 (+ ?x28955 ?x28956)))
 (let ((?x28960 (+ ?x28958 ?x28959)))
 (let ((?x28961 (+ ?x28960 ?x28870)))
 (let (($x28979 (and (= (to_real (+ ?x28961 ?x28902)) 0.0) (= (to_real (+ ?x28974 ?x28975)) 0.0))))
 (let (($x28499 (and true $x17282)))
 (let (($x27660 (and true in_region_3)))
 (let ((?x28947 (ite c_1_4 1 0)))
 (let ((?x28945 (ite c_0_3 1 0)))
 (let ((?x28943 (ite c_3_2 1 0)))
 (let ((?x28941 (ite c_11_7 1 0)))
 (let ((?x28939 (ite c_10_6 1 0)))
 (let ((?x28937 (ite c_8_5 1 0)))
 (let ((?x28938 (+ 0 ?x28937)))
 (let ((?x28940 (+ ?x28938 ?x28939)))
 (let ((?x28942 (+ ?x28940 ?x28941)))
 (let ((?x28944 (+ ?x28942 ?x28943)))
 (let ((?x28946 (+ ?x28944 ?x28945)))
 (let ((?x28927 (ite c_10_1 1 0)))
 (let ((?x28898 (ite c_8_1 1 0)))
 (let ((?x28929 (+ 0 ?x28898)))
 (let ((?x28928 (+ ?x28929 ?x28927)))
 (let ((?x28931 (+ ?x28928 ?x28930)))
 (let ((?x28932 (+ ?x28931 ?x28868)))
 (let ((?x28933 (+ ?x28932 ?x28902)))
 (let (($x28951 (and (= (to_real (+ ?x28933 ?x28864)) 0.0) (= (to_real (+ ?x28946 ?x28947)) 0.0))))
 (let (($x28495 (and true $x17268)))
 (let (($x27654 (and true in_region_2)))
 (let ((?x28919 (ite c_9_4 1 0)))
 (let ((?x28917 (ite c_6_3 1 0)))
 (let ((?x28915 (ite c_0_2 1 0)))
 (let ((?x28913 (ite c_2_7 1 0)))
 (let ((?x28911 (ite c_8_6 1 0)))
 (let ((?x28909 (ite c_7_5 1 0)))
 (let ((?x28910 (+ 0 ?x28909)))
 (let ((?x28912 (+ ?x28910 ?x28911)))
 (let ((?x28914 (+ ?x28912 ?x28913)))
 (let ((?x28916 (+ ?x28914 ?x28915)))
 (let ((?x28918 (+ ?x28916 ?x28917)))
 (let ((?x28899 (ite c_7_1 1 0)))
 (let ((?x28900 (+ 0 ?x28899)))
 (let ((?x28897 (+ ?x28900 ?x28898)))
 (let ((?x28901 (+ ?x28897 ?x28866)))
 (let ((?x28903 (+ ?x28901 ?x28902)))
 (let ((?x28904 (+ ?x28903 ?x28874)))
 (let (($x28923 (and (= (to_real (+ ?x28904 ?x28905)) 0.0) (= (to_real (+ ?x28918 ?x28919)) 0.0))))
 (let (($x28491 (and true $x17254)))
 (let (($x27648 (and true in_region_1)))
 (let ((?x28889 (ite c_6_4 1 0)))
 (let ((?x28887 (ite c_5_3 1 0)))
 (let ((?x28885 (ite c_4_2 1 0)))
 (let ((?x28883 (ite c_3_7 1 0)))
 (let ((?x28881 (ite c_2_6 1 0)))
 (let ((?x28879 (ite c_1_5 1 0)))
 (let ((?x28880 (+ 0 ?x28879)))
 (let ((?x28882 (+ ?x28880 ?x28881)))
 (let ((?x28884 (+ ?x28882 ?x28883)))
 (let ((?x28886 (+ ?x28884 ?x28885)))
 (let ((?x28888 (+ ?x28886 ?x28887)))
 (let ((?x28876 (to_real (+ (+ (+ (+ (+ (+ 0 ?x28864) ?x28866) ?x28868) ?x28870) ?x28872) ?x28874))))
 (let (($x28485 (and true $x17338)))
 (let (($x27644 (and true in_region_0)))
 (let (($x28895 (and $x27644 (and $x28485 (and (= ?x28876 0.0) (= (to_real (+ ?x28888 ?x28889)) 0.0))))))
 (let (($x27691 (and true in_region_13)))
 (let (($x27988 (and $x27691 in_region_4)))
 (let (($x27690 (and true in_region_12)))
 (let (($x27983 (and $x27690 in_region_3)))
 (let (($x27689 (and true in_region_11)))
 (let (($x27979 (and $x27689 in_region_2)))
 (let (($x27975 (and $x27678 in_region_18)))
 (let (($x27971 (and $x27672 in_region_17)))
 (let (($x27955 (and $x27648 in_region_9)))
 (let (($x27688 (and true in_region_10)))
 (let (($x27941 (and $x27688 in_region_2)))
 (let (($x27686 (and true in_region_8)))
 (let (($x27937 (and $x27686 in_region_1)))
 (let (($x27933 (and $x27678 in_region_17)))
 (let (($x27929 (and $x27672 in_region_16)))
 (let (($x27925 (and $x27666 in_region_15)))
 (let (($x27687 (and true in_region_9)))
 (let (($x27904 (and $x27687 in_region_6)))
 (let (($x27684 (and true in_region_7)))
 (let (($x27894 (and $x27684 in_region_1)))
 (let (($x27886 (and $x27672 in_region_15)))
 (let (($x27882 (and $x27666 in_region_14)))
 (let (($x27878 (and $x27660 in_region_13)))
 (let (($x27711 (and true in_region_18)))
 (let (($x27856 (and $x27711 in_region_6)))
 (let (($x27710 (and true in_region_17)))
 (let (($x27852 (and $x27710 in_region_5)))
 (let (($x27835 (and $x27666 in_region_13)))
 (let (($x27831 (and $x27660 in_region_12)))
 (let (($x27827 (and $x27654 in_region_11)))
 (let (($x27708 (and true in_region_16)))
 (let (($x27804 (and $x27708 in_region_5)))
 (let (($x27702 (and true in_region_15)))
 (let (($x27800 (and $x27702 in_region_4)))
 (let (($x27784 (and $x27660 in_region_11)))
 (let (($x27780 (and $x27654 in_region_10)))
 (let (($x27776 (and $x27648 in_region_8)))
 (let (($x27696 (and true in_region_14)))
 (let (($x27697 (and $x27696 in_region_4)))
 (let (($x27679 (and $x27678 in_region_9)))
 (let (($x27655 (and $x27654 in_region_8)))
 (let (($x27649 (and $x27648 in_region_7)))
 (let (($x17458 (or c_13_2 c_13_3 c_13_4 c_13_5 c_13_6 c_13_7)))
 (let (($x28516 (and true $x17458)))
 (let (($x17444 (or c_12_2 c_12_3 c_12_4 c_12_5 c_12_6 c_12_7)))
 (let (($x28679 (and true $x17444)))
 (let (($x17418 (or c_11_2 c_11_3 c_11_4 c_11_5 c_11_6 c_11_7)))
 (let (($x28652 (and true $x17418)))
 (let (($x17404 (or c_10_2 c_10_3 c_10_4 c_10_5 c_10_6 c_10_7)))
 (let (($x28647 (and true $x17404)))
 (let (($x17365 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_7)))
 (let (($x28615 (and true $x17365)))
 (let (($x17386 (or c_9_2 c_9_3 c_9_4 c_9_5 c_9_6 c_9_7)))
 (let (($x28575 (and true $x17386)))
 (let (($x17351 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_7)))
 (let (($x28611 (and true $x17351)))
 (let (($x17564 (or c_18_2 c_18_3 c_18_4 c_18_5 c_18_6 c_18_7)))
 (let (($x28585 (and true $x17564)))
 (let (($x17538 (or c_17_2 c_17_3 c_17_4 c_17_5 c_17_6 c_17_7)))
 (let (($x28555 (and true $x17538)))
 (let (($x17524 (or c_16_2 c_16_3 c_16_4 c_16_5 c_16_6 c_16_7)))
 (let (($x28550 (and true $x17524)))
 (let (($x17498 (or c_15_2 c_15_3 c_15_4 c_15_5 c_15_6 c_15_7)))
 (let (($x28521 (and true $x17498)))
 (let (($x17484 (or c_14_2 c_14_3 c_14_4 c_14_5 c_14_6 c_14_7)))
 (let (($x28519 (and true $x17484)))
 (let (($x28483 (and $x27988 (and (and true c_13_8) (and c_4_1 (not in_target_4))))))
 (let (($x28480 (and $x27983 (and (and true c_12_8) (and c_3_1 (not in_target_3))))))
 (let (($x28477 (and $x27979 (and (and true c_11_8) (and c_2_1 (not in_target_2))))))
 (let (($x28473 (and $x27975 (and (and true c_6_8) (and c_18_1 (not in_target_18))))))
 (let (($x28470 (and $x27971 (and (and true c_5_8) (and c_17_1 (not in_target_17))))))
 (let (($x27967 (and $x27666 in_region_5)))
 (let (($x28467 (and $x27967 (and (and true c_4_8) (and c_5_1 (not in_target_5))))))
 (let (($x27963 (and $x27660 in_region_0)))
 (let (($x28464 (and $x27963 (and (and true c_3_8) (and c_0_1 (not in_target_0))))))
 (let (($x27959 (and $x27654 in_region_1)))
 (let (($x28461 (and $x27959 (and (and true c_2_8) (and c_1_1 (not in_target_1))))))
 (let (($x28458 (and $x27955 (and (and true c_1_8) (and c_9_1 (not in_target_9))))))
 (let (($x27951 (and $x27644 in_region_6)))
 (let (($x28455 (and $x27951 (and (and true c_0_8) (and c_6_1 (not in_target_6))))))
 (let (($x27946 (and $x27689 in_region_3)))
 (let (($x28452 (and $x27946 (and (and true c_11_8) (and c_3_1 (not in_target_3))))))
 (let (($x28449 (and $x27941 (and (and true c_10_8) (and c_2_1 (not in_target_2))))))
 (let (($x28446 (and $x27937 (and (and true c_8_8) (and c_1_1 (not in_target_1))))))
 (let (($x28442 (and $x27933 (and (and true c_6_8) (and c_17_1 (not in_target_17))))))
 (let (($x28438 (and $x27929 (and (and true c_5_8) (and c_16_1 (not in_target_16))))))
 (let (($x28435 (and $x27925 (and (and true c_4_8) (and c_15_1 (not in_target_15))))))
 (let (($x27921 (and $x27660 in_region_4)))
 (let (($x28432 (and $x27921 (and (and true c_3_8) (and c_4_1 (not in_target_4))))))
 (let (($x27917 (and $x27654 in_region_0)))
 (let (($x28429 (and $x27917 (and (and true c_2_8) (and c_0_1 (not in_target_0))))))
 (let (($x27913 (and $x27648 in_region_6)))
 (let (($x28426 (and $x27913 (and (and true c_1_8) (and c_6_1 (not in_target_6))))))
 (let (($x27908 (and $x27644 in_region_5)))
 (let (($x28423 (and $x27908 (and (and true c_0_8) (and c_5_1 (not in_target_5))))))
 (let (($x28420 (and $x27904 (and (and true c_9_8) (and c_6_1 (not in_target_6))))))
 (let (($x27899 (and $x27686 in_region_2)))
 (let (($x28417 (and $x27899 (and (and true c_8_8) (and c_2_1 (not in_target_2))))))
 (let (($x28414 (and $x27894 (and (and true c_7_8) (and c_1_1 (not in_target_1))))))
 (let (($x27890 (and $x27678 in_region_5)))
 (let (($x28411 (and $x27890 (and (and true c_6_8) (and c_5_1 (not in_target_5))))))
 (let (($x28407 (and $x27886 (and (and true c_5_8) (and c_15_1 (not in_target_15))))))
 (let (($x28403 (and $x27882 (and (and true c_4_8) (and c_14_1 (not in_target_14))))))
 (let (($x28400 (and $x27878 (and (and true c_3_8) (and c_13_1 (not in_target_13))))))
 (let (($x27874 (and $x27654 in_region_3)))
 (let (($x28397 (and $x27874 (and (and true c_2_8) (and c_3_1 (not in_target_3))))))
 (let (($x27870 (and $x27648 in_region_0)))
 (let (($x28394 (and $x27870 (and (and true c_1_8) (and c_0_1 (not in_target_0))))))
 (let (($x27861 (and $x27644 in_region_4)))
 (let (($x28391 (and $x27861 (and (and true c_0_8) (and c_4_1 (not in_target_4))))))
 (let (($x28388 (and $x27856 (and (and true c_18_8) (and c_6_1 (not in_target_6))))))
 (let (($x28385 (and $x27852 (and (and true c_17_8) (and c_5_1 (not in_target_5))))))
 (let (($x27847 (and $x27687 in_region_1)))
 (let (($x28382 (and $x27847 (and (and true c_9_8) (and c_1_1 (not in_target_1))))))
 (let (($x27843 (and $x27678 in_region_0)))
 (let (($x28379 (and $x27843 (and (and true c_6_8) (and c_0_1 (not in_target_0))))))
 (let (($x27839 (and $x27672 in_region_4)))
 (let (($x28376 (and $x27839 (and (and true c_5_8) (and c_4_1 (not in_target_4))))))
 (let (($x28372 (and $x27835 (and (and true c_4_8) (and c_13_1 (not in_target_13))))))
 (let (($x28368 (and $x27831 (and (and true c_3_8) (and c_12_1 (not in_target_12))))))
 (let (($x28365 (and $x27827 (and (and true c_2_8) (and c_11_1 (not in_target_11))))))
 (let (($x27823 (and $x27648 in_region_2)))
 (let (($x28362 (and $x27823 (and (and true c_1_8) (and c_2_1 (not in_target_2))))))
 (let (($x27814 (and $x27644 in_region_3)))
 (let (($x28359 (and $x27814 (and (and true c_0_8) (and c_3_1 (not in_target_3))))))
 (let (($x27809 (and $x27710 in_region_6)))
 (let (($x28356 (and $x27809 (and (and true c_17_8) (and c_6_1 (not in_target_6))))))
 (let (($x28353 (and $x27804 (and (and true c_16_8) (and c_5_1 (not in_target_5))))))
 (let (($x28350 (and $x27800 (and (and true c_15_8) (and c_4_1 (not in_target_4))))))
 (let (($x27796 (and $x27678 in_region_1)))
 (let (($x28347 (and $x27796 (and (and true c_6_8) (and c_1_1 (not in_target_1))))))
 (let (($x27792 (and $x27672 in_region_0)))
 (let (($x28344 (and $x27792 (and (and true c_5_8) (and c_0_1 (not in_target_0))))))
 (let (($x27788 (and $x27666 in_region_3)))
 (let (($x28341 (and $x27788 (and (and true c_4_8) (and c_3_1 (not in_target_3))))))
 (let (($x28337 (and $x27784 (and (and true c_3_8) (and c_11_1 (not in_target_11))))))
 (let (($x28333 (and $x27780 (and (and true c_2_8) (and c_10_1 (not in_target_10))))))
 (let (($x28330 (and $x27776 (and (and true c_1_8) (and c_8_1 (not in_target_8))))))
 (let (($x27709 (and $x27644 in_region_2)))
 (let (($x28327 (and $x27709 (and (and true c_0_8) (and c_2_1 (not in_target_2))))))
 (let (($x27703 (and $x27702 in_region_5)))
 (let (($x28323 (and $x27703 (and (and true c_15_8) (and c_5_1 (not in_target_5))))))
 (let (($x28319 (and $x27697 (and (and true c_14_8) (and c_4_1 (not in_target_4))))))
 (let (($x27685 (and $x27691 in_region_3)))
 (let (($x28315 (and $x27685 (and (and true c_13_8) (and c_3_1 (not in_target_3))))))
 (let (($x28311 (and $x27679 (and (and true c_6_8) (and c_9_1 (not in_target_9))))))
 (let (($x27673 (and $x27672 in_region_6)))
 (let (($x28307 (and $x27673 (and (and true c_5_8) (and c_6_1 (not in_target_6))))))
 (let (($x27667 (and $x27666 in_region_0)))
 (let (($x28303 (and $x27667 (and (and true c_4_8) (and c_0_1 (not in_target_0))))))
 (let (($x27661 (and $x27660 in_region_2)))
 (let (($x28299 (and $x27661 (and (and true c_3_8) (and c_2_1 (not in_target_2))))))
 (let (($x28295 (and $x27655 (and (and true c_2_8) (and c_8_1 (not in_target_8))))))
 (let (($x28291 (and $x27649 (and (and true c_1_8) (and c_7_1 (not in_target_7))))))
 (let (($x27645 (and $x27644 in_region_1)))
 (let (($x28287 (and $x27645 (and (and true c_0_8) (and c_1_1 (not in_target_1))))))
 (let (($x28286 (and $x27988 (and (and true c_13_8) (or $x22426 $x22428 $x22430 $x22432 $x22434 $x22436)))))
 (let (($x28275 (and $x27983 (and (and true c_12_8) (or $x22391 $x22393 $x22395 $x22397 $x22399 $x22401)))))
 (let (($x28279 (and $x27979 (and (and true c_11_8) (or $x22356 $x22358 $x22360 $x22362 $x22364 $x22366)))))
 (let (($x23108 (and c_18_7 in_target_18)))
 (let (($x23106 (and c_18_6 in_target_18)))
 (let (($x23104 (and c_18_5 in_target_18)))
 (let (($x23102 (and c_18_4 in_target_18)))
 (let (($x23100 (and c_18_3 in_target_18)))
 (let (($x23098 (and c_18_2 in_target_18)))
 (let (($x28278 (or $x23098 $x23100 $x23102 $x23104 $x23106 $x23108)))
 (let (($x27680 (and true c_6_8)))
 (let (($x23038 (and c_17_7 in_target_17)))
 (let (($x23036 (and c_17_6 in_target_17)))
 (let (($x23034 (and c_17_5 in_target_17)))
 (let (($x23032 (and c_17_4 in_target_17)))
 (let (($x23030 (and c_17_3 in_target_17)))
 (let (($x23028 (and c_17_2 in_target_17)))
 (let (($x28242 (or $x23028 $x23030 $x23032 $x23034 $x23036 $x23038)))
 (let (($x27674 (and true c_5_8)))
 (let (($x28264 (and $x27967 (and (and true c_4_8) (or $x22461 $x22463 $x22465 $x22467 $x22469 $x22471)))))
 (let (($x28263 (and $x27963 (and (and true c_3_8) (or $x22195 $x22197 $x22199 $x22201 $x22203 $x22205)))))
 (let (($x28249 (and $x27959 (and (and true c_2_8) (or $x22320 $x22322 $x22324 $x22326 $x22328 $x22330)))))
 (let (($x22638 (and c_9_7 in_target_9)))
 (let (($x22636 (and c_9_6 in_target_9)))
 (let (($x22634 (and c_9_5 in_target_9)))
 (let (($x22632 (and c_9_4 in_target_9)))
 (let (($x22630 (and c_9_3 in_target_9)))
 (let (($x22628 (and c_9_2 in_target_9)))
 (let (($x28056 (or $x22628 $x22630 $x22632 $x22634 $x22636 $x22638)))
 (let (($x27650 (and true c_1_8)))
 (let (($x28252 (and $x27951 (and (and true c_0_8) (or $x22496 $x22498 $x22500 $x22502 $x22504 $x22506)))))
 (let (($x28243 (and $x27946 (and (and true c_11_8) (or $x22391 $x22393 $x22395 $x22397 $x22399 $x22401)))))
 (let (($x28246 (and $x27941 (and (and true c_10_8) (or $x22356 $x22358 $x22360 $x22362 $x22364 $x22366)))))
 (let (($x28241 (and $x27937 (and (and true c_8_8) (or $x22320 $x22322 $x22324 $x22326 $x22328 $x22330)))))
 (let (($x23003 (and c_16_7 in_target_16)))
 (let (($x23001 (and c_16_6 in_target_16)))
 (let (($x22999 (and c_16_5 in_target_16)))
 (let (($x22997 (and c_16_4 in_target_16)))
 (let (($x22995 (and c_16_3 in_target_16)))
 (let (($x22993 (and c_16_2 in_target_16)))
 (let (($x28233 (or $x22993 $x22995 $x22997 $x22999 $x23001 $x23003)))
 (let (($x22933 (and c_15_7 in_target_15)))
 (let (($x22931 (and c_15_6 in_target_15)))
 (let (($x22929 (and c_15_5 in_target_15)))
 (let (($x22927 (and c_15_4 in_target_15)))
 (let (($x22925 (and c_15_3 in_target_15)))
 (let (($x22923 (and c_15_2 in_target_15)))
 (let (($x28197 (or $x22923 $x22925 $x22927 $x22929 $x22931 $x22933)))
 (let (($x27668 (and true c_4_8)))
 (let (($x28220 (and $x27921 (and (and true c_3_8) (or $x22426 $x22428 $x22430 $x22432 $x22434 $x22436)))))
 (let (($x28218 (and $x27917 (and (and true c_2_8) (or $x22195 $x22197 $x22199 $x22201 $x22203 $x22205)))))
 (let (($x28210 (and $x27908 (and (and true c_0_8) (or $x22461 $x22463 $x22465 $x22467 $x22469 $x22471)))))
 (let (($x28207 (and $x27904 (and (and true c_9_8) (or $x22496 $x22498 $x22500 $x22502 $x22504 $x22506)))))
 (let (($x28204 (and $x27899 (and (and true c_8_8) (or $x22356 $x22358 $x22360 $x22362 $x22364 $x22366)))))
 (let (($x28199 (and $x27894 (and (and true c_7_8) (or $x22320 $x22322 $x22324 $x22326 $x22328 $x22330)))))
 (let (($x22898 (and c_14_7 in_target_14)))
 (let (($x22896 (and c_14_6 in_target_14)))
 (let (($x22894 (and c_14_5 in_target_14)))
 (let (($x22892 (and c_14_4 in_target_14)))
 (let (($x22890 (and c_14_3 in_target_14)))
 (let (($x22888 (and c_14_2 in_target_14)))
 (let (($x28188 (or $x22888 $x22890 $x22892 $x22894 $x22896 $x22898)))
 (let (($x22828 (and c_13_7 in_target_13)))
 (let (($x22826 (and c_13_6 in_target_13)))
 (let (($x22824 (and c_13_5 in_target_13)))
 (let (($x22822 (and c_13_4 in_target_13)))
 (let (($x22820 (and c_13_3 in_target_13)))
 (let (($x22818 (and c_13_2 in_target_13)))
 (let (($x28152 (or $x22818 $x22820 $x22822 $x22824 $x22826 $x22828)))
 (let (($x27662 (and true c_3_8)))
 (let (($x28171 (and $x27874 (and (and true c_2_8) (or $x22391 $x22393 $x22395 $x22397 $x22399 $x22401)))))
 (let (($x28169 (and $x27861 (and (and true c_0_8) (or $x22426 $x22428 $x22430 $x22432 $x22434 $x22436)))))
 (let (($x28165 (and $x27856 (and (and true c_18_8) (or $x22496 $x22498 $x22500 $x22502 $x22504 $x22506)))))
 (let (($x28162 (and $x27852 (and (and true c_17_8) (or $x22461 $x22463 $x22465 $x22467 $x22469 $x22471)))))
 (let (($x28156 (and $x27847 (and (and true c_9_8) (or $x22320 $x22322 $x22324 $x22326 $x22328 $x22330)))))
 (let (($x22793 (and c_12_7 in_target_12)))
 (let (($x22791 (and c_12_6 in_target_12)))
 (let (($x22789 (and c_12_5 in_target_12)))
 (let (($x22787 (and c_12_4 in_target_12)))
 (let (($x22785 (and c_12_3 in_target_12)))
 (let (($x22783 (and c_12_2 in_target_12)))
 (let (($x28143 (or $x22783 $x22785 $x22787 $x22789 $x22791 $x22793)))
 (let (($x22723 (and c_11_7 in_target_11)))
 (let (($x22721 (and c_11_6 in_target_11)))
 (let (($x22719 (and c_11_5 in_target_11)))
 (let (($x22717 (and c_11_4 in_target_11)))
 (let (($x22715 (and c_11_3 in_target_11)))
 (let (($x22713 (and c_11_2 in_target_11)))
 (let (($x28107 (or $x22713 $x22715 $x22717 $x22719 $x22721 $x22723)))
 (let (($x27656 (and true c_2_8)))
 (let (($x28121 (and $x27814 (and (and true c_0_8) (or $x22391 $x22393 $x22395 $x22397 $x22399 $x22401)))))
 (let (($x28123 (and $x27809 (and (and true c_17_8) (or $x22496 $x22498 $x22500 $x22502 $x22504 $x22506)))))
 (let (($x28120 (and $x27804 (and (and true c_16_8) (or $x22461 $x22463 $x22465 $x22467 $x22469 $x22471)))))
 (let (($x28118 (and $x27800 (and (and true c_15_8) (or $x22426 $x22428 $x22430 $x22432 $x22434 $x22436)))))
 (let (($x22688 (and c_10_7 in_target_10)))
 (let (($x22686 (and c_10_6 in_target_10)))
 (let (($x22684 (and c_10_5 in_target_10)))
 (let (($x22682 (and c_10_4 in_target_10)))
 (let (($x22680 (and c_10_3 in_target_10)))
 (let (($x22678 (and c_10_2 in_target_10)))
 (let (($x28098 (or $x22678 $x22680 $x22682 $x22684 $x22686 $x22688)))
 (let (($x22588 (and c_8_7 in_target_8)))
 (let (($x22586 (and c_8_6 in_target_8)))
 (let (($x22584 (and c_8_5 in_target_8)))
 (let (($x22582 (and c_8_4 in_target_8)))
 (let (($x22580 (and c_8_3 in_target_8)))
 (let (($x22578 (and c_8_2 in_target_8)))
 (let (($x28020 (or $x22578 $x22580 $x22582 $x22584 $x22586 $x22588)))
 (let (($x28084 (and $x27709 (and (and true c_0_8) (or $x22356 $x22358 $x22360 $x22362 $x22364 $x22366)))))
 (let (($x28080 (and $x27703 (and (and true c_15_8) (or $x22461 $x22463 $x22465 $x22467 $x22469 $x22471)))))
 (let (($x28072 (and $x27697 (and (and true c_14_8) (or $x22426 $x22428 $x22430 $x22432 $x22434 $x22436)))))
 (let (($x28061 (and $x27685 (and (and true c_13_8) (or $x22391 $x22393 $x22395 $x22397 $x22399 $x22401)))))
 (let (($x22552 (and c_7_7 in_target_7)))
 (let (($x22550 (and c_7_6 in_target_7)))
 (let (($x22548 (and c_7_5 in_target_7)))
 (let (($x22546 (and c_7_4 in_target_7)))
 (let (($x22544 (and c_7_3 in_target_7)))
 (let (($x22542 (and c_7_2 in_target_7)))
 (let (($x28011 (or $x22542 $x22544 $x22546 $x22548 $x22550 $x22552)))
 (let (($x27998 (and $x27645 (and (and true c_0_8) (or $x22320 $x22322 $x22324 $x22326 $x22328 $x22330)))))
 (let (($x27647 (or false (and $x27645 (and (and true c_0_8) $x22318)))))
 (let (($x27653 (or $x27647 (and $x27649 (and $x27650 (and c_7_1 in_target_7))))))
 (let (($x27659 (or $x27653 (and $x27655 (and $x27656 (and c_8_1 in_target_8))))))
 (let (($x27665 (or $x27659 (and $x27661 (and $x27662 $x22354)))))
 (let (($x27671 (or $x27665 (and $x27667 (and $x27668 $x22193)))))
 (let (($x27677 (or $x27671 (and $x27673 (and $x27674 $x22494)))))
 (let (($x27683 (or $x27677 (and $x27679 (and $x27680 (and c_9_1 in_target_9))))))
 (let (($x27695 (or $x27683 (and $x27685 (and (and true c_13_8) $x22389)))))
 (let (($x27701 (or $x27695 (and $x27697 (and (and true c_14_8) $x22424)))))
 (let (($x27707 (or $x27701 (and $x27703 (and (and true c_15_8) $x22459)))))
 (let (($x27775 (or $x27707 (and $x27709 (and (and true c_0_8) $x22354)))))
 (let (($x27779 (or $x27775 (and $x27776 (and $x27650 (and c_8_1 in_target_8))))))
 (let (($x27783 (or $x27779 (and $x27780 (and $x27656 (and c_10_1 in_target_10))))))
 (let (($x27787 (or $x27783 (and $x27784 (and $x27662 (and c_11_1 in_target_11))))))
 (let (($x27791 (or $x27787 (and $x27788 (and $x27668 $x22389)))))
 (let (($x27795 (or $x27791 (and $x27792 (and $x27674 $x22193)))))
 (let (($x27799 (or $x27795 (and $x27796 (and $x27680 $x22318)))))
 (let (($x27803 (or $x27799 (and $x27800 (and (and true c_15_8) $x22424)))))
 (let (($x27808 (or $x27803 (and $x27804 (and (and true c_16_8) $x22459)))))
 (let (($x27813 (or $x27808 (and $x27809 (and (and true c_17_8) $x22494)))))
 (let (($x27822 (or $x27813 (and $x27814 (and (and true c_0_8) $x22389)))))
 (let (($x27826 (or $x27822 (and $x27823 (and $x27650 $x22354)))))
 (let (($x27830 (or $x27826 (and $x27827 (and $x27656 (and c_11_1 in_target_11))))))
 (let (($x27834 (or $x27830 (and $x27831 (and $x27662 (and c_12_1 in_target_12))))))
 (let (($x27838 (or $x27834 (and $x27835 (and $x27668 (and c_13_1 in_target_13))))))
 (let (($x27842 (or $x27838 (and $x27839 (and $x27674 $x22424)))))
 (let (($x27846 (or $x27842 (and $x27843 (and $x27680 $x22193)))))
 (let (($x27851 (or $x27846 (and $x27847 (and (and true c_9_8) $x22318)))))
 (let (($x27855 (or $x27851 (and $x27852 (and (and true c_17_8) $x22459)))))
 (let (($x27860 (or $x27855 (and $x27856 (and (and true c_18_8) $x22494)))))
 (let (($x27869 (or $x27860 (and $x27861 (and (and true c_0_8) $x22424)))))
 (let (($x27873 (or $x27869 (and $x27870 (and $x27650 $x22193)))))
 (let (($x27877 (or $x27873 (and $x27874 (and $x27656 $x22389)))))
 (let (($x27881 (or $x27877 (and $x27878 (and $x27662 (and c_13_1 in_target_13))))))
 (let (($x27885 (or $x27881 (and $x27882 (and $x27668 (and c_14_1 in_target_14))))))
 (let (($x27889 (or $x27885 (and $x27886 (and $x27674 (and c_15_1 in_target_15))))))
 (let (($x27893 (or $x27889 (and $x27890 (and $x27680 $x22459)))))
 (let (($x27898 (or $x27893 (and $x27894 (and (and true c_7_8) $x22318)))))
 (let (($x27903 (or $x27898 (and $x27899 (and (and true c_8_8) $x22354)))))
 (let (($x27907 (or $x27903 (and $x27904 (and (and true c_9_8) $x22494)))))
 (let (($x27912 (or $x27907 (and $x27908 (and (and true c_0_8) $x22459)))))
 (let (($x27916 (or $x27912 (and $x27913 (and $x27650 $x22494)))))
 (let (($x27920 (or $x27916 (and $x27917 (and $x27656 $x22193)))))
 (let (($x27924 (or $x27920 (and $x27921 (and $x27662 $x22424)))))
 (let (($x27928 (or $x27924 (and $x27925 (and $x27668 (and c_15_1 in_target_15))))))
 (let (($x27932 (or $x27928 (and $x27929 (and $x27674 (and c_16_1 in_target_16))))))
 (let (($x27936 (or $x27932 (and $x27933 (and $x27680 (and c_17_1 in_target_17))))))
 (let (($x27940 (or $x27936 (and $x27937 (and (and true c_8_8) $x22318)))))
 (let (($x27945 (or $x27940 (and $x27941 (and (and true c_10_8) $x22354)))))
 (let (($x27950 (or $x27945 (and $x27946 (and (and true c_11_8) $x22389)))))
 (let (($x27954 (or $x27950 (and $x27951 (and (and true c_0_8) $x22494)))))
 (let (($x27958 (or $x27954 (and $x27955 (and $x27650 (and c_9_1 in_target_9))))))
 (let (($x27962 (or $x27958 (and $x27959 (and $x27656 $x22318)))))
 (let (($x27966 (or $x27962 (and $x27963 (and $x27662 $x22193)))))
 (let (($x27970 (or $x27966 (and $x27967 (and $x27668 $x22459)))))
 (let (($x27974 (or $x27970 (and $x27971 (and $x27674 (and c_17_1 in_target_17))))))
 (let (($x27978 (or $x27974 (and $x27975 (and $x27680 (and c_18_1 in_target_18))))))
 (let (($x27982 (or $x27978 (and $x27979 (and (and true c_11_8) $x22354)))))
 (let (($x27987 (or $x27982 (and $x27983 (and (and true c_12_8) $x22389)))))
 (let (($x27991 (or $x27987 (and $x27988 (and (and true c_13_8) $x22424)))))
 (let (($x28001 (or $x27991 $x27998)))
 (let (($x28007 (or $x28001 (and $x27649 (and $x27650 $x28011)))))
 (let (($x28017 (or $x28007 (and $x27655 (and $x27656 $x28020)))))
 (let (($x28028 (or $x28017 (and $x27661 (and $x27662 (or $x22356 $x22358 $x22360 $x22362 $x22364 $x22366))))))
 (let (($x28034 (or $x28028 (and $x27667 (and $x27668 (or $x22195 $x22197 $x22199 $x22201 $x22203 $x22205))))))
 (let (($x28045 (or $x28034 (and $x27673 (and $x27674 (or $x22496 $x22498 $x22500 $x22502 $x22504 $x22506))))))
 (let (($x28054 (or $x28045 (and $x27679 (and $x27680 $x28056)))))
 (let (($x28063 (or $x28054 $x28061)))
 (let (($x28070 (or $x28063 $x28072)))
 (let (($x28082 (or $x28070 $x28080)))
 (let (($x28086 (or $x28082 $x28084)))
 (let (($x28087 (or $x28086 (and $x27776 (and $x27650 $x28020)))))
 (let (($x28097 (or $x28087 (and $x27780 (and $x27656 $x28098)))))
 (let (($x28106 (or $x28097 (and $x27784 (and $x27662 $x28107)))))
 (let (($x28109 (or $x28106 (and $x27788 (and $x27668 (or $x22391 $x22393 $x22395 $x22397 $x22399 $x22401))))))
 (let (($x28108 (or $x28109 (and $x27792 (and $x27674 (or $x22195 $x22197 $x22199 $x22201 $x22203 $x22205))))))
 (let (($x28116 (or $x28108 (and $x27796 (and $x27680 (or $x22320 $x22322 $x22324 $x22326 $x22328 $x22330))))))
 (let (($x28114 (or $x28116 $x28118)))
 (let (($x28122 (or $x28114 $x28120)))
 (let (($x28124 (or $x28122 $x28123)))
 (let (($x28127 (or $x28124 $x28121)))
 (let (($x28131 (or $x28127 (and $x27823 (and $x27650 (or $x22356 $x22358 $x22360 $x22362 $x22364 $x22366))))))
 (let (($x28134 (or $x28131 (and $x27827 (and $x27656 $x28107)))))
 (let (($x28141 (or $x28134 (and $x27831 (and $x27662 $x28143)))))
 (let (($x28148 (or $x28141 (and $x27835 (and $x27668 $x28152)))))
 (let (($x28150 (or $x28148 (and $x27839 (and $x27674 (or $x22426 $x22428 $x22430 $x22432 $x22434 $x22436))))))
 (let (($x28155 (or $x28150 (and $x27843 (and $x27680 (or $x22195 $x22197 $x22199 $x22201 $x22203 $x22205))))))
 (let (($x28161 (or $x28155 $x28156)))
 (let (($x28164 (or $x28161 $x28162)))
 (let (($x28166 (or $x28164 $x28165)))
 (let (($x28163 (or $x28166 $x28169)))
 (let (($x28170 (or $x28163 (and $x27870 (and $x27650 (or $x22195 $x22197 $x22199 $x22201 $x22203 $x22205))))))
 (let (($x28175 (or $x28170 $x28171)))
 (let (($x28174 (or $x28175 (and $x27878 (and $x27662 $x28152)))))
 (let (($x28185 (or $x28174 (and $x27882 (and $x27668 $x28188)))))
 (let (($x28195 (or $x28185 (and $x27886 (and $x27674 $x28197)))))
 (let (($x28200 (or $x28195 (and $x27890 (and $x27680 (or $x22461 $x22463 $x22465 $x22467 $x22469 $x22471))))))
 (let (($x28203 (or $x28200 $x28199)))
 (let (($x28206 (or $x28203 $x28204)))
 (let (($x28208 (or $x28206 $x28207)))
 (let (($x28212 (or $x28208 $x28210)))
 (let (($x28214 (or $x28212 (and $x27913 (and $x27650 (or $x22496 $x22498 $x22500 $x22502 $x22504 $x22506))))))
 (let (($x28211 (or $x28214 $x28218)))
 (let (($x28216 (or $x28211 $x28220)))
 (let (($x28223 (or $x28216 (and $x27925 (and $x27668 $x28197)))))
 (let (($x28231 (or $x28223 (and $x27929 (and $x27674 $x28233)))))
 (let (($x28239 (or $x28231 (and $x27933 (and $x27680 $x28242)))))
 (let (($x28245 (or $x28239 $x28241)))
 (let (($x28248 (or $x28245 $x28246)))
 (let (($x28250 (or $x28248 $x28243)))
 (let (($x28253 (or $x28250 $x28252)))
 (let (($x28256 (or $x28253 (and $x27955 (and $x27650 $x28056)))))
 (let (($x28260 (or $x28256 $x28249)))
 (let (($x28258 (or $x28260 $x28263)))
 (let (($x28266 (or $x28258 $x28264)))
 (let (($x28267 (or $x28266 (and $x27971 (and $x27674 $x28242)))))
 (let (($x28274 (or $x28267 (and $x27975 (and $x27680 $x28278)))))
 (let (($x28281 (or $x28274 $x28279)))
 (let (($x28283 (or $x28281 $x28275)))
 (let (($x28282 (or $x28283 $x28286)))
 (let (($x28289 (or $x28282 $x28287)))
 (let (($x28293 (or $x28289 $x28291)))
 (let (($x28297 (or $x28293 $x28295)))
 (let (($x28301 (or $x28297 $x28299)))
 (let (($x28305 (or $x28301 $x28303)))
 (let (($x28309 (or $x28305 $x28307)))
 (let (($x28313 (or $x28309 $x28311)))
 (let (($x28317 (or $x28313 $x28315)))
 (let (($x28321 (or $x28317 $x28319)))
 (let (($x28325 (or $x28321 $x28323)))
 (let (($x28328 (or $x28325 $x28327)))
 (let (($x28331 (or $x28328 $x28330)))
 (let (($x28335 (or $x28331 $x28333)))
 (let (($x28339 (or $x28335 $x28337)))
 (let (($x28342 (or $x28339 $x28341)))
 (let (($x28345 (or $x28342 $x28344)))
 (let (($x28348 (or $x28345 $x28347)))
 (let (($x28351 (or $x28348 $x28350)))
 (let (($x28354 (or $x28351 $x28353)))
 (let (($x28357 (or $x28354 $x28356)))
 (let (($x28360 (or $x28357 $x28359)))
 (let (($x28363 (or $x28360 $x28362)))
 (let (($x28366 (or $x28363 $x28365)))
 (let (($x28370 (or $x28366 $x28368)))
 (let (($x28374 (or $x28370 $x28372)))
 (let (($x28377 (or $x28374 $x28376)))
 (let (($x28380 (or $x28377 $x28379)))
 (let (($x28383 (or $x28380 $x28382)))
 (let (($x28386 (or $x28383 $x28385)))
 (let (($x28389 (or $x28386 $x28388)))
 (let (($x28392 (or $x28389 $x28391)))
 (let (($x28395 (or $x28392 $x28394)))
 (let (($x28398 (or $x28395 $x28397)))
 (let (($x28401 (or $x28398 $x28400)))
 (let (($x28405 (or $x28401 $x28403)))
 (let (($x28409 (or $x28405 $x28407)))
 (let (($x28412 (or $x28409 $x28411)))
 (let (($x28415 (or $x28412 $x28414)))
 (let (($x28418 (or $x28415 $x28417)))
 (let (($x28421 (or $x28418 $x28420)))
 (let (($x28424 (or $x28421 $x28423)))
 (let (($x28427 (or $x28424 $x28426)))
 (let (($x28430 (or $x28427 $x28429)))
 (let (($x28433 (or $x28430 $x28432)))
 (let (($x28436 (or $x28433 $x28435)))
 (let (($x28440 (or $x28436 $x28438)))
 (let (($x28444 (or $x28440 $x28442)))
 (let (($x28447 (or $x28444 $x28446)))
 (let (($x28450 (or $x28447 $x28449)))
 (let (($x28453 (or $x28450 $x28452)))
 (let (($x28456 (or $x28453 $x28455)))
 (let (($x28459 (or $x28456 $x28458)))
 (let (($x28462 (or $x28459 $x28461)))
 (let (($x28465 (or $x28462 $x28464)))
 (let (($x28468 (or $x28465 $x28467)))
 (let (($x28471 (or $x28468 $x28470)))
 (let (($x28475 (or $x28471 $x28473)))
 (let (($x28478 (or $x28475 $x28477)))
 (let (($x28481 (or $x28478 $x28480)))
 (let (($x28484 (or $x28481 $x28483)))
 (let (($x28488 (or $x28484 (and $x27645 (and $x28485 c_1_1)))))
 (let (($x28489 (or $x28488 (and $x27649 (and $x28491 c_7_1)))))
 (let (($x28496 (or $x28489 (and $x27655 (and $x28495 c_8_1)))))
 (let (($x28500 (or $x28496 (and $x27661 (and $x28499 c_2_1)))))
 (let (($x28502 (or $x28500 (and $x27667 (and $x28503 c_0_1)))))
 (let (($x28508 (or $x28502 (and $x27673 (and $x28505 c_6_1)))))
 (let (($x28509 (or $x28508 (and $x27679 (and $x28511 c_9_1)))))
 (let (($x28513 (or $x28509 (and $x27685 (and $x28516 c_3_1)))))
 (let (($x28517 (or $x28513 (and $x27697 (and $x28519 c_4_1)))))
 (let (($x28523 (or $x28517 (and $x27703 (and $x28521 c_5_1)))))
 (let (($x28527 (or $x28523 (and $x27709 (and $x28485 c_2_1)))))
 (let (($x28529 (or $x28527 (and $x27776 (and $x28491 c_8_1)))))
 (let (($x28532 (or $x28529 (and $x27780 (and $x28495 c_10_1)))))
 (let (($x28535 (or $x28532 (and $x27784 (and $x28499 c_11_1)))))
 (let (($x28540 (or $x28535 (and $x27788 (and $x28503 c_3_1)))))
 (let (($x28541 (or $x28540 (and $x27792 (and $x28505 c_0_1)))))
 (let (($x28546 (or $x28541 (and $x27796 (and $x28511 c_1_1)))))
 (let (($x28547 (or $x28546 (and $x27800 (and $x28521 c_4_1)))))
 (let (($x28552 (or $x28547 (and $x27804 (and $x28550 c_5_1)))))
 (let (($x28556 (or $x28552 (and $x27809 (and $x28555 c_6_1)))))
 (let (($x28559 (or $x28556 (and $x27814 (and $x28485 c_3_1)))))
 (let (($x28561 (or $x28559 (and $x27823 (and $x28491 c_2_1)))))
 (let (($x28564 (or $x28561 (and $x27827 (and $x28495 c_11_1)))))
 (let (($x28567 (or $x28564 (and $x27831 (and $x28499 c_12_1)))))
 (let (($x28572 (or $x28567 (and $x27835 (and $x28503 c_13_1)))))
 (let (($x28573 (or $x28572 (and $x27839 (and $x28505 c_4_1)))))
 (let (($x28578 (or $x28573 (and $x27843 (and $x28511 c_0_1)))))
 (let (($x28581 (or $x28578 (and $x27847 (and $x28575 c_1_1)))))
 (let (($x28582 (or $x28581 (and $x27852 (and $x28555 c_5_1)))))
 (let (($x28588 (or $x28582 (and $x27856 (and $x28585 c_6_1)))))
 (let (($x28591 (or $x28588 (and $x27861 (and $x28485 c_4_1)))))
 (let (($x28593 (or $x28591 (and $x27870 (and $x28491 c_0_1)))))
 (let (($x28596 (or $x28593 (and $x27874 (and $x28495 c_3_1)))))
 (let (($x28599 (or $x28596 (and $x27878 (and $x28499 c_13_1)))))
 (let (($x28604 (or $x28599 (and $x27882 (and $x28503 c_14_1)))))
 (let (($x28605 (or $x28604 (and $x27886 (and $x28505 c_15_1)))))
 (let (($x28610 (or $x28605 (and $x27890 (and $x28511 c_5_1)))))
 (let (($x28607 (or $x28610 (and $x27894 (and $x28611 c_1_1)))))
 (let (($x28616 (or $x28607 (and $x27899 (and $x28615 c_2_1)))))
 (let (($x28620 (or $x28616 (and $x27904 (and $x28575 c_6_1)))))
 (let (($x28623 (or $x28620 (and $x27908 (and $x28485 c_5_1)))))
 (let (($x28625 (or $x28623 (and $x27913 (and $x28491 c_6_1)))))
 (let (($x28628 (or $x28625 (and $x27917 (and $x28495 c_0_1)))))
 (let (($x28631 (or $x28628 (and $x27921 (and $x28499 c_4_1)))))
 (let (($x28636 (or $x28631 (and $x27925 (and $x28503 c_15_1)))))
 (let (($x28637 (or $x28636 (and $x27929 (and $x28505 c_16_1)))))
 (let (($x28642 (or $x28637 (and $x27933 (and $x28511 c_17_1)))))
 (let (($x28639 (or $x28642 (and $x27937 (and $x28615 c_1_1)))))
 (let (($x28648 (or $x28639 (and $x27941 (and $x28647 c_2_1)))))
 (let (($x28651 (or $x28648 (and $x27946 (and $x28652 c_3_1)))))
 (let (($x28655 (or $x28651 (and $x27951 (and $x28485 c_6_1)))))
 (let (($x28657 (or $x28655 (and $x27955 (and $x28491 c_9_1)))))
 (let (($x28660 (or $x28657 (and $x27959 (and $x28495 c_1_1)))))
 (let (($x28663 (or $x28660 (and $x27963 (and $x28499 c_0_1)))))
 (let (($x28668 (or $x28663 (and $x27967 (and $x28503 c_5_1)))))
 (let (($x28669 (or $x28668 (and $x27971 (and $x28505 c_17_1)))))
 (let (($x28674 (or $x28669 (and $x27975 (and $x28511 c_18_1)))))
 (let (($x28675 (or $x28674 (and $x27979 (and $x28652 c_2_1)))))
 (let (($x28680 (or $x28675 (and $x27983 (and $x28679 c_3_1)))))
 (let (($x28682 (or $x28680 (and $x27988 (and $x28516 c_4_1)))))
 (let (($x28686 (or $x28682 (and $x27645 (and (and true c_0_8) $x22317)))))
 (let (($x28689 (or $x28686 (and $x27649 (and $x27650 (and c_7_0 in_target_7))))))
 (let (($x28692 (or $x28689 (and $x27655 (and $x27656 (and c_8_0 in_target_8))))))
 (let (($x28695 (or $x28692 (and $x27661 (and $x27662 $x22353)))))
 (let (($x28698 (or $x28695 (and $x27667 (and $x27668 $x22192)))))
 (let (($x28701 (or $x28698 (and $x27673 (and $x27674 $x22493)))))
 (let (($x28704 (or $x28701 (and $x27679 (and $x27680 (and c_9_0 in_target_9))))))
 (let (($x28707 (or $x28704 (and $x27685 (and (and true c_13_8) $x22388)))))
 (let (($x28710 (or $x28707 (and $x27697 (and (and true c_14_8) $x22423)))))
 (let (($x28713 (or $x28710 (and $x27703 (and (and true c_15_8) $x22458)))))
 (let (($x28716 (or $x28713 (and $x27709 (and (and true c_0_8) $x22353)))))
 (let (($x28719 (or $x28716 (and $x27776 (and $x27650 (and c_8_0 in_target_8))))))
 (let (($x28722 (or $x28719 (and $x27780 (and $x27656 (and c_10_0 in_target_10))))))
 (let (($x28725 (or $x28722 (and $x27784 (and $x27662 (and c_11_0 in_target_11))))))
 (let (($x28728 (or $x28725 (and $x27788 (and $x27668 $x22388)))))
 (let (($x28731 (or $x28728 (and $x27792 (and $x27674 $x22192)))))
 (let (($x28734 (or $x28731 (and $x27796 (and $x27680 $x22317)))))
 (let (($x28737 (or $x28734 (and $x27800 (and (and true c_15_8) $x22423)))))
 (let (($x28740 (or $x28737 (and $x27804 (and (and true c_16_8) $x22458)))))
 (let (($x28743 (or $x28740 (and $x27809 (and (and true c_17_8) $x22493)))))
 (let (($x28746 (or $x28743 (and $x27814 (and (and true c_0_8) $x22388)))))
 (let (($x28749 (or $x28746 (and $x27823 (and $x27650 $x22353)))))
 (let (($x28752 (or $x28749 (and $x27827 (and $x27656 (and c_11_0 in_target_11))))))
 (let (($x28755 (or $x28752 (and $x27831 (and $x27662 (and c_12_0 in_target_12))))))
 (let (($x28758 (or $x28755 (and $x27835 (and $x27668 (and c_13_0 in_target_13))))))
 (let (($x28761 (or $x28758 (and $x27839 (and $x27674 $x22423)))))
 (let (($x28764 (or $x28761 (and $x27843 (and $x27680 $x22192)))))
 (let (($x28767 (or $x28764 (and $x27847 (and (and true c_9_8) $x22317)))))
 (let (($x28770 (or $x28767 (and $x27852 (and (and true c_17_8) $x22458)))))
 (let (($x28773 (or $x28770 (and $x27856 (and (and true c_18_8) $x22493)))))
 (let (($x28776 (or $x28773 (and $x27861 (and (and true c_0_8) $x22423)))))
 (let (($x28779 (or $x28776 (and $x27870 (and $x27650 $x22192)))))
 (let (($x28782 (or $x28779 (and $x27874 (and $x27656 $x22388)))))
 (let (($x28785 (or $x28782 (and $x27878 (and $x27662 (and c_13_0 in_target_13))))))
 (let (($x28788 (or $x28785 (and $x27882 (and $x27668 (and c_14_0 in_target_14))))))
 (let (($x28791 (or $x28788 (and $x27886 (and $x27674 (and c_15_0 in_target_15))))))
 (let (($x28794 (or $x28791 (and $x27890 (and $x27680 $x22458)))))
 (let (($x28797 (or $x28794 (and $x27894 (and (and true c_7_8) $x22317)))))
 (let (($x28800 (or $x28797 (and $x27899 (and (and true c_8_8) $x22353)))))
 (let (($x28803 (or $x28800 (and $x27904 (and (and true c_9_8) $x22493)))))
 (let (($x28806 (or $x28803 (and $x27908 (and (and true c_0_8) $x22458)))))
 (let (($x28809 (or $x28806 (and $x27913 (and $x27650 $x22493)))))
 (let (($x28812 (or $x28809 (and $x27917 (and $x27656 $x22192)))))
 (let (($x28815 (or $x28812 (and $x27921 (and $x27662 $x22423)))))
 (let (($x28818 (or $x28815 (and $x27925 (and $x27668 (and c_15_0 in_target_15))))))
 (let (($x28821 (or $x28818 (and $x27929 (and $x27674 (and c_16_0 in_target_16))))))
 (let (($x28824 (or $x28821 (and $x27933 (and $x27680 (and c_17_0 in_target_17))))))
 (let (($x28827 (or $x28824 (and $x27937 (and (and true c_8_8) $x22317)))))
 (let (($x28830 (or $x28827 (and $x27941 (and (and true c_10_8) $x22353)))))
 (let (($x28833 (or $x28830 (and $x27946 (and (and true c_11_8) $x22388)))))
 (let (($x28836 (or $x28833 (and $x27951 (and (and true c_0_8) $x22493)))))
 (let (($x28839 (or $x28836 (and $x27955 (and $x27650 (and c_9_0 in_target_9))))))
 (let (($x28842 (or $x28839 (and $x27959 (and $x27656 $x22317)))))
 (let (($x28845 (or $x28842 (and $x27963 (and $x27662 $x22192)))))
 (let (($x28848 (or $x28845 (and $x27967 (and $x27668 $x22458)))))
 (let (($x28851 (or $x28848 (and $x27971 (and $x27674 (and c_17_0 in_target_17))))))
 (let (($x28854 (or $x28851 (and $x27975 (and $x27680 (and c_18_0 in_target_18))))))
 (let (($x28857 (or $x28854 (and $x27979 (and (and true c_11_8) $x22353)))))
 (let (($x28860 (or $x28857 (and $x27983 (and (and true c_12_8) $x22388)))))
 (let (($x28863 (or $x28860 (and $x27988 (and (and true c_13_8) $x22423)))))
 (let (($x28896 (or $x28863 $x28895)))
 (let (($x28926 (or $x28896 (and $x27648 (and $x28491 $x28923)))))
 (let (($x28954 (or $x28926 (and $x27654 (and $x28495 $x28951)))))
 (let (($x28982 (or $x28954 (and $x27660 (and $x28499 $x28979)))))
 (let (($x29010 (or $x28982 (and $x27666 (and $x28503 $x29007)))))
 (let (($x29038 (or $x29010 (and $x27672 (and $x28505 $x29035)))))
 (let (($x29068 (not (or (and c_0_0 (not in_target_0)) $x22207))))
 (let (($x27413 (not c_90_8)))
 (let (($x27431 (or (and c_90_0 in_target_90) (and c_90_1 in_target_90) (and c_90_2 in_target_90) (and c_90_3 in_target_90) (and c_90_4 in_target_90) (and c_90_5 in_target_90) (and c_90_6 in_target_90) (and c_90_7 in_target_90) (and c_90_8 in_target_90))))
 (let (($x27370 (= ghost_2_60 1)))
 (let (($x27394 (and c_90_8 $x27370)))
 (let (($x27343 (not c_89_8)))
 (let (($x27361 (or (and c_89_0 in_target_89) (and c_89_1 in_target_89) (and c_89_2 in_target_89) (and c_89_3 in_target_89) (and c_89_4 in_target_89) (and c_89_5 in_target_89) (and c_89_6 in_target_89) (and c_89_7 in_target_89) (and c_89_8 in_target_89))))
 (let (($x27344 (and $x27361 $x27343)))
 (let (($x27392 (and c_89_8 $x27370)))
 (let (($x25483 (not c_59_8)))
 (let (($x25501 (or (and c_59_0 in_target_59) (and c_59_1 in_target_59) (and c_59_2 in_target_59) (and c_59_3 in_target_59) (and c_59_4 in_target_59) (and c_59_5 in_target_59) (and c_59_6 in_target_59) (and c_59_7 in_target_59) (and c_59_8 in_target_59))))
 (let (($x25484 (and $x25501 $x25483)))
 (let (($x27384 (and c_59_8 $x27370)))
 (let (($x24113 (not c_36_8)))
 (let (($x24131 (or (and c_36_0 in_target_36) (and c_36_1 in_target_36) (and c_36_2 in_target_36) (and c_36_3 in_target_36) (and c_36_4 in_target_36) (and c_36_5 in_target_36) (and c_36_6 in_target_36) (and c_36_7 in_target_36) (and c_36_8 in_target_36))))
 (let (($x24114 (and $x24131 $x24113)))
 (let (($x27380 (and c_36_8 $x27370)))
 (let (($x24523 (not c_43_8)))
 (let (($x24541 (or (and c_43_0 in_target_43) (and c_43_1 in_target_43) (and c_43_2 in_target_43) (and c_43_3 in_target_43) (and c_43_4 in_target_43) (and c_43_5 in_target_43) (and c_43_6 in_target_43) (and c_43_7 in_target_43) (and c_43_8 in_target_43))))
 (let (($x24524 (and $x24541 $x24523)))
 (let (($x27362 (and c_43_8 $x27370)))
 (let (($x26103 (not c_69_8)))
 (let (($x26121 (or (and c_69_0 in_target_69) (and c_69_1 in_target_69) (and c_69_2 in_target_69) (and c_69_3 in_target_69) (and c_69_4 in_target_69) (and c_69_5 in_target_69) (and c_69_6 in_target_69) (and c_69_7 in_target_69) (and c_69_8 in_target_69))))
 (let (($x26104 (and $x26121 $x26103)))
 (let (($x27375 (or (or false (and c_69_8 $x27370)) (and $x26104 (= ghost_2_69 (- ghost_2_60 1))))))
 (let (($x27378 (or (or $x27375 $x27362) (and $x24524 (= ghost_2_43 (- ghost_2_60 1))))))
 (let (($x27385 (or (or $x27378 $x27380) (and $x24114 (= ghost_2_36 (- ghost_2_60 1))))))
 (let (($x27389 (or (or $x27385 $x27384) (and $x25484 (= ghost_2_59 (- ghost_2_60 1))))))
 (let (($x27391 (or (or $x27389 $x27392) (and $x27344 (= ghost_2_89 (- ghost_2_60 1))))))
 (let (($x27427 (or (or $x27391 $x27394) (and (and $x27431 $x27413) (= ghost_2_90 (- ghost_2_60 1))))))
 (let (($x27437 (>= ghost_2_60 1)))
 (let (($x25553 (not c_60_8)))
 (let (($x25571 (or (and c_60_0 in_target_60) (and c_60_1 in_target_60) (and c_60_2 in_target_60) (and c_60_3 in_target_60) (and c_60_4 in_target_60) (and c_60_5 in_target_60) (and c_60_6 in_target_60) (and c_60_7 in_target_60) (and c_60_8 in_target_60))))
 (let (($x25554 (and $x25571 $x25553)))
 (let (($x27434 (and (=> (and $x25571 c_60_8) (= ghost_2_60 0)) (=> $x25554 (and $x27437 $x27427)))))
 (let (($x27300 (= ghost_2_59 1)))
 (let (($x27326 (and c_89_8 $x27300)))
 (let (($x27273 (not c_88_8)))
 (let (($x27291 (or (and c_88_0 in_target_88) (and c_88_1 in_target_88) (and c_88_2 in_target_88) (and c_88_3 in_target_88) (and c_88_4 in_target_88) (and c_88_5 in_target_88) (and c_88_6 in_target_88) (and c_88_7 in_target_88) (and c_88_8 in_target_88))))
 (let (($x27274 (and $x27291 $x27273)))
 (let (($x27322 (and c_88_8 $x27300)))
 (let (($x25413 (not c_58_8)))
 (let (($x25431 (or (and c_58_0 in_target_58) (and c_58_1 in_target_58) (and c_58_2 in_target_58) (and c_58_3 in_target_58) (and c_58_4 in_target_58) (and c_58_5 in_target_58) (and c_58_6 in_target_58) (and c_58_7 in_target_58) (and c_58_8 in_target_58))))
 (let (($x25414 (and $x25431 $x25413)))
 (let (($x27318 (and c_58_8 $x27300)))
 (let (($x24043 (not c_35_8)))
 (let (($x24061 (or (and c_35_0 in_target_35) (and c_35_1 in_target_35) (and c_35_2 in_target_35) (and c_35_3 in_target_35) (and c_35_4 in_target_35) (and c_35_5 in_target_35) (and c_35_6 in_target_35) (and c_35_7 in_target_35) (and c_35_8 in_target_35))))
 (let (($x24044 (and $x24061 $x24043)))
 (let (($x27309 (and c_35_8 $x27300)))
 (let (($x27302 (and c_36_8 $x27300)))
 (let (($x27306 (or (or false (and c_60_8 $x27300)) (and $x25554 (= ghost_2_60 (- ghost_2_59 1))))))
 (let (($x27310 (or (or $x27306 $x27302) (and $x24114 (= ghost_2_36 (- ghost_2_59 1))))))
 (let (($x27311 (or (or $x27310 $x27309) (and $x24044 (= ghost_2_35 (- ghost_2_59 1))))))
 (let (($x27319 (or (or $x27311 $x27318) (and $x25414 (= ghost_2_58 (- ghost_2_59 1))))))
 (let (($x27325 (or (or $x27319 $x27322) (and $x27274 (= ghost_2_88 (- ghost_2_59 1))))))
 (let (($x27359 (or (or $x27325 $x27326) (and $x27344 (= ghost_2_89 (- ghost_2_59 1))))))
 (let (($x27363 (>= ghost_2_59 1)))
 (let (($x27367 (and (=> (and $x25501 c_59_8) (= ghost_2_59 0)) (=> $x25484 (and $x27363 $x27359)))))
 (let (($x27229 (= ghost_2_58 1)))
 (let (($x27250 (and c_88_8 $x27229)))
 (let (($x27203 (not c_87_8)))
 (let (($x27221 (or (and c_87_0 in_target_87) (and c_87_1 in_target_87) (and c_87_2 in_target_87) (and c_87_3 in_target_87) (and c_87_4 in_target_87) (and c_87_5 in_target_87) (and c_87_6 in_target_87) (and c_87_7 in_target_87) (and c_87_8 in_target_87))))
 (let (($x27204 (and $x27221 $x27203)))
 (let (($x27251 (and c_87_8 $x27229)))
 (let (($x25343 (not c_57_8)))
 (let (($x25361 (or (and c_57_0 in_target_57) (and c_57_1 in_target_57) (and c_57_2 in_target_57) (and c_57_3 in_target_57) (and c_57_4 in_target_57) (and c_57_5 in_target_57) (and c_57_6 in_target_57) (and c_57_7 in_target_57) (and c_57_8 in_target_57))))
 (let (($x25344 (and $x25361 $x25343)))
 (let (($x27247 (and c_57_8 $x27229)))
 (let (($x23973 (not c_34_8)))
 (let (($x23991 (or (and c_34_0 in_target_34) (and c_34_1 in_target_34) (and c_34_2 in_target_34) (and c_34_3 in_target_34) (and c_34_4 in_target_34) (and c_34_5 in_target_34) (and c_34_6 in_target_34) (and c_34_7 in_target_34) (and c_34_8 in_target_34))))
 (let (($x23974 (and $x23991 $x23973)))
 (let (($x27243 (and c_34_8 $x27229)))
 (let (($x27234 (and c_35_8 $x27229)))
 (let (($x27236 (or (or false (and c_59_8 $x27229)) (and $x25484 (= ghost_2_59 (- ghost_2_58 1))))))
 (let (($x27224 (or (or $x27236 $x27234) (and $x24044 (= ghost_2_35 (- ghost_2_58 1))))))
 (let (($x27245 (or (or $x27224 $x27243) (and $x23974 (= ghost_2_34 (- ghost_2_58 1))))))
 (let (($x27252 (or (or $x27245 $x27247) (and $x25344 (= ghost_2_57 (- ghost_2_58 1))))))
 (let (($x27255 (or (or $x27252 $x27251) (and $x27204 (= ghost_2_87 (- ghost_2_58 1))))))
 (let (($x27287 (or (or $x27255 $x27250) (and $x27274 (= ghost_2_88 (- ghost_2_58 1))))))
 (let (($x27293 (>= ghost_2_58 1)))
 (let (($x27292 (and (=> (and $x25431 c_58_8) (= ghost_2_58 0)) (=> $x25414 (and $x27293 $x27287)))))
 (let (($x27154 (= ghost_2_57 1)))
 (let (($x27181 (and c_87_8 $x27154)))
 (let (($x27133 (not c_86_8)))
 (let (($x27151 (or (and c_86_0 in_target_86) (and c_86_1 in_target_86) (and c_86_2 in_target_86) (and c_86_3 in_target_86) (and c_86_4 in_target_86) (and c_86_5 in_target_86) (and c_86_6 in_target_86) (and c_86_7 in_target_86) (and c_86_8 in_target_86))))
 (let (($x27134 (and $x27151 $x27133)))
 (let (($x27178 (and c_86_8 $x27154)))
 (let (($x25308 (not c_56_8)))
 (let (($x25326 (or (and c_56_0 in_target_56) (and c_56_1 in_target_56) (and c_56_2 in_target_56) (and c_56_3 in_target_56) (and c_56_4 in_target_56) (and c_56_5 in_target_56) (and c_56_6 in_target_56) (and c_56_7 in_target_56) (and c_56_8 in_target_56))))
 (let (($x25309 (and $x25326 $x25308)))
 (let (($x27176 (and c_56_8 $x27154)))
 (let (($x23938 (not c_33_8)))
 (let (($x23956 (or (and c_33_0 in_target_33) (and c_33_1 in_target_33) (and c_33_2 in_target_33) (and c_33_3 in_target_33) (and c_33_4 in_target_33) (and c_33_5 in_target_33) (and c_33_6 in_target_33) (and c_33_7 in_target_33) (and c_33_8 in_target_33))))
 (let (($x23939 (and $x23956 $x23938)))
 (let (($x27172 (and c_33_8 $x27154)))
 (let (($x27167 (and c_34_8 $x27154)))
 (let (($x27166 (or (or false (and c_58_8 $x27154)) (and $x25414 (= ghost_2_58 (- ghost_2_57 1))))))
 (let (($x27170 (or (or $x27166 $x27167) (and $x23974 (= ghost_2_34 (- ghost_2_57 1))))))
 (let (($x27175 (or (or $x27170 $x27172) (and $x23939 (= ghost_2_33 (- ghost_2_57 1))))))
 (let (($x27182 (or (or $x27175 $x27176) (and $x25309 (= ghost_2_56 (- ghost_2_57 1))))))
 (let (($x27186 (or (or $x27182 $x27178) (and $x27134 (= ghost_2_86 (- ghost_2_57 1))))))
 (let (($x27219 (or (or $x27186 $x27181) (and $x27204 (= ghost_2_87 (- ghost_2_57 1))))))
 (let (($x27226 (>= ghost_2_57 1)))
 (let (($x27223 (and (=> (and $x25361 c_57_8) (= ghost_2_57 0)) (=> $x25344 (and $x27226 $x27219)))))
 (let (($x27059 (= ghost_2_56 1)))
 (let (($x27104 (and c_86_8 $x27059)))
 (let (($x27098 (not c_85_8)))
 (let (($x27116 (or (and c_85_0 in_target_85) (and c_85_1 in_target_85) (and c_85_2 in_target_85) (and c_85_3 in_target_85) (and c_85_4 in_target_85) (and c_85_5 in_target_85) (and c_85_6 in_target_85) (and c_85_7 in_target_85) (and c_85_8 in_target_85))))
 (let (($x27081 (and c_85_8 $x27059)))
 (let (($x27028 (not c_84_8)))
 (let (($x27046 (or (and c_84_0 in_target_84) (and c_84_1 in_target_84) (and c_84_2 in_target_84) (and c_84_3 in_target_84) (and c_84_4 in_target_84) (and c_84_5 in_target_84) (and c_84_6 in_target_84) (and c_84_7 in_target_84) (and c_84_8 in_target_84))))
 (let (($x27029 (and $x27046 $x27028)))
 (let (($x27076 (and c_84_8 $x27059)))
 (let (($x25238 (not c_55_8)))
 (let (($x25256 (or (and c_55_0 in_target_55) (and c_55_1 in_target_55) (and c_55_2 in_target_55) (and c_55_3 in_target_55) (and c_55_4 in_target_55) (and c_55_5 in_target_55) (and c_55_6 in_target_55) (and c_55_7 in_target_55) (and c_55_8 in_target_55))))
 (let (($x25239 (and $x25256 $x25238)))
 (let (($x27071 (and c_55_8 $x27059)))
 (let (($x27067 (and c_33_8 $x27059)))
 (let (($x27065 (or (or false (and c_57_8 $x27059)) (and $x25344 (= ghost_2_57 (- ghost_2_56 1))))))
 (let (($x27070 (or (or $x27065 $x27067) (and $x23939 (= ghost_2_33 (- ghost_2_56 1))))))
 (let (($x27078 (or (or $x27070 $x27071) (and $x25239 (= ghost_2_55 (- ghost_2_56 1))))))
 (let (($x27074 (or (or $x27078 $x27076) (and $x27029 (= ghost_2_84 (- ghost_2_56 1))))))
 (let (($x27108 (or (or $x27074 $x27081) (and (and $x27116 $x27098) (= ghost_2_85 (- ghost_2_56 1))))))
 (let (($x27149 (or (or $x27108 $x27104) (and $x27134 (= ghost_2_86 (- ghost_2_56 1))))))
 (let (($x27156 (>= ghost_2_56 1)))
 (let (($x27157 (and (=> (and $x25326 c_56_8) (= ghost_2_56 0)) (=> $x25309 (and $x27156 $x27149)))))
 (let (($x26990 (= ghost_2_55 1)))
 (let (($x27032 (and c_56_8 $x26990)))
 (let (($x27009 (and c_84_8 $x26990)))
 (let (($x26958 (not c_83_8)))
 (let (($x26976 (or (and c_83_0 in_target_83) (and c_83_1 in_target_83) (and c_83_2 in_target_83) (and c_83_3 in_target_83) (and c_83_4 in_target_83) (and c_83_5 in_target_83) (and c_83_6 in_target_83) (and c_83_7 in_target_83) (and c_83_8 in_target_83))))
 (let (($x26959 (and $x26976 $x26958)))
 (let (($x27007 (and c_83_8 $x26990)))
 (let (($x25168 (not c_54_8)))
 (let (($x25186 (or (and c_54_0 in_target_54) (and c_54_1 in_target_54) (and c_54_2 in_target_54) (and c_54_3 in_target_54) (and c_54_4 in_target_54) (and c_54_5 in_target_54) (and c_54_6 in_target_54) (and c_54_7 in_target_54) (and c_54_8 in_target_54))))
 (let (($x25169 (and $x25186 $x25168)))
 (let (($x27001 (and c_54_8 $x26990)))
 (let (($x23868 (not c_32_8)))
 (let (($x23886 (or (and c_32_0 in_target_32) (and c_32_1 in_target_32) (and c_32_2 in_target_32) (and c_32_3 in_target_32) (and c_32_4 in_target_32) (and c_32_5 in_target_32) (and c_32_6 in_target_32) (and c_32_7 in_target_32) (and c_32_8 in_target_32))))
 (let (($x23869 (and $x23886 $x23868)))
 (let (($x26991 (and c_32_8 $x26990)))
 (let (($x26995 (or (or false (and c_33_8 $x26990)) (and $x23939 (= ghost_2_33 (- ghost_2_55 1))))))
 (let (($x27000 (or (or $x26995 $x26991) (and $x23869 (= ghost_2_32 (- ghost_2_55 1))))))
 (let (($x27004 (or (or $x27000 $x27001) (and $x25169 (= ghost_2_54 (- ghost_2_55 1))))))
 (let (($x26997 (or (or $x27004 $x27007) (and $x26959 (= ghost_2_83 (- ghost_2_55 1))))))
 (let (($x27044 (or (or $x26997 $x27009) (and $x27029 (= ghost_2_84 (- ghost_2_55 1))))))
 (let (($x27052 (or (or $x27044 $x27032) (and $x25309 (= ghost_2_56 (- ghost_2_55 1))))))
 (let (($x27057 (>= ghost_2_55 1)))
 (let (($x27056 (and (=> (and $x25256 c_55_8) (= ghost_2_55 0)) (=> $x25239 (and $x27057 $x27052)))))
 (let (($x26914 (= ghost_2_54 1)))
 (let (($x26970 (and c_55_8 $x26914)))
 (let (($x26937 (and c_83_8 $x26914)))
 (let (($x26888 (not c_82_8)))
 (let (($x26906 (or (and c_82_0 in_target_82) (and c_82_1 in_target_82) (and c_82_2 in_target_82) (and c_82_3 in_target_82) (and c_82_4 in_target_82) (and c_82_5 in_target_82) (and c_82_6 in_target_82) (and c_82_7 in_target_82) (and c_82_8 in_target_82))))
 (let (($x26889 (and $x26906 $x26888)))
 (let (($x26929 (and c_82_8 $x26914)))
 (let (($x25098 (not c_53_8)))
 (let (($x25116 (or (and c_53_0 in_target_53) (and c_53_1 in_target_53) (and c_53_2 in_target_53) (and c_53_3 in_target_53) (and c_53_4 in_target_53) (and c_53_5 in_target_53) (and c_53_6 in_target_53) (and c_53_7 in_target_53) (and c_53_8 in_target_53))))
 (let (($x25099 (and $x25116 $x25098)))
 (let (($x26920 (and c_53_8 $x26914)))
 (let (($x23798 (not c_31_8)))
 (let (($x23816 (or (and c_31_0 in_target_31) (and c_31_1 in_target_31) (and c_31_2 in_target_31) (and c_31_3 in_target_31) (and c_31_4 in_target_31) (and c_31_5 in_target_31) (and c_31_6 in_target_31) (and c_31_7 in_target_31) (and c_31_8 in_target_31))))
 (let (($x23799 (and $x23816 $x23798)))
 (let (($x26926 (and c_31_8 $x26914)))
 (let (($x26925 (or (or false (and c_32_8 $x26914)) (and $x23869 (= ghost_2_32 (- ghost_2_54 1))))))
 (let (($x26930 (or (or $x26925 $x26926) (and $x23799 (= ghost_2_31 (- ghost_2_54 1))))))
 (let (($x26928 (or (or $x26930 $x26920) (and $x25099 (= ghost_2_53 (- ghost_2_54 1))))))
 (let (($x26940 (or (or $x26928 $x26929) (and $x26889 (= ghost_2_82 (- ghost_2_54 1))))))
 (let (($x26972 (or (or $x26940 $x26937) (and $x26959 (= ghost_2_83 (- ghost_2_54 1))))))
 (let (($x26983 (or (or $x26972 $x26970) (and $x25239 (= ghost_2_55 (- ghost_2_54 1))))))
 (let (($x26979 (>= ghost_2_54 1)))
 (let (($x26977 (and (=> (and $x25186 c_54_8) (= ghost_2_54 0)) (=> $x25169 (and $x26979 $x26983)))))
 (let (($x26845 (= ghost_2_53 1)))
 (let (($x26892 (and c_54_8 $x26845)))
 (let (($x26870 (and c_82_8 $x26845)))
 (let (($x26818 (not c_81_8)))
 (let (($x26836 (or (and c_81_0 in_target_81) (and c_81_1 in_target_81) (and c_81_2 in_target_81) (and c_81_3 in_target_81) (and c_81_4 in_target_81) (and c_81_5 in_target_81) (and c_81_6 in_target_81) (and c_81_7 in_target_81) (and c_81_8 in_target_81))))
 (let (($x26819 (and $x26836 $x26818)))
 (let (($x26864 (and c_81_8 $x26845)))
 (let (($x25063 (not c_52_8)))
 (let (($x25081 (or (and c_52_0 in_target_52) (and c_52_1 in_target_52) (and c_52_2 in_target_52) (and c_52_3 in_target_52) (and c_52_4 in_target_52) (and c_52_5 in_target_52) (and c_52_6 in_target_52) (and c_52_7 in_target_52) (and c_52_8 in_target_52))))
 (let (($x25064 (and $x25081 $x25063)))
 (let (($x26861 (and c_52_8 $x26845)))
 (let (($x23763 (not c_30_8)))
 (let (($x23781 (or (and c_30_0 in_target_30) (and c_30_1 in_target_30) (and c_30_2 in_target_30) (and c_30_3 in_target_30) (and c_30_4 in_target_30) (and c_30_5 in_target_30) (and c_30_6 in_target_30) (and c_30_7 in_target_30) (and c_30_8 in_target_30))))
 (let (($x23764 (and $x23781 $x23763)))
 (let (($x26857 (and c_30_8 $x26845)))
 (let (($x26849 (or (or false (and c_31_8 $x26845)) (and $x23799 (= ghost_2_31 (- ghost_2_53 1))))))
 (let (($x26858 (or (or $x26849 $x26857) (and $x23764 (= ghost_2_30 (- ghost_2_53 1))))))
 (let (($x26860 (or (or $x26858 $x26861) (and $x25064 (= ghost_2_52 (- ghost_2_53 1))))))
 (let (($x26868 (or (or $x26860 $x26864) (and $x26819 (= ghost_2_81 (- ghost_2_53 1))))))
 (let (($x26900 (or (or $x26868 $x26870) (and $x26889 (= ghost_2_82 (- ghost_2_53 1))))))
 (let (($x26909 (or (or $x26900 $x26892) (and $x25169 (= ghost_2_54 (- ghost_2_53 1))))))
 (let (($x26908 (>= ghost_2_53 1)))
 (let (($x26915 (and (=> (and $x25116 c_53_8) (= ghost_2_53 0)) (=> $x25099 (and $x26908 $x26909)))))
 (let (($x26750 (= ghost_2_52 1)))
 (let (($x26826 (and c_53_8 $x26750)))
 (let (($x26797 (and c_81_8 $x26750)))
 (let (($x26783 (not c_80_8)))
 (let (($x26801 (or (and c_80_0 in_target_80) (and c_80_1 in_target_80) (and c_80_2 in_target_80) (and c_80_3 in_target_80) (and c_80_4 in_target_80) (and c_80_5 in_target_80) (and c_80_6 in_target_80) (and c_80_7 in_target_80) (and c_80_8 in_target_80))))
 (let (($x26756 (and c_80_8 $x26750)))
 (let (($x26713 (not c_79_8)))
 (let (($x26731 (or (and c_79_0 in_target_79) (and c_79_1 in_target_79) (and c_79_2 in_target_79) (and c_79_3 in_target_79) (and c_79_4 in_target_79) (and c_79_5 in_target_79) (and c_79_6 in_target_79) (and c_79_7 in_target_79) (and c_79_8 in_target_79))))
 (let (($x26714 (and $x26731 $x26713)))
 (let (($x26762 (and c_79_8 $x26750)))
 (let (($x24993 (not c_51_8)))
 (let (($x25011 (or (and c_51_0 in_target_51) (and c_51_1 in_target_51) (and c_51_2 in_target_51) (and c_51_3 in_target_51) (and c_51_4 in_target_51) (and c_51_5 in_target_51) (and c_51_6 in_target_51) (and c_51_7 in_target_51) (and c_51_8 in_target_51))))
 (let (($x24994 (and $x25011 $x24993)))
 (let (($x26757 (and c_51_8 $x26750)))
 (let (($x26755 (or (or false (and c_30_8 $x26750)) (and $x23764 (= ghost_2_30 (- ghost_2_52 1))))))
 (let (($x26759 (or (or $x26755 $x26757) (and $x24994 (= ghost_2_51 (- ghost_2_52 1))))))
 (let (($x26758 (or (or $x26759 $x26762) (and $x26714 (= ghost_2_79 (- ghost_2_52 1))))))
 (let (($x26793 (or (or $x26758 $x26756) (and (and $x26801 $x26783) (= ghost_2_80 (- ghost_2_52 1))))))
 (let (($x26832 (or (or $x26793 $x26797) (and $x26819 (= ghost_2_81 (- ghost_2_52 1))))))
 (let (($x26838 (or (or $x26832 $x26826) (and $x25099 (= ghost_2_53 (- ghost_2_52 1))))))
 (let (($x26840 (>= ghost_2_52 1)))
 (let (($x26843 (and (=> (and $x25081 c_52_8) (= ghost_2_52 0)) (=> $x25064 (and $x26840 $x26838)))))
 (let (($x26681 (= ghost_2_51 1)))
 (let (($x26734 (and c_30_8 $x26681)))
 (let (($x26723 (and c_52_8 $x26681)))
 (let (($x26696 (and c_79_8 $x26681)))
 (let (($x26643 (not c_78_8)))
 (let (($x26661 (or (and c_78_0 in_target_78) (and c_78_1 in_target_78) (and c_78_2 in_target_78) (and c_78_3 in_target_78) (and c_78_4 in_target_78) (and c_78_5 in_target_78) (and c_78_6 in_target_78) (and c_78_7 in_target_78) (and c_78_8 in_target_78))))
 (let (($x26644 (and $x26661 $x26643)))
 (let (($x26693 (and c_78_8 $x26681)))
 (let (($x24923 (not c_50_8)))
 (let (($x24941 (or (and c_50_0 in_target_50) (and c_50_1 in_target_50) (and c_50_2 in_target_50) (and c_50_3 in_target_50) (and c_50_4 in_target_50) (and c_50_5 in_target_50) (and c_50_6 in_target_50) (and c_50_7 in_target_50) (and c_50_8 in_target_50))))
 (let (($x24924 (and $x24941 $x24923)))
 (let (($x26684 (and c_50_8 $x26681)))
 (let (($x23693 (not c_29_8)))
 (let (($x23711 (or (and c_29_0 in_target_29) (and c_29_1 in_target_29) (and c_29_2 in_target_29) (and c_29_3 in_target_29) (and c_29_4 in_target_29) (and c_29_5 in_target_29) (and c_29_6 in_target_29) (and c_29_7 in_target_29) (and c_29_8 in_target_29))))
 (let (($x23694 (and $x23711 $x23693)))
 (let (($x26686 (or (or false (and c_29_8 $x26681)) (and $x23694 (= ghost_2_29 (- ghost_2_51 1))))))
 (let (($x26689 (or (or $x26686 $x26684) (and $x24924 (= ghost_2_50 (- ghost_2_51 1))))))
 (let (($x26697 (or (or $x26689 $x26693) (and $x26644 (= ghost_2_78 (- ghost_2_51 1))))))
 (let (($x26727 (or (or $x26697 $x26696) (and $x26714 (= ghost_2_79 (- ghost_2_51 1))))))
 (let (($x26732 (or (or $x26727 $x26723) (and $x25064 (= ghost_2_52 (- ghost_2_51 1))))))
 (let (($x26736 (or (or $x26732 $x26734) (and $x23764 (= ghost_2_30 (- ghost_2_51 1))))))
 (let (($x26742 (>= ghost_2_51 1)))
 (let (($x26745 (and (=> (and $x25011 c_51_8) (= ghost_2_51 0)) (=> $x24994 (and $x26742 $x26736)))))
 (let (($x26593 (= ghost_2_50 1)))
 (let (($x26667 (and c_29_8 $x26593)))
 (let (($x26651 (and c_51_8 $x26593)))
 (let (($x26625 (and c_78_8 $x26593)))
 (let (($x26573 (not c_77_8)))
 (let (($x26591 (or (and c_77_0 in_target_77) (and c_77_1 in_target_77) (and c_77_2 in_target_77) (and c_77_3 in_target_77) (and c_77_4 in_target_77) (and c_77_5 in_target_77) (and c_77_6 in_target_77) (and c_77_7 in_target_77) (and c_77_8 in_target_77))))
 (let (($x26574 (and $x26591 $x26573)))
 (let (($x26617 (and c_77_8 $x26593)))
 (let (($x24853 (not c_49_8)))
 (let (($x24871 (or (and c_49_0 in_target_49) (and c_49_1 in_target_49) (and c_49_2 in_target_49) (and c_49_3 in_target_49) (and c_49_4 in_target_49) (and c_49_5 in_target_49) (and c_49_6 in_target_49) (and c_49_7 in_target_49) (and c_49_8 in_target_49))))
 (let (($x24854 (and $x24871 $x24853)))
 (let (($x26614 (and c_49_8 $x26593)))
 (let (($x23623 (not c_28_8)))
 (let (($x23641 (or (and c_28_0 in_target_28) (and c_28_1 in_target_28) (and c_28_2 in_target_28) (and c_28_3 in_target_28) (and c_28_4 in_target_28) (and c_28_5 in_target_28) (and c_28_6 in_target_28) (and c_28_7 in_target_28) (and c_28_8 in_target_28))))
 (let (($x23624 (and $x23641 $x23623)))
 (let (($x26616 (or (or false (and c_28_8 $x26593)) (and $x23624 (= ghost_2_28 (- ghost_2_50 1))))))
 (let (($x26620 (or (or $x26616 $x26614) (and $x24854 (= ghost_2_49 (- ghost_2_50 1))))))
 (let (($x26622 (or (or $x26620 $x26617) (and $x26574 (= ghost_2_77 (- ghost_2_50 1))))))
 (let (($x26649 (or (or $x26622 $x26625) (and $x26644 (= ghost_2_78 (- ghost_2_50 1))))))
 (let (($x26664 (or (or $x26649 $x26651) (and $x24994 (= ghost_2_51 (- ghost_2_50 1))))))
 (let (($x26669 (or (or $x26664 $x26667) (and $x23694 (= ghost_2_29 (- ghost_2_50 1))))))
 (let (($x26662 (>= ghost_2_50 1)))
 (let (($x26675 (and (=> (and $x24941 c_50_8) (= ghost_2_50 0)) (=> $x24924 (and $x26662 $x26669)))))
 (let (($x26541 (= ghost_2_49 1)))
 (let (($x26598 (and c_28_8 $x26541)))
 (let (($x26579 (and c_50_8 $x26541)))
 (let (($x26555 (and c_77_8 $x26541)))
 (let (($x26503 (not c_76_8)))
 (let (($x26521 (or (and c_76_0 in_target_76) (and c_76_1 in_target_76) (and c_76_2 in_target_76) (and c_76_3 in_target_76) (and c_76_4 in_target_76) (and c_76_5 in_target_76) (and c_76_6 in_target_76) (and c_76_7 in_target_76) (and c_76_8 in_target_76))))
 (let (($x26504 (and $x26521 $x26503)))
 (let (($x26553 (and c_76_8 $x26541)))
 (let (($x24818 (not c_48_8)))
 (let (($x24836 (or (and c_48_0 in_target_48) (and c_48_1 in_target_48) (and c_48_2 in_target_48) (and c_48_3 in_target_48) (and c_48_4 in_target_48) (and c_48_5 in_target_48) (and c_48_6 in_target_48) (and c_48_7 in_target_48) (and c_48_8 in_target_48))))
 (let (($x24819 (and $x24836 $x24818)))
 (let (($x26544 (and c_48_8 $x26541)))
 (let (($x23588 (not c_27_8)))
 (let (($x23606 (or (and c_27_0 in_target_27) (and c_27_1 in_target_27) (and c_27_2 in_target_27) (and c_27_3 in_target_27) (and c_27_4 in_target_27) (and c_27_5 in_target_27) (and c_27_6 in_target_27) (and c_27_7 in_target_27) (and c_27_8 in_target_27))))
 (let (($x23589 (and $x23606 $x23588)))
 (let (($x26547 (or (or false (and c_27_8 $x26541)) (and $x23589 (= ghost_2_27 (- ghost_2_49 1))))))
 (let (($x26548 (or (or $x26547 $x26544) (and $x24819 (= ghost_2_48 (- ghost_2_49 1))))))
 (let (($x26549 (or (or $x26548 $x26553) (and $x26504 (= ghost_2_76 (- ghost_2_49 1))))))
 (let (($x26589 (or (or $x26549 $x26555) (and $x26574 (= ghost_2_77 (- ghost_2_49 1))))))
 (let (($x26594 (or (or $x26589 $x26579) (and $x24924 (= ghost_2_50 (- ghost_2_49 1))))))
 (let (($x26599 (or (or $x26594 $x26598) (and $x23624 (= ghost_2_28 (- ghost_2_49 1))))))
 (let (($x26604 (>= ghost_2_49 1)))
 (let (($x26603 (and (=> (and $x24871 c_49_8) (= ghost_2_49 0)) (=> $x24854 (and $x26604 $x26599)))))
 (let (($x26434 (= ghost_2_48 1)))
 (let (($x26522 (and c_27_8 $x26434)))
 (let (($x26515 (and c_49_8 $x26434)))
 (let (($x26474 (and c_76_8 $x26434)))
 (let (($x26468 (not c_75_8)))
 (let (($x26486 (or (and c_75_0 in_target_75) (and c_75_1 in_target_75) (and c_75_2 in_target_75) (and c_75_3 in_target_75) (and c_75_4 in_target_75) (and c_75_5 in_target_75) (and c_75_6 in_target_75) (and c_75_7 in_target_75) (and c_75_8 in_target_75))))
 (let (($x26451 (and c_75_8 $x26434)))
 (let (($x26398 (not c_74_8)))
 (let (($x26416 (or (and c_74_0 in_target_74) (and c_74_1 in_target_74) (and c_74_2 in_target_74) (and c_74_3 in_target_74) (and c_74_4 in_target_74) (and c_74_5 in_target_74) (and c_74_6 in_target_74) (and c_74_7 in_target_74) (and c_74_8 in_target_74))))
 (let (($x26399 (and $x26416 $x26398)))
 (let (($x26443 (and c_74_8 $x26434)))
 (let (($x24748 (not c_47_8)))
 (let (($x24766 (or (and c_47_0 in_target_47) (and c_47_1 in_target_47) (and c_47_2 in_target_47) (and c_47_3 in_target_47) (and c_47_4 in_target_47) (and c_47_5 in_target_47) (and c_47_6 in_target_47) (and c_47_7 in_target_47) (and c_47_8 in_target_47))))
 (let (($x24749 (and $x24766 $x24748)))
 (let (($x26436 (or (or false (and c_47_8 $x26434)) (and $x24749 (= ghost_2_47 (- ghost_2_48 1))))))
 (let (($x26448 (or (or $x26436 $x26443) (and $x26399 (= ghost_2_74 (- ghost_2_48 1))))))
 (let (($x26472 (or (or $x26448 $x26451) (and (and $x26486 $x26468) (= ghost_2_75 (- ghost_2_48 1))))))
 (let (($x26519 (or (or $x26472 $x26474) (and $x26504 (= ghost_2_76 (- ghost_2_48 1))))))
 (let (($x26525 (or (or $x26519 $x26515) (and $x24854 (= ghost_2_49 (- ghost_2_48 1))))))
 (let (($x26531 (or (or $x26525 $x26522) (and $x23589 (= ghost_2_27 (- ghost_2_48 1))))))
 (let (($x26532 (>= ghost_2_48 1)))
 (let (($x26534 (and (=> (and $x24836 c_48_8) (= ghost_2_48 0)) (=> $x24819 (and $x26532 $x26531)))))
 (let (($x23518 (not c_26_8)))
 (let (($x23536 (or (and c_26_0 in_target_26) (and c_26_1 in_target_26) (and c_26_2 in_target_26) (and c_26_3 in_target_26) (and c_26_4 in_target_26) (and c_26_5 in_target_26) (and c_26_6 in_target_26) (and c_26_7 in_target_26) (and c_26_8 in_target_26))))
 (let (($x23519 (and $x23536 $x23518)))
 (let (($x26368 (= ghost_2_47 1)))
 (let (($x26428 (and c_26_8 $x26368)))
 (let (($x26423 (and c_27_8 $x26368)))
 (let (($x26406 (and c_48_8 $x26368)))
 (let (($x26379 (and c_74_8 $x26368)))
 (let (($x26328 (not c_73_8)))
 (let (($x26346 (or (and c_73_0 in_target_73) (and c_73_1 in_target_73) (and c_73_2 in_target_73) (and c_73_3 in_target_73) (and c_73_4 in_target_73) (and c_73_5 in_target_73) (and c_73_6 in_target_73) (and c_73_7 in_target_73) (and c_73_8 in_target_73))))
 (let (($x26329 (and $x26346 $x26328)))
 (let (($x26371 (and c_73_8 $x26368)))
 (let (($x24678 (not c_46_8)))
 (let (($x24696 (or (and c_46_0 in_target_46) (and c_46_1 in_target_46) (and c_46_2 in_target_46) (and c_46_3 in_target_46) (and c_46_4 in_target_46) (and c_46_5 in_target_46) (and c_46_6 in_target_46) (and c_46_7 in_target_46) (and c_46_8 in_target_46))))
 (let (($x24679 (and $x24696 $x24678)))
 (let (($x26374 (or (or false (and c_46_8 $x26368)) (and $x24679 (= ghost_2_46 (- ghost_2_47 1))))))
 (let (($x26378 (or (or $x26374 $x26371) (and $x26329 (= ghost_2_73 (- ghost_2_47 1))))))
 (let (($x26414 (or (or $x26378 $x26379) (and $x26399 (= ghost_2_74 (- ghost_2_47 1))))))
 (let (($x26418 (or (or $x26414 $x26406) (and $x24819 (= ghost_2_48 (- ghost_2_47 1))))))
 (let (($x26426 (or (or $x26418 $x26423) (and $x23589 (= ghost_2_27 (- ghost_2_47 1))))))
 (let (($x26424 (or (or $x26426 $x26428) (and $x23519 (= ghost_2_26 (- ghost_2_47 1))))))
 (let (($x26437 (>= ghost_2_47 1)))
 (let (($x26435 (and (=> (and $x24766 c_47_8) (= ghost_2_47 0)) (=> $x24749 (and $x26437 $x26424)))))
 (let (($x23448 (not c_25_8)))
 (let (($x23466 (or (and c_25_0 in_target_25) (and c_25_1 in_target_25) (and c_25_2 in_target_25) (and c_25_3 in_target_25) (and c_25_4 in_target_25) (and c_25_5 in_target_25) (and c_25_6 in_target_25) (and c_25_7 in_target_25) (and c_25_8 in_target_25))))
 (let (($x23449 (and $x23466 $x23448)))
 (let (($x26301 (= ghost_2_46 1)))
 (let (($x26354 (and c_25_8 $x26301)))
 (let (($x26347 (and c_26_8 $x26301)))
 (let (($x26342 (and c_47_8 $x26301)))
 (let (($x26310 (and c_73_8 $x26301)))
 (let (($x26258 (not c_72_8)))
 (let (($x26276 (or (and c_72_0 in_target_72) (and c_72_1 in_target_72) (and c_72_2 in_target_72) (and c_72_3 in_target_72) (and c_72_4 in_target_72) (and c_72_5 in_target_72) (and c_72_6 in_target_72) (and c_72_7 in_target_72) (and c_72_8 in_target_72))))
 (let (($x26259 (and $x26276 $x26258)))
 (let (($x26305 (and c_72_8 $x26301)))
 (let (($x24608 (not c_45_8)))
 (let (($x24626 (or (and c_45_0 in_target_45) (and c_45_1 in_target_45) (and c_45_2 in_target_45) (and c_45_3 in_target_45) (and c_45_4 in_target_45) (and c_45_5 in_target_45) (and c_45_6 in_target_45) (and c_45_7 in_target_45) (and c_45_8 in_target_45))))
 (let (($x24609 (and $x24626 $x24608)))
 (let (($x26307 (or (or false (and c_45_8 $x26301)) (and $x24609 (= ghost_2_45 (- ghost_2_46 1))))))
 (let (($x26308 (or (or $x26307 $x26305) (and $x26259 (= ghost_2_72 (- ghost_2_46 1))))))
 (let (($x26338 (or (or $x26308 $x26310) (and $x26329 (= ghost_2_73 (- ghost_2_46 1))))))
 (let (($x26353 (or (or $x26338 $x26342) (and $x24749 (= ghost_2_47 (- ghost_2_46 1))))))
 (let (($x26348 (or (or $x26353 $x26347) (and $x23519 (= ghost_2_26 (- ghost_2_46 1))))))
 (let (($x26359 (or (or $x26348 $x26354) (and $x23449 (= ghost_2_25 (- ghost_2_46 1))))))
 (let (($x26363 (>= ghost_2_46 1)))
 (let (($x26365 (and (=> (and $x24696 c_46_8) (= ghost_2_46 0)) (=> $x24679 (and $x26363 $x26359)))))
 (let (($x23413 (not c_24_8)))
 (let (($x23431 (or (and c_24_0 in_target_24) (and c_24_1 in_target_24) (and c_24_2 in_target_24) (and c_24_3 in_target_24) (and c_24_4 in_target_24) (and c_24_5 in_target_24) (and c_24_6 in_target_24) (and c_24_7 in_target_24) (and c_24_8 in_target_24))))
 (let (($x23414 (and $x23431 $x23413)))
 (let (($x26225 (= ghost_2_45 1)))
 (let (($x26286 (and c_24_8 $x26225)))
 (let (($x26280 (and c_25_8 $x26225)))
 (let (($x26270 (and c_46_8 $x26225)))
 (let (($x26242 (and c_72_8 $x26225)))
 (let (($x26188 (not c_71_8)))
 (let (($x26206 (or (and c_71_0 in_target_71) (and c_71_1 in_target_71) (and c_71_2 in_target_71) (and c_71_3 in_target_71) (and c_71_4 in_target_71) (and c_71_5 in_target_71) (and c_71_6 in_target_71) (and c_71_7 in_target_71) (and c_71_8 in_target_71))))
 (let (($x26189 (and $x26206 $x26188)))
 (let (($x26232 (and c_71_8 $x26225)))
 (let (($x24573 (not c_44_8)))
 (let (($x24591 (or (and c_44_0 in_target_44) (and c_44_1 in_target_44) (and c_44_2 in_target_44) (and c_44_3 in_target_44) (and c_44_4 in_target_44) (and c_44_5 in_target_44) (and c_44_6 in_target_44) (and c_44_7 in_target_44) (and c_44_8 in_target_44))))
 (let (($x24574 (and $x24591 $x24573)))
 (let (($x26233 (or (or false (and c_44_8 $x26225)) (and $x24574 (= ghost_2_44 (- ghost_2_45 1))))))
 (let (($x26239 (or (or $x26233 $x26232) (and $x26189 (= ghost_2_71 (- ghost_2_45 1))))))
 (let (($x26274 (or (or $x26239 $x26242) (and $x26259 (= ghost_2_72 (- ghost_2_45 1))))))
 (let (($x26278 (or (or $x26274 $x26270) (and $x24679 (= ghost_2_46 (- ghost_2_45 1))))))
 (let (($x26284 (or (or $x26278 $x26280) (and $x23449 (= ghost_2_25 (- ghost_2_45 1))))))
 (let (($x26283 (or (or $x26284 $x26286) (and $x23414 (= ghost_2_24 (- ghost_2_45 1))))))
 (let (($x26289 (>= ghost_2_45 1)))
 (let (($x26290 (and (=> (and $x24626 c_45_8) (= ghost_2_45 0)) (=> $x24609 (and $x26289 $x26283)))))
 (let (($x24433 (not c_42_8)))
 (let (($x24451 (or (and c_42_0 in_target_42) (and c_42_1 in_target_42) (and c_42_2 in_target_42) (and c_42_3 in_target_42) (and c_42_4 in_target_42) (and c_42_5 in_target_42) (and c_42_6 in_target_42) (and c_42_7 in_target_42) (and c_42_8 in_target_42))))
 (let (($x24434 (and $x24451 $x24433)))
 (let (($x26128 (= ghost_2_44 1)))
 (let (($x26209 (and c_42_8 $x26128)))
 (let (($x26213 (and c_24_8 $x26128)))
 (let (($x26194 (and c_45_8 $x26128)))
 (let (($x26161 (and c_71_8 $x26128)))
 (let (($x26153 (not c_70_8)))
 (let (($x26171 (or (and c_70_0 in_target_70) (and c_70_1 in_target_70) (and c_70_2 in_target_70) (and c_70_3 in_target_70) (and c_70_4 in_target_70) (and c_70_5 in_target_70) (and c_70_6 in_target_70) (and c_70_7 in_target_70) (and c_70_8 in_target_70))))
 (let (($x26137 (and c_70_8 $x26128)))
 (let (($x26013 (not c_68_8)))
 (let (($x26031 (or (and c_68_0 in_target_68) (and c_68_1 in_target_68) (and c_68_2 in_target_68) (and c_68_3 in_target_68) (and c_68_4 in_target_68) (and c_68_5 in_target_68) (and c_68_6 in_target_68) (and c_68_7 in_target_68) (and c_68_8 in_target_68))))
 (let (($x26014 (and $x26031 $x26013)))
 (let (($x26135 (or (or false (and c_68_8 $x26128)) (and $x26014 (= ghost_2_68 (- ghost_2_44 1))))))
 (let (($x26159 (or (or $x26135 $x26137) (and (and $x26171 $x26153) (= ghost_2_70 (- ghost_2_44 1))))))
 (let (($x26200 (or (or $x26159 $x26161) (and $x26189 (= ghost_2_71 (- ghost_2_44 1))))))
 (let (($x26208 (or (or $x26200 $x26194) (and $x24609 (= ghost_2_45 (- ghost_2_44 1))))))
 (let (($x26212 (or (or $x26208 $x26213) (and $x23414 (= ghost_2_24 (- ghost_2_44 1))))))
 (let (($x26216 (or (or $x26212 $x26209) (and $x24434 (= ghost_2_42 (- ghost_2_44 1))))))
 (let (($x26227 (>= ghost_2_44 1)))
 (let (($x26222 (and (=> (and $x24591 c_44_8) (= ghost_2_44 0)) (=> $x24574 (and $x26227 $x26216)))))
 (let (($x26056 (= ghost_2_43 1)))
 (let (($x26087 (and c_69_8 $x26056)))
 (let (($x26079 (and c_60_8 $x26056)))
 (let (($x26076 (and c_36_8 $x26056)))
 (let (($x23363 (not c_23_8)))
 (let (($x23381 (or (and c_23_0 in_target_23) (and c_23_1 in_target_23) (and c_23_2 in_target_23) (and c_23_3 in_target_23) (and c_23_4 in_target_23) (and c_23_5 in_target_23) (and c_23_6 in_target_23) (and c_23_7 in_target_23) (and c_23_8 in_target_23))))
 (let (($x23364 (and $x23381 $x23363)))
 (let (($x26069 (and c_23_8 $x26056)))
 (let (($x24383 (not c_41_8)))
 (let (($x24401 (or (and c_41_0 in_target_41) (and c_41_1 in_target_41) (and c_41_2 in_target_41) (and c_41_3 in_target_41) (and c_41_4 in_target_41) (and c_41_5 in_target_41) (and c_41_6 in_target_41) (and c_41_7 in_target_41) (and c_41_8 in_target_41))))
 (let (($x24384 (and $x24401 $x24383)))
 (let (($x26063 (and c_41_8 $x26056)))
 (let (($x25963 (not c_67_8)))
 (let (($x25981 (or (and c_67_0 in_target_67) (and c_67_1 in_target_67) (and c_67_2 in_target_67) (and c_67_3 in_target_67) (and c_67_4 in_target_67) (and c_67_5 in_target_67) (and c_67_6 in_target_67) (and c_67_7 in_target_67) (and c_67_8 in_target_67))))
 (let (($x25964 (and $x25981 $x25963)))
 (let (($x26066 (or (or false (and c_67_8 $x26056)) (and $x25964 (= ghost_2_67 (- ghost_2_43 1))))))
 (let (($x26068 (or (or $x26066 $x26063) (and $x24384 (= ghost_2_41 (- ghost_2_43 1))))))
 (let (($x26065 (or (or $x26068 $x26069) (and $x23364 (= ghost_2_23 (- ghost_2_43 1))))))
 (let (($x26080 (or (or $x26065 $x26076) (and $x24114 (= ghost_2_36 (- ghost_2_43 1))))))
 (let (($x26088 (or (or $x26080 $x26079) (and $x25554 (= ghost_2_60 (- ghost_2_43 1))))))
 (let (($x26107 (or (or $x26088 $x26087) (and $x26104 (= ghost_2_69 (- ghost_2_43 1))))))
 (let (($x26122 (>= ghost_2_43 1)))
 (let (($x26125 (and (=> (and $x24541 c_43_8) (= ghost_2_43 0)) (=> $x24524 (and $x26122 $x26107)))))
 (let (($x24293 (not c_40_8)))
 (let (($x24311 (or (and c_40_0 in_target_40) (and c_40_1 in_target_40) (and c_40_2 in_target_40) (and c_40_3 in_target_40) (and c_40_4 in_target_40) (and c_40_5 in_target_40) (and c_40_6 in_target_40) (and c_40_7 in_target_40) (and c_40_8 in_target_40))))
 (let (($x24294 (and $x24311 $x24293)))
 (let (($x25975 (= ghost_2_42 1)))
 (let (($x26041 (and c_40_8 $x25975)))
 (let (($x23273 (not c_22_8)))
 (let (($x23291 (or (and c_22_0 in_target_22) (and c_22_1 in_target_22) (and c_22_2 in_target_22) (and c_22_3 in_target_22) (and c_22_4 in_target_22) (and c_22_5 in_target_22) (and c_22_6 in_target_22) (and c_22_7 in_target_22) (and c_22_8 in_target_22))))
 (let (($x23274 (and $x23291 $x23273)))
 (let (($x26035 (and c_22_8 $x25975)))
 (let (($x26034 (and c_24_8 $x25975)))
 (let (($x26019 (and c_44_8 $x25975)))
 (let (($x25993 (and c_68_8 $x25975)))
 (let (($x25873 (not c_66_8)))
 (let (($x25891 (or (and c_66_0 in_target_66) (and c_66_1 in_target_66) (and c_66_2 in_target_66) (and c_66_3 in_target_66) (and c_66_4 in_target_66) (and c_66_5 in_target_66) (and c_66_6 in_target_66) (and c_66_7 in_target_66) (and c_66_8 in_target_66))))
 (let (($x25874 (and $x25891 $x25873)))
 (let (($x25997 (or (or false (and c_66_8 $x25975)) (and $x25874 (= ghost_2_66 (- ghost_2_42 1))))))
 (let (($x26029 (or (or $x25997 $x25993) (and $x26014 (= ghost_2_68 (- ghost_2_42 1))))))
 (let (($x26038 (or (or $x26029 $x26019) (and $x24574 (= ghost_2_44 (- ghost_2_42 1))))))
 (let (($x26036 (or (or $x26038 $x26034) (and $x23414 (= ghost_2_24 (- ghost_2_42 1))))))
 (let (($x26046 (or (or $x26036 $x26035) (and $x23274 (= ghost_2_22 (- ghost_2_42 1))))))
 (let (($x26048 (or (or $x26046 $x26041) (and $x24294 (= ghost_2_40 (- ghost_2_42 1))))))
 (let (($x26052 (>= ghost_2_42 1)))
 (let (($x26055 (and (=> (and $x24451 c_42_8) (= ghost_2_42 0)) (=> $x24434 (and $x26052 $x26048)))))
 (let (($x25917 (= ghost_2_41 1)))
 (let (($x25945 (and c_67_8 $x25917)))
 (let (($x25941 (and c_43_8 $x25917)))
 (let (($x25938 (and c_23_8 $x25917)))
 (let (($x23223 (not c_21_8)))
 (let (($x23241 (or (and c_21_0 in_target_21) (and c_21_1 in_target_21) (and c_21_2 in_target_21) (and c_21_3 in_target_21) (and c_21_4 in_target_21) (and c_21_5 in_target_21) (and c_21_6 in_target_21) (and c_21_7 in_target_21) (and c_21_8 in_target_21))))
 (let (($x23224 (and $x23241 $x23223)))
 (let (($x25925 (and c_21_8 $x25917)))
 (let (($x24243 (not c_39_8)))
 (let (($x24261 (or (and c_39_0 in_target_39) (and c_39_1 in_target_39) (and c_39_2 in_target_39) (and c_39_3 in_target_39) (and c_39_4 in_target_39) (and c_39_5 in_target_39) (and c_39_6 in_target_39) (and c_39_7 in_target_39) (and c_39_8 in_target_39))))
 (let (($x24244 (and $x24261 $x24243)))
 (let (($x25926 (and c_39_8 $x25917)))
 (let (($x25823 (not c_65_8)))
 (let (($x25841 (or (and c_65_0 in_target_65) (and c_65_1 in_target_65) (and c_65_2 in_target_65) (and c_65_3 in_target_65) (and c_65_4 in_target_65) (and c_65_5 in_target_65) (and c_65_6 in_target_65) (and c_65_7 in_target_65) (and c_65_8 in_target_65))))
 (let (($x25824 (and $x25841 $x25823)))
 (let (($x25924 (or (or false (and c_65_8 $x25917)) (and $x25824 (= ghost_2_65 (- ghost_2_41 1))))))
 (let (($x25933 (or (or $x25924 $x25926) (and $x24244 (= ghost_2_39 (- ghost_2_41 1))))))
 (let (($x25930 (or (or $x25933 $x25925) (and $x23224 (= ghost_2_21 (- ghost_2_41 1))))))
 (let (($x25934 (or (or $x25930 $x25938) (and $x23364 (= ghost_2_23 (- ghost_2_41 1))))))
 (let (($x25939 (or (or $x25934 $x25941) (and $x24524 (= ghost_2_43 (- ghost_2_41 1))))))
 (let (($x25971 (or (or $x25939 $x25945) (and $x25964 (= ghost_2_67 (- ghost_2_41 1))))))
 (let (($x25982 (>= ghost_2_41 1)))
 (let (($x25984 (and (=> (and $x24401 c_41_8) (= ghost_2_41 0)) (=> $x24384 (and $x25982 $x25971)))))
 (let (($x24193 (not c_38_8)))
 (let (($x24211 (or (and c_38_0 in_target_38) (and c_38_1 in_target_38) (and c_38_2 in_target_38) (and c_38_3 in_target_38) (and c_38_4 in_target_38) (and c_38_5 in_target_38) (and c_38_6 in_target_38) (and c_38_7 in_target_38) (and c_38_8 in_target_38))))
 (let (($x24194 (and $x24211 $x24193)))
 (let (($x25842 (= ghost_2_40 1)))
 (let (($x25903 (and c_38_8 $x25842)))
 (let (($x23173 (not c_20_8)))
 (let (($x23191 (or (and c_20_0 in_target_20) (and c_20_1 in_target_20) (and c_20_2 in_target_20) (and c_20_3 in_target_20) (and c_20_4 in_target_20) (and c_20_5 in_target_20) (and c_20_6 in_target_20) (and c_20_7 in_target_20) (and c_20_8 in_target_20))))
 (let (($x23174 (and $x23191 $x23173)))
 (let (($x25898 (and c_20_8 $x25842)))
 (let (($x25892 (and c_22_8 $x25842)))
 (let (($x25879 (and c_42_8 $x25842)))
 (let (($x25856 (and c_66_8 $x25842)))
 (let (($x25733 (not c_64_8)))
 (let (($x25751 (or (and c_64_0 in_target_64) (and c_64_1 in_target_64) (and c_64_2 in_target_64) (and c_64_3 in_target_64) (and c_64_4 in_target_64) (and c_64_5 in_target_64) (and c_64_6 in_target_64) (and c_64_7 in_target_64) (and c_64_8 in_target_64))))
 (let (($x25734 (and $x25751 $x25733)))
 (let (($x25853 (or (or false (and c_64_8 $x25842)) (and $x25734 (= ghost_2_64 (- ghost_2_40 1))))))
 (let (($x25881 (or (or $x25853 $x25856) (and $x25874 (= ghost_2_66 (- ghost_2_40 1))))))
 (let (($x25893 (or (or $x25881 $x25879) (and $x24434 (= ghost_2_42 (- ghost_2_40 1))))))
 (let (($x25901 (or (or $x25893 $x25892) (and $x23274 (= ghost_2_22 (- ghost_2_40 1))))))
 (let (($x25904 (or (or $x25901 $x25898) (and $x23174 (= ghost_2_20 (- ghost_2_40 1))))))
 (let (($x25911 (or (or $x25904 $x25903) (and $x24194 (= ghost_2_38 (- ghost_2_40 1))))))
 (let (($x25910 (>= ghost_2_40 1)))
 (let (($x25914 (and (=> (and $x24311 c_40_8) (= ghost_2_40 0)) (=> $x24294 (and $x25910 $x25911)))))
 (let (($x25777 (= ghost_2_39 1)))
 (let (($x25804 (and c_65_8 $x25777)))
 (let (($x25803 (and c_41_8 $x25777)))
 (let (($x25795 (and c_21_8 $x25777)))
 (let (($x23137 (not c_19_8)))
 (let (($x23155 (or (and c_19_0 in_target_19) (and c_19_1 in_target_19) (and c_19_2 in_target_19) (and c_19_3 in_target_19) (and c_19_4 in_target_19) (and c_19_5 in_target_19) (and c_19_6 in_target_19) (and c_19_7 in_target_19) (and c_19_8 in_target_19))))
 (let (($x23138 (and $x23155 $x23137)))
 (let (($x25790 (and c_19_8 $x25777)))
 (let (($x24157 (not c_37_8)))
 (let (($x24175 (or (and c_37_0 in_target_37) (and c_37_1 in_target_37) (and c_37_2 in_target_37) (and c_37_3 in_target_37) (and c_37_4 in_target_37) (and c_37_5 in_target_37) (and c_37_6 in_target_37) (and c_37_7 in_target_37) (and c_37_8 in_target_37))))
 (let (($x24158 (and $x24175 $x24157)))
 (let (($x25785 (and c_37_8 $x25777)))
 (let (($x25683 (not c_63_8)))
 (let (($x25701 (or (and c_63_0 in_target_63) (and c_63_1 in_target_63) (and c_63_2 in_target_63) (and c_63_3 in_target_63) (and c_63_4 in_target_63) (and c_63_5 in_target_63) (and c_63_6 in_target_63) (and c_63_7 in_target_63) (and c_63_8 in_target_63))))
 (let (($x25684 (and $x25701 $x25683)))
 (let (($x25786 (or (or false (and c_63_8 $x25777)) (and $x25684 (= ghost_2_63 (- ghost_2_39 1))))))
 (let (($x25789 (or (or $x25786 $x25785) (and $x24158 (= ghost_2_37 (- ghost_2_39 1))))))
 (let (($x25796 (or (or $x25789 $x25790) (and $x23138 (= ghost_2_19 (- ghost_2_39 1))))))
 (let (($x25798 (or (or $x25796 $x25795) (and $x23224 (= ghost_2_21 (- ghost_2_39 1))))))
 (let (($x25799 (or (or $x25798 $x25803) (and $x24384 (= ghost_2_41 (- ghost_2_39 1))))))
 (let (($x25837 (or (or $x25799 $x25804) (and $x25824 (= ghost_2_65 (- ghost_2_39 1))))))
 (let (($x25847 (>= ghost_2_39 1)))
 (let (($x25846 (and (=> (and $x24261 c_39_8) (= ghost_2_39 0)) (=> $x24244 (and $x25847 $x25837)))))
 (let (($x25708 (= ghost_2_38 1)))
 (let (($x25765 (and c_37_8 $x25708)))
 (let (($x25758 (and c_19_8 $x25708)))
 (let (($x25754 (and c_20_8 $x25708)))
 (let (($x25745 (and c_40_8 $x25708)))
 (let (($x25716 (and c_64_8 $x25708)))
 (let (($x25633 (not c_62_8)))
 (let (($x25651 (or (and c_62_0 in_target_62) (and c_62_1 in_target_62) (and c_62_2 in_target_62) (and c_62_3 in_target_62) (and c_62_4 in_target_62) (and c_62_5 in_target_62) (and c_62_6 in_target_62) (and c_62_7 in_target_62) (and c_62_8 in_target_62))))
 (let (($x25634 (and $x25651 $x25633)))
 (let (($x25715 (or (or false (and c_62_8 $x25708)) (and $x25634 (= ghost_2_62 (- ghost_2_38 1))))))
 (let (($x25747 (or (or $x25715 $x25716) (and $x25734 (= ghost_2_64 (- ghost_2_38 1))))))
 (let (($x25753 (or (or $x25747 $x25745) (and $x24294 (= ghost_2_40 (- ghost_2_38 1))))))
 (let (($x25759 (or (or $x25753 $x25754) (and $x23174 (= ghost_2_20 (- ghost_2_38 1))))))
 (let (($x25766 (or (or $x25759 $x25758) (and $x23138 (= ghost_2_19 (- ghost_2_38 1))))))
 (let (($x25769 (or (or $x25766 $x25765) (and $x24158 (= ghost_2_37 (- ghost_2_38 1))))))
 (let (($x25775 (>= ghost_2_38 1)))
 (let (($x25776 (and (=> (and $x24211 c_38_8) (= ghost_2_38 0)) (=> $x24194 (and $x25775 $x25769)))))
 (let (($x25572 (= ghost_2_37 1)))
 (let (($x25663 (and c_63_8 $x25572)))
 (let (($x25660 (and c_39_8 $x25572)))
 (let (($x25652 (and c_19_8 $x25572)))
 (let (($x25649 (and c_38_8 $x25572)))
 (let (($x25613 (and c_62_8 $x25572)))
 (let (($x25597 (not c_61_8)))
 (let (($x25615 (or (and c_61_0 in_target_61) (and c_61_1 in_target_61) (and c_61_2 in_target_61) (and c_61_3 in_target_61) (and c_61_4 in_target_61) (and c_61_5 in_target_61) (and c_61_6 in_target_61) (and c_61_7 in_target_61) (and c_61_8 in_target_61))))
 (let (($x25611 (or (or false (and c_61_8 $x25572)) (and (and $x25615 $x25597) (= ghost_2_61 (- ghost_2_37 1))))))
 (let (($x25647 (or (or $x25611 $x25613) (and $x25634 (= ghost_2_62 (- ghost_2_37 1))))))
 (let (($x25656 (or (or $x25647 $x25649) (and $x24194 (= ghost_2_38 (- ghost_2_37 1))))))
 (let (($x25661 (or (or $x25656 $x25652) (and $x23138 (= ghost_2_19 (- ghost_2_37 1))))))
 (let (($x25668 (or (or $x25661 $x25660) (and $x24244 (= ghost_2_39 (- ghost_2_37 1))))))
 (let (($x25695 (or (or $x25668 $x25663) (and $x25684 (= ghost_2_63 (- ghost_2_37 1))))))
 (let (($x25703 (>= ghost_2_37 1)))
 (let (($x25706 (and (=> (and $x24175 c_37_8) (= ghost_2_37 0)) (=> $x24158 (and $x25703 $x25695)))))
 (let (($x25511 (= ghost_2_36 1)))
 (let (($x25537 (and c_60_8 $x25511)))
 (let (($x25533 (and c_59_8 $x25511)))
 (let (($x25519 (and c_35_8 $x25511)))
 (let (($x23093 (not c_18_8)))
 (let (($x23096 (and c_18_1 in_target_18)))
 (let (($x23095 (and c_18_0 in_target_18)))
 (let (($x23111 (or $x23095 $x23096 $x23098 $x23100 $x23102 $x23104 $x23106 $x23108 (and c_18_8 in_target_18))))
 (let (($x23094 (and $x23111 $x23093)))
 (let (($x25521 (and c_18_8 $x25511)))
 (let (($x25516 (and c_23_8 $x25511)))
 (let (($x25514 (or (or false (and c_43_8 $x25511)) (and $x24524 (= ghost_2_43 (- ghost_2_36 1))))))
 (let (($x25518 (or (or $x25514 $x25516) (and $x23364 (= ghost_2_23 (- ghost_2_36 1))))))
 (let (($x25523 (or (or $x25518 $x25521) (and $x23094 (= ghost_2_18 (- ghost_2_36 1))))))
 (let (($x25525 (or (or $x25523 $x25519) (and $x24044 (= ghost_2_35 (- ghost_2_36 1))))))
 (let (($x25534 (or (or $x25525 $x25533) (and $x25484 (= ghost_2_59 (- ghost_2_36 1))))))
 (let (($x25559 (or (or $x25534 $x25537) (and $x25554 (= ghost_2_60 (- ghost_2_36 1))))))
 (let (($x25574 (>= ghost_2_36 1)))
 (let (($x25577 (and (=> (and $x24131 c_36_8) (= ghost_2_36 0)) (=> $x24114 (and $x25574 $x25559)))))
 (let (($x25440 (= ghost_2_35 1)))
 (let (($x25467 (and c_59_8 $x25440)))
 (let (($x25462 (and c_58_8 $x25440)))
 (let (($x25457 (and c_34_8 $x25440)))
 (let (($x23023 (not c_17_8)))
 (let (($x23026 (and c_17_1 in_target_17)))
 (let (($x23025 (and c_17_0 in_target_17)))
 (let (($x23041 (or $x23025 $x23026 $x23028 $x23030 $x23032 $x23034 $x23036 $x23038 (and c_17_8 in_target_17))))
 (let (($x23024 (and $x23041 $x23023)))
 (let (($x25448 (and c_17_8 $x25440)))
 (let (($x25446 (and c_18_8 $x25440)))
 (let (($x25443 (or (or false (and c_36_8 $x25440)) (and $x24114 (= ghost_2_36 (- ghost_2_35 1))))))
 (let (($x25442 (or (or $x25443 $x25446) (and $x23094 (= ghost_2_18 (- ghost_2_35 1))))))
 (let (($x25455 (or (or $x25442 $x25448) (and $x23024 (= ghost_2_17 (- ghost_2_35 1))))))
 (let (($x25460 (or (or $x25455 $x25457) (and $x23974 (= ghost_2_34 (- ghost_2_35 1))))))
 (let (($x25464 (or (or $x25460 $x25462) (and $x25414 (= ghost_2_58 (- ghost_2_35 1))))))
 (let (($x25493 (or (or $x25464 $x25467) (and $x25484 (= ghost_2_59 (- ghost_2_35 1))))))
 (let (($x25487 (>= ghost_2_35 1)))
 (let (($x25504 (and (=> (and $x24061 c_35_8) (= ghost_2_35 0)) (=> $x24044 (and $x25487 $x25493)))))
 (let (($x25369 (= ghost_2_34 1)))
 (let (($x25396 (and c_58_8 $x25369)))
 (let (($x25391 (and c_57_8 $x25369)))
 (let (($x25383 (and c_33_8 $x25369)))
 (let (($x22988 (not c_16_8)))
 (let (($x22991 (and c_16_1 in_target_16)))
 (let (($x22990 (and c_16_0 in_target_16)))
 (let (($x23006 (or $x22990 $x22991 $x22993 $x22995 $x22997 $x22999 $x23001 $x23003 (and c_16_8 in_target_16))))
 (let (($x22989 (and $x23006 $x22988)))
 (let (($x25382 (and c_16_8 $x25369)))
 (let (($x25372 (and c_17_8 $x25369)))
 (let (($x25377 (or (or false (and c_35_8 $x25369)) (and $x24044 (= ghost_2_35 (- ghost_2_34 1))))))
 (let (($x25380 (or (or $x25377 $x25372) (and $x23024 (= ghost_2_17 (- ghost_2_34 1))))))
 (let (($x25385 (or (or $x25380 $x25382) (and $x22989 (= ghost_2_16 (- ghost_2_34 1))))))
 (let (($x25390 (or (or $x25385 $x25383) (and $x23939 (= ghost_2_33 (- ghost_2_34 1))))))
 (let (($x25397 (or (or $x25390 $x25391) (and $x25344 (= ghost_2_57 (- ghost_2_34 1))))))
 (let (($x25429 (or (or $x25397 $x25396) (and $x25414 (= ghost_2_58 (- ghost_2_34 1))))))
 (let (($x25434 (>= ghost_2_34 1)))
 (let (($x25435 (and (=> (and $x23991 c_34_8) (= ghost_2_34 0)) (=> $x23974 (and $x25434 $x25429)))))
 (let (($x25269 (= ghost_2_33 1)))
 (let (($x25324 (and c_57_8 $x25269)))
 (let (($x25291 (and c_56_8 $x25269)))
 (let (($x25286 (and c_55_8 $x25269)))
 (let (($x25273 (and c_32_8 $x25269)))
 (let (($x25272 (and c_16_8 $x25269)))
 (let (($x25276 (or (or false (and c_34_8 $x25269)) (and $x23974 (= ghost_2_34 (- ghost_2_33 1))))))
 (let (($x25280 (or (or $x25276 $x25272) (and $x22989 (= ghost_2_16 (- ghost_2_33 1))))))
 (let (($x25285 (or (or $x25280 $x25273) (and $x23869 (= ghost_2_32 (- ghost_2_33 1))))))
 (let (($x25293 (or (or $x25285 $x25286) (and $x25239 (= ghost_2_55 (- ghost_2_33 1))))))
 (let (($x25312 (or (or $x25293 $x25291) (and $x25309 (= ghost_2_56 (- ghost_2_33 1))))))
 (let (($x25359 (or (or $x25312 $x25324) (and $x25344 (= ghost_2_57 (- ghost_2_33 1))))))
 (let (($x25364 (>= ghost_2_33 1)))
 (let (($x25362 (and (=> (and $x23956 c_33_8) (= ghost_2_33 0)) (=> $x23939 (and $x25364 $x25359)))))
 (let (($x25196 (= ghost_2_32 1)))
 (let (($x25252 (and c_33_8 $x25196)))
 (let (($x25222 (and c_55_8 $x25196)))
 (let (($x25211 (and c_54_8 $x25196)))
 (let (($x25213 (and c_31_8 $x25196)))
 (let (($x22918 (not c_15_8)))
 (let (($x22921 (and c_15_1 in_target_15)))
 (let (($x22920 (and c_15_0 in_target_15)))
 (let (($x22936 (or $x22920 $x22921 $x22923 $x22925 $x22927 $x22929 $x22931 $x22933 (and c_15_8 in_target_15))))
 (let (($x22919 (and $x22936 $x22918)))
 (let (($x25205 (and c_15_8 $x25196)))
 (let (($x25187 (or (or false (and c_16_8 $x25196)) (and $x22989 (= ghost_2_16 (- ghost_2_32 1))))))
 (let (($x25207 (or (or $x25187 $x25205) (and $x22919 (= ghost_2_15 (- ghost_2_32 1))))))
 (let (($x25215 (or (or $x25207 $x25213) (and $x23799 (= ghost_2_31 (- ghost_2_32 1))))))
 (let (($x25219 (or (or $x25215 $x25211) (and $x25169 (= ghost_2_54 (- ghost_2_32 1))))))
 (let (($x25248 (or (or $x25219 $x25222) (and $x25239 (= ghost_2_55 (- ghost_2_32 1))))))
 (let (($x25260 (or (or $x25248 $x25252) (and $x23939 (= ghost_2_33 (- ghost_2_32 1))))))
 (let (($x25264 (>= ghost_2_32 1)))
 (let (($x25263 (and (=> (and $x23886 c_32_8) (= ghost_2_32 0)) (=> $x23869 (and $x25264 $x25260)))))
 (let (($x25129 (= ghost_2_31 1)))
 (let (($x25172 (and c_32_8 $x25129)))
 (let (($x25145 (and c_54_8 $x25129)))
 (let (($x25146 (and c_53_8 $x25129)))
 (let (($x25142 (and c_30_8 $x25129)))
 (let (($x22883 (not c_14_8)))
 (let (($x22886 (and c_14_1 in_target_14)))
 (let (($x22885 (and c_14_0 in_target_14)))
 (let (($x22901 (or $x22885 $x22886 $x22888 $x22890 $x22892 $x22894 $x22896 $x22898 (and c_14_8 in_target_14))))
 (let (($x22884 (and $x22901 $x22883)))
 (let (($x25132 (and c_14_8 $x25129)))
 (let (($x25137 (or (or false (and c_15_8 $x25129)) (and $x22919 (= ghost_2_15 (- ghost_2_31 1))))))
 (let (($x25140 (or (or $x25137 $x25132) (and $x22884 (= ghost_2_14 (- ghost_2_31 1))))))
 (let (($x25136 (or (or $x25140 $x25142) (and $x23764 (= ghost_2_30 (- ghost_2_31 1))))))
 (let (($x25147 (or (or $x25136 $x25146) (and $x25099 (= ghost_2_53 (- ghost_2_31 1))))))
 (let (($x25180 (or (or $x25147 $x25145) (and $x25169 (= ghost_2_54 (- ghost_2_31 1))))))
 (let (($x25190 (or (or $x25180 $x25172) (and $x23869 (= ghost_2_32 (- ghost_2_31 1))))))
 (let (($x25194 (>= ghost_2_31 1)))
 (let (($x25195 (and (=> (and $x23816 c_31_8) (= ghost_2_31 0)) (=> $x23799 (and $x25194 $x25190)))))
 (let (($x25030 (= ghost_2_30 1)))
 (let (($x25110 (and c_31_8 $x25030)))
 (let (($x25069 (and c_53_8 $x25030)))
 (let (($x25047 (and c_52_8 $x25030)))
 (let (($x25042 (and c_51_8 $x25030)))
 (let (($x25032 (and c_29_8 $x25030)))
 (let (($x25036 (or (or false (and c_14_8 $x25030)) (and $x22884 (= ghost_2_14 (- ghost_2_30 1))))))
 (let (($x25039 (or (or $x25036 $x25032) (and $x23694 (= ghost_2_29 (- ghost_2_30 1))))))
 (let (($x25044 (or (or $x25039 $x25042) (and $x24994 (= ghost_2_51 (- ghost_2_30 1))))))
 (let (($x25073 (or (or $x25044 $x25047) (and $x25064 (= ghost_2_52 (- ghost_2_30 1))))))
 (let (($x25106 (or (or $x25073 $x25069) (and $x25099 (= ghost_2_53 (- ghost_2_30 1))))))
 (let (($x25120 (or (or $x25106 $x25110) (and $x23799 (= ghost_2_31 (- ghost_2_30 1))))))
 (let (($x25119 (>= ghost_2_30 1)))
 (let (($x25122 (and (=> (and $x23781 c_30_8) (= ghost_2_30 0)) (=> $x23764 (and $x25119 $x25120)))))
 (let (($x24960 (= ghost_2_29 1)))
 (let (($x25016 (and c_14_8 $x24960)))
 (let (($x25005 (and c_30_8 $x24960)))
 (let (($x24978 (and c_51_8 $x24960)))
 (let (($x24972 (and c_50_8 $x24960)))
 (let (($x24962 (and c_28_8 $x24960)))
 (let (($x22813 (not c_13_8)))
 (let (($x22816 (and c_13_1 in_target_13)))
 (let (($x22815 (and c_13_0 in_target_13)))
 (let (($x22831 (or $x22815 $x22816 $x22818 $x22820 $x22822 $x22824 $x22826 $x22828 (and c_13_8 in_target_13))))
 (let (($x22814 (and $x22831 $x22813)))
 (let (($x24964 (or (or false (and c_13_8 $x24960)) (and $x22814 (= ghost_2_13 (- ghost_2_29 1))))))
 (let (($x24969 (or (or $x24964 $x24962) (and $x23624 (= ghost_2_28 (- ghost_2_29 1))))))
 (let (($x24974 (or (or $x24969 $x24972) (and $x24924 (= ghost_2_50 (- ghost_2_29 1))))))
 (let (($x25009 (or (or $x24974 $x24978) (and $x24994 (= ghost_2_51 (- ghost_2_29 1))))))
 (let (($x25013 (or (or $x25009 $x25005) (and $x23764 (= ghost_2_30 (- ghost_2_29 1))))))
 (let (($x25020 (or (or $x25013 $x25016) (and $x22884 (= ghost_2_14 (- ghost_2_29 1))))))
 (let (($x25015 (>= ghost_2_29 1)))
 (let (($x25021 (and (=> (and $x23711 c_29_8) (= ghost_2_29 0)) (=> $x23694 (and $x25015 $x25020)))))
 (let (($x24891 (= ghost_2_28 1)))
 (let (($x24947 (and c_13_8 $x24891)))
 (let (($x24935 (and c_29_8 $x24891)))
 (let (($x24902 (and c_50_8 $x24891)))
 (let (($x24903 (and c_49_8 $x24891)))
 (let (($x24893 (and c_27_8 $x24891)))
 (let (($x22778 (not c_12_8)))
 (let (($x22781 (and c_12_1 in_target_12)))
 (let (($x22780 (and c_12_0 in_target_12)))
 (let (($x22796 (or $x22780 $x22781 $x22783 $x22785 $x22787 $x22789 $x22791 $x22793 (and c_12_8 in_target_12))))
 (let (($x22779 (and $x22796 $x22778)))
 (let (($x24892 (or (or false (and c_12_8 $x24891)) (and $x22779 (= ghost_2_12 (- ghost_2_28 1))))))
 (let (($x24901 (or (or $x24892 $x24893) (and $x23589 (= ghost_2_27 (- ghost_2_28 1))))))
 (let (($x24905 (or (or $x24901 $x24903) (and $x24854 (= ghost_2_49 (- ghost_2_28 1))))))
 (let (($x24927 (or (or $x24905 $x24902) (and $x24924 (= ghost_2_50 (- ghost_2_28 1))))))
 (let (($x24944 (or (or $x24927 $x24935) (and $x23694 (= ghost_2_29 (- ghost_2_28 1))))))
 (let (($x24951 (or (or $x24944 $x24947) (and $x22814 (= ghost_2_13 (- ghost_2_28 1))))))
 (let (($x24952 (>= ghost_2_28 1)))
 (let (($x24949 (and (=> (and $x23641 c_28_8) (= ghost_2_28 0)) (=> $x23624 (and $x24952 $x24951)))))
 (let (($x24787 (= ghost_2_27 1)))
 (let (($x24877 (and c_12_8 $x24787)))
 (let (($x24861 (and c_28_8 $x24787)))
 (let (($x24828 (and c_49_8 $x24787)))
 (let (($x24797 (and c_48_8 $x24787)))
 (let (($x24795 (and c_47_8 $x24787)))
 (let (($x24793 (or (or false (and c_26_8 $x24787)) (and $x23519 (= ghost_2_26 (- ghost_2_27 1))))))
 (let (($x24803 (or (or $x24793 $x24795) (and $x24749 (= ghost_2_47 (- ghost_2_27 1))))))
 (let (($x24832 (or (or $x24803 $x24797) (and $x24819 (= ghost_2_48 (- ghost_2_27 1))))))
 (let (($x24865 (or (or $x24832 $x24828) (and $x24854 (= ghost_2_49 (- ghost_2_27 1))))))
 (let (($x24874 (or (or $x24865 $x24861) (and $x23624 (= ghost_2_28 (- ghost_2_27 1))))))
 (let (($x24882 (or (or $x24874 $x24877) (and $x22779 (= ghost_2_12 (- ghost_2_27 1))))))
 (let (($x24885 (>= ghost_2_27 1)))
 (let (($x24873 (and (=> (and $x23606 c_27_8) (= ghost_2_27 0)) (=> $x23589 (and $x24885 $x24882)))))
 (let (($x22708 (not c_11_8)))
 (let (($x22711 (and c_11_1 in_target_11)))
 (let (($x22710 (and c_11_0 in_target_11)))
 (let (($x22726 (or $x22710 $x22711 $x22713 $x22715 $x22717 $x22719 $x22721 $x22723 (and c_11_8 in_target_11))))
 (let (($x22709 (and $x22726 $x22708)))
 (let (($x24719 (= ghost_2_26 1)))
 (let (($x24769 (and c_11_8 $x24719)))
 (let (($x24773 (and c_12_8 $x24719)))
 (let (($x24760 (and c_27_8 $x24719)))
 (let (($x24730 (and c_47_8 $x24719)))
 (let (($x24724 (and c_46_8 $x24719)))
 (let (($x24725 (or (or false (and c_25_8 $x24719)) (and $x23449 (= ghost_2_25 (- ghost_2_26 1))))))
 (let (($x24728 (or (or $x24725 $x24724) (and $x24679 (= ghost_2_46 (- ghost_2_26 1))))))
 (let (($x24756 (or (or $x24728 $x24730) (and $x24749 (= ghost_2_47 (- ghost_2_26 1))))))
 (let (($x24771 (or (or $x24756 $x24760) (and $x23589 (= ghost_2_27 (- ghost_2_26 1))))))
 (let (($x24777 (or (or $x24771 $x24773) (and $x22779 (= ghost_2_12 (- ghost_2_26 1))))))
 (let (($x24778 (or (or $x24777 $x24769) (and $x22709 (= ghost_2_11 (- ghost_2_26 1))))))
 (let (($x24783 (>= ghost_2_26 1)))
 (let (($x24784 (and (=> (and $x23536 c_26_8) (= ghost_2_26 0)) (=> $x23519 (and $x24783 $x24778)))))
 (let (($x22673 (not c_10_8)))
 (let (($x22676 (and c_10_1 in_target_10)))
 (let (($x22675 (and c_10_0 in_target_10)))
 (let (($x22691 (or $x22675 $x22676 $x22678 $x22680 $x22682 $x22684 $x22686 $x22688 (and c_10_8 in_target_10))))
 (let (($x22674 (and $x22691 $x22673)))
 (let (($x24644 (= ghost_2_25 1)))
 (let (($x24707 (and c_10_8 $x24644)))
 (let (($x24699 (and c_11_8 $x24644)))
 (let (($x24690 (and c_26_8 $x24644)))
 (let (($x24663 (and c_46_8 $x24644)))
 (let (($x24657 (and c_45_8 $x24644)))
 (let (($x24649 (or (or false (and c_24_8 $x24644)) (and $x23414 (= ghost_2_24 (- ghost_2_25 1))))))
 (let (($x24658 (or (or $x24649 $x24657) (and $x24609 (= ghost_2_45 (- ghost_2_25 1))))))
 (let (($x24682 (or (or $x24658 $x24663) (and $x24679 (= ghost_2_46 (- ghost_2_25 1))))))
 (let (($x24698 (or (or $x24682 $x24690) (and $x23519 (= ghost_2_26 (- ghost_2_25 1))))))
 (let (($x24703 (or (or $x24698 $x24699) (and $x22709 (= ghost_2_11 (- ghost_2_25 1))))))
 (let (($x24711 (or (or $x24703 $x24707) (and $x22674 (= ghost_2_10 (- ghost_2_25 1))))))
 (let (($x24709 (>= ghost_2_25 1)))
 (let (($x24710 (and (=> (and $x23466 c_25_8) (= ghost_2_25 0)) (=> $x23449 (and $x24709 $x24711)))))
 (let (($x24549 (= ghost_2_24 1)))
 (let (($x24633 (and c_22_8 $x24549)))
 (let (($x24631 (and c_10_8 $x24549)))
 (let (($x24612 (and c_25_8 $x24549)))
 (let (($x24577 (and c_45_8 $x24549)))
 (let (($x24553 (and c_44_8 $x24549)))
 (let (($x24543 (or (or false (and c_42_8 $x24549)) (and $x24434 (= ghost_2_42 (- ghost_2_24 1))))))
 (let (($x24579 (or (or $x24543 $x24553) (and $x24574 (= ghost_2_44 (- ghost_2_24 1))))))
 (let (($x24620 (or (or $x24579 $x24577) (and $x24609 (= ghost_2_45 (- ghost_2_24 1))))))
 (let (($x24629 (or (or $x24620 $x24612) (and $x23449 (= ghost_2_25 (- ghost_2_24 1))))))
 (let (($x24636 (or (or $x24629 $x24631) (and $x22674 (= ghost_2_10 (- ghost_2_24 1))))))
 (let (($x24641 (or (or $x24636 $x24633) (and $x23274 (= ghost_2_22 (- ghost_2_24 1))))))
 (let (($x24638 (>= ghost_2_24 1)))
 (let (($x24646 (and (=> (and $x23431 c_24_8) (= ghost_2_24 0)) (=> $x23414 (and $x24638 $x24641)))))
 (let (($x24473 (= ghost_2_23 1)))
 (let (($x24504 (and c_43_8 $x24473)))
 (let (($x24494 (and c_36_8 $x24473)))
 (let (($x24495 (and c_18_8 $x24473)))
 (let (($x22623 (not c_9_8)))
 (let (($x22626 (and c_9_1 in_target_9)))
 (let (($x22625 (and c_9_0 in_target_9)))
 (let (($x22641 (or $x22625 $x22626 $x22628 $x22630 $x22632 $x22634 $x22636 $x22638 (and c_9_8 in_target_9))))
 (let (($x22624 (and $x22641 $x22623)))
 (let (($x24493 (and c_9_8 $x24473)))
 (let (($x24487 (and c_21_8 $x24473)))
 (let (($x24483 (or (or false (and c_41_8 $x24473)) (and $x24384 (= ghost_2_41 (- ghost_2_23 1))))))
 (let (($x24481 (or (or $x24483 $x24487) (and $x23224 (= ghost_2_21 (- ghost_2_23 1))))))
 (let (($x24498 (or (or $x24481 $x24493) (and $x22624 (= ghost_2_9 (- ghost_2_23 1))))))
 (let (($x24496 (or (or $x24498 $x24495) (and $x23094 (= ghost_2_18 (- ghost_2_23 1))))))
 (let (($x24505 (or (or $x24496 $x24494) (and $x24114 (= ghost_2_36 (- ghost_2_23 1))))))
 (let (($x24537 (or (or $x24505 $x24504) (and $x24524 (= ghost_2_43 (- ghost_2_23 1))))))
 (let (($x24542 (>= ghost_2_23 1)))
 (let (($x24544 (and (=> (and $x23381 c_23_8) (= ghost_2_23 0)) (=> $x23364 (and $x24542 $x24537)))))
 (let (($x24411 (= ghost_2_22 1)))
 (let (($x24463 (and c_20_8 $x24411)))
 (let (($x22573 (not c_8_8)))
 (let (($x22576 (and c_8_1 in_target_8)))
 (let (($x22575 (and c_8_0 in_target_8)))
 (let (($x22591 (or $x22575 $x22576 $x22578 $x22580 $x22582 $x22584 $x22586 $x22588 (and c_8_8 in_target_8))))
 (let (($x22574 (and $x22591 $x22573)))
 (let (($x24454 (and c_8_8 $x24411)))
 (let (($x24452 (and c_10_8 $x24411)))
 (let (($x24445 (and c_24_8 $x24411)))
 (let (($x24403 (and c_42_8 $x24411)))
 (let (($x24413 (or (or false (and c_40_8 $x24411)) (and $x24294 (= ghost_2_40 (- ghost_2_22 1))))))
 (let (($x24441 (or (or $x24413 $x24403) (and $x24434 (= ghost_2_42 (- ghost_2_22 1))))))
 (let (($x24453 (or (or $x24441 $x24445) (and $x23414 (= ghost_2_24 (- ghost_2_22 1))))))
 (let (($x24461 (or (or $x24453 $x24452) (and $x22674 (= ghost_2_10 (- ghost_2_22 1))))))
 (let (($x24464 (or (or $x24461 $x24454) (and $x22574 (= ghost_2_8 (- ghost_2_22 1))))))
 (let (($x24469 (or (or $x24464 $x24463) (and $x23174 (= ghost_2_20 (- ghost_2_22 1))))))
 (let (($x24475 (>= ghost_2_22 1)))
 (let (($x24471 (and (=> (and $x23291 c_22_8) (= ghost_2_22 0)) (=> $x23274 (and $x24475 $x24469)))))
 (let (($x24332 (= ghost_2_21 1)))
 (let (($x24366 (and c_41_8 $x24332)))
 (let (($x24360 (and c_23_8 $x24332)))
 (let (($x24356 (and c_9_8 $x24332)))
 (let (($x22537 (not c_7_8)))
 (let (($x22540 (and c_7_1 in_target_7)))
 (let (($x22539 (and c_7_0 in_target_7)))
 (let (($x22555 (or $x22539 $x22540 $x22542 $x22544 $x22546 $x22548 $x22550 $x22552 (and c_7_8 in_target_7))))
 (let (($x22538 (and $x22555 $x22537)))
 (let (($x24350 (and c_7_8 $x24332)))
 (let (($x24345 (and c_19_8 $x24332)))
 (let (($x24339 (or (or false (and c_39_8 $x24332)) (and $x24244 (= ghost_2_39 (- ghost_2_21 1))))))
 (let (($x24351 (or (or $x24339 $x24345) (and $x23138 (= ghost_2_19 (- ghost_2_21 1))))))
 (let (($x24355 (or (or $x24351 $x24350) (and $x22538 (= ghost_2_7 (- ghost_2_21 1))))))
 (let (($x24363 (or (or $x24355 $x24356) (and $x22624 (= ghost_2_9 (- ghost_2_21 1))))))
 (let (($x24359 (or (or $x24363 $x24360) (and $x23364 (= ghost_2_23 (- ghost_2_21 1))))))
 (let (($x24399 (or (or $x24359 $x24366) (and $x24384 (= ghost_2_41 (- ghost_2_21 1))))))
 (let (($x24387 (>= ghost_2_21 1)))
 (let (($x24404 (and (=> (and $x23241 c_21_8) (= ghost_2_21 0)) (=> $x23224 (and $x24387 $x24399)))))
 (let (($x24268 (= ghost_2_20 1)))
 (let (($x24326 (and c_19_8 $x24268)))
 (let (($x24312 (and c_7_8 $x24268)))
 (let (($x24313 (and c_8_8 $x24268)))
 (let (($x24303 (and c_22_8 $x24268)))
 (let (($x24273 (and c_40_8 $x24268)))
 (let (($x24266 (or (or false (and c_38_8 $x24268)) (and $x24194 (= ghost_2_38 (- ghost_2_20 1))))))
 (let (($x24297 (or (or $x24266 $x24273) (and $x24294 (= ghost_2_40 (- ghost_2_20 1))))))
 (let (($x24316 (or (or $x24297 $x24303) (and $x23274 (= ghost_2_22 (- ghost_2_20 1))))))
 (let (($x24319 (or (or $x24316 $x24313) (and $x22574 (= ghost_2_8 (- ghost_2_20 1))))))
 (let (($x24325 (or (or $x24319 $x24312) (and $x22538 (= ghost_2_7 (- ghost_2_20 1))))))
 (let (($x24331 (or (or $x24325 $x24326) (and $x23138 (= ghost_2_19 (- ghost_2_20 1))))))
 (let (($x24327 (>= ghost_2_20 1)))
 (let (($x24336 (and (=> (and $x23191 c_20_8) (= ghost_2_20 0)) (=> $x23174 (and $x24327 $x24331)))))
 (let (($x24134 (= ghost_2_19 1)))
 (let (($x24228 (and c_39_8 $x24134)))
 (let (($x24221 (and c_21_8 $x24134)))
 (let (($x24213 (and c_7_8 $x24134)))
 (let (($x24207 (and c_20_8 $x24134)))
 (let (($x24163 (and c_38_8 $x24134)))
 (let (($x24171 (or (or false (and c_37_8 $x24134)) (and $x24158 (= ghost_2_37 (- ghost_2_19 1))))))
 (let (($x24201 (or (or $x24171 $x24163) (and $x24194 (= ghost_2_38 (- ghost_2_19 1))))))
 (let (($x24214 (or (or $x24201 $x24207) (and $x23174 (= ghost_2_20 (- ghost_2_19 1))))))
 (let (($x24220 (or (or $x24214 $x24213) (and $x22538 (= ghost_2_7 (- ghost_2_19 1))))))
 (let (($x24222 (or (or $x24220 $x24221) (and $x23224 (= ghost_2_21 (- ghost_2_19 1))))))
 (let (($x24255 (or (or $x24222 $x24228) (and $x24244 (= ghost_2_39 (- ghost_2_19 1))))))
 (let (($x24265 (>= ghost_2_19 1)))
 (let (($x24263 (and (=> (and $x23155 c_19_8) (= ghost_2_19 0)) (=> $x23138 (and $x24265 $x24255)))))
 (let (($x24070 (= ghost_2_18 1)))
 (let (($x24098 (and c_36_8 $x24070)))
 (let (($x24092 (and c_35_8 $x24070)))
 (let (($x24085 (and c_17_8 $x24070)))
 (let (($x24080 (and c_6_8 $x24070)))
 (let (($x24076 (and c_9_8 $x24070)))
 (let (($x24075 (or (or false (and c_23_8 $x24070)) (and $x23364 (= ghost_2_23 (- ghost_2_18 1))))))
 (let (($x24083 (or (or $x24075 $x24076) (and $x22624 (= ghost_2_9 (- ghost_2_18 1))))))
 (let (($x24081 (or (or $x24083 $x24080) (and (and $x22509 (not c_6_8)) (= ghost_2_6 (- ghost_2_18 1))))))
 (let (($x24090 (or (or $x24081 $x24085) (and $x23024 (= ghost_2_17 (- ghost_2_18 1))))))
 (let (($x24093 (or (or $x24090 $x24092) (and $x24044 (= ghost_2_35 (- ghost_2_18 1))))))
 (let (($x24127 (or (or $x24093 $x24098) (and $x24114 (= ghost_2_36 (- ghost_2_18 1))))))
 (let (($x24119 (>= ghost_2_18 1)))
 (let (($x24133 (and (=> (and $x23111 c_18_8) (= ghost_2_18 0)) (=> $x23094 (and $x24119 $x24127)))))
 (let (($x23996 (= ghost_2_17 1)))
 (let (($x24027 (and c_35_8 $x23996)))
 (let (($x24018 (and c_34_8 $x23996)))
 (let (($x24017 (and c_16_8 $x23996)))
 (let (($x24010 (and c_5_8 $x23996)))
 (let (($x24006 (and c_6_8 $x23996)))
 (let (($x24002 (or (or false (and c_18_8 $x23996)) (and $x23094 (= ghost_2_18 (- ghost_2_17 1))))))
 (let (($x24007 (or (or $x24002 $x24006) (and (and $x22509 (not c_6_8)) (= ghost_2_6 (- ghost_2_17 1))))))
 (let (($x24015 (or (or $x24007 $x24010) (and (and $x22474 (not c_5_8)) (= ghost_2_5 (- ghost_2_17 1))))))
 (let (($x24020 (or (or $x24015 $x24017) (and $x22989 (= ghost_2_16 (- ghost_2_17 1))))))
 (let (($x24025 (or (or $x24020 $x24018) (and $x23974 (= ghost_2_34 (- ghost_2_17 1))))))
 (let (($x24049 (or (or $x24025 $x24027) (and $x24044 (= ghost_2_35 (- ghost_2_17 1))))))
 (let (($x24064 (>= ghost_2_17 1)))
 (let (($x24065 (and (=> (and $x23041 c_17_8) (= ghost_2_17 0)) (=> $x23024 (and $x24064 $x24049)))))
 (let (($x23901 (= ghost_2_16 1)))
 (let (($x23944 (and c_34_8 $x23901)))
 (let (($x23921 (and c_33_8 $x23901)))
 (let (($x23918 (and c_32_8 $x23901)))
 (let (($x23912 (and c_15_8 $x23901)))
 (let (($x23902 (and c_5_8 $x23901)))
 (let (($x23906 (or (or false (and c_17_8 $x23901)) (and $x23024 (= ghost_2_17 (- ghost_2_16 1))))))
 (let (($x23910 (or (or $x23906 $x23902) (and (and $x22474 (not c_5_8)) (= ghost_2_5 (- ghost_2_16 1))))))
 (let (($x23913 (or (or $x23910 $x23912) (and $x22919 (= ghost_2_15 (- ghost_2_16 1))))))
 (let (($x23920 (or (or $x23913 $x23918) (and $x23869 (= ghost_2_32 (- ghost_2_16 1))))))
 (let (($x23942 (or (or $x23920 $x23921) (and $x23939 (= ghost_2_33 (- ghost_2_16 1))))))
 (let (($x23979 (or (or $x23942 $x23944) (and $x23974 (= ghost_2_34 (- ghost_2_16 1))))))
 (let (($x23994 (>= ghost_2_16 1)))
 (let (($x23992 (and (=> (and $x23006 c_16_8) (= ghost_2_16 0)) (=> $x22989 (and $x23994 $x23979)))))
 (let (($x23830 (= ghost_2_15 1)))
 (let (($x23876 (and c_16_8 $x23830)))
 (let (($x23846 (and c_32_8 $x23830)))
 (let (($x23847 (and c_31_8 $x23830)))
 (let (($x23839 (and c_14_8 $x23830)))
 (let (($x23833 (and c_4_8 $x23830)))
 (let (($x23836 (or (or false (and c_5_8 $x23830)) (and (and $x22474 (not c_5_8)) (= ghost_2_5 (- ghost_2_15 1))))))
 (let (($x23835 (or (or $x23836 $x23833) (and (and $x22439 (not c_4_8)) (= ghost_2_4 (- ghost_2_15 1))))))
 (let (($x23845 (or (or $x23835 $x23839) (and $x22884 (= ghost_2_14 (- ghost_2_15 1))))))
 (let (($x23850 (or (or $x23845 $x23847) (and $x23799 (= ghost_2_31 (- ghost_2_15 1))))))
 (let (($x23882 (or (or $x23850 $x23846) (and $x23869 (= ghost_2_32 (- ghost_2_15 1))))))
 (let (($x23890 (or (or $x23882 $x23876) (and $x22989 (= ghost_2_16 (- ghost_2_15 1))))))
 (let (($x23892 (>= ghost_2_15 1)))
 (let (($x23893 (and (=> (and $x22936 c_15_8) (= ghost_2_15 0)) (=> $x22919 (and $x23892 $x23890)))))
 (let (($x23728 (= ghost_2_14 1)))
 (let (($x23810 (and c_15_8 $x23728)))
 (let (($x23767 (and c_31_8 $x23728)))
 (let (($x23747 (and c_30_8 $x23728)))
 (let (($x23740 (and c_29_8 $x23728)))
 (let (($x23732 (and c_13_8 $x23728)))
 (let (($x23733 (or (or false (and c_4_8 $x23728)) (and (and $x22439 (not c_4_8)) (= ghost_2_4 (- ghost_2_14 1))))))
 (let (($x23741 (or (or $x23733 $x23732) (and $x22814 (= ghost_2_13 (- ghost_2_14 1))))))
 (let (($x23744 (or (or $x23741 $x23740) (and $x23694 (= ghost_2_29 (- ghost_2_14 1))))))
 (let (($x23779 (or (or $x23744 $x23747) (and $x23764 (= ghost_2_30 (- ghost_2_14 1))))))
 (let (($x23814 (or (or $x23779 $x23767) (and $x23799 (= ghost_2_31 (- ghost_2_14 1))))))
 (let (($x23817 (or (or $x23814 $x23810) (and $x22919 (= ghost_2_15 (- ghost_2_14 1))))))
 (let (($x23824 (>= ghost_2_14 1)))
 (let (($x23822 (and (=> (and $x22901 c_14_8) (= ghost_2_14 0)) (=> $x22884 (and $x23824 $x23817)))))
 (let (($x23654 (= ghost_2_13 1)))
 (let (($x23717 (and c_4_8 $x23654)))
 (let (($x23699 (and c_14_8 $x23654)))
 (let (($x23677 (and c_29_8 $x23654)))
 (let (($x23668 (and c_28_8 $x23654)))
 (let (($x23662 (and c_12_8 $x23654)))
 (let (($x23666 (or (or false (and c_3_8 $x23654)) (and (and $x22404 (not c_3_8)) (= ghost_2_3 (- ghost_2_13 1))))))
 (let (($x23672 (or (or $x23666 $x23662) (and $x22779 (= ghost_2_12 (- ghost_2_13 1))))))
 (let (($x23674 (or (or $x23672 $x23668) (and $x23624 (= ghost_2_28 (- ghost_2_13 1))))))
 (let (($x23703 (or (or $x23674 $x23677) (and $x23694 (= ghost_2_29 (- ghost_2_13 1))))))
 (let (($x23715 (or (or $x23703 $x23699) (and $x22884 (= ghost_2_14 (- ghost_2_13 1))))))
 (let (($x23716 (or (or $x23715 $x23717) (and (and $x22439 (not c_4_8)) (= ghost_2_4 (- ghost_2_13 1))))))
 (let (($x23725 (>= ghost_2_13 1)))
 (let (($x23722 (and (=> (and $x22831 c_13_8) (= ghost_2_13 0)) (=> $x22814 (and $x23725 $x23716)))))
 (let (($x23560 (= ghost_2_12 1)))
 (let (($x23645 (and c_3_8 $x23560)))
 (let (($x23627 (and c_13_8 $x23560)))
 (let (($x23592 (and c_28_8 $x23560)))
 (let (($x23569 (and c_27_8 $x23560)))
 (let (($x23563 (and c_26_8 $x23560)))
 (let (($x23566 (or (or false (and c_11_8 $x23560)) (and $x22709 (= ghost_2_11 (- ghost_2_12 1))))))
 (let (($x23568 (or (or $x23566 $x23563) (and $x23519 (= ghost_2_26 (- ghost_2_12 1))))))
 (let (($x23598 (or (or $x23568 $x23569) (and $x23589 (= ghost_2_27 (- ghost_2_12 1))))))
 (let (($x23633 (or (or $x23598 $x23592) (and $x23624 (= ghost_2_28 (- ghost_2_12 1))))))
 (let (($x23646 (or (or $x23633 $x23627) (and $x22814 (= ghost_2_13 (- ghost_2_12 1))))))
 (let (($x23651 (or (or $x23646 $x23645) (and (and $x22404 (not c_3_8)) (= ghost_2_3 (- ghost_2_12 1))))))
 (let (($x23656 (>= ghost_2_12 1)))
 (let (($x23655 (and (=> (and $x22796 c_12_8) (= ghost_2_12 0)) (=> $x22779 (and $x23656 $x23651)))))
 (let (($x23484 (= ghost_2_11 1)))
 (let (($x23547 (and c_2_8 $x23484)))
 (let (($x23538 (and c_3_8 $x23484)))
 (let (($x23528 (and c_12_8 $x23484)))
 (let (($x23501 (and c_26_8 $x23484)))
 (let (($x23492 (and c_25_8 $x23484)))
 (let (($x23473 (or (or false (and c_10_8 $x23484)) (and $x22674 (= ghost_2_10 (- ghost_2_11 1))))))
 (let (($x23499 (or (or $x23473 $x23492) (and $x23449 (= ghost_2_25 (- ghost_2_11 1))))))
 (let (($x23530 (or (or $x23499 $x23501) (and $x23519 (= ghost_2_26 (- ghost_2_11 1))))))
 (let (($x23542 (or (or $x23530 $x23528) (and $x22779 (= ghost_2_12 (- ghost_2_11 1))))))
 (let (($x23546 (or (or $x23542 $x23538) (and (and $x22404 (not c_3_8)) (= ghost_2_3 (- ghost_2_11 1))))))
 (let (($x23550 (or (or $x23546 $x23547) (and (and $x22369 (not c_2_8)) (= ghost_2_2 (- ghost_2_11 1))))))
 (let (($x23540 (>= ghost_2_11 1)))
 (let (($x23555 (and (=> (and $x22726 c_11_8) (= ghost_2_11 0)) (=> $x22709 (and $x23540 $x23550)))))
 (let (($x23388 (= ghost_2_10 1)))
 (let (($x23477 (and c_8_8 $x23388)))
 (let (($x23472 (and c_2_8 $x23388)))
 (let (($x23452 (and c_11_8 $x23388)))
 (let (($x23427 (and c_25_8 $x23388)))
 (let (($x23396 (and c_24_8 $x23388)))
 (let (($x23392 (or (or false (and c_22_8 $x23388)) (and $x23274 (= ghost_2_22 (- ghost_2_10 1))))))
 (let (($x23429 (or (or $x23392 $x23396) (and $x23414 (= ghost_2_24 (- ghost_2_10 1))))))
 (let (($x23458 (or (or $x23429 $x23427) (and $x23449 (= ghost_2_25 (- ghost_2_10 1))))))
 (let (($x23468 (or (or $x23458 $x23452) (and $x22709 (= ghost_2_11 (- ghost_2_10 1))))))
 (let (($x23475 (or (or $x23468 $x23472) (and (and $x22369 (not c_2_8)) (= ghost_2_2 (- ghost_2_10 1))))))
 (let (($x23485 (>= ghost_2_10 1)))
 (let (($x23480 (and $x23485 (or (or $x23475 $x23477) (and $x22574 (= ghost_2_8 (- ghost_2_10 1)))))))
 (let (($x23314 (= ghost_2_9 1)))
 (let (($x23337 (and c_23_8 $x23314)))
 (let (($x23340 (and c_18_8 $x23314)))
 (let (($x23332 (and c_6_8 $x23314)))
 (let (($x23331 (and c_1_8 $x23314)))
 (let (($x23322 (and c_7_8 $x23314)))
 (let (($x23327 (or (or false (and c_21_8 $x23314)) (and $x23224 (= ghost_2_21 (- ghost_2_9 1))))))
 (let (($x23330 (or (or $x23327 $x23322) (and $x22538 (= ghost_2_7 (- ghost_2_9 1))))))
 (let (($x23338 (or (or $x23330 $x23331) (and (and $x22333 (not c_1_8)) (= ghost_2_1 (- ghost_2_9 1))))))
 (let (($x23336 (or (or $x23338 $x23332) (and (and $x22509 (not c_6_8)) (= ghost_2_6 (- ghost_2_9 1))))))
 (let (($x23339 (or (or $x23336 $x23340) (and $x23094 (= ghost_2_18 (- ghost_2_9 1))))))
 (let (($x23387 (>= ghost_2_9 1)))
 (let (($x23384 (and $x23387 (or (or $x23339 $x23337) (and $x23364 (= ghost_2_23 (- ghost_2_9 1)))))))
 (let (($x23249 (= ghost_2_8 1)))
 (let (($x23294 (and c_7_8 $x23249)))
 (let (($x23302 (and c_1_8 $x23249)))
 (let (($x23292 (and c_2_8 $x23249)))
 (let (($x23281 (and c_10_8 $x23249)))
 (let (($x23254 (and c_22_8 $x23249)))
 (let (($x23252 (or (or false (and c_20_8 $x23249)) (and $x23174 (= ghost_2_20 (- ghost_2_8 1))))))
 (let (($x23287 (or (or $x23252 $x23254) (and $x23274 (= ghost_2_22 (- ghost_2_8 1))))))
 (let (($x23296 (or (or $x23287 $x23281) (and $x22674 (= ghost_2_10 (- ghost_2_8 1))))))
 (let (($x23300 (or (or $x23296 $x23292) (and (and $x22369 (not c_2_8)) (= ghost_2_2 (- ghost_2_8 1))))))
 (let (($x23308 (or (or $x23300 $x23302) (and (and $x22333 (not c_1_8)) (= ghost_2_1 (- ghost_2_8 1))))))
 (let (($x23307 (>= ghost_2_8 1)))
 (let (($x23306 (and $x23307 (or (or $x23308 $x23294) (and $x22538 (= ghost_2_7 (- ghost_2_8 1)))))))
 (let (($x23118 (= ghost_2_7 1)))
 (let (($x23205 (and c_21_8 $x23118)))
 (let (($x23196 (and c_9_8 $x23118)))
 (let (($x23192 (and c_1_8 $x23118)))
 (let (($x23187 (and c_8_8 $x23118)))
 (let (($x23151 (and c_20_8 $x23118)))
 (let (($x23145 (or (or false (and c_19_8 $x23118)) (and $x23138 (= ghost_2_19 (- ghost_2_7 1))))))
 (let (($x23183 (or (or $x23145 $x23151) (and $x23174 (= ghost_2_20 (- ghost_2_7 1))))))
 (let (($x23194 (or (or $x23183 $x23187) (and $x22574 (= ghost_2_8 (- ghost_2_7 1))))))
 (let (($x23203 (or (or $x23194 $x23192) (and (and $x22333 (not c_1_8)) (= ghost_2_1 (- ghost_2_7 1))))))
 (let (($x23208 (or (or $x23203 $x23196) (and $x22624 (= ghost_2_9 (- ghost_2_7 1))))))
 (let (($x23244 (>= ghost_2_7 1)))
 (let (($x23245 (and $x23244 (or (or $x23208 $x23205) (and $x23224 (= ghost_2_21 (- ghost_2_7 1)))))))
 (let (($x23050 (= ghost_2_6 1)))
 (let (($x23077 (and c_18_8 $x23050)))
 (let (($x23072 (and c_17_8 $x23050)))
 (let (($x23061 (and c_5_8 $x23050)))
 (let (($x23053 (and c_0_8 $x23050)))
 (let (($x23056 (and c_1_8 $x23050)))
 (let (($x23054 (or (or false (and c_9_8 $x23050)) (and $x22624 (= ghost_2_9 (- ghost_2_6 1))))))
 (let (($x23063 (or (or $x23054 $x23056) (and (and $x22333 (not c_1_8)) (= ghost_2_1 (- ghost_2_6 1))))))
 (let (($x23067 (or (or $x23063 $x23053) (and (and $x22208 (not c_0_8)) (= ghost_2_0 (- ghost_2_6 1))))))
 (let (($x23070 (or (or $x23067 $x23061) (and (and $x22474 (not c_5_8)) (= ghost_2_5 (- ghost_2_6 1))))))
 (let (($x23075 (or (or $x23070 $x23072) (and $x23024 (= ghost_2_17 (- ghost_2_6 1))))))
 (let (($x23109 (>= ghost_2_6 1)))
 (let (($x23114 (and $x23109 (or (or $x23075 $x23077) (and $x23094 (= ghost_2_18 (- ghost_2_6 1)))))))
 (let (($x22491 (not c_6_8)))
 (let (($x22492 (and $x22509 $x22491)))
 (let (($x22947 (= ghost_2_5 1)))
 (let (($x22994 (and c_17_8 $x22947)))
 (let (($x22973 (and c_16_8 $x22947)))
 (let (($x22964 (and c_15_8 $x22947)))
 (let (($x22952 (and c_4_8 $x22947)))
 (let (($x22955 (and c_0_8 $x22947)))
 (let (($x22954 (or (or false (and c_6_8 $x22947)) (and $x22492 (= ghost_2_6 (- ghost_2_5 1))))))
 (let (($x22962 (or (or $x22954 $x22955) (and (and $x22208 (not c_0_8)) (= ghost_2_0 (- ghost_2_5 1))))))
 (let (($x22958 (or (or $x22962 $x22952) (and (and $x22439 (not c_4_8)) (= ghost_2_4 (- ghost_2_5 1))))))
 (let (($x22966 (or (or $x22958 $x22964) (and $x22919 (= ghost_2_15 (- ghost_2_5 1))))))
 (let (($x23000 (or (or $x22966 $x22973) (and $x22989 (= ghost_2_16 (- ghost_2_5 1))))))
 (let (($x23044 (>= ghost_2_5 1)))
 (let (($x23046 (and $x23044 (or (or $x23000 $x22994) (and $x23024 (= ghost_2_17 (- ghost_2_5 1)))))))
 (let (($x22456 (not c_5_8)))
 (let (($x22457 (and $x22474 $x22456)))
 (let (($x22850 (= ghost_2_4 1)))
 (let (($x22926 (and c_5_8 $x22850)))
 (let (($x22891 (and c_15_8 $x22850)))
 (let (($x22865 (and c_14_8 $x22850)))
 (let (($x22862 (and c_13_8 $x22850)))
 (let (($x22854 (and c_3_8 $x22850)))
 (let (($x22847 (or (or false (and c_0_8 $x22850)) (and (and $x22208 (not c_0_8)) (= ghost_2_0 (- ghost_2_4 1))))))
 (let (($x22861 (or (or $x22847 $x22854) (and (and $x22404 (not c_3_8)) (= ghost_2_3 (- ghost_2_4 1))))))
 (let (($x22866 (or (or $x22861 $x22862) (and $x22814 (= ghost_2_13 (- ghost_2_4 1))))))
 (let (($x22889 (or (or $x22866 $x22865) (and $x22884 (= ghost_2_14 (- ghost_2_4 1))))))
 (let (($x22924 (or (or $x22889 $x22891) (and $x22919 (= ghost_2_15 (- ghost_2_4 1))))))
 (let (($x22937 (>= ghost_2_4 1)))
 (let (($x22941 (and $x22937 (or (or $x22924 $x22926) (and $x22457 (= ghost_2_5 (- ghost_2_4 1)))))))
 (let (($x22421 (not c_4_8)))
 (let (($x22422 (and $x22439 $x22421)))
 (let (($x22750 (= ghost_2_3 1)))
 (let (($x22834 (and c_0_8 $x22750)))
 (let (($x22817 (and c_4_8 $x22750)))
 (let (($x22790 (and c_13_8 $x22750)))
 (let (($x22762 (and c_12_8 $x22750)))
 (let (($x22755 (and c_11_8 $x22750)))
 (let (($x22756 (or (or false (and c_2_8 $x22750)) (and (and $x22369 (not c_2_8)) (= ghost_2_2 (- ghost_2_3 1))))))
 (let (($x22758 (or (or $x22756 $x22755) (and $x22709 (= ghost_2_11 (- ghost_2_3 1))))))
 (let (($x22786 (or (or $x22758 $x22762) (and $x22779 (= ghost_2_12 (- ghost_2_3 1))))))
 (let (($x22819 (or (or $x22786 $x22790) (and $x22814 (= ghost_2_13 (- ghost_2_3 1))))))
 (let (($x22832 (or (or $x22819 $x22817) (and $x22422 (= ghost_2_4 (- ghost_2_3 1))))))
 (let (($x22842 (or (or $x22832 $x22834) (and (and $x22208 (not c_0_8)) (= ghost_2_0 (- ghost_2_3 1))))))
 (let (($x22845 (>= ghost_2_3 1)))
 (let (($x22386 (not c_3_8)))
 (let (($x22387 (and $x22404 $x22386)))
 (let (($x22844 (and (=> (and $x22404 c_3_8) (= ghost_2_3 0)) (=> $x22387 (and $x22845 $x22842)))))
 (let (($x22644 (= ghost_2_2 1)))
 (let (($x22729 (and c_1_8 $x22644)))
 (let (($x22732 (and c_0_8 $x22644)))
 (let (($x22720 (and c_3_8 $x22644)))
 (let (($x22687 (and c_11_8 $x22644)))
 (let (($x22656 (and c_10_8 $x22644)))
 (let (($x22650 (or (or false (and c_8_8 $x22644)) (and $x22574 (= ghost_2_8 (- ghost_2_2 1))))))
 (let (($x22679 (or (or $x22650 $x22656) (and $x22674 (= ghost_2_10 (- ghost_2_2 1))))))
 (let (($x22716 (or (or $x22679 $x22687) (and $x22709 (= ghost_2_11 (- ghost_2_2 1))))))
 (let (($x22731 (or (or $x22716 $x22720) (and $x22387 (= ghost_2_3 (- ghost_2_2 1))))))
 (let (($x22737 (or (or $x22731 $x22732) (and (and $x22208 (not c_0_8)) (= ghost_2_0 (- ghost_2_2 1))))))
 (let (($x22743 (or (or $x22737 $x22729) (and (and $x22333 (not c_1_8)) (= ghost_2_1 (- ghost_2_2 1))))))
 (let (($x22744 (>= ghost_2_2 1)))
 (let (($x22351 (not c_2_8)))
 (let (($x22352 (and $x22369 $x22351)))
 (let (($x22742 (and (=> (and $x22369 c_2_8) (= ghost_2_2 0)) (=> $x22352 (and $x22744 $x22743)))))
 (let (($x22513 (= ghost_2_1 1)))
 (let (($x22605 (and c_9_8 $x22513)))
 (let (($x22593 (and c_6_8 $x22513)))
 (let (($x22597 (and c_0_8 $x22513)))
 (let (($x22589 (and c_2_8 $x22513)))
 (let (($x22541 (and c_8_8 $x22513)))
 (let (($x22545 (or (or false (and c_7_8 $x22513)) (and $x22538 (= ghost_2_7 (- ghost_2_1 1))))))
 (let (($x22587 (or (or $x22545 $x22541) (and $x22574 (= ghost_2_8 (- ghost_2_1 1))))))
 (let (($x22595 (or (or $x22587 $x22589) (and $x22352 (= ghost_2_2 (- ghost_2_1 1))))))
 (let (($x22602 (or (or $x22595 $x22597) (and (and $x22208 (not c_0_8)) (= ghost_2_0 (- ghost_2_1 1))))))
 (let (($x22592 (or (or $x22602 $x22593) (and $x22492 (= ghost_2_6 (- ghost_2_1 1))))))
 (let (($x22647 (>= ghost_2_1 1)))
 (let (($x22631 (and $x22647 (or (or $x22592 $x22605) (and $x22624 (= ghost_2_9 (- ghost_2_1 1)))))))
 (let (($x22315 (not c_1_8)))
 (let (($x22316 (and $x22333 $x22315)))
 (let (($x22294 (= ghost_2_0 1)))
 (let (($x22462 (and c_6_8 $x22294)))
 (let (($x22431 (and c_5_8 $x22294)))
 (let (($x22396 (and c_4_8 $x22294)))
 (let (($x22359 (and c_3_8 $x22294)))
 (let (($x22325 (and c_2_8 $x22294)))
 (let (($x22321 (or (or false (and c_1_8 $x22294)) (and $x22316 (= ghost_2_1 (- ghost_2_0 1))))))
 (let (($x22363 (or (or $x22321 $x22325) (and $x22352 (= ghost_2_2 (- ghost_2_0 1))))))
 (let (($x22392 (or (or $x22363 $x22359) (and $x22387 (= ghost_2_3 (- ghost_2_0 1))))))
 (let (($x22427 (or (or $x22392 $x22396) (and $x22422 (= ghost_2_4 (- ghost_2_0 1))))))
 (let (($x22464 (or (or $x22427 $x22431) (and $x22457 (= ghost_2_5 (- ghost_2_0 1))))))
 (let (($x22514 (>= ghost_2_0 1)))
 (let (($x22497 (and $x22514 (or (or $x22464 $x22462) (and $x22492 (= ghost_2_6 (- ghost_2_0 1)))))))
 (let (($x22512 (not c_0_8)))
 (let (($x22511 (and $x22208 $x22512)))
 (let (($x22516 (and true (and (=> (and $x22208 c_0_8) (= ghost_2_0 0)) (=> $x22511 $x22497)))))
 (let (($x22651 (and $x22516 (and (=> (and $x22333 c_1_8) (= ghost_2_1 0)) (=> $x22316 $x22631)))))
 (let (($x22748 (and $x22651 $x22742)))
 (let (($x22849 (and $x22748 $x22844)))
 (let (($x22946 (and $x22849 (and (=> (and $x22439 c_4_8) (= ghost_2_4 0)) (=> $x22422 $x22941)))))
 (let (($x23048 (and $x22946 (and (=> (and $x22474 c_5_8) (= ghost_2_5 0)) (=> $x22457 $x23046)))))
 (let (($x23117 (and $x23048 (and (=> (and $x22509 c_6_8) (= ghost_2_6 0)) (=> $x22492 $x23114)))))
 (let (($x23248 (and $x23117 (and (=> (and $x22555 c_7_8) (= ghost_2_7 0)) (=> $x22538 $x23245)))))
 (let (($x23312 (and $x23248 (and (=> (and $x22591 c_8_8) (= ghost_2_8 0)) (=> $x22574 $x23306)))))
 (let (($x23391 (and $x23312 (and (=> (and $x22641 c_9_8) (= ghost_2_9 0)) (=> $x22624 $x23384)))))
 (let (($x23489 (and $x23391 (and (=> (and $x22691 c_10_8) (= ghost_2_10 0)) (=> $x22674 $x23480)))))
 (let (($x23557 (and $x23489 $x23555)))
 (let (($x23660 (and $x23557 $x23655)))
 (let (($x23729 (and $x23660 $x23722)))
 (let (($x23828 (and $x23729 $x23822)))
 (let (($x23894 (and $x23828 $x23893)))
 (let (($x23998 (and $x23894 $x23992)))
 (let (($x24068 (and $x23998 $x24065)))
 (let (($x24135 (and $x24068 $x24133)))
 (let (($x24269 (and $x24135 $x24263)))
 (let (($x24335 (and $x24269 $x24336)))
 (let (($x24405 (and $x24335 $x24404)))
 (let (($x24479 (and $x24405 $x24471)))
 (let (($x24547 (and $x24479 $x24544)))
 (let (($x24643 (and $x24547 $x24646)))
 (let (($x24713 (and $x24643 $x24710)))
 (let (($x24780 (and $x24713 $x24784)))
 (let (($x24889 (and $x24780 $x24873)))
 (let (($x24957 (and $x24889 $x24949)))
 (let (($x25023 (and $x24957 $x25021)))
 (let (($x25124 (and $x25023 $x25122)))
 (let (($x25198 (and $x25124 $x25195)))
 (let (($x25268 (and $x25198 $x25263)))
 (let (($x25368 (and $x25268 $x25362)))
 (let (($x25438 (and $x25368 $x25435)))
 (let (($x25506 (and $x25438 $x25504)))
 (let (($x25578 (and $x25506 $x25577)))
 (let (($x25707 (and $x25578 $x25706)))
 (let (($x25779 (and $x25707 $x25776)))
 (let (($x25851 (and $x25779 $x25846)))
 (let (($x25916 (and $x25851 $x25914)))
 (let (($x25985 (and $x25916 $x25984)))
 (let (($x26054 (and $x25985 $x26055)))
 (let (($x26119 (and $x26054 $x26125)))
 (let (($x26231 (and $x26119 $x26222)))
 (let (($x26291 (and $x26231 $x26290)))
 (let (($x26358 (and $x26291 $x26365)))
 (let (($x26441 (and $x26358 $x26435)))
 (let (($x26529 (and $x26441 $x26534)))
 (let (($x26608 (and $x26529 $x26603)))
 (let (($x26671 (and $x26608 $x26675)))
 (let (($x26740 (and $x26671 $x26745)))
 (let (($x26846 (and $x26740 $x26843)))
 (let (($x26917 (and $x26846 $x26915)))
 (let (($x26987 (and $x26917 $x26977)))
 (let (($x27061 (and $x26987 $x27056)))
 (let (($x27160 (and $x27061 $x27157)))
 (let (($x27230 (and $x27160 $x27223)))
 (let (($x27281 (and $x27230 $x27292)))
 (let (($x27355 (and $x27281 $x27367)))
 (let (($x29072 (and (and (and $x27355 $x27434) $x29068) (not (or $x29038 (and $x27678 (and $x28511 $x29062)))))))
 (let (($x29075 (or (and $x29072 (not (or $x27633 (and (and $x27613 $x27433) (or $x27630 $x27637))))) (or false $x22191))))
 (let (($x22162 (or c_90_2 c_90_3 c_90_4 c_90_5 c_90_6 c_90_7 c_90_8)))
 (let (($x22160 (not $x22162)))
 (let (($x22128 (= ghost_1_60 1)))
 (let (($x22152 (and $x22162 $x22128)))
 (let (($x22117 (or c_89_2 c_89_3 c_89_4 c_89_5 c_89_6 c_89_7 c_89_8)))
 (let (($x22113 (not $x22117)))
 (let (($x22116 (and c_89_1 $x22113)))
 (let (($x22150 (and $x22117 $x22128)))
 (let (($x21007 (or c_59_2 c_59_3 c_59_4 c_59_5 c_59_6 c_59_7 c_59_8)))
 (let (($x21006 (not $x21007)))
 (let (($x21005 (and c_59_1 $x21006)))
 (let (($x22146 (and $x21007 $x22128)))
 (let (($x20212 (or c_36_2 c_36_3 c_36_4 c_36_5 c_36_6 c_36_7 c_36_8)))
 (let (($x20210 (not $x20212)))
 (let (($x20211 (and c_36_1 $x20210)))
 (let (($x22138 (and $x20212 $x22128)))
 (let (($x20447 (or c_43_2 c_43_3 c_43_4 c_43_5 c_43_6 c_43_7 c_43_8)))
 (let (($x20446 (not $x20447)))
 (let (($x20444 (and c_43_1 $x20446)))
 (let (($x22132 (and $x20447 $x22128)))
 (let (($x21377 (or c_69_2 c_69_3 c_69_4 c_69_5 c_69_6 c_69_7 c_69_8)))
 (let (($x21375 (not $x21377)))
 (let (($x21374 (and c_69_1 $x21375)))
 (let (($x22133 (or (or false (and $x21377 $x22128)) (and $x21374 (= ghost_1_69 (- ghost_1_60 1))))))
 (let (($x22141 (or (or $x22133 $x22132) (and $x20444 (= ghost_1_43 (- ghost_1_60 1))))))
 (let (($x22145 (or (or $x22141 $x22138) (and $x20211 (= ghost_1_36 (- ghost_1_60 1))))))
 (let (($x22151 (or (or $x22145 $x22146) (and $x21005 (= ghost_1_59 (- ghost_1_60 1))))))
 (let (($x22153 (or (or $x22151 $x22150) (and $x22116 (= ghost_1_89 (- ghost_1_60 1))))))
 (let (($x22161 (or (or $x22153 $x22152) (and (and c_90_1 $x22160) (= ghost_1_90 (- ghost_1_60 1))))))
 (let (($x22170 (>= ghost_1_60 1)))
 (let (($x21052 (or c_60_2 c_60_3 c_60_4 c_60_5 c_60_6 c_60_7 c_60_8)))
 (let (($x21051 (not $x21052)))
 (let (($x21050 (and c_60_1 $x21051)))
 (let (($x22167 (and (=> (and c_60_1 $x21052) (= ghost_1_60 0)) (=> $x21050 (and $x22170 $x22161)))))
 (let (($x22082 (= ghost_1_59 1)))
 (let (($x22108 (and $x22117 $x22082)))
 (let (($x22072 (or c_88_2 c_88_3 c_88_4 c_88_5 c_88_6 c_88_7 c_88_8)))
 (let (($x22071 (not $x22072)))
 (let (($x22069 (and c_88_1 $x22071)))
 (let (($x22100 (and $x22072 $x22082)))
 (let (($x20962 (or c_58_2 c_58_3 c_58_4 c_58_5 c_58_6 c_58_7 c_58_8)))
 (let (($x20960 (not $x20962)))
 (let (($x20959 (and c_58_1 $x20960)))
 (let (($x22099 (and $x20962 $x22082)))
 (let (($x20167 (or c_35_2 c_35_3 c_35_4 c_35_5 c_35_6 c_35_7 c_35_8)))
 (let (($x20164 (not $x20167)))
 (let (($x20163 (and c_35_1 $x20164)))
 (let (($x22096 (and $x20167 $x22082)))
 (let (($x22088 (and $x20212 $x22082)))
 (let (($x22089 (or (or false (and $x21052 $x22082)) (and $x21050 (= ghost_1_60 (- ghost_1_59 1))))))
 (let (($x22095 (or (or $x22089 $x22088) (and $x20211 (= ghost_1_36 (- ghost_1_59 1))))))
 (let (($x22098 (or (or $x22095 $x22096) (and $x20163 (= ghost_1_35 (- ghost_1_59 1))))))
 (let (($x22105 (or (or $x22098 $x22099) (and $x20959 (= ghost_1_58 (- ghost_1_59 1))))))
 (let (($x22111 (or (or $x22105 $x22100) (and $x22069 (= ghost_1_88 (- ghost_1_59 1))))))
 (let (($x22118 (or (or $x22111 $x22108) (and $x22116 (= ghost_1_89 (- ghost_1_59 1))))))
 (let (($x22125 (>= ghost_1_59 1)))
 (let (($x22123 (and (=> (and c_59_1 $x21007) (= ghost_1_59 0)) (=> $x21005 (and $x22125 $x22118)))))
 (let (($x22039 (= ghost_1_58 1)))
 (let (($x22065 (and $x22072 $x22039)))
 (let (($x22027 (or c_87_2 c_87_3 c_87_4 c_87_5 c_87_6 c_87_7 c_87_8)))
 (let (($x22024 (not $x22027)))
 (let (($x22026 (and c_87_1 $x22024)))
 (let (($x22061 (and $x22027 $x22039)))
 (let (($x20917 (or c_57_2 c_57_3 c_57_4 c_57_5 c_57_6 c_57_7 c_57_8)))
 (let (($x20915 (not $x20917)))
 (let (($x20916 (and c_57_1 $x20915)))
 (let (($x22055 (and $x20917 $x22039)))
 (let (($x20122 (or c_34_2 c_34_3 c_34_4 c_34_5 c_34_6 c_34_7 c_34_8)))
 (let (($x20121 (not $x20122)))
 (let (($x20120 (and c_34_1 $x20121)))
 (let (($x22049 (and $x20122 $x22039)))
 (let (($x22040 (and $x20167 $x22039)))
 (let (($x22044 (or (or false (and $x21007 $x22039)) (and $x21005 (= ghost_1_59 (- ghost_1_58 1))))))
 (let (($x22048 (or (or $x22044 $x22040) (and $x20163 (= ghost_1_35 (- ghost_1_58 1))))))
 (let (($x22056 (or (or $x22048 $x22049) (and $x20120 (= ghost_1_34 (- ghost_1_58 1))))))
 (let (($x22060 (or (or $x22056 $x22055) (and $x20916 (= ghost_1_57 (- ghost_1_58 1))))))
 (let (($x22063 (or (or $x22060 $x22061) (and $x22026 (= ghost_1_87 (- ghost_1_58 1))))))
 (let (($x22073 (or (or $x22063 $x22065) (and $x22069 (= ghost_1_88 (- ghost_1_58 1))))))
 (let (($x22079 (>= ghost_1_58 1)))
 (let (($x22077 (and (=> (and c_58_1 $x20962) (= ghost_1_58 0)) (=> $x20959 (and $x22079 $x22073)))))
 (let (($x21991 (= ghost_1_57 1)))
 (let (($x22018 (and $x22027 $x21991)))
 (let (($x21982 (or c_86_2 c_86_3 c_86_4 c_86_5 c_86_6 c_86_7 c_86_8)))
 (let (($x21981 (not $x21982)))
 (let (($x21979 (and c_86_1 $x21981)))
 (let (($x22012 (and $x21982 $x21991)))
 (let (($x20907 (or c_56_2 c_56_3 c_56_4 c_56_5 c_56_6 c_56_7 c_56_8)))
 (let (($x20906 (not $x20907)))
 (let (($x20903 (and c_56_1 $x20906)))
 (let (($x22002 (and $x20907 $x21991)))
 (let (($x20112 (or c_33_2 c_33_3 c_33_4 c_33_5 c_33_6 c_33_7 c_33_8)))
 (let (($x20110 (not $x20112)))
 (let (($x20109 (and c_33_1 $x20110)))
 (let (($x22005 (and $x20112 $x21991)))
 (let (($x22000 (and $x20122 $x21991)))
 (let (($x21998 (or (or false (and $x20962 $x21991)) (and $x20959 (= ghost_1_58 (- ghost_1_57 1))))))
 (let (($x22006 (or (or $x21998 $x22000) (and $x20120 (= ghost_1_34 (- ghost_1_57 1))))))
 (let (($x22010 (or (or $x22006 $x22005) (and $x20109 (= ghost_1_33 (- ghost_1_57 1))))))
 (let (($x22016 (or (or $x22010 $x22002) (and $x20903 (= ghost_1_56 (- ghost_1_57 1))))))
 (let (($x22021 (or (or $x22016 $x22012) (and $x21979 (= ghost_1_86 (- ghost_1_57 1))))))
 (let (($x22023 (or (or $x22021 $x22018) (and $x22026 (= ghost_1_87 (- ghost_1_57 1))))))
 (let (($x22034 (>= ghost_1_57 1)))
 (let (($x22032 (and (=> (and c_57_1 $x20917) (= ghost_1_57 0)) (=> $x20916 (and $x22034 $x22023)))))
 (let (($x21944 (= ghost_1_56 1)))
 (let (($x21976 (and $x21982 $x21944)))
 (let (($x21972 (or c_85_2 c_85_3 c_85_4 c_85_5 c_85_6 c_85_7 c_85_8)))
 (let (($x21968 (not $x21972)))
 (let (($x21965 (and $x21972 $x21944)))
 (let (($x21927 (or c_84_2 c_84_3 c_84_4 c_84_5 c_84_6 c_84_7 c_84_8)))
 (let (($x21923 (not $x21927)))
 (let (($x21924 (and c_84_1 $x21923)))
 (let (($x21961 (and $x21927 $x21944)))
 (let (($x20862 (or c_55_2 c_55_3 c_55_4 c_55_5 c_55_6 c_55_7 c_55_8)))
 (let (($x20858 (not $x20862)))
 (let (($x20861 (and c_55_1 $x20858)))
 (let (($x21951 (and $x20862 $x21944)))
 (let (($x21948 (and $x20112 $x21944)))
 (let (($x21950 (or (or false (and $x20917 $x21944)) (and $x20916 (= ghost_1_57 (- ghost_1_56 1))))))
 (let (($x21955 (or (or $x21950 $x21948) (and $x20109 (= ghost_1_33 (- ghost_1_56 1))))))
 (let (($x21957 (or (or $x21955 $x21951) (and $x20861 (= ghost_1_55 (- ghost_1_56 1))))))
 (let (($x21964 (or (or $x21957 $x21961) (and $x21924 (= ghost_1_84 (- ghost_1_56 1))))))
 (let (($x21973 (or (or $x21964 $x21965) (and (and c_85_1 $x21968) (= ghost_1_85 (- ghost_1_56 1))))))
 (let (($x21983 (or (or $x21973 $x21976) (and $x21979 (= ghost_1_86 (- ghost_1_56 1))))))
 (let (($x21990 (>= ghost_1_56 1)))
 (let (($x21989 (and (=> (and c_56_1 $x20907) (= ghost_1_56 0)) (=> $x20903 (and $x21990 $x21983)))))
 (let (($x21898 (= ghost_1_55 1)))
 (let (($x21928 (and $x20907 $x21898)))
 (let (($x21917 (and $x21927 $x21898)))
 (let (($x21882 (or c_83_2 c_83_3 c_83_4 c_83_5 c_83_6 c_83_7 c_83_8)))
 (let (($x21880 (not $x21882)))
 (let (($x21881 (and c_83_1 $x21880)))
 (let (($x21915 (and $x21882 $x21898)))
 (let (($x20817 (or c_54_2 c_54_3 c_54_4 c_54_5 c_54_6 c_54_7 c_54_8)))
 (let (($x20813 (not $x20817)))
 (let (($x20815 (and c_54_1 $x20813)))
 (let (($x21911 (and $x20817 $x21898)))
 (let (($x20067 (or c_32_2 c_32_3 c_32_4 c_32_5 c_32_6 c_32_7 c_32_8)))
 (let (($x20064 (not $x20067)))
 (let (($x20066 (and c_32_1 $x20064)))
 (let (($x21905 (and $x20067 $x21898)))
 (let (($x21903 (or (or false (and $x20112 $x21898)) (and $x20109 (= ghost_1_33 (- ghost_1_55 1))))))
 (let (($x21908 (or (or $x21903 $x21905) (and $x20066 (= ghost_1_32 (- ghost_1_55 1))))))
 (let (($x21914 (or (or $x21908 $x21911) (and $x20815 (= ghost_1_54 (- ghost_1_55 1))))))
 (let (($x21920 (or (or $x21914 $x21915) (and $x21881 (= ghost_1_83 (- ghost_1_55 1))))))
 (let (($x21929 (or (or $x21920 $x21917) (and $x21924 (= ghost_1_84 (- ghost_1_55 1))))))
 (let (($x21936 (or (or $x21929 $x21928) (and $x20903 (= ghost_1_56 (- ghost_1_55 1))))))
 (let (($x21937 (>= ghost_1_55 1)))
 (let (($x21939 (and (=> (and c_55_1 $x20862) (= ghost_1_55 0)) (=> $x20861 (and $x21937 $x21936)))))
 (let (($x21853 (= ghost_1_54 1)))
 (let (($x21879 (and $x20862 $x21853)))
 (let (($x21872 (and $x21882 $x21853)))
 (let (($x21837 (or c_82_2 c_82_3 c_82_4 c_82_5 c_82_6 c_82_7 c_82_8)))
 (let (($x21835 (not $x21837)))
 (let (($x21833 (and c_82_1 $x21835)))
 (let (($x21870 (and $x21837 $x21853)))
 (let (($x20772 (or c_53_2 c_53_3 c_53_4 c_53_5 c_53_6 c_53_7 c_53_8)))
 (let (($x20771 (not $x20772)))
 (let (($x20770 (and c_53_1 $x20771)))
 (let (($x21865 (and $x20772 $x21853)))
 (let (($x20022 (or c_31_2 c_31_3 c_31_4 c_31_5 c_31_6 c_31_7 c_31_8)))
 (let (($x20019 (not $x20022)))
 (let (($x20020 (and c_31_1 $x20019)))
 (let (($x21856 (and $x20022 $x21853)))
 (let (($x21860 (or (or false (and $x20067 $x21853)) (and $x20066 (= ghost_1_32 (- ghost_1_54 1))))))
 (let (($x21864 (or (or $x21860 $x21856) (and $x20020 (= ghost_1_31 (- ghost_1_54 1))))))
 (let (($x21871 (or (or $x21864 $x21865) (and $x20770 (= ghost_1_53 (- ghost_1_54 1))))))
 (let (($x21875 (or (or $x21871 $x21870) (and $x21833 (= ghost_1_82 (- ghost_1_54 1))))))
 (let (($x21878 (or (or $x21875 $x21872) (and $x21881 (= ghost_1_83 (- ghost_1_54 1))))))
 (let (($x21887 (or (or $x21878 $x21879) (and $x20861 (= ghost_1_55 (- ghost_1_54 1))))))
 (let (($x21892 (>= ghost_1_54 1)))
 (let (($x21893 (and (=> (and c_54_1 $x20817) (= ghost_1_54 0)) (=> $x20815 (and $x21892 $x21887)))))
 (let (($x21809 (= ghost_1_53 1)))
 (let (($x21834 (and $x20817 $x21809)))
 (let (($x21831 (and $x21837 $x21809)))
 (let (($x21792 (or c_81_2 c_81_3 c_81_4 c_81_5 c_81_6 c_81_7 c_81_8)))
 (let (($x21790 (not $x21792)))
 (let (($x21789 (and c_81_1 $x21790)))
 (let (($x21826 (and $x21792 $x21809)))
 (let (($x20762 (or c_52_2 c_52_3 c_52_4 c_52_5 c_52_6 c_52_7 c_52_8)))
 (let (($x20760 (not $x20762)))
 (let (($x20761 (and c_52_1 $x20760)))
 (let (($x21818 (and $x20762 $x21809)))
 (let (($x20012 (or c_30_2 c_30_3 c_30_4 c_30_5 c_30_6 c_30_7 c_30_8)))
 (let (($x20011 (not $x20012)))
 (let (($x20008 (and c_30_1 $x20011)))
 (let (($x21812 (and $x20012 $x21809)))
 (let (($x21814 (or (or false (and $x20022 $x21809)) (and $x20020 (= ghost_1_31 (- ghost_1_53 1))))))
 (let (($x21821 (or (or $x21814 $x21812) (and $x20008 (= ghost_1_30 (- ghost_1_53 1))))))
 (let (($x21825 (or (or $x21821 $x21818) (and $x20761 (= ghost_1_52 (- ghost_1_53 1))))))
 (let (($x21830 (or (or $x21825 $x21826) (and $x21789 (= ghost_1_81 (- ghost_1_53 1))))))
 (let (($x21839 (or (or $x21830 $x21831) (and $x21833 (= ghost_1_82 (- ghost_1_53 1))))))
 (let (($x21844 (or (or $x21839 $x21834) (and $x20815 (= ghost_1_54 (- ghost_1_53 1))))))
 (let (($x21850 (>= ghost_1_53 1)))
 (let (($x21847 (and (=> (and c_53_1 $x20772) (= ghost_1_53 0)) (=> $x20770 (and $x21850 $x21844)))))
 (let (($x21756 (= ghost_1_52 1)))
 (let (($x21794 (and $x20772 $x21756)))
 (let (($x21786 (and $x21792 $x21756)))
 (let (($x21782 (or c_80_2 c_80_3 c_80_4 c_80_5 c_80_6 c_80_7 c_80_8)))
 (let (($x21778 (not $x21782)))
 (let (($x21775 (and $x21782 $x21756)))
 (let (($x21737 (or c_79_2 c_79_3 c_79_4 c_79_5 c_79_6 c_79_7 c_79_8)))
 (let (($x21734 (not $x21737)))
 (let (($x21733 (and c_79_1 $x21734)))
 (let (($x21769 (and $x21737 $x21756)))
 (let (($x20717 (or c_51_2 c_51_3 c_51_4 c_51_5 c_51_6 c_51_7 c_51_8)))
 (let (($x20714 (not $x20717)))
 (let (($x20713 (and c_51_1 $x20714)))
 (let (($x21764 (and $x20717 $x21756)))
 (let (($x21760 (or (or false (and $x20012 $x21756)) (and $x20008 (= ghost_1_30 (- ghost_1_52 1))))))
 (let (($x21768 (or (or $x21760 $x21764) (and $x20713 (= ghost_1_51 (- ghost_1_52 1))))))
 (let (($x21773 (or (or $x21768 $x21769) (and $x21733 (= ghost_1_79 (- ghost_1_52 1))))))
 (let (($x21781 (or (or $x21773 $x21775) (and (and c_80_1 $x21778) (= ghost_1_80 (- ghost_1_52 1))))))
 (let (($x21788 (or (or $x21781 $x21786) (and $x21789 (= ghost_1_81 (- ghost_1_52 1))))))
 (let (($x21801 (or (or $x21788 $x21794) (and $x20770 (= ghost_1_53 (- ghost_1_52 1))))))
 (let (($x21804 (>= ghost_1_52 1)))
 (let (($x21802 (and (=> (and c_52_1 $x20762) (= ghost_1_52 0)) (=> $x20761 (and $x21804 $x21801)))))
 (let (($x21713 (= ghost_1_51 1)))
 (let (($x21746 (and $x20012 $x21713)))
 (let (($x21738 (and $x20762 $x21713)))
 (let (($x21731 (and $x21737 $x21713)))
 (let (($x21692 (or c_78_2 c_78_3 c_78_4 c_78_5 c_78_6 c_78_7 c_78_8)))
 (let (($x21689 (not $x21692)))
 (let (($x21688 (and c_78_1 $x21689)))
 (let (($x21725 (and $x21692 $x21713)))
 (let (($x20672 (or c_50_2 c_50_3 c_50_4 c_50_5 c_50_6 c_50_7 c_50_8)))
 (let (($x20669 (not $x20672)))
 (let (($x20670 (and c_50_1 $x20669)))
 (let (($x21718 (and $x20672 $x21713)))
 (let (($x19967 (or c_29_2 c_29_3 c_29_4 c_29_5 c_29_6 c_29_7 c_29_8)))
 (let (($x19963 (not $x19967)))
 (let (($x19965 (and c_29_1 $x19963)))
 (let (($x21719 (or (or false (and $x19967 $x21713)) (and $x19965 (= ghost_1_29 (- ghost_1_51 1))))))
 (let (($x21724 (or (or $x21719 $x21718) (and $x20670 (= ghost_1_50 (- ghost_1_51 1))))))
 (let (($x21729 (or (or $x21724 $x21725) (and $x21688 (= ghost_1_78 (- ghost_1_51 1))))))
 (let (($x21739 (or (or $x21729 $x21731) (and $x21733 (= ghost_1_79 (- ghost_1_51 1))))))
 (let (($x21745 (or (or $x21739 $x21738) (and $x20761 (= ghost_1_52 (- ghost_1_51 1))))))
 (let (($x21751 (or (or $x21745 $x21746) (and $x20008 (= ghost_1_30 (- ghost_1_51 1))))))
 (let (($x21753 (>= ghost_1_51 1)))
 (let (($x21754 (and (=> (and c_51_1 $x20717) (= ghost_1_51 0)) (=> $x20713 (and $x21753 $x21751)))))
 (let (($x21668 (= ghost_1_50 1)))
 (let (($x21699 (and $x19967 $x21668)))
 (let (($x21694 (and $x20717 $x21668)))
 (let (($x21686 (and $x21692 $x21668)))
 (let (($x21647 (or c_77_2 c_77_3 c_77_4 c_77_5 c_77_6 c_77_7 c_77_8)))
 (let (($x21644 (not $x21647)))
 (let (($x21643 (and c_77_1 $x21644)))
 (let (($x21680 (and $x21647 $x21668)))
 (let (($x20627 (or c_49_2 c_49_3 c_49_4 c_49_5 c_49_6 c_49_7 c_49_8)))
 (let (($x20623 (not $x20627)))
 (let (($x20625 (and c_49_1 $x20623)))
 (let (($x21670 (and $x20627 $x21668)))
 (let (($x19922 (or c_28_2 c_28_3 c_28_4 c_28_5 c_28_6 c_28_7 c_28_8)))
 (let (($x19921 (not $x19922)))
 (let (($x19920 (and c_28_1 $x19921)))
 (let (($x21674 (or (or false (and $x19922 $x21668)) (and $x19920 (= ghost_1_28 (- ghost_1_50 1))))))
 (let (($x21679 (or (or $x21674 $x21670) (and $x20625 (= ghost_1_49 (- ghost_1_50 1))))))
 (let (($x21684 (or (or $x21679 $x21680) (and $x21643 (= ghost_1_77 (- ghost_1_50 1))))))
 (let (($x21693 (or (or $x21684 $x21686) (and $x21688 (= ghost_1_78 (- ghost_1_50 1))))))
 (let (($x21698 (or (or $x21693 $x21694) (and $x20713 (= ghost_1_51 (- ghost_1_50 1))))))
 (let (($x21702 (or (or $x21698 $x21699) (and $x19965 (= ghost_1_29 (- ghost_1_50 1))))))
 (let (($x21708 (>= ghost_1_50 1)))
 (let (($x21710 (and (=> (and c_50_1 $x20672) (= ghost_1_50 0)) (=> $x20670 (and $x21708 $x21702)))))
 (let (($x21624 (= ghost_1_49 1)))
 (let (($x21655 (and $x19922 $x21624)))
 (let (($x21649 (and $x20672 $x21624)))
 (let (($x21640 (and $x21647 $x21624)))
 (let (($x21602 (or c_76_2 c_76_3 c_76_4 c_76_5 c_76_6 c_76_7 c_76_8)))
 (let (($x21601 (not $x21602)))
 (let (($x21599 (and c_76_1 $x21601)))
 (let (($x21636 (and $x21602 $x21624)))
 (let (($x20617 (or c_48_2 c_48_3 c_48_4 c_48_5 c_48_6 c_48_7 c_48_8)))
 (let (($x20615 (not $x20617)))
 (let (($x20616 (and c_48_1 $x20615)))
 (let (($x21628 (and $x20617 $x21624)))
 (let (($x19912 (or c_27_2 c_27_3 c_27_4 c_27_5 c_27_6 c_27_7 c_27_8)))
 (let (($x19910 (not $x19912)))
 (let (($x19908 (and c_27_1 $x19910)))
 (let (($x21627 (or (or false (and $x19912 $x21624)) (and $x19908 (= ghost_1_27 (- ghost_1_49 1))))))
 (let (($x21635 (or (or $x21627 $x21628) (and $x20616 (= ghost_1_48 (- ghost_1_49 1))))))
 (let (($x21641 (or (or $x21635 $x21636) (and $x21599 (= ghost_1_76 (- ghost_1_49 1))))))
 (let (($x21648 (or (or $x21641 $x21640) (and $x21643 (= ghost_1_77 (- ghost_1_49 1))))))
 (let (($x21654 (or (or $x21648 $x21649) (and $x20670 (= ghost_1_50 (- ghost_1_49 1))))))
 (let (($x21661 (or (or $x21654 $x21655) (and $x19920 (= ghost_1_28 (- ghost_1_49 1))))))
 (let (($x21662 (>= ghost_1_49 1)))
 (let (($x21663 (and (=> (and c_49_1 $x20627) (= ghost_1_49 0)) (=> $x20625 (and $x21662 $x21661)))))
 (let (($x21572 (= ghost_1_48 1)))
 (let (($x21610 (and $x19912 $x21572)))
 (let (($x21603 (and $x20627 $x21572)))
 (let (($x21596 (and $x21602 $x21572)))
 (let (($x21592 (or c_75_2 c_75_3 c_75_4 c_75_5 c_75_6 c_75_7 c_75_8)))
 (let (($x21589 (not $x21592)))
 (let (($x21582 (and $x21592 $x21572)))
 (let (($x21547 (or c_74_2 c_74_3 c_74_4 c_74_5 c_74_6 c_74_7 c_74_8)))
 (let (($x21543 (not $x21547)))
 (let (($x21546 (and c_74_1 $x21543)))
 (let (($x21577 (and $x21547 $x21572)))
 (let (($x20572 (or c_47_2 c_47_3 c_47_4 c_47_5 c_47_6 c_47_7 c_47_8)))
 (let (($x20570 (not $x20572)))
 (let (($x20569 (and c_47_1 $x20570)))
 (let (($x21578 (or (or false (and $x20572 $x21572)) (and $x20569 (= ghost_1_47 (- ghost_1_48 1))))))
 (let (($x21583 (or (or $x21578 $x21577) (and $x21546 (= ghost_1_74 (- ghost_1_48 1))))))
 (let (($x21593 (or (or $x21583 $x21582) (and (and c_75_1 $x21589) (= ghost_1_75 (- ghost_1_48 1))))))
 (let (($x21598 (or (or $x21593 $x21596) (and $x21599 (= ghost_1_76 (- ghost_1_48 1))))))
 (let (($x21609 (or (or $x21598 $x21603) (and $x20625 (= ghost_1_49 (- ghost_1_48 1))))))
 (let (($x21615 (or (or $x21609 $x21610) (and $x19908 (= ghost_1_27 (- ghost_1_48 1))))))
 (let (($x21619 (>= ghost_1_48 1)))
 (let (($x21617 (and (=> (and c_48_1 $x20617) (= ghost_1_48 0)) (=> $x20616 (and $x21619 $x21615)))))
 (let (($x19867 (or c_26_2 c_26_3 c_26_4 c_26_5 c_26_6 c_26_7 c_26_8)))
 (let (($x19865 (not $x19867)))
 (let (($x19863 (and c_26_1 $x19865)))
 (let (($x21529 (= ghost_1_47 1)))
 (let (($x21557 (and $x19867 $x21529)))
 (let (($x21556 (and $x19912 $x21529)))
 (let (($x21544 (and $x20617 $x21529)))
 (let (($x21541 (and $x21547 $x21529)))
 (let (($x21502 (or c_73_2 c_73_3 c_73_4 c_73_5 c_73_6 c_73_7 c_73_8)))
 (let (($x21499 (not $x21502)))
 (let (($x21498 (and c_73_1 $x21499)))
 (let (($x21534 (and $x21502 $x21529)))
 (let (($x20527 (or c_46_2 c_46_3 c_46_4 c_46_5 c_46_6 c_46_7 c_46_8)))
 (let (($x20523 (not $x20527)))
 (let (($x20526 (and c_46_1 $x20523)))
 (let (($x21535 (or (or false (and $x20527 $x21529)) (and $x20526 (= ghost_1_46 (- ghost_1_47 1))))))
 (let (($x21539 (or (or $x21535 $x21534) (and $x21498 (= ghost_1_73 (- ghost_1_47 1))))))
 (let (($x21548 (or (or $x21539 $x21541) (and $x21546 (= ghost_1_74 (- ghost_1_47 1))))))
 (let (($x21555 (or (or $x21548 $x21544) (and $x20616 (= ghost_1_48 (- ghost_1_47 1))))))
 (let (($x21560 (or (or $x21555 $x21556) (and $x19908 (= ghost_1_27 (- ghost_1_47 1))))))
 (let (($x21565 (or (or $x21560 $x21557) (and $x19863 (= ghost_1_26 (- ghost_1_47 1))))))
 (let (($x21569 (>= ghost_1_47 1)))
 (let (($x21570 (and (=> (and c_47_1 $x20572) (= ghost_1_47 0)) (=> $x20569 (and $x21569 $x21565)))))
 (let (($x19822 (or c_25_2 c_25_3 c_25_4 c_25_5 c_25_6 c_25_7 c_25_8)))
 (let (($x19820 (not $x19822)))
 (let (($x19818 (and c_25_1 $x19820)))
 (let (($x21482 (= ghost_1_46 1)))
 (let (($x21512 (and $x19822 $x21482)))
 (let (($x21509 (and $x19867 $x21482)))
 (let (($x21504 (and $x20572 $x21482)))
 (let (($x21495 (and $x21502 $x21482)))
 (let (($x21457 (or c_72_2 c_72_3 c_72_4 c_72_5 c_72_6 c_72_7 c_72_8)))
 (let (($x21456 (not $x21457)))
 (let (($x21454 (and c_72_1 $x21456)))
 (let (($x21486 (and $x21457 $x21482)))
 (let (($x20482 (or c_45_2 c_45_3 c_45_4 c_45_5 c_45_6 c_45_7 c_45_8)))
 (let (($x20481 (not $x20482)))
 (let (($x20479 (and c_45_1 $x20481)))
 (let (($x21488 (or (or false (and $x20482 $x21482)) (and $x20479 (= ghost_1_45 (- ghost_1_46 1))))))
 (let (($x21496 (or (or $x21488 $x21486) (and $x21454 (= ghost_1_72 (- ghost_1_46 1))))))
 (let (($x21503 (or (or $x21496 $x21495) (and $x21498 (= ghost_1_73 (- ghost_1_46 1))))))
 (let (($x21510 (or (or $x21503 $x21504) (and $x20569 (= ghost_1_47 (- ghost_1_46 1))))))
 (let (($x21515 (or (or $x21510 $x21509) (and $x19863 (= ghost_1_26 (- ghost_1_46 1))))))
 (let (($x21520 (or (or $x21515 $x21512) (and $x19818 (= ghost_1_25 (- ghost_1_46 1))))))
 (let (($x21522 (>= ghost_1_46 1)))
 (let (($x21523 (and (=> (and c_46_1 $x20527) (= ghost_1_46 0)) (=> $x20526 (and $x21522 $x21520)))))
 (let (($x19812 (or c_24_2 c_24_3 c_24_4 c_24_5 c_24_6 c_24_7 c_24_8)))
 (let (($x19808 (not $x19812)))
 (let (($x19809 (and c_24_1 $x19808)))
 (let (($x21437 (= ghost_1_45 1)))
 (let (($x21467 (and $x19812 $x21437)))
 (let (($x21466 (and $x19822 $x21437)))
 (let (($x21458 (and $x20527 $x21437)))
 (let (($x21450 (and $x21457 $x21437)))
 (let (($x21412 (or c_71_2 c_71_3 c_71_4 c_71_5 c_71_6 c_71_7 c_71_8)))
 (let (($x21411 (not $x21412)))
 (let (($x21409 (and c_71_1 $x21411)))
 (let (($x21441 (and $x21412 $x21437)))
 (let (($x20472 (or c_44_2 c_44_3 c_44_4 c_44_5 c_44_6 c_44_7 c_44_8)))
 (let (($x20471 (not $x20472)))
 (let (($x20469 (and c_44_1 $x20471)))
 (let (($x21443 (or (or false (and $x20472 $x21437)) (and $x20469 (= ghost_1_44 (- ghost_1_45 1))))))
 (let (($x21451 (or (or $x21443 $x21441) (and $x21409 (= ghost_1_71 (- ghost_1_45 1))))))
 (let (($x21453 (or (or $x21451 $x21450) (and $x21454 (= ghost_1_72 (- ghost_1_45 1))))))
 (let (($x21463 (or (or $x21453 $x21458) (and $x20526 (= ghost_1_46 (- ghost_1_45 1))))))
 (let (($x21470 (or (or $x21463 $x21466) (and $x19818 (= ghost_1_25 (- ghost_1_45 1))))))
 (let (($x21473 (or (or $x21470 $x21467) (and $x19809 (= ghost_1_24 (- ghost_1_45 1))))))
 (let (($x21480 (>= ghost_1_45 1)))
 (let (($x21479 (and (=> (and c_45_1 $x20482) (= ghost_1_45 0)) (=> $x20479 (and $x21480 $x21473)))))
 (let (($x20382 (or c_42_2 c_42_3 c_42_4 c_42_5 c_42_6 c_42_7 c_42_8)))
 (let (($x20380 (not $x20382)))
 (let (($x20379 (and c_42_1 $x20380)))
 (let (($x21387 (= ghost_1_44 1)))
 (let (($x21424 (and $x20382 $x21387)))
 (let (($x21418 (and $x19812 $x21387)))
 (let (($x21413 (and $x20482 $x21387)))
 (let (($x21406 (and $x21412 $x21387)))
 (let (($x21402 (or c_70_2 c_70_3 c_70_4 c_70_5 c_70_6 c_70_7 c_70_8)))
 (let (($x21400 (not $x21402)))
 (let (($x21396 (and $x21402 $x21387)))
 (let (($x21312 (or c_68_2 c_68_3 c_68_4 c_68_5 c_68_6 c_68_7 c_68_8)))
 (let (($x21309 (not $x21312)))
 (let (($x21311 (and c_68_1 $x21309)))
 (let (($x21395 (or (or false (and $x21312 $x21387)) (and $x21311 (= ghost_1_68 (- ghost_1_44 1))))))
 (let (($x21401 (or (or $x21395 $x21396) (and (and c_70_1 $x21400) (= ghost_1_70 (- ghost_1_44 1))))))
 (let (($x21408 (or (or $x21401 $x21406) (and $x21409 (= ghost_1_71 (- ghost_1_44 1))))))
 (let (($x21421 (or (or $x21408 $x21413) (and $x20479 (= ghost_1_45 (- ghost_1_44 1))))))
 (let (($x21423 (or (or $x21421 $x21418) (and $x19809 (= ghost_1_24 (- ghost_1_44 1))))))
 (let (($x21430 (or (or $x21423 $x21424) (and $x20379 (= ghost_1_42 (- ghost_1_44 1))))))
 (let (($x21435 (>= ghost_1_44 1)))
 (let (($x21434 (and (=> (and c_44_1 $x20472) (= ghost_1_44 0)) (=> $x20469 (and $x21435 $x21430)))))
 (let (($x21342 (= ghost_1_43 1)))
 (let (($x21367 (and $x21377 $x21342)))
 (let (($x21366 (and $x21052 $x21342)))
 (let (($x21361 (and $x20212 $x21342)))
 (let (($x19787 (or c_23_2 c_23_3 c_23_4 c_23_5 c_23_6 c_23_7 c_23_8)))
 (let (($x19783 (not $x19787)))
 (let (($x19786 (and c_23_1 $x19783)))
 (let (($x21356 (and $x19787 $x21342)))
 (let (($x20357 (or c_41_2 c_41_3 c_41_4 c_41_5 c_41_6 c_41_7 c_41_8)))
 (let (($x20355 (not $x20357)))
 (let (($x20356 (and c_41_1 $x20355)))
 (let (($x21346 (and $x20357 $x21342)))
 (let (($x21287 (or c_67_2 c_67_3 c_67_4 c_67_5 c_67_6 c_67_7 c_67_8)))
 (let (($x21284 (not $x21287)))
 (let (($x21286 (and c_67_1 $x21284)))
 (let (($x21350 (or (or false (and $x21287 $x21342)) (and $x21286 (= ghost_1_67 (- ghost_1_43 1))))))
 (let (($x21355 (or (or $x21350 $x21346) (and $x20356 (= ghost_1_41 (- ghost_1_43 1))))))
 (let (($x21358 (or (or $x21355 $x21356) (and $x19786 (= ghost_1_23 (- ghost_1_43 1))))))
 (let (($x21365 (or (or $x21358 $x21361) (and $x20211 (= ghost_1_36 (- ghost_1_43 1))))))
 (let (($x21371 (or (or $x21365 $x21366) (and $x21050 (= ghost_1_60 (- ghost_1_43 1))))))
 (let (($x21373 (or (or $x21371 $x21367) (and $x21374 (= ghost_1_69 (- ghost_1_43 1))))))
 (let (($x21385 (>= ghost_1_43 1)))
 (let (($x21384 (and (=> (and c_43_1 $x20447) (= ghost_1_43 0)) (=> $x20444 (and $x21385 $x21373)))))
 (let (($x20292 (or c_40_2 c_40_3 c_40_4 c_40_5 c_40_6 c_40_7 c_40_8)))
 (let (($x20289 (not $x20292)))
 (let (($x20288 (and c_40_1 $x20289)))
 (let (($x21299 (= ghost_1_42 1)))
 (let (($x21330 (and $x20292 $x21299)))
 (let (($x19722 (or c_22_2 c_22_3 c_22_4 c_22_5 c_22_6 c_22_7 c_22_8)))
 (let (($x19718 (not $x19722)))
 (let (($x19720 (and c_22_1 $x19718)))
 (let (($x21324 (and $x19722 $x21299)))
 (let (($x21318 (and $x19812 $x21299)))
 (let (($x21310 (and $x20472 $x21299)))
 (let (($x21306 (and $x21312 $x21299)))
 (let (($x21222 (or c_66_2 c_66_3 c_66_4 c_66_5 c_66_6 c_66_7 c_66_8)))
 (let (($x21219 (not $x21222)))
 (let (($x21221 (and c_66_1 $x21219)))
 (let (($x21305 (or (or false (and $x21222 $x21299)) (and $x21221 (= ghost_1_66 (- ghost_1_42 1))))))
 (let (($x21313 (or (or $x21305 $x21306) (and $x21311 (= ghost_1_68 (- ghost_1_42 1))))))
 (let (($x21321 (or (or $x21313 $x21310) (and $x20469 (= ghost_1_44 (- ghost_1_42 1))))))
 (let (($x21323 (or (or $x21321 $x21318) (and $x19809 (= ghost_1_24 (- ghost_1_42 1))))))
 (let (($x21329 (or (or $x21323 $x21324) (and $x19720 (= ghost_1_22 (- ghost_1_42 1))))))
 (let (($x21333 (or (or $x21329 $x21330) (and $x20288 (= ghost_1_40 (- ghost_1_42 1))))))
 (let (($x21339 (>= ghost_1_42 1)))
 (let (($x21337 (and (=> (and c_42_1 $x20382) (= ghost_1_42 0)) (=> $x20379 (and $x21339 $x21333)))))
 (let (($x21251 (= ghost_1_41 1)))
 (let (($x21280 (and $x21287 $x21251)))
 (let (($x21276 (and $x20447 $x21251)))
 (let (($x21271 (and $x19787 $x21251)))
 (let (($x19697 (or c_21_2 c_21_3 c_21_4 c_21_5 c_21_6 c_21_7 c_21_8)))
 (let (($x19695 (not $x19697)))
 (let (($x19696 (and c_21_1 $x19695)))
 (let (($x21261 (and $x19697 $x21251)))
 (let (($x20267 (or c_39_2 c_39_3 c_39_4 c_39_5 c_39_6 c_39_7 c_39_8)))
 (let (($x20266 (not $x20267)))
 (let (($x20264 (and c_39_1 $x20266)))
 (let (($x21259 (and $x20267 $x21251)))
 (let (($x21197 (or c_65_2 c_65_3 c_65_4 c_65_5 c_65_6 c_65_7 c_65_8)))
 (let (($x21196 (not $x21197)))
 (let (($x21193 (and c_65_1 $x21196)))
 (let (($x21255 (or (or false (and $x21197 $x21251)) (and $x21193 (= ghost_1_65 (- ghost_1_41 1))))))
 (let (($x21266 (or (or $x21255 $x21259) (and $x20264 (= ghost_1_39 (- ghost_1_41 1))))))
 (let (($x21270 (or (or $x21266 $x21261) (and $x19696 (= ghost_1_21 (- ghost_1_41 1))))))
 (let (($x21273 (or (or $x21270 $x21271) (and $x19786 (= ghost_1_23 (- ghost_1_41 1))))))
 (let (($x21281 (or (or $x21273 $x21276) (and $x20444 (= ghost_1_43 (- ghost_1_41 1))))))
 (let (($x21283 (or (or $x21281 $x21280) (and $x21286 (= ghost_1_67 (- ghost_1_41 1))))))
 (let (($x21294 (>= ghost_1_41 1)))
 (let (($x21293 (and (=> (and c_41_1 $x20357) (= ghost_1_41 0)) (=> $x20356 (and $x21294 $x21283)))))
 (let (($x20242 (or c_38_2 c_38_3 c_38_4 c_38_5 c_38_6 c_38_7 c_38_8)))
 (let (($x20240 (not $x20242)))
 (let (($x20238 (and c_38_1 $x20240)))
 (let (($x21207 (= ghost_1_40 1)))
 (let (($x21241 (and $x20242 $x21207)))
 (let (($x19672 (or c_20_2 c_20_3 c_20_4 c_20_5 c_20_6 c_20_7 c_20_8)))
 (let (($x19670 (not $x19672)))
 (let (($x19671 (and c_20_1 $x19670)))
 (let (($x21235 (and $x19672 $x21207)))
 (let (($x21226 (and $x19722 $x21207)))
 (let (($x21223 (and $x20382 $x21207)))
 (let (($x21216 (and $x21222 $x21207)))
 (let (($x21132 (or c_64_2 c_64_3 c_64_4 c_64_5 c_64_6 c_64_7 c_64_8)))
 (let (($x21128 (not $x21132)))
 (let (($x21130 (and c_64_1 $x21128)))
 (let (($x21214 (or (or false (and $x21132 $x21207)) (and $x21130 (= ghost_1_64 (- ghost_1_40 1))))))
 (let (($x21218 (or (or $x21214 $x21216) (and $x21221 (= ghost_1_66 (- ghost_1_40 1))))))
 (let (($x21230 (or (or $x21218 $x21223) (and $x20379 (= ghost_1_42 (- ghost_1_40 1))))))
 (let (($x21234 (or (or $x21230 $x21226) (and $x19720 (= ghost_1_22 (- ghost_1_40 1))))))
 (let (($x21240 (or (or $x21234 $x21235) (and $x19671 (= ghost_1_20 (- ghost_1_40 1))))))
 (let (($x21245 (or (or $x21240 $x21241) (and $x20238 (= ghost_1_38 (- ghost_1_40 1))))))
 (let (($x21248 (>= ghost_1_40 1)))
 (let (($x21249 (and (=> (and c_40_1 $x20292) (= ghost_1_40 0)) (=> $x20288 (and $x21248 $x21245)))))
 (let (($x21161 (= ghost_1_39 1)))
 (let (($x21187 (and $x21197 $x21161)))
 (let (($x21186 (and $x20357 $x21161)))
 (let (($x21173 (and $x19697 $x21161)))
 (let (($x19660 (or c_19_2 c_19_3 c_19_4 c_19_5 c_19_6 c_19_7 c_19_8)))
 (let (($x19657 (not $x19660)))
 (let (($x19659 (and c_19_1 $x19657)))
 (let (($x21171 (and $x19660 $x21161)))
 (let (($x20230 (or c_37_2 c_37_3 c_37_4 c_37_5 c_37_6 c_37_7 c_37_8)))
 (let (($x20227 (not $x20230)))
 (let (($x20228 (and c_37_1 $x20227)))
 (let (($x21165 (and $x20230 $x21161)))
 (let (($x21107 (or c_63_2 c_63_3 c_63_4 c_63_5 c_63_6 c_63_7 c_63_8)))
 (let (($x21105 (not $x21107)))
 (let (($x21106 (and c_63_1 $x21105)))
 (let (($x21170 (or (or false (and $x21107 $x21161)) (and $x21106 (= ghost_1_63 (- ghost_1_39 1))))))
 (let (($x21176 (or (or $x21170 $x21165) (and $x20228 (= ghost_1_37 (- ghost_1_39 1))))))
 (let (($x21180 (or (or $x21176 $x21171) (and $x19659 (= ghost_1_19 (- ghost_1_39 1))))))
 (let (($x21185 (or (or $x21180 $x21173) (and $x19696 (= ghost_1_21 (- ghost_1_39 1))))))
 (let (($x21190 (or (or $x21185 $x21186) (and $x20356 (= ghost_1_41 (- ghost_1_39 1))))))
 (let (($x21198 (or (or $x21190 $x21187) (and $x21193 (= ghost_1_65 (- ghost_1_39 1))))))
 (let (($x21205 (>= ghost_1_39 1)))
 (let (($x21202 (and (=> (and c_39_1 $x20267) (= ghost_1_39 0)) (=> $x20264 (and $x21205 $x21198)))))
 (let (($x21117 (= ghost_1_38 1)))
 (let (($x21142 (and $x20230 $x21117)))
 (let (($x21146 (and $x19660 $x21117)))
 (let (($x21139 (and $x19672 $x21117)))
 (let (($x21134 (and $x20292 $x21117)))
 (let (($x21126 (and $x21132 $x21117)))
 (let (($x21082 (or c_62_2 c_62_3 c_62_4 c_62_5 c_62_6 c_62_7 c_62_8)))
 (let (($x21078 (not $x21082)))
 (let (($x21079 (and c_62_1 $x21078)))
 (let (($x21123 (or (or false (and $x21082 $x21117)) (and $x21079 (= ghost_1_62 (- ghost_1_38 1))))))
 (let (($x21131 (or (or $x21123 $x21126) (and $x21130 (= ghost_1_64 (- ghost_1_38 1))))))
 (let (($x21138 (or (or $x21131 $x21134) (and $x20288 (= ghost_1_40 (- ghost_1_38 1))))))
 (let (($x21145 (or (or $x21138 $x21139) (and $x19671 (= ghost_1_20 (- ghost_1_38 1))))))
 (let (($x21150 (or (or $x21145 $x21146) (and $x19659 (= ghost_1_19 (- ghost_1_38 1))))))
 (let (($x21156 (or (or $x21150 $x21142) (and $x20228 (= ghost_1_37 (- ghost_1_38 1))))))
 (let (($x21159 (>= ghost_1_38 1)))
 (let (($x21160 (and (=> (and c_38_1 $x20242) (= ghost_1_38 0)) (=> $x20238 (and $x21159 $x21156)))))
 (let (($x21061 (= ghost_1_37 1)))
 (let (($x21098 (and $x21107 $x21061)))
 (let (($x21091 (and $x20267 $x21061)))
 (let (($x21087 (and $x19660 $x21061)))
 (let (($x21083 (and $x20242 $x21061)))
 (let (($x21076 (and $x21082 $x21061)))
 (let (($x21070 (or c_61_2 c_61_3 c_61_4 c_61_5 c_61_6 c_61_7 c_61_8)))
 (let (($x21069 (not $x21070)))
 (let (($x21071 (or (or false (and $x21070 $x21061)) (and (and c_61_1 $x21069) (= ghost_1_61 (- ghost_1_37 1))))))
 (let (($x21084 (or (or $x21071 $x21076) (and $x21079 (= ghost_1_62 (- ghost_1_37 1))))))
 (let (($x21090 (or (or $x21084 $x21083) (and $x20238 (= ghost_1_38 (- ghost_1_37 1))))))
 (let (($x21095 (or (or $x21090 $x21087) (and $x19659 (= ghost_1_19 (- ghost_1_37 1))))))
 (let (($x21101 (or (or $x21095 $x21091) (and $x20264 (= ghost_1_39 (- ghost_1_37 1))))))
 (let (($x21103 (or (or $x21101 $x21098) (and $x21106 (= ghost_1_63 (- ghost_1_37 1))))))
 (let (($x21115 (>= ghost_1_37 1)))
 (let (($x21112 (and (=> (and c_37_1 $x20230) (= ghost_1_37 0)) (=> $x20228 (and $x21115 $x21103)))))
 (let (($x21016 (= ghost_1_36 1)))
 (let (($x21042 (and $x21052 $x21016)))
 (let (($x21039 (and $x21007 $x21016)))
 (let (($x21034 (and $x20167 $x21016)))
 (let (($x19642 (or c_18_2 c_18_3 c_18_4 c_18_5 c_18_6 c_18_7 c_18_8)))
 (let (($x19638 (not $x19642)))
 (let (($x19639 (and c_18_1 $x19638)))
 (let (($x21031 (and $x19642 $x21016)))
 (let (($x21021 (and $x19787 $x21016)))
 (let (($x21023 (or (or false (and $x20447 $x21016)) (and $x20444 (= ghost_1_43 (- ghost_1_36 1))))))
 (let (($x21028 (or (or $x21023 $x21021) (and $x19786 (= ghost_1_23 (- ghost_1_36 1))))))
 (let (($x21033 (or (or $x21028 $x21031) (and $x19639 (= ghost_1_18 (- ghost_1_36 1))))))
 (let (($x21038 (or (or $x21033 $x21034) (and $x20163 (= ghost_1_35 (- ghost_1_36 1))))))
 (let (($x21046 (or (or $x21038 $x21039) (and $x21005 (= ghost_1_59 (- ghost_1_36 1))))))
 (let (($x21048 (or (or $x21046 $x21042) (and $x21050 (= ghost_1_60 (- ghost_1_36 1))))))
 (let (($x21059 (>= ghost_1_36 1)))
 (let (($x21057 (and (=> (and c_36_1 $x20212) (= ghost_1_36 0)) (=> $x20211 (and $x21059 $x21048)))))
 (let (($x20973 (= ghost_1_35 1)))
 (let (($x20999 (and $x21007 $x20973)))
 (let (($x20995 (and $x20962 $x20973)))
 (let (($x20989 (and $x20122 $x20973)))
 (let (($x19597 (or c_17_2 c_17_3 c_17_4 c_17_5 c_17_6 c_17_7 c_17_8)))
 (let (($x19595 (not $x19597)))
 (let (($x19594 (and c_17_1 $x19595)))
 (let (($x20984 (and $x19597 $x20973)))
 (let (($x20978 (and $x19642 $x20973)))
 (let (($x20980 (or (or false (and $x20212 $x20973)) (and $x20211 (= ghost_1_36 (- ghost_1_35 1))))))
 (let (($x20983 (or (or $x20980 $x20978) (and $x19639 (= ghost_1_18 (- ghost_1_35 1))))))
 (let (($x20990 (or (or $x20983 $x20984) (and $x19594 (= ghost_1_17 (- ghost_1_35 1))))))
 (let (($x20996 (or (or $x20990 $x20989) (and $x20120 (= ghost_1_34 (- ghost_1_35 1))))))
 (let (($x21000 (or (or $x20996 $x20995) (and $x20959 (= ghost_1_58 (- ghost_1_35 1))))))
 (let (($x21003 (or (or $x21000 $x20999) (and $x21005 (= ghost_1_59 (- ghost_1_35 1))))))
 (let (($x21013 (>= ghost_1_35 1)))
 (let (($x21014 (and (=> (and c_35_1 $x20167) (= ghost_1_35 0)) (=> $x20163 (and $x21013 $x21003)))))
 (let (($x20927 (= ghost_1_34 1)))
 (let (($x20952 (and $x20962 $x20927)))
 (let (($x20946 (and $x20917 $x20927)))
 (let (($x20943 (and $x20112 $x20927)))
 (let (($x19587 (or c_16_2 c_16_3 c_16_4 c_16_5 c_16_6 c_16_7 c_16_8)))
 (let (($x19584 (not $x19587)))
 (let (($x19583 (and c_16_1 $x19584)))
 (let (($x20939 (and $x19587 $x20927)))
 (let (($x20935 (and $x19597 $x20927)))
 (let (($x20931 (or (or false (and $x20167 $x20927)) (and $x20163 (= ghost_1_35 (- ghost_1_34 1))))))
 (let (($x20940 (or (or $x20931 $x20935) (and $x19594 (= ghost_1_17 (- ghost_1_34 1))))))
 (let (($x20944 (or (or $x20940 $x20939) (and $x19583 (= ghost_1_16 (- ghost_1_34 1))))))
 (let (($x20950 (or (or $x20944 $x20943) (and $x20109 (= ghost_1_33 (- ghost_1_34 1))))))
 (let (($x20955 (or (or $x20950 $x20946) (and $x20916 (= ghost_1_57 (- ghost_1_34 1))))))
 (let (($x20964 (or (or $x20955 $x20952) (and $x20959 (= ghost_1_58 (- ghost_1_34 1))))))
 (let (($x20970 (>= ghost_1_34 1)))
 (let (($x20967 (and (=> (and c_34_1 $x20122) (= ghost_1_34 0)) (=> $x20120 (and $x20970 $x20964)))))
 (let (($x20879 (= ghost_1_33 1)))
 (let (($x20911 (and $x20917 $x20879)))
 (let (($x20900 (and $x20907 $x20879)))
 (let (($x20896 (and $x20862 $x20879)))
 (let (($x20888 (and $x20067 $x20879)))
 (let (($x20883 (and $x19587 $x20879)))
 (let (($x20884 (or (or false (and $x20122 $x20879)) (and $x20120 (= ghost_1_34 (- ghost_1_33 1))))))
 (let (($x20889 (or (or $x20884 $x20883) (and $x19583 (= ghost_1_16 (- ghost_1_33 1))))))
 (let (($x20893 (or (or $x20889 $x20888) (and $x20066 (= ghost_1_32 (- ghost_1_33 1))))))
 (let (($x20897 (or (or $x20893 $x20896) (and $x20861 (= ghost_1_55 (- ghost_1_33 1))))))
 (let (($x20905 (or (or $x20897 $x20900) (and $x20903 (= ghost_1_56 (- ghost_1_33 1))))))
 (let (($x20913 (or (or $x20905 $x20911) (and $x20916 (= ghost_1_57 (- ghost_1_33 1))))))
 (let (($x20924 (>= ghost_1_33 1)))
 (let (($x20922 (and (=> (and c_33_1 $x20112) (= ghost_1_33 0)) (=> $x20109 (and $x20924 $x20913)))))
 (let (($x20833 (= ghost_1_32 1)))
 (let (($x20863 (and $x20112 $x20833)))
 (let (($x20852 (and $x20862 $x20833)))
 (let (($x20850 (and $x20817 $x20833)))
 (let (($x20846 (and $x20022 $x20833)))
 (let (($x19542 (or c_15_2 c_15_3 c_15_4 c_15_5 c_15_6 c_15_7 c_15_8)))
 (let (($x19538 (not $x19542)))
 (let (($x19541 (and c_15_1 $x19538)))
 (let (($x20839 (and $x19542 $x20833)))
 (let (($x20837 (or (or false (and $x19587 $x20833)) (and $x19583 (= ghost_1_16 (- ghost_1_32 1))))))
 (let (($x20842 (or (or $x20837 $x20839) (and $x19541 (= ghost_1_15 (- ghost_1_32 1))))))
 (let (($x20849 (or (or $x20842 $x20846) (and $x20020 (= ghost_1_31 (- ghost_1_32 1))))))
 (let (($x20854 (or (or $x20849 $x20850) (and $x20815 (= ghost_1_54 (- ghost_1_32 1))))))
 (let (($x20860 (or (or $x20854 $x20852) (and $x20861 (= ghost_1_55 (- ghost_1_32 1))))))
 (let (($x20870 (or (or $x20860 $x20863) (and $x20109 (= ghost_1_33 (- ghost_1_32 1))))))
 (let (($x20873 (>= ghost_1_32 1)))
 (let (($x20874 (and (=> (and c_32_1 $x20067) (= ghost_1_32 0)) (=> $x20066 (and $x20873 $x20870)))))
 (let (($x20786 (= ghost_1_31 1)))
 (let (($x20814 (and $x20067 $x20786)))
 (let (($x20807 (and $x20817 $x20786)))
 (let (($x20803 (and $x20772 $x20786)))
 (let (($x20796 (and $x20012 $x20786)))
 (let (($x19532 (or c_14_2 c_14_3 c_14_4 c_14_5 c_14_6 c_14_7 c_14_8)))
 (let (($x19530 (not $x19532)))
 (let (($x19529 (and c_14_1 $x19530)))
 (let (($x20793 (and $x19532 $x20786)))
 (let (($x20795 (or (or false (and $x19542 $x20786)) (and $x19541 (= ghost_1_15 (- ghost_1_31 1))))))
 (let (($x20800 (or (or $x20795 $x20793) (and $x19529 (= ghost_1_14 (- ghost_1_31 1))))))
 (let (($x20806 (or (or $x20800 $x20796) (and $x20008 (= ghost_1_30 (- ghost_1_31 1))))))
 (let (($x20811 (or (or $x20806 $x20803) (and $x20770 (= ghost_1_53 (- ghost_1_31 1))))))
 (let (($x20819 (or (or $x20811 $x20807) (and $x20815 (= ghost_1_54 (- ghost_1_31 1))))))
 (let (($x20823 (or (or $x20819 $x20814) (and $x20066 (= ghost_1_32 (- ghost_1_31 1))))))
 (let (($x20828 (>= ghost_1_31 1)))
 (let (($x20830 (and (=> (and c_31_1 $x20022) (= ghost_1_31 0)) (=> $x20020 (and $x20828 $x20823)))))
 (let (($x20738 (= ghost_1_30 1)))
 (let (($x20769 (and $x20022 $x20738)))
 (let (($x20766 (and $x20772 $x20738)))
 (let (($x20755 (and $x20762 $x20738)))
 (let (($x20750 (and $x20717 $x20738)))
 (let (($x20745 (and $x19967 $x20738)))
 (let (($x20743 (or (or false (and $x19532 $x20738)) (and $x19529 (= ghost_1_14 (- ghost_1_30 1))))))
 (let (($x20747 (or (or $x20743 $x20745) (and $x19965 (= ghost_1_29 (- ghost_1_30 1))))))
 (let (($x20753 (or (or $x20747 $x20750) (and $x20713 (= ghost_1_51 (- ghost_1_30 1))))))
 (let (($x20758 (or (or $x20753 $x20755) (and $x20761 (= ghost_1_52 (- ghost_1_30 1))))))
 (let (($x20768 (or (or $x20758 $x20766) (and $x20770 (= ghost_1_53 (- ghost_1_30 1))))))
 (let (($x20779 (or (or $x20768 $x20769) (and $x20020 (= ghost_1_31 (- ghost_1_30 1))))))
 (let (($x20785 (>= ghost_1_30 1)))
 (let (($x20783 (and (=> (and c_30_1 $x20012) (= ghost_1_30 0)) (=> $x20008 (and $x20785 $x20779)))))
 (let (($x20693 (= ghost_1_29 1)))
 (let (($x20723 (and $x19532 $x20693)))
 (let (($x20718 (and $x20012 $x20693)))
 (let (($x20711 (and $x20717 $x20693)))
 (let (($x20705 (and $x20672 $x20693)))
 (let (($x20698 (and $x19922 $x20693)))
 (let (($x19487 (or c_13_2 c_13_3 c_13_4 c_13_5 c_13_6 c_13_7 c_13_8)))
 (let (($x19486 (not $x19487)))
 (let (($x19485 (and c_13_1 $x19486)))
 (let (($x20699 (or (or false (and $x19487 $x20693)) (and $x19485 (= ghost_1_13 (- ghost_1_29 1))))))
 (let (($x20706 (or (or $x20699 $x20698) (and $x19920 (= ghost_1_28 (- ghost_1_29 1))))))
 (let (($x20709 (or (or $x20706 $x20705) (and $x20670 (= ghost_1_50 (- ghost_1_29 1))))))
 (let (($x20719 (or (or $x20709 $x20711) (and $x20713 (= ghost_1_51 (- ghost_1_29 1))))))
 (let (($x20726 (or (or $x20719 $x20718) (and $x20008 (= ghost_1_30 (- ghost_1_29 1))))))
 (let (($x20730 (or (or $x20726 $x20723) (and $x19529 (= ghost_1_14 (- ghost_1_29 1))))))
 (let (($x20732 (>= ghost_1_29 1)))
 (let (($x20735 (and (=> (and c_29_1 $x19967) (= ghost_1_29 0)) (=> $x19965 (and $x20732 $x20730)))))
 (let (($x20646 (= ghost_1_28 1)))
 (let (($x20680 (and $x19487 $x20646)))
 (let (($x20674 (and $x19967 $x20646)))
 (let (($x20662 (and $x20672 $x20646)))
 (let (($x20657 (and $x20627 $x20646)))
 (let (($x20652 (and $x19912 $x20646)))
 (let (($x19477 (or c_12_2 c_12_3 c_12_4 c_12_5 c_12_6 c_12_7 c_12_8)))
 (let (($x19475 (not $x19477)))
 (let (($x19474 (and c_12_1 $x19475)))
 (let (($x20653 (or (or false (and $x19477 $x20646)) (and $x19474 (= ghost_1_12 (- ghost_1_28 1))))))
 (let (($x20660 (or (or $x20653 $x20652) (and $x19908 (= ghost_1_27 (- ghost_1_28 1))))))
 (let (($x20664 (or (or $x20660 $x20657) (and $x20625 (= ghost_1_49 (- ghost_1_28 1))))))
 (let (($x20668 (or (or $x20664 $x20662) (and $x20670 (= ghost_1_50 (- ghost_1_28 1))))))
 (let (($x20677 (or (or $x20668 $x20674) (and $x19965 (= ghost_1_29 (- ghost_1_28 1))))))
 (let (($x20686 (or (or $x20677 $x20680) (and $x19485 (= ghost_1_13 (- ghost_1_28 1))))))
 (let (($x20690 (>= ghost_1_28 1)))
 (let (($x20688 (and (=> (and c_28_1 $x19922) (= ghost_1_28 0)) (=> $x19920 (and $x20690 $x20686)))))
 (let (($x20596 (= ghost_1_27 1)))
 (let (($x20635 (and $x19477 $x20596)))
 (let (($x20624 (and $x19922 $x20596)))
 (let (($x20621 (and $x20627 $x20596)))
 (let (($x20611 (and $x20617 $x20596)))
 (let (($x20603 (and $x20572 $x20596)))
 (let (($x20602 (or (or false (and $x19867 $x20596)) (and $x19863 (= ghost_1_26 (- ghost_1_27 1))))))
 (let (($x20610 (or (or $x20602 $x20603) (and $x20569 (= ghost_1_47 (- ghost_1_27 1))))))
 (let (($x20613 (or (or $x20610 $x20611) (and $x20616 (= ghost_1_48 (- ghost_1_27 1))))))
 (let (($x20629 (or (or $x20613 $x20621) (and $x20625 (= ghost_1_49 (- ghost_1_27 1))))))
 (let (($x20636 (or (or $x20629 $x20624) (and $x19920 (= ghost_1_28 (- ghost_1_27 1))))))
 (let (($x20640 (or (or $x20636 $x20635) (and $x19474 (= ghost_1_12 (- ghost_1_27 1))))))
 (let (($x20644 (>= ghost_1_27 1)))
 (let (($x20645 (and (=> (and c_27_1 $x19912) (= ghost_1_27 0)) (=> $x19908 (and $x20644 $x20640)))))
 (let (($x19432 (or c_11_2 c_11_3 c_11_4 c_11_5 c_11_6 c_11_7 c_11_8)))
 (let (($x19431 (not $x19432)))
 (let (($x19428 (and c_11_1 $x19431)))
 (let (($x20551 (= ghost_1_26 1)))
 (let (($x20584 (and $x19432 $x20551)))
 (let (($x20577 (and $x19477 $x20551)))
 (let (($x20574 (and $x19912 $x20551)))
 (let (($x20562 (and $x20572 $x20551)))
 (let (($x20558 (and $x20527 $x20551)))
 (let (($x20557 (or (or false (and $x19822 $x20551)) (and $x19818 (= ghost_1_25 (- ghost_1_26 1))))))
 (let (($x20563 (or (or $x20557 $x20558) (and $x20526 (= ghost_1_46 (- ghost_1_26 1))))))
 (let (($x20568 (or (or $x20563 $x20562) (and $x20569 (= ghost_1_47 (- ghost_1_26 1))))))
 (let (($x20580 (or (or $x20568 $x20574) (and $x19908 (= ghost_1_27 (- ghost_1_26 1))))))
 (let (($x20585 (or (or $x20580 $x20577) (and $x19474 (= ghost_1_12 (- ghost_1_26 1))))))
 (let (($x20591 (or (or $x20585 $x20584) (and $x19428 (= ghost_1_11 (- ghost_1_26 1))))))
 (let (($x20594 (>= ghost_1_26 1)))
 (let (($x20595 (and (=> (and c_26_1 $x19867) (= ghost_1_26 0)) (=> $x19863 (and $x20594 $x20591)))))
 (let (($x19422 (or c_10_2 c_10_3 c_10_4 c_10_5 c_10_6 c_10_7 c_10_8)))
 (let (($x19420 (not $x19422)))
 (let (($x19419 (and c_10_1 $x19420)))
 (let (($x20507 (= ghost_1_25 1)))
 (let (($x20537 (and $x19422 $x20507)))
 (let (($x20532 (and $x19432 $x20507)))
 (let (($x20524 (and $x19867 $x20507)))
 (let (($x20520 (and $x20527 $x20507)))
 (let (($x20514 (and $x20482 $x20507)))
 (let (($x20513 (or (or false (and $x19812 $x20507)) (and $x19809 (= ghost_1_24 (- ghost_1_25 1))))))
 (let (($x20521 (or (or $x20513 $x20514) (and $x20479 (= ghost_1_45 (- ghost_1_25 1))))))
 (let (($x20528 (or (or $x20521 $x20520) (and $x20526 (= ghost_1_46 (- ghost_1_25 1))))))
 (let (($x20535 (or (or $x20528 $x20524) (and $x19863 (= ghost_1_26 (- ghost_1_25 1))))))
 (let (($x20541 (or (or $x20535 $x20532) (and $x19428 (= ghost_1_11 (- ghost_1_25 1))))))
 (let (($x20545 (or (or $x20541 $x20537) (and $x19419 (= ghost_1_10 (- ghost_1_25 1))))))
 (let (($x20549 (>= ghost_1_25 1)))
 (let (($x20550 (and (=> (and c_25_1 $x19822) (= ghost_1_25 0)) (=> $x19818 (and $x20549 $x20545)))))
 (let (($x20459 (= ghost_1_24 1)))
 (let (($x20494 (and $x19722 $x20459)))
 (let (($x20487 (and $x19422 $x20459)))
 (let (($x20483 (and $x19822 $x20459)))
 (let (($x20476 (and $x20482 $x20459)))
 (let (($x20466 (and $x20472 $x20459)))
 (let (($x20463 (or (or false (and $x20382 $x20459)) (and $x20379 (= ghost_1_42 (- ghost_1_24 1))))))
 (let (($x20468 (or (or $x20463 $x20466) (and $x20469 (= ghost_1_44 (- ghost_1_24 1))))))
 (let (($x20478 (or (or $x20468 $x20476) (and $x20479 (= ghost_1_45 (- ghost_1_24 1))))))
 (let (($x20490 (or (or $x20478 $x20483) (and $x19818 (= ghost_1_25 (- ghost_1_24 1))))))
 (let (($x20495 (or (or $x20490 $x20487) (and $x19419 (= ghost_1_10 (- ghost_1_24 1))))))
 (let (($x20499 (or (or $x20495 $x20494) (and $x19720 (= ghost_1_22 (- ghost_1_24 1))))))
 (let (($x20502 (>= ghost_1_24 1)))
 (let (($x20505 (and (=> (and c_24_1 $x19812) (= ghost_1_24 0)) (=> $x19809 (and $x20502 $x20499)))))
 (let (($x20413 (= ghost_1_23 1)))
 (let (($x20437 (and $x20447 $x20413)))
 (let (($x20434 (and $x20212 $x20413)))
 (let (($x20431 (and $x19642 $x20413)))
 (let (($x19397 (or c_9_2 c_9_3 c_9_4 c_9_5 c_9_6 c_9_7 c_9_8)))
 (let (($x19393 (not $x19397)))
 (let (($x19396 (and c_9_1 $x19393)))
 (let (($x20426 (and $x19397 $x20413)))
 (let (($x20415 (and $x19697 $x20413)))
 (let (($x20420 (or (or false (and $x20357 $x20413)) (and $x20356 (= ghost_1_41 (- ghost_1_23 1))))))
 (let (($x20425 (or (or $x20420 $x20415) (and $x19696 (= ghost_1_21 (- ghost_1_23 1))))))
 (let (($x20428 (or (or $x20425 $x20426) (and $x19396 (= ghost_1_9 (- ghost_1_23 1))))))
 (let (($x20433 (or (or $x20428 $x20431) (and $x19639 (= ghost_1_18 (- ghost_1_23 1))))))
 (let (($x20440 (or (or $x20433 $x20434) (and $x20211 (= ghost_1_36 (- ghost_1_23 1))))))
 (let (($x20443 (or (or $x20440 $x20437) (and $x20444 (= ghost_1_43 (- ghost_1_23 1))))))
 (let (($x20452 (>= ghost_1_23 1)))
 (let (($x20453 (and (=> (and c_23_1 $x19787) (= ghost_1_23 0)) (=> $x19786 (and $x20452 $x20443)))))
 (let (($x20369 (= ghost_1_22 1)))
 (let (($x20401 (and $x19672 $x20369)))
 (let (($x19372 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_7 c_8_8)))
 (let (($x19369 (not $x19372)))
 (let (($x19371 (and c_8_1 $x19369)))
 (let (($x20394 (and $x19372 $x20369)))
 (let (($x20389 (and $x19422 $x20369)))
 (let (($x20381 (and $x19812 $x20369)))
 (let (($x20376 (and $x20382 $x20369)))
 (let (($x20371 (or (or false (and $x20292 $x20369)) (and $x20288 (= ghost_1_40 (- ghost_1_22 1))))))
 (let (($x20384 (or (or $x20371 $x20376) (and $x20379 (= ghost_1_42 (- ghost_1_22 1))))))
 (let (($x20388 (or (or $x20384 $x20381) (and $x19809 (= ghost_1_24 (- ghost_1_22 1))))))
 (let (($x20395 (or (or $x20388 $x20389) (and $x19419 (= ghost_1_10 (- ghost_1_22 1))))))
 (let (($x20398 (or (or $x20395 $x20394) (and $x19371 (= ghost_1_8 (- ghost_1_22 1))))))
 (let (($x20405 (or (or $x20398 $x20401) (and $x19671 (= ghost_1_20 (- ghost_1_22 1))))))
 (let (($x20407 (>= ghost_1_22 1)))
 (let (($x20408 (and (=> (and c_22_1 $x19722) (= ghost_1_22 0)) (=> $x19720 (and $x20407 $x20405)))))
 (let (($x20324 (= ghost_1_21 1)))
 (let (($x20347 (and $x20357 $x20324)))
 (let (($x20346 (and $x19787 $x20324)))
 (let (($x20341 (and $x19397 $x20324)))
 (let (($x19360 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_7 c_7_8)))
 (let (($x19359 (not $x19360)))
 (let (($x19357 (and c_7_1 $x19359)))
 (let (($x20331 (and $x19360 $x20324)))
 (let (($x20329 (and $x19660 $x20324)))
 (let (($x20328 (or (or false (and $x20267 $x20324)) (and $x20264 (= ghost_1_39 (- ghost_1_21 1))))))
 (let (($x20335 (or (or $x20328 $x20329) (and $x19659 (= ghost_1_19 (- ghost_1_21 1))))))
 (let (($x20340 (or (or $x20335 $x20331) (and $x19357 (= ghost_1_7 (- ghost_1_21 1))))))
 (let (($x20343 (or (or $x20340 $x20341) (and $x19396 (= ghost_1_9 (- ghost_1_21 1))))))
 (let (($x20348 (or (or $x20343 $x20346) (and $x19786 (= ghost_1_23 (- ghost_1_21 1))))))
 (let (($x20353 (or (or $x20348 $x20347) (and $x20356 (= ghost_1_41 (- ghost_1_21 1))))))
 (let (($x20364 (>= ghost_1_21 1)))
 (let (($x20362 (and (=> (and c_21_1 $x19697) (= ghost_1_21 0)) (=> $x19696 (and $x20364 $x20353)))))
 (let (($x20277 (= ghost_1_20 1)))
 (let (($x20311 (and $x19660 $x20277)))
 (let (($x20306 (and $x19360 $x20277)))
 (let (($x20300 (and $x19372 $x20277)))
 (let (($x20293 (and $x19722 $x20277)))
 (let (($x20286 (and $x20292 $x20277)))
 (let (($x20282 (or (or false (and $x20242 $x20277)) (and $x20238 (= ghost_1_38 (- ghost_1_20 1))))))
 (let (($x20294 (or (or $x20282 $x20286) (and $x20288 (= ghost_1_40 (- ghost_1_20 1))))))
 (let (($x20299 (or (or $x20294 $x20293) (and $x19720 (= ghost_1_22 (- ghost_1_20 1))))))
 (let (($x20303 (or (or $x20299 $x20300) (and $x19371 (= ghost_1_8 (- ghost_1_20 1))))))
 (let (($x20310 (or (or $x20303 $x20306) (and $x19357 (= ghost_1_7 (- ghost_1_20 1))))))
 (let (($x20315 (or (or $x20310 $x20311) (and $x19659 (= ghost_1_19 (- ghost_1_20 1))))))
 (let (($x20319 (>= ghost_1_20 1)))
 (let (($x20318 (and (=> (and c_20_1 $x19672) (= ghost_1_20 0)) (=> $x19671 (and $x20319 $x20315)))))
 (let (($x20224 (= ghost_1_19 1)))
 (let (($x20257 (and $x20267 $x20224)))
 (let (($x20256 (and $x19697 $x20224)))
 (let (($x20251 (and $x19360 $x20224)))
 (let (($x20244 (and $x19672 $x20224)))
 (let (($x20236 (and $x20242 $x20224)))
 (let (($x20226 (or (or false (and $x20230 $x20224)) (and $x20228 (= ghost_1_37 (- ghost_1_19 1))))))
 (let (($x20241 (or (or $x20226 $x20236) (and $x20238 (= ghost_1_38 (- ghost_1_19 1))))))
 (let (($x20250 (or (or $x20241 $x20244) (and $x19671 (= ghost_1_20 (- ghost_1_19 1))))))
 (let (($x20255 (or (or $x20250 $x20251) (and $x19357 (= ghost_1_7 (- ghost_1_19 1))))))
 (let (($x20260 (or (or $x20255 $x20256) (and $x19696 (= ghost_1_21 (- ghost_1_19 1))))))
 (let (($x20268 (or (or $x20260 $x20257) (and $x20264 (= ghost_1_39 (- ghost_1_19 1))))))
 (let (($x20274 (>= ghost_1_19 1)))
 (let (($x20272 (and (=> (and c_19_1 $x19660) (= ghost_1_19 0)) (=> $x19659 (and $x20274 $x20268)))))
 (let (($x20177 (= ghost_1_18 1)))
 (let (($x20205 (and $x20212 $x20177)))
 (let (($x20199 (and $x20167 $x20177)))
 (let (($x20187 (and $x19597 $x20177)))
 (let (($x19336 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_7 c_6_8)))
 (let (($x19334 (not $x19336)))
 (let (($x19333 (and c_6_1 $x19334)))
 (let (($x20191 (and $x19336 $x20177)))
 (let (($x20184 (and $x19397 $x20177)))
 (let (($x20185 (or (or false (and $x19787 $x20177)) (and $x19786 (= ghost_1_23 (- ghost_1_18 1))))))
 (let (($x20188 (or (or $x20185 $x20184) (and $x19396 (= ghost_1_9 (- ghost_1_18 1))))))
 (let (($x20195 (or (or $x20188 $x20191) (and $x19333 (= ghost_1_6 (- ghost_1_18 1))))))
 (let (($x20200 (or (or $x20195 $x20187) (and $x19594 (= ghost_1_17 (- ghost_1_18 1))))))
 (let (($x20203 (or (or $x20200 $x20199) (and $x20163 (= ghost_1_35 (- ghost_1_18 1))))))
 (let (($x20208 (or (or $x20203 $x20205) (and $x20211 (= ghost_1_36 (- ghost_1_18 1))))))
 (let (($x20217 (>= ghost_1_18 1)))
 (let (($x20220 (and (=> (and c_18_1 $x19642) (= ghost_1_18 0)) (=> $x19639 (and $x20217 $x20208)))))
 (let (($x20131 (= ghost_1_17 1)))
 (let (($x20157 (and $x20167 $x20131)))
 (let (($x20153 (and $x20122 $x20131)))
 (let (($x20150 (and $x19587 $x20131)))
 (let (($x19326 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8)))
 (let (($x19325 (not $x19326)))
 (let (($x19324 (and c_5_1 $x19325)))
 (let (($x20141 (and $x19326 $x20131)))
 (let (($x20139 (and $x19336 $x20131)))
 (let (($x20138 (or (or false (and $x19642 $x20131)) (and $x19639 (= ghost_1_18 (- ghost_1_17 1))))))
 (let (($x20145 (or (or $x20138 $x20139) (and $x19333 (= ghost_1_6 (- ghost_1_17 1))))))
 (let (($x20151 (or (or $x20145 $x20141) (and $x19324 (= ghost_1_5 (- ghost_1_17 1))))))
 (let (($x20154 (or (or $x20151 $x20150) (and $x19583 (= ghost_1_16 (- ghost_1_17 1))))))
 (let (($x20161 (or (or $x20154 $x20153) (and $x20120 (= ghost_1_34 (- ghost_1_17 1))))))
 (let (($x20169 (or (or $x20161 $x20157) (and $x20163 (= ghost_1_35 (- ghost_1_17 1))))))
 (let (($x20174 (>= ghost_1_17 1)))
 (let (($x20175 (and (=> (and c_17_1 $x19597) (= ghost_1_17 0)) (=> $x19594 (and $x20174 $x20169)))))
 (let (($x20084 (= ghost_1_16 1)))
 (let (($x20116 (and $x20122 $x20084)))
 (let (($x20105 (and $x20112 $x20084)))
 (let (($x20101 (and $x20067 $x20084)))
 (let (($x20095 (and $x19542 $x20084)))
 (let (($x20087 (and $x19326 $x20084)))
 (let (($x20088 (or (or false (and $x19597 $x20084)) (and $x19594 (= ghost_1_17 (- ghost_1_16 1))))))
 (let (($x20096 (or (or $x20088 $x20087) (and $x19324 (= ghost_1_5 (- ghost_1_16 1))))))
 (let (($x20097 (or (or $x20096 $x20095) (and $x19541 (= ghost_1_15 (- ghost_1_16 1))))))
 (let (($x20103 (or (or $x20097 $x20101) (and $x20066 (= ghost_1_32 (- ghost_1_16 1))))))
 (let (($x20114 (or (or $x20103 $x20105) (and $x20109 (= ghost_1_33 (- ghost_1_16 1))))))
 (let (($x20118 (or (or $x20114 $x20116) (and $x20120 (= ghost_1_34 (- ghost_1_16 1))))))
 (let (($x20128 (>= ghost_1_16 1)))
 (let (($x20130 (and (=> (and c_16_1 $x19587) (= ghost_1_16 0)) (=> $x19583 (and $x20128 $x20118)))))
 (let (($x20037 (= ghost_1_15 1)))
 (let (($x20068 (and $x19587 $x20037)))
 (let (($x20061 (and $x20067 $x20037)))
 (let (($x20047 (and $x20022 $x20037)))
 (let (($x20049 (and $x19532 $x20037)))
 (let (($x19316 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8)))
 (let (($x19314 (not $x19316)))
 (let (($x19312 (and c_4_1 $x19314)))
 (let (($x20040 (and $x19316 $x20037)))
 (let (($x20044 (or (or false (and $x19326 $x20037)) (and $x19324 (= ghost_1_5 (- ghost_1_15 1))))))
 (let (($x20050 (or (or $x20044 $x20040) (and $x19312 (= ghost_1_4 (- ghost_1_15 1))))))
 (let (($x20055 (or (or $x20050 $x20049) (and $x19529 (= ghost_1_14 (- ghost_1_15 1))))))
 (let (($x20059 (or (or $x20055 $x20047) (and $x20020 (= ghost_1_31 (- ghost_1_15 1))))))
 (let (($x20063 (or (or $x20059 $x20061) (and $x20066 (= ghost_1_32 (- ghost_1_15 1))))))
 (let (($x20074 (or (or $x20063 $x20068) (and $x19583 (= ghost_1_16 (- ghost_1_15 1))))))
 (let (($x20077 (>= ghost_1_15 1)))
 (let (($x20079 (and (=> (and c_15_1 $x19542) (= ghost_1_15 0)) (=> $x19541 (and $x20077 $x20074)))))
 (let (($x19988 (= ghost_1_14 1)))
 (let (($x20024 (and $x19542 $x19988)))
 (let (($x20016 (and $x20022 $x19988)))
 (let (($x20006 (and $x20012 $x19988)))
 (let (($x20000 (and $x19967 $x19988)))
 (let (($x19995 (and $x19487 $x19988)))
 (let (($x19990 (or (or false (and $x19316 $x19988)) (and $x19312 (= ghost_1_4 (- ghost_1_14 1))))))
 (let (($x20001 (or (or $x19990 $x19995) (and $x19485 (= ghost_1_13 (- ghost_1_14 1))))))
 (let (($x20002 (or (or $x20001 $x20000) (and $x19965 (= ghost_1_29 (- ghost_1_14 1))))))
 (let (($x20013 (or (or $x20002 $x20006) (and $x20008 (= ghost_1_30 (- ghost_1_14 1))))))
 (let (($x20018 (or (or $x20013 $x20016) (and $x20020 (= ghost_1_31 (- ghost_1_14 1))))))
 (let (($x20027 (or (or $x20018 $x20024) (and $x19541 (= ghost_1_15 (- ghost_1_14 1))))))
 (let (($x20034 (>= ghost_1_14 1)))
 (let (($x20032 (and (=> (and c_14_1 $x19532) (= ghost_1_14 0)) (=> $x19529 (and $x20034 $x20027)))))
 (let (($x19942 (= ghost_1_13 1)))
 (let (($x19971 (and $x19316 $x19942)))
 (let (($x19969 (and $x19532 $x19942)))
 (let (($x19957 (and $x19967 $x19942)))
 (let (($x19954 (and $x19922 $x19942)))
 (let (($x19948 (and $x19477 $x19942)))
 (let (($x19306 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8)))
 (let (($x19304 (not $x19306)))
 (let (($x19302 (and c_3_1 $x19304)))
 (let (($x19947 (or (or false (and $x19306 $x19942)) (and $x19302 (= ghost_1_3 (- ghost_1_13 1))))))
 (let (($x19955 (or (or $x19947 $x19948) (and $x19474 (= ghost_1_12 (- ghost_1_13 1))))))
 (let (($x19961 (or (or $x19955 $x19954) (and $x19920 (= ghost_1_28 (- ghost_1_13 1))))))
 (let (($x19966 (or (or $x19961 $x19957) (and $x19965 (= ghost_1_29 (- ghost_1_13 1))))))
 (let (($x19975 (or (or $x19966 $x19969) (and $x19529 (= ghost_1_14 (- ghost_1_13 1))))))
 (let (($x19985 (>= ghost_1_13 1)))
 (let (($x19984 (and $x19985 (or (or $x19975 $x19971) (and $x19312 (= ghost_1_4 (- ghost_1_13 1)))))))
 (let (($x19891 (= ghost_1_12 1)))
 (let (($x19930 (and $x19306 $x19891)))
 (let (($x19919 (and $x19487 $x19891)))
 (let (($x19916 (and $x19922 $x19891)))
 (let (($x19906 (and $x19912 $x19891)))
 (let (($x19898 (and $x19867 $x19891)))
 (let (($x19896 (or (or false (and $x19432 $x19891)) (and $x19428 (= ghost_1_11 (- ghost_1_12 1))))))
 (let (($x19905 (or (or $x19896 $x19898) (and $x19863 (= ghost_1_26 (- ghost_1_12 1))))))
 (let (($x19911 (or (or $x19905 $x19906) (and $x19908 (= ghost_1_27 (- ghost_1_12 1))))))
 (let (($x19918 (or (or $x19911 $x19916) (and $x19920 (= ghost_1_28 (- ghost_1_12 1))))))
 (let (($x19931 (or (or $x19918 $x19919) (and $x19485 (= ghost_1_13 (- ghost_1_12 1))))))
 (let (($x19939 (>= ghost_1_12 1)))
 (let (($x19938 (and $x19939 (or (or $x19931 $x19930) (and $x19302 (= ghost_1_3 (- ghost_1_12 1)))))))
 (let (($x19296 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8)))
 (let (($x19293 (not $x19296)))
 (let (($x19292 (and c_2_1 $x19293)))
 (let (($x19847 (= ghost_1_11 1)))
 (let (($x19877 (and $x19296 $x19847)))
 (let (($x19874 (and $x19306 $x19847)))
 (let (($x19869 (and $x19477 $x19847)))
 (let (($x19861 (and $x19867 $x19847)))
 (let (($x19852 (and $x19822 $x19847)))
 (let (($x19853 (or (or false (and $x19422 $x19847)) (and $x19419 (= ghost_1_10 (- ghost_1_11 1))))))
 (let (($x19860 (or (or $x19853 $x19852) (and $x19818 (= ghost_1_25 (- ghost_1_11 1))))))
 (let (($x19866 (or (or $x19860 $x19861) (and $x19863 (= ghost_1_26 (- ghost_1_11 1))))))
 (let (($x19875 (or (or $x19866 $x19869) (and $x19474 (= ghost_1_12 (- ghost_1_11 1))))))
 (let (($x19880 (or (or $x19875 $x19874) (and $x19302 (= ghost_1_3 (- ghost_1_11 1))))))
 (let (($x19890 (>= ghost_1_11 1)))
 (let (($x19887 (and $x19890 (or (or $x19880 $x19877) (and $x19292 (= ghost_1_2 (- ghost_1_11 1)))))))
 (let (($x19799 (= ghost_1_10 1)))
 (let (($x19833 (and $x19372 $x19799)))
 (let (($x19827 (and $x19296 $x19799)))
 (let (($x19824 (and $x19432 $x19799)))
 (let (($x19816 (and $x19822 $x19799)))
 (let (($x19806 (and $x19812 $x19799)))
 (let (($x19804 (or (or false (and $x19722 $x19799)) (and $x19720 (= ghost_1_22 (- ghost_1_10 1))))))
 (let (($x19813 (or (or $x19804 $x19806) (and $x19809 (= ghost_1_24 (- ghost_1_10 1))))))
 (let (($x19821 (or (or $x19813 $x19816) (and $x19818 (= ghost_1_25 (- ghost_1_10 1))))))
 (let (($x19831 (or (or $x19821 $x19824) (and $x19428 (= ghost_1_11 (- ghost_1_10 1))))))
 (let (($x19834 (or (or $x19831 $x19827) (and $x19292 (= ghost_1_2 (- ghost_1_10 1))))))
 (let (($x19844 (>= ghost_1_10 1)))
 (let (($x19843 (and $x19844 (or (or $x19834 $x19833) (and $x19371 (= ghost_1_8 (- ghost_1_10 1)))))))
 (let (($x19754 (= ghost_1_9 1)))
 (let (($x19781 (and $x19787 $x19754)))
 (let (($x19767 (and $x19642 $x19754)))
 (let (($x19771 (and $x19336 $x19754)))
 (let (($x19283 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8)))
 (let (($x19280 (not $x19283)))
 (let (($x19279 (and c_1_1 $x19280)))
 (let (($x19766 (and $x19283 $x19754)))
 (let (($x19758 (and $x19360 $x19754)))
 (let (($x19760 (or (or false (and $x19697 $x19754)) (and $x19696 (= ghost_1_21 (- ghost_1_9 1))))))
 (let (($x19765 (or (or $x19760 $x19758) (and $x19357 (= ghost_1_7 (- ghost_1_9 1))))))
 (let (($x19770 (or (or $x19765 $x19766) (and $x19279 (= ghost_1_1 (- ghost_1_9 1))))))
 (let (($x19775 (or (or $x19770 $x19771) (and $x19333 (= ghost_1_6 (- ghost_1_9 1))))))
 (let (($x19778 (or (or $x19775 $x19767) (and $x19639 (= ghost_1_18 (- ghost_1_9 1))))))
 (let (($x19792 (>= ghost_1_9 1)))
 (let (($x19795 (and $x19792 (or (or $x19778 $x19781) (and $x19786 (= ghost_1_23 (- ghost_1_9 1)))))))
 (let (($x19709 (= ghost_1_8 1)))
 (let (($x19741 (and $x19360 $x19709)))
 (let (($x19733 (and $x19283 $x19709)))
 (let (($x19729 (and $x19296 $x19709)))
 (let (($x19719 (and $x19422 $x19709)))
 (let (($x19716 (and $x19722 $x19709)))
 (let (($x19715 (or (or false (and $x19672 $x19709)) (and $x19671 (= ghost_1_20 (- ghost_1_8 1))))))
 (let (($x19724 (or (or $x19715 $x19716) (and $x19720 (= ghost_1_22 (- ghost_1_8 1))))))
 (let (($x19730 (or (or $x19724 $x19719) (and $x19419 (= ghost_1_10 (- ghost_1_8 1))))))
 (let (($x19734 (or (or $x19730 $x19729) (and $x19292 (= ghost_1_2 (- ghost_1_8 1))))))
 (let (($x19740 (or (or $x19734 $x19733) (and $x19279 (= ghost_1_1 (- ghost_1_8 1))))))
 (let (($x19748 (>= ghost_1_8 1)))
 (let (($x19750 (and $x19748 (or (or $x19740 $x19741) (and $x19357 (= ghost_1_7 (- ghost_1_8 1)))))))
 (let (($x19651 (= ghost_1_7 1)))
 (let (($x19687 (and $x19697 $x19651)))
 (let (($x19686 (and $x19397 $x19651)))
 (let (($x19681 (and $x19283 $x19651)))
 (let (($x19669 (and $x19372 $x19651)))
 (let (($x19666 (and $x19672 $x19651)))
 (let (($x19656 (or (or false (and $x19660 $x19651)) (and $x19659 (= ghost_1_19 (- ghost_1_7 1))))))
 (let (($x19668 (or (or $x19656 $x19666) (and $x19671 (= ghost_1_20 (- ghost_1_7 1))))))
 (let (($x19678 (or (or $x19668 $x19669) (and $x19371 (= ghost_1_8 (- ghost_1_7 1))))))
 (let (($x19685 (or (or $x19678 $x19681) (and $x19279 (= ghost_1_1 (- ghost_1_7 1))))))
 (let (($x19688 (or (or $x19685 $x19686) (and $x19396 (= ghost_1_9 (- ghost_1_7 1))))))
 (let (($x19704 (>= ghost_1_7 1)))
 (let (($x19705 (and $x19704 (or (or $x19688 $x19687) (and $x19696 (= ghost_1_21 (- ghost_1_7 1)))))))
 (let (($x19608 (= ghost_1_6 1)))
 (let (($x19636 (and $x19642 $x19608)))
 (let (($x19630 (and $x19597 $x19608)))
 (let (($x19624 (and $x19326 $x19608)))
 (let (($x19348 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8)))
 (let (($x19347 (not $x19348)))
 (let (($x19346 (and c_0_1 $x19347)))
 (let (($x19621 (and $x19348 $x19608)))
 (let (($x19614 (and $x19283 $x19608)))
 (let (($x19615 (or (or false (and $x19397 $x19608)) (and $x19396 (= ghost_1_9 (- ghost_1_6 1))))))
 (let (($x19620 (or (or $x19615 $x19614) (and $x19279 (= ghost_1_1 (- ghost_1_6 1))))))
 (let (($x19623 (or (or $x19620 $x19621) (and $x19346 (= ghost_1_0 (- ghost_1_6 1))))))
 (let (($x19631 (or (or $x19623 $x19624) (and $x19324 (= ghost_1_5 (- ghost_1_6 1))))))
 (let (($x19635 (or (or $x19631 $x19630) (and $x19594 (= ghost_1_17 (- ghost_1_6 1))))))
 (let (($x19649 (>= ghost_1_6 1)))
 (let (($x19648 (and $x19649 (or (or $x19635 $x19636) (and $x19639 (= ghost_1_18 (- ghost_1_6 1)))))))
 (let (($x19556 (= ghost_1_5 1)))
 (let (($x19591 (and $x19597 $x19556)))
 (let (($x19580 (and $x19587 $x19556)))
 (let (($x19574 (and $x19542 $x19556)))
 (let (($x19569 (and $x19316 $x19556)))
 (let (($x19565 (and $x19348 $x19556)))
 (let (($x19563 (or (or false (and $x19336 $x19556)) (and $x19333 (= ghost_1_6 (- ghost_1_5 1))))))
 (let (($x19568 (or (or $x19563 $x19565) (and $x19346 (= ghost_1_0 (- ghost_1_5 1))))))
 (let (($x19575 (or (or $x19568 $x19569) (and $x19312 (= ghost_1_4 (- ghost_1_5 1))))))
 (let (($x19577 (or (or $x19575 $x19574) (and $x19541 (= ghost_1_15 (- ghost_1_5 1))))))
 (let (($x19588 (or (or $x19577 $x19580) (and $x19583 (= ghost_1_16 (- ghost_1_5 1))))))
 (let (($x19605 (>= ghost_1_5 1)))
 (let (($x19604 (and $x19605 (or (or $x19588 $x19591) (and $x19594 (= ghost_1_17 (- ghost_1_5 1)))))))
 (let (($x19506 (= ghost_1_4 1)))
 (let (($x19543 (and $x19326 $x19506)))
 (let (($x19536 (and $x19542 $x19506)))
 (let (($x19522 (and $x19532 $x19506)))
 (let (($x19517 (and $x19487 $x19506)))
 (let (($x19515 (and $x19306 $x19506)))
 (let (($x19511 (or (or false (and $x19348 $x19506)) (and $x19346 (= ghost_1_0 (- ghost_1_4 1))))))
 (let (($x19520 (or (or $x19511 $x19515) (and $x19302 (= ghost_1_3 (- ghost_1_4 1))))))
 (let (($x19526 (or (or $x19520 $x19517) (and $x19485 (= ghost_1_13 (- ghost_1_4 1))))))
 (let (($x19534 (or (or $x19526 $x19522) (and $x19529 (= ghost_1_14 (- ghost_1_4 1))))))
 (let (($x19540 (or (or $x19534 $x19536) (and $x19541 (= ghost_1_15 (- ghost_1_4 1))))))
 (let (($x19554 (>= ghost_1_4 1)))
 (let (($x19552 (and $x19554 (or (or $x19540 $x19543) (and $x19324 (= ghost_1_5 (- ghost_1_4 1)))))))
 (let (($x19456 (= ghost_1_3 1)))
 (let (($x19494 (and $x19348 $x19456)))
 (let (($x19484 (and $x19316 $x19456)))
 (let (($x19481 (and $x19487 $x19456)))
 (let (($x19470 (and $x19477 $x19456)))
 (let (($x19464 (and $x19432 $x19456)))
 (let (($x19462 (or (or false (and $x19296 $x19456)) (and $x19292 (= ghost_1_2 (- ghost_1_3 1))))))
 (let (($x19471 (or (or $x19462 $x19464) (and $x19428 (= ghost_1_11 (- ghost_1_3 1))))))
 (let (($x19473 (or (or $x19471 $x19470) (and $x19474 (= ghost_1_12 (- ghost_1_3 1))))))
 (let (($x19483 (or (or $x19473 $x19481) (and $x19485 (= ghost_1_13 (- ghost_1_3 1))))))
 (let (($x19495 (or (or $x19483 $x19484) (and $x19312 (= ghost_1_4 (- ghost_1_3 1))))))
 (let (($x19504 (>= ghost_1_3 1)))
 (let (($x19502 (and $x19504 (or (or $x19495 $x19494) (and $x19346 (= ghost_1_0 (- ghost_1_3 1)))))))
 (let (($x19409 (= ghost_1_2 1)))
 (let (($x19444 (and $x19283 $x19409)))
 (let (($x19437 (and $x19348 $x19409)))
 (let (($x19433 (and $x19306 $x19409)))
 (let (($x19426 (and $x19432 $x19409)))
 (let (($x19416 (and $x19422 $x19409)))
 (let (($x19415 (or (or false (and $x19372 $x19409)) (and $x19371 (= ghost_1_8 (- ghost_1_2 1))))))
 (let (($x19418 (or (or $x19415 $x19416) (and $x19419 (= ghost_1_10 (- ghost_1_2 1))))))
 (let (($x19430 (or (or $x19418 $x19426) (and $x19428 (= ghost_1_11 (- ghost_1_2 1))))))
 (let (($x19440 (or (or $x19430 $x19433) (and $x19302 (= ghost_1_3 (- ghost_1_2 1))))))
 (let (($x19443 (or (or $x19440 $x19437) (and $x19346 (= ghost_1_0 (- ghost_1_2 1))))))
 (let (($x19453 (>= ghost_1_2 1)))
 (let (($x19452 (and $x19453 (or (or $x19443 $x19444) (and $x19279 (= ghost_1_1 (- ghost_1_2 1)))))))
 (let (($x19354 (= ghost_1_1 1)))
 (let (($x19389 (and $x19397 $x19354)))
 (let (($x19384 (and $x19336 $x19354)))
 (let (($x19378 (and $x19348 $x19354)))
 (let (($x19373 (and $x19296 $x19354)))
 (let (($x19366 (and $x19372 $x19354)))
 (let (($x19356 (or (or false (and $x19360 $x19354)) (and $x19357 (= ghost_1_7 (- ghost_1_1 1))))))
 (let (($x19368 (or (or $x19356 $x19366) (and $x19371 (= ghost_1_8 (- ghost_1_1 1))))))
 (let (($x19379 (or (or $x19368 $x19373) (and $x19292 (= ghost_1_2 (- ghost_1_1 1))))))
 (let (($x19383 (or (or $x19379 $x19378) (and $x19346 (= ghost_1_0 (- ghost_1_1 1))))))
 (let (($x19390 (or (or $x19383 $x19384) (and $x19333 (= ghost_1_6 (- ghost_1_1 1))))))
 (let (($x19404 (>= ghost_1_1 1)))
 (let (($x19405 (and $x19404 (or (or $x19390 $x19389) (and $x19396 (= ghost_1_9 (- ghost_1_1 1)))))))
 (let (($x19278 (= ghost_1_0 1)))
 (let (($x19330 (and $x19336 $x19278)))
 (let (($x19320 (and $x19326 $x19278)))
 (let (($x19310 (and $x19316 $x19278)))
 (let (($x19300 (and $x19306 $x19278)))
 (let (($x19290 (and $x19296 $x19278)))
 (let (($x19284 (or (or false (and $x19283 $x19278)) (and $x19279 (= ghost_1_1 (- ghost_1_0 1))))))
 (let (($x19297 (or (or $x19284 $x19290) (and $x19292 (= ghost_1_2 (- ghost_1_0 1))))))
 (let (($x19305 (or (or $x19297 $x19300) (and $x19302 (= ghost_1_3 (- ghost_1_0 1))))))
 (let (($x19318 (or (or $x19305 $x19310) (and $x19312 (= ghost_1_4 (- ghost_1_0 1))))))
 (let (($x19322 (or (or $x19318 $x19320) (and $x19324 (= ghost_1_5 (- ghost_1_0 1))))))
 (let (($x19345 (>= ghost_1_0 1)))
 (let (($x19344 (and $x19345 (or (or $x19322 $x19330) (and $x19333 (= ghost_1_6 (- ghost_1_0 1)))))))
 (let (($x19178 (or (or c_90_2 c_90_3 c_90_4 c_90_5 c_90_6 c_90_7) c_90_8)))
 (let (($x19152 (or (or c_89_2 c_89_3 c_89_4 c_89_5 c_89_6 c_89_7) c_89_8)))
 (let (($x18462 (or c_59_2 c_59_3 c_59_4 c_59_5 c_59_6 c_59_7)))
 (let (($x18456 (or $x18462 c_59_8)))
 (let (($x17948 (or c_36_2 c_36_3 c_36_4 c_36_5 c_36_6 c_36_7)))
 (let (($x17942 (or $x17948 c_36_8)))
 (let (($x18102 (or c_43_2 c_43_3 c_43_4 c_43_5 c_43_6 c_43_7)))
 (let (($x18096 (or $x18102 c_43_8)))
 (let (($x18688 (or (or c_69_2 c_69_3 c_69_4 c_69_5 c_69_6 c_69_7) c_69_8)))
 (let (($x19161 (or false (and c_60_2 $x18688))))
 (let (($x19155 (or $x19161 (and c_60_3 $x18096))))
 (let (($x19163 (or $x19155 (and c_60_4 $x17942))))
 (let (($x19164 (or $x19163 (and c_60_5 $x18456))))
 (let (($x19169 (or $x19164 (and c_60_6 $x19152))))
 (let (($x18488 (or c_60_2 c_60_3 c_60_4 c_60_5 c_60_6 c_60_7)))
 (let (($x19126 (or (or c_88_2 c_88_3 c_88_4 c_88_5 c_88_6 c_88_7) c_88_8)))
 (let (($x18436 (or c_58_2 c_58_3 c_58_4 c_58_5 c_58_6 c_58_7)))
 (let (($x18430 (or $x18436 c_58_8)))
 (let (($x17922 (or c_35_2 c_35_3 c_35_4 c_35_5 c_35_6 c_35_7)))
 (let (($x17916 (or $x17922 c_35_8)))
 (let (($x19133 (or false (and c_59_2 (or $x18488 c_60_8)))))
 (let (($x19136 (or $x19133 (and c_59_3 $x17942))))
 (let (($x19135 (or $x19136 (and c_59_4 $x17916))))
 (let (($x19139 (or $x19135 (and c_59_5 $x18430))))
 (let (($x19141 (or $x19139 (and c_59_6 $x19126))))
 (let (($x19100 (or (or c_87_2 c_87_3 c_87_4 c_87_5 c_87_6 c_87_7) c_87_8)))
 (let (($x18410 (or c_57_2 c_57_3 c_57_4 c_57_5 c_57_6 c_57_7)))
 (let (($x18404 (or $x18410 c_57_8)))
 (let (($x17896 (or c_34_2 c_34_3 c_34_4 c_34_5 c_34_6 c_34_7)))
 (let (($x17890 (or $x17896 c_34_8)))
 (let (($x19107 (or false (and c_58_2 $x18456))))
 (let (($x19111 (or $x19107 (and c_58_3 $x17916))))
 (let (($x19109 (or $x19111 (and c_58_4 $x17890))))
 (let (($x19114 (or $x19109 (and c_58_5 $x18404))))
 (let (($x19112 (or $x19114 (and c_58_6 $x19100))))
 (let (($x19074 (or (or c_86_2 c_86_3 c_86_4 c_86_5 c_86_6 c_86_7) c_86_8)))
 (let (($x18396 (or c_56_2 c_56_3 c_56_4 c_56_5 c_56_6 c_56_7)))
 (let (($x18390 (or $x18396 c_56_8)))
 (let (($x17882 (or c_33_2 c_33_3 c_33_4 c_33_5 c_33_6 c_33_7)))
 (let (($x17876 (or $x17882 c_33_8)))
 (let (($x19082 (or false (and c_57_2 $x18430))))
 (let (($x19081 (or $x19082 (and c_57_3 $x17890))))
 (let (($x19086 (or $x19081 (and c_57_4 $x17876))))
 (let (($x19088 (or $x19086 (and c_57_5 $x18390))))
 (let (($x19090 (or $x19088 (and c_57_6 $x19074))))
 (let (($x19060 (or (or c_85_2 c_85_3 c_85_4 c_85_5 c_85_6 c_85_7) c_85_8)))
 (let (($x19034 (or (or c_84_2 c_84_3 c_84_4 c_84_5 c_84_6 c_84_7) c_84_8)))
 (let (($x18370 (or c_55_2 c_55_3 c_55_4 c_55_5 c_55_6 c_55_7)))
 (let (($x18364 (or $x18370 c_55_8)))
 (let (($x19041 (or false (and c_56_2 $x18404))))
 (let (($x19044 (or $x19041 (and c_56_3 $x17876))))
 (let (($x19048 (or $x19044 (and c_56_4 $x18364))))
 (let (($x19047 (or $x19048 (and c_56_5 $x19034))))
 (let (($x19062 (or $x19047 (and c_56_6 $x19060))))
 (let (($x19008 (or (or c_83_2 c_83_3 c_83_4 c_83_5 c_83_6 c_83_7) c_83_8)))
 (let (($x18344 (or c_54_2 c_54_3 c_54_4 c_54_5 c_54_6 c_54_7)))
 (let (($x18338 (or $x18344 c_54_8)))
 (let (($x17856 (or c_32_2 c_32_3 c_32_4 c_32_5 c_32_6 c_32_7)))
 (let (($x17850 (or $x17856 c_32_8)))
 (let (($x19018 (or false (and c_55_2 $x17876))))
 (let (($x19020 (or $x19018 (and c_55_3 $x17850))))
 (let (($x19023 (or $x19020 (and c_55_4 $x18338))))
 (let (($x19024 (or $x19023 (and c_55_5 $x19008))))
 (let (($x19036 (or $x19024 (and c_55_6 $x19034))))
 (let (($x18982 (or (or c_82_2 c_82_3 c_82_4 c_82_5 c_82_6 c_82_7) c_82_8)))
 (let (($x18318 (or c_53_2 c_53_3 c_53_4 c_53_5 c_53_6 c_53_7)))
 (let (($x18312 (or $x18318 c_53_8)))
 (let (($x17830 (or c_31_2 c_31_3 c_31_4 c_31_5 c_31_6 c_31_7)))
 (let (($x17824 (or $x17830 c_31_8)))
 (let (($x18992 (or false (and c_54_2 $x17850))))
 (let (($x18995 (or $x18992 (and c_54_3 $x17824))))
 (let (($x18996 (or $x18995 (and c_54_4 $x18312))))
 (let (($x18998 (or $x18996 (and c_54_5 $x18982))))
 (let (($x19012 (or $x18998 (and c_54_6 $x19008))))
 (let (($x18956 (or (or c_81_2 c_81_3 c_81_4 c_81_5 c_81_6 c_81_7) c_81_8)))
 (let (($x18304 (or c_52_2 c_52_3 c_52_4 c_52_5 c_52_6 c_52_7)))
 (let (($x18298 (or $x18304 c_52_8)))
 (let (($x17816 (or c_30_2 c_30_3 c_30_4 c_30_5 c_30_6 c_30_7)))
 (let (($x17810 (or $x17816 c_30_8)))
 (let (($x18967 (or false (and c_53_2 $x17824))))
 (let (($x18968 (or $x18967 (and c_53_3 $x17810))))
 (let (($x18971 (or $x18968 (and c_53_4 $x18298))))
 (let (($x18973 (or $x18971 (and c_53_5 $x18956))))
 (let (($x18986 (or $x18973 (and c_53_6 $x18982))))
 (let (($x18942 (or (or c_80_2 c_80_3 c_80_4 c_80_5 c_80_6 c_80_7) c_80_8)))
 (let (($x18916 (or (or c_79_2 c_79_3 c_79_4 c_79_5 c_79_6 c_79_7) c_79_8)))
 (let (($x18278 (or c_51_2 c_51_3 c_51_4 c_51_5 c_51_6 c_51_7)))
 (let (($x18272 (or $x18278 c_51_8)))
 (let (($x18926 (or false (and c_52_2 $x17810))))
 (let (($x18931 (or $x18926 (and c_52_3 $x18272))))
 (let (($x18930 (or $x18931 (and c_52_4 $x18916))))
 (let (($x18944 (or $x18930 (and c_52_5 $x18942))))
 (let (($x18960 (or $x18944 (and c_52_6 $x18956))))
 (let (($x18890 (or (or c_78_2 c_78_3 c_78_4 c_78_5 c_78_6 c_78_7) c_78_8)))
 (let (($x18252 (or c_50_2 c_50_3 c_50_4 c_50_5 c_50_6 c_50_7)))
 (let (($x18246 (or $x18252 c_50_8)))
 (let (($x17790 (or c_29_2 c_29_3 c_29_4 c_29_5 c_29_6 c_29_7)))
 (let (($x17784 (or $x17790 c_29_8)))
 (let (($x18902 (or false (and c_51_2 $x17784))))
 (let (($x18903 (or $x18902 (and c_51_3 $x18246))))
 (let (($x18906 (or $x18903 (and c_51_4 $x18890))))
 (let (($x18919 (or $x18906 (and c_51_5 $x18916))))
 (let (($x18921 (or $x18919 (and c_51_6 $x18298))))
 (let (($x18864 (or (or c_77_2 c_77_3 c_77_4 c_77_5 c_77_6 c_77_7) c_77_8)))
 (let (($x18226 (or c_49_2 c_49_3 c_49_4 c_49_5 c_49_6 c_49_7)))
 (let (($x18220 (or $x18226 c_49_8)))
 (let (($x17764 (or c_28_2 c_28_3 c_28_4 c_28_5 c_28_6 c_28_7)))
 (let (($x17758 (or $x17764 c_28_8)))
 (let (($x18876 (or false (and c_50_2 $x17758))))
 (let (($x18878 (or $x18876 (and c_50_3 $x18220))))
 (let (($x18880 (or $x18878 (and c_50_4 $x18864))))
 (let (($x18893 (or $x18880 (and c_50_5 $x18890))))
 (let (($x18894 (or $x18893 (and c_50_6 $x18272))))
 (let (($x18838 (or (or c_76_2 c_76_3 c_76_4 c_76_5 c_76_6 c_76_7) c_76_8)))
 (let (($x18212 (or c_48_2 c_48_3 c_48_4 c_48_5 c_48_6 c_48_7)))
 (let (($x18206 (or $x18212 c_48_8)))
 (let (($x17750 (or c_27_2 c_27_3 c_27_4 c_27_5 c_27_6 c_27_7)))
 (let (($x17744 (or $x17750 c_27_8)))
 (let (($x18851 (or false (and c_49_2 $x17744))))
 (let (($x18849 (or $x18851 (and c_49_3 $x18206))))
 (let (($x18855 (or $x18849 (and c_49_4 $x18838))))
 (let (($x18867 (or $x18855 (and c_49_5 $x18864))))
 (let (($x18868 (or $x18867 (and c_49_6 $x18246))))
 (let (($x18824 (or (or c_75_2 c_75_3 c_75_4 c_75_5 c_75_6 c_75_7) c_75_8)))
 (let (($x18798 (or (or c_74_2 c_74_3 c_74_4 c_74_5 c_74_6 c_74_7) c_74_8)))
 (let (($x18186 (or c_47_2 c_47_3 c_47_4 c_47_5 c_47_6 c_47_7)))
 (let (($x18180 (or $x18186 c_47_8)))
 (let (($x18811 (or false (and c_48_2 $x18180))))
 (let (($x18813 (or $x18811 (and c_48_3 $x18798))))
 (let (($x18827 (or $x18813 (and c_48_4 $x18824))))
 (let (($x18843 (or $x18827 (and c_48_5 $x18838))))
 (let (($x18840 (or $x18843 (and c_48_6 $x18220))))
 (let (($x17724 (or c_26_2 c_26_3 c_26_4 c_26_5 c_26_6 c_26_7)))
 (let (($x17718 (or $x17724 c_26_8)))
 (let (($x18772 (or (or c_73_2 c_73_3 c_73_4 c_73_5 c_73_6 c_73_7) c_73_8)))
 (let (($x18160 (or c_46_2 c_46_3 c_46_4 c_46_5 c_46_6 c_46_7)))
 (let (($x18154 (or $x18160 c_46_8)))
 (let (($x18787 (or false (and c_47_2 $x18154))))
 (let (($x18789 (or $x18787 (and c_47_3 $x18772))))
 (let (($x18802 (or $x18789 (and c_47_4 $x18798))))
 (let (($x18800 (or $x18802 (and c_47_5 $x18206))))
 (let (($x18807 (or $x18800 (and c_47_6 $x17744))))
 (let (($x17698 (or c_25_2 c_25_3 c_25_4 c_25_5 c_25_6 c_25_7)))
 (let (($x17692 (or $x17698 c_25_8)))
 (let (($x18746 (or (or c_72_2 c_72_3 c_72_4 c_72_5 c_72_6 c_72_7) c_72_8)))
 (let (($x18134 (or c_45_2 c_45_3 c_45_4 c_45_5 c_45_6 c_45_7)))
 (let (($x18128 (or $x18134 c_45_8)))
 (let (($x18759 (or false (and c_46_2 $x18128))))
 (let (($x18760 (or $x18759 (and c_46_3 $x18746))))
 (let (($x18775 (or $x18760 (and c_46_4 $x18772))))
 (let (($x18776 (or $x18775 (and c_46_5 $x18180))))
 (let (($x18779 (or $x18776 (and c_46_6 $x17718))))
 (let (($x17684 (or c_24_2 c_24_3 c_24_4 c_24_5 c_24_6 c_24_7)))
 (let (($x17678 (or $x17684 c_24_8)))
 (let (($x18720 (or (or c_71_2 c_71_3 c_71_4 c_71_5 c_71_6 c_71_7) c_71_8)))
 (let (($x18120 (or c_44_2 c_44_3 c_44_4 c_44_5 c_44_6 c_44_7)))
 (let (($x18114 (or $x18120 c_44_8)))
 (let (($x18730 (or false (and c_45_2 $x18114))))
 (let (($x18734 (or $x18730 (and c_45_3 $x18720))))
 (let (($x18751 (or $x18734 (and c_45_4 $x18746))))
 (let (($x18748 (or $x18751 (and c_45_5 $x18154))))
 (let (($x18755 (or $x18748 (and c_45_6 $x17692))))
 (let (($x18068 (or c_42_2 c_42_3 c_42_4 c_42_5 c_42_6 c_42_7)))
 (let (($x18062 (or $x18068 c_42_8)))
 (let (($x18706 (or (or c_70_2 c_70_3 c_70_4 c_70_5 c_70_6 c_70_7) c_70_8)))
 (let (($x18654 (or (or c_68_2 c_68_3 c_68_4 c_68_5 c_68_6 c_68_7) c_68_8)))
 (let (($x18695 (or false (and c_44_2 $x18654))))
 (let (($x18710 (or $x18695 (and c_44_3 $x18706))))
 (let (($x18725 (or $x18710 (and c_44_4 $x18720))))
 (let (($x18722 (or $x18725 (and c_44_5 $x18128))))
 (let (($x18727 (or $x18722 (and c_44_6 $x17678))))
 (let (($x17666 (or c_23_2 c_23_3 c_23_4 c_23_5 c_23_6 c_23_7)))
 (let (($x17660 (or $x17666 c_23_8)))
 (let (($x18050 (or c_41_2 c_41_3 c_41_4 c_41_5 c_41_6 c_41_7)))
 (let (($x18044 (or $x18050 c_41_8)))
 (let (($x18636 (or (or c_67_2 c_67_3 c_67_4 c_67_5 c_67_6 c_67_7) c_67_8)))
 (let (($x18668 (or false (and c_43_2 $x18636))))
 (let (($x18673 (or $x18668 (and c_43_3 $x18044))))
 (let (($x18672 (or $x18673 (and c_43_4 $x17660))))
 (let (($x18676 (or $x18672 (and c_43_5 $x17942))))
 (let (($x18671 (or $x18676 (and c_43_6 (or $x18488 c_60_8)))))
 (let (($x18016 (or c_40_2 c_40_3 c_40_4 c_40_5 c_40_6 c_40_7)))
 (let (($x18010 (or $x18016 c_40_8)))
 (let (($x17632 (or c_22_2 c_22_3 c_22_4 c_22_5 c_22_6 c_22_7)))
 (let (($x17626 (or $x17632 c_22_8)))
 (let (($x18602 (or (or c_66_2 c_66_3 c_66_4 c_66_5 c_66_6 c_66_7) c_66_8)))
 (let (($x18643 (or false (and c_42_2 $x18602))))
 (let (($x18657 (or $x18643 (and c_42_3 $x18654))))
 (let (($x18658 (or $x18657 (and c_42_4 $x18114))))
 (let (($x18661 (or $x18658 (and c_42_5 $x17678))))
 (let (($x18662 (or $x18661 (and c_42_6 $x17626))))
 (let (($x17614 (or c_21_2 c_21_3 c_21_4 c_21_5 c_21_6 c_21_7)))
 (let (($x17608 (or $x17614 c_21_8)))
 (let (($x17998 (or c_39_2 c_39_3 c_39_4 c_39_5 c_39_6 c_39_7)))
 (let (($x17992 (or $x17998 c_39_8)))
 (let (($x18584 (or (or c_65_2 c_65_3 c_65_4 c_65_5 c_65_6 c_65_7) c_65_8)))
 (let (($x18615 (or false (and c_41_2 $x18584))))
 (let (($x18620 (or $x18615 (and c_41_3 $x17992))))
 (let (($x18623 (or $x18620 (and c_41_4 $x17608))))
 (let (($x18625 (or $x18623 (and c_41_5 $x17660))))
 (let (($x18626 (or $x18625 (and c_41_6 $x18096))))
 (let (($x17978 (or c_38_2 c_38_3 c_38_4 c_38_5 c_38_6 c_38_7)))
 (let (($x17972 (or $x17978 c_38_8)))
 (let (($x17594 (or c_20_2 c_20_3 c_20_4 c_20_5 c_20_6 c_20_7)))
 (let (($x17588 (or $x17594 c_20_8)))
 (let (($x18550 (or (or c_64_2 c_64_3 c_64_4 c_64_5 c_64_6 c_64_7) c_64_8)))
 (let (($x18593 (or false (and c_40_2 $x18550))))
 (let (($x18605 (or $x18593 (and c_40_3 $x18602))))
 (let (($x18604 (or $x18605 (and c_40_4 $x18062))))
 (let (($x18609 (or $x18604 (and c_40_5 $x17626))))
 (let (($x18612 (or $x18609 (and c_40_6 $x17588))))
 (let (($x17580 (or c_19_2 c_19_3 c_19_4 c_19_5 c_19_6 c_19_7)))
 (let (($x17574 (or $x17580 c_19_8)))
 (let (($x17964 (or c_37_2 c_37_3 c_37_4 c_37_5 c_37_6 c_37_7)))
 (let (($x17958 (or $x17964 c_37_8)))
 (let (($x18532 (or (or c_63_2 c_63_3 c_63_4 c_63_5 c_63_6 c_63_7) c_63_8)))
 (let (($x18558 (or false (and c_39_2 $x18532))))
 (let (($x18565 (or $x18558 (and c_39_3 $x17958))))
 (let (($x18569 (or $x18565 (and c_39_4 $x17574))))
 (let (($x18571 (or $x18569 (and c_39_5 $x17608))))
 (let (($x18575 (or $x18571 (and c_39_6 $x18044))))
 (let (($x18512 (or (or c_62_2 c_62_3 c_62_4 c_62_5 c_62_6 c_62_7) c_62_8)))
 (let (($x18535 (or false (and c_38_2 $x18512))))
 (let (($x18552 (or $x18535 (and c_38_3 $x18550))))
 (let (($x18553 (or $x18552 (and c_38_4 $x18010))))
 (let (($x18555 (or $x18553 (and c_38_5 $x17588))))
 (let (($x18559 (or $x18555 (and c_38_6 $x17574))))
 (let (($x18498 (or (or c_61_2 c_61_3 c_61_4 c_61_5 c_61_6 c_61_7) c_61_8)))
 (let (($x18502 (or false (and c_37_2 $x18498))))
 (let (($x18514 (or $x18502 (and c_37_3 $x18512))))
 (let (($x18517 (or $x18514 (and c_37_4 $x17972))))
 (let (($x18516 (or $x18517 (and c_37_5 $x17574))))
 (let (($x18521 (or $x18516 (and c_37_6 $x17992))))
 (let (($x18463 (or false (and c_36_2 $x18096))))
 (let (($x18465 (or $x18463 (and c_36_3 $x17660))))
 (let (($x18468 (or $x18465 (and c_36_4 (or $x17564 c_18_8)))))
 (let (($x18466 (or $x18468 (and c_36_5 $x17916))))
 (let (($x18471 (or $x18466 (and c_36_6 $x18456))))
 (let (($x18438 (or false (and c_35_2 $x17942))))
 (let (($x18432 (or $x18438 (and c_35_3 (or $x17564 c_18_8)))))
 (let (($x18441 (or $x18432 (and c_35_4 (or $x17538 c_17_8)))))
 (let (($x18443 (or $x18441 (and c_35_5 $x17890))))
 (let (($x18446 (or $x18443 (and c_35_6 $x18430))))
 (let (($x18412 (or false (and c_34_2 $x17916))))
 (let (($x18406 (or $x18412 (and c_34_3 (or $x17538 c_17_8)))))
 (let (($x18415 (or $x18406 (and c_34_4 (or $x17524 c_16_8)))))
 (let (($x18418 (or $x18415 (and c_34_5 $x17876))))
 (let (($x18420 (or $x18418 (and c_34_6 $x18404))))
 (let (($x18375 (or false (and c_33_2 $x17890))))
 (let (($x18376 (or $x18375 (and c_33_3 (or $x17524 c_16_8)))))
 (let (($x18378 (or $x18376 (and c_33_4 $x17850))))
 (let (($x18381 (or $x18378 (and c_33_5 $x18364))))
 (let (($x18392 (or $x18381 (and c_33_6 $x18390))))
 (let (($x18348 (or false (and c_32_2 (or $x17524 c_16_8)))))
 (let (($x18350 (or $x18348 (and c_32_3 (or $x17498 c_15_8)))))
 (let (($x18353 (or $x18350 (and c_32_4 $x17824))))
 (let (($x18354 (or $x18353 (and c_32_5 $x18338))))
 (let (($x18366 (or $x18354 (and c_32_6 $x18364))))
 (let (($x18323 (or false (and c_31_2 (or $x17498 c_15_8)))))
 (let (($x18325 (or $x18323 (and c_31_3 (or $x17484 c_14_8)))))
 (let (($x18324 (or $x18325 (and c_31_4 $x17810))))
 (let (($x18329 (or $x18324 (and c_31_5 $x18312))))
 (let (($x18340 (or $x18329 (and c_31_6 $x18338))))
 (let (($x18280 (or false (and c_30_2 (or $x17484 c_14_8)))))
 (let (($x18285 (or $x18280 (and c_30_3 $x17784))))
 (let (($x18284 (or $x18285 (and c_30_4 $x18272))))
 (let (($x18302 (or $x18284 (and c_30_5 $x18298))))
 (let (($x18317 (or $x18302 (and c_30_6 $x18312))))
 (let (($x18258 (or false (and c_29_2 (or $x17458 c_13_8)))))
 (let (($x18260 (or $x18258 (and c_29_3 $x17758))))
 (let (($x18262 (or $x18260 (and c_29_4 $x18246))))
 (let (($x18275 (or $x18262 (and c_29_5 $x18272))))
 (let (($x18277 (or $x18275 (and c_29_6 $x17810))))
 (let (($x18223 (or false (and c_28_2 (or $x17444 c_12_8)))))
 (let (($x18233 (or $x18223 (and c_28_3 $x17744))))
 (let (($x18231 (or $x18233 (and c_28_4 $x18220))))
 (let (($x18249 (or $x18231 (and c_28_5 $x18246))))
 (let (($x18248 (or $x18249 (and c_28_6 $x17784))))
 (let (($x18191 (or false (and c_27_2 $x17718))))
 (let (($x18192 (or $x18191 (and c_27_3 $x18180))))
 (let (($x18210 (or $x18192 (and c_27_4 $x18206))))
 (let (($x18222 (or $x18210 (and c_27_5 $x18220))))
 (let (($x18225 (or $x18222 (and c_27_6 $x17758))))
 (let (($x18163 (or false (and c_26_2 $x17692))))
 (let (($x18167 (or $x18163 (and c_26_3 $x18154))))
 (let (($x18184 (or $x18167 (and c_26_4 $x18180))))
 (let (($x18182 (or $x18184 (and c_26_5 $x17744))))
 (let (($x18185 (or $x18182 (and c_26_6 (or $x17444 c_12_8)))))
 (let (($x18139 (or false (and c_25_2 $x17678))))
 (let (($x18143 (or $x18139 (and c_25_3 $x18128))))
 (let (($x18156 (or $x18143 (and c_25_4 $x18154))))
 (let (($x18158 (or $x18156 (and c_25_5 $x17718))))
 (let (($x18157 (or $x18158 (and c_25_6 (or $x17418 c_11_8)))))
 (let (($x18104 (or false (and c_24_2 $x18062))))
 (let (($x18119 (or $x18104 (and c_24_3 $x18114))))
 (let (($x18133 (or $x18119 (and c_24_4 $x18128))))
 (let (($x18130 (or $x18133 (and c_24_5 $x17692))))
 (let (($x18132 (or $x18130 (and c_24_6 (or $x17404 c_10_8)))))
 (let (($x18078 (or false (and c_23_2 $x18044))))
 (let (($x18077 (or $x18078 (and c_23_3 $x17608))))
 (let (($x18083 (or $x18077 (and c_23_4 (or $x17386 c_9_8)))))
 (let (($x18081 (or $x18083 (and c_23_5 (or $x17564 c_18_8)))))
 (let (($x18085 (or $x18081 (and c_23_6 $x17942))))
 (let (($x18053 (or false (and c_22_2 $x18010))))
 (let (($x18066 (or $x18053 (and c_22_3 $x18062))))
 (let (($x18067 (or $x18066 (and c_22_4 $x17678))))
 (let (($x18069 (or $x18067 (and c_22_5 (or $x17404 c_10_8)))))
 (let (($x18071 (or $x18069 (and c_22_6 (or $x17365 c_8_8)))))
 (let (($x18025 (or false (and c_21_2 $x17992))))
 (let (($x18029 (or $x18025 (and c_21_3 $x17574))))
 (let (($x18028 (or $x18029 (and c_21_4 (or $x17351 c_7_8)))))
 (let (($x18033 (or $x18028 (and c_21_5 (or $x17386 c_9_8)))))
 (let (($x18031 (or $x18033 (and c_21_6 $x17660))))
 (let (($x17999 (or false (and c_20_2 $x17972))))
 (let (($x18013 (or $x17999 (and c_20_3 $x18010))))
 (let (($x18015 (or $x18013 (and c_20_4 $x17626))))
 (let (($x18018 (or $x18015 (and c_20_5 (or $x17365 c_8_8)))))
 (let (($x18021 (or $x18018 (and c_20_6 (or $x17351 c_7_8)))))
 (let (($x17962 (or false (and c_19_2 $x17958))))
 (let (($x17976 (or $x17962 (and c_19_3 $x17972))))
 (let (($x17975 (or $x17976 (and c_19_4 $x17588))))
 (let (($x17977 (or $x17975 (and c_19_5 (or $x17351 c_7_8)))))
 (let (($x17983 (or $x17977 (and c_19_6 $x17608))))
 (let (($x17923 (or false (and c_18_2 $x17660))))
 (let (($x17926 (or $x17923 (and c_18_3 (or $x17386 c_9_8)))))
 (let (($x17925 (or $x17926 (and c_18_4 (or $x17324 c_6_8)))))
 (let (($x17929 (or $x17925 (and c_18_5 (or $x17538 c_17_8)))))
 (let (($x17928 (or $x17929 (and c_18_6 $x17916))))
 (let (($x17898 (or false (and c_17_2 (or $x17564 c_18_8)))))
 (let (($x17899 (or $x17898 (and c_17_3 (or $x17324 c_6_8)))))
 (let (($x17901 (or $x17899 (and c_17_4 (or $x17310 c_5_8)))))
 (let (($x17904 (or $x17901 (and c_17_5 (or $x17524 c_16_8)))))
 (let (($x17906 (or $x17904 (and c_17_6 $x17890))))
 (let (($x17861 (or false (and c_16_2 (or $x17538 c_17_8)))))
 (let (($x17860 (or $x17861 (and c_16_3 (or $x17310 c_5_8)))))
 (let (($x17864 (or $x17860 (and c_16_4 (or $x17498 c_15_8)))))
 (let (($x17867 (or $x17864 (and c_16_5 $x17850))))
 (let (($x17879 (or $x17867 (and c_16_6 $x17876))))
 (let (($x17832 (or false (and c_15_2 (or $x17310 c_5_8)))))
 (let (($x17836 (or $x17832 (and c_15_3 (or $x17296 c_4_8)))))
 (let (($x17831 (or $x17836 (and c_15_4 (or $x17484 c_14_8)))))
 (let (($x17837 (or $x17831 (and c_15_5 $x17824))))
 (let (($x17853 (or $x17837 (and c_15_6 $x17850))))
 (let (($x17796 (or false (and c_14_2 (or $x17296 c_4_8)))))
 (let (($x17789 (or $x17796 (and c_14_3 (or $x17458 c_13_8)))))
 (let (($x17800 (or $x17789 (and c_14_4 $x17784))))
 (let (($x17812 (or $x17800 (and c_14_5 $x17810))))
 (let (($x17827 (or $x17812 (and c_14_6 $x17824))))
 (let (($x17769 (or false (and c_13_2 (or $x17282 c_3_8)))))
 (let (($x17761 (or $x17769 (and c_13_3 (or $x17444 c_12_8)))))
 (let (($x17773 (or $x17761 (and c_13_4 $x17758))))
 (let (($x17786 (or $x17773 (and c_13_5 $x17784))))
 (let (($x17788 (or $x17786 (and c_13_6 (or $x17484 c_14_8)))))
 (let (($x17729 (or false (and c_12_2 (or $x17418 c_11_8)))))
 (let (($x17731 (or $x17729 (and c_12_3 $x17718))))
 (let (($x17748 (or $x17731 (and c_12_4 $x17744))))
 (let (($x17763 (or $x17748 (and c_12_5 $x17758))))
 (let (($x17760 (or $x17763 (and c_12_6 (or $x17458 c_13_8)))))
 (let (($x17704 (or false (and c_11_2 (or $x17404 c_10_8)))))
 (let (($x17707 (or $x17704 (and c_11_3 $x17692))))
 (let (($x17722 (or $x17707 (and c_11_4 $x17718))))
 (let (($x17721 (or $x17722 (and c_11_5 (or $x17444 c_12_8)))))
 (let (($x17725 (or $x17721 (and c_11_6 (or $x17282 c_3_8)))))
 (let (($x17667 (or false (and c_10_2 $x17626))))
 (let (($x17680 (or $x17667 (and c_10_3 $x17678))))
 (let (($x17696 (or $x17680 (and c_10_4 $x17692))))
 (let (($x17695 (or $x17696 (and c_10_5 (or $x17418 c_11_8)))))
 (let (($x17697 (or $x17695 (and c_10_6 (or $x17268 c_2_8)))))
 (let (($x17643 (or false (and c_9_2 $x17608))))
 (let (($x17645 (or $x17643 (and c_9_3 (or $x17351 c_7_8)))))
 (let (($x17647 (or $x17645 (and c_9_4 (or $x17254 c_1_8)))))
 (let (($x17649 (or $x17647 (and c_9_5 (or $x17324 c_6_8)))))
 (let (($x17646 (or $x17649 (and c_9_6 (or $x17564 c_18_8)))))
 (let (($x17617 (or false (and c_8_2 $x17588))))
 (let (($x17628 (or $x17617 (and c_8_3 $x17626))))
 (let (($x17631 (or $x17628 (and c_8_4 (or $x17404 c_10_8)))))
 (let (($x17633 (or $x17631 (and c_8_5 (or $x17268 c_2_8)))))
 (let (($x17629 (or $x17633 (and c_8_6 (or $x17254 c_1_8)))))
 (let (($x17578 (or false (and c_7_2 $x17574))))
 (let (($x17592 (or $x17578 (and c_7_3 $x17588))))
 (let (($x17591 (or $x17592 (and c_7_4 (or $x17365 c_8_8)))))
 (let (($x17597 (or $x17591 (and c_7_5 (or $x17254 c_1_8)))))
 (let (($x17599 (or $x17597 (and c_7_6 (or $x17386 c_9_8)))))
 (let (($x17540 (or false (and c_6_2 (or $x17386 c_9_8)))))
 (let (($x17541 (or $x17540 (and c_6_3 (or $x17254 c_1_8)))))
 (let (($x17545 (or $x17541 (and c_6_4 (or $x17338 c_0_8)))))
 (let (($x17542 (or $x17545 (and c_6_5 (or $x17310 c_5_8)))))
 (let (($x17548 (or $x17542 (and c_6_6 (or $x17538 c_17_8)))))
 (let (($x17499 (or false (and c_5_2 (or $x17324 c_6_8)))))
 (let (($x17501 (or $x17499 (and c_5_3 (or $x17338 c_0_8)))))
 (let (($x17503 (or $x17501 (and c_5_4 (or $x17296 c_4_8)))))
 (let (($x17506 (or $x17503 (and c_5_5 (or $x17498 c_15_8)))))
 (let (($x17521 (or $x17506 (and c_5_6 (or $x17524 c_16_8)))))
 (let (($x17462 (or false (and c_4_2 (or $x17338 c_0_8)))))
 (let (($x17465 (or $x17462 (and c_4_3 (or $x17282 c_3_8)))))
 (let (($x17466 (or $x17465 (and c_4_4 (or $x17458 c_13_8)))))
 (let (($x17482 (or $x17466 (and c_4_5 (or $x17484 c_14_8)))))
 (let (($x17494 (or $x17482 (and c_4_6 (or $x17498 c_15_8)))))
 (let (($x17423 (or false (and c_3_2 (or $x17268 c_2_8)))))
 (let (($x17422 (or $x17423 (and c_3_3 (or $x17418 c_11_8)))))
 (let (($x17442 (or $x17422 (and c_3_4 (or $x17444 c_12_8)))))
 (let (($x17457 (or $x17442 (and c_3_5 (or $x17458 c_13_8)))))
 (let (($x17455 (or $x17457 (and c_3_6 (or $x17296 c_4_8)))))
 (let (($x17389 (or false (and c_2_2 (or $x17365 c_8_8)))))
 (let (($x17402 (or $x17389 (and c_2_3 (or $x17404 c_10_8)))))
 (let (($x17417 (or $x17402 (and c_2_4 (or $x17418 c_11_8)))))
 (let (($x17415 (or $x17417 (and c_2_5 (or $x17282 c_3_8)))))
 (let (($x17416 (or $x17415 (and c_2_6 (or $x17338 c_0_8)))))
 (let (($x17348 (or false (and c_1_2 (or $x17351 c_7_8)))))
 (let (($x17362 (or $x17348 (and c_1_3 (or $x17365 c_8_8)))))
 (let (($x17361 (or $x17362 (and c_1_4 (or $x17268 c_2_8)))))
 (let (($x17366 (or $x17361 (and c_1_5 (or $x17338 c_0_8)))))
 (let (($x17369 (or $x17366 (and c_1_6 (or $x17324 c_6_8)))))
 (let (($x17252 (or false (and c_0_2 (or $x17254 c_1_8)))))
 (let (($x17266 (or $x17252 (and c_0_3 (or $x17268 c_2_8)))))
 (let (($x17280 (or $x17266 (and c_0_4 (or $x17282 c_3_8)))))
 (let (($x17294 (or $x17280 (and c_0_5 (or $x17296 c_4_8)))))
 (let (($x17306 (or $x17294 (and c_0_6 (or $x17310 c_5_8)))))
 (let (($x17235 (not (and c_60_8 (not in_target_60)))))
 (let (($x17230 (not (and c_59_8 (not in_target_59)))))
 (let (($x17225 (not (and c_58_8 (not in_target_58)))))
 (let (($x17220 (not (and c_57_8 (not in_target_57)))))
 (let (($x17215 (not (and c_56_8 (not in_target_56)))))
 (let (($x17210 (not (and c_55_8 (not in_target_55)))))
 (let (($x17205 (not (and c_54_8 (not in_target_54)))))
 (let (($x17200 (not (and c_53_8 (not in_target_53)))))
 (let (($x17195 (not (and c_52_8 (not in_target_52)))))
 (let (($x17190 (not (and c_51_8 (not in_target_51)))))
 (let (($x17185 (not (and c_50_8 (not in_target_50)))))
 (let (($x17180 (not (and c_49_8 (not in_target_49)))))
 (let (($x17175 (not (and c_48_8 (not in_target_48)))))
 (let (($x17170 (not (and c_47_8 (not in_target_47)))))
 (let (($x17165 (not (and c_46_8 (not in_target_46)))))
 (let (($x17160 (not (and c_45_8 (not in_target_45)))))
 (let (($x17155 (not (and c_44_8 (not in_target_44)))))
 (let (($x17150 (not (and c_43_8 (not in_target_43)))))
 (let (($x17145 (not (and c_42_8 (not in_target_42)))))
 (let (($x17140 (not (and c_41_8 (not in_target_41)))))
 (let (($x17135 (not (and c_40_8 (not in_target_40)))))
 (let (($x17130 (not (and c_39_8 (not in_target_39)))))
 (let (($x17125 (not (and c_38_8 (not in_target_38)))))
 (let (($x17120 (not (and c_37_8 (not in_target_37)))))
 (let (($x17115 (not (and c_36_8 (not in_target_36)))))
 (let (($x17110 (not (and c_35_8 (not in_target_35)))))
 (let (($x17105 (not (and c_34_8 (not in_target_34)))))
 (let (($x17100 (not (and c_33_8 (not in_target_33)))))
 (let (($x17095 (not (and c_32_8 (not in_target_32)))))
 (let (($x17090 (not (and c_31_8 (not in_target_31)))))
 (let (($x17085 (not (and c_30_8 (not in_target_30)))))
 (let (($x17080 (not (and c_29_8 (not in_target_29)))))
 (let (($x17075 (not (and c_28_8 (not in_target_28)))))
 (let (($x17070 (not (and c_27_8 (not in_target_27)))))
 (let (($x17065 (not (and c_26_8 (not in_target_26)))))
 (let (($x17060 (not (and c_25_8 (not in_target_25)))))
 (let (($x17055 (not (and c_24_8 (not in_target_24)))))
 (let (($x17050 (not (and c_23_8 (not in_target_23)))))
 (let (($x17045 (not (and c_22_8 (not in_target_22)))))
 (let (($x17040 (not (and c_21_8 (not in_target_21)))))
 (let (($x17035 (not (and c_20_8 (not in_target_20)))))
 (let (($x17030 (not (and c_19_8 (not in_target_19)))))
 (let (($x17025 (not (and c_18_8 (not in_target_18)))))
 (let (($x17020 (not (and c_17_8 (not in_target_17)))))
 (let (($x17015 (not (and c_16_8 (not in_target_16)))))
 (let (($x17010 (not (and c_15_8 (not in_target_15)))))
 (let (($x17005 (not (and c_14_8 (not in_target_14)))))
 (let (($x17000 (not (and c_13_8 (not in_target_13)))))
 (let (($x16995 (not (and c_12_8 (not in_target_12)))))
 (let (($x16990 (not (and c_11_8 (not in_target_11)))))
 (let (($x16985 (not (and c_10_8 (not in_target_10)))))
 (let (($x16980 (not (and c_9_8 (not in_target_9)))))
 (let (($x16975 (not (and c_8_8 (not in_target_8)))))
 (let (($x16970 (not (and c_7_8 (not in_target_7)))))
 (let (($x16965 (not (and c_6_8 (not in_target_6)))))
 (let (($x16960 (not (and c_5_8 (not in_target_5)))))
 (let (($x16955 (not (and c_4_8 (not in_target_4)))))
 (let (($x16950 (not (and c_3_8 (not in_target_3)))))
 (let (($x16945 (not (and c_2_8 (not in_target_2)))))
 (let (($x16940 (not (and c_1_8 (not in_target_1)))))
 (let (($x16935 (not (and c_0_8 (not in_target_0)))))
 (let (($x16930 (or in_region_90 (and c_90_0 (not in_target_90)))))
 (let (($x16925 (or in_region_89 (and c_89_0 (not in_target_89)))))
 (let (($x16920 (or in_region_88 (and c_88_0 (not in_target_88)))))
 (let (($x16915 (or in_region_87 (and c_87_0 (not in_target_87)))))
 (let (($x16910 (or in_region_86 (and c_86_0 (not in_target_86)))))
 (let (($x16905 (or in_region_85 (and c_85_0 (not in_target_85)))))
 (let (($x16900 (or in_region_84 (and c_84_0 (not in_target_84)))))
 (let (($x16895 (or in_region_83 (and c_83_0 (not in_target_83)))))
 (let (($x16890 (or in_region_82 (and c_82_0 (not in_target_82)))))
 (let (($x16885 (or in_region_81 (and c_81_0 (not in_target_81)))))
 (let (($x16880 (or in_region_80 (and c_80_0 (not in_target_80)))))
 (let (($x16875 (or in_region_79 (and c_79_0 (not in_target_79)))))
 (let (($x16870 (or in_region_78 (and c_78_0 (not in_target_78)))))
 (let (($x16865 (or in_region_77 (and c_77_0 (not in_target_77)))))
 (let (($x16860 (or in_region_76 (and c_76_0 (not in_target_76)))))
 (let (($x16855 (or in_region_75 (and c_75_0 (not in_target_75)))))
 (let (($x16850 (or in_region_74 (and c_74_0 (not in_target_74)))))
 (let (($x16845 (or in_region_73 (and c_73_0 (not in_target_73)))))
 (let (($x16840 (or in_region_72 (and c_72_0 (not in_target_72)))))
 (let (($x16835 (or in_region_71 (and c_71_0 (not in_target_71)))))
 (let (($x16830 (or in_region_70 (and c_70_0 (not in_target_70)))))
 (let (($x16825 (or in_region_69 (and c_69_0 (not in_target_69)))))
 (let (($x16820 (or in_region_68 (and c_68_0 (not in_target_68)))))
 (let (($x16815 (or in_region_67 (and c_67_0 (not in_target_67)))))
 (let (($x16810 (or in_region_66 (and c_66_0 (not in_target_66)))))
 (let (($x16805 (or in_region_65 (and c_65_0 (not in_target_65)))))
 (let (($x16800 (or in_region_64 (and c_64_0 (not in_target_64)))))
 (let (($x16795 (or in_region_63 (and c_63_0 (not in_target_63)))))
 (let (($x16790 (or in_region_62 (and c_62_0 (not in_target_62)))))
 (let (($x16785 (or in_region_61 (and c_61_0 (not in_target_61)))))
 (let (($x16780 (or in_region_60 (and c_60_0 (not in_target_60)))))
 (let (($x16775 (or in_region_59 (and c_59_0 (not in_target_59)))))
 (let (($x16770 (or in_region_58 (and c_58_0 (not in_target_58)))))
 (let (($x16765 (or in_region_57 (and c_57_0 (not in_target_57)))))
 (let (($x16760 (or in_region_56 (and c_56_0 (not in_target_56)))))
 (let (($x16755 (or in_region_55 (and c_55_0 (not in_target_55)))))
 (let (($x16750 (or in_region_54 (and c_54_0 (not in_target_54)))))
 (let (($x16745 (or in_region_53 (and c_53_0 (not in_target_53)))))
 (let (($x16740 (or in_region_52 (and c_52_0 (not in_target_52)))))
 (let (($x16735 (or in_region_51 (and c_51_0 (not in_target_51)))))
 (let (($x16730 (or in_region_50 (and c_50_0 (not in_target_50)))))
 (let (($x16725 (or in_region_49 (and c_49_0 (not in_target_49)))))
 (let (($x16720 (or in_region_48 (and c_48_0 (not in_target_48)))))
 (let (($x16715 (or in_region_47 (and c_47_0 (not in_target_47)))))
 (let (($x16710 (or in_region_46 (and c_46_0 (not in_target_46)))))
 (let (($x16705 (or in_region_45 (and c_45_0 (not in_target_45)))))
 (let (($x16700 (or in_region_44 (and c_44_0 (not in_target_44)))))
 (let (($x16695 (or in_region_43 (and c_43_0 (not in_target_43)))))
 (let (($x16690 (or in_region_42 (and c_42_0 (not in_target_42)))))
 (let (($x16685 (or in_region_41 (and c_41_0 (not in_target_41)))))
 (let (($x16680 (or in_region_40 (and c_40_0 (not in_target_40)))))
 (let (($x16675 (or in_region_39 (and c_39_0 (not in_target_39)))))
 (let (($x16670 (or in_region_38 (and c_38_0 (not in_target_38)))))
 (let (($x16665 (or in_region_37 (and c_37_0 (not in_target_37)))))
 (let (($x16660 (or in_region_36 (and c_36_0 (not in_target_36)))))
 (let (($x16655 (or in_region_35 (and c_35_0 (not in_target_35)))))
 (let (($x16650 (or in_region_34 (and c_34_0 (not in_target_34)))))
 (let (($x16645 (or in_region_33 (and c_33_0 (not in_target_33)))))
 (let (($x16640 (or in_region_32 (and c_32_0 (not in_target_32)))))
 (let (($x16635 (or in_region_31 (and c_31_0 (not in_target_31)))))
 (let (($x16630 (or in_region_30 (and c_30_0 (not in_target_30)))))
 (let (($x16625 (or in_region_29 (and c_29_0 (not in_target_29)))))
 (let (($x16620 (or in_region_28 (and c_28_0 (not in_target_28)))))
 (let (($x16615 (or in_region_27 (and c_27_0 (not in_target_27)))))
 (let (($x16610 (or in_region_26 (and c_26_0 (not in_target_26)))))
 (let (($x16605 (or in_region_25 (and c_25_0 (not in_target_25)))))
 (let (($x16600 (or in_region_24 (and c_24_0 (not in_target_24)))))
 (let (($x16595 (or in_region_23 (and c_23_0 (not in_target_23)))))
 (let (($x16590 (or in_region_22 (and c_22_0 (not in_target_22)))))
 (let (($x16585 (or in_region_21 (and c_21_0 (not in_target_21)))))
 (let (($x16580 (or in_region_20 (and c_20_0 (not in_target_20)))))
 (let (($x16575 (or in_region_19 (and c_19_0 (not in_target_19)))))
 (let (($x16570 (or in_region_18 (and c_18_0 (not in_target_18)))))
 (let (($x16565 (or in_region_17 (and c_17_0 (not in_target_17)))))
 (let (($x16560 (or in_region_16 (and c_16_0 (not in_target_16)))))
 (let (($x16555 (or in_region_15 (and c_15_0 (not in_target_15)))))
 (let (($x16550 (or in_region_14 (and c_14_0 (not in_target_14)))))
 (let (($x16545 (or in_region_13 (and c_13_0 (not in_target_13)))))
 (let (($x16540 (or in_region_12 (and c_12_0 (not in_target_12)))))
 (let (($x16535 (or in_region_11 (and c_11_0 (not in_target_11)))))
 (let (($x16530 (or in_region_10 (and c_10_0 (not in_target_10)))))
 (let (($x16525 (or in_region_9 (and c_9_0 (not in_target_9)))))
 (let (($x16520 (or in_region_8 (and c_8_0 (not in_target_8)))))
 (let (($x16515 (or in_region_7 (and c_7_0 (not in_target_7)))))
 (let (($x16508 (not in_target_6)))
 (let (($x16509 (and c_6_0 $x16508)))
 (let (($x16510 (or in_region_6 $x16509)))
 (let (($x16503 (not in_target_5)))
 (let (($x16504 (and c_5_0 $x16503)))
 (let (($x16505 (or in_region_5 $x16504)))
 (let (($x16498 (not in_target_4)))
 (let (($x16499 (and c_4_0 $x16498)))
 (let (($x16500 (or in_region_4 $x16499)))
 (let (($x16493 (not in_target_3)))
 (let (($x16494 (and c_3_0 $x16493)))
 (let (($x16495 (or in_region_3 $x16494)))
 (let (($x16488 (not in_target_2)))
 (let (($x16489 (and c_2_0 $x16488)))
 (let (($x16490 (or in_region_2 $x16489)))
 (let (($x16483 (not in_target_1)))
 (let (($x16484 (and c_1_0 $x16483)))
 (let (($x16485 (or in_region_1 $x16484)))
 (let (($x16478 (not in_target_0)))
 (let (($x16479 (and c_0_0 $x16478)))
 (let (($x16480 (or in_region_0 $x16479)))
 (let (($x16481 (and true $x16480)))
 (let (($x16486 (and $x16481 $x16485)))
 (let (($x16491 (and $x16486 $x16490)))
 (let (($x16496 (and $x16491 $x16495)))
 (let (($x16501 (and $x16496 $x16500)))
 (let (($x16506 (and $x16501 $x16505)))
 (let (($x16511 (and $x16506 $x16510)))
 (let (($x16516 (and $x16511 $x16515)))
 (let (($x16521 (and $x16516 $x16520)))
 (let (($x16526 (and $x16521 $x16525)))
 (let (($x16531 (and $x16526 $x16530)))
 (let (($x16536 (and $x16531 $x16535)))
 (let (($x16541 (and $x16536 $x16540)))
 (let (($x16546 (and $x16541 $x16545)))
 (let (($x16551 (and $x16546 $x16550)))
 (let (($x16556 (and $x16551 $x16555)))
 (let (($x16561 (and $x16556 $x16560)))
 (let (($x16566 (and $x16561 $x16565)))
 (let (($x16571 (and $x16566 $x16570)))
 (let (($x16576 (and $x16571 $x16575)))
 (let (($x16581 (and $x16576 $x16580)))
 (let (($x16586 (and $x16581 $x16585)))
 (let (($x16591 (and $x16586 $x16590)))
 (let (($x16596 (and $x16591 $x16595)))
 (let (($x16601 (and $x16596 $x16600)))
 (let (($x16606 (and $x16601 $x16605)))
 (let (($x16611 (and $x16606 $x16610)))
 (let (($x16616 (and $x16611 $x16615)))
 (let (($x16621 (and $x16616 $x16620)))
 (let (($x16626 (and $x16621 $x16625)))
 (let (($x16631 (and $x16626 $x16630)))
 (let (($x16636 (and $x16631 $x16635)))
 (let (($x16641 (and $x16636 $x16640)))
 (let (($x16646 (and $x16641 $x16645)))
 (let (($x16651 (and $x16646 $x16650)))
 (let (($x16656 (and $x16651 $x16655)))
 (let (($x16661 (and $x16656 $x16660)))
 (let (($x16666 (and $x16661 $x16665)))
 (let (($x16671 (and $x16666 $x16670)))
 (let (($x16676 (and $x16671 $x16675)))
 (let (($x16681 (and $x16676 $x16680)))
 (let (($x16686 (and $x16681 $x16685)))
 (let (($x16691 (and $x16686 $x16690)))
 (let (($x16696 (and $x16691 $x16695)))
 (let (($x16701 (and $x16696 $x16700)))
 (let (($x16706 (and $x16701 $x16705)))
 (let (($x16711 (and $x16706 $x16710)))
 (let (($x16716 (and $x16711 $x16715)))
 (let (($x16721 (and $x16716 $x16720)))
 (let (($x16726 (and $x16721 $x16725)))
 (let (($x16731 (and $x16726 $x16730)))
 (let (($x16736 (and $x16731 $x16735)))
 (let (($x16741 (and $x16736 $x16740)))
 (let (($x16746 (and $x16741 $x16745)))
 (let (($x16751 (and $x16746 $x16750)))
 (let (($x16756 (and $x16751 $x16755)))
 (let (($x16761 (and $x16756 $x16760)))
 (let (($x16766 (and $x16761 $x16765)))
 (let (($x16771 (and $x16766 $x16770)))
 (let (($x16776 (and $x16771 $x16775)))
 (let (($x16781 (and $x16776 $x16780)))
 (let (($x16786 (and $x16781 $x16785)))
 (let (($x16791 (and $x16786 $x16790)))
 (let (($x16796 (and $x16791 $x16795)))
 (let (($x16801 (and $x16796 $x16800)))
 (let (($x16806 (and $x16801 $x16805)))
 (let (($x16811 (and $x16806 $x16810)))
 (let (($x16816 (and $x16811 $x16815)))
 (let (($x16821 (and $x16816 $x16820)))
 (let (($x16826 (and $x16821 $x16825)))
 (let (($x16831 (and $x16826 $x16830)))
 (let (($x16836 (and $x16831 $x16835)))
 (let (($x16841 (and $x16836 $x16840)))
 (let (($x16846 (and $x16841 $x16845)))
 (let (($x16851 (and $x16846 $x16850)))
 (let (($x16856 (and $x16851 $x16855)))
 (let (($x16861 (and $x16856 $x16860)))
 (let (($x16866 (and $x16861 $x16865)))
 (let (($x16871 (and $x16866 $x16870)))
 (let (($x16876 (and $x16871 $x16875)))
 (let (($x16881 (and $x16876 $x16880)))
 (let (($x16886 (and $x16881 $x16885)))
 (let (($x16891 (and $x16886 $x16890)))
 (let (($x16896 (and $x16891 $x16895)))
 (let (($x16901 (and $x16896 $x16900)))
 (let (($x16906 (and $x16901 $x16905)))
 (let (($x16911 (and $x16906 $x16910)))
 (let (($x16916 (and $x16911 $x16915)))
 (let (($x16921 (and $x16916 $x16920)))
 (let (($x16926 (and $x16921 $x16925)))
 (let (($x16931 (and $x16926 $x16930)))
 (let (($x16932 (and $x16931 in_region_0)))
 (let (($x16936 (and $x16932 $x16935)))
 (let (($x16941 (and $x16936 $x16940)))
 (let (($x16946 (and $x16941 $x16945)))
 (let (($x16951 (and $x16946 $x16950)))
 (let (($x16956 (and $x16951 $x16955)))
 (let (($x16961 (and $x16956 $x16960)))
 (let (($x16966 (and $x16961 $x16965)))
 (let (($x16971 (and $x16966 $x16970)))
 (let (($x16976 (and $x16971 $x16975)))
 (let (($x16981 (and $x16976 $x16980)))
 (let (($x16986 (and $x16981 $x16985)))
 (let (($x16991 (and $x16986 $x16990)))
 (let (($x16996 (and $x16991 $x16995)))
 (let (($x17001 (and $x16996 $x17000)))
 (let (($x17006 (and $x17001 $x17005)))
 (let (($x17011 (and $x17006 $x17010)))
 (let (($x17016 (and $x17011 $x17015)))
 (let (($x17021 (and $x17016 $x17020)))
 (let (($x17026 (and $x17021 $x17025)))
 (let (($x17031 (and $x17026 $x17030)))
 (let (($x17036 (and $x17031 $x17035)))
 (let (($x17041 (and $x17036 $x17040)))
 (let (($x17046 (and $x17041 $x17045)))
 (let (($x17051 (and $x17046 $x17050)))
 (let (($x17056 (and $x17051 $x17055)))
 (let (($x17061 (and $x17056 $x17060)))
 (let (($x17066 (and $x17061 $x17065)))
 (let (($x17071 (and $x17066 $x17070)))
 (let (($x17076 (and $x17071 $x17075)))
 (let (($x17081 (and $x17076 $x17080)))
 (let (($x17086 (and $x17081 $x17085)))
 (let (($x17091 (and $x17086 $x17090)))
 (let (($x17096 (and $x17091 $x17095)))
 (let (($x17101 (and $x17096 $x17100)))
 (let (($x17106 (and $x17101 $x17105)))
 (let (($x17111 (and $x17106 $x17110)))
 (let (($x17116 (and $x17111 $x17115)))
 (let (($x17121 (and $x17116 $x17120)))
 (let (($x17126 (and $x17121 $x17125)))
 (let (($x17131 (and $x17126 $x17130)))
 (let (($x17136 (and $x17131 $x17135)))
 (let (($x17141 (and $x17136 $x17140)))
 (let (($x17146 (and $x17141 $x17145)))
 (let (($x17151 (and $x17146 $x17150)))
 (let (($x17156 (and $x17151 $x17155)))
 (let (($x17161 (and $x17156 $x17160)))
 (let (($x17166 (and $x17161 $x17165)))
 (let (($x17171 (and $x17166 $x17170)))
 (let (($x17176 (and $x17171 $x17175)))
 (let (($x17181 (and $x17176 $x17180)))
 (let (($x17186 (and $x17181 $x17185)))
 (let (($x17191 (and $x17186 $x17190)))
 (let (($x17196 (and $x17191 $x17195)))
 (let (($x17201 (and $x17196 $x17200)))
 (let (($x17206 (and $x17201 $x17205)))
 (let (($x17211 (and $x17206 $x17210)))
 (let (($x17216 (and $x17211 $x17215)))
 (let (($x17221 (and $x17216 $x17220)))
 (let (($x17226 (and $x17221 $x17225)))
 (let (($x17231 (and $x17226 $x17230)))
 (let (($x17236 (and $x17231 $x17235)))
 (let (($x17333 (and $x17236 (=> $x17338 (or $x17306 (and c_0_7 (or $x17324 c_6_8)))))))
 (let (($x17384 (and $x17333 (=> $x17254 (or $x17369 (and c_1_7 (or $x17386 c_9_8)))))))
 (let (($x17425 (and $x17384 (=> $x17268 (or $x17416 (and c_2_7 (or $x17254 c_1_8)))))))
 (let (($x17459 (and $x17425 (=> $x17282 (or $x17455 (and c_3_7 (or $x17338 c_0_8)))))))
 (let (($x17500 (and $x17459 (=> $x17296 (or $x17494 (and c_4_7 (or $x17310 c_5_8)))))))
 (let (($x17534 (and $x17500 (=> $x17310 (or $x17521 (and c_5_7 (or $x17538 c_17_8)))))))
 (let (($x17562 (and $x17534 (=> $x17324 (or $x17548 (and c_6_7 (or $x17564 c_18_8)))))))
 (let (($x17611 (and $x17562 (=> $x17351 (or $x17599 (and c_7_7 $x17608))))))
 (let (($x17641 (and $x17611 (=> $x17365 (or $x17629 (and c_8_7 (or $x17351 c_7_8)))))))
 (let (($x17665 (and $x17641 (=> $x17386 (or $x17646 (and c_9_7 $x17660))))))
 (let (($x17705 (and $x17665 (=> $x17404 (or $x17697 (and c_10_7 (or $x17365 c_8_8)))))))
 (let (($x17727 (and $x17705 (=> $x17418 (or $x17725 (and c_11_7 (or $x17268 c_2_8)))))))
 (let (($x17765 (and $x17727 (=> $x17444 (or $x17760 (and c_12_7 (or $x17282 c_3_8)))))))
 (let (($x17793 (and $x17765 (=> $x17458 (or $x17788 (and c_13_7 (or $x17296 c_4_8)))))))
 (let (($x17833 (and $x17793 (=> $x17484 (or $x17827 (and c_14_7 (or $x17498 c_15_8)))))))
 (let (($x17858 (and $x17833 (=> $x17498 (or $x17853 (and c_15_7 (or $x17524 c_16_8)))))))
 (let (($x17893 (and $x17858 (=> $x17524 (or $x17879 (and c_16_7 $x17890))))))
 (let (($x17920 (and $x17893 (=> $x17538 (or $x17906 (and c_17_7 $x17916))))))
 (let (($x17946 (and $x17920 (=> $x17564 (or $x17928 (and c_18_7 $x17942))))))
 (let (($x17994 (and $x17946 (=> $x17580 (or $x17983 (and c_19_7 $x17992))))))
 (let (($x18019 (and $x17994 (=> $x17594 (or $x18021 (and c_20_7 $x17574))))))
 (let (($x18049 (and $x18019 (=> $x17614 (or $x18031 (and c_21_7 $x18044))))))
 (let (($x18070 (and $x18049 (=> $x17632 (or $x18071 (and c_22_7 $x17588))))))
 (let (($x18098 (and $x18070 (=> $x17666 (or $x18085 (and c_23_7 $x18096))))))
 (let (($x18140 (and $x18098 (=> $x17684 (or $x18132 (and c_24_7 $x17626))))))
 (let (($x18164 (and $x18140 (=> $x17698 (or $x18157 (and c_25_7 (or $x17404 c_10_8)))))))
 (let (($x18187 (and $x18164 (=> $x17724 (or $x18185 (and c_26_7 (or $x17418 c_11_8)))))))
 (let (($x18227 (and $x18187 (=> $x17750 (or $x18225 (and c_27_7 (or $x17444 c_12_8)))))))
 (let (($x18256 (and $x18227 (=> $x17764 (or $x18248 (and c_28_7 (or $x17458 c_13_8)))))))
 (let (($x18279 (and $x18256 (=> $x17790 (or $x18277 (and c_29_7 (or $x17484 c_14_8)))))))
 (let (($x18320 (and $x18279 (=> $x17816 (or $x18317 (and c_30_7 $x17824))))))
 (let (($x18347 (and $x18320 (=> $x17830 (or $x18340 (and c_31_7 $x17850))))))
 (let (($x18372 (and $x18347 (=> $x17856 (or $x18366 (and c_32_7 $x17876))))))
 (let (($x18409 (and $x18372 (=> $x17882 (or $x18392 (and c_33_7 $x18404))))))
 (let (($x18435 (and $x18409 (=> $x17896 (or $x18420 (and c_34_7 $x18430))))))
 (let (($x18459 (and $x18435 (=> $x17922 (or $x18446 (and c_35_7 $x18456))))))
 (let (($x18485 (and $x18459 (=> $x17948 (or $x18471 (and c_36_7 (or $x18488 c_60_8)))))))
 (let (($x18537 (and $x18485 (=> $x17964 (or $x18521 (and c_37_7 $x18532))))))
 (let (($x18563 (and $x18537 (=> $x17978 (or $x18559 (and c_38_7 $x17958))))))
 (let (($x18587 (and $x18563 (=> $x17998 (or $x18575 (and c_39_7 $x18584))))))
 (let (($x18607 (and $x18587 (=> $x18016 (or $x18612 (and c_40_7 $x17972))))))
 (let (($x18638 (and $x18607 (=> $x18050 (or $x18626 (and c_41_7 $x18636))))))
 (let (($x18667 (and $x18638 (=> $x18068 (or $x18662 (and c_42_7 $x18010))))))
 (let (($x18690 (and $x18667 (=> $x18102 (or $x18671 (and c_43_7 $x18688))))))
 (let (($x18731 (and $x18690 (=> $x18120 (or $x18727 (and c_44_7 $x18062))))))
 (let (($x18757 (and $x18731 (=> $x18134 (or $x18755 (and c_45_7 $x17678))))))
 (let (($x18781 (and $x18757 (=> $x18160 (or $x18779 (and c_46_7 $x17692))))))
 (let (($x18801 (and $x18781 (=> $x18186 (or $x18807 (and c_47_7 $x17718))))))
 (let (($x18847 (and $x18801 (=> $x18212 (or $x18840 (and c_48_7 $x17744))))))
 (let (($x18874 (and $x18847 (=> $x18226 (or $x18868 (and c_49_7 $x17758))))))
 (let (($x18898 (and $x18874 (=> $x18252 (or $x18894 (and c_50_7 $x17784))))))
 (let (($x18927 (and $x18898 (=> $x18278 (or $x18921 (and c_51_7 $x17810))))))
 (let (($x18964 (and $x18927 (=> $x18304 (or $x18960 (and c_52_7 $x18312))))))
 (let (($x18990 (and $x18964 (=> $x18318 (or $x18986 (and c_53_7 $x18338))))))
 (let (($x19015 (and $x18990 (=> $x18344 (or $x19012 (and c_54_7 $x18364))))))
 (let (($x19042 (and $x19015 (=> $x18370 (or $x19036 (and c_55_7 $x18390))))))
 (let (($x19078 (and $x19042 (=> $x18396 (or $x19062 (and c_56_7 $x19074))))))
 (let (($x19102 (and $x19078 (=> $x18410 (or $x19090 (and c_57_7 $x19100))))))
 (let (($x19130 (and $x19102 (=> $x18436 (or $x19112 (and c_58_7 $x19126))))))
 (let (($x19157 (and $x19130 (=> $x18462 (or $x19141 (and c_59_7 $x19152))))))
 (let (($x19181 (and $x19157 (=> $x18488 (or $x19169 (and c_60_7 $x19178))))))
 (let (($x19352 (and $x19181 (and (=> (and c_0_1 $x19348) (= ghost_1_0 0)) (=> $x19346 $x19344)))))
 (let (($x19408 (and $x19352 (and (=> (and c_1_1 $x19283) (= ghost_1_1 0)) (=> $x19279 $x19405)))))
 (let (($x19457 (and $x19408 (and (=> (and c_2_1 $x19296) (= ghost_1_2 0)) (=> $x19292 $x19452)))))
 (let (($x19508 (and $x19457 (and (=> (and c_3_1 $x19306) (= ghost_1_3 0)) (=> $x19302 $x19502)))))
 (let (($x19558 (and $x19508 (and (=> (and c_4_1 $x19316) (= ghost_1_4 0)) (=> $x19312 $x19552)))))
 (let (($x19609 (and $x19558 (and (=> (and c_5_1 $x19326) (= ghost_1_5 0)) (=> $x19324 $x19604)))))
 (let (($x19653 (and $x19609 (and (=> (and c_6_1 $x19336) (= ghost_1_6 0)) (=> $x19333 $x19648)))))
 (let (($x19708 (and $x19653 (and (=> (and c_7_1 $x19360) (= ghost_1_7 0)) (=> $x19357 $x19705)))))
 (let (($x19752 (and $x19708 (and (=> (and c_8_1 $x19372) (= ghost_1_8 0)) (=> $x19371 $x19750)))))
 (let (($x19796 (and $x19752 (and (=> (and c_9_1 $x19397) (= ghost_1_9 0)) (=> $x19396 $x19795)))))
 (let (($x19848 (and $x19796 (and (=> (and c_10_1 $x19422) (= ghost_1_10 0)) (=> $x19419 $x19843)))))
 (let (($x19894 (and $x19848 (and (=> (and c_11_1 $x19432) (= ghost_1_11 0)) (=> $x19428 $x19887)))))
 (let (($x19943 (and $x19894 (and (=> (and c_12_1 $x19477) (= ghost_1_12 0)) (=> $x19474 $x19938)))))
 (let (($x19989 (and $x19943 (and (=> (and c_13_1 $x19487) (= ghost_1_13 0)) (=> $x19485 $x19984)))))
 (let (($x20038 (and $x19989 $x20032)))
 (let (($x20081 (and $x20038 $x20079)))
 (let (($x20132 (and $x20081 $x20130)))
 (let (($x20178 (and $x20132 $x20175)))
 (let (($x20221 (and $x20178 $x20220)))
 (let (($x20278 (and $x20221 $x20272)))
 (let (($x20323 (and $x20278 $x20318)))
 (let (($x20368 (and $x20323 $x20362)))
 (let (($x20411 (and $x20368 $x20408)))
 (let (($x20456 (and $x20411 $x20453)))
 (let (($x20506 (and $x20456 $x20505)))
 (let (($x20553 (and $x20506 $x20550)))
 (let (($x20598 (and $x20553 $x20595)))
 (let (($x20648 (and $x20598 $x20645)))
 (let (($x20694 (and $x20648 $x20688)))
 (let (($x20736 (and $x20694 $x20735)))
 (let (($x20789 (and $x20736 $x20783)))
 (let (($x20832 (and $x20789 $x20830)))
 (let (($x20877 (and $x20832 $x20874)))
 (let (($x20928 (and $x20877 $x20922)))
 (let (($x20974 (and $x20928 $x20967)))
 (let (($x21017 (and $x20974 $x21014)))
 (let (($x21063 (and $x21017 $x21057)))
 (let (($x21119 (and $x21063 $x21112)))
 (let (($x21163 (and $x21119 $x21160)))
 (let (($x21209 (and $x21163 $x21202)))
 (let (($x21252 (and $x21209 $x21249)))
 (let (($x21298 (and $x21252 $x21293)))
 (let (($x21343 (and $x21298 $x21337)))
 (let (($x21389 (and $x21343 $x21384)))
 (let (($x21439 (and $x21389 $x21434)))
 (let (($x21484 (and $x21439 $x21479)))
 (let (($x21526 (and $x21484 $x21523)))
 (let (($x21573 (and $x21526 $x21570)))
 (let (($x21623 (and $x21573 $x21617)))
 (let (($x21666 (and $x21623 $x21663)))
 (let (($x21712 (and $x21666 $x21710)))
 (let (($x21757 (and $x21712 $x21754)))
 (let (($x21808 (and $x21757 $x21802)))
 (let (($x21854 (and $x21808 $x21847)))
 (let (($x21896 (and $x21854 $x21893)))
 (let (($x21941 (and $x21896 $x21939)))
 (let (($x21994 (and $x21941 $x21989)))
 (let (($x22038 (and $x21994 $x22032)))
 (let (($x22083 (and $x22038 $x22077)))
 (let (($x22129 (and $x22083 $x22123)))
 (let (($x29076 (and (and $x22129 $x22167) $x29075)))
 (=> instance_0 $x29076)))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(assert
 (or instance_0))
(check-sat)
