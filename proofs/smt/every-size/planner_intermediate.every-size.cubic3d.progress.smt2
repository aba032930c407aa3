; holon proof obligation for every region: system planner_intermediate, lattice cubic3d, property progress
; window: every rule shape with its first cell at the origin, and every point within 3 steps of its pattern, free (129 cells; proofs/README.md)
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
(declare-fun c_91_8 () Bool)
(declare-fun c_91_7 () Bool)
(declare-fun c_91_6 () Bool)
(declare-fun c_91_5 () Bool)
(declare-fun c_91_4 () Bool)
(declare-fun c_91_3 () Bool)
(declare-fun c_91_2 () Bool)
(declare-fun c_91_1 () Bool)
(declare-fun c_91_0 () Bool)
(declare-fun c_92_8 () Bool)
(declare-fun c_92_7 () Bool)
(declare-fun c_92_6 () Bool)
(declare-fun c_92_5 () Bool)
(declare-fun c_92_4 () Bool)
(declare-fun c_92_3 () Bool)
(declare-fun c_92_2 () Bool)
(declare-fun c_92_1 () Bool)
(declare-fun c_92_0 () Bool)
(declare-fun c_93_8 () Bool)
(declare-fun c_93_7 () Bool)
(declare-fun c_93_6 () Bool)
(declare-fun c_93_5 () Bool)
(declare-fun c_93_4 () Bool)
(declare-fun c_93_3 () Bool)
(declare-fun c_93_2 () Bool)
(declare-fun c_93_1 () Bool)
(declare-fun c_93_0 () Bool)
(declare-fun c_94_8 () Bool)
(declare-fun c_94_7 () Bool)
(declare-fun c_94_6 () Bool)
(declare-fun c_94_5 () Bool)
(declare-fun c_94_4 () Bool)
(declare-fun c_94_3 () Bool)
(declare-fun c_94_2 () Bool)
(declare-fun c_94_1 () Bool)
(declare-fun c_94_0 () Bool)
(declare-fun c_95_8 () Bool)
(declare-fun c_95_7 () Bool)
(declare-fun c_95_6 () Bool)
(declare-fun c_95_5 () Bool)
(declare-fun c_95_4 () Bool)
(declare-fun c_95_3 () Bool)
(declare-fun c_95_2 () Bool)
(declare-fun c_95_1 () Bool)
(declare-fun c_95_0 () Bool)
(declare-fun c_96_8 () Bool)
(declare-fun c_96_7 () Bool)
(declare-fun c_96_6 () Bool)
(declare-fun c_96_5 () Bool)
(declare-fun c_96_4 () Bool)
(declare-fun c_96_3 () Bool)
(declare-fun c_96_2 () Bool)
(declare-fun c_96_1 () Bool)
(declare-fun c_96_0 () Bool)
(declare-fun c_97_8 () Bool)
(declare-fun c_97_7 () Bool)
(declare-fun c_97_6 () Bool)
(declare-fun c_97_5 () Bool)
(declare-fun c_97_4 () Bool)
(declare-fun c_97_3 () Bool)
(declare-fun c_97_2 () Bool)
(declare-fun c_97_1 () Bool)
(declare-fun c_97_0 () Bool)
(declare-fun c_98_8 () Bool)
(declare-fun c_98_7 () Bool)
(declare-fun c_98_6 () Bool)
(declare-fun c_98_5 () Bool)
(declare-fun c_98_4 () Bool)
(declare-fun c_98_3 () Bool)
(declare-fun c_98_2 () Bool)
(declare-fun c_98_1 () Bool)
(declare-fun c_98_0 () Bool)
(declare-fun c_99_8 () Bool)
(declare-fun c_99_7 () Bool)
(declare-fun c_99_6 () Bool)
(declare-fun c_99_5 () Bool)
(declare-fun c_99_4 () Bool)
(declare-fun c_99_3 () Bool)
(declare-fun c_99_2 () Bool)
(declare-fun c_99_1 () Bool)
(declare-fun c_99_0 () Bool)
(declare-fun c_100_8 () Bool)
(declare-fun c_100_7 () Bool)
(declare-fun c_100_6 () Bool)
(declare-fun c_100_5 () Bool)
(declare-fun c_100_4 () Bool)
(declare-fun c_100_3 () Bool)
(declare-fun c_100_2 () Bool)
(declare-fun c_100_1 () Bool)
(declare-fun c_100_0 () Bool)
(declare-fun c_101_8 () Bool)
(declare-fun c_101_7 () Bool)
(declare-fun c_101_6 () Bool)
(declare-fun c_101_5 () Bool)
(declare-fun c_101_4 () Bool)
(declare-fun c_101_3 () Bool)
(declare-fun c_101_2 () Bool)
(declare-fun c_101_1 () Bool)
(declare-fun c_101_0 () Bool)
(declare-fun c_102_8 () Bool)
(declare-fun c_102_7 () Bool)
(declare-fun c_102_6 () Bool)
(declare-fun c_102_5 () Bool)
(declare-fun c_102_4 () Bool)
(declare-fun c_102_3 () Bool)
(declare-fun c_102_2 () Bool)
(declare-fun c_102_1 () Bool)
(declare-fun c_102_0 () Bool)
(declare-fun c_103_8 () Bool)
(declare-fun c_103_7 () Bool)
(declare-fun c_103_6 () Bool)
(declare-fun c_103_5 () Bool)
(declare-fun c_103_4 () Bool)
(declare-fun c_103_3 () Bool)
(declare-fun c_103_2 () Bool)
(declare-fun c_103_1 () Bool)
(declare-fun c_103_0 () Bool)
(declare-fun c_104_8 () Bool)
(declare-fun c_104_7 () Bool)
(declare-fun c_104_6 () Bool)
(declare-fun c_104_5 () Bool)
(declare-fun c_104_4 () Bool)
(declare-fun c_104_3 () Bool)
(declare-fun c_104_2 () Bool)
(declare-fun c_104_1 () Bool)
(declare-fun c_104_0 () Bool)
(declare-fun c_105_8 () Bool)
(declare-fun c_105_7 () Bool)
(declare-fun c_105_6 () Bool)
(declare-fun c_105_5 () Bool)
(declare-fun c_105_4 () Bool)
(declare-fun c_105_3 () Bool)
(declare-fun c_105_2 () Bool)
(declare-fun c_105_1 () Bool)
(declare-fun c_105_0 () Bool)
(declare-fun c_106_8 () Bool)
(declare-fun c_106_7 () Bool)
(declare-fun c_106_6 () Bool)
(declare-fun c_106_5 () Bool)
(declare-fun c_106_4 () Bool)
(declare-fun c_106_3 () Bool)
(declare-fun c_106_2 () Bool)
(declare-fun c_106_1 () Bool)
(declare-fun c_106_0 () Bool)
(declare-fun c_107_8 () Bool)
(declare-fun c_107_7 () Bool)
(declare-fun c_107_6 () Bool)
(declare-fun c_107_5 () Bool)
(declare-fun c_107_4 () Bool)
(declare-fun c_107_3 () Bool)
(declare-fun c_107_2 () Bool)
(declare-fun c_107_1 () Bool)
(declare-fun c_107_0 () Bool)
(declare-fun c_108_8 () Bool)
(declare-fun c_108_7 () Bool)
(declare-fun c_108_6 () Bool)
(declare-fun c_108_5 () Bool)
(declare-fun c_108_4 () Bool)
(declare-fun c_108_3 () Bool)
(declare-fun c_108_2 () Bool)
(declare-fun c_108_1 () Bool)
(declare-fun c_108_0 () Bool)
(declare-fun c_109_8 () Bool)
(declare-fun c_109_7 () Bool)
(declare-fun c_109_6 () Bool)
(declare-fun c_109_5 () Bool)
(declare-fun c_109_4 () Bool)
(declare-fun c_109_3 () Bool)
(declare-fun c_109_2 () Bool)
(declare-fun c_109_1 () Bool)
(declare-fun c_109_0 () Bool)
(declare-fun c_110_8 () Bool)
(declare-fun c_110_7 () Bool)
(declare-fun c_110_6 () Bool)
(declare-fun c_110_5 () Bool)
(declare-fun c_110_4 () Bool)
(declare-fun c_110_3 () Bool)
(declare-fun c_110_2 () Bool)
(declare-fun c_110_1 () Bool)
(declare-fun c_110_0 () Bool)
(declare-fun c_111_8 () Bool)
(declare-fun c_111_7 () Bool)
(declare-fun c_111_6 () Bool)
(declare-fun c_111_5 () Bool)
(declare-fun c_111_4 () Bool)
(declare-fun c_111_3 () Bool)
(declare-fun c_111_2 () Bool)
(declare-fun c_111_1 () Bool)
(declare-fun c_111_0 () Bool)
(declare-fun c_112_8 () Bool)
(declare-fun c_112_7 () Bool)
(declare-fun c_112_6 () Bool)
(declare-fun c_112_5 () Bool)
(declare-fun c_112_4 () Bool)
(declare-fun c_112_3 () Bool)
(declare-fun c_112_2 () Bool)
(declare-fun c_112_1 () Bool)
(declare-fun c_112_0 () Bool)
(declare-fun c_113_8 () Bool)
(declare-fun c_113_7 () Bool)
(declare-fun c_113_6 () Bool)
(declare-fun c_113_5 () Bool)
(declare-fun c_113_4 () Bool)
(declare-fun c_113_3 () Bool)
(declare-fun c_113_2 () Bool)
(declare-fun c_113_1 () Bool)
(declare-fun c_113_0 () Bool)
(declare-fun c_114_8 () Bool)
(declare-fun c_114_7 () Bool)
(declare-fun c_114_6 () Bool)
(declare-fun c_114_5 () Bool)
(declare-fun c_114_4 () Bool)
(declare-fun c_114_3 () Bool)
(declare-fun c_114_2 () Bool)
(declare-fun c_114_1 () Bool)
(declare-fun c_114_0 () Bool)
(declare-fun c_115_8 () Bool)
(declare-fun c_115_7 () Bool)
(declare-fun c_115_6 () Bool)
(declare-fun c_115_5 () Bool)
(declare-fun c_115_4 () Bool)
(declare-fun c_115_3 () Bool)
(declare-fun c_115_2 () Bool)
(declare-fun c_115_1 () Bool)
(declare-fun c_115_0 () Bool)
(declare-fun c_116_8 () Bool)
(declare-fun c_116_7 () Bool)
(declare-fun c_116_6 () Bool)
(declare-fun c_116_5 () Bool)
(declare-fun c_116_4 () Bool)
(declare-fun c_116_3 () Bool)
(declare-fun c_116_2 () Bool)
(declare-fun c_116_1 () Bool)
(declare-fun c_116_0 () Bool)
(declare-fun c_117_8 () Bool)
(declare-fun c_117_7 () Bool)
(declare-fun c_117_6 () Bool)
(declare-fun c_117_5 () Bool)
(declare-fun c_117_4 () Bool)
(declare-fun c_117_3 () Bool)
(declare-fun c_117_2 () Bool)
(declare-fun c_117_1 () Bool)
(declare-fun c_117_0 () Bool)
(declare-fun c_118_8 () Bool)
(declare-fun c_118_7 () Bool)
(declare-fun c_118_6 () Bool)
(declare-fun c_118_5 () Bool)
(declare-fun c_118_4 () Bool)
(declare-fun c_118_3 () Bool)
(declare-fun c_118_2 () Bool)
(declare-fun c_118_1 () Bool)
(declare-fun c_118_0 () Bool)
(declare-fun c_119_8 () Bool)
(declare-fun c_119_7 () Bool)
(declare-fun c_119_6 () Bool)
(declare-fun c_119_5 () Bool)
(declare-fun c_119_4 () Bool)
(declare-fun c_119_3 () Bool)
(declare-fun c_119_2 () Bool)
(declare-fun c_119_1 () Bool)
(declare-fun c_119_0 () Bool)
(declare-fun c_120_8 () Bool)
(declare-fun c_120_7 () Bool)
(declare-fun c_120_6 () Bool)
(declare-fun c_120_5 () Bool)
(declare-fun c_120_4 () Bool)
(declare-fun c_120_3 () Bool)
(declare-fun c_120_2 () Bool)
(declare-fun c_120_1 () Bool)
(declare-fun c_120_0 () Bool)
(declare-fun c_121_8 () Bool)
(declare-fun c_121_7 () Bool)
(declare-fun c_121_6 () Bool)
(declare-fun c_121_5 () Bool)
(declare-fun c_121_4 () Bool)
(declare-fun c_121_3 () Bool)
(declare-fun c_121_2 () Bool)
(declare-fun c_121_1 () Bool)
(declare-fun c_121_0 () Bool)
(declare-fun c_122_8 () Bool)
(declare-fun c_122_7 () Bool)
(declare-fun c_122_6 () Bool)
(declare-fun c_122_5 () Bool)
(declare-fun c_122_4 () Bool)
(declare-fun c_122_3 () Bool)
(declare-fun c_122_2 () Bool)
(declare-fun c_122_1 () Bool)
(declare-fun c_122_0 () Bool)
(declare-fun c_123_8 () Bool)
(declare-fun c_123_7 () Bool)
(declare-fun c_123_6 () Bool)
(declare-fun c_123_5 () Bool)
(declare-fun c_123_4 () Bool)
(declare-fun c_123_3 () Bool)
(declare-fun c_123_2 () Bool)
(declare-fun c_123_1 () Bool)
(declare-fun c_123_0 () Bool)
(declare-fun c_124_8 () Bool)
(declare-fun c_124_7 () Bool)
(declare-fun c_124_6 () Bool)
(declare-fun c_124_5 () Bool)
(declare-fun c_124_4 () Bool)
(declare-fun c_124_3 () Bool)
(declare-fun c_124_2 () Bool)
(declare-fun c_124_1 () Bool)
(declare-fun c_124_0 () Bool)
(declare-fun c_125_8 () Bool)
(declare-fun c_125_7 () Bool)
(declare-fun c_125_6 () Bool)
(declare-fun c_125_5 () Bool)
(declare-fun c_125_4 () Bool)
(declare-fun c_125_3 () Bool)
(declare-fun c_125_2 () Bool)
(declare-fun c_125_1 () Bool)
(declare-fun c_125_0 () Bool)
(declare-fun c_126_8 () Bool)
(declare-fun c_126_7 () Bool)
(declare-fun c_126_6 () Bool)
(declare-fun c_126_5 () Bool)
(declare-fun c_126_4 () Bool)
(declare-fun c_126_3 () Bool)
(declare-fun c_126_2 () Bool)
(declare-fun c_126_1 () Bool)
(declare-fun c_126_0 () Bool)
(declare-fun c_127_8 () Bool)
(declare-fun c_127_7 () Bool)
(declare-fun c_127_6 () Bool)
(declare-fun c_127_5 () Bool)
(declare-fun c_127_4 () Bool)
(declare-fun c_127_3 () Bool)
(declare-fun c_127_2 () Bool)
(declare-fun c_127_1 () Bool)
(declare-fun c_127_0 () Bool)
(declare-fun c_128_8 () Bool)
(declare-fun c_128_7 () Bool)
(declare-fun c_128_6 () Bool)
(declare-fun c_128_5 () Bool)
(declare-fun c_128_4 () Bool)
(declare-fun c_128_3 () Bool)
(declare-fun c_128_2 () Bool)
(declare-fun c_128_1 () Bool)
(declare-fun c_128_0 () Bool)
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
(declare-fun d_91_8 () Bool)
(declare-fun d_91_7 () Bool)
(declare-fun d_91_6 () Bool)
(declare-fun d_91_5 () Bool)
(declare-fun d_91_4 () Bool)
(declare-fun d_91_3 () Bool)
(declare-fun d_91_2 () Bool)
(declare-fun d_91_1 () Bool)
(declare-fun d_91_0 () Bool)
(declare-fun d_92_8 () Bool)
(declare-fun d_92_7 () Bool)
(declare-fun d_92_6 () Bool)
(declare-fun d_92_5 () Bool)
(declare-fun d_92_4 () Bool)
(declare-fun d_92_3 () Bool)
(declare-fun d_92_2 () Bool)
(declare-fun d_92_1 () Bool)
(declare-fun d_92_0 () Bool)
(declare-fun d_93_8 () Bool)
(declare-fun d_93_7 () Bool)
(declare-fun d_93_6 () Bool)
(declare-fun d_93_5 () Bool)
(declare-fun d_93_4 () Bool)
(declare-fun d_93_3 () Bool)
(declare-fun d_93_2 () Bool)
(declare-fun d_93_1 () Bool)
(declare-fun d_93_0 () Bool)
(declare-fun d_94_8 () Bool)
(declare-fun d_94_7 () Bool)
(declare-fun d_94_6 () Bool)
(declare-fun d_94_5 () Bool)
(declare-fun d_94_4 () Bool)
(declare-fun d_94_3 () Bool)
(declare-fun d_94_2 () Bool)
(declare-fun d_94_1 () Bool)
(declare-fun d_94_0 () Bool)
(declare-fun d_95_8 () Bool)
(declare-fun d_95_7 () Bool)
(declare-fun d_95_6 () Bool)
(declare-fun d_95_5 () Bool)
(declare-fun d_95_4 () Bool)
(declare-fun d_95_3 () Bool)
(declare-fun d_95_2 () Bool)
(declare-fun d_95_1 () Bool)
(declare-fun d_95_0 () Bool)
(declare-fun d_96_8 () Bool)
(declare-fun d_96_7 () Bool)
(declare-fun d_96_6 () Bool)
(declare-fun d_96_5 () Bool)
(declare-fun d_96_4 () Bool)
(declare-fun d_96_3 () Bool)
(declare-fun d_96_2 () Bool)
(declare-fun d_96_1 () Bool)
(declare-fun d_96_0 () Bool)
(declare-fun d_97_8 () Bool)
(declare-fun d_97_7 () Bool)
(declare-fun d_97_6 () Bool)
(declare-fun d_97_5 () Bool)
(declare-fun d_97_4 () Bool)
(declare-fun d_97_3 () Bool)
(declare-fun d_97_2 () Bool)
(declare-fun d_97_1 () Bool)
(declare-fun d_97_0 () Bool)
(declare-fun d_98_8 () Bool)
(declare-fun d_98_7 () Bool)
(declare-fun d_98_6 () Bool)
(declare-fun d_98_5 () Bool)
(declare-fun d_98_4 () Bool)
(declare-fun d_98_3 () Bool)
(declare-fun d_98_2 () Bool)
(declare-fun d_98_1 () Bool)
(declare-fun d_98_0 () Bool)
(declare-fun d_99_8 () Bool)
(declare-fun d_99_7 () Bool)
(declare-fun d_99_6 () Bool)
(declare-fun d_99_5 () Bool)
(declare-fun d_99_4 () Bool)
(declare-fun d_99_3 () Bool)
(declare-fun d_99_2 () Bool)
(declare-fun d_99_1 () Bool)
(declare-fun d_99_0 () Bool)
(declare-fun d_100_8 () Bool)
(declare-fun d_100_7 () Bool)
(declare-fun d_100_6 () Bool)
(declare-fun d_100_5 () Bool)
(declare-fun d_100_4 () Bool)
(declare-fun d_100_3 () Bool)
(declare-fun d_100_2 () Bool)
(declare-fun d_100_1 () Bool)
(declare-fun d_100_0 () Bool)
(declare-fun d_101_8 () Bool)
(declare-fun d_101_7 () Bool)
(declare-fun d_101_6 () Bool)
(declare-fun d_101_5 () Bool)
(declare-fun d_101_4 () Bool)
(declare-fun d_101_3 () Bool)
(declare-fun d_101_2 () Bool)
(declare-fun d_101_1 () Bool)
(declare-fun d_101_0 () Bool)
(declare-fun d_102_8 () Bool)
(declare-fun d_102_7 () Bool)
(declare-fun d_102_6 () Bool)
(declare-fun d_102_5 () Bool)
(declare-fun d_102_4 () Bool)
(declare-fun d_102_3 () Bool)
(declare-fun d_102_2 () Bool)
(declare-fun d_102_1 () Bool)
(declare-fun d_102_0 () Bool)
(declare-fun d_103_8 () Bool)
(declare-fun d_103_7 () Bool)
(declare-fun d_103_6 () Bool)
(declare-fun d_103_5 () Bool)
(declare-fun d_103_4 () Bool)
(declare-fun d_103_3 () Bool)
(declare-fun d_103_2 () Bool)
(declare-fun d_103_1 () Bool)
(declare-fun d_103_0 () Bool)
(declare-fun d_104_8 () Bool)
(declare-fun d_104_7 () Bool)
(declare-fun d_104_6 () Bool)
(declare-fun d_104_5 () Bool)
(declare-fun d_104_4 () Bool)
(declare-fun d_104_3 () Bool)
(declare-fun d_104_2 () Bool)
(declare-fun d_104_1 () Bool)
(declare-fun d_104_0 () Bool)
(declare-fun d_105_8 () Bool)
(declare-fun d_105_7 () Bool)
(declare-fun d_105_6 () Bool)
(declare-fun d_105_5 () Bool)
(declare-fun d_105_4 () Bool)
(declare-fun d_105_3 () Bool)
(declare-fun d_105_2 () Bool)
(declare-fun d_105_1 () Bool)
(declare-fun d_105_0 () Bool)
(declare-fun d_106_8 () Bool)
(declare-fun d_106_7 () Bool)
(declare-fun d_106_6 () Bool)
(declare-fun d_106_5 () Bool)
(declare-fun d_106_4 () Bool)
(declare-fun d_106_3 () Bool)
(declare-fun d_106_2 () Bool)
(declare-fun d_106_1 () Bool)
(declare-fun d_106_0 () Bool)
(declare-fun d_107_8 () Bool)
(declare-fun d_107_7 () Bool)
(declare-fun d_107_6 () Bool)
(declare-fun d_107_5 () Bool)
(declare-fun d_107_4 () Bool)
(declare-fun d_107_3 () Bool)
(declare-fun d_107_2 () Bool)
(declare-fun d_107_1 () Bool)
(declare-fun d_107_0 () Bool)
(declare-fun d_108_8 () Bool)
(declare-fun d_108_7 () Bool)
(declare-fun d_108_6 () Bool)
(declare-fun d_108_5 () Bool)
(declare-fun d_108_4 () Bool)
(declare-fun d_108_3 () Bool)
(declare-fun d_108_2 () Bool)
(declare-fun d_108_1 () Bool)
(declare-fun d_108_0 () Bool)
(declare-fun d_109_8 () Bool)
(declare-fun d_109_7 () Bool)
(declare-fun d_109_6 () Bool)
(declare-fun d_109_5 () Bool)
(declare-fun d_109_4 () Bool)
(declare-fun d_109_3 () Bool)
(declare-fun d_109_2 () Bool)
(declare-fun d_109_1 () Bool)
(declare-fun d_109_0 () Bool)
(declare-fun d_110_8 () Bool)
(declare-fun d_110_7 () Bool)
(declare-fun d_110_6 () Bool)
(declare-fun d_110_5 () Bool)
(declare-fun d_110_4 () Bool)
(declare-fun d_110_3 () Bool)
(declare-fun d_110_2 () Bool)
(declare-fun d_110_1 () Bool)
(declare-fun d_110_0 () Bool)
(declare-fun d_111_8 () Bool)
(declare-fun d_111_7 () Bool)
(declare-fun d_111_6 () Bool)
(declare-fun d_111_5 () Bool)
(declare-fun d_111_4 () Bool)
(declare-fun d_111_3 () Bool)
(declare-fun d_111_2 () Bool)
(declare-fun d_111_1 () Bool)
(declare-fun d_111_0 () Bool)
(declare-fun d_112_8 () Bool)
(declare-fun d_112_7 () Bool)
(declare-fun d_112_6 () Bool)
(declare-fun d_112_5 () Bool)
(declare-fun d_112_4 () Bool)
(declare-fun d_112_3 () Bool)
(declare-fun d_112_2 () Bool)
(declare-fun d_112_1 () Bool)
(declare-fun d_112_0 () Bool)
(declare-fun d_113_8 () Bool)
(declare-fun d_113_7 () Bool)
(declare-fun d_113_6 () Bool)
(declare-fun d_113_5 () Bool)
(declare-fun d_113_4 () Bool)
(declare-fun d_113_3 () Bool)
(declare-fun d_113_2 () Bool)
(declare-fun d_113_1 () Bool)
(declare-fun d_113_0 () Bool)
(declare-fun d_114_8 () Bool)
(declare-fun d_114_7 () Bool)
(declare-fun d_114_6 () Bool)
(declare-fun d_114_5 () Bool)
(declare-fun d_114_4 () Bool)
(declare-fun d_114_3 () Bool)
(declare-fun d_114_2 () Bool)
(declare-fun d_114_1 () Bool)
(declare-fun d_114_0 () Bool)
(declare-fun d_115_8 () Bool)
(declare-fun d_115_7 () Bool)
(declare-fun d_115_6 () Bool)
(declare-fun d_115_5 () Bool)
(declare-fun d_115_4 () Bool)
(declare-fun d_115_3 () Bool)
(declare-fun d_115_2 () Bool)
(declare-fun d_115_1 () Bool)
(declare-fun d_115_0 () Bool)
(declare-fun d_116_8 () Bool)
(declare-fun d_116_7 () Bool)
(declare-fun d_116_6 () Bool)
(declare-fun d_116_5 () Bool)
(declare-fun d_116_4 () Bool)
(declare-fun d_116_3 () Bool)
(declare-fun d_116_2 () Bool)
(declare-fun d_116_1 () Bool)
(declare-fun d_116_0 () Bool)
(declare-fun d_117_8 () Bool)
(declare-fun d_117_7 () Bool)
(declare-fun d_117_6 () Bool)
(declare-fun d_117_5 () Bool)
(declare-fun d_117_4 () Bool)
(declare-fun d_117_3 () Bool)
(declare-fun d_117_2 () Bool)
(declare-fun d_117_1 () Bool)
(declare-fun d_117_0 () Bool)
(declare-fun d_118_8 () Bool)
(declare-fun d_118_7 () Bool)
(declare-fun d_118_6 () Bool)
(declare-fun d_118_5 () Bool)
(declare-fun d_118_4 () Bool)
(declare-fun d_118_3 () Bool)
(declare-fun d_118_2 () Bool)
(declare-fun d_118_1 () Bool)
(declare-fun d_118_0 () Bool)
(declare-fun d_119_8 () Bool)
(declare-fun d_119_7 () Bool)
(declare-fun d_119_6 () Bool)
(declare-fun d_119_5 () Bool)
(declare-fun d_119_4 () Bool)
(declare-fun d_119_3 () Bool)
(declare-fun d_119_2 () Bool)
(declare-fun d_119_1 () Bool)
(declare-fun d_119_0 () Bool)
(declare-fun d_120_8 () Bool)
(declare-fun d_120_7 () Bool)
(declare-fun d_120_6 () Bool)
(declare-fun d_120_5 () Bool)
(declare-fun d_120_4 () Bool)
(declare-fun d_120_3 () Bool)
(declare-fun d_120_2 () Bool)
(declare-fun d_120_1 () Bool)
(declare-fun d_120_0 () Bool)
(declare-fun d_121_8 () Bool)
(declare-fun d_121_7 () Bool)
(declare-fun d_121_6 () Bool)
(declare-fun d_121_5 () Bool)
(declare-fun d_121_4 () Bool)
(declare-fun d_121_3 () Bool)
(declare-fun d_121_2 () Bool)
(declare-fun d_121_1 () Bool)
(declare-fun d_121_0 () Bool)
(declare-fun d_122_8 () Bool)
(declare-fun d_122_7 () Bool)
(declare-fun d_122_6 () Bool)
(declare-fun d_122_5 () Bool)
(declare-fun d_122_4 () Bool)
(declare-fun d_122_3 () Bool)
(declare-fun d_122_2 () Bool)
(declare-fun d_122_1 () Bool)
(declare-fun d_122_0 () Bool)
(declare-fun d_123_8 () Bool)
(declare-fun d_123_7 () Bool)
(declare-fun d_123_6 () Bool)
(declare-fun d_123_5 () Bool)
(declare-fun d_123_4 () Bool)
(declare-fun d_123_3 () Bool)
(declare-fun d_123_2 () Bool)
(declare-fun d_123_1 () Bool)
(declare-fun d_123_0 () Bool)
(declare-fun d_124_8 () Bool)
(declare-fun d_124_7 () Bool)
(declare-fun d_124_6 () Bool)
(declare-fun d_124_5 () Bool)
(declare-fun d_124_4 () Bool)
(declare-fun d_124_3 () Bool)
(declare-fun d_124_2 () Bool)
(declare-fun d_124_1 () Bool)
(declare-fun d_124_0 () Bool)
(declare-fun d_125_8 () Bool)
(declare-fun d_125_7 () Bool)
(declare-fun d_125_6 () Bool)
(declare-fun d_125_5 () Bool)
(declare-fun d_125_4 () Bool)
(declare-fun d_125_3 () Bool)
(declare-fun d_125_2 () Bool)
(declare-fun d_125_1 () Bool)
(declare-fun d_125_0 () Bool)
(declare-fun d_126_8 () Bool)
(declare-fun d_126_7 () Bool)
(declare-fun d_126_6 () Bool)
(declare-fun d_126_5 () Bool)
(declare-fun d_126_4 () Bool)
(declare-fun d_126_3 () Bool)
(declare-fun d_126_2 () Bool)
(declare-fun d_126_1 () Bool)
(declare-fun d_126_0 () Bool)
(declare-fun d_127_8 () Bool)
(declare-fun d_127_7 () Bool)
(declare-fun d_127_6 () Bool)
(declare-fun d_127_5 () Bool)
(declare-fun d_127_4 () Bool)
(declare-fun d_127_3 () Bool)
(declare-fun d_127_2 () Bool)
(declare-fun d_127_1 () Bool)
(declare-fun d_127_0 () Bool)
(declare-fun d_128_8 () Bool)
(declare-fun d_128_7 () Bool)
(declare-fun d_128_6 () Bool)
(declare-fun d_128_5 () Bool)
(declare-fun d_128_4 () Bool)
(declare-fun d_128_3 () Bool)
(declare-fun d_128_2 () Bool)
(declare-fun d_128_1 () Bool)
(declare-fun d_128_0 () Bool)
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
(declare-fun in_target_3 () Bool)
(declare-fun in_region_3 () Bool)
(declare-fun ghost_2_3 () Int)
(declare-fun ghost_1_3 () Int)
(declare-fun in_target_4 () Bool)
(declare-fun in_region_4 () Bool)
(declare-fun ghost_2_4 () Int)
(declare-fun ghost_1_4 () Int)
(declare-fun in_target_2 () Bool)
(declare-fun in_region_2 () Bool)
(declare-fun ghost_2_2 () Int)
(declare-fun ghost_1_2 () Int)
(declare-fun in_target_1 () Bool)
(declare-fun in_region_1 () Bool)
(declare-fun ghost_2_1 () Int)
(declare-fun ghost_1_1 () Int)
(declare-fun in_region_0 () Bool)
(declare-fun in_region_21 () Bool)
(declare-fun in_region_20 () Bool)
(declare-fun in_region_16 () Bool)
(declare-fun in_region_13 () Bool)
(declare-fun in_region_9 () Bool)
(declare-fun in_target_24 () Bool)
(declare-fun in_region_24 () Bool)
(declare-fun in_target_23 () Bool)
(declare-fun in_region_23 () Bool)
(declare-fun in_target_19 () Bool)
(declare-fun in_region_19 () Bool)
(declare-fun in_target_15 () Bool)
(declare-fun in_region_15 () Bool)
(declare-fun in_target_11 () Bool)
(declare-fun in_region_11 () Bool)
(declare-fun in_region_14 () Bool)
(declare-fun in_region_12 () Bool)
(declare-fun in_region_8 () Bool)
(declare-fun in_target_22 () Bool)
(declare-fun in_region_22 () Bool)
(declare-fun in_target_21 () Bool)
(declare-fun in_target_18 () Bool)
(declare-fun in_region_18 () Bool)
(declare-fun in_target_10 () Bool)
(declare-fun in_region_10 () Bool)
(declare-fun in_target_20 () Bool)
(declare-fun in_target_16 () Bool)
(declare-fun in_target_13 () Bool)
(declare-fun in_target_9 () Bool)
(declare-fun in_region_7 () Bool)
(declare-fun in_target_17 () Bool)
(declare-fun in_region_17 () Bool)
(declare-fun in_target_14 () Bool)
(declare-fun in_target_12 () Bool)
(declare-fun in_target_8 () Bool)
(declare-fun in_target_7 () Bool)
(declare-fun ghost_2_62 () Int)
(declare-fun ghost_2_128 () Int)
(declare-fun in_target_128 () Bool)
(declare-fun ghost_2_127 () Int)
(declare-fun in_target_127 () Bool)
(declare-fun ghost_2_119 () Int)
(declare-fun in_target_119 () Bool)
(declare-fun ghost_2_24 () Int)
(declare-fun ghost_2_103 () Int)
(declare-fun in_target_103 () Bool)
(declare-fun ghost_2_87 () Int)
(declare-fun in_target_87 () Bool)
(declare-fun in_target_62 () Bool)
(declare-fun ghost_2_61 () Int)
(declare-fun ghost_2_126 () Int)
(declare-fun in_target_126 () Bool)
(declare-fun ghost_2_118 () Int)
(declare-fun in_target_118 () Bool)
(declare-fun ghost_2_23 () Int)
(declare-fun ghost_2_86 () Int)
(declare-fun in_target_86 () Bool)
(declare-fun in_target_61 () Bool)
(declare-fun ghost_2_60 () Int)
(declare-fun ghost_2_125 () Int)
(declare-fun in_target_125 () Bool)
(declare-fun ghost_2_117 () Int)
(declare-fun in_target_117 () Bool)
(declare-fun ghost_2_22 () Int)
(declare-fun ghost_2_85 () Int)
(declare-fun in_target_85 () Bool)
(declare-fun in_target_60 () Bool)
(declare-fun ghost_2_59 () Int)
(declare-fun ghost_2_124 () Int)
(declare-fun in_target_124 () Bool)
(declare-fun ghost_2_116 () Int)
(declare-fun in_target_116 () Bool)
(declare-fun ghost_2_123 () Int)
(declare-fun in_target_123 () Bool)
(declare-fun ghost_2_84 () Int)
(declare-fun in_target_84 () Bool)
(declare-fun in_target_59 () Bool)
(declare-fun ghost_2_58 () Int)
(declare-fun ghost_2_109 () Int)
(declare-fun in_target_109 () Bool)
(declare-fun ghost_2_122 () Int)
(declare-fun in_target_122 () Bool)
(declare-fun ghost_2_21 () Int)
(declare-fun ghost_2_83 () Int)
(declare-fun in_target_83 () Bool)
(declare-fun in_target_58 () Bool)
(declare-fun ghost_2_57 () Int)
(declare-fun ghost_2_106 () Int)
(declare-fun in_target_106 () Bool)
(declare-fun ghost_2_121 () Int)
(declare-fun in_target_121 () Bool)
(declare-fun ghost_2_20 () Int)
(declare-fun ghost_2_82 () Int)
(declare-fun in_target_82 () Bool)
(declare-fun in_target_57 () Bool)
(declare-fun ghost_2_56 () Int)
(declare-fun ghost_2_104 () Int)
(declare-fun in_target_104 () Bool)
(declare-fun ghost_2_120 () Int)
(declare-fun in_target_120 () Bool)
(declare-fun ghost_2_97 () Int)
(declare-fun in_target_97 () Bool)
(declare-fun ghost_2_81 () Int)
(declare-fun in_target_81 () Bool)
(declare-fun in_target_56 () Bool)
(declare-fun ghost_2_55 () Int)
(declare-fun ghost_2_115 () Int)
(declare-fun in_target_115 () Bool)
(declare-fun ghost_2_19 () Int)
(declare-fun ghost_2_102 () Int)
(declare-fun in_target_102 () Bool)
(declare-fun in_target_55 () Bool)
(declare-fun ghost_2_54 () Int)
(declare-fun ghost_2_114 () Int)
(declare-fun in_target_114 () Bool)
(declare-fun ghost_2_18 () Int)
(declare-fun in_target_54 () Bool)
(declare-fun ghost_2_53 () Int)
(declare-fun ghost_2_113 () Int)
(declare-fun in_target_113 () Bool)
(declare-fun in_target_53 () Bool)
(declare-fun ghost_2_52 () Int)
(declare-fun ghost_2_112 () Int)
(declare-fun in_target_112 () Bool)
(declare-fun ghost_2_17 () Int)
(declare-fun ghost_2_101 () Int)
(declare-fun in_target_101 () Bool)
(declare-fun in_target_52 () Bool)
(declare-fun ghost_2_51 () Int)
(declare-fun ghost_2_111 () Int)
(declare-fun in_target_111 () Bool)
(declare-fun ghost_2_108 () Int)
(declare-fun in_target_108 () Bool)
(declare-fun in_target_51 () Bool)
(declare-fun ghost_2_50 () Int)
(declare-fun ghost_2_110 () Int)
(declare-fun in_target_110 () Bool)
(declare-fun ghost_2_107 () Int)
(declare-fun in_target_107 () Bool)
(declare-fun ghost_2_100 () Int)
(declare-fun in_target_100 () Bool)
(declare-fun in_target_50 () Bool)
(declare-fun ghost_2_49 () Int)
(declare-fun ghost_2_16 () Int)
(declare-fun in_target_49 () Bool)
(declare-fun ghost_2_48 () Int)
(declare-fun ghost_2_105 () Int)
(declare-fun in_target_105 () Bool)
(declare-fun ghost_2_99 () Int)
(declare-fun in_target_99 () Bool)
(declare-fun in_target_48 () Bool)
(declare-fun ghost_2_47 () Int)
(declare-fun ghost_2_98 () Int)
(declare-fun in_target_98 () Bool)
(declare-fun in_target_47 () Bool)
(declare-fun ghost_2_46 () Int)
(declare-fun ghost_2_15 () Int)
(declare-fun ghost_2_96 () Int)
(declare-fun in_target_96 () Bool)
(declare-fun ghost_2_80 () Int)
(declare-fun in_target_80 () Bool)
(declare-fun in_target_46 () Bool)
(declare-fun ghost_2_45 () Int)
(declare-fun ghost_2_14 () Int)
(declare-fun ghost_2_95 () Int)
(declare-fun in_target_95 () Bool)
(declare-fun in_target_45 () Bool)
(declare-fun ghost_2_44 () Int)
(declare-fun ghost_2_94 () Int)
(declare-fun in_target_94 () Bool)
(declare-fun in_target_44 () Bool)
(declare-fun ghost_2_43 () Int)
(declare-fun ghost_2_93 () Int)
(declare-fun in_target_93 () Bool)
(declare-fun ghost_2_13 () Int)
(declare-fun in_target_43 () Bool)
(declare-fun ghost_2_42 () Int)
(declare-fun ghost_2_92 () Int)
(declare-fun in_target_92 () Bool)
(declare-fun ghost_2_79 () Int)
(declare-fun in_target_79 () Bool)
(declare-fun in_target_42 () Bool)
(declare-fun ghost_2_41 () Int)
(declare-fun ghost_2_12 () Int)
(declare-fun ghost_2_91 () Int)
(declare-fun in_target_91 () Bool)
(declare-fun ghost_2_78 () Int)
(declare-fun in_target_78 () Bool)
(declare-fun in_target_41 () Bool)
(declare-fun ghost_2_40 () Int)
(declare-fun ghost_2_90 () Int)
(declare-fun in_target_90 () Bool)
(declare-fun in_target_40 () Bool)
(declare-fun ghost_2_39 () Int)
(declare-fun ghost_2_89 () Int)
(declare-fun in_target_89 () Bool)
(declare-fun ghost_2_77 () Int)
(declare-fun in_target_77 () Bool)
(declare-fun in_target_39 () Bool)
(declare-fun ghost_2_38 () Int)
(declare-fun ghost_2_88 () Int)
(declare-fun in_target_88 () Bool)
(declare-fun ghost_2_76 () Int)
(declare-fun in_target_76 () Bool)
(declare-fun in_target_38 () Bool)
(declare-fun ghost_2_37 () Int)
(declare-fun ghost_2_11 () Int)
(declare-fun ghost_2_75 () Int)
(declare-fun in_target_75 () Bool)
(declare-fun in_target_37 () Bool)
(declare-fun ghost_2_36 () Int)
(declare-fun ghost_2_10 () Int)
(declare-fun ghost_2_74 () Int)
(declare-fun in_target_74 () Bool)
(declare-fun in_target_36 () Bool)
(declare-fun ghost_2_35 () Int)
(declare-fun ghost_2_73 () Int)
(declare-fun in_target_73 () Bool)
(declare-fun in_target_35 () Bool)
(declare-fun ghost_2_34 () Int)
(declare-fun ghost_2_9 () Int)
(declare-fun ghost_2_72 () Int)
(declare-fun in_target_72 () Bool)
(declare-fun in_target_34 () Bool)
(declare-fun ghost_2_33 () Int)
(declare-fun ghost_2_71 () Int)
(declare-fun in_target_71 () Bool)
(declare-fun in_target_33 () Bool)
(declare-fun ghost_2_32 () Int)
(declare-fun ghost_2_8 () Int)
(declare-fun ghost_2_70 () Int)
(declare-fun in_target_70 () Bool)
(declare-fun in_target_32 () Bool)
(declare-fun ghost_2_31 () Int)
(declare-fun ghost_2_69 () Int)
(declare-fun in_target_69 () Bool)
(declare-fun in_target_31 () Bool)
(declare-fun ghost_2_30 () Int)
(declare-fun ghost_2_68 () Int)
(declare-fun in_target_68 () Bool)
(declare-fun in_target_30 () Bool)
(declare-fun ghost_2_29 () Int)
(declare-fun ghost_2_7 () Int)
(declare-fun ghost_2_67 () Int)
(declare-fun in_target_67 () Bool)
(declare-fun in_target_29 () Bool)
(declare-fun ghost_2_28 () Int)
(declare-fun ghost_2_66 () Int)
(declare-fun in_target_66 () Bool)
(declare-fun in_target_28 () Bool)
(declare-fun ghost_2_27 () Int)
(declare-fun ghost_2_65 () Int)
(declare-fun in_target_65 () Bool)
(declare-fun in_target_27 () Bool)
(declare-fun ghost_2_26 () Int)
(declare-fun ghost_2_64 () Int)
(declare-fun in_target_64 () Bool)
(declare-fun in_target_26 () Bool)
(declare-fun ghost_2_25 () Int)
(declare-fun ghost_2_63 () Int)
(declare-fun in_target_63 () Bool)
(declare-fun in_target_25 () Bool)
(declare-fun ghost_1_62 () Int)
(declare-fun ghost_1_128 () Int)
(declare-fun ghost_1_127 () Int)
(declare-fun ghost_1_119 () Int)
(declare-fun ghost_1_24 () Int)
(declare-fun ghost_1_103 () Int)
(declare-fun ghost_1_87 () Int)
(declare-fun ghost_1_61 () Int)
(declare-fun ghost_1_126 () Int)
(declare-fun ghost_1_118 () Int)
(declare-fun ghost_1_23 () Int)
(declare-fun ghost_1_86 () Int)
(declare-fun ghost_1_60 () Int)
(declare-fun ghost_1_125 () Int)
(declare-fun ghost_1_117 () Int)
(declare-fun ghost_1_22 () Int)
(declare-fun ghost_1_85 () Int)
(declare-fun ghost_1_59 () Int)
(declare-fun ghost_1_124 () Int)
(declare-fun ghost_1_116 () Int)
(declare-fun ghost_1_123 () Int)
(declare-fun ghost_1_84 () Int)
(declare-fun ghost_1_58 () Int)
(declare-fun ghost_1_109 () Int)
(declare-fun ghost_1_122 () Int)
(declare-fun ghost_1_21 () Int)
(declare-fun ghost_1_83 () Int)
(declare-fun ghost_1_57 () Int)
(declare-fun ghost_1_106 () Int)
(declare-fun ghost_1_121 () Int)
(declare-fun ghost_1_20 () Int)
(declare-fun ghost_1_82 () Int)
(declare-fun ghost_1_56 () Int)
(declare-fun ghost_1_104 () Int)
(declare-fun ghost_1_120 () Int)
(declare-fun ghost_1_97 () Int)
(declare-fun ghost_1_81 () Int)
(declare-fun ghost_1_55 () Int)
(declare-fun ghost_1_115 () Int)
(declare-fun ghost_1_19 () Int)
(declare-fun ghost_1_102 () Int)
(declare-fun ghost_1_54 () Int)
(declare-fun ghost_1_114 () Int)
(declare-fun ghost_1_18 () Int)
(declare-fun ghost_1_53 () Int)
(declare-fun ghost_1_113 () Int)
(declare-fun ghost_1_52 () Int)
(declare-fun ghost_1_112 () Int)
(declare-fun ghost_1_17 () Int)
(declare-fun ghost_1_101 () Int)
(declare-fun ghost_1_51 () Int)
(declare-fun ghost_1_111 () Int)
(declare-fun ghost_1_108 () Int)
(declare-fun ghost_1_50 () Int)
(declare-fun ghost_1_110 () Int)
(declare-fun ghost_1_107 () Int)
(declare-fun ghost_1_100 () Int)
(declare-fun ghost_1_49 () Int)
(declare-fun ghost_1_16 () Int)
(declare-fun ghost_1_48 () Int)
(declare-fun ghost_1_105 () Int)
(declare-fun ghost_1_99 () Int)
(declare-fun ghost_1_47 () Int)
(declare-fun ghost_1_98 () Int)
(declare-fun ghost_1_46 () Int)
(declare-fun ghost_1_15 () Int)
(declare-fun ghost_1_96 () Int)
(declare-fun ghost_1_80 () Int)
(declare-fun ghost_1_45 () Int)
(declare-fun ghost_1_14 () Int)
(declare-fun ghost_1_95 () Int)
(declare-fun ghost_1_44 () Int)
(declare-fun ghost_1_94 () Int)
(declare-fun ghost_1_43 () Int)
(declare-fun ghost_1_93 () Int)
(declare-fun ghost_1_13 () Int)
(declare-fun ghost_1_42 () Int)
(declare-fun ghost_1_92 () Int)
(declare-fun ghost_1_79 () Int)
(declare-fun ghost_1_41 () Int)
(declare-fun ghost_1_12 () Int)
(declare-fun ghost_1_91 () Int)
(declare-fun ghost_1_78 () Int)
(declare-fun ghost_1_40 () Int)
(declare-fun ghost_1_90 () Int)
(declare-fun ghost_1_39 () Int)
(declare-fun ghost_1_89 () Int)
(declare-fun ghost_1_77 () Int)
(declare-fun ghost_1_38 () Int)
(declare-fun ghost_1_88 () Int)
(declare-fun ghost_1_76 () Int)
(declare-fun ghost_1_37 () Int)
(declare-fun ghost_1_11 () Int)
(declare-fun ghost_1_75 () Int)
(declare-fun ghost_1_36 () Int)
(declare-fun ghost_1_10 () Int)
(declare-fun ghost_1_74 () Int)
(declare-fun ghost_1_35 () Int)
(declare-fun ghost_1_73 () Int)
(declare-fun ghost_1_34 () Int)
(declare-fun ghost_1_9 () Int)
(declare-fun ghost_1_72 () Int)
(declare-fun ghost_1_33 () Int)
(declare-fun ghost_1_71 () Int)
(declare-fun ghost_1_32 () Int)
(declare-fun ghost_1_8 () Int)
(declare-fun ghost_1_70 () Int)
(declare-fun ghost_1_31 () Int)
(declare-fun ghost_1_69 () Int)
(declare-fun ghost_1_30 () Int)
(declare-fun ghost_1_68 () Int)
(declare-fun ghost_1_29 () Int)
(declare-fun ghost_1_7 () Int)
(declare-fun ghost_1_67 () Int)
(declare-fun ghost_1_28 () Int)
(declare-fun ghost_1_66 () Int)
(declare-fun ghost_1_27 () Int)
(declare-fun ghost_1_65 () Int)
(declare-fun ghost_1_26 () Int)
(declare-fun ghost_1_64 () Int)
(declare-fun ghost_1_25 () Int)
(declare-fun ghost_1_63 () Int)
(declare-fun in_region_128 () Bool)
(declare-fun in_region_127 () Bool)
(declare-fun in_region_126 () Bool)
(declare-fun in_region_125 () Bool)
(declare-fun in_region_124 () Bool)
(declare-fun in_region_123 () Bool)
(declare-fun in_region_122 () Bool)
(declare-fun in_region_121 () Bool)
(declare-fun in_region_120 () Bool)
(declare-fun in_region_119 () Bool)
(declare-fun in_region_118 () Bool)
(declare-fun in_region_117 () Bool)
(declare-fun in_region_116 () Bool)
(declare-fun in_region_115 () Bool)
(declare-fun in_region_114 () Bool)
(declare-fun in_region_113 () Bool)
(declare-fun in_region_112 () Bool)
(declare-fun in_region_111 () Bool)
(declare-fun in_region_110 () Bool)
(declare-fun in_region_109 () Bool)
(declare-fun in_region_108 () Bool)
(declare-fun in_region_107 () Bool)
(declare-fun in_region_106 () Bool)
(declare-fun in_region_105 () Bool)
(declare-fun in_region_104 () Bool)
(declare-fun in_region_103 () Bool)
(declare-fun in_region_102 () Bool)
(declare-fun in_region_101 () Bool)
(declare-fun in_region_100 () Bool)
(declare-fun in_region_99 () Bool)
(declare-fun in_region_98 () Bool)
(declare-fun in_region_97 () Bool)
(declare-fun in_region_96 () Bool)
(declare-fun in_region_95 () Bool)
(declare-fun in_region_94 () Bool)
(declare-fun in_region_93 () Bool)
(declare-fun in_region_92 () Bool)
(declare-fun in_region_91 () Bool)
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
(declare-fun instance_0 () Bool)
(assert
 (let (($x135 (or false c_0_0)))
 (let (($x137 (or $x135 c_0_1)))
 (let (($x139 (or $x137 c_0_2)))
 (let (($x141 (or $x139 c_0_3)))
 (let (($x143 (or $x141 c_0_4)))
 (let (($x145 (or $x143 c_0_5)))
 (let (($x147 (or $x145 c_0_6)))
 (let (($x149 (or $x147 c_0_7)))
 (or $x149 c_0_8))))))))))
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
 (let (($x225 (or false c_1_0)))
 (let (($x227 (or $x225 c_1_1)))
 (let (($x229 (or $x227 c_1_2)))
 (let (($x231 (or $x229 c_1_3)))
 (let (($x233 (or $x231 c_1_4)))
 (let (($x235 (or $x233 c_1_5)))
 (let (($x237 (or $x235 c_1_6)))
 (let (($x239 (or $x237 c_1_7)))
 (or $x239 c_1_8))))))))))
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
 (let (($x315 (or false c_2_0)))
 (let (($x317 (or $x315 c_2_1)))
 (let (($x319 (or $x317 c_2_2)))
 (let (($x321 (or $x319 c_2_3)))
 (let (($x323 (or $x321 c_2_4)))
 (let (($x325 (or $x323 c_2_5)))
 (let (($x327 (or $x325 c_2_6)))
 (let (($x329 (or $x327 c_2_7)))
 (or $x329 c_2_8))))))))))
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
 (let (($x405 (or false c_3_0)))
 (let (($x407 (or $x405 c_3_1)))
 (let (($x409 (or $x407 c_3_2)))
 (let (($x411 (or $x409 c_3_3)))
 (let (($x413 (or $x411 c_3_4)))
 (let (($x415 (or $x413 c_3_5)))
 (let (($x417 (or $x415 c_3_6)))
 (let (($x419 (or $x417 c_3_7)))
 (or $x419 c_3_8))))))))))
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
 (let (($x495 (or false c_4_0)))
 (let (($x497 (or $x495 c_4_1)))
 (let (($x499 (or $x497 c_4_2)))
 (let (($x501 (or $x499 c_4_3)))
 (let (($x503 (or $x501 c_4_4)))
 (let (($x505 (or $x503 c_4_5)))
 (let (($x507 (or $x505 c_4_6)))
 (let (($x509 (or $x507 c_4_7)))
 (or $x509 c_4_8))))))))))
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
 (let (($x585 (or false c_5_0)))
 (let (($x587 (or $x585 c_5_1)))
 (let (($x589 (or $x587 c_5_2)))
 (let (($x591 (or $x589 c_5_3)))
 (let (($x593 (or $x591 c_5_4)))
 (let (($x595 (or $x593 c_5_5)))
 (let (($x597 (or $x595 c_5_6)))
 (let (($x599 (or $x597 c_5_7)))
 (or $x599 c_5_8))))))))))
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
 (let (($x675 (or false c_6_0)))
 (let (($x677 (or $x675 c_6_1)))
 (let (($x679 (or $x677 c_6_2)))
 (let (($x681 (or $x679 c_6_3)))
 (let (($x683 (or $x681 c_6_4)))
 (let (($x685 (or $x683 c_6_5)))
 (let (($x687 (or $x685 c_6_6)))
 (let (($x689 (or $x687 c_6_7)))
 (or $x689 c_6_8))))))))))
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
 (let (($x765 (or false c_7_0)))
 (let (($x767 (or $x765 c_7_1)))
 (let (($x769 (or $x767 c_7_2)))
 (let (($x771 (or $x769 c_7_3)))
 (let (($x773 (or $x771 c_7_4)))
 (let (($x775 (or $x773 c_7_5)))
 (let (($x777 (or $x775 c_7_6)))
 (let (($x779 (or $x777 c_7_7)))
 (or $x779 c_7_8))))))))))
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
 (let (($x855 (or false c_8_0)))
 (let (($x857 (or $x855 c_8_1)))
 (let (($x859 (or $x857 c_8_2)))
 (let (($x861 (or $x859 c_8_3)))
 (let (($x863 (or $x861 c_8_4)))
 (let (($x865 (or $x863 c_8_5)))
 (let (($x867 (or $x865 c_8_6)))
 (let (($x869 (or $x867 c_8_7)))
 (or $x869 c_8_8))))))))))
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
 (let (($x945 (or false c_9_0)))
 (let (($x947 (or $x945 c_9_1)))
 (let (($x949 (or $x947 c_9_2)))
 (let (($x951 (or $x949 c_9_3)))
 (let (($x953 (or $x951 c_9_4)))
 (let (($x955 (or $x953 c_9_5)))
 (let (($x957 (or $x955 c_9_6)))
 (let (($x959 (or $x957 c_9_7)))
 (or $x959 c_9_8))))))))))
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
 (let (($x1035 (or false c_10_0)))
 (let (($x1037 (or $x1035 c_10_1)))
 (let (($x1039 (or $x1037 c_10_2)))
 (let (($x1041 (or $x1039 c_10_3)))
 (let (($x1043 (or $x1041 c_10_4)))
 (let (($x1045 (or $x1043 c_10_5)))
 (let (($x1047 (or $x1045 c_10_6)))
 (let (($x1049 (or $x1047 c_10_7)))
 (or $x1049 c_10_8))))))))))
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
 (let (($x1125 (or false c_11_0)))
 (let (($x1127 (or $x1125 c_11_1)))
 (let (($x1129 (or $x1127 c_11_2)))
 (let (($x1131 (or $x1129 c_11_3)))
 (let (($x1133 (or $x1131 c_11_4)))
 (let (($x1135 (or $x1133 c_11_5)))
 (let (($x1137 (or $x1135 c_11_6)))
 (let (($x1139 (or $x1137 c_11_7)))
 (or $x1139 c_11_8))))))))))
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
 (let (($x1215 (or false c_12_0)))
 (let (($x1217 (or $x1215 c_12_1)))
 (let (($x1219 (or $x1217 c_12_2)))
 (let (($x1221 (or $x1219 c_12_3)))
 (let (($x1223 (or $x1221 c_12_4)))
 (let (($x1225 (or $x1223 c_12_5)))
 (let (($x1227 (or $x1225 c_12_6)))
 (let (($x1229 (or $x1227 c_12_7)))
 (or $x1229 c_12_8))))))))))
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
 (let (($x1305 (or false c_13_0)))
 (let (($x1307 (or $x1305 c_13_1)))
 (let (($x1309 (or $x1307 c_13_2)))
 (let (($x1311 (or $x1309 c_13_3)))
 (let (($x1313 (or $x1311 c_13_4)))
 (let (($x1315 (or $x1313 c_13_5)))
 (let (($x1317 (or $x1315 c_13_6)))
 (let (($x1319 (or $x1317 c_13_7)))
 (or $x1319 c_13_8))))))))))
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
 (let (($x1395 (or false c_14_0)))
 (let (($x1397 (or $x1395 c_14_1)))
 (let (($x1399 (or $x1397 c_14_2)))
 (let (($x1401 (or $x1399 c_14_3)))
 (let (($x1403 (or $x1401 c_14_4)))
 (let (($x1405 (or $x1403 c_14_5)))
 (let (($x1407 (or $x1405 c_14_6)))
 (let (($x1409 (or $x1407 c_14_7)))
 (or $x1409 c_14_8))))))))))
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
 (let (($x1485 (or false c_15_0)))
 (let (($x1487 (or $x1485 c_15_1)))
 (let (($x1489 (or $x1487 c_15_2)))
 (let (($x1491 (or $x1489 c_15_3)))
 (let (($x1493 (or $x1491 c_15_4)))
 (let (($x1495 (or $x1493 c_15_5)))
 (let (($x1497 (or $x1495 c_15_6)))
 (let (($x1499 (or $x1497 c_15_7)))
 (or $x1499 c_15_8))))))))))
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
 (let (($x1575 (or false c_16_0)))
 (let (($x1577 (or $x1575 c_16_1)))
 (let (($x1579 (or $x1577 c_16_2)))
 (let (($x1581 (or $x1579 c_16_3)))
 (let (($x1583 (or $x1581 c_16_4)))
 (let (($x1585 (or $x1583 c_16_5)))
 (let (($x1587 (or $x1585 c_16_6)))
 (let (($x1589 (or $x1587 c_16_7)))
 (or $x1589 c_16_8))))))))))
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
 (let (($x1665 (or false c_17_0)))
 (let (($x1667 (or $x1665 c_17_1)))
 (let (($x1669 (or $x1667 c_17_2)))
 (let (($x1671 (or $x1669 c_17_3)))
 (let (($x1673 (or $x1671 c_17_4)))
 (let (($x1675 (or $x1673 c_17_5)))
 (let (($x1677 (or $x1675 c_17_6)))
 (let (($x1679 (or $x1677 c_17_7)))
 (or $x1679 c_17_8))))))))))
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
 (let (($x1755 (or false c_18_0)))
 (let (($x1757 (or $x1755 c_18_1)))
 (let (($x1759 (or $x1757 c_18_2)))
 (let (($x1761 (or $x1759 c_18_3)))
 (let (($x1763 (or $x1761 c_18_4)))
 (let (($x1765 (or $x1763 c_18_5)))
 (let (($x1767 (or $x1765 c_18_6)))
 (let (($x1769 (or $x1767 c_18_7)))
 (or $x1769 c_18_8))))))))))
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
 (let (($x1845 (or false c_19_0)))
 (let (($x1847 (or $x1845 c_19_1)))
 (let (($x1849 (or $x1847 c_19_2)))
 (let (($x1851 (or $x1849 c_19_3)))
 (let (($x1853 (or $x1851 c_19_4)))
 (let (($x1855 (or $x1853 c_19_5)))
 (let (($x1857 (or $x1855 c_19_6)))
 (let (($x1859 (or $x1857 c_19_7)))
 (or $x1859 c_19_8))))))))))
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
 (let (($x1935 (or false c_20_0)))
 (let (($x1937 (or $x1935 c_20_1)))
 (let (($x1939 (or $x1937 c_20_2)))
 (let (($x1941 (or $x1939 c_20_3)))
 (let (($x1943 (or $x1941 c_20_4)))
 (let (($x1945 (or $x1943 c_20_5)))
 (let (($x1947 (or $x1945 c_20_6)))
 (let (($x1949 (or $x1947 c_20_7)))
 (or $x1949 c_20_8))))))))))
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
 (let (($x2025 (or false c_21_0)))
 (let (($x2027 (or $x2025 c_21_1)))
 (let (($x2029 (or $x2027 c_21_2)))
 (let (($x2031 (or $x2029 c_21_3)))
 (let (($x2033 (or $x2031 c_21_4)))
 (let (($x2035 (or $x2033 c_21_5)))
 (let (($x2037 (or $x2035 c_21_6)))
 (let (($x2039 (or $x2037 c_21_7)))
 (or $x2039 c_21_8))))))))))
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
 (let (($x2115 (or false c_22_0)))
 (let (($x2117 (or $x2115 c_22_1)))
 (let (($x2119 (or $x2117 c_22_2)))
 (let (($x2121 (or $x2119 c_22_3)))
 (let (($x2123 (or $x2121 c_22_4)))
 (let (($x2125 (or $x2123 c_22_5)))
 (let (($x2127 (or $x2125 c_22_6)))
 (let (($x2129 (or $x2127 c_22_7)))
 (or $x2129 c_22_8))))))))))
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
 (let (($x2205 (or false c_23_0)))
 (let (($x2207 (or $x2205 c_23_1)))
 (let (($x2209 (or $x2207 c_23_2)))
 (let (($x2211 (or $x2209 c_23_3)))
 (let (($x2213 (or $x2211 c_23_4)))
 (let (($x2215 (or $x2213 c_23_5)))
 (let (($x2217 (or $x2215 c_23_6)))
 (let (($x2219 (or $x2217 c_23_7)))
 (or $x2219 c_23_8))))))))))
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
 (let (($x2295 (or false c_24_0)))
 (let (($x2297 (or $x2295 c_24_1)))
 (let (($x2299 (or $x2297 c_24_2)))
 (let (($x2301 (or $x2299 c_24_3)))
 (let (($x2303 (or $x2301 c_24_4)))
 (let (($x2305 (or $x2303 c_24_5)))
 (let (($x2307 (or $x2305 c_24_6)))
 (let (($x2309 (or $x2307 c_24_7)))
 (or $x2309 c_24_8))))))))))
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
 (let (($x2385 (or false c_25_0)))
 (let (($x2387 (or $x2385 c_25_1)))
 (let (($x2389 (or $x2387 c_25_2)))
 (let (($x2391 (or $x2389 c_25_3)))
 (let (($x2393 (or $x2391 c_25_4)))
 (let (($x2395 (or $x2393 c_25_5)))
 (let (($x2397 (or $x2395 c_25_6)))
 (let (($x2399 (or $x2397 c_25_7)))
 (or $x2399 c_25_8))))))))))
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
 (let (($x2475 (or false c_26_0)))
 (let (($x2477 (or $x2475 c_26_1)))
 (let (($x2479 (or $x2477 c_26_2)))
 (let (($x2481 (or $x2479 c_26_3)))
 (let (($x2483 (or $x2481 c_26_4)))
 (let (($x2485 (or $x2483 c_26_5)))
 (let (($x2487 (or $x2485 c_26_6)))
 (let (($x2489 (or $x2487 c_26_7)))
 (or $x2489 c_26_8))))))))))
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
 (let (($x2565 (or false c_27_0)))
 (let (($x2567 (or $x2565 c_27_1)))
 (let (($x2569 (or $x2567 c_27_2)))
 (let (($x2571 (or $x2569 c_27_3)))
 (let (($x2573 (or $x2571 c_27_4)))
 (let (($x2575 (or $x2573 c_27_5)))
 (let (($x2577 (or $x2575 c_27_6)))
 (let (($x2579 (or $x2577 c_27_7)))
 (or $x2579 c_27_8))))))))))
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
 (let (($x2655 (or false c_28_0)))
 (let (($x2657 (or $x2655 c_28_1)))
 (let (($x2659 (or $x2657 c_28_2)))
 (let (($x2661 (or $x2659 c_28_3)))
 (let (($x2663 (or $x2661 c_28_4)))
 (let (($x2665 (or $x2663 c_28_5)))
 (let (($x2667 (or $x2665 c_28_6)))
 (let (($x2669 (or $x2667 c_28_7)))
 (or $x2669 c_28_8))))))))))
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
 (let (($x2745 (or false c_29_0)))
 (let (($x2747 (or $x2745 c_29_1)))
 (let (($x2749 (or $x2747 c_29_2)))
 (let (($x2751 (or $x2749 c_29_3)))
 (let (($x2753 (or $x2751 c_29_4)))
 (let (($x2755 (or $x2753 c_29_5)))
 (let (($x2757 (or $x2755 c_29_6)))
 (let (($x2759 (or $x2757 c_29_7)))
 (or $x2759 c_29_8))))))))))
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
 (let (($x2835 (or false c_30_0)))
 (let (($x2837 (or $x2835 c_30_1)))
 (let (($x2839 (or $x2837 c_30_2)))
 (let (($x2841 (or $x2839 c_30_3)))
 (let (($x2843 (or $x2841 c_30_4)))
 (let (($x2845 (or $x2843 c_30_5)))
 (let (($x2847 (or $x2845 c_30_6)))
 (let (($x2849 (or $x2847 c_30_7)))
 (or $x2849 c_30_8))))))))))
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
 (let (($x2925 (or false c_31_0)))
 (let (($x2927 (or $x2925 c_31_1)))
 (let (($x2929 (or $x2927 c_31_2)))
 (let (($x2931 (or $x2929 c_31_3)))
 (let (($x2933 (or $x2931 c_31_4)))
 (let (($x2935 (or $x2933 c_31_5)))
 (let (($x2937 (or $x2935 c_31_6)))
 (let (($x2939 (or $x2937 c_31_7)))
 (or $x2939 c_31_8))))))))))
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
 (let (($x3015 (or false c_32_0)))
 (let (($x3017 (or $x3015 c_32_1)))
 (let (($x3019 (or $x3017 c_32_2)))
 (let (($x3021 (or $x3019 c_32_3)))
 (let (($x3023 (or $x3021 c_32_4)))
 (let (($x3025 (or $x3023 c_32_5)))
 (let (($x3027 (or $x3025 c_32_6)))
 (let (($x3029 (or $x3027 c_32_7)))
 (or $x3029 c_32_8))))))))))
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
 (let (($x3105 (or false c_33_0)))
 (let (($x3107 (or $x3105 c_33_1)))
 (let (($x3109 (or $x3107 c_33_2)))
 (let (($x3111 (or $x3109 c_33_3)))
 (let (($x3113 (or $x3111 c_33_4)))
 (let (($x3115 (or $x3113 c_33_5)))
 (let (($x3117 (or $x3115 c_33_6)))
 (let (($x3119 (or $x3117 c_33_7)))
 (or $x3119 c_33_8))))))))))
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
 (let (($x3195 (or false c_34_0)))
 (let (($x3197 (or $x3195 c_34_1)))
 (let (($x3199 (or $x3197 c_34_2)))
 (let (($x3201 (or $x3199 c_34_3)))
 (let (($x3203 (or $x3201 c_34_4)))
 (let (($x3205 (or $x3203 c_34_5)))
 (let (($x3207 (or $x3205 c_34_6)))
 (let (($x3209 (or $x3207 c_34_7)))
 (or $x3209 c_34_8))))))))))
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
 (let (($x3285 (or false c_35_0)))
 (let (($x3287 (or $x3285 c_35_1)))
 (let (($x3289 (or $x3287 c_35_2)))
 (let (($x3291 (or $x3289 c_35_3)))
 (let (($x3293 (or $x3291 c_35_4)))
 (let (($x3295 (or $x3293 c_35_5)))
 (let (($x3297 (or $x3295 c_35_6)))
 (let (($x3299 (or $x3297 c_35_7)))
 (or $x3299 c_35_8))))))))))
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
 (let (($x3375 (or false c_36_0)))
 (let (($x3377 (or $x3375 c_36_1)))
 (let (($x3379 (or $x3377 c_36_2)))
 (let (($x3381 (or $x3379 c_36_3)))
 (let (($x3383 (or $x3381 c_36_4)))
 (let (($x3385 (or $x3383 c_36_5)))
 (let (($x3387 (or $x3385 c_36_6)))
 (let (($x3389 (or $x3387 c_36_7)))
 (or $x3389 c_36_8))))))))))
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
 (let (($x3465 (or false c_37_0)))
 (let (($x3467 (or $x3465 c_37_1)))
 (let (($x3469 (or $x3467 c_37_2)))
 (let (($x3471 (or $x3469 c_37_3)))
 (let (($x3473 (or $x3471 c_37_4)))
 (let (($x3475 (or $x3473 c_37_5)))
 (let (($x3477 (or $x3475 c_37_6)))
 (let (($x3479 (or $x3477 c_37_7)))
 (or $x3479 c_37_8))))))))))
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
 (let (($x3555 (or false c_38_0)))
 (let (($x3557 (or $x3555 c_38_1)))
 (let (($x3559 (or $x3557 c_38_2)))
 (let (($x3561 (or $x3559 c_38_3)))
 (let (($x3563 (or $x3561 c_38_4)))
 (let (($x3565 (or $x3563 c_38_5)))
 (let (($x3567 (or $x3565 c_38_6)))
 (let (($x3569 (or $x3567 c_38_7)))
 (or $x3569 c_38_8))))))))))
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
 (let (($x3645 (or false c_39_0)))
 (let (($x3647 (or $x3645 c_39_1)))
 (let (($x3649 (or $x3647 c_39_2)))
 (let (($x3651 (or $x3649 c_39_3)))
 (let (($x3653 (or $x3651 c_39_4)))
 (let (($x3655 (or $x3653 c_39_5)))
 (let (($x3657 (or $x3655 c_39_6)))
 (let (($x3659 (or $x3657 c_39_7)))
 (or $x3659 c_39_8))))))))))
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
 (let (($x3735 (or false c_40_0)))
 (let (($x3737 (or $x3735 c_40_1)))
 (let (($x3739 (or $x3737 c_40_2)))
 (let (($x3741 (or $x3739 c_40_3)))
 (let (($x3743 (or $x3741 c_40_4)))
 (let (($x3745 (or $x3743 c_40_5)))
 (let (($x3747 (or $x3745 c_40_6)))
 (let (($x3749 (or $x3747 c_40_7)))
 (or $x3749 c_40_8))))))))))
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
 (let (($x3825 (or false c_41_0)))
 (let (($x3827 (or $x3825 c_41_1)))
 (let (($x3829 (or $x3827 c_41_2)))
 (let (($x3831 (or $x3829 c_41_3)))
 (let (($x3833 (or $x3831 c_41_4)))
 (let (($x3835 (or $x3833 c_41_5)))
 (let (($x3837 (or $x3835 c_41_6)))
 (let (($x3839 (or $x3837 c_41_7)))
 (or $x3839 c_41_8))))))))))
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
 (let (($x3915 (or false c_42_0)))
 (let (($x3917 (or $x3915 c_42_1)))
 (let (($x3919 (or $x3917 c_42_2)))
 (let (($x3921 (or $x3919 c_42_3)))
 (let (($x3923 (or $x3921 c_42_4)))
 (let (($x3925 (or $x3923 c_42_5)))
 (let (($x3927 (or $x3925 c_42_6)))
 (let (($x3929 (or $x3927 c_42_7)))
 (or $x3929 c_42_8))))))))))
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
 (let (($x4005 (or false c_43_0)))
 (let (($x4007 (or $x4005 c_43_1)))
 (let (($x4009 (or $x4007 c_43_2)))
 (let (($x4011 (or $x4009 c_43_3)))
 (let (($x4013 (or $x4011 c_43_4)))
 (let (($x4015 (or $x4013 c_43_5)))
 (let (($x4017 (or $x4015 c_43_6)))
 (let (($x4019 (or $x4017 c_43_7)))
 (or $x4019 c_43_8))))))))))
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
 (let (($x4095 (or false c_44_0)))
 (let (($x4097 (or $x4095 c_44_1)))
 (let (($x4099 (or $x4097 c_44_2)))
 (let (($x4101 (or $x4099 c_44_3)))
 (let (($x4103 (or $x4101 c_44_4)))
 (let (($x4105 (or $x4103 c_44_5)))
 (let (($x4107 (or $x4105 c_44_6)))
 (let (($x4109 (or $x4107 c_44_7)))
 (or $x4109 c_44_8))))))))))
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
 (let (($x4185 (or false c_45_0)))
 (let (($x4187 (or $x4185 c_45_1)))
 (let (($x4189 (or $x4187 c_45_2)))
 (let (($x4191 (or $x4189 c_45_3)))
 (let (($x4193 (or $x4191 c_45_4)))
 (let (($x4195 (or $x4193 c_45_5)))
 (let (($x4197 (or $x4195 c_45_6)))
 (let (($x4199 (or $x4197 c_45_7)))
 (or $x4199 c_45_8))))))))))
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
 (let (($x4275 (or false c_46_0)))
 (let (($x4277 (or $x4275 c_46_1)))
 (let (($x4279 (or $x4277 c_46_2)))
 (let (($x4281 (or $x4279 c_46_3)))
 (let (($x4283 (or $x4281 c_46_4)))
 (let (($x4285 (or $x4283 c_46_5)))
 (let (($x4287 (or $x4285 c_46_6)))
 (let (($x4289 (or $x4287 c_46_7)))
 (or $x4289 c_46_8))))))))))
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
 (let (($x4365 (or false c_47_0)))
 (let (($x4367 (or $x4365 c_47_1)))
 (let (($x4369 (or $x4367 c_47_2)))
 (let (($x4371 (or $x4369 c_47_3)))
 (let (($x4373 (or $x4371 c_47_4)))
 (let (($x4375 (or $x4373 c_47_5)))
 (let (($x4377 (or $x4375 c_47_6)))
 (let (($x4379 (or $x4377 c_47_7)))
 (or $x4379 c_47_8))))))))))
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
 (let (($x4455 (or false c_48_0)))
 (let (($x4457 (or $x4455 c_48_1)))
 (let (($x4459 (or $x4457 c_48_2)))
 (let (($x4461 (or $x4459 c_48_3)))
 (let (($x4463 (or $x4461 c_48_4)))
 (let (($x4465 (or $x4463 c_48_5)))
 (let (($x4467 (or $x4465 c_48_6)))
 (let (($x4469 (or $x4467 c_48_7)))
 (or $x4469 c_48_8))))))))))
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
 (let (($x4545 (or false c_49_0)))
 (let (($x4547 (or $x4545 c_49_1)))
 (let (($x4549 (or $x4547 c_49_2)))
 (let (($x4551 (or $x4549 c_49_3)))
 (let (($x4553 (or $x4551 c_49_4)))
 (let (($x4555 (or $x4553 c_49_5)))
 (let (($x4557 (or $x4555 c_49_6)))
 (let (($x4559 (or $x4557 c_49_7)))
 (or $x4559 c_49_8))))))))))
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
 (let (($x4635 (or false c_50_0)))
 (let (($x4637 (or $x4635 c_50_1)))
 (let (($x4639 (or $x4637 c_50_2)))
 (let (($x4641 (or $x4639 c_50_3)))
 (let (($x4643 (or $x4641 c_50_4)))
 (let (($x4645 (or $x4643 c_50_5)))
 (let (($x4647 (or $x4645 c_50_6)))
 (let (($x4649 (or $x4647 c_50_7)))
 (or $x4649 c_50_8))))))))))
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
 (let (($x4725 (or false c_51_0)))
 (let (($x4727 (or $x4725 c_51_1)))
 (let (($x4729 (or $x4727 c_51_2)))
 (let (($x4731 (or $x4729 c_51_3)))
 (let (($x4733 (or $x4731 c_51_4)))
 (let (($x4735 (or $x4733 c_51_5)))
 (let (($x4737 (or $x4735 c_51_6)))
 (let (($x4739 (or $x4737 c_51_7)))
 (or $x4739 c_51_8))))))))))
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
 (let (($x4815 (or false c_52_0)))
 (let (($x4817 (or $x4815 c_52_1)))
 (let (($x4819 (or $x4817 c_52_2)))
 (let (($x4821 (or $x4819 c_52_3)))
 (let (($x4823 (or $x4821 c_52_4)))
 (let (($x4825 (or $x4823 c_52_5)))
 (let (($x4827 (or $x4825 c_52_6)))
 (let (($x4829 (or $x4827 c_52_7)))
 (or $x4829 c_52_8))))))))))
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
 (let (($x4905 (or false c_53_0)))
 (let (($x4907 (or $x4905 c_53_1)))
 (let (($x4909 (or $x4907 c_53_2)))
 (let (($x4911 (or $x4909 c_53_3)))
 (let (($x4913 (or $x4911 c_53_4)))
 (let (($x4915 (or $x4913 c_53_5)))
 (let (($x4917 (or $x4915 c_53_6)))
 (let (($x4919 (or $x4917 c_53_7)))
 (or $x4919 c_53_8))))))))))
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
 (let (($x4995 (or false c_54_0)))
 (let (($x4997 (or $x4995 c_54_1)))
 (let (($x4999 (or $x4997 c_54_2)))
 (let (($x5001 (or $x4999 c_54_3)))
 (let (($x5003 (or $x5001 c_54_4)))
 (let (($x5005 (or $x5003 c_54_5)))
 (let (($x5007 (or $x5005 c_54_6)))
 (let (($x5009 (or $x5007 c_54_7)))
 (or $x5009 c_54_8))))))))))
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
 (let (($x5085 (or false c_55_0)))
 (let (($x5087 (or $x5085 c_55_1)))
 (let (($x5089 (or $x5087 c_55_2)))
 (let (($x5091 (or $x5089 c_55_3)))
 (let (($x5093 (or $x5091 c_55_4)))
 (let (($x5095 (or $x5093 c_55_5)))
 (let (($x5097 (or $x5095 c_55_6)))
 (let (($x5099 (or $x5097 c_55_7)))
 (or $x5099 c_55_8))))))))))
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
 (let (($x5175 (or false c_56_0)))
 (let (($x5177 (or $x5175 c_56_1)))
 (let (($x5179 (or $x5177 c_56_2)))
 (let (($x5181 (or $x5179 c_56_3)))
 (let (($x5183 (or $x5181 c_56_4)))
 (let (($x5185 (or $x5183 c_56_5)))
 (let (($x5187 (or $x5185 c_56_6)))
 (let (($x5189 (or $x5187 c_56_7)))
 (or $x5189 c_56_8))))))))))
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
 (let (($x5265 (or false c_57_0)))
 (let (($x5267 (or $x5265 c_57_1)))
 (let (($x5269 (or $x5267 c_57_2)))
 (let (($x5271 (or $x5269 c_57_3)))
 (let (($x5273 (or $x5271 c_57_4)))
 (let (($x5275 (or $x5273 c_57_5)))
 (let (($x5277 (or $x5275 c_57_6)))
 (let (($x5279 (or $x5277 c_57_7)))
 (or $x5279 c_57_8))))))))))
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
 (let (($x5355 (or false c_58_0)))
 (let (($x5357 (or $x5355 c_58_1)))
 (let (($x5359 (or $x5357 c_58_2)))
 (let (($x5361 (or $x5359 c_58_3)))
 (let (($x5363 (or $x5361 c_58_4)))
 (let (($x5365 (or $x5363 c_58_5)))
 (let (($x5367 (or $x5365 c_58_6)))
 (let (($x5369 (or $x5367 c_58_7)))
 (or $x5369 c_58_8))))))))))
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
 (let (($x5445 (or false c_59_0)))
 (let (($x5447 (or $x5445 c_59_1)))
 (let (($x5449 (or $x5447 c_59_2)))
 (let (($x5451 (or $x5449 c_59_3)))
 (let (($x5453 (or $x5451 c_59_4)))
 (let (($x5455 (or $x5453 c_59_5)))
 (let (($x5457 (or $x5455 c_59_6)))
 (let (($x5459 (or $x5457 c_59_7)))
 (or $x5459 c_59_8))))))))))
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
 (let (($x5535 (or false c_60_0)))
 (let (($x5537 (or $x5535 c_60_1)))
 (let (($x5539 (or $x5537 c_60_2)))
 (let (($x5541 (or $x5539 c_60_3)))
 (let (($x5543 (or $x5541 c_60_4)))
 (let (($x5545 (or $x5543 c_60_5)))
 (let (($x5547 (or $x5545 c_60_6)))
 (let (($x5549 (or $x5547 c_60_7)))
 (or $x5549 c_60_8))))))))))
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
 (let (($x5625 (or false c_61_0)))
 (let (($x5627 (or $x5625 c_61_1)))
 (let (($x5629 (or $x5627 c_61_2)))
 (let (($x5631 (or $x5629 c_61_3)))
 (let (($x5633 (or $x5631 c_61_4)))
 (let (($x5635 (or $x5633 c_61_5)))
 (let (($x5637 (or $x5635 c_61_6)))
 (let (($x5639 (or $x5637 c_61_7)))
 (or $x5639 c_61_8))))))))))
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
 (let (($x5715 (or false c_62_0)))
 (let (($x5717 (or $x5715 c_62_1)))
 (let (($x5719 (or $x5717 c_62_2)))
 (let (($x5721 (or $x5719 c_62_3)))
 (let (($x5723 (or $x5721 c_62_4)))
 (let (($x5725 (or $x5723 c_62_5)))
 (let (($x5727 (or $x5725 c_62_6)))
 (let (($x5729 (or $x5727 c_62_7)))
 (or $x5729 c_62_8))))))))))
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
 (let (($x5805 (or false c_63_0)))
 (let (($x5807 (or $x5805 c_63_1)))
 (let (($x5809 (or $x5807 c_63_2)))
 (let (($x5811 (or $x5809 c_63_3)))
 (let (($x5813 (or $x5811 c_63_4)))
 (let (($x5815 (or $x5813 c_63_5)))
 (let (($x5817 (or $x5815 c_63_6)))
 (let (($x5819 (or $x5817 c_63_7)))
 (or $x5819 c_63_8))))))))))
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
 (let (($x5895 (or false c_64_0)))
 (let (($x5897 (or $x5895 c_64_1)))
 (let (($x5899 (or $x5897 c_64_2)))
 (let (($x5901 (or $x5899 c_64_3)))
 (let (($x5903 (or $x5901 c_64_4)))
 (let (($x5905 (or $x5903 c_64_5)))
 (let (($x5907 (or $x5905 c_64_6)))
 (let (($x5909 (or $x5907 c_64_7)))
 (or $x5909 c_64_8))))))))))
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
 (let (($x5985 (or false c_65_0)))
 (let (($x5987 (or $x5985 c_65_1)))
 (let (($x5989 (or $x5987 c_65_2)))
 (let (($x5991 (or $x5989 c_65_3)))
 (let (($x5993 (or $x5991 c_65_4)))
 (let (($x5995 (or $x5993 c_65_5)))
 (let (($x5997 (or $x5995 c_65_6)))
 (let (($x5999 (or $x5997 c_65_7)))
 (or $x5999 c_65_8))))))))))
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
 (let (($x6075 (or false c_66_0)))
 (let (($x6077 (or $x6075 c_66_1)))
 (let (($x6079 (or $x6077 c_66_2)))
 (let (($x6081 (or $x6079 c_66_3)))
 (let (($x6083 (or $x6081 c_66_4)))
 (let (($x6085 (or $x6083 c_66_5)))
 (let (($x6087 (or $x6085 c_66_6)))
 (let (($x6089 (or $x6087 c_66_7)))
 (or $x6089 c_66_8))))))))))
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
 (let (($x6165 (or false c_67_0)))
 (let (($x6167 (or $x6165 c_67_1)))
 (let (($x6169 (or $x6167 c_67_2)))
 (let (($x6171 (or $x6169 c_67_3)))
 (let (($x6173 (or $x6171 c_67_4)))
 (let (($x6175 (or $x6173 c_67_5)))
 (let (($x6177 (or $x6175 c_67_6)))
 (let (($x6179 (or $x6177 c_67_7)))
 (or $x6179 c_67_8))))))))))
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
 (let (($x6255 (or false c_68_0)))
 (let (($x6257 (or $x6255 c_68_1)))
 (let (($x6259 (or $x6257 c_68_2)))
 (let (($x6261 (or $x6259 c_68_3)))
 (let (($x6263 (or $x6261 c_68_4)))
 (let (($x6265 (or $x6263 c_68_5)))
 (let (($x6267 (or $x6265 c_68_6)))
 (let (($x6269 (or $x6267 c_68_7)))
 (or $x6269 c_68_8))))))))))
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
 (let (($x6345 (or false c_69_0)))
 (let (($x6347 (or $x6345 c_69_1)))
 (let (($x6349 (or $x6347 c_69_2)))
 (let (($x6351 (or $x6349 c_69_3)))
 (let (($x6353 (or $x6351 c_69_4)))
 (let (($x6355 (or $x6353 c_69_5)))
 (let (($x6357 (or $x6355 c_69_6)))
 (let (($x6359 (or $x6357 c_69_7)))
 (or $x6359 c_69_8))))))))))
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
 (let (($x6435 (or false c_70_0)))
 (let (($x6437 (or $x6435 c_70_1)))
 (let (($x6439 (or $x6437 c_70_2)))
 (let (($x6441 (or $x6439 c_70_3)))
 (let (($x6443 (or $x6441 c_70_4)))
 (let (($x6445 (or $x6443 c_70_5)))
 (let (($x6447 (or $x6445 c_70_6)))
 (let (($x6449 (or $x6447 c_70_7)))
 (or $x6449 c_70_8))))))))))
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
 (let (($x6525 (or false c_71_0)))
 (let (($x6527 (or $x6525 c_71_1)))
 (let (($x6529 (or $x6527 c_71_2)))
 (let (($x6531 (or $x6529 c_71_3)))
 (let (($x6533 (or $x6531 c_71_4)))
 (let (($x6535 (or $x6533 c_71_5)))
 (let (($x6537 (or $x6535 c_71_6)))
 (let (($x6539 (or $x6537 c_71_7)))
 (or $x6539 c_71_8))))))))))
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
 (let (($x6615 (or false c_72_0)))
 (let (($x6617 (or $x6615 c_72_1)))
 (let (($x6619 (or $x6617 c_72_2)))
 (let (($x6621 (or $x6619 c_72_3)))
 (let (($x6623 (or $x6621 c_72_4)))
 (let (($x6625 (or $x6623 c_72_5)))
 (let (($x6627 (or $x6625 c_72_6)))
 (let (($x6629 (or $x6627 c_72_7)))
 (or $x6629 c_72_8))))))))))
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
 (let (($x6705 (or false c_73_0)))
 (let (($x6707 (or $x6705 c_73_1)))
 (let (($x6709 (or $x6707 c_73_2)))
 (let (($x6711 (or $x6709 c_73_3)))
 (let (($x6713 (or $x6711 c_73_4)))
 (let (($x6715 (or $x6713 c_73_5)))
 (let (($x6717 (or $x6715 c_73_6)))
 (let (($x6719 (or $x6717 c_73_7)))
 (or $x6719 c_73_8))))))))))
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
 (let (($x6795 (or false c_74_0)))
 (let (($x6797 (or $x6795 c_74_1)))
 (let (($x6799 (or $x6797 c_74_2)))
 (let (($x6801 (or $x6799 c_74_3)))
 (let (($x6803 (or $x6801 c_74_4)))
 (let (($x6805 (or $x6803 c_74_5)))
 (let (($x6807 (or $x6805 c_74_6)))
 (let (($x6809 (or $x6807 c_74_7)))
 (or $x6809 c_74_8))))))))))
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
 (let (($x6885 (or false c_75_0)))
 (let (($x6887 (or $x6885 c_75_1)))
 (let (($x6889 (or $x6887 c_75_2)))
 (let (($x6891 (or $x6889 c_75_3)))
 (let (($x6893 (or $x6891 c_75_4)))
 (let (($x6895 (or $x6893 c_75_5)))
 (let (($x6897 (or $x6895 c_75_6)))
 (let (($x6899 (or $x6897 c_75_7)))
 (or $x6899 c_75_8))))))))))
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
 (let (($x6975 (or false c_76_0)))
 (let (($x6977 (or $x6975 c_76_1)))
 (let (($x6979 (or $x6977 c_76_2)))
 (let (($x6981 (or $x6979 c_76_3)))
 (let (($x6983 (or $x6981 c_76_4)))
 (let (($x6985 (or $x6983 c_76_5)))
 (let (($x6987 (or $x6985 c_76_6)))
 (let (($x6989 (or $x6987 c_76_7)))
 (or $x6989 c_76_8))))))))))
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
 (let (($x7065 (or false c_77_0)))
 (let (($x7067 (or $x7065 c_77_1)))
 (let (($x7069 (or $x7067 c_77_2)))
 (let (($x7071 (or $x7069 c_77_3)))
 (let (($x7073 (or $x7071 c_77_4)))
 (let (($x7075 (or $x7073 c_77_5)))
 (let (($x7077 (or $x7075 c_77_6)))
 (let (($x7079 (or $x7077 c_77_7)))
 (or $x7079 c_77_8))))))))))
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
 (let (($x7155 (or false c_78_0)))
 (let (($x7157 (or $x7155 c_78_1)))
 (let (($x7159 (or $x7157 c_78_2)))
 (let (($x7161 (or $x7159 c_78_3)))
 (let (($x7163 (or $x7161 c_78_4)))
 (let (($x7165 (or $x7163 c_78_5)))
 (let (($x7167 (or $x7165 c_78_6)))
 (let (($x7169 (or $x7167 c_78_7)))
 (or $x7169 c_78_8))))))))))
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
 (let (($x7245 (or false c_79_0)))
 (let (($x7247 (or $x7245 c_79_1)))
 (let (($x7249 (or $x7247 c_79_2)))
 (let (($x7251 (or $x7249 c_79_3)))
 (let (($x7253 (or $x7251 c_79_4)))
 (let (($x7255 (or $x7253 c_79_5)))
 (let (($x7257 (or $x7255 c_79_6)))
 (let (($x7259 (or $x7257 c_79_7)))
 (or $x7259 c_79_8))))))))))
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
 (let (($x7335 (or false c_80_0)))
 (let (($x7337 (or $x7335 c_80_1)))
 (let (($x7339 (or $x7337 c_80_2)))
 (let (($x7341 (or $x7339 c_80_3)))
 (let (($x7343 (or $x7341 c_80_4)))
 (let (($x7345 (or $x7343 c_80_5)))
 (let (($x7347 (or $x7345 c_80_6)))
 (let (($x7349 (or $x7347 c_80_7)))
 (or $x7349 c_80_8))))))))))
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
 (let (($x7425 (or false c_81_0)))
 (let (($x7427 (or $x7425 c_81_1)))
 (let (($x7429 (or $x7427 c_81_2)))
 (let (($x7431 (or $x7429 c_81_3)))
 (let (($x7433 (or $x7431 c_81_4)))
 (let (($x7435 (or $x7433 c_81_5)))
 (let (($x7437 (or $x7435 c_81_6)))
 (let (($x7439 (or $x7437 c_81_7)))
 (or $x7439 c_81_8))))))))))
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
 (let (($x7515 (or false c_82_0)))
 (let (($x7517 (or $x7515 c_82_1)))
 (let (($x7519 (or $x7517 c_82_2)))
 (let (($x7521 (or $x7519 c_82_3)))
 (let (($x7523 (or $x7521 c_82_4)))
 (let (($x7525 (or $x7523 c_82_5)))
 (let (($x7527 (or $x7525 c_82_6)))
 (let (($x7529 (or $x7527 c_82_7)))
 (or $x7529 c_82_8))))))))))
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
 (let (($x7605 (or false c_83_0)))
 (let (($x7607 (or $x7605 c_83_1)))
 (let (($x7609 (or $x7607 c_83_2)))
 (let (($x7611 (or $x7609 c_83_3)))
 (let (($x7613 (or $x7611 c_83_4)))
 (let (($x7615 (or $x7613 c_83_5)))
 (let (($x7617 (or $x7615 c_83_6)))
 (let (($x7619 (or $x7617 c_83_7)))
 (or $x7619 c_83_8))))))))))
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
 (let (($x7695 (or false c_84_0)))
 (let (($x7697 (or $x7695 c_84_1)))
 (let (($x7699 (or $x7697 c_84_2)))
 (let (($x7701 (or $x7699 c_84_3)))
 (let (($x7703 (or $x7701 c_84_4)))
 (let (($x7705 (or $x7703 c_84_5)))
 (let (($x7707 (or $x7705 c_84_6)))
 (let (($x7709 (or $x7707 c_84_7)))
 (or $x7709 c_84_8))))))))))
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
 (let (($x7785 (or false c_85_0)))
 (let (($x7787 (or $x7785 c_85_1)))
 (let (($x7789 (or $x7787 c_85_2)))
 (let (($x7791 (or $x7789 c_85_3)))
 (let (($x7793 (or $x7791 c_85_4)))
 (let (($x7795 (or $x7793 c_85_5)))
 (let (($x7797 (or $x7795 c_85_6)))
 (let (($x7799 (or $x7797 c_85_7)))
 (or $x7799 c_85_8))))))))))
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
 (let (($x7875 (or false c_86_0)))
 (let (($x7877 (or $x7875 c_86_1)))
 (let (($x7879 (or $x7877 c_86_2)))
 (let (($x7881 (or $x7879 c_86_3)))
 (let (($x7883 (or $x7881 c_86_4)))
 (let (($x7885 (or $x7883 c_86_5)))
 (let (($x7887 (or $x7885 c_86_6)))
 (let (($x7889 (or $x7887 c_86_7)))
 (or $x7889 c_86_8))))))))))
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
 (let (($x7965 (or false c_87_0)))
 (let (($x7967 (or $x7965 c_87_1)))
 (let (($x7969 (or $x7967 c_87_2)))
 (let (($x7971 (or $x7969 c_87_3)))
 (let (($x7973 (or $x7971 c_87_4)))
 (let (($x7975 (or $x7973 c_87_5)))
 (let (($x7977 (or $x7975 c_87_6)))
 (let (($x7979 (or $x7977 c_87_7)))
 (or $x7979 c_87_8))))))))))
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
 (let (($x8055 (or false c_88_0)))
 (let (($x8057 (or $x8055 c_88_1)))
 (let (($x8059 (or $x8057 c_88_2)))
 (let (($x8061 (or $x8059 c_88_3)))
 (let (($x8063 (or $x8061 c_88_4)))
 (let (($x8065 (or $x8063 c_88_5)))
 (let (($x8067 (or $x8065 c_88_6)))
 (let (($x8069 (or $x8067 c_88_7)))
 (or $x8069 c_88_8))))))))))
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
 (let (($x8145 (or false c_89_0)))
 (let (($x8147 (or $x8145 c_89_1)))
 (let (($x8149 (or $x8147 c_89_2)))
 (let (($x8151 (or $x8149 c_89_3)))
 (let (($x8153 (or $x8151 c_89_4)))
 (let (($x8155 (or $x8153 c_89_5)))
 (let (($x8157 (or $x8155 c_89_6)))
 (let (($x8159 (or $x8157 c_89_7)))
 (or $x8159 c_89_8))))))))))
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
 (let (($x8235 (or false c_90_0)))
 (let (($x8237 (or $x8235 c_90_1)))
 (let (($x8239 (or $x8237 c_90_2)))
 (let (($x8241 (or $x8239 c_90_3)))
 (let (($x8243 (or $x8241 c_90_4)))
 (let (($x8245 (or $x8243 c_90_5)))
 (let (($x8247 (or $x8245 c_90_6)))
 (let (($x8249 (or $x8247 c_90_7)))
 (or $x8249 c_90_8))))))))))
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
 (let (($x8325 (or false c_91_0)))
 (let (($x8327 (or $x8325 c_91_1)))
 (let (($x8329 (or $x8327 c_91_2)))
 (let (($x8331 (or $x8329 c_91_3)))
 (let (($x8333 (or $x8331 c_91_4)))
 (let (($x8335 (or $x8333 c_91_5)))
 (let (($x8337 (or $x8335 c_91_6)))
 (let (($x8339 (or $x8337 c_91_7)))
 (or $x8339 c_91_8))))))))))
(assert
 (not (and c_91_0 c_91_1)))
(assert
 (not (and c_91_0 c_91_2)))
(assert
 (not (and c_91_0 c_91_3)))
(assert
 (not (and c_91_0 c_91_4)))
(assert
 (not (and c_91_0 c_91_5)))
(assert
 (not (and c_91_0 c_91_6)))
(assert
 (not (and c_91_0 c_91_7)))
(assert
 (not (and c_91_0 c_91_8)))
(assert
 (not (and c_91_1 c_91_2)))
(assert
 (not (and c_91_1 c_91_3)))
(assert
 (not (and c_91_1 c_91_4)))
(assert
 (not (and c_91_1 c_91_5)))
(assert
 (not (and c_91_1 c_91_6)))
(assert
 (not (and c_91_1 c_91_7)))
(assert
 (not (and c_91_1 c_91_8)))
(assert
 (not (and c_91_2 c_91_3)))
(assert
 (not (and c_91_2 c_91_4)))
(assert
 (not (and c_91_2 c_91_5)))
(assert
 (not (and c_91_2 c_91_6)))
(assert
 (not (and c_91_2 c_91_7)))
(assert
 (not (and c_91_2 c_91_8)))
(assert
 (not (and c_91_3 c_91_4)))
(assert
 (not (and c_91_3 c_91_5)))
(assert
 (not (and c_91_3 c_91_6)))
(assert
 (not (and c_91_3 c_91_7)))
(assert
 (not (and c_91_3 c_91_8)))
(assert
 (not (and c_91_4 c_91_5)))
(assert
 (not (and c_91_4 c_91_6)))
(assert
 (not (and c_91_4 c_91_7)))
(assert
 (not (and c_91_4 c_91_8)))
(assert
 (not (and c_91_5 c_91_6)))
(assert
 (not (and c_91_5 c_91_7)))
(assert
 (not (and c_91_5 c_91_8)))
(assert
 (not (and c_91_6 c_91_7)))
(assert
 (not (and c_91_6 c_91_8)))
(assert
 (not (and c_91_7 c_91_8)))
(assert
 (let (($x8415 (or false c_92_0)))
 (let (($x8417 (or $x8415 c_92_1)))
 (let (($x8419 (or $x8417 c_92_2)))
 (let (($x8421 (or $x8419 c_92_3)))
 (let (($x8423 (or $x8421 c_92_4)))
 (let (($x8425 (or $x8423 c_92_5)))
 (let (($x8427 (or $x8425 c_92_6)))
 (let (($x8429 (or $x8427 c_92_7)))
 (or $x8429 c_92_8))))))))))
(assert
 (not (and c_92_0 c_92_1)))
(assert
 (not (and c_92_0 c_92_2)))
(assert
 (not (and c_92_0 c_92_3)))
(assert
 (not (and c_92_0 c_92_4)))
(assert
 (not (and c_92_0 c_92_5)))
(assert
 (not (and c_92_0 c_92_6)))
(assert
 (not (and c_92_0 c_92_7)))
(assert
 (not (and c_92_0 c_92_8)))
(assert
 (not (and c_92_1 c_92_2)))
(assert
 (not (and c_92_1 c_92_3)))
(assert
 (not (and c_92_1 c_92_4)))
(assert
 (not (and c_92_1 c_92_5)))
(assert
 (not (and c_92_1 c_92_6)))
(assert
 (not (and c_92_1 c_92_7)))
(assert
 (not (and c_92_1 c_92_8)))
(assert
 (not (and c_92_2 c_92_3)))
(assert
 (not (and c_92_2 c_92_4)))
(assert
 (not (and c_92_2 c_92_5)))
(assert
 (not (and c_92_2 c_92_6)))
(assert
 (not (and c_92_2 c_92_7)))
(assert
 (not (and c_92_2 c_92_8)))
(assert
 (not (and c_92_3 c_92_4)))
(assert
 (not (and c_92_3 c_92_5)))
(assert
 (not (and c_92_3 c_92_6)))
(assert
 (not (and c_92_3 c_92_7)))
(assert
 (not (and c_92_3 c_92_8)))
(assert
 (not (and c_92_4 c_92_5)))
(assert
 (not (and c_92_4 c_92_6)))
(assert
 (not (and c_92_4 c_92_7)))
(assert
 (not (and c_92_4 c_92_8)))
(assert
 (not (and c_92_5 c_92_6)))
(assert
 (not (and c_92_5 c_92_7)))
(assert
 (not (and c_92_5 c_92_8)))
(assert
 (not (and c_92_6 c_92_7)))
(assert
 (not (and c_92_6 c_92_8)))
(assert
 (not (and c_92_7 c_92_8)))
(assert
 (let (($x8505 (or false c_93_0)))
 (let (($x8507 (or $x8505 c_93_1)))
 (let (($x8509 (or $x8507 c_93_2)))
 (let (($x8511 (or $x8509 c_93_3)))
 (let (($x8513 (or $x8511 c_93_4)))
 (let (($x8515 (or $x8513 c_93_5)))
 (let (($x8517 (or $x8515 c_93_6)))
 (let (($x8519 (or $x8517 c_93_7)))
 (or $x8519 c_93_8))))))))))
(assert
 (not (and c_93_0 c_93_1)))
(assert
 (not (and c_93_0 c_93_2)))
(assert
 (not (and c_93_0 c_93_3)))
(assert
 (not (and c_93_0 c_93_4)))
(assert
 (not (and c_93_0 c_93_5)))
(assert
 (not (and c_93_0 c_93_6)))
(assert
 (not (and c_93_0 c_93_7)))
(assert
 (not (and c_93_0 c_93_8)))
(assert
 (not (and c_93_1 c_93_2)))
(assert
 (not (and c_93_1 c_93_3)))
(assert
 (not (and c_93_1 c_93_4)))
(assert
 (not (and c_93_1 c_93_5)))
(assert
 (not (and c_93_1 c_93_6)))
(assert
 (not (and c_93_1 c_93_7)))
(assert
 (not (and c_93_1 c_93_8)))
(assert
 (not (and c_93_2 c_93_3)))
(assert
 (not (and c_93_2 c_93_4)))
(assert
 (not (and c_93_2 c_93_5)))
(assert
 (not (and c_93_2 c_93_6)))
(assert
 (not (and c_93_2 c_93_7)))
(assert
 (not (and c_93_2 c_93_8)))
(assert
 (not (and c_93_3 c_93_4)))
(assert
 (not (and c_93_3 c_93_5)))
(assert
 (not (and c_93_3 c_93_6)))
(assert
 (not (and c_93_3 c_93_7)))
(assert
 (not (and c_93_3 c_93_8)))
(assert
 (not (and c_93_4 c_93_5)))
(assert
 (not (and c_93_4 c_93_6)))
(assert
 (not (and c_93_4 c_93_7)))
(assert
 (not (and c_93_4 c_93_8)))
(assert
 (not (and c_93_5 c_93_6)))
(assert
 (not (and c_93_5 c_93_7)))
(assert
 (not (and c_93_5 c_93_8)))
(assert
 (not (and c_93_6 c_93_7)))
(assert
 (not (and c_93_6 c_93_8)))
(assert
 (not (and c_93_7 c_93_8)))
(assert
 (let (($x8595 (or false c_94_0)))
 (let (($x8597 (or $x8595 c_94_1)))
 (let (($x8599 (or $x8597 c_94_2)))
 (let (($x8601 (or $x8599 c_94_3)))
 (let (($x8603 (or $x8601 c_94_4)))
 (let (($x8605 (or $x8603 c_94_5)))
 (let (($x8607 (or $x8605 c_94_6)))
 (let (($x8609 (or $x8607 c_94_7)))
 (or $x8609 c_94_8))))))))))
(assert
 (not (and c_94_0 c_94_1)))
(assert
 (not (and c_94_0 c_94_2)))
(assert
 (not (and c_94_0 c_94_3)))
(assert
 (not (and c_94_0 c_94_4)))
(assert
 (not (and c_94_0 c_94_5)))
(assert
 (not (and c_94_0 c_94_6)))
(assert
 (not (and c_94_0 c_94_7)))
(assert
 (not (and c_94_0 c_94_8)))
(assert
 (not (and c_94_1 c_94_2)))
(assert
 (not (and c_94_1 c_94_3)))
(assert
 (not (and c_94_1 c_94_4)))
(assert
 (not (and c_94_1 c_94_5)))
(assert
 (not (and c_94_1 c_94_6)))
(assert
 (not (and c_94_1 c_94_7)))
(assert
 (not (and c_94_1 c_94_8)))
(assert
 (not (and c_94_2 c_94_3)))
(assert
 (not (and c_94_2 c_94_4)))
(assert
 (not (and c_94_2 c_94_5)))
(assert
 (not (and c_94_2 c_94_6)))
(assert
 (not (and c_94_2 c_94_7)))
(assert
 (not (and c_94_2 c_94_8)))
(assert
 (not (and c_94_3 c_94_4)))
(assert
 (not (and c_94_3 c_94_5)))
(assert
 (not (and c_94_3 c_94_6)))
(assert
 (not (and c_94_3 c_94_7)))
(assert
 (not (and c_94_3 c_94_8)))
(assert
 (not (and c_94_4 c_94_5)))
(assert
 (not (and c_94_4 c_94_6)))
(assert
 (not (and c_94_4 c_94_7)))
(assert
 (not (and c_94_4 c_94_8)))
(assert
 (not (and c_94_5 c_94_6)))
(assert
 (not (and c_94_5 c_94_7)))
(assert
 (not (and c_94_5 c_94_8)))
(assert
 (not (and c_94_6 c_94_7)))
(assert
 (not (and c_94_6 c_94_8)))
(assert
 (not (and c_94_7 c_94_8)))
(assert
 (let (($x8685 (or false c_95_0)))
 (let (($x8687 (or $x8685 c_95_1)))
 (let (($x8689 (or $x8687 c_95_2)))
 (let (($x8691 (or $x8689 c_95_3)))
 (let (($x8693 (or $x8691 c_95_4)))
 (let (($x8695 (or $x8693 c_95_5)))
 (let (($x8697 (or $x8695 c_95_6)))
 (let (($x8699 (or $x8697 c_95_7)))
 (or $x8699 c_95_8))))))))))
(assert
 (not (and c_95_0 c_95_1)))
(assert
 (not (and c_95_0 c_95_2)))
(assert
 (not (and c_95_0 c_95_3)))
(assert
 (not (and c_95_0 c_95_4)))
(assert
 (not (and c_95_0 c_95_5)))
(assert
 (not (and c_95_0 c_95_6)))
(assert
 (not (and c_95_0 c_95_7)))
(assert
 (not (and c_95_0 c_95_8)))
(assert
 (not (and c_95_1 c_95_2)))
(assert
 (not (and c_95_1 c_95_3)))
(assert
 (not (and c_95_1 c_95_4)))
(assert
 (not (and c_95_1 c_95_5)))
(assert
 (not (and c_95_1 c_95_6)))
(assert
 (not (and c_95_1 c_95_7)))
(assert
 (not (and c_95_1 c_95_8)))
(assert
 (not (and c_95_2 c_95_3)))
(assert
 (not (and c_95_2 c_95_4)))
(assert
 (not (and c_95_2 c_95_5)))
(assert
 (not (and c_95_2 c_95_6)))
(assert
 (not (and c_95_2 c_95_7)))
(assert
 (not (and c_95_2 c_95_8)))
(assert
 (not (and c_95_3 c_95_4)))
(assert
 (not (and c_95_3 c_95_5)))
(assert
 (not (and c_95_3 c_95_6)))
(assert
 (not (and c_95_3 c_95_7)))
(assert
 (not (and c_95_3 c_95_8)))
(assert
 (not (and c_95_4 c_95_5)))
(assert
 (not (and c_95_4 c_95_6)))
(assert
 (not (and c_95_4 c_95_7)))
(assert
 (not (and c_95_4 c_95_8)))
(assert
 (not (and c_95_5 c_95_6)))
(assert
 (not (and c_95_5 c_95_7)))
(assert
 (not (and c_95_5 c_95_8)))
(assert
 (not (and c_95_6 c_95_7)))
(assert
 (not (and c_95_6 c_95_8)))
(assert
 (not (and c_95_7 c_95_8)))
(assert
 (let (($x8775 (or false c_96_0)))
 (let (($x8777 (or $x8775 c_96_1)))
 (let (($x8779 (or $x8777 c_96_2)))
 (let (($x8781 (or $x8779 c_96_3)))
 (let (($x8783 (or $x8781 c_96_4)))
 (let (($x8785 (or $x8783 c_96_5)))
 (let (($x8787 (or $x8785 c_96_6)))
 (let (($x8789 (or $x8787 c_96_7)))
 (or $x8789 c_96_8))))))))))
(assert
 (not (and c_96_0 c_96_1)))
(assert
 (not (and c_96_0 c_96_2)))
(assert
 (not (and c_96_0 c_96_3)))
(assert
 (not (and c_96_0 c_96_4)))
(assert
 (not (and c_96_0 c_96_5)))
(assert
 (not (and c_96_0 c_96_6)))
(assert
 (not (and c_96_0 c_96_7)))
(assert
 (not (and c_96_0 c_96_8)))
(assert
 (not (and c_96_1 c_96_2)))
(assert
 (not (and c_96_1 c_96_3)))
(assert
 (not (and c_96_1 c_96_4)))
(assert
 (not (and c_96_1 c_96_5)))
(assert
 (not (and c_96_1 c_96_6)))
(assert
 (not (and c_96_1 c_96_7)))
(assert
 (not (and c_96_1 c_96_8)))
(assert
 (not (and c_96_2 c_96_3)))
(assert
 (not (and c_96_2 c_96_4)))
(assert
 (not (and c_96_2 c_96_5)))
(assert
 (not (and c_96_2 c_96_6)))
(assert
 (not (and c_96_2 c_96_7)))
(assert
 (not (and c_96_2 c_96_8)))
(assert
 (not (and c_96_3 c_96_4)))
(assert
 (not (and c_96_3 c_96_5)))
(assert
 (not (and c_96_3 c_96_6)))
(assert
 (not (and c_96_3 c_96_7)))
(assert
 (not (and c_96_3 c_96_8)))
(assert
 (not (and c_96_4 c_96_5)))
(assert
 (not (and c_96_4 c_96_6)))
(assert
 (not (and c_96_4 c_96_7)))
(assert
 (not (and c_96_4 c_96_8)))
(assert
 (not (and c_96_5 c_96_6)))
(assert
 (not (and c_96_5 c_96_7)))
(assert
 (not (and c_96_5 c_96_8)))
(assert
 (not (and c_96_6 c_96_7)))
(assert
 (not (and c_96_6 c_96_8)))
(assert
 (not (and c_96_7 c_96_8)))
(assert
 (let (($x8865 (or false c_97_0)))
 (let (($x8867 (or $x8865 c_97_1)))
 (let (($x8869 (or $x8867 c_97_2)))
 (let (($x8871 (or $x8869 c_97_3)))
 (let (($x8873 (or $x8871 c_97_4)))
 (let (($x8875 (or $x8873 c_97_5)))
 (let (($x8877 (or $x8875 c_97_6)))
 (let (($x8879 (or $x8877 c_97_7)))
 (or $x8879 c_97_8))))))))))
(assert
 (not (and c_97_0 c_97_1)))
(assert
 (not (and c_97_0 c_97_2)))
(assert
 (not (and c_97_0 c_97_3)))
(assert
 (not (and c_97_0 c_97_4)))
(assert
 (not (and c_97_0 c_97_5)))
(assert
 (not (and c_97_0 c_97_6)))
(assert
 (not (and c_97_0 c_97_7)))
(assert
 (not (and c_97_0 c_97_8)))
(assert
 (not (and c_97_1 c_97_2)))
(assert
 (not (and c_97_1 c_97_3)))
(assert
 (not (and c_97_1 c_97_4)))
(assert
 (not (and c_97_1 c_97_5)))
(assert
 (not (and c_97_1 c_97_6)))
(assert
 (not (and c_97_1 c_97_7)))
(assert
 (not (and c_97_1 c_97_8)))
(assert
 (not (and c_97_2 c_97_3)))
(assert
 (not (and c_97_2 c_97_4)))
(assert
 (not (and c_97_2 c_97_5)))
(assert
 (not (and c_97_2 c_97_6)))
(assert
 (not (and c_97_2 c_97_7)))
(assert
 (not (and c_97_2 c_97_8)))
(assert
 (not (and c_97_3 c_97_4)))
(assert
 (not (and c_97_3 c_97_5)))
(assert
 (not (and c_97_3 c_97_6)))
(assert
 (not (and c_97_3 c_97_7)))
(assert
 (not (and c_97_3 c_97_8)))
(assert
 (not (and c_97_4 c_97_5)))
(assert
 (not (and c_97_4 c_97_6)))
(assert
 (not (and c_97_4 c_97_7)))
(assert
 (not (and c_97_4 c_97_8)))
(assert
 (not (and c_97_5 c_97_6)))
(assert
 (not (and c_97_5 c_97_7)))
(assert
 (not (and c_97_5 c_97_8)))
(assert
 (not (and c_97_6 c_97_7)))
(assert
 (not (and c_97_6 c_97_8)))
(assert
 (not (and c_97_7 c_97_8)))
(assert
 (let (($x8955 (or false c_98_0)))
 (let (($x8957 (or $x8955 c_98_1)))
 (let (($x8959 (or $x8957 c_98_2)))
 (let (($x8961 (or $x8959 c_98_3)))
 (let (($x8963 (or $x8961 c_98_4)))
 (let (($x8965 (or $x8963 c_98_5)))
 (let (($x8967 (or $x8965 c_98_6)))
 (let (($x8969 (or $x8967 c_98_7)))
 (or $x8969 c_98_8))))))))))
(assert
 (not (and c_98_0 c_98_1)))
(assert
 (not (and c_98_0 c_98_2)))
(assert
 (not (and c_98_0 c_98_3)))
(assert
 (not (and c_98_0 c_98_4)))
(assert
 (not (and c_98_0 c_98_5)))
(assert
 (not (and c_98_0 c_98_6)))
(assert
 (not (and c_98_0 c_98_7)))
(assert
 (not (and c_98_0 c_98_8)))
(assert
 (not (and c_98_1 c_98_2)))
(assert
 (not (and c_98_1 c_98_3)))
(assert
 (not (and c_98_1 c_98_4)))
(assert
 (not (and c_98_1 c_98_5)))
(assert
 (not (and c_98_1 c_98_6)))
(assert
 (not (and c_98_1 c_98_7)))
(assert
 (not (and c_98_1 c_98_8)))
(assert
 (not (and c_98_2 c_98_3)))
(assert
 (not (and c_98_2 c_98_4)))
(assert
 (not (and c_98_2 c_98_5)))
(assert
 (not (and c_98_2 c_98_6)))
(assert
 (not (and c_98_2 c_98_7)))
(assert
 (not (and c_98_2 c_98_8)))
(assert
 (not (and c_98_3 c_98_4)))
(assert
 (not (and c_98_3 c_98_5)))
(assert
 (not (and c_98_3 c_98_6)))
(assert
 (not (and c_98_3 c_98_7)))
(assert
 (not (and c_98_3 c_98_8)))
(assert
 (not (and c_98_4 c_98_5)))
(assert
 (not (and c_98_4 c_98_6)))
(assert
 (not (and c_98_4 c_98_7)))
(assert
 (not (and c_98_4 c_98_8)))
(assert
 (not (and c_98_5 c_98_6)))
(assert
 (not (and c_98_5 c_98_7)))
(assert
 (not (and c_98_5 c_98_8)))
(assert
 (not (and c_98_6 c_98_7)))
(assert
 (not (and c_98_6 c_98_8)))
(assert
 (not (and c_98_7 c_98_8)))
(assert
 (let (($x9045 (or false c_99_0)))
 (let (($x9047 (or $x9045 c_99_1)))
 (let (($x9049 (or $x9047 c_99_2)))
 (let (($x9051 (or $x9049 c_99_3)))
 (let (($x9053 (or $x9051 c_99_4)))
 (let (($x9055 (or $x9053 c_99_5)))
 (let (($x9057 (or $x9055 c_99_6)))
 (let (($x9059 (or $x9057 c_99_7)))
 (or $x9059 c_99_8))))))))))
(assert
 (not (and c_99_0 c_99_1)))
(assert
 (not (and c_99_0 c_99_2)))
(assert
 (not (and c_99_0 c_99_3)))
(assert
 (not (and c_99_0 c_99_4)))
(assert
 (not (and c_99_0 c_99_5)))
(assert
 (not (and c_99_0 c_99_6)))
(assert
 (not (and c_99_0 c_99_7)))
(assert
 (not (and c_99_0 c_99_8)))
(assert
 (not (and c_99_1 c_99_2)))
(assert
 (not (and c_99_1 c_99_3)))
(assert
 (not (and c_99_1 c_99_4)))
(assert
 (not (and c_99_1 c_99_5)))
(assert
 (not (and c_99_1 c_99_6)))
(assert
 (not (and c_99_1 c_99_7)))
(assert
 (not (and c_99_1 c_99_8)))
(assert
 (not (and c_99_2 c_99_3)))
(assert
 (not (and c_99_2 c_99_4)))
(assert
 (not (and c_99_2 c_99_5)))
(assert
 (not (and c_99_2 c_99_6)))
(assert
 (not (and c_99_2 c_99_7)))
(assert
 (not (and c_99_2 c_99_8)))
(assert
 (not (and c_99_3 c_99_4)))
(assert
 (not (and c_99_3 c_99_5)))
(assert
 (not (and c_99_3 c_99_6)))
(assert
 (not (and c_99_3 c_99_7)))
(assert
 (not (and c_99_3 c_99_8)))
(assert
 (not (and c_99_4 c_99_5)))
(assert
 (not (and c_99_4 c_99_6)))
(assert
 (not (and c_99_4 c_99_7)))
(assert
 (not (and c_99_4 c_99_8)))
(assert
 (not (and c_99_5 c_99_6)))
(assert
 (not (and c_99_5 c_99_7)))
(assert
 (not (and c_99_5 c_99_8)))
(assert
 (not (and c_99_6 c_99_7)))
(assert
 (not (and c_99_6 c_99_8)))
(assert
 (not (and c_99_7 c_99_8)))
(assert
 (let (($x9135 (or false c_100_0)))
 (let (($x9137 (or $x9135 c_100_1)))
 (let (($x9139 (or $x9137 c_100_2)))
 (let (($x9141 (or $x9139 c_100_3)))
 (let (($x9143 (or $x9141 c_100_4)))
 (let (($x9145 (or $x9143 c_100_5)))
 (let (($x9147 (or $x9145 c_100_6)))
 (let (($x9149 (or $x9147 c_100_7)))
 (or $x9149 c_100_8))))))))))
(assert
 (not (and c_100_0 c_100_1)))
(assert
 (not (and c_100_0 c_100_2)))
(assert
 (not (and c_100_0 c_100_3)))
(assert
 (not (and c_100_0 c_100_4)))
(assert
 (not (and c_100_0 c_100_5)))
(assert
 (not (and c_100_0 c_100_6)))
(assert
 (not (and c_100_0 c_100_7)))
(assert
 (not (and c_100_0 c_100_8)))
(assert
 (not (and c_100_1 c_100_2)))
(assert
 (not (and c_100_1 c_100_3)))
(assert
 (not (and c_100_1 c_100_4)))
(assert
 (not (and c_100_1 c_100_5)))
(assert
 (not (and c_100_1 c_100_6)))
(assert
 (not (and c_100_1 c_100_7)))
(assert
 (not (and c_100_1 c_100_8)))
(assert
 (not (and c_100_2 c_100_3)))
(assert
 (not (and c_100_2 c_100_4)))
(assert
 (not (and c_100_2 c_100_5)))
(assert
 (not (and c_100_2 c_100_6)))
(assert
 (not (and c_100_2 c_100_7)))
(assert
 (not (and c_100_2 c_100_8)))
(assert
 (not (and c_100_3 c_100_4)))
(assert
 (not (and c_100_3 c_100_5)))
(assert
 (not (and c_100_3 c_100_6)))
(assert
 (not (and c_100_3 c_100_7)))
(assert
 (not (and c_100_3 c_100_8)))
(assert
 (not (and c_100_4 c_100_5)))
(assert
 (not (and c_100_4 c_100_6)))
(assert
 (not (and c_100_4 c_100_7)))
(assert
 (not (and c_100_4 c_100_8)))
(assert
 (not (and c_100_5 c_100_6)))
(assert
 (not (and c_100_5 c_100_7)))
(assert
 (not (and c_100_5 c_100_8)))
(assert
 (not (and c_100_6 c_100_7)))
(assert
 (not (and c_100_6 c_100_8)))
(assert
 (not (and c_100_7 c_100_8)))
(assert
 (let (($x9225 (or false c_101_0)))
 (let (($x9227 (or $x9225 c_101_1)))
 (let (($x9229 (or $x9227 c_101_2)))
 (let (($x9231 (or $x9229 c_101_3)))
 (let (($x9233 (or $x9231 c_101_4)))
 (let (($x9235 (or $x9233 c_101_5)))
 (let (($x9237 (or $x9235 c_101_6)))
 (let (($x9239 (or $x9237 c_101_7)))
 (or $x9239 c_101_8))))))))))
(assert
 (not (and c_101_0 c_101_1)))
(assert
 (not (and c_101_0 c_101_2)))
(assert
 (not (and c_101_0 c_101_3)))
(assert
 (not (and c_101_0 c_101_4)))
(assert
 (not (and c_101_0 c_101_5)))
(assert
 (not (and c_101_0 c_101_6)))
(assert
 (not (and c_101_0 c_101_7)))
(assert
 (not (and c_101_0 c_101_8)))
(assert
 (not (and c_101_1 c_101_2)))
(assert
 (not (and c_101_1 c_101_3)))
(assert
 (not (and c_101_1 c_101_4)))
(assert
 (not (and c_101_1 c_101_5)))
(assert
 (not (and c_101_1 c_101_6)))
(assert
 (not (and c_101_1 c_101_7)))
(assert
 (not (and c_101_1 c_101_8)))
(assert
 (not (and c_101_2 c_101_3)))
(assert
 (not (and c_101_2 c_101_4)))
(assert
 (not (and c_101_2 c_101_5)))
(assert
 (not (and c_101_2 c_101_6)))
(assert
 (not (and c_101_2 c_101_7)))
(assert
 (not (and c_101_2 c_101_8)))
(assert
 (not (and c_101_3 c_101_4)))
(assert
 (not (and c_101_3 c_101_5)))
(assert
 (not (and c_101_3 c_101_6)))
(assert
 (not (and c_101_3 c_101_7)))
(assert
 (not (and c_101_3 c_101_8)))
(assert
 (not (and c_101_4 c_101_5)))
(assert
 (not (and c_101_4 c_101_6)))
(assert
 (not (and c_101_4 c_101_7)))
(assert
 (not (and c_101_4 c_101_8)))
(assert
 (not (and c_101_5 c_101_6)))
(assert
 (not (and c_101_5 c_101_7)))
(assert
 (not (and c_101_5 c_101_8)))
(assert
 (not (and c_101_6 c_101_7)))
(assert
 (not (and c_101_6 c_101_8)))
(assert
 (not (and c_101_7 c_101_8)))
(assert
 (let (($x9315 (or false c_102_0)))
 (let (($x9317 (or $x9315 c_102_1)))
 (let (($x9319 (or $x9317 c_102_2)))
 (let (($x9321 (or $x9319 c_102_3)))
 (let (($x9323 (or $x9321 c_102_4)))
 (let (($x9325 (or $x9323 c_102_5)))
 (let (($x9327 (or $x9325 c_102_6)))
 (let (($x9329 (or $x9327 c_102_7)))
 (or $x9329 c_102_8))))))))))
(assert
 (not (and c_102_0 c_102_1)))
(assert
 (not (and c_102_0 c_102_2)))
(assert
 (not (and c_102_0 c_102_3)))
(assert
 (not (and c_102_0 c_102_4)))
(assert
 (not (and c_102_0 c_102_5)))
(assert
 (not (and c_102_0 c_102_6)))
(assert
 (not (and c_102_0 c_102_7)))
(assert
 (not (and c_102_0 c_102_8)))
(assert
 (not (and c_102_1 c_102_2)))
(assert
 (not (and c_102_1 c_102_3)))
(assert
 (not (and c_102_1 c_102_4)))
(assert
 (not (and c_102_1 c_102_5)))
(assert
 (not (and c_102_1 c_102_6)))
(assert
 (not (and c_102_1 c_102_7)))
(assert
 (not (and c_102_1 c_102_8)))
(assert
 (not (and c_102_2 c_102_3)))
(assert
 (not (and c_102_2 c_102_4)))
(assert
 (not (and c_102_2 c_102_5)))
(assert
 (not (and c_102_2 c_102_6)))
(assert
 (not (and c_102_2 c_102_7)))
(assert
 (not (and c_102_2 c_102_8)))
(assert
 (not (and c_102_3 c_102_4)))
(assert
 (not (and c_102_3 c_102_5)))
(assert
 (not (and c_102_3 c_102_6)))
(assert
 (not (and c_102_3 c_102_7)))
(assert
 (not (and c_102_3 c_102_8)))
(assert
 (not (and c_102_4 c_102_5)))
(assert
 (not (and c_102_4 c_102_6)))
(assert
 (not (and c_102_4 c_102_7)))
(assert
 (not (and c_102_4 c_102_8)))
(assert
 (not (and c_102_5 c_102_6)))
(assert
 (not (and c_102_5 c_102_7)))
(assert
 (not (and c_102_5 c_102_8)))
(assert
 (not (and c_102_6 c_102_7)))
(assert
 (not (and c_102_6 c_102_8)))
(assert
 (not (and c_102_7 c_102_8)))
(assert
 (let (($x9405 (or false c_103_0)))
 (let (($x9407 (or $x9405 c_103_1)))
 (let (($x9409 (or $x9407 c_103_2)))
 (let (($x9411 (or $x9409 c_103_3)))
 (let (($x9413 (or $x9411 c_103_4)))
 (let (($x9415 (or $x9413 c_103_5)))
 (let (($x9417 (or $x9415 c_103_6)))
 (let (($x9419 (or $x9417 c_103_7)))
 (or $x9419 c_103_8))))))))))
(assert
 (not (and c_103_0 c_103_1)))
(assert
 (not (and c_103_0 c_103_2)))
(assert
 (not (and c_103_0 c_103_3)))
(assert
 (not (and c_103_0 c_103_4)))
(assert
 (not (and c_103_0 c_103_5)))
(assert
 (not (and c_103_0 c_103_6)))
(assert
 (not (and c_103_0 c_103_7)))
(assert
 (not (and c_103_0 c_103_8)))
(assert
 (not (and c_103_1 c_103_2)))
(assert
 (not (and c_103_1 c_103_3)))
(assert
 (not (and c_103_1 c_103_4)))
(assert
 (not (and c_103_1 c_103_5)))
(assert
 (not (and c_103_1 c_103_6)))
(assert
 (not (and c_103_1 c_103_7)))
(assert
 (not (and c_103_1 c_103_8)))
(assert
 (not (and c_103_2 c_103_3)))
(assert
 (not (and c_103_2 c_103_4)))
(assert
 (not (and c_103_2 c_103_5)))
(assert
 (not (and c_103_2 c_103_6)))
(assert
 (not (and c_103_2 c_103_7)))
(assert
 (not (and c_103_2 c_103_8)))
(assert
 (not (and c_103_3 c_103_4)))
(assert
 (not (and c_103_3 c_103_5)))
(assert
 (not (and c_103_3 c_103_6)))
(assert
 (not (and c_103_3 c_103_7)))
(assert
 (not (and c_103_3 c_103_8)))
(assert
 (not (and c_103_4 c_103_5)))
(assert
 (not (and c_103_4 c_103_6)))
(assert
 (not (and c_103_4 c_103_7)))
(assert
 (not (and c_103_4 c_103_8)))
(assert
 (not (and c_103_5 c_103_6)))
(assert
 (not (and c_103_5 c_103_7)))
(assert
 (not (and c_103_5 c_103_8)))
(assert
 (not (and c_103_6 c_103_7)))
(assert
 (not (and c_103_6 c_103_8)))
(assert
 (not (and c_103_7 c_103_8)))
(assert
 (let (($x9495 (or false c_104_0)))
 (let (($x9497 (or $x9495 c_104_1)))
 (let (($x9499 (or $x9497 c_104_2)))
 (let (($x9501 (or $x9499 c_104_3)))
 (let (($x9503 (or $x9501 c_104_4)))
 (let (($x9505 (or $x9503 c_104_5)))
 (let (($x9507 (or $x9505 c_104_6)))
 (let (($x9509 (or $x9507 c_104_7)))
 (or $x9509 c_104_8))))))))))
(assert
 (not (and c_104_0 c_104_1)))
(assert
 (not (and c_104_0 c_104_2)))
(assert
 (not (and c_104_0 c_104_3)))
(assert
 (not (and c_104_0 c_104_4)))
(assert
 (not (and c_104_0 c_104_5)))
(assert
 (not (and c_104_0 c_104_6)))
(assert
 (not (and c_104_0 c_104_7)))
(assert
 (not (and c_104_0 c_104_8)))
(assert
 (not (and c_104_1 c_104_2)))
(assert
 (not (and c_104_1 c_104_3)))
(assert
 (not (and c_104_1 c_104_4)))
(assert
 (not (and c_104_1 c_104_5)))
(assert
 (not (and c_104_1 c_104_6)))
(assert
 (not (and c_104_1 c_104_7)))
(assert
 (not (and c_104_1 c_104_8)))
(assert
 (not (and c_104_2 c_104_3)))
(assert
 (not (and c_104_2 c_104_4)))
(assert
 (not (and c_104_2 c_104_5)))
(assert
 (not (and c_104_2 c_104_6)))
(assert
 (not (and c_104_2 c_104_7)))
(assert
 (not (and c_104_2 c_104_8)))
(assert
 (not (and c_104_3 c_104_4)))
(assert
 (not (and c_104_3 c_104_5)))
(assert
 (not (and c_104_3 c_104_6)))
(assert
 (not (and c_104_3 c_104_7)))
(assert
 (not (and c_104_3 c_104_8)))
(assert
 (not (and c_104_4 c_104_5)))
(assert
 (not (and c_104_4 c_104_6)))
(assert
 (not (and c_104_4 c_104_7)))
(assert
 (not (and c_104_4 c_104_8)))
(assert
 (not (and c_104_5 c_104_6)))
(assert
 (not (and c_104_5 c_104_7)))
(assert
 (not (and c_104_5 c_104_8)))
(assert
 (not (and c_104_6 c_104_7)))
(assert
 (not (and c_104_6 c_104_8)))
(assert
 (not (and c_104_7 c_104_8)))
(assert
 (let (($x9585 (or false c_105_0)))
 (let (($x9587 (or $x9585 c_105_1)))
 (let (($x9589 (or $x9587 c_105_2)))
 (let (($x9591 (or $x9589 c_105_3)))
 (let (($x9593 (or $x9591 c_105_4)))
 (let (($x9595 (or $x9593 c_105_5)))
 (let (($x9597 (or $x9595 c_105_6)))
 (let (($x9599 (or $x9597 c_105_7)))
 (or $x9599 c_105_8))))))))))
(assert
 (not (and c_105_0 c_105_1)))
(assert
 (not (and c_105_0 c_105_2)))
(assert
 (not (and c_105_0 c_105_3)))
(assert
 (not (and c_105_0 c_105_4)))
(assert
 (not (and c_105_0 c_105_5)))
(assert
 (not (and c_105_0 c_105_6)))
(assert
 (not (and c_105_0 c_105_7)))
(assert
 (not (and c_105_0 c_105_8)))
(assert
 (not (and c_105_1 c_105_2)))
(assert
 (not (and c_105_1 c_105_3)))
(assert
 (not (and c_105_1 c_105_4)))
(assert
 (not (and c_105_1 c_105_5)))
(assert
 (not (and c_105_1 c_105_6)))
(assert
 (not (and c_105_1 c_105_7)))
(assert
 (not (and c_105_1 c_105_8)))
(assert
 (not (and c_105_2 c_105_3)))
(assert
 (not (and c_105_2 c_105_4)))
(assert
 (not (and c_105_2 c_105_5)))
(assert
 (not (and c_105_2 c_105_6)))
(assert
 (not (and c_105_2 c_105_7)))
(assert
 (not (and c_105_2 c_105_8)))
(assert
 (not (and c_105_3 c_105_4)))
(assert
 (not (and c_105_3 c_105_5)))
(assert
 (not (and c_105_3 c_105_6)))
(assert
 (not (and c_105_3 c_105_7)))
(assert
 (not (and c_105_3 c_105_8)))
(assert
 (not (and c_105_4 c_105_5)))
(assert
 (not (and c_105_4 c_105_6)))
(assert
 (not (and c_105_4 c_105_7)))
(assert
 (not (and c_105_4 c_105_8)))
(assert
 (not (and c_105_5 c_105_6)))
(assert
 (not (and c_105_5 c_105_7)))
(assert
 (not (and c_105_5 c_105_8)))
(assert
 (not (and c_105_6 c_105_7)))
(assert
 (not (and c_105_6 c_105_8)))
(assert
 (not (and c_105_7 c_105_8)))
(assert
 (let (($x9675 (or false c_106_0)))
 (let (($x9677 (or $x9675 c_106_1)))
 (let (($x9679 (or $x9677 c_106_2)))
 (let (($x9681 (or $x9679 c_106_3)))
 (let (($x9683 (or $x9681 c_106_4)))
 (let (($x9685 (or $x9683 c_106_5)))
 (let (($x9687 (or $x9685 c_106_6)))
 (let (($x9689 (or $x9687 c_106_7)))
 (or $x9689 c_106_8))))))))))
(assert
 (not (and c_106_0 c_106_1)))
(assert
 (not (and c_106_0 c_106_2)))
(assert
 (not (and c_106_0 c_106_3)))
(assert
 (not (and c_106_0 c_106_4)))
(assert
 (not (and c_106_0 c_106_5)))
(assert
 (not (and c_106_0 c_106_6)))
(assert
 (not (and c_106_0 c_106_7)))
(assert
 (not (and c_106_0 c_106_8)))
(assert
 (not (and c_106_1 c_106_2)))
(assert
 (not (and c_106_1 c_106_3)))
(assert
 (not (and c_106_1 c_106_4)))
(assert
 (not (and c_106_1 c_106_5)))
(assert
 (not (and c_106_1 c_106_6)))
(assert
 (not (and c_106_1 c_106_7)))
(assert
 (not (and c_106_1 c_106_8)))
(assert
 (not (and c_106_2 c_106_3)))
(assert
 (not (and c_106_2 c_106_4)))
(assert
 (not (and c_106_2 c_106_5)))
(assert
 (not (and c_106_2 c_106_6)))
(assert
 (not (and c_106_2 c_106_7)))
(assert
 (not (and c_106_2 c_106_8)))
(assert
 (not (and c_106_3 c_106_4)))
(assert
 (not (and c_106_3 c_106_5)))
(assert
 (not (and c_106_3 c_106_6)))
(assert
 (not (and c_106_3 c_106_7)))
(assert
 (not (and c_106_3 c_106_8)))
(assert
 (not (and c_106_4 c_106_5)))
(assert
 (not (and c_106_4 c_106_6)))
(assert
 (not (and c_106_4 c_106_7)))
(assert
 (not (and c_106_4 c_106_8)))
(assert
 (not (and c_106_5 c_106_6)))
(assert
 (not (and c_106_5 c_106_7)))
(assert
 (not (and c_106_5 c_106_8)))
(assert
 (not (and c_106_6 c_106_7)))
(assert
 (not (and c_106_6 c_106_8)))
(assert
 (not (and c_106_7 c_106_8)))
(assert
 (let (($x9765 (or false c_107_0)))
 (let (($x9767 (or $x9765 c_107_1)))
 (let (($x9769 (or $x9767 c_107_2)))
 (let (($x9771 (or $x9769 c_107_3)))
 (let (($x9773 (or $x9771 c_107_4)))
 (let (($x9775 (or $x9773 c_107_5)))
 (let (($x9777 (or $x9775 c_107_6)))
 (let (($x9779 (or $x9777 c_107_7)))
 (or $x9779 c_107_8))))))))))
(assert
 (not (and c_107_0 c_107_1)))
(assert
 (not (and c_107_0 c_107_2)))
(assert
 (not (and c_107_0 c_107_3)))
(assert
 (not (and c_107_0 c_107_4)))
(assert
 (not (and c_107_0 c_107_5)))
(assert
 (not (and c_107_0 c_107_6)))
(assert
 (not (and c_107_0 c_107_7)))
(assert
 (not (and c_107_0 c_107_8)))
(assert
 (not (and c_107_1 c_107_2)))
(assert
 (not (and c_107_1 c_107_3)))
(assert
 (not (and c_107_1 c_107_4)))
(assert
 (not (and c_107_1 c_107_5)))
(assert
 (not (and c_107_1 c_107_6)))
(assert
 (not (and c_107_1 c_107_7)))
(assert
 (not (and c_107_1 c_107_8)))
(assert
 (not (and c_107_2 c_107_3)))
(assert
 (not (and c_107_2 c_107_4)))
(assert
 (not (and c_107_2 c_107_5)))
(assert
 (not (and c_107_2 c_107_6)))
(assert
 (not (and c_107_2 c_107_7)))
(assert
 (not (and c_107_2 c_107_8)))
(assert
 (not (and c_107_3 c_107_4)))
(assert
 (not (and c_107_3 c_107_5)))
(assert
 (not (and c_107_3 c_107_6)))
(assert
 (not (and c_107_3 c_107_7)))
(assert
 (not (and c_107_3 c_107_8)))
(assert
 (not (and c_107_4 c_107_5)))
(assert
 (not (and c_107_4 c_107_6)))
(assert
 (not (and c_107_4 c_107_7)))
(assert
 (not (and c_107_4 c_107_8)))
(assert
 (not (and c_107_5 c_107_6)))
(assert
 (not (and c_107_5 c_107_7)))
(assert
 (not (and c_107_5 c_107_8)))
(assert
 (not (and c_107_6 c_107_7)))
(assert
 (not (and c_107_6 c_107_8)))
(assert
 (not (and c_107_7 c_107_8)))
(assert
 (let (($x9855 (or false c_108_0)))
 (let (($x9857 (or $x9855 c_108_1)))
 (let (($x9859 (or $x9857 c_108_2)))
 (let (($x9861 (or $x9859 c_108_3)))
 (let (($x9863 (or $x9861 c_108_4)))
 (let (($x9865 (or $x9863 c_108_5)))
 (let (($x9867 (or $x9865 c_108_6)))
 (let (($x9869 (or $x9867 c_108_7)))
 (or $x9869 c_108_8))))))))))
(assert
 (not (and c_108_0 c_108_1)))
(assert
 (not (and c_108_0 c_108_2)))
(assert
 (not (and c_108_0 c_108_3)))
(assert
 (not (and c_108_0 c_108_4)))
(assert
 (not (and c_108_0 c_108_5)))
(assert
 (not (and c_108_0 c_108_6)))
(assert
 (not (and c_108_0 c_108_7)))
(assert
 (not (and c_108_0 c_108_8)))
(assert
 (not (and c_108_1 c_108_2)))
(assert
 (not (and c_108_1 c_108_3)))
(assert
 (not (and c_108_1 c_108_4)))
(assert
 (not (and c_108_1 c_108_5)))
(assert
 (not (and c_108_1 c_108_6)))
(assert
 (not (and c_108_1 c_108_7)))
(assert
 (not (and c_108_1 c_108_8)))
(assert
 (not (and c_108_2 c_108_3)))
(assert
 (not (and c_108_2 c_108_4)))
(assert
 (not (and c_108_2 c_108_5)))
(assert
 (not (and c_108_2 c_108_6)))
(assert
 (not (and c_108_2 c_108_7)))
(assert
 (not (and c_108_2 c_108_8)))
(assert
 (not (and c_108_3 c_108_4)))
(assert
 (not (and c_108_3 c_108_5)))
(assert
 (not (and c_108_3 c_108_6)))
(assert
 (not (and c_108_3 c_108_7)))
(assert
 (not (and c_108_3 c_108_8)))
(assert
 (not (and c_108_4 c_108_5)))
(assert
 (not (and c_108_4 c_108_6)))
(assert
 (not (and c_108_4 c_108_7)))
(assert
 (not (and c_108_4 c_108_8)))
(assert
 (not (and c_108_5 c_108_6)))
(assert
 (not (and c_108_5 c_108_7)))
(assert
 (not (and c_108_5 c_108_8)))
(assert
 (not (and c_108_6 c_108_7)))
(assert
 (not (and c_108_6 c_108_8)))
(assert
 (not (and c_108_7 c_108_8)))
(assert
 (let (($x9945 (or false c_109_0)))
 (let (($x9947 (or $x9945 c_109_1)))
 (let (($x9949 (or $x9947 c_109_2)))
 (let (($x9951 (or $x9949 c_109_3)))
 (let (($x9953 (or $x9951 c_109_4)))
 (let (($x9955 (or $x9953 c_109_5)))
 (let (($x9957 (or $x9955 c_109_6)))
 (let (($x9959 (or $x9957 c_109_7)))
 (or $x9959 c_109_8))))))))))
(assert
 (not (and c_109_0 c_109_1)))
(assert
 (not (and c_109_0 c_109_2)))
(assert
 (not (and c_109_0 c_109_3)))
(assert
 (not (and c_109_0 c_109_4)))
(assert
 (not (and c_109_0 c_109_5)))
(assert
 (not (and c_109_0 c_109_6)))
(assert
 (not (and c_109_0 c_109_7)))
(assert
 (not (and c_109_0 c_109_8)))
(assert
 (not (and c_109_1 c_109_2)))
(assert
 (not (and c_109_1 c_109_3)))
(assert
 (not (and c_109_1 c_109_4)))
(assert
 (not (and c_109_1 c_109_5)))
(assert
 (not (and c_109_1 c_109_6)))
(assert
 (not (and c_109_1 c_109_7)))
(assert
 (not (and c_109_1 c_109_8)))
(assert
 (not (and c_109_2 c_109_3)))
(assert
 (not (and c_109_2 c_109_4)))
(assert
 (not (and c_109_2 c_109_5)))
(assert
 (not (and c_109_2 c_109_6)))
(assert
 (not (and c_109_2 c_109_7)))
(assert
 (not (and c_109_2 c_109_8)))
(assert
 (not (and c_109_3 c_109_4)))
(assert
 (not (and c_109_3 c_109_5)))
(assert
 (not (and c_109_3 c_109_6)))
(assert
 (not (and c_109_3 c_109_7)))
(assert
 (not (and c_109_3 c_109_8)))
(assert
 (not (and c_109_4 c_109_5)))
(assert
 (not (and c_109_4 c_109_6)))
(assert
 (not (and c_109_4 c_109_7)))
(assert
 (not (and c_109_4 c_109_8)))
(assert
 (not (and c_109_5 c_109_6)))
(assert
 (not (and c_109_5 c_109_7)))
(assert
 (not (and c_109_5 c_109_8)))
(assert
 (not (and c_109_6 c_109_7)))
(assert
 (not (and c_109_6 c_109_8)))
(assert
 (not (and c_109_7 c_109_8)))
(assert
 (let (($x10035 (or false c_110_0)))
 (let (($x10037 (or $x10035 c_110_1)))
 (let (($x10039 (or $x10037 c_110_2)))
 (let (($x10041 (or $x10039 c_110_3)))
 (let (($x10043 (or $x10041 c_110_4)))
 (let (($x10045 (or $x10043 c_110_5)))
 (let (($x10047 (or $x10045 c_110_6)))
 (let (($x10049 (or $x10047 c_110_7)))
 (or $x10049 c_110_8))))))))))
(assert
 (not (and c_110_0 c_110_1)))
(assert
 (not (and c_110_0 c_110_2)))
(assert
 (not (and c_110_0 c_110_3)))
(assert
 (not (and c_110_0 c_110_4)))
(assert
 (not (and c_110_0 c_110_5)))
(assert
 (not (and c_110_0 c_110_6)))
(assert
 (not (and c_110_0 c_110_7)))
(assert
 (not (and c_110_0 c_110_8)))
(assert
 (not (and c_110_1 c_110_2)))
(assert
 (not (and c_110_1 c_110_3)))
(assert
 (not (and c_110_1 c_110_4)))
(assert
 (not (and c_110_1 c_110_5)))
(assert
 (not (and c_110_1 c_110_6)))
(assert
 (not (and c_110_1 c_110_7)))
(assert
 (not (and c_110_1 c_110_8)))
(assert
 (not (and c_110_2 c_110_3)))
(assert
 (not (and c_110_2 c_110_4)))
(assert
 (not (and c_110_2 c_110_5)))
(assert
 (not (and c_110_2 c_110_6)))
(assert
 (not (and c_110_2 c_110_7)))
(assert
 (not (and c_110_2 c_110_8)))
(assert
 (not (and c_110_3 c_110_4)))
(assert
 (not (and c_110_3 c_110_5)))
(assert
 (not (and c_110_3 c_110_6)))
(assert
 (not (and c_110_3 c_110_7)))
(assert
 (not (and c_110_3 c_110_8)))
(assert
 (not (and c_110_4 c_110_5)))
(assert
 (not (and c_110_4 c_110_6)))
(assert
 (not (and c_110_4 c_110_7)))
(assert
 (not (and c_110_4 c_110_8)))
(assert
 (not (and c_110_5 c_110_6)))
(assert
 (not (and c_110_5 c_110_7)))
(assert
 (not (and c_110_5 c_110_8)))
(assert
 (not (and c_110_6 c_110_7)))
(assert
 (not (and c_110_6 c_110_8)))
(assert
 (not (and c_110_7 c_110_8)))
(assert
 (let (($x10125 (or false c_111_0)))
 (let (($x10127 (or $x10125 c_111_1)))
 (let (($x10129 (or $x10127 c_111_2)))
 (let (($x10131 (or $x10129 c_111_3)))
 (let (($x10133 (or $x10131 c_111_4)))
 (let (($x10135 (or $x10133 c_111_5)))
 (let (($x10137 (or $x10135 c_111_6)))
 (let (($x10139 (or $x10137 c_111_7)))
 (or $x10139 c_111_8))))))))))
(assert
 (not (and c_111_0 c_111_1)))
(assert
 (not (and c_111_0 c_111_2)))
(assert
 (not (and c_111_0 c_111_3)))
(assert
 (not (and c_111_0 c_111_4)))
(assert
 (not (and c_111_0 c_111_5)))
(assert
 (not (and c_111_0 c_111_6)))
(assert
 (not (and c_111_0 c_111_7)))
(assert
 (not (and c_111_0 c_111_8)))
(assert
 (not (and c_111_1 c_111_2)))
(assert
 (not (and c_111_1 c_111_3)))
(assert
 (not (and c_111_1 c_111_4)))
(assert
 (not (and c_111_1 c_111_5)))
(assert
 (not (and c_111_1 c_111_6)))
(assert
 (not (and c_111_1 c_111_7)))
(assert
 (not (and c_111_1 c_111_8)))
(assert
 (not (and c_111_2 c_111_3)))
(assert
 (not (and c_111_2 c_111_4)))
(assert
 (not (and c_111_2 c_111_5)))
(assert
 (not (and c_111_2 c_111_6)))
(assert
 (not (and c_111_2 c_111_7)))
(assert
 (not (and c_111_2 c_111_8)))
(assert
 (not (and c_111_3 c_111_4)))
(assert
 (not (and c_111_3 c_111_5)))
(assert
 (not (and c_111_3 c_111_6)))
(assert
 (not (and c_111_3 c_111_7)))
(assert
 (not (and c_111_3 c_111_8)))
(assert
 (not (and c_111_4 c_111_5)))
(assert
 (not (and c_111_4 c_111_6)))
(assert
 (not (and c_111_4 c_111_7)))
(assert
 (not (and c_111_4 c_111_8)))
(assert
 (not (and c_111_5 c_111_6)))
(assert
 (not (and c_111_5 c_111_7)))
(assert
 (not (and c_111_5 c_111_8)))
(assert
 (not (and c_111_6 c_111_7)))
(assert
 (not (and c_111_6 c_111_8)))
(assert
 (not (and c_111_7 c_111_8)))
(assert
 (let (($x10215 (or false c_112_0)))
 (let (($x10217 (or $x10215 c_112_1)))
 (let (($x10219 (or $x10217 c_112_2)))
 (let (($x10221 (or $x10219 c_112_3)))
 (let (($x10223 (or $x10221 c_112_4)))
 (let (($x10225 (or $x10223 c_112_5)))
 (let (($x10227 (or $x10225 c_112_6)))
 (let (($x10229 (or $x10227 c_112_7)))
 (or $x10229 c_112_8))))))))))
(assert
 (not (and c_112_0 c_112_1)))
(assert
 (not (and c_112_0 c_112_2)))
(assert
 (not (and c_112_0 c_112_3)))
(assert
 (not (and c_112_0 c_112_4)))
(assert
 (not (and c_112_0 c_112_5)))
(assert
 (not (and c_112_0 c_112_6)))
(assert
 (not (and c_112_0 c_112_7)))
(assert
 (not (and c_112_0 c_112_8)))
(assert
 (not (and c_112_1 c_112_2)))
(assert
 (not (and c_112_1 c_112_3)))
(assert
 (not (and c_112_1 c_112_4)))
(assert
 (not (and c_112_1 c_112_5)))
(assert
 (not (and c_112_1 c_112_6)))
(assert
 (not (and c_112_1 c_112_7)))
(assert
 (not (and c_112_1 c_112_8)))
(assert
 (not (and c_112_2 c_112_3)))
(assert
 (not (and c_112_2 c_112_4)))
(assert
 (not (and c_112_2 c_112_5)))
(assert
 (not (and c_112_2 c_112_6)))
(assert
 (not (and c_112_2 c_112_7)))
(assert
 (not (and c_112_2 c_112_8)))
(assert
 (not (and c_112_3 c_112_4)))
(assert
 (not (and c_112_3 c_112_5)))
(assert
 (not (and c_112_3 c_112_6)))
(assert
 (not (and c_112_3 c_112_7)))
(assert
 (not (and c_112_3 c_112_8)))
(assert
 (not (and c_112_4 c_112_5)))
(assert
 (not (and c_112_4 c_112_6)))
(assert
 (not (and c_112_4 c_112_7)))
(assert
 (not (and c_112_4 c_112_8)))
(assert
 (not (and c_112_5 c_112_6)))
(assert
 (not (and c_112_5 c_112_7)))
(assert
 (not (and c_112_5 c_112_8)))
(assert
 (not (and c_112_6 c_112_7)))
(assert
 (not (and c_112_6 c_112_8)))
(assert
 (not (and c_112_7 c_112_8)))
(assert
 (let (($x10305 (or false c_113_0)))
 (let (($x10307 (or $x10305 c_113_1)))
 (let (($x10309 (or $x10307 c_113_2)))
 (let (($x10311 (or $x10309 c_113_3)))
 (let (($x10313 (or $x10311 c_113_4)))
 (let (($x10315 (or $x10313 c_113_5)))
 (let (($x10317 (or $x10315 c_113_6)))
 (let (($x10319 (or $x10317 c_113_7)))
 (or $x10319 c_113_8))))))))))
(assert
 (not (and c_113_0 c_113_1)))
(assert
 (not (and c_113_0 c_113_2)))
(assert
 (not (and c_113_0 c_113_3)))
(assert
 (not (and c_113_0 c_113_4)))
(assert
 (not (and c_113_0 c_113_5)))
(assert
 (not (and c_113_0 c_113_6)))
(assert
 (not (and c_113_0 c_113_7)))
(assert
 (not (and c_113_0 c_113_8)))
(assert
 (not (and c_113_1 c_113_2)))
(assert
 (not (and c_113_1 c_113_3)))
(assert
 (not (and c_113_1 c_113_4)))
(assert
 (not (and c_113_1 c_113_5)))
(assert
 (not (and c_113_1 c_113_6)))
(assert
 (not (and c_113_1 c_113_7)))
(assert
 (not (and c_113_1 c_113_8)))
(assert
 (not (and c_113_2 c_113_3)))
(assert
 (not (and c_113_2 c_113_4)))
(assert
 (not (and c_113_2 c_113_5)))
(assert
 (not (and c_113_2 c_113_6)))
(assert
 (not (and c_113_2 c_113_7)))
(assert
 (not (and c_113_2 c_113_8)))
(assert
 (not (and c_113_3 c_113_4)))
(assert
 (not (and c_113_3 c_113_5)))
(assert
 (not (and c_113_3 c_113_6)))
(assert
 (not (and c_113_3 c_113_7)))
(assert
 (not (and c_113_3 c_113_8)))
(assert
 (not (and c_113_4 c_113_5)))
(assert
 (not (and c_113_4 c_113_6)))
(assert
 (not (and c_113_4 c_113_7)))
(assert
 (not (and c_113_4 c_113_8)))
(assert
 (not (and c_113_5 c_113_6)))
(assert
 (not (and c_113_5 c_113_7)))
(assert
 (not (and c_113_5 c_113_8)))
(assert
 (not (and c_113_6 c_113_7)))
(assert
 (not (and c_113_6 c_113_8)))
(assert
 (not (and c_113_7 c_113_8)))
(assert
 (let (($x10395 (or false c_114_0)))
 (let (($x10397 (or $x10395 c_114_1)))
 (let (($x10399 (or $x10397 c_114_2)))
 (let (($x10401 (or $x10399 c_114_3)))
 (let (($x10403 (or $x10401 c_114_4)))
 (let (($x10405 (or $x10403 c_114_5)))
 (let (($x10407 (or $x10405 c_114_6)))
 (let (($x10409 (or $x10407 c_114_7)))
 (or $x10409 c_114_8))))))))))
(assert
 (not (and c_114_0 c_114_1)))
(assert
 (not (and c_114_0 c_114_2)))
(assert
 (not (and c_114_0 c_114_3)))
(assert
 (not (and c_114_0 c_114_4)))
(assert
 (not (and c_114_0 c_114_5)))
(assert
 (not (and c_114_0 c_114_6)))
(assert
 (not (and c_114_0 c_114_7)))
(assert
 (not (and c_114_0 c_114_8)))
(assert
 (not (and c_114_1 c_114_2)))
(assert
 (not (and c_114_1 c_114_3)))
(assert
 (not (and c_114_1 c_114_4)))
(assert
 (not (and c_114_1 c_114_5)))
(assert
 (not (and c_114_1 c_114_6)))
(assert
 (not (and c_114_1 c_114_7)))
(assert
 (not (and c_114_1 c_114_8)))
(assert
 (not (and c_114_2 c_114_3)))
(assert
 (not (and c_114_2 c_114_4)))
(assert
 (not (and c_114_2 c_114_5)))
(assert
 (not (and c_114_2 c_114_6)))
(assert
 (not (and c_114_2 c_114_7)))
(assert
 (not (and c_114_2 c_114_8)))
(assert
 (not (and c_114_3 c_114_4)))
(assert
 (not (and c_114_3 c_114_5)))
(assert
 (not (and c_114_3 c_114_6)))
(assert
 (not (and c_114_3 c_114_7)))
(assert
 (not (and c_114_3 c_114_8)))
(assert
 (not (and c_114_4 c_114_5)))
(assert
 (not (and c_114_4 c_114_6)))
(assert
 (not (and c_114_4 c_114_7)))
(assert
 (not (and c_114_4 c_114_8)))
(assert
 (not (and c_114_5 c_114_6)))
(assert
 (not (and c_114_5 c_114_7)))
(assert
 (not (and c_114_5 c_114_8)))
(assert
 (not (and c_114_6 c_114_7)))
(assert
 (not (and c_114_6 c_114_8)))
(assert
 (not (and c_114_7 c_114_8)))
(assert
 (let (($x10485 (or false c_115_0)))
 (let (($x10487 (or $x10485 c_115_1)))
 (let (($x10489 (or $x10487 c_115_2)))
 (let (($x10491 (or $x10489 c_115_3)))
 (let (($x10493 (or $x10491 c_115_4)))
 (let (($x10495 (or $x10493 c_115_5)))
 (let (($x10497 (or $x10495 c_115_6)))
 (let (($x10499 (or $x10497 c_115_7)))
 (or $x10499 c_115_8))))))))))
(assert
 (not (and c_115_0 c_115_1)))
(assert
 (not (and c_115_0 c_115_2)))
(assert
 (not (and c_115_0 c_115_3)))
(assert
 (not (and c_115_0 c_115_4)))
(assert
 (not (and c_115_0 c_115_5)))
(assert
 (not (and c_115_0 c_115_6)))
(assert
 (not (and c_115_0 c_115_7)))
(assert
 (not (and c_115_0 c_115_8)))
(assert
 (not (and c_115_1 c_115_2)))
(assert
 (not (and c_115_1 c_115_3)))
(assert
 (not (and c_115_1 c_115_4)))
(assert
 (not (and c_115_1 c_115_5)))
(assert
 (not (and c_115_1 c_115_6)))
(assert
 (not (and c_115_1 c_115_7)))
(assert
 (not (and c_115_1 c_115_8)))
(assert
 (not (and c_115_2 c_115_3)))
(assert
 (not (and c_115_2 c_115_4)))
(assert
 (not (and c_115_2 c_115_5)))
(assert
 (not (and c_115_2 c_115_6)))
(assert
 (not (and c_115_2 c_115_7)))
(assert
 (not (and c_115_2 c_115_8)))
(assert
 (not (and c_115_3 c_115_4)))
(assert
 (not (and c_115_3 c_115_5)))
(assert
 (not (and c_115_3 c_115_6)))
(assert
 (not (and c_115_3 c_115_7)))
(assert
 (not (and c_115_3 c_115_8)))
(assert
 (not (and c_115_4 c_115_5)))
(assert
 (not (and c_115_4 c_115_6)))
(assert
 (not (and c_115_4 c_115_7)))
(assert
 (not (and c_115_4 c_115_8)))
(assert
 (not (and c_115_5 c_115_6)))
(assert
 (not (and c_115_5 c_115_7)))
(assert
 (not (and c_115_5 c_115_8)))
(assert
 (not (and c_115_6 c_115_7)))
(assert
 (not (and c_115_6 c_115_8)))
(assert
 (not (and c_115_7 c_115_8)))
(assert
 (let (($x10575 (or false c_116_0)))
 (let (($x10577 (or $x10575 c_116_1)))
 (let (($x10579 (or $x10577 c_116_2)))
 (let (($x10581 (or $x10579 c_116_3)))
 (let (($x10583 (or $x10581 c_116_4)))
 (let (($x10585 (or $x10583 c_116_5)))
 (let (($x10587 (or $x10585 c_116_6)))
 (let (($x10589 (or $x10587 c_116_7)))
 (or $x10589 c_116_8))))))))))
(assert
 (not (and c_116_0 c_116_1)))
(assert
 (not (and c_116_0 c_116_2)))
(assert
 (not (and c_116_0 c_116_3)))
(assert
 (not (and c_116_0 c_116_4)))
(assert
 (not (and c_116_0 c_116_5)))
(assert
 (not (and c_116_0 c_116_6)))
(assert
 (not (and c_116_0 c_116_7)))
(assert
 (not (and c_116_0 c_116_8)))
(assert
 (not (and c_116_1 c_116_2)))
(assert
 (not (and c_116_1 c_116_3)))
(assert
 (not (and c_116_1 c_116_4)))
(assert
 (not (and c_116_1 c_116_5)))
(assert
 (not (and c_116_1 c_116_6)))
(assert
 (not (and c_116_1 c_116_7)))
(assert
 (not (and c_116_1 c_116_8)))
(assert
 (not (and c_116_2 c_116_3)))
(assert
 (not (and c_116_2 c_116_4)))
(assert
 (not (and c_116_2 c_116_5)))
(assert
 (not (and c_116_2 c_116_6)))
(assert
 (not (and c_116_2 c_116_7)))
(assert
 (not (and c_116_2 c_116_8)))
(assert
 (not (and c_116_3 c_116_4)))
(assert
 (not (and c_116_3 c_116_5)))
(assert
 (not (and c_116_3 c_116_6)))
(assert
 (not (and c_116_3 c_116_7)))
(assert
 (not (and c_116_3 c_116_8)))
(assert
 (not (and c_116_4 c_116_5)))
(assert
 (not (and c_116_4 c_116_6)))
(assert
 (not (and c_116_4 c_116_7)))
(assert
 (not (and c_116_4 c_116_8)))
(assert
 (not (and c_116_5 c_116_6)))
(assert
 (not (and c_116_5 c_116_7)))
(assert
 (not (and c_116_5 c_116_8)))
(assert
 (not (and c_116_6 c_116_7)))
(assert
 (not (and c_116_6 c_116_8)))
(assert
 (not (and c_116_7 c_116_8)))
(assert
 (let (($x10665 (or false c_117_0)))
 (let (($x10667 (or $x10665 c_117_1)))
 (let (($x10669 (or $x10667 c_117_2)))
 (let (($x10671 (or $x10669 c_117_3)))
 (let (($x10673 (or $x10671 c_117_4)))
 (let (($x10675 (or $x10673 c_117_5)))
 (let (($x10677 (or $x10675 c_117_6)))
 (let (($x10679 (or $x10677 c_117_7)))
 (or $x10679 c_117_8))))))))))
(assert
 (not (and c_117_0 c_117_1)))
(assert
 (not (and c_117_0 c_117_2)))
(assert
 (not (and c_117_0 c_117_3)))
(assert
 (not (and c_117_0 c_117_4)))
(assert
 (not (and c_117_0 c_117_5)))
(assert
 (not (and c_117_0 c_117_6)))
(assert
 (not (and c_117_0 c_117_7)))
(assert
 (not (and c_117_0 c_117_8)))
(assert
 (not (and c_117_1 c_117_2)))
(assert
 (not (and c_117_1 c_117_3)))
(assert
 (not (and c_117_1 c_117_4)))
(assert
 (not (and c_117_1 c_117_5)))
(assert
 (not (and c_117_1 c_117_6)))
(assert
 (not (and c_117_1 c_117_7)))
(assert
 (not (and c_117_1 c_117_8)))
(assert
 (not (and c_117_2 c_117_3)))
(assert
 (not (and c_117_2 c_117_4)))
(assert
 (not (and c_117_2 c_117_5)))
(assert
 (not (and c_117_2 c_117_6)))
(assert
 (not (and c_117_2 c_117_7)))
(assert
 (not (and c_117_2 c_117_8)))
(assert
 (not (and c_117_3 c_117_4)))
(assert
 (not (and c_117_3 c_117_5)))
(assert
 (not (and c_117_3 c_117_6)))
(assert
 (not (and c_117_3 c_117_7)))
(assert
 (not (and c_117_3 c_117_8)))
(assert
 (not (and c_117_4 c_117_5)))
(assert
 (not (and c_117_4 c_117_6)))
(assert
 (not (and c_117_4 c_117_7)))
(assert
 (not (and c_117_4 c_117_8)))
(assert
 (not (and c_117_5 c_117_6)))
(assert
 (not (and c_117_5 c_117_7)))
(assert
 (not (and c_117_5 c_117_8)))
(assert
 (not (and c_117_6 c_117_7)))
(assert
 (not (and c_117_6 c_117_8)))
(assert
 (not (and c_117_7 c_117_8)))
(assert
 (let (($x10755 (or false c_118_0)))
 (let (($x10757 (or $x10755 c_118_1)))
 (let (($x10759 (or $x10757 c_118_2)))
 (let (($x10761 (or $x10759 c_118_3)))
 (let (($x10763 (or $x10761 c_118_4)))
 (let (($x10765 (or $x10763 c_118_5)))
 (let (($x10767 (or $x10765 c_118_6)))
 (let (($x10769 (or $x10767 c_118_7)))
 (or $x10769 c_118_8))))))))))
(assert
 (not (and c_118_0 c_118_1)))
(assert
 (not (and c_118_0 c_118_2)))
(assert
 (not (and c_118_0 c_118_3)))
(assert
 (not (and c_118_0 c_118_4)))
(assert
 (not (and c_118_0 c_118_5)))
(assert
 (not (and c_118_0 c_118_6)))
(assert
 (not (and c_118_0 c_118_7)))
(assert
 (not (and c_118_0 c_118_8)))
(assert
 (not (and c_118_1 c_118_2)))
(assert
 (not (and c_118_1 c_118_3)))
(assert
 (not (and c_118_1 c_118_4)))
(assert
 (not (and c_118_1 c_118_5)))
(assert
 (not (and c_118_1 c_118_6)))
(assert
 (not (and c_118_1 c_118_7)))
(assert
 (not (and c_118_1 c_118_8)))
(assert
 (not (and c_118_2 c_118_3)))
(assert
 (not (and c_118_2 c_118_4)))
(assert
 (not (and c_118_2 c_118_5)))
(assert
 (not (and c_118_2 c_118_6)))
(assert
 (not (and c_118_2 c_118_7)))
(assert
 (not (and c_118_2 c_118_8)))
(assert
 (not (and c_118_3 c_118_4)))
(assert
 (not (and c_118_3 c_118_5)))
(assert
 (not (and c_118_3 c_118_6)))
(assert
 (not (and c_118_3 c_118_7)))
(assert
 (not (and c_118_3 c_118_8)))
(assert
 (not (and c_118_4 c_118_5)))
(assert
 (not (and c_118_4 c_118_6)))
(assert
 (not (and c_118_4 c_118_7)))
(assert
 (not (and c_118_4 c_118_8)))
(assert
 (not (and c_118_5 c_118_6)))
(assert
 (not (and c_118_5 c_118_7)))
(assert
 (not (and c_118_5 c_118_8)))
(assert
 (not (and c_118_6 c_118_7)))
(assert
 (not (and c_118_6 c_118_8)))
(assert
 (not (and c_118_7 c_118_8)))
(assert
 (let (($x10845 (or false c_119_0)))
 (let (($x10847 (or $x10845 c_119_1)))
 (let (($x10849 (or $x10847 c_119_2)))
 (let (($x10851 (or $x10849 c_119_3)))
 (let (($x10853 (or $x10851 c_119_4)))
 (let (($x10855 (or $x10853 c_119_5)))
 (let (($x10857 (or $x10855 c_119_6)))
 (let (($x10859 (or $x10857 c_119_7)))
 (or $x10859 c_119_8))))))))))
(assert
 (not (and c_119_0 c_119_1)))
(assert
 (not (and c_119_0 c_119_2)))
(assert
 (not (and c_119_0 c_119_3)))
(assert
 (not (and c_119_0 c_119_4)))
(assert
 (not (and c_119_0 c_119_5)))
(assert
 (not (and c_119_0 c_119_6)))
(assert
 (not (and c_119_0 c_119_7)))
(assert
 (not (and c_119_0 c_119_8)))
(assert
 (not (and c_119_1 c_119_2)))
(assert
 (not (and c_119_1 c_119_3)))
(assert
 (not (and c_119_1 c_119_4)))
(assert
 (not (and c_119_1 c_119_5)))
(assert
 (not (and c_119_1 c_119_6)))
(assert
 (not (and c_119_1 c_119_7)))
(assert
 (not (and c_119_1 c_119_8)))
(assert
 (not (and c_119_2 c_119_3)))
(assert
 (not (and c_119_2 c_119_4)))
(assert
 (not (and c_119_2 c_119_5)))
(assert
 (not (and c_119_2 c_119_6)))
(assert
 (not (and c_119_2 c_119_7)))
(assert
 (not (and c_119_2 c_119_8)))
(assert
 (not (and c_119_3 c_119_4)))
(assert
 (not (and c_119_3 c_119_5)))
(assert
 (not (and c_119_3 c_119_6)))
(assert
 (not (and c_119_3 c_119_7)))
(assert
 (not (and c_119_3 c_119_8)))
(assert
 (not (and c_119_4 c_119_5)))
(assert
 (not (and c_119_4 c_119_6)))
(assert
 (not (and c_119_4 c_119_7)))
(assert
 (not (and c_119_4 c_119_8)))
(assert
 (not (and c_119_5 c_119_6)))
(assert
 (not (and c_119_5 c_119_7)))
(assert
 (not (and c_119_5 c_119_8)))
(assert
 (not (and c_119_6 c_119_7)))
(assert
 (not (and c_119_6 c_119_8)))
(assert
 (not (and c_119_7 c_119_8)))
(assert
 (let (($x10935 (or false c_120_0)))
 (let (($x10937 (or $x10935 c_120_1)))
 (let (($x10939 (or $x10937 c_120_2)))
 (let (($x10941 (or $x10939 c_120_3)))
 (let (($x10943 (or $x10941 c_120_4)))
 (let (($x10945 (or $x10943 c_120_5)))
 (let (($x10947 (or $x10945 c_120_6)))
 (let (($x10949 (or $x10947 c_120_7)))
 (or $x10949 c_120_8))))))))))
(assert
 (not (and c_120_0 c_120_1)))
(assert
 (not (and c_120_0 c_120_2)))
(assert
 (not (and c_120_0 c_120_3)))
(assert
 (not (and c_120_0 c_120_4)))
(assert
 (not (and c_120_0 c_120_5)))
(assert
 (not (and c_120_0 c_120_6)))
(assert
 (not (and c_120_0 c_120_7)))
(assert
 (not (and c_120_0 c_120_8)))
(assert
 (not (and c_120_1 c_120_2)))
(assert
 (not (and c_120_1 c_120_3)))
(assert
 (not (and c_120_1 c_120_4)))
(assert
 (not (and c_120_1 c_120_5)))
(assert
 (not (and c_120_1 c_120_6)))
(assert
 (not (and c_120_1 c_120_7)))
(assert
 (not (and c_120_1 c_120_8)))
(assert
 (not (and c_120_2 c_120_3)))
(assert
 (not (and c_120_2 c_120_4)))
(assert
 (not (and c_120_2 c_120_5)))
(assert
 (not (and c_120_2 c_120_6)))
(assert
 (not (and c_120_2 c_120_7)))
(assert
 (not (and c_120_2 c_120_8)))
(assert
 (not (and c_120_3 c_120_4)))
(assert
 (not (and c_120_3 c_120_5)))
(assert
 (not (and c_120_3 c_120_6)))
(assert
 (not (and c_120_3 c_120_7)))
(assert
 (not (and c_120_3 c_120_8)))
(assert
 (not (and c_120_4 c_120_5)))
(assert
 (not (and c_120_4 c_120_6)))
(assert
 (not (and c_120_4 c_120_7)))
(assert
 (not (and c_120_4 c_120_8)))
(assert
 (not (and c_120_5 c_120_6)))
(assert
 (not (and c_120_5 c_120_7)))
(assert
 (not (and c_120_5 c_120_8)))
(assert
 (not (and c_120_6 c_120_7)))
(assert
 (not (and c_120_6 c_120_8)))
(assert
 (not (and c_120_7 c_120_8)))
(assert
 (let (($x11025 (or false c_121_0)))
 (let (($x11027 (or $x11025 c_121_1)))
 (let (($x11029 (or $x11027 c_121_2)))
 (let (($x11031 (or $x11029 c_121_3)))
 (let (($x11033 (or $x11031 c_121_4)))
 (let (($x11035 (or $x11033 c_121_5)))
 (let (($x11037 (or $x11035 c_121_6)))
 (let (($x11039 (or $x11037 c_121_7)))
 (or $x11039 c_121_8))))))))))
(assert
 (not (and c_121_0 c_121_1)))
(assert
 (not (and c_121_0 c_121_2)))
(assert
 (not (and c_121_0 c_121_3)))
(assert
 (not (and c_121_0 c_121_4)))
(assert
 (not (and c_121_0 c_121_5)))
(assert
 (not (and c_121_0 c_121_6)))
(assert
 (not (and c_121_0 c_121_7)))
(assert
 (not (and c_121_0 c_121_8)))
(assert
 (not (and c_121_1 c_121_2)))
(assert
 (not (and c_121_1 c_121_3)))
(assert
 (not (and c_121_1 c_121_4)))
(assert
 (not (and c_121_1 c_121_5)))
(assert
 (not (and c_121_1 c_121_6)))
(assert
 (not (and c_121_1 c_121_7)))
(assert
 (not (and c_121_1 c_121_8)))
(assert
 (not (and c_121_2 c_121_3)))
(assert
 (not (and c_121_2 c_121_4)))
(assert
 (not (and c_121_2 c_121_5)))
(assert
 (not (and c_121_2 c_121_6)))
(assert
 (not (and c_121_2 c_121_7)))
(assert
 (not (and c_121_2 c_121_8)))
(assert
 (not (and c_121_3 c_121_4)))
(assert
 (not (and c_121_3 c_121_5)))
(assert
 (not (and c_121_3 c_121_6)))
(assert
 (not (and c_121_3 c_121_7)))
(assert
 (not (and c_121_3 c_121_8)))
(assert
 (not (and c_121_4 c_121_5)))
(assert
 (not (and c_121_4 c_121_6)))
(assert
 (not (and c_121_4 c_121_7)))
(assert
 (not (and c_121_4 c_121_8)))
(assert
 (not (and c_121_5 c_121_6)))
(assert
 (not (and c_121_5 c_121_7)))
(assert
 (not (and c_121_5 c_121_8)))
(assert
 (not (and c_121_6 c_121_7)))
(assert
 (not (and c_121_6 c_121_8)))
(assert
 (not (and c_121_7 c_121_8)))
(assert
 (let (($x11115 (or false c_122_0)))
 (let (($x11117 (or $x11115 c_122_1)))
 (let (($x11119 (or $x11117 c_122_2)))
 (let (($x11121 (or $x11119 c_122_3)))
 (let (($x11123 (or $x11121 c_122_4)))
 (let (($x11125 (or $x11123 c_122_5)))
 (let (($x11127 (or $x11125 c_122_6)))
 (let (($x11129 (or $x11127 c_122_7)))
 (or $x11129 c_122_8))))))))))
(assert
 (not (and c_122_0 c_122_1)))
(assert
 (not (and c_122_0 c_122_2)))
(assert
 (not (and c_122_0 c_122_3)))
(assert
 (not (and c_122_0 c_122_4)))
(assert
 (not (and c_122_0 c_122_5)))
(assert
 (not (and c_122_0 c_122_6)))
(assert
 (not (and c_122_0 c_122_7)))
(assert
 (not (and c_122_0 c_122_8)))
(assert
 (not (and c_122_1 c_122_2)))
(assert
 (not (and c_122_1 c_122_3)))
(assert
 (not (and c_122_1 c_122_4)))
(assert
 (not (and c_122_1 c_122_5)))
(assert
 (not (and c_122_1 c_122_6)))
(assert
 (not (and c_122_1 c_122_7)))
(assert
 (not (and c_122_1 c_122_8)))
(assert
 (not (and c_122_2 c_122_3)))
(assert
 (not (and c_122_2 c_122_4)))
(assert
 (not (and c_122_2 c_122_5)))
(assert
 (not (and c_122_2 c_122_6)))
(assert
 (not (and c_122_2 c_122_7)))
(assert
 (not (and c_122_2 c_122_8)))
(assert
 (not (and c_122_3 c_122_4)))
(assert
 (not (and c_122_3 c_122_5)))
(assert
 (not (and c_122_3 c_122_6)))
(assert
 (not (and c_122_3 c_122_7)))
(assert
 (not (and c_122_3 c_122_8)))
(assert
 (not (and c_122_4 c_122_5)))
(assert
 (not (and c_122_4 c_122_6)))
(assert
 (not (and c_122_4 c_122_7)))
(assert
 (not (and c_122_4 c_122_8)))
(assert
 (not (and c_122_5 c_122_6)))
(assert
 (not (and c_122_5 c_122_7)))
(assert
 (not (and c_122_5 c_122_8)))
(assert
 (not (and c_122_6 c_122_7)))
(assert
 (not (and c_122_6 c_122_8)))
(assert
 (not (and c_122_7 c_122_8)))
(assert
 (let (($x11205 (or false c_123_0)))
 (let (($x11207 (or $x11205 c_123_1)))
 (let (($x11209 (or $x11207 c_123_2)))
 (let (($x11211 (or $x11209 c_123_3)))
 (let (($x11213 (or $x11211 c_123_4)))
 (let (($x11215 (or $x11213 c_123_5)))
 (let (($x11217 (or $x11215 c_123_6)))
 (let (($x11219 (or $x11217 c_123_7)))
 (or $x11219 c_123_8))))))))))
(assert
 (not (and c_123_0 c_123_1)))
(assert
 (not (and c_123_0 c_123_2)))
(assert
 (not (and c_123_0 c_123_3)))
(assert
 (not (and c_123_0 c_123_4)))
(assert
 (not (and c_123_0 c_123_5)))
(assert
 (not (and c_123_0 c_123_6)))
(assert
 (not (and c_123_0 c_123_7)))
(assert
 (not (and c_123_0 c_123_8)))
(assert
 (not (and c_123_1 c_123_2)))
(assert
 (not (and c_123_1 c_123_3)))
(assert
 (not (and c_123_1 c_123_4)))
(assert
 (not (and c_123_1 c_123_5)))
(assert
 (not (and c_123_1 c_123_6)))
(assert
 (not (and c_123_1 c_123_7)))
(assert
 (not (and c_123_1 c_123_8)))
(assert
 (not (and c_123_2 c_123_3)))
(assert
 (not (and c_123_2 c_123_4)))
(assert
 (not (and c_123_2 c_123_5)))
(assert
 (not (and c_123_2 c_123_6)))
(assert
 (not (and c_123_2 c_123_7)))
(assert
 (not (and c_123_2 c_123_8)))
(assert
 (not (and c_123_3 c_123_4)))
(assert
 (not (and c_123_3 c_123_5)))
(assert
 (not (and c_123_3 c_123_6)))
(assert
 (not (and c_123_3 c_123_7)))
(assert
 (not (and c_123_3 c_123_8)))
(assert
 (not (and c_123_4 c_123_5)))
(assert
 (not (and c_123_4 c_123_6)))
(assert
 (not (and c_123_4 c_123_7)))
(assert
 (not (and c_123_4 c_123_8)))
(assert
 (not (and c_123_5 c_123_6)))
(assert
 (not (and c_123_5 c_123_7)))
(assert
 (not (and c_123_5 c_123_8)))
(assert
 (not (and c_123_6 c_123_7)))
(assert
 (not (and c_123_6 c_123_8)))
(assert
 (not (and c_123_7 c_123_8)))
(assert
 (let (($x11295 (or false c_124_0)))
 (let (($x11297 (or $x11295 c_124_1)))
 (let (($x11299 (or $x11297 c_124_2)))
 (let (($x11301 (or $x11299 c_124_3)))
 (let (($x11303 (or $x11301 c_124_4)))
 (let (($x11305 (or $x11303 c_124_5)))
 (let (($x11307 (or $x11305 c_124_6)))
 (let (($x11309 (or $x11307 c_124_7)))
 (or $x11309 c_124_8))))))))))
(assert
 (not (and c_124_0 c_124_1)))
(assert
 (not (and c_124_0 c_124_2)))
(assert
 (not (and c_124_0 c_124_3)))
(assert
 (not (and c_124_0 c_124_4)))
(assert
 (not (and c_124_0 c_124_5)))
(assert
 (not (and c_124_0 c_124_6)))
(assert
 (not (and c_124_0 c_124_7)))
(assert
 (not (and c_124_0 c_124_8)))
(assert
 (not (and c_124_1 c_124_2)))
(assert
 (not (and c_124_1 c_124_3)))
(assert
 (not (and c_124_1 c_124_4)))
(assert
 (not (and c_124_1 c_124_5)))
(assert
 (not (and c_124_1 c_124_6)))
(assert
 (not (and c_124_1 c_124_7)))
(assert
 (not (and c_124_1 c_124_8)))
(assert
 (not (and c_124_2 c_124_3)))
(assert
 (not (and c_124_2 c_124_4)))
(assert
 (not (and c_124_2 c_124_5)))
(assert
 (not (and c_124_2 c_124_6)))
(assert
 (not (and c_124_2 c_124_7)))
(assert
 (not (and c_124_2 c_124_8)))
(assert
 (not (and c_124_3 c_124_4)))
(assert
 (not (and c_124_3 c_124_5)))
(assert
 (not (and c_124_3 c_124_6)))
(assert
 (not (and c_124_3 c_124_7)))
(assert
 (not (and c_124_3 c_124_8)))
(assert
 (not (and c_124_4 c_124_5)))
(assert
 (not (and c_124_4 c_124_6)))
(assert
 (not (and c_124_4 c_124_7)))
(assert
 (not (and c_124_4 c_124_8)))
(assert
 (not (and c_124_5 c_124_6)))
(assert
 (not (and c_124_5 c_124_7)))
(assert
 (not (and c_124_5 c_124_8)))
(assert
 (not (and c_124_6 c_124_7)))
(assert
 (not (and c_124_6 c_124_8)))
(assert
 (not (and c_124_7 c_124_8)))
(assert
 (let (($x11385 (or false c_125_0)))
 (let (($x11387 (or $x11385 c_125_1)))
 (let (($x11389 (or $x11387 c_125_2)))
 (let (($x11391 (or $x11389 c_125_3)))
 (let (($x11393 (or $x11391 c_125_4)))
 (let (($x11395 (or $x11393 c_125_5)))
 (let (($x11397 (or $x11395 c_125_6)))
 (let (($x11399 (or $x11397 c_125_7)))
 (or $x11399 c_125_8))))))))))
(assert
 (not (and c_125_0 c_125_1)))
(assert
 (not (and c_125_0 c_125_2)))
(assert
 (not (and c_125_0 c_125_3)))
(assert
 (not (and c_125_0 c_125_4)))
(assert
 (not (and c_125_0 c_125_5)))
(assert
 (not (and c_125_0 c_125_6)))
(assert
 (not (and c_125_0 c_125_7)))
(assert
 (not (and c_125_0 c_125_8)))
(assert
 (not (and c_125_1 c_125_2)))
(assert
 (not (and c_125_1 c_125_3)))
(assert
 (not (and c_125_1 c_125_4)))
(assert
 (not (and c_125_1 c_125_5)))
(assert
 (not (and c_125_1 c_125_6)))
(assert
 (not (and c_125_1 c_125_7)))
(assert
 (not (and c_125_1 c_125_8)))
(assert
 (not (and c_125_2 c_125_3)))
(assert
 (not (and c_125_2 c_125_4)))
(assert
 (not (and c_125_2 c_125_5)))
(assert
 (not (and c_125_2 c_125_6)))
(assert
 (not (and c_125_2 c_125_7)))
(assert
 (not (and c_125_2 c_125_8)))
(assert
 (not (and c_125_3 c_125_4)))
(assert
 (not (and c_125_3 c_125_5)))
(assert
 (not (and c_125_3 c_125_6)))
(assert
 (not (and c_125_3 c_125_7)))
(assert
 (not (and c_125_3 c_125_8)))
(assert
 (not (and c_125_4 c_125_5)))
(assert
 (not (and c_125_4 c_125_6)))
(assert
 (not (and c_125_4 c_125_7)))
(assert
 (not (and c_125_4 c_125_8)))
(assert
 (not (and c_125_5 c_125_6)))
(assert
 (not (and c_125_5 c_125_7)))
(assert
 (not (and c_125_5 c_125_8)))
(assert
 (not (and c_125_6 c_125_7)))
(assert
 (not (and c_125_6 c_125_8)))
(assert
 (not (and c_125_7 c_125_8)))
(assert
 (let (($x11475 (or false c_126_0)))
 (let (($x11477 (or $x11475 c_126_1)))
 (let (($x11479 (or $x11477 c_126_2)))
 (let (($x11481 (or $x11479 c_126_3)))
 (let (($x11483 (or $x11481 c_126_4)))
 (let (($x11485 (or $x11483 c_126_5)))
 (let (($x11487 (or $x11485 c_126_6)))
 (let (($x11489 (or $x11487 c_126_7)))
 (or $x11489 c_126_8))))))))))
(assert
 (not (and c_126_0 c_126_1)))
(assert
 (not (and c_126_0 c_126_2)))
(assert
 (not (and c_126_0 c_126_3)))
(assert
 (not (and c_126_0 c_126_4)))
(assert
 (not (and c_126_0 c_126_5)))
(assert
 (not (and c_126_0 c_126_6)))
(assert
 (not (and c_126_0 c_126_7)))
(assert
 (not (and c_126_0 c_126_8)))
(assert
 (not (and c_126_1 c_126_2)))
(assert
 (not (and c_126_1 c_126_3)))
(assert
 (not (and c_126_1 c_126_4)))
(assert
 (not (and c_126_1 c_126_5)))
(assert
 (not (and c_126_1 c_126_6)))
(assert
 (not (and c_126_1 c_126_7)))
(assert
 (not (and c_126_1 c_126_8)))
(assert
 (not (and c_126_2 c_126_3)))
(assert
 (not (and c_126_2 c_126_4)))
(assert
 (not (and c_126_2 c_126_5)))
(assert
 (not (and c_126_2 c_126_6)))
(assert
 (not (and c_126_2 c_126_7)))
(assert
 (not (and c_126_2 c_126_8)))
(assert
 (not (and c_126_3 c_126_4)))
(assert
 (not (and c_126_3 c_126_5)))
(assert
 (not (and c_126_3 c_126_6)))
(assert
 (not (and c_126_3 c_126_7)))
(assert
 (not (and c_126_3 c_126_8)))
(assert
 (not (and c_126_4 c_126_5)))
(assert
 (not (and c_126_4 c_126_6)))
(assert
 (not (and c_126_4 c_126_7)))
(assert
 (not (and c_126_4 c_126_8)))
(assert
 (not (and c_126_5 c_126_6)))
(assert
 (not (and c_126_5 c_126_7)))
(assert
 (not (and c_126_5 c_126_8)))
(assert
 (not (and c_126_6 c_126_7)))
(assert
 (not (and c_126_6 c_126_8)))
(assert
 (not (and c_126_7 c_126_8)))
(assert
 (let (($x11565 (or false c_127_0)))
 (let (($x11567 (or $x11565 c_127_1)))
 (let (($x11569 (or $x11567 c_127_2)))
 (let (($x11571 (or $x11569 c_127_3)))
 (let (($x11573 (or $x11571 c_127_4)))
 (let (($x11575 (or $x11573 c_127_5)))
 (let (($x11577 (or $x11575 c_127_6)))
 (let (($x11579 (or $x11577 c_127_7)))
 (or $x11579 c_127_8))))))))))
(assert
 (not (and c_127_0 c_127_1)))
(assert
 (not (and c_127_0 c_127_2)))
(assert
 (not (and c_127_0 c_127_3)))
(assert
 (not (and c_127_0 c_127_4)))
(assert
 (not (and c_127_0 c_127_5)))
(assert
 (not (and c_127_0 c_127_6)))
(assert
 (not (and c_127_0 c_127_7)))
(assert
 (not (and c_127_0 c_127_8)))
(assert
 (not (and c_127_1 c_127_2)))
(assert
 (not (and c_127_1 c_127_3)))
(assert
 (not (and c_127_1 c_127_4)))
(assert
 (not (and c_127_1 c_127_5)))
(assert
 (not (and c_127_1 c_127_6)))
(assert
 (not (and c_127_1 c_127_7)))
(assert
 (not (and c_127_1 c_127_8)))
(assert
 (not (and c_127_2 c_127_3)))
(assert
 (not (and c_127_2 c_127_4)))
(assert
 (not (and c_127_2 c_127_5)))
(assert
 (not (and c_127_2 c_127_6)))
(assert
 (not (and c_127_2 c_127_7)))
(assert
 (not (and c_127_2 c_127_8)))
(assert
 (not (and c_127_3 c_127_4)))
(assert
 (not (and c_127_3 c_127_5)))
(assert
 (not (and c_127_3 c_127_6)))
(assert
 (not (and c_127_3 c_127_7)))
(assert
 (not (and c_127_3 c_127_8)))
(assert
 (not (and c_127_4 c_127_5)))
(assert
 (not (and c_127_4 c_127_6)))
(assert
 (not (and c_127_4 c_127_7)))
(assert
 (not (and c_127_4 c_127_8)))
(assert
 (not (and c_127_5 c_127_6)))
(assert
 (not (and c_127_5 c_127_7)))
(assert
 (not (and c_127_5 c_127_8)))
(assert
 (not (and c_127_6 c_127_7)))
(assert
 (not (and c_127_6 c_127_8)))
(assert
 (not (and c_127_7 c_127_8)))
(assert
 (let (($x11655 (or false c_128_0)))
 (let (($x11657 (or $x11655 c_128_1)))
 (let (($x11659 (or $x11657 c_128_2)))
 (let (($x11661 (or $x11659 c_128_3)))
 (let (($x11663 (or $x11661 c_128_4)))
 (let (($x11665 (or $x11663 c_128_5)))
 (let (($x11667 (or $x11665 c_128_6)))
 (let (($x11669 (or $x11667 c_128_7)))
 (or $x11669 c_128_8))))))))))
(assert
 (not (and c_128_0 c_128_1)))
(assert
 (not (and c_128_0 c_128_2)))
(assert
 (not (and c_128_0 c_128_3)))
(assert
 (not (and c_128_0 c_128_4)))
(assert
 (not (and c_128_0 c_128_5)))
(assert
 (not (and c_128_0 c_128_6)))
(assert
 (not (and c_128_0 c_128_7)))
(assert
 (not (and c_128_0 c_128_8)))
(assert
 (not (and c_128_1 c_128_2)))
(assert
 (not (and c_128_1 c_128_3)))
(assert
 (not (and c_128_1 c_128_4)))
(assert
 (not (and c_128_1 c_128_5)))
(assert
 (not (and c_128_1 c_128_6)))
(assert
 (not (and c_128_1 c_128_7)))
(assert
 (not (and c_128_1 c_128_8)))
(assert
 (not (and c_128_2 c_128_3)))
(assert
 (not (and c_128_2 c_128_4)))
(assert
 (not (and c_128_2 c_128_5)))
(assert
 (not (and c_128_2 c_128_6)))
(assert
 (not (and c_128_2 c_128_7)))
(assert
 (not (and c_128_2 c_128_8)))
(assert
 (not (and c_128_3 c_128_4)))
(assert
 (not (and c_128_3 c_128_5)))
(assert
 (not (and c_128_3 c_128_6)))
(assert
 (not (and c_128_3 c_128_7)))
(assert
 (not (and c_128_3 c_128_8)))
(assert
 (not (and c_128_4 c_128_5)))
(assert
 (not (and c_128_4 c_128_6)))
(assert
 (not (and c_128_4 c_128_7)))
(assert
 (not (and c_128_4 c_128_8)))
(assert
 (not (and c_128_5 c_128_6)))
(assert
 (not (and c_128_5 c_128_7)))
(assert
 (not (and c_128_5 c_128_8)))
(assert
 (not (and c_128_6 c_128_7)))
(assert
 (not (and c_128_6 c_128_8)))
(assert
 (not (and c_128_7 c_128_8)))
(assert
 (let (($x11745 (or false d_0_0)))
 (let (($x11747 (or $x11745 d_0_1)))
 (let (($x11749 (or $x11747 d_0_2)))
 (let (($x11751 (or $x11749 d_0_3)))
 (let (($x11753 (or $x11751 d_0_4)))
 (let (($x11755 (or $x11753 d_0_5)))
 (let (($x11757 (or $x11755 d_0_6)))
 (let (($x11759 (or $x11757 d_0_7)))
 (or $x11759 d_0_8))))))))))
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
 (let (($x11835 (or false d_1_0)))
 (let (($x11837 (or $x11835 d_1_1)))
 (let (($x11839 (or $x11837 d_1_2)))
 (let (($x11841 (or $x11839 d_1_3)))
 (let (($x11843 (or $x11841 d_1_4)))
 (let (($x11845 (or $x11843 d_1_5)))
 (let (($x11847 (or $x11845 d_1_6)))
 (let (($x11849 (or $x11847 d_1_7)))
 (or $x11849 d_1_8))))))))))
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
 (let (($x11925 (or false d_2_0)))
 (let (($x11927 (or $x11925 d_2_1)))
 (let (($x11929 (or $x11927 d_2_2)))
 (let (($x11931 (or $x11929 d_2_3)))
 (let (($x11933 (or $x11931 d_2_4)))
 (let (($x11935 (or $x11933 d_2_5)))
 (let (($x11937 (or $x11935 d_2_6)))
 (let (($x11939 (or $x11937 d_2_7)))
 (or $x11939 d_2_8))))))))))
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
 (let (($x12015 (or false d_3_0)))
 (let (($x12017 (or $x12015 d_3_1)))
 (let (($x12019 (or $x12017 d_3_2)))
 (let (($x12021 (or $x12019 d_3_3)))
 (let (($x12023 (or $x12021 d_3_4)))
 (let (($x12025 (or $x12023 d_3_5)))
 (let (($x12027 (or $x12025 d_3_6)))
 (let (($x12029 (or $x12027 d_3_7)))
 (or $x12029 d_3_8))))))))))
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
 (let (($x12105 (or false d_4_0)))
 (let (($x12107 (or $x12105 d_4_1)))
 (let (($x12109 (or $x12107 d_4_2)))
 (let (($x12111 (or $x12109 d_4_3)))
 (let (($x12113 (or $x12111 d_4_4)))
 (let (($x12115 (or $x12113 d_4_5)))
 (let (($x12117 (or $x12115 d_4_6)))
 (let (($x12119 (or $x12117 d_4_7)))
 (or $x12119 d_4_8))))))))))
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
 (let (($x12195 (or false d_5_0)))
 (let (($x12197 (or $x12195 d_5_1)))
 (let (($x12199 (or $x12197 d_5_2)))
 (let (($x12201 (or $x12199 d_5_3)))
 (let (($x12203 (or $x12201 d_5_4)))
 (let (($x12205 (or $x12203 d_5_5)))
 (let (($x12207 (or $x12205 d_5_6)))
 (let (($x12209 (or $x12207 d_5_7)))
 (or $x12209 d_5_8))))))))))
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
 (let (($x12285 (or false d_6_0)))
 (let (($x12287 (or $x12285 d_6_1)))
 (let (($x12289 (or $x12287 d_6_2)))
 (let (($x12291 (or $x12289 d_6_3)))
 (let (($x12293 (or $x12291 d_6_4)))
 (let (($x12295 (or $x12293 d_6_5)))
 (let (($x12297 (or $x12295 d_6_6)))
 (let (($x12299 (or $x12297 d_6_7)))
 (or $x12299 d_6_8))))))))))
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
 (let (($x12375 (or false d_7_0)))
 (let (($x12377 (or $x12375 d_7_1)))
 (let (($x12379 (or $x12377 d_7_2)))
 (let (($x12381 (or $x12379 d_7_3)))
 (let (($x12383 (or $x12381 d_7_4)))
 (let (($x12385 (or $x12383 d_7_5)))
 (let (($x12387 (or $x12385 d_7_6)))
 (let (($x12389 (or $x12387 d_7_7)))
 (or $x12389 d_7_8))))))))))
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
 (let (($x12465 (or false d_8_0)))
 (let (($x12467 (or $x12465 d_8_1)))
 (let (($x12469 (or $x12467 d_8_2)))
 (let (($x12471 (or $x12469 d_8_3)))
 (let (($x12473 (or $x12471 d_8_4)))
 (let (($x12475 (or $x12473 d_8_5)))
 (let (($x12477 (or $x12475 d_8_6)))
 (let (($x12479 (or $x12477 d_8_7)))
 (or $x12479 d_8_8))))))))))
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
 (let (($x12555 (or false d_9_0)))
 (let (($x12557 (or $x12555 d_9_1)))
 (let (($x12559 (or $x12557 d_9_2)))
 (let (($x12561 (or $x12559 d_9_3)))
 (let (($x12563 (or $x12561 d_9_4)))
 (let (($x12565 (or $x12563 d_9_5)))
 (let (($x12567 (or $x12565 d_9_6)))
 (let (($x12569 (or $x12567 d_9_7)))
 (or $x12569 d_9_8))))))))))
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
 (let (($x12645 (or false d_10_0)))
 (let (($x12647 (or $x12645 d_10_1)))
 (let (($x12649 (or $x12647 d_10_2)))
 (let (($x12651 (or $x12649 d_10_3)))
 (let (($x12653 (or $x12651 d_10_4)))
 (let (($x12655 (or $x12653 d_10_5)))
 (let (($x12657 (or $x12655 d_10_6)))
 (let (($x12659 (or $x12657 d_10_7)))
 (or $x12659 d_10_8))))))))))
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
 (let (($x12735 (or false d_11_0)))
 (let (($x12737 (or $x12735 d_11_1)))
 (let (($x12739 (or $x12737 d_11_2)))
 (let (($x12741 (or $x12739 d_11_3)))
 (let (($x12743 (or $x12741 d_11_4)))
 (let (($x12745 (or $x12743 d_11_5)))
 (let (($x12747 (or $x12745 d_11_6)))
 (let (($x12749 (or $x12747 d_11_7)))
 (or $x12749 d_11_8))))))))))
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
 (let (($x12825 (or false d_12_0)))
 (let (($x12827 (or $x12825 d_12_1)))
 (let (($x12829 (or $x12827 d_12_2)))
 (let (($x12831 (or $x12829 d_12_3)))
 (let (($x12833 (or $x12831 d_12_4)))
 (let (($x12835 (or $x12833 d_12_5)))
 (let (($x12837 (or $x12835 d_12_6)))
 (let (($x12839 (or $x12837 d_12_7)))
 (or $x12839 d_12_8))))))))))
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
 (let (($x12915 (or false d_13_0)))
 (let (($x12917 (or $x12915 d_13_1)))
 (let (($x12919 (or $x12917 d_13_2)))
 (let (($x12921 (or $x12919 d_13_3)))
 (let (($x12923 (or $x12921 d_13_4)))
 (let (($x12925 (or $x12923 d_13_5)))
 (let (($x12927 (or $x12925 d_13_6)))
 (let (($x12929 (or $x12927 d_13_7)))
 (or $x12929 d_13_8))))))))))
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
 (let (($x13005 (or false d_14_0)))
 (let (($x13007 (or $x13005 d_14_1)))
 (let (($x13009 (or $x13007 d_14_2)))
 (let (($x13011 (or $x13009 d_14_3)))
 (let (($x13013 (or $x13011 d_14_4)))
 (let (($x13015 (or $x13013 d_14_5)))
 (let (($x13017 (or $x13015 d_14_6)))
 (let (($x13019 (or $x13017 d_14_7)))
 (or $x13019 d_14_8))))))))))
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
 (let (($x13095 (or false d_15_0)))
 (let (($x13097 (or $x13095 d_15_1)))
 (let (($x13099 (or $x13097 d_15_2)))
 (let (($x13101 (or $x13099 d_15_3)))
 (let (($x13103 (or $x13101 d_15_4)))
 (let (($x13105 (or $x13103 d_15_5)))
 (let (($x13107 (or $x13105 d_15_6)))
 (let (($x13109 (or $x13107 d_15_7)))
 (or $x13109 d_15_8))))))))))
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
 (let (($x13185 (or false d_16_0)))
 (let (($x13187 (or $x13185 d_16_1)))
 (let (($x13189 (or $x13187 d_16_2)))
 (let (($x13191 (or $x13189 d_16_3)))
 (let (($x13193 (or $x13191 d_16_4)))
 (let (($x13195 (or $x13193 d_16_5)))
 (let (($x13197 (or $x13195 d_16_6)))
 (let (($x13199 (or $x13197 d_16_7)))
 (or $x13199 d_16_8))))))))))
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
 (let (($x13275 (or false d_17_0)))
 (let (($x13277 (or $x13275 d_17_1)))
 (let (($x13279 (or $x13277 d_17_2)))
 (let (($x13281 (or $x13279 d_17_3)))
 (let (($x13283 (or $x13281 d_17_4)))
 (let (($x13285 (or $x13283 d_17_5)))
 (let (($x13287 (or $x13285 d_17_6)))
 (let (($x13289 (or $x13287 d_17_7)))
 (or $x13289 d_17_8))))))))))
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
 (let (($x13365 (or false d_18_0)))
 (let (($x13367 (or $x13365 d_18_1)))
 (let (($x13369 (or $x13367 d_18_2)))
 (let (($x13371 (or $x13369 d_18_3)))
 (let (($x13373 (or $x13371 d_18_4)))
 (let (($x13375 (or $x13373 d_18_5)))
 (let (($x13377 (or $x13375 d_18_6)))
 (let (($x13379 (or $x13377 d_18_7)))
 (or $x13379 d_18_8))))))))))
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
 (let (($x13455 (or false d_19_0)))
 (let (($x13457 (or $x13455 d_19_1)))
 (let (($x13459 (or $x13457 d_19_2)))
 (let (($x13461 (or $x13459 d_19_3)))
 (let (($x13463 (or $x13461 d_19_4)))
 (let (($x13465 (or $x13463 d_19_5)))
 (let (($x13467 (or $x13465 d_19_6)))
 (let (($x13469 (or $x13467 d_19_7)))
 (or $x13469 d_19_8))))))))))
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
 (let (($x13545 (or false d_20_0)))
 (let (($x13547 (or $x13545 d_20_1)))
 (let (($x13549 (or $x13547 d_20_2)))
 (let (($x13551 (or $x13549 d_20_3)))
 (let (($x13553 (or $x13551 d_20_4)))
 (let (($x13555 (or $x13553 d_20_5)))
 (let (($x13557 (or $x13555 d_20_6)))
 (let (($x13559 (or $x13557 d_20_7)))
 (or $x13559 d_20_8))))))))))
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
 (let (($x13635 (or false d_21_0)))
 (let (($x13637 (or $x13635 d_21_1)))
 (let (($x13639 (or $x13637 d_21_2)))
 (let (($x13641 (or $x13639 d_21_3)))
 (let (($x13643 (or $x13641 d_21_4)))
 (let (($x13645 (or $x13643 d_21_5)))
 (let (($x13647 (or $x13645 d_21_6)))
 (let (($x13649 (or $x13647 d_21_7)))
 (or $x13649 d_21_8))))))))))
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
 (let (($x13725 (or false d_22_0)))
 (let (($x13727 (or $x13725 d_22_1)))
 (let (($x13729 (or $x13727 d_22_2)))
 (let (($x13731 (or $x13729 d_22_3)))
 (let (($x13733 (or $x13731 d_22_4)))
 (let (($x13735 (or $x13733 d_22_5)))
 (let (($x13737 (or $x13735 d_22_6)))
 (let (($x13739 (or $x13737 d_22_7)))
 (or $x13739 d_22_8))))))))))
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
 (let (($x13815 (or false d_23_0)))
 (let (($x13817 (or $x13815 d_23_1)))
 (let (($x13819 (or $x13817 d_23_2)))
 (let (($x13821 (or $x13819 d_23_3)))
 (let (($x13823 (or $x13821 d_23_4)))
 (let (($x13825 (or $x13823 d_23_5)))
 (let (($x13827 (or $x13825 d_23_6)))
 (let (($x13829 (or $x13827 d_23_7)))
 (or $x13829 d_23_8))))))))))
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
 (let (($x13905 (or false d_24_0)))
 (let (($x13907 (or $x13905 d_24_1)))
 (let (($x13909 (or $x13907 d_24_2)))
 (let (($x13911 (or $x13909 d_24_3)))
 (let (($x13913 (or $x13911 d_24_4)))
 (let (($x13915 (or $x13913 d_24_5)))
 (let (($x13917 (or $x13915 d_24_6)))
 (let (($x13919 (or $x13917 d_24_7)))
 (or $x13919 d_24_8))))))))))
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
 (let (($x13995 (or false d_25_0)))
 (let (($x13997 (or $x13995 d_25_1)))
 (let (($x13999 (or $x13997 d_25_2)))
 (let (($x14001 (or $x13999 d_25_3)))
 (let (($x14003 (or $x14001 d_25_4)))
 (let (($x14005 (or $x14003 d_25_5)))
 (let (($x14007 (or $x14005 d_25_6)))
 (let (($x14009 (or $x14007 d_25_7)))
 (or $x14009 d_25_8))))))))))
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
 (let (($x14085 (or false d_26_0)))
 (let (($x14087 (or $x14085 d_26_1)))
 (let (($x14089 (or $x14087 d_26_2)))
 (let (($x14091 (or $x14089 d_26_3)))
 (let (($x14093 (or $x14091 d_26_4)))
 (let (($x14095 (or $x14093 d_26_5)))
 (let (($x14097 (or $x14095 d_26_6)))
 (let (($x14099 (or $x14097 d_26_7)))
 (or $x14099 d_26_8))))))))))
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
 (let (($x14175 (or false d_27_0)))
 (let (($x14177 (or $x14175 d_27_1)))
 (let (($x14179 (or $x14177 d_27_2)))
 (let (($x14181 (or $x14179 d_27_3)))
 (let (($x14183 (or $x14181 d_27_4)))
 (let (($x14185 (or $x14183 d_27_5)))
 (let (($x14187 (or $x14185 d_27_6)))
 (let (($x14189 (or $x14187 d_27_7)))
 (or $x14189 d_27_8))))))))))
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
 (let (($x14265 (or false d_28_0)))
 (let (($x14267 (or $x14265 d_28_1)))
 (let (($x14269 (or $x14267 d_28_2)))
 (let (($x14271 (or $x14269 d_28_3)))
 (let (($x14273 (or $x14271 d_28_4)))
 (let (($x14275 (or $x14273 d_28_5)))
 (let (($x14277 (or $x14275 d_28_6)))
 (let (($x14279 (or $x14277 d_28_7)))
 (or $x14279 d_28_8))))))))))
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
 (let (($x14355 (or false d_29_0)))
 (let (($x14357 (or $x14355 d_29_1)))
 (let (($x14359 (or $x14357 d_29_2)))
 (let (($x14361 (or $x14359 d_29_3)))
 (let (($x14363 (or $x14361 d_29_4)))
 (let (($x14365 (or $x14363 d_29_5)))
 (let (($x14367 (or $x14365 d_29_6)))
 (let (($x14369 (or $x14367 d_29_7)))
 (or $x14369 d_29_8))))))))))
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
 (let (($x14445 (or false d_30_0)))
 (let (($x14447 (or $x14445 d_30_1)))
 (let (($x14449 (or $x14447 d_30_2)))
 (let (($x14451 (or $x14449 d_30_3)))
 (let (($x14453 (or $x14451 d_30_4)))
 (let (($x14455 (or $x14453 d_30_5)))
 (let (($x14457 (or $x14455 d_30_6)))
 (let (($x14459 (or $x14457 d_30_7)))
 (or $x14459 d_30_8))))))))))
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
 (let (($x14535 (or false d_31_0)))
 (let (($x14537 (or $x14535 d_31_1)))
 (let (($x14539 (or $x14537 d_31_2)))
 (let (($x14541 (or $x14539 d_31_3)))
 (let (($x14543 (or $x14541 d_31_4)))
 (let (($x14545 (or $x14543 d_31_5)))
 (let (($x14547 (or $x14545 d_31_6)))
 (let (($x14549 (or $x14547 d_31_7)))
 (or $x14549 d_31_8))))))))))
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
 (let (($x14625 (or false d_32_0)))
 (let (($x14627 (or $x14625 d_32_1)))
 (let (($x14629 (or $x14627 d_32_2)))
 (let (($x14631 (or $x14629 d_32_3)))
 (let (($x14633 (or $x14631 d_32_4)))
 (let (($x14635 (or $x14633 d_32_5)))
 (let (($x14637 (or $x14635 d_32_6)))
 (let (($x14639 (or $x14637 d_32_7)))
 (or $x14639 d_32_8))))))))))
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
 (let (($x14715 (or false d_33_0)))
 (let (($x14717 (or $x14715 d_33_1)))
 (let (($x14719 (or $x14717 d_33_2)))
 (let (($x14721 (or $x14719 d_33_3)))
 (let (($x14723 (or $x14721 d_33_4)))
 (let (($x14725 (or $x14723 d_33_5)))
 (let (($x14727 (or $x14725 d_33_6)))
 (let (($x14729 (or $x14727 d_33_7)))
 (or $x14729 d_33_8))))))))))
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
 (let (($x14805 (or false d_34_0)))
 (let (($x14807 (or $x14805 d_34_1)))
 (let (($x14809 (or $x14807 d_34_2)))
 (let (($x14811 (or $x14809 d_34_3)))
 (let (($x14813 (or $x14811 d_34_4)))
 (let (($x14815 (or $x14813 d_34_5)))
 (let (($x14817 (or $x14815 d_34_6)))
 (let (($x14819 (or $x14817 d_34_7)))
 (or $x14819 d_34_8))))))))))
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
 (let (($x14895 (or false d_35_0)))
 (let (($x14897 (or $x14895 d_35_1)))
 (let (($x14899 (or $x14897 d_35_2)))
 (let (($x14901 (or $x14899 d_35_3)))
 (let (($x14903 (or $x14901 d_35_4)))
 (let (($x14905 (or $x14903 d_35_5)))
 (let (($x14907 (or $x14905 d_35_6)))
 (let (($x14909 (or $x14907 d_35_7)))
 (or $x14909 d_35_8))))))))))
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
 (let (($x14985 (or false d_36_0)))
 (let (($x14987 (or $x14985 d_36_1)))
 (let (($x14989 (or $x14987 d_36_2)))
 (let (($x14991 (or $x14989 d_36_3)))
 (let (($x14993 (or $x14991 d_36_4)))
 (let (($x14995 (or $x14993 d_36_5)))
 (let (($x14997 (or $x14995 d_36_6)))
 (let (($x14999 (or $x14997 d_36_7)))
 (or $x14999 d_36_8))))))))))
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
 (let (($x15075 (or false d_37_0)))
 (let (($x15077 (or $x15075 d_37_1)))
 (let (($x15079 (or $x15077 d_37_2)))
 (let (($x15081 (or $x15079 d_37_3)))
 (let (($x15083 (or $x15081 d_37_4)))
 (let (($x15085 (or $x15083 d_37_5)))
 (let (($x15087 (or $x15085 d_37_6)))
 (let (($x15089 (or $x15087 d_37_7)))
 (or $x15089 d_37_8))))))))))
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
 (let (($x15165 (or false d_38_0)))
 (let (($x15167 (or $x15165 d_38_1)))
 (let (($x15169 (or $x15167 d_38_2)))
 (let (($x15171 (or $x15169 d_38_3)))
 (let (($x15173 (or $x15171 d_38_4)))
 (let (($x15175 (or $x15173 d_38_5)))
 (let (($x15177 (or $x15175 d_38_6)))
 (let (($x15179 (or $x15177 d_38_7)))
 (or $x15179 d_38_8))))))))))
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
 (let (($x15255 (or false d_39_0)))
 (let (($x15257 (or $x15255 d_39_1)))
 (let (($x15259 (or $x15257 d_39_2)))
 (let (($x15261 (or $x15259 d_39_3)))
 (let (($x15263 (or $x15261 d_39_4)))
 (let (($x15265 (or $x15263 d_39_5)))
 (let (($x15267 (or $x15265 d_39_6)))
 (let (($x15269 (or $x15267 d_39_7)))
 (or $x15269 d_39_8))))))))))
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
 (let (($x15345 (or false d_40_0)))
 (let (($x15347 (or $x15345 d_40_1)))
 (let (($x15349 (or $x15347 d_40_2)))
 (let (($x15351 (or $x15349 d_40_3)))
 (let (($x15353 (or $x15351 d_40_4)))
 (let (($x15355 (or $x15353 d_40_5)))
 (let (($x15357 (or $x15355 d_40_6)))
 (let (($x15359 (or $x15357 d_40_7)))
 (or $x15359 d_40_8))))))))))
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
 (let (($x15435 (or false d_41_0)))
 (let (($x15437 (or $x15435 d_41_1)))
 (let (($x15439 (or $x15437 d_41_2)))
 (let (($x15441 (or $x15439 d_41_3)))
 (let (($x15443 (or $x15441 d_41_4)))
 (let (($x15445 (or $x15443 d_41_5)))
 (let (($x15447 (or $x15445 d_41_6)))
 (let (($x15449 (or $x15447 d_41_7)))
 (or $x15449 d_41_8))))))))))
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
 (let (($x15525 (or false d_42_0)))
 (let (($x15527 (or $x15525 d_42_1)))
 (let (($x15529 (or $x15527 d_42_2)))
 (let (($x15531 (or $x15529 d_42_3)))
 (let (($x15533 (or $x15531 d_42_4)))
 (let (($x15535 (or $x15533 d_42_5)))
 (let (($x15537 (or $x15535 d_42_6)))
 (let (($x15539 (or $x15537 d_42_7)))
 (or $x15539 d_42_8))))))))))
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
 (let (($x15615 (or false d_43_0)))
 (let (($x15617 (or $x15615 d_43_1)))
 (let (($x15619 (or $x15617 d_43_2)))
 (let (($x15621 (or $x15619 d_43_3)))
 (let (($x15623 (or $x15621 d_43_4)))
 (let (($x15625 (or $x15623 d_43_5)))
 (let (($x15627 (or $x15625 d_43_6)))
 (let (($x15629 (or $x15627 d_43_7)))
 (or $x15629 d_43_8))))))))))
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
 (let (($x15705 (or false d_44_0)))
 (let (($x15707 (or $x15705 d_44_1)))
 (let (($x15709 (or $x15707 d_44_2)))
 (let (($x15711 (or $x15709 d_44_3)))
 (let (($x15713 (or $x15711 d_44_4)))
 (let (($x15715 (or $x15713 d_44_5)))
 (let (($x15717 (or $x15715 d_44_6)))
 (let (($x15719 (or $x15717 d_44_7)))
 (or $x15719 d_44_8))))))))))
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
 (let (($x15795 (or false d_45_0)))
 (let (($x15797 (or $x15795 d_45_1)))
 (let (($x15799 (or $x15797 d_45_2)))
 (let (($x15801 (or $x15799 d_45_3)))
 (let (($x15803 (or $x15801 d_45_4)))
 (let (($x15805 (or $x15803 d_45_5)))
 (let (($x15807 (or $x15805 d_45_6)))
 (let (($x15809 (or $x15807 d_45_7)))
 (or $x15809 d_45_8))))))))))
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
 (let (($x15885 (or false d_46_0)))
 (let (($x15887 (or $x15885 d_46_1)))
 (let (($x15889 (or $x15887 d_46_2)))
 (let (($x15891 (or $x15889 d_46_3)))
 (let (($x15893 (or $x15891 d_46_4)))
 (let (($x15895 (or $x15893 d_46_5)))
 (let (($x15897 (or $x15895 d_46_6)))
 (let (($x15899 (or $x15897 d_46_7)))
 (or $x15899 d_46_8))))))))))
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
 (let (($x15975 (or false d_47_0)))
 (let (($x15977 (or $x15975 d_47_1)))
 (let (($x15979 (or $x15977 d_47_2)))
 (let (($x15981 (or $x15979 d_47_3)))
 (let (($x15983 (or $x15981 d_47_4)))
 (let (($x15985 (or $x15983 d_47_5)))
 (let (($x15987 (or $x15985 d_47_6)))
 (let (($x15989 (or $x15987 d_47_7)))
 (or $x15989 d_47_8))))))))))
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
 (let (($x16065 (or false d_48_0)))
 (let (($x16067 (or $x16065 d_48_1)))
 (let (($x16069 (or $x16067 d_48_2)))
 (let (($x16071 (or $x16069 d_48_3)))
 (let (($x16073 (or $x16071 d_48_4)))
 (let (($x16075 (or $x16073 d_48_5)))
 (let (($x16077 (or $x16075 d_48_6)))
 (let (($x16079 (or $x16077 d_48_7)))
 (or $x16079 d_48_8))))))))))
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
 (let (($x16155 (or false d_49_0)))
 (let (($x16157 (or $x16155 d_49_1)))
 (let (($x16159 (or $x16157 d_49_2)))
 (let (($x16161 (or $x16159 d_49_3)))
 (let (($x16163 (or $x16161 d_49_4)))
 (let (($x16165 (or $x16163 d_49_5)))
 (let (($x16167 (or $x16165 d_49_6)))
 (let (($x16169 (or $x16167 d_49_7)))
 (or $x16169 d_49_8))))))))))
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
 (let (($x16245 (or false d_50_0)))
 (let (($x16247 (or $x16245 d_50_1)))
 (let (($x16249 (or $x16247 d_50_2)))
 (let (($x16251 (or $x16249 d_50_3)))
 (let (($x16253 (or $x16251 d_50_4)))
 (let (($x16255 (or $x16253 d_50_5)))
 (let (($x16257 (or $x16255 d_50_6)))
 (let (($x16259 (or $x16257 d_50_7)))
 (or $x16259 d_50_8))))))))))
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
 (let (($x16335 (or false d_51_0)))
 (let (($x16337 (or $x16335 d_51_1)))
 (let (($x16339 (or $x16337 d_51_2)))
 (let (($x16341 (or $x16339 d_51_3)))
 (let (($x16343 (or $x16341 d_51_4)))
 (let (($x16345 (or $x16343 d_51_5)))
 (let (($x16347 (or $x16345 d_51_6)))
 (let (($x16349 (or $x16347 d_51_7)))
 (or $x16349 d_51_8))))))))))
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
 (let (($x16425 (or false d_52_0)))
 (let (($x16427 (or $x16425 d_52_1)))
 (let (($x16429 (or $x16427 d_52_2)))
 (let (($x16431 (or $x16429 d_52_3)))
 (let (($x16433 (or $x16431 d_52_4)))
 (let (($x16435 (or $x16433 d_52_5)))
 (let (($x16437 (or $x16435 d_52_6)))
 (let (($x16439 (or $x16437 d_52_7)))
 (or $x16439 d_52_8))))))))))
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
 (let (($x16515 (or false d_53_0)))
 (let (($x16517 (or $x16515 d_53_1)))
 (let (($x16519 (or $x16517 d_53_2)))
 (let (($x16521 (or $x16519 d_53_3)))
 (let (($x16523 (or $x16521 d_53_4)))
 (let (($x16525 (or $x16523 d_53_5)))
 (let (($x16527 (or $x16525 d_53_6)))
 (let (($x16529 (or $x16527 d_53_7)))
 (or $x16529 d_53_8))))))))))
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
 (let (($x16605 (or false d_54_0)))
 (let (($x16607 (or $x16605 d_54_1)))
 (let (($x16609 (or $x16607 d_54_2)))
 (let (($x16611 (or $x16609 d_54_3)))
 (let (($x16613 (or $x16611 d_54_4)))
 (let (($x16615 (or $x16613 d_54_5)))
 (let (($x16617 (or $x16615 d_54_6)))
 (let (($x16619 (or $x16617 d_54_7)))
 (or $x16619 d_54_8))))))))))
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
 (let (($x16695 (or false d_55_0)))
 (let (($x16697 (or $x16695 d_55_1)))
 (let (($x16699 (or $x16697 d_55_2)))
 (let (($x16701 (or $x16699 d_55_3)))
 (let (($x16703 (or $x16701 d_55_4)))
 (let (($x16705 (or $x16703 d_55_5)))
 (let (($x16707 (or $x16705 d_55_6)))
 (let (($x16709 (or $x16707 d_55_7)))
 (or $x16709 d_55_8))))))))))
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
 (let (($x16785 (or false d_56_0)))
 (let (($x16787 (or $x16785 d_56_1)))
 (let (($x16789 (or $x16787 d_56_2)))
 (let (($x16791 (or $x16789 d_56_3)))
 (let (($x16793 (or $x16791 d_56_4)))
 (let (($x16795 (or $x16793 d_56_5)))
 (let (($x16797 (or $x16795 d_56_6)))
 (let (($x16799 (or $x16797 d_56_7)))
 (or $x16799 d_56_8))))))))))
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
 (let (($x16875 (or false d_57_0)))
 (let (($x16877 (or $x16875 d_57_1)))
 (let (($x16879 (or $x16877 d_57_2)))
 (let (($x16881 (or $x16879 d_57_3)))
 (let (($x16883 (or $x16881 d_57_4)))
 (let (($x16885 (or $x16883 d_57_5)))
 (let (($x16887 (or $x16885 d_57_6)))
 (let (($x16889 (or $x16887 d_57_7)))
 (or $x16889 d_57_8))))))))))
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
 (let (($x16965 (or false d_58_0)))
 (let (($x16967 (or $x16965 d_58_1)))
 (let (($x16969 (or $x16967 d_58_2)))
 (let (($x16971 (or $x16969 d_58_3)))
 (let (($x16973 (or $x16971 d_58_4)))
 (let (($x16975 (or $x16973 d_58_5)))
 (let (($x16977 (or $x16975 d_58_6)))
 (let (($x16979 (or $x16977 d_58_7)))
 (or $x16979 d_58_8))))))))))
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
 (let (($x17055 (or false d_59_0)))
 (let (($x17057 (or $x17055 d_59_1)))
 (let (($x17059 (or $x17057 d_59_2)))
 (let (($x17061 (or $x17059 d_59_3)))
 (let (($x17063 (or $x17061 d_59_4)))
 (let (($x17065 (or $x17063 d_59_5)))
 (let (($x17067 (or $x17065 d_59_6)))
 (let (($x17069 (or $x17067 d_59_7)))
 (or $x17069 d_59_8))))))))))
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
 (let (($x17145 (or false d_60_0)))
 (let (($x17147 (or $x17145 d_60_1)))
 (let (($x17149 (or $x17147 d_60_2)))
 (let (($x17151 (or $x17149 d_60_3)))
 (let (($x17153 (or $x17151 d_60_4)))
 (let (($x17155 (or $x17153 d_60_5)))
 (let (($x17157 (or $x17155 d_60_6)))
 (let (($x17159 (or $x17157 d_60_7)))
 (or $x17159 d_60_8))))))))))
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
 (let (($x17235 (or false d_61_0)))
 (let (($x17237 (or $x17235 d_61_1)))
 (let (($x17239 (or $x17237 d_61_2)))
 (let (($x17241 (or $x17239 d_61_3)))
 (let (($x17243 (or $x17241 d_61_4)))
 (let (($x17245 (or $x17243 d_61_5)))
 (let (($x17247 (or $x17245 d_61_6)))
 (let (($x17249 (or $x17247 d_61_7)))
 (or $x17249 d_61_8))))))))))
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
 (let (($x17325 (or false d_62_0)))
 (let (($x17327 (or $x17325 d_62_1)))
 (let (($x17329 (or $x17327 d_62_2)))
 (let (($x17331 (or $x17329 d_62_3)))
 (let (($x17333 (or $x17331 d_62_4)))
 (let (($x17335 (or $x17333 d_62_5)))
 (let (($x17337 (or $x17335 d_62_6)))
 (let (($x17339 (or $x17337 d_62_7)))
 (or $x17339 d_62_8))))))))))
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
 (let (($x17415 (or false d_63_0)))
 (let (($x17417 (or $x17415 d_63_1)))
 (let (($x17419 (or $x17417 d_63_2)))
 (let (($x17421 (or $x17419 d_63_3)))
 (let (($x17423 (or $x17421 d_63_4)))
 (let (($x17425 (or $x17423 d_63_5)))
 (let (($x17427 (or $x17425 d_63_6)))
 (let (($x17429 (or $x17427 d_63_7)))
 (or $x17429 d_63_8))))))))))
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
 (let (($x17505 (or false d_64_0)))
 (let (($x17507 (or $x17505 d_64_1)))
 (let (($x17509 (or $x17507 d_64_2)))
 (let (($x17511 (or $x17509 d_64_3)))
 (let (($x17513 (or $x17511 d_64_4)))
 (let (($x17515 (or $x17513 d_64_5)))
 (let (($x17517 (or $x17515 d_64_6)))
 (let (($x17519 (or $x17517 d_64_7)))
 (or $x17519 d_64_8))))))))))
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
 (let (($x17595 (or false d_65_0)))
 (let (($x17597 (or $x17595 d_65_1)))
 (let (($x17599 (or $x17597 d_65_2)))
 (let (($x17601 (or $x17599 d_65_3)))
 (let (($x17603 (or $x17601 d_65_4)))
 (let (($x17605 (or $x17603 d_65_5)))
 (let (($x17607 (or $x17605 d_65_6)))
 (let (($x17609 (or $x17607 d_65_7)))
 (or $x17609 d_65_8))))))))))
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
 (let (($x17685 (or false d_66_0)))
 (let (($x17687 (or $x17685 d_66_1)))
 (let (($x17689 (or $x17687 d_66_2)))
 (let (($x17691 (or $x17689 d_66_3)))
 (let (($x17693 (or $x17691 d_66_4)))
 (let (($x17695 (or $x17693 d_66_5)))
 (let (($x17697 (or $x17695 d_66_6)))
 (let (($x17699 (or $x17697 d_66_7)))
 (or $x17699 d_66_8))))))))))
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
 (let (($x17775 (or false d_67_0)))
 (let (($x17777 (or $x17775 d_67_1)))
 (let (($x17779 (or $x17777 d_67_2)))
 (let (($x17781 (or $x17779 d_67_3)))
 (let (($x17783 (or $x17781 d_67_4)))
 (let (($x17785 (or $x17783 d_67_5)))
 (let (($x17787 (or $x17785 d_67_6)))
 (let (($x17789 (or $x17787 d_67_7)))
 (or $x17789 d_67_8))))))))))
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
 (let (($x17865 (or false d_68_0)))
 (let (($x17867 (or $x17865 d_68_1)))
 (let (($x17869 (or $x17867 d_68_2)))
 (let (($x17871 (or $x17869 d_68_3)))
 (let (($x17873 (or $x17871 d_68_4)))
 (let (($x17875 (or $x17873 d_68_5)))
 (let (($x17877 (or $x17875 d_68_6)))
 (let (($x17879 (or $x17877 d_68_7)))
 (or $x17879 d_68_8))))))))))
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
 (let (($x17955 (or false d_69_0)))
 (let (($x17957 (or $x17955 d_69_1)))
 (let (($x17959 (or $x17957 d_69_2)))
 (let (($x17961 (or $x17959 d_69_3)))
 (let (($x17963 (or $x17961 d_69_4)))
 (let (($x17965 (or $x17963 d_69_5)))
 (let (($x17967 (or $x17965 d_69_6)))
 (let (($x17969 (or $x17967 d_69_7)))
 (or $x17969 d_69_8))))))))))
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
 (let (($x18045 (or false d_70_0)))
 (let (($x18047 (or $x18045 d_70_1)))
 (let (($x18049 (or $x18047 d_70_2)))
 (let (($x18051 (or $x18049 d_70_3)))
 (let (($x18053 (or $x18051 d_70_4)))
 (let (($x18055 (or $x18053 d_70_5)))
 (let (($x18057 (or $x18055 d_70_6)))
 (let (($x18059 (or $x18057 d_70_7)))
 (or $x18059 d_70_8))))))))))
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
 (let (($x18135 (or false d_71_0)))
 (let (($x18137 (or $x18135 d_71_1)))
 (let (($x18139 (or $x18137 d_71_2)))
 (let (($x18141 (or $x18139 d_71_3)))
 (let (($x18143 (or $x18141 d_71_4)))
 (let (($x18145 (or $x18143 d_71_5)))
 (let (($x18147 (or $x18145 d_71_6)))
 (let (($x18149 (or $x18147 d_71_7)))
 (or $x18149 d_71_8))))))))))
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
 (let (($x18225 (or false d_72_0)))
 (let (($x18227 (or $x18225 d_72_1)))
 (let (($x18229 (or $x18227 d_72_2)))
 (let (($x18231 (or $x18229 d_72_3)))
 (let (($x18233 (or $x18231 d_72_4)))
 (let (($x18235 (or $x18233 d_72_5)))
 (let (($x18237 (or $x18235 d_72_6)))
 (let (($x18239 (or $x18237 d_72_7)))
 (or $x18239 d_72_8))))))))))
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
 (let (($x18315 (or false d_73_0)))
 (let (($x18317 (or $x18315 d_73_1)))
 (let (($x18319 (or $x18317 d_73_2)))
 (let (($x18321 (or $x18319 d_73_3)))
 (let (($x18323 (or $x18321 d_73_4)))
 (let (($x18325 (or $x18323 d_73_5)))
 (let (($x18327 (or $x18325 d_73_6)))
 (let (($x18329 (or $x18327 d_73_7)))
 (or $x18329 d_73_8))))))))))
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
 (let (($x18405 (or false d_74_0)))
 (let (($x18407 (or $x18405 d_74_1)))
 (let (($x18409 (or $x18407 d_74_2)))
 (let (($x18411 (or $x18409 d_74_3)))
 (let (($x18413 (or $x18411 d_74_4)))
 (let (($x18415 (or $x18413 d_74_5)))
 (let (($x18417 (or $x18415 d_74_6)))
 (let (($x18419 (or $x18417 d_74_7)))
 (or $x18419 d_74_8))))))))))
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
 (let (($x18495 (or false d_75_0)))
 (let (($x18497 (or $x18495 d_75_1)))
 (let (($x18499 (or $x18497 d_75_2)))
 (let (($x18501 (or $x18499 d_75_3)))
 (let (($x18503 (or $x18501 d_75_4)))
 (let (($x18505 (or $x18503 d_75_5)))
 (let (($x18507 (or $x18505 d_75_6)))
 (let (($x18509 (or $x18507 d_75_7)))
 (or $x18509 d_75_8))))))))))
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
 (let (($x18585 (or false d_76_0)))
 (let (($x18587 (or $x18585 d_76_1)))
 (let (($x18589 (or $x18587 d_76_2)))
 (let (($x18591 (or $x18589 d_76_3)))
 (let (($x18593 (or $x18591 d_76_4)))
 (let (($x18595 (or $x18593 d_76_5)))
 (let (($x18597 (or $x18595 d_76_6)))
 (let (($x18599 (or $x18597 d_76_7)))
 (or $x18599 d_76_8))))))))))
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
 (let (($x18675 (or false d_77_0)))
 (let (($x18677 (or $x18675 d_77_1)))
 (let (($x18679 (or $x18677 d_77_2)))
 (let (($x18681 (or $x18679 d_77_3)))
 (let (($x18683 (or $x18681 d_77_4)))
 (let (($x18685 (or $x18683 d_77_5)))
 (let (($x18687 (or $x18685 d_77_6)))
 (let (($x18689 (or $x18687 d_77_7)))
 (or $x18689 d_77_8))))))))))
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
 (let (($x18765 (or false d_78_0)))
 (let (($x18767 (or $x18765 d_78_1)))
 (let (($x18769 (or $x18767 d_78_2)))
 (let (($x18771 (or $x18769 d_78_3)))
 (let (($x18773 (or $x18771 d_78_4)))
 (let (($x18775 (or $x18773 d_78_5)))
 (let (($x18777 (or $x18775 d_78_6)))
 (let (($x18779 (or $x18777 d_78_7)))
 (or $x18779 d_78_8))))))))))
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
 (let (($x18855 (or false d_79_0)))
 (let (($x18857 (or $x18855 d_79_1)))
 (let (($x18859 (or $x18857 d_79_2)))
 (let (($x18861 (or $x18859 d_79_3)))
 (let (($x18863 (or $x18861 d_79_4)))
 (let (($x18865 (or $x18863 d_79_5)))
 (let (($x18867 (or $x18865 d_79_6)))
 (let (($x18869 (or $x18867 d_79_7)))
 (or $x18869 d_79_8))))))))))
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
 (let (($x18945 (or false d_80_0)))
 (let (($x18947 (or $x18945 d_80_1)))
 (let (($x18949 (or $x18947 d_80_2)))
 (let (($x18951 (or $x18949 d_80_3)))
 (let (($x18953 (or $x18951 d_80_4)))
 (let (($x18955 (or $x18953 d_80_5)))
 (let (($x18957 (or $x18955 d_80_6)))
 (let (($x18959 (or $x18957 d_80_7)))
 (or $x18959 d_80_8))))))))))
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
 (let (($x19035 (or false d_81_0)))
 (let (($x19037 (or $x19035 d_81_1)))
 (let (($x19039 (or $x19037 d_81_2)))
 (let (($x19041 (or $x19039 d_81_3)))
 (let (($x19043 (or $x19041 d_81_4)))
 (let (($x19045 (or $x19043 d_81_5)))
 (let (($x19047 (or $x19045 d_81_6)))
 (let (($x19049 (or $x19047 d_81_7)))
 (or $x19049 d_81_8))))))))))
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
 (let (($x19125 (or false d_82_0)))
 (let (($x19127 (or $x19125 d_82_1)))
 (let (($x19129 (or $x19127 d_82_2)))
 (let (($x19131 (or $x19129 d_82_3)))
 (let (($x19133 (or $x19131 d_82_4)))
 (let (($x19135 (or $x19133 d_82_5)))
 (let (($x19137 (or $x19135 d_82_6)))
 (let (($x19139 (or $x19137 d_82_7)))
 (or $x19139 d_82_8))))))))))
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
 (let (($x19215 (or false d_83_0)))
 (let (($x19217 (or $x19215 d_83_1)))
 (let (($x19219 (or $x19217 d_83_2)))
 (let (($x19221 (or $x19219 d_83_3)))
 (let (($x19223 (or $x19221 d_83_4)))
 (let (($x19225 (or $x19223 d_83_5)))
 (let (($x19227 (or $x19225 d_83_6)))
 (let (($x19229 (or $x19227 d_83_7)))
 (or $x19229 d_83_8))))))))))
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
 (let (($x19305 (or false d_84_0)))
 (let (($x19307 (or $x19305 d_84_1)))
 (let (($x19309 (or $x19307 d_84_2)))
 (let (($x19311 (or $x19309 d_84_3)))
 (let (($x19313 (or $x19311 d_84_4)))
 (let (($x19315 (or $x19313 d_84_5)))
 (let (($x19317 (or $x19315 d_84_6)))
 (let (($x19319 (or $x19317 d_84_7)))
 (or $x19319 d_84_8))))))))))
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
 (let (($x19395 (or false d_85_0)))
 (let (($x19397 (or $x19395 d_85_1)))
 (let (($x19399 (or $x19397 d_85_2)))
 (let (($x19401 (or $x19399 d_85_3)))
 (let (($x19403 (or $x19401 d_85_4)))
 (let (($x19405 (or $x19403 d_85_5)))
 (let (($x19407 (or $x19405 d_85_6)))
 (let (($x19409 (or $x19407 d_85_7)))
 (or $x19409 d_85_8))))))))))
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
 (let (($x19485 (or false d_86_0)))
 (let (($x19487 (or $x19485 d_86_1)))
 (let (($x19489 (or $x19487 d_86_2)))
 (let (($x19491 (or $x19489 d_86_3)))
 (let (($x19493 (or $x19491 d_86_4)))
 (let (($x19495 (or $x19493 d_86_5)))
 (let (($x19497 (or $x19495 d_86_6)))
 (let (($x19499 (or $x19497 d_86_7)))
 (or $x19499 d_86_8))))))))))
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
 (let (($x19575 (or false d_87_0)))
 (let (($x19577 (or $x19575 d_87_1)))
 (let (($x19579 (or $x19577 d_87_2)))
 (let (($x19581 (or $x19579 d_87_3)))
 (let (($x19583 (or $x19581 d_87_4)))
 (let (($x19585 (or $x19583 d_87_5)))
 (let (($x19587 (or $x19585 d_87_6)))
 (let (($x19589 (or $x19587 d_87_7)))
 (or $x19589 d_87_8))))))))))
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
 (let (($x19665 (or false d_88_0)))
 (let (($x19667 (or $x19665 d_88_1)))
 (let (($x19669 (or $x19667 d_88_2)))
 (let (($x19671 (or $x19669 d_88_3)))
 (let (($x19673 (or $x19671 d_88_4)))
 (let (($x19675 (or $x19673 d_88_5)))
 (let (($x19677 (or $x19675 d_88_6)))
 (let (($x19679 (or $x19677 d_88_7)))
 (or $x19679 d_88_8))))))))))
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
 (let (($x19755 (or false d_89_0)))
 (let (($x19757 (or $x19755 d_89_1)))
 (let (($x19759 (or $x19757 d_89_2)))
 (let (($x19761 (or $x19759 d_89_3)))
 (let (($x19763 (or $x19761 d_89_4)))
 (let (($x19765 (or $x19763 d_89_5)))
 (let (($x19767 (or $x19765 d_89_6)))
 (let (($x19769 (or $x19767 d_89_7)))
 (or $x19769 d_89_8))))))))))
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
 (let (($x19845 (or false d_90_0)))
 (let (($x19847 (or $x19845 d_90_1)))
 (let (($x19849 (or $x19847 d_90_2)))
 (let (($x19851 (or $x19849 d_90_3)))
 (let (($x19853 (or $x19851 d_90_4)))
 (let (($x19855 (or $x19853 d_90_5)))
 (let (($x19857 (or $x19855 d_90_6)))
 (let (($x19859 (or $x19857 d_90_7)))
 (or $x19859 d_90_8))))))))))
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
 (let (($x19935 (or false d_91_0)))
 (let (($x19937 (or $x19935 d_91_1)))
 (let (($x19939 (or $x19937 d_91_2)))
 (let (($x19941 (or $x19939 d_91_3)))
 (let (($x19943 (or $x19941 d_91_4)))
 (let (($x19945 (or $x19943 d_91_5)))
 (let (($x19947 (or $x19945 d_91_6)))
 (let (($x19949 (or $x19947 d_91_7)))
 (or $x19949 d_91_8))))))))))
(assert
 (not (and d_91_0 d_91_1)))
(assert
 (not (and d_91_0 d_91_2)))
(assert
 (not (and d_91_0 d_91_3)))
(assert
 (not (and d_91_0 d_91_4)))
(assert
 (not (and d_91_0 d_91_5)))
(assert
 (not (and d_91_0 d_91_6)))
(assert
 (not (and d_91_0 d_91_7)))
(assert
 (not (and d_91_0 d_91_8)))
(assert
 (not (and d_91_1 d_91_2)))
(assert
 (not (and d_91_1 d_91_3)))
(assert
 (not (and d_91_1 d_91_4)))
(assert
 (not (and d_91_1 d_91_5)))
(assert
 (not (and d_91_1 d_91_6)))
(assert
 (not (and d_91_1 d_91_7)))
(assert
 (not (and d_91_1 d_91_8)))
(assert
 (not (and d_91_2 d_91_3)))
(assert
 (not (and d_91_2 d_91_4)))
(assert
 (not (and d_91_2 d_91_5)))
(assert
 (not (and d_91_2 d_91_6)))
(assert
 (not (and d_91_2 d_91_7)))
(assert
 (not (and d_91_2 d_91_8)))
(assert
 (not (and d_91_3 d_91_4)))
(assert
 (not (and d_91_3 d_91_5)))
(assert
 (not (and d_91_3 d_91_6)))
(assert
 (not (and d_91_3 d_91_7)))
(assert
 (not (and d_91_3 d_91_8)))
(assert
 (not (and d_91_4 d_91_5)))
(assert
 (not (and d_91_4 d_91_6)))
(assert
 (not (and d_91_4 d_91_7)))
(assert
 (not (and d_91_4 d_91_8)))
(assert
 (not (and d_91_5 d_91_6)))
(assert
 (not (and d_91_5 d_91_7)))
(assert
 (not (and d_91_5 d_91_8)))
(assert
 (not (and d_91_6 d_91_7)))
(assert
 (not (and d_91_6 d_91_8)))
(assert
 (not (and d_91_7 d_91_8)))
(assert
 (let (($x20025 (or false d_92_0)))
 (let (($x20027 (or $x20025 d_92_1)))
 (let (($x20029 (or $x20027 d_92_2)))
 (let (($x20031 (or $x20029 d_92_3)))
 (let (($x20033 (or $x20031 d_92_4)))
 (let (($x20035 (or $x20033 d_92_5)))
 (let (($x20037 (or $x20035 d_92_6)))
 (let (($x20039 (or $x20037 d_92_7)))
 (or $x20039 d_92_8))))))))))
(assert
 (not (and d_92_0 d_92_1)))
(assert
 (not (and d_92_0 d_92_2)))
(assert
 (not (and d_92_0 d_92_3)))
(assert
 (not (and d_92_0 d_92_4)))
(assert
 (not (and d_92_0 d_92_5)))
(assert
 (not (and d_92_0 d_92_6)))
(assert
 (not (and d_92_0 d_92_7)))
(assert
 (not (and d_92_0 d_92_8)))
(assert
 (not (and d_92_1 d_92_2)))
(assert
 (not (and d_92_1 d_92_3)))
(assert
 (not (and d_92_1 d_92_4)))
(assert
 (not (and d_92_1 d_92_5)))
(assert
 (not (and d_92_1 d_92_6)))
(assert
 (not (and d_92_1 d_92_7)))
(assert
 (not (and d_92_1 d_92_8)))
(assert
 (not (and d_92_2 d_92_3)))
(assert
 (not (and d_92_2 d_92_4)))
(assert
 (not (and d_92_2 d_92_5)))
(assert
 (not (and d_92_2 d_92_6)))
(assert
 (not (and d_92_2 d_92_7)))
(assert
 (not (and d_92_2 d_92_8)))
(assert
 (not (and d_92_3 d_92_4)))
(assert
 (not (and d_92_3 d_92_5)))
(assert
 (not (and d_92_3 d_92_6)))
(assert
 (not (and d_92_3 d_92_7)))
(assert
 (not (and d_92_3 d_92_8)))
(assert
 (not (and d_92_4 d_92_5)))
(assert
 (not (and d_92_4 d_92_6)))
(assert
 (not (and d_92_4 d_92_7)))
(assert
 (not (and d_92_4 d_92_8)))
(assert
 (not (and d_92_5 d_92_6)))
(assert
 (not (and d_92_5 d_92_7)))
(assert
 (not (and d_92_5 d_92_8)))
(assert
 (not (and d_92_6 d_92_7)))
(assert
 (not (and d_92_6 d_92_8)))
(assert
 (not (and d_92_7 d_92_8)))
(assert
 (let (($x20115 (or false d_93_0)))
 (let (($x20117 (or $x20115 d_93_1)))
 (let (($x20119 (or $x20117 d_93_2)))
 (let (($x20121 (or $x20119 d_93_3)))
 (let (($x20123 (or $x20121 d_93_4)))
 (let (($x20125 (or $x20123 d_93_5)))
 (let (($x20127 (or $x20125 d_93_6)))
 (let (($x20129 (or $x20127 d_93_7)))
 (or $x20129 d_93_8))))))))))
(assert
 (not (and d_93_0 d_93_1)))
(assert
 (not (and d_93_0 d_93_2)))
(assert
 (not (and d_93_0 d_93_3)))
(assert
 (not (and d_93_0 d_93_4)))
(assert
 (not (and d_93_0 d_93_5)))
(assert
 (not (and d_93_0 d_93_6)))
(assert
 (not (and d_93_0 d_93_7)))
(assert
 (not (and d_93_0 d_93_8)))
(assert
 (not (and d_93_1 d_93_2)))
(assert
 (not (and d_93_1 d_93_3)))
(assert
 (not (and d_93_1 d_93_4)))
(assert
 (not (and d_93_1 d_93_5)))
(assert
 (not (and d_93_1 d_93_6)))
(assert
 (not (and d_93_1 d_93_7)))
(assert
 (not (and d_93_1 d_93_8)))
(assert
 (not (and d_93_2 d_93_3)))
(assert
 (not (and d_93_2 d_93_4)))
(assert
 (not (and d_93_2 d_93_5)))
(assert
 (not (and d_93_2 d_93_6)))
(assert
 (not (and d_93_2 d_93_7)))
(assert
 (not (and d_93_2 d_93_8)))
(assert
 (not (and d_93_3 d_93_4)))
(assert
 (not (and d_93_3 d_93_5)))
(assert
 (not (and d_93_3 d_93_6)))
(assert
 (not (and d_93_3 d_93_7)))
(assert
 (not (and d_93_3 d_93_8)))
(assert
 (not (and d_93_4 d_93_5)))
(assert
 (not (and d_93_4 d_93_6)))
(assert
 (not (and d_93_4 d_93_7)))
(assert
 (not (and d_93_4 d_93_8)))
(assert
 (not (and d_93_5 d_93_6)))
(assert
 (not (and d_93_5 d_93_7)))
(assert
 (not (and d_93_5 d_93_8)))
(assert
 (not (and d_93_6 d_93_7)))
(assert
 (not (and d_93_6 d_93_8)))
(assert
 (not (and d_93_7 d_93_8)))
(assert
 (let (($x20205 (or false d_94_0)))
 (let (($x20207 (or $x20205 d_94_1)))
 (let (($x20209 (or $x20207 d_94_2)))
 (let (($x20211 (or $x20209 d_94_3)))
 (let (($x20213 (or $x20211 d_94_4)))
 (let (($x20215 (or $x20213 d_94_5)))
 (let (($x20217 (or $x20215 d_94_6)))
 (let (($x20219 (or $x20217 d_94_7)))
 (or $x20219 d_94_8))))))))))
(assert
 (not (and d_94_0 d_94_1)))
(assert
 (not (and d_94_0 d_94_2)))
(assert
 (not (and d_94_0 d_94_3)))
(assert
 (not (and d_94_0 d_94_4)))
(assert
 (not (and d_94_0 d_94_5)))
(assert
 (not (and d_94_0 d_94_6)))
(assert
 (not (and d_94_0 d_94_7)))
(assert
 (not (and d_94_0 d_94_8)))
(assert
 (not (and d_94_1 d_94_2)))
(assert
 (not (and d_94_1 d_94_3)))
(assert
 (not (and d_94_1 d_94_4)))
(assert
 (not (and d_94_1 d_94_5)))
(assert
 (not (and d_94_1 d_94_6)))
(assert
 (not (and d_94_1 d_94_7)))
(assert
 (not (and d_94_1 d_94_8)))
(assert
 (not (and d_94_2 d_94_3)))
(assert
 (not (and d_94_2 d_94_4)))
(assert
 (not (and d_94_2 d_94_5)))
(assert
 (not (and d_94_2 d_94_6)))
(assert
 (not (and d_94_2 d_94_7)))
(assert
 (not (and d_94_2 d_94_8)))
(assert
 (not (and d_94_3 d_94_4)))
(assert
 (not (and d_94_3 d_94_5)))
(assert
 (not (and d_94_3 d_94_6)))
(assert
 (not (and d_94_3 d_94_7)))
(assert
 (not (and d_94_3 d_94_8)))
(assert
 (not (and d_94_4 d_94_5)))
(assert
 (not (and d_94_4 d_94_6)))
(assert
 (not (and d_94_4 d_94_7)))
(assert
 (not (and d_94_4 d_94_8)))
(assert
 (not (and d_94_5 d_94_6)))
(assert
 (not (and d_94_5 d_94_7)))
(assert
 (not (and d_94_5 d_94_8)))
(assert
 (not (and d_94_6 d_94_7)))
(assert
 (not (and d_94_6 d_94_8)))
(assert
 (not (and d_94_7 d_94_8)))
(assert
 (let (($x20295 (or false d_95_0)))
 (let (($x20297 (or $x20295 d_95_1)))
 (let (($x20299 (or $x20297 d_95_2)))
 (let (($x20301 (or $x20299 d_95_3)))
 (let (($x20303 (or $x20301 d_95_4)))
 (let (($x20305 (or $x20303 d_95_5)))
 (let (($x20307 (or $x20305 d_95_6)))
 (let (($x20309 (or $x20307 d_95_7)))
 (or $x20309 d_95_8))))))))))
(assert
 (not (and d_95_0 d_95_1)))
(assert
 (not (and d_95_0 d_95_2)))
(assert
 (not (and d_95_0 d_95_3)))
(assert
 (not (and d_95_0 d_95_4)))
(assert
 (not (and d_95_0 d_95_5)))
(assert
 (not (and d_95_0 d_95_6)))
(assert
 (not (and d_95_0 d_95_7)))
(assert
 (not (and d_95_0 d_95_8)))
(assert
 (not (and d_95_1 d_95_2)))
(assert
 (not (and d_95_1 d_95_3)))
(assert
 (not (and d_95_1 d_95_4)))
(assert
 (not (and d_95_1 d_95_5)))
(assert
 (not (and d_95_1 d_95_6)))
(assert
 (not (and d_95_1 d_95_7)))
(assert
 (not (and d_95_1 d_95_8)))
(assert
 (not (and d_95_2 d_95_3)))
(assert
 (not (and d_95_2 d_95_4)))
(assert
 (not (and d_95_2 d_95_5)))
(assert
 (not (and d_95_2 d_95_6)))
(assert
 (not (and d_95_2 d_95_7)))
(assert
 (not (and d_95_2 d_95_8)))
(assert
 (not (and d_95_3 d_95_4)))
(assert
 (not (and d_95_3 d_95_5)))
(assert
 (not (and d_95_3 d_95_6)))
(assert
 (not (and d_95_3 d_95_7)))
(assert
 (not (and d_95_3 d_95_8)))
(assert
 (not (and d_95_4 d_95_5)))
(assert
 (not (and d_95_4 d_95_6)))
(assert
 (not (and d_95_4 d_95_7)))
(assert
 (not (and d_95_4 d_95_8)))
(assert
 (not (and d_95_5 d_95_6)))
(assert
 (not (and d_95_5 d_95_7)))
(assert
 (not (and d_95_5 d_95_8)))
(assert
 (not (and d_95_6 d_95_7)))
(assert
 (not (and d_95_6 d_95_8)))
(assert
 (not (and d_95_7 d_95_8)))
(assert
 (let (($x20385 (or false d_96_0)))
 (let (($x20387 (or $x20385 d_96_1)))
 (let (($x20389 (or $x20387 d_96_2)))
 (let (($x20391 (or $x20389 d_96_3)))
 (let (($x20393 (or $x20391 d_96_4)))
 (let (($x20395 (or $x20393 d_96_5)))
 (let (($x20397 (or $x20395 d_96_6)))
 (let (($x20399 (or $x20397 d_96_7)))
 (or $x20399 d_96_8))))))))))
(assert
 (not (and d_96_0 d_96_1)))
(assert
 (not (and d_96_0 d_96_2)))
(assert
 (not (and d_96_0 d_96_3)))
(assert
 (not (and d_96_0 d_96_4)))
(assert
 (not (and d_96_0 d_96_5)))
(assert
 (not (and d_96_0 d_96_6)))
(assert
 (not (and d_96_0 d_96_7)))
(assert
 (not (and d_96_0 d_96_8)))
(assert
 (not (and d_96_1 d_96_2)))
(assert
 (not (and d_96_1 d_96_3)))
(assert
 (not (and d_96_1 d_96_4)))
(assert
 (not (and d_96_1 d_96_5)))
(assert
 (not (and d_96_1 d_96_6)))
(assert
 (not (and d_96_1 d_96_7)))
(assert
 (not (and d_96_1 d_96_8)))
(assert
 (not (and d_96_2 d_96_3)))
(assert
 (not (and d_96_2 d_96_4)))
(assert
 (not (and d_96_2 d_96_5)))
(assert
 (not (and d_96_2 d_96_6)))
(assert
 (not (and d_96_2 d_96_7)))
(assert
 (not (and d_96_2 d_96_8)))
(assert
 (not (and d_96_3 d_96_4)))
(assert
 (not (and d_96_3 d_96_5)))
(assert
 (not (and d_96_3 d_96_6)))
(assert
 (not (and d_96_3 d_96_7)))
(assert
 (not (and d_96_3 d_96_8)))
(assert
 (not (and d_96_4 d_96_5)))
(assert
 (not (and d_96_4 d_96_6)))
(assert
 (not (and d_96_4 d_96_7)))
(assert
 (not (and d_96_4 d_96_8)))
(assert
 (not (and d_96_5 d_96_6)))
(assert
 (not (and d_96_5 d_96_7)))
(assert
 (not (and d_96_5 d_96_8)))
(assert
 (not (and d_96_6 d_96_7)))
(assert
 (not (and d_96_6 d_96_8)))
(assert
 (not (and d_96_7 d_96_8)))
(assert
 (let (($x20475 (or false d_97_0)))
 (let (($x20477 (or $x20475 d_97_1)))
 (let (($x20479 (or $x20477 d_97_2)))
 (let (($x20481 (or $x20479 d_97_3)))
 (let (($x20483 (or $x20481 d_97_4)))
 (let (($x20485 (or $x20483 d_97_5)))
 (let (($x20487 (or $x20485 d_97_6)))
 (let (($x20489 (or $x20487 d_97_7)))
 (or $x20489 d_97_8))))))))))
(assert
 (not (and d_97_0 d_97_1)))
(assert
 (not (and d_97_0 d_97_2)))
(assert
 (not (and d_97_0 d_97_3)))
(assert
 (not (and d_97_0 d_97_4)))
(assert
 (not (and d_97_0 d_97_5)))
(assert
 (not (and d_97_0 d_97_6)))
(assert
 (not (and d_97_0 d_97_7)))
(assert
 (not (and d_97_0 d_97_8)))
(assert
 (not (and d_97_1 d_97_2)))
(assert
 (not (and d_97_1 d_97_3)))
(assert
 (not (and d_97_1 d_97_4)))
(assert
 (not (and d_97_1 d_97_5)))
(assert
 (not (and d_97_1 d_97_6)))
(assert
 (not (and d_97_1 d_97_7)))
(assert
 (not (and d_97_1 d_97_8)))
(assert
 (not (and d_97_2 d_97_3)))
(assert
 (not (and d_97_2 d_97_4)))
(assert
 (not (and d_97_2 d_97_5)))
(assert
 (not (and d_97_2 d_97_6)))
(assert
 (not (and d_97_2 d_97_7)))
(assert
 (not (and d_97_2 d_97_8)))
(assert
 (not (and d_97_3 d_97_4)))
(assert
 (not (and d_97_3 d_97_5)))
(assert
 (not (and d_97_3 d_97_6)))
(assert
 (not (and d_97_3 d_97_7)))
(assert
 (not (and d_97_3 d_97_8)))
(assert
 (not (and d_97_4 d_97_5)))
(assert
 (not (and d_97_4 d_97_6)))
(assert
 (not (and d_97_4 d_97_7)))
(assert
 (not (and d_97_4 d_97_8)))
(assert
 (not (and d_97_5 d_97_6)))
(assert
 (not (and d_97_5 d_97_7)))
(assert
 (not (and d_97_5 d_97_8)))
(assert
 (not (and d_97_6 d_97_7)))
(assert
 (not (and d_97_6 d_97_8)))
(assert
 (not (and d_97_7 d_97_8)))
(assert
 (let (($x20565 (or false d_98_0)))
 (let (($x20567 (or $x20565 d_98_1)))
 (let (($x20569 (or $x20567 d_98_2)))
 (let (($x20571 (or $x20569 d_98_3)))
 (let (($x20573 (or $x20571 d_98_4)))
 (let (($x20575 (or $x20573 d_98_5)))
 (let (($x20577 (or $x20575 d_98_6)))
 (let (($x20579 (or $x20577 d_98_7)))
 (or $x20579 d_98_8))))))))))
(assert
 (not (and d_98_0 d_98_1)))
(assert
 (not (and d_98_0 d_98_2)))
(assert
 (not (and d_98_0 d_98_3)))
(assert
 (not (and d_98_0 d_98_4)))
(assert
 (not (and d_98_0 d_98_5)))
(assert
 (not (and d_98_0 d_98_6)))
(assert
 (not (and d_98_0 d_98_7)))
(assert
 (not (and d_98_0 d_98_8)))
(assert
 (not (and d_98_1 d_98_2)))
(assert
 (not (and d_98_1 d_98_3)))
(assert
 (not (and d_98_1 d_98_4)))
(assert
 (not (and d_98_1 d_98_5)))
(assert
 (not (and d_98_1 d_98_6)))
(assert
 (not (and d_98_1 d_98_7)))
(assert
 (not (and d_98_1 d_98_8)))
(assert
 (not (and d_98_2 d_98_3)))
(assert
 (not (and d_98_2 d_98_4)))
(assert
 (not (and d_98_2 d_98_5)))
(assert
 (not (and d_98_2 d_98_6)))
(assert
 (not (and d_98_2 d_98_7)))
(assert
 (not (and d_98_2 d_98_8)))
(assert
 (not (and d_98_3 d_98_4)))
(assert
 (not (and d_98_3 d_98_5)))
(assert
 (not (and d_98_3 d_98_6)))
(assert
 (not (and d_98_3 d_98_7)))
(assert
 (not (and d_98_3 d_98_8)))
(assert
 (not (and d_98_4 d_98_5)))
(assert
 (not (and d_98_4 d_98_6)))
(assert
 (not (and d_98_4 d_98_7)))
(assert
 (not (and d_98_4 d_98_8)))
(assert
 (not (and d_98_5 d_98_6)))
(assert
 (not (and d_98_5 d_98_7)))
(assert
 (not (and d_98_5 d_98_8)))
(assert
 (not (and d_98_6 d_98_7)))
(assert
 (not (and d_98_6 d_98_8)))
(assert
 (not (and d_98_7 d_98_8)))
(assert
 (let (($x20655 (or false d_99_0)))
 (let (($x20657 (or $x20655 d_99_1)))
 (let (($x20659 (or $x20657 d_99_2)))
 (let (($x20661 (or $x20659 d_99_3)))
 (let (($x20663 (or $x20661 d_99_4)))
 (let (($x20665 (or $x20663 d_99_5)))
 (let (($x20667 (or $x20665 d_99_6)))
 (let (($x20669 (or $x20667 d_99_7)))
 (or $x20669 d_99_8))))))))))
(assert
 (not (and d_99_0 d_99_1)))
(assert
 (not (and d_99_0 d_99_2)))
(assert
 (not (and d_99_0 d_99_3)))
(assert
 (not (and d_99_0 d_99_4)))
(assert
 (not (and d_99_0 d_99_5)))
(assert
 (not (and d_99_0 d_99_6)))
(assert
 (not (and d_99_0 d_99_7)))
(assert
 (not (and d_99_0 d_99_8)))
(assert
 (not (and d_99_1 d_99_2)))
(assert
 (not (and d_99_1 d_99_3)))
(assert
 (not (and d_99_1 d_99_4)))
(assert
 (not (and d_99_1 d_99_5)))
(assert
 (not (and d_99_1 d_99_6)))
(assert
 (not (and d_99_1 d_99_7)))
(assert
 (not (and d_99_1 d_99_8)))
(assert
 (not (and d_99_2 d_99_3)))
(assert
 (not (and d_99_2 d_99_4)))
(assert
 (not (and d_99_2 d_99_5)))
(assert
 (not (and d_99_2 d_99_6)))
(assert
 (not (and d_99_2 d_99_7)))
(assert
 (not (and d_99_2 d_99_8)))
(assert
 (not (and d_99_3 d_99_4)))
(assert
 (not (and d_99_3 d_99_5)))
(assert
 (not (and d_99_3 d_99_6)))
(assert
 (not (and d_99_3 d_99_7)))
(assert
 (not (and d_99_3 d_99_8)))
(assert
 (not (and d_99_4 d_99_5)))
(assert
 (not (and d_99_4 d_99_6)))
(assert
 (not (and d_99_4 d_99_7)))
(assert
 (not (and d_99_4 d_99_8)))
(assert
 (not (and d_99_5 d_99_6)))
(assert
 (not (and d_99_5 d_99_7)))
(assert
 (not (and d_99_5 d_99_8)))
(assert
 (not (and d_99_6 d_99_7)))
(assert
 (not (and d_99_6 d_99_8)))
(assert
 (not (and d_99_7 d_99_8)))
(assert
 (let (($x20745 (or false d_100_0)))
 (let (($x20747 (or $x20745 d_100_1)))
 (let (($x20749 (or $x20747 d_100_2)))
 (let (($x20751 (or $x20749 d_100_3)))
 (let (($x20753 (or $x20751 d_100_4)))
 (let (($x20755 (or $x20753 d_100_5)))
 (let (($x20757 (or $x20755 d_100_6)))
 (let (($x20759 (or $x20757 d_100_7)))
 (or $x20759 d_100_8))))))))))
(assert
 (not (and d_100_0 d_100_1)))
(assert
 (not (and d_100_0 d_100_2)))
(assert
 (not (and d_100_0 d_100_3)))
(assert
 (not (and d_100_0 d_100_4)))
(assert
 (not (and d_100_0 d_100_5)))
(assert
 (not (and d_100_0 d_100_6)))
(assert
 (not (and d_100_0 d_100_7)))
(assert
 (not (and d_100_0 d_100_8)))
(assert
 (not (and d_100_1 d_100_2)))
(assert
 (not (and d_100_1 d_100_3)))
(assert
 (not (and d_100_1 d_100_4)))
(assert
 (not (and d_100_1 d_100_5)))
(assert
 (not (and d_100_1 d_100_6)))
(assert
 (not (and d_100_1 d_100_7)))
(assert
 (not (and d_100_1 d_100_8)))
(assert
 (not (and d_100_2 d_100_3)))
(assert
 (not (and d_100_2 d_100_4)))
(assert
 (not (and d_100_2 d_100_5)))
(assert
 (not (and d_100_2 d_100_6)))
(assert
 (not (and d_100_2 d_100_7)))
(assert
 (not (and d_100_2 d_100_8)))
(assert
 (not (and d_100_3 d_100_4)))
(assert
 (not (and d_100_3 d_100_5)))
(assert
 (not (and d_100_3 d_100_6)))
(assert
 (not (and d_100_3 d_100_7)))
(assert
 (not (and d_100_3 d_100_8)))
(assert
 (not (and d_100_4 d_100_5)))
(assert
 (not (and d_100_4 d_100_6)))
(assert
 (not (and d_100_4 d_100_7)))
(assert
 (not (and d_100_4 d_100_8)))
(assert
 (not (and d_100_5 d_100_6)))
(assert
 (not (and d_100_5 d_100_7)))
(assert
 (not (and d_100_5 d_100_8)))
(assert
 (not (and d_100_6 d_100_7)))
(assert
 (not (and d_100_6 d_100_8)))
(assert
 (not (and d_100_7 d_100_8)))
(assert
 (let (($x20835 (or false d_101_0)))
 (let (($x20837 (or $x20835 d_101_1)))
 (let (($x20839 (or $x20837 d_101_2)))
 (let (($x20841 (or $x20839 d_101_3)))
 (let (($x20843 (or $x20841 d_101_4)))
 (let (($x20845 (or $x20843 d_101_5)))
 (let (($x20847 (or $x20845 d_101_6)))
 (let (($x20849 (or $x20847 d_101_7)))
 (or $x20849 d_101_8))))))))))
(assert
 (not (and d_101_0 d_101_1)))
(assert
 (not (and d_101_0 d_101_2)))
(assert
 (not (and d_101_0 d_101_3)))
(assert
 (not (and d_101_0 d_101_4)))
(assert
 (not (and d_101_0 d_101_5)))
(assert
 (not (and d_101_0 d_101_6)))
(assert
 (not (and d_101_0 d_101_7)))
(assert
 (not (and d_101_0 d_101_8)))
(assert
 (not (and d_101_1 d_101_2)))
(assert
 (not (and d_101_1 d_101_3)))
(assert
 (not (and d_101_1 d_101_4)))
(assert
 (not (and d_101_1 d_101_5)))
(assert
 (not (and d_101_1 d_101_6)))
(assert
 (not (and d_101_1 d_101_7)))
(assert
 (not (and d_101_1 d_101_8)))
(assert
 (not (and d_101_2 d_101_3)))
(assert
 (not (and d_101_2 d_101_4)))
(assert
 (not (and d_101_2 d_101_5)))
(assert
 (not (and d_101_2 d_101_6)))
(assert
 (not (and d_101_2 d_101_7)))
(assert
 (not (and d_101_2 d_101_8)))
(assert
 (not (and d_101_3 d_101_4)))
(assert
 (not (and d_101_3 d_101_5)))
(assert
 (not (and d_101_3 d_101_6)))
(assert
 (not (and d_101_3 d_101_7)))
(assert
 (not (and d_101_3 d_101_8)))
(assert
 (not (and d_101_4 d_101_5)))
(assert
 (not (and d_101_4 d_101_6)))
(assert
 (not (and d_101_4 d_101_7)))
(assert
 (not (and d_101_4 d_101_8)))
(assert
 (not (and d_101_5 d_101_6)))
(assert
 (not (and d_101_5 d_101_7)))
(assert
 (not (and d_101_5 d_101_8)))
(assert
 (not (and d_101_6 d_101_7)))
(assert
 (not (and d_101_6 d_101_8)))
(assert
 (not (and d_101_7 d_101_8)))
(assert
 (let (($x20925 (or false d_102_0)))
 (let (($x20927 (or $x20925 d_102_1)))
 (let (($x20929 (or $x20927 d_102_2)))
 (let (($x20931 (or $x20929 d_102_3)))
 (let (($x20933 (or $x20931 d_102_4)))
 (let (($x20935 (or $x20933 d_102_5)))
 (let (($x20937 (or $x20935 d_102_6)))
 (let (($x20939 (or $x20937 d_102_7)))
 (or $x20939 d_102_8))))))))))
(assert
 (not (and d_102_0 d_102_1)))
(assert
 (not (and d_102_0 d_102_2)))
(assert
 (not (and d_102_0 d_102_3)))
(assert
 (not (and d_102_0 d_102_4)))
(assert
 (not (and d_102_0 d_102_5)))
(assert
 (not (and d_102_0 d_102_6)))
(assert
 (not (and d_102_0 d_102_7)))
(assert
 (not (and d_102_0 d_102_8)))
(assert
 (not (and d_102_1 d_102_2)))
(assert
 (not (and d_102_1 d_102_3)))
(assert
 (not (and d_102_1 d_102_4)))
(assert
 (not (and d_102_1 d_102_5)))
(assert
 (not (and d_102_1 d_102_6)))
(assert
 (not (and d_102_1 d_102_7)))
(assert
 (not (and d_102_1 d_102_8)))
(assert
 (not (and d_102_2 d_102_3)))
(assert
 (not (and d_102_2 d_102_4)))
(assert
 (not (and d_102_2 d_102_5)))
(assert
 (not (and d_102_2 d_102_6)))
(assert
 (not (and d_102_2 d_102_7)))
(assert
 (not (and d_102_2 d_102_8)))
(assert
 (not (and d_102_3 d_102_4)))
(assert
 (not (and d_102_3 d_102_5)))
(assert
 (not (and d_102_3 d_102_6)))
(assert
 (not (and d_102_3 d_102_7)))
(assert
 (not (and d_102_3 d_102_8)))
(assert
 (not (and d_102_4 d_102_5)))
(assert
 (not (and d_102_4 d_102_6)))
(assert
 (not (and d_102_4 d_102_7)))
(assert
 (not (and d_102_4 d_102_8)))
(assert
 (not (and d_102_5 d_102_6)))
(assert
 (not (and d_102_5 d_102_7)))
(assert
 (not (and d_102_5 d_102_8)))
(assert
 (not (and d_102_6 d_102_7)))
(assert
 (not (and d_102_6 d_102_8)))
(assert
 (not (and d_102_7 d_102_8)))
(assert
 (let (($x21015 (or false d_103_0)))
 (let (($x21017 (or $x21015 d_103_1)))
 (let (($x21019 (or $x21017 d_103_2)))
 (let (($x21021 (or $x21019 d_103_3)))
 (let (($x21023 (or $x21021 d_103_4)))
 (let (($x21025 (or $x21023 d_103_5)))
 (let (($x21027 (or $x21025 d_103_6)))
 (let (($x21029 (or $x21027 d_103_7)))
 (or $x21029 d_103_8))))))))))
(assert
 (not (and d_103_0 d_103_1)))
(assert
 (not (and d_103_0 d_103_2)))
(assert
 (not (and d_103_0 d_103_3)))
(assert
 (not (and d_103_0 d_103_4)))
(assert
 (not (and d_103_0 d_103_5)))
(assert
 (not (and d_103_0 d_103_6)))
(assert
 (not (and d_103_0 d_103_7)))
(assert
 (not (and d_103_0 d_103_8)))
(assert
 (not (and d_103_1 d_103_2)))
(assert
 (not (and d_103_1 d_103_3)))
(assert
 (not (and d_103_1 d_103_4)))
(assert
 (not (and d_103_1 d_103_5)))
(assert
 (not (and d_103_1 d_103_6)))
(assert
 (not (and d_103_1 d_103_7)))
(assert
 (not (and d_103_1 d_103_8)))
(assert
 (not (and d_103_2 d_103_3)))
(assert
 (not (and d_103_2 d_103_4)))
(assert
 (not (and d_103_2 d_103_5)))
(assert
 (not (and d_103_2 d_103_6)))
(assert
 (not (and d_103_2 d_103_7)))
(assert
 (not (and d_103_2 d_103_8)))
(assert
 (not (and d_103_3 d_103_4)))
(assert
 (not (and d_103_3 d_103_5)))
(assert
 (not (and d_103_3 d_103_6)))
(assert
 (not (and d_103_3 d_103_7)))
(assert
 (not (and d_103_3 d_103_8)))
(assert
 (not (and d_103_4 d_103_5)))
(assert
 (not (and d_103_4 d_103_6)))
(assert
 (not (and d_103_4 d_103_7)))
(assert
 (not (and d_103_4 d_103_8)))
(assert
 (not (and d_103_5 d_103_6)))
(assert
 (not (and d_103_5 d_103_7)))
(assert
 (not (and d_103_5 d_103_8)))
(assert
 (not (and d_103_6 d_103_7)))
(assert
 (not (and d_103_6 d_103_8)))
(assert
 (not (and d_103_7 d_103_8)))
(assert
 (let (($x21105 (or false d_104_0)))
 (let (($x21107 (or $x21105 d_104_1)))
 (let (($x21109 (or $x21107 d_104_2)))
 (let (($x21111 (or $x21109 d_104_3)))
 (let (($x21113 (or $x21111 d_104_4)))
 (let (($x21115 (or $x21113 d_104_5)))
 (let (($x21117 (or $x21115 d_104_6)))
 (let (($x21119 (or $x21117 d_104_7)))
 (or $x21119 d_104_8))))))))))
(assert
 (not (and d_104_0 d_104_1)))
(assert
 (not (and d_104_0 d_104_2)))
(assert
 (not (and d_104_0 d_104_3)))
(assert
 (not (and d_104_0 d_104_4)))
(assert
 (not (and d_104_0 d_104_5)))
(assert
 (not (and d_104_0 d_104_6)))
(assert
 (not (and d_104_0 d_104_7)))
(assert
 (not (and d_104_0 d_104_8)))
(assert
 (not (and d_104_1 d_104_2)))
(assert
 (not (and d_104_1 d_104_3)))
(assert
 (not (and d_104_1 d_104_4)))
(assert
 (not (and d_104_1 d_104_5)))
(assert
 (not (and d_104_1 d_104_6)))
(assert
 (not (and d_104_1 d_104_7)))
(assert
 (not (and d_104_1 d_104_8)))
(assert
 (not (and d_104_2 d_104_3)))
(assert
 (not (and d_104_2 d_104_4)))
(assert
 (not (and d_104_2 d_104_5)))
(assert
 (not (and d_104_2 d_104_6)))
(assert
 (not (and d_104_2 d_104_7)))
(assert
 (not (and d_104_2 d_104_8)))
(assert
 (not (and d_104_3 d_104_4)))
(assert
 (not (and d_104_3 d_104_5)))
(assert
 (not (and d_104_3 d_104_6)))
(assert
 (not (and d_104_3 d_104_7)))
(assert
 (not (and d_104_3 d_104_8)))
(assert
 (not (and d_104_4 d_104_5)))
(assert
 (not (and d_104_4 d_104_6)))
(assert
 (not (and d_104_4 d_104_7)))
(assert
 (not (and d_104_4 d_104_8)))
(assert
 (not (and d_104_5 d_104_6)))
(assert
 (not (and d_104_5 d_104_7)))
(assert
 (not (and d_104_5 d_104_8)))
(assert
 (not (and d_104_6 d_104_7)))
(assert
 (not (and d_104_6 d_104_8)))
(assert
 (not (and d_104_7 d_104_8)))
(assert
 (let (($x21195 (or false d_105_0)))
 (let (($x21197 (or $x21195 d_105_1)))
 (let (($x21199 (or $x21197 d_105_2)))
 (let (($x21201 (or $x21199 d_105_3)))
 (let (($x21203 (or $x21201 d_105_4)))
 (let (($x21205 (or $x21203 d_105_5)))
 (let (($x21207 (or $x21205 d_105_6)))
 (let (($x21209 (or $x21207 d_105_7)))
 (or $x21209 d_105_8))))))))))
(assert
 (not (and d_105_0 d_105_1)))
(assert
 (not (and d_105_0 d_105_2)))
(assert
 (not (and d_105_0 d_105_3)))
(assert
 (not (and d_105_0 d_105_4)))
(assert
 (not (and d_105_0 d_105_5)))
(assert
 (not (and d_105_0 d_105_6)))
(assert
 (not (and d_105_0 d_105_7)))
(assert
 (not (and d_105_0 d_105_8)))
(assert
 (not (and d_105_1 d_105_2)))
(assert
 (not (and d_105_1 d_105_3)))
(assert
 (not (and d_105_1 d_105_4)))
(assert
 (not (and d_105_1 d_105_5)))
(assert
 (not (and d_105_1 d_105_6)))
(assert
 (not (and d_105_1 d_105_7)))
(assert
 (not (and d_105_1 d_105_8)))
(assert
 (not (and d_105_2 d_105_3)))
(assert
 (not (and d_105_2 d_105_4)))
(assert
 (not (and d_105_2 d_105_5)))
(assert
 (not (and d_105_2 d_105_6)))
(assert
 (not (and d_105_2 d_105_7)))
(assert
 (not (and d_105_2 d_105_8)))
(assert
 (not (and d_105_3 d_105_4)))
(assert
 (not (and d_105_3 d_105_5)))
(assert
 (not (and d_105_3 d_105_6)))
(assert
 (not (and d_105_3 d_105_7)))
(assert
 (not (and d_105_3 d_105_8)))
(assert
 (not (and d_105_4 d_105_5)))
(assert
 (not (and d_105_4 d_105_6)))
(assert
 (not (and d_105_4 d_105_7)))
(assert
 (not (and d_105_4 d_105_8)))
(assert
 (not (and d_105_5 d_105_6)))
(assert
 (not (and d_105_5 d_105_7)))
(assert
 (not (and d_105_5 d_105_8)))
(assert
 (not (and d_105_6 d_105_7)))
(assert
 (not (and d_105_6 d_105_8)))
(assert
 (not (and d_105_7 d_105_8)))
(assert
 (let (($x21285 (or false d_106_0)))
 (let (($x21287 (or $x21285 d_106_1)))
 (let (($x21289 (or $x21287 d_106_2)))
 (let (($x21291 (or $x21289 d_106_3)))
 (let (($x21293 (or $x21291 d_106_4)))
 (let (($x21295 (or $x21293 d_106_5)))
 (let (($x21297 (or $x21295 d_106_6)))
 (let (($x21299 (or $x21297 d_106_7)))
 (or $x21299 d_106_8))))))))))
(assert
 (not (and d_106_0 d_106_1)))
(assert
 (not (and d_106_0 d_106_2)))
(assert
 (not (and d_106_0 d_106_3)))
(assert
 (not (and d_106_0 d_106_4)))
(assert
 (not (and d_106_0 d_106_5)))
(assert
 (not (and d_106_0 d_106_6)))
(assert
 (not (and d_106_0 d_106_7)))
(assert
 (not (and d_106_0 d_106_8)))
(assert
 (not (and d_106_1 d_106_2)))
(assert
 (not (and d_106_1 d_106_3)))
(assert
 (not (and d_106_1 d_106_4)))
(assert
 (not (and d_106_1 d_106_5)))
(assert
 (not (and d_106_1 d_106_6)))
(assert
 (not (and d_106_1 d_106_7)))
(assert
 (not (and d_106_1 d_106_8)))
(assert
 (not (and d_106_2 d_106_3)))
(assert
 (not (and d_106_2 d_106_4)))
(assert
 (not (and d_106_2 d_106_5)))
(assert
 (not (and d_106_2 d_106_6)))
(assert
 (not (and d_106_2 d_106_7)))
(assert
 (not (and d_106_2 d_106_8)))
(assert
 (not (and d_106_3 d_106_4)))
(assert
 (not (and d_106_3 d_106_5)))
(assert
 (not (and d_106_3 d_106_6)))
(assert
 (not (and d_106_3 d_106_7)))
(assert
 (not (and d_106_3 d_106_8)))
(assert
 (not (and d_106_4 d_106_5)))
(assert
 (not (and d_106_4 d_106_6)))
(assert
 (not (and d_106_4 d_106_7)))
(assert
 (not (and d_106_4 d_106_8)))
(assert
 (not (and d_106_5 d_106_6)))
(assert
 (not (and d_106_5 d_106_7)))
(assert
 (not (and d_106_5 d_106_8)))
(assert
 (not (and d_106_6 d_106_7)))
(assert
 (not (and d_106_6 d_106_8)))
(assert
 (not (and d_106_7 d_106_8)))
(assert
 (let (($x21375 (or false d_107_0)))
 (let (($x21377 (or $x21375 d_107_1)))
 (let (($x21379 (or $x21377 d_107_2)))
 (let (($x21381 (or $x21379 d_107_3)))
 (let (($x21383 (or $x21381 d_107_4)))
 (let (($x21385 (or $x21383 d_107_5)))
 (let (($x21387 (or $x21385 d_107_6)))
 (let (($x21389 (or $x21387 d_107_7)))
 (or $x21389 d_107_8))))))))))
(assert
 (not (and d_107_0 d_107_1)))
(assert
 (not (and d_107_0 d_107_2)))
(assert
 (not (and d_107_0 d_107_3)))
(assert
 (not (and d_107_0 d_107_4)))
(assert
 (not (and d_107_0 d_107_5)))
(assert
 (not (and d_107_0 d_107_6)))
(assert
 (not (and d_107_0 d_107_7)))
(assert
 (not (and d_107_0 d_107_8)))
(assert
 (not (and d_107_1 d_107_2)))
(assert
 (not (and d_107_1 d_107_3)))
(assert
 (not (and d_107_1 d_107_4)))
(assert
 (not (and d_107_1 d_107_5)))
(assert
 (not (and d_107_1 d_107_6)))
(assert
 (not (and d_107_1 d_107_7)))
(assert
 (not (and d_107_1 d_107_8)))
(assert
 (not (and d_107_2 d_107_3)))
(assert
 (not (and d_107_2 d_107_4)))
(assert
 (not (and d_107_2 d_107_5)))
(assert
 (not (and d_107_2 d_107_6)))
(assert
 (not (and d_107_2 d_107_7)))
(assert
 (not (and d_107_2 d_107_8)))
(assert
 (not (and d_107_3 d_107_4)))
(assert
 (not (and d_107_3 d_107_5)))
(assert
 (not (and d_107_3 d_107_6)))
(assert
 (not (and d_107_3 d_107_7)))
(assert
 (not (and d_107_3 d_107_8)))
(assert
 (not (and d_107_4 d_107_5)))
(assert
 (not (and d_107_4 d_107_6)))
(assert
 (not (and d_107_4 d_107_7)))
(assert
 (not (and d_107_4 d_107_8)))
(assert
 (not (and d_107_5 d_107_6)))
(assert
 (not (and d_107_5 d_107_7)))
(assert
 (not (and d_107_5 d_107_8)))
(assert
 (not (and d_107_6 d_107_7)))
(assert
 (not (and d_107_6 d_107_8)))
(assert
 (not (and d_107_7 d_107_8)))
(assert
 (let (($x21465 (or false d_108_0)))
 (let (($x21467 (or $x21465 d_108_1)))
 (let (($x21469 (or $x21467 d_108_2)))
 (let (($x21471 (or $x21469 d_108_3)))
 (let (($x21473 (or $x21471 d_108_4)))
 (let (($x21475 (or $x21473 d_108_5)))
 (let (($x21477 (or $x21475 d_108_6)))
 (let (($x21479 (or $x21477 d_108_7)))
 (or $x21479 d_108_8))))))))))
(assert
 (not (and d_108_0 d_108_1)))
(assert
 (not (and d_108_0 d_108_2)))
(assert
 (not (and d_108_0 d_108_3)))
(assert
 (not (and d_108_0 d_108_4)))
(assert
 (not (and d_108_0 d_108_5)))
(assert
 (not (and d_108_0 d_108_6)))
(assert
 (not (and d_108_0 d_108_7)))
(assert
 (not (and d_108_0 d_108_8)))
(assert
 (not (and d_108_1 d_108_2)))
(assert
 (not (and d_108_1 d_108_3)))
(assert
 (not (and d_108_1 d_108_4)))
(assert
 (not (and d_108_1 d_108_5)))
(assert
 (not (and d_108_1 d_108_6)))
(assert
 (not (and d_108_1 d_108_7)))
(assert
 (not (and d_108_1 d_108_8)))
(assert
 (not (and d_108_2 d_108_3)))
(assert
 (not (and d_108_2 d_108_4)))
(assert
 (not (and d_108_2 d_108_5)))
(assert
 (not (and d_108_2 d_108_6)))
(assert
 (not (and d_108_2 d_108_7)))
(assert
 (not (and d_108_2 d_108_8)))
(assert
 (not (and d_108_3 d_108_4)))
(assert
 (not (and d_108_3 d_108_5)))
(assert
 (not (and d_108_3 d_108_6)))
(assert
 (not (and d_108_3 d_108_7)))
(assert
 (not (and d_108_3 d_108_8)))
(assert
 (not (and d_108_4 d_108_5)))
(assert
 (not (and d_108_4 d_108_6)))
(assert
 (not (and d_108_4 d_108_7)))
(assert
 (not (and d_108_4 d_108_8)))
(assert
 (not (and d_108_5 d_108_6)))
(assert
 (not (and d_108_5 d_108_7)))
(assert
 (not (and d_108_5 d_108_8)))
(assert
 (not (and d_108_6 d_108_7)))
(assert
 (not (and d_108_6 d_108_8)))
(assert
 (not (and d_108_7 d_108_8)))
(assert
 (let (($x21555 (or false d_109_0)))
 (let (($x21557 (or $x21555 d_109_1)))
 (let (($x21559 (or $x21557 d_109_2)))
 (let (($x21561 (or $x21559 d_109_3)))
 (let (($x21563 (or $x21561 d_109_4)))
 (let (($x21565 (or $x21563 d_109_5)))
 (let (($x21567 (or $x21565 d_109_6)))
 (let (($x21569 (or $x21567 d_109_7)))
 (or $x21569 d_109_8))))))))))
(assert
 (not (and d_109_0 d_109_1)))
(assert
 (not (and d_109_0 d_109_2)))
(assert
 (not (and d_109_0 d_109_3)))
(assert
 (not (and d_109_0 d_109_4)))
(assert
 (not (and d_109_0 d_109_5)))
(assert
 (not (and d_109_0 d_109_6)))
(assert
 (not (and d_109_0 d_109_7)))
(assert
 (not (and d_109_0 d_109_8)))
(assert
 (not (and d_109_1 d_109_2)))
(assert
 (not (and d_109_1 d_109_3)))
(assert
 (not (and d_109_1 d_109_4)))
(assert
 (not (and d_109_1 d_109_5)))
(assert
 (not (and d_109_1 d_109_6)))
(assert
 (not (and d_109_1 d_109_7)))
(assert
 (not (and d_109_1 d_109_8)))
(assert
 (not (and d_109_2 d_109_3)))
(assert
 (not (and d_109_2 d_109_4)))
(assert
 (not (and d_109_2 d_109_5)))
(assert
 (not (and d_109_2 d_109_6)))
(assert
 (not (and d_109_2 d_109_7)))
(assert
 (not (and d_109_2 d_109_8)))
(assert
 (not (and d_109_3 d_109_4)))
(assert
 (not (and d_109_3 d_109_5)))
(assert
 (not (and d_109_3 d_109_6)))
(assert
 (not (and d_109_3 d_109_7)))
(assert
 (not (and d_109_3 d_109_8)))
(assert
 (not (and d_109_4 d_109_5)))
(assert
 (not (and d_109_4 d_109_6)))
(assert
 (not (and d_109_4 d_109_7)))
(assert
 (not (and d_109_4 d_109_8)))
(assert
 (not (and d_109_5 d_109_6)))
(assert
 (not (and d_109_5 d_109_7)))
(assert
 (not (and d_109_5 d_109_8)))
(assert
 (not (and d_109_6 d_109_7)))
(assert
 (not (and d_109_6 d_109_8)))
(assert
 (not (and d_109_7 d_109_8)))
(assert
 (let (($x21645 (or false d_110_0)))
 (let (($x21647 (or $x21645 d_110_1)))
 (let (($x21649 (or $x21647 d_110_2)))
 (let (($x21651 (or $x21649 d_110_3)))
 (let (($x21653 (or $x21651 d_110_4)))
 (let (($x21655 (or $x21653 d_110_5)))
 (let (($x21657 (or $x21655 d_110_6)))
 (let (($x21659 (or $x21657 d_110_7)))
 (or $x21659 d_110_8))))))))))
(assert
 (not (and d_110_0 d_110_1)))
(assert
 (not (and d_110_0 d_110_2)))
(assert
 (not (and d_110_0 d_110_3)))
(assert
 (not (and d_110_0 d_110_4)))
(assert
 (not (and d_110_0 d_110_5)))
(assert
 (not (and d_110_0 d_110_6)))
(assert
 (not (and d_110_0 d_110_7)))
(assert
 (not (and d_110_0 d_110_8)))
(assert
 (not (and d_110_1 d_110_2)))
(assert
 (not (and d_110_1 d_110_3)))
(assert
 (not (and d_110_1 d_110_4)))
(assert
 (not (and d_110_1 d_110_5)))
(assert
 (not (and d_110_1 d_110_6)))
(assert
 (not (and d_110_1 d_110_7)))
(assert
 (not (and d_110_1 d_110_8)))
(assert
 (not (and d_110_2 d_110_3)))
(assert
 (not (and d_110_2 d_110_4)))
(assert
 (not (and d_110_2 d_110_5)))
(assert
 (not (and d_110_2 d_110_6)))
(assert
 (not (and d_110_2 d_110_7)))
(assert
 (not (and d_110_2 d_110_8)))
(assert
 (not (and d_110_3 d_110_4)))
(assert
 (not (and d_110_3 d_110_5)))
(assert
 (not (and d_110_3 d_110_6)))
(assert
 (not (and d_110_3 d_110_7)))
(assert
 (not (and d_110_3 d_110_8)))
(assert
 (not (and d_110_4 d_110_5)))
(assert
 (not (and d_110_4 d_110_6)))
(assert
 (not (and d_110_4 d_110_7)))
(assert
 (not (and d_110_4 d_110_8)))
(assert
 (not (and d_110_5 d_110_6)))
(assert
 (not (and d_110_5 d_110_7)))
(assert
 (not (and d_110_5 d_110_8)))
(assert
 (not (and d_110_6 d_110_7)))
(assert
 (not (and d_110_6 d_110_8)))
(assert
 (not (and d_110_7 d_110_8)))
(assert
 (let (($x21735 (or false d_111_0)))
 (let (($x21737 (or $x21735 d_111_1)))
 (let (($x21739 (or $x21737 d_111_2)))
 (let (($x21741 (or $x21739 d_111_3)))
 (let (($x21743 (or $x21741 d_111_4)))
 (let (($x21745 (or $x21743 d_111_5)))
 (let (($x21747 (or $x21745 d_111_6)))
 (let (($x21749 (or $x21747 d_111_7)))
 (or $x21749 d_111_8))))))))))
(assert
 (not (and d_111_0 d_111_1)))
(assert
 (not (and d_111_0 d_111_2)))
(assert
 (not (and d_111_0 d_111_3)))
(assert
 (not (and d_111_0 d_111_4)))
(assert
 (not (and d_111_0 d_111_5)))
(assert
 (not (and d_111_0 d_111_6)))
(assert
 (not (and d_111_0 d_111_7)))
(assert
 (not (and d_111_0 d_111_8)))
(assert
 (not (and d_111_1 d_111_2)))
(assert
 (not (and d_111_1 d_111_3)))
(assert
 (not (and d_111_1 d_111_4)))
(assert
 (not (and d_111_1 d_111_5)))
(assert
 (not (and d_111_1 d_111_6)))
(assert
 (not (and d_111_1 d_111_7)))
(assert
 (not (and d_111_1 d_111_8)))
(assert
 (not (and d_111_2 d_111_3)))
(assert
 (not (and d_111_2 d_111_4)))
(assert
 (not (and d_111_2 d_111_5)))
(assert
 (not (and d_111_2 d_111_6)))
(assert
 (not (and d_111_2 d_111_7)))
(assert
 (not (and d_111_2 d_111_8)))
(assert
 (not (and d_111_3 d_111_4)))
(assert
 (not (and d_111_3 d_111_5)))
(assert
 (not (and d_111_3 d_111_6)))
(assert
 (not (and d_111_3 d_111_7)))
(assert
 (not (and d_111_3 d_111_8)))
(assert
 (not (and d_111_4 d_111_5)))
(assert
 (not (and d_111_4 d_111_6)))
(assert
 (not (and d_111_4 d_111_7)))
(assert
 (not (and d_111_4 d_111_8)))
(assert
 (not (and d_111_5 d_111_6)))
(assert
 (not (and d_111_5 d_111_7)))
(assert
 (not (and d_111_5 d_111_8)))
(assert
 (not (and d_111_6 d_111_7)))
(assert
 (not (and d_111_6 d_111_8)))
(assert
 (not (and d_111_7 d_111_8)))
(assert
 (let (($x21825 (or false d_112_0)))
 (let (($x21827 (or $x21825 d_112_1)))
 (let (($x21829 (or $x21827 d_112_2)))
 (let (($x21831 (or $x21829 d_112_3)))
 (let (($x21833 (or $x21831 d_112_4)))
 (let (($x21835 (or $x21833 d_112_5)))
 (let (($x21837 (or $x21835 d_112_6)))
 (let (($x21839 (or $x21837 d_112_7)))
 (or $x21839 d_112_8))))))))))
(assert
 (not (and d_112_0 d_112_1)))
(assert
 (not (and d_112_0 d_112_2)))
(assert
 (not (and d_112_0 d_112_3)))
(assert
 (not (and d_112_0 d_112_4)))
(assert
 (not (and d_112_0 d_112_5)))
(assert
 (not (and d_112_0 d_112_6)))
(assert
 (not (and d_112_0 d_112_7)))
(assert
 (not (and d_112_0 d_112_8)))
(assert
 (not (and d_112_1 d_112_2)))
(assert
 (not (and d_112_1 d_112_3)))
(assert
 (not (and d_112_1 d_112_4)))
(assert
 (not (and d_112_1 d_112_5)))
(assert
 (not (and d_112_1 d_112_6)))
(assert
 (not (and d_112_1 d_112_7)))
(assert
 (not (and d_112_1 d_112_8)))
(assert
 (not (and d_112_2 d_112_3)))
(assert
 (not (and d_112_2 d_112_4)))
(assert
 (not (and d_112_2 d_112_5)))
(assert
 (not (and d_112_2 d_112_6)))
(assert
 (not (and d_112_2 d_112_7)))
(assert
 (not (and d_112_2 d_112_8)))
(assert
 (not (and d_112_3 d_112_4)))
(assert
 (not (and d_112_3 d_112_5)))
(assert
 (not (and d_112_3 d_112_6)))
(assert
 (not (and d_112_3 d_112_7)))
(assert
 (not (and d_112_3 d_112_8)))
(assert
 (not (and d_112_4 d_112_5)))
(assert
 (not (and d_112_4 d_112_6)))
(assert
 (not (and d_112_4 d_112_7)))
(assert
 (not (and d_112_4 d_112_8)))
(assert
 (not (and d_112_5 d_112_6)))
(assert
 (not (and d_112_5 d_112_7)))
(assert
 (not (and d_112_5 d_112_8)))
(assert
 (not (and d_112_6 d_112_7)))
(assert
 (not (and d_112_6 d_112_8)))
(assert
 (not (and d_112_7 d_112_8)))
(assert
 (let (($x21915 (or false d_113_0)))
 (let (($x21917 (or $x21915 d_113_1)))
 (let (($x21919 (or $x21917 d_113_2)))
 (let (($x21921 (or $x21919 d_113_3)))
 (let (($x21923 (or $x21921 d_113_4)))
 (let (($x21925 (or $x21923 d_113_5)))
 (let (($x21927 (or $x21925 d_113_6)))
 (let (($x21929 (or $x21927 d_113_7)))
 (or $x21929 d_113_8))))))))))
(assert
 (not (and d_113_0 d_113_1)))
(assert
 (not (and d_113_0 d_113_2)))
(assert
 (not (and d_113_0 d_113_3)))
(assert
 (not (and d_113_0 d_113_4)))
(assert
 (not (and d_113_0 d_113_5)))
(assert
 (not (and d_113_0 d_113_6)))
(assert
 (not (and d_113_0 d_113_7)))
(assert
 (not (and d_113_0 d_113_8)))
(assert
 (not (and d_113_1 d_113_2)))
(assert
 (not (and d_113_1 d_113_3)))
(assert
 (not (and d_113_1 d_113_4)))
(assert
 (not (and d_113_1 d_113_5)))
(assert
 (not (and d_113_1 d_113_6)))
(assert
 (not (and d_113_1 d_113_7)))
(assert
 (not (and d_113_1 d_113_8)))
(assert
 (not (and d_113_2 d_113_3)))
(assert
 (not (and d_113_2 d_113_4)))
(assert
 (not (and d_113_2 d_113_5)))
(assert
 (not (and d_113_2 d_113_6)))
(assert
 (not (and d_113_2 d_113_7)))
(assert
 (not (and d_113_2 d_113_8)))
(assert
 (not (and d_113_3 d_113_4)))
(assert
 (not (and d_113_3 d_113_5)))
(assert
 (not (and d_113_3 d_113_6)))
(assert
 (not (and d_113_3 d_113_7)))
(assert
 (not (and d_113_3 d_113_8)))
(assert
 (not (and d_113_4 d_113_5)))
(assert
 (not (and d_113_4 d_113_6)))
(assert
 (not (and d_113_4 d_113_7)))
(assert
 (not (and d_113_4 d_113_8)))
(assert
 (not (and d_113_5 d_113_6)))
(assert
 (not (and d_113_5 d_113_7)))
(assert
 (not (and d_113_5 d_113_8)))
(assert
 (not (and d_113_6 d_113_7)))
(assert
 (not (and d_113_6 d_113_8)))
(assert
 (not (and d_113_7 d_113_8)))
(assert
 (let (($x22005 (or false d_114_0)))
 (let (($x22007 (or $x22005 d_114_1)))
 (let (($x22009 (or $x22007 d_114_2)))
 (let (($x22011 (or $x22009 d_114_3)))
 (let (($x22013 (or $x22011 d_114_4)))
 (let (($x22015 (or $x22013 d_114_5)))
 (let (($x22017 (or $x22015 d_114_6)))
 (let (($x22019 (or $x22017 d_114_7)))
 (or $x22019 d_114_8))))))))))
(assert
 (not (and d_114_0 d_114_1)))
(assert
 (not (and d_114_0 d_114_2)))
(assert
 (not (and d_114_0 d_114_3)))
(assert
 (not (and d_114_0 d_114_4)))
(assert
 (not (and d_114_0 d_114_5)))
(assert
 (not (and d_114_0 d_114_6)))
(assert
 (not (and d_114_0 d_114_7)))
(assert
 (not (and d_114_0 d_114_8)))
(assert
 (not (and d_114_1 d_114_2)))
(assert
 (not (and d_114_1 d_114_3)))
(assert
 (not (and d_114_1 d_114_4)))
(assert
 (not (and d_114_1 d_114_5)))
(assert
 (not (and d_114_1 d_114_6)))
(assert
 (not (and d_114_1 d_114_7)))
(assert
 (not (and d_114_1 d_114_8)))
(assert
 (not (and d_114_2 d_114_3)))
(assert
 (not (and d_114_2 d_114_4)))
(assert
 (not (and d_114_2 d_114_5)))
(assert
 (not (and d_114_2 d_114_6)))
(assert
 (not (and d_114_2 d_114_7)))
(assert
 (not (and d_114_2 d_114_8)))
(assert
 (not (and d_114_3 d_114_4)))
(assert
 (not (and d_114_3 d_114_5)))
(assert
 (not (and d_114_3 d_114_6)))
(assert
 (not (and d_114_3 d_114_7)))
(assert
 (not (and d_114_3 d_114_8)))
(assert
 (not (and d_114_4 d_114_5)))
(assert
 (not (and d_114_4 d_114_6)))
(assert
 (not (and d_114_4 d_114_7)))
(assert
 (not (and d_114_4 d_114_8)))
(assert
 (not (and d_114_5 d_114_6)))
(assert
 (not (and d_114_5 d_114_7)))
(assert
 (not (and d_114_5 d_114_8)))
(assert
 (not (and d_114_6 d_114_7)))
(assert
 (not (and d_114_6 d_114_8)))
(assert
 (not (and d_114_7 d_114_8)))
(assert
 (let (($x22095 (or false d_115_0)))
 (let (($x22097 (or $x22095 d_115_1)))
 (let (($x22099 (or $x22097 d_115_2)))
 (let (($x22101 (or $x22099 d_115_3)))
 (let (($x22103 (or $x22101 d_115_4)))
 (let (($x22105 (or $x22103 d_115_5)))
 (let (($x22107 (or $x22105 d_115_6)))
 (let (($x22109 (or $x22107 d_115_7)))
 (or $x22109 d_115_8))))))))))
(assert
 (not (and d_115_0 d_115_1)))
(assert
 (not (and d_115_0 d_115_2)))
(assert
 (not (and d_115_0 d_115_3)))
(assert
 (not (and d_115_0 d_115_4)))
(assert
 (not (and d_115_0 d_115_5)))
(assert
 (not (and d_115_0 d_115_6)))
(assert
 (not (and d_115_0 d_115_7)))
(assert
 (not (and d_115_0 d_115_8)))
(assert
 (not (and d_115_1 d_115_2)))
(assert
 (not (and d_115_1 d_115_3)))
(assert
 (not (and d_115_1 d_115_4)))
(assert
 (not (and d_115_1 d_115_5)))
(assert
 (not (and d_115_1 d_115_6)))
(assert
 (not (and d_115_1 d_115_7)))
(assert
 (not (and d_115_1 d_115_8)))
(assert
 (not (and d_115_2 d_115_3)))
(assert
 (not (and d_115_2 d_115_4)))
(assert
 (not (and d_115_2 d_115_5)))
(assert
 (not (and d_115_2 d_115_6)))
(assert
 (not (and d_115_2 d_115_7)))
(assert
 (not (and d_115_2 d_115_8)))
(assert
 (not (and d_115_3 d_115_4)))
(assert
 (not (and d_115_3 d_115_5)))
(assert
 (not (and d_115_3 d_115_6)))
(assert
 (not (and d_115_3 d_115_7)))
(assert
 (not (and d_115_3 d_115_8)))
(assert
 (not (and d_115_4 d_115_5)))
(assert
 (not (and d_115_4 d_115_6)))
(assert
 (not (and d_115_4 d_115_7)))
(assert
 (not (and d_115_4 d_115_8)))
(assert
 (not (and d_115_5 d_115_6)))
(assert
 (not (and d_115_5 d_115_7)))
(assert
 (not (and d_115_5 d_115_8)))
(assert
 (not (and d_115_6 d_115_7)))
(assert
 (not (and d_115_6 d_115_8)))
(assert
 (not (and d_115_7 d_115_8)))
(assert
 (let (($x22185 (or false d_116_0)))
 (let (($x22187 (or $x22185 d_116_1)))
 (let (($x22189 (or $x22187 d_116_2)))
 (let (($x22191 (or $x22189 d_116_3)))
 (let (($x22193 (or $x22191 d_116_4)))
 (let (($x22195 (or $x22193 d_116_5)))
 (let (($x22197 (or $x22195 d_116_6)))
 (let (($x22199 (or $x22197 d_116_7)))
 (or $x22199 d_116_8))))))))))
(assert
 (not (and d_116_0 d_116_1)))
(assert
 (not (and d_116_0 d_116_2)))
(assert
 (not (and d_116_0 d_116_3)))
(assert
 (not (and d_116_0 d_116_4)))
(assert
 (not (and d_116_0 d_116_5)))
(assert
 (not (and d_116_0 d_116_6)))
(assert
 (not (and d_116_0 d_116_7)))
(assert
 (not (and d_116_0 d_116_8)))
(assert
 (not (and d_116_1 d_116_2)))
(assert
 (not (and d_116_1 d_116_3)))
(assert
 (not (and d_116_1 d_116_4)))
(assert
 (not (and d_116_1 d_116_5)))
(assert
 (not (and d_116_1 d_116_6)))
(assert
 (not (and d_116_1 d_116_7)))
(assert
 (not (and d_116_1 d_116_8)))
(assert
 (not (and d_116_2 d_116_3)))
(assert
 (not (and d_116_2 d_116_4)))
(assert
 (not (and d_116_2 d_116_5)))
(assert
 (not (and d_116_2 d_116_6)))
(assert
 (not (and d_116_2 d_116_7)))
(assert
 (not (and d_116_2 d_116_8)))
(assert
 (not (and d_116_3 d_116_4)))
(assert
 (not (and d_116_3 d_116_5)))
(assert
 (not (and d_116_3 d_116_6)))
(assert
 (not (and d_116_3 d_116_7)))
(assert
 (not (and d_116_3 d_116_8)))
(assert
 (not (and d_116_4 d_116_5)))
(assert
 (not (and d_116_4 d_116_6)))
(assert
 (not (and d_116_4 d_116_7)))
(assert
 (not (and d_116_4 d_116_8)))
(assert
 (not (and d_116_5 d_116_6)))
(assert
 (not (and d_116_5 d_116_7)))
(assert
 (not (and d_116_5 d_116_8)))
(assert
 (not (and d_116_6 d_116_7)))
(assert
 (not (and d_116_6 d_116_8)))
(assert
 (not (and d_116_7 d_116_8)))
(assert
 (let (($x22275 (or false d_117_0)))
 (let (($x22277 (or $x22275 d_117_1)))
 (let (($x22279 (or $x22277 d_117_2)))
 (let (($x22281 (or $x22279 d_117_3)))
 (let (($x22283 (or $x22281 d_117_4)))
 (let (($x22285 (or $x22283 d_117_5)))
 (let (($x22287 (or $x22285 d_117_6)))
 (let (($x22289 (or $x22287 d_117_7)))
 (or $x22289 d_117_8))))))))))
(assert
 (not (and d_117_0 d_117_1)))
(assert
 (not (and d_117_0 d_117_2)))
(assert
 (not (and d_117_0 d_117_3)))
(assert
 (not (and d_117_0 d_117_4)))
(assert
 (not (and d_117_0 d_117_5)))
(assert
 (not (and d_117_0 d_117_6)))
(assert
 (not (and d_117_0 d_117_7)))
(assert
 (not (and d_117_0 d_117_8)))
(assert
 (not (and d_117_1 d_117_2)))
(assert
 (not (and d_117_1 d_117_3)))
(assert
 (not (and d_117_1 d_117_4)))
(assert
 (not (and d_117_1 d_117_5)))
(assert
 (not (and d_117_1 d_117_6)))
(assert
 (not (and d_117_1 d_117_7)))
(assert
 (not (and d_117_1 d_117_8)))
(assert
 (not (and d_117_2 d_117_3)))
(assert
 (not (and d_117_2 d_117_4)))
(assert
 (not (and d_117_2 d_117_5)))
(assert
 (not (and d_117_2 d_117_6)))
(assert
 (not (and d_117_2 d_117_7)))
(assert
 (not (and d_117_2 d_117_8)))
(assert
 (not (and d_117_3 d_117_4)))
(assert
 (not (and d_117_3 d_117_5)))
(assert
 (not (and d_117_3 d_117_6)))
(assert
 (not (and d_117_3 d_117_7)))
(assert
 (not (and d_117_3 d_117_8)))
(assert
 (not (and d_117_4 d_117_5)))
(assert
 (not (and d_117_4 d_117_6)))
(assert
 (not (and d_117_4 d_117_7)))
(assert
 (not (and d_117_4 d_117_8)))
(assert
 (not (and d_117_5 d_117_6)))
(assert
 (not (and d_117_5 d_117_7)))
(assert
 (not (and d_117_5 d_117_8)))
(assert
 (not (and d_117_6 d_117_7)))
(assert
 (not (and d_117_6 d_117_8)))
(assert
 (not (and d_117_7 d_117_8)))
(assert
 (let (($x22365 (or false d_118_0)))
 (let (($x22367 (or $x22365 d_118_1)))
 (let (($x22369 (or $x22367 d_118_2)))
 (let (($x22371 (or $x22369 d_118_3)))
 (let (($x22373 (or $x22371 d_118_4)))
 (let (($x22375 (or $x22373 d_118_5)))
 (let (($x22377 (or $x22375 d_118_6)))
 (let (($x22379 (or $x22377 d_118_7)))
 (or $x22379 d_118_8))))))))))
(assert
 (not (and d_118_0 d_118_1)))
(assert
 (not (and d_118_0 d_118_2)))
(assert
 (not (and d_118_0 d_118_3)))
(assert
 (not (and d_118_0 d_118_4)))
(assert
 (not (and d_118_0 d_118_5)))
(assert
 (not (and d_118_0 d_118_6)))
(assert
 (not (and d_118_0 d_118_7)))
(assert
 (not (and d_118_0 d_118_8)))
(assert
 (not (and d_118_1 d_118_2)))
(assert
 (not (and d_118_1 d_118_3)))
(assert
 (not (and d_118_1 d_118_4)))
(assert
 (not (and d_118_1 d_118_5)))
(assert
 (not (and d_118_1 d_118_6)))
(assert
 (not (and d_118_1 d_118_7)))
(assert
 (not (and d_118_1 d_118_8)))
(assert
 (not (and d_118_2 d_118_3)))
(assert
 (not (and d_118_2 d_118_4)))
(assert
 (not (and d_118_2 d_118_5)))
(assert
 (not (and d_118_2 d_118_6)))
(assert
 (not (and d_118_2 d_118_7)))
(assert
 (not (and d_118_2 d_118_8)))
(assert
 (not (and d_118_3 d_118_4)))
(assert
 (not (and d_118_3 d_118_5)))
(assert
 (not (and d_118_3 d_118_6)))
(assert
 (not (and d_118_3 d_118_7)))
(assert
 (not (and d_118_3 d_118_8)))
(assert
 (not (and d_118_4 d_118_5)))
(assert
 (not (and d_118_4 d_118_6)))
(assert
 (not (and d_118_4 d_118_7)))
(assert
 (not (and d_118_4 d_118_8)))
(assert
 (not (and d_118_5 d_118_6)))
(assert
 (not (and d_118_5 d_118_7)))
(assert
 (not (and d_118_5 d_118_8)))
(assert
 (not (and d_118_6 d_118_7)))
(assert
 (not (and d_118_6 d_118_8)))
(assert
 (not (and d_118_7 d_118_8)))
(assert
 (let (($x22455 (or false d_119_0)))
 (let (($x22457 (or $x22455 d_119_1)))
 (let (($x22459 (or $x22457 d_119_2)))
 (let (($x22461 (or $x22459 d_119_3)))
 (let (($x22463 (or $x22461 d_119_4)))
 (let (($x22465 (or $x22463 d_119_5)))
 (let (($x22467 (or $x22465 d_119_6)))
 (let (($x22469 (or $x22467 d_119_7)))
 (or $x22469 d_119_8))))))))))
(assert
 (not (and d_119_0 d_119_1)))
(assert
 (not (and d_119_0 d_119_2)))
(assert
 (not (and d_119_0 d_119_3)))
(assert
 (not (and d_119_0 d_119_4)))
(assert
 (not (and d_119_0 d_119_5)))
(assert
 (not (and d_119_0 d_119_6)))
(assert
 (not (and d_119_0 d_119_7)))
(assert
 (not (and d_119_0 d_119_8)))
(assert
 (not (and d_119_1 d_119_2)))
(assert
 (not (and d_119_1 d_119_3)))
(assert
 (not (and d_119_1 d_119_4)))
(assert
 (not (and d_119_1 d_119_5)))
(assert
 (not (and d_119_1 d_119_6)))
(assert
 (not (and d_119_1 d_119_7)))
(assert
 (not (and d_119_1 d_119_8)))
(assert
 (not (and d_119_2 d_119_3)))
(assert
 (not (and d_119_2 d_119_4)))
(assert
 (not (and d_119_2 d_119_5)))
(assert
 (not (and d_119_2 d_119_6)))
(assert
 (not (and d_119_2 d_119_7)))
(assert
 (not (and d_119_2 d_119_8)))
(assert
 (not (and d_119_3 d_119_4)))
(assert
 (not (and d_119_3 d_119_5)))
(assert
 (not (and d_119_3 d_119_6)))
(assert
 (not (and d_119_3 d_119_7)))
(assert
 (not (and d_119_3 d_119_8)))
(assert
 (not (and d_119_4 d_119_5)))
(assert
 (not (and d_119_4 d_119_6)))
(assert
 (not (and d_119_4 d_119_7)))
(assert
 (not (and d_119_4 d_119_8)))
(assert
 (not (and d_119_5 d_119_6)))
(assert
 (not (and d_119_5 d_119_7)))
(assert
 (not (and d_119_5 d_119_8)))
(assert
 (not (and d_119_6 d_119_7)))
(assert
 (not (and d_119_6 d_119_8)))
(assert
 (not (and d_119_7 d_119_8)))
(assert
 (let (($x22545 (or false d_120_0)))
 (let (($x22547 (or $x22545 d_120_1)))
 (let (($x22549 (or $x22547 d_120_2)))
 (let (($x22551 (or $x22549 d_120_3)))
 (let (($x22553 (or $x22551 d_120_4)))
 (let (($x22555 (or $x22553 d_120_5)))
 (let (($x22557 (or $x22555 d_120_6)))
 (let (($x22559 (or $x22557 d_120_7)))
 (or $x22559 d_120_8))))))))))
(assert
 (not (and d_120_0 d_120_1)))
(assert
 (not (and d_120_0 d_120_2)))
(assert
 (not (and d_120_0 d_120_3)))
(assert
 (not (and d_120_0 d_120_4)))
(assert
 (not (and d_120_0 d_120_5)))
(assert
 (not (and d_120_0 d_120_6)))
(assert
 (not (and d_120_0 d_120_7)))
(assert
 (not (and d_120_0 d_120_8)))
(assert
 (not (and d_120_1 d_120_2)))
(assert
 (not (and d_120_1 d_120_3)))
(assert
 (not (and d_120_1 d_120_4)))
(assert
 (not (and d_120_1 d_120_5)))
(assert
 (not (and d_120_1 d_120_6)))
(assert
 (not (and d_120_1 d_120_7)))
(assert
 (not (and d_120_1 d_120_8)))
(assert
 (not (and d_120_2 d_120_3)))
(assert
 (not (and d_120_2 d_120_4)))
(assert
 (not (and d_120_2 d_120_5)))
(assert
 (not (and d_120_2 d_120_6)))
(assert
 (not (and d_120_2 d_120_7)))
(assert
 (not (and d_120_2 d_120_8)))
(assert
 (not (and d_120_3 d_120_4)))
(assert
 (not (and d_120_3 d_120_5)))
(assert
 (not (and d_120_3 d_120_6)))
(assert
 (not (and d_120_3 d_120_7)))
(assert
 (not (and d_120_3 d_120_8)))
(assert
 (not (and d_120_4 d_120_5)))
(assert
 (not (and d_120_4 d_120_6)))
(assert
 (not (and d_120_4 d_120_7)))
(assert
 (not (and d_120_4 d_120_8)))
(assert
 (not (and d_120_5 d_120_6)))
(assert
 (not (and d_120_5 d_120_7)))
(assert
 (not (and d_120_5 d_120_8)))
(assert
 (not (and d_120_6 d_120_7)))
(assert
 (not (and d_120_6 d_120_8)))
(assert
 (not (and d_120_7 d_120_8)))
(assert
 (let (($x22635 (or false d_121_0)))
 (let (($x22637 (or $x22635 d_121_1)))
 (let (($x22639 (or $x22637 d_121_2)))
 (let (($x22641 (or $x22639 d_121_3)))
 (let (($x22643 (or $x22641 d_121_4)))
 (let (($x22645 (or $x22643 d_121_5)))
 (let (($x22647 (or $x22645 d_121_6)))
 (let (($x22649 (or $x22647 d_121_7)))
 (or $x22649 d_121_8))))))))))
(assert
 (not (and d_121_0 d_121_1)))
(assert
 (not (and d_121_0 d_121_2)))
(assert
 (not (and d_121_0 d_121_3)))
(assert
 (not (and d_121_0 d_121_4)))
(assert
 (not (and d_121_0 d_121_5)))
(assert
 (not (and d_121_0 d_121_6)))
(assert
 (not (and d_121_0 d_121_7)))
(assert
 (not (and d_121_0 d_121_8)))
(assert
 (not (and d_121_1 d_121_2)))
(assert
 (not (and d_121_1 d_121_3)))
(assert
 (not (and d_121_1 d_121_4)))
(assert
 (not (and d_121_1 d_121_5)))
(assert
 (not (and d_121_1 d_121_6)))
(assert
 (not (and d_121_1 d_121_7)))
(assert
 (not (and d_121_1 d_121_8)))
(assert
 (not (and d_121_2 d_121_3)))
(assert
 (not (and d_121_2 d_121_4)))
(assert
 (not (and d_121_2 d_121_5)))
(assert
 (not (and d_121_2 d_121_6)))
(assert
 (not (and d_121_2 d_121_7)))
(assert
 (not (and d_121_2 d_121_8)))
(assert
 (not (and d_121_3 d_121_4)))
(assert
 (not (and d_121_3 d_121_5)))
(assert
 (not (and d_121_3 d_121_6)))
(assert
 (not (and d_121_3 d_121_7)))
(assert
 (not (and d_121_3 d_121_8)))
(assert
 (not (and d_121_4 d_121_5)))
(assert
 (not (and d_121_4 d_121_6)))
(assert
 (not (and d_121_4 d_121_7)))
(assert
 (not (and d_121_4 d_121_8)))
(assert
 (not (and d_121_5 d_121_6)))
(assert
 (not (and d_121_5 d_121_7)))
(assert
 (not (and d_121_5 d_121_8)))
(assert
 (not (and d_121_6 d_121_7)))
(assert
 (not (and d_121_6 d_121_8)))
(assert
 (not (and d_121_7 d_121_8)))
(assert
 (let (($x22725 (or false d_122_0)))
 (let (($x22727 (or $x22725 d_122_1)))
 (let (($x22729 (or $x22727 d_122_2)))
 (let (($x22731 (or $x22729 d_122_3)))
 (let (($x22733 (or $x22731 d_122_4)))
 (let (($x22735 (or $x22733 d_122_5)))
 (let (($x22737 (or $x22735 d_122_6)))
 (let (($x22739 (or $x22737 d_122_7)))
 (or $x22739 d_122_8))))))))))
(assert
 (not (and d_122_0 d_122_1)))
(assert
 (not (and d_122_0 d_122_2)))
(assert
 (not (and d_122_0 d_122_3)))
(assert
 (not (and d_122_0 d_122_4)))
(assert
 (not (and d_122_0 d_122_5)))
(assert
 (not (and d_122_0 d_122_6)))
(assert
 (not (and d_122_0 d_122_7)))
(assert
 (not (and d_122_0 d_122_8)))
(assert
 (not (and d_122_1 d_122_2)))
(assert
 (not (and d_122_1 d_122_3)))
(assert
 (not (and d_122_1 d_122_4)))
(assert
 (not (and d_122_1 d_122_5)))
(assert
 (not (and d_122_1 d_122_6)))
(assert
 (not (and d_122_1 d_122_7)))
(assert
 (not (and d_122_1 d_122_8)))
(assert
 (not (and d_122_2 d_122_3)))
(assert
 (not (and d_122_2 d_122_4)))
(assert
 (not (and d_122_2 d_122_5)))
(assert
 (not (and d_122_2 d_122_6)))
(assert
 (not (and d_122_2 d_122_7)))
(assert
 (not (and d_122_2 d_122_8)))
(assert
 (not (and d_122_3 d_122_4)))
(assert
 (not (and d_122_3 d_122_5)))
(assert
 (not (and d_122_3 d_122_6)))
(assert
 (not (and d_122_3 d_122_7)))
(assert
 (not (and d_122_3 d_122_8)))
(assert
 (not (and d_122_4 d_122_5)))
(assert
 (not (and d_122_4 d_122_6)))
(assert
 (not (and d_122_4 d_122_7)))
(assert
 (not (and d_122_4 d_122_8)))
(assert
 (not (and d_122_5 d_122_6)))
(assert
 (not (and d_122_5 d_122_7)))
(assert
 (not (and d_122_5 d_122_8)))
(assert
 (not (and d_122_6 d_122_7)))
(assert
 (not (and d_122_6 d_122_8)))
(assert
 (not (and d_122_7 d_122_8)))
(assert
 (let (($x22815 (or false d_123_0)))
 (let (($x22817 (or $x22815 d_123_1)))
 (let (($x22819 (or $x22817 d_123_2)))
 (let (($x22821 (or $x22819 d_123_3)))
 (let (($x22823 (or $x22821 d_123_4)))
 (let (($x22825 (or $x22823 d_123_5)))
 (let (($x22827 (or $x22825 d_123_6)))
 (let (($x22829 (or $x22827 d_123_7)))
 (or $x22829 d_123_8))))))))))
(assert
 (not (and d_123_0 d_123_1)))
(assert
 (not (and d_123_0 d_123_2)))
(assert
 (not (and d_123_0 d_123_3)))
(assert
 (not (and d_123_0 d_123_4)))
(assert
 (not (and d_123_0 d_123_5)))
(assert
 (not (and d_123_0 d_123_6)))
(assert
 (not (and d_123_0 d_123_7)))
(assert
 (not (and d_123_0 d_123_8)))
(assert
 (not (and d_123_1 d_123_2)))
(assert
 (not (and d_123_1 d_123_3)))
(assert
 (not (and d_123_1 d_123_4)))
(assert
 (not (and d_123_1 d_123_5)))
(assert
 (not (and d_123_1 d_123_6)))
(assert
 (not (and d_123_1 d_123_7)))
(assert
 (not (and d_123_1 d_123_8)))
(assert
 (not (and d_123_2 d_123_3)))
(assert
 (not (and d_123_2 d_123_4)))
(assert
 (not (and d_123_2 d_123_5)))
(assert
 (not (and d_123_2 d_123_6)))
(assert
 (not (and d_123_2 d_123_7)))
(assert
 (not (and d_123_2 d_123_8)))
(assert
 (not (and d_123_3 d_123_4)))
(assert
 (not (and d_123_3 d_123_5)))
(assert
 (not (and d_123_3 d_123_6)))
(assert
 (not (and d_123_3 d_123_7)))
(assert
 (not (and d_123_3 d_123_8)))
(assert
 (not (and d_123_4 d_123_5)))
(assert
 (not (and d_123_4 d_123_6)))
(assert
 (not (and d_123_4 d_123_7)))
(assert
 (not (and d_123_4 d_123_8)))
(assert
 (not (and d_123_5 d_123_6)))
(assert
 (not (and d_123_5 d_123_7)))
(assert
 (not (and d_123_5 d_123_8)))
(assert
 (not (and d_123_6 d_123_7)))
(assert
 (not (and d_123_6 d_123_8)))
(assert
 (not (and d_123_7 d_123_8)))
(assert
 (let (($x22905 (or false d_124_0)))
 (let (($x22907 (or $x22905 d_124_1)))
 (let (($x22909 (or $x22907 d_124_2)))
 (let (($x22911 (or $x22909 d_124_3)))
 (let (($x22913 (or $x22911 d_124_4)))
 (let (($x22915 (or $x22913 d_124_5)))
 (let (($x22917 (or $x22915 d_124_6)))
 (let (($x22919 (or $x22917 d_124_7)))
 (or $x22919 d_124_8))))))))))
(assert
 (not (and d_124_0 d_124_1)))
(assert
 (not (and d_124_0 d_124_2)))
(assert
 (not (and d_124_0 d_124_3)))
(assert
 (not (and d_124_0 d_124_4)))
(assert
 (not (and d_124_0 d_124_5)))
(assert
 (not (and d_124_0 d_124_6)))
(assert
 (not (and d_124_0 d_124_7)))
(assert
 (not (and d_124_0 d_124_8)))
(assert
 (not (and d_124_1 d_124_2)))
(assert
 (not (and d_124_1 d_124_3)))
(assert
 (not (and d_124_1 d_124_4)))
(assert
 (not (and d_124_1 d_124_5)))
(assert
 (not (and d_124_1 d_124_6)))
(assert
 (not (and d_124_1 d_124_7)))
(assert
 (not (and d_124_1 d_124_8)))
(assert
 (not (and d_124_2 d_124_3)))
(assert
 (not (and d_124_2 d_124_4)))
(assert
 (not (and d_124_2 d_124_5)))
(assert
 (not (and d_124_2 d_124_6)))
(assert
 (not (and d_124_2 d_124_7)))
(assert
 (not (and d_124_2 d_124_8)))
(assert
 (not (and d_124_3 d_124_4)))
(assert
 (not (and d_124_3 d_124_5)))
(assert
 (not (and d_124_3 d_124_6)))
(assert
 (not (and d_124_3 d_124_7)))
(assert
 (not (and d_124_3 d_124_8)))
(assert
 (not (and d_124_4 d_124_5)))
(assert
 (not (and d_124_4 d_124_6)))
(assert
 (not (and d_124_4 d_124_7)))
(assert
 (not (and d_124_4 d_124_8)))
(assert
 (not (and d_124_5 d_124_6)))
(assert
 (not (and d_124_5 d_124_7)))
(assert
 (not (and d_124_5 d_124_8)))
(assert
 (not (and d_124_6 d_124_7)))
(assert
 (not (and d_124_6 d_124_8)))
(assert
 (not (and d_124_7 d_124_8)))
(assert
 (let (($x22995 (or false d_125_0)))
 (let (($x22997 (or $x22995 d_125_1)))
 (let (($x22999 (or $x22997 d_125_2)))
 (let (($x23001 (or $x22999 d_125_3)))
 (let (($x23003 (or $x23001 d_125_4)))
 (let (($x23005 (or $x23003 d_125_5)))
 (let (($x23007 (or $x23005 d_125_6)))
 (let (($x23009 (or $x23007 d_125_7)))
 (or $x23009 d_125_8))))))))))
(assert
 (not (and d_125_0 d_125_1)))
(assert
 (not (and d_125_0 d_125_2)))
(assert
 (not (and d_125_0 d_125_3)))
(assert
 (not (and d_125_0 d_125_4)))
(assert
 (not (and d_125_0 d_125_5)))
(assert
 (not (and d_125_0 d_125_6)))
(assert
 (not (and d_125_0 d_125_7)))
(assert
 (not (and d_125_0 d_125_8)))
(assert
 (not (and d_125_1 d_125_2)))
(assert
 (not (and d_125_1 d_125_3)))
(assert
 (not (and d_125_1 d_125_4)))
(assert
 (not (and d_125_1 d_125_5)))
(assert
 (not (and d_125_1 d_125_6)))
(assert
 (not (and d_125_1 d_125_7)))
(assert
 (not (and d_125_1 d_125_8)))
(assert
 (not (and d_125_2 d_125_3)))
(assert
 (not (and d_125_2 d_125_4)))
(assert
 (not (and d_125_2 d_125_5)))
(assert
 (not (and d_125_2 d_125_6)))
(assert
 (not (and d_125_2 d_125_7)))
(assert
 (not (and d_125_2 d_125_8)))
(assert
 (not (and d_125_3 d_125_4)))
(assert
 (not (and d_125_3 d_125_5)))
(assert
 (not (and d_125_3 d_125_6)))
(assert
 (not (and d_125_3 d_125_7)))
(assert
 (not (and d_125_3 d_125_8)))
(assert
 (not (and d_125_4 d_125_5)))
(assert
 (not (and d_125_4 d_125_6)))
(assert
 (not (and d_125_4 d_125_7)))
(assert
 (not (and d_125_4 d_125_8)))
(assert
 (not (and d_125_5 d_125_6)))
(assert
 (not (and d_125_5 d_125_7)))
(assert
 (not (and d_125_5 d_125_8)))
(assert
 (not (and d_125_6 d_125_7)))
(assert
 (not (and d_125_6 d_125_8)))
(assert
 (not (and d_125_7 d_125_8)))
(assert
 (let (($x23085 (or false d_126_0)))
 (let (($x23087 (or $x23085 d_126_1)))
 (let (($x23089 (or $x23087 d_126_2)))
 (let (($x23091 (or $x23089 d_126_3)))
 (let (($x23093 (or $x23091 d_126_4)))
 (let (($x23095 (or $x23093 d_126_5)))
 (let (($x23097 (or $x23095 d_126_6)))
 (let (($x23099 (or $x23097 d_126_7)))
 (or $x23099 d_126_8))))))))))
(assert
 (not (and d_126_0 d_126_1)))
(assert
 (not (and d_126_0 d_126_2)))
(assert
 (not (and d_126_0 d_126_3)))
(assert
 (not (and d_126_0 d_126_4)))
(assert
 (not (and d_126_0 d_126_5)))
(assert
 (not (and d_126_0 d_126_6)))
(assert
 (not (and d_126_0 d_126_7)))
(assert
 (not (and d_126_0 d_126_8)))
(assert
 (not (and d_126_1 d_126_2)))
(assert
 (not (and d_126_1 d_126_3)))
(assert
 (not (and d_126_1 d_126_4)))
(assert
 (not (and d_126_1 d_126_5)))
(assert
 (not (and d_126_1 d_126_6)))
(assert
 (not (and d_126_1 d_126_7)))
(assert
 (not (and d_126_1 d_126_8)))
(assert
 (not (and d_126_2 d_126_3)))
(assert
 (not (and d_126_2 d_126_4)))
(assert
 (not (and d_126_2 d_126_5)))
(assert
 (not (and d_126_2 d_126_6)))
(assert
 (not (and d_126_2 d_126_7)))
(assert
 (not (and d_126_2 d_126_8)))
(assert
 (not (and d_126_3 d_126_4)))
(assert
 (not (and d_126_3 d_126_5)))
(assert
 (not (and d_126_3 d_126_6)))
(assert
 (not (and d_126_3 d_126_7)))
(assert
 (not (and d_126_3 d_126_8)))
(assert
 (not (and d_126_4 d_126_5)))
(assert
 (not (and d_126_4 d_126_6)))
(assert
 (not (and d_126_4 d_126_7)))
(assert
 (not (and d_126_4 d_126_8)))
(assert
 (not (and d_126_5 d_126_6)))
(assert
 (not (and d_126_5 d_126_7)))
(assert
 (not (and d_126_5 d_126_8)))
(assert
 (not (and d_126_6 d_126_7)))
(assert
 (not (and d_126_6 d_126_8)))
(assert
 (not (and d_126_7 d_126_8)))
(assert
 (let (($x23175 (or false d_127_0)))
 (let (($x23177 (or $x23175 d_127_1)))
 (let (($x23179 (or $x23177 d_127_2)))
 (let (($x23181 (or $x23179 d_127_3)))
 (let (($x23183 (or $x23181 d_127_4)))
 (let (($x23185 (or $x23183 d_127_5)))
 (let (($x23187 (or $x23185 d_127_6)))
 (let (($x23189 (or $x23187 d_127_7)))
 (or $x23189 d_127_8))))))))))
(assert
 (not (and d_127_0 d_127_1)))
(assert
 (not (and d_127_0 d_127_2)))
(assert
 (not (and d_127_0 d_127_3)))
(assert
 (not (and d_127_0 d_127_4)))
(assert
 (not (and d_127_0 d_127_5)))
(assert
 (not (and d_127_0 d_127_6)))
(assert
 (not (and d_127_0 d_127_7)))
(assert
 (not (and d_127_0 d_127_8)))
(assert
 (not (and d_127_1 d_127_2)))
(assert
 (not (and d_127_1 d_127_3)))
(assert
 (not (and d_127_1 d_127_4)))
(assert
 (not (and d_127_1 d_127_5)))
(assert
 (not (and d_127_1 d_127_6)))
(assert
 (not (and d_127_1 d_127_7)))
(assert
 (not (and d_127_1 d_127_8)))
(assert
 (not (and d_127_2 d_127_3)))
(assert
 (not (and d_127_2 d_127_4)))
(assert
 (not (and d_127_2 d_127_5)))
(assert
 (not (and d_127_2 d_127_6)))
(assert
 (not (and d_127_2 d_127_7)))
(assert
 (not (and d_127_2 d_127_8)))
(assert
 (not (and d_127_3 d_127_4)))
(assert
 (not (and d_127_3 d_127_5)))
(assert
 (not (and d_127_3 d_127_6)))
(assert
 (not (and d_127_3 d_127_7)))
(assert
 (not (and d_127_3 d_127_8)))
(assert
 (not (and d_127_4 d_127_5)))
(assert
 (not (and d_127_4 d_127_6)))
(assert
 (not (and d_127_4 d_127_7)))
(assert
 (not (and d_127_4 d_127_8)))
(assert
 (not (and d_127_5 d_127_6)))
(assert
 (not (and d_127_5 d_127_7)))
(assert
 (not (and d_127_5 d_127_8)))
(assert
 (not (and d_127_6 d_127_7)))
(assert
 (not (and d_127_6 d_127_8)))
(assert
 (not (and d_127_7 d_127_8)))
(assert
 (let (($x23265 (or false d_128_0)))
 (let (($x23267 (or $x23265 d_128_1)))
 (let (($x23269 (or $x23267 d_128_2)))
 (let (($x23271 (or $x23269 d_128_3)))
 (let (($x23273 (or $x23271 d_128_4)))
 (let (($x23275 (or $x23273 d_128_5)))
 (let (($x23277 (or $x23275 d_128_6)))
 (let (($x23279 (or $x23277 d_128_7)))
 (or $x23279 d_128_8))))))))))
(assert
 (not (and d_128_0 d_128_1)))
(assert
 (not (and d_128_0 d_128_2)))
(assert
 (not (and d_128_0 d_128_3)))
(assert
 (not (and d_128_0 d_128_4)))
(assert
 (not (and d_128_0 d_128_5)))
(assert
 (not (and d_128_0 d_128_6)))
(assert
 (not (and d_128_0 d_128_7)))
(assert
 (not (and d_128_0 d_128_8)))
(assert
 (not (and d_128_1 d_128_2)))
(assert
 (not (and d_128_1 d_128_3)))
(assert
 (not (and d_128_1 d_128_4)))
(assert
 (not (and d_128_1 d_128_5)))
(assert
 (not (and d_128_1 d_128_6)))
(assert
 (not (and d_128_1 d_128_7)))
(assert
 (not (and d_128_1 d_128_8)))
(assert
 (not (and d_128_2 d_128_3)))
(assert
 (not (and d_128_2 d_128_4)))
(assert
 (not (and d_128_2 d_128_5)))
(assert
 (not (and d_128_2 d_128_6)))
(assert
 (not (and d_128_2 d_128_7)))
(assert
 (not (and d_128_2 d_128_8)))
(assert
 (not (and d_128_3 d_128_4)))
(assert
 (not (and d_128_3 d_128_5)))
(assert
 (not (and d_128_3 d_128_6)))
(assert
 (not (and d_128_3 d_128_7)))
(assert
 (not (and d_128_3 d_128_8)))
(assert
 (not (and d_128_4 d_128_5)))
(assert
 (not (and d_128_4 d_128_6)))
(assert
 (not (and d_128_4 d_128_7)))
(assert
 (not (and d_128_4 d_128_8)))
(assert
 (not (and d_128_5 d_128_6)))
(assert
 (not (and d_128_5 d_128_7)))
(assert
 (not (and d_128_5 d_128_8)))
(assert
 (not (and d_128_6 d_128_7)))
(assert
 (not (and d_128_6 d_128_8)))
(assert
 (not (and d_128_7 d_128_8)))
(assert
 (let (($x30077 (and c_0_8 in_target_0)))
 (let (($x30075 (and c_0_7 in_target_0)))
 (let (($x30073 (and c_0_6 in_target_0)))
 (let (($x30071 (and c_0_5 in_target_0)))
 (let (($x30069 (and c_0_4 in_target_0)))
 (let (($x30067 (and c_0_3 in_target_0)))
 (let (($x30065 (and c_0_2 in_target_0)))
 (let (($x30063 (and c_0_1 in_target_0)))
 (let (($x30062 (and c_0_0 in_target_0)))
 (let (($x30078 (or $x30062 $x30063 $x30065 $x30067 $x30069 $x30071 $x30073 $x30075 $x30077)))
 (let (($x30060 (not $x30078)))
 (let (($x30061 (and c_0_8 $x30060)))
 (let (($x36764 (not c_6_1)))
 (let (($x24402 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_7)))
 (let (($x36751 (not $x24402)))
 (let (($x30416 (and c_6_8 in_target_6)))
 (let (($x30414 (and c_6_7 in_target_6)))
 (let (($x30412 (and c_6_6 in_target_6)))
 (let (($x30410 (and c_6_5 in_target_6)))
 (let (($x30408 (and c_6_4 in_target_6)))
 (let (($x30406 (and c_6_3 in_target_6)))
 (let (($x30404 (and c_6_2 in_target_6)))
 (let (($x30402 (and c_6_1 in_target_6)))
 (let (($x30401 (and c_6_0 in_target_6)))
 (let (($x30417 (or $x30401 $x30402 $x30404 $x30406 $x30408 $x30410 $x30412 $x30414 $x30416)))
 (let (($x36756 (and $x30417 $x36751)))
 (let (($x36765 (and $x36756 $x36764)))
 (let (($x36747 (and c_6_1 $x36751)))
 (let (($x36749 (or false $x24402)))
 (let (($x36758 (or $x36749 $x36747)))
 (let (($x36569 (not c_0_1)))
 (let (($x24416 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7)))
 (let (($x36567 (not $x24416)))
 (let (($x36568 (and true $x36567)))
 (let (($x36553 (and $x36568 $x36569)))
 (let (($x36562 (and $x36553 $x30060)))
 (let (($x36735 (not (or (and c_6_0 (not in_target_6)) $x30416))))
 (let (($x36741 (and in_region_6 $x36735)))
 (let (($x36766 (and (and $x36741 (and (and $x30078 $x36567) $x36569)) (or $x36758 (and $x36765 (< ghost_2_6 ghost_2_0))))))
 (let (($x36754 (and (and $x36741 (and c_0_1 $x36567)) (or $x36749 (and $x36747 (< ghost_1_6 ghost_1_0))))))
 (let (($x36732 (not c_5_1)))
 (let (($x24388 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7)))
 (let (($x36715 (not $x24388)))
 (let (($x30381 (and c_5_8 in_target_5)))
 (let (($x30379 (and c_5_7 in_target_5)))
 (let (($x30377 (and c_5_6 in_target_5)))
 (let (($x30375 (and c_5_5 in_target_5)))
 (let (($x30373 (and c_5_4 in_target_5)))
 (let (($x30371 (and c_5_3 in_target_5)))
 (let (($x30369 (and c_5_2 in_target_5)))
 (let (($x30367 (and c_5_1 in_target_5)))
 (let (($x30366 (and c_5_0 in_target_5)))
 (let (($x30382 (or $x30366 $x30367 $x30369 $x30371 $x30373 $x30375 $x30377 $x30379 $x30381)))
 (let (($x36724 (and $x30382 $x36715)))
 (let (($x36731 (and $x36724 $x36732)))
 (let (($x36718 (and c_5_1 $x36715)))
 (let (($x36714 (or false $x24388)))
 (let (($x36723 (or $x36714 $x36718)))
 (let (($x36708 (not (or (and c_5_0 (not in_target_5)) $x30381))))
 (let (($x36704 (and in_region_5 $x36708)))
 (let (($x36726 (and (and $x36704 (and (and $x30078 $x36567) $x36569)) (or $x36723 (and $x36731 (< ghost_2_5 ghost_2_0))))))
 (let (($x36721 (and (and $x36704 (and c_0_1 $x36567)) (or $x36714 (and $x36718 (< ghost_1_5 ghost_1_0))))))
 (let (($x36691 (not c_3_1)))
 (let (($x24374 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7)))
 (let (($x36685 (not $x24374)))
 (let (($x30346 (and c_3_8 in_target_3)))
 (let (($x30344 (and c_3_7 in_target_3)))
 (let (($x30342 (and c_3_6 in_target_3)))
 (let (($x30340 (and c_3_5 in_target_3)))
 (let (($x30338 (and c_3_4 in_target_3)))
 (let (($x30336 (and c_3_3 in_target_3)))
 (let (($x30334 (and c_3_2 in_target_3)))
 (let (($x30332 (and c_3_1 in_target_3)))
 (let (($x30331 (and c_3_0 in_target_3)))
 (let (($x30347 (or $x30331 $x30332 $x30334 $x30336 $x30338 $x30340 $x30342 $x30344 $x30346)))
 (let (($x36694 (and $x30347 $x36685)))
 (let (($x36698 (and $x36694 $x36691)))
 (let (($x36682 (and c_3_1 $x36685)))
 (let (($x36683 (or false $x24374)))
 (let (($x36692 (or $x36683 $x36682)))
 (let (($x36674 (not (or (and c_3_0 (not in_target_3)) $x30346))))
 (let (($x36673 (and in_region_3 $x36674)))
 (let (($x36700 (and (and $x36673 (and (and $x30078 $x36567) $x36569)) (or $x36692 (and $x36698 (< ghost_2_3 ghost_2_0))))))
 (let (($x36688 (and (and $x36673 (and c_0_1 $x36567)) (or $x36683 (and $x36682 (< ghost_1_3 ghost_1_0))))))
 (let (($x36660 (not c_4_1)))
 (let (($x24360 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7)))
 (let (($x36652 (not $x24360)))
 (let (($x30311 (and c_4_8 in_target_4)))
 (let (($x30309 (and c_4_7 in_target_4)))
 (let (($x30307 (and c_4_6 in_target_4)))
 (let (($x30305 (and c_4_5 in_target_4)))
 (let (($x30303 (and c_4_4 in_target_4)))
 (let (($x30301 (and c_4_3 in_target_4)))
 (let (($x30299 (and c_4_2 in_target_4)))
 (let (($x30297 (and c_4_1 in_target_4)))
 (let (($x30296 (and c_4_0 in_target_4)))
 (let (($x30312 (or $x30296 $x30297 $x30299 $x30301 $x30303 $x30305 $x30307 $x30309 $x30311)))
 (let (($x36658 (and $x30312 $x36652)))
 (let (($x36662 (and $x36658 $x36660)))
 (let (($x36651 (and c_4_1 $x36652)))
 (let (($x36650 (or false $x24360)))
 (let (($x36659 (or $x36650 $x36651)))
 (let (($x36642 (not (or (and c_4_0 (not in_target_4)) $x30311))))
 (let (($x36637 (and in_region_4 $x36642)))
 (let (($x36664 (and (and $x36637 (and (and $x30078 $x36567) $x36569)) (or $x36659 (and $x36662 (< ghost_2_4 ghost_2_0))))))
 (let (($x36655 (and (and $x36637 (and c_0_1 $x36567)) (or $x36650 (and $x36651 (< ghost_1_4 ghost_1_0))))))
 (let (($x36625 (not c_2_1)))
 (let (($x24346 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7)))
 (let (($x36619 (not $x24346)))
 (let (($x30276 (and c_2_8 in_target_2)))
 (let (($x30274 (and c_2_7 in_target_2)))
 (let (($x30272 (and c_2_6 in_target_2)))
 (let (($x30270 (and c_2_5 in_target_2)))
 (let (($x30268 (and c_2_4 in_target_2)))
 (let (($x30266 (and c_2_3 in_target_2)))
 (let (($x30264 (and c_2_2 in_target_2)))
 (let (($x30262 (and c_2_1 in_target_2)))
 (let (($x30261 (and c_2_0 in_target_2)))
 (let (($x30277 (or $x30261 $x30262 $x30264 $x30266 $x30268 $x30270 $x30272 $x30274 $x30276)))
 (let (($x36633 (and $x30277 $x36619)))
 (let (($x36632 (and $x36633 $x36625)))
 (let (($x36616 (and c_2_1 $x36619)))
 (let (($x36617 (or false $x24346)))
 (let (($x36626 (or $x36617 $x36616)))
 (let (($x36606 (not (or (and c_2_0 (not in_target_2)) $x30276))))
 (let (($x36607 (and in_region_2 $x36606)))
 (let (($x36634 (and (and $x36607 (and (and $x30078 $x36567) $x36569)) (or $x36626 (and $x36632 (< ghost_2_2 ghost_2_0))))))
 (let (($x36622 (and (and $x36607 (and c_0_1 $x36567)) (or $x36617 (and $x36616 (< ghost_1_2 ghost_1_0))))))
 (let (($x36594 (not c_1_1)))
 (let (($x24332 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7)))
 (let (($x36584 (not $x24332)))
 (let (($x30240 (and c_1_8 in_target_1)))
 (let (($x30238 (and c_1_7 in_target_1)))
 (let (($x30236 (and c_1_6 in_target_1)))
 (let (($x30234 (and c_1_5 in_target_1)))
 (let (($x30232 (and c_1_4 in_target_1)))
 (let (($x30230 (and c_1_3 in_target_1)))
 (let (($x30228 (and c_1_2 in_target_1)))
 (let (($x30226 (and c_1_1 in_target_1)))
 (let (($x30225 (and c_1_0 in_target_1)))
 (let (($x30241 (or $x30225 $x30226 $x30228 $x30230 $x30232 $x30234 $x30236 $x30238 $x30240)))
 (let (($x36601 (and $x30241 $x36584)))
 (let (($x36595 (and $x36601 $x36594)))
 (let (($x36585 (and c_1_1 $x36584)))
 (let (($x36581 (or false $x24332)))
 (let (($x36591 (or $x36581 $x36585)))
 (let (($x36570 (not (or (and c_1_0 (not in_target_1)) $x30240))))
 (let (($x36573 (and in_region_1 $x36570)))
 (let (($x36596 (and (and $x36573 (and (and $x30078 $x36567) $x36569)) (or $x36591 (and $x36595 (< ghost_2_1 ghost_2_0))))))
 (let (($x36587 (and (and $x36573 (and c_0_1 $x36567)) (or $x36581 (and $x36585 (< ghost_1_1 ghost_1_0))))))
 (let (($x36571 (or false (and (and $x36573 $x24416) (or false (and $x24332 c_1_5))))))
 (let (($x36588 (or $x36571 $x36587)))
 (let (($x36599 (or $x36588 $x36596)))
 (let (($x36600 (or $x36599 (and (and $x36573 $x36562) (or $x36591 $x36595)))))
 (let (($x36614 (or $x36600 (and (and $x36607 $x24416) (or false (and $x24346 c_2_6))))))
 (let (($x36623 (or $x36614 $x36622)))
 (let (($x36630 (or $x36623 $x36634)))
 (let (($x36641 (or $x36630 (and (and $x36607 $x36562) (or $x36626 $x36632)))))
 (let (($x36645 (or $x36641 (and (and $x36637 $x24416) (or false (and $x24360 c_4_7))))))
 (let (($x36656 (or $x36645 $x36655)))
 (let (($x36661 (or $x36656 $x36664)))
 (let (($x36668 (or $x36661 (and (and $x36637 $x36562) (or $x36659 $x36662)))))
 (let (($x36680 (or $x36668 (and (and $x36673 $x24416) (or false (and $x24374 c_3_2))))))
 (let (($x36689 (or $x36680 $x36688)))
 (let (($x36695 (or $x36689 $x36700)))
 (let (($x36707 (or $x36695 (and (and $x36673 $x36562) (or $x36692 $x36698)))))
 (let (($x36713 (or $x36707 (and (and $x36704 $x24416) (or false (and $x24388 c_5_3))))))
 (let (($x36722 (or $x36713 $x36721)))
 (let (($x36733 (or $x36722 $x36726)))
 (let (($x36740 (or $x36733 (and (and $x36704 $x36562) (or $x36723 $x36731)))))
 (let (($x36743 (or $x36740 (and (and $x36741 $x24416) (or false (and $x24402 c_6_4))))))
 (let (($x36755 (or $x36743 $x36754)))
 (let (($x36761 (or $x36755 $x36766)))
 (let ((?x38476 (ite c_24_4 1 0)))
 (let ((?x38474 (ite c_23_3 1 0)))
 (let ((?x38472 (ite c_19_2 1 0)))
 (let ((?x38470 (ite c_0_7 1 0)))
 (let ((?x38468 (ite c_15_6 1 0)))
 (let ((?x38466 (ite c_11_5 1 0)))
 (let ((?x38467 (+ 0 ?x38466)))
 (let ((?x38469 (+ ?x38467 ?x38468)))
 (let ((?x38471 (+ ?x38469 ?x38470)))
 (let ((?x38473 (+ ?x38471 ?x38472)))
 (let ((?x38475 (+ ?x38473 ?x38474)))
 (let ((?x38462 (ite c_24_1 1 0)))
 (let ((?x38435 (ite c_23_1 1 0)))
 (let ((?x38379 (ite c_19_1 1 0)))
 (let ((?x38315 (ite c_0_1 1 0)))
 (let ((?x38349 (ite c_15_1 1 0)))
 (let ((?x38319 (ite c_11_1 1 0)))
 (let ((?x38459 (+ 0 ?x38319)))
 (let ((?x38458 (+ ?x38459 ?x38349)))
 (let ((?x38460 (+ ?x38458 ?x38315)))
 (let ((?x38457 (+ ?x38460 ?x38379)))
 (let ((?x38461 (+ ?x38457 ?x38435)))
 (let (($x38480 (and (= (to_real (+ ?x38461 ?x38462)) 0.0) (= (to_real (+ ?x38475 ?x38476)) 0.0))))
 (let (($x37845 (and true $x24402)))
 (let (($x36806 (and true in_region_6)))
 (let ((?x38449 (ite c_23_4 1 0)))
 (let ((?x38447 (ite c_22_3 1 0)))
 (let ((?x38445 (ite c_18_2 1 0)))
 (let ((?x38443 (ite c_21_7 1 0)))
 (let ((?x38441 (ite c_0_6 1 0)))
 (let ((?x38439 (ite c_10_5 1 0)))
 (let ((?x38440 (+ 0 ?x38439)))
 (let ((?x38442 (+ ?x38440 ?x38441)))
 (let ((?x38444 (+ ?x38442 ?x38443)))
 (let ((?x38446 (+ ?x38444 ?x38445)))
 (let ((?x38448 (+ ?x38446 ?x38447)))
 (let ((?x38433 (ite c_22_1 1 0)))
 (let ((?x38377 (ite c_18_1 1 0)))
 (let ((?x38406 (ite c_21_1 1 0)))
 (let ((?x38317 (ite c_10_1 1 0)))
 (let ((?x38429 (+ 0 ?x38317)))
 (let ((?x38431 (+ ?x38429 ?x38315)))
 (let ((?x38430 (+ ?x38431 ?x38406)))
 (let ((?x38432 (+ ?x38430 ?x38377)))
 (let ((?x38434 (+ ?x38432 ?x38433)))
 (let (($x38453 (and (= (to_real (+ ?x38434 ?x38435)) 0.0) (= (to_real (+ ?x38448 ?x38449)) 0.0))))
 (let (($x37839 (and true $x24388)))
 (let (($x36800 (and true in_region_5)))
 (let ((?x38421 (ite c_0_4 1 0)))
 (let ((?x38419 (ite c_21_3 1 0)))
 (let ((?x38417 (ite c_16_2 1 0)))
 (let ((?x38415 (ite c_20_7 1 0)))
 (let ((?x38413 (ite c_13_6 1 0)))
 (let ((?x38411 (ite c_9_5 1 0)))
 (let ((?x38412 (+ 0 ?x38411)))
 (let ((?x38414 (+ ?x38412 ?x38413)))
 (let ((?x38416 (+ ?x38414 ?x38415)))
 (let ((?x38418 (+ ?x38416 ?x38417)))
 (let ((?x38420 (+ ?x38418 ?x38419)))
 (let ((?x38372 (ite c_16_1 1 0)))
 (let ((?x38404 (ite c_20_1 1 0)))
 (let ((?x38344 (ite c_13_1 1 0)))
 (let ((?x38313 (ite c_9_1 1 0)))
 (let ((?x38403 (+ 0 ?x38313)))
 (let ((?x38401 (+ ?x38403 ?x38344)))
 (let ((?x38402 (+ ?x38401 ?x38404)))
 (let ((?x38405 (+ ?x38402 ?x38372)))
 (let ((?x38407 (+ ?x38405 ?x38406)))
 (let (($x38425 (and (= (to_real (+ ?x38407 ?x38315)) 0.0) (= (to_real (+ ?x38420 ?x38421)) 0.0))))
 (let (($x37837 (and true $x24360)))
 (let (($x36794 (and true in_region_4)))
 (let ((?x38393 (ite c_19_4 1 0)))
 (let ((?x38391 (ite c_18_3 1 0)))
 (let ((?x38389 (ite c_17_2 1 0)))
 (let ((?x38387 (ite c_16_7 1 0)))
 (let ((?x38385 (ite c_14_6 1 0)))
 (let ((?x38383 (ite c_0_5 1 0)))
 (let ((?x38384 (+ 0 ?x38383)))
 (let ((?x38386 (+ ?x38384 ?x38385)))
 (let ((?x38388 (+ ?x38386 ?x38387)))
 (let ((?x38390 (+ ?x38388 ?x38389)))
 (let ((?x38392 (+ ?x38390 ?x38391)))
 (let ((?x38375 (ite c_17_1 1 0)))
 (let ((?x38346 (ite c_14_1 1 0)))
 (let ((?x38373 (+ 0 ?x38315)))
 (let ((?x38371 (+ ?x38373 ?x38346)))
 (let ((?x38374 (+ ?x38371 ?x38372)))
 (let ((?x38376 (+ ?x38374 ?x38375)))
 (let ((?x38378 (+ ?x38376 ?x38377)))
 (let (($x38397 (and (= (to_real (+ ?x38378 ?x38379)) 0.0) (= (to_real (+ ?x38392 ?x38393)) 0.0))))
 (let (($x37833 (and true $x24374)))
 (let (($x36788 (and true in_region_3)))
 (let ((?x38363 (ite c_15_4 1 0)))
 (let ((?x38361 (ite c_0_3 1 0)))
 (let ((?x38359 (ite c_14_2 1 0)))
 (let ((?x38357 (ite c_13_7 1 0)))
 (let ((?x38355 (ite c_12_6 1 0)))
 (let ((?x38353 (ite c_8_5 1 0)))
 (let ((?x38354 (+ 0 ?x38353)))
 (let ((?x38356 (+ ?x38354 ?x38355)))
 (let ((?x38358 (+ ?x38356 ?x38357)))
 (let ((?x38360 (+ ?x38358 ?x38359)))
 (let ((?x38362 (+ ?x38360 ?x38361)))
 (let ((?x38341 (ite c_12_1 1 0)))
 (let ((?x38310 (ite c_8_1 1 0)))
 (let ((?x38343 (+ 0 ?x38310)))
 (let ((?x38342 (+ ?x38343 ?x38341)))
 (let ((?x38345 (+ ?x38342 ?x38344)))
 (let ((?x38347 (+ ?x38345 ?x38346)))
 (let ((?x38348 (+ ?x38347 ?x38315)))
 (let (($x38367 (and (= (to_real (+ ?x38348 ?x38349)) 0.0) (= (to_real (+ ?x38362 ?x38363)) 0.0))))
 (let (($x37829 (and true $x24346)))
 (let (($x36782 (and true in_region_2)))
 (let ((?x38333 (ite c_11_4 1 0)))
 (let ((?x38331 (ite c_10_3 1 0)))
 (let ((?x38329 (ite c_0_2 1 0)))
 (let ((?x38327 (ite c_9_7 1 0)))
 (let ((?x38325 (ite c_8_6 1 0)))
 (let ((?x38323 (ite c_7_5 1 0)))
 (let ((?x38324 (+ 0 ?x38323)))
 (let ((?x38326 (+ ?x38324 ?x38325)))
 (let ((?x38328 (+ ?x38326 ?x38327)))
 (let ((?x38330 (+ ?x38328 ?x38329)))
 (let ((?x38332 (+ ?x38330 ?x38331)))
 (let ((?x38311 (ite c_7_1 1 0)))
 (let ((?x38312 (+ 0 ?x38311)))
 (let ((?x38309 (+ ?x38312 ?x38310)))
 (let ((?x38314 (+ ?x38309 ?x38313)))
 (let ((?x38316 (+ ?x38314 ?x38315)))
 (let ((?x38318 (+ ?x38316 ?x38317)))
 (let (($x38337 (and (= (to_real (+ ?x38318 ?x38319)) 0.0) (= (to_real (+ ?x38332 ?x38333)) 0.0))))
 (let (($x37825 (and true $x24332)))
 (let (($x36776 (and true in_region_1)))
 (let ((?x38301 (ite c_6_4 1 0)))
 (let ((?x38299 (ite c_5_3 1 0)))
 (let ((?x38297 (ite c_3_2 1 0)))
 (let ((?x38295 (ite c_4_7 1 0)))
 (let ((?x38293 (ite c_2_6 1 0)))
 (let ((?x38291 (ite c_1_5 1 0)))
 (let ((?x38292 (+ 0 ?x38291)))
 (let ((?x38294 (+ ?x38292 ?x38293)))
 (let ((?x38296 (+ ?x38294 ?x38295)))
 (let ((?x38298 (+ ?x38296 ?x38297)))
 (let ((?x38300 (+ ?x38298 ?x38299)))
 (let ((?x38286 (ite c_6_1 1 0)))
 (let ((?x38284 (ite c_5_1 1 0)))
 (let ((?x38282 (ite c_3_1 1 0)))
 (let ((?x38280 (ite c_4_1 1 0)))
 (let ((?x38278 (ite c_2_1 1 0)))
 (let ((?x38276 (ite c_1_1 1 0)))
 (let ((?x38277 (+ 0 ?x38276)))
 (let ((?x38279 (+ ?x38277 ?x38278)))
 (let ((?x38281 (+ ?x38279 ?x38280)))
 (let ((?x38283 (+ ?x38281 ?x38282)))
 (let ((?x38285 (+ ?x38283 ?x38284)))
 (let (($x38305 (and (= (to_real (+ ?x38285 ?x38286)) 0.0) (= (to_real (+ ?x38300 ?x38301)) 0.0))))
 (let (($x37819 (and true $x24416)))
 (let (($x36772 (and true in_region_0)))
 (let (($x36852 (and true in_region_21)))
 (let (($x37207 (and $x36852 in_region_5)))
 (let (($x36850 (and true in_region_20)))
 (let (($x37202 (and $x36850 in_region_4)))
 (let (($x36827 (and true in_region_16)))
 (let (($x37198 (and $x36827 in_region_3)))
 (let (($x36819 (and true in_region_13)))
 (let (($x37194 (and $x36819 in_region_2)))
 (let (($x36815 (and true in_region_9)))
 (let (($x37190 (and $x36815 in_region_1)))
 (let (($x37186 (and $x36806 in_region_24)))
 (let (($x37182 (and $x36800 in_region_23)))
 (let (($x37174 (and $x36788 in_region_19)))
 (let (($x37170 (and $x36782 in_region_15)))
 (let (($x37166 (and $x36776 in_region_11)))
 (let (($x36825 (and true in_region_15)))
 (let (($x37154 (and $x36825 in_region_6)))
 (let (($x36820 (and true in_region_14)))
 (let (($x37150 (and $x36820 in_region_3)))
 (let (($x36818 (and true in_region_12)))
 (let (($x37140 (and $x36818 in_region_2)))
 (let (($x36814 (and true in_region_8)))
 (let (($x37136 (and $x36814 in_region_1)))
 (let (($x37132 (and $x36806 in_region_23)))
 (let (($x37128 (and $x36800 in_region_22)))
 (let (($x37124 (and $x36794 in_region_21)))
 (let (($x37120 (and $x36788 in_region_18)))
 (let (($x37112 (and $x36776 in_region_10)))
 (let (($x36855 (and true in_region_24)))
 (let (($x37099 (and $x36855 in_region_6)))
 (let (($x36854 (and true in_region_23)))
 (let (($x37095 (and $x36854 in_region_5)))
 (let (($x36844 (and true in_region_19)))
 (let (($x37091 (and $x36844 in_region_3)))
 (let (($x36817 (and true in_region_11)))
 (let (($x37082 (and $x36817 in_region_1)))
 (let (($x37074 (and $x36800 in_region_21)))
 (let (($x37070 (and $x36794 in_region_20)))
 (let (($x37066 (and $x36788 in_region_16)))
 (let (($x37062 (and $x36782 in_region_13)))
 (let (($x37058 (and $x36776 in_region_9)))
 (let (($x36816 (and true in_region_10)))
 (let (($x37029 (and $x36816 in_region_5)))
 (let (($x36812 (and true in_region_7)))
 (let (($x37014 (and $x36812 in_region_1)))
 (let (($x37010 (and $x36806 in_region_19)))
 (let (($x37006 (and $x36800 in_region_18)))
 (let (($x37002 (and $x36794 in_region_16)))
 (let (($x36998 (and $x36788 in_region_17)))
 (let (($x36994 (and $x36782 in_region_14)))
 (let (($x36853 (and true in_region_22)))
 (let (($x36960 (and $x36853 in_region_5)))
 (let (($x36838 (and true in_region_18)))
 (let (($x36951 (and $x36838 in_region_3)))
 (let (($x36942 (and $x36806 in_region_15)))
 (let (($x36934 (and $x36794 in_region_13)))
 (let (($x36930 (and $x36788 in_region_14)))
 (let (($x36926 (and $x36782 in_region_12)))
 (let (($x36922 (and $x36776 in_region_8)))
 (let (($x36832 (and true in_region_17)))
 (let (($x36833 (and $x36832 in_region_3)))
 (let (($x36807 (and $x36806 in_region_11)))
 (let (($x36801 (and $x36800 in_region_10)))
 (let (($x36795 (and $x36794 in_region_9)))
 (let (($x36783 (and $x36782 in_region_8)))
 (let (($x36777 (and $x36776 in_region_7)))
 (let (($x24648 (or c_21_2 c_21_3 c_21_4 c_21_5 c_21_6 c_21_7)))
 (let (($x37897 (and true $x24648)))
 (let (($x24632 (or c_20_2 c_20_3 c_20_4 c_20_5 c_20_6 c_20_7)))
 (let (($x38055 (and true $x24632)))
 (let (($x24570 (or c_16_2 c_16_3 c_16_4 c_16_5 c_16_6 c_16_7)))
 (let (($x37852 (and true $x24570)))
 (let (($x24520 (or c_13_2 c_13_3 c_13_4 c_13_5 c_13_6 c_13_7)))
 (let (($x38016 (and true $x24520)))
 (let (($x24457 (or c_9_2 c_9_3 c_9_4 c_9_5 c_9_6 c_9_7)))
 (let (($x37936 (and true $x24457)))
 (let (($x24550 (or c_15_2 c_15_3 c_15_4 c_15_5 c_15_6 c_15_7)))
 (let (($x37970 (and true $x24550)))
 (let (($x24534 (or c_14_2 c_14_3 c_14_4 c_14_5 c_14_6 c_14_7)))
 (let (($x37849 (and true $x24534)))
 (let (($x24506 (or c_12_2 c_12_3 c_12_4 c_12_5 c_12_6 c_12_7)))
 (let (($x38011 (and true $x24506)))
 (let (($x24443 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_7)))
 (let (($x37933 (and true $x24443)))
 (let (($x24714 (or c_24_2 c_24_3 c_24_4 c_24_5 c_24_6 c_24_7)))
 (let (($x37979 (and true $x24714)))
 (let (($x24688 (or c_23_2 c_23_3 c_23_4 c_23_5 c_23_6 c_23_7)))
 (let (($x37903 (and true $x24688)))
 (let (($x24612 (or c_19_2 c_19_3 c_19_4 c_19_5 c_19_6 c_19_7)))
 (let (($x37865 (and true $x24612)))
 (let (($x24488 (or c_11_2 c_11_3 c_11_4 c_11_5 c_11_6 c_11_7)))
 (let (($x37946 (and true $x24488)))
 (let (($x24474 (or c_10_2 c_10_3 c_10_4 c_10_5 c_10_6 c_10_7)))
 (let (($x37890 (and true $x24474)))
 (let (($x24429 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_7)))
 (let (($x37929 (and true $x24429)))
 (let (($x24674 (or c_22_2 c_22_3 c_22_4 c_22_5 c_22_6 c_22_7)))
 (let (($x37899 (and true $x24674)))
 (let (($x24598 (or c_18_2 c_18_3 c_18_4 c_18_5 c_18_6 c_18_7)))
 (let (($x37859 (and true $x24598)))
 (let (($x24584 (or c_17_2 c_17_3 c_17_4 c_17_5 c_17_6 c_17_7)))
 (let (($x37857 (and true $x24584)))
 (let (($x37817 (and $x37207 (and (and true c_21_8) (and c_5_1 (not in_target_5))))))
 (let (($x37814 (and $x37202 (and (and true c_20_8) (and c_4_1 (not in_target_4))))))
 (let (($x37811 (and $x37198 (and (and true c_16_8) (and c_3_1 (not in_target_3))))))
 (let (($x37808 (and $x37194 (and (and true c_13_8) (and c_2_1 (not in_target_2))))))
 (let (($x37805 (and $x37190 (and (and true c_9_8) (and c_1_1 (not in_target_1))))))
 (let (($x37801 (and $x37186 (and (and true c_6_8) (and c_24_1 (not in_target_24))))))
 (let (($x37798 (and $x37182 (and (and true c_5_8) (and c_23_1 (not in_target_23))))))
 (let (($x37178 (and $x36794 in_region_0)))
 (let (($x37795 (and $x37178 (and (and true c_4_8) (and c_0_1 (not in_target_0))))))
 (let (($x37792 (and $x37174 (and (and true c_3_8) (and c_19_1 (not in_target_19))))))
 (let (($x37789 (and $x37170 (and (and true c_2_8) (and c_15_1 (not in_target_15))))))
 (let (($x37786 (and $x37166 (and (and true c_1_8) (and c_11_1 (not in_target_11))))))
 (let (($x37158 (and $x36772 in_region_6)))
 (let (($x37783 (and $x37158 (and (and true c_0_8) (and c_6_1 (not in_target_6))))))
 (let (($x37780 (and $x37154 (and (and true c_15_8) (and c_6_1 (not in_target_6))))))
 (let (($x37777 (and $x37150 (and (and true c_14_8) (and c_3_1 (not in_target_3))))))
 (let (($x37145 (and $x36819 in_region_4)))
 (let (($x37774 (and $x37145 (and (and true c_13_8) (and c_4_1 (not in_target_4))))))
 (let (($x37771 (and $x37140 (and (and true c_12_8) (and c_2_1 (not in_target_2))))))
 (let (($x37768 (and $x37136 (and (and true c_8_8) (and c_1_1 (not in_target_1))))))
 (let (($x37764 (and $x37132 (and (and true c_6_8) (and c_23_1 (not in_target_23))))))
 (let (($x37760 (and $x37128 (and (and true c_5_8) (and c_22_1 (not in_target_22))))))
 (let (($x37757 (and $x37124 (and (and true c_4_8) (and c_21_1 (not in_target_21))))))
 (let (($x37754 (and $x37120 (and (and true c_3_8) (and c_18_1 (not in_target_18))))))
 (let (($x37116 (and $x36782 in_region_0)))
 (let (($x37751 (and $x37116 (and (and true c_2_8) (and c_0_1 (not in_target_0))))))
 (let (($x37748 (and $x37112 (and (and true c_1_8) (and c_10_1 (not in_target_10))))))
 (let (($x37104 (and $x36772 in_region_5)))
 (let (($x37745 (and $x37104 (and (and true c_0_8) (and c_5_1 (not in_target_5))))))
 (let (($x37742 (and $x37099 (and (and true c_24_8) (and c_6_1 (not in_target_6))))))
 (let (($x37739 (and $x37095 (and (and true c_23_8) (and c_5_1 (not in_target_5))))))
 (let (($x37736 (and $x37091 (and (and true c_19_8) (and c_3_1 (not in_target_3))))))
 (let (($x37086 (and $x36825 in_region_2)))
 (let (($x37733 (and $x37086 (and (and true c_15_8) (and c_2_1 (not in_target_2))))))
 (let (($x37730 (and $x37082 (and (and true c_11_8) (and c_1_1 (not in_target_1))))))
 (let (($x37078 (and $x36806 in_region_0)))
 (let (($x37727 (and $x37078 (and (and true c_6_8) (and c_0_1 (not in_target_0))))))
 (let (($x37723 (and $x37074 (and (and true c_5_8) (and c_21_1 (not in_target_21))))))
 (let (($x37719 (and $x37070 (and (and true c_4_8) (and c_20_1 (not in_target_20))))))
 (let (($x37716 (and $x37066 (and (and true c_3_8) (and c_16_1 (not in_target_16))))))
 (let (($x37713 (and $x37062 (and (and true c_2_8) (and c_13_1 (not in_target_13))))))
 (let (($x37710 (and $x37058 (and (and true c_1_8) (and c_9_1 (not in_target_9))))))
 (let (($x37038 (and $x36772 in_region_4)))
 (let (($x37707 (and $x37038 (and (and true c_0_8) (and c_4_1 (not in_target_4))))))
 (let (($x37033 (and $x36817 in_region_6)))
 (let (($x37704 (and $x37033 (and (and true c_11_8) (and c_6_1 (not in_target_6))))))
 (let (($x37701 (and $x37029 (and (and true c_10_8) (and c_5_1 (not in_target_5))))))
 (let (($x37024 (and $x36815 in_region_4)))
 (let (($x37698 (and $x37024 (and (and true c_9_8) (and c_4_1 (not in_target_4))))))
 (let (($x37019 (and $x36814 in_region_2)))
 (let (($x37695 (and $x37019 (and (and true c_8_8) (and c_2_1 (not in_target_2))))))
 (let (($x37692 (and $x37014 (and (and true c_7_8) (and c_1_1 (not in_target_1))))))
 (let (($x37688 (and $x37010 (and (and true c_6_8) (and c_19_1 (not in_target_19))))))
 (let (($x37684 (and $x37006 (and (and true c_5_8) (and c_18_1 (not in_target_18))))))
 (let (($x37680 (and $x37002 (and (and true c_4_8) (and c_16_1 (not in_target_16))))))
 (let (($x37676 (and $x36998 (and (and true c_3_8) (and c_17_1 (not in_target_17))))))
 (let (($x37673 (and $x36994 (and (and true c_2_8) (and c_14_1 (not in_target_14))))))
 (let (($x36990 (and $x36776 in_region_0)))
 (let (($x37670 (and $x36990 (and (and true c_1_8) (and c_0_1 (not in_target_0))))))
 (let (($x36970 (and $x36772 in_region_3)))
 (let (($x37667 (and $x36970 (and (and true c_0_8) (and c_3_1 (not in_target_3))))))
 (let (($x36965 (and $x36854 in_region_6)))
 (let (($x37664 (and $x36965 (and (and true c_23_8) (and c_6_1 (not in_target_6))))))
 (let (($x37661 (and $x36960 (and (and true c_22_8) (and c_5_1 (not in_target_5))))))
 (let (($x36955 (and $x36852 in_region_4)))
 (let (($x37658 (and $x36955 (and (and true c_21_8) (and c_4_1 (not in_target_4))))))
 (let (($x37655 (and $x36951 (and (and true c_18_8) (and c_3_1 (not in_target_3))))))
 (let (($x36946 (and $x36816 in_region_1)))
 (let (($x37652 (and $x36946 (and (and true c_10_8) (and c_1_1 (not in_target_1))))))
 (let (($x37648 (and $x36942 (and (and true c_6_8) (and c_15_1 (not in_target_15))))))
 (let (($x36938 (and $x36800 in_region_0)))
 (let (($x37645 (and $x36938 (and (and true c_5_8) (and c_0_1 (not in_target_0))))))
 (let (($x37641 (and $x36934 (and (and true c_4_8) (and c_13_1 (not in_target_13))))))
 (let (($x37637 (and $x36930 (and (and true c_3_8) (and c_14_1 (not in_target_14))))))
 (let (($x37633 (and $x36926 (and (and true c_2_8) (and c_12_1 (not in_target_12))))))
 (let (($x37630 (and $x36922 (and (and true c_1_8) (and c_8_1 (not in_target_8))))))
 (let (($x36851 (and $x36772 in_region_2)))
 (let (($x37627 (and $x36851 (and (and true c_0_8) (and c_2_1 (not in_target_2))))))
 (let (($x36845 (and $x36844 in_region_6)))
 (let (($x37623 (and $x36845 (and (and true c_19_8) (and c_6_1 (not in_target_6))))))
 (let (($x36839 (and $x36838 in_region_5)))
 (let (($x37619 (and $x36839 (and (and true c_18_8) (and c_5_1 (not in_target_5))))))
 (let (($x37615 (and $x36833 (and (and true c_17_8) (and c_3_1 (not in_target_3))))))
 (let (($x36826 (and $x36827 in_region_4)))
 (let (($x37611 (and $x36826 (and (and true c_16_8) (and c_4_1 (not in_target_4))))))
 (let (($x36813 (and $x36820 in_region_2)))
 (let (($x37607 (and $x36813 (and (and true c_14_8) (and c_2_1 (not in_target_2))))))
 (let (($x37603 (and $x36807 (and (and true c_6_8) (and c_11_1 (not in_target_11))))))
 (let (($x37599 (and $x36801 (and (and true c_5_8) (and c_10_1 (not in_target_10))))))
 (let (($x37595 (and $x36795 (and (and true c_4_8) (and c_9_1 (not in_target_9))))))
 (let (($x36789 (and $x36788 in_region_0)))
 (let (($x37591 (and $x36789 (and (and true c_3_8) (and c_0_1 (not in_target_0))))))
 (let (($x37587 (and $x36783 (and (and true c_2_8) (and c_8_1 (not in_target_8))))))
 (let (($x37583 (and $x36777 (and (and true c_1_8) (and c_7_1 (not in_target_7))))))
 (let (($x36773 (and $x36772 in_region_1)))
 (let (($x37578 (and $x36773 (and (and true c_0_8) (and c_1_1 (not in_target_1))))))
 (let (($x37577 (and $x37207 (and (and true c_21_8) (or $x30369 $x30371 $x30373 $x30375 $x30377 $x30379)))))
 (let (($x37575 (and $x37202 (and (and true c_20_8) (or $x30299 $x30301 $x30303 $x30305 $x30307 $x30309)))))
 (let (($x37565 (and $x37198 (and (and true c_16_8) (or $x30334 $x30336 $x30338 $x30340 $x30342 $x30344)))))
 (let (($x37568 (and $x37194 (and (and true c_13_8) (or $x30264 $x30266 $x30268 $x30270 $x30272 $x30274)))))
 (let (($x37562 (and $x37190 (and (and true c_9_8) (or $x30228 $x30230 $x30232 $x30234 $x30236 $x30238)))))
 (let (($x31196 (and c_24_7 in_target_24)))
 (let (($x31194 (and c_24_6 in_target_24)))
 (let (($x31192 (and c_24_5 in_target_24)))
 (let (($x31190 (and c_24_4 in_target_24)))
 (let (($x31188 (and c_24_3 in_target_24)))
 (let (($x31186 (and c_24_2 in_target_24)))
 (let (($x37564 (or $x31186 $x31188 $x31190 $x31192 $x31194 $x31196)))
 (let (($x36808 (and true c_6_8)))
 (let (($x31126 (and c_23_7 in_target_23)))
 (let (($x31124 (and c_23_6 in_target_23)))
 (let (($x31122 (and c_23_5 in_target_23)))
 (let (($x31120 (and c_23_4 in_target_23)))
 (let (($x31118 (and c_23_3 in_target_23)))
 (let (($x31116 (and c_23_2 in_target_23)))
 (let (($x37522 (or $x31116 $x31118 $x31120 $x31122 $x31124 $x31126)))
 (let (($x36802 (and true c_5_8)))
 (let (($x37552 (and $x37178 (and (and true c_4_8) (or $x30065 $x30067 $x30069 $x30071 $x30073 $x30075)))))
 (let (($x30926 (and c_19_7 in_target_19)))
 (let (($x30924 (and c_19_6 in_target_19)))
 (let (($x30922 (and c_19_5 in_target_19)))
 (let (($x30920 (and c_19_4 in_target_19)))
 (let (($x30918 (and c_19_3 in_target_19)))
 (let (($x30916 (and c_19_2 in_target_19)))
 (let (($x37426 (or $x30916 $x30918 $x30920 $x30922 $x30924 $x30926)))
 (let (($x36790 (and true c_3_8)))
 (let (($x30766 (and c_15_7 in_target_15)))
 (let (($x30764 (and c_15_6 in_target_15)))
 (let (($x30762 (and c_15_5 in_target_15)))
 (let (($x30760 (and c_15_4 in_target_15)))
 (let (($x30758 (and c_15_3 in_target_15)))
 (let (($x30756 (and c_15_2 in_target_15)))
 (let (($x37366 (or $x30756 $x30758 $x30760 $x30762 $x30764 $x30766)))
 (let (($x36784 (and true c_2_8)))
 (let (($x30606 (and c_11_7 in_target_11)))
 (let (($x30604 (and c_11_6 in_target_11)))
 (let (($x30602 (and c_11_5 in_target_11)))
 (let (($x30600 (and c_11_4 in_target_11)))
 (let (($x30598 (and c_11_3 in_target_11)))
 (let (($x30596 (and c_11_2 in_target_11)))
 (let (($x37276 (or $x30596 $x30598 $x30600 $x30602 $x30604 $x30606)))
 (let (($x36778 (and true c_1_8)))
 (let (($x37538 (and $x37158 (and (and true c_0_8) (or $x30404 $x30406 $x30408 $x30410 $x30412 $x30414)))))
 (let (($x37535 (and $x37154 (and (and true c_15_8) (or $x30404 $x30406 $x30408 $x30410 $x30412 $x30414)))))
 (let (($x37531 (and $x37150 (and (and true c_14_8) (or $x30334 $x30336 $x30338 $x30340 $x30342 $x30344)))))
 (let (($x37530 (and $x37145 (and (and true c_13_8) (or $x30299 $x30301 $x30303 $x30305 $x30307 $x30309)))))
 (let (($x37526 (and $x37140 (and (and true c_12_8) (or $x30264 $x30266 $x30268 $x30270 $x30272 $x30274)))))
 (let (($x37521 (and $x37136 (and (and true c_8_8) (or $x30228 $x30230 $x30232 $x30234 $x30236 $x30238)))))
 (let (($x31091 (and c_22_7 in_target_22)))
 (let (($x31089 (and c_22_6 in_target_22)))
 (let (($x31087 (and c_22_5 in_target_22)))
 (let (($x31085 (and c_22_4 in_target_22)))
 (let (($x31083 (and c_22_3 in_target_22)))
 (let (($x31081 (and c_22_2 in_target_22)))
 (let (($x37513 (or $x31081 $x31083 $x31085 $x31087 $x31089 $x31091)))
 (let (($x31021 (and c_21_7 in_target_21)))
 (let (($x31019 (and c_21_6 in_target_21)))
 (let (($x31017 (and c_21_5 in_target_21)))
 (let (($x31015 (and c_21_4 in_target_21)))
 (let (($x31013 (and c_21_3 in_target_21)))
 (let (($x31011 (and c_21_2 in_target_21)))
 (let (($x37471 (or $x31011 $x31013 $x31015 $x31017 $x31019 $x31021)))
 (let (($x36796 (and true c_4_8)))
 (let (($x30891 (and c_18_7 in_target_18)))
 (let (($x30889 (and c_18_6 in_target_18)))
 (let (($x30887 (and c_18_5 in_target_18)))
 (let (($x30885 (and c_18_4 in_target_18)))
 (let (($x30883 (and c_18_3 in_target_18)))
 (let (($x30881 (and c_18_2 in_target_18)))
 (let (($x37417 (or $x30881 $x30883 $x30885 $x30887 $x30889 $x30891)))
 (let (($x30571 (and c_10_7 in_target_10)))
 (let (($x30569 (and c_10_6 in_target_10)))
 (let (($x30567 (and c_10_5 in_target_10)))
 (let (($x30565 (and c_10_4 in_target_10)))
 (let (($x30563 (and c_10_3 in_target_10)))
 (let (($x30561 (and c_10_2 in_target_10)))
 (let (($x37267 (or $x30561 $x30563 $x30565 $x30567 $x30569 $x30571)))
 (let (($x37490 (and $x37104 (and (and true c_0_8) (or $x30369 $x30371 $x30373 $x30375 $x30377 $x30379)))))
 (let (($x37487 (and $x37099 (and (and true c_24_8) (or $x30404 $x30406 $x30408 $x30410 $x30412 $x30414)))))
 (let (($x37484 (and $x37095 (and (and true c_23_8) (or $x30369 $x30371 $x30373 $x30375 $x30377 $x30379)))))
 (let (($x37475 (and $x37091 (and (and true c_19_8) (or $x30334 $x30336 $x30338 $x30340 $x30342 $x30344)))))
 (let (($x37478 (and $x37086 (and (and true c_15_8) (or $x30264 $x30266 $x30268 $x30270 $x30272 $x30274)))))
 (let (($x37472 (and $x37082 (and (and true c_11_8) (or $x30228 $x30230 $x30232 $x30234 $x30236 $x30238)))))
 (let (($x30981 (and c_20_7 in_target_20)))
 (let (($x30979 (and c_20_6 in_target_20)))
 (let (($x30977 (and c_20_5 in_target_20)))
 (let (($x30975 (and c_20_4 in_target_20)))
 (let (($x30973 (and c_20_3 in_target_20)))
 (let (($x30971 (and c_20_2 in_target_20)))
 (let (($x37462 (or $x30971 $x30973 $x30975 $x30977 $x30979 $x30981)))
 (let (($x30821 (and c_16_7 in_target_16)))
 (let (($x30819 (and c_16_6 in_target_16)))
 (let (($x30817 (and c_16_5 in_target_16)))
 (let (($x30815 (and c_16_4 in_target_16)))
 (let (($x30813 (and c_16_3 in_target_16)))
 (let (($x30811 (and c_16_2 in_target_16)))
 (let (($x37408 (or $x30811 $x30813 $x30815 $x30817 $x30819 $x30821)))
 (let (($x30691 (and c_13_7 in_target_13)))
 (let (($x30689 (and c_13_6 in_target_13)))
 (let (($x30687 (and c_13_5 in_target_13)))
 (let (($x30685 (and c_13_4 in_target_13)))
 (let (($x30683 (and c_13_3 in_target_13)))
 (let (($x30681 (and c_13_2 in_target_13)))
 (let (($x37354 (or $x30681 $x30683 $x30685 $x30687 $x30689 $x30691)))
 (let (($x30531 (and c_9_7 in_target_9)))
 (let (($x30529 (and c_9_6 in_target_9)))
 (let (($x30527 (and c_9_5 in_target_9)))
 (let (($x30525 (and c_9_4 in_target_9)))
 (let (($x30523 (and c_9_3 in_target_9)))
 (let (($x30521 (and c_9_2 in_target_9)))
 (let (($x37258 (or $x30521 $x30523 $x30525 $x30527 $x30529 $x30531)))
 (let (($x37443 (and $x37038 (and (and true c_0_8) (or $x30299 $x30301 $x30303 $x30305 $x30307 $x30309)))))
 (let (($x37439 (and $x37033 (and (and true c_11_8) (or $x30404 $x30406 $x30408 $x30410 $x30412 $x30414)))))
 (let (($x37436 (and $x37029 (and (and true c_10_8) (or $x30369 $x30371 $x30373 $x30375 $x30377 $x30379)))))
 (let (($x37434 (and $x37024 (and (and true c_9_8) (or $x30299 $x30301 $x30303 $x30305 $x30307 $x30309)))))
 (let (($x37430 (and $x37019 (and (and true c_8_8) (or $x30264 $x30266 $x30268 $x30270 $x30272 $x30274)))))
 (let (($x37425 (and $x37014 (and (and true c_7_8) (or $x30228 $x30230 $x30232 $x30234 $x30236 $x30238)))))
 (let (($x30856 (and c_17_7 in_target_17)))
 (let (($x30854 (and c_17_6 in_target_17)))
 (let (($x30852 (and c_17_5 in_target_17)))
 (let (($x30850 (and c_17_4 in_target_17)))
 (let (($x30848 (and c_17_3 in_target_17)))
 (let (($x30846 (and c_17_2 in_target_17)))
 (let (($x37399 (or $x30846 $x30848 $x30850 $x30852 $x30854 $x30856)))
 (let (($x30726 (and c_14_7 in_target_14)))
 (let (($x30724 (and c_14_6 in_target_14)))
 (let (($x30722 (and c_14_5 in_target_14)))
 (let (($x30720 (and c_14_4 in_target_14)))
 (let (($x30718 (and c_14_3 in_target_14)))
 (let (($x30716 (and c_14_2 in_target_14)))
 (let (($x37345 (or $x30716 $x30718 $x30720 $x30722 $x30724 $x30726)))
 (let (($x37377 (and $x36970 (and (and true c_0_8) (or $x30334 $x30336 $x30338 $x30340 $x30342 $x30344)))))
 (let (($x37379 (and $x36965 (and (and true c_23_8) (or $x30404 $x30406 $x30408 $x30410 $x30412 $x30414)))))
 (let (($x37376 (and $x36960 (and (and true c_22_8) (or $x30369 $x30371 $x30373 $x30375 $x30377 $x30379)))))
 (let (($x37374 (and $x36955 (and (and true c_21_8) (or $x30299 $x30301 $x30303 $x30305 $x30307 $x30309)))))
 (let (($x37367 (and $x36951 (and (and true c_18_8) (or $x30334 $x30336 $x30338 $x30340 $x30342 $x30344)))))
 (let (($x37362 (and $x36946 (and (and true c_10_8) (or $x30228 $x30230 $x30232 $x30234 $x30236 $x30238)))))
 (let (($x30656 (and c_12_7 in_target_12)))
 (let (($x30654 (and c_12_6 in_target_12)))
 (let (($x30652 (and c_12_5 in_target_12)))
 (let (($x30650 (and c_12_4 in_target_12)))
 (let (($x30648 (and c_12_3 in_target_12)))
 (let (($x30646 (and c_12_2 in_target_12)))
 (let (($x37336 (or $x30646 $x30648 $x30650 $x30652 $x30654 $x30656)))
 (let (($x30496 (and c_8_7 in_target_8)))
 (let (($x30494 (and c_8_6 in_target_8)))
 (let (($x30492 (and c_8_5 in_target_8)))
 (let (($x30490 (and c_8_4 in_target_8)))
 (let (($x30488 (and c_8_3 in_target_8)))
 (let (($x30486 (and c_8_2 in_target_8)))
 (let (($x37240 (or $x30486 $x30488 $x30490 $x30492 $x30494 $x30496)))
 (let (($x37322 (and $x36851 (and (and true c_0_8) (or $x30264 $x30266 $x30268 $x30270 $x30272 $x30274)))))
 (let (($x37318 (and $x36845 (and (and true c_19_8) (or $x30404 $x30406 $x30408 $x30410 $x30412 $x30414)))))
 (let (($x37309 (and $x36839 (and (and true c_18_8) (or $x30369 $x30371 $x30373 $x30375 $x30377 $x30379)))))
 (let (($x37299 (and $x36833 (and (and true c_17_8) (or $x30334 $x30336 $x30338 $x30340 $x30342 $x30344)))))
 (let (($x37292 (and $x36826 (and (and true c_16_8) (or $x30299 $x30301 $x30303 $x30305 $x30307 $x30309)))))
 (let (($x37282 (and $x36813 (and (and true c_14_8) (or $x30264 $x30266 $x30268 $x30270 $x30272 $x30274)))))
 (let (($x30460 (and c_7_7 in_target_7)))
 (let (($x30458 (and c_7_6 in_target_7)))
 (let (($x30456 (and c_7_5 in_target_7)))
 (let (($x30454 (and c_7_4 in_target_7)))
 (let (($x30452 (and c_7_3 in_target_7)))
 (let (($x30450 (and c_7_2 in_target_7)))
 (let (($x37231 (or $x30450 $x30452 $x30454 $x30456 $x30458 $x30460)))
 (let (($x37218 (and $x36773 (and (and true c_0_8) (or $x30228 $x30230 $x30232 $x30234 $x30236 $x30238)))))
 (let (($x36775 (or false (and $x36773 (and (and true c_0_8) $x30226)))))
 (let (($x36781 (or $x36775 (and $x36777 (and $x36778 (and c_7_1 in_target_7))))))
 (let (($x36787 (or $x36781 (and $x36783 (and $x36784 (and c_8_1 in_target_8))))))
 (let (($x36793 (or $x36787 (and $x36789 (and $x36790 $x30063)))))
 (let (($x36799 (or $x36793 (and $x36795 (and $x36796 (and c_9_1 in_target_9))))))
 (let (($x36805 (or $x36799 (and $x36801 (and $x36802 (and c_10_1 in_target_10))))))
 (let (($x36811 (or $x36805 (and $x36807 (and $x36808 (and c_11_1 in_target_11))))))
 (let (($x36824 (or $x36811 (and $x36813 (and (and true c_14_8) $x30262)))))
 (let (($x36831 (or $x36824 (and $x36826 (and (and true c_16_8) $x30297)))))
 (let (($x36837 (or $x36831 (and $x36833 (and (and true c_17_8) $x30332)))))
 (let (($x36843 (or $x36837 (and $x36839 (and (and true c_18_8) $x30367)))))
 (let (($x36849 (or $x36843 (and $x36845 (and (and true c_19_8) $x30402)))))
 (let (($x36921 (or $x36849 (and $x36851 (and (and true c_0_8) $x30262)))))
 (let (($x36925 (or $x36921 (and $x36922 (and $x36778 (and c_8_1 in_target_8))))))
 (let (($x36929 (or $x36925 (and $x36926 (and $x36784 (and c_12_1 in_target_12))))))
 (let (($x36933 (or $x36929 (and $x36930 (and $x36790 (and c_14_1 in_target_14))))))
 (let (($x36937 (or $x36933 (and $x36934 (and $x36796 (and c_13_1 in_target_13))))))
 (let (($x36941 (or $x36937 (and $x36938 (and $x36802 $x30063)))))
 (let (($x36945 (or $x36941 (and $x36942 (and $x36808 (and c_15_1 in_target_15))))))
 (let (($x36950 (or $x36945 (and $x36946 (and (and true c_10_8) $x30226)))))
 (let (($x36954 (or $x36950 (and $x36951 (and (and true c_18_8) $x30332)))))
 (let (($x36959 (or $x36954 (and $x36955 (and (and true c_21_8) $x30297)))))
 (let (($x36964 (or $x36959 (and $x36960 (and (and true c_22_8) $x30367)))))
 (let (($x36969 (or $x36964 (and $x36965 (and (and true c_23_8) $x30402)))))
 (let (($x36989 (or $x36969 (and $x36970 (and (and true c_0_8) $x30332)))))
 (let (($x36993 (or $x36989 (and $x36990 (and $x36778 $x30063)))))
 (let (($x36997 (or $x36993 (and $x36994 (and $x36784 (and c_14_1 in_target_14))))))
 (let (($x37001 (or $x36997 (and $x36998 (and $x36790 (and c_17_1 in_target_17))))))
 (let (($x37005 (or $x37001 (and $x37002 (and $x36796 (and c_16_1 in_target_16))))))
 (let (($x37009 (or $x37005 (and $x37006 (and $x36802 (and c_18_1 in_target_18))))))
 (let (($x37013 (or $x37009 (and $x37010 (and $x36808 (and c_19_1 in_target_19))))))
 (let (($x37018 (or $x37013 (and $x37014 (and (and true c_7_8) $x30226)))))
 (let (($x37023 (or $x37018 (and $x37019 (and (and true c_8_8) $x30262)))))
 (let (($x37028 (or $x37023 (and $x37024 (and (and true c_9_8) $x30297)))))
 (let (($x37032 (or $x37028 (and $x37029 (and (and true c_10_8) $x30367)))))
 (let (($x37037 (or $x37032 (and $x37033 (and (and true c_11_8) $x30402)))))
 (let (($x37057 (or $x37037 (and $x37038 (and (and true c_0_8) $x30297)))))
 (let (($x37061 (or $x37057 (and $x37058 (and $x36778 (and c_9_1 in_target_9))))))
 (let (($x37065 (or $x37061 (and $x37062 (and $x36784 (and c_13_1 in_target_13))))))
 (let (($x37069 (or $x37065 (and $x37066 (and $x36790 (and c_16_1 in_target_16))))))
 (let (($x37073 (or $x37069 (and $x37070 (and $x36796 (and c_20_1 in_target_20))))))
 (let (($x37077 (or $x37073 (and $x37074 (and $x36802 (and c_21_1 in_target_21))))))
 (let (($x37081 (or $x37077 (and $x37078 (and $x36808 $x30063)))))
 (let (($x37085 (or $x37081 (and $x37082 (and (and true c_11_8) $x30226)))))
 (let (($x37090 (or $x37085 (and $x37086 (and (and true c_15_8) $x30262)))))
 (let (($x37094 (or $x37090 (and $x37091 (and (and true c_19_8) $x30332)))))
 (let (($x37098 (or $x37094 (and $x37095 (and (and true c_23_8) $x30367)))))
 (let (($x37103 (or $x37098 (and $x37099 (and (and true c_24_8) $x30402)))))
 (let (($x37111 (or $x37103 (and $x37104 (and (and true c_0_8) $x30367)))))
 (let (($x37115 (or $x37111 (and $x37112 (and $x36778 (and c_10_1 in_target_10))))))
 (let (($x37119 (or $x37115 (and $x37116 (and $x36784 $x30063)))))
 (let (($x37123 (or $x37119 (and $x37120 (and $x36790 (and c_18_1 in_target_18))))))
 (let (($x37127 (or $x37123 (and $x37124 (and $x36796 (and c_21_1 in_target_21))))))
 (let (($x37131 (or $x37127 (and $x37128 (and $x36802 (and c_22_1 in_target_22))))))
 (let (($x37135 (or $x37131 (and $x37132 (and $x36808 (and c_23_1 in_target_23))))))
 (let (($x37139 (or $x37135 (and $x37136 (and (and true c_8_8) $x30226)))))
 (let (($x37144 (or $x37139 (and $x37140 (and (and true c_12_8) $x30262)))))
 (let (($x37149 (or $x37144 (and $x37145 (and (and true c_13_8) $x30297)))))
 (let (($x37153 (or $x37149 (and $x37150 (and (and true c_14_8) $x30332)))))
 (let (($x37157 (or $x37153 (and $x37154 (and (and true c_15_8) $x30402)))))
 (let (($x37165 (or $x37157 (and $x37158 (and (and true c_0_8) $x30402)))))
 (let (($x37169 (or $x37165 (and $x37166 (and $x36778 (and c_11_1 in_target_11))))))
 (let (($x37173 (or $x37169 (and $x37170 (and $x36784 (and c_15_1 in_target_15))))))
 (let (($x37177 (or $x37173 (and $x37174 (and $x36790 (and c_19_1 in_target_19))))))
 (let (($x37181 (or $x37177 (and $x37178 (and $x36796 $x30063)))))
 (let (($x37185 (or $x37181 (and $x37182 (and $x36802 (and c_23_1 in_target_23))))))
 (let (($x37189 (or $x37185 (and $x37186 (and $x36808 (and c_24_1 in_target_24))))))
 (let (($x37193 (or $x37189 (and $x37190 (and (and true c_9_8) $x30226)))))
 (let (($x37197 (or $x37193 (and $x37194 (and (and true c_13_8) $x30262)))))
 (let (($x37201 (or $x37197 (and $x37198 (and (and true c_16_8) $x30332)))))
 (let (($x37206 (or $x37201 (and $x37202 (and (and true c_20_8) $x30297)))))
 (let (($x37210 (or $x37206 (and $x37207 (and (and true c_21_8) $x30367)))))
 (let (($x37221 (or $x37210 $x37218)))
 (let (($x37227 (or $x37221 (and $x36777 (and $x36778 $x37231)))))
 (let (($x37237 (or $x37227 (and $x36783 (and $x36784 $x37240)))))
 (let (($x37245 (or $x37237 (and $x36789 (and $x36790 (or $x30065 $x30067 $x30069 $x30071 $x30073 $x30075))))))
 (let (($x37256 (or $x37245 (and $x36795 (and $x36796 $x37258)))))
 (let (($x37266 (or $x37256 (and $x36801 (and $x36802 $x37267)))))
 (let (($x37275 (or $x37266 (and $x36807 (and $x36808 $x37276)))))
 (let (($x37284 (or $x37275 $x37282)))
 (let (($x37290 (or $x37284 $x37292)))
 (let (($x37301 (or $x37290 $x37299)))
 (let (($x37311 (or $x37301 $x37309)))
 (let (($x37319 (or $x37311 $x37318)))
 (let (($x37324 (or $x37319 $x37322)))
 (let (($x37325 (or $x37324 (and $x36922 (and $x36778 $x37240)))))
 (let (($x37334 (or $x37325 (and $x36926 (and $x36784 $x37336)))))
 (let (($x37342 (or $x37334 (and $x36930 (and $x36790 $x37345)))))
 (let (($x37350 (or $x37342 (and $x36934 (and $x36796 $x37354)))))
 (let (($x37352 (or $x37350 (and $x36938 (and $x36802 (or $x30065 $x30067 $x30069 $x30071 $x30073 $x30075))))))
 (let (($x37364 (or $x37352 (and $x36942 (and $x36808 $x37366)))))
 (let (($x37369 (or $x37364 $x37362)))
 (let (($x37371 (or $x37369 $x37367)))
 (let (($x37370 (or $x37371 $x37374)))
 (let (($x37378 (or $x37370 $x37376)))
 (let (($x37380 (or $x37378 $x37379)))
 (let (($x37383 (or $x37380 $x37377)))
 (let (($x37382 (or $x37383 (and $x36990 (and $x36778 (or $x30065 $x30067 $x30069 $x30071 $x30073 $x30075))))))
 (let (($x37388 (or $x37382 (and $x36994 (and $x36784 $x37345)))))
 (let (($x37396 (or $x37388 (and $x36998 (and $x36790 $x37399)))))
 (let (($x37406 (or $x37396 (and $x37002 (and $x36796 $x37408)))))
 (let (($x37413 (or $x37406 (and $x37006 (and $x36802 $x37417)))))
 (let (($x37422 (or $x37413 (and $x37010 (and $x36808 $x37426)))))
 (let (($x37429 (or $x37422 $x37425)))
 (let (($x37432 (or $x37429 $x37430)))
 (let (($x37427 (or $x37432 $x37434)))
 (let (($x37438 (or $x37427 $x37436)))
 (let (($x37440 (or $x37438 $x37439)))
 (let (($x37437 (or $x37440 $x37443)))
 (let (($x37446 (or $x37437 (and $x37058 (and $x36778 $x37258)))))
 (let (($x37444 (or $x37446 (and $x37062 (and $x36784 $x37354)))))
 (let (($x37452 (or $x37444 (and $x37066 (and $x36790 $x37408)))))
 (let (($x37460 (or $x37452 (and $x37070 (and $x36796 $x37462)))))
 (let (($x37470 (or $x37460 (and $x37074 (and $x36802 $x37471)))))
 (let (($x37468 (or $x37470 (and $x37078 (and $x36808 (or $x30065 $x30067 $x30069 $x30071 $x30073 $x30075))))))
 (let (($x37477 (or $x37468 $x37472)))
 (let (($x37480 (or $x37477 $x37478)))
 (let (($x37482 (or $x37480 $x37475)))
 (let (($x37486 (or $x37482 $x37484)))
 (let (($x37488 (or $x37486 $x37487)))
 (let (($x37492 (or $x37488 $x37490)))
 (let (($x37495 (or $x37492 (and $x37112 (and $x36778 $x37267)))))
 (let (($x37491 (or $x37495 (and $x37116 (and $x36784 (or $x30065 $x30067 $x30069 $x30071 $x30073 $x30075))))))
 (let (($x37496 (or $x37491 (and $x37120 (and $x36790 $x37417)))))
 (let (($x37504 (or $x37496 (and $x37124 (and $x36796 $x37471)))))
 (let (($x37510 (or $x37504 (and $x37128 (and $x36802 $x37513)))))
 (let (($x37518 (or $x37510 (and $x37132 (and $x36808 $x37522)))))
 (let (($x37525 (or $x37518 $x37521)))
 (let (($x37528 (or $x37525 $x37526)))
 (let (($x37523 (or $x37528 $x37530)))
 (let (($x37533 (or $x37523 $x37531)))
 (let (($x37536 (or $x37533 $x37535)))
 (let (($x37539 (or $x37536 $x37538)))
 (let (($x37543 (or $x37539 (and $x37166 (and $x36778 $x37276)))))
 (let (($x37545 (or $x37543 (and $x37170 (and $x36784 $x37366)))))
 (let (($x37542 (or $x37545 (and $x37174 (and $x36790 $x37426)))))
 (let (($x37549 (or $x37542 $x37552)))
 (let (($x37550 (or $x37549 (and $x37182 (and $x36802 $x37522)))))
 (let (($x37561 (or $x37550 (and $x37186 (and $x36808 $x37564)))))
 (let (($x37567 (or $x37561 $x37562)))
 (let (($x37570 (or $x37567 $x37568)))
 (let (($x37572 (or $x37570 $x37565)))
 (let (($x37571 (or $x37572 $x37575)))
 (let (($x37579 (or $x37571 $x37577)))
 (let (($x37581 (or $x37579 $x37578)))
 (let (($x37585 (or $x37581 $x37583)))
 (let (($x37589 (or $x37585 $x37587)))
 (let (($x37593 (or $x37589 $x37591)))
 (let (($x37597 (or $x37593 $x37595)))
 (let (($x37601 (or $x37597 $x37599)))
 (let (($x37605 (or $x37601 $x37603)))
 (let (($x37609 (or $x37605 $x37607)))
 (let (($x37613 (or $x37609 $x37611)))
 (let (($x37617 (or $x37613 $x37615)))
 (let (($x37621 (or $x37617 $x37619)))
 (let (($x37625 (or $x37621 $x37623)))
 (let (($x37628 (or $x37625 $x37627)))
 (let (($x37631 (or $x37628 $x37630)))
 (let (($x37635 (or $x37631 $x37633)))
 (let (($x37639 (or $x37635 $x37637)))
 (let (($x37643 (or $x37639 $x37641)))
 (let (($x37646 (or $x37643 $x37645)))
 (let (($x37650 (or $x37646 $x37648)))
 (let (($x37653 (or $x37650 $x37652)))
 (let (($x37656 (or $x37653 $x37655)))
 (let (($x37659 (or $x37656 $x37658)))
 (let (($x37662 (or $x37659 $x37661)))
 (let (($x37665 (or $x37662 $x37664)))
 (let (($x37668 (or $x37665 $x37667)))
 (let (($x37671 (or $x37668 $x37670)))
 (let (($x37674 (or $x37671 $x37673)))
 (let (($x37678 (or $x37674 $x37676)))
 (let (($x37682 (or $x37678 $x37680)))
 (let (($x37686 (or $x37682 $x37684)))
 (let (($x37690 (or $x37686 $x37688)))
 (let (($x37693 (or $x37690 $x37692)))
 (let (($x37696 (or $x37693 $x37695)))
 (let (($x37699 (or $x37696 $x37698)))
 (let (($x37702 (or $x37699 $x37701)))
 (let (($x37705 (or $x37702 $x37704)))
 (let (($x37708 (or $x37705 $x37707)))
 (let (($x37711 (or $x37708 $x37710)))
 (let (($x37714 (or $x37711 $x37713)))
 (let (($x37717 (or $x37714 $x37716)))
 (let (($x37721 (or $x37717 $x37719)))
 (let (($x37725 (or $x37721 $x37723)))
 (let (($x37728 (or $x37725 $x37727)))
 (let (($x37731 (or $x37728 $x37730)))
 (let (($x37734 (or $x37731 $x37733)))
 (let (($x37737 (or $x37734 $x37736)))
 (let (($x37740 (or $x37737 $x37739)))
 (let (($x37743 (or $x37740 $x37742)))
 (let (($x37746 (or $x37743 $x37745)))
 (let (($x37749 (or $x37746 $x37748)))
 (let (($x37752 (or $x37749 $x37751)))
 (let (($x37755 (or $x37752 $x37754)))
 (let (($x37758 (or $x37755 $x37757)))
 (let (($x37762 (or $x37758 $x37760)))
 (let (($x37766 (or $x37762 $x37764)))
 (let (($x37769 (or $x37766 $x37768)))
 (let (($x37772 (or $x37769 $x37771)))
 (let (($x37775 (or $x37772 $x37774)))
 (let (($x37778 (or $x37775 $x37777)))
 (let (($x37781 (or $x37778 $x37780)))
 (let (($x37784 (or $x37781 $x37783)))
 (let (($x37787 (or $x37784 $x37786)))
 (let (($x37790 (or $x37787 $x37789)))
 (let (($x37793 (or $x37790 $x37792)))
 (let (($x37796 (or $x37793 $x37795)))
 (let (($x37799 (or $x37796 $x37798)))
 (let (($x37803 (or $x37799 $x37801)))
 (let (($x37806 (or $x37803 $x37805)))
 (let (($x37809 (or $x37806 $x37808)))
 (let (($x37812 (or $x37809 $x37811)))
 (let (($x37815 (or $x37812 $x37814)))
 (let (($x37818 (or $x37815 $x37817)))
 (let (($x37822 (or $x37818 (and $x36773 (and $x37819 c_1_1)))))
 (let (($x37823 (or $x37822 (and $x36777 (and $x37825 c_7_1)))))
 (let (($x37830 (or $x37823 (and $x36783 (and $x37829 c_8_1)))))
 (let (($x37834 (or $x37830 (and $x36789 (and $x37833 c_0_1)))))
 (let (($x37836 (or $x37834 (and $x36795 (and $x37837 c_9_1)))))
 (let (($x37842 (or $x37836 (and $x36801 (and $x37839 c_10_1)))))
 (let (($x37843 (or $x37842 (and $x36807 (and $x37845 c_11_1)))))
 (let (($x37847 (or $x37843 (and $x36813 (and $x37849 c_2_1)))))
 (let (($x37854 (or $x37847 (and $x36826 (and $x37852 c_4_1)))))
 (let (($x37858 (or $x37854 (and $x36833 (and $x37857 c_3_1)))))
 (let (($x37862 (or $x37858 (and $x36839 (and $x37859 c_5_1)))))
 (let (($x37863 (or $x37862 (and $x36845 (and $x37865 c_6_1)))))
 (let (($x37869 (or $x37863 (and $x36851 (and $x37819 c_2_1)))))
 (let (($x37871 (or $x37869 (and $x36922 (and $x37825 c_8_1)))))
 (let (($x37874 (or $x37871 (and $x36926 (and $x37829 c_12_1)))))
 (let (($x37877 (or $x37874 (and $x36930 (and $x37833 c_14_1)))))
 (let (($x37882 (or $x37877 (and $x36934 (and $x37837 c_13_1)))))
 (let (($x37883 (or $x37882 (and $x36938 (and $x37839 c_0_1)))))
 (let (($x37888 (or $x37883 (and $x36942 (and $x37845 c_15_1)))))
 (let (($x37891 (or $x37888 (and $x36946 (and $x37890 c_1_1)))))
 (let (($x37894 (or $x37891 (and $x36951 (and $x37859 c_3_1)))))
 (let (($x37895 (or $x37894 (and $x36955 (and $x37897 c_4_1)))))
 (let (($x37900 (or $x37895 (and $x36960 (and $x37899 c_5_1)))))
 (let (($x37904 (or $x37900 (and $x36965 (and $x37903 c_6_1)))))
 (let (($x37909 (or $x37904 (and $x36970 (and $x37819 c_3_1)))))
 (let (($x37911 (or $x37909 (and $x36990 (and $x37825 c_0_1)))))
 (let (($x37914 (or $x37911 (and $x36994 (and $x37829 c_14_1)))))
 (let (($x37917 (or $x37914 (and $x36998 (and $x37833 c_17_1)))))
 (let (($x37922 (or $x37917 (and $x37002 (and $x37837 c_16_1)))))
 (let (($x37923 (or $x37922 (and $x37006 (and $x37839 c_18_1)))))
 (let (($x37928 (or $x37923 (and $x37010 (and $x37845 c_19_1)))))
 (let (($x37925 (or $x37928 (and $x37014 (and $x37929 c_1_1)))))
 (let (($x37934 (or $x37925 (and $x37019 (and $x37933 c_2_1)))))
 (let (($x37939 (or $x37934 (and $x37024 (and $x37936 c_4_1)))))
 (let (($x37940 (or $x37939 (and $x37029 (and $x37890 c_5_1)))))
 (let (($x37945 (or $x37940 (and $x37033 (and $x37946 c_6_1)))))
 (let (($x37949 (or $x37945 (and $x37038 (and $x37819 c_4_1)))))
 (let (($x37951 (or $x37949 (and $x37058 (and $x37825 c_9_1)))))
 (let (($x37954 (or $x37951 (and $x37062 (and $x37829 c_13_1)))))
 (let (($x37957 (or $x37954 (and $x37066 (and $x37833 c_16_1)))))
 (let (($x37962 (or $x37957 (and $x37070 (and $x37837 c_20_1)))))
 (let (($x37963 (or $x37962 (and $x37074 (and $x37839 c_21_1)))))
 (let (($x37968 (or $x37963 (and $x37078 (and $x37845 c_0_1)))))
 (let (($x37969 (or $x37968 (and $x37082 (and $x37946 c_1_1)))))
 (let (($x37973 (or $x37969 (and $x37086 (and $x37970 c_2_1)))))
 (let (($x37978 (or $x37973 (and $x37091 (and $x37865 c_3_1)))))
 (let (($x37981 (or $x37978 (and $x37095 (and $x37903 c_5_1)))))
 (let (($x37984 (or $x37981 (and $x37099 (and $x37979 c_6_1)))))
 (let (($x37987 (or $x37984 (and $x37104 (and $x37819 c_5_1)))))
 (let (($x37989 (or $x37987 (and $x37112 (and $x37825 c_10_1)))))
 (let (($x37992 (or $x37989 (and $x37116 (and $x37829 c_0_1)))))
 (let (($x37995 (or $x37992 (and $x37120 (and $x37833 c_18_1)))))
 (let (($x38000 (or $x37995 (and $x37124 (and $x37837 c_21_1)))))
 (let (($x38001 (or $x38000 (and $x37128 (and $x37839 c_22_1)))))
 (let (($x38006 (or $x38001 (and $x37132 (and $x37845 c_23_1)))))
 (let (($x38003 (or $x38006 (and $x37136 (and $x37933 c_1_1)))))
 (let (($x38012 (or $x38003 (and $x37140 (and $x38011 c_2_1)))))
 (let (($x38013 (or $x38012 (and $x37145 (and $x38016 c_4_1)))))
 (let (($x38020 (or $x38013 (and $x37150 (and $x37849 c_3_1)))))
 (let (($x38021 (or $x38020 (and $x37154 (and $x37970 c_6_1)))))
 (let (($x38025 (or $x38021 (and $x37158 (and $x37819 c_6_1)))))
 (let (($x38027 (or $x38025 (and $x37166 (and $x37825 c_11_1)))))
 (let (($x38030 (or $x38027 (and $x37170 (and $x37829 c_15_1)))))
 (let (($x38033 (or $x38030 (and $x37174 (and $x37833 c_19_1)))))
 (let (($x38038 (or $x38033 (and $x37178 (and $x37837 c_0_1)))))
 (let (($x38039 (or $x38038 (and $x37182 (and $x37839 c_23_1)))))
 (let (($x38044 (or $x38039 (and $x37186 (and $x37845 c_24_1)))))
 (let (($x38046 (or $x38044 (and $x37190 (and $x37936 c_1_1)))))
 (let (($x38048 (or $x38046 (and $x37194 (and $x38016 c_2_1)))))
 (let (($x38047 (or $x38048 (and $x37198 (and $x37852 c_3_1)))))
 (let (($x38056 (or $x38047 (and $x37202 (and $x38055 c_4_1)))))
 (let (($x38058 (or $x38056 (and $x37207 (and $x37897 c_5_1)))))
 (let (($x38062 (or $x38058 (and $x36773 (and (and true c_0_8) $x30225)))))
 (let (($x38065 (or $x38062 (and $x36777 (and $x36778 (and c_7_0 in_target_7))))))
 (let (($x38068 (or $x38065 (and $x36783 (and $x36784 (and c_8_0 in_target_8))))))
 (let (($x38071 (or $x38068 (and $x36789 (and $x36790 $x30062)))))
 (let (($x38074 (or $x38071 (and $x36795 (and $x36796 (and c_9_0 in_target_9))))))
 (let (($x38077 (or $x38074 (and $x36801 (and $x36802 (and c_10_0 in_target_10))))))
 (let (($x38080 (or $x38077 (and $x36807 (and $x36808 (and c_11_0 in_target_11))))))
 (let (($x38083 (or $x38080 (and $x36813 (and (and true c_14_8) $x30261)))))
 (let (($x38086 (or $x38083 (and $x36826 (and (and true c_16_8) $x30296)))))
 (let (($x38089 (or $x38086 (and $x36833 (and (and true c_17_8) $x30331)))))
 (let (($x38092 (or $x38089 (and $x36839 (and (and true c_18_8) $x30366)))))
 (let (($x38095 (or $x38092 (and $x36845 (and (and true c_19_8) $x30401)))))
 (let (($x38098 (or $x38095 (and $x36851 (and (and true c_0_8) $x30261)))))
 (let (($x38101 (or $x38098 (and $x36922 (and $x36778 (and c_8_0 in_target_8))))))
 (let (($x38104 (or $x38101 (and $x36926 (and $x36784 (and c_12_0 in_target_12))))))
 (let (($x38107 (or $x38104 (and $x36930 (and $x36790 (and c_14_0 in_target_14))))))
 (let (($x38110 (or $x38107 (and $x36934 (and $x36796 (and c_13_0 in_target_13))))))
 (let (($x38113 (or $x38110 (and $x36938 (and $x36802 $x30062)))))
 (let (($x38116 (or $x38113 (and $x36942 (and $x36808 (and c_15_0 in_target_15))))))
 (let (($x38119 (or $x38116 (and $x36946 (and (and true c_10_8) $x30225)))))
 (let (($x38122 (or $x38119 (and $x36951 (and (and true c_18_8) $x30331)))))
 (let (($x38125 (or $x38122 (and $x36955 (and (and true c_21_8) $x30296)))))
 (let (($x38128 (or $x38125 (and $x36960 (and (and true c_22_8) $x30366)))))
 (let (($x38131 (or $x38128 (and $x36965 (and (and true c_23_8) $x30401)))))
 (let (($x38134 (or $x38131 (and $x36970 (and (and true c_0_8) $x30331)))))
 (let (($x38137 (or $x38134 (and $x36990 (and $x36778 $x30062)))))
 (let (($x38140 (or $x38137 (and $x36994 (and $x36784 (and c_14_0 in_target_14))))))
 (let (($x38143 (or $x38140 (and $x36998 (and $x36790 (and c_17_0 in_target_17))))))
 (let (($x38146 (or $x38143 (and $x37002 (and $x36796 (and c_16_0 in_target_16))))))
 (let (($x38149 (or $x38146 (and $x37006 (and $x36802 (and c_18_0 in_target_18))))))
 (let (($x38152 (or $x38149 (and $x37010 (and $x36808 (and c_19_0 in_target_19))))))
 (let (($x38155 (or $x38152 (and $x37014 (and (and true c_7_8) $x30225)))))
 (let (($x38158 (or $x38155 (and $x37019 (and (and true c_8_8) $x30261)))))
 (let (($x38161 (or $x38158 (and $x37024 (and (and true c_9_8) $x30296)))))
 (let (($x38164 (or $x38161 (and $x37029 (and (and true c_10_8) $x30366)))))
 (let (($x38167 (or $x38164 (and $x37033 (and (and true c_11_8) $x30401)))))
 (let (($x38170 (or $x38167 (and $x37038 (and (and true c_0_8) $x30296)))))
 (let (($x38173 (or $x38170 (and $x37058 (and $x36778 (and c_9_0 in_target_9))))))
 (let (($x38176 (or $x38173 (and $x37062 (and $x36784 (and c_13_0 in_target_13))))))
 (let (($x38179 (or $x38176 (and $x37066 (and $x36790 (and c_16_0 in_target_16))))))
 (let (($x38182 (or $x38179 (and $x37070 (and $x36796 (and c_20_0 in_target_20))))))
 (let (($x38185 (or $x38182 (and $x37074 (and $x36802 (and c_21_0 in_target_21))))))
 (let (($x38188 (or $x38185 (and $x37078 (and $x36808 $x30062)))))
 (let (($x38191 (or $x38188 (and $x37082 (and (and true c_11_8) $x30225)))))
 (let (($x38194 (or $x38191 (and $x37086 (and (and true c_15_8) $x30261)))))
 (let (($x38197 (or $x38194 (and $x37091 (and (and true c_19_8) $x30331)))))
 (let (($x38200 (or $x38197 (and $x37095 (and (and true c_23_8) $x30366)))))
 (let (($x38203 (or $x38200 (and $x37099 (and (and true c_24_8) $x30401)))))
 (let (($x38206 (or $x38203 (and $x37104 (and (and true c_0_8) $x30366)))))
 (let (($x38209 (or $x38206 (and $x37112 (and $x36778 (and c_10_0 in_target_10))))))
 (let (($x38212 (or $x38209 (and $x37116 (and $x36784 $x30062)))))
 (let (($x38215 (or $x38212 (and $x37120 (and $x36790 (and c_18_0 in_target_18))))))
 (let (($x38218 (or $x38215 (and $x37124 (and $x36796 (and c_21_0 in_target_21))))))
 (let (($x38221 (or $x38218 (and $x37128 (and $x36802 (and c_22_0 in_target_22))))))
 (let (($x38224 (or $x38221 (and $x37132 (and $x36808 (and c_23_0 in_target_23))))))
 (let (($x38227 (or $x38224 (and $x37136 (and (and true c_8_8) $x30225)))))
 (let (($x38230 (or $x38227 (and $x37140 (and (and true c_12_8) $x30261)))))
 (let (($x38233 (or $x38230 (and $x37145 (and (and true c_13_8) $x30296)))))
 (let (($x38236 (or $x38233 (and $x37150 (and (and true c_14_8) $x30331)))))
 (let (($x38239 (or $x38236 (and $x37154 (and (and true c_15_8) $x30401)))))
 (let (($x38242 (or $x38239 (and $x37158 (and (and true c_0_8) $x30401)))))
 (let (($x38245 (or $x38242 (and $x37166 (and $x36778 (and c_11_0 in_target_11))))))
 (let (($x38248 (or $x38245 (and $x37170 (and $x36784 (and c_15_0 in_target_15))))))
 (let (($x38251 (or $x38248 (and $x37174 (and $x36790 (and c_19_0 in_target_19))))))
 (let (($x38254 (or $x38251 (and $x37178 (and $x36796 $x30062)))))
 (let (($x38257 (or $x38254 (and $x37182 (and $x36802 (and c_23_0 in_target_23))))))
 (let (($x38260 (or $x38257 (and $x37186 (and $x36808 (and c_24_0 in_target_24))))))
 (let (($x38263 (or $x38260 (and $x37190 (and (and true c_9_8) $x30225)))))
 (let (($x38266 (or $x38263 (and $x37194 (and (and true c_13_8) $x30261)))))
 (let (($x38269 (or $x38266 (and $x37198 (and (and true c_16_8) $x30331)))))
 (let (($x38272 (or $x38269 (and $x37202 (and (and true c_20_8) $x30296)))))
 (let (($x38275 (or $x38272 (and $x37207 (and (and true c_21_8) $x30366)))))
 (let (($x38308 (or $x38275 (and $x36772 (and $x37819 $x38305)))))
 (let (($x38340 (or $x38308 (and $x36776 (and $x37825 $x38337)))))
 (let (($x38370 (or $x38340 (and $x36782 (and $x37829 $x38367)))))
 (let (($x38400 (or $x38370 (and $x36788 (and $x37833 $x38397)))))
 (let (($x38428 (or $x38400 (and $x36794 (and $x37837 $x38425)))))
 (let (($x38456 (or $x38428 (and $x36800 (and $x37839 $x38453)))))
 (let (($x38486 (not (or (and c_0_0 (not in_target_0)) $x30077))))
 (let (($x36541 (not c_128_8)))
 (let (($x36559 (or (and c_128_0 in_target_128) (and c_128_1 in_target_128) (and c_128_2 in_target_128) (and c_128_3 in_target_128) (and c_128_4 in_target_128) (and c_128_5 in_target_128) (and c_128_6 in_target_128) (and c_128_7 in_target_128) (and c_128_8 in_target_128))))
 (let (($x36497 (= ghost_2_62 1)))
 (let (($x36520 (and c_128_8 $x36497)))
 (let (($x36471 (not c_127_8)))
 (let (($x36489 (or (and c_127_0 in_target_127) (and c_127_1 in_target_127) (and c_127_2 in_target_127) (and c_127_3 in_target_127) (and c_127_4 in_target_127) (and c_127_5 in_target_127) (and c_127_6 in_target_127) (and c_127_7 in_target_127) (and c_127_8 in_target_127))))
 (let (($x36472 (and $x36489 $x36471)))
 (let (($x36517 (and c_127_8 $x36497)))
 (let (($x35991 (not c_119_8)))
 (let (($x36009 (or (and c_119_0 in_target_119) (and c_119_1 in_target_119) (and c_119_2 in_target_119) (and c_119_3 in_target_119) (and c_119_4 in_target_119) (and c_119_5 in_target_119) (and c_119_6 in_target_119) (and c_119_7 in_target_119) (and c_119_8 in_target_119))))
 (let (($x35992 (and $x36009 $x35991)))
 (let (($x36511 (and c_119_8 $x36497)))
 (let (($x31181 (not c_24_8)))
 (let (($x31184 (and c_24_1 in_target_24)))
 (let (($x31183 (and c_24_0 in_target_24)))
 (let (($x31199 (or $x31183 $x31184 $x31186 $x31188 $x31190 $x31192 $x31194 $x31196 (and c_24_8 in_target_24))))
 (let (($x31182 (and $x31199 $x31181)))
 (let (($x36506 (and c_24_8 $x36497)))
 (let (($x35151 (not c_103_8)))
 (let (($x35169 (or (and c_103_0 in_target_103) (and c_103_1 in_target_103) (and c_103_2 in_target_103) (and c_103_3 in_target_103) (and c_103_4 in_target_103) (and c_103_5 in_target_103) (and c_103_6 in_target_103) (and c_103_7 in_target_103) (and c_103_8 in_target_103))))
 (let (($x35152 (and $x35169 $x35151)))
 (let (($x36505 (and c_103_8 $x36497)))
 (let (($x34311 (not c_87_8)))
 (let (($x34329 (or (and c_87_0 in_target_87) (and c_87_1 in_target_87) (and c_87_2 in_target_87) (and c_87_3 in_target_87) (and c_87_4 in_target_87) (and c_87_5 in_target_87) (and c_87_6 in_target_87) (and c_87_7 in_target_87) (and c_87_8 in_target_87))))
 (let (($x34312 (and $x34329 $x34311)))
 (let (($x36492 (or (or false (and c_87_8 $x36497)) (and $x34312 (= ghost_2_87 (- ghost_2_62 1))))))
 (let (($x36507 (or (or $x36492 $x36505) (and $x35152 (= ghost_2_103 (- ghost_2_62 1))))))
 (let (($x36509 (or (or $x36507 $x36506) (and $x31182 (= ghost_2_24 (- ghost_2_62 1))))))
 (let (($x36512 (or (or $x36509 $x36511) (and $x35992 (= ghost_2_119 (- ghost_2_62 1))))))
 (let (($x36526 (or (or $x36512 $x36517) (and $x36472 (= ghost_2_127 (- ghost_2_62 1))))))
 (let (($x36545 (or (or $x36526 $x36520) (and (and $x36559 $x36541) (= ghost_2_128 (- ghost_2_62 1))))))
 (let (($x36560 (>= ghost_2_62 1)))
 (let (($x33041 (not c_62_8)))
 (let (($x33059 (or (and c_62_0 in_target_62) (and c_62_1 in_target_62) (and c_62_2 in_target_62) (and c_62_3 in_target_62) (and c_62_4 in_target_62) (and c_62_5 in_target_62) (and c_62_6 in_target_62) (and c_62_7 in_target_62) (and c_62_8 in_target_62))))
 (let (($x33042 (and $x33059 $x33041)))
 (let (($x36565 (and (=> (and $x33059 c_62_8) (= ghost_2_62 0)) (=> $x33042 (and $x36560 $x36545)))))
 (let (($x36428 (= ghost_2_61 1)))
 (let (($x36456 (and c_127_8 $x36428)))
 (let (($x36401 (not c_126_8)))
 (let (($x36419 (or (and c_126_0 in_target_126) (and c_126_1 in_target_126) (and c_126_2 in_target_126) (and c_126_3 in_target_126) (and c_126_4 in_target_126) (and c_126_5 in_target_126) (and c_126_6 in_target_126) (and c_126_7 in_target_126) (and c_126_8 in_target_126))))
 (let (($x36402 (and $x36419 $x36401)))
 (let (($x36450 (and c_126_8 $x36428)))
 (let (($x35921 (not c_118_8)))
 (let (($x35939 (or (and c_118_0 in_target_118) (and c_118_1 in_target_118) (and c_118_2 in_target_118) (and c_118_3 in_target_118) (and c_118_4 in_target_118) (and c_118_5 in_target_118) (and c_118_6 in_target_118) (and c_118_7 in_target_118) (and c_118_8 in_target_118))))
 (let (($x35922 (and $x35939 $x35921)))
 (let (($x36444 (and c_118_8 $x36428)))
 (let (($x31111 (not c_23_8)))
 (let (($x31114 (and c_23_1 in_target_23)))
 (let (($x31113 (and c_23_0 in_target_23)))
 (let (($x31129 (or $x31113 $x31114 $x31116 $x31118 $x31120 $x31122 $x31124 $x31126 (and c_23_8 in_target_23))))
 (let (($x31112 (and $x31129 $x31111)))
 (let (($x36431 (and c_23_8 $x36428)))
 (let (($x36435 (and c_24_8 $x36428)))
 (let (($x34241 (not c_86_8)))
 (let (($x34259 (or (and c_86_0 in_target_86) (and c_86_1 in_target_86) (and c_86_2 in_target_86) (and c_86_3 in_target_86) (and c_86_4 in_target_86) (and c_86_5 in_target_86) (and c_86_6 in_target_86) (and c_86_7 in_target_86) (and c_86_8 in_target_86))))
 (let (($x34242 (and $x34259 $x34241)))
 (let (($x36430 (or (or false (and c_86_8 $x36428)) (and $x34242 (= ghost_2_86 (- ghost_2_61 1))))))
 (let (($x36436 (or (or $x36430 $x36435) (and $x31182 (= ghost_2_24 (- ghost_2_61 1))))))
 (let (($x36439 (or (or $x36436 $x36431) (and $x31112 (= ghost_2_23 (- ghost_2_61 1))))))
 (let (($x36449 (or (or $x36439 $x36444) (and $x35922 (= ghost_2_118 (- ghost_2_61 1))))))
 (let (($x36448 (or (or $x36449 $x36450) (and $x36402 (= ghost_2_126 (- ghost_2_61 1))))))
 (let (($x36481 (or (or $x36448 $x36456) (and $x36472 (= ghost_2_127 (- ghost_2_61 1))))))
 (let (($x36491 (>= ghost_2_61 1)))
 (let (($x32971 (not c_61_8)))
 (let (($x32989 (or (and c_61_0 in_target_61) (and c_61_1 in_target_61) (and c_61_2 in_target_61) (and c_61_3 in_target_61) (and c_61_4 in_target_61) (and c_61_5 in_target_61) (and c_61_6 in_target_61) (and c_61_7 in_target_61) (and c_61_8 in_target_61))))
 (let (($x32972 (and $x32989 $x32971)))
 (let (($x36494 (and (=> (and $x32989 c_61_8) (= ghost_2_61 0)) (=> $x32972 (and $x36491 $x36481)))))
 (let (($x36358 (= ghost_2_60 1)))
 (let (($x36377 (and c_126_8 $x36358)))
 (let (($x36331 (not c_125_8)))
 (let (($x36349 (or (and c_125_0 in_target_125) (and c_125_1 in_target_125) (and c_125_2 in_target_125) (and c_125_3 in_target_125) (and c_125_4 in_target_125) (and c_125_5 in_target_125) (and c_125_6 in_target_125) (and c_125_7 in_target_125) (and c_125_8 in_target_125))))
 (let (($x36332 (and $x36349 $x36331)))
 (let (($x36378 (and c_125_8 $x36358)))
 (let (($x35851 (not c_117_8)))
 (let (($x35869 (or (and c_117_0 in_target_117) (and c_117_1 in_target_117) (and c_117_2 in_target_117) (and c_117_3 in_target_117) (and c_117_4 in_target_117) (and c_117_5 in_target_117) (and c_117_6 in_target_117) (and c_117_7 in_target_117) (and c_117_8 in_target_117))))
 (let (($x35852 (and $x35869 $x35851)))
 (let (($x36367 (and c_117_8 $x36358)))
 (let (($x31076 (not c_22_8)))
 (let (($x31079 (and c_22_1 in_target_22)))
 (let (($x31078 (and c_22_0 in_target_22)))
 (let (($x31094 (or $x31078 $x31079 $x31081 $x31083 $x31085 $x31087 $x31089 $x31091 (and c_22_8 in_target_22))))
 (let (($x31077 (and $x31094 $x31076)))
 (let (($x36369 (and c_22_8 $x36358)))
 (let (($x36362 (and c_23_8 $x36358)))
 (let (($x34171 (not c_85_8)))
 (let (($x34189 (or (and c_85_0 in_target_85) (and c_85_1 in_target_85) (and c_85_2 in_target_85) (and c_85_3 in_target_85) (and c_85_4 in_target_85) (and c_85_5 in_target_85) (and c_85_6 in_target_85) (and c_85_7 in_target_85) (and c_85_8 in_target_85))))
 (let (($x34172 (and $x34189 $x34171)))
 (let (($x36361 (or (or false (and c_85_8 $x36358)) (and $x34172 (= ghost_2_85 (- ghost_2_60 1))))))
 (let (($x36366 (or (or $x36361 $x36362) (and $x31112 (= ghost_2_23 (- ghost_2_60 1))))))
 (let (($x36374 (or (or $x36366 $x36369) (and $x31077 (= ghost_2_22 (- ghost_2_60 1))))))
 (let (($x36371 (or (or $x36374 $x36367) (and $x35852 (= ghost_2_117 (- ghost_2_60 1))))))
 (let (($x36386 (or (or $x36371 $x36378) (and $x36332 (= ghost_2_125 (- ghost_2_60 1))))))
 (let (($x36415 (or (or $x36386 $x36377) (and $x36402 (= ghost_2_126 (- ghost_2_60 1))))))
 (let (($x36425 (>= ghost_2_60 1)))
 (let (($x32901 (not c_60_8)))
 (let (($x32919 (or (and c_60_0 in_target_60) (and c_60_1 in_target_60) (and c_60_2 in_target_60) (and c_60_3 in_target_60) (and c_60_4 in_target_60) (and c_60_5 in_target_60) (and c_60_6 in_target_60) (and c_60_7 in_target_60) (and c_60_8 in_target_60))))
 (let (($x32902 (and $x32919 $x32901)))
 (let (($x36422 (and (=> (and $x32919 c_60_8) (= ghost_2_60 0)) (=> $x32902 (and $x36425 $x36415)))))
 (let (($x36258 (= ghost_2_59 1)))
 (let (($x36306 (and c_125_8 $x36258)))
 (let (($x36296 (not c_124_8)))
 (let (($x36314 (or (and c_124_0 in_target_124) (and c_124_1 in_target_124) (and c_124_2 in_target_124) (and c_124_3 in_target_124) (and c_124_4 in_target_124) (and c_124_5 in_target_124) (and c_124_6 in_target_124) (and c_124_7 in_target_124) (and c_124_8 in_target_124))))
 (let (($x36280 (and c_124_8 $x36258)))
 (let (($x35816 (not c_116_8)))
 (let (($x35834 (or (and c_116_0 in_target_116) (and c_116_1 in_target_116) (and c_116_2 in_target_116) (and c_116_3 in_target_116) (and c_116_4 in_target_116) (and c_116_5 in_target_116) (and c_116_6 in_target_116) (and c_116_7 in_target_116) (and c_116_8 in_target_116))))
 (let (($x35817 (and $x35834 $x35816)))
 (let (($x36271 (and c_116_8 $x36258)))
 (let (($x36226 (not c_123_8)))
 (let (($x36244 (or (and c_123_0 in_target_123) (and c_123_1 in_target_123) (and c_123_2 in_target_123) (and c_123_3 in_target_123) (and c_123_4 in_target_123) (and c_123_5 in_target_123) (and c_123_6 in_target_123) (and c_123_7 in_target_123) (and c_123_8 in_target_123))))
 (let (($x36227 (and $x36244 $x36226)))
 (let (($x36266 (and c_123_8 $x36258)))
 (let (($x36265 (and c_22_8 $x36258)))
 (let (($x34136 (not c_84_8)))
 (let (($x34154 (or (and c_84_0 in_target_84) (and c_84_1 in_target_84) (and c_84_2 in_target_84) (and c_84_3 in_target_84) (and c_84_4 in_target_84) (and c_84_5 in_target_84) (and c_84_6 in_target_84) (and c_84_7 in_target_84) (and c_84_8 in_target_84))))
 (let (($x34137 (and $x34154 $x34136)))
 (let (($x36263 (or (or false (and c_84_8 $x36258)) (and $x34137 (= ghost_2_84 (- ghost_2_59 1))))))
 (let (($x36269 (or (or $x36263 $x36265) (and $x31077 (= ghost_2_22 (- ghost_2_59 1))))))
 (let (($x36262 (or (or $x36269 $x36266) (and $x36227 (= ghost_2_123 (- ghost_2_59 1))))))
 (let (($x36276 (or (or $x36262 $x36271) (and $x35817 (= ghost_2_116 (- ghost_2_59 1))))))
 (let (($x36304 (or (or $x36276 $x36280) (and (and $x36314 $x36296) (= ghost_2_124 (- ghost_2_59 1))))))
 (let (($x36341 (or (or $x36304 $x36306) (and $x36332 (= ghost_2_125 (- ghost_2_59 1))))))
 (let (($x36351 (>= ghost_2_59 1)))
 (let (($x32866 (not c_59_8)))
 (let (($x32884 (or (and c_59_0 in_target_59) (and c_59_1 in_target_59) (and c_59_2 in_target_59) (and c_59_3 in_target_59) (and c_59_4 in_target_59) (and c_59_5 in_target_59) (and c_59_6 in_target_59) (and c_59_7 in_target_59) (and c_59_8 in_target_59))))
 (let (($x32867 (and $x32884 $x32866)))
 (let (($x36355 (and (=> (and $x32884 c_59_8) (= ghost_2_59 0)) (=> $x32867 (and $x36351 $x36341)))))
 (let (($x36187 (= ghost_2_58 1)))
 (let (($x36240 (and c_22_8 $x36187)))
 (let (($x36206 (and c_123_8 $x36187)))
 (let (($x35446 (not c_109_8)))
 (let (($x35464 (or (and c_109_0 in_target_109) (and c_109_1 in_target_109) (and c_109_2 in_target_109) (and c_109_3 in_target_109) (and c_109_4 in_target_109) (and c_109_5 in_target_109) (and c_109_6 in_target_109) (and c_109_7 in_target_109) (and c_109_8 in_target_109))))
 (let (($x35447 (and $x35464 $x35446)))
 (let (($x36203 (and c_109_8 $x36187)))
 (let (($x36156 (not c_122_8)))
 (let (($x36174 (or (and c_122_0 in_target_122) (and c_122_1 in_target_122) (and c_122_2 in_target_122) (and c_122_3 in_target_122) (and c_122_4 in_target_122) (and c_122_5 in_target_122) (and c_122_6 in_target_122) (and c_122_7 in_target_122) (and c_122_8 in_target_122))))
 (let (($x36157 (and $x36174 $x36156)))
 (let (($x36201 (and c_122_8 $x36187)))
 (let (($x31006 (not c_21_8)))
 (let (($x31009 (and c_21_1 in_target_21)))
 (let (($x31008 (and c_21_0 in_target_21)))
 (let (($x31024 (or $x31008 $x31009 $x31011 $x31013 $x31015 $x31017 $x31019 $x31021 (and c_21_8 in_target_21))))
 (let (($x31007 (and $x31024 $x31006)))
 (let (($x36194 (and c_21_8 $x36187)))
 (let (($x34066 (not c_83_8)))
 (let (($x34084 (or (and c_83_0 in_target_83) (and c_83_1 in_target_83) (and c_83_2 in_target_83) (and c_83_3 in_target_83) (and c_83_4 in_target_83) (and c_83_5 in_target_83) (and c_83_6 in_target_83) (and c_83_7 in_target_83) (and c_83_8 in_target_83))))
 (let (($x34067 (and $x34084 $x34066)))
 (let (($x36191 (or (or false (and c_83_8 $x36187)) (and $x34067 (= ghost_2_83 (- ghost_2_58 1))))))
 (let (($x36190 (or (or $x36191 $x36194) (and $x31007 (= ghost_2_21 (- ghost_2_58 1))))))
 (let (($x36200 (or (or $x36190 $x36201) (and $x36157 (= ghost_2_122 (- ghost_2_58 1))))))
 (let (($x36208 (or (or $x36200 $x36203) (and $x35447 (= ghost_2_109 (- ghost_2_58 1))))))
 (let (($x36238 (or (or $x36208 $x36206) (and $x36227 (= ghost_2_123 (- ghost_2_58 1))))))
 (let (($x36249 (or (or $x36238 $x36240) (and $x31077 (= ghost_2_22 (- ghost_2_58 1))))))
 (let (($x36251 (>= ghost_2_58 1)))
 (let (($x32796 (not c_58_8)))
 (let (($x32814 (or (and c_58_0 in_target_58) (and c_58_1 in_target_58) (and c_58_2 in_target_58) (and c_58_3 in_target_58) (and c_58_4 in_target_58) (and c_58_5 in_target_58) (and c_58_6 in_target_58) (and c_58_7 in_target_58) (and c_58_8 in_target_58))))
 (let (($x32797 (and $x32814 $x32796)))
 (let (($x36245 (and (=> (and $x32814 c_58_8) (= ghost_2_58 0)) (=> $x32797 (and $x36251 $x36249)))))
 (let (($x36112 (= ghost_2_57 1)))
 (let (($x36162 (and c_21_8 $x36112)))
 (let (($x36121 (and c_122_8 $x36112)))
 (let (($x35276 (not c_106_8)))
 (let (($x35294 (or (and c_106_0 in_target_106) (and c_106_1 in_target_106) (and c_106_2 in_target_106) (and c_106_3 in_target_106) (and c_106_4 in_target_106) (and c_106_5 in_target_106) (and c_106_6 in_target_106) (and c_106_7 in_target_106) (and c_106_8 in_target_106))))
 (let (($x35277 (and $x35294 $x35276)))
 (let (($x36135 (and c_106_8 $x36112)))
 (let (($x36086 (not c_121_8)))
 (let (($x36104 (or (and c_121_0 in_target_121) (and c_121_1 in_target_121) (and c_121_2 in_target_121) (and c_121_3 in_target_121) (and c_121_4 in_target_121) (and c_121_5 in_target_121) (and c_121_6 in_target_121) (and c_121_7 in_target_121) (and c_121_8 in_target_121))))
 (let (($x36087 (and $x36104 $x36086)))
 (let (($x36126 (and c_121_8 $x36112)))
 (let (($x30966 (not c_20_8)))
 (let (($x30969 (and c_20_1 in_target_20)))
 (let (($x30968 (and c_20_0 in_target_20)))
 (let (($x30984 (or $x30968 $x30969 $x30971 $x30973 $x30975 $x30977 $x30979 $x30981 (and c_20_8 in_target_20))))
 (let (($x30967 (and $x30984 $x30966)))
 (let (($x36123 (and c_20_8 $x36112)))
 (let (($x33996 (not c_82_8)))
 (let (($x34014 (or (and c_82_0 in_target_82) (and c_82_1 in_target_82) (and c_82_2 in_target_82) (and c_82_3 in_target_82) (and c_82_4 in_target_82) (and c_82_5 in_target_82) (and c_82_6 in_target_82) (and c_82_7 in_target_82) (and c_82_8 in_target_82))))
 (let (($x33997 (and $x34014 $x33996)))
 (let (($x36120 (or (or false (and c_82_8 $x36112)) (and $x33997 (= ghost_2_82 (- ghost_2_57 1))))))
 (let (($x36127 (or (or $x36120 $x36123) (and $x30967 (= ghost_2_20 (- ghost_2_57 1))))))
 (let (($x36136 (or (or $x36127 $x36126) (and $x36087 (= ghost_2_121 (- ghost_2_57 1))))))
 (let (($x36138 (or (or $x36136 $x36135) (and $x35277 (= ghost_2_106 (- ghost_2_57 1))))))
 (let (($x36164 (or (or $x36138 $x36121) (and $x36157 (= ghost_2_122 (- ghost_2_57 1))))))
 (let (($x36175 (or (or $x36164 $x36162) (and $x31007 (= ghost_2_21 (- ghost_2_57 1))))))
 (let (($x36184 (>= ghost_2_57 1)))
 (let (($x32726 (not c_57_8)))
 (let (($x32744 (or (and c_57_0 in_target_57) (and c_57_1 in_target_57) (and c_57_2 in_target_57) (and c_57_3 in_target_57) (and c_57_4 in_target_57) (and c_57_5 in_target_57) (and c_57_6 in_target_57) (and c_57_7 in_target_57) (and c_57_8 in_target_57))))
 (let (($x32727 (and $x32744 $x32726)))
 (let (($x36177 (and (=> (and $x32744 c_57_8) (= ghost_2_57 0)) (=> $x32727 (and $x36184 $x36175)))))
 (let (($x36017 (= ghost_2_56 1)))
 (let (($x36096 (and c_20_8 $x36017)))
 (let (($x36070 (and c_121_8 $x36017)))
 (let (($x35206 (not c_104_8)))
 (let (($x35224 (or (and c_104_0 in_target_104) (and c_104_1 in_target_104) (and c_104_2 in_target_104) (and c_104_3 in_target_104) (and c_104_4 in_target_104) (and c_104_5 in_target_104) (and c_104_6 in_target_104) (and c_104_7 in_target_104) (and c_104_8 in_target_104))))
 (let (($x35207 (and $x35224 $x35206)))
 (let (($x36052 (and c_104_8 $x36017)))
 (let (($x36046 (not c_120_8)))
 (let (($x36064 (or (and c_120_0 in_target_120) (and c_120_1 in_target_120) (and c_120_2 in_target_120) (and c_120_3 in_target_120) (and c_120_4 in_target_120) (and c_120_5 in_target_120) (and c_120_6 in_target_120) (and c_120_7 in_target_120) (and c_120_8 in_target_120))))
 (let (($x36025 (and c_120_8 $x36017)))
 (let (($x34796 (not c_97_8)))
 (let (($x34814 (or (and c_97_0 in_target_97) (and c_97_1 in_target_97) (and c_97_2 in_target_97) (and c_97_3 in_target_97) (and c_97_4 in_target_97) (and c_97_5 in_target_97) (and c_97_6 in_target_97) (and c_97_7 in_target_97) (and c_97_8 in_target_97))))
 (let (($x34797 (and $x34814 $x34796)))
 (let (($x36024 (and c_97_8 $x36017)))
 (let (($x33956 (not c_81_8)))
 (let (($x33974 (or (and c_81_0 in_target_81) (and c_81_1 in_target_81) (and c_81_2 in_target_81) (and c_81_3 in_target_81) (and c_81_4 in_target_81) (and c_81_5 in_target_81) (and c_81_6 in_target_81) (and c_81_7 in_target_81) (and c_81_8 in_target_81))))
 (let (($x33957 (and $x33974 $x33956)))
 (let (($x36022 (or (or false (and c_81_8 $x36017)) (and $x33957 (= ghost_2_81 (- ghost_2_56 1))))))
 (let (($x36026 (or (or $x36022 $x36024) (and $x34797 (= ghost_2_97 (- ghost_2_56 1))))))
 (let (($x36056 (or (or $x36026 $x36025) (and (and $x36064 $x36046) (= ghost_2_120 (- ghost_2_56 1))))))
 (let (($x36069 (or (or $x36056 $x36052) (and $x35207 (= ghost_2_104 (- ghost_2_56 1))))))
 (let (($x36092 (or (or $x36069 $x36070) (and $x36087 (= ghost_2_121 (- ghost_2_56 1))))))
 (let (($x36107 (or (or $x36092 $x36096) (and $x30967 (= ghost_2_20 (- ghost_2_56 1))))))
 (let (($x36114 (>= ghost_2_56 1)))
 (let (($x32686 (not c_56_8)))
 (let (($x32704 (or (and c_56_0 in_target_56) (and c_56_1 in_target_56) (and c_56_2 in_target_56) (and c_56_3 in_target_56) (and c_56_4 in_target_56) (and c_56_5 in_target_56) (and c_56_6 in_target_56) (and c_56_7 in_target_56) (and c_56_8 in_target_56))))
 (let (($x32687 (and $x32704 $x32686)))
 (let (($x36115 (and (=> (and $x32704 c_56_8) (= ghost_2_56 0)) (=> $x32687 (and $x36114 $x36107)))))
 (let (($x35948 (= ghost_2_55 1)))
 (let (($x35975 (and c_119_8 $x35948)))
 (let (($x35961 (and c_118_8 $x35948)))
 (let (($x35751 (not c_115_8)))
 (let (($x35769 (or (and c_115_0 in_target_115) (and c_115_1 in_target_115) (and c_115_2 in_target_115) (and c_115_3 in_target_115) (and c_115_4 in_target_115) (and c_115_5 in_target_115) (and c_115_6 in_target_115) (and c_115_7 in_target_115) (and c_115_8 in_target_115))))
 (let (($x35752 (and $x35769 $x35751)))
 (let (($x35963 (and c_115_8 $x35948)))
 (let (($x30911 (not c_19_8)))
 (let (($x30914 (and c_19_1 in_target_19)))
 (let (($x30913 (and c_19_0 in_target_19)))
 (let (($x30929 (or $x30913 $x30914 $x30916 $x30918 $x30920 $x30922 $x30924 $x30926 (and c_19_8 in_target_19))))
 (let (($x30912 (and $x30929 $x30911)))
 (let (($x35953 (and c_19_8 $x35948)))
 (let (($x35081 (not c_102_8)))
 (let (($x35099 (or (and c_102_0 in_target_102) (and c_102_1 in_target_102) (and c_102_2 in_target_102) (and c_102_3 in_target_102) (and c_102_4 in_target_102) (and c_102_5 in_target_102) (and c_102_6 in_target_102) (and c_102_7 in_target_102) (and c_102_8 in_target_102))))
 (let (($x35082 (and $x35099 $x35081)))
 (let (($x35955 (and c_102_8 $x35948)))
 (let (($x35949 (or (or false (and c_24_8 $x35948)) (and $x31182 (= ghost_2_24 (- ghost_2_55 1))))))
 (let (($x35957 (or (or $x35949 $x35955) (and $x35082 (= ghost_2_102 (- ghost_2_55 1))))))
 (let (($x35964 (or (or $x35957 $x35953) (and $x30912 (= ghost_2_19 (- ghost_2_55 1))))))
 (let (($x35967 (or (or $x35964 $x35963) (and $x35752 (= ghost_2_115 (- ghost_2_55 1))))))
 (let (($x35974 (or (or $x35967 $x35961) (and $x35922 (= ghost_2_118 (- ghost_2_55 1))))))
 (let (($x36003 (or (or $x35974 $x35975) (and $x35992 (= ghost_2_119 (- ghost_2_55 1))))))
 (let (($x36015 (>= ghost_2_55 1)))
 (let (($x32631 (not c_55_8)))
 (let (($x32649 (or (and c_55_0 in_target_55) (and c_55_1 in_target_55) (and c_55_2 in_target_55) (and c_55_3 in_target_55) (and c_55_4 in_target_55) (and c_55_5 in_target_55) (and c_55_6 in_target_55) (and c_55_7 in_target_55) (and c_55_8 in_target_55))))
 (let (($x32632 (and $x32649 $x32631)))
 (let (($x36014 (and (=> (and $x32649 c_55_8) (= ghost_2_55 0)) (=> $x32632 (and $x36015 $x36003)))))
 (let (($x35872 (= ghost_2_54 1)))
 (let (($x35903 (and c_118_8 $x35872)))
 (let (($x35900 (and c_117_8 $x35872)))
 (let (($x35681 (not c_114_8)))
 (let (($x35699 (or (and c_114_0 in_target_114) (and c_114_1 in_target_114) (and c_114_2 in_target_114) (and c_114_3 in_target_114) (and c_114_4 in_target_114) (and c_114_5 in_target_114) (and c_114_6 in_target_114) (and c_114_7 in_target_114) (and c_114_8 in_target_114))))
 (let (($x35682 (and $x35699 $x35681)))
 (let (($x35881 (and c_114_8 $x35872)))
 (let (($x30876 (not c_18_8)))
 (let (($x30879 (and c_18_1 in_target_18)))
 (let (($x30878 (and c_18_0 in_target_18)))
 (let (($x30894 (or $x30878 $x30879 $x30881 $x30883 $x30885 $x30887 $x30889 $x30891 (and c_18_8 in_target_18))))
 (let (($x30877 (and $x30894 $x30876)))
 (let (($x35888 (and c_18_8 $x35872)))
 (let (($x35884 (and c_19_8 $x35872)))
 (let (($x35883 (or (or false (and c_23_8 $x35872)) (and $x31112 (= ghost_2_23 (- ghost_2_54 1))))))
 (let (($x35889 (or (or $x35883 $x35884) (and $x30912 (= ghost_2_19 (- ghost_2_54 1))))))
 (let (($x35891 (or (or $x35889 $x35888) (and $x30877 (= ghost_2_18 (- ghost_2_54 1))))))
 (let (($x35898 (or (or $x35891 $x35881) (and $x35682 (= ghost_2_114 (- ghost_2_54 1))))))
 (let (($x35896 (or (or $x35898 $x35900) (and $x35852 (= ghost_2_117 (- ghost_2_54 1))))))
 (let (($x35929 (or (or $x35896 $x35903) (and $x35922 (= ghost_2_118 (- ghost_2_54 1))))))
 (let (($x35941 (>= ghost_2_54 1)))
 (let (($x32561 (not c_54_8)))
 (let (($x32579 (or (and c_54_0 in_target_54) (and c_54_1 in_target_54) (and c_54_2 in_target_54) (and c_54_3 in_target_54) (and c_54_4 in_target_54) (and c_54_5 in_target_54) (and c_54_6 in_target_54) (and c_54_7 in_target_54) (and c_54_8 in_target_54))))
 (let (($x32562 (and $x32579 $x32561)))
 (let (($x35927 (and (=> (and $x32579 c_54_8) (= ghost_2_54 0)) (=> $x32562 (and $x35941 $x35929)))))
 (let (($x35773 (= ghost_2_53 1)))
 (let (($x35826 (and c_117_8 $x35773)))
 (let (($x35798 (and c_116_8 $x35773)))
 (let (($x35646 (not c_113_8)))
 (let (($x35664 (or (and c_113_0 in_target_113) (and c_113_1 in_target_113) (and c_113_2 in_target_113) (and c_113_3 in_target_113) (and c_113_4 in_target_113) (and c_113_5 in_target_113) (and c_113_6 in_target_113) (and c_113_7 in_target_113) (and c_113_8 in_target_113))))
 (let (($x35647 (and $x35664 $x35646)))
 (let (($x35788 (and c_113_8 $x35773)))
 (let (($x35786 (and c_109_8 $x35773)))
 (let (($x35784 (and c_18_8 $x35773)))
 (let (($x35780 (or (or false (and c_22_8 $x35773)) (and $x31077 (= ghost_2_22 (- ghost_2_53 1))))))
 (let (($x35785 (or (or $x35780 $x35784) (and $x30877 (= ghost_2_18 (- ghost_2_53 1))))))
 (let (($x35793 (or (or $x35785 $x35786) (and $x35447 (= ghost_2_109 (- ghost_2_53 1))))))
 (let (($x35799 (or (or $x35793 $x35788) (and $x35647 (= ghost_2_113 (- ghost_2_53 1))))))
 (let (($x35828 (or (or $x35799 $x35798) (and $x35817 (= ghost_2_116 (- ghost_2_53 1))))))
 (let (($x35857 (or (or $x35828 $x35826) (and $x35852 (= ghost_2_117 (- ghost_2_53 1))))))
 (let (($x35870 (>= ghost_2_53 1)))
 (let (($x32526 (not c_53_8)))
 (let (($x32544 (or (and c_53_0 in_target_53) (and c_53_1 in_target_53) (and c_53_2 in_target_53) (and c_53_3 in_target_53) (and c_53_4 in_target_53) (and c_53_5 in_target_53) (and c_53_6 in_target_53) (and c_53_7 in_target_53) (and c_53_8 in_target_53))))
 (let (($x32527 (and $x32544 $x32526)))
 (let (($x35873 (and (=> (and $x32544 c_53_8) (= ghost_2_53 0)) (=> $x32527 (and $x35870 $x35857)))))
 (let (($x35708 (= ghost_2_52 1)))
 (let (($x35735 (and c_115_8 $x35708)))
 (let (($x35728 (and c_114_8 $x35708)))
 (let (($x35581 (not c_112_8)))
 (let (($x35599 (or (and c_112_0 in_target_112) (and c_112_1 in_target_112) (and c_112_2 in_target_112) (and c_112_3 in_target_112) (and c_112_4 in_target_112) (and c_112_5 in_target_112) (and c_112_6 in_target_112) (and c_112_7 in_target_112) (and c_112_8 in_target_112))))
 (let (($x35582 (and $x35599 $x35581)))
 (let (($x35725 (and c_112_8 $x35708)))
 (let (($x30841 (not c_17_8)))
 (let (($x30844 (and c_17_1 in_target_17)))
 (let (($x30843 (and c_17_0 in_target_17)))
 (let (($x30859 (or $x30843 $x30844 $x30846 $x30848 $x30850 $x30852 $x30854 $x30856 (and c_17_8 in_target_17))))
 (let (($x30842 (and $x30859 $x30841)))
 (let (($x35718 (and c_17_8 $x35708)))
 (let (($x35011 (not c_101_8)))
 (let (($x35029 (or (and c_101_0 in_target_101) (and c_101_1 in_target_101) (and c_101_2 in_target_101) (and c_101_3 in_target_101) (and c_101_4 in_target_101) (and c_101_5 in_target_101) (and c_101_6 in_target_101) (and c_101_7 in_target_101) (and c_101_8 in_target_101))))
 (let (($x35012 (and $x35029 $x35011)))
 (let (($x35710 (and c_101_8 $x35708)))
 (let (($x35712 (or (or false (and c_19_8 $x35708)) (and $x30912 (= ghost_2_19 (- ghost_2_52 1))))))
 (let (($x35716 (or (or $x35712 $x35710) (and $x35012 (= ghost_2_101 (- ghost_2_52 1))))))
 (let (($x35723 (or (or $x35716 $x35718) (and $x30842 (= ghost_2_17 (- ghost_2_52 1))))))
 (let (($x35722 (or (or $x35723 $x35725) (and $x35582 (= ghost_2_112 (- ghost_2_52 1))))))
 (let (($x35733 (or (or $x35722 $x35728) (and $x35682 (= ghost_2_114 (- ghost_2_52 1))))))
 (let (($x35763 (or (or $x35733 $x35735) (and $x35752 (= ghost_2_115 (- ghost_2_52 1))))))
 (let (($x35755 (>= ghost_2_52 1)))
 (let (($x32461 (not c_52_8)))
 (let (($x32479 (or (and c_52_0 in_target_52) (and c_52_1 in_target_52) (and c_52_2 in_target_52) (and c_52_3 in_target_52) (and c_52_4 in_target_52) (and c_52_5 in_target_52) (and c_52_6 in_target_52) (and c_52_7 in_target_52) (and c_52_8 in_target_52))))
 (let (($x32462 (and $x32479 $x32461)))
 (let (($x35770 (and (=> (and $x32479 c_52_8) (= ghost_2_52 0)) (=> $x32462 (and $x35755 $x35763)))))
 (let (($x35609 (= ghost_2_51 1)))
 (let (($x35654 (and c_114_8 $x35609)))
 (let (($x35631 (and c_113_8 $x35609)))
 (let (($x35546 (not c_111_8)))
 (let (($x35564 (or (and c_111_0 in_target_111) (and c_111_1 in_target_111) (and c_111_2 in_target_111) (and c_111_3 in_target_111) (and c_111_4 in_target_111) (and c_111_5 in_target_111) (and c_111_6 in_target_111) (and c_111_7 in_target_111) (and c_111_8 in_target_111))))
 (let (($x35547 (and $x35564 $x35546)))
 (let (($x35622 (and c_111_8 $x35609)))
 (let (($x35376 (not c_108_8)))
 (let (($x35394 (or (and c_108_0 in_target_108) (and c_108_1 in_target_108) (and c_108_2 in_target_108) (and c_108_3 in_target_108) (and c_108_4 in_target_108) (and c_108_5 in_target_108) (and c_108_6 in_target_108) (and c_108_7 in_target_108) (and c_108_8 in_target_108))))
 (let (($x35377 (and $x35394 $x35376)))
 (let (($x35620 (and c_108_8 $x35609)))
 (let (($x35614 (and c_17_8 $x35609)))
 (let (($x35610 (or (or false (and c_18_8 $x35609)) (and $x30877 (= ghost_2_18 (- ghost_2_51 1))))))
 (let (($x35618 (or (or $x35610 $x35614) (and $x30842 (= ghost_2_17 (- ghost_2_51 1))))))
 (let (($x35624 (or (or $x35618 $x35620) (and $x35377 (= ghost_2_108 (- ghost_2_51 1))))))
 (let (($x35630 (or (or $x35624 $x35622) (and $x35547 (= ghost_2_111 (- ghost_2_51 1))))))
 (let (($x35660 (or (or $x35630 $x35631) (and $x35647 (= ghost_2_113 (- ghost_2_51 1))))))
 (let (($x35693 (or (or $x35660 $x35654) (and $x35682 (= ghost_2_114 (- ghost_2_51 1))))))
 (let (($x35701 (>= ghost_2_51 1)))
 (let (($x32426 (not c_51_8)))
 (let (($x32444 (or (and c_51_0 in_target_51) (and c_51_1 in_target_51) (and c_51_2 in_target_51) (and c_51_3 in_target_51) (and c_51_4 in_target_51) (and c_51_5 in_target_51) (and c_51_6 in_target_51) (and c_51_7 in_target_51) (and c_51_8 in_target_51))))
 (let (($x32427 (and $x32444 $x32426)))
 (let (($x35703 (and (=> (and $x32444 c_51_8) (= ghost_2_51 0)) (=> $x32427 (and $x35701 $x35693)))))
 (let (($x35468 (= ghost_2_50 1)))
 (let (($x35554 (and c_112_8 $x35468)))
 (let (($x35525 (and c_111_8 $x35468)))
 (let (($x35511 (not c_110_8)))
 (let (($x35529 (or (and c_110_0 in_target_110) (and c_110_1 in_target_110) (and c_110_2 in_target_110) (and c_110_3 in_target_110) (and c_110_4 in_target_110) (and c_110_5 in_target_110) (and c_110_6 in_target_110) (and c_110_7 in_target_110) (and c_110_8 in_target_110))))
 (let (($x35494 (and c_110_8 $x35468)))
 (let (($x35341 (not c_107_8)))
 (let (($x35359 (or (and c_107_0 in_target_107) (and c_107_1 in_target_107) (and c_107_2 in_target_107) (and c_107_3 in_target_107) (and c_107_4 in_target_107) (and c_107_5 in_target_107) (and c_107_6 in_target_107) (and c_107_7 in_target_107) (and c_107_8 in_target_107))))
 (let (($x35342 (and $x35359 $x35341)))
 (let (($x35491 (and c_107_8 $x35468)))
 (let (($x34971 (not c_100_8)))
 (let (($x34989 (or (and c_100_0 in_target_100) (and c_100_1 in_target_100) (and c_100_2 in_target_100) (and c_100_3 in_target_100) (and c_100_4 in_target_100) (and c_100_5 in_target_100) (and c_100_6 in_target_100) (and c_100_7 in_target_100) (and c_100_8 in_target_100))))
 (let (($x34972 (and $x34989 $x34971)))
 (let (($x35480 (and c_100_8 $x35468)))
 (let (($x35484 (or (or false (and c_17_8 $x35468)) (and $x30842 (= ghost_2_17 (- ghost_2_50 1))))))
 (let (($x35486 (or (or $x35484 $x35480) (and $x34972 (= ghost_2_100 (- ghost_2_50 1))))))
 (let (($x35481 (or (or $x35486 $x35491) (and $x35342 (= ghost_2_107 (- ghost_2_50 1))))))
 (let (($x35523 (or (or $x35481 $x35494) (and (and $x35529 $x35511) (= ghost_2_110 (- ghost_2_50 1))))))
 (let (($x35558 (or (or $x35523 $x35525) (and $x35547 (= ghost_2_111 (- ghost_2_50 1))))))
 (let (($x35595 (or (or $x35558 $x35554) (and $x35582 (= ghost_2_112 (- ghost_2_50 1))))))
 (let (($x35601 (>= ghost_2_50 1)))
 (let (($x32391 (not c_50_8)))
 (let (($x32409 (or (and c_50_0 in_target_50) (and c_50_1 in_target_50) (and c_50_2 in_target_50) (and c_50_3 in_target_50) (and c_50_4 in_target_50) (and c_50_5 in_target_50) (and c_50_6 in_target_50) (and c_50_7 in_target_50) (and c_50_8 in_target_50))))
 (let (($x32392 (and $x32409 $x32391)))
 (let (($x35603 (and (=> (and $x32409 c_50_8) (= ghost_2_50 0)) (=> $x32392 (and $x35601 $x35595)))))
 (let (($x35409 (= ghost_2_49 1)))
 (let (($x35452 (and c_18_8 $x35409)))
 (let (($x35427 (and c_109_8 $x35409)))
 (let (($x35421 (and c_108_8 $x35409)))
 (let (($x35411 (and c_106_8 $x35409)))
 (let (($x30806 (not c_16_8)))
 (let (($x30809 (and c_16_1 in_target_16)))
 (let (($x30808 (and c_16_0 in_target_16)))
 (let (($x30824 (or $x30808 $x30809 $x30811 $x30813 $x30815 $x30817 $x30819 $x30821 (and c_16_8 in_target_16))))
 (let (($x30807 (and $x30824 $x30806)))
 (let (($x35410 (and c_16_8 $x35409)))
 (let (($x35415 (or (or false (and c_21_8 $x35409)) (and $x31007 (= ghost_2_21 (- ghost_2_49 1))))))
 (let (($x35418 (or (or $x35415 $x35410) (and $x30807 (= ghost_2_16 (- ghost_2_49 1))))))
 (let (($x35423 (or (or $x35418 $x35411) (and $x35277 (= ghost_2_106 (- ghost_2_49 1))))))
 (let (($x35429 (or (or $x35423 $x35421) (and $x35377 (= ghost_2_108 (- ghost_2_49 1))))))
 (let (($x35462 (or (or $x35429 $x35427) (and $x35447 (= ghost_2_109 (- ghost_2_49 1))))))
 (let (($x35465 (or (or $x35462 $x35452) (and $x30877 (= ghost_2_18 (- ghost_2_49 1))))))
 (let (($x35472 (>= ghost_2_49 1)))
 (let (($x32326 (not c_49_8)))
 (let (($x32344 (or (and c_49_0 in_target_49) (and c_49_1 in_target_49) (and c_49_2 in_target_49) (and c_49_3 in_target_49) (and c_49_4 in_target_49) (and c_49_5 in_target_49) (and c_49_6 in_target_49) (and c_49_7 in_target_49) (and c_49_8 in_target_49))))
 (let (($x32327 (and $x32344 $x32326)))
 (let (($x35471 (and (=> (and $x32344 c_49_8) (= ghost_2_49 0)) (=> $x32327 (and $x35472 $x35465)))))
 (let (($x35302 (= ghost_2_48 1)))
 (let (($x35380 (and c_17_8 $x35302)))
 (let (($x35357 (and c_108_8 $x35302)))
 (let (($x35321 (and c_107_8 $x35302)))
 (let (($x35241 (not c_105_8)))
 (let (($x35259 (or (and c_105_0 in_target_105) (and c_105_1 in_target_105) (and c_105_2 in_target_105) (and c_105_3 in_target_105) (and c_105_4 in_target_105) (and c_105_5 in_target_105) (and c_105_6 in_target_105) (and c_105_7 in_target_105) (and c_105_8 in_target_105))))
 (let (($x35242 (and $x35259 $x35241)))
 (let (($x35318 (and c_105_8 $x35302)))
 (let (($x34901 (not c_99_8)))
 (let (($x34919 (or (and c_99_0 in_target_99) (and c_99_1 in_target_99) (and c_99_2 in_target_99) (and c_99_3 in_target_99) (and c_99_4 in_target_99) (and c_99_5 in_target_99) (and c_99_6 in_target_99) (and c_99_7 in_target_99) (and c_99_8 in_target_99))))
 (let (($x34902 (and $x34919 $x34901)))
 (let (($x35313 (and c_99_8 $x35302)))
 (let (($x35304 (or (or false (and c_16_8 $x35302)) (and $x30807 (= ghost_2_16 (- ghost_2_48 1))))))
 (let (($x35315 (or (or $x35304 $x35313) (and $x34902 (= ghost_2_99 (- ghost_2_48 1))))))
 (let (($x35325 (or (or $x35315 $x35318) (and $x35242 (= ghost_2_105 (- ghost_2_48 1))))))
 (let (($x35355 (or (or $x35325 $x35321) (and $x35342 (= ghost_2_107 (- ghost_2_48 1))))))
 (let (($x35386 (or (or $x35355 $x35357) (and $x35377 (= ghost_2_108 (- ghost_2_48 1))))))
 (let (($x35398 (or (or $x35386 $x35380) (and $x30842 (= ghost_2_17 (- ghost_2_48 1))))))
 (let (($x35401 (>= ghost_2_48 1)))
 (let (($x32291 (not c_48_8)))
 (let (($x32309 (or (and c_48_0 in_target_48) (and c_48_1 in_target_48) (and c_48_2 in_target_48) (and c_48_3 in_target_48) (and c_48_4 in_target_48) (and c_48_5 in_target_48) (and c_48_6 in_target_48) (and c_48_7 in_target_48) (and c_48_8 in_target_48))))
 (let (($x32292 (and $x32309 $x32291)))
 (let (($x35402 (and (=> (and $x32309 c_48_8) (= ghost_2_48 0)) (=> $x32292 (and $x35401 $x35398)))))
 (let (($x35176 (= ghost_2_47 1)))
 (let (($x35292 (and c_16_8 $x35176)))
 (let (($x35247 (and c_106_8 $x35176)))
 (let (($x35210 (and c_105_8 $x35176)))
 (let (($x35190 (and c_104_8 $x35176)))
 (let (($x34831 (not c_98_8)))
 (let (($x34849 (or (and c_98_0 in_target_98) (and c_98_1 in_target_98) (and c_98_2 in_target_98) (and c_98_3 in_target_98) (and c_98_4 in_target_98) (and c_98_5 in_target_98) (and c_98_6 in_target_98) (and c_98_7 in_target_98) (and c_98_8 in_target_98))))
 (let (($x34832 (and $x34849 $x34831)))
 (let (($x35182 (and c_98_8 $x35176)))
 (let (($x35180 (or (or false (and c_20_8 $x35176)) (and $x30967 (= ghost_2_20 (- ghost_2_47 1))))))
 (let (($x35187 (or (or $x35180 $x35182) (and $x34832 (= ghost_2_98 (- ghost_2_47 1))))))
 (let (($x35214 (or (or $x35187 $x35190) (and $x35207 (= ghost_2_104 (- ghost_2_47 1))))))
 (let (($x35251 (or (or $x35214 $x35210) (and $x35242 (= ghost_2_105 (- ghost_2_47 1))))))
 (let (($x35290 (or (or $x35251 $x35247) (and $x35277 (= ghost_2_106 (- ghost_2_47 1))))))
 (let (($x35298 (or (or $x35290 $x35292) (and $x30807 (= ghost_2_16 (- ghost_2_47 1))))))
 (let (($x35305 (>= ghost_2_47 1)))
 (let (($x32256 (not c_47_8)))
 (let (($x32274 (or (and c_47_0 in_target_47) (and c_47_1 in_target_47) (and c_47_2 in_target_47) (and c_47_3 in_target_47) (and c_47_4 in_target_47) (and c_47_5 in_target_47) (and c_47_6 in_target_47) (and c_47_7 in_target_47) (and c_47_8 in_target_47))))
 (let (($x32257 (and $x32274 $x32256)))
 (let (($x35303 (and (=> (and $x32274 c_47_8) (= ghost_2_47 0)) (=> $x32257 (and $x35305 $x35298)))))
 (let (($x35109 (= ghost_2_46 1)))
 (let (($x35131 (and c_103_8 $x35109)))
 (let (($x35124 (and c_24_8 $x35109)))
 (let (($x35126 (and c_102_8 $x35109)))
 (let (($x30751 (not c_15_8)))
 (let (($x30754 (and c_15_1 in_target_15)))
 (let (($x30753 (and c_15_0 in_target_15)))
 (let (($x30769 (or $x30753 $x30754 $x30756 $x30758 $x30760 $x30762 $x30764 $x30766 (and c_15_8 in_target_15))))
 (let (($x30752 (and $x30769 $x30751)))
 (let (($x35118 (and c_15_8 $x35109)))
 (let (($x34741 (not c_96_8)))
 (let (($x34759 (or (and c_96_0 in_target_96) (and c_96_1 in_target_96) (and c_96_2 in_target_96) (and c_96_3 in_target_96) (and c_96_4 in_target_96) (and c_96_5 in_target_96) (and c_96_6 in_target_96) (and c_96_7 in_target_96) (and c_96_8 in_target_96))))
 (let (($x34742 (and $x34759 $x34741)))
 (let (($x35112 (and c_96_8 $x35109)))
 (let (($x33901 (not c_80_8)))
 (let (($x33919 (or (and c_80_0 in_target_80) (and c_80_1 in_target_80) (and c_80_2 in_target_80) (and c_80_3 in_target_80) (and c_80_4 in_target_80) (and c_80_5 in_target_80) (and c_80_6 in_target_80) (and c_80_7 in_target_80) (and c_80_8 in_target_80))))
 (let (($x33902 (and $x33919 $x33901)))
 (let (($x35111 (or (or false (and c_80_8 $x35109)) (and $x33902 (= ghost_2_80 (- ghost_2_46 1))))))
 (let (($x35116 (or (or $x35111 $x35112) (and $x34742 (= ghost_2_96 (- ghost_2_46 1))))))
 (let (($x35115 (or (or $x35116 $x35118) (and $x30752 (= ghost_2_15 (- ghost_2_46 1))))))
 (let (($x35127 (or (or $x35115 $x35126) (and $x35082 (= ghost_2_102 (- ghost_2_46 1))))))
 (let (($x35125 (or (or $x35127 $x35124) (and $x31182 (= ghost_2_24 (- ghost_2_46 1))))))
 (let (($x35161 (or (or $x35125 $x35131) (and $x35152 (= ghost_2_103 (- ghost_2_46 1))))))
 (let (($x35170 (>= ghost_2_46 1)))
 (let (($x32201 (not c_46_8)))
 (let (($x32219 (or (and c_46_0 in_target_46) (and c_46_1 in_target_46) (and c_46_2 in_target_46) (and c_46_3 in_target_46) (and c_46_4 in_target_46) (and c_46_5 in_target_46) (and c_46_6 in_target_46) (and c_46_7 in_target_46) (and c_46_8 in_target_46))))
 (let (($x32202 (and $x32219 $x32201)))
 (let (($x35173 (and (=> (and $x32219 c_46_8) (= ghost_2_46 0)) (=> $x32202 (and $x35170 $x35161)))))
 (let (($x35033 (= ghost_2_45 1)))
 (let (($x35063 (and c_102_8 $x35033)))
 (let (($x35058 (and c_19_8 $x35033)))
 (let (($x35055 (and c_101_8 $x35033)))
 (let (($x30711 (not c_14_8)))
 (let (($x30714 (and c_14_1 in_target_14)))
 (let (($x30713 (and c_14_0 in_target_14)))
 (let (($x30729 (or $x30713 $x30714 $x30716 $x30718 $x30720 $x30722 $x30724 $x30726 (and c_14_8 in_target_14))))
 (let (($x30712 (and $x30729 $x30711)))
 (let (($x35046 (and c_14_8 $x35033)))
 (let (($x34671 (not c_95_8)))
 (let (($x34689 (or (and c_95_0 in_target_95) (and c_95_1 in_target_95) (and c_95_2 in_target_95) (and c_95_3 in_target_95) (and c_95_4 in_target_95) (and c_95_5 in_target_95) (and c_95_6 in_target_95) (and c_95_7 in_target_95) (and c_95_8 in_target_95))))
 (let (($x34672 (and $x34689 $x34671)))
 (let (($x35040 (and c_95_8 $x35033)))
 (let (($x35045 (or (or false (and c_15_8 $x35033)) (and $x30752 (= ghost_2_15 (- ghost_2_45 1))))))
 (let (($x35051 (or (or $x35045 $x35040) (and $x34672 (= ghost_2_95 (- ghost_2_45 1))))))
 (let (($x35053 (or (or $x35051 $x35046) (and $x30712 (= ghost_2_14 (- ghost_2_45 1))))))
 (let (($x35044 (or (or $x35053 $x35055) (and $x35012 (= ghost_2_101 (- ghost_2_45 1))))))
 (let (($x35064 (or (or $x35044 $x35058) (and $x30912 (= ghost_2_19 (- ghost_2_45 1))))))
 (let (($x35091 (or (or $x35064 $x35063) (and $x35082 (= ghost_2_102 (- ghost_2_45 1))))))
 (let (($x35100 (>= ghost_2_45 1)))
 (let (($x32131 (not c_45_8)))
 (let (($x32149 (or (and c_45_0 in_target_45) (and c_45_1 in_target_45) (and c_45_2 in_target_45) (and c_45_3 in_target_45) (and c_45_4 in_target_45) (and c_45_5 in_target_45) (and c_45_6 in_target_45) (and c_45_7 in_target_45) (and c_45_8 in_target_45))))
 (let (($x32132 (and $x32149 $x32131)))
 (let (($x35087 (and (=> (and $x32149 c_45_8) (= ghost_2_45 0)) (=> $x32132 (and $x35100 $x35091)))))
 (let (($x34936 (= ghost_2_44 1)))
 (let (($x34995 (and c_101_8 $x34936)))
 (let (($x34981 (and c_17_8 $x34936)))
 (let (($x34953 (and c_100_8 $x34936)))
 (let (($x34946 (and c_99_8 $x34936)))
 (let (($x34631 (not c_94_8)))
 (let (($x34649 (or (and c_94_0 in_target_94) (and c_94_1 in_target_94) (and c_94_2 in_target_94) (and c_94_3 in_target_94) (and c_94_4 in_target_94) (and c_94_5 in_target_94) (and c_94_6 in_target_94) (and c_94_7 in_target_94) (and c_94_8 in_target_94))))
 (let (($x34632 (and $x34649 $x34631)))
 (let (($x34940 (and c_94_8 $x34936)))
 (let (($x34944 (or (or false (and c_14_8 $x34936)) (and $x30712 (= ghost_2_14 (- ghost_2_44 1))))))
 (let (($x34947 (or (or $x34944 $x34940) (and $x34632 (= ghost_2_94 (- ghost_2_44 1))))))
 (let (($x34951 (or (or $x34947 $x34946) (and $x34902 (= ghost_2_99 (- ghost_2_44 1))))))
 (let (($x34985 (or (or $x34951 $x34953) (and $x34972 (= ghost_2_100 (- ghost_2_44 1))))))
 (let (($x34993 (or (or $x34985 $x34981) (and $x30842 (= ghost_2_17 (- ghost_2_44 1))))))
 (let (($x35025 (or (or $x34993 $x34995) (and $x35012 (= ghost_2_101 (- ghost_2_44 1))))))
 (let (($x35035 (>= ghost_2_44 1)))
 (let (($x32091 (not c_44_8)))
 (let (($x32109 (or (and c_44_0 in_target_44) (and c_44_1 in_target_44) (and c_44_2 in_target_44) (and c_44_3 in_target_44) (and c_44_4 in_target_44) (and c_44_5 in_target_44) (and c_44_6 in_target_44) (and c_44_7 in_target_44) (and c_44_8 in_target_44))))
 (let (($x32092 (and $x32109 $x32091)))
 (let (($x35023 (and (=> (and $x32109 c_44_8) (= ghost_2_44 0)) (=> $x32092 (and $x35035 $x35025)))))
 (let (($x34864 (= ghost_2_43 1)))
 (let (($x34920 (and c_14_8 $x34864)))
 (let (($x34907 (and c_16_8 $x34864)))
 (let (($x34885 (and c_99_8 $x34864)))
 (let (($x34881 (and c_98_8 $x34864)))
 (let (($x34561 (not c_93_8)))
 (let (($x34579 (or (and c_93_0 in_target_93) (and c_93_1 in_target_93) (and c_93_2 in_target_93) (and c_93_3 in_target_93) (and c_93_4 in_target_93) (and c_93_5 in_target_93) (and c_93_6 in_target_93) (and c_93_7 in_target_93) (and c_93_8 in_target_93))))
 (let (($x34562 (and $x34579 $x34561)))
 (let (($x34870 (and c_93_8 $x34864)))
 (let (($x30676 (not c_13_8)))
 (let (($x30679 (and c_13_1 in_target_13)))
 (let (($x30678 (and c_13_0 in_target_13)))
 (let (($x30694 (or $x30678 $x30679 $x30681 $x30683 $x30685 $x30687 $x30689 $x30691 (and c_13_8 in_target_13))))
 (let (($x30677 (and $x30694 $x30676)))
 (let (($x34872 (or (or false (and c_13_8 $x34864)) (and $x30677 (= ghost_2_13 (- ghost_2_43 1))))))
 (let (($x34874 (or (or $x34872 $x34870) (and $x34562 (= ghost_2_93 (- ghost_2_43 1))))))
 (let (($x34882 (or (or $x34874 $x34881) (and $x34832 (= ghost_2_98 (- ghost_2_43 1))))))
 (let (($x34915 (or (or $x34882 $x34885) (and $x34902 (= ghost_2_99 (- ghost_2_43 1))))))
 (let (($x34923 (or (or $x34915 $x34907) (and $x30807 (= ghost_2_16 (- ghost_2_43 1))))))
 (let (($x34928 (or (or $x34923 $x34920) (and $x30712 (= ghost_2_14 (- ghost_2_43 1))))))
 (let (($x34929 (>= ghost_2_43 1)))
 (let (($x32021 (not c_43_8)))
 (let (($x32039 (or (and c_43_0 in_target_43) (and c_43_1 in_target_43) (and c_43_2 in_target_43) (and c_43_3 in_target_43) (and c_43_4 in_target_43) (and c_43_5 in_target_43) (and c_43_6 in_target_43) (and c_43_7 in_target_43) (and c_43_8 in_target_43))))
 (let (($x32022 (and $x32039 $x32021)))
 (let (($x34933 (and (=> (and $x32039 c_43_8) (= ghost_2_43 0)) (=> $x32022 (and $x34929 $x34928)))))
 (let (($x34753 (= ghost_2_42 1)))
 (let (($x34851 (and c_13_8 $x34753)))
 (let (($x34847 (and c_20_8 $x34753)))
 (let (($x34804 (and c_98_8 $x34753)))
 (let (($x34771 (and c_97_8 $x34753)))
 (let (($x34526 (not c_92_8)))
 (let (($x34544 (or (and c_92_0 in_target_92) (and c_92_1 in_target_92) (and c_92_2 in_target_92) (and c_92_3 in_target_92) (and c_92_4 in_target_92) (and c_92_5 in_target_92) (and c_92_6 in_target_92) (and c_92_7 in_target_92) (and c_92_8 in_target_92))))
 (let (($x34527 (and $x34544 $x34526)))
 (let (($x34774 (and c_92_8 $x34753)))
 (let (($x33816 (not c_79_8)))
 (let (($x33834 (or (and c_79_0 in_target_79) (and c_79_1 in_target_79) (and c_79_2 in_target_79) (and c_79_3 in_target_79) (and c_79_4 in_target_79) (and c_79_5 in_target_79) (and c_79_6 in_target_79) (and c_79_7 in_target_79) (and c_79_8 in_target_79))))
 (let (($x33817 (and $x33834 $x33816)))
 (let (($x34764 (or (or false (and c_79_8 $x34753)) (and $x33817 (= ghost_2_79 (- ghost_2_42 1))))))
 (let (($x34780 (or (or $x34764 $x34774) (and $x34527 (= ghost_2_92 (- ghost_2_42 1))))))
 (let (($x34808 (or (or $x34780 $x34771) (and $x34797 (= ghost_2_97 (- ghost_2_42 1))))))
 (let (($x34841 (or (or $x34808 $x34804) (and $x34832 (= ghost_2_98 (- ghost_2_42 1))))))
 (let (($x34852 (or (or $x34841 $x34847) (and $x30967 (= ghost_2_20 (- ghost_2_42 1))))))
 (let (($x34859 (or (or $x34852 $x34851) (and $x30677 (= ghost_2_13 (- ghost_2_42 1))))))
 (let (($x34861 (>= ghost_2_42 1)))
 (let (($x31986 (not c_42_8)))
 (let (($x32004 (or (and c_42_0 in_target_42) (and c_42_1 in_target_42) (and c_42_2 in_target_42) (and c_42_3 in_target_42) (and c_42_4 in_target_42) (and c_42_5 in_target_42) (and c_42_6 in_target_42) (and c_42_7 in_target_42) (and c_42_8 in_target_42))))
 (let (($x31987 (and $x32004 $x31986)))
 (let (($x34863 (and (=> (and $x32004 c_42_8) (= ghost_2_42 0)) (=> $x31987 (and $x34861 $x34859)))))
 (let (($x34695 (= ghost_2_41 1)))
 (let (($x34726 (and c_96_8 $x34695)))
 (let (($x34716 (and c_15_8 $x34695)))
 (let (($x34711 (and c_95_8 $x34695)))
 (let (($x30641 (not c_12_8)))
 (let (($x30644 (and c_12_1 in_target_12)))
 (let (($x30643 (and c_12_0 in_target_12)))
 (let (($x30659 (or $x30643 $x30644 $x30646 $x30648 $x30650 $x30652 $x30654 $x30656 (and c_12_8 in_target_12))))
 (let (($x30642 (and $x30659 $x30641)))
 (let (($x34705 (and c_12_8 $x34695)))
 (let (($x34471 (not c_91_8)))
 (let (($x34489 (or (and c_91_0 in_target_91) (and c_91_1 in_target_91) (and c_91_2 in_target_91) (and c_91_3 in_target_91) (and c_91_4 in_target_91) (and c_91_5 in_target_91) (and c_91_6 in_target_91) (and c_91_7 in_target_91) (and c_91_8 in_target_91))))
 (let (($x34472 (and $x34489 $x34471)))
 (let (($x34700 (and c_91_8 $x34695)))
 (let (($x33761 (not c_78_8)))
 (let (($x33779 (or (and c_78_0 in_target_78) (and c_78_1 in_target_78) (and c_78_2 in_target_78) (and c_78_3 in_target_78) (and c_78_4 in_target_78) (and c_78_5 in_target_78) (and c_78_6 in_target_78) (and c_78_7 in_target_78) (and c_78_8 in_target_78))))
 (let (($x33762 (and $x33779 $x33761)))
 (let (($x34703 (or (or false (and c_78_8 $x34695)) (and $x33762 (= ghost_2_78 (- ghost_2_41 1))))))
 (let (($x34706 (or (or $x34703 $x34700) (and $x34472 (= ghost_2_91 (- ghost_2_41 1))))))
 (let (($x34715 (or (or $x34706 $x34705) (and $x30642 (= ghost_2_12 (- ghost_2_41 1))))))
 (let (($x34721 (or (or $x34715 $x34711) (and $x34672 (= ghost_2_95 (- ghost_2_41 1))))))
 (let (($x34713 (or (or $x34721 $x34716) (and $x30752 (= ghost_2_15 (- ghost_2_41 1))))))
 (let (($x34757 (or (or $x34713 $x34726) (and $x34742 (= ghost_2_96 (- ghost_2_41 1))))))
 (let (($x34760 (>= ghost_2_41 1)))
 (let (($x31931 (not c_41_8)))
 (let (($x31949 (or (and c_41_0 in_target_41) (and c_41_1 in_target_41) (and c_41_2 in_target_41) (and c_41_3 in_target_41) (and c_41_4 in_target_41) (and c_41_5 in_target_41) (and c_41_6 in_target_41) (and c_41_7 in_target_41) (and c_41_8 in_target_41))))
 (let (($x31932 (and $x31949 $x31931)))
 (let (($x34762 (and (=> (and $x31949 c_41_8) (= ghost_2_41 0)) (=> $x31932 (and $x34760 $x34757)))))
 (let (($x34588 (= ghost_2_40 1)))
 (let (($x34655 (and c_95_8 $x34588)))
 (let (($x34645 (and c_14_8 $x34588)))
 (let (($x34616 (and c_94_8 $x34588)))
 (let (($x34605 (and c_93_8 $x34588)))
 (let (($x34431 (not c_90_8)))
 (let (($x34449 (or (and c_90_0 in_target_90) (and c_90_1 in_target_90) (and c_90_2 in_target_90) (and c_90_3 in_target_90) (and c_90_4 in_target_90) (and c_90_5 in_target_90) (and c_90_6 in_target_90) (and c_90_7 in_target_90) (and c_90_8 in_target_90))))
 (let (($x34432 (and $x34449 $x34431)))
 (let (($x34601 (and c_90_8 $x34588)))
 (let (($x34600 (or (or false (and c_12_8 $x34588)) (and $x30642 (= ghost_2_12 (- ghost_2_40 1))))))
 (let (($x34611 (or (or $x34600 $x34601) (and $x34432 (= ghost_2_90 (- ghost_2_40 1))))))
 (let (($x34606 (or (or $x34611 $x34605) (and $x34562 (= ghost_2_93 (- ghost_2_40 1))))))
 (let (($x34641 (or (or $x34606 $x34616) (and $x34632 (= ghost_2_94 (- ghost_2_40 1))))))
 (let (($x34653 (or (or $x34641 $x34645) (and $x30712 (= ghost_2_14 (- ghost_2_40 1))))))
 (let (($x34685 (or (or $x34653 $x34655) (and $x34672 (= ghost_2_95 (- ghost_2_40 1))))))
 (let (($x34690 (>= ghost_2_40 1)))
 (let (($x31891 (not c_40_8)))
 (let (($x31909 (or (and c_40_0 in_target_40) (and c_40_1 in_target_40) (and c_40_2 in_target_40) (and c_40_3 in_target_40) (and c_40_4 in_target_40) (and c_40_5 in_target_40) (and c_40_6 in_target_40) (and c_40_7 in_target_40) (and c_40_8 in_target_40))))
 (let (($x31892 (and $x31909 $x31891)))
 (let (($x34692 (and (=> (and $x31909 c_40_8) (= ghost_2_40 0)) (=> $x31892 (and $x34690 $x34685)))))
 (let (($x34495 (= ghost_2_39 1)))
 (let (($x34583 (and c_12_8 $x34495)))
 (let (($x34567 (and c_13_8 $x34495)))
 (let (($x34532 (and c_93_8 $x34495)))
 (let (($x34507 (and c_92_8 $x34495)))
 (let (($x34396 (not c_89_8)))
 (let (($x34414 (or (and c_89_0 in_target_89) (and c_89_1 in_target_89) (and c_89_2 in_target_89) (and c_89_3 in_target_89) (and c_89_4 in_target_89) (and c_89_5 in_target_89) (and c_89_6 in_target_89) (and c_89_7 in_target_89) (and c_89_8 in_target_89))))
 (let (($x34397 (and $x34414 $x34396)))
 (let (($x34505 (and c_89_8 $x34495)))
 (let (($x33716 (not c_77_8)))
 (let (($x33734 (or (and c_77_0 in_target_77) (and c_77_1 in_target_77) (and c_77_2 in_target_77) (and c_77_3 in_target_77) (and c_77_4 in_target_77) (and c_77_5 in_target_77) (and c_77_6 in_target_77) (and c_77_7 in_target_77) (and c_77_8 in_target_77))))
 (let (($x33717 (and $x33734 $x33716)))
 (let (($x34502 (or (or false (and c_77_8 $x34495)) (and $x33717 (= ghost_2_77 (- ghost_2_39 1))))))
 (let (($x34503 (or (or $x34502 $x34505) (and $x34397 (= ghost_2_89 (- ghost_2_39 1))))))
 (let (($x34542 (or (or $x34503 $x34507) (and $x34527 (= ghost_2_92 (- ghost_2_39 1))))))
 (let (($x34569 (or (or $x34542 $x34532) (and $x34562 (= ghost_2_93 (- ghost_2_39 1))))))
 (let (($x34584 (or (or $x34569 $x34567) (and $x30677 (= ghost_2_13 (- ghost_2_39 1))))))
 (let (($x34590 (or (or $x34584 $x34583) (and $x30642 (= ghost_2_12 (- ghost_2_39 1))))))
 (let (($x34595 (>= ghost_2_39 1)))
 (let (($x31856 (not c_39_8)))
 (let (($x31874 (or (and c_39_0 in_target_39) (and c_39_1 in_target_39) (and c_39_2 in_target_39) (and c_39_3 in_target_39) (and c_39_4 in_target_39) (and c_39_5 in_target_39) (and c_39_6 in_target_39) (and c_39_7 in_target_39) (and c_39_8 in_target_39))))
 (let (($x31857 (and $x31874 $x31856)))
 (let (($x34594 (and (=> (and $x31874 c_39_8) (= ghost_2_39 0)) (=> $x31857 (and $x34595 $x34590)))))
 (let (($x34336 (= ghost_2_38 1)))
 (let (($x34451 (and c_91_8 $x34336)))
 (let (($x34443 (and c_12_8 $x34336)))
 (let (($x34410 (and c_90_8 $x34336)))
 (let (($x34377 (and c_89_8 $x34336)))
 (let (($x34361 (not c_88_8)))
 (let (($x34379 (or (and c_88_0 in_target_88) (and c_88_1 in_target_88) (and c_88_2 in_target_88) (and c_88_3 in_target_88) (and c_88_4 in_target_88) (and c_88_5 in_target_88) (and c_88_6 in_target_88) (and c_88_7 in_target_88) (and c_88_8 in_target_88))))
 (let (($x34345 (and c_88_8 $x34336)))
 (let (($x33681 (not c_76_8)))
 (let (($x33699 (or (and c_76_0 in_target_76) (and c_76_1 in_target_76) (and c_76_2 in_target_76) (and c_76_3 in_target_76) (and c_76_4 in_target_76) (and c_76_5 in_target_76) (and c_76_6 in_target_76) (and c_76_7 in_target_76) (and c_76_8 in_target_76))))
 (let (($x33682 (and $x33699 $x33681)))
 (let (($x34342 (or (or false (and c_76_8 $x34336)) (and $x33682 (= ghost_2_76 (- ghost_2_38 1))))))
 (let (($x34375 (or (or $x34342 $x34345) (and (and $x34379 $x34361) (= ghost_2_88 (- ghost_2_38 1))))))
 (let (($x34412 (or (or $x34375 $x34377) (and $x34397 (= ghost_2_89 (- ghost_2_38 1))))))
 (let (($x34445 (or (or $x34412 $x34410) (and $x34432 (= ghost_2_90 (- ghost_2_38 1))))))
 (let (($x34455 (or (or $x34445 $x34443) (and $x30642 (= ghost_2_12 (- ghost_2_38 1))))))
 (let (($x34481 (or (or $x34455 $x34451) (and $x34472 (= ghost_2_91 (- ghost_2_38 1))))))
 (let (($x34493 (>= ghost_2_38 1)))
 (let (($x31821 (not c_38_8)))
 (let (($x31839 (or (and c_38_0 in_target_38) (and c_38_1 in_target_38) (and c_38_2 in_target_38) (and c_38_3 in_target_38) (and c_38_4 in_target_38) (and c_38_5 in_target_38) (and c_38_6 in_target_38) (and c_38_7 in_target_38) (and c_38_8 in_target_38))))
 (let (($x31822 (and $x31839 $x31821)))
 (let (($x34494 (and (=> (and $x31839 c_38_8) (= ghost_2_38 0)) (=> $x31822 (and $x34493 $x34481)))))
 (let (($x34260 (= ghost_2_37 1)))
 (let (($x34289 (and c_87_8 $x34260)))
 (let (($x34286 (and c_86_8 $x34260)))
 (let (($x34285 (and c_24_8 $x34260)))
 (let (($x30591 (not c_11_8)))
 (let (($x30594 (and c_11_1 in_target_11)))
 (let (($x30593 (and c_11_0 in_target_11)))
 (let (($x30609 (or $x30593 $x30594 $x30596 $x30598 $x30600 $x30602 $x30604 $x30606 (and c_11_8 in_target_11))))
 (let (($x30592 (and $x30609 $x30591)))
 (let (($x34277 (and c_11_8 $x34260)))
 (let (($x34263 (and c_80_8 $x34260)))
 (let (($x33631 (not c_75_8)))
 (let (($x33649 (or (and c_75_0 in_target_75) (and c_75_1 in_target_75) (and c_75_2 in_target_75) (and c_75_3 in_target_75) (and c_75_4 in_target_75) (and c_75_5 in_target_75) (and c_75_6 in_target_75) (and c_75_7 in_target_75) (and c_75_8 in_target_75))))
 (let (($x33632 (and $x33649 $x33631)))
 (let (($x34272 (or (or false (and c_75_8 $x34260)) (and $x33632 (= ghost_2_75 (- ghost_2_37 1))))))
 (let (($x34276 (or (or $x34272 $x34263) (and $x33902 (= ghost_2_80 (- ghost_2_37 1))))))
 (let (($x34281 (or (or $x34276 $x34277) (and $x30592 (= ghost_2_11 (- ghost_2_37 1))))))
 (let (($x34279 (or (or $x34281 $x34285) (and $x31182 (= ghost_2_24 (- ghost_2_37 1))))))
 (let (($x34294 (or (or $x34279 $x34286) (and $x34242 (= ghost_2_86 (- ghost_2_37 1))))))
 (let (($x34327 (or (or $x34294 $x34289) (and $x34312 (= ghost_2_87 (- ghost_2_37 1))))))
 (let (($x34331 (>= ghost_2_37 1)))
 (let (($x31771 (not c_37_8)))
 (let (($x31789 (or (and c_37_0 in_target_37) (and c_37_1 in_target_37) (and c_37_2 in_target_37) (and c_37_3 in_target_37) (and c_37_4 in_target_37) (and c_37_5 in_target_37) (and c_37_6 in_target_37) (and c_37_7 in_target_37) (and c_37_8 in_target_37))))
 (let (($x31772 (and $x31789 $x31771)))
 (let (($x34334 (and (=> (and $x31789 c_37_8) (= ghost_2_37 0)) (=> $x31772 (and $x34331 $x34327)))))
 (let (($x34199 (= ghost_2_36 1)))
 (let (($x34222 (and c_86_8 $x34199)))
 (let (($x34219 (and c_85_8 $x34199)))
 (let (($x34211 (and c_23_8 $x34199)))
 (let (($x30556 (not c_10_8)))
 (let (($x30559 (and c_10_1 in_target_10)))
 (let (($x30558 (and c_10_0 in_target_10)))
 (let (($x30574 (or $x30558 $x30559 $x30561 $x30563 $x30565 $x30567 $x30569 $x30571 (and c_10_8 in_target_10))))
 (let (($x30557 (and $x30574 $x30556)))
 (let (($x34210 (and c_10_8 $x34199)))
 (let (($x34205 (and c_11_8 $x34199)))
 (let (($x33561 (not c_74_8)))
 (let (($x33579 (or (and c_74_0 in_target_74) (and c_74_1 in_target_74) (and c_74_2 in_target_74) (and c_74_3 in_target_74) (and c_74_4 in_target_74) (and c_74_5 in_target_74) (and c_74_6 in_target_74) (and c_74_7 in_target_74) (and c_74_8 in_target_74))))
 (let (($x33562 (and $x33579 $x33561)))
 (let (($x34203 (or (or false (and c_74_8 $x34199)) (and $x33562 (= ghost_2_74 (- ghost_2_36 1))))))
 (let (($x34206 (or (or $x34203 $x34205) (and $x30592 (= ghost_2_11 (- ghost_2_36 1))))))
 (let (($x34214 (or (or $x34206 $x34210) (and $x30557 (= ghost_2_10 (- ghost_2_36 1))))))
 (let (($x34212 (or (or $x34214 $x34211) (and $x31112 (= ghost_2_23 (- ghost_2_36 1))))))
 (let (($x34225 (or (or $x34212 $x34219) (and $x34172 (= ghost_2_85 (- ghost_2_36 1))))))
 (let (($x34257 (or (or $x34225 $x34222) (and $x34242 (= ghost_2_86 (- ghost_2_36 1))))))
 (let (($x34262 (>= ghost_2_36 1)))
 (let (($x31701 (not c_36_8)))
 (let (($x31719 (or (and c_36_0 in_target_36) (and c_36_1 in_target_36) (and c_36_2 in_target_36) (and c_36_3 in_target_36) (and c_36_4 in_target_36) (and c_36_5 in_target_36) (and c_36_6 in_target_36) (and c_36_7 in_target_36) (and c_36_8 in_target_36))))
 (let (($x31702 (and $x31719 $x31701)))
 (let (($x34265 (and (=> (and $x31719 c_36_8) (= ghost_2_36 0)) (=> $x31702 (and $x34262 $x34257)))))
 (let (($x34098 (= ghost_2_35 1)))
 (let (($x34140 (and c_85_8 $x34098)))
 (let (($x34107 (and c_84_8 $x34098)))
 (let (($x34112 (and c_22_8 $x34098)))
 (let (($x34105 (and c_83_8 $x34098)))
 (let (($x34102 (and c_10_8 $x34098)))
 (let (($x33526 (not c_73_8)))
 (let (($x33544 (or (and c_73_0 in_target_73) (and c_73_1 in_target_73) (and c_73_2 in_target_73) (and c_73_3 in_target_73) (and c_73_4 in_target_73) (and c_73_5 in_target_73) (and c_73_6 in_target_73) (and c_73_7 in_target_73) (and c_73_8 in_target_73))))
 (let (($x33527 (and $x33544 $x33526)))
 (let (($x34101 (or (or false (and c_73_8 $x34098)) (and $x33527 (= ghost_2_73 (- ghost_2_35 1))))))
 (let (($x34109 (or (or $x34101 $x34102) (and $x30557 (= ghost_2_10 (- ghost_2_35 1))))))
 (let (($x34111 (or (or $x34109 $x34105) (and $x34067 (= ghost_2_83 (- ghost_2_35 1))))))
 (let (($x34119 (or (or $x34111 $x34112) (and $x31077 (= ghost_2_22 (- ghost_2_35 1))))))
 (let (($x34152 (or (or $x34119 $x34107) (and $x34137 (= ghost_2_84 (- ghost_2_35 1))))))
 (let (($x34181 (or (or $x34152 $x34140) (and $x34172 (= ghost_2_85 (- ghost_2_35 1))))))
 (let (($x34183 (>= ghost_2_35 1)))
 (let (($x31666 (not c_35_8)))
 (let (($x31684 (or (and c_35_0 in_target_35) (and c_35_1 in_target_35) (and c_35_2 in_target_35) (and c_35_3 in_target_35) (and c_35_4 in_target_35) (and c_35_5 in_target_35) (and c_35_6 in_target_35) (and c_35_7 in_target_35) (and c_35_8 in_target_35))))
 (let (($x31667 (and $x31684 $x31666)))
 (let (($x34192 (and (=> (and $x31684 c_35_8) (= ghost_2_35 0)) (=> $x31667 (and $x34183 $x34181)))))
 (let (($x34027 (= ghost_2_34 1)))
 (let (($x34078 (and c_10_8 $x34027)))
 (let (($x34051 (and c_83_8 $x34027)))
 (let (($x34037 (and c_21_8 $x34027)))
 (let (($x34038 (and c_82_8 $x34027)))
 (let (($x30516 (not c_9_8)))
 (let (($x30519 (and c_9_1 in_target_9)))
 (let (($x30518 (and c_9_0 in_target_9)))
 (let (($x30534 (or $x30518 $x30519 $x30521 $x30523 $x30525 $x30527 $x30529 $x30531 (and c_9_8 in_target_9))))
 (let (($x30517 (and $x30534 $x30516)))
 (let (($x34035 (and c_9_8 $x34027)))
 (let (($x33456 (not c_72_8)))
 (let (($x33474 (or (and c_72_0 in_target_72) (and c_72_1 in_target_72) (and c_72_2 in_target_72) (and c_72_3 in_target_72) (and c_72_4 in_target_72) (and c_72_5 in_target_72) (and c_72_6 in_target_72) (and c_72_7 in_target_72) (and c_72_8 in_target_72))))
 (let (($x33457 (and $x33474 $x33456)))
 (let (($x34032 (or (or false (and c_72_8 $x34027)) (and $x33457 (= ghost_2_72 (- ghost_2_34 1))))))
 (let (($x34041 (or (or $x34032 $x34035) (and $x30517 (= ghost_2_9 (- ghost_2_34 1))))))
 (let (($x34043 (or (or $x34041 $x34038) (and $x33997 (= ghost_2_82 (- ghost_2_34 1))))))
 (let (($x34046 (or (or $x34043 $x34037) (and $x31007 (= ghost_2_21 (- ghost_2_34 1))))))
 (let (($x34080 (or (or $x34046 $x34051) (and $x34067 (= ghost_2_83 (- ghost_2_34 1))))))
 (let (($x34089 (or (or $x34080 $x34078) (and $x30557 (= ghost_2_10 (- ghost_2_34 1))))))
 (let (($x34092 (>= ghost_2_34 1)))
 (let (($x31596 (not c_34_8)))
 (let (($x31614 (or (and c_34_0 in_target_34) (and c_34_1 in_target_34) (and c_34_2 in_target_34) (and c_34_3 in_target_34) (and c_34_4 in_target_34) (and c_34_5 in_target_34) (and c_34_6 in_target_34) (and c_34_7 in_target_34) (and c_34_8 in_target_34))))
 (let (($x31597 (and $x31614 $x31596)))
 (let (($x34093 (and (=> (and $x31614 c_34_8) (= ghost_2_34 0)) (=> $x31597 (and $x34092 $x34089)))))
 (let (($x33927 (= ghost_2_33 1)))
 (let (($x34000 (and c_9_8 $x33927)))
 (let (($x33976 (and c_82_8 $x33927)))
 (let (($x33964 (and c_20_8 $x33927)))
 (let (($x33935 (and c_81_8 $x33927)))
 (let (($x33933 (and c_79_8 $x33927)))
 (let (($x33416 (not c_71_8)))
 (let (($x33434 (or (and c_71_0 in_target_71) (and c_71_1 in_target_71) (and c_71_2 in_target_71) (and c_71_3 in_target_71) (and c_71_4 in_target_71) (and c_71_5 in_target_71) (and c_71_6 in_target_71) (and c_71_7 in_target_71) (and c_71_8 in_target_71))))
 (let (($x33417 (and $x33434 $x33416)))
 (let (($x33934 (or (or false (and c_71_8 $x33927)) (and $x33417 (= ghost_2_71 (- ghost_2_33 1))))))
 (let (($x33936 (or (or $x33934 $x33933) (and $x33817 (= ghost_2_79 (- ghost_2_33 1))))))
 (let (($x33970 (or (or $x33936 $x33935) (and $x33957 (= ghost_2_81 (- ghost_2_33 1))))))
 (let (($x33977 (or (or $x33970 $x33964) (and $x30967 (= ghost_2_20 (- ghost_2_33 1))))))
 (let (($x34008 (or (or $x33977 $x33976) (and $x33997 (= ghost_2_82 (- ghost_2_33 1))))))
 (let (($x34022 (>= ghost_2_33 1)))
 (let (($x34023 (and $x34022 (or (or $x34008 $x34000) (and $x30517 (= ghost_2_9 (- ghost_2_33 1)))))))
 (let (($x31556 (not c_33_8)))
 (let (($x31574 (or (and c_33_0 in_target_33) (and c_33_1 in_target_33) (and c_33_2 in_target_33) (and c_33_3 in_target_33) (and c_33_4 in_target_33) (and c_33_5 in_target_33) (and c_33_6 in_target_33) (and c_33_7 in_target_33) (and c_33_8 in_target_33))))
 (let (($x31557 (and $x31574 $x31556)))
 (let (($x33854 (= ghost_2_32 1)))
 (let (($x33885 (and c_80_8 $x33854)))
 (let (($x33881 (and c_11_8 $x33854)))
 (let (($x33868 (and c_15_8 $x33854)))
 (let (($x30481 (not c_8_8)))
 (let (($x30484 (and c_8_1 in_target_8)))
 (let (($x30483 (and c_8_0 in_target_8)))
 (let (($x30499 (or $x30483 $x30484 $x30486 $x30488 $x30490 $x30492 $x30494 $x30496 (and c_8_8 in_target_8))))
 (let (($x30482 (and $x30499 $x30481)))
 (let (($x33869 (and c_8_8 $x33854)))
 (let (($x33860 (and c_78_8 $x33854)))
 (let (($x33361 (not c_70_8)))
 (let (($x33379 (or (and c_70_0 in_target_70) (and c_70_1 in_target_70) (and c_70_2 in_target_70) (and c_70_3 in_target_70) (and c_70_4 in_target_70) (and c_70_5 in_target_70) (and c_70_6 in_target_70) (and c_70_7 in_target_70) (and c_70_8 in_target_70))))
 (let (($x33362 (and $x33379 $x33361)))
 (let (($x33864 (or (or false (and c_70_8 $x33854)) (and $x33362 (= ghost_2_70 (- ghost_2_32 1))))))
 (let (($x33870 (or (or $x33864 $x33860) (and $x33762 (= ghost_2_78 (- ghost_2_32 1))))))
 (let (($x33872 (or (or $x33870 $x33869) (and $x30482 (= ghost_2_8 (- ghost_2_32 1))))))
 (let (($x33874 (or (or $x33872 $x33868) (and $x30752 (= ghost_2_15 (- ghost_2_32 1))))))
 (let (($x33880 (or (or $x33874 $x33881) (and $x30592 (= ghost_2_11 (- ghost_2_32 1))))))
 (let (($x33911 (or (or $x33880 $x33885) (and $x33902 (= ghost_2_80 (- ghost_2_32 1))))))
 (let (($x33922 (>= ghost_2_32 1)))
 (let (($x31501 (not c_32_8)))
 (let (($x31519 (or (and c_32_0 in_target_32) (and c_32_1 in_target_32) (and c_32_2 in_target_32) (and c_32_3 in_target_32) (and c_32_4 in_target_32) (and c_32_5 in_target_32) (and c_32_6 in_target_32) (and c_32_7 in_target_32) (and c_32_8 in_target_32))))
 (let (($x31502 (and $x31519 $x31501)))
 (let (($x33921 (and (=> (and $x31519 c_32_8) (= ghost_2_32 0)) (=> $x31502 (and $x33922 $x33911)))))
 (let (($x33787 (= ghost_2_31 1)))
 (let (($x33843 (and c_8_8 $x33787)))
 (let (($x33838 (and c_9_8 $x33787)))
 (let (($x33826 (and c_13_8 $x33787)))
 (let (($x33798 (and c_79_8 $x33787)))
 (let (($x33788 (and c_77_8 $x33787)))
 (let (($x33316 (not c_69_8)))
 (let (($x33334 (or (and c_69_0 in_target_69) (and c_69_1 in_target_69) (and c_69_2 in_target_69) (and c_69_3 in_target_69) (and c_69_4 in_target_69) (and c_69_5 in_target_69) (and c_69_6 in_target_69) (and c_69_7 in_target_69) (and c_69_8 in_target_69))))
 (let (($x33317 (and $x33334 $x33316)))
 (let (($x33793 (or (or false (and c_69_8 $x33787)) (and $x33317 (= ghost_2_69 (- ghost_2_31 1))))))
 (let (($x33795 (or (or $x33793 $x33788) (and $x33717 (= ghost_2_77 (- ghost_2_31 1))))))
 (let (($x33830 (or (or $x33795 $x33798) (and $x33817 (= ghost_2_79 (- ghost_2_31 1))))))
 (let (($x33839 (or (or $x33830 $x33826) (and $x30677 (= ghost_2_13 (- ghost_2_31 1))))))
 (let (($x33846 (or (or $x33839 $x33838) (and $x30517 (= ghost_2_9 (- ghost_2_31 1))))))
 (let (($x33852 (>= ghost_2_31 1)))
 (let (($x33848 (and $x33852 (or (or $x33846 $x33843) (and $x30482 (= ghost_2_8 (- ghost_2_31 1)))))))
 (let (($x31456 (not c_31_8)))
 (let (($x31474 (or (and c_31_0 in_target_31) (and c_31_1 in_target_31) (and c_31_2 in_target_31) (and c_31_3 in_target_31) (and c_31_4 in_target_31) (and c_31_5 in_target_31) (and c_31_6 in_target_31) (and c_31_7 in_target_31) (and c_31_8 in_target_31))))
 (let (($x31457 (and $x31474 $x31456)))
 (let (($x33658 (= ghost_2_30 1)))
 (let (($x33738 (and c_78_8 $x33658)))
 (let (($x33736 (and c_8_8 $x33658)))
 (let (($x33722 (and c_12_8 $x33658)))
 (let (($x33693 (and c_77_8 $x33658)))
 (let (($x33665 (and c_76_8 $x33658)))
 (let (($x33281 (not c_68_8)))
 (let (($x33299 (or (and c_68_0 in_target_68) (and c_68_1 in_target_68) (and c_68_2 in_target_68) (and c_68_3 in_target_68) (and c_68_4 in_target_68) (and c_68_5 in_target_68) (and c_68_6 in_target_68) (and c_68_7 in_target_68) (and c_68_8 in_target_68))))
 (let (($x33282 (and $x33299 $x33281)))
 (let (($x33663 (or (or false (and c_68_8 $x33658)) (and $x33282 (= ghost_2_68 (- ghost_2_30 1))))))
 (let (($x33697 (or (or $x33663 $x33665) (and $x33682 (= ghost_2_76 (- ghost_2_30 1))))))
 (let (($x33732 (or (or $x33697 $x33693) (and $x33717 (= ghost_2_77 (- ghost_2_30 1))))))
 (let (($x33740 (or (or $x33732 $x33722) (and $x30642 (= ghost_2_12 (- ghost_2_30 1))))))
 (let (($x33742 (or (or $x33740 $x33736) (and $x30482 (= ghost_2_8 (- ghost_2_30 1))))))
 (let (($x33767 (or (or $x33742 $x33738) (and $x33762 (= ghost_2_78 (- ghost_2_30 1))))))
 (let (($x33780 (>= ghost_2_30 1)))
 (let (($x31421 (not c_30_8)))
 (let (($x31439 (or (and c_30_0 in_target_30) (and c_30_1 in_target_30) (and c_30_2 in_target_30) (and c_30_3 in_target_30) (and c_30_4 in_target_30) (and c_30_5 in_target_30) (and c_30_6 in_target_30) (and c_30_7 in_target_30) (and c_30_8 in_target_30))))
 (let (($x31422 (and $x31439 $x31421)))
 (let (($x33777 (and (=> (and $x31439 c_30_8) (= ghost_2_30 0)) (=> $x31422 (and $x33780 $x33767)))))
 (let (($x33588 (= ghost_2_29 1)))
 (let (($x33614 (and c_75_8 $x33588)))
 (let (($x33610 (and c_74_8 $x33588)))
 (let (($x33604 (and c_11_8 $x33588)))
 (let (($x30445 (not c_7_8)))
 (let (($x30448 (and c_7_1 in_target_7)))
 (let (($x30447 (and c_7_0 in_target_7)))
 (let (($x30463 (or $x30447 $x30448 $x30450 $x30452 $x30454 $x30456 $x30458 $x30460 (and c_7_8 in_target_7))))
 (let (($x30446 (and $x30463 $x30445)))
 (let (($x33600 (and c_7_8 $x33588)))
 (let (($x33591 (and c_70_8 $x33588)))
 (let (($x33231 (not c_67_8)))
 (let (($x33249 (or (and c_67_0 in_target_67) (and c_67_1 in_target_67) (and c_67_2 in_target_67) (and c_67_3 in_target_67) (and c_67_4 in_target_67) (and c_67_5 in_target_67) (and c_67_6 in_target_67) (and c_67_7 in_target_67) (and c_67_8 in_target_67))))
 (let (($x33232 (and $x33249 $x33231)))
 (let (($x33594 (or (or false (and c_67_8 $x33588)) (and $x33232 (= ghost_2_67 (- ghost_2_29 1))))))
 (let (($x33598 (or (or $x33594 $x33591) (and $x33362 (= ghost_2_70 (- ghost_2_29 1))))))
 (let (($x33603 (or (or $x33598 $x33600) (and $x30446 (= ghost_2_7 (- ghost_2_29 1))))))
 (let (($x33593 (or (or $x33603 $x33604) (and $x30592 (= ghost_2_11 (- ghost_2_29 1))))))
 (let (($x33605 (or (or $x33593 $x33610) (and $x33562 (= ghost_2_74 (- ghost_2_29 1))))))
 (let (($x33635 (or (or $x33605 $x33614) (and $x33632 (= ghost_2_75 (- ghost_2_29 1))))))
 (let (($x33651 (>= ghost_2_29 1)))
 (let (($x31371 (not c_29_8)))
 (let (($x31389 (or (and c_29_0 in_target_29) (and c_29_1 in_target_29) (and c_29_2 in_target_29) (and c_29_3 in_target_29) (and c_29_4 in_target_29) (and c_29_5 in_target_29) (and c_29_6 in_target_29) (and c_29_7 in_target_29) (and c_29_8 in_target_29))))
 (let (($x31372 (and $x31389 $x31371)))
 (let (($x33650 (and (=> (and $x31389 c_29_8) (= ghost_2_29 0)) (=> $x31372 (and $x33651 $x33635)))))
 (let (($x33489 (= ghost_2_28 1)))
 (let (($x33540 (and c_74_8 $x33489)))
 (let (($x33505 (and c_73_8 $x33489)))
 (let (($x33503 (and c_10_8 $x33489)))
 (let (($x33499 (and c_72_8 $x33489)))
 (let (($x33491 (and c_7_8 $x33489)))
 (let (($x33196 (not c_66_8)))
 (let (($x33214 (or (and c_66_0 in_target_66) (and c_66_1 in_target_66) (and c_66_2 in_target_66) (and c_66_3 in_target_66) (and c_66_4 in_target_66) (and c_66_5 in_target_66) (and c_66_6 in_target_66) (and c_66_7 in_target_66) (and c_66_8 in_target_66))))
 (let (($x33197 (and $x33214 $x33196)))
 (let (($x33495 (or (or false (and c_66_8 $x33489)) (and $x33197 (= ghost_2_66 (- ghost_2_28 1))))))
 (let (($x33498 (or (or $x33495 $x33491) (and $x30446 (= ghost_2_7 (- ghost_2_28 1))))))
 (let (($x33496 (or (or $x33498 $x33499) (and $x33457 (= ghost_2_72 (- ghost_2_28 1))))))
 (let (($x33509 (or (or $x33496 $x33503) (and $x30557 (= ghost_2_10 (- ghost_2_28 1))))))
 (let (($x33536 (or (or $x33509 $x33505) (and $x33527 (= ghost_2_73 (- ghost_2_28 1))))))
 (let (($x33577 (or (or $x33536 $x33540) (and $x33562 (= ghost_2_74 (- ghost_2_28 1))))))
 (let (($x33581 (>= ghost_2_28 1)))
 (let (($x31336 (not c_28_8)))
 (let (($x31354 (or (and c_28_0 in_target_28) (and c_28_1 in_target_28) (and c_28_2 in_target_28) (and c_28_3 in_target_28) (and c_28_4 in_target_28) (and c_28_5 in_target_28) (and c_28_6 in_target_28) (and c_28_7 in_target_28) (and c_28_8 in_target_28))))
 (let (($x31337 (and $x31354 $x31336)))
 (let (($x33575 (and (=> (and $x31354 c_28_8) (= ghost_2_28 0)) (=> $x31337 (and $x33581 $x33577)))))
 (let (($x33385 (= ghost_2_27 1)))
 (let (($x33468 (and c_7_8 $x33385)))
 (let (($x33438 (and c_72_8 $x33385)))
 (let (($x33422 (and c_9_8 $x33385)))
 (let (($x33399 (and c_71_8 $x33385)))
 (let (($x33394 (and c_69_8 $x33385)))
 (let (($x33156 (not c_65_8)))
 (let (($x33174 (or (and c_65_0 in_target_65) (and c_65_1 in_target_65) (and c_65_2 in_target_65) (and c_65_3 in_target_65) (and c_65_4 in_target_65) (and c_65_5 in_target_65) (and c_65_6 in_target_65) (and c_65_7 in_target_65) (and c_65_8 in_target_65))))
 (let (($x33157 (and $x33174 $x33156)))
 (let (($x33392 (or (or false (and c_65_8 $x33385)) (and $x33157 (= ghost_2_65 (- ghost_2_27 1))))))
 (let (($x33396 (or (or $x33392 $x33394) (and $x33317 (= ghost_2_69 (- ghost_2_27 1))))))
 (let (($x33428 (or (or $x33396 $x33399) (and $x33417 (= ghost_2_71 (- ghost_2_27 1))))))
 (let (($x33441 (or (or $x33428 $x33422) (and $x30517 (= ghost_2_9 (- ghost_2_27 1))))))
 (let (($x33472 (or (or $x33441 $x33438) (and $x33457 (= ghost_2_72 (- ghost_2_27 1))))))
 (let (($x33483 (>= ghost_2_27 1)))
 (let (($x33485 (and $x33483 (or (or $x33472 $x33468) (and $x30446 (= ghost_2_7 (- ghost_2_27 1)))))))
 (let (($x31296 (not c_27_8)))
 (let (($x31314 (or (and c_27_0 in_target_27) (and c_27_1 in_target_27) (and c_27_2 in_target_27) (and c_27_3 in_target_27) (and c_27_4 in_target_27) (and c_27_5 in_target_27) (and c_27_6 in_target_27) (and c_27_7 in_target_27) (and c_27_8 in_target_27))))
 (let (($x31297 (and $x31314 $x31296)))
 (let (($x33257 (= ghost_2_26 1)))
 (let (($x33344 (and c_70_8 $x33257)))
 (let (($x33335 (and c_7_8 $x33257)))
 (let (($x33324 (and c_8_8 $x33257)))
 (let (($x33287 (and c_69_8 $x33257)))
 (let (($x33264 (and c_68_8 $x33257)))
 (let (($x33121 (not c_64_8)))
 (let (($x33139 (or (and c_64_0 in_target_64) (and c_64_1 in_target_64) (and c_64_2 in_target_64) (and c_64_3 in_target_64) (and c_64_4 in_target_64) (and c_64_5 in_target_64) (and c_64_6 in_target_64) (and c_64_7 in_target_64) (and c_64_8 in_target_64))))
 (let (($x33122 (and $x33139 $x33121)))
 (let (($x33261 (or (or false (and c_64_8 $x33257)) (and $x33122 (= ghost_2_64 (- ghost_2_26 1))))))
 (let (($x33297 (or (or $x33261 $x33264) (and $x33282 (= ghost_2_68 (- ghost_2_26 1))))))
 (let (($x33320 (or (or $x33297 $x33287) (and $x33317 (= ghost_2_69 (- ghost_2_26 1))))))
 (let (($x33337 (or (or $x33320 $x33324) (and $x30482 (= ghost_2_8 (- ghost_2_26 1))))))
 (let (($x33343 (or (or $x33337 $x33335) (and $x30446 (= ghost_2_7 (- ghost_2_26 1))))))
 (let (($x33367 (or (or $x33343 $x33344) (and $x33362 (= ghost_2_70 (- ghost_2_26 1))))))
 (let (($x33380 (>= ghost_2_26 1)))
 (let (($x31261 (not c_26_8)))
 (let (($x31279 (or (and c_26_0 in_target_26) (and c_26_1 in_target_26) (and c_26_2 in_target_26) (and c_26_3 in_target_26) (and c_26_4 in_target_26) (and c_26_5 in_target_26) (and c_26_6 in_target_26) (and c_26_7 in_target_26) (and c_26_8 in_target_26))))
 (let (($x31262 (and $x31279 $x31261)))
 (let (($x33382 (and (=> (and $x31279 c_26_8) (= ghost_2_26 0)) (=> $x31262 (and $x33380 $x33367)))))
 (let (($x33062 (= ghost_2_25 1)))
 (let (($x33202 (and c_67_8 $x33062)))
 (let (($x33179 (and c_66_8 $x33062)))
 (let (($x33160 (and c_7_8 $x33062)))
 (let (($x33133 (and c_65_8 $x33062)))
 (let (($x33091 (and c_64_8 $x33062)))
 (let (($x33085 (not c_63_8)))
 (let (($x33103 (or (and c_63_0 in_target_63) (and c_63_1 in_target_63) (and c_63_2 in_target_63) (and c_63_3 in_target_63) (and c_63_4 in_target_63) (and c_63_5 in_target_63) (and c_63_6 in_target_63) (and c_63_7 in_target_63) (and c_63_8 in_target_63))))
 (let (($x33101 (or (or false (and c_63_8 $x33062)) (and (and $x33103 $x33085) (= ghost_2_63 (- ghost_2_25 1))))))
 (let (($x33135 (or (or $x33101 $x33091) (and $x33122 (= ghost_2_64 (- ghost_2_25 1))))))
 (let (($x33170 (or (or $x33135 $x33133) (and $x33157 (= ghost_2_65 (- ghost_2_25 1))))))
 (let (($x33178 (or (or $x33170 $x33160) (and $x30446 (= ghost_2_7 (- ghost_2_25 1))))))
 (let (($x33204 (or (or $x33178 $x33179) (and $x33197 (= ghost_2_66 (- ghost_2_25 1))))))
 (let (($x33239 (or (or $x33204 $x33202) (and $x33232 (= ghost_2_67 (- ghost_2_25 1))))))
 (let (($x33251 (>= ghost_2_25 1)))
 (let (($x31225 (not c_25_8)))
 (let (($x31243 (or (and c_25_0 in_target_25) (and c_25_1 in_target_25) (and c_25_2 in_target_25) (and c_25_3 in_target_25) (and c_25_4 in_target_25) (and c_25_5 in_target_25) (and c_25_6 in_target_25) (and c_25_7 in_target_25) (and c_25_8 in_target_25))))
 (let (($x31226 (and $x31243 $x31225)))
 (let (($x33243 (and (=> (and $x31243 c_25_8) (= ghost_2_25 0)) (=> $x31226 (and $x33251 $x33239)))))
 (let (($x32997 (= ghost_2_24 1)))
 (let (($x33024 (and c_62_8 $x32997)))
 (let (($x33019 (and c_61_8 $x32997)))
 (let (($x33013 (and c_55_8 $x32997)))
 (let (($x33008 (and c_6_8 $x32997)))
 (let (($x33003 (and c_46_8 $x32997)))
 (let (($x33002 (or (or false (and c_37_8 $x32997)) (and $x31772 (= ghost_2_37 (- ghost_2_24 1))))))
 (let (($x33006 (or (or $x33002 $x33003) (and $x32202 (= ghost_2_46 (- ghost_2_24 1))))))
 (let (($x33007 (or (or $x33006 $x33008) (and (and $x30417 (not c_6_8)) (= ghost_2_6 (- ghost_2_24 1))))))
 (let (($x33021 (or (or $x33007 $x33013) (and $x32632 (= ghost_2_55 (- ghost_2_24 1))))))
 (let (($x33022 (or (or $x33021 $x33019) (and $x32972 (= ghost_2_61 (- ghost_2_24 1))))))
 (let (($x33055 (or (or $x33022 $x33024) (and $x33042 (= ghost_2_62 (- ghost_2_24 1))))))
 (let (($x33060 (>= ghost_2_24 1)))
 (let (($x33064 (and (=> (and $x31199 c_24_8) (= ghost_2_24 0)) (=> $x31182 (and $x33060 $x33055)))))
 (let (($x32913 (= ghost_2_23 1)))
 (let (($x32955 (and c_61_8 $x32913)))
 (let (($x32950 (and c_60_8 $x32913)))
 (let (($x32945 (and c_54_8 $x32913)))
 (let (($x32938 (and c_5_8 $x32913)))
 (let (($x32934 (and c_6_8 $x32913)))
 (let (($x32931 (or (or false (and c_36_8 $x32913)) (and $x31702 (= ghost_2_36 (- ghost_2_23 1))))))
 (let (($x32930 (or (or $x32931 $x32934) (and (and $x30417 (not c_6_8)) (= ghost_2_6 (- ghost_2_23 1))))))
 (let (($x32943 (or (or $x32930 $x32938) (and (and $x30382 (not c_5_8)) (= ghost_2_5 (- ghost_2_23 1))))))
 (let (($x32947 (or (or $x32943 $x32945) (and $x32562 (= ghost_2_54 (- ghost_2_23 1))))))
 (let (($x32956 (or (or $x32947 $x32950) (and $x32902 (= ghost_2_60 (- ghost_2_23 1))))))
 (let (($x32975 (or (or $x32956 $x32955) (and $x32972 (= ghost_2_61 (- ghost_2_23 1))))))
 (let (($x32990 (>= ghost_2_23 1)))
 (let (($x32992 (and (=> (and $x31129 c_23_8) (= ghost_2_23 0)) (=> $x31112 (and $x32990 $x32975)))))
 (let (($x32829 (= ghost_2_22 1)))
 (let (($x32882 (and c_60_8 $x32829)))
 (let (($x32844 (and c_59_8 $x32829)))
 (let (($x32845 (and c_53_8 $x32829)))
 (let (($x32840 (and c_58_8 $x32829)))
 (let (($x32830 (and c_5_8 $x32829)))
 (let (($x32835 (or (or false (and c_35_8 $x32829)) (and $x31667 (= ghost_2_35 (- ghost_2_22 1))))))
 (let (($x32838 (or (or $x32835 $x32830) (and (and $x30382 (not c_5_8)) (= ghost_2_5 (- ghost_2_22 1))))))
 (let (($x32842 (or (or $x32838 $x32840) (and $x32797 (= ghost_2_58 (- ghost_2_22 1))))))
 (let (($x32841 (or (or $x32842 $x32845) (and $x32527 (= ghost_2_53 (- ghost_2_22 1))))))
 (let (($x32876 (or (or $x32841 $x32844) (and $x32867 (= ghost_2_59 (- ghost_2_22 1))))))
 (let (($x32907 (or (or $x32876 $x32882) (and $x32902 (= ghost_2_60 (- ghost_2_22 1))))))
 (let (($x32923 (>= ghost_2_22 1)))
 (let (($x32921 (and (=> (and $x31094 c_22_8) (= ghost_2_22 0)) (=> $x31077 (and $x32923 $x32907)))))
 (let (($x32750 (= ghost_2_21 1)))
 (let (($x32802 (and c_5_8 $x32750)))
 (let (($x32773 (and c_58_8 $x32750)))
 (let (($x32774 (and c_49_8 $x32750)))
 (let (($x32767 (and c_57_8 $x32750)))
 (let (($x32760 (and c_4_8 $x32750)))
 (let (($x32764 (or (or false (and c_34_8 $x32750)) (and $x31597 (= ghost_2_34 (- ghost_2_21 1))))))
 (let (($x32761 (or (or $x32764 $x32760) (and (and $x30312 (not c_4_8)) (= ghost_2_4 (- ghost_2_21 1))))))
 (let (($x32775 (or (or $x32761 $x32767) (and $x32727 (= ghost_2_57 (- ghost_2_21 1))))))
 (let (($x32778 (or (or $x32775 $x32774) (and $x32327 (= ghost_2_49 (- ghost_2_21 1))))))
 (let (($x32812 (or (or $x32778 $x32773) (and $x32797 (= ghost_2_58 (- ghost_2_21 1))))))
 (let (($x32818 (or (or $x32812 $x32802) (and (and $x30382 (not c_5_8)) (= ghost_2_5 (- ghost_2_21 1))))))
 (let (($x32815 (>= ghost_2_21 1)))
 (let (($x32822 (and (=> (and $x31024 c_21_8) (= ghost_2_21 0)) (=> $x31007 (and $x32815 $x32818)))))
 (let (($x32656 (= ghost_2_20 1)))
 (let (($x32734 (and c_4_8 $x32656)))
 (let (($x32705 (and c_57_8 $x32656)))
 (let (($x32702 (and c_47_8 $x32656)))
 (let (($x32665 (and c_56_8 $x32656)))
 (let (($x32654 (and c_42_8 $x32656)))
 (let (($x32663 (or (or false (and c_33_8 $x32656)) (and $x31557 (= ghost_2_33 (- ghost_2_20 1))))))
 (let (($x32666 (or (or $x32663 $x32654) (and $x31987 (= ghost_2_42 (- ghost_2_20 1))))))
 (let (($x32690 (or (or $x32666 $x32665) (and $x32687 (= ghost_2_56 (- ghost_2_20 1))))))
 (let (($x32711 (or (or $x32690 $x32702) (and $x32257 (= ghost_2_47 (- ghost_2_20 1))))))
 (let (($x32742 (or (or $x32711 $x32705) (and $x32727 (= ghost_2_57 (- ghost_2_20 1))))))
 (let (($x32745 (or (or $x32742 $x32734) (and (and $x30312 (not c_4_8)) (= ghost_2_4 (- ghost_2_20 1))))))
 (let (($x32751 (>= ghost_2_20 1)))
 (let (($x32754 (and (=> (and $x30984 c_20_8) (= ghost_2_20 0)) (=> $x30967 (and $x32751 $x32745)))))
 (let (($x32582 (= ghost_2_19 1)))
 (let (($x32615 (and c_55_8 $x32582)))
 (let (($x32607 (and c_54_8 $x32582)))
 (let (($x32605 (and c_52_8 $x32582)))
 (let (($x32601 (and c_3_8 $x32582)))
 (let (($x32593 (and c_45_8 $x32582)))
 (let (($x32592 (or (or false (and c_6_8 $x32582)) (and (and $x30417 (not c_6_8)) (= ghost_2_6 (- ghost_2_19 1))))))
 (let (($x32596 (or (or $x32592 $x32593) (and $x32132 (= ghost_2_45 (- ghost_2_19 1))))))
 (let (($x32604 (or (or $x32596 $x32601) (and (and $x30347 (not c_3_8)) (= ghost_2_3 (- ghost_2_19 1))))))
 (let (($x32602 (or (or $x32604 $x32605) (and $x32462 (= ghost_2_52 (- ghost_2_19 1))))))
 (let (($x32612 (or (or $x32602 $x32607) (and $x32562 (= ghost_2_54 (- ghost_2_19 1))))))
 (let (($x32641 (or (or $x32612 $x32615) (and $x32632 (= ghost_2_55 (- ghost_2_19 1))))))
 (let (($x32653 (>= ghost_2_19 1)))
 (let (($x32651 (and (=> (and $x30929 c_19_8) (= ghost_2_19 0)) (=> $x30912 (and $x32653 $x32641)))))
 (let (($x32488 (= ghost_2_18 1)))
 (let (($x32538 (and c_54_8 $x32488)))
 (let (($x32510 (and c_53_8 $x32488)))
 (let (($x32497 (and c_51_8 $x32488)))
 (let (($x32500 (and c_49_8 $x32488)))
 (let (($x32491 (and c_3_8 $x32488)))
 (let (($x32494 (or (or false (and c_5_8 $x32488)) (and (and $x30382 (not c_5_8)) (= ghost_2_5 (- ghost_2_18 1))))))
 (let (($x32499 (or (or $x32494 $x32491) (and (and $x30347 (not c_3_8)) (= ghost_2_3 (- ghost_2_18 1))))))
 (let (($x32503 (or (or $x32499 $x32500) (and $x32327 (= ghost_2_49 (- ghost_2_18 1))))))
 (let (($x32507 (or (or $x32503 $x32497) (and $x32427 (= ghost_2_51 (- ghost_2_18 1))))))
 (let (($x32534 (or (or $x32507 $x32510) (and $x32527 (= ghost_2_53 (- ghost_2_18 1))))))
 (let (($x32573 (or (or $x32534 $x32538) (and $x32562 (= ghost_2_54 (- ghost_2_18 1))))))
 (let (($x32577 (>= ghost_2_18 1)))
 (let (($x32581 (and (=> (and $x30894 c_18_8) (= ghost_2_18 0)) (=> $x30877 (and $x32577 $x32573)))))
 (let (($x32354 (= ghost_2_17 1)))
 (let (($x32438 (and c_52_8 $x32354)))
 (let (($x32403 (and c_51_8 $x32354)))
 (let (($x32376 (and c_50_8 $x32354)))
 (let (($x32367 (and c_48_8 $x32354)))
 (let (($x32360 (and c_44_8 $x32354)))
 (let (($x32364 (or (or false (and c_3_8 $x32354)) (and (and $x30347 (not c_3_8)) (= ghost_2_3 (- ghost_2_17 1))))))
 (let (($x32371 (or (or $x32364 $x32360) (and $x32092 (= ghost_2_44 (- ghost_2_17 1))))))
 (let (($x32369 (or (or $x32371 $x32367) (and $x32292 (= ghost_2_48 (- ghost_2_17 1))))))
 (let (($x32395 (or (or $x32369 $x32376) (and $x32392 (= ghost_2_50 (- ghost_2_17 1))))))
 (let (($x32442 (or (or $x32395 $x32403) (and $x32427 (= ghost_2_51 (- ghost_2_17 1))))))
 (let (($x32471 (or (or $x32442 $x32438) (and $x32462 (= ghost_2_52 (- ghost_2_17 1))))))
 (let (($x32482 (>= ghost_2_17 1)))
 (let (($x32483 (and (=> (and $x30859 c_17_8) (= ghost_2_17 0)) (=> $x30842 (and $x32482 $x32471)))))
 (let (($x32229 (= ghost_2_16 1)))
 (let (($x32334 (and c_3_8 $x32229)))
 (let (($x32301 (and c_49_8 $x32229)))
 (let (($x32268 (and c_48_8 $x32229)))
 (let (($x32238 (and c_47_8 $x32229)))
 (let (($x32230 (and c_43_8 $x32229)))
 (let (($x32231 (or (or false (and c_4_8 $x32229)) (and (and $x30312 (not c_4_8)) (= ghost_2_4 (- ghost_2_16 1))))))
 (let (($x32236 (or (or $x32231 $x32230) (and $x32022 (= ghost_2_43 (- ghost_2_16 1))))))
 (let (($x32264 (or (or $x32236 $x32238) (and $x32257 (= ghost_2_47 (- ghost_2_16 1))))))
 (let (($x32305 (or (or $x32264 $x32268) (and $x32292 (= ghost_2_48 (- ghost_2_16 1))))))
 (let (($x32338 (or (or $x32305 $x32301) (and $x32327 (= ghost_2_49 (- ghost_2_16 1))))))
 (let (($x32349 (or (or $x32338 $x32334) (and (and $x30347 (not c_3_8)) (= ghost_2_3 (- ghost_2_16 1))))))
 (let (($x32352 (>= ghost_2_16 1)))
 (let (($x32347 (and (=> (and $x30824 c_16_8) (= ghost_2_16 0)) (=> $x30807 (and $x32352 $x32349)))))
 (let (($x32158 (= ghost_2_15 1)))
 (let (($x32183 (and c_46_8 $x32158)))
 (let (($x32181 (and c_6_8 $x32158)))
 (let (($x32175 (and c_45_8 $x32158)))
 (let (($x32167 (and c_2_8 $x32158)))
 (let (($x32164 (and c_41_8 $x32158)))
 (let (($x32163 (or (or false (and c_32_8 $x32158)) (and $x31502 (= ghost_2_32 (- ghost_2_15 1))))))
 (let (($x32166 (or (or $x32163 $x32164) (and $x31932 (= ghost_2_41 (- ghost_2_15 1))))))
 (let (($x32173 (or (or $x32166 $x32167) (and (and $x30277 (not c_2_8)) (= ghost_2_2 (- ghost_2_15 1))))))
 (let (($x32169 (or (or $x32173 $x32175) (and $x32132 (= ghost_2_45 (- ghost_2_15 1))))))
 (let (($x32177 (or (or $x32169 $x32181) (and (and $x30417 (not c_6_8)) (= ghost_2_6 (- ghost_2_15 1))))))
 (let (($x32205 (or (or $x32177 $x32183) (and $x32202 (= ghost_2_46 (- ghost_2_15 1))))))
 (let (($x32217 (>= ghost_2_15 1)))
 (let (($x32221 (and (=> (and $x30769 c_15_8) (= ghost_2_15 0)) (=> $x30752 (and $x32217 $x32205)))))
 (let (($x32056 (= ghost_2_14 1)))
 (let (($x32115 (and c_45_8 $x32056)))
 (let (($x32095 (and c_3_8 $x32056)))
 (let (($x32073 (and c_44_8 $x32056)))
 (let (($x32067 (and c_43_8 $x32056)))
 (let (($x32063 (and c_40_8 $x32056)))
 (let (($x32064 (or (or false (and c_2_8 $x32056)) (and (and $x30277 (not c_2_8)) (= ghost_2_2 (- ghost_2_14 1))))))
 (let (($x32066 (or (or $x32064 $x32063) (and $x31892 (= ghost_2_40 (- ghost_2_14 1))))))
 (let (($x32071 (or (or $x32066 $x32067) (and $x32022 (= ghost_2_43 (- ghost_2_14 1))))))
 (let (($x32097 (or (or $x32071 $x32073) (and $x32092 (= ghost_2_44 (- ghost_2_14 1))))))
 (let (($x32114 (or (or $x32097 $x32095) (and (and $x30347 (not c_3_8)) (= ghost_2_3 (- ghost_2_14 1))))))
 (let (($x32143 (or (or $x32114 $x32115) (and $x32132 (= ghost_2_45 (- ghost_2_14 1))))))
 (let (($x32152 (>= ghost_2_14 1)))
 (let (($x32151 (and (=> (and $x30729 c_14_8) (= ghost_2_14 0)) (=> $x30712 (and $x32152 $x32143)))))
 (let (($x31952 (= ghost_2_13 1)))
 (let (($x32042 (and c_2_8 $x31952)))
 (let (($x32033 (and c_4_8 $x31952)))
 (let (($x31998 (and c_43_8 $x31952)))
 (let (($x31960 (and c_42_8 $x31952)))
 (let (($x31965 (and c_39_8 $x31952)))
 (let (($x31959 (or (or false (and c_31_8 $x31952)) (and $x31457 (= ghost_2_31 (- ghost_2_13 1))))))
 (let (($x31971 (or (or $x31959 $x31965) (and $x31857 (= ghost_2_39 (- ghost_2_13 1))))))
 (let (($x31994 (or (or $x31971 $x31960) (and $x31987 (= ghost_2_42 (- ghost_2_13 1))))))
 (let (($x32035 (or (or $x31994 $x31998) (and $x32022 (= ghost_2_43 (- ghost_2_13 1))))))
 (let (($x32040 (or (or $x32035 $x32033) (and (and $x30312 (not c_4_8)) (= ghost_2_4 (- ghost_2_13 1))))))
 (let (($x32048 (or (or $x32040 $x32042) (and (and $x30277 (not c_2_8)) (= ghost_2_2 (- ghost_2_13 1))))))
 (let (($x32053 (>= ghost_2_13 1)))
 (let (($x32051 (and (=> (and $x30694 c_13_8) (= ghost_2_13 0)) (=> $x30677 (and $x32053 $x32048)))))
 (let (($x31798 (= ghost_2_12 1)))
 (let (($x31915 (and c_41_8 $x31798)))
 (let (($x31901 (and c_2_8 $x31798)))
 (let (($x31870 (and c_40_8 $x31798)))
 (let (($x31835 (and c_39_8 $x31798)))
 (let (($x31805 (and c_38_8 $x31798)))
 (let (($x31803 (or (or false (and c_30_8 $x31798)) (and $x31422 (= ghost_2_30 (- ghost_2_12 1))))))
 (let (($x31829 (or (or $x31803 $x31805) (and $x31822 (= ghost_2_38 (- ghost_2_12 1))))))
 (let (($x31868 (or (or $x31829 $x31835) (and $x31857 (= ghost_2_39 (- ghost_2_12 1))))))
 (let (($x31895 (or (or $x31868 $x31870) (and $x31892 (= ghost_2_40 (- ghost_2_12 1))))))
 (let (($x31913 (or (or $x31895 $x31901) (and (and $x30277 (not c_2_8)) (= ghost_2_2 (- ghost_2_12 1))))))
 (let (($x31947 (or (or $x31913 $x31915) (and $x31932 (= ghost_2_41 (- ghost_2_12 1))))))
 (let (($x31954 (>= ghost_2_12 1)))
 (let (($x31953 (and (=> (and $x30659 c_12_8) (= ghost_2_12 0)) (=> $x30642 (and $x31954 $x31947)))))
 (let (($x31722 (= ghost_2_11 1)))
 (let (($x31752 (and c_37_8 $x31722)))
 (let (($x31748 (and c_36_8 $x31722)))
 (let (($x31741 (and c_6_8 $x31722)))
 (let (($x31739 (and c_1_8 $x31722)))
 (let (($x31732 (and c_32_8 $x31722)))
 (let (($x31734 (or (or false (and c_29_8 $x31722)) (and $x31372 (= ghost_2_29 (- ghost_2_11 1))))))
 (let (($x31738 (or (or $x31734 $x31732) (and $x31502 (= ghost_2_32 (- ghost_2_11 1))))))
 (let (($x31746 (or (or $x31738 $x31739) (and (and $x30241 (not c_1_8)) (= ghost_2_1 (- ghost_2_11 1))))))
 (let (($x31744 (or (or $x31746 $x31741) (and (and $x30417 (not c_6_8)) (= ghost_2_6 (- ghost_2_11 1))))))
 (let (($x31753 (or (or $x31744 $x31748) (and $x31702 (= ghost_2_36 (- ghost_2_11 1))))))
 (let (($x31783 (or (or $x31753 $x31752) (and $x31772 (= ghost_2_37 (- ghost_2_11 1))))))
 (let (($x31790 (>= ghost_2_11 1)))
 (let (($x31793 (and (=> (and $x30609 c_11_8) (= ghost_2_11 0)) (=> $x30592 (and $x31790 $x31783)))))
 (let (($x31626 (= ghost_2_10 1)))
 (let (($x31676 (and c_36_8 $x31626)))
 (let (($x31650 (and c_35_8 $x31626)))
 (let (($x31645 (and c_5_8 $x31626)))
 (let (($x31635 (and c_34_8 $x31626)))
 (let (($x31632 (and c_1_8 $x31626)))
 (let (($x31634 (or (or false (and c_28_8 $x31626)) (and $x31337 (= ghost_2_28 (- ghost_2_10 1))))))
 (let (($x31641 (or (or $x31634 $x31632) (and (and $x30241 (not c_1_8)) (= ghost_2_1 (- ghost_2_10 1))))))
 (let (($x31643 (or (or $x31641 $x31635) (and $x31597 (= ghost_2_34 (- ghost_2_10 1))))))
 (let (($x31648 (or (or $x31643 $x31645) (and (and $x30382 (not c_5_8)) (= ghost_2_5 (- ghost_2_10 1))))))
 (let (($x31672 (or (or $x31648 $x31650) (and $x31667 (= ghost_2_35 (- ghost_2_10 1))))))
 (let (($x31715 (or (or $x31672 $x31676) (and $x31702 (= ghost_2_36 (- ghost_2_10 1))))))
 (let (($x31723 (>= ghost_2_10 1)))
 (let (($x31724 (and (=> (and $x30574 c_10_8) (= ghost_2_10 0)) (=> $x30557 (and $x31723 $x31715)))))
 (let (($x31522 (= ghost_2_9 1)))
 (let (($x31608 (and c_1_8 $x31522)))
 (let (($x31577 (and c_34_8 $x31522)))
 (let (($x31562 (and c_4_8 $x31522)))
 (let (($x31531 (and c_33_8 $x31522)))
 (let (($x31532 (and c_31_8 $x31522)))
 (let (($x31535 (or (or false (and c_27_8 $x31522)) (and $x31297 (= ghost_2_27 (- ghost_2_9 1))))))
 (let (($x31538 (or (or $x31535 $x31532) (and $x31457 (= ghost_2_31 (- ghost_2_9 1))))))
 (let (($x31560 (or (or $x31538 $x31531) (and $x31557 (= ghost_2_33 (- ghost_2_9 1))))))
 (let (($x31575 (or (or $x31560 $x31562) (and (and $x30312 (not c_4_8)) (= ghost_2_4 (- ghost_2_9 1))))))
 (let (($x31602 (or (or $x31575 $x31577) (and $x31597 (= ghost_2_34 (- ghost_2_9 1))))))
 (let (($x31621 (or (or $x31602 $x31608) (and (and $x30241 (not c_1_8)) (= ghost_2_1 (- ghost_2_9 1))))))
 (let (($x31625 (>= ghost_2_9 1)))
 (let (($x31618 (and (=> (and $x30534 c_9_8) (= ghost_2_9 0)) (=> $x30517 (and $x31625 $x31621)))))
 (let (($x31397 (= ghost_2_8 1)))
 (let (($x31476 (and c_32_8 $x31397)))
 (let (($x31480 (and c_1_8 $x31397)))
 (let (($x31468 (and c_2_8 $x31397)))
 (let (($x31425 (and c_31_8 $x31397)))
 (let (($x31403 (and c_30_8 $x31397)))
 (let (($x31401 (or (or false (and c_26_8 $x31397)) (and $x31262 (= ghost_2_26 (- ghost_2_8 1))))))
 (let (($x31437 (or (or $x31401 $x31403) (and $x31422 (= ghost_2_30 (- ghost_2_8 1))))))
 (let (($x31472 (or (or $x31437 $x31425) (and $x31457 (= ghost_2_31 (- ghost_2_8 1))))))
 (let (($x31478 (or (or $x31472 $x31468) (and (and $x30277 (not c_2_8)) (= ghost_2_2 (- ghost_2_8 1))))))
 (let (($x31486 (or (or $x31478 $x31480) (and (and $x30241 (not c_1_8)) (= ghost_2_1 (- ghost_2_8 1))))))
 (let (($x31521 (>= ghost_2_8 1)))
 (let (($x31505 (and $x31521 (or (or $x31486 $x31476) (and $x31502 (= ghost_2_32 (- ghost_2_8 1)))))))
 (let (($x31206 (= ghost_2_7 1)))
 (let (($x31340 (and c_29_8 $x31206)))
 (let (($x31315 (and c_28_8 $x31206)))
 (let (($x31300 (and c_1_8 $x31206)))
 (let (($x31271 (and c_27_8 $x31206)))
 (let (($x31239 (and c_26_8 $x31206)))
 (let (($x31229 (or (or false (and c_25_8 $x31206)) (and $x31226 (= ghost_2_25 (- ghost_2_7 1))))))
 (let (($x31273 (or (or $x31229 $x31239) (and $x31262 (= ghost_2_26 (- ghost_2_7 1))))))
 (let (($x31306 (or (or $x31273 $x31271) (and $x31297 (= ghost_2_27 (- ghost_2_7 1))))))
 (let (($x31321 (or (or $x31306 $x31300) (and (and $x30241 (not c_1_8)) (= ghost_2_1 (- ghost_2_7 1))))))
 (let (($x31346 (or (or $x31321 $x31315) (and $x31337 (= ghost_2_28 (- ghost_2_7 1))))))
 (let (($x31392 (>= ghost_2_7 1)))
 (let (($x31393 (and $x31392 (or (or $x31346 $x31340) (and $x31372 (= ghost_2_29 (- ghost_2_7 1)))))))
 (let (($x31138 (= ghost_2_6 1)))
 (let (($x31164 (and c_24_8 $x31138)))
 (let (($x31158 (and c_23_8 $x31138)))
 (let (($x31149 (and c_19_8 $x31138)))
 (let (($x31151 (and c_0_8 $x31138)))
 (let (($x31141 (and c_15_8 $x31138)))
 (let (($x31144 (or (or false (and c_11_8 $x31138)) (and $x30592 (= ghost_2_11 (- ghost_2_6 1))))))
 (let (($x31137 (or (or $x31144 $x31141) (and $x30752 (= ghost_2_15 (- ghost_2_6 1))))))
 (let (($x31155 (or (or $x31137 $x31151) (and (and $x30078 (not c_0_8)) (= ghost_2_0 (- ghost_2_6 1))))))
 (let (($x31159 (or (or $x31155 $x31149) (and $x30912 (= ghost_2_19 (- ghost_2_6 1))))))
 (let (($x31150 (or (or $x31159 $x31158) (and $x31112 (= ghost_2_23 (- ghost_2_6 1))))))
 (let (($x31193 (>= ghost_2_6 1)))
 (let (($x31202 (and $x31193 (or (or $x31150 $x31164) (and $x31182 (= ghost_2_24 (- ghost_2_6 1)))))))
 (let (($x30399 (not c_6_8)))
 (let (($x30400 (and $x30417 $x30399)))
 (let (($x31035 (= ghost_2_5 1)))
 (let (($x31084 (and c_23_8 $x31035)))
 (let (($x31052 (and c_22_8 $x31035)))
 (let (($x31056 (and c_18_8 $x31035)))
 (let (($x31041 (and c_21_8 $x31035)))
 (let (($x31040 (and c_0_8 $x31035)))
 (let (($x31039 (or (or false (and c_10_8 $x31035)) (and $x30557 (= ghost_2_10 (- ghost_2_5 1))))))
 (let (($x31050 (or (or $x31039 $x31040) (and (and $x30078 (not c_0_8)) (= ghost_2_0 (- ghost_2_5 1))))))
 (let (($x31046 (or (or $x31050 $x31041) (and $x31007 (= ghost_2_21 (- ghost_2_5 1))))))
 (let (($x31055 (or (or $x31046 $x31056) (and $x30877 (= ghost_2_18 (- ghost_2_5 1))))))
 (let (($x31090 (or (or $x31055 $x31052) (and $x31077 (= ghost_2_22 (- ghost_2_5 1))))))
 (let (($x31132 (>= ghost_2_5 1)))
 (let (($x31134 (and $x31132 (or (or $x31090 $x31084) (and $x31112 (= ghost_2_23 (- ghost_2_5 1)))))))
 (let (($x30364 (not c_5_8)))
 (let (($x30365 (and $x30382 $x30364)))
 (let (($x30938 (= ghost_2_4 1)))
 (let (($x31016 (and c_0_8 $x30938)))
 (let (($x30985 (and c_21_8 $x30938)))
 (let (($x30980 (and c_16_8 $x30938)))
 (let (($x30948 (and c_20_8 $x30938)))
 (let (($x30944 (and c_13_8 $x30938)))
 (let (($x30942 (or (or false (and c_9_8 $x30938)) (and $x30517 (= ghost_2_9 (- ghost_2_4 1))))))
 (let (($x30949 (or (or $x30942 $x30944) (and $x30677 (= ghost_2_13 (- ghost_2_4 1))))))
 (let (($x30976 (or (or $x30949 $x30948) (and $x30967 (= ghost_2_20 (- ghost_2_4 1))))))
 (let (($x30988 (or (or $x30976 $x30980) (and $x30807 (= ghost_2_16 (- ghost_2_4 1))))))
 (let (($x31012 (or (or $x30988 $x30985) (and $x31007 (= ghost_2_21 (- ghost_2_4 1))))))
 (let (($x31030 (or (or $x31012 $x31016) (and (and $x30078 (not c_0_8)) (= ghost_2_0 (- ghost_2_4 1))))))
 (let (($x31031 (>= ghost_2_4 1)))
 (let (($x30294 (not c_4_8)))
 (let (($x30295 (and $x30312 $x30294)))
 (let (($x31032 (and (=> (and $x30312 c_4_8) (= ghost_2_4 0)) (=> $x30295 (and $x31031 $x31030)))))
 (let (($x30778 (= ghost_2_3 1)))
 (let (($x30884 (and c_19_8 $x30778)))
 (let (($x30853 (and c_18_8 $x30778)))
 (let (($x30812 (and c_17_8 $x30778)))
 (let (($x30790 (and c_16_8 $x30778)))
 (let (($x30782 (and c_14_8 $x30778)))
 (let (($x30775 (or (or false (and c_0_8 $x30778)) (and (and $x30078 (not c_0_8)) (= ghost_2_0 (- ghost_2_3 1))))))
 (let (($x30788 (or (or $x30775 $x30782) (and $x30712 (= ghost_2_14 (- ghost_2_3 1))))))
 (let (($x30818 (or (or $x30788 $x30790) (and $x30807 (= ghost_2_16 (- ghost_2_3 1))))))
 (let (($x30847 (or (or $x30818 $x30812) (and $x30842 (= ghost_2_17 (- ghost_2_3 1))))))
 (let (($x30890 (or (or $x30847 $x30853) (and $x30877 (= ghost_2_18 (- ghost_2_3 1))))))
 (let (($x30933 (>= ghost_2_3 1)))
 (let (($x30934 (and $x30933 (or (or $x30890 $x30884) (and $x30912 (= ghost_2_19 (- ghost_2_3 1)))))))
 (let (($x30329 (not c_3_8)))
 (let (($x30330 (and $x30347 $x30329)))
 (let (($x30612 (= ghost_2_2 1)))
 (let (($x30730 (and c_15_8 $x30612)))
 (let (($x30719 (and c_0_8 $x30612)))
 (let (($x30680 (and c_14_8 $x30612)))
 (let (($x30653 (and c_13_8 $x30612)))
 (let (($x30624 (and c_12_8 $x30612)))
 (let (($x30618 (or (or false (and c_8_8 $x30612)) (and $x30482 (= ghost_2_8 (- ghost_2_2 1))))))
 (let (($x30649 (or (or $x30618 $x30624) (and $x30642 (= ghost_2_12 (- ghost_2_2 1))))))
 (let (($x30682 (or (or $x30649 $x30653) (and $x30677 (= ghost_2_13 (- ghost_2_2 1))))))
 (let (($x30717 (or (or $x30682 $x30680) (and $x30712 (= ghost_2_14 (- ghost_2_2 1))))))
 (let (($x30735 (or (or $x30717 $x30719) (and (and $x30078 (not c_0_8)) (= ghost_2_0 (- ghost_2_2 1))))))
 (let (($x30772 (>= ghost_2_2 1)))
 (let (($x30774 (and $x30772 (or (or $x30735 $x30730) (and $x30752 (= ghost_2_15 (- ghost_2_2 1)))))))
 (let (($x30259 (not c_2_8)))
 (let (($x30260 (and $x30277 $x30259)))
 (let (($x30421 (= ghost_2_1 1)))
 (let (($x30570 (and c_11_8 $x30421)))
 (let (($x30535 (and c_10_8 $x30421)))
 (let (($x30520 (and c_0_8 $x30421)))
 (let (($x30497 (and c_9_8 $x30421)))
 (let (($x30449 (and c_8_8 $x30421)))
 (let (($x30453 (or (or false (and c_7_8 $x30421)) (and $x30446 (= ghost_2_7 (- ghost_2_1 1))))))
 (let (($x30495 (or (or $x30453 $x30449) (and $x30482 (= ghost_2_8 (- ghost_2_1 1))))))
 (let (($x30530 (or (or $x30495 $x30497) (and $x30517 (= ghost_2_9 (- ghost_2_1 1))))))
 (let (($x30540 (or (or $x30530 $x30520) (and (and $x30078 (not c_0_8)) (= ghost_2_0 (- ghost_2_1 1))))))
 (let (($x30562 (or (or $x30540 $x30535) (and $x30557 (= ghost_2_10 (- ghost_2_1 1))))))
 (let (($x30615 (>= ghost_2_1 1)))
 (let (($x30595 (and $x30615 (or (or $x30562 $x30570) (and $x30592 (= ghost_2_11 (- ghost_2_1 1)))))))
 (let (($x30223 (not c_1_8)))
 (let (($x30224 (and $x30241 $x30223)))
 (let (($x30202 (= ghost_2_0 1)))
 (let (($x30370 (and c_6_8 $x30202)))
 (let (($x30339 (and c_5_8 $x30202)))
 (let (($x30304 (and c_3_8 $x30202)))
 (let (($x30267 (and c_4_8 $x30202)))
 (let (($x30233 (and c_2_8 $x30202)))
 (let (($x30229 (or (or false (and c_1_8 $x30202)) (and $x30224 (= ghost_2_1 (- ghost_2_0 1))))))
 (let (($x30271 (or (or $x30229 $x30233) (and $x30260 (= ghost_2_2 (- ghost_2_0 1))))))
 (let (($x30300 (or (or $x30271 $x30267) (and $x30295 (= ghost_2_4 (- ghost_2_0 1))))))
 (let (($x30335 (or (or $x30300 $x30304) (and $x30330 (= ghost_2_3 (- ghost_2_0 1))))))
 (let (($x30372 (or (or $x30335 $x30339) (and $x30365 (= ghost_2_5 (- ghost_2_0 1))))))
 (let (($x30422 (>= ghost_2_0 1)))
 (let (($x30405 (and $x30422 (or (or $x30372 $x30370) (and $x30400 (= ghost_2_6 (- ghost_2_0 1)))))))
 (let (($x30420 (not c_0_8)))
 (let (($x30419 (and $x30078 $x30420)))
 (let (($x30424 (and true (and (=> (and $x30078 c_0_8) (= ghost_2_0 0)) (=> $x30419 $x30405)))))
 (let (($x30619 (and $x30424 (and (=> (and $x30241 c_1_8) (= ghost_2_1 0)) (=> $x30224 $x30595)))))
 (let (($x30776 (and $x30619 (and (=> (and $x30277 c_2_8) (= ghost_2_2 0)) (=> $x30260 $x30774)))))
 (let (($x30937 (and $x30776 (and (=> (and $x30347 c_3_8) (= ghost_2_3 0)) (=> $x30330 $x30934)))))
 (let (($x31034 (and $x30937 $x31032)))
 (let (($x31136 (and $x31034 (and (=> (and $x30382 c_5_8) (= ghost_2_5 0)) (=> $x30365 $x31134)))))
 (let (($x31205 (and $x31136 (and (=> (and $x30417 c_6_8) (= ghost_2_6 0)) (=> $x30400 $x31202)))))
 (let (($x31396 (and $x31205 (and (=> (and $x30463 c_7_8) (= ghost_2_7 0)) (=> $x30446 $x31393)))))
 (let (($x31520 (and $x31396 (and (=> (and $x30499 c_8_8) (= ghost_2_8 0)) (=> $x30482 $x31505)))))
 (let (($x31629 (and $x31520 $x31618)))
 (let (($x31727 (and $x31629 $x31724)))
 (let (($x31795 (and $x31727 $x31793)))
 (let (($x31958 (and $x31795 $x31953)))
 (let (($x32057 (and $x31958 $x32051)))
 (let (($x32156 (and $x32057 $x32151)))
 (let (($x32222 (and $x32156 $x32221)))
 (let (($x32356 (and $x32222 $x32347)))
 (let (($x32486 (and $x32356 $x32483)))
 (let (($x32583 (and $x32486 $x32581)))
 (let (($x32657 (and $x32583 $x32651)))
 (let (($x32753 (and $x32657 $x32754)))
 (let (($x32823 (and $x32753 $x32822)))
 (let (($x32927 (and $x32823 $x32921)))
 (let (($x32995 (and $x32927 $x32992)))
 (let (($x33061 (and $x32995 $x33064)))
 (let (($x33250 (and $x33061 $x33243)))
 (let (($x33365 (and $x33250 $x33382)))
 (let (($x33487 (and $x33365 (and (=> (and $x31314 c_27_8) (= ghost_2_27 0)) (=> $x31297 $x33485)))))
 (let (($x33585 (and $x33487 $x33575)))
 (let (($x33645 (and $x33585 $x33650)))
 (let (($x33782 (and $x33645 $x33777)))
 (let (($x33856 (and $x33782 (and (=> (and $x31474 c_31_8) (= ghost_2_31 0)) (=> $x31457 $x33848)))))
 (let (($x33926 (and $x33856 $x33921)))
 (let (($x34026 (and $x33926 (and (=> (and $x31574 c_33_8) (= ghost_2_33 0)) (=> $x31557 $x34023)))))
 (let (($x34096 (and $x34026 $x34093)))
 (let (($x34194 (and $x34096 $x34192)))
 (let (($x34266 (and $x34194 $x34265)))
 (let (($x34335 (and $x34266 $x34334)))
 (let (($x34497 (and $x34335 $x34494)))
 (let (($x34599 (and $x34497 $x34594)))
 (let (($x34694 (and $x34599 $x34692)))
 (let (($x34763 (and $x34694 $x34762)))
 (let (($x34862 (and $x34763 $x34863)))
 (let (($x34931 (and $x34862 $x34933)))
 (let (($x35039 (and $x34931 $x35023)))
 (let (($x35101 (and $x35039 $x35087)))
 (let (($x35171 (and $x35101 $x35173)))
 (let (($x35309 (and $x35171 $x35303)))
 (let (($x35397 (and $x35309 $x35402)))
 (let (($x35476 (and $x35397 $x35471)))
 (let (($x35600 (and $x35476 $x35603)))
 (let (($x35700 (and $x35600 $x35703)))
 (let (($x35774 (and $x35700 $x35770)))
 (let (($x35875 (and $x35774 $x35873)))
 (let (($x35945 (and $x35875 $x35927)))
 (let (($x36019 (and $x35945 $x36014)))
 (let (($x36118 (and $x36019 $x36115)))
 (let (($x36188 (and $x36118 $x36177)))
 (let (($x36248 (and $x36188 $x36245)))
 (let (($x36343 (and $x36248 $x36355)))
 (let (($x36429 (and $x36343 $x36422)))
 (let (($x36490 (and $x36429 $x36494)))
 (let (($x38490 (and (and (and $x36490 $x36565) $x38486) (not (or $x38456 (and $x36806 (and $x37845 $x38480)))))))
 (let (($x38493 (or (and $x38490 (not (or $x36761 (and (and $x36741 $x36562) (or $x36758 $x36765))))) (or false $x30061))))
 (let (($x30032 (or c_128_2 c_128_3 c_128_4 c_128_5 c_128_6 c_128_7 c_128_8)))
 (let (($x30030 (not $x30032)))
 (let (($x29999 (= ghost_1_62 1)))
 (let (($x30025 (and $x30032 $x29999)))
 (let (($x29987 (or c_127_2 c_127_3 c_127_4 c_127_5 c_127_6 c_127_7 c_127_8)))
 (let (($x29986 (not $x29987)))
 (let (($x29984 (and c_127_1 $x29986)))
 (let (($x30020 (and $x29987 $x29999)))
 (let (($x29707 (or c_119_2 c_119_3 c_119_4 c_119_5 c_119_6 c_119_7 c_119_8)))
 (let (($x29706 (not $x29707)))
 (let (($x29705 (and c_119_1 $x29706)))
 (let (($x30014 (and $x29707 $x29999)))
 (let (($x27272 (or c_24_2 c_24_3 c_24_4 c_24_5 c_24_6 c_24_7 c_24_8)))
 (let (($x27268 (not $x27272)))
 (let (($x27269 (and c_24_1 $x27268)))
 (let (($x30009 (and $x27272 $x29999)))
 (let (($x29267 (or c_103_2 c_103_3 c_103_4 c_103_5 c_103_6 c_103_7 c_103_8)))
 (let (($x29264 (not $x29267)))
 (let (($x29263 (and c_103_1 $x29264)))
 (let (($x30001 (and $x29267 $x29999)))
 (let (($x28827 (or c_87_2 c_87_3 c_87_4 c_87_5 c_87_6 c_87_7 c_87_8)))
 (let (($x28824 (not $x28827)))
 (let (($x28826 (and c_87_1 $x28824)))
 (let (($x30005 (or (or false (and $x28827 $x29999)) (and $x28826 (= ghost_1_87 (- ghost_1_62 1))))))
 (let (($x30008 (or (or $x30005 $x30001) (and $x29263 (= ghost_1_103 (- ghost_1_62 1))))))
 (let (($x30013 (or (or $x30008 $x30009) (and $x27269 (= ghost_1_24 (- ghost_1_62 1))))))
 (let (($x30021 (or (or $x30013 $x30014) (and $x29705 (= ghost_1_119 (- ghost_1_62 1))))))
 (let (($x30026 (or (or $x30021 $x30020) (and $x29984 (= ghost_1_127 (- ghost_1_62 1))))))
 (let (($x30034 (or (or $x30026 $x30025) (and (and c_128_1 $x30030) (= ghost_1_128 (- ghost_1_62 1))))))
 (let (($x30037 (>= ghost_1_62 1)))
 (let (($x28182 (or c_62_2 c_62_3 c_62_4 c_62_5 c_62_6 c_62_7 c_62_8)))
 (let (($x28178 (not $x28182)))
 (let (($x28179 (and c_62_1 $x28178)))
 (let (($x30039 (and (=> (and c_62_1 $x28182) (= ghost_1_62 0)) (=> $x28179 (and $x30037 $x30034)))))
 (let (($x29953 (= ghost_1_61 1)))
 (let (($x29980 (and $x29987 $x29953)))
 (let (($x29942 (or c_126_2 c_126_3 c_126_4 c_126_5 c_126_6 c_126_7 c_126_8)))
 (let (($x29941 (not $x29942)))
 (let (($x29938 (and c_126_1 $x29941)))
 (let (($x29974 (and $x29942 $x29953)))
 (let (($x29662 (or c_118_2 c_118_3 c_118_4 c_118_5 c_118_6 c_118_7 c_118_8)))
 (let (($x29660 (not $x29662)))
 (let (($x29659 (and c_118_1 $x29660)))
 (let (($x29971 (and $x29662 $x29953)))
 (let (($x27227 (or c_23_2 c_23_3 c_23_4 c_23_5 c_23_6 c_23_7 c_23_8)))
 (let (($x27223 (not $x27227)))
 (let (($x27226 (and c_23_1 $x27223)))
 (let (($x29964 (and $x27227 $x29953)))
 (let (($x29959 (and $x27272 $x29953)))
 (let (($x28782 (or c_86_2 c_86_3 c_86_4 c_86_5 c_86_6 c_86_7 c_86_8)))
 (let (($x28781 (not $x28782)))
 (let (($x28779 (and c_86_1 $x28781)))
 (let (($x29958 (or (or false (and $x28782 $x29953)) (and $x28779 (= ghost_1_86 (- ghost_1_61 1))))))
 (let (($x29963 (or (or $x29958 $x29959) (and $x27269 (= ghost_1_24 (- ghost_1_61 1))))))
 (let (($x29968 (or (or $x29963 $x29964) (and $x27226 (= ghost_1_23 (- ghost_1_61 1))))))
 (let (($x29975 (or (or $x29968 $x29971) (and $x29659 (= ghost_1_118 (- ghost_1_61 1))))))
 (let (($x29981 (or (or $x29975 $x29974) (and $x29938 (= ghost_1_126 (- ghost_1_61 1))))))
 (let (($x29983 (or (or $x29981 $x29980) (and $x29984 (= ghost_1_127 (- ghost_1_61 1))))))
 (let (($x29994 (>= ghost_1_61 1)))
 (let (($x28137 (or c_61_2 c_61_3 c_61_4 c_61_5 c_61_6 c_61_7 c_61_8)))
 (let (($x28135 (not $x28137)))
 (let (($x28136 (and c_61_1 $x28135)))
 (let (($x29993 (and (=> (and c_61_1 $x28137) (= ghost_1_61 0)) (=> $x28136 (and $x29994 $x29983)))))
 (let (($x29908 (= ghost_1_60 1)))
 (let (($x29936 (and $x29942 $x29908)))
 (let (($x29897 (or c_125_2 c_125_3 c_125_4 c_125_5 c_125_6 c_125_7 c_125_8)))
 (let (($x29893 (not $x29897)))
 (let (($x29894 (and c_125_1 $x29893)))
 (let (($x29928 (and $x29897 $x29908)))
 (let (($x29617 (or c_117_2 c_117_3 c_117_4 c_117_5 c_117_6 c_117_7 c_117_8)))
 (let (($x29616 (not $x29617)))
 (let (($x29613 (and c_117_1 $x29616)))
 (let (($x29925 (and $x29617 $x29908)))
 (let (($x27217 (or c_22_2 c_22_3 c_22_4 c_22_5 c_22_6 c_22_7 c_22_8)))
 (let (($x27213 (not $x27217)))
 (let (($x27215 (and c_22_1 $x27213)))
 (let (($x29921 (and $x27217 $x29908)))
 (let (($x29914 (and $x27227 $x29908)))
 (let (($x28737 (or c_85_2 c_85_3 c_85_4 c_85_5 c_85_6 c_85_7 c_85_8)))
 (let (($x28733 (not $x28737)))
 (let (($x28736 (and c_85_1 $x28733)))
 (let (($x29915 (or (or false (and $x28737 $x29908)) (and $x28736 (= ghost_1_85 (- ghost_1_60 1))))))
 (let (($x29918 (or (or $x29915 $x29914) (and $x27226 (= ghost_1_23 (- ghost_1_60 1))))))
 (let (($x29924 (or (or $x29918 $x29921) (and $x27215 (= ghost_1_22 (- ghost_1_60 1))))))
 (let (($x29931 (or (or $x29924 $x29925) (and $x29613 (= ghost_1_117 (- ghost_1_60 1))))))
 (let (($x29933 (or (or $x29931 $x29928) (and $x29894 (= ghost_1_125 (- ghost_1_60 1))))))
 (let (($x29940 (or (or $x29933 $x29936) (and $x29938 (= ghost_1_126 (- ghost_1_60 1))))))
 (let (($x29950 (>= ghost_1_60 1)))
 (let (($x28092 (or c_60_2 c_60_3 c_60_4 c_60_5 c_60_6 c_60_7 c_60_8)))
 (let (($x28091 (not $x28092)))
 (let (($x28090 (and c_60_1 $x28091)))
 (let (($x29947 (and (=> (and c_60_1 $x28092) (= ghost_1_60 0)) (=> $x28090 (and $x29950 $x29940)))))
 (let (($x29857 (= ghost_1_59 1)))
 (let (($x29891 (and $x29897 $x29857)))
 (let (($x29887 (or c_124_2 c_124_3 c_124_4 c_124_5 c_124_6 c_124_7 c_124_8)))
 (let (($x29884 (not $x29887)))
 (let (($x29877 (and $x29887 $x29857)))
 (let (($x29607 (or c_116_2 c_116_3 c_116_4 c_116_5 c_116_6 c_116_7 c_116_8)))
 (let (($x29603 (not $x29607)))
 (let (($x29605 (and c_116_1 $x29603)))
 (let (($x29876 (and $x29607 $x29857)))
 (let (($x29842 (or c_123_2 c_123_3 c_123_4 c_123_5 c_123_6 c_123_7 c_123_8)))
 (let (($x29839 (not $x29842)))
 (let (($x29841 (and c_123_1 $x29839)))
 (let (($x29870 (and $x29842 $x29857)))
 (let (($x29865 (and $x27217 $x29857)))
 (let (($x28727 (or c_84_2 c_84_3 c_84_4 c_84_5 c_84_6 c_84_7 c_84_8)))
 (let (($x28723 (not $x28727)))
 (let (($x28724 (and c_84_1 $x28723)))
 (let (($x29863 (or (or false (and $x28727 $x29857)) (and $x28724 (= ghost_1_84 (- ghost_1_59 1))))))
 (let (($x29869 (or (or $x29863 $x29865) (and $x27215 (= ghost_1_22 (- ghost_1_59 1))))))
 (let (($x29873 (or (or $x29869 $x29870) (and $x29841 (= ghost_1_123 (- ghost_1_59 1))))))
 (let (($x29879 (or (or $x29873 $x29876) (and $x29605 (= ghost_1_116 (- ghost_1_59 1))))))
 (let (($x29888 (or (or $x29879 $x29877) (and (and c_124_1 $x29884) (= ghost_1_124 (- ghost_1_59 1))))))
 (let (($x29898 (or (or $x29888 $x29891) (and $x29894 (= ghost_1_125 (- ghost_1_59 1))))))
 (let (($x29905 (>= ghost_1_59 1)))
 (let (($x28082 (or c_59_2 c_59_3 c_59_4 c_59_5 c_59_6 c_59_7 c_59_8)))
 (let (($x28081 (not $x28082)))
 (let (($x28080 (and c_59_1 $x28081)))
 (let (($x29903 (and (=> (and c_59_1 $x28082) (= ghost_1_59 0)) (=> $x28080 (and $x29905 $x29898)))))
 (let (($x29814 (= ghost_1_58 1)))
 (let (($x29843 (and $x27217 $x29814)))
 (let (($x29832 (and $x29842 $x29814)))
 (let (($x29412 (or c_109_2 c_109_3 c_109_4 c_109_5 c_109_6 c_109_7 c_109_8)))
 (let (($x29411 (not $x29412)))
 (let (($x29410 (and c_109_1 $x29411)))
 (let (($x29827 (and $x29412 $x29814)))
 (let (($x29797 (or c_122_2 c_122_3 c_122_4 c_122_5 c_122_6 c_122_7 c_122_8)))
 (let (($x29795 (not $x29797)))
 (let (($x29793 (and c_122_1 $x29795)))
 (let (($x29826 (and $x29797 $x29814)))
 (let (($x27172 (or c_21_2 c_21_3 c_21_4 c_21_5 c_21_6 c_21_7 c_21_8)))
 (let (($x27170 (not $x27172)))
 (let (($x27171 (and c_21_1 $x27170)))
 (let (($x29818 (and $x27172 $x29814)))
 (let (($x28682 (or c_83_2 c_83_3 c_83_4 c_83_5 c_83_6 c_83_7 c_83_8)))
 (let (($x28680 (not $x28682)))
 (let (($x28681 (and c_83_1 $x28680)))
 (let (($x29820 (or (or false (and $x28682 $x29814)) (and $x28681 (= ghost_1_83 (- ghost_1_58 1))))))
 (let (($x29825 (or (or $x29820 $x29818) (and $x27171 (= ghost_1_21 (- ghost_1_58 1))))))
 (let (($x29830 (or (or $x29825 $x29826) (and $x29793 (= ghost_1_122 (- ghost_1_58 1))))))
 (let (($x29836 (or (or $x29830 $x29827) (and $x29410 (= ghost_1_109 (- ghost_1_58 1))))))
 (let (($x29838 (or (or $x29836 $x29832) (and $x29841 (= ghost_1_123 (- ghost_1_58 1))))))
 (let (($x29849 (or (or $x29838 $x29843) (and $x27215 (= ghost_1_22 (- ghost_1_58 1))))))
 (let (($x29854 (>= ghost_1_58 1)))
 (let (($x28037 (or c_58_2 c_58_3 c_58_4 c_58_5 c_58_6 c_58_7 c_58_8)))
 (let (($x28035 (not $x28037)))
 (let (($x28034 (and c_58_1 $x28035)))
 (let (($x29852 (and (=> (and c_58_1 $x28037) (= ghost_1_58 0)) (=> $x28034 (and $x29854 $x29849)))))
 (let (($x29766 (= ghost_1_57 1)))
 (let (($x29799 (and $x27172 $x29766)))
 (let (($x29791 (and $x29797 $x29766)))
 (let (($x29317 (or c_106_2 c_106_3 c_106_4 c_106_5 c_106_6 c_106_7 c_106_8)))
 (let (($x29315 (not $x29317)))
 (let (($x29314 (and c_106_1 $x29315)))
 (let (($x29783 (and $x29317 $x29766)))
 (let (($x29752 (or c_121_2 c_121_3 c_121_4 c_121_5 c_121_6 c_121_7 c_121_8)))
 (let (($x29751 (not $x29752)))
 (let (($x29748 (and c_121_1 $x29751)))
 (let (($x29781 (and $x29752 $x29766)))
 (let (($x27157 (or c_20_2 c_20_3 c_20_4 c_20_5 c_20_6 c_20_7 c_20_8)))
 (let (($x27155 (not $x27157)))
 (let (($x27156 (and c_20_1 $x27155)))
 (let (($x29775 (and $x27157 $x29766)))
 (let (($x28637 (or c_82_2 c_82_3 c_82_4 c_82_5 c_82_6 c_82_7 c_82_8)))
 (let (($x28635 (not $x28637)))
 (let (($x28633 (and c_82_1 $x28635)))
 (let (($x29770 (or (or false (and $x28637 $x29766)) (and $x28633 (= ghost_1_82 (- ghost_1_57 1))))))
 (let (($x29780 (or (or $x29770 $x29775) (and $x27156 (= ghost_1_20 (- ghost_1_57 1))))))
 (let (($x29786 (or (or $x29780 $x29781) (and $x29748 (= ghost_1_121 (- ghost_1_57 1))))))
 (let (($x29790 (or (or $x29786 $x29783) (and $x29314 (= ghost_1_106 (- ghost_1_57 1))))))
 (let (($x29796 (or (or $x29790 $x29791) (and $x29793 (= ghost_1_122 (- ghost_1_57 1))))))
 (let (($x29805 (or (or $x29796 $x29799) (and $x27171 (= ghost_1_21 (- ghost_1_57 1))))))
 (let (($x29809 (>= ghost_1_57 1)))
 (let (($x27992 (or c_57_2 c_57_3 c_57_4 c_57_5 c_57_6 c_57_7 c_57_8)))
 (let (($x27990 (not $x27992)))
 (let (($x27991 (and c_57_1 $x27990)))
 (let (($x29807 (and (=> (and c_57_1 $x27992) (= ghost_1_57 0)) (=> $x27991 (and $x29809 $x29805)))))
 (let (($x29719 (= ghost_1_56 1)))
 (let (($x29749 (and $x27157 $x29719)))
 (let (($x29745 (and $x29752 $x29719)))
 (let (($x29297 (or c_104_2 c_104_3 c_104_4 c_104_5 c_104_6 c_104_7 c_104_8)))
 (let (($x29294 (not $x29297)))
 (let (($x29296 (and c_104_1 $x29294)))
 (let (($x29734 (and $x29297 $x29719)))
 (let (($x29737 (or c_120_2 c_120_3 c_120_4 c_120_5 c_120_6 c_120_7 c_120_8)))
 (let (($x29735 (not $x29737)))
 (let (($x29731 (and $x29737 $x29719)))
 (let (($x29062 (or c_97_2 c_97_3 c_97_4 c_97_5 c_97_6 c_97_7 c_97_8)))
 (let (($x29058 (not $x29062)))
 (let (($x29059 (and c_97_1 $x29058)))
 (let (($x29722 (and $x29062 $x29719)))
 (let (($x28622 (or c_81_2 c_81_3 c_81_4 c_81_5 c_81_6 c_81_7 c_81_8)))
 (let (($x28620 (not $x28622)))
 (let (($x28619 (and c_81_1 $x28620)))
 (let (($x29723 (or (or false (and $x28622 $x29719)) (and $x28619 (= ghost_1_81 (- ghost_1_56 1))))))
 (let (($x29728 (or (or $x29723 $x29722) (and $x29059 (= ghost_1_97 (- ghost_1_56 1))))))
 (let (($x29739 (or (or $x29728 $x29731) (and (and c_120_1 $x29735) (= ghost_1_120 (- ghost_1_56 1))))))
 (let (($x29743 (or (or $x29739 $x29734) (and $x29296 (= ghost_1_104 (- ghost_1_56 1))))))
 (let (($x29753 (or (or $x29743 $x29745) (and $x29748 (= ghost_1_121 (- ghost_1_56 1))))))
 (let (($x29760 (or (or $x29753 $x29749) (and $x27156 (= ghost_1_20 (- ghost_1_56 1))))))
 (let (($x29765 (>= ghost_1_56 1)))
 (let (($x27977 (or c_56_2 c_56_3 c_56_4 c_56_5 c_56_6 c_56_7 c_56_8)))
 (let (($x27976 (not $x27977)))
 (let (($x27973 (and c_56_1 $x27976)))
 (let (($x29764 (and (=> (and c_56_1 $x27977) (= ghost_1_56 0)) (=> $x27973 (and $x29765 $x29760)))))
 (let (($x29673 (= ghost_1_55 1)))
 (let (($x29701 (and $x29707 $x29673)))
 (let (($x29696 (and $x29662 $x29673)))
 (let (($x29567 (or c_115_2 c_115_3 c_115_4 c_115_5 c_115_6 c_115_7 c_115_8)))
 (let (($x29563 (not $x29567)))
 (let (($x29566 (and c_115_1 $x29563)))
 (let (($x29684 (and $x29567 $x29673)))
 (let (($x27127 (or c_19_2 c_19_3 c_19_4 c_19_5 c_19_6 c_19_7 c_19_8)))
 (let (($x27125 (not $x27127)))
 (let (($x27124 (and c_19_1 $x27125)))
 (let (($x29685 (and $x27127 $x29673)))
 (let (($x29222 (or c_102_2 c_102_3 c_102_4 c_102_5 c_102_6 c_102_7 c_102_8)))
 (let (($x29219 (not $x29222)))
 (let (($x29220 (and c_102_1 $x29219)))
 (let (($x29679 (and $x29222 $x29673)))
 (let (($x29678 (or (or false (and $x27272 $x29673)) (and $x27269 (= ghost_1_24 (- ghost_1_55 1))))))
 (let (($x29681 (or (or $x29678 $x29679) (and $x29220 (= ghost_1_102 (- ghost_1_55 1))))))
 (let (($x29690 (or (or $x29681 $x29685) (and $x27124 (= ghost_1_19 (- ghost_1_55 1))))))
 (let (($x29693 (or (or $x29690 $x29684) (and $x29566 (= ghost_1_115 (- ghost_1_55 1))))))
 (let (($x29700 (or (or $x29693 $x29696) (and $x29659 (= ghost_1_118 (- ghost_1_55 1))))))
 (let (($x29703 (or (or $x29700 $x29701) (and $x29705 (= ghost_1_119 (- ghost_1_55 1))))))
 (let (($x29712 (>= ghost_1_55 1)))
 (let (($x27947 (or c_55_2 c_55_3 c_55_4 c_55_5 c_55_6 c_55_7 c_55_8)))
 (let (($x27943 (not $x27947)))
 (let (($x27946 (and c_55_1 $x27943)))
 (let (($x29714 (and (=> (and c_55_1 $x27947) (= ghost_1_55 0)) (=> $x27946 (and $x29712 $x29703)))))
 (let (($x29628 (= ghost_1_54 1)))
 (let (($x29652 (and $x29662 $x29628)))
 (let (($x29651 (and $x29617 $x29628)))
 (let (($x29522 (or c_114_2 c_114_3 c_114_4 c_114_5 c_114_6 c_114_7 c_114_8)))
 (let (($x29520 (not $x29522)))
 (let (($x29521 (and c_114_1 $x29520)))
 (let (($x29644 (and $x29522 $x29628)))
 (let (($x27117 (or c_18_2 c_18_3 c_18_4 c_18_5 c_18_6 c_18_7 c_18_8)))
 (let (($x27113 (not $x27117)))
 (let (($x27114 (and c_18_1 $x27113)))
 (let (($x29636 (and $x27117 $x29628)))
 (let (($x29634 (and $x27127 $x29628)))
 (let (($x29635 (or (or false (and $x27227 $x29628)) (and $x27226 (= ghost_1_23 (- ghost_1_54 1))))))
 (let (($x29640 (or (or $x29635 $x29634) (and $x27124 (= ghost_1_19 (- ghost_1_54 1))))))
 (let (($x29643 (or (or $x29640 $x29636) (and $x27114 (= ghost_1_18 (- ghost_1_54 1))))))
 (let (($x29650 (or (or $x29643 $x29644) (and $x29521 (= ghost_1_114 (- ghost_1_54 1))))))
 (let (($x29656 (or (or $x29650 $x29651) (and $x29613 (= ghost_1_117 (- ghost_1_54 1))))))
 (let (($x29658 (or (or $x29656 $x29652) (and $x29659 (= ghost_1_118 (- ghost_1_54 1))))))
 (let (($x29667 (>= ghost_1_54 1)))
 (let (($x27902 (or c_54_2 c_54_3 c_54_4 c_54_5 c_54_6 c_54_7 c_54_8)))
 (let (($x27898 (not $x27902)))
 (let (($x27900 (and c_54_1 $x27898)))
 (let (($x29668 (and (=> (and c_54_1 $x27902) (= ghost_1_54 0)) (=> $x27900 (and $x29667 $x29658)))))
 (let (($x29579 (= ghost_1_53 1)))
 (let (($x29611 (and $x29617 $x29579)))
 (let (($x29601 (and $x29607 $x29579)))
 (let (($x29512 (or c_113_2 c_113_3 c_113_4 c_113_5 c_113_6 c_113_7 c_113_8)))
 (let (($x29509 (not $x29512)))
 (let (($x29510 (and c_113_1 $x29509)))
 (let (($x29595 (and $x29512 $x29579)))
 (let (($x29589 (and $x29412 $x29579)))
 (let (($x29585 (and $x27117 $x29579)))
 (let (($x29584 (or (or false (and $x27217 $x29579)) (and $x27215 (= ghost_1_22 (- ghost_1_53 1))))))
 (let (($x29588 (or (or $x29584 $x29585) (and $x27114 (= ghost_1_18 (- ghost_1_53 1))))))
 (let (($x29596 (or (or $x29588 $x29589) (and $x29410 (= ghost_1_109 (- ghost_1_53 1))))))
 (let (($x29599 (or (or $x29596 $x29595) (and $x29510 (= ghost_1_113 (- ghost_1_53 1))))))
 (let (($x29609 (or (or $x29599 $x29601) (and $x29605 (= ghost_1_116 (- ghost_1_53 1))))))
 (let (($x29618 (or (or $x29609 $x29611) (and $x29613 (= ghost_1_117 (- ghost_1_53 1))))))
 (let (($x29625 (>= ghost_1_53 1)))
 (let (($x27892 (or c_53_2 c_53_3 c_53_4 c_53_5 c_53_6 c_53_7 c_53_8)))
 (let (($x27891 (not $x27892)))
 (let (($x27890 (and c_53_1 $x27891)))
 (let (($x29622 (and (=> (and c_53_1 $x27892) (= ghost_1_53 0)) (=> $x27890 (and $x29625 $x29618)))))
 (let (($x29531 (= ghost_1_52 1)))
 (let (($x29557 (and $x29567 $x29531)))
 (let (($x29554 (and $x29522 $x29531)))
 (let (($x29472 (or c_112_2 c_112_3 c_112_4 c_112_5 c_112_6 c_112_7 c_112_8)))
 (let (($x29470 (not $x29472)))
 (let (($x29468 (and c_112_1 $x29470)))
 (let (($x29549 (and $x29472 $x29531)))
 (let (($x27107 (or c_17_2 c_17_3 c_17_4 c_17_5 c_17_6 c_17_7 c_17_8)))
 (let (($x27105 (not $x27107)))
 (let (($x27104 (and c_17_1 $x27105)))
 (let (($x29546 (and $x27107 $x29531)))
 (let (($x29177 (or c_101_2 c_101_3 c_101_4 c_101_5 c_101_6 c_101_7 c_101_8)))
 (let (($x29173 (not $x29177)))
 (let (($x29176 (and c_101_1 $x29173)))
 (let (($x29540 (and $x29177 $x29531)))
 (let (($x29538 (or (or false (and $x27127 $x29531)) (and $x27124 (= ghost_1_19 (- ghost_1_52 1))))))
 (let (($x29543 (or (or $x29538 $x29540) (and $x29176 (= ghost_1_101 (- ghost_1_52 1))))))
 (let (($x29550 (or (or $x29543 $x29546) (and $x27104 (= ghost_1_17 (- ghost_1_52 1))))))
 (let (($x29555 (or (or $x29550 $x29549) (and $x29468 (= ghost_1_112 (- ghost_1_52 1))))))
 (let (($x29560 (or (or $x29555 $x29554) (and $x29521 (= ghost_1_114 (- ghost_1_52 1))))))
 (let (($x29568 (or (or $x29560 $x29557) (and $x29566 (= ghost_1_115 (- ghost_1_52 1))))))
 (let (($x29574 (>= ghost_1_52 1)))
 (let (($x27852 (or c_52_2 c_52_3 c_52_4 c_52_5 c_52_6 c_52_7 c_52_8)))
 (let (($x27850 (not $x27852)))
 (let (($x27851 (and c_52_1 $x27850)))
 (let (($x29572 (and (=> (and c_52_1 $x27852) (= ghost_1_52 0)) (=> $x27851 (and $x29574 $x29568)))))
 (let (($x29483 (= ghost_1_51 1)))
 (let (($x29516 (and $x29522 $x29483)))
 (let (($x29502 (and $x29512 $x29483)))
 (let (($x29462 (or c_111_2 c_111_3 c_111_4 c_111_5 c_111_6 c_111_7 c_111_8)))
 (let (($x29460 (not $x29462)))
 (let (($x29461 (and c_111_1 $x29460)))
 (let (($x29501 (and $x29462 $x29483)))
 (let (($x29367 (or c_108_2 c_108_3 c_108_4 c_108_5 c_108_6 c_108_7 c_108_8)))
 (let (($x29363 (not $x29367)))
 (let (($x29366 (and c_108_1 $x29363)))
 (let (($x29494 (and $x29367 $x29483)))
 (let (($x29489 (and $x27107 $x29483)))
 (let (($x29488 (or (or false (and $x27117 $x29483)) (and $x27114 (= ghost_1_18 (- ghost_1_51 1))))))
 (let (($x29495 (or (or $x29488 $x29489) (and $x27104 (= ghost_1_17 (- ghost_1_51 1))))))
 (let (($x29498 (or (or $x29495 $x29494) (and $x29366 (= ghost_1_108 (- ghost_1_51 1))))))
 (let (($x29505 (or (or $x29498 $x29501) (and $x29461 (= ghost_1_111 (- ghost_1_51 1))))))
 (let (($x29508 (or (or $x29505 $x29502) (and $x29510 (= ghost_1_113 (- ghost_1_51 1))))))
 (let (($x29518 (or (or $x29508 $x29516) (and $x29521 (= ghost_1_114 (- ghost_1_51 1))))))
 (let (($x29528 (>= ghost_1_51 1)))
 (let (($x27842 (or c_51_2 c_51_3 c_51_4 c_51_5 c_51_6 c_51_7 c_51_8)))
 (let (($x27839 (not $x27842)))
 (let (($x27838 (and c_51_1 $x27839)))
 (let (($x29529 (and (=> (and c_51_1 $x27842) (= ghost_1_51 0)) (=> $x27838 (and $x29528 $x29518)))))
 (let (($x29428 (= ghost_1_50 1)))
 (let (($x29466 (and $x29472 $x29428)))
 (let (($x29456 (and $x29462 $x29428)))
 (let (($x29452 (or c_110_2 c_110_3 c_110_4 c_110_5 c_110_6 c_110_7 c_110_8)))
 (let (($x29449 (not $x29452)))
 (let (($x29443 (and $x29452 $x29428)))
 (let (($x29357 (or c_107_2 c_107_3 c_107_4 c_107_5 c_107_6 c_107_7 c_107_8)))
 (let (($x29356 (not $x29357)))
 (let (($x29354 (and c_107_1 $x29356)))
 (let (($x29440 (and $x29357 $x29428)))
 (let (($x29162 (or c_100_2 c_100_3 c_100_4 c_100_5 c_100_6 c_100_7 c_100_8)))
 (let (($x29161 (not $x29162)))
 (let (($x29160 (and c_100_1 $x29161)))
 (let (($x29432 (and $x29162 $x29428)))
 (let (($x29433 (or (or false (and $x27107 $x29428)) (and $x27104 (= ghost_1_17 (- ghost_1_50 1))))))
 (let (($x29441 (or (or $x29433 $x29432) (and $x29160 (= ghost_1_100 (- ghost_1_50 1))))))
 (let (($x29446 (or (or $x29441 $x29440) (and $x29354 (= ghost_1_107 (- ghost_1_50 1))))))
 (let (($x29453 (or (or $x29446 $x29443) (and (and c_110_1 $x29449) (= ghost_1_110 (- ghost_1_50 1))))))
 (let (($x29458 (or (or $x29453 $x29456) (and $x29461 (= ghost_1_111 (- ghost_1_50 1))))))
 (let (($x29474 (or (or $x29458 $x29466) (and $x29468 (= ghost_1_112 (- ghost_1_50 1))))))
 (let (($x29478 (>= ghost_1_50 1)))
 (let (($x27832 (or c_50_2 c_50_3 c_50_4 c_50_5 c_50_6 c_50_7 c_50_8)))
 (let (($x27829 (not $x27832)))
 (let (($x27830 (and c_50_1 $x27829)))
 (let (($x29480 (and (=> (and c_50_1 $x27832) (= ghost_1_50 0)) (=> $x27830 (and $x29478 $x29474)))))
 (let (($x29384 (= ghost_1_49 1)))
 (let (($x29409 (and $x27117 $x29384)))
 (let (($x29402 (and $x29412 $x29384)))
 (let (($x29399 (and $x29367 $x29384)))
 (let (($x29393 (and $x29317 $x29384)))
 (let (($x27097 (or c_16_2 c_16_3 c_16_4 c_16_5 c_16_6 c_16_7 c_16_8)))
 (let (($x27094 (not $x27097)))
 (let (($x27093 (and c_16_1 $x27094)))
 (let (($x29388 (and $x27097 $x29384)))
 (let (($x29390 (or (or false (and $x27172 $x29384)) (and $x27171 (= ghost_1_21 (- ghost_1_49 1))))))
 (let (($x29394 (or (or $x29390 $x29388) (and $x27093 (= ghost_1_16 (- ghost_1_49 1))))))
 (let (($x29400 (or (or $x29394 $x29393) (and $x29314 (= ghost_1_106 (- ghost_1_49 1))))))
 (let (($x29403 (or (or $x29400 $x29399) (and $x29366 (= ghost_1_108 (- ghost_1_49 1))))))
 (let (($x29408 (or (or $x29403 $x29402) (and $x29410 (= ghost_1_109 (- ghost_1_49 1))))))
 (let (($x29418 (or (or $x29408 $x29409) (and $x27114 (= ghost_1_18 (- ghost_1_49 1))))))
 (let (($x29422 (>= ghost_1_49 1)))
 (let (($x27792 (or c_49_2 c_49_3 c_49_4 c_49_5 c_49_6 c_49_7 c_49_8)))
 (let (($x27788 (not $x27792)))
 (let (($x27790 (and c_49_1 $x27788)))
 (let (($x29423 (and (=> (and c_49_1 $x27792) (= ghost_1_49 0)) (=> $x27790 (and $x29422 $x29418)))))
 (let (($x29332 (= ghost_1_48 1)))
 (let (($x29364 (and $x27107 $x29332)))
 (let (($x29361 (and $x29367 $x29332)))
 (let (($x29350 (and $x29357 $x29332)))
 (let (($x29307 (or c_105_2 c_105_3 c_105_4 c_105_5 c_105_6 c_105_7 c_105_8)))
 (let (($x29304 (not $x29307)))
 (let (($x29303 (and c_105_1 $x29304)))
 (let (($x29343 (and $x29307 $x29332)))
 (let (($x29117 (or c_99_2 c_99_3 c_99_4 c_99_5 c_99_6 c_99_7 c_99_8)))
 (let (($x29114 (not $x29117)))
 (let (($x29113 (and c_99_1 $x29114)))
 (let (($x29339 (and $x29117 $x29332)))
 (let (($x29337 (or (or false (and $x27097 $x29332)) (and $x27093 (= ghost_1_16 (- ghost_1_48 1))))))
 (let (($x29344 (or (or $x29337 $x29339) (and $x29113 (= ghost_1_99 (- ghost_1_48 1))))))
 (let (($x29348 (or (or $x29344 $x29343) (and $x29303 (= ghost_1_105 (- ghost_1_48 1))))))
 (let (($x29358 (or (or $x29348 $x29350) (and $x29354 (= ghost_1_107 (- ghost_1_48 1))))))
 (let (($x29368 (or (or $x29358 $x29361) (and $x29366 (= ghost_1_108 (- ghost_1_48 1))))))
 (let (($x29375 (or (or $x29368 $x29364) (and $x27104 (= ghost_1_17 (- ghost_1_48 1))))))
 (let (($x29379 (>= ghost_1_48 1)))
 (let (($x27782 (or c_48_2 c_48_3 c_48_4 c_48_5 c_48_6 c_48_7 c_48_8)))
 (let (($x27780 (not $x27782)))
 (let (($x27781 (and c_48_1 $x27780)))
 (let (($x29377 (and (=> (and c_48_1 $x27782) (= ghost_1_48 0)) (=> $x27781 (and $x29379 $x29375)))))
 (let (($x29279 (= ghost_1_47 1)))
 (let (($x29319 (and $x27097 $x29279)))
 (let (($x29311 (and $x29317 $x29279)))
 (let (($x29301 (and $x29307 $x29279)))
 (let (($x29291 (and $x29297 $x29279)))
 (let (($x29072 (or c_98_2 c_98_3 c_98_4 c_98_5 c_98_6 c_98_7 c_98_8)))
 (let (($x29068 (not $x29072)))
 (let (($x29070 (and c_98_1 $x29068)))
 (let (($x29280 (and $x29072 $x29279)))
 (let (($x29285 (or (or false (and $x27157 $x29279)) (and $x27156 (= ghost_1_20 (- ghost_1_47 1))))))
 (let (($x29287 (or (or $x29285 $x29280) (and $x29070 (= ghost_1_98 (- ghost_1_47 1))))))
 (let (($x29293 (or (or $x29287 $x29291) (and $x29296 (= ghost_1_104 (- ghost_1_47 1))))))
 (let (($x29309 (or (or $x29293 $x29301) (and $x29303 (= ghost_1_105 (- ghost_1_47 1))))))
 (let (($x29313 (or (or $x29309 $x29311) (and $x29314 (= ghost_1_106 (- ghost_1_47 1))))))
 (let (($x29324 (or (or $x29313 $x29319) (and $x27093 (= ghost_1_16 (- ghost_1_47 1))))))
 (let (($x29329 (>= ghost_1_47 1)))
 (let (($x27772 (or c_47_2 c_47_3 c_47_4 c_47_5 c_47_6 c_47_7 c_47_8)))
 (let (($x27770 (not $x27772)))
 (let (($x27769 (and c_47_1 $x27770)))
 (let (($x29330 (and (=> (and c_47_1 $x27772) (= ghost_1_47 0)) (=> $x27769 (and $x29329 $x29324)))))
 (let (($x29232 (= ghost_1_46 1)))
 (let (($x29261 (and $x29267 $x29232)))
 (let (($x29255 (and $x27272 $x29232)))
 (let (($x29251 (and $x29222 $x29232)))
 (let (($x27067 (or c_15_2 c_15_3 c_15_4 c_15_5 c_15_6 c_15_7 c_15_8)))
 (let (($x27063 (not $x27067)))
 (let (($x27066 (and c_15_1 $x27063)))
 (let (($x29245 (and $x27067 $x29232)))
 (let (($x29032 (or c_96_2 c_96_3 c_96_4 c_96_5 c_96_6 c_96_7 c_96_8)))
 (let (($x29031 (not $x29032)))
 (let (($x29030 (and c_96_1 $x29031)))
 (let (($x29238 (and $x29032 $x29232)))
 (let (($x28592 (or c_80_2 c_80_3 c_80_4 c_80_5 c_80_6 c_80_7 c_80_8)))
 (let (($x28588 (not $x28592)))
 (let (($x28590 (and c_80_1 $x28588)))
 (let (($x29239 (or (or false (and $x28592 $x29232)) (and $x28590 (= ghost_1_80 (- ghost_1_46 1))))))
 (let (($x29246 (or (or $x29239 $x29238) (and $x29030 (= ghost_1_96 (- ghost_1_46 1))))))
 (let (($x29247 (or (or $x29246 $x29245) (and $x27066 (= ghost_1_15 (- ghost_1_46 1))))))
 (let (($x29250 (or (or $x29247 $x29251) (and $x29220 (= ghost_1_102 (- ghost_1_46 1))))))
 (let (($x29258 (or (or $x29250 $x29255) (and $x27269 (= ghost_1_24 (- ghost_1_46 1))))))
 (let (($x29269 (or (or $x29258 $x29261) (and $x29263 (= ghost_1_103 (- ghost_1_46 1))))))
 (let (($x29272 (>= ghost_1_46 1)))
 (let (($x27742 (or c_46_2 c_46_3 c_46_4 c_46_5 c_46_6 c_46_7 c_46_8)))
 (let (($x27738 (not $x27742)))
 (let (($x27741 (and c_46_1 $x27738)))
 (let (($x29273 (and (=> (and c_46_1 $x27742) (= ghost_1_46 0)) (=> $x27741 (and $x29272 $x29269)))))
 (let (($x29187 (= ghost_1_45 1)))
 (let (($x29214 (and $x29222 $x29187)))
 (let (($x29211 (and $x27127 $x29187)))
 (let (($x29197 (and $x29177 $x29187)))
 (let (($x27052 (or c_14_2 c_14_3 c_14_4 c_14_5 c_14_6 c_14_7 c_14_8)))
 (let (($x27050 (not $x27052)))
 (let (($x27049 (and c_14_1 $x27050)))
 (let (($x29200 (and $x27052 $x29187)))
 (let (($x28987 (or c_95_2 c_95_3 c_95_4 c_95_5 c_95_6 c_95_7 c_95_8)))
 (let (($x28986 (not $x28987)))
 (let (($x28985 (and c_95_1 $x28986)))
 (let (($x29193 (and $x28987 $x29187)))
 (let (($x29195 (or (or false (and $x27067 $x29187)) (and $x27066 (= ghost_1_15 (- ghost_1_45 1))))))
 (let (($x29201 (or (or $x29195 $x29193) (and $x28985 (= ghost_1_95 (- ghost_1_45 1))))))
 (let (($x29205 (or (or $x29201 $x29200) (and $x27049 (= ghost_1_14 (- ghost_1_45 1))))))
 (let (($x29208 (or (or $x29205 $x29197) (and $x29176 (= ghost_1_101 (- ghost_1_45 1))))))
 (let (($x29215 (or (or $x29208 $x29211) (and $x27124 (= ghost_1_19 (- ghost_1_45 1))))))
 (let (($x29224 (or (or $x29215 $x29214) (and $x29220 (= ghost_1_102 (- ghost_1_45 1))))))
 (let (($x29230 (>= ghost_1_45 1)))
 (let (($x27697 (or c_45_2 c_45_3 c_45_4 c_45_5 c_45_6 c_45_7 c_45_8)))
 (let (($x27696 (not $x27697)))
 (let (($x27694 (and c_45_1 $x27696)))
 (let (($x29229 (and (=> (and c_45_1 $x27697) (= ghost_1_45 0)) (=> $x27694 (and $x29230 $x29224)))))
 (let (($x29137 (= ghost_1_44 1)))
 (let (($x29171 (and $x29177 $x29137)))
 (let (($x29159 (and $x27107 $x29137)))
 (let (($x29156 (and $x29162 $x29137)))
 (let (($x29151 (and $x29117 $x29137)))
 (let (($x28972 (or c_94_2 c_94_3 c_94_4 c_94_5 c_94_6 c_94_7 c_94_8)))
 (let (($x28970 (not $x28972)))
 (let (($x28971 (and c_94_1 $x28970)))
 (let (($x29145 (and $x28972 $x29137)))
 (let (($x29143 (or (or false (and $x27052 $x29137)) (and $x27049 (= ghost_1_14 (- ghost_1_44 1))))))
 (let (($x29150 (or (or $x29143 $x29145) (and $x28971 (= ghost_1_94 (- ghost_1_44 1))))))
 (let (($x29154 (or (or $x29150 $x29151) (and $x29113 (= ghost_1_99 (- ghost_1_44 1))))))
 (let (($x29158 (or (or $x29154 $x29156) (and $x29160 (= ghost_1_100 (- ghost_1_44 1))))))
 (let (($x29170 (or (or $x29158 $x29159) (and $x27104 (= ghost_1_17 (- ghost_1_44 1))))))
 (let (($x29178 (or (or $x29170 $x29171) (and $x29176 (= ghost_1_101 (- ghost_1_44 1))))))
 (let (($x29185 (>= ghost_1_44 1)))
 (let (($x27682 (or c_44_2 c_44_3 c_44_4 c_44_5 c_44_6 c_44_7 c_44_8)))
 (let (($x27681 (not $x27682)))
 (let (($x27679 (and c_44_1 $x27681)))
 (let (($x29184 (and (=> (and c_44_1 $x27682) (= ghost_1_44 0)) (=> $x27679 (and $x29185 $x29178)))))
 (let (($x29092 (= ghost_1_43 1)))
 (let (($x29123 (and $x27052 $x29092)))
 (let (($x29119 (and $x27097 $x29092)))
 (let (($x29111 (and $x29117 $x29092)))
 (let (($x29106 (and $x29072 $x29092)))
 (let (($x28927 (or c_93_2 c_93_3 c_93_4 c_93_5 c_93_6 c_93_7 c_93_8)))
 (let (($x28924 (not $x28927)))
 (let (($x28926 (and c_93_1 $x28924)))
 (let (($x29098 (and $x28927 $x29092)))
 (let (($x27042 (or c_13_2 c_13_3 c_13_4 c_13_5 c_13_6 c_13_7 c_13_8)))
 (let (($x27041 (not $x27042)))
 (let (($x27040 (and c_13_1 $x27041)))
 (let (($x29099 (or (or false (and $x27042 $x29092)) (and $x27040 (= ghost_1_13 (- ghost_1_43 1))))))
 (let (($x29103 (or (or $x29099 $x29098) (and $x28926 (= ghost_1_93 (- ghost_1_43 1))))))
 (let (($x29107 (or (or $x29103 $x29106) (and $x29070 (= ghost_1_98 (- ghost_1_43 1))))))
 (let (($x29118 (or (or $x29107 $x29111) (and $x29113 (= ghost_1_99 (- ghost_1_43 1))))))
 (let (($x29124 (or (or $x29118 $x29119) (and $x27093 (= ghost_1_16 (- ghost_1_43 1))))))
 (let (($x29130 (or (or $x29124 $x29123) (and $x27049 (= ghost_1_14 (- ghost_1_43 1))))))
 (let (($x29135 (>= ghost_1_43 1)))
 (let (($x27637 (or c_43_2 c_43_3 c_43_4 c_43_5 c_43_6 c_43_7 c_43_8)))
 (let (($x27636 (not $x27637)))
 (let (($x27634 (and c_43_1 $x27636)))
 (let (($x29134 (and (=> (and c_43_1 $x27637) (= ghost_1_43 0)) (=> $x27634 (and $x29135 $x29130)))))
 (let (($x29044 (= ghost_1_42 1)))
 (let (($x29081 (and $x27042 $x29044)))
 (let (($x29074 (and $x27157 $x29044)))
 (let (($x29066 (and $x29072 $x29044)))
 (let (($x29052 (and $x29062 $x29044)))
 (let (($x28917 (or c_92_2 c_92_3 c_92_4 c_92_5 c_92_6 c_92_7 c_92_8)))
 (let (($x28915 (not $x28917)))
 (let (($x28916 (and c_92_1 $x28915)))
 (let (($x29050 (and $x28917 $x29044)))
 (let (($x28532 (or c_79_2 c_79_3 c_79_4 c_79_5 c_79_6 c_79_7 c_79_8)))
 (let (($x28529 (not $x28532)))
 (let (($x28528 (and c_79_1 $x28529)))
 (let (($x29046 (or (or false (and $x28532 $x29044)) (and $x28528 (= ghost_1_79 (- ghost_1_42 1))))))
 (let (($x29055 (or (or $x29046 $x29050) (and $x28916 (= ghost_1_92 (- ghost_1_42 1))))))
 (let (($x29063 (or (or $x29055 $x29052) (and $x29059 (= ghost_1_97 (- ghost_1_42 1))))))
 (let (($x29071 (or (or $x29063 $x29066) (and $x29070 (= ghost_1_98 (- ghost_1_42 1))))))
 (let (($x29080 (or (or $x29071 $x29074) (and $x27156 (= ghost_1_20 (- ghost_1_42 1))))))
 (let (($x29086 (or (or $x29080 $x29081) (and $x27040 (= ghost_1_13 (- ghost_1_42 1))))))
 (let (($x29089 (>= ghost_1_42 1)))
 (let (($x27627 (or c_42_2 c_42_3 c_42_4 c_42_5 c_42_6 c_42_7 c_42_8)))
 (let (($x27625 (not $x27627)))
 (let (($x27624 (and c_42_1 $x27625)))
 (let (($x29087 (and (=> (and c_42_1 $x27627) (= ghost_1_42 0)) (=> $x27624 (and $x29089 $x29086)))))
 (let (($x28996 (= ghost_1_41 1)))
 (let (($x29025 (and $x29032 $x28996)))
 (let (($x29020 (and $x27067 $x28996)))
 (let (($x29014 (and $x28987 $x28996)))
 (let (($x27032 (or c_12_2 c_12_3 c_12_4 c_12_5 c_12_6 c_12_7 c_12_8)))
 (let (($x27030 (not $x27032)))
 (let (($x27029 (and c_12_1 $x27030)))
 (let (($x29009 (and $x27032 $x28996)))
 (let (($x28887 (or c_91_2 c_91_3 c_91_4 c_91_5 c_91_6 c_91_7 c_91_8)))
 (let (($x28885 (not $x28887)))
 (let (($x28884 (and c_91_1 $x28885)))
 (let (($x29004 (and $x28887 $x28996)))
 (let (($x28502 (or c_78_2 c_78_3 c_78_4 c_78_5 c_78_6 c_78_7 c_78_8)))
 (let (($x28499 (not $x28502)))
 (let (($x28498 (and c_78_1 $x28499)))
 (let (($x29002 (or (or false (and $x28502 $x28996)) (and $x28498 (= ghost_1_78 (- ghost_1_41 1))))))
 (let (($x29010 (or (or $x29002 $x29004) (and $x28884 (= ghost_1_91 (- ghost_1_41 1))))))
 (let (($x29015 (or (or $x29010 $x29009) (and $x27029 (= ghost_1_12 (- ghost_1_41 1))))))
 (let (($x29021 (or (or $x29015 $x29014) (and $x28985 (= ghost_1_95 (- ghost_1_41 1))))))
 (let (($x29022 (or (or $x29021 $x29020) (and $x27066 (= ghost_1_15 (- ghost_1_41 1))))))
 (let (($x29028 (or (or $x29022 $x29025) (and $x29030 (= ghost_1_96 (- ghost_1_41 1))))))
 (let (($x29039 (>= ghost_1_41 1)))
 (let (($x27597 (or c_41_2 c_41_3 c_41_4 c_41_5 c_41_6 c_41_7 c_41_8)))
 (let (($x27595 (not $x27597)))
 (let (($x27596 (and c_41_1 $x27595)))
 (let (($x29038 (and (=> (and c_41_1 $x27597) (= ghost_1_41 0)) (=> $x27596 (and $x29039 $x29028)))))
 (let (($x28947 (= ghost_1_40 1)))
 (let (($x28979 (and $x28987 $x28947)))
 (let (($x28969 (and $x27052 $x28947)))
 (let (($x28965 (and $x28972 $x28947)))
 (let (($x28957 (and $x28927 $x28947)))
 (let (($x28872 (or c_90_2 c_90_3 c_90_4 c_90_5 c_90_6 c_90_7 c_90_8)))
 (let (($x28870 (not $x28872)))
 (let (($x28868 (and c_90_1 $x28870)))
 (let (($x28952 (and $x28872 $x28947)))
 (let (($x28953 (or (or false (and $x27032 $x28947)) (and $x27029 (= ghost_1_12 (- ghost_1_40 1))))))
 (let (($x28960 (or (or $x28953 $x28952) (and $x28868 (= ghost_1_90 (- ghost_1_40 1))))))
 (let (($x28963 (or (or $x28960 $x28957) (and $x28926 (= ghost_1_93 (- ghost_1_40 1))))))
 (let (($x28968 (or (or $x28963 $x28965) (and $x28971 (= ghost_1_94 (- ghost_1_40 1))))))
 (let (($x28980 (or (or $x28968 $x28969) (and $x27049 (= ghost_1_14 (- ghost_1_40 1))))))
 (let (($x28983 (or (or $x28980 $x28979) (and $x28985 (= ghost_1_95 (- ghost_1_40 1))))))
 (let (($x28993 (>= ghost_1_40 1)))
 (let (($x27582 (or c_40_2 c_40_3 c_40_4 c_40_5 c_40_6 c_40_7 c_40_8)))
 (let (($x27579 (not $x27582)))
 (let (($x27578 (and c_40_1 $x27579)))
 (let (($x28994 (and (=> (and c_40_1 $x27582) (= ghost_1_40 0)) (=> $x27578 (and $x28993 $x28983)))))
 (let (($x28896 (= ghost_1_39 1)))
 (let (($x28935 (and $x27032 $x28896)))
 (let (($x28928 (and $x27042 $x28896)))
 (let (($x28921 (and $x28927 $x28896)))
 (let (($x28907 (and $x28917 $x28896)))
 (let (($x28862 (or c_89_2 c_89_3 c_89_4 c_89_5 c_89_6 c_89_7 c_89_8)))
 (let (($x28858 (not $x28862)))
 (let (($x28861 (and c_89_1 $x28858)))
 (let (($x28904 (and $x28862 $x28896)))
 (let (($x28482 (or c_77_2 c_77_3 c_77_4 c_77_5 c_77_6 c_77_7 c_77_8)))
 (let (($x28479 (not $x28482)))
 (let (($x28478 (and c_77_1 $x28479)))
 (let (($x28902 (or (or false (and $x28482 $x28896)) (and $x28478 (= ghost_1_77 (- ghost_1_39 1))))))
 (let (($x28908 (or (or $x28902 $x28904) (and $x28861 (= ghost_1_89 (- ghost_1_39 1))))))
 (let (($x28913 (or (or $x28908 $x28907) (and $x28916 (= ghost_1_92 (- ghost_1_39 1))))))
 (let (($x28923 (or (or $x28913 $x28921) (and $x28926 (= ghost_1_93 (- ghost_1_39 1))))))
 (let (($x28936 (or (or $x28923 $x28928) (and $x27040 (= ghost_1_13 (- ghost_1_39 1))))))
 (let (($x28940 (or (or $x28936 $x28935) (and $x27029 (= ghost_1_12 (- ghost_1_39 1))))))
 (let (($x28945 (>= ghost_1_39 1)))
 (let (($x27572 (or c_39_2 c_39_3 c_39_4 c_39_5 c_39_6 c_39_7 c_39_8)))
 (let (($x27571 (not $x27572)))
 (let (($x27569 (and c_39_1 $x27571)))
 (let (($x28942 (and (=> (and c_39_1 $x27572) (= ghost_1_39 0)) (=> $x27569 (and $x28945 $x28940)))))
 (let (($x28837 (= ghost_1_38 1)))
 (let (($x28881 (and $x28887 $x28837)))
 (let (($x28874 (and $x27032 $x28837)))
 (let (($x28866 (and $x28872 $x28837)))
 (let (($x28856 (and $x28862 $x28837)))
 (let (($x28852 (or c_88_2 c_88_3 c_88_4 c_88_5 c_88_6 c_88_7 c_88_8)))
 (let (($x28851 (not $x28852)))
 (let (($x28846 (and $x28852 $x28837)))
 (let (($x28472 (or c_76_2 c_76_3 c_76_4 c_76_5 c_76_6 c_76_7 c_76_8)))
 (let (($x28471 (not $x28472)))
 (let (($x28469 (and c_76_1 $x28471)))
 (let (($x28843 (or (or false (and $x28472 $x28837)) (and $x28469 (= ghost_1_76 (- ghost_1_38 1))))))
 (let (($x28853 (or (or $x28843 $x28846) (and (and c_88_1 $x28851) (= ghost_1_88 (- ghost_1_38 1))))))
 (let (($x28863 (or (or $x28853 $x28856) (and $x28861 (= ghost_1_89 (- ghost_1_38 1))))))
 (let (($x28871 (or (or $x28863 $x28866) (and $x28868 (= ghost_1_90 (- ghost_1_38 1))))))
 (let (($x28880 (or (or $x28871 $x28874) (and $x27029 (= ghost_1_12 (- ghost_1_38 1))))))
 (let (($x28883 (or (or $x28880 $x28881) (and $x28884 (= ghost_1_91 (- ghost_1_38 1))))))
 (let (($x28894 (>= ghost_1_38 1)))
 (let (($x27562 (or c_38_2 c_38_3 c_38_4 c_38_5 c_38_6 c_38_7 c_38_8)))
 (let (($x27560 (not $x27562)))
 (let (($x27558 (and c_38_1 $x27560)))
 (let (($x28895 (and (=> (and c_38_1 $x27562) (= ghost_1_38 0)) (=> $x27558 (and $x28894 $x28883)))))
 (let (($x28794 (= ghost_1_37 1)))
 (let (($x28818 (and $x28827 $x28794)))
 (let (($x28814 (and $x28782 $x28794)))
 (let (($x28807 (and $x27272 $x28794)))
 (let (($x27007 (or c_11_2 c_11_3 c_11_4 c_11_5 c_11_6 c_11_7 c_11_8)))
 (let (($x27006 (not $x27007)))
 (let (($x27003 (and c_11_1 $x27006)))
 (let (($x28805 (and $x27007 $x28794)))
 (let (($x28799 (and $x28592 $x28794)))
 (let (($x28447 (or c_75_2 c_75_3 c_75_4 c_75_5 c_75_6 c_75_7 c_75_8)))
 (let (($x28444 (not $x28447)))
 (let (($x28443 (and c_75_1 $x28444)))
 (let (($x28797 (or (or false (and $x28447 $x28794)) (and $x28443 (= ghost_1_75 (- ghost_1_37 1))))))
 (let (($x28802 (or (or $x28797 $x28799) (and $x28590 (= ghost_1_80 (- ghost_1_37 1))))))
 (let (($x28811 (or (or $x28802 $x28805) (and $x27003 (= ghost_1_11 (- ghost_1_37 1))))))
 (let (($x28813 (or (or $x28811 $x28807) (and $x27269 (= ghost_1_24 (- ghost_1_37 1))))))
 (let (($x28821 (or (or $x28813 $x28814) (and $x28779 (= ghost_1_86 (- ghost_1_37 1))))))
 (let (($x28823 (or (or $x28821 $x28818) (and $x28826 (= ghost_1_87 (- ghost_1_37 1))))))
 (let (($x28835 (>= ghost_1_37 1)))
 (let (($x27537 (or c_37_2 c_37_3 c_37_4 c_37_5 c_37_6 c_37_7 c_37_8)))
 (let (($x27536 (not $x27537)))
 (let (($x27534 (and c_37_1 $x27536)))
 (let (($x28832 (and (=> (and c_37_1 $x27537) (= ghost_1_37 0)) (=> $x27534 (and $x28835 $x28823)))))
 (let (($x28746 (= ghost_1_36 1)))
 (let (($x28772 (and $x28782 $x28746)))
 (let (($x28771 (and $x28737 $x28746)))
 (let (($x28764 (and $x27227 $x28746)))
 (let (($x26997 (or c_10_2 c_10_3 c_10_4 c_10_5 c_10_6 c_10_7 c_10_8)))
 (let (($x26995 (not $x26997)))
 (let (($x26994 (and c_10_1 $x26995)))
 (let (($x28757 (and $x26997 $x28746)))
 (let (($x28754 (and $x27007 $x28746)))
 (let (($x28402 (or c_74_2 c_74_3 c_74_4 c_74_5 c_74_6 c_74_7 c_74_8)))
 (let (($x28398 (not $x28402)))
 (let (($x28401 (and c_74_1 $x28398)))
 (let (($x28755 (or (or false (and $x28402 $x28746)) (and $x28401 (= ghost_1_74 (- ghost_1_36 1))))))
 (let (($x28761 (or (or $x28755 $x28754) (and $x27003 (= ghost_1_11 (- ghost_1_36 1))))))
 (let (($x28765 (or (or $x28761 $x28757) (and $x26994 (= ghost_1_10 (- ghost_1_36 1))))))
 (let (($x28768 (or (or $x28765 $x28764) (and $x27226 (= ghost_1_23 (- ghost_1_36 1))))))
 (let (($x28773 (or (or $x28768 $x28771) (and $x28736 (= ghost_1_85 (- ghost_1_36 1))))))
 (let (($x28783 (or (or $x28773 $x28772) (and $x28779 (= ghost_1_86 (- ghost_1_36 1))))))
 (let (($x28789 (>= ghost_1_36 1)))
 (let (($x27492 (or c_36_2 c_36_3 c_36_4 c_36_5 c_36_6 c_36_7 c_36_8)))
 (let (($x27490 (not $x27492)))
 (let (($x27491 (and c_36_1 $x27490)))
 (let (($x28787 (and (=> (and c_36_1 $x27492) (= ghost_1_36 0)) (=> $x27491 (and $x28789 $x28783)))))
 (let (($x28698 (= ghost_1_35 1)))
 (let (($x28731 (and $x28737 $x28698)))
 (let (($x28717 (and $x28727 $x28698)))
 (let (($x28716 (and $x27217 $x28698)))
 (let (($x28709 (and $x28682 $x28698)))
 (let (($x28704 (and $x26997 $x28698)))
 (let (($x28392 (or c_73_2 c_73_3 c_73_4 c_73_5 c_73_6 c_73_7 c_73_8)))
 (let (($x28389 (not $x28392)))
 (let (($x28388 (and c_73_1 $x28389)))
 (let (($x28702 (or (or false (and $x28392 $x28698)) (and $x28388 (= ghost_1_73 (- ghost_1_35 1))))))
 (let (($x28710 (or (or $x28702 $x28704) (and $x26994 (= ghost_1_10 (- ghost_1_35 1))))))
 (let (($x28715 (or (or $x28710 $x28709) (and $x28681 (= ghost_1_83 (- ghost_1_35 1))))))
 (let (($x28719 (or (or $x28715 $x28716) (and $x27215 (= ghost_1_22 (- ghost_1_35 1))))))
 (let (($x28729 (or (or $x28719 $x28717) (and $x28724 (= ghost_1_84 (- ghost_1_35 1))))))
 (let (($x28738 (or (or $x28729 $x28731) (and $x28736 (= ghost_1_85 (- ghost_1_35 1))))))
 (let (($x28743 (>= ghost_1_35 1)))
 (let (($x27482 (or c_35_2 c_35_3 c_35_4 c_35_5 c_35_6 c_35_7 c_35_8)))
 (let (($x27479 (not $x27482)))
 (let (($x27478 (and c_35_1 $x27479)))
 (let (($x28744 (and (=> (and c_35_1 $x27482) (= ghost_1_35 0)) (=> $x27478 (and $x28743 $x28738)))))
 (let (($x28652 (= ghost_1_34 1)))
 (let (($x28679 (and $x26997 $x28652)))
 (let (($x28672 (and $x28682 $x28652)))
 (let (($x28669 (and $x27172 $x28652)))
 (let (($x28666 (and $x28637 $x28652)))
 (let (($x26982 (or c_9_2 c_9_3 c_9_4 c_9_5 c_9_6 c_9_7 c_9_8)))
 (let (($x26978 (not $x26982)))
 (let (($x26981 (and c_9_1 $x26978)))
 (let (($x28656 (and $x26982 $x28652)))
 (let (($x28347 (or c_72_2 c_72_3 c_72_4 c_72_5 c_72_6 c_72_7 c_72_8)))
 (let (($x28346 (not $x28347)))
 (let (($x28344 (and c_72_1 $x28346)))
 (let (($x28658 (or (or false (and $x28347 $x28652)) (and $x28344 (= ghost_1_72 (- ghost_1_34 1))))))
 (let (($x28663 (or (or $x28658 $x28656) (and $x26981 (= ghost_1_9 (- ghost_1_34 1))))))
 (let (($x28670 (or (or $x28663 $x28666) (and $x28633 (= ghost_1_82 (- ghost_1_34 1))))))
 (let (($x28675 (or (or $x28670 $x28669) (and $x27171 (= ghost_1_21 (- ghost_1_34 1))))))
 (let (($x28678 (or (or $x28675 $x28672) (and $x28681 (= ghost_1_83 (- ghost_1_34 1))))))
 (let (($x28690 (or (or $x28678 $x28679) (and $x26994 (= ghost_1_10 (- ghost_1_34 1))))))
 (let (($x28695 (>= ghost_1_34 1)))
 (let (($x27437 (or c_34_2 c_34_3 c_34_4 c_34_5 c_34_6 c_34_7 c_34_8)))
 (let (($x27436 (not $x27437)))
 (let (($x27435 (and c_34_1 $x27436)))
 (let (($x28692 (and (=> (and c_34_1 $x27437) (= ghost_1_34 0)) (=> $x27435 (and $x28695 $x28690)))))
 (let (($x28604 (= ghost_1_33 1)))
 (let (($x28634 (and $x26982 $x28604)))
 (let (($x28627 (and $x28637 $x28604)))
 (let (($x28624 (and $x27157 $x28604)))
 (let (($x28615 (and $x28622 $x28604)))
 (let (($x28606 (and $x28532 $x28604)))
 (let (($x28332 (or c_71_2 c_71_3 c_71_4 c_71_5 c_71_6 c_71_7 c_71_8)))
 (let (($x28331 (not $x28332)))
 (let (($x28329 (and c_71_1 $x28331)))
 (let (($x28608 (or (or false (and $x28332 $x28604)) (and $x28329 (= ghost_1_71 (- ghost_1_33 1))))))
 (let (($x28613 (or (or $x28608 $x28606) (and $x28528 (= ghost_1_79 (- ghost_1_33 1))))))
 (let (($x28618 (or (or $x28613 $x28615) (and $x28619 (= ghost_1_81 (- ghost_1_33 1))))))
 (let (($x28630 (or (or $x28618 $x28624) (and $x27156 (= ghost_1_20 (- ghost_1_33 1))))))
 (let (($x28639 (or (or $x28630 $x28627) (and $x28633 (= ghost_1_82 (- ghost_1_33 1))))))
 (let (($x28649 (>= ghost_1_33 1)))
 (let (($x28648 (and $x28649 (or (or $x28639 $x28634) (and $x26981 (= ghost_1_9 (- ghost_1_33 1)))))))
 (let (($x27422 (or c_33_2 c_33_3 c_33_4 c_33_5 c_33_6 c_33_7 c_33_8)))
 (let (($x27420 (not $x27422)))
 (let (($x27419 (and c_33_1 $x27420)))
 (let (($x28558 (= ghost_1_32 1)))
 (let (($x28585 (and $x28592 $x28558)))
 (let (($x28581 (and $x27007 $x28558)))
 (let (($x28576 (and $x27067 $x28558)))
 (let (($x26972 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_6 c_8_7 c_8_8)))
 (let (($x26969 (not $x26972)))
 (let (($x26971 (and c_8_1 $x26969)))
 (let (($x28568 (and $x26972 $x28558)))
 (let (($x28563 (and $x28502 $x28558)))
 (let (($x28302 (or c_70_2 c_70_3 c_70_4 c_70_5 c_70_6 c_70_7 c_70_8)))
 (let (($x28300 (not $x28302)))
 (let (($x28298 (and c_70_1 $x28300)))
 (let (($x28562 (or (or false (and $x28302 $x28558)) (and $x28298 (= ghost_1_70 (- ghost_1_32 1))))))
 (let (($x28569 (or (or $x28562 $x28563) (and $x28498 (= ghost_1_78 (- ghost_1_32 1))))))
 (let (($x28573 (or (or $x28569 $x28568) (and $x26971 (= ghost_1_8 (- ghost_1_32 1))))))
 (let (($x28577 (or (or $x28573 $x28576) (and $x27066 (= ghost_1_15 (- ghost_1_32 1))))))
 (let (($x28586 (or (or $x28577 $x28581) (and $x27003 (= ghost_1_11 (- ghost_1_32 1))))))
 (let (($x28591 (or (or $x28586 $x28585) (and $x28590 (= ghost_1_80 (- ghost_1_32 1))))))
 (let (($x28598 (>= ghost_1_32 1)))
 (let (($x27392 (or c_32_2 c_32_3 c_32_4 c_32_5 c_32_6 c_32_7 c_32_8)))
 (let (($x27389 (not $x27392)))
 (let (($x27391 (and c_32_1 $x27389)))
 (let (($x28599 (and (=> (and c_32_1 $x27392) (= ghost_1_32 0)) (=> $x27391 (and $x28598 $x28591)))))
 (let (($x28511 (= ghost_1_31 1)))
 (let (($x28546 (and $x26972 $x28511)))
 (let (($x28540 (and $x26982 $x28511)))
 (let (($x28533 (and $x27042 $x28511)))
 (let (($x28526 (and $x28532 $x28511)))
 (let (($x28517 (and $x28482 $x28511)))
 (let (($x28282 (or c_69_2 c_69_3 c_69_4 c_69_5 c_69_6 c_69_7 c_69_8)))
 (let (($x28280 (not $x28282)))
 (let (($x28279 (and c_69_1 $x28280)))
 (let (($x28518 (or (or false (and $x28282 $x28511)) (and $x28279 (= ghost_1_69 (- ghost_1_31 1))))))
 (let (($x28524 (or (or $x28518 $x28517) (and $x28478 (= ghost_1_77 (- ghost_1_31 1))))))
 (let (($x28534 (or (or $x28524 $x28526) (and $x28528 (= ghost_1_79 (- ghost_1_31 1))))))
 (let (($x28541 (or (or $x28534 $x28533) (and $x27040 (= ghost_1_13 (- ghost_1_31 1))))))
 (let (($x28543 (or (or $x28541 $x28540) (and $x26981 (= ghost_1_9 (- ghost_1_31 1))))))
 (let (($x28553 (>= ghost_1_31 1)))
 (let (($x28554 (and $x28553 (or (or $x28543 $x28546) (and $x26971 (= ghost_1_8 (- ghost_1_31 1)))))))
 (let (($x27372 (or c_31_2 c_31_3 c_31_4 c_31_5 c_31_6 c_31_7 c_31_8)))
 (let (($x27369 (not $x27372)))
 (let (($x27370 (and c_31_1 $x27369)))
 (let (($x28458 (= ghost_1_30 1)))
 (let (($x28495 (and $x28502 $x28458)))
 (let (($x28489 (and $x26972 $x28458)))
 (let (($x28484 (and $x27032 $x28458)))
 (let (($x28476 (and $x28482 $x28458)))
 (let (($x28466 (and $x28472 $x28458)))
 (let (($x28272 (or c_68_2 c_68_3 c_68_4 c_68_5 c_68_6 c_68_7 c_68_8)))
 (let (($x28269 (not $x28272)))
 (let (($x28271 (and c_68_1 $x28269)))
 (let (($x28465 (or (or false (and $x28272 $x28458)) (and $x28271 (= ghost_1_68 (- ghost_1_30 1))))))
 (let (($x28468 (or (or $x28465 $x28466) (and $x28469 (= ghost_1_76 (- ghost_1_30 1))))))
 (let (($x28483 (or (or $x28468 $x28476) (and $x28478 (= ghost_1_77 (- ghost_1_30 1))))))
 (let (($x28490 (or (or $x28483 $x28484) (and $x27029 (= ghost_1_12 (- ghost_1_30 1))))))
 (let (($x28493 (or (or $x28490 $x28489) (and $x26971 (= ghost_1_8 (- ghost_1_30 1))))))
 (let (($x28503 (or (or $x28493 $x28495) (and $x28498 (= ghost_1_78 (- ghost_1_30 1))))))
 (let (($x28510 (>= ghost_1_30 1)))
 (let (($x27362 (or c_30_2 c_30_3 c_30_4 c_30_5 c_30_6 c_30_7 c_30_8)))
 (let (($x27361 (not $x27362)))
 (let (($x27358 (and c_30_1 $x27361)))
 (let (($x28508 (and (=> (and c_30_1 $x27362) (= ghost_1_30 0)) (=> $x27358 (and $x28510 $x28503)))))
 (let (($x28413 (= ghost_1_29 1)))
 (let (($x28437 (and $x28447 $x28413)))
 (let (($x28432 (and $x28402 $x28413)))
 (let (($x28431 (and $x27007 $x28413)))
 (let (($x26960 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_6 c_7_7 c_7_8)))
 (let (($x26959 (not $x26960)))
 (let (($x26957 (and c_7_1 $x26959)))
 (let (($x28422 (and $x26960 $x28413)))
 (let (($x28416 (and $x28302 $x28413)))
 (let (($x28247 (or c_67_2 c_67_3 c_67_4 c_67_5 c_67_6 c_67_7 c_67_8)))
 (let (($x28244 (not $x28247)))
 (let (($x28246 (and c_67_1 $x28244)))
 (let (($x28420 (or (or false (and $x28247 $x28413)) (and $x28246 (= ghost_1_67 (- ghost_1_29 1))))))
 (let (($x28425 (or (or $x28420 $x28416) (and $x28298 (= ghost_1_70 (- ghost_1_29 1))))))
 (let (($x28430 (or (or $x28425 $x28422) (and $x26957 (= ghost_1_7 (- ghost_1_29 1))))))
 (let (($x28436 (or (or $x28430 $x28431) (and $x27003 (= ghost_1_11 (- ghost_1_29 1))))))
 (let (($x28438 (or (or $x28436 $x28432) (and $x28401 (= ghost_1_74 (- ghost_1_29 1))))))
 (let (($x28448 (or (or $x28438 $x28437) (and $x28443 (= ghost_1_75 (- ghost_1_29 1))))))
 (let (($x28452 (>= ghost_1_29 1)))
 (let (($x27337 (or c_29_2 c_29_3 c_29_4 c_29_5 c_29_6 c_29_7 c_29_8)))
 (let (($x27333 (not $x27337)))
 (let (($x27335 (and c_29_1 $x27333)))
 (let (($x28455 (and (=> (and c_29_1 $x27337) (= ghost_1_29 0)) (=> $x27335 (and $x28452 $x28448)))))
 (let (($x28361 (= ghost_1_28 1)))
 (let (($x28396 (and $x28402 $x28361)))
 (let (($x28386 (and $x28392 $x28361)))
 (let (($x28378 (and $x26997 $x28361)))
 (let (($x28376 (and $x28347 $x28361)))
 (let (($x28366 (and $x26960 $x28361)))
 (let (($x28237 (or c_66_2 c_66_3 c_66_4 c_66_5 c_66_6 c_66_7 c_66_8)))
 (let (($x28234 (not $x28237)))
 (let (($x28236 (and c_66_1 $x28234)))
 (let (($x28370 (or (or false (and $x28237 $x28361)) (and $x28236 (= ghost_1_66 (- ghost_1_28 1))))))
 (let (($x28375 (or (or $x28370 $x28366) (and $x26957 (= ghost_1_7 (- ghost_1_28 1))))))
 (let (($x28381 (or (or $x28375 $x28376) (and $x28344 (= ghost_1_72 (- ghost_1_28 1))))))
 (let (($x28385 (or (or $x28381 $x28378) (and $x26994 (= ghost_1_10 (- ghost_1_28 1))))))
 (let (($x28393 (or (or $x28385 $x28386) (and $x28388 (= ghost_1_73 (- ghost_1_28 1))))))
 (let (($x28403 (or (or $x28393 $x28396) (and $x28401 (= ghost_1_74 (- ghost_1_28 1))))))
 (let (($x28410 (>= ghost_1_28 1)))
 (let (($x27327 (or c_28_2 c_28_3 c_28_4 c_28_5 c_28_6 c_28_7 c_28_8)))
 (let (($x27326 (not $x27327)))
 (let (($x27325 (and c_28_1 $x27326)))
 (let (($x28408 (and (=> (and c_28_1 $x27327) (= ghost_1_28 0)) (=> $x27325 (and $x28410 $x28403)))))
 (let (($x28311 (= ghost_1_27 1)))
 (let (($x28348 (and $x26960 $x28311)))
 (let (($x28337 (and $x28347 $x28311)))
 (let (($x28333 (and $x26982 $x28311)))
 (let (($x28326 (and $x28332 $x28311)))
 (let (($x28319 (and $x28282 $x28311)))
 (let (($x28222 (or c_65_2 c_65_3 c_65_4 c_65_5 c_65_6 c_65_7 c_65_8)))
 (let (($x28221 (not $x28222)))
 (let (($x28218 (and c_65_1 $x28221)))
 (let (($x28315 (or (or false (and $x28222 $x28311)) (and $x28218 (= ghost_1_65 (- ghost_1_27 1))))))
 (let (($x28325 (or (or $x28315 $x28319) (and $x28279 (= ghost_1_69 (- ghost_1_27 1))))))
 (let (($x28328 (or (or $x28325 $x28326) (and $x28329 (= ghost_1_71 (- ghost_1_27 1))))))
 (let (($x28338 (or (or $x28328 $x28333) (and $x26981 (= ghost_1_9 (- ghost_1_27 1))))))
 (let (($x28343 (or (or $x28338 $x28337) (and $x28344 (= ghost_1_72 (- ghost_1_27 1))))))
 (let (($x28359 (>= ghost_1_27 1)))
 (let (($x28357 (and $x28359 (or (or $x28343 $x28348) (and $x26957 (= ghost_1_7 (- ghost_1_27 1)))))))
 (let (($x27312 (or c_27_2 c_27_3 c_27_4 c_27_5 c_27_6 c_27_7 c_27_8)))
 (let (($x27310 (not $x27312)))
 (let (($x27308 (and c_27_1 $x27310)))
 (let (($x28256 (= ghost_1_26 1)))
 (let (($x28292 (and $x28302 $x28256)))
 (let (($x28291 (and $x26960 $x28256)))
 (let (($x28284 (and $x26972 $x28256)))
 (let (($x28276 (and $x28282 $x28256)))
 (let (($x28266 (and $x28272 $x28256)))
 (let (($x28212 (or c_64_2 c_64_3 c_64_4 c_64_5 c_64_6 c_64_7 c_64_8)))
 (let (($x28208 (not $x28212)))
 (let (($x28210 (and c_64_1 $x28208)))
 (let (($x28264 (or (or false (and $x28212 $x28256)) (and $x28210 (= ghost_1_64 (- ghost_1_26 1))))))
 (let (($x28273 (or (or $x28264 $x28266) (and $x28271 (= ghost_1_68 (- ghost_1_26 1))))))
 (let (($x28278 (or (or $x28273 $x28276) (and $x28279 (= ghost_1_69 (- ghost_1_26 1))))))
 (let (($x28288 (or (or $x28278 $x28284) (and $x26971 (= ghost_1_8 (- ghost_1_26 1))))))
 (let (($x28295 (or (or $x28288 $x28291) (and $x26957 (= ghost_1_7 (- ghost_1_26 1))))))
 (let (($x28301 (or (or $x28295 $x28292) (and $x28298 (= ghost_1_70 (- ghost_1_26 1))))))
 (let (($x28309 (>= ghost_1_26 1)))
 (let (($x27302 (or c_26_2 c_26_3 c_26_4 c_26_5 c_26_6 c_26_7 c_26_8)))
 (let (($x27300 (not $x27302)))
 (let (($x27298 (and c_26_1 $x27300)))
 (let (($x28310 (and (=> (and c_26_1 $x27302) (= ghost_1_26 0)) (=> $x27298 (and $x28309 $x28301)))))
 (let (($x28194 (= ghost_1_25 1)))
 (let (($x28241 (and $x28247 $x28194)))
 (let (($x28227 (and $x28237 $x28194)))
 (let (($x28219 (and $x26960 $x28194)))
 (let (($x28216 (and $x28222 $x28194)))
 (let (($x28206 (and $x28212 $x28194)))
 (let (($x28200 (or c_63_2 c_63_3 c_63_4 c_63_5 c_63_6 c_63_7 c_63_8)))
 (let (($x28199 (not $x28200)))
 (let (($x28201 (or (or false (and $x28200 $x28194)) (and (and c_63_1 $x28199) (= ghost_1_63 (- ghost_1_25 1))))))
 (let (($x28211 (or (or $x28201 $x28206) (and $x28210 (= ghost_1_64 (- ghost_1_25 1))))))
 (let (($x28223 (or (or $x28211 $x28216) (and $x28218 (= ghost_1_65 (- ghost_1_25 1))))))
 (let (($x28230 (or (or $x28223 $x28219) (and $x26957 (= ghost_1_7 (- ghost_1_25 1))))))
 (let (($x28233 (or (or $x28230 $x28227) (and $x28236 (= ghost_1_66 (- ghost_1_25 1))))))
 (let (($x28243 (or (or $x28233 $x28241) (and $x28246 (= ghost_1_67 (- ghost_1_25 1))))))
 (let (($x28254 (>= ghost_1_25 1)))
 (let (($x27290 (or c_25_2 c_25_3 c_25_4 c_25_5 c_25_6 c_25_7 c_25_8)))
 (let (($x27286 (not $x27290)))
 (let (($x27287 (and c_25_1 $x27286)))
 (let (($x28255 (and (=> (and c_25_1 $x27290) (= ghost_1_25 0)) (=> $x27287 (and $x28254 $x28243)))))
 (let (($x28149 (= ghost_1_24 1)))
 (let (($x28172 (and $x28182 $x28149)))
 (let (($x28171 (and $x28137 $x28149)))
 (let (($x28157 (and $x27947 $x28149)))
 (let (($x26936 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_6 c_6_7 c_6_8)))
 (let (($x26934 (not $x26936)))
 (let (($x26933 (and c_6_1 $x26934)))
 (let (($x28161 (and $x26936 $x28149)))
 (let (($x28154 (and $x27742 $x28149)))
 (let (($x28153 (or (or false (and $x27537 $x28149)) (and $x27534 (= ghost_1_37 (- ghost_1_24 1))))))
 (let (($x28158 (or (or $x28153 $x28154) (and $x27741 (= ghost_1_46 (- ghost_1_24 1))))))
 (let (($x28165 (or (or $x28158 $x28161) (and $x26933 (= ghost_1_6 (- ghost_1_24 1))))))
 (let (($x28167 (or (or $x28165 $x28157) (and $x27946 (= ghost_1_55 (- ghost_1_24 1))))))
 (let (($x28175 (or (or $x28167 $x28171) (and $x28136 (= ghost_1_61 (- ghost_1_24 1))))))
 (let (($x28184 (or (or $x28175 $x28172) (and $x28179 (= ghost_1_62 (- ghost_1_24 1))))))
 (let (($x28187 (>= ghost_1_24 1)))
 (let (($x28190 (and (=> (and c_24_1 $x27272) (= ghost_1_24 0)) (=> $x27269 (and $x28187 $x28184)))))
 (let (($x28103 (= ghost_1_23 1)))
 (let (($x28127 (and $x28137 $x28103)))
 (let (($x28125 (and $x28092 $x28103)))
 (let (($x28120 (and $x27902 $x28103)))
 (let (($x26926 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6 c_5_7 c_5_8)))
 (let (($x26925 (not $x26926)))
 (let (($x26924 (and c_5_1 $x26925)))
 (let (($x28111 (and $x26926 $x28103)))
 (let (($x28108 (and $x26936 $x28103)))
 (let (($x28110 (or (or false (and $x27492 $x28103)) (and $x27491 (= ghost_1_36 (- ghost_1_23 1))))))
 (let (($x28115 (or (or $x28110 $x28108) (and $x26933 (= ghost_1_6 (- ghost_1_23 1))))))
 (let (($x28121 (or (or $x28115 $x28111) (and $x26924 (= ghost_1_5 (- ghost_1_23 1))))))
 (let (($x28124 (or (or $x28121 $x28120) (and $x27900 (= ghost_1_54 (- ghost_1_23 1))))))
 (let (($x28131 (or (or $x28124 $x28125) (and $x28090 (= ghost_1_60 (- ghost_1_23 1))))))
 (let (($x28133 (or (or $x28131 $x28127) (and $x28136 (= ghost_1_61 (- ghost_1_23 1))))))
 (let (($x28142 (>= ghost_1_23 1)))
 (let (($x28143 (and (=> (and c_23_1 $x27227) (= ghost_1_23 0)) (=> $x27226 (and $x28142 $x28133)))))
 (let (($x28054 (= ghost_1_22 1)))
 (let (($x28086 (and $x28092 $x28054)))
 (let (($x28072 (and $x28082 $x28054)))
 (let (($x28062 (and $x27892 $x28054)))
 (let (($x28065 (and $x28037 $x28054)))
 (let (($x28060 (and $x26926 $x28054)))
 (let (($x28056 (or (or false (and $x27482 $x28054)) (and $x27478 (= ghost_1_35 (- ghost_1_22 1))))))
 (let (($x28066 (or (or $x28056 $x28060) (and $x26924 (= ghost_1_5 (- ghost_1_22 1))))))
 (let (($x28070 (or (or $x28066 $x28065) (and $x28034 (= ghost_1_58 (- ghost_1_22 1))))))
 (let (($x28076 (or (or $x28070 $x28062) (and $x27890 (= ghost_1_53 (- ghost_1_22 1))))))
 (let (($x28078 (or (or $x28076 $x28072) (and $x28080 (= ghost_1_59 (- ghost_1_22 1))))))
 (let (($x28088 (or (or $x28078 $x28086) (and $x28090 (= ghost_1_60 (- ghost_1_22 1))))))
 (let (($x28097 (>= ghost_1_22 1)))
 (let (($x28098 (and (=> (and c_22_1 $x27217) (= ghost_1_22 0)) (=> $x27215 (and $x28097 $x28088)))))
 (let (($x28009 (= ghost_1_21 1)))
 (let (($x28036 (and $x26926 $x28009)))
 (let (($x28027 (and $x28037 $x28009)))
 (let (($x28026 (and $x27792 $x28009)))
 (let (($x28019 (and $x27992 $x28009)))
 (let (($x26906 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6 c_4_7 c_4_8)))
 (let (($x26904 (not $x26906)))
 (let (($x26902 (and c_4_1 $x26904)))
 (let (($x28013 (and $x26906 $x28009)))
 (let (($x28014 (or (or false (and $x27437 $x28009)) (and $x27435 (= ghost_1_34 (- ghost_1_21 1))))))
 (let (($x28020 (or (or $x28014 $x28013) (and $x26902 (= ghost_1_4 (- ghost_1_21 1))))))
 (let (($x28025 (or (or $x28020 $x28019) (and $x27991 (= ghost_1_57 (- ghost_1_21 1))))))
 (let (($x28029 (or (or $x28025 $x28026) (and $x27790 (= ghost_1_49 (- ghost_1_21 1))))))
 (let (($x28039 (or (or $x28029 $x28027) (and $x28034 (= ghost_1_58 (- ghost_1_21 1))))))
 (let (($x28049 (>= ghost_1_21 1)))
 (let (($x28050 (and $x28049 (or (or $x28039 $x28036) (and $x26924 (= ghost_1_5 (- ghost_1_21 1)))))))
 (let (($x27957 (= ghost_1_20 1)))
 (let (($x27989 (and $x26906 $x27957)))
 (let (($x27986 (and $x27992 $x27957)))
 (let (($x27978 (and $x27772 $x27957)))
 (let (($x27969 (and $x27977 $x27957)))
 (let (($x27965 (and $x27627 $x27957)))
 (let (($x27963 (or (or false (and $x27422 $x27957)) (and $x27419 (= ghost_1_33 (- ghost_1_20 1))))))
 (let (($x27970 (or (or $x27963 $x27965) (and $x27624 (= ghost_1_42 (- ghost_1_20 1))))))
 (let (($x27975 (or (or $x27970 $x27969) (and $x27973 (= ghost_1_56 (- ghost_1_20 1))))))
 (let (($x27985 (or (or $x27975 $x27978) (and $x27769 (= ghost_1_47 (- ghost_1_20 1))))))
 (let (($x27988 (or (or $x27985 $x27986) (and $x27991 (= ghost_1_57 (- ghost_1_20 1))))))
 (let (($x28004 (>= ghost_1_20 1)))
 (let (($x28005 (and $x28004 (or (or $x27988 $x27989) (and $x26902 (= ghost_1_4 (- ghost_1_20 1)))))))
 (let (($x27912 (= ghost_1_19 1)))
 (let (($x27937 (and $x27947 $x27912)))
 (let (($x27936 (and $x27902 $x27912)))
 (let (($x27927 (and $x27852 $x27912)))
 (let (($x26916 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6 c_3_7 c_3_8)))
 (let (($x26914 (not $x26916)))
 (let (($x26912 (and c_3_1 $x26914)))
 (let (($x27923 (and $x26916 $x27912)))
 (let (($x27920 (and $x27697 $x27912)))
 (let (($x27918 (or (or false (and $x26936 $x27912)) (and $x26933 (= ghost_1_6 (- ghost_1_19 1))))))
 (let (($x27926 (or (or $x27918 $x27920) (and $x27694 (= ghost_1_45 (- ghost_1_19 1))))))
 (let (($x27930 (or (or $x27926 $x27923) (and $x26912 (= ghost_1_3 (- ghost_1_19 1))))))
 (let (($x27935 (or (or $x27930 $x27927) (and $x27851 (= ghost_1_52 (- ghost_1_19 1))))))
 (let (($x27939 (or (or $x27935 $x27936) (and $x27900 (= ghost_1_54 (- ghost_1_19 1))))))
 (let (($x27945 (or (or $x27939 $x27937) (and $x27946 (= ghost_1_55 (- ghost_1_19 1))))))
 (let (($x27954 (>= ghost_1_19 1)))
 (let (($x27952 (and (=> (and c_19_1 $x27127) (= ghost_1_19 0)) (=> $x27124 (and $x27954 $x27945)))))
 (let (($x27862 (= ghost_1_18 1)))
 (let (($x27896 (and $x27902 $x27862)))
 (let (($x27885 (and $x27892 $x27862)))
 (let (($x27880 (and $x27842 $x27862)))
 (let (($x27872 (and $x27792 $x27862)))
 (let (($x27865 (and $x26916 $x27862)))
 (let (($x27869 (or (or false (and $x26926 $x27862)) (and $x26924 (= ghost_1_5 (- ghost_1_18 1))))))
 (let (($x27875 (or (or $x27869 $x27865) (and $x26912 (= ghost_1_3 (- ghost_1_18 1))))))
 (let (($x27879 (or (or $x27875 $x27872) (and $x27790 (= ghost_1_49 (- ghost_1_18 1))))))
 (let (($x27883 (or (or $x27879 $x27880) (and $x27838 (= ghost_1_51 (- ghost_1_18 1))))))
 (let (($x27888 (or (or $x27883 $x27885) (and $x27890 (= ghost_1_53 (- ghost_1_18 1))))))
 (let (($x27904 (or (or $x27888 $x27896) (and $x27900 (= ghost_1_54 (- ghost_1_18 1))))))
 (let (($x27907 (>= ghost_1_18 1)))
 (let (($x27910 (and (=> (and c_18_1 $x27117) (= ghost_1_18 0)) (=> $x27114 (and $x27907 $x27904)))))
 (let (($x27806 (= ghost_1_17 1)))
 (let (($x27846 (and $x27852 $x27806)))
 (let (($x27836 (and $x27842 $x27806)))
 (let (($x27822 (and $x27832 $x27806)))
 (let (($x27818 (and $x27782 $x27806)))
 (let (($x27813 (and $x27682 $x27806)))
 (let (($x27812 (or (or false (and $x26916 $x27806)) (and $x26912 (= ghost_1_3 (- ghost_1_17 1))))))
 (let (($x27821 (or (or $x27812 $x27813) (and $x27679 (= ghost_1_44 (- ghost_1_17 1))))))
 (let (($x27825 (or (or $x27821 $x27818) (and $x27781 (= ghost_1_48 (- ghost_1_17 1))))))
 (let (($x27828 (or (or $x27825 $x27822) (and $x27830 (= ghost_1_50 (- ghost_1_17 1))))))
 (let (($x27844 (or (or $x27828 $x27836) (and $x27838 (= ghost_1_51 (- ghost_1_17 1))))))
 (let (($x27848 (or (or $x27844 $x27846) (and $x27851 (= ghost_1_52 (- ghost_1_17 1))))))
 (let (($x27859 (>= ghost_1_17 1)))
 (let (($x27860 (and (=> (and c_17_1 $x27107) (= ghost_1_17 0)) (=> $x27104 (and $x27859 $x27848)))))
 (let (($x27754 (= ghost_1_16 1)))
 (let (($x27789 (and $x26916 $x27754)))
 (let (($x27786 (and $x27792 $x27754)))
 (let (($x27776 (and $x27782 $x27754)))
 (let (($x27765 (and $x27772 $x27754)))
 (let (($x27760 (and $x27637 $x27754)))
 (let (($x27755 (or (or false (and $x26906 $x27754)) (and $x26902 (= ghost_1_4 (- ghost_1_16 1))))))
 (let (($x27766 (or (or $x27755 $x27760) (and $x27634 (= ghost_1_43 (- ghost_1_16 1))))))
 (let (($x27768 (or (or $x27766 $x27765) (and $x27769 (= ghost_1_47 (- ghost_1_16 1))))))
 (let (($x27778 (or (or $x27768 $x27776) (and $x27781 (= ghost_1_48 (- ghost_1_16 1))))))
 (let (($x27794 (or (or $x27778 $x27786) (and $x27790 (= ghost_1_49 (- ghost_1_16 1))))))
 (let (($x27803 (>= ghost_1_16 1)))
 (let (($x27802 (and $x27803 (or (or $x27794 $x27789) (and $x26912 (= ghost_1_3 (- ghost_1_16 1)))))))
 (let (($x27707 (= ghost_1_15 1)))
 (let (($x27734 (and $x27742 $x27707)))
 (let (($x27728 (and $x26936 $x27707)))
 (let (($x27723 (and $x27697 $x27707)))
 (let (($x26896 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6 c_2_7 c_2_8)))
 (let (($x26893 (not $x26896)))
 (let (($x26892 (and c_2_1 $x26893)))
 (let (($x27721 (and $x26896 $x27707)))
 (let (($x27711 (and $x27597 $x27707)))
 (let (($x27715 (or (or false (and $x27392 $x27707)) (and $x27391 (= ghost_1_32 (- ghost_1_15 1))))))
 (let (($x27720 (or (or $x27715 $x27711) (and $x27596 (= ghost_1_41 (- ghost_1_15 1))))))
 (let (($x27724 (or (or $x27720 $x27721) (and $x26892 (= ghost_1_2 (- ghost_1_15 1))))))
 (let (($x27731 (or (or $x27724 $x27723) (and $x27694 (= ghost_1_45 (- ghost_1_15 1))))))
 (let (($x27735 (or (or $x27731 $x27728) (and $x26933 (= ghost_1_6 (- ghost_1_15 1))))))
 (let (($x27743 (or (or $x27735 $x27734) (and $x27741 (= ghost_1_46 (- ghost_1_15 1))))))
 (let (($x27747 (>= ghost_1_15 1)))
 (let (($x27749 (and (=> (and c_15_1 $x27067) (= ghost_1_15 0)) (=> $x27066 (and $x27747 $x27743)))))
 (let (($x27658 (= ghost_1_14 1)))
 (let (($x27691 (and $x27697 $x27658)))
 (let (($x27683 (and $x26916 $x27658)))
 (let (($x27675 (and $x27682 $x27658)))
 (let (($x27669 (and $x27637 $x27658)))
 (let (($x27664 (and $x27582 $x27658)))
 (let (($x27662 (or (or false (and $x26896 $x27658)) (and $x26892 (= ghost_1_2 (- ghost_1_14 1))))))
 (let (($x27668 (or (or $x27662 $x27664) (and $x27578 (= ghost_1_40 (- ghost_1_14 1))))))
 (let (($x27676 (or (or $x27668 $x27669) (and $x27634 (= ghost_1_43 (- ghost_1_14 1))))))
 (let (($x27678 (or (or $x27676 $x27675) (and $x27679 (= ghost_1_44 (- ghost_1_14 1))))))
 (let (($x27690 (or (or $x27678 $x27683) (and $x26912 (= ghost_1_3 (- ghost_1_14 1))))))
 (let (($x27693 (or (or $x27690 $x27691) (and $x27694 (= ghost_1_45 (- ghost_1_14 1))))))
 (let (($x27704 (>= ghost_1_14 1)))
 (let (($x27702 (and (=> (and c_14_1 $x27052) (= ghost_1_14 0)) (=> $x27049 (and $x27704 $x27693)))))
 (let (($x27607 (= ghost_1_13 1)))
 (let (($x27644 (and $x26896 $x27607)))
 (let (($x27638 (and $x26906 $x27607)))
 (let (($x27631 (and $x27637 $x27607)))
 (let (($x27618 (and $x27627 $x27607)))
 (let (($x27612 (and $x27572 $x27607)))
 (let (($x27614 (or (or false (and $x27372 $x27607)) (and $x27370 (= ghost_1_31 (- ghost_1_13 1))))))
 (let (($x27621 (or (or $x27614 $x27612) (and $x27569 (= ghost_1_39 (- ghost_1_13 1))))))
 (let (($x27629 (or (or $x27621 $x27618) (and $x27624 (= ghost_1_42 (- ghost_1_13 1))))))
 (let (($x27633 (or (or $x27629 $x27631) (and $x27634 (= ghost_1_43 (- ghost_1_13 1))))))
 (let (($x27645 (or (or $x27633 $x27638) (and $x26902 (= ghost_1_4 (- ghost_1_13 1))))))
 (let (($x27655 (>= ghost_1_13 1)))
 (let (($x27654 (and $x27655 (or (or $x27645 $x27644) (and $x26892 (= ghost_1_2 (- ghost_1_13 1)))))))
 (let (($x27546 (= ghost_1_12 1)))
 (let (($x27591 (and $x27597 $x27546)))
 (let (($x27583 (and $x26896 $x27546)))
 (let (($x27576 (and $x27582 $x27546)))
 (let (($x27566 (and $x27572 $x27546)))
 (let (($x27556 (and $x27562 $x27546)))
 (let (($x27550 (or (or false (and $x27362 $x27546)) (and $x27358 (= ghost_1_30 (- ghost_1_12 1))))))
 (let (($x27561 (or (or $x27550 $x27556) (and $x27558 (= ghost_1_38 (- ghost_1_12 1))))))
 (let (($x27573 (or (or $x27561 $x27566) (and $x27569 (= ghost_1_39 (- ghost_1_12 1))))))
 (let (($x27584 (or (or $x27573 $x27576) (and $x27578 (= ghost_1_40 (- ghost_1_12 1))))))
 (let (($x27589 (or (or $x27584 $x27583) (and $x26892 (= ghost_1_2 (- ghost_1_12 1))))))
 (let (($x27593 (or (or $x27589 $x27591) (and $x27596 (= ghost_1_41 (- ghost_1_12 1))))))
 (let (($x27604 (>= ghost_1_12 1)))
 (let (($x27605 (and (=> (and c_12_1 $x27032) (= ghost_1_12 0)) (=> $x27029 (and $x27604 $x27593)))))
 (let (($x27502 (= ghost_1_11 1)))
 (let (($x27527 (and $x27537 $x27502)))
 (let (($x27517 (and $x27492 $x27502)))
 (let (($x27521 (and $x26936 $x27502)))
 (let (($x26883 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6 c_1_7 c_1_8)))
 (let (($x26880 (not $x26883)))
 (let (($x26879 (and c_1_1 $x26880)))
 (let (($x27516 (and $x26883 $x27502)))
 (let (($x27508 (and $x27392 $x27502)))
 (let (($x27509 (or (or false (and $x27337 $x27502)) (and $x27335 (= ghost_1_29 (- ghost_1_11 1))))))
 (let (($x27513 (or (or $x27509 $x27508) (and $x27391 (= ghost_1_32 (- ghost_1_11 1))))))
 (let (($x27520 (or (or $x27513 $x27516) (and $x26879 (= ghost_1_1 (- ghost_1_11 1))))))
 (let (($x27525 (or (or $x27520 $x27521) (and $x26933 (= ghost_1_6 (- ghost_1_11 1))))))
 (let (($x27530 (or (or $x27525 $x27517) (and $x27491 (= ghost_1_36 (- ghost_1_11 1))))))
 (let (($x27538 (or (or $x27530 $x27527) (and $x27534 (= ghost_1_37 (- ghost_1_11 1))))))
 (let (($x27545 (>= ghost_1_11 1)))
 (let (($x27544 (and (=> (and c_11_1 $x27007) (= ghost_1_11 0)) (=> $x27003 (and $x27545 $x27538)))))
 (let (($x27454 (= ghost_1_10 1)))
 (let (($x27486 (and $x27492 $x27454)))
 (let (($x27472 (and $x27482 $x27454)))
 (let (($x27470 (and $x26926 $x27454)))
 (let (($x27466 (and $x27437 $x27454)))
 (let (($x27455 (and $x26883 $x27454)))
 (let (($x27459 (or (or false (and $x27327 $x27454)) (and $x27325 (= ghost_1_28 (- ghost_1_10 1))))))
 (let (($x27465 (or (or $x27459 $x27455) (and $x26879 (= ghost_1_1 (- ghost_1_10 1))))))
 (let (($x27471 (or (or $x27465 $x27466) (and $x27435 (= ghost_1_34 (- ghost_1_10 1))))))
 (let (($x27476 (or (or $x27471 $x27470) (and $x26924 (= ghost_1_5 (- ghost_1_10 1))))))
 (let (($x27484 (or (or $x27476 $x27472) (and $x27478 (= ghost_1_35 (- ghost_1_10 1))))))
 (let (($x27488 (or (or $x27484 $x27486) (and $x27491 (= ghost_1_36 (- ghost_1_10 1))))))
 (let (($x27499 (>= ghost_1_10 1)))
 (let (($x27500 (and (=> (and c_10_1 $x26997) (= ghost_1_10 0)) (=> $x26994 (and $x27499 $x27488)))))
 (let (($x27404 (= ghost_1_9 1)))
 (let (($x27434 (and $x26883 $x27404)))
 (let (($x27427 (and $x27437 $x27404)))
 (let (($x27421 (and $x26906 $x27404)))
 (let (($x27416 (and $x27422 $x27404)))
 (let (($x27408 (and $x27372 $x27404)))
 (let (($x27407 (or (or false (and $x27312 $x27404)) (and $x27308 (= ghost_1_27 (- ghost_1_9 1))))))
 (let (($x27414 (or (or $x27407 $x27408) (and $x27370 (= ghost_1_31 (- ghost_1_9 1))))))
 (let (($x27424 (or (or $x27414 $x27416) (and $x27419 (= ghost_1_33 (- ghost_1_9 1))))))
 (let (($x27430 (or (or $x27424 $x27421) (and $x26902 (= ghost_1_4 (- ghost_1_9 1))))))
 (let (($x27433 (or (or $x27430 $x27427) (and $x27435 (= ghost_1_34 (- ghost_1_9 1))))))
 (let (($x27447 (>= ghost_1_9 1)))
 (let (($x27450 (and $x27447 (or (or $x27433 $x27434) (and $x26879 (= ghost_1_1 (- ghost_1_9 1)))))))
 (let (($x27349 (= ghost_1_8 1)))
 (let (($x27382 (and $x27392 $x27349)))
 (let (($x27378 (and $x26883 $x27349)))
 (let (($x27374 (and $x26896 $x27349)))
 (let (($x27366 (and $x27372 $x27349)))
 (let (($x27356 (and $x27362 $x27349)))
 (let (($x27352 (or (or false (and $x27302 $x27349)) (and $x27298 (= ghost_1_26 (- ghost_1_8 1))))))
 (let (($x27363 (or (or $x27352 $x27356) (and $x27358 (= ghost_1_30 (- ghost_1_8 1))))))
 (let (($x27368 (or (or $x27363 $x27366) (and $x27370 (= ghost_1_31 (- ghost_1_8 1))))))
 (let (($x27379 (or (or $x27368 $x27374) (and $x26892 (= ghost_1_2 (- ghost_1_8 1))))))
 (let (($x27385 (or (or $x27379 $x27378) (and $x26879 (= ghost_1_1 (- ghost_1_8 1))))))
 (let (($x27398 (>= ghost_1_8 1)))
 (let (($x27400 (and $x27398 (or (or $x27385 $x27382) (and $x27391 (= ghost_1_32 (- ghost_1_8 1)))))))
 (let (($x27281 (= ghost_1_7 1)))
 (let (($x27331 (and $x27337 $x27281)))
 (let (($x27317 (and $x27327 $x27281)))
 (let (($x27314 (and $x26883 $x27281)))
 (let (($x27306 (and $x27312 $x27281)))
 (let (($x27296 (and $x27302 $x27281)))
 (let (($x27293 (or (or false (and $x27290 $x27281)) (and $x27287 (= ghost_1_25 (- ghost_1_7 1))))))
 (let (($x27301 (or (or $x27293 $x27296) (and $x27298 (= ghost_1_26 (- ghost_1_7 1))))))
 (let (($x27311 (or (or $x27301 $x27306) (and $x27308 (= ghost_1_27 (- ghost_1_7 1))))))
 (let (($x27320 (or (or $x27311 $x27314) (and $x26879 (= ghost_1_1 (- ghost_1_7 1))))))
 (let (($x27323 (or (or $x27320 $x27317) (and $x27325 (= ghost_1_28 (- ghost_1_7 1))))))
 (let (($x27344 (>= ghost_1_7 1)))
 (let (($x27345 (and $x27344 (or (or $x27323 $x27331) (and $x27335 (= ghost_1_29 (- ghost_1_7 1)))))))
 (let (($x27238 (= ghost_1_6 1)))
 (let (($x27262 (and $x27272 $x27238)))
 (let (($x27255 (and $x27227 $x27238)))
 (let (($x27254 (and $x27127 $x27238)))
 (let (($x26948 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6 c_0_7 c_0_8)))
 (let (($x26947 (not $x26948)))
 (let (($x26946 (and c_0_1 $x26947)))
 (let (($x27251 (and $x26948 $x27238)))
 (let (($x27243 (and $x27067 $x27238)))
 (let (($x27241 (or (or false (and $x27007 $x27238)) (and $x27003 (= ghost_1_11 (- ghost_1_6 1))))))
 (let (($x27247 (or (or $x27241 $x27243) (and $x27066 (= ghost_1_15 (- ghost_1_6 1))))))
 (let (($x27253 (or (or $x27247 $x27251) (and $x26946 (= ghost_1_0 (- ghost_1_6 1))))))
 (let (($x27260 (or (or $x27253 $x27254) (and $x27124 (= ghost_1_19 (- ghost_1_6 1))))))
 (let (($x27263 (or (or $x27260 $x27255) (and $x27226 (= ghost_1_23 (- ghost_1_6 1))))))
 (let (($x27279 (>= ghost_1_6 1)))
 (let (($x27278 (and $x27279 (or (or $x27263 $x27262) (and $x27269 (= ghost_1_24 (- ghost_1_6 1)))))))
 (let (($x27186 (= ghost_1_5 1)))
 (let (($x27221 (and $x27227 $x27186)))
 (let (($x27211 (and $x27217 $x27186)))
 (let (($x27206 (and $x27117 $x27186)))
 (let (($x27199 (and $x27172 $x27186)))
 (let (($x27192 (and $x26948 $x27186)))
 (let (($x27193 (or (or false (and $x26997 $x27186)) (and $x26994 (= ghost_1_10 (- ghost_1_5 1))))))
 (let (($x27198 (or (or $x27193 $x27192) (and $x26946 (= ghost_1_0 (- ghost_1_5 1))))))
 (let (($x27205 (or (or $x27198 $x27199) (and $x27171 (= ghost_1_21 (- ghost_1_5 1))))))
 (let (($x27208 (or (or $x27205 $x27206) (and $x27114 (= ghost_1_18 (- ghost_1_5 1))))))
 (let (($x27219 (or (or $x27208 $x27211) (and $x27215 (= ghost_1_22 (- ghost_1_5 1))))))
 (let (($x27235 (>= ghost_1_5 1)))
 (let (($x27234 (and $x27235 (or (or $x27219 $x27221) (and $x27226 (= ghost_1_23 (- ghost_1_5 1)))))))
 (let (($x27136 (= ghost_1_4 1)))
 (let (($x27169 (and $x26948 $x27136)))
 (let (($x27166 (and $x27172 $x27136)))
 (let (($x27154 (and $x27097 $x27136)))
 (let (($x27147 (and $x27157 $x27136)))
 (let (($x27144 (and $x27042 $x27136)))
 (let (($x27145 (or (or false (and $x26982 $x27136)) (and $x26981 (= ghost_1_9 (- ghost_1_4 1))))))
 (let (($x27151 (or (or $x27145 $x27144) (and $x27040 (= ghost_1_13 (- ghost_1_4 1))))))
 (let (($x27153 (or (or $x27151 $x27147) (and $x27156 (= ghost_1_20 (- ghost_1_4 1))))))
 (let (($x27164 (or (or $x27153 $x27154) (and $x27093 (= ghost_1_16 (- ghost_1_4 1))))))
 (let (($x27168 (or (or $x27164 $x27166) (and $x27171 (= ghost_1_21 (- ghost_1_4 1))))))
 (let (($x27184 (>= ghost_1_4 1)))
 (let (($x27182 (and $x27184 (or (or $x27168 $x27169) (and $x26946 (= ghost_1_0 (- ghost_1_4 1)))))))
 (let (($x27076 (= ghost_1_3 1)))
 (let (($x27121 (and $x27127 $x27076)))
 (let (($x27111 (and $x27117 $x27076)))
 (let (($x27101 (and $x27107 $x27076)))
 (let (($x27089 (and $x27097 $x27076)))
 (let (($x27085 (and $x27052 $x27076)))
 (let (($x27081 (or (or false (and $x26948 $x27076)) (and $x26946 (= ghost_1_0 (- ghost_1_3 1))))))
 (let (($x27090 (or (or $x27081 $x27085) (and $x27049 (= ghost_1_14 (- ghost_1_3 1))))))
 (let (($x27098 (or (or $x27090 $x27089) (and $x27093 (= ghost_1_16 (- ghost_1_3 1))))))
 (let (($x27103 (or (or $x27098 $x27101) (and $x27104 (= ghost_1_17 (- ghost_1_3 1))))))
 (let (($x27118 (or (or $x27103 $x27111) (and $x27114 (= ghost_1_18 (- ghost_1_3 1))))))
 (let (($x27134 (>= ghost_1_3 1)))
 (let (($x27132 (and $x27134 (or (or $x27118 $x27121) (and $x27124 (= ghost_1_19 (- ghost_1_3 1)))))))
 (let (($x27019 (= ghost_1_2 1)))
 (let (($x27060 (and $x27067 $x27019)))
 (let (($x27051 (and $x26948 $x27019)))
 (let (($x27046 (and $x27052 $x27019)))
 (let (($x27036 (and $x27042 $x27019)))
 (let (($x27026 (and $x27032 $x27019)))
 (let (($x27025 (or (or false (and $x26972 $x27019)) (and $x26971 (= ghost_1_8 (- ghost_1_2 1))))))
 (let (($x27028 (or (or $x27025 $x27026) (and $x27029 (= ghost_1_12 (- ghost_1_2 1))))))
 (let (($x27038 (or (or $x27028 $x27036) (and $x27040 (= ghost_1_13 (- ghost_1_2 1))))))
 (let (($x27054 (or (or $x27038 $x27046) (and $x27049 (= ghost_1_14 (- ghost_1_2 1))))))
 (let (($x27058 (or (or $x27054 $x27051) (and $x26946 (= ghost_1_0 (- ghost_1_2 1))))))
 (let (($x27073 (>= ghost_1_2 1)))
 (let (($x27072 (and $x27073 (or (or $x27058 $x27060) (and $x27066 (= ghost_1_15 (- ghost_1_2 1)))))))
 (let (($x26954 (= ghost_1_1 1)))
 (let (($x27001 (and $x27007 $x26954)))
 (let (($x26990 (and $x26997 $x26954)))
 (let (($x26979 (and $x26948 $x26954)))
 (let (($x26976 (and $x26982 $x26954)))
 (let (($x26966 (and $x26972 $x26954)))
 (let (($x26956 (or (or false (and $x26960 $x26954)) (and $x26957 (= ghost_1_7 (- ghost_1_1 1))))))
 (let (($x26968 (or (or $x26956 $x26966) (and $x26971 (= ghost_1_8 (- ghost_1_1 1))))))
 (let (($x26983 (or (or $x26968 $x26976) (and $x26981 (= ghost_1_9 (- ghost_1_1 1))))))
 (let (($x26988 (or (or $x26983 $x26979) (and $x26946 (= ghost_1_0 (- ghost_1_1 1))))))
 (let (($x26993 (or (or $x26988 $x26990) (and $x26994 (= ghost_1_10 (- ghost_1_1 1))))))
 (let (($x27014 (>= ghost_1_1 1)))
 (let (($x27015 (and $x27014 (or (or $x26993 $x27001) (and $x27003 (= ghost_1_11 (- ghost_1_1 1)))))))
 (let (($x26878 (= ghost_1_0 1)))
 (let (($x26930 (and $x26936 $x26878)))
 (let (($x26920 (and $x26926 $x26878)))
 (let (($x26910 (and $x26916 $x26878)))
 (let (($x26900 (and $x26906 $x26878)))
 (let (($x26890 (and $x26896 $x26878)))
 (let (($x26884 (or (or false (and $x26883 $x26878)) (and $x26879 (= ghost_1_1 (- ghost_1_0 1))))))
 (let (($x26897 (or (or $x26884 $x26890) (and $x26892 (= ghost_1_2 (- ghost_1_0 1))))))
 (let (($x26908 (or (or $x26897 $x26900) (and $x26902 (= ghost_1_4 (- ghost_1_0 1))))))
 (let (($x26915 (or (or $x26908 $x26910) (and $x26912 (= ghost_1_3 (- ghost_1_0 1))))))
 (let (($x26922 (or (or $x26915 $x26920) (and $x26924 (= ghost_1_5 (- ghost_1_0 1))))))
 (let (($x26945 (>= ghost_1_0 1)))
 (let (($x26944 (and $x26945 (or (or $x26922 $x26930) (and $x26933 (= ghost_1_6 (- ghost_1_0 1)))))))
 (let (($x26740 (or (or c_128_2 c_128_3 c_128_4 c_128_5 c_128_6 c_128_7) c_128_8)))
 (let (($x26714 (or (or c_127_2 c_127_3 c_127_4 c_127_5 c_127_6 c_127_7) c_127_8)))
 (let (($x26534 (or (or c_119_2 c_119_3 c_119_4 c_119_5 c_119_6 c_119_7) c_119_8)))
 (let (($x26216 (or (or c_103_2 c_103_3 c_103_4 c_103_5 c_103_6 c_103_7) c_103_8)))
 (let (($x25898 (or (or c_87_2 c_87_3 c_87_4 c_87_5 c_87_6 c_87_7) c_87_8)))
 (let (($x26723 (or false (and c_62_2 $x25898))))
 (let (($x26725 (or $x26723 (and c_62_3 $x26216))))
 (let (($x26727 (or $x26725 (and c_62_4 (or $x24714 c_24_8)))))
 (let (($x26726 (or $x26727 (and c_62_5 $x26534))))
 (let (($x26730 (or $x26726 (and c_62_6 $x26714))))
 (let (($x25422 (or c_62_2 c_62_3 c_62_4 c_62_5 c_62_6 c_62_7)))
 (let (($x26688 (or (or c_126_2 c_126_3 c_126_4 c_126_5 c_126_6 c_126_7) c_126_8)))
 (let (($x26508 (or (or c_118_2 c_118_3 c_118_4 c_118_5 c_118_6 c_118_7) c_118_8)))
 (let (($x25872 (or (or c_86_2 c_86_3 c_86_4 c_86_5 c_86_6 c_86_7) c_86_8)))
 (let (($x26696 (or false (and c_61_2 $x25872))))
 (let (($x26692 (or $x26696 (and c_61_3 (or $x24714 c_24_8)))))
 (let (($x26695 (or $x26692 (and c_61_4 (or $x24688 c_23_8)))))
 (let (($x26702 (or $x26695 (and c_61_5 $x26508))))
 (let (($x26701 (or $x26702 (and c_61_6 $x26688))))
 (let (($x25396 (or c_61_2 c_61_3 c_61_4 c_61_5 c_61_6 c_61_7)))
 (let (($x26662 (or (or c_125_2 c_125_3 c_125_4 c_125_5 c_125_6 c_125_7) c_125_8)))
 (let (($x26482 (or (or c_117_2 c_117_3 c_117_4 c_117_5 c_117_6 c_117_7) c_117_8)))
 (let (($x25846 (or (or c_85_2 c_85_3 c_85_4 c_85_5 c_85_6 c_85_7) c_85_8)))
 (let (($x26671 (or false (and c_60_2 $x25846))))
 (let (($x26673 (or $x26671 (and c_60_3 (or $x24688 c_23_8)))))
 (let (($x26674 (or $x26673 (and c_60_4 (or $x24674 c_22_8)))))
 (let (($x26676 (or $x26674 (and c_60_5 $x26482))))
 (let (($x26677 (or $x26676 (and c_60_6 $x26662))))
 (let (($x25370 (or c_60_2 c_60_3 c_60_4 c_60_5 c_60_6 c_60_7)))
 (let (($x26648 (or (or c_124_2 c_124_3 c_124_4 c_124_5 c_124_6 c_124_7) c_124_8)))
 (let (($x26468 (or (or c_116_2 c_116_3 c_116_4 c_116_5 c_116_6 c_116_7) c_116_8)))
 (let (($x26622 (or (or c_123_2 c_123_3 c_123_4 c_123_5 c_123_6 c_123_7) c_123_8)))
 (let (($x25832 (or (or c_84_2 c_84_3 c_84_4 c_84_5 c_84_6 c_84_7) c_84_8)))
 (let (($x26629 (or false (and c_59_2 $x25832))))
 (let (($x26631 (or $x26629 (and c_59_3 (or $x24674 c_22_8)))))
 (let (($x26636 (or $x26631 (and c_59_4 $x26622))))
 (let (($x26639 (or $x26636 (and c_59_5 $x26468))))
 (let (($x26651 (or $x26639 (and c_59_6 $x26648))))
 (let (($x25356 (or c_59_2 c_59_3 c_59_4 c_59_5 c_59_6 c_59_7)))
 (let (($x26328 (or (or c_109_2 c_109_3 c_109_4 c_109_5 c_109_6 c_109_7) c_109_8)))
 (let (($x26596 (or (or c_122_2 c_122_3 c_122_4 c_122_5 c_122_6 c_122_7) c_122_8)))
 (let (($x25806 (or (or c_83_2 c_83_3 c_83_4 c_83_5 c_83_6 c_83_7) c_83_8)))
 (let (($x26601 (or false (and c_58_2 $x25806))))
 (let (($x26609 (or $x26601 (and c_58_3 (or $x24648 c_21_8)))))
 (let (($x26611 (or $x26609 (and c_58_4 $x26596))))
 (let (($x26612 (or $x26611 (and c_58_5 $x26328))))
 (let (($x26625 (or $x26612 (and c_58_6 $x26622))))
 (let (($x25330 (or c_58_2 c_58_3 c_58_4 c_58_5 c_58_6 c_58_7)))
 (let (($x26264 (or (or c_106_2 c_106_3 c_106_4 c_106_5 c_106_6 c_106_7) c_106_8)))
 (let (($x26570 (or (or c_121_2 c_121_3 c_121_4 c_121_5 c_121_6 c_121_7) c_121_8)))
 (let (($x25780 (or (or c_82_2 c_82_3 c_82_4 c_82_5 c_82_6 c_82_7) c_82_8)))
 (let (($x26580 (or false (and c_57_2 $x25780))))
 (let (($x26581 (or $x26580 (and c_57_3 (or $x24632 c_20_8)))))
 (let (($x26583 (or $x26581 (and c_57_4 $x26570))))
 (let (($x26579 (or $x26583 (and c_57_5 $x26264))))
 (let (($x26598 (or $x26579 (and c_57_6 $x26596))))
 (let (($x25304 (or c_57_2 c_57_3 c_57_4 c_57_5 c_57_6 c_57_7)))
 (let (($x26236 (or (or c_104_2 c_104_3 c_104_4 c_104_5 c_104_6 c_104_7) c_104_8)))
 (let (($x26554 (or (or c_120_2 c_120_3 c_120_4 c_120_5 c_120_6 c_120_7) c_120_8)))
 (let (($x26082 (or (or c_97_2 c_97_3 c_97_4 c_97_5 c_97_6 c_97_7) c_97_8)))
 (let (($x25764 (or (or c_81_2 c_81_3 c_81_4 c_81_5 c_81_6 c_81_7) c_81_8)))
 (let (($x26541 (or false (and c_56_2 $x25764))))
 (let (($x26542 (or $x26541 (and c_56_3 $x26082))))
 (let (($x26557 (or $x26542 (and c_56_4 $x26554))))
 (let (($x26556 (or $x26557 (and c_56_5 $x26236))))
 (let (($x26575 (or $x26556 (and c_56_6 $x26570))))
 (let (($x25288 (or c_56_2 c_56_3 c_56_4 c_56_5 c_56_6 c_56_7)))
 (let (($x26444 (or (or c_115_2 c_115_3 c_115_4 c_115_5 c_115_6 c_115_7) c_115_8)))
 (let (($x26190 (or (or c_102_2 c_102_3 c_102_4 c_102_5 c_102_6 c_102_7) c_102_8)))
 (let (($x26516 (or false (and c_55_2 (or $x24714 c_24_8)))))
 (let (($x26515 (or $x26516 (and c_55_3 $x26190))))
 (let (($x26519 (or $x26515 (and c_55_4 (or $x24612 c_19_8)))))
 (let (($x26521 (or $x26519 (and c_55_5 $x26444))))
 (let (($x26525 (or $x26521 (and c_55_6 $x26508))))
 (let (($x25268 (or c_55_2 c_55_3 c_55_4 c_55_5 c_55_6 c_55_7)))
 (let (($x26418 (or (or c_114_2 c_114_3 c_114_4 c_114_5 c_114_6 c_114_7) c_114_8)))
 (let (($x26490 (or false (and c_54_2 (or $x24688 c_23_8)))))
 (let (($x26492 (or $x26490 (and c_54_3 (or $x24612 c_19_8)))))
 (let (($x26485 (or $x26492 (and c_54_4 (or $x24598 c_18_8)))))
 (let (($x26493 (or $x26485 (and c_54_5 $x26418))))
 (let (($x26497 (or $x26493 (and c_54_6 $x26482))))
 (let (($x25242 (or c_54_2 c_54_3 c_54_4 c_54_5 c_54_6 c_54_7)))
 (let (($x26404 (or (or c_113_2 c_113_3 c_113_4 c_113_5 c_113_6 c_113_7) c_113_8)))
 (let (($x26453 (or false (and c_53_2 (or $x24674 c_22_8)))))
 (let (($x26454 (or $x26453 (and c_53_3 (or $x24598 c_18_8)))))
 (let (($x26447 (or $x26454 (and c_53_4 $x26328))))
 (let (($x26459 (or $x26447 (and c_53_5 $x26404))))
 (let (($x26470 (or $x26459 (and c_53_6 $x26468))))
 (let (($x25228 (or c_53_2 c_53_3 c_53_4 c_53_5 c_53_6 c_53_7)))
 (let (($x26380 (or (or c_112_2 c_112_3 c_112_4 c_112_5 c_112_6 c_112_7) c_112_8)))
 (let (($x26164 (or (or c_101_2 c_101_3 c_101_4 c_101_5 c_101_6 c_101_7) c_101_8)))
 (let (($x26420 (or false (and c_52_2 (or $x24612 c_19_8)))))
 (let (($x26426 (or $x26420 (and c_52_3 $x26164))))
 (let (($x26431 (or $x26426 (and c_52_4 (or $x24584 c_17_8)))))
 (let (($x26427 (or $x26431 (and c_52_5 $x26380))))
 (let (($x26433 (or $x26427 (and c_52_6 $x26418))))
 (let (($x25204 (or c_52_2 c_52_3 c_52_4 c_52_5 c_52_6 c_52_7)))
 (let (($x26366 (or (or c_111_2 c_111_3 c_111_4 c_111_5 c_111_6 c_111_7) c_111_8)))
 (let (($x26302 (or (or c_108_2 c_108_3 c_108_4 c_108_5 c_108_6 c_108_7) c_108_8)))
 (let (($x26388 (or false (and c_51_2 (or $x24598 c_18_8)))))
 (let (($x26389 (or $x26388 (and c_51_3 (or $x24584 c_17_8)))))
 (let (($x26391 (or $x26389 (and c_51_4 $x26302))))
 (let (($x26395 (or $x26391 (and c_51_5 $x26366))))
 (let (($x26406 (or $x26395 (and c_51_6 $x26404))))
 (let (($x25190 (or c_51_2 c_51_3 c_51_4 c_51_5 c_51_6 c_51_7)))
 (let (($x26352 (or (or c_110_2 c_110_3 c_110_4 c_110_5 c_110_6 c_110_7) c_110_8)))
 (let (($x26288 (or (or c_107_2 c_107_3 c_107_4 c_107_5 c_107_6 c_107_7) c_107_8)))
 (let (($x26148 (or (or c_100_2 c_100_3 c_100_4 c_100_5 c_100_6 c_100_7) c_100_8)))
 (let (($x26338 (or false (and c_50_2 (or $x24584 c_17_8)))))
 (let (($x26337 (or $x26338 (and c_50_3 $x26148))))
 (let (($x26343 (or $x26337 (and c_50_4 $x26288))))
 (let (($x26355 (or $x26343 (and c_50_5 $x26352))))
 (let (($x26370 (or $x26355 (and c_50_6 $x26366))))
 (let (($x25176 (or c_50_2 c_50_3 c_50_4 c_50_5 c_50_6 c_50_7)))
 (let (($x26313 (or false (and c_49_2 (or $x24648 c_21_8)))))
 (let (($x26315 (or $x26313 (and c_49_3 (or $x24570 c_16_8)))))
 (let (($x26316 (or $x26315 (and c_49_4 $x26264))))
 (let (($x26317 (or $x26316 (and c_49_5 $x26302))))
 (let (($x26330 (or $x26317 (and c_49_6 $x26328))))
 (let (($x25152 (or c_49_2 c_49_3 c_49_4 c_49_5 c_49_6 c_49_7)))
 (let (($x26250 (or (or c_105_2 c_105_3 c_105_4 c_105_5 c_105_6 c_105_7) c_105_8)))
 (let (($x26122 (or (or c_99_2 c_99_3 c_99_4 c_99_5 c_99_6 c_99_7) c_99_8)))
 (let (($x26273 (or false (and c_48_2 (or $x24570 c_16_8)))))
 (let (($x26276 (or $x26273 (and c_48_3 $x26122))))
 (let (($x26278 (or $x26276 (and c_48_4 $x26250))))
 (let (($x26293 (or $x26278 (and c_48_5 $x26288))))
 (let (($x26304 (or $x26293 (and c_48_6 $x26302))))
 (let (($x25138 (or c_48_2 c_48_3 c_48_4 c_48_5 c_48_6 c_48_7)))
 (let (($x26096 (or (or c_98_2 c_98_3 c_98_4 c_98_5 c_98_6 c_98_7) c_98_8)))
 (let (($x26225 (or false (and c_47_2 (or $x24632 c_20_8)))))
 (let (($x26224 (or $x26225 (and c_47_3 $x26096))))
 (let (($x26239 (or $x26224 (and c_47_4 $x26236))))
 (let (($x26253 (or $x26239 (and c_47_5 $x26250))))
 (let (($x26268 (or $x26253 (and c_47_6 $x26264))))
 (let (($x25124 (or c_47_2 c_47_3 c_47_4 c_47_5 c_47_6 c_47_7)))
 (let (($x26062 (or (or c_96_2 c_96_3 c_96_4 c_96_5 c_96_6 c_96_7) c_96_8)))
 (let (($x25744 (or (or c_80_2 c_80_3 c_80_4 c_80_5 c_80_6 c_80_7) c_80_8)))
 (let (($x26197 (or false (and c_46_2 $x25744))))
 (let (($x26200 (or $x26197 (and c_46_3 $x26062))))
 (let (($x26202 (or $x26200 (and c_46_4 (or $x24550 c_15_8)))))
 (let (($x26205 (or $x26202 (and c_46_5 $x26190))))
 (let (($x26204 (or $x26205 (and c_46_6 (or $x24714 c_24_8)))))
 (let (($x25104 (or c_46_2 c_46_3 c_46_4 c_46_5 c_46_6 c_46_7)))
 (let (($x26036 (or (or c_95_2 c_95_3 c_95_4 c_95_5 c_95_6 c_95_7) c_95_8)))
 (let (($x26171 (or false (and c_45_2 (or $x24550 c_15_8)))))
 (let (($x26175 (or $x26171 (and c_45_3 $x26036))))
 (let (($x26176 (or $x26175 (and c_45_4 (or $x24534 c_14_8)))))
 (let (($x26172 (or $x26176 (and c_45_5 $x26164))))
 (let (($x26181 (or $x26172 (and c_45_6 (or $x24612 c_19_8)))))
 (let (($x25078 (or c_45_2 c_45_3 c_45_4 c_45_5 c_45_6 c_45_7)))
 (let (($x26020 (or (or c_94_2 c_94_3 c_94_4 c_94_5 c_94_6 c_94_7) c_94_8)))
 (let (($x26127 (or false (and c_44_2 (or $x24534 c_14_8)))))
 (let (($x26134 (or $x26127 (and c_44_3 $x26020))))
 (let (($x26137 (or $x26134 (and c_44_4 $x26122))))
 (let (($x26152 (or $x26137 (and c_44_5 $x26148))))
 (let (($x26151 (or $x26152 (and c_44_6 (or $x24584 c_17_8)))))
 (let (($x25062 (or c_44_2 c_44_3 c_44_4 c_44_5 c_44_6 c_44_7)))
 (let (($x25994 (or (or c_93_2 c_93_3 c_93_4 c_93_5 c_93_6 c_93_7) c_93_8)))
 (let (($x26103 (or false (and c_43_2 (or $x24520 c_13_8)))))
 (let (($x26110 (or $x26103 (and c_43_3 $x25994))))
 (let (($x26113 (or $x26110 (and c_43_4 $x26096))))
 (let (($x26125 (or $x26113 (and c_43_5 $x26122))))
 (let (($x26124 (or $x26125 (and c_43_6 (or $x24570 c_16_8)))))
 (let (($x25036 (or c_43_2 c_43_3 c_43_4 c_43_5 c_43_6 c_43_7)))
 (let (($x25980 (or (or c_92_2 c_92_3 c_92_4 c_92_5 c_92_6 c_92_7) c_92_8)))
 (let (($x25712 (or (or c_79_2 c_79_3 c_79_4 c_79_5 c_79_6 c_79_7) c_79_8)))
 (let (($x26069 (or false (and c_42_2 $x25712))))
 (let (($x26071 (or $x26069 (and c_42_3 $x25980))))
 (let (($x26084 (or $x26071 (and c_42_4 $x26082))))
 (let (($x26098 (or $x26084 (and c_42_5 $x26096))))
 (let (($x26099 (or $x26098 (and c_42_6 (or $x24632 c_20_8)))))
 (let (($x25022 (or c_42_2 c_42_3 c_42_4 c_42_5 c_42_6 c_42_7)))
 (let (($x25960 (or (or c_91_2 c_91_3 c_91_4 c_91_5 c_91_6 c_91_7) c_91_8)))
 (let (($x25692 (or (or c_78_2 c_78_3 c_78_4 c_78_5 c_78_6 c_78_7) c_78_8)))
 (let (($x26038 (or false (and c_41_2 $x25692))))
 (let (($x26045 (or $x26038 (and c_41_3 $x25960))))
 (let (($x26047 (or $x26045 (and c_41_4 (or $x24506 c_12_8)))))
 (let (($x26049 (or $x26047 (and c_41_5 $x26036))))
 (let (($x26052 (or $x26049 (and c_41_6 (or $x24550 c_15_8)))))
 (let (($x25002 (or c_41_2 c_41_3 c_41_4 c_41_5 c_41_6 c_41_7)))
 (let (($x25944 (or (or c_90_2 c_90_3 c_90_4 c_90_5 c_90_6 c_90_7) c_90_8)))
 (let (($x26007 (or false (and c_40_2 (or $x24506 c_12_8)))))
 (let (($x26006 (or $x26007 (and c_40_3 $x25944))))
 (let (($x26001 (or $x26006 (and c_40_4 $x25994))))
 (let (($x26024 (or $x26001 (and c_40_5 $x26020))))
 (let (($x26025 (or $x26024 (and c_40_6 (or $x24534 c_14_8)))))
 (let (($x24986 (or c_40_2 c_40_3 c_40_4 c_40_5 c_40_6 c_40_7)))
 (let (($x25930 (or (or c_89_2 c_89_3 c_89_4 c_89_5 c_89_6 c_89_7) c_89_8)))
 (let (($x25674 (or (or c_77_2 c_77_3 c_77_4 c_77_5 c_77_6 c_77_7) c_77_8)))
 (let (($x25965 (or false (and c_39_2 $x25674))))
 (let (($x25967 (or $x25965 (and c_39_3 $x25930))))
 (let (($x25984 (or $x25967 (and c_39_4 $x25980))))
 (let (($x25997 (or $x25984 (and c_39_5 $x25994))))
 (let (($x25996 (or $x25997 (and c_39_6 (or $x24520 c_13_8)))))
 (let (($x24972 (or c_39_2 c_39_3 c_39_4 c_39_5 c_39_6 c_39_7)))
 (let (($x25916 (or (or c_88_2 c_88_3 c_88_4 c_88_5 c_88_6 c_88_7) c_88_8)))
 (let (($x25660 (or (or c_76_2 c_76_3 c_76_4 c_76_5 c_76_6 c_76_7) c_76_8)))
 (let (($x25902 (or false (and c_38_2 $x25660))))
 (let (($x25921 (or $x25902 (and c_38_3 $x25916))))
 (let (($x25932 (or $x25921 (and c_38_4 $x25930))))
 (let (($x25948 (or $x25932 (and c_38_5 $x25944))))
 (let (($x25947 (or $x25948 (and c_38_6 (or $x24506 c_12_8)))))
 (let (($x24958 (or c_38_2 c_38_3 c_38_4 c_38_5 c_38_6 c_38_7)))
 (let (($x25642 (or (or c_75_2 c_75_3 c_75_4 c_75_5 c_75_6 c_75_7) c_75_8)))
 (let (($x25879 (or false (and c_37_2 $x25642))))
 (let (($x25880 (or $x25879 (and c_37_3 $x25744))))
 (let (($x25884 (or $x25880 (and c_37_4 (or $x24488 c_11_8)))))
 (let (($x25883 (or $x25884 (and c_37_5 (or $x24714 c_24_8)))))
 (let (($x25886 (or $x25883 (and c_37_6 $x25872))))
 (let (($x24940 (or c_37_2 c_37_3 c_37_4 c_37_5 c_37_6 c_37_7)))
 (let (($x25616 (or (or c_74_2 c_74_3 c_74_4 c_74_5 c_74_6 c_74_7) c_74_8)))
 (let (($x25853 (or false (and c_36_2 $x25616))))
 (let (($x25857 (or $x25853 (and c_36_3 (or $x24488 c_11_8)))))
 (let (($x25854 (or $x25857 (and c_36_4 (or $x24474 c_10_8)))))
 (let (($x25858 (or $x25854 (and c_36_5 (or $x24688 c_23_8)))))
 (let (($x25862 (or $x25858 (and c_36_6 $x25846))))
 (let (($x24914 (or c_36_2 c_36_3 c_36_4 c_36_5 c_36_6 c_36_7)))
 (let (($x25602 (or (or c_73_2 c_73_3 c_73_4 c_73_5 c_73_6 c_73_7) c_73_8)))
 (let (($x25816 (or false (and c_35_2 $x25602))))
 (let (($x25815 (or $x25816 (and c_35_3 (or $x24474 c_10_8)))))
 (let (($x25819 (or $x25815 (and c_35_4 $x25806))))
 (let (($x25823 (or $x25819 (and c_35_5 (or $x24674 c_22_8)))))
 (let (($x25834 (or $x25823 (and c_35_6 $x25832))))
 (let (($x24900 (or c_35_2 c_35_3 c_35_4 c_35_5 c_35_6 c_35_7)))
 (let (($x25576 (or (or c_72_2 c_72_3 c_72_4 c_72_5 c_72_6 c_72_7) c_72_8)))
 (let (($x25790 (or false (and c_34_2 $x25576))))
 (let (($x25788 (or $x25790 (and c_34_3 (or $x24457 c_9_8)))))
 (let (($x25792 (or $x25788 (and c_34_4 $x25780))))
 (let (($x25794 (or $x25792 (and c_34_5 (or $x24648 c_21_8)))))
 (let (($x25810 (or $x25794 (and c_34_6 $x25806))))
 (let (($x24874 (or c_34_2 c_34_3 c_34_4 c_34_5 c_34_6 c_34_7)))
 (let (($x25560 (or (or c_71_2 c_71_3 c_71_4 c_71_5 c_71_6 c_71_7) c_71_8)))
 (let (($x25753 (or false (and c_33_2 $x25560))))
 (let (($x25752 (or $x25753 (and c_33_3 $x25712))))
 (let (($x25768 (or $x25752 (and c_33_4 $x25764))))
 (let (($x25766 (or $x25768 (and c_33_5 (or $x24632 c_20_8)))))
 (let (($x25784 (or $x25766 (and c_33_6 $x25780))))
 (let (($x24858 (or c_33_2 c_33_3 c_33_4 c_33_5 c_33_6 c_33_7)))
 (let (($x25540 (or (or c_70_2 c_70_3 c_70_4 c_70_5 c_70_6 c_70_7) c_70_8)))
 (let (($x25726 (or false (and c_32_2 $x25540))))
 (let (($x25722 (or $x25726 (and c_32_3 $x25692))))
 (let (($x25727 (or $x25722 (and c_32_4 (or $x24443 c_8_8)))))
 (let (($x25733 (or $x25727 (and c_32_5 (or $x24550 c_15_8)))))
 (let (($x25735 (or $x25733 (and c_32_6 (or $x24488 c_11_8)))))
 (let (($x24838 (or c_32_2 c_32_3 c_32_4 c_32_5 c_32_6 c_32_7)))
 (let (($x25522 (or (or c_69_2 c_69_3 c_69_4 c_69_5 c_69_6 c_69_7) c_69_8)))
 (let (($x25701 (or false (and c_31_2 $x25522))))
 (let (($x25699 (or $x25701 (and c_31_3 $x25674))))
 (let (($x25715 (or $x25699 (and c_31_4 $x25712))))
 (let (($x25717 (or $x25715 (and c_31_5 (or $x24520 c_13_8)))))
 (let (($x25720 (or $x25717 (and c_31_6 (or $x24457 c_9_8)))))
 (let (($x24820 (or c_31_2 c_31_3 c_31_4 c_31_5 c_31_6 c_31_7)))
 (let (($x25508 (or (or c_68_2 c_68_3 c_68_4 c_68_5 c_68_6 c_68_7) c_68_8)))
 (let (($x25649 (or false (and c_30_2 $x25508))))
 (let (($x25665 (or $x25649 (and c_30_3 $x25660))))
 (let (($x25677 (or $x25665 (and c_30_4 $x25674))))
 (let (($x25678 (or $x25677 (and c_30_5 (or $x24506 c_12_8)))))
 (let (($x25681 (or $x25678 (and c_30_6 (or $x24443 c_8_8)))))
 (let (($x24806 (or c_30_2 c_30_3 c_30_4 c_30_5 c_30_6 c_30_7)))
 (let (($x25490 (or (or c_67_2 c_67_3 c_67_4 c_67_5 c_67_6 c_67_7) c_67_8)))
 (let (($x25624 (or false (and c_29_2 $x25490))))
 (let (($x25627 (or $x25624 (and c_29_3 $x25540))))
 (let (($x25619 (or $x25627 (and c_29_4 (or $x24429 c_7_8)))))
 (let (($x25631 (or $x25619 (and c_29_5 (or $x24488 c_11_8)))))
 (let (($x25630 (or $x25631 (and c_29_6 $x25616))))
 (let (($x24788 (or c_29_2 c_29_3 c_29_4 c_29_5 c_29_6 c_29_7)))
 (let (($x25476 (or (or c_66_2 c_66_3 c_66_4 c_66_5 c_66_6 c_66_7) c_66_8)))
 (let (($x25584 (or false (and c_28_2 $x25476))))
 (let (($x25588 (or $x25584 (and c_28_3 (or $x24429 c_7_8)))))
 (let (($x25591 (or $x25588 (and c_28_4 $x25576))))
 (let (($x25580 (or $x25591 (and c_28_5 (or $x24474 c_10_8)))))
 (let (($x25605 (or $x25580 (and c_28_6 $x25602))))
 (let (($x24774 (or c_28_2 c_28_3 c_28_4 c_28_5 c_28_6 c_28_7)))
 (let (($x25460 (or (or c_65_2 c_65_3 c_65_4 c_65_5 c_65_6 c_65_7) c_65_8)))
 (let (($x25545 (or false (and c_27_2 $x25460))))
 (let (($x25550 (or $x25545 (and c_27_3 $x25522))))
 (let (($x25565 (or $x25550 (and c_27_4 $x25560))))
 (let (($x25562 (or $x25565 (and c_27_5 (or $x24457 c_9_8)))))
 (let (($x25581 (or $x25562 (and c_27_6 $x25576))))
 (let (($x24758 (or c_27_2 c_27_3 c_27_4 c_27_5 c_27_6 c_27_7)))
 (let (($x25446 (or (or c_64_2 c_64_3 c_64_4 c_64_5 c_64_6 c_64_7) c_64_8)))
 (let (($x25494 (or false (and c_26_2 $x25446))))
 (let (($x25511 (or $x25494 (and c_26_3 $x25508))))
 (let (($x25526 (or $x25511 (and c_26_4 $x25522))))
 (let (($x25524 (or $x25526 (and c_26_5 (or $x24443 c_8_8)))))
 (let (($x25531 (or $x25524 (and c_26_6 (or $x24429 c_7_8)))))
 (let (($x24744 (or c_26_2 c_26_3 c_26_4 c_26_5 c_26_6 c_26_7)))
 (let (($x25432 (or (or c_63_2 c_63_3 c_63_4 c_63_5 c_63_6 c_63_7) c_63_8)))
 (let (($x25436 (or false (and c_25_2 $x25432))))
 (let (($x25448 (or $x25436 (and c_25_3 $x25446))))
 (let (($x25462 (or $x25448 (and c_25_4 $x25460))))
 (let (($x25463 (or $x25462 (and c_25_5 (or $x24429 c_7_8)))))
 (let (($x25479 (or $x25463 (and c_25_6 $x25476))))
 (let (($x24730 (or c_25_2 c_25_3 c_25_4 c_25_5 c_25_6 c_25_7)))
 (let (($x25398 (or false (and c_24_2 (or $x24940 c_37_8)))))
 (let (($x25399 (or $x25398 (and c_24_3 (or $x25104 c_46_8)))))
 (let (($x25403 (or $x25399 (and c_24_4 (or $x24402 c_6_8)))))
 (let (($x25401 (or $x25403 (and c_24_5 (or $x25268 c_55_8)))))
 (let (($x25402 (or $x25401 (and c_24_6 (or $x25396 c_61_8)))))
 (let (($x25372 (or false (and c_23_2 (or $x24914 c_36_8)))))
 (let (($x25371 (or $x25372 (and c_23_3 (or $x24402 c_6_8)))))
 (let (($x25375 (or $x25371 (and c_23_4 (or $x24388 c_5_8)))))
 (let (($x25378 (or $x25375 (and c_23_5 (or $x25242 c_54_8)))))
 (let (($x25380 (or $x25378 (and c_23_6 (or $x25370 c_60_8)))))
 (let (($x25335 (or false (and c_22_2 (or $x24900 c_35_8)))))
 (let (($x25331 (or $x25335 (and c_22_3 (or $x24388 c_5_8)))))
 (let (($x25338 (or $x25331 (and c_22_4 (or $x25330 c_58_8)))))
 (let (($x25339 (or $x25338 (and c_22_5 (or $x25228 c_53_8)))))
 (let (($x25354 (or $x25339 (and c_22_6 (or $x25356 c_59_8)))))
 (let (($x25307 (or false (and c_21_2 (or $x24874 c_34_8)))))
 (let (($x25310 (or $x25307 (and c_21_3 (or $x24360 c_4_8)))))
 (let (($x25309 (or $x25310 (and c_21_4 (or $x25304 c_57_8)))))
 (let (($x25305 (or $x25309 (and c_21_5 (or $x25152 c_49_8)))))
 (let (($x25328 (or $x25305 (and c_21_6 (or $x25330 c_58_8)))))
 (let (($x25269 (or false (and c_20_2 (or $x24858 c_33_8)))))
 (let (($x25272 (or $x25269 (and c_20_3 (or $x25022 c_42_8)))))
 (let (($x25284 (or $x25272 (and c_20_4 (or $x25288 c_56_8)))))
 (let (($x25287 (or $x25284 (and c_20_5 (or $x25124 c_47_8)))))
 (let (($x25302 (or $x25287 (and c_20_6 (or $x25304 c_57_8)))))
 (let (($x25243 (or false (and c_19_2 (or $x24402 c_6_8)))))
 (let (($x25245 (or $x25243 (and c_19_3 (or $x25078 c_45_8)))))
 (let (($x25244 (or $x25245 (and c_19_4 (or $x24374 c_3_8)))))
 (let (($x25247 (or $x25244 (and c_19_5 (or $x25204 c_52_8)))))
 (let (($x25253 (or $x25247 (and c_19_6 (or $x25242 c_54_8)))))
 (let (($x25205 (or false (and c_18_2 (or $x24388 c_5_8)))))
 (let (($x25208 (or $x25205 (and c_18_3 (or $x24374 c_3_8)))))
 (let (($x25207 (or $x25208 (and c_18_4 (or $x25152 c_49_8)))))
 (let (($x25212 (or $x25207 (and c_18_5 (or $x25190 c_51_8)))))
 (let (($x25227 (or $x25212 (and c_18_6 (or $x25228 c_53_8)))))
 (let (($x25156 (or false (and c_17_2 (or $x24374 c_3_8)))))
 (let (($x25153 (or $x25156 (and c_17_3 (or $x25062 c_44_8)))))
 (let (($x25159 (or $x25153 (and c_17_4 (or $x25138 c_48_8)))))
 (let (($x25173 (or $x25159 (and c_17_5 (or $x25176 c_50_8)))))
 (let (($x25187 (or $x25173 (and c_17_6 (or $x25190 c_51_8)))))
 (let (($x25107 (or false (and c_16_2 (or $x24360 c_4_8)))))
 (let (($x25105 (or $x25107 (and c_16_3 (or $x25036 c_43_8)))))
 (let (($x25122 (or $x25105 (and c_16_4 (or $x25124 c_47_8)))))
 (let (($x25136 (or $x25122 (and c_16_5 (or $x25138 c_48_8)))))
 (let (($x25148 (or $x25136 (and c_16_6 (or $x25152 c_49_8)))))
 (let (($x25079 (or false (and c_15_2 (or $x24838 c_32_8)))))
 (let (($x25083 (or $x25079 (and c_15_3 (or $x25002 c_41_8)))))
 (let (($x25082 (or $x25083 (and c_15_4 (or $x24346 c_2_8)))))
 (let (($x25085 (or $x25082 (and c_15_5 (or $x25078 c_45_8)))))
 (let (($x25087 (or $x25085 (and c_15_6 (or $x24402 c_6_8)))))
 (let (($x25042 (or false (and c_14_2 (or $x24346 c_2_8)))))
 (let (($x25041 (or $x25042 (and c_14_3 (or $x24986 c_40_8)))))
 (let (($x25037 (or $x25041 (and c_14_4 (or $x25036 c_43_8)))))
 (let (($x25061 (or $x25037 (and c_14_5 (or $x25062 c_44_8)))))
 (let (($x25058 (or $x25061 (and c_14_6 (or $x24374 c_3_8)))))
 (let (($x25003 (or false (and c_13_2 (or $x24820 c_31_8)))))
 (let (($x25006 (or $x25003 (and c_13_3 (or $x24972 c_39_8)))))
 (let (($x25020 (or $x25006 (and c_13_4 (or $x25022 c_42_8)))))
 (let (($x25035 (or $x25020 (and c_13_5 (or $x25036 c_43_8)))))
 (let (($x25032 (or $x25035 (and c_13_6 (or $x24360 c_4_8)))))
 (let (($x24939 (or false (and c_12_2 (or $x24806 c_30_8)))))
 (let (($x24956 (or $x24939 (and c_12_3 (or $x24958 c_38_8)))))
 (let (($x24969 (or $x24956 (and c_12_4 (or $x24972 c_39_8)))))
 (let (($x24983 (or $x24969 (and c_12_5 (or $x24986 c_40_8)))))
 (let (($x24985 (or $x24983 (and c_12_6 (or $x24346 c_2_8)))))
 (let (($x24915 (or false (and c_11_2 (or $x24788 c_29_8)))))
 (let (($x24917 (or $x24915 (and c_11_3 (or $x24838 c_32_8)))))
 (let (($x24921 (or $x24917 (and c_11_4 (or $x24332 c_1_8)))))
 (let (($x24923 (or $x24921 (and c_11_5 (or $x24402 c_6_8)))))
 (let (($x24918 (or $x24923 (and c_11_6 (or $x24914 c_36_8)))))
 (let (($x24870 (or false (and c_10_2 (or $x24774 c_28_8)))))
 (let (($x24880 (or $x24870 (and c_10_3 (or $x24332 c_1_8)))))
 (let (($x24883 (or $x24880 (and c_10_4 (or $x24874 c_34_8)))))
 (let (($x24884 (or $x24883 (and c_10_5 (or $x24388 c_5_8)))))
 (let (($x24896 (or $x24884 (and c_10_6 (or $x24900 c_35_8)))))
 (let (($x24841 (or false (and c_9_2 (or $x24758 c_27_8)))))
 (let (($x24836 (or $x24841 (and c_9_3 (or $x24820 c_31_8)))))
 (let (($x24855 (or $x24836 (and c_9_4 (or $x24858 c_33_8)))))
 (let (($x24857 (or $x24855 (and c_9_5 (or $x24360 c_4_8)))))
 (let (($x24873 (or $x24857 (and c_9_6 (or $x24874 c_34_8)))))
 (let (($x24791 (or false (and c_8_2 (or $x24744 c_26_8)))))
 (let (($x24802 (or $x24791 (and c_8_3 (or $x24806 c_30_8)))))
 (let (($x24817 (or $x24802 (and c_8_4 (or $x24820 c_31_8)))))
 (let (($x24816 (or $x24817 (and c_8_5 (or $x24346 c_2_8)))))
 (let (($x24819 (or $x24816 (and c_8_6 (or $x24332 c_1_8)))))
 (let (($x24728 (or false (and c_7_2 (or $x24730 c_25_8)))))
 (let (($x24742 (or $x24728 (and c_7_3 (or $x24744 c_26_8)))))
 (let (($x24756 (or $x24742 (and c_7_4 (or $x24758 c_27_8)))))
 (let (($x24755 (or $x24756 (and c_7_5 (or $x24332 c_1_8)))))
 (let (($x24773 (or $x24755 (and c_7_6 (or $x24774 c_28_8)))))
 (let (($x24690 (or false (and c_6_2 (or $x24488 c_11_8)))))
 (let (($x24689 (or $x24690 (and c_6_3 (or $x24550 c_15_8)))))
 (let (($x24695 (or $x24689 (and c_6_4 (or $x24416 c_0_8)))))
 (let (($x24694 (or $x24695 (and c_6_5 (or $x24612 c_19_8)))))
 (let (($x24697 (or $x24694 (and c_6_6 (or $x24688 c_23_8)))))
 (let (($x24650 (or false (and c_5_2 (or $x24474 c_10_8)))))
 (let (($x24651 (or $x24650 (and c_5_3 (or $x24416 c_0_8)))))
 (let (($x24655 (or $x24651 (and c_5_4 (or $x24648 c_21_8)))))
 (let (($x24659 (or $x24655 (and c_5_5 (or $x24598 c_18_8)))))
 (let (($x24670 (or $x24659 (and c_5_6 (or $x24674 c_22_8)))))
 (let (($x24608 (or false (and c_4_2 (or $x24457 c_9_8)))))
 (let (($x24615 (or $x24608 (and c_4_3 (or $x24520 c_13_8)))))
 (let (($x24630 (or $x24615 (and c_4_4 (or $x24632 c_20_8)))))
 (let (($x24629 (or $x24630 (and c_4_5 (or $x24570 c_16_8)))))
 (let (($x24646 (or $x24629 (and c_4_6 (or $x24648 c_21_8)))))
 (let (($x24548 (or false (and c_3_2 (or $x24416 c_0_8)))))
 (let (($x24553 (or $x24548 (and c_3_3 (or $x24534 c_14_8)))))
 (let (($x24567 (or $x24553 (and c_3_4 (or $x24570 c_16_8)))))
 (let (($x24582 (or $x24567 (and c_3_5 (or $x24584 c_17_8)))))
 (let (($x24594 (or $x24582 (and c_3_6 (or $x24598 c_18_8)))))
 (let (($x24491 (or false (and c_2_2 (or $x24443 c_8_8)))))
 (let (($x24504 (or $x24491 (and c_2_3 (or $x24506 c_12_8)))))
 (let (($x24519 (or $x24504 (and c_2_4 (or $x24520 c_13_8)))))
 (let (($x24532 (or $x24519 (and c_2_5 (or $x24534 c_14_8)))))
 (let (($x24533 (or $x24532 (and c_2_6 (or $x24416 c_0_8)))))
 (let (($x24426 (or false (and c_1_2 (or $x24429 c_7_8)))))
 (let (($x24440 (or $x24426 (and c_1_3 (or $x24443 c_8_8)))))
 (let (($x24453 (or $x24440 (and c_1_4 (or $x24457 c_9_8)))))
 (let (($x24456 (or $x24453 (and c_1_5 (or $x24416 c_0_8)))))
 (let (($x24472 (or $x24456 (and c_1_6 (or $x24474 c_10_8)))))
 (let (($x24330 (or false (and c_0_2 (or $x24332 c_1_8)))))
 (let (($x24344 (or $x24330 (and c_0_3 (or $x24346 c_2_8)))))
 (let (($x24358 (or $x24344 (and c_0_4 (or $x24360 c_4_8)))))
 (let (($x24372 (or $x24358 (and c_0_5 (or $x24374 c_3_8)))))
 (let (($x24384 (or $x24372 (and c_0_6 (or $x24388 c_5_8)))))
 (let (($x24313 (not (and c_62_8 (not in_target_62)))))
 (let (($x24308 (not (and c_61_8 (not in_target_61)))))
 (let (($x24303 (not (and c_60_8 (not in_target_60)))))
 (let (($x24298 (not (and c_59_8 (not in_target_59)))))
 (let (($x24293 (not (and c_58_8 (not in_target_58)))))
 (let (($x24288 (not (and c_57_8 (not in_target_57)))))
 (let (($x24283 (not (and c_56_8 (not in_target_56)))))
 (let (($x24278 (not (and c_55_8 (not in_target_55)))))
 (let (($x24273 (not (and c_54_8 (not in_target_54)))))
 (let (($x24268 (not (and c_53_8 (not in_target_53)))))
 (let (($x24263 (not (and c_52_8 (not in_target_52)))))
 (let (($x24258 (not (and c_51_8 (not in_target_51)))))
 (let (($x24253 (not (and c_50_8 (not in_target_50)))))
 (let (($x24248 (not (and c_49_8 (not in_target_49)))))
 (let (($x24243 (not (and c_48_8 (not in_target_48)))))
 (let (($x24238 (not (and c_47_8 (not in_target_47)))))
 (let (($x24233 (not (and c_46_8 (not in_target_46)))))
 (let (($x24228 (not (and c_45_8 (not in_target_45)))))
 (let (($x24223 (not (and c_44_8 (not in_target_44)))))
 (let (($x24218 (not (and c_43_8 (not in_target_43)))))
 (let (($x24213 (not (and c_42_8 (not in_target_42)))))
 (let (($x24208 (not (and c_41_8 (not in_target_41)))))
 (let (($x24203 (not (and c_40_8 (not in_target_40)))))
 (let (($x24198 (not (and c_39_8 (not in_target_39)))))
 (let (($x24193 (not (and c_38_8 (not in_target_38)))))
 (let (($x24188 (not (and c_37_8 (not in_target_37)))))
 (let (($x24183 (not (and c_36_8 (not in_target_36)))))
 (let (($x24178 (not (and c_35_8 (not in_target_35)))))
 (let (($x24173 (not (and c_34_8 (not in_target_34)))))
 (let (($x24168 (not (and c_33_8 (not in_target_33)))))
 (let (($x24163 (not (and c_32_8 (not in_target_32)))))
 (let (($x24158 (not (and c_31_8 (not in_target_31)))))
 (let (($x24153 (not (and c_30_8 (not in_target_30)))))
 (let (($x24148 (not (and c_29_8 (not in_target_29)))))
 (let (($x24143 (not (and c_28_8 (not in_target_28)))))
 (let (($x24138 (not (and c_27_8 (not in_target_27)))))
 (let (($x24133 (not (and c_26_8 (not in_target_26)))))
 (let (($x24128 (not (and c_25_8 (not in_target_25)))))
 (let (($x24123 (not (and c_24_8 (not in_target_24)))))
 (let (($x24118 (not (and c_23_8 (not in_target_23)))))
 (let (($x24113 (not (and c_22_8 (not in_target_22)))))
 (let (($x24108 (not (and c_21_8 (not in_target_21)))))
 (let (($x24103 (not (and c_20_8 (not in_target_20)))))
 (let (($x24098 (not (and c_19_8 (not in_target_19)))))
 (let (($x24093 (not (and c_18_8 (not in_target_18)))))
 (let (($x24088 (not (and c_17_8 (not in_target_17)))))
 (let (($x24083 (not (and c_16_8 (not in_target_16)))))
 (let (($x24078 (not (and c_15_8 (not in_target_15)))))
 (let (($x24073 (not (and c_14_8 (not in_target_14)))))
 (let (($x24068 (not (and c_13_8 (not in_target_13)))))
 (let (($x24063 (not (and c_12_8 (not in_target_12)))))
 (let (($x24058 (not (and c_11_8 (not in_target_11)))))
 (let (($x24053 (not (and c_10_8 (not in_target_10)))))
 (let (($x24048 (not (and c_9_8 (not in_target_9)))))
 (let (($x24043 (not (and c_8_8 (not in_target_8)))))
 (let (($x24038 (not (and c_7_8 (not in_target_7)))))
 (let (($x24033 (not (and c_6_8 (not in_target_6)))))
 (let (($x24028 (not (and c_5_8 (not in_target_5)))))
 (let (($x24023 (not (and c_4_8 (not in_target_4)))))
 (let (($x24018 (not (and c_3_8 (not in_target_3)))))
 (let (($x24013 (not (and c_2_8 (not in_target_2)))))
 (let (($x24008 (not (and c_1_8 (not in_target_1)))))
 (let (($x24003 (not (and c_0_8 (not in_target_0)))))
 (let (($x23998 (or in_region_128 (and c_128_0 (not in_target_128)))))
 (let (($x23993 (or in_region_127 (and c_127_0 (not in_target_127)))))
 (let (($x23988 (or in_region_126 (and c_126_0 (not in_target_126)))))
 (let (($x23983 (or in_region_125 (and c_125_0 (not in_target_125)))))
 (let (($x23978 (or in_region_124 (and c_124_0 (not in_target_124)))))
 (let (($x23973 (or in_region_123 (and c_123_0 (not in_target_123)))))
 (let (($x23968 (or in_region_122 (and c_122_0 (not in_target_122)))))
 (let (($x23963 (or in_region_121 (and c_121_0 (not in_target_121)))))
 (let (($x23958 (or in_region_120 (and c_120_0 (not in_target_120)))))
 (let (($x23953 (or in_region_119 (and c_119_0 (not in_target_119)))))
 (let (($x23948 (or in_region_118 (and c_118_0 (not in_target_118)))))
 (let (($x23943 (or in_region_117 (and c_117_0 (not in_target_117)))))
 (let (($x23938 (or in_region_116 (and c_116_0 (not in_target_116)))))
 (let (($x23933 (or in_region_115 (and c_115_0 (not in_target_115)))))
 (let (($x23928 (or in_region_114 (and c_114_0 (not in_target_114)))))
 (let (($x23923 (or in_region_113 (and c_113_0 (not in_target_113)))))
 (let (($x23918 (or in_region_112 (and c_112_0 (not in_target_112)))))
 (let (($x23913 (or in_region_111 (and c_111_0 (not in_target_111)))))
 (let (($x23908 (or in_region_110 (and c_110_0 (not in_target_110)))))
 (let (($x23903 (or in_region_109 (and c_109_0 (not in_target_109)))))
 (let (($x23898 (or in_region_108 (and c_108_0 (not in_target_108)))))
 (let (($x23893 (or in_region_107 (and c_107_0 (not in_target_107)))))
 (let (($x23888 (or in_region_106 (and c_106_0 (not in_target_106)))))
 (let (($x23883 (or in_region_105 (and c_105_0 (not in_target_105)))))
 (let (($x23878 (or in_region_104 (and c_104_0 (not in_target_104)))))
 (let (($x23873 (or in_region_103 (and c_103_0 (not in_target_103)))))
 (let (($x23868 (or in_region_102 (and c_102_0 (not in_target_102)))))
 (let (($x23863 (or in_region_101 (and c_101_0 (not in_target_101)))))
 (let (($x23858 (or in_region_100 (and c_100_0 (not in_target_100)))))
 (let (($x23853 (or in_region_99 (and c_99_0 (not in_target_99)))))
 (let (($x23848 (or in_region_98 (and c_98_0 (not in_target_98)))))
 (let (($x23843 (or in_region_97 (and c_97_0 (not in_target_97)))))
 (let (($x23838 (or in_region_96 (and c_96_0 (not in_target_96)))))
 (let (($x23833 (or in_region_95 (and c_95_0 (not in_target_95)))))
 (let (($x23828 (or in_region_94 (and c_94_0 (not in_target_94)))))
 (let (($x23823 (or in_region_93 (and c_93_0 (not in_target_93)))))
 (let (($x23818 (or in_region_92 (and c_92_0 (not in_target_92)))))
 (let (($x23813 (or in_region_91 (and c_91_0 (not in_target_91)))))
 (let (($x23808 (or in_region_90 (and c_90_0 (not in_target_90)))))
 (let (($x23803 (or in_region_89 (and c_89_0 (not in_target_89)))))
 (let (($x23798 (or in_region_88 (and c_88_0 (not in_target_88)))))
 (let (($x23793 (or in_region_87 (and c_87_0 (not in_target_87)))))
 (let (($x23788 (or in_region_86 (and c_86_0 (not in_target_86)))))
 (let (($x23783 (or in_region_85 (and c_85_0 (not in_target_85)))))
 (let (($x23778 (or in_region_84 (and c_84_0 (not in_target_84)))))
 (let (($x23773 (or in_region_83 (and c_83_0 (not in_target_83)))))
 (let (($x23768 (or in_region_82 (and c_82_0 (not in_target_82)))))
 (let (($x23763 (or in_region_81 (and c_81_0 (not in_target_81)))))
 (let (($x23758 (or in_region_80 (and c_80_0 (not in_target_80)))))
 (let (($x23753 (or in_region_79 (and c_79_0 (not in_target_79)))))
 (let (($x23748 (or in_region_78 (and c_78_0 (not in_target_78)))))
 (let (($x23743 (or in_region_77 (and c_77_0 (not in_target_77)))))
 (let (($x23738 (or in_region_76 (and c_76_0 (not in_target_76)))))
 (let (($x23733 (or in_region_75 (and c_75_0 (not in_target_75)))))
 (let (($x23728 (or in_region_74 (and c_74_0 (not in_target_74)))))
 (let (($x23723 (or in_region_73 (and c_73_0 (not in_target_73)))))
 (let (($x23718 (or in_region_72 (and c_72_0 (not in_target_72)))))
 (let (($x23713 (or in_region_71 (and c_71_0 (not in_target_71)))))
 (let (($x23708 (or in_region_70 (and c_70_0 (not in_target_70)))))
 (let (($x23703 (or in_region_69 (and c_69_0 (not in_target_69)))))
 (let (($x23698 (or in_region_68 (and c_68_0 (not in_target_68)))))
 (let (($x23693 (or in_region_67 (and c_67_0 (not in_target_67)))))
 (let (($x23688 (or in_region_66 (and c_66_0 (not in_target_66)))))
 (let (($x23683 (or in_region_65 (and c_65_0 (not in_target_65)))))
 (let (($x23678 (or in_region_64 (and c_64_0 (not in_target_64)))))
 (let (($x23673 (or in_region_63 (and c_63_0 (not in_target_63)))))
 (let (($x23668 (or in_region_62 (and c_62_0 (not in_target_62)))))
 (let (($x23663 (or in_region_61 (and c_61_0 (not in_target_61)))))
 (let (($x23658 (or in_region_60 (and c_60_0 (not in_target_60)))))
 (let (($x23653 (or in_region_59 (and c_59_0 (not in_target_59)))))
 (let (($x23648 (or in_region_58 (and c_58_0 (not in_target_58)))))
 (let (($x23643 (or in_region_57 (and c_57_0 (not in_target_57)))))
 (let (($x23638 (or in_region_56 (and c_56_0 (not in_target_56)))))
 (let (($x23633 (or in_region_55 (and c_55_0 (not in_target_55)))))
 (let (($x23628 (or in_region_54 (and c_54_0 (not in_target_54)))))
 (let (($x23623 (or in_region_53 (and c_53_0 (not in_target_53)))))
 (let (($x23618 (or in_region_52 (and c_52_0 (not in_target_52)))))
 (let (($x23613 (or in_region_51 (and c_51_0 (not in_target_51)))))
 (let (($x23608 (or in_region_50 (and c_50_0 (not in_target_50)))))
 (let (($x23603 (or in_region_49 (and c_49_0 (not in_target_49)))))
 (let (($x23598 (or in_region_48 (and c_48_0 (not in_target_48)))))
 (let (($x23593 (or in_region_47 (and c_47_0 (not in_target_47)))))
 (let (($x23588 (or in_region_46 (and c_46_0 (not in_target_46)))))
 (let (($x23583 (or in_region_45 (and c_45_0 (not in_target_45)))))
 (let (($x23578 (or in_region_44 (and c_44_0 (not in_target_44)))))
 (let (($x23573 (or in_region_43 (and c_43_0 (not in_target_43)))))
 (let (($x23568 (or in_region_42 (and c_42_0 (not in_target_42)))))
 (let (($x23563 (or in_region_41 (and c_41_0 (not in_target_41)))))
 (let (($x23558 (or in_region_40 (and c_40_0 (not in_target_40)))))
 (let (($x23553 (or in_region_39 (and c_39_0 (not in_target_39)))))
 (let (($x23548 (or in_region_38 (and c_38_0 (not in_target_38)))))
 (let (($x23543 (or in_region_37 (and c_37_0 (not in_target_37)))))
 (let (($x23538 (or in_region_36 (and c_36_0 (not in_target_36)))))
 (let (($x23533 (or in_region_35 (and c_35_0 (not in_target_35)))))
 (let (($x23528 (or in_region_34 (and c_34_0 (not in_target_34)))))
 (let (($x23523 (or in_region_33 (and c_33_0 (not in_target_33)))))
 (let (($x23518 (or in_region_32 (and c_32_0 (not in_target_32)))))
 (let (($x23513 (or in_region_31 (and c_31_0 (not in_target_31)))))
 (let (($x23508 (or in_region_30 (and c_30_0 (not in_target_30)))))
 (let (($x23503 (or in_region_29 (and c_29_0 (not in_target_29)))))
 (let (($x23498 (or in_region_28 (and c_28_0 (not in_target_28)))))
 (let (($x23493 (or in_region_27 (and c_27_0 (not in_target_27)))))
 (let (($x23488 (or in_region_26 (and c_26_0 (not in_target_26)))))
 (let (($x23483 (or in_region_25 (and c_25_0 (not in_target_25)))))
 (let (($x23478 (or in_region_24 (and c_24_0 (not in_target_24)))))
 (let (($x23473 (or in_region_23 (and c_23_0 (not in_target_23)))))
 (let (($x23468 (or in_region_22 (and c_22_0 (not in_target_22)))))
 (let (($x23463 (or in_region_21 (and c_21_0 (not in_target_21)))))
 (let (($x23458 (or in_region_20 (and c_20_0 (not in_target_20)))))
 (let (($x23453 (or in_region_19 (and c_19_0 (not in_target_19)))))
 (let (($x23448 (or in_region_18 (and c_18_0 (not in_target_18)))))
 (let (($x23443 (or in_region_17 (and c_17_0 (not in_target_17)))))
 (let (($x23438 (or in_region_16 (and c_16_0 (not in_target_16)))))
 (let (($x23433 (or in_region_15 (and c_15_0 (not in_target_15)))))
 (let (($x23428 (or in_region_14 (and c_14_0 (not in_target_14)))))
 (let (($x23423 (or in_region_13 (and c_13_0 (not in_target_13)))))
 (let (($x23418 (or in_region_12 (and c_12_0 (not in_target_12)))))
 (let (($x23413 (or in_region_11 (and c_11_0 (not in_target_11)))))
 (let (($x23408 (or in_region_10 (and c_10_0 (not in_target_10)))))
 (let (($x23403 (or in_region_9 (and c_9_0 (not in_target_9)))))
 (let (($x23398 (or in_region_8 (and c_8_0 (not in_target_8)))))
 (let (($x23393 (or in_region_7 (and c_7_0 (not in_target_7)))))
 (let (($x23386 (not in_target_6)))
 (let (($x23387 (and c_6_0 $x23386)))
 (let (($x23388 (or in_region_6 $x23387)))
 (let (($x23381 (not in_target_5)))
 (let (($x23382 (and c_5_0 $x23381)))
 (let (($x23383 (or in_region_5 $x23382)))
 (let (($x23376 (not in_target_4)))
 (let (($x23377 (and c_4_0 $x23376)))
 (let (($x23378 (or in_region_4 $x23377)))
 (let (($x23371 (not in_target_3)))
 (let (($x23372 (and c_3_0 $x23371)))
 (let (($x23373 (or in_region_3 $x23372)))
 (let (($x23366 (not in_target_2)))
 (let (($x23367 (and c_2_0 $x23366)))
 (let (($x23368 (or in_region_2 $x23367)))
 (let (($x23361 (not in_target_1)))
 (let (($x23362 (and c_1_0 $x23361)))
 (let (($x23363 (or in_region_1 $x23362)))
 (let (($x23356 (not in_target_0)))
 (let (($x23357 (and c_0_0 $x23356)))
 (let (($x23358 (or in_region_0 $x23357)))
 (let (($x23359 (and true $x23358)))
 (let (($x23364 (and $x23359 $x23363)))
 (let (($x23369 (and $x23364 $x23368)))
 (let (($x23374 (and $x23369 $x23373)))
 (let (($x23379 (and $x23374 $x23378)))
 (let (($x23384 (and $x23379 $x23383)))
 (let (($x23389 (and $x23384 $x23388)))
 (let (($x23394 (and $x23389 $x23393)))
 (let (($x23399 (and $x23394 $x23398)))
 (let (($x23404 (and $x23399 $x23403)))
 (let (($x23409 (and $x23404 $x23408)))
 (let (($x23414 (and $x23409 $x23413)))
 (let (($x23419 (and $x23414 $x23418)))
 (let (($x23424 (and $x23419 $x23423)))
 (let (($x23429 (and $x23424 $x23428)))
 (let (($x23434 (and $x23429 $x23433)))
 (let (($x23439 (and $x23434 $x23438)))
 (let (($x23444 (and $x23439 $x23443)))
 (let (($x23449 (and $x23444 $x23448)))
 (let (($x23454 (and $x23449 $x23453)))
 (let (($x23459 (and $x23454 $x23458)))
 (let (($x23464 (and $x23459 $x23463)))
 (let (($x23469 (and $x23464 $x23468)))
 (let (($x23474 (and $x23469 $x23473)))
 (let (($x23479 (and $x23474 $x23478)))
 (let (($x23484 (and $x23479 $x23483)))
 (let (($x23489 (and $x23484 $x23488)))
 (let (($x23494 (and $x23489 $x23493)))
 (let (($x23499 (and $x23494 $x23498)))
 (let (($x23504 (and $x23499 $x23503)))
 (let (($x23509 (and $x23504 $x23508)))
 (let (($x23514 (and $x23509 $x23513)))
 (let (($x23519 (and $x23514 $x23518)))
 (let (($x23524 (and $x23519 $x23523)))
 (let (($x23529 (and $x23524 $x23528)))
 (let (($x23534 (and $x23529 $x23533)))
 (let (($x23539 (and $x23534 $x23538)))
 (let (($x23544 (and $x23539 $x23543)))
 (let (($x23549 (and $x23544 $x23548)))
 (let (($x23554 (and $x23549 $x23553)))
 (let (($x23559 (and $x23554 $x23558)))
 (let (($x23564 (and $x23559 $x23563)))
 (let (($x23569 (and $x23564 $x23568)))
 (let (($x23574 (and $x23569 $x23573)))
 (let (($x23579 (and $x23574 $x23578)))
 (let (($x23584 (and $x23579 $x23583)))
 (let (($x23589 (and $x23584 $x23588)))
 (let (($x23594 (and $x23589 $x23593)))
 (let (($x23599 (and $x23594 $x23598)))
 (let (($x23604 (and $x23599 $x23603)))
 (let (($x23609 (and $x23604 $x23608)))
 (let (($x23614 (and $x23609 $x23613)))
 (let (($x23619 (and $x23614 $x23618)))
 (let (($x23624 (and $x23619 $x23623)))
 (let (($x23629 (and $x23624 $x23628)))
 (let (($x23634 (and $x23629 $x23633)))
 (let (($x23639 (and $x23634 $x23638)))
 (let (($x23644 (and $x23639 $x23643)))
 (let (($x23649 (and $x23644 $x23648)))
 (let (($x23654 (and $x23649 $x23653)))
 (let (($x23659 (and $x23654 $x23658)))
 (let (($x23664 (and $x23659 $x23663)))
 (let (($x23669 (and $x23664 $x23668)))
 (let (($x23674 (and $x23669 $x23673)))
 (let (($x23679 (and $x23674 $x23678)))
 (let (($x23684 (and $x23679 $x23683)))
 (let (($x23689 (and $x23684 $x23688)))
 (let (($x23694 (and $x23689 $x23693)))
 (let (($x23699 (and $x23694 $x23698)))
 (let (($x23704 (and $x23699 $x23703)))
 (let (($x23709 (and $x23704 $x23708)))
 (let (($x23714 (and $x23709 $x23713)))
 (let (($x23719 (and $x23714 $x23718)))
 (let (($x23724 (and $x23719 $x23723)))
 (let (($x23729 (and $x23724 $x23728)))
 (let (($x23734 (and $x23729 $x23733)))
 (let (($x23739 (and $x23734 $x23738)))
 (let (($x23744 (and $x23739 $x23743)))
 (let (($x23749 (and $x23744 $x23748)))
 (let (($x23754 (and $x23749 $x23753)))
 (let (($x23759 (and $x23754 $x23758)))
 (let (($x23764 (and $x23759 $x23763)))
 (let (($x23769 (and $x23764 $x23768)))
 (let (($x23774 (and $x23769 $x23773)))
 (let (($x23779 (and $x23774 $x23778)))
 (let (($x23784 (and $x23779 $x23783)))
 (let (($x23789 (and $x23784 $x23788)))
 (let (($x23794 (and $x23789 $x23793)))
 (let (($x23799 (and $x23794 $x23798)))
 (let (($x23804 (and $x23799 $x23803)))
 (let (($x23809 (and $x23804 $x23808)))
 (let (($x23814 (and $x23809 $x23813)))
 (let (($x23819 (and $x23814 $x23818)))
 (let (($x23824 (and $x23819 $x23823)))
 (let (($x23829 (and $x23824 $x23828)))
 (let (($x23834 (and $x23829 $x23833)))
 (let (($x23839 (and $x23834 $x23838)))
 (let (($x23844 (and $x23839 $x23843)))
 (let (($x23849 (and $x23844 $x23848)))
 (let (($x23854 (and $x23849 $x23853)))
 (let (($x23859 (and $x23854 $x23858)))
 (let (($x23864 (and $x23859 $x23863)))
 (let (($x23869 (and $x23864 $x23868)))
 (let (($x23874 (and $x23869 $x23873)))
 (let (($x23879 (and $x23874 $x23878)))
 (let (($x23884 (and $x23879 $x23883)))
 (let (($x23889 (and $x23884 $x23888)))
 (let (($x23894 (and $x23889 $x23893)))
 (let (($x23899 (and $x23894 $x23898)))
 (let (($x23904 (and $x23899 $x23903)))
 (let (($x23909 (and $x23904 $x23908)))
 (let (($x23914 (and $x23909 $x23913)))
 (let (($x23919 (and $x23914 $x23918)))
 (let (($x23924 (and $x23919 $x23923)))
 (let (($x23929 (and $x23924 $x23928)))
 (let (($x23934 (and $x23929 $x23933)))
 (let (($x23939 (and $x23934 $x23938)))
 (let (($x23944 (and $x23939 $x23943)))
 (let (($x23949 (and $x23944 $x23948)))
 (let (($x23954 (and $x23949 $x23953)))
 (let (($x23959 (and $x23954 $x23958)))
 (let (($x23964 (and $x23959 $x23963)))
 (let (($x23969 (and $x23964 $x23968)))
 (let (($x23974 (and $x23969 $x23973)))
 (let (($x23979 (and $x23974 $x23978)))
 (let (($x23984 (and $x23979 $x23983)))
 (let (($x23989 (and $x23984 $x23988)))
 (let (($x23994 (and $x23989 $x23993)))
 (let (($x23999 (and $x23994 $x23998)))
 (let (($x24000 (and $x23999 in_region_0)))
 (let (($x24004 (and $x24000 $x24003)))
 (let (($x24009 (and $x24004 $x24008)))
 (let (($x24014 (and $x24009 $x24013)))
 (let (($x24019 (and $x24014 $x24018)))
 (let (($x24024 (and $x24019 $x24023)))
 (let (($x24029 (and $x24024 $x24028)))
 (let (($x24034 (and $x24029 $x24033)))
 (let (($x24039 (and $x24034 $x24038)))
 (let (($x24044 (and $x24039 $x24043)))
 (let (($x24049 (and $x24044 $x24048)))
 (let (($x24054 (and $x24049 $x24053)))
 (let (($x24059 (and $x24054 $x24058)))
 (let (($x24064 (and $x24059 $x24063)))
 (let (($x24069 (and $x24064 $x24068)))
 (let (($x24074 (and $x24069 $x24073)))
 (let (($x24079 (and $x24074 $x24078)))
 (let (($x24084 (and $x24079 $x24083)))
 (let (($x24089 (and $x24084 $x24088)))
 (let (($x24094 (and $x24089 $x24093)))
 (let (($x24099 (and $x24094 $x24098)))
 (let (($x24104 (and $x24099 $x24103)))
 (let (($x24109 (and $x24104 $x24108)))
 (let (($x24114 (and $x24109 $x24113)))
 (let (($x24119 (and $x24114 $x24118)))
 (let (($x24124 (and $x24119 $x24123)))
 (let (($x24129 (and $x24124 $x24128)))
 (let (($x24134 (and $x24129 $x24133)))
 (let (($x24139 (and $x24134 $x24138)))
 (let (($x24144 (and $x24139 $x24143)))
 (let (($x24149 (and $x24144 $x24148)))
 (let (($x24154 (and $x24149 $x24153)))
 (let (($x24159 (and $x24154 $x24158)))
 (let (($x24164 (and $x24159 $x24163)))
 (let (($x24169 (and $x24164 $x24168)))
 (let (($x24174 (and $x24169 $x24173)))
 (let (($x24179 (and $x24174 $x24178)))
 (let (($x24184 (and $x24179 $x24183)))
 (let (($x24189 (and $x24184 $x24188)))
 (let (($x24194 (and $x24189 $x24193)))
 (let (($x24199 (and $x24194 $x24198)))
 (let (($x24204 (and $x24199 $x24203)))
 (let (($x24209 (and $x24204 $x24208)))
 (let (($x24214 (and $x24209 $x24213)))
 (let (($x24219 (and $x24214 $x24218)))
 (let (($x24224 (and $x24219 $x24223)))
 (let (($x24229 (and $x24224 $x24228)))
 (let (($x24234 (and $x24229 $x24233)))
 (let (($x24239 (and $x24234 $x24238)))
 (let (($x24244 (and $x24239 $x24243)))
 (let (($x24249 (and $x24244 $x24248)))
 (let (($x24254 (and $x24249 $x24253)))
 (let (($x24259 (and $x24254 $x24258)))
 (let (($x24264 (and $x24259 $x24263)))
 (let (($x24269 (and $x24264 $x24268)))
 (let (($x24274 (and $x24269 $x24273)))
 (let (($x24279 (and $x24274 $x24278)))
 (let (($x24284 (and $x24279 $x24283)))
 (let (($x24289 (and $x24284 $x24288)))
 (let (($x24294 (and $x24289 $x24293)))
 (let (($x24299 (and $x24294 $x24298)))
 (let (($x24304 (and $x24299 $x24303)))
 (let (($x24309 (and $x24304 $x24308)))
 (let (($x24314 (and $x24309 $x24313)))
 (let (($x24411 (and $x24314 (=> $x24416 (or $x24384 (and c_0_7 (or $x24402 c_6_8)))))))
 (let (($x24485 (and $x24411 (=> $x24332 (or $x24472 (and c_1_7 (or $x24488 c_11_8)))))))
 (let (($x24547 (and $x24485 (=> $x24346 (or $x24533 (and c_2_7 (or $x24550 c_15_8)))))))
 (let (($x24611 (and $x24547 (=> $x24374 (or $x24594 (and c_3_7 (or $x24612 c_19_8)))))))
 (let (($x24649 (and $x24611 (=> $x24360 (or $x24646 (and c_4_7 (or $x24416 c_0_8)))))))
 (let (($x24687 (and $x24649 (=> $x24388 (or $x24670 (and c_5_7 (or $x24688 c_23_8)))))))
 (let (($x24712 (and $x24687 (=> $x24402 (or $x24697 (and c_6_7 (or $x24714 c_24_8)))))))
 (let (($x24786 (and $x24712 (=> $x24429 (or $x24773 (and c_7_7 (or $x24788 c_29_8)))))))
 (let (($x24834 (and $x24786 (=> $x24443 (or $x24819 (and c_8_7 (or $x24838 c_32_8)))))))
 (let (($x24877 (and $x24834 (=> $x24457 (or $x24873 (and c_9_7 (or $x24332 c_1_8)))))))
 (let (($x24912 (and $x24877 (=> $x24474 (or $x24896 (and c_10_7 (or $x24914 c_36_8)))))))
 (let (($x24937 (and $x24912 (=> $x24488 (or $x24918 (and c_11_7 (or $x24940 c_37_8)))))))
 (let (($x25001 (and $x24937 (=> $x24506 (or $x24985 (and c_12_7 (or $x25002 c_41_8)))))))
 (let (($x25039 (and $x25001 (=> $x24520 (or $x25032 (and c_13_7 (or $x24346 c_2_8)))))))
 (let (($x25074 (and $x25039 (=> $x24534 (or $x25058 (and c_14_7 (or $x25078 c_45_8)))))))
 (let (($x25102 (and $x25074 (=> $x24550 (or $x25087 (and c_15_7 (or $x25104 c_46_8)))))))
 (let (($x25149 (and $x25102 (=> $x24570 (or $x25148 (and c_16_7 (or $x24374 c_3_8)))))))
 (let (($x25201 (and $x25149 (=> $x24584 (or $x25187 (and c_17_7 (or $x25204 c_52_8)))))))
 (let (($x25241 (and $x25201 (=> $x24598 (or $x25227 (and c_18_7 (or $x25242 c_54_8)))))))
 (let (($x25267 (and $x25241 (=> $x24612 (or $x25253 (and c_19_7 (or $x25268 c_55_8)))))))
 (let (($x25300 (and $x25267 (=> $x24632 (or $x25302 (and c_20_7 (or $x24360 c_4_8)))))))
 (let (($x25332 (and $x25300 (=> $x24648 (or $x25328 (and c_21_7 (or $x24388 c_5_8)))))))
 (let (($x25367 (and $x25332 (=> $x24674 (or $x25354 (and c_22_7 (or $x25370 c_60_8)))))))
 (let (($x25392 (and $x25367 (=> $x24688 (or $x25380 (and c_23_7 (or $x25396 c_61_8)))))))
 (let (($x25421 (and $x25392 (=> $x24714 (or $x25402 (and c_24_7 (or $x25422 c_62_8)))))))
 (let (($x25492 (and $x25421 (=> $x24730 (or $x25479 (and c_25_7 $x25490))))))
 (let (($x25543 (and $x25492 (=> $x24744 (or $x25531 (and c_26_7 $x25540))))))
 (let (($x25585 (and $x25543 (=> $x24758 (or $x25581 (and c_27_7 (or $x24429 c_7_8)))))))
 (let (($x25618 (and $x25585 (=> $x24774 (or $x25605 (and c_28_7 $x25616))))))
 (let (($x25646 (and $x25618 (=> $x24788 (or $x25630 (and c_29_7 $x25642))))))
 (let (($x25696 (and $x25646 (=> $x24806 (or $x25681 (and c_30_7 $x25692))))))
 (let (($x25725 (and $x25696 (=> $x24820 (or $x25720 (and c_31_7 (or $x24443 c_8_8)))))))
 (let (($x25747 (and $x25725 (=> $x24838 (or $x25735 (and c_32_7 $x25744))))))
 (let (($x25787 (and $x25747 (=> $x24858 (or $x25784 (and c_33_7 (or $x24457 c_9_8)))))))
 (let (($x25813 (and $x25787 (=> $x24874 (or $x25810 (and c_34_7 (or $x24474 c_10_8)))))))
 (let (($x25850 (and $x25813 (=> $x24900 (or $x25834 (and c_35_7 $x25846))))))
 (let (($x25876 (and $x25850 (=> $x24914 (or $x25862 (and c_36_7 $x25872))))))
 (let (($x25900 (and $x25876 (=> $x24940 (or $x25886 (and c_37_7 $x25898))))))
 (let (($x25962 (and $x25900 (=> $x24958 (or $x25947 (and c_38_7 $x25960))))))
 (let (($x25998 (and $x25962 (=> $x24972 (or $x25996 (and c_39_7 (or $x24506 c_12_8)))))))
 (let (($x26039 (and $x25998 (=> $x24986 (or $x26025 (and c_40_7 $x26036))))))
 (let (($x26065 (and $x26039 (=> $x25002 (or $x26052 (and c_41_7 $x26062))))))
 (let (($x26106 (and $x26065 (=> $x25022 (or $x26099 (and c_42_7 (or $x24520 c_13_8)))))))
 (let (($x26131 (and $x26106 (=> $x25036 (or $x26124 (and c_43_7 (or $x24534 c_14_8)))))))
 (let (($x26168 (and $x26131 (=> $x25062 (or $x26151 (and c_44_7 $x26164))))))
 (let (($x26192 (and $x26168 (=> $x25078 (or $x26181 (and c_45_7 $x26190))))))
 (let (($x26218 (and $x26192 (=> $x25104 (or $x26204 (and c_46_7 $x26216))))))
 (let (($x26272 (and $x26218 (=> $x25124 (or $x26268 (and c_47_7 (or $x24570 c_16_8)))))))
 (let (($x26309 (and $x26272 (=> $x25138 (or $x26304 (and c_48_7 (or $x24584 c_17_8)))))))
 (let (($x26335 (and $x26309 (=> $x25152 (or $x26330 (and c_49_7 (or $x24598 c_18_8)))))))
 (let (($x26384 (and $x26335 (=> $x25176 (or $x26370 (and c_50_7 $x26380))))))
 (let (($x26423 (and $x26384 (=> $x25190 (or $x26406 (and c_51_7 $x26418))))))
 (let (($x26448 (and $x26423 (=> $x25204 (or $x26433 (and c_52_7 $x26444))))))
 (let (($x26486 (and $x26448 (=> $x25228 (or $x26470 (and c_53_7 $x26482))))))
 (let (($x26513 (and $x26486 (=> $x25242 (or $x26497 (and c_54_7 $x26508))))))
 (let (($x26537 (and $x26513 (=> $x25268 (or $x26525 (and c_55_7 $x26534))))))
 (let (($x26573 (and $x26537 (=> $x25288 (or $x26575 (and c_56_7 (or $x24632 c_20_8)))))))
 (let (($x26605 (and $x26573 (=> $x25304 (or $x26598 (and c_57_7 (or $x24648 c_21_8)))))))
 (let (($x26630 (and $x26605 (=> $x25330 (or $x26625 (and c_58_7 (or $x24674 c_22_8)))))))
 (let (($x26667 (and $x26630 (=> $x25356 (or $x26651 (and c_59_7 $x26662))))))
 (let (($x26691 (and $x26667 (=> $x25370 (or $x26677 (and c_60_7 $x26688))))))
 (let (($x26718 (and $x26691 (=> $x25396 (or $x26701 (and c_61_7 $x26714))))))
 (let (($x26745 (and $x26718 (=> $x25422 (or $x26730 (and c_62_7 $x26740))))))
 (let (($x26952 (and $x26745 (and (=> (and c_0_1 $x26948) (= ghost_1_0 0)) (=> $x26946 $x26944)))))
 (let (($x27018 (and $x26952 (and (=> (and c_1_1 $x26883) (= ghost_1_1 0)) (=> $x26879 $x27015)))))
 (let (($x27077 (and $x27018 (and (=> (and c_2_1 $x26896) (= ghost_1_2 0)) (=> $x26892 $x27072)))))
 (let (($x27138 (and $x27077 (and (=> (and c_3_1 $x26916) (= ghost_1_3 0)) (=> $x26912 $x27132)))))
 (let (($x27188 (and $x27138 (and (=> (and c_4_1 $x26906) (= ghost_1_4 0)) (=> $x26902 $x27182)))))
 (let (($x27239 (and $x27188 (and (=> (and c_5_1 $x26926) (= ghost_1_5 0)) (=> $x26924 $x27234)))))
 (let (($x27283 (and $x27239 (and (=> (and c_6_1 $x26936) (= ghost_1_6 0)) (=> $x26933 $x27278)))))
 (let (($x27348 (and $x27283 (and (=> (and c_7_1 $x26960) (= ghost_1_7 0)) (=> $x26957 $x27345)))))
 (let (($x27402 (and $x27348 (and (=> (and c_8_1 $x26972) (= ghost_1_8 0)) (=> $x26971 $x27400)))))
 (let (($x27451 (and $x27402 (and (=> (and c_9_1 $x26982) (= ghost_1_9 0)) (=> $x26981 $x27450)))))
 (let (($x27503 (and $x27451 $x27500)))
 (let (($x27549 (and $x27503 $x27544)))
 (let (($x27608 (and $x27549 $x27605)))
 (let (($x27659 (and $x27608 (and (=> (and c_13_1 $x27042) (= ghost_1_13 0)) (=> $x27040 $x27654)))))
 (let (($x27708 (and $x27659 $x27702)))
 (let (($x27751 (and $x27708 $x27749)))
 (let (($x27807 (and $x27751 (and (=> (and c_16_1 $x27097) (= ghost_1_16 0)) (=> $x27093 $x27802)))))
 (let (($x27863 (and $x27807 $x27860)))
 (let (($x27911 (and $x27863 $x27910)))
 (let (($x27958 (and $x27911 $x27952)))
 (let (($x28008 (and $x27958 (and (=> (and c_20_1 $x27157) (= ghost_1_20 0)) (=> $x27156 $x28005)))))
 (let (($x28053 (and $x28008 (and (=> (and c_21_1 $x27172) (= ghost_1_21 0)) (=> $x27171 $x28050)))))
 (let (($x28101 (and $x28053 $x28098)))
 (let (($x28146 (and $x28101 $x28143)))
 (let (($x28191 (and $x28146 $x28190)))
 (let (($x28258 (and $x28191 $x28255)))
 (let (($x28313 (and $x28258 $x28310)))
 (let (($x28363 (and $x28313 (and (=> (and c_27_1 $x27312) (= ghost_1_27 0)) (=> $x27308 $x28357)))))
 (let (($x28414 (and $x28363 $x28408)))
 (let (($x28456 (and $x28414 $x28455)))
 (let (($x28514 (and $x28456 $x28508)))
 (let (($x28557 (and $x28514 (and (=> (and c_31_1 $x27372) (= ghost_1_31 0)) (=> $x27370 $x28554)))))
 (let (($x28602 (and $x28557 $x28599)))
 (let (($x28653 (and $x28602 (and (=> (and c_33_1 $x27422) (= ghost_1_33 0)) (=> $x27419 $x28648)))))
 (let (($x28699 (and $x28653 $x28692)))
 (let (($x28747 (and $x28699 $x28744)))
 (let (($x28793 (and $x28747 $x28787)))
 (let (($x28839 (and $x28793 $x28832)))
 (let (($x28898 (and $x28839 $x28895)))
 (let (($x28949 (and $x28898 $x28942)))
 (let (($x28997 (and $x28949 $x28994)))
 (let (($x29043 (and $x28997 $x29038)))
 (let (($x29093 (and $x29043 $x29087)))
 (let (($x29139 (and $x29093 $x29134)))
 (let (($x29189 (and $x29139 $x29184)))
 (let (($x29234 (and $x29189 $x29229)))
 (let (($x29276 (and $x29234 $x29273)))
 (let (($x29333 (and $x29276 $x29330)))
 (let (($x29383 (and $x29333 $x29377)))
 (let (($x29426 (and $x29383 $x29423)))
 (let (($x29482 (and $x29426 $x29480)))
 (let (($x29532 (and $x29482 $x29529)))
 (let (($x29578 (and $x29532 $x29572)))
 (let (($x29629 (and $x29578 $x29622)))
 (let (($x29671 (and $x29629 $x29668)))
 (let (($x29716 (and $x29671 $x29714)))
 (let (($x29769 (and $x29716 $x29764)))
 (let (($x29813 (and $x29769 $x29807)))
 (let (($x29858 (and $x29813 $x29852)))
 (let (($x29909 (and $x29858 $x29903)))
 (let (($x29954 (and $x29909 $x29947)))
 (let (($x29998 (and $x29954 $x29993)))
 (let (($x38494 (and (and $x29998 $x30039) $x38493)))
 (=> instance_0 $x38494))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(assert
 (or instance_0))
(check-sat)
