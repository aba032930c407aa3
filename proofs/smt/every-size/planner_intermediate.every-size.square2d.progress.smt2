; holon proof obligation for every region: system planner_intermediate, lattice square2d, property progress
; window: every rule shape with its first cell at the origin, and every point within 3 steps of its pattern, free (41 cells; proofs/README.md)
; expected: unsat (the property holds on every region of the lattice)
(set-logic ALL)
; 
(set-info :status unknown)
(declare-fun c_0_6 () Bool)
(declare-fun c_0_5 () Bool)
(declare-fun c_0_4 () Bool)
(declare-fun c_0_3 () Bool)
(declare-fun c_0_2 () Bool)
(declare-fun c_0_1 () Bool)
(declare-fun c_0_0 () Bool)
(declare-fun c_1_6 () Bool)
(declare-fun c_1_5 () Bool)
(declare-fun c_1_4 () Bool)
(declare-fun c_1_3 () Bool)
(declare-fun c_1_2 () Bool)
(declare-fun c_1_1 () Bool)
(declare-fun c_1_0 () Bool)
(declare-fun c_2_6 () Bool)
(declare-fun c_2_5 () Bool)
(declare-fun c_2_4 () Bool)
(declare-fun c_2_3 () Bool)
(declare-fun c_2_2 () Bool)
(declare-fun c_2_1 () Bool)
(declare-fun c_2_0 () Bool)
(declare-fun c_3_6 () Bool)
(declare-fun c_3_5 () Bool)
(declare-fun c_3_4 () Bool)
(declare-fun c_3_3 () Bool)
(declare-fun c_3_2 () Bool)
(declare-fun c_3_1 () Bool)
(declare-fun c_3_0 () Bool)
(declare-fun c_4_6 () Bool)
(declare-fun c_4_5 () Bool)
(declare-fun c_4_4 () Bool)
(declare-fun c_4_3 () Bool)
(declare-fun c_4_2 () Bool)
(declare-fun c_4_1 () Bool)
(declare-fun c_4_0 () Bool)
(declare-fun c_5_6 () Bool)
(declare-fun c_5_5 () Bool)
(declare-fun c_5_4 () Bool)
(declare-fun c_5_3 () Bool)
(declare-fun c_5_2 () Bool)
(declare-fun c_5_1 () Bool)
(declare-fun c_5_0 () Bool)
(declare-fun c_6_6 () Bool)
(declare-fun c_6_5 () Bool)
(declare-fun c_6_4 () Bool)
(declare-fun c_6_3 () Bool)
(declare-fun c_6_2 () Bool)
(declare-fun c_6_1 () Bool)
(declare-fun c_6_0 () Bool)
(declare-fun c_7_6 () Bool)
(declare-fun c_7_5 () Bool)
(declare-fun c_7_4 () Bool)
(declare-fun c_7_3 () Bool)
(declare-fun c_7_2 () Bool)
(declare-fun c_7_1 () Bool)
(declare-fun c_7_0 () Bool)
(declare-fun c_8_6 () Bool)
(declare-fun c_8_5 () Bool)
(declare-fun c_8_4 () Bool)
(declare-fun c_8_3 () Bool)
(declare-fun c_8_2 () Bool)
(declare-fun c_8_1 () Bool)
(declare-fun c_8_0 () Bool)
(declare-fun c_9_6 () Bool)
(declare-fun c_9_5 () Bool)
(declare-fun c_9_4 () Bool)
(declare-fun c_9_3 () Bool)
(declare-fun c_9_2 () Bool)
(declare-fun c_9_1 () Bool)
(declare-fun c_9_0 () Bool)
(declare-fun c_10_6 () Bool)
(declare-fun c_10_5 () Bool)
(declare-fun c_10_4 () Bool)
(declare-fun c_10_3 () Bool)
(declare-fun c_10_2 () Bool)
(declare-fun c_10_1 () Bool)
(declare-fun c_10_0 () Bool)
(declare-fun c_11_6 () Bool)
(declare-fun c_11_5 () Bool)
(declare-fun c_11_4 () Bool)
(declare-fun c_11_3 () Bool)
(declare-fun c_11_2 () Bool)
(declare-fun c_11_1 () Bool)
(declare-fun c_11_0 () Bool)
(declare-fun c_12_6 () Bool)
(declare-fun c_12_5 () Bool)
(declare-fun c_12_4 () Bool)
(declare-fun c_12_3 () Bool)
(declare-fun c_12_2 () Bool)
(declare-fun c_12_1 () Bool)
(declare-fun c_12_0 () Bool)
(declare-fun c_13_6 () Bool)
(declare-fun c_13_5 () Bool)
(declare-fun c_13_4 () Bool)
(declare-fun c_13_3 () Bool)
(declare-fun c_13_2 () Bool)
(declare-fun c_13_1 () Bool)
(declare-fun c_13_0 () Bool)
(declare-fun c_14_6 () Bool)
(declare-fun c_14_5 () Bool)
(declare-fun c_14_4 () Bool)
(declare-fun c_14_3 () Bool)
(declare-fun c_14_2 () Bool)
(declare-fun c_14_1 () Bool)
(declare-fun c_14_0 () Bool)
(declare-fun c_15_6 () Bool)
(declare-fun c_15_5 () Bool)
(declare-fun c_15_4 () Bool)
(declare-fun c_15_3 () Bool)
(declare-fun c_15_2 () Bool)
(declare-fun c_15_1 () Bool)
(declare-fun c_15_0 () Bool)
(declare-fun c_16_6 () Bool)
(declare-fun c_16_5 () Bool)
(declare-fun c_16_4 () Bool)
(declare-fun c_16_3 () Bool)
(declare-fun c_16_2 () Bool)
(declare-fun c_16_1 () Bool)
(declare-fun c_16_0 () Bool)
(declare-fun c_17_6 () Bool)
(declare-fun c_17_5 () Bool)
(declare-fun c_17_4 () Bool)
(declare-fun c_17_3 () Bool)
(declare-fun c_17_2 () Bool)
(declare-fun c_17_1 () Bool)
(declare-fun c_17_0 () Bool)
(declare-fun c_18_6 () Bool)
(declare-fun c_18_5 () Bool)
(declare-fun c_18_4 () Bool)
(declare-fun c_18_3 () Bool)
(declare-fun c_18_2 () Bool)
(declare-fun c_18_1 () Bool)
(declare-fun c_18_0 () Bool)
(declare-fun c_19_6 () Bool)
(declare-fun c_19_5 () Bool)
(declare-fun c_19_4 () Bool)
(declare-fun c_19_3 () Bool)
(declare-fun c_19_2 () Bool)
(declare-fun c_19_1 () Bool)
(declare-fun c_19_0 () Bool)
(declare-fun c_20_6 () Bool)
(declare-fun c_20_5 () Bool)
(declare-fun c_20_4 () Bool)
(declare-fun c_20_3 () Bool)
(declare-fun c_20_2 () Bool)
(declare-fun c_20_1 () Bool)
(declare-fun c_20_0 () Bool)
(declare-fun c_21_6 () Bool)
(declare-fun c_21_5 () Bool)
(declare-fun c_21_4 () Bool)
(declare-fun c_21_3 () Bool)
(declare-fun c_21_2 () Bool)
(declare-fun c_21_1 () Bool)
(declare-fun c_21_0 () Bool)
(declare-fun c_22_6 () Bool)
(declare-fun c_22_5 () Bool)
(declare-fun c_22_4 () Bool)
(declare-fun c_22_3 () Bool)
(declare-fun c_22_2 () Bool)
(declare-fun c_22_1 () Bool)
(declare-fun c_22_0 () Bool)
(declare-fun c_23_6 () Bool)
(declare-fun c_23_5 () Bool)
(declare-fun c_23_4 () Bool)
(declare-fun c_23_3 () Bool)
(declare-fun c_23_2 () Bool)
(declare-fun c_23_1 () Bool)
(declare-fun c_23_0 () Bool)
(declare-fun c_24_6 () Bool)
(declare-fun c_24_5 () Bool)
(declare-fun c_24_4 () Bool)
(declare-fun c_24_3 () Bool)
(declare-fun c_24_2 () Bool)
(declare-fun c_24_1 () Bool)
(declare-fun c_24_0 () Bool)
(declare-fun c_25_6 () Bool)
(declare-fun c_25_5 () Bool)
(declare-fun c_25_4 () Bool)
(declare-fun c_25_3 () Bool)
(declare-fun c_25_2 () Bool)
(declare-fun c_25_1 () Bool)
(declare-fun c_25_0 () Bool)
(declare-fun c_26_6 () Bool)
(declare-fun c_26_5 () Bool)
(declare-fun c_26_4 () Bool)
(declare-fun c_26_3 () Bool)
(declare-fun c_26_2 () Bool)
(declare-fun c_26_1 () Bool)
(declare-fun c_26_0 () Bool)
(declare-fun c_27_6 () Bool)
(declare-fun c_27_5 () Bool)
(declare-fun c_27_4 () Bool)
(declare-fun c_27_3 () Bool)
(declare-fun c_27_2 () Bool)
(declare-fun c_27_1 () Bool)
(declare-fun c_27_0 () Bool)
(declare-fun c_28_6 () Bool)
(declare-fun c_28_5 () Bool)
(declare-fun c_28_4 () Bool)
(declare-fun c_28_3 () Bool)
(declare-fun c_28_2 () Bool)
(declare-fun c_28_1 () Bool)
(declare-fun c_28_0 () Bool)
(declare-fun c_29_6 () Bool)
(declare-fun c_29_5 () Bool)
(declare-fun c_29_4 () Bool)
(declare-fun c_29_3 () Bool)
(declare-fun c_29_2 () Bool)
(declare-fun c_29_1 () Bool)
(declare-fun c_29_0 () Bool)
(declare-fun c_30_6 () Bool)
(declare-fun c_30_5 () Bool)
(declare-fun c_30_4 () Bool)
(declare-fun c_30_3 () Bool)
(declare-fun c_30_2 () Bool)
(declare-fun c_30_1 () Bool)
(declare-fun c_30_0 () Bool)
(declare-fun c_31_6 () Bool)
(declare-fun c_31_5 () Bool)
(declare-fun c_31_4 () Bool)
(declare-fun c_31_3 () Bool)
(declare-fun c_31_2 () Bool)
(declare-fun c_31_1 () Bool)
(declare-fun c_31_0 () Bool)
(declare-fun c_32_6 () Bool)
(declare-fun c_32_5 () Bool)
(declare-fun c_32_4 () Bool)
(declare-fun c_32_3 () Bool)
(declare-fun c_32_2 () Bool)
(declare-fun c_32_1 () Bool)
(declare-fun c_32_0 () Bool)
(declare-fun c_33_6 () Bool)
(declare-fun c_33_5 () Bool)
(declare-fun c_33_4 () Bool)
(declare-fun c_33_3 () Bool)
(declare-fun c_33_2 () Bool)
(declare-fun c_33_1 () Bool)
(declare-fun c_33_0 () Bool)
(declare-fun c_34_6 () Bool)
(declare-fun c_34_5 () Bool)
(declare-fun c_34_4 () Bool)
(declare-fun c_34_3 () Bool)
(declare-fun c_34_2 () Bool)
(declare-fun c_34_1 () Bool)
(declare-fun c_34_0 () Bool)
(declare-fun c_35_6 () Bool)
(declare-fun c_35_5 () Bool)
(declare-fun c_35_4 () Bool)
(declare-fun c_35_3 () Bool)
(declare-fun c_35_2 () Bool)
(declare-fun c_35_1 () Bool)
(declare-fun c_35_0 () Bool)
(declare-fun c_36_6 () Bool)
(declare-fun c_36_5 () Bool)
(declare-fun c_36_4 () Bool)
(declare-fun c_36_3 () Bool)
(declare-fun c_36_2 () Bool)
(declare-fun c_36_1 () Bool)
(declare-fun c_36_0 () Bool)
(declare-fun c_37_6 () Bool)
(declare-fun c_37_5 () Bool)
(declare-fun c_37_4 () Bool)
(declare-fun c_37_3 () Bool)
(declare-fun c_37_2 () Bool)
(declare-fun c_37_1 () Bool)
(declare-fun c_37_0 () Bool)
(declare-fun c_38_6 () Bool)
(declare-fun c_38_5 () Bool)
(declare-fun c_38_4 () Bool)
(declare-fun c_38_3 () Bool)
(declare-fun c_38_2 () Bool)
(declare-fun c_38_1 () Bool)
(declare-fun c_38_0 () Bool)
(declare-fun c_39_6 () Bool)
(declare-fun c_39_5 () Bool)
(declare-fun c_39_4 () Bool)
(declare-fun c_39_3 () Bool)
(declare-fun c_39_2 () Bool)
(declare-fun c_39_1 () Bool)
(declare-fun c_39_0 () Bool)
(declare-fun c_40_6 () Bool)
(declare-fun c_40_5 () Bool)
(declare-fun c_40_4 () Bool)
(declare-fun c_40_3 () Bool)
(declare-fun c_40_2 () Bool)
(declare-fun c_40_1 () Bool)
(declare-fun c_40_0 () Bool)
(declare-fun d_0_6 () Bool)
(declare-fun d_0_5 () Bool)
(declare-fun d_0_4 () Bool)
(declare-fun d_0_3 () Bool)
(declare-fun d_0_2 () Bool)
(declare-fun d_0_1 () Bool)
(declare-fun d_0_0 () Bool)
(declare-fun d_1_6 () Bool)
(declare-fun d_1_5 () Bool)
(declare-fun d_1_4 () Bool)
(declare-fun d_1_3 () Bool)
(declare-fun d_1_2 () Bool)
(declare-fun d_1_1 () Bool)
(declare-fun d_1_0 () Bool)
(declare-fun d_2_6 () Bool)
(declare-fun d_2_5 () Bool)
(declare-fun d_2_4 () Bool)
(declare-fun d_2_3 () Bool)
(declare-fun d_2_2 () Bool)
(declare-fun d_2_1 () Bool)
(declare-fun d_2_0 () Bool)
(declare-fun d_3_6 () Bool)
(declare-fun d_3_5 () Bool)
(declare-fun d_3_4 () Bool)
(declare-fun d_3_3 () Bool)
(declare-fun d_3_2 () Bool)
(declare-fun d_3_1 () Bool)
(declare-fun d_3_0 () Bool)
(declare-fun d_4_6 () Bool)
(declare-fun d_4_5 () Bool)
(declare-fun d_4_4 () Bool)
(declare-fun d_4_3 () Bool)
(declare-fun d_4_2 () Bool)
(declare-fun d_4_1 () Bool)
(declare-fun d_4_0 () Bool)
(declare-fun d_5_6 () Bool)
(declare-fun d_5_5 () Bool)
(declare-fun d_5_4 () Bool)
(declare-fun d_5_3 () Bool)
(declare-fun d_5_2 () Bool)
(declare-fun d_5_1 () Bool)
(declare-fun d_5_0 () Bool)
(declare-fun d_6_6 () Bool)
(declare-fun d_6_5 () Bool)
(declare-fun d_6_4 () Bool)
(declare-fun d_6_3 () Bool)
(declare-fun d_6_2 () Bool)
(declare-fun d_6_1 () Bool)
(declare-fun d_6_0 () Bool)
(declare-fun d_7_6 () Bool)
(declare-fun d_7_5 () Bool)
(declare-fun d_7_4 () Bool)
(declare-fun d_7_3 () Bool)
(declare-fun d_7_2 () Bool)
(declare-fun d_7_1 () Bool)
(declare-fun d_7_0 () Bool)
(declare-fun d_8_6 () Bool)
(declare-fun d_8_5 () Bool)
(declare-fun d_8_4 () Bool)
(declare-fun d_8_3 () Bool)
(declare-fun d_8_2 () Bool)
(declare-fun d_8_1 () Bool)
(declare-fun d_8_0 () Bool)
(declare-fun d_9_6 () Bool)
(declare-fun d_9_5 () Bool)
(declare-fun d_9_4 () Bool)
(declare-fun d_9_3 () Bool)
(declare-fun d_9_2 () Bool)
(declare-fun d_9_1 () Bool)
(declare-fun d_9_0 () Bool)
(declare-fun d_10_6 () Bool)
(declare-fun d_10_5 () Bool)
(declare-fun d_10_4 () Bool)
(declare-fun d_10_3 () Bool)
(declare-fun d_10_2 () Bool)
(declare-fun d_10_1 () Bool)
(declare-fun d_10_0 () Bool)
(declare-fun d_11_6 () Bool)
(declare-fun d_11_5 () Bool)
(declare-fun d_11_4 () Bool)
(declare-fun d_11_3 () Bool)
(declare-fun d_11_2 () Bool)
(declare-fun d_11_1 () Bool)
(declare-fun d_11_0 () Bool)
(declare-fun d_12_6 () Bool)
(declare-fun d_12_5 () Bool)
(declare-fun d_12_4 () Bool)
(declare-fun d_12_3 () Bool)
(declare-fun d_12_2 () Bool)
(declare-fun d_12_1 () Bool)
(declare-fun d_12_0 () Bool)
(declare-fun d_13_6 () Bool)
(declare-fun d_13_5 () Bool)
(declare-fun d_13_4 () Bool)
(declare-fun d_13_3 () Bool)
(declare-fun d_13_2 () Bool)
(declare-fun d_13_1 () Bool)
(declare-fun d_13_0 () Bool)
(declare-fun d_14_6 () Bool)
(declare-fun d_14_5 () Bool)
(declare-fun d_14_4 () Bool)
(declare-fun d_14_3 () Bool)
(declare-fun d_14_2 () Bool)
(declare-fun d_14_1 () Bool)
(declare-fun d_14_0 () Bool)
(declare-fun d_15_6 () Bool)
(declare-fun d_15_5 () Bool)
(declare-fun d_15_4 () Bool)
(declare-fun d_15_3 () Bool)
(declare-fun d_15_2 () Bool)
(declare-fun d_15_1 () Bool)
(declare-fun d_15_0 () Bool)
(declare-fun d_16_6 () Bool)
(declare-fun d_16_5 () Bool)
(declare-fun d_16_4 () Bool)
(declare-fun d_16_3 () Bool)
(declare-fun d_16_2 () Bool)
(declare-fun d_16_1 () Bool)
(declare-fun d_16_0 () Bool)
(declare-fun d_17_6 () Bool)
(declare-fun d_17_5 () Bool)
(declare-fun d_17_4 () Bool)
(declare-fun d_17_3 () Bool)
(declare-fun d_17_2 () Bool)
(declare-fun d_17_1 () Bool)
(declare-fun d_17_0 () Bool)
(declare-fun d_18_6 () Bool)
(declare-fun d_18_5 () Bool)
(declare-fun d_18_4 () Bool)
(declare-fun d_18_3 () Bool)
(declare-fun d_18_2 () Bool)
(declare-fun d_18_1 () Bool)
(declare-fun d_18_0 () Bool)
(declare-fun d_19_6 () Bool)
(declare-fun d_19_5 () Bool)
(declare-fun d_19_4 () Bool)
(declare-fun d_19_3 () Bool)
(declare-fun d_19_2 () Bool)
(declare-fun d_19_1 () Bool)
(declare-fun d_19_0 () Bool)
(declare-fun d_20_6 () Bool)
(declare-fun d_20_5 () Bool)
(declare-fun d_20_4 () Bool)
(declare-fun d_20_3 () Bool)
(declare-fun d_20_2 () Bool)
(declare-fun d_20_1 () Bool)
(declare-fun d_20_0 () Bool)
(declare-fun d_21_6 () Bool)
(declare-fun d_21_5 () Bool)
(declare-fun d_21_4 () Bool)
(declare-fun d_21_3 () Bool)
(declare-fun d_21_2 () Bool)
(declare-fun d_21_1 () Bool)
(declare-fun d_21_0 () Bool)
(declare-fun d_22_6 () Bool)
(declare-fun d_22_5 () Bool)
(declare-fun d_22_4 () Bool)
(declare-fun d_22_3 () Bool)
(declare-fun d_22_2 () Bool)
(declare-fun d_22_1 () Bool)
(declare-fun d_22_0 () Bool)
(declare-fun d_23_6 () Bool)
(declare-fun d_23_5 () Bool)
(declare-fun d_23_4 () Bool)
(declare-fun d_23_3 () Bool)
(declare-fun d_23_2 () Bool)
(declare-fun d_23_1 () Bool)
(declare-fun d_23_0 () Bool)
(declare-fun d_24_6 () Bool)
(declare-fun d_24_5 () Bool)
(declare-fun d_24_4 () Bool)
(declare-fun d_24_3 () Bool)
(declare-fun d_24_2 () Bool)
(declare-fun d_24_1 () Bool)
(declare-fun d_24_0 () Bool)
(declare-fun d_25_6 () Bool)
(declare-fun d_25_5 () Bool)
(declare-fun d_25_4 () Bool)
(declare-fun d_25_3 () Bool)
(declare-fun d_25_2 () Bool)
(declare-fun d_25_1 () Bool)
(declare-fun d_25_0 () Bool)
(declare-fun d_26_6 () Bool)
(declare-fun d_26_5 () Bool)
(declare-fun d_26_4 () Bool)
(declare-fun d_26_3 () Bool)
(declare-fun d_26_2 () Bool)
(declare-fun d_26_1 () Bool)
(declare-fun d_26_0 () Bool)
(declare-fun d_27_6 () Bool)
(declare-fun d_27_5 () Bool)
(declare-fun d_27_4 () Bool)
(declare-fun d_27_3 () Bool)
(declare-fun d_27_2 () Bool)
(declare-fun d_27_1 () Bool)
(declare-fun d_27_0 () Bool)
(declare-fun d_28_6 () Bool)
(declare-fun d_28_5 () Bool)
(declare-fun d_28_4 () Bool)
(declare-fun d_28_3 () Bool)
(declare-fun d_28_2 () Bool)
(declare-fun d_28_1 () Bool)
(declare-fun d_28_0 () Bool)
(declare-fun d_29_6 () Bool)
(declare-fun d_29_5 () Bool)
(declare-fun d_29_4 () Bool)
(declare-fun d_29_3 () Bool)
(declare-fun d_29_2 () Bool)
(declare-fun d_29_1 () Bool)
(declare-fun d_29_0 () Bool)
(declare-fun d_30_6 () Bool)
(declare-fun d_30_5 () Bool)
(declare-fun d_30_4 () Bool)
(declare-fun d_30_3 () Bool)
(declare-fun d_30_2 () Bool)
(declare-fun d_30_1 () Bool)
(declare-fun d_30_0 () Bool)
(declare-fun d_31_6 () Bool)
(declare-fun d_31_5 () Bool)
(declare-fun d_31_4 () Bool)
(declare-fun d_31_3 () Bool)
(declare-fun d_31_2 () Bool)
(declare-fun d_31_1 () Bool)
(declare-fun d_31_0 () Bool)
(declare-fun d_32_6 () Bool)
(declare-fun d_32_5 () Bool)
(declare-fun d_32_4 () Bool)
(declare-fun d_32_3 () Bool)
(declare-fun d_32_2 () Bool)
(declare-fun d_32_1 () Bool)
(declare-fun d_32_0 () Bool)
(declare-fun d_33_6 () Bool)
(declare-fun d_33_5 () Bool)
(declare-fun d_33_4 () Bool)
(declare-fun d_33_3 () Bool)
(declare-fun d_33_2 () Bool)
(declare-fun d_33_1 () Bool)
(declare-fun d_33_0 () Bool)
(declare-fun d_34_6 () Bool)
(declare-fun d_34_5 () Bool)
(declare-fun d_34_4 () Bool)
(declare-fun d_34_3 () Bool)
(declare-fun d_34_2 () Bool)
(declare-fun d_34_1 () Bool)
(declare-fun d_34_0 () Bool)
(declare-fun d_35_6 () Bool)
(declare-fun d_35_5 () Bool)
(declare-fun d_35_4 () Bool)
(declare-fun d_35_3 () Bool)
(declare-fun d_35_2 () Bool)
(declare-fun d_35_1 () Bool)
(declare-fun d_35_0 () Bool)
(declare-fun d_36_6 () Bool)
(declare-fun d_36_5 () Bool)
(declare-fun d_36_4 () Bool)
(declare-fun d_36_3 () Bool)
(declare-fun d_36_2 () Bool)
(declare-fun d_36_1 () Bool)
(declare-fun d_36_0 () Bool)
(declare-fun d_37_6 () Bool)
(declare-fun d_37_5 () Bool)
(declare-fun d_37_4 () Bool)
(declare-fun d_37_3 () Bool)
(declare-fun d_37_2 () Bool)
(declare-fun d_37_1 () Bool)
(declare-fun d_37_0 () Bool)
(declare-fun d_38_6 () Bool)
(declare-fun d_38_5 () Bool)
(declare-fun d_38_4 () Bool)
(declare-fun d_38_3 () Bool)
(declare-fun d_38_2 () Bool)
(declare-fun d_38_1 () Bool)
(declare-fun d_38_0 () Bool)
(declare-fun d_39_6 () Bool)
(declare-fun d_39_5 () Bool)
(declare-fun d_39_4 () Bool)
(declare-fun d_39_3 () Bool)
(declare-fun d_39_2 () Bool)
(declare-fun d_39_1 () Bool)
(declare-fun d_39_0 () Bool)
(declare-fun d_40_6 () Bool)
(declare-fun d_40_5 () Bool)
(declare-fun d_40_4 () Bool)
(declare-fun d_40_3 () Bool)
(declare-fun d_40_2 () Bool)
(declare-fun d_40_1 () Bool)
(declare-fun d_40_0 () Bool)
(declare-fun in_target_0 () Bool)
(declare-fun in_target_4 () Bool)
(declare-fun in_region_4 () Bool)
(declare-fun ghost_2_0 () Int)
(declare-fun ghost_2_4 () Int)
(declare-fun ghost_1_0 () Int)
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
(declare-fun in_region_9 () Bool)
(declare-fun in_region_8 () Bool)
(declare-fun in_region_6 () Bool)
(declare-fun in_target_12 () Bool)
(declare-fun in_region_12 () Bool)
(declare-fun in_target_11 () Bool)
(declare-fun in_region_11 () Bool)
(declare-fun in_target_7 () Bool)
(declare-fun in_region_7 () Bool)
(declare-fun in_region_5 () Bool)
(declare-fun in_target_10 () Bool)
(declare-fun in_region_10 () Bool)
(declare-fun in_target_9 () Bool)
(declare-fun in_target_8 () Bool)
(declare-fun in_target_6 () Bool)
(declare-fun in_target_5 () Bool)
(declare-fun ghost_2_24 () Int)
(declare-fun ghost_2_40 () Int)
(declare-fun in_target_40 () Bool)
(declare-fun ghost_2_39 () Int)
(declare-fun in_target_39 () Bool)
(declare-fun ghost_2_12 () Int)
(declare-fun ghost_2_31 () Int)
(declare-fun in_target_31 () Bool)
(declare-fun in_target_24 () Bool)
(declare-fun ghost_2_23 () Int)
(declare-fun ghost_2_38 () Int)
(declare-fun in_target_38 () Bool)
(declare-fun ghost_2_11 () Int)
(declare-fun in_target_23 () Bool)
(declare-fun ghost_2_22 () Int)
(declare-fun ghost_2_37 () Int)
(declare-fun in_target_37 () Bool)
(declare-fun ghost_2_10 () Int)
(declare-fun in_target_22 () Bool)
(declare-fun ghost_2_21 () Int)
(declare-fun ghost_2_36 () Int)
(declare-fun in_target_36 () Bool)
(declare-fun ghost_2_35 () Int)
(declare-fun in_target_35 () Bool)
(declare-fun in_target_21 () Bool)
(declare-fun ghost_2_20 () Int)
(declare-fun ghost_2_34 () Int)
(declare-fun in_target_34 () Bool)
(declare-fun ghost_2_9 () Int)
(declare-fun in_target_20 () Bool)
(declare-fun ghost_2_19 () Int)
(declare-fun ghost_2_33 () Int)
(declare-fun in_target_33 () Bool)
(declare-fun ghost_2_8 () Int)
(declare-fun in_target_19 () Bool)
(declare-fun ghost_2_18 () Int)
(declare-fun ghost_2_32 () Int)
(declare-fun in_target_32 () Bool)
(declare-fun ghost_2_30 () Int)
(declare-fun in_target_30 () Bool)
(declare-fun in_target_18 () Bool)
(declare-fun ghost_2_17 () Int)
(declare-fun ghost_2_7 () Int)
(declare-fun ghost_2_29 () Int)
(declare-fun in_target_29 () Bool)
(declare-fun in_target_17 () Bool)
(declare-fun ghost_2_16 () Int)
(declare-fun ghost_2_6 () Int)
(declare-fun ghost_2_28 () Int)
(declare-fun in_target_28 () Bool)
(declare-fun in_target_16 () Bool)
(declare-fun ghost_2_15 () Int)
(declare-fun ghost_2_5 () Int)
(declare-fun ghost_2_27 () Int)
(declare-fun in_target_27 () Bool)
(declare-fun in_target_15 () Bool)
(declare-fun ghost_2_14 () Int)
(declare-fun ghost_2_26 () Int)
(declare-fun in_target_26 () Bool)
(declare-fun in_target_14 () Bool)
(declare-fun ghost_2_13 () Int)
(declare-fun ghost_2_25 () Int)
(declare-fun in_target_25 () Bool)
(declare-fun in_target_13 () Bool)
(declare-fun ghost_1_24 () Int)
(declare-fun ghost_1_40 () Int)
(declare-fun ghost_1_39 () Int)
(declare-fun ghost_1_12 () Int)
(declare-fun ghost_1_31 () Int)
(declare-fun ghost_1_23 () Int)
(declare-fun ghost_1_38 () Int)
(declare-fun ghost_1_11 () Int)
(declare-fun ghost_1_22 () Int)
(declare-fun ghost_1_37 () Int)
(declare-fun ghost_1_10 () Int)
(declare-fun ghost_1_21 () Int)
(declare-fun ghost_1_36 () Int)
(declare-fun ghost_1_35 () Int)
(declare-fun ghost_1_20 () Int)
(declare-fun ghost_1_34 () Int)
(declare-fun ghost_1_9 () Int)
(declare-fun ghost_1_19 () Int)
(declare-fun ghost_1_33 () Int)
(declare-fun ghost_1_8 () Int)
(declare-fun ghost_1_18 () Int)
(declare-fun ghost_1_32 () Int)
(declare-fun ghost_1_30 () Int)
(declare-fun ghost_1_17 () Int)
(declare-fun ghost_1_7 () Int)
(declare-fun ghost_1_29 () Int)
(declare-fun ghost_1_16 () Int)
(declare-fun ghost_1_6 () Int)
(declare-fun ghost_1_28 () Int)
(declare-fun ghost_1_15 () Int)
(declare-fun ghost_1_5 () Int)
(declare-fun ghost_1_27 () Int)
(declare-fun ghost_1_14 () Int)
(declare-fun ghost_1_26 () Int)
(declare-fun ghost_1_13 () Int)
(declare-fun ghost_1_25 () Int)
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
(declare-fun in_region_18 () Bool)
(declare-fun in_region_17 () Bool)
(declare-fun in_region_16 () Bool)
(declare-fun in_region_15 () Bool)
(declare-fun in_region_14 () Bool)
(declare-fun in_region_13 () Bool)
(declare-fun instance_0 () Bool)
(assert
 (let (($x47 (or false c_0_0)))
 (let (($x49 (or $x47 c_0_1)))
 (let (($x51 (or $x49 c_0_2)))
 (let (($x53 (or $x51 c_0_3)))
 (let (($x55 (or $x53 c_0_4)))
 (let (($x57 (or $x55 c_0_5)))
 (or $x57 c_0_6))))))))
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
 (not (and c_0_2 c_0_3)))
(assert
 (not (and c_0_2 c_0_4)))
(assert
 (not (and c_0_2 c_0_5)))
(assert
 (not (and c_0_2 c_0_6)))
(assert
 (not (and c_0_3 c_0_4)))
(assert
 (not (and c_0_3 c_0_5)))
(assert
 (not (and c_0_3 c_0_6)))
(assert
 (not (and c_0_4 c_0_5)))
(assert
 (not (and c_0_4 c_0_6)))
(assert
 (not (and c_0_5 c_0_6)))
(assert
 (let (($x103 (or false c_1_0)))
 (let (($x105 (or $x103 c_1_1)))
 (let (($x107 (or $x105 c_1_2)))
 (let (($x109 (or $x107 c_1_3)))
 (let (($x111 (or $x109 c_1_4)))
 (let (($x113 (or $x111 c_1_5)))
 (or $x113 c_1_6))))))))
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
 (not (and c_1_2 c_1_3)))
(assert
 (not (and c_1_2 c_1_4)))
(assert
 (not (and c_1_2 c_1_5)))
(assert
 (not (and c_1_2 c_1_6)))
(assert
 (not (and c_1_3 c_1_4)))
(assert
 (not (and c_1_3 c_1_5)))
(assert
 (not (and c_1_3 c_1_6)))
(assert
 (not (and c_1_4 c_1_5)))
(assert
 (not (and c_1_4 c_1_6)))
(assert
 (not (and c_1_5 c_1_6)))
(assert
 (let (($x159 (or false c_2_0)))
 (let (($x161 (or $x159 c_2_1)))
 (let (($x163 (or $x161 c_2_2)))
 (let (($x165 (or $x163 c_2_3)))
 (let (($x167 (or $x165 c_2_4)))
 (let (($x169 (or $x167 c_2_5)))
 (or $x169 c_2_6))))))))
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
 (not (and c_2_2 c_2_3)))
(assert
 (not (and c_2_2 c_2_4)))
(assert
 (not (and c_2_2 c_2_5)))
(assert
 (not (and c_2_2 c_2_6)))
(assert
 (not (and c_2_3 c_2_4)))
(assert
 (not (and c_2_3 c_2_5)))
(assert
 (not (and c_2_3 c_2_6)))
(assert
 (not (and c_2_4 c_2_5)))
(assert
 (not (and c_2_4 c_2_6)))
(assert
 (not (and c_2_5 c_2_6)))
(assert
 (let (($x215 (or false c_3_0)))
 (let (($x217 (or $x215 c_3_1)))
 (let (($x219 (or $x217 c_3_2)))
 (let (($x221 (or $x219 c_3_3)))
 (let (($x223 (or $x221 c_3_4)))
 (let (($x225 (or $x223 c_3_5)))
 (or $x225 c_3_6))))))))
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
 (not (and c_3_2 c_3_3)))
(assert
 (not (and c_3_2 c_3_4)))
(assert
 (not (and c_3_2 c_3_5)))
(assert
 (not (and c_3_2 c_3_6)))
(assert
 (not (and c_3_3 c_3_4)))
(assert
 (not (and c_3_3 c_3_5)))
(assert
 (not (and c_3_3 c_3_6)))
(assert
 (not (and c_3_4 c_3_5)))
(assert
 (not (and c_3_4 c_3_6)))
(assert
 (not (and c_3_5 c_3_6)))
(assert
 (let (($x271 (or false c_4_0)))
 (let (($x273 (or $x271 c_4_1)))
 (let (($x275 (or $x273 c_4_2)))
 (let (($x277 (or $x275 c_4_3)))
 (let (($x279 (or $x277 c_4_4)))
 (let (($x281 (or $x279 c_4_5)))
 (or $x281 c_4_6))))))))
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
 (not (and c_4_2 c_4_3)))
(assert
 (not (and c_4_2 c_4_4)))
(assert
 (not (and c_4_2 c_4_5)))
(assert
 (not (and c_4_2 c_4_6)))
(assert
 (not (and c_4_3 c_4_4)))
(assert
 (not (and c_4_3 c_4_5)))
(assert
 (not (and c_4_3 c_4_6)))
(assert
 (not (and c_4_4 c_4_5)))
(assert
 (not (and c_4_4 c_4_6)))
(assert
 (not (and c_4_5 c_4_6)))
(assert
 (let (($x327 (or false c_5_0)))
 (let (($x329 (or $x327 c_5_1)))
 (let (($x331 (or $x329 c_5_2)))
 (let (($x333 (or $x331 c_5_3)))
 (let (($x335 (or $x333 c_5_4)))
 (let (($x337 (or $x335 c_5_5)))
 (or $x337 c_5_6))))))))
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
 (not (and c_5_2 c_5_3)))
(assert
 (not (and c_5_2 c_5_4)))
(assert
 (not (and c_5_2 c_5_5)))
(assert
 (not (and c_5_2 c_5_6)))
(assert
 (not (and c_5_3 c_5_4)))
(assert
 (not (and c_5_3 c_5_5)))
(assert
 (not (and c_5_3 c_5_6)))
(assert
 (not (and c_5_4 c_5_5)))
(assert
 (not (and c_5_4 c_5_6)))
(assert
 (not (and c_5_5 c_5_6)))
(assert
 (let (($x383 (or false c_6_0)))
 (let (($x385 (or $x383 c_6_1)))
 (let (($x387 (or $x385 c_6_2)))
 (let (($x389 (or $x387 c_6_3)))
 (let (($x391 (or $x389 c_6_4)))
 (let (($x393 (or $x391 c_6_5)))
 (or $x393 c_6_6))))))))
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
 (not (and c_6_2 c_6_3)))
(assert
 (not (and c_6_2 c_6_4)))
(assert
 (not (and c_6_2 c_6_5)))
(assert
 (not (and c_6_2 c_6_6)))
(assert
 (not (and c_6_3 c_6_4)))
(assert
 (not (and c_6_3 c_6_5)))
(assert
 (not (and c_6_3 c_6_6)))
(assert
 (not (and c_6_4 c_6_5)))
(assert
 (not (and c_6_4 c_6_6)))
(assert
 (not (and c_6_5 c_6_6)))
(assert
 (let (($x439 (or false c_7_0)))
 (let (($x441 (or $x439 c_7_1)))
 (let (($x443 (or $x441 c_7_2)))
 (let (($x445 (or $x443 c_7_3)))
 (let (($x447 (or $x445 c_7_4)))
 (let (($x449 (or $x447 c_7_5)))
 (or $x449 c_7_6))))))))
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
 (not (and c_7_2 c_7_3)))
(assert
 (not (and c_7_2 c_7_4)))
(assert
 (not (and c_7_2 c_7_5)))
(assert
 (not (and c_7_2 c_7_6)))
(assert
 (not (and c_7_3 c_7_4)))
(assert
 (not (and c_7_3 c_7_5)))
(assert
 (not (and c_7_3 c_7_6)))
(assert
 (not (and c_7_4 c_7_5)))
(assert
 (not (and c_7_4 c_7_6)))
(assert
 (not (and c_7_5 c_7_6)))
(assert
 (let (($x495 (or false c_8_0)))
 (let (($x497 (or $x495 c_8_1)))
 (let (($x499 (or $x497 c_8_2)))
 (let (($x501 (or $x499 c_8_3)))
 (let (($x503 (or $x501 c_8_4)))
 (let (($x505 (or $x503 c_8_5)))
 (or $x505 c_8_6))))))))
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
 (not (and c_8_2 c_8_3)))
(assert
 (not (and c_8_2 c_8_4)))
(assert
 (not (and c_8_2 c_8_5)))
(assert
 (not (and c_8_2 c_8_6)))
(assert
 (not (and c_8_3 c_8_4)))
(assert
 (not (and c_8_3 c_8_5)))
(assert
 (not (and c_8_3 c_8_6)))
(assert
 (not (and c_8_4 c_8_5)))
(assert
 (not (and c_8_4 c_8_6)))
(assert
 (not (and c_8_5 c_8_6)))
(assert
 (let (($x551 (or false c_9_0)))
 (let (($x553 (or $x551 c_9_1)))
 (let (($x555 (or $x553 c_9_2)))
 (let (($x557 (or $x555 c_9_3)))
 (let (($x559 (or $x557 c_9_4)))
 (let (($x561 (or $x559 c_9_5)))
 (or $x561 c_9_6))))))))
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
 (not (and c_9_2 c_9_3)))
(assert
 (not (and c_9_2 c_9_4)))
(assert
 (not (and c_9_2 c_9_5)))
(assert
 (not (and c_9_2 c_9_6)))
(assert
 (not (and c_9_3 c_9_4)))
(assert
 (not (and c_9_3 c_9_5)))
(assert
 (not (and c_9_3 c_9_6)))
(assert
 (not (and c_9_4 c_9_5)))
(assert
 (not (and c_9_4 c_9_6)))
(assert
 (not (and c_9_5 c_9_6)))
(assert
 (let (($x607 (or false c_10_0)))
 (let (($x609 (or $x607 c_10_1)))
 (let (($x611 (or $x609 c_10_2)))
 (let (($x613 (or $x611 c_10_3)))
 (let (($x615 (or $x613 c_10_4)))
 (let (($x617 (or $x615 c_10_5)))
 (or $x617 c_10_6))))))))
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
 (not (and c_10_2 c_10_3)))
(assert
 (not (and c_10_2 c_10_4)))
(assert
 (not (and c_10_2 c_10_5)))
(assert
 (not (and c_10_2 c_10_6)))
(assert
 (not (and c_10_3 c_10_4)))
(assert
 (not (and c_10_3 c_10_5)))
(assert
 (not (and c_10_3 c_10_6)))
(assert
 (not (and c_10_4 c_10_5)))
(assert
 (not (and c_10_4 c_10_6)))
(assert
 (not (and c_10_5 c_10_6)))
(assert
 (let (($x663 (or false c_11_0)))
 (let (($x665 (or $x663 c_11_1)))
 (let (($x667 (or $x665 c_11_2)))
 (let (($x669 (or $x667 c_11_3)))
 (let (($x671 (or $x669 c_11_4)))
 (let (($x673 (or $x671 c_11_5)))
 (or $x673 c_11_6))))))))
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
 (not (and c_11_2 c_11_3)))
(assert
 (not (and c_11_2 c_11_4)))
(assert
 (not (and c_11_2 c_11_5)))
(assert
 (not (and c_11_2 c_11_6)))
(assert
 (not (and c_11_3 c_11_4)))
(assert
 (not (and c_11_3 c_11_5)))
(assert
 (not (and c_11_3 c_11_6)))
(assert
 (not (and c_11_4 c_11_5)))
(assert
 (not (and c_11_4 c_11_6)))
(assert
 (not (and c_11_5 c_11_6)))
(assert
 (let (($x719 (or false c_12_0)))
 (let (($x721 (or $x719 c_12_1)))
 (let (($x723 (or $x721 c_12_2)))
 (let (($x725 (or $x723 c_12_3)))
 (let (($x727 (or $x725 c_12_4)))
 (let (($x729 (or $x727 c_12_5)))
 (or $x729 c_12_6))))))))
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
 (not (and c_12_2 c_12_3)))
(assert
 (not (and c_12_2 c_12_4)))
(assert
 (not (and c_12_2 c_12_5)))
(assert
 (not (and c_12_2 c_12_6)))
(assert
 (not (and c_12_3 c_12_4)))
(assert
 (not (and c_12_3 c_12_5)))
(assert
 (not (and c_12_3 c_12_6)))
(assert
 (not (and c_12_4 c_12_5)))
(assert
 (not (and c_12_4 c_12_6)))
(assert
 (not (and c_12_5 c_12_6)))
(assert
 (let (($x775 (or false c_13_0)))
 (let (($x777 (or $x775 c_13_1)))
 (let (($x779 (or $x777 c_13_2)))
 (let (($x781 (or $x779 c_13_3)))
 (let (($x783 (or $x781 c_13_4)))
 (let (($x785 (or $x783 c_13_5)))
 (or $x785 c_13_6))))))))
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
 (not (and c_13_2 c_13_3)))
(assert
 (not (and c_13_2 c_13_4)))
(assert
 (not (and c_13_2 c_13_5)))
(assert
 (not (and c_13_2 c_13_6)))
(assert
 (not (and c_13_3 c_13_4)))
(assert
 (not (and c_13_3 c_13_5)))
(assert
 (not (and c_13_3 c_13_6)))
(assert
 (not (and c_13_4 c_13_5)))
(assert
 (not (and c_13_4 c_13_6)))
(assert
 (not (and c_13_5 c_13_6)))
(assert
 (let (($x831 (or false c_14_0)))
 (let (($x833 (or $x831 c_14_1)))
 (let (($x835 (or $x833 c_14_2)))
 (let (($x837 (or $x835 c_14_3)))
 (let (($x839 (or $x837 c_14_4)))
 (let (($x841 (or $x839 c_14_5)))
 (or $x841 c_14_6))))))))
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
 (not (and c_14_2 c_14_3)))
(assert
 (not (and c_14_2 c_14_4)))
(assert
 (not (and c_14_2 c_14_5)))
(assert
 (not (and c_14_2 c_14_6)))
(assert
 (not (and c_14_3 c_14_4)))
(assert
 (not (and c_14_3 c_14_5)))
(assert
 (not (and c_14_3 c_14_6)))
(assert
 (not (and c_14_4 c_14_5)))
(assert
 (not (and c_14_4 c_14_6)))
(assert
 (not (and c_14_5 c_14_6)))
(assert
 (let (($x887 (or false c_15_0)))
 (let (($x889 (or $x887 c_15_1)))
 (let (($x891 (or $x889 c_15_2)))
 (let (($x893 (or $x891 c_15_3)))
 (let (($x895 (or $x893 c_15_4)))
 (let (($x897 (or $x895 c_15_5)))
 (or $x897 c_15_6))))))))
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
 (not (and c_15_2 c_15_3)))
(assert
 (not (and c_15_2 c_15_4)))
(assert
 (not (and c_15_2 c_15_5)))
(assert
 (not (and c_15_2 c_15_6)))
(assert
 (not (and c_15_3 c_15_4)))
(assert
 (not (and c_15_3 c_15_5)))
(assert
 (not (and c_15_3 c_15_6)))
(assert
 (not (and c_15_4 c_15_5)))
(assert
 (not (and c_15_4 c_15_6)))
(assert
 (not (and c_15_5 c_15_6)))
(assert
 (let (($x943 (or false c_16_0)))
 (let (($x945 (or $x943 c_16_1)))
 (let (($x947 (or $x945 c_16_2)))
 (let (($x949 (or $x947 c_16_3)))
 (let (($x951 (or $x949 c_16_4)))
 (let (($x953 (or $x951 c_16_5)))
 (or $x953 c_16_6))))))))
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
 (not (and c_16_2 c_16_3)))
(assert
 (not (and c_16_2 c_16_4)))
(assert
 (not (and c_16_2 c_16_5)))
(assert
 (not (and c_16_2 c_16_6)))
(assert
 (not (and c_16_3 c_16_4)))
(assert
 (not (and c_16_3 c_16_5)))
(assert
 (not (and c_16_3 c_16_6)))
(assert
 (not (and c_16_4 c_16_5)))
(assert
 (not (and c_16_4 c_16_6)))
(assert
 (not (and c_16_5 c_16_6)))
(assert
 (let (($x999 (or false c_17_0)))
 (let (($x1001 (or $x999 c_17_1)))
 (let (($x1003 (or $x1001 c_17_2)))
 (let (($x1005 (or $x1003 c_17_3)))
 (let (($x1007 (or $x1005 c_17_4)))
 (let (($x1009 (or $x1007 c_17_5)))
 (or $x1009 c_17_6))))))))
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
 (not (and c_17_2 c_17_3)))
(assert
 (not (and c_17_2 c_17_4)))
(assert
 (not (and c_17_2 c_17_5)))
(assert
 (not (and c_17_2 c_17_6)))
(assert
 (not (and c_17_3 c_17_4)))
(assert
 (not (and c_17_3 c_17_5)))
(assert
 (not (and c_17_3 c_17_6)))
(assert
 (not (and c_17_4 c_17_5)))
(assert
 (not (and c_17_4 c_17_6)))
(assert
 (not (and c_17_5 c_17_6)))
(assert
 (let (($x1055 (or false c_18_0)))
 (let (($x1057 (or $x1055 c_18_1)))
 (let (($x1059 (or $x1057 c_18_2)))
 (let (($x1061 (or $x1059 c_18_3)))
 (let (($x1063 (or $x1061 c_18_4)))
 (let (($x1065 (or $x1063 c_18_5)))
 (or $x1065 c_18_6))))))))
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
 (not (and c_18_2 c_18_3)))
(assert
 (not (and c_18_2 c_18_4)))
(assert
 (not (and c_18_2 c_18_5)))
(assert
 (not (and c_18_2 c_18_6)))
(assert
 (not (and c_18_3 c_18_4)))
(assert
 (not (and c_18_3 c_18_5)))
(assert
 (not (and c_18_3 c_18_6)))
(assert
 (not (and c_18_4 c_18_5)))
(assert
 (not (and c_18_4 c_18_6)))
(assert
 (not (and c_18_5 c_18_6)))
(assert
 (let (($x1111 (or false c_19_0)))
 (let (($x1113 (or $x1111 c_19_1)))
 (let (($x1115 (or $x1113 c_19_2)))
 (let (($x1117 (or $x1115 c_19_3)))
 (let (($x1119 (or $x1117 c_19_4)))
 (let (($x1121 (or $x1119 c_19_5)))
 (or $x1121 c_19_6))))))))
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
 (not (and c_19_2 c_19_3)))
(assert
 (not (and c_19_2 c_19_4)))
(assert
 (not (and c_19_2 c_19_5)))
(assert
 (not (and c_19_2 c_19_6)))
(assert
 (not (and c_19_3 c_19_4)))
(assert
 (not (and c_19_3 c_19_5)))
(assert
 (not (and c_19_3 c_19_6)))
(assert
 (not (and c_19_4 c_19_5)))
(assert
 (not (and c_19_4 c_19_6)))
(assert
 (not (and c_19_5 c_19_6)))
(assert
 (let (($x1167 (or false c_20_0)))
 (let (($x1169 (or $x1167 c_20_1)))
 (let (($x1171 (or $x1169 c_20_2)))
 (let (($x1173 (or $x1171 c_20_3)))
 (let (($x1175 (or $x1173 c_20_4)))
 (let (($x1177 (or $x1175 c_20_5)))
 (or $x1177 c_20_6))))))))
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
 (not (and c_20_2 c_20_3)))
(assert
 (not (and c_20_2 c_20_4)))
(assert
 (not (and c_20_2 c_20_5)))
(assert
 (not (and c_20_2 c_20_6)))
(assert
 (not (and c_20_3 c_20_4)))
(assert
 (not (and c_20_3 c_20_5)))
(assert
 (not (and c_20_3 c_20_6)))
(assert
 (not (and c_20_4 c_20_5)))
(assert
 (not (and c_20_4 c_20_6)))
(assert
 (not (and c_20_5 c_20_6)))
(assert
 (let (($x1223 (or false c_21_0)))
 (let (($x1225 (or $x1223 c_21_1)))
 (let (($x1227 (or $x1225 c_21_2)))
 (let (($x1229 (or $x1227 c_21_3)))
 (let (($x1231 (or $x1229 c_21_4)))
 (let (($x1233 (or $x1231 c_21_5)))
 (or $x1233 c_21_6))))))))
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
 (not (and c_21_2 c_21_3)))
(assert
 (not (and c_21_2 c_21_4)))
(assert
 (not (and c_21_2 c_21_5)))
(assert
 (not (and c_21_2 c_21_6)))
(assert
 (not (and c_21_3 c_21_4)))
(assert
 (not (and c_21_3 c_21_5)))
(assert
 (not (and c_21_3 c_21_6)))
(assert
 (not (and c_21_4 c_21_5)))
(assert
 (not (and c_21_4 c_21_6)))
(assert
 (not (and c_21_5 c_21_6)))
(assert
 (let (($x1279 (or false c_22_0)))
 (let (($x1281 (or $x1279 c_22_1)))
 (let (($x1283 (or $x1281 c_22_2)))
 (let (($x1285 (or $x1283 c_22_3)))
 (let (($x1287 (or $x1285 c_22_4)))
 (let (($x1289 (or $x1287 c_22_5)))
 (or $x1289 c_22_6))))))))
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
 (not (and c_22_2 c_22_3)))
(assert
 (not (and c_22_2 c_22_4)))
(assert
 (not (and c_22_2 c_22_5)))
(assert
 (not (and c_22_2 c_22_6)))
(assert
 (not (and c_22_3 c_22_4)))
(assert
 (not (and c_22_3 c_22_5)))
(assert
 (not (and c_22_3 c_22_6)))
(assert
 (not (and c_22_4 c_22_5)))
(assert
 (not (and c_22_4 c_22_6)))
(assert
 (not (and c_22_5 c_22_6)))
(assert
 (let (($x1335 (or false c_23_0)))
 (let (($x1337 (or $x1335 c_23_1)))
 (let (($x1339 (or $x1337 c_23_2)))
 (let (($x1341 (or $x1339 c_23_3)))
 (let (($x1343 (or $x1341 c_23_4)))
 (let (($x1345 (or $x1343 c_23_5)))
 (or $x1345 c_23_6))))))))
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
 (not (and c_23_2 c_23_3)))
(assert
 (not (and c_23_2 c_23_4)))
(assert
 (not (and c_23_2 c_23_5)))
(assert
 (not (and c_23_2 c_23_6)))
(assert
 (not (and c_23_3 c_23_4)))
(assert
 (not (and c_23_3 c_23_5)))
(assert
 (not (and c_23_3 c_23_6)))
(assert
 (not (and c_23_4 c_23_5)))
(assert
 (not (and c_23_4 c_23_6)))
(assert
 (not (and c_23_5 c_23_6)))
(assert
 (let (($x1391 (or false c_24_0)))
 (let (($x1393 (or $x1391 c_24_1)))
 (let (($x1395 (or $x1393 c_24_2)))
 (let (($x1397 (or $x1395 c_24_3)))
 (let (($x1399 (or $x1397 c_24_4)))
 (let (($x1401 (or $x1399 c_24_5)))
 (or $x1401 c_24_6))))))))
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
 (not (and c_24_2 c_24_3)))
(assert
 (not (and c_24_2 c_24_4)))
(assert
 (not (and c_24_2 c_24_5)))
(assert
 (not (and c_24_2 c_24_6)))
(assert
 (not (and c_24_3 c_24_4)))
(assert
 (not (and c_24_3 c_24_5)))
(assert
 (not (and c_24_3 c_24_6)))
(assert
 (not (and c_24_4 c_24_5)))
(assert
 (not (and c_24_4 c_24_6)))
(assert
 (not (and c_24_5 c_24_6)))
(assert
 (let (($x1447 (or false c_25_0)))
 (let (($x1449 (or $x1447 c_25_1)))
 (let (($x1451 (or $x1449 c_25_2)))
 (let (($x1453 (or $x1451 c_25_3)))
 (let (($x1455 (or $x1453 c_25_4)))
 (let (($x1457 (or $x1455 c_25_5)))
 (or $x1457 c_25_6))))))))
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
 (not (and c_25_2 c_25_3)))
(assert
 (not (and c_25_2 c_25_4)))
(assert
 (not (and c_25_2 c_25_5)))
(assert
 (not (and c_25_2 c_25_6)))
(assert
 (not (and c_25_3 c_25_4)))
(assert
 (not (and c_25_3 c_25_5)))
(assert
 (not (and c_25_3 c_25_6)))
(assert
 (not (and c_25_4 c_25_5)))
(assert
 (not (and c_25_4 c_25_6)))
(assert
 (not (and c_25_5 c_25_6)))
(assert
 (let (($x1503 (or false c_26_0)))
 (let (($x1505 (or $x1503 c_26_1)))
 (let (($x1507 (or $x1505 c_26_2)))
 (let (($x1509 (or $x1507 c_26_3)))
 (let (($x1511 (or $x1509 c_26_4)))
 (let (($x1513 (or $x1511 c_26_5)))
 (or $x1513 c_26_6))))))))
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
 (not (and c_26_2 c_26_3)))
(assert
 (not (and c_26_2 c_26_4)))
(assert
 (not (and c_26_2 c_26_5)))
(assert
 (not (and c_26_2 c_26_6)))
(assert
 (not (and c_26_3 c_26_4)))
(assert
 (not (and c_26_3 c_26_5)))
(assert
 (not (and c_26_3 c_26_6)))
(assert
 (not (and c_26_4 c_26_5)))
(assert
 (not (and c_26_4 c_26_6)))
(assert
 (not (and c_26_5 c_26_6)))
(assert
 (let (($x1559 (or false c_27_0)))
 (let (($x1561 (or $x1559 c_27_1)))
 (let (($x1563 (or $x1561 c_27_2)))
 (let (($x1565 (or $x1563 c_27_3)))
 (let (($x1567 (or $x1565 c_27_4)))
 (let (($x1569 (or $x1567 c_27_5)))
 (or $x1569 c_27_6))))))))
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
 (not (and c_27_2 c_27_3)))
(assert
 (not (and c_27_2 c_27_4)))
(assert
 (not (and c_27_2 c_27_5)))
(assert
 (not (and c_27_2 c_27_6)))
(assert
 (not (and c_27_3 c_27_4)))
(assert
 (not (and c_27_3 c_27_5)))
(assert
 (not (and c_27_3 c_27_6)))
(assert
 (not (and c_27_4 c_27_5)))
(assert
 (not (and c_27_4 c_27_6)))
(assert
 (not (and c_27_5 c_27_6)))
(assert
 (let (($x1615 (or false c_28_0)))
 (let (($x1617 (or $x1615 c_28_1)))
 (let (($x1619 (or $x1617 c_28_2)))
 (let (($x1621 (or $x1619 c_28_3)))
 (let (($x1623 (or $x1621 c_28_4)))
 (let (($x1625 (or $x1623 c_28_5)))
 (or $x1625 c_28_6))))))))
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
 (not (and c_28_2 c_28_3)))
(assert
 (not (and c_28_2 c_28_4)))
(assert
 (not (and c_28_2 c_28_5)))
(assert
 (not (and c_28_2 c_28_6)))
(assert
 (not (and c_28_3 c_28_4)))
(assert
 (not (and c_28_3 c_28_5)))
(assert
 (not (and c_28_3 c_28_6)))
(assert
 (not (and c_28_4 c_28_5)))
(assert
 (not (and c_28_4 c_28_6)))
(assert
 (not (and c_28_5 c_28_6)))
(assert
 (let (($x1671 (or false c_29_0)))
 (let (($x1673 (or $x1671 c_29_1)))
 (let (($x1675 (or $x1673 c_29_2)))
 (let (($x1677 (or $x1675 c_29_3)))
 (let (($x1679 (or $x1677 c_29_4)))
 (let (($x1681 (or $x1679 c_29_5)))
 (or $x1681 c_29_6))))))))
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
 (not (and c_29_2 c_29_3)))
(assert
 (not (and c_29_2 c_29_4)))
(assert
 (not (and c_29_2 c_29_5)))
(assert
 (not (and c_29_2 c_29_6)))
(assert
 (not (and c_29_3 c_29_4)))
(assert
 (not (and c_29_3 c_29_5)))
(assert
 (not (and c_29_3 c_29_6)))
(assert
 (not (and c_29_4 c_29_5)))
(assert
 (not (and c_29_4 c_29_6)))
(assert
 (not (and c_29_5 c_29_6)))
(assert
 (let (($x1727 (or false c_30_0)))
 (let (($x1729 (or $x1727 c_30_1)))
 (let (($x1731 (or $x1729 c_30_2)))
 (let (($x1733 (or $x1731 c_30_3)))
 (let (($x1735 (or $x1733 c_30_4)))
 (let (($x1737 (or $x1735 c_30_5)))
 (or $x1737 c_30_6))))))))
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
 (not (and c_30_2 c_30_3)))
(assert
 (not (and c_30_2 c_30_4)))
(assert
 (not (and c_30_2 c_30_5)))
(assert
 (not (and c_30_2 c_30_6)))
(assert
 (not (and c_30_3 c_30_4)))
(assert
 (not (and c_30_3 c_30_5)))
(assert
 (not (and c_30_3 c_30_6)))
(assert
 (not (and c_30_4 c_30_5)))
(assert
 (not (and c_30_4 c_30_6)))
(assert
 (not (and c_30_5 c_30_6)))
(assert
 (let (($x1783 (or false c_31_0)))
 (let (($x1785 (or $x1783 c_31_1)))
 (let (($x1787 (or $x1785 c_31_2)))
 (let (($x1789 (or $x1787 c_31_3)))
 (let (($x1791 (or $x1789 c_31_4)))
 (let (($x1793 (or $x1791 c_31_5)))
 (or $x1793 c_31_6))))))))
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
 (not (and c_31_2 c_31_3)))
(assert
 (not (and c_31_2 c_31_4)))
(assert
 (not (and c_31_2 c_31_5)))
(assert
 (not (and c_31_2 c_31_6)))
(assert
 (not (and c_31_3 c_31_4)))
(assert
 (not (and c_31_3 c_31_5)))
(assert
 (not (and c_31_3 c_31_6)))
(assert
 (not (and c_31_4 c_31_5)))
(assert
 (not (and c_31_4 c_31_6)))
(assert
 (not (and c_31_5 c_31_6)))
(assert
 (let (($x1839 (or false c_32_0)))
 (let (($x1841 (or $x1839 c_32_1)))
 (let (($x1843 (or $x1841 c_32_2)))
 (let (($x1845 (or $x1843 c_32_3)))
 (let (($x1847 (or $x1845 c_32_4)))
 (let (($x1849 (or $x1847 c_32_5)))
 (or $x1849 c_32_6))))))))
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
 (not (and c_32_2 c_32_3)))
(assert
 (not (and c_32_2 c_32_4)))
(assert
 (not (and c_32_2 c_32_5)))
(assert
 (not (and c_32_2 c_32_6)))
(assert
 (not (and c_32_3 c_32_4)))
(assert
 (not (and c_32_3 c_32_5)))
(assert
 (not (and c_32_3 c_32_6)))
(assert
 (not (and c_32_4 c_32_5)))
(assert
 (not (and c_32_4 c_32_6)))
(assert
 (not (and c_32_5 c_32_6)))
(assert
 (let (($x1895 (or false c_33_0)))
 (let (($x1897 (or $x1895 c_33_1)))
 (let (($x1899 (or $x1897 c_33_2)))
 (let (($x1901 (or $x1899 c_33_3)))
 (let (($x1903 (or $x1901 c_33_4)))
 (let (($x1905 (or $x1903 c_33_5)))
 (or $x1905 c_33_6))))))))
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
 (not (and c_33_2 c_33_3)))
(assert
 (not (and c_33_2 c_33_4)))
(assert
 (not (and c_33_2 c_33_5)))
(assert
 (not (and c_33_2 c_33_6)))
(assert
 (not (and c_33_3 c_33_4)))
(assert
 (not (and c_33_3 c_33_5)))
(assert
 (not (and c_33_3 c_33_6)))
(assert
 (not (and c_33_4 c_33_5)))
(assert
 (not (and c_33_4 c_33_6)))
(assert
 (not (and c_33_5 c_33_6)))
(assert
 (let (($x1951 (or false c_34_0)))
 (let (($x1953 (or $x1951 c_34_1)))
 (let (($x1955 (or $x1953 c_34_2)))
 (let (($x1957 (or $x1955 c_34_3)))
 (let (($x1959 (or $x1957 c_34_4)))
 (let (($x1961 (or $x1959 c_34_5)))
 (or $x1961 c_34_6))))))))
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
 (not (and c_34_2 c_34_3)))
(assert
 (not (and c_34_2 c_34_4)))
(assert
 (not (and c_34_2 c_34_5)))
(assert
 (not (and c_34_2 c_34_6)))
(assert
 (not (and c_34_3 c_34_4)))
(assert
 (not (and c_34_3 c_34_5)))
(assert
 (not (and c_34_3 c_34_6)))
(assert
 (not (and c_34_4 c_34_5)))
(assert
 (not (and c_34_4 c_34_6)))
(assert
 (not (and c_34_5 c_34_6)))
(assert
 (let (($x2007 (or false c_35_0)))
 (let (($x2009 (or $x2007 c_35_1)))
 (let (($x2011 (or $x2009 c_35_2)))
 (let (($x2013 (or $x2011 c_35_3)))
 (let (($x2015 (or $x2013 c_35_4)))
 (let (($x2017 (or $x2015 c_35_5)))
 (or $x2017 c_35_6))))))))
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
 (not (and c_35_2 c_35_3)))
(assert
 (not (and c_35_2 c_35_4)))
(assert
 (not (and c_35_2 c_35_5)))
(assert
 (not (and c_35_2 c_35_6)))
(assert
 (not (and c_35_3 c_35_4)))
(assert
 (not (and c_35_3 c_35_5)))
(assert
 (not (and c_35_3 c_35_6)))
(assert
 (not (and c_35_4 c_35_5)))
(assert
 (not (and c_35_4 c_35_6)))
(assert
 (not (and c_35_5 c_35_6)))
(assert
 (let (($x2063 (or false c_36_0)))
 (let (($x2065 (or $x2063 c_36_1)))
 (let (($x2067 (or $x2065 c_36_2)))
 (let (($x2069 (or $x2067 c_36_3)))
 (let (($x2071 (or $x2069 c_36_4)))
 (let (($x2073 (or $x2071 c_36_5)))
 (or $x2073 c_36_6))))))))
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
 (not (and c_36_2 c_36_3)))
(assert
 (not (and c_36_2 c_36_4)))
(assert
 (not (and c_36_2 c_36_5)))
(assert
 (not (and c_36_2 c_36_6)))
(assert
 (not (and c_36_3 c_36_4)))
(assert
 (not (and c_36_3 c_36_5)))
(assert
 (not (and c_36_3 c_36_6)))
(assert
 (not (and c_36_4 c_36_5)))
(assert
 (not (and c_36_4 c_36_6)))
(assert
 (not (and c_36_5 c_36_6)))
(assert
 (let (($x2119 (or false c_37_0)))
 (let (($x2121 (or $x2119 c_37_1)))
 (let (($x2123 (or $x2121 c_37_2)))
 (let (($x2125 (or $x2123 c_37_3)))
 (let (($x2127 (or $x2125 c_37_4)))
 (let (($x2129 (or $x2127 c_37_5)))
 (or $x2129 c_37_6))))))))
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
 (not (and c_37_2 c_37_3)))
(assert
 (not (and c_37_2 c_37_4)))
(assert
 (not (and c_37_2 c_37_5)))
(assert
 (not (and c_37_2 c_37_6)))
(assert
 (not (and c_37_3 c_37_4)))
(assert
 (not (and c_37_3 c_37_5)))
(assert
 (not (and c_37_3 c_37_6)))
(assert
 (not (and c_37_4 c_37_5)))
(assert
 (not (and c_37_4 c_37_6)))
(assert
 (not (and c_37_5 c_37_6)))
(assert
 (let (($x2175 (or false c_38_0)))
 (let (($x2177 (or $x2175 c_38_1)))
 (let (($x2179 (or $x2177 c_38_2)))
 (let (($x2181 (or $x2179 c_38_3)))
 (let (($x2183 (or $x2181 c_38_4)))
 (let (($x2185 (or $x2183 c_38_5)))
 (or $x2185 c_38_6))))))))
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
 (not (and c_38_2 c_38_3)))
(assert
 (not (and c_38_2 c_38_4)))
(assert
 (not (and c_38_2 c_38_5)))
(assert
 (not (and c_38_2 c_38_6)))
(assert
 (not (and c_38_3 c_38_4)))
(assert
 (not (and c_38_3 c_38_5)))
(assert
 (not (and c_38_3 c_38_6)))
(assert
 (not (and c_38_4 c_38_5)))
(assert
 (not (and c_38_4 c_38_6)))
(assert
 (not (and c_38_5 c_38_6)))
(assert
 (let (($x2231 (or false c_39_0)))
 (let (($x2233 (or $x2231 c_39_1)))
 (let (($x2235 (or $x2233 c_39_2)))
 (let (($x2237 (or $x2235 c_39_3)))
 (let (($x2239 (or $x2237 c_39_4)))
 (let (($x2241 (or $x2239 c_39_5)))
 (or $x2241 c_39_6))))))))
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
 (not (and c_39_2 c_39_3)))
(assert
 (not (and c_39_2 c_39_4)))
(assert
 (not (and c_39_2 c_39_5)))
(assert
 (not (and c_39_2 c_39_6)))
(assert
 (not (and c_39_3 c_39_4)))
(assert
 (not (and c_39_3 c_39_5)))
(assert
 (not (and c_39_3 c_39_6)))
(assert
 (not (and c_39_4 c_39_5)))
(assert
 (not (and c_39_4 c_39_6)))
(assert
 (not (and c_39_5 c_39_6)))
(assert
 (let (($x2287 (or false c_40_0)))
 (let (($x2289 (or $x2287 c_40_1)))
 (let (($x2291 (or $x2289 c_40_2)))
 (let (($x2293 (or $x2291 c_40_3)))
 (let (($x2295 (or $x2293 c_40_4)))
 (let (($x2297 (or $x2295 c_40_5)))
 (or $x2297 c_40_6))))))))
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
 (not (and c_40_2 c_40_3)))
(assert
 (not (and c_40_2 c_40_4)))
(assert
 (not (and c_40_2 c_40_5)))
(assert
 (not (and c_40_2 c_40_6)))
(assert
 (not (and c_40_3 c_40_4)))
(assert
 (not (and c_40_3 c_40_5)))
(assert
 (not (and c_40_3 c_40_6)))
(assert
 (not (and c_40_4 c_40_5)))
(assert
 (not (and c_40_4 c_40_6)))
(assert
 (not (and c_40_5 c_40_6)))
(assert
 (let (($x2343 (or false d_0_0)))
 (let (($x2345 (or $x2343 d_0_1)))
 (let (($x2347 (or $x2345 d_0_2)))
 (let (($x2349 (or $x2347 d_0_3)))
 (let (($x2351 (or $x2349 d_0_4)))
 (let (($x2353 (or $x2351 d_0_5)))
 (or $x2353 d_0_6))))))))
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
 (not (and d_0_2 d_0_3)))
(assert
 (not (and d_0_2 d_0_4)))
(assert
 (not (and d_0_2 d_0_5)))
(assert
 (not (and d_0_2 d_0_6)))
(assert
 (not (and d_0_3 d_0_4)))
(assert
 (not (and d_0_3 d_0_5)))
(assert
 (not (and d_0_3 d_0_6)))
(assert
 (not (and d_0_4 d_0_5)))
(assert
 (not (and d_0_4 d_0_6)))
(assert
 (not (and d_0_5 d_0_6)))
(assert
 (let (($x2399 (or false d_1_0)))
 (let (($x2401 (or $x2399 d_1_1)))
 (let (($x2403 (or $x2401 d_1_2)))
 (let (($x2405 (or $x2403 d_1_3)))
 (let (($x2407 (or $x2405 d_1_4)))
 (let (($x2409 (or $x2407 d_1_5)))
 (or $x2409 d_1_6))))))))
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
 (not (and d_1_2 d_1_3)))
(assert
 (not (and d_1_2 d_1_4)))
(assert
 (not (and d_1_2 d_1_5)))
(assert
 (not (and d_1_2 d_1_6)))
(assert
 (not (and d_1_3 d_1_4)))
(assert
 (not (and d_1_3 d_1_5)))
(assert
 (not (and d_1_3 d_1_6)))
(assert
 (not (and d_1_4 d_1_5)))
(assert
 (not (and d_1_4 d_1_6)))
(assert
 (not (and d_1_5 d_1_6)))
(assert
 (let (($x2455 (or false d_2_0)))
 (let (($x2457 (or $x2455 d_2_1)))
 (let (($x2459 (or $x2457 d_2_2)))
 (let (($x2461 (or $x2459 d_2_3)))
 (let (($x2463 (or $x2461 d_2_4)))
 (let (($x2465 (or $x2463 d_2_5)))
 (or $x2465 d_2_6))))))))
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
 (not (and d_2_2 d_2_3)))
(assert
 (not (and d_2_2 d_2_4)))
(assert
 (not (and d_2_2 d_2_5)))
(assert
 (not (and d_2_2 d_2_6)))
(assert
 (not (and d_2_3 d_2_4)))
(assert
 (not (and d_2_3 d_2_5)))
(assert
 (not (and d_2_3 d_2_6)))
(assert
 (not (and d_2_4 d_2_5)))
(assert
 (not (and d_2_4 d_2_6)))
(assert
 (not (and d_2_5 d_2_6)))
(assert
 (let (($x2511 (or false d_3_0)))
 (let (($x2513 (or $x2511 d_3_1)))
 (let (($x2515 (or $x2513 d_3_2)))
 (let (($x2517 (or $x2515 d_3_3)))
 (let (($x2519 (or $x2517 d_3_4)))
 (let (($x2521 (or $x2519 d_3_5)))
 (or $x2521 d_3_6))))))))
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
 (not (and d_3_2 d_3_3)))
(assert
 (not (and d_3_2 d_3_4)))
(assert
 (not (and d_3_2 d_3_5)))
(assert
 (not (and d_3_2 d_3_6)))
(assert
 (not (and d_3_3 d_3_4)))
(assert
 (not (and d_3_3 d_3_5)))
(assert
 (not (and d_3_3 d_3_6)))
(assert
 (not (and d_3_4 d_3_5)))
(assert
 (not (and d_3_4 d_3_6)))
(assert
 (not (and d_3_5 d_3_6)))
(assert
 (let (($x2567 (or false d_4_0)))
 (let (($x2569 (or $x2567 d_4_1)))
 (let (($x2571 (or $x2569 d_4_2)))
 (let (($x2573 (or $x2571 d_4_3)))
 (let (($x2575 (or $x2573 d_4_4)))
 (let (($x2577 (or $x2575 d_4_5)))
 (or $x2577 d_4_6))))))))
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
 (not (and d_4_2 d_4_3)))
(assert
 (not (and d_4_2 d_4_4)))
(assert
 (not (and d_4_2 d_4_5)))
(assert
 (not (and d_4_2 d_4_6)))
(assert
 (not (and d_4_3 d_4_4)))
(assert
 (not (and d_4_3 d_4_5)))
(assert
 (not (and d_4_3 d_4_6)))
(assert
 (not (and d_4_4 d_4_5)))
(assert
 (not (and d_4_4 d_4_6)))
(assert
 (not (and d_4_5 d_4_6)))
(assert
 (let (($x2623 (or false d_5_0)))
 (let (($x2625 (or $x2623 d_5_1)))
 (let (($x2627 (or $x2625 d_5_2)))
 (let (($x2629 (or $x2627 d_5_3)))
 (let (($x2631 (or $x2629 d_5_4)))
 (let (($x2633 (or $x2631 d_5_5)))
 (or $x2633 d_5_6))))))))
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
 (not (and d_5_2 d_5_3)))
(assert
 (not (and d_5_2 d_5_4)))
(assert
 (not (and d_5_2 d_5_5)))
(assert
 (not (and d_5_2 d_5_6)))
(assert
 (not (and d_5_3 d_5_4)))
(assert
 (not (and d_5_3 d_5_5)))
(assert
 (not (and d_5_3 d_5_6)))
(assert
 (not (and d_5_4 d_5_5)))
(assert
 (not (and d_5_4 d_5_6)))
(assert
 (not (and d_5_5 d_5_6)))
(assert
 (let (($x2679 (or false d_6_0)))
 (let (($x2681 (or $x2679 d_6_1)))
 (let (($x2683 (or $x2681 d_6_2)))
 (let (($x2685 (or $x2683 d_6_3)))
 (let (($x2687 (or $x2685 d_6_4)))
 (let (($x2689 (or $x2687 d_6_5)))
 (or $x2689 d_6_6))))))))
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
 (not (and d_6_2 d_6_3)))
(assert
 (not (and d_6_2 d_6_4)))
(assert
 (not (and d_6_2 d_6_5)))
(assert
 (not (and d_6_2 d_6_6)))
(assert
 (not (and d_6_3 d_6_4)))
(assert
 (not (and d_6_3 d_6_5)))
(assert
 (not (and d_6_3 d_6_6)))
(assert
 (not (and d_6_4 d_6_5)))
(assert
 (not (and d_6_4 d_6_6)))
(assert
 (not (and d_6_5 d_6_6)))
(assert
 (let (($x2735 (or false d_7_0)))
 (let (($x2737 (or $x2735 d_7_1)))
 (let (($x2739 (or $x2737 d_7_2)))
 (let (($x2741 (or $x2739 d_7_3)))
 (let (($x2743 (or $x2741 d_7_4)))
 (let (($x2745 (or $x2743 d_7_5)))
 (or $x2745 d_7_6))))))))
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
 (not (and d_7_2 d_7_3)))
(assert
 (not (and d_7_2 d_7_4)))
(assert
 (not (and d_7_2 d_7_5)))
(assert
 (not (and d_7_2 d_7_6)))
(assert
 (not (and d_7_3 d_7_4)))
(assert
 (not (and d_7_3 d_7_5)))
(assert
 (not (and d_7_3 d_7_6)))
(assert
 (not (and d_7_4 d_7_5)))
(assert
 (not (and d_7_4 d_7_6)))
(assert
 (not (and d_7_5 d_7_6)))
(assert
 (let (($x2791 (or false d_8_0)))
 (let (($x2793 (or $x2791 d_8_1)))
 (let (($x2795 (or $x2793 d_8_2)))
 (let (($x2797 (or $x2795 d_8_3)))
 (let (($x2799 (or $x2797 d_8_4)))
 (let (($x2801 (or $x2799 d_8_5)))
 (or $x2801 d_8_6))))))))
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
 (not (and d_8_2 d_8_3)))
(assert
 (not (and d_8_2 d_8_4)))
(assert
 (not (and d_8_2 d_8_5)))
(assert
 (not (and d_8_2 d_8_6)))
(assert
 (not (and d_8_3 d_8_4)))
(assert
 (not (and d_8_3 d_8_5)))
(assert
 (not (and d_8_3 d_8_6)))
(assert
 (not (and d_8_4 d_8_5)))
(assert
 (not (and d_8_4 d_8_6)))
(assert
 (not (and d_8_5 d_8_6)))
(assert
 (let (($x2847 (or false d_9_0)))
 (let (($x2849 (or $x2847 d_9_1)))
 (let (($x2851 (or $x2849 d_9_2)))
 (let (($x2853 (or $x2851 d_9_3)))
 (let (($x2855 (or $x2853 d_9_4)))
 (let (($x2857 (or $x2855 d_9_5)))
 (or $x2857 d_9_6))))))))
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
 (not (and d_9_2 d_9_3)))
(assert
 (not (and d_9_2 d_9_4)))
(assert
 (not (and d_9_2 d_9_5)))
(assert
 (not (and d_9_2 d_9_6)))
(assert
 (not (and d_9_3 d_9_4)))
(assert
 (not (and d_9_3 d_9_5)))
(assert
 (not (and d_9_3 d_9_6)))
(assert
 (not (and d_9_4 d_9_5)))
(assert
 (not (and d_9_4 d_9_6)))
(assert
 (not (and d_9_5 d_9_6)))
(assert
 (let (($x2903 (or false d_10_0)))
 (let (($x2905 (or $x2903 d_10_1)))
 (let (($x2907 (or $x2905 d_10_2)))
 (let (($x2909 (or $x2907 d_10_3)))
 (let (($x2911 (or $x2909 d_10_4)))
 (let (($x2913 (or $x2911 d_10_5)))
 (or $x2913 d_10_6))))))))
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
 (not (and d_10_2 d_10_3)))
(assert
 (not (and d_10_2 d_10_4)))
(assert
 (not (and d_10_2 d_10_5)))
(assert
 (not (and d_10_2 d_10_6)))
(assert
 (not (and d_10_3 d_10_4)))
(assert
 (not (and d_10_3 d_10_5)))
(assert
 (not (and d_10_3 d_10_6)))
(assert
 (not (and d_10_4 d_10_5)))
(assert
 (not (and d_10_4 d_10_6)))
(assert
 (not (and d_10_5 d_10_6)))
(assert
 (let (($x2959 (or false d_11_0)))
 (let (($x2961 (or $x2959 d_11_1)))
 (let (($x2963 (or $x2961 d_11_2)))
 (let (($x2965 (or $x2963 d_11_3)))
 (let (($x2967 (or $x2965 d_11_4)))
 (let (($x2969 (or $x2967 d_11_5)))
 (or $x2969 d_11_6))))))))
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
 (not (and d_11_2 d_11_3)))
(assert
 (not (and d_11_2 d_11_4)))
(assert
 (not (and d_11_2 d_11_5)))
(assert
 (not (and d_11_2 d_11_6)))
(assert
 (not (and d_11_3 d_11_4)))
(assert
 (not (and d_11_3 d_11_5)))
(assert
 (not (and d_11_3 d_11_6)))
(assert
 (not (and d_11_4 d_11_5)))
(assert
 (not (and d_11_4 d_11_6)))
(assert
 (not (and d_11_5 d_11_6)))
(assert
 (let (($x3015 (or false d_12_0)))
 (let (($x3017 (or $x3015 d_12_1)))
 (let (($x3019 (or $x3017 d_12_2)))
 (let (($x3021 (or $x3019 d_12_3)))
 (let (($x3023 (or $x3021 d_12_4)))
 (let (($x3025 (or $x3023 d_12_5)))
 (or $x3025 d_12_6))))))))
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
 (not (and d_12_2 d_12_3)))
(assert
 (not (and d_12_2 d_12_4)))
(assert
 (not (and d_12_2 d_12_5)))
(assert
 (not (and d_12_2 d_12_6)))
(assert
 (not (and d_12_3 d_12_4)))
(assert
 (not (and d_12_3 d_12_5)))
(assert
 (not (and d_12_3 d_12_6)))
(assert
 (not (and d_12_4 d_12_5)))
(assert
 (not (and d_12_4 d_12_6)))
(assert
 (not (and d_12_5 d_12_6)))
(assert
 (let (($x3071 (or false d_13_0)))
 (let (($x3073 (or $x3071 d_13_1)))
 (let (($x3075 (or $x3073 d_13_2)))
 (let (($x3077 (or $x3075 d_13_3)))
 (let (($x3079 (or $x3077 d_13_4)))
 (let (($x3081 (or $x3079 d_13_5)))
 (or $x3081 d_13_6))))))))
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
 (not (and d_13_2 d_13_3)))
(assert
 (not (and d_13_2 d_13_4)))
(assert
 (not (and d_13_2 d_13_5)))
(assert
 (not (and d_13_2 d_13_6)))
(assert
 (not (and d_13_3 d_13_4)))
(assert
 (not (and d_13_3 d_13_5)))
(assert
 (not (and d_13_3 d_13_6)))
(assert
 (not (and d_13_4 d_13_5)))
(assert
 (not (and d_13_4 d_13_6)))
(assert
 (not (and d_13_5 d_13_6)))
(assert
 (let (($x3127 (or false d_14_0)))
 (let (($x3129 (or $x3127 d_14_1)))
 (let (($x3131 (or $x3129 d_14_2)))
 (let (($x3133 (or $x3131 d_14_3)))
 (let (($x3135 (or $x3133 d_14_4)))
 (let (($x3137 (or $x3135 d_14_5)))
 (or $x3137 d_14_6))))))))
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
 (not (and d_14_2 d_14_3)))
(assert
 (not (and d_14_2 d_14_4)))
(assert
 (not (and d_14_2 d_14_5)))
(assert
 (not (and d_14_2 d_14_6)))
(assert
 (not (and d_14_3 d_14_4)))
(assert
 (not (and d_14_3 d_14_5)))
(assert
 (not (and d_14_3 d_14_6)))
(assert
 (not (and d_14_4 d_14_5)))
(assert
 (not (and d_14_4 d_14_6)))
(assert
 (not (and d_14_5 d_14_6)))
(assert
 (let (($x3183 (or false d_15_0)))
 (let (($x3185 (or $x3183 d_15_1)))
 (let (($x3187 (or $x3185 d_15_2)))
 (let (($x3189 (or $x3187 d_15_3)))
 (let (($x3191 (or $x3189 d_15_4)))
 (let (($x3193 (or $x3191 d_15_5)))
 (or $x3193 d_15_6))))))))
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
 (not (and d_15_2 d_15_3)))
(assert
 (not (and d_15_2 d_15_4)))
(assert
 (not (and d_15_2 d_15_5)))
(assert
 (not (and d_15_2 d_15_6)))
(assert
 (not (and d_15_3 d_15_4)))
(assert
 (not (and d_15_3 d_15_5)))
(assert
 (not (and d_15_3 d_15_6)))
(assert
 (not (and d_15_4 d_15_5)))
(assert
 (not (and d_15_4 d_15_6)))
(assert
 (not (and d_15_5 d_15_6)))
(assert
 (let (($x3239 (or false d_16_0)))
 (let (($x3241 (or $x3239 d_16_1)))
 (let (($x3243 (or $x3241 d_16_2)))
 (let (($x3245 (or $x3243 d_16_3)))
 (let (($x3247 (or $x3245 d_16_4)))
 (let (($x3249 (or $x3247 d_16_5)))
 (or $x3249 d_16_6))))))))
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
 (not (and d_16_2 d_16_3)))
(assert
 (not (and d_16_2 d_16_4)))
(assert
 (not (and d_16_2 d_16_5)))
(assert
 (not (and d_16_2 d_16_6)))
(assert
 (not (and d_16_3 d_16_4)))
(assert
 (not (and d_16_3 d_16_5)))
(assert
 (not (and d_16_3 d_16_6)))
(assert
 (not (and d_16_4 d_16_5)))
(assert
 (not (and d_16_4 d_16_6)))
(assert
 (not (and d_16_5 d_16_6)))
(assert
 (let (($x3295 (or false d_17_0)))
 (let (($x3297 (or $x3295 d_17_1)))
 (let (($x3299 (or $x3297 d_17_2)))
 (let (($x3301 (or $x3299 d_17_3)))
 (let (($x3303 (or $x3301 d_17_4)))
 (let (($x3305 (or $x3303 d_17_5)))
 (or $x3305 d_17_6))))))))
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
 (not (and d_17_2 d_17_3)))
(assert
 (not (and d_17_2 d_17_4)))
(assert
 (not (and d_17_2 d_17_5)))
(assert
 (not (and d_17_2 d_17_6)))
(assert
 (not (and d_17_3 d_17_4)))
(assert
 (not (and d_17_3 d_17_5)))
(assert
 (not (and d_17_3 d_17_6)))
(assert
 (not (and d_17_4 d_17_5)))
(assert
 (not (and d_17_4 d_17_6)))
(assert
 (not (and d_17_5 d_17_6)))
(assert
 (let (($x3351 (or false d_18_0)))
 (let (($x3353 (or $x3351 d_18_1)))
 (let (($x3355 (or $x3353 d_18_2)))
 (let (($x3357 (or $x3355 d_18_3)))
 (let (($x3359 (or $x3357 d_18_4)))
 (let (($x3361 (or $x3359 d_18_5)))
 (or $x3361 d_18_6))))))))
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
 (not (and d_18_2 d_18_3)))
(assert
 (not (and d_18_2 d_18_4)))
(assert
 (not (and d_18_2 d_18_5)))
(assert
 (not (and d_18_2 d_18_6)))
(assert
 (not (and d_18_3 d_18_4)))
(assert
 (not (and d_18_3 d_18_5)))
(assert
 (not (and d_18_3 d_18_6)))
(assert
 (not (and d_18_4 d_18_5)))
(assert
 (not (and d_18_4 d_18_6)))
(assert
 (not (and d_18_5 d_18_6)))
(assert
 (let (($x3407 (or false d_19_0)))
 (let (($x3409 (or $x3407 d_19_1)))
 (let (($x3411 (or $x3409 d_19_2)))
 (let (($x3413 (or $x3411 d_19_3)))
 (let (($x3415 (or $x3413 d_19_4)))
 (let (($x3417 (or $x3415 d_19_5)))
 (or $x3417 d_19_6))))))))
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
 (not (and d_19_2 d_19_3)))
(assert
 (not (and d_19_2 d_19_4)))
(assert
 (not (and d_19_2 d_19_5)))
(assert
 (not (and d_19_2 d_19_6)))
(assert
 (not (and d_19_3 d_19_4)))
(assert
 (not (and d_19_3 d_19_5)))
(assert
 (not (and d_19_3 d_19_6)))
(assert
 (not (and d_19_4 d_19_5)))
(assert
 (not (and d_19_4 d_19_6)))
(assert
 (not (and d_19_5 d_19_6)))
(assert
 (let (($x3463 (or false d_20_0)))
 (let (($x3465 (or $x3463 d_20_1)))
 (let (($x3467 (or $x3465 d_20_2)))
 (let (($x3469 (or $x3467 d_20_3)))
 (let (($x3471 (or $x3469 d_20_4)))
 (let (($x3473 (or $x3471 d_20_5)))
 (or $x3473 d_20_6))))))))
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
 (not (and d_20_2 d_20_3)))
(assert
 (not (and d_20_2 d_20_4)))
(assert
 (not (and d_20_2 d_20_5)))
(assert
 (not (and d_20_2 d_20_6)))
(assert
 (not (and d_20_3 d_20_4)))
(assert
 (not (and d_20_3 d_20_5)))
(assert
 (not (and d_20_3 d_20_6)))
(assert
 (not (and d_20_4 d_20_5)))
(assert
 (not (and d_20_4 d_20_6)))
(assert
 (not (and d_20_5 d_20_6)))
(assert
 (let (($x3519 (or false d_21_0)))
 (let (($x3521 (or $x3519 d_21_1)))
 (let (($x3523 (or $x3521 d_21_2)))
 (let (($x3525 (or $x3523 d_21_3)))
 (let (($x3527 (or $x3525 d_21_4)))
 (let (($x3529 (or $x3527 d_21_5)))
 (or $x3529 d_21_6))))))))
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
 (not (and d_21_2 d_21_3)))
(assert
 (not (and d_21_2 d_21_4)))
(assert
 (not (and d_21_2 d_21_5)))
(assert
 (not (and d_21_2 d_21_6)))
(assert
 (not (and d_21_3 d_21_4)))
(assert
 (not (and d_21_3 d_21_5)))
(assert
 (not (and d_21_3 d_21_6)))
(assert
 (not (and d_21_4 d_21_5)))
(assert
 (not (and d_21_4 d_21_6)))
(assert
 (not (and d_21_5 d_21_6)))
(assert
 (let (($x3575 (or false d_22_0)))
 (let (($x3577 (or $x3575 d_22_1)))
 (let (($x3579 (or $x3577 d_22_2)))
 (let (($x3581 (or $x3579 d_22_3)))
 (let (($x3583 (or $x3581 d_22_4)))
 (let (($x3585 (or $x3583 d_22_5)))
 (or $x3585 d_22_6))))))))
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
 (not (and d_22_2 d_22_3)))
(assert
 (not (and d_22_2 d_22_4)))
(assert
 (not (and d_22_2 d_22_5)))
(assert
 (not (and d_22_2 d_22_6)))
(assert
 (not (and d_22_3 d_22_4)))
(assert
 (not (and d_22_3 d_22_5)))
(assert
 (not (and d_22_3 d_22_6)))
(assert
 (not (and d_22_4 d_22_5)))
(assert
 (not (and d_22_4 d_22_6)))
(assert
 (not (and d_22_5 d_22_6)))
(assert
 (let (($x3631 (or false d_23_0)))
 (let (($x3633 (or $x3631 d_23_1)))
 (let (($x3635 (or $x3633 d_23_2)))
 (let (($x3637 (or $x3635 d_23_3)))
 (let (($x3639 (or $x3637 d_23_4)))
 (let (($x3641 (or $x3639 d_23_5)))
 (or $x3641 d_23_6))))))))
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
 (not (and d_23_2 d_23_3)))
(assert
 (not (and d_23_2 d_23_4)))
(assert
 (not (and d_23_2 d_23_5)))
(assert
 (not (and d_23_2 d_23_6)))
(assert
 (not (and d_23_3 d_23_4)))
(assert
 (not (and d_23_3 d_23_5)))
(assert
 (not (and d_23_3 d_23_6)))
(assert
 (not (and d_23_4 d_23_5)))
(assert
 (not (and d_23_4 d_23_6)))
(assert
 (not (and d_23_5 d_23_6)))
(assert
 (let (($x3687 (or false d_24_0)))
 (let (($x3689 (or $x3687 d_24_1)))
 (let (($x3691 (or $x3689 d_24_2)))
 (let (($x3693 (or $x3691 d_24_3)))
 (let (($x3695 (or $x3693 d_24_4)))
 (let (($x3697 (or $x3695 d_24_5)))
 (or $x3697 d_24_6))))))))
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
 (not (and d_24_2 d_24_3)))
(assert
 (not (and d_24_2 d_24_4)))
(assert
 (not (and d_24_2 d_24_5)))
(assert
 (not (and d_24_2 d_24_6)))
(assert
 (not (and d_24_3 d_24_4)))
(assert
 (not (and d_24_3 d_24_5)))
(assert
 (not (and d_24_3 d_24_6)))
(assert
 (not (and d_24_4 d_24_5)))
(assert
 (not (and d_24_4 d_24_6)))
(assert
 (not (and d_24_5 d_24_6)))
(assert
 (let (($x3743 (or false d_25_0)))
 (let (($x3745 (or $x3743 d_25_1)))
 (let (($x3747 (or $x3745 d_25_2)))
 (let (($x3749 (or $x3747 d_25_3)))
 (let (($x3751 (or $x3749 d_25_4)))
 (let (($x3753 (or $x3751 d_25_5)))
 (or $x3753 d_25_6))))))))
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
 (not (and d_25_2 d_25_3)))
(assert
 (not (and d_25_2 d_25_4)))
(assert
 (not (and d_25_2 d_25_5)))
(assert
 (not (and d_25_2 d_25_6)))
(assert
 (not (and d_25_3 d_25_4)))
(assert
 (not (and d_25_3 d_25_5)))
(assert
 (not (and d_25_3 d_25_6)))
(assert
 (not (and d_25_4 d_25_5)))
(assert
 (not (and d_25_4 d_25_6)))
(assert
 (not (and d_25_5 d_25_6)))
(assert
 (let (($x3799 (or false d_26_0)))
 (let (($x3801 (or $x3799 d_26_1)))
 (let (($x3803 (or $x3801 d_26_2)))
 (let (($x3805 (or $x3803 d_26_3)))
 (let (($x3807 (or $x3805 d_26_4)))
 (let (($x3809 (or $x3807 d_26_5)))
 (or $x3809 d_26_6))))))))
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
 (not (and d_26_2 d_26_3)))
(assert
 (not (and d_26_2 d_26_4)))
(assert
 (not (and d_26_2 d_26_5)))
(assert
 (not (and d_26_2 d_26_6)))
(assert
 (not (and d_26_3 d_26_4)))
(assert
 (not (and d_26_3 d_26_5)))
(assert
 (not (and d_26_3 d_26_6)))
(assert
 (not (and d_26_4 d_26_5)))
(assert
 (not (and d_26_4 d_26_6)))
(assert
 (not (and d_26_5 d_26_6)))
(assert
 (let (($x3855 (or false d_27_0)))
 (let (($x3857 (or $x3855 d_27_1)))
 (let (($x3859 (or $x3857 d_27_2)))
 (let (($x3861 (or $x3859 d_27_3)))
 (let (($x3863 (or $x3861 d_27_4)))
 (let (($x3865 (or $x3863 d_27_5)))
 (or $x3865 d_27_6))))))))
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
 (not (and d_27_2 d_27_3)))
(assert
 (not (and d_27_2 d_27_4)))
(assert
 (not (and d_27_2 d_27_5)))
(assert
 (not (and d_27_2 d_27_6)))
(assert
 (not (and d_27_3 d_27_4)))
(assert
 (not (and d_27_3 d_27_5)))
(assert
 (not (and d_27_3 d_27_6)))
(assert
 (not (and d_27_4 d_27_5)))
(assert
 (not (and d_27_4 d_27_6)))
(assert
 (not (and d_27_5 d_27_6)))
(assert
 (let (($x3911 (or false d_28_0)))
 (let (($x3913 (or $x3911 d_28_1)))
 (let (($x3915 (or $x3913 d_28_2)))
 (let (($x3917 (or $x3915 d_28_3)))
 (let (($x3919 (or $x3917 d_28_4)))
 (let (($x3921 (or $x3919 d_28_5)))
 (or $x3921 d_28_6))))))))
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
 (not (and d_28_2 d_28_3)))
(assert
 (not (and d_28_2 d_28_4)))
(assert
 (not (and d_28_2 d_28_5)))
(assert
 (not (and d_28_2 d_28_6)))
(assert
 (not (and d_28_3 d_28_4)))
(assert
 (not (and d_28_3 d_28_5)))
(assert
 (not (and d_28_3 d_28_6)))
(assert
 (not (and d_28_4 d_28_5)))
(assert
 (not (and d_28_4 d_28_6)))
(assert
 (not (and d_28_5 d_28_6)))
(assert
 (let (($x3967 (or false d_29_0)))
 (let (($x3969 (or $x3967 d_29_1)))
 (let (($x3971 (or $x3969 d_29_2)))
 (let (($x3973 (or $x3971 d_29_3)))
 (let (($x3975 (or $x3973 d_29_4)))
 (let (($x3977 (or $x3975 d_29_5)))
 (or $x3977 d_29_6))))))))
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
 (not (and d_29_2 d_29_3)))
(assert
 (not (and d_29_2 d_29_4)))
(assert
 (not (and d_29_2 d_29_5)))
(assert
 (not (and d_29_2 d_29_6)))
(assert
 (not (and d_29_3 d_29_4)))
(assert
 (not (and d_29_3 d_29_5)))
(assert
 (not (and d_29_3 d_29_6)))
(assert
 (not (and d_29_4 d_29_5)))
(assert
 (not (and d_29_4 d_29_6)))
(assert
 (not (and d_29_5 d_29_6)))
(assert
 (let (($x4023 (or false d_30_0)))
 (let (($x4025 (or $x4023 d_30_1)))
 (let (($x4027 (or $x4025 d_30_2)))
 (let (($x4029 (or $x4027 d_30_3)))
 (let (($x4031 (or $x4029 d_30_4)))
 (let (($x4033 (or $x4031 d_30_5)))
 (or $x4033 d_30_6))))))))
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
 (not (and d_30_2 d_30_3)))
(assert
 (not (and d_30_2 d_30_4)))
(assert
 (not (and d_30_2 d_30_5)))
(assert
 (not (and d_30_2 d_30_6)))
(assert
 (not (and d_30_3 d_30_4)))
(assert
 (not (and d_30_3 d_30_5)))
(assert
 (not (and d_30_3 d_30_6)))
(assert
 (not (and d_30_4 d_30_5)))
(assert
 (not (and d_30_4 d_30_6)))
(assert
 (not (and d_30_5 d_30_6)))
(assert
 (let (($x4079 (or false d_31_0)))
 (let (($x4081 (or $x4079 d_31_1)))
 (let (($x4083 (or $x4081 d_31_2)))
 (let (($x4085 (or $x4083 d_31_3)))
 (let (($x4087 (or $x4085 d_31_4)))
 (let (($x4089 (or $x4087 d_31_5)))
 (or $x4089 d_31_6))))))))
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
 (not (and d_31_2 d_31_3)))
(assert
 (not (and d_31_2 d_31_4)))
(assert
 (not (and d_31_2 d_31_5)))
(assert
 (not (and d_31_2 d_31_6)))
(assert
 (not (and d_31_3 d_31_4)))
(assert
 (not (and d_31_3 d_31_5)))
(assert
 (not (and d_31_3 d_31_6)))
(assert
 (not (and d_31_4 d_31_5)))
(assert
 (not (and d_31_4 d_31_6)))
(assert
 (not (and d_31_5 d_31_6)))
(assert
 (let (($x4135 (or false d_32_0)))
 (let (($x4137 (or $x4135 d_32_1)))
 (let (($x4139 (or $x4137 d_32_2)))
 (let (($x4141 (or $x4139 d_32_3)))
 (let (($x4143 (or $x4141 d_32_4)))
 (let (($x4145 (or $x4143 d_32_5)))
 (or $x4145 d_32_6))))))))
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
 (not (and d_32_2 d_32_3)))
(assert
 (not (and d_32_2 d_32_4)))
(assert
 (not (and d_32_2 d_32_5)))
(assert
 (not (and d_32_2 d_32_6)))
(assert
 (not (and d_32_3 d_32_4)))
(assert
 (not (and d_32_3 d_32_5)))
(assert
 (not (and d_32_3 d_32_6)))
(assert
 (not (and d_32_4 d_32_5)))
(assert
 (not (and d_32_4 d_32_6)))
(assert
 (not (and d_32_5 d_32_6)))
(assert
 (let (($x4191 (or false d_33_0)))
 (let (($x4193 (or $x4191 d_33_1)))
 (let (($x4195 (or $x4193 d_33_2)))
 (let (($x4197 (or $x4195 d_33_3)))
 (let (($x4199 (or $x4197 d_33_4)))
 (let (($x4201 (or $x4199 d_33_5)))
 (or $x4201 d_33_6))))))))
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
 (not (and d_33_2 d_33_3)))
(assert
 (not (and d_33_2 d_33_4)))
(assert
 (not (and d_33_2 d_33_5)))
(assert
 (not (and d_33_2 d_33_6)))
(assert
 (not (and d_33_3 d_33_4)))
(assert
 (not (and d_33_3 d_33_5)))
(assert
 (not (and d_33_3 d_33_6)))
(assert
 (not (and d_33_4 d_33_5)))
(assert
 (not (and d_33_4 d_33_6)))
(assert
 (not (and d_33_5 d_33_6)))
(assert
 (let (($x4247 (or false d_34_0)))
 (let (($x4249 (or $x4247 d_34_1)))
 (let (($x4251 (or $x4249 d_34_2)))
 (let (($x4253 (or $x4251 d_34_3)))
 (let (($x4255 (or $x4253 d_34_4)))
 (let (($x4257 (or $x4255 d_34_5)))
 (or $x4257 d_34_6))))))))
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
 (not (and d_34_2 d_34_3)))
(assert
 (not (and d_34_2 d_34_4)))
(assert
 (not (and d_34_2 d_34_5)))
(assert
 (not (and d_34_2 d_34_6)))
(assert
 (not (and d_34_3 d_34_4)))
(assert
 (not (and d_34_3 d_34_5)))
(assert
 (not (and d_34_3 d_34_6)))
(assert
 (not (and d_34_4 d_34_5)))
(assert
 (not (and d_34_4 d_34_6)))
(assert
 (not (and d_34_5 d_34_6)))
(assert
 (let (($x4303 (or false d_35_0)))
 (let (($x4305 (or $x4303 d_35_1)))
 (let (($x4307 (or $x4305 d_35_2)))
 (let (($x4309 (or $x4307 d_35_3)))
 (let (($x4311 (or $x4309 d_35_4)))
 (let (($x4313 (or $x4311 d_35_5)))
 (or $x4313 d_35_6))))))))
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
 (not (and d_35_2 d_35_3)))
(assert
 (not (and d_35_2 d_35_4)))
(assert
 (not (and d_35_2 d_35_5)))
(assert
 (not (and d_35_2 d_35_6)))
(assert
 (not (and d_35_3 d_35_4)))
(assert
 (not (and d_35_3 d_35_5)))
(assert
 (not (and d_35_3 d_35_6)))
(assert
 (not (and d_35_4 d_35_5)))
(assert
 (not (and d_35_4 d_35_6)))
(assert
 (not (and d_35_5 d_35_6)))
(assert
 (let (($x4359 (or false d_36_0)))
 (let (($x4361 (or $x4359 d_36_1)))
 (let (($x4363 (or $x4361 d_36_2)))
 (let (($x4365 (or $x4363 d_36_3)))
 (let (($x4367 (or $x4365 d_36_4)))
 (let (($x4369 (or $x4367 d_36_5)))
 (or $x4369 d_36_6))))))))
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
 (not (and d_36_2 d_36_3)))
(assert
 (not (and d_36_2 d_36_4)))
(assert
 (not (and d_36_2 d_36_5)))
(assert
 (not (and d_36_2 d_36_6)))
(assert
 (not (and d_36_3 d_36_4)))
(assert
 (not (and d_36_3 d_36_5)))
(assert
 (not (and d_36_3 d_36_6)))
(assert
 (not (and d_36_4 d_36_5)))
(assert
 (not (and d_36_4 d_36_6)))
(assert
 (not (and d_36_5 d_36_6)))
(assert
 (let (($x4415 (or false d_37_0)))
 (let (($x4417 (or $x4415 d_37_1)))
 (let (($x4419 (or $x4417 d_37_2)))
 (let (($x4421 (or $x4419 d_37_3)))
 (let (($x4423 (or $x4421 d_37_4)))
 (let (($x4425 (or $x4423 d_37_5)))
 (or $x4425 d_37_6))))))))
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
 (not (and d_37_2 d_37_3)))
(assert
 (not (and d_37_2 d_37_4)))
(assert
 (not (and d_37_2 d_37_5)))
(assert
 (not (and d_37_2 d_37_6)))
(assert
 (not (and d_37_3 d_37_4)))
(assert
 (not (and d_37_3 d_37_5)))
(assert
 (not (and d_37_3 d_37_6)))
(assert
 (not (and d_37_4 d_37_5)))
(assert
 (not (and d_37_4 d_37_6)))
(assert
 (not (and d_37_5 d_37_6)))
(assert
 (let (($x4471 (or false d_38_0)))
 (let (($x4473 (or $x4471 d_38_1)))
 (let (($x4475 (or $x4473 d_38_2)))
 (let (($x4477 (or $x4475 d_38_3)))
 (let (($x4479 (or $x4477 d_38_4)))
 (let (($x4481 (or $x4479 d_38_5)))
 (or $x4481 d_38_6))))))))
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
 (not (and d_38_2 d_38_3)))
(assert
 (not (and d_38_2 d_38_4)))
(assert
 (not (and d_38_2 d_38_5)))
(assert
 (not (and d_38_2 d_38_6)))
(assert
 (not (and d_38_3 d_38_4)))
(assert
 (not (and d_38_3 d_38_5)))
(assert
 (not (and d_38_3 d_38_6)))
(assert
 (not (and d_38_4 d_38_5)))
(assert
 (not (and d_38_4 d_38_6)))
(assert
 (not (and d_38_5 d_38_6)))
(assert
 (let (($x4527 (or false d_39_0)))
 (let (($x4529 (or $x4527 d_39_1)))
 (let (($x4531 (or $x4529 d_39_2)))
 (let (($x4533 (or $x4531 d_39_3)))
 (let (($x4535 (or $x4533 d_39_4)))
 (let (($x4537 (or $x4535 d_39_5)))
 (or $x4537 d_39_6))))))))
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
 (not (and d_39_2 d_39_3)))
(assert
 (not (and d_39_2 d_39_4)))
(assert
 (not (and d_39_2 d_39_5)))
(assert
 (not (and d_39_2 d_39_6)))
(assert
 (not (and d_39_3 d_39_4)))
(assert
 (not (and d_39_3 d_39_5)))
(assert
 (not (and d_39_3 d_39_6)))
(assert
 (not (and d_39_4 d_39_5)))
(assert
 (not (and d_39_4 d_39_6)))
(assert
 (not (and d_39_5 d_39_6)))
(assert
 (let (($x4583 (or false d_40_0)))
 (let (($x4585 (or $x4583 d_40_1)))
 (let (($x4587 (or $x4585 d_40_2)))
 (let (($x4589 (or $x4587 d_40_3)))
 (let (($x4591 (or $x4589 d_40_4)))
 (let (($x4593 (or $x4591 d_40_5)))
 (or $x4593 d_40_6))))))))
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
 (not (and d_40_2 d_40_3)))
(assert
 (not (and d_40_2 d_40_4)))
(assert
 (not (and d_40_2 d_40_5)))
(assert
 (not (and d_40_2 d_40_6)))
(assert
 (not (and d_40_3 d_40_4)))
(assert
 (not (and d_40_3 d_40_5)))
(assert
 (not (and d_40_3 d_40_6)))
(assert
 (not (and d_40_4 d_40_5)))
(assert
 (not (and d_40_4 d_40_6)))
(assert
 (not (and d_40_5 d_40_6)))
(assert
 (let (($x6573 (and c_0_6 in_target_0)))
 (let (($x6571 (and c_0_5 in_target_0)))
 (let (($x6569 (and c_0_4 in_target_0)))
 (let (($x6567 (and c_0_3 in_target_0)))
 (let (($x6565 (and c_0_2 in_target_0)))
 (let (($x6563 (and c_0_1 in_target_0)))
 (let (($x6562 (and c_0_0 in_target_0)))
 (let (($x6574 (or $x6562 $x6563 $x6565 $x6567 $x6569 $x6571 $x6573)))
 (let (($x6560 (not $x6574)))
 (let (($x6561 (and c_0_6 $x6560)))
 (let (($x8453 (not c_4_1)))
 (let (($x5010 (or c_4_2 c_4_3 c_4_4 c_4_5)))
 (let (($x8443 (not $x5010)))
 (let (($x6730 (and c_4_6 in_target_4)))
 (let (($x6728 (and c_4_5 in_target_4)))
 (let (($x6726 (and c_4_4 in_target_4)))
 (let (($x6724 (and c_4_3 in_target_4)))
 (let (($x6722 (and c_4_2 in_target_4)))
 (let (($x6720 (and c_4_1 in_target_4)))
 (let (($x6719 (and c_4_0 in_target_4)))
 (let (($x6731 (or $x6719 $x6720 $x6722 $x6724 $x6726 $x6728 $x6730)))
 (let (($x8452 (and $x6731 $x8443)))
 (let (($x8456 (and $x8452 $x8453)))
 (let (($x8444 (and c_4_1 $x8443)))
 (let (($x8441 (or false $x5010)))
 (let (($x8450 (or $x8441 $x8444)))
 (let (($x8325 (not c_0_1)))
 (let (($x5020 (or c_0_2 c_0_3 c_0_4 c_0_5)))
 (let (($x8323 (not $x5020)))
 (let (($x8326 (and true $x8323)))
 (let (($x8327 (and $x8326 $x8325)))
 (let (($x8328 (and $x8327 $x6560)))
 (let (($x8429 (not (or (and c_4_0 (not in_target_4)) $x6730))))
 (let (($x8434 (and in_region_4 $x8429)))
 (let (($x8458 (and (and $x8434 (and (and $x6574 $x8323) $x8325)) (or $x8450 (and $x8456 (< ghost_2_4 ghost_2_0))))))
 (let (($x8448 (and (and $x8434 (and c_0_1 $x8323)) (or $x8441 (and $x8444 (< ghost_1_4 ghost_1_0))))))
 (let (($x8420 (not c_3_1)))
 (let (($x5000 (or c_3_2 c_3_3 c_3_4 c_3_5)))
 (let (($x8410 (not $x5000)))
 (let (($x6701 (and c_3_6 in_target_3)))
 (let (($x6699 (and c_3_5 in_target_3)))
 (let (($x6697 (and c_3_4 in_target_3)))
 (let (($x6695 (and c_3_3 in_target_3)))
 (let (($x6693 (and c_3_2 in_target_3)))
 (let (($x6691 (and c_3_1 in_target_3)))
 (let (($x6690 (and c_3_0 in_target_3)))
 (let (($x6702 (or $x6690 $x6691 $x6693 $x6695 $x6697 $x6699 $x6701)))
 (let (($x8419 (and $x6702 $x8410)))
 (let (($x8425 (and $x8419 $x8420)))
 (let (($x8411 (and c_3_1 $x8410)))
 (let (($x8408 (or false $x5000)))
 (let (($x8417 (or $x8408 $x8411)))
 (let (($x8396 (not (or (and c_3_0 (not in_target_3)) $x6701))))
 (let (($x8401 (and in_region_3 $x8396)))
 (let (($x8423 (and (and $x8401 (and (and $x6574 $x8323) $x8325)) (or $x8417 (and $x8425 (< ghost_2_3 ghost_2_0))))))
 (let (($x8415 (and (and $x8401 (and c_0_1 $x8323)) (or $x8408 (and $x8411 (< ghost_1_3 ghost_1_0))))))
 (let (($x8387 (not c_2_1)))
 (let (($x4990 (or c_2_2 c_2_3 c_2_4 c_2_5)))
 (let (($x8377 (not $x4990)))
 (let (($x6672 (and c_2_6 in_target_2)))
 (let (($x6670 (and c_2_5 in_target_2)))
 (let (($x6668 (and c_2_4 in_target_2)))
 (let (($x6666 (and c_2_3 in_target_2)))
 (let (($x6664 (and c_2_2 in_target_2)))
 (let (($x6662 (and c_2_1 in_target_2)))
 (let (($x6661 (and c_2_0 in_target_2)))
 (let (($x6673 (or $x6661 $x6662 $x6664 $x6666 $x6668 $x6670 $x6672)))
 (let (($x8386 (and $x6673 $x8377)))
 (let (($x8391 (and $x8386 $x8387)))
 (let (($x8378 (and c_2_1 $x8377)))
 (let (($x8375 (or false $x4990)))
 (let (($x8384 (or $x8375 $x8378)))
 (let (($x8367 (not (or (and c_2_0 (not in_target_2)) $x6672))))
 (let (($x8368 (and in_region_2 $x8367)))
 (let (($x8390 (and (and $x8368 (and (and $x6574 $x8323) $x8325)) (or $x8384 (and $x8391 (< ghost_2_2 ghost_2_0))))))
 (let (($x8382 (and (and $x8368 (and c_0_1 $x8323)) (or $x8375 (and $x8378 (< ghost_1_2 ghost_1_0))))))
 (let (($x8354 (not c_1_1)))
 (let (($x4980 (or c_1_2 c_1_3 c_1_4 c_1_5)))
 (let (($x8342 (not $x4980)))
 (let (($x6642 (and c_1_6 in_target_1)))
 (let (($x6640 (and c_1_5 in_target_1)))
 (let (($x6638 (and c_1_4 in_target_1)))
 (let (($x6636 (and c_1_3 in_target_1)))
 (let (($x6634 (and c_1_2 in_target_1)))
 (let (($x6632 (and c_1_1 in_target_1)))
 (let (($x6631 (and c_1_0 in_target_1)))
 (let (($x6643 (or $x6631 $x6632 $x6634 $x6636 $x6638 $x6640 $x6642)))
 (let (($x8355 (and $x6643 $x8342)))
 (let (($x8353 (and $x8355 $x8354)))
 (let (($x8343 (and c_1_1 $x8342)))
 (let (($x8339 (or false $x4980)))
 (let (($x8349 (or $x8339 $x8343)))
 (let (($x8333 (not (or (and c_1_0 (not in_target_1)) $x6642))))
 (let (($x8332 (and in_region_1 $x8333)))
 (let (($x8359 (and (and $x8332 (and (and $x6574 $x8323) $x8325)) (or $x8349 (and $x8353 (< ghost_2_1 ghost_2_0))))))
 (let (($x8347 (and (and $x8332 (and c_0_1 $x8323)) (or $x8339 (and $x8343 (< ghost_1_1 ghost_1_0))))))
 (let (($x8338 (or false (and (and $x8332 $x5020) (or false (and $x4980 c_1_4))))))
 (let (($x8348 (or $x8338 $x8347)))
 (let (($x8360 (or $x8348 $x8359)))
 (let (($x8365 (or $x8360 (and (and $x8332 $x8328) (or $x8349 $x8353)))))
 (let (($x8374 (or $x8365 (and (and $x8368 $x5020) (or false (and $x4990 c_2_5))))))
 (let (($x8383 (or $x8374 $x8382)))
 (let (($x8393 (or $x8383 $x8390)))
 (let (($x8400 (or $x8393 (and (and $x8368 $x8328) (or $x8384 $x8391)))))
 (let (($x8407 (or $x8400 (and (and $x8401 $x5020) (or false (and $x5000 c_3_2))))))
 (let (($x8416 (or $x8407 $x8415)))
 (let (($x8426 (or $x8416 $x8423)))
 (let (($x8430 (or $x8426 (and (and $x8401 $x8328) (or $x8417 $x8425)))))
 (let (($x8440 (or $x8430 (and (and $x8434 $x5020) (or false (and $x5010 c_4_3))))))
 (let (($x8449 (or $x8440 $x8448)))
 (let (($x8459 (or $x8449 $x8458)))
 (let ((?x9214 (ite c_12_3 1 0)))
 (let ((?x9212 (ite c_11_2 1 0)))
 (let ((?x9210 (ite c_0_5 1 0)))
 (let ((?x9208 (ite c_7_4 1 0)))
 (let ((?x9209 (+ 0 ?x9208)))
 (let ((?x9211 (+ ?x9209 ?x9210)))
 (let ((?x9213 (+ ?x9211 ?x9212)))
 (let ((?x9204 (ite c_12_1 1 0)))
 (let ((?x9183 (ite c_11_1 1 0)))
 (let ((?x9137 (ite c_0_1 1 0)))
 (let ((?x9139 (ite c_7_1 1 0)))
 (let ((?x9201 (+ 0 ?x9139)))
 (let ((?x9202 (+ ?x9201 ?x9137)))
 (let ((?x9203 (+ ?x9202 ?x9183)))
 (let (($x9218 (and (= (to_real (+ ?x9203 ?x9204)) 0.0) (= (to_real (+ ?x9213 ?x9214)) 0.0))))
 (let (($x8919 (and true $x5010)))
 (let (($x8488 (and true in_region_4)))
 (let ((?x9193 (ite c_11_3 1 0)))
 (let ((?x9191 (ite c_10_2 1 0)))
 (let ((?x9189 (ite c_9_5 1 0)))
 (let ((?x9187 (ite c_0_4 1 0)))
 (let ((?x9188 (+ 0 ?x9187)))
 (let ((?x9190 (+ ?x9188 ?x9189)))
 (let ((?x9192 (+ ?x9190 ?x9191)))
 (let ((?x9181 (ite c_10_1 1 0)))
 (let ((?x9160 (ite c_9_1 1 0)))
 (let ((?x9179 (+ 0 ?x9137)))
 (let ((?x9180 (+ ?x9179 ?x9160)))
 (let ((?x9182 (+ ?x9180 ?x9181)))
 (let (($x9197 (and (= (to_real (+ ?x9182 ?x9183)) 0.0) (= (to_real (+ ?x9192 ?x9193)) 0.0))))
 (let (($x8915 (and true $x5000)))
 (let (($x8482 (and true in_region_3)))
 (let ((?x9171 (ite c_0_3 1 0)))
 (let ((?x9169 (ite c_9_2 1 0)))
 (let ((?x9167 (ite c_8_5 1 0)))
 (let ((?x9165 (ite c_6_4 1 0)))
 (let ((?x9166 (+ 0 ?x9165)))
 (let ((?x9168 (+ ?x9166 ?x9167)))
 (let ((?x9170 (+ ?x9168 ?x9169)))
 (let ((?x9158 (ite c_8_1 1 0)))
 (let ((?x9135 (ite c_6_1 1 0)))
 (let ((?x9157 (+ 0 ?x9135)))
 (let ((?x9159 (+ ?x9157 ?x9158)))
 (let ((?x9161 (+ ?x9159 ?x9160)))
 (let (($x9175 (and (= (to_real (+ ?x9161 ?x9137)) 0.0) (= (to_real (+ ?x9170 ?x9171)) 0.0))))
 (let (($x8911 (and true $x4990)))
 (let (($x8476 (and true in_region_2)))
 (let ((?x9149 (ite c_7_3 1 0)))
 (let ((?x9147 (ite c_0_2 1 0)))
 (let ((?x9145 (ite c_6_5 1 0)))
 (let ((?x9143 (ite c_5_4 1 0)))
 (let ((?x9144 (+ 0 ?x9143)))
 (let ((?x9146 (+ ?x9144 ?x9145)))
 (let ((?x9148 (+ ?x9146 ?x9147)))
 (let ((?x9141 (to_real (+ (+ (+ (+ 0 (ite c_5_1 1 0)) ?x9135) ?x9137) ?x9139))))
 (let (($x8907 (and true $x4980)))
 (let (($x8470 (and true in_region_1)))
 (let (($x9155 (and $x8470 (and $x8907 (and (= ?x9141 0.0) (= (to_real (+ ?x9148 ?x9149)) 0.0))))))
 (let ((?x9125 (ite c_4_3 1 0)))
 (let ((?x9123 (ite c_3_2 1 0)))
 (let ((?x9121 (ite c_2_5 1 0)))
 (let ((?x9119 (ite c_1_4 1 0)))
 (let ((?x9120 (+ 0 ?x9119)))
 (let ((?x9122 (+ ?x9120 ?x9121)))
 (let ((?x9124 (+ ?x9122 ?x9123)))
 (let ((?x9114 (ite c_4_1 1 0)))
 (let ((?x9112 (ite c_3_1 1 0)))
 (let ((?x9110 (ite c_2_1 1 0)))
 (let ((?x9108 (ite c_1_1 1 0)))
 (let ((?x9109 (+ 0 ?x9108)))
 (let ((?x9111 (+ ?x9109 ?x9110)))
 (let ((?x9113 (+ ?x9111 ?x9112)))
 (let (($x9129 (and (= (to_real (+ ?x9113 ?x9114)) 0.0) (= (to_real (+ ?x9124 ?x9125)) 0.0))))
 (let (($x8903 (and true $x5020)))
 (let (($x8463 (and true in_region_0)))
 (let (($x8499 (and true in_region_9)))
 (let (($x8641 (and $x8499 in_region_3)))
 (let (($x8498 (and true in_region_8)))
 (let (($x8636 (and $x8498 in_region_2)))
 (let (($x8496 (and true in_region_6)))
 (let (($x8632 (and $x8496 in_region_1)))
 (let (($x8628 (and $x8488 in_region_12)))
 (let (($x8624 (and $x8482 in_region_11)))
 (let (($x8616 (and $x8470 in_region_7)))
 (let (($x8497 (and true in_region_7)))
 (let (($x8604 (and $x8497 in_region_4)))
 (let (($x8494 (and true in_region_5)))
 (let (($x8594 (and $x8494 in_region_1)))
 (let (($x8590 (and $x8488 in_region_11)))
 (let (($x8586 (and $x8482 in_region_10)))
 (let (($x8582 (and $x8476 in_region_9)))
 (let (($x8516 (and true in_region_12)))
 (let (($x8565 (and $x8516 in_region_4)))
 (let (($x8510 (and true in_region_11)))
 (let (($x8561 (and $x8510 in_region_3)))
 (let (($x8548 (and $x8482 in_region_9)))
 (let (($x8544 (and $x8476 in_region_8)))
 (let (($x8540 (and $x8470 in_region_6)))
 (let (($x8504 (and true in_region_10)))
 (let (($x8505 (and $x8504 in_region_3)))
 (let (($x8489 (and $x8488 in_region_7)))
 (let (($x8477 (and $x8476 in_region_6)))
 (let (($x8471 (and $x8470 in_region_5)))
 (let (($x9010 (and $x8641 (and (and true (or c_9_2 c_9_3 c_9_4 c_9_5)) c_3_1))))
 (let (($x9007 (and $x8636 (and (and true (or c_8_2 c_8_3 c_8_4 c_8_5)) c_2_1))))
 (let (($x9002 (and $x8632 (and (and true (or c_6_2 c_6_3 c_6_4 c_6_5)) c_1_1))))
 (let (($x8984 (and $x8604 (and (and true (or c_7_2 c_7_3 c_7_4 c_7_5)) c_4_1))))
 (let (($x8599 (and $x8496 in_region_2)))
 (let (($x8982 (and $x8599 (and (and true (or c_6_2 c_6_3 c_6_4 c_6_5)) c_2_1))))
 (let (($x8978 (and $x8594 (and (and true (or c_5_2 c_5_3 c_5_4 c_5_5)) c_1_1))))
 (let (($x8959 (and $x8565 (and (and true (or c_12_2 c_12_3 c_12_4 c_12_5)) c_4_1))))
 (let (($x8955 (and $x8561 (and (and true (or c_11_2 c_11_3 c_11_4 c_11_5)) c_3_1))))
 (let (($x8556 (and $x8497 in_region_1)))
 (let (($x8952 (and $x8556 (and (and true (or c_7_2 c_7_3 c_7_4 c_7_5)) c_1_1))))
 (let (($x8511 (and $x8510 in_region_4)))
 (let (($x8933 (and $x8511 (and (and true (or c_11_2 c_11_3 c_11_4 c_11_5)) c_4_1))))
 (let (($x8929 (and $x8505 (and (and true (or c_10_2 c_10_3 c_10_4 c_10_5)) c_3_1))))
 (let (($x8495 (and $x8499 in_region_2)))
 (let (($x8925 (and $x8495 (and (and true (or c_9_2 c_9_3 c_9_4 c_9_5)) c_2_1))))
 (let (($x8901 (and $x8641 (and (and true c_9_6) (and c_3_1 (not in_target_3))))))
 (let (($x8898 (and $x8636 (and (and true c_8_6) (and c_2_1 (not in_target_2))))))
 (let (($x8895 (and $x8632 (and (and true c_6_6) (and c_1_1 (not in_target_1))))))
 (let (($x8891 (and $x8628 (and (and true c_4_6) (and c_12_1 (not in_target_12))))))
 (let (($x8888 (and $x8624 (and (and true c_3_6) (and c_11_1 (not in_target_11))))))
 (let (($x8620 (and $x8476 in_region_0)))
 (let (($x8885 (and $x8620 (and (and true c_2_6) (and c_0_1 (not in_target_0))))))
 (let (($x8882 (and $x8616 (and (and true c_1_6) (and c_7_1 (not in_target_7))))))
 (let (($x8608 (and $x8463 in_region_4)))
 (let (($x8879 (and $x8608 (and (and true c_0_6) (and c_4_1 (not in_target_4))))))
 (let (($x8876 (and $x8604 (and (and true c_7_6) (and c_4_1 (not in_target_4))))))
 (let (($x8873 (and $x8599 (and (and true c_6_6) (and c_2_1 (not in_target_2))))))
 (let (($x8870 (and $x8594 (and (and true c_5_6) (and c_1_1 (not in_target_1))))))
 (let (($x8866 (and $x8590 (and (and true c_4_6) (and c_11_1 (not in_target_11))))))
 (let (($x8862 (and $x8586 (and (and true c_3_6) (and c_10_1 (not in_target_10))))))
 (let (($x8859 (and $x8582 (and (and true c_2_6) (and c_9_1 (not in_target_9))))))
 (let (($x8578 (and $x8470 in_region_0)))
 (let (($x8856 (and $x8578 (and (and true c_1_6) (and c_0_1 (not in_target_0))))))
 (let (($x8570 (and $x8463 in_region_3)))
 (let (($x8853 (and $x8570 (and (and true c_0_6) (and c_3_1 (not in_target_3))))))
 (let (($x8850 (and $x8565 (and (and true c_12_6) (and c_4_1 (not in_target_4))))))
 (let (($x8847 (and $x8561 (and (and true c_11_6) (and c_3_1 (not in_target_3))))))
 (let (($x8844 (and $x8556 (and (and true c_7_6) (and c_1_1 (not in_target_1))))))
 (let (($x8552 (and $x8488 in_region_0)))
 (let (($x8841 (and $x8552 (and (and true c_4_6) (and c_0_1 (not in_target_0))))))
 (let (($x8837 (and $x8548 (and (and true c_3_6) (and c_9_1 (not in_target_9))))))
 (let (($x8833 (and $x8544 (and (and true c_2_6) (and c_8_1 (not in_target_8))))))
 (let (($x8830 (and $x8540 (and (and true c_1_6) (and c_6_1 (not in_target_6))))))
 (let (($x8517 (and $x8463 in_region_2)))
 (let (($x8827 (and $x8517 (and (and true c_0_6) (and c_2_1 (not in_target_2))))))
 (let (($x8823 (and $x8511 (and (and true c_11_6) (and c_4_1 (not in_target_4))))))
 (let (($x8819 (and $x8505 (and (and true c_10_6) (and c_3_1 (not in_target_3))))))
 (let (($x8815 (and $x8495 (and (and true c_9_6) (and c_2_1 (not in_target_2))))))
 (let (($x8811 (and $x8489 (and (and true c_4_6) (and c_7_1 (not in_target_7))))))
 (let (($x8483 (and $x8482 in_region_0)))
 (let (($x8807 (and $x8483 (and (and true c_3_6) (and c_0_1 (not in_target_0))))))
 (let (($x8803 (and $x8477 (and (and true c_2_6) (and c_6_1 (not in_target_6))))))
 (let (($x8799 (and $x8471 (and (and true c_1_6) (and c_5_1 (not in_target_5))))))
 (let (($x8465 (and $x8463 in_region_1)))
 (let (($x8795 (and $x8465 (and (and true c_0_6) (and c_1_1 (not in_target_1))))))
 (let (($x7042 (and c_12_5 in_target_12)))
 (let (($x7040 (and c_12_4 in_target_12)))
 (let (($x7038 (and c_12_3 in_target_12)))
 (let (($x7036 (and c_12_2 in_target_12)))
 (let (($x8784 (or $x7036 $x7038 $x7040 $x7042)))
 (let (($x8490 (and true c_4_6)))
 (let (($x6988 (and c_11_5 in_target_11)))
 (let (($x6986 (and c_11_4 in_target_11)))
 (let (($x6984 (and c_11_3 in_target_11)))
 (let (($x6982 (and c_11_2 in_target_11)))
 (let (($x8756 (or $x6982 $x6984 $x6986 $x6988)))
 (let (($x8484 (and true c_3_6)))
 (let (($x6832 (and c_7_5 in_target_7)))
 (let (($x6830 (and c_7_4 in_target_7)))
 (let (($x6828 (and c_7_3 in_target_7)))
 (let (($x6826 (and c_7_2 in_target_7)))
 (let (($x8680 (or $x6826 $x6828 $x6830 $x6832)))
 (let (($x8472 (and true c_1_6)))
 (let (($x6959 (and c_10_5 in_target_10)))
 (let (($x6957 (and c_10_4 in_target_10)))
 (let (($x6955 (and c_10_3 in_target_10)))
 (let (($x6953 (and c_10_2 in_target_10)))
 (let (($x8749 (or $x6953 $x6955 $x6957 $x6959)))
 (let (($x6905 (and c_9_5 in_target_9)))
 (let (($x6903 (and c_9_4 in_target_9)))
 (let (($x6901 (and c_9_3 in_target_9)))
 (let (($x6899 (and c_9_2 in_target_9)))
 (let (($x8721 (or $x6899 $x6901 $x6903 $x6905)))
 (let (($x8478 (and true c_2_6)))
 (let (($x6876 (and c_8_5 in_target_8)))
 (let (($x6874 (and c_8_4 in_target_8)))
 (let (($x6872 (and c_8_3 in_target_8)))
 (let (($x6870 (and c_8_2 in_target_8)))
 (let (($x8714 (or $x6870 $x6872 $x6874 $x6876)))
 (let (($x6798 (and c_6_5 in_target_6)))
 (let (($x6796 (and c_6_4 in_target_6)))
 (let (($x6794 (and c_6_3 in_target_6)))
 (let (($x6792 (and c_6_2 in_target_6)))
 (let (($x8666 (or $x6792 $x6794 $x6796 $x6798)))
 (let (($x6768 (and c_5_5 in_target_5)))
 (let (($x6766 (and c_5_4 in_target_5)))
 (let (($x6764 (and c_5_3 in_target_5)))
 (let (($x6762 (and c_5_2 in_target_5)))
 (let (($x8659 (or $x6762 $x6764 $x6766 $x6768)))
 (let (($x8469 (or false (and $x8465 (and (and true c_0_6) $x6632)))))
 (let (($x8475 (or $x8469 (and $x8471 (and $x8472 (and c_5_1 in_target_5))))))
 (let (($x8481 (or $x8475 (and $x8477 (and $x8478 (and c_6_1 in_target_6))))))
 (let (($x8487 (or $x8481 (and $x8483 (and $x8484 $x6563)))))
 (let (($x8493 (or $x8487 (and $x8489 (and $x8490 (and c_7_1 in_target_7))))))
 (let (($x8503 (or $x8493 (and $x8495 (and (and true c_9_6) $x6662)))))
 (let (($x8509 (or $x8503 (and $x8505 (and (and true c_10_6) $x6691)))))
 (let (($x8515 (or $x8509 (and $x8511 (and (and true c_11_6) $x6720)))))
 (let (($x8539 (or $x8515 (and $x8517 (and (and true c_0_6) $x6662)))))
 (let (($x8543 (or $x8539 (and $x8540 (and $x8472 (and c_6_1 in_target_6))))))
 (let (($x8547 (or $x8543 (and $x8544 (and $x8478 (and c_8_1 in_target_8))))))
 (let (($x8551 (or $x8547 (and $x8548 (and $x8484 (and c_9_1 in_target_9))))))
 (let (($x8555 (or $x8551 (and $x8552 (and $x8490 $x6563)))))
 (let (($x8560 (or $x8555 (and $x8556 (and (and true c_7_6) $x6632)))))
 (let (($x8564 (or $x8560 (and $x8561 (and (and true c_11_6) $x6691)))))
 (let (($x8569 (or $x8564 (and $x8565 (and (and true c_12_6) $x6720)))))
 (let (($x8577 (or $x8569 (and $x8570 (and (and true c_0_6) $x6691)))))
 (let (($x8581 (or $x8577 (and $x8578 (and $x8472 $x6563)))))
 (let (($x8585 (or $x8581 (and $x8582 (and $x8478 (and c_9_1 in_target_9))))))
 (let (($x8589 (or $x8585 (and $x8586 (and $x8484 (and c_10_1 in_target_10))))))
 (let (($x8593 (or $x8589 (and $x8590 (and $x8490 (and c_11_1 in_target_11))))))
 (let (($x8598 (or $x8593 (and $x8594 (and (and true c_5_6) $x6632)))))
 (let (($x8603 (or $x8598 (and $x8599 (and (and true c_6_6) $x6662)))))
 (let (($x8607 (or $x8603 (and $x8604 (and (and true c_7_6) $x6720)))))
 (let (($x8615 (or $x8607 (and $x8608 (and (and true c_0_6) $x6720)))))
 (let (($x8619 (or $x8615 (and $x8616 (and $x8472 (and c_7_1 in_target_7))))))
 (let (($x8623 (or $x8619 (and $x8620 (and $x8478 $x6563)))))
 (let (($x8627 (or $x8623 (and $x8624 (and $x8484 (and c_11_1 in_target_11))))))
 (let (($x8631 (or $x8627 (and $x8628 (and $x8490 (and c_12_1 in_target_12))))))
 (let (($x8635 (or $x8631 (and $x8632 (and (and true c_6_6) $x6632)))))
 (let (($x8640 (or $x8635 (and $x8636 (and (and true c_8_6) $x6662)))))
 (let (($x8644 (or $x8640 (and $x8641 (and (and true c_9_6) $x6691)))))
 (let (($x8650 (or $x8644 (and $x8465 (and (and true c_0_6) (or $x6634 $x6636 $x6638 $x6640))))))
 (let (($x8657 (or $x8650 (and $x8471 (and $x8472 $x8659)))))
 (let (($x8664 (or $x8657 (and $x8477 (and $x8478 $x8666)))))
 (let (($x8671 (or $x8664 (and $x8483 (and $x8484 (or $x6565 $x6567 $x6569 $x6571))))))
 (let (($x8679 (or $x8671 (and $x8489 (and $x8490 $x8680)))))
 (let (($x8685 (or $x8679 (and $x8495 (and (and true c_9_6) (or $x6664 $x6666 $x6668 $x6670))))))
 (let (($x8693 (or $x8685 (and $x8505 (and (and true c_10_6) (or $x6693 $x6695 $x6697 $x6699))))))
 (let (($x8700 (or $x8693 (and $x8511 (and (and true c_11_6) (or $x6722 $x6724 $x6726 $x6728))))))
 (let (($x8703 (or $x8700 (and $x8517 (and (and true c_0_6) (or $x6664 $x6666 $x6668 $x6670))))))
 (let (($x8706 (or $x8703 (and $x8540 (and $x8472 $x8666)))))
 (let (($x8713 (or $x8706 (and $x8544 (and $x8478 $x8714)))))
 (let (($x8719 (or $x8713 (and $x8548 (and $x8484 $x8721)))))
 (let (($x8723 (or $x8719 (and $x8552 (and $x8490 (or $x6565 $x6567 $x6569 $x6571))))))
 (let (($x8726 (or $x8723 (and $x8556 (and (and true c_7_6) (or $x6634 $x6636 $x6638 $x6640))))))
 (let (($x8730 (or $x8726 (and $x8561 (and (and true c_11_6) (or $x6693 $x6695 $x6697 $x6699))))))
 (let (($x8733 (or $x8730 (and $x8565 (and (and true c_12_6) (or $x6722 $x6724 $x6726 $x6728))))))
 (let (($x8736 (or $x8733 (and $x8570 (and (and true c_0_6) (or $x6693 $x6695 $x6697 $x6699))))))
 (let (($x8738 (or $x8736 (and $x8578 (and $x8472 (or $x6565 $x6567 $x6569 $x6571))))))
 (let (($x8741 (or $x8738 (and $x8582 (and $x8478 $x8721)))))
 (let (($x8747 (or $x8741 (and $x8586 (and $x8484 $x8749)))))
 (let (($x8754 (or $x8747 (and $x8590 (and $x8490 $x8756)))))
 (let (($x8758 (or $x8754 (and $x8594 (and (and true c_5_6) (or $x6634 $x6636 $x6638 $x6640))))))
 (let (($x8761 (or $x8758 (and $x8599 (and (and true c_6_6) (or $x6664 $x6666 $x6668 $x6670))))))
 (let (($x8765 (or $x8761 (and $x8604 (and (and true c_7_6) (or $x6722 $x6724 $x6726 $x6728))))))
 (let (($x8768 (or $x8765 (and $x8608 (and (and true c_0_6) (or $x6722 $x6724 $x6726 $x6728))))))
 (let (($x8771 (or $x8768 (and $x8616 (and $x8472 $x8680)))))
 (let (($x8773 (or $x8771 (and $x8620 (and $x8478 (or $x6565 $x6567 $x6569 $x6571))))))
 (let (($x8776 (or $x8773 (and $x8624 (and $x8484 $x8756)))))
 (let (($x8783 (or $x8776 (and $x8628 (and $x8490 $x8784)))))
 (let (($x8786 (or $x8783 (and $x8632 (and (and true c_6_6) (or $x6634 $x6636 $x6638 $x6640))))))
 (let (($x8789 (or $x8786 (and $x8636 (and (and true c_8_6) (or $x6664 $x6666 $x6668 $x6670))))))
 (let (($x8793 (or $x8789 (and $x8641 (and (and true c_9_6) (or $x6693 $x6695 $x6697 $x6699))))))
 (let (($x8797 (or $x8793 $x8795)))
 (let (($x8801 (or $x8797 $x8799)))
 (let (($x8805 (or $x8801 $x8803)))
 (let (($x8809 (or $x8805 $x8807)))
 (let (($x8813 (or $x8809 $x8811)))
 (let (($x8817 (or $x8813 $x8815)))
 (let (($x8821 (or $x8817 $x8819)))
 (let (($x8825 (or $x8821 $x8823)))
 (let (($x8828 (or $x8825 $x8827)))
 (let (($x8831 (or $x8828 $x8830)))
 (let (($x8835 (or $x8831 $x8833)))
 (let (($x8839 (or $x8835 $x8837)))
 (let (($x8842 (or $x8839 $x8841)))
 (let (($x8845 (or $x8842 $x8844)))
 (let (($x8848 (or $x8845 $x8847)))
 (let (($x8851 (or $x8848 $x8850)))
 (let (($x8854 (or $x8851 $x8853)))
 (let (($x8857 (or $x8854 $x8856)))
 (let (($x8860 (or $x8857 $x8859)))
 (let (($x8864 (or $x8860 $x8862)))
 (let (($x8868 (or $x8864 $x8866)))
 (let (($x8871 (or $x8868 $x8870)))
 (let (($x8874 (or $x8871 $x8873)))
 (let (($x8877 (or $x8874 $x8876)))
 (let (($x8880 (or $x8877 $x8879)))
 (let (($x8883 (or $x8880 $x8882)))
 (let (($x8886 (or $x8883 $x8885)))
 (let (($x8889 (or $x8886 $x8888)))
 (let (($x8893 (or $x8889 $x8891)))
 (let (($x8896 (or $x8893 $x8895)))
 (let (($x8899 (or $x8896 $x8898)))
 (let (($x8902 (or $x8899 $x8901)))
 (let (($x8906 (or $x8902 (and $x8465 (and $x8903 c_1_1)))))
 (let (($x8910 (or $x8906 (and $x8471 (and $x8907 c_5_1)))))
 (let (($x8914 (or $x8910 (and $x8477 (and $x8911 c_6_1)))))
 (let (($x8918 (or $x8914 (and $x8483 (and $x8915 c_0_1)))))
 (let (($x8922 (or $x8918 (and $x8489 (and $x8919 c_7_1)))))
 (let (($x8926 (or $x8922 $x8925)))
 (let (($x8930 (or $x8926 $x8929)))
 (let (($x8934 (or $x8930 $x8933)))
 (let (($x8937 (or $x8934 (and $x8517 (and $x8903 c_2_1)))))
 (let (($x8940 (or $x8937 (and $x8540 (and $x8907 c_6_1)))))
 (let (($x8943 (or $x8940 (and $x8544 (and $x8911 c_8_1)))))
 (let (($x8946 (or $x8943 (and $x8548 (and $x8915 c_9_1)))))
 (let (($x8949 (or $x8946 (and $x8552 (and $x8919 c_0_1)))))
 (let (($x8953 (or $x8949 $x8952)))
 (let (($x8956 (or $x8953 $x8955)))
 (let (($x8960 (or $x8956 $x8959)))
 (let (($x8963 (or $x8960 (and $x8570 (and $x8903 c_3_1)))))
 (let (($x8966 (or $x8963 (and $x8578 (and $x8907 c_0_1)))))
 (let (($x8969 (or $x8966 (and $x8582 (and $x8911 c_9_1)))))
 (let (($x8972 (or $x8969 (and $x8586 (and $x8915 c_10_1)))))
 (let (($x8975 (or $x8972 (and $x8590 (and $x8919 c_11_1)))))
 (let (($x8979 (or $x8975 $x8978)))
 (let (($x8983 (or $x8979 $x8982)))
 (let (($x8986 (or $x8983 $x8984)))
 (let (($x8989 (or $x8986 (and $x8608 (and $x8903 c_4_1)))))
 (let (($x8992 (or $x8989 (and $x8616 (and $x8907 c_7_1)))))
 (let (($x8995 (or $x8992 (and $x8620 (and $x8911 c_0_1)))))
 (let (($x8998 (or $x8995 (and $x8624 (and $x8915 c_11_1)))))
 (let (($x9001 (or $x8998 (and $x8628 (and $x8919 c_12_1)))))
 (let (($x9004 (or $x9001 $x9002)))
 (let (($x9008 (or $x9004 $x9007)))
 (let (($x9011 (or $x9008 $x9010)))
 (let (($x9014 (or $x9011 (and $x8465 (and (and true c_0_6) $x6631)))))
 (let (($x9017 (or $x9014 (and $x8471 (and $x8472 (and c_5_0 in_target_5))))))
 (let (($x9020 (or $x9017 (and $x8477 (and $x8478 (and c_6_0 in_target_6))))))
 (let (($x9023 (or $x9020 (and $x8483 (and $x8484 $x6562)))))
 (let (($x9026 (or $x9023 (and $x8489 (and $x8490 (and c_7_0 in_target_7))))))
 (let (($x9029 (or $x9026 (and $x8495 (and (and true c_9_6) $x6661)))))
 (let (($x9032 (or $x9029 (and $x8505 (and (and true c_10_6) $x6690)))))
 (let (($x9035 (or $x9032 (and $x8511 (and (and true c_11_6) $x6719)))))
 (let (($x9038 (or $x9035 (and $x8517 (and (and true c_0_6) $x6661)))))
 (let (($x9041 (or $x9038 (and $x8540 (and $x8472 (and c_6_0 in_target_6))))))
 (let (($x9044 (or $x9041 (and $x8544 (and $x8478 (and c_8_0 in_target_8))))))
 (let (($x9047 (or $x9044 (and $x8548 (and $x8484 (and c_9_0 in_target_9))))))
 (let (($x9050 (or $x9047 (and $x8552 (and $x8490 $x6562)))))
 (let (($x9053 (or $x9050 (and $x8556 (and (and true c_7_6) $x6631)))))
 (let (($x9056 (or $x9053 (and $x8561 (and (and true c_11_6) $x6690)))))
 (let (($x9059 (or $x9056 (and $x8565 (and (and true c_12_6) $x6719)))))
 (let (($x9062 (or $x9059 (and $x8570 (and (and true c_0_6) $x6690)))))
 (let (($x9065 (or $x9062 (and $x8578 (and $x8472 $x6562)))))
 (let (($x9068 (or $x9065 (and $x8582 (and $x8478 (and c_9_0 in_target_9))))))
 (let (($x9071 (or $x9068 (and $x8586 (and $x8484 (and c_10_0 in_target_10))))))
 (let (($x9074 (or $x9071 (and $x8590 (and $x8490 (and c_11_0 in_target_11))))))
 (let (($x9077 (or $x9074 (and $x8594 (and (and true c_5_6) $x6631)))))
 (let (($x9080 (or $x9077 (and $x8599 (and (and true c_6_6) $x6661)))))
 (let (($x9083 (or $x9080 (and $x8604 (and (and true c_7_6) $x6719)))))
 (let (($x9086 (or $x9083 (and $x8608 (and (and true c_0_6) $x6719)))))
 (let (($x9089 (or $x9086 (and $x8616 (and $x8472 (and c_7_0 in_target_7))))))
 (let (($x9092 (or $x9089 (and $x8620 (and $x8478 $x6562)))))
 (let (($x9095 (or $x9092 (and $x8624 (and $x8484 (and c_11_0 in_target_11))))))
 (let (($x9098 (or $x9095 (and $x8628 (and $x8490 (and c_12_0 in_target_12))))))
 (let (($x9101 (or $x9098 (and $x8632 (and (and true c_6_6) $x6631)))))
 (let (($x9104 (or $x9101 (and $x8636 (and (and true c_8_6) $x6661)))))
 (let (($x9107 (or $x9104 (and $x8641 (and (and true c_9_6) $x6690)))))
 (let (($x9132 (or $x9107 (and $x8463 (and $x8903 $x9129)))))
 (let (($x9156 (or $x9132 $x9155)))
 (let (($x9178 (or $x9156 (and $x8476 (and $x8911 $x9175)))))
 (let (($x9200 (or $x9178 (and $x8482 (and $x8915 $x9197)))))
 (let (($x9224 (not (or (and c_0_0 (not in_target_0)) $x6573))))
 (let (($x8303 (not c_40_6)))
 (let (($x8317 (or (and c_40_0 in_target_40) (and c_40_1 in_target_40) (and c_40_2 in_target_40) (and c_40_3 in_target_40) (and c_40_4 in_target_40) (and c_40_5 in_target_40) (and c_40_6 in_target_40))))
 (let (($x8273 (= ghost_2_24 1)))
 (let (($x8287 (and c_40_6 $x8273)))
 (let (($x8249 (not c_39_6)))
 (let (($x8263 (or (and c_39_0 in_target_39) (and c_39_1 in_target_39) (and c_39_2 in_target_39) (and c_39_3 in_target_39) (and c_39_4 in_target_39) (and c_39_5 in_target_39) (and c_39_6 in_target_39))))
 (let (($x8250 (and $x8263 $x8249)))
 (let (($x8283 (and c_39_6 $x8273)))
 (let (($x7031 (not c_12_6)))
 (let (($x7034 (and c_12_1 in_target_12)))
 (let (($x7033 (and c_12_0 in_target_12)))
 (let (($x7045 (or $x7033 $x7034 $x7036 $x7038 $x7040 $x7042 (and c_12_6 in_target_12))))
 (let (($x7032 (and $x7045 $x7031)))
 (let (($x8279 (and c_12_6 $x8273)))
 (let (($x7877 (not c_31_6)))
 (let (($x7891 (or (and c_31_0 in_target_31) (and c_31_1 in_target_31) (and c_31_2 in_target_31) (and c_31_3 in_target_31) (and c_31_4 in_target_31) (and c_31_5 in_target_31) (and c_31_6 in_target_31))))
 (let (($x7878 (and $x7891 $x7877)))
 (let (($x8275 (or (or false (and c_31_6 $x8273)) (and $x7878 (= ghost_2_31 (- ghost_2_24 1))))))
 (let (($x8282 (or (or $x8275 $x8279) (and $x7032 (= ghost_2_12 (- ghost_2_24 1))))))
 (let (($x8290 (or (or $x8282 $x8283) (and $x8250 (= ghost_2_39 (- ghost_2_24 1))))))
 (let (($x8307 (or (or $x8290 $x8287) (and (and $x8317 $x8303) (= ghost_2_40 (- ghost_2_24 1))))))
 (let (($x8320 (>= ghost_2_24 1)))
 (let (($x7559 (not c_24_6)))
 (let (($x7573 (or (and c_24_0 in_target_24) (and c_24_1 in_target_24) (and c_24_2 in_target_24) (and c_24_3 in_target_24) (and c_24_4 in_target_24) (and c_24_5 in_target_24) (and c_24_6 in_target_24))))
 (let (($x7560 (and $x7573 $x7559)))
 (let (($x8321 (and (=> (and $x7573 c_24_6) (= ghost_2_24 0)) (=> $x7560 (and $x8320 $x8307)))))
 (let (($x8218 (= ghost_2_23 1)))
 (let (($x8232 (and c_39_6 $x8218)))
 (let (($x8195 (not c_38_6)))
 (let (($x8209 (or (and c_38_0 in_target_38) (and c_38_1 in_target_38) (and c_38_2 in_target_38) (and c_38_3 in_target_38) (and c_38_4 in_target_38) (and c_38_5 in_target_38) (and c_38_6 in_target_38))))
 (let (($x8196 (and $x8209 $x8195)))
 (let (($x8229 (and c_38_6 $x8218)))
 (let (($x6977 (not c_11_6)))
 (let (($x6980 (and c_11_1 in_target_11)))
 (let (($x6979 (and c_11_0 in_target_11)))
 (let (($x6991 (or $x6979 $x6980 $x6982 $x6984 $x6986 $x6988 (and c_11_6 in_target_11))))
 (let (($x6978 (and $x6991 $x6977)))
 (let (($x8225 (and c_11_6 $x8218)))
 (let (($x8223 (or (or false (and c_12_6 $x8218)) (and $x7032 (= ghost_2_12 (- ghost_2_23 1))))))
 (let (($x8228 (or (or $x8223 $x8225) (and $x6978 (= ghost_2_11 (- ghost_2_23 1))))))
 (let (($x8236 (or (or $x8228 $x8229) (and $x8196 (= ghost_2_38 (- ghost_2_23 1))))))
 (let (($x8253 (or (or $x8236 $x8232) (and $x8250 (= ghost_2_39 (- ghost_2_23 1))))))
 (let (($x8266 (>= ghost_2_23 1)))
 (let (($x7505 (not c_23_6)))
 (let (($x7519 (or (and c_23_0 in_target_23) (and c_23_1 in_target_23) (and c_23_2 in_target_23) (and c_23_3 in_target_23) (and c_23_4 in_target_23) (and c_23_5 in_target_23) (and c_23_6 in_target_23))))
 (let (($x7506 (and $x7519 $x7505)))
 (let (($x8265 (and (=> (and $x7519 c_23_6) (= ghost_2_23 0)) (=> $x7506 (and $x8266 $x8253)))))
 (let (($x8162 (= ghost_2_22 1)))
 (let (($x8181 (and c_38_6 $x8162)))
 (let (($x8141 (not c_37_6)))
 (let (($x8155 (or (and c_37_0 in_target_37) (and c_37_1 in_target_37) (and c_37_2 in_target_37) (and c_37_3 in_target_37) (and c_37_4 in_target_37) (and c_37_5 in_target_37) (and c_37_6 in_target_37))))
 (let (($x8142 (and $x8155 $x8141)))
 (let (($x8173 (and c_37_6 $x8162)))
 (let (($x6948 (not c_10_6)))
 (let (($x6951 (and c_10_1 in_target_10)))
 (let (($x6950 (and c_10_0 in_target_10)))
 (let (($x6962 (or $x6950 $x6951 $x6953 $x6955 $x6957 $x6959 (and c_10_6 in_target_10))))
 (let (($x6949 (and $x6962 $x6948)))
 (let (($x8171 (and c_10_6 $x8162)))
 (let (($x8169 (or (or false (and c_11_6 $x8162)) (and $x6978 (= ghost_2_11 (- ghost_2_22 1))))))
 (let (($x8174 (or (or $x8169 $x8171) (and $x6949 (= ghost_2_10 (- ghost_2_22 1))))))
 (let (($x8180 (or (or $x8174 $x8173) (and $x8142 (= ghost_2_37 (- ghost_2_22 1))))))
 (let (($x8203 (or (or $x8180 $x8181) (and $x8196 (= ghost_2_38 (- ghost_2_22 1))))))
 (let (($x8212 (>= ghost_2_22 1)))
 (let (($x7451 (not c_22_6)))
 (let (($x7465 (or (and c_22_0 in_target_22) (and c_22_1 in_target_22) (and c_22_2 in_target_22) (and c_22_3 in_target_22) (and c_22_4 in_target_22) (and c_22_5 in_target_22) (and c_22_6 in_target_22))))
 (let (($x7452 (and $x7465 $x7451)))
 (let (($x8211 (and (=> (and $x7465 c_22_6) (= ghost_2_22 0)) (=> $x7452 (and $x8212 $x8203)))))
 (let (($x8084 (= ghost_2_21 1)))
 (let (($x8124 (and c_37_6 $x8084)))
 (let (($x8112 (not c_36_6)))
 (let (($x8126 (or (and c_36_0 in_target_36) (and c_36_1 in_target_36) (and c_36_2 in_target_36) (and c_36_3 in_target_36) (and c_36_4 in_target_36) (and c_36_5 in_target_36) (and c_36_6 in_target_36))))
 (let (($x8096 (and c_36_6 $x8084)))
 (let (($x8058 (not c_35_6)))
 (let (($x8072 (or (and c_35_0 in_target_35) (and c_35_1 in_target_35) (and c_35_2 in_target_35) (and c_35_3 in_target_35) (and c_35_4 in_target_35) (and c_35_5 in_target_35) (and c_35_6 in_target_35))))
 (let (($x8059 (and $x8072 $x8058)))
 (let (($x8093 (and c_35_6 $x8084)))
 (let (($x8089 (or (or false (and c_10_6 $x8084)) (and $x6949 (= ghost_2_10 (- ghost_2_21 1))))))
 (let (($x8095 (or (or $x8089 $x8093) (and $x8059 (= ghost_2_35 (- ghost_2_21 1))))))
 (let (($x8116 (or (or $x8095 $x8096) (and (and $x8126 $x8112) (= ghost_2_36 (- ghost_2_21 1))))))
 (let (($x8153 (or (or $x8116 $x8124) (and $x8142 (= ghost_2_37 (- ghost_2_21 1))))))
 (let (($x8157 (>= ghost_2_21 1)))
 (let (($x7422 (not c_21_6)))
 (let (($x7436 (or (and c_21_0 in_target_21) (and c_21_1 in_target_21) (and c_21_2 in_target_21) (and c_21_3 in_target_21) (and c_21_4 in_target_21) (and c_21_5 in_target_21) (and c_21_6 in_target_21))))
 (let (($x7423 (and $x7436 $x7422)))
 (let (($x8161 (and (=> (and $x7436 c_21_6) (= ghost_2_21 0)) (=> $x7423 (and $x8157 $x8153)))))
 (let (($x8028 (= ghost_2_20 1)))
 (let (($x8070 (and c_10_6 $x8028)))
 (let (($x8042 (and c_35_6 $x8028)))
 (let (($x8004 (not c_34_6)))
 (let (($x8018 (or (and c_34_0 in_target_34) (and c_34_1 in_target_34) (and c_34_2 in_target_34) (and c_34_3 in_target_34) (and c_34_4 in_target_34) (and c_34_5 in_target_34) (and c_34_6 in_target_34))))
 (let (($x8005 (and $x8018 $x8004)))
 (let (($x8036 (and c_34_6 $x8028)))
 (let (($x6894 (not c_9_6)))
 (let (($x6897 (and c_9_1 in_target_9)))
 (let (($x6896 (and c_9_0 in_target_9)))
 (let (($x6908 (or $x6896 $x6897 $x6899 $x6901 $x6903 $x6905 (and c_9_6 in_target_9))))
 (let (($x6895 (and $x6908 $x6894)))
 (let (($x8035 (or (or false (and c_9_6 $x8028)) (and $x6895 (= ghost_2_9 (- ghost_2_20 1))))))
 (let (($x8044 (or (or $x8035 $x8036) (and $x8005 (= ghost_2_34 (- ghost_2_20 1))))))
 (let (($x8068 (or (or $x8044 $x8042) (and $x8059 (= ghost_2_35 (- ghost_2_20 1))))))
 (let (($x8076 (or (or $x8068 $x8070) (and $x6949 (= ghost_2_10 (- ghost_2_20 1))))))
 (let (($x8081 (>= ghost_2_20 1)))
 (let (($x7368 (not c_20_6)))
 (let (($x7382 (or (and c_20_0 in_target_20) (and c_20_1 in_target_20) (and c_20_2 in_target_20) (and c_20_3 in_target_20) (and c_20_4 in_target_20) (and c_20_5 in_target_20) (and c_20_6 in_target_20))))
 (let (($x7369 (and $x7382 $x7368)))
 (let (($x8077 (and (=> (and $x7382 c_20_6) (= ghost_2_20 0)) (=> $x7369 (and $x8081 $x8076)))))
 (let (($x7976 (= ghost_2_19 1)))
 (let (($x8008 (and c_9_6 $x7976)))
 (let (($x7991 (and c_34_6 $x7976)))
 (let (($x7950 (not c_33_6)))
 (let (($x7964 (or (and c_33_0 in_target_33) (and c_33_1 in_target_33) (and c_33_2 in_target_33) (and c_33_3 in_target_33) (and c_33_4 in_target_33) (and c_33_5 in_target_33) (and c_33_6 in_target_33))))
 (let (($x7951 (and $x7964 $x7950)))
 (let (($x7984 (and c_33_6 $x7976)))
 (let (($x6865 (not c_8_6)))
 (let (($x6868 (and c_8_1 in_target_8)))
 (let (($x6867 (and c_8_0 in_target_8)))
 (let (($x6879 (or $x6867 $x6868 $x6870 $x6872 $x6874 $x6876 (and c_8_6 in_target_8))))
 (let (($x6866 (and $x6879 $x6865)))
 (let (($x7981 (or (or false (and c_8_6 $x7976)) (and $x6866 (= ghost_2_8 (- ghost_2_19 1))))))
 (let (($x7990 (or (or $x7981 $x7984) (and $x7951 (= ghost_2_33 (- ghost_2_19 1))))))
 (let (($x8016 (or (or $x7990 $x7991) (and $x8005 (= ghost_2_34 (- ghost_2_19 1))))))
 (let (($x8029 (>= ghost_2_19 1)))
 (let (($x8023 (and $x8029 (or (or $x8016 $x8008) (and $x6895 (= ghost_2_9 (- ghost_2_19 1)))))))
 (let (($x7314 (not c_19_6)))
 (let (($x7328 (or (and c_19_0 in_target_19) (and c_19_1 in_target_19) (and c_19_2 in_target_19) (and c_19_3 in_target_19) (and c_19_4 in_target_19) (and c_19_5 in_target_19) (and c_19_6 in_target_19))))
 (let (($x7315 (and $x7328 $x7314)))
 (let (($x7898 (= ghost_2_18 1)))
 (let (($x7956 (and c_8_6 $x7898)))
 (let (($x7927 (and c_33_6 $x7898)))
 (let (($x7921 (not c_32_6)))
 (let (($x7935 (or (and c_32_0 in_target_32) (and c_32_1 in_target_32) (and c_32_2 in_target_32) (and c_32_3 in_target_32) (and c_32_4 in_target_32) (and c_32_5 in_target_32) (and c_32_6 in_target_32))))
 (let (($x7903 (and c_32_6 $x7898)))
 (let (($x7813 (not c_30_6)))
 (let (($x7827 (or (and c_30_0 in_target_30) (and c_30_1 in_target_30) (and c_30_2 in_target_30) (and c_30_3 in_target_30) (and c_30_4 in_target_30) (and c_30_5 in_target_30) (and c_30_6 in_target_30))))
 (let (($x7814 (and $x7827 $x7813)))
 (let (($x7907 (or (or false (and c_30_6 $x7898)) (and $x7814 (= ghost_2_30 (- ghost_2_18 1))))))
 (let (($x7929 (or (or $x7907 $x7903) (and (and $x7935 $x7921) (= ghost_2_32 (- ghost_2_18 1))))))
 (let (($x7954 (or (or $x7929 $x7927) (and $x7951 (= ghost_2_33 (- ghost_2_18 1))))))
 (let (($x7971 (>= ghost_2_18 1)))
 (let (($x7972 (and $x7971 (or (or $x7954 $x7956) (and $x6866 (= ghost_2_8 (- ghost_2_18 1)))))))
 (let (($x7285 (not c_18_6)))
 (let (($x7299 (or (and c_18_0 in_target_18) (and c_18_1 in_target_18) (and c_18_2 in_target_18) (and c_18_3 in_target_18) (and c_18_4 in_target_18) (and c_18_5 in_target_18) (and c_18_6 in_target_18))))
 (let (($x7286 (and $x7299 $x7285)))
 (let (($x7841 (= ghost_2_17 1)))
 (let (($x7862 (and c_31_6 $x7841)))
 (let (($x7859 (and c_12_6 $x7841)))
 (let (($x6821 (not c_7_6)))
 (let (($x6824 (and c_7_1 in_target_7)))
 (let (($x6823 (and c_7_0 in_target_7)))
 (let (($x6835 (or $x6823 $x6824 $x6826 $x6828 $x6830 $x6832 (and c_7_6 in_target_7))))
 (let (($x6822 (and $x6835 $x6821)))
 (let (($x7850 (and c_7_6 $x7841)))
 (let (($x7769 (not c_29_6)))
 (let (($x7783 (or (and c_29_0 in_target_29) (and c_29_1 in_target_29) (and c_29_2 in_target_29) (and c_29_3 in_target_29) (and c_29_4 in_target_29) (and c_29_5 in_target_29) (and c_29_6 in_target_29))))
 (let (($x7770 (and $x7783 $x7769)))
 (let (($x7852 (or (or false (and c_29_6 $x7841)) (and $x7770 (= ghost_2_29 (- ghost_2_17 1))))))
 (let (($x7858 (or (or $x7852 $x7850) (and $x6822 (= ghost_2_7 (- ghost_2_17 1))))))
 (let (($x7861 (or (or $x7858 $x7859) (and $x7032 (= ghost_2_12 (- ghost_2_17 1))))))
 (let (($x7889 (or (or $x7861 $x7862) (and $x7878 (= ghost_2_31 (- ghost_2_17 1))))))
 (let (($x7896 (>= ghost_2_17 1)))
 (let (($x7241 (not c_17_6)))
 (let (($x7255 (or (and c_17_0 in_target_17) (and c_17_1 in_target_17) (and c_17_2 in_target_17) (and c_17_3 in_target_17) (and c_17_4 in_target_17) (and c_17_5 in_target_17) (and c_17_6 in_target_17))))
 (let (($x7242 (and $x7255 $x7241)))
 (let (($x7893 (and (=> (and $x7255 c_17_6) (= ghost_2_17 0)) (=> $x7242 (and $x7896 $x7889)))))
 (let (($x6787 (not c_6_6)))
 (let (($x6790 (and c_6_1 in_target_6)))
 (let (($x6789 (and c_6_0 in_target_6)))
 (let (($x6801 (or $x6789 $x6790 $x6792 $x6794 $x6796 $x6798 (and c_6_6 in_target_6))))
 (let (($x6788 (and $x6801 $x6787)))
 (let (($x7790 (= ghost_2_16 1)))
 (let (($x7830 (and c_6_6 $x7790)))
 (let (($x7821 (and c_8_6 $x7790)))
 (let (($x7795 (and c_30_6 $x7790)))
 (let (($x7705 (not c_28_6)))
 (let (($x7719 (or (and c_28_0 in_target_28) (and c_28_1 in_target_28) (and c_28_2 in_target_28) (and c_28_3 in_target_28) (and c_28_4 in_target_28) (and c_28_5 in_target_28) (and c_28_6 in_target_28))))
 (let (($x7706 (and $x7719 $x7705)))
 (let (($x7798 (or (or false (and c_28_6 $x7790)) (and $x7706 (= ghost_2_28 (- ghost_2_16 1))))))
 (let (($x7817 (or (or $x7798 $x7795) (and $x7814 (= ghost_2_30 (- ghost_2_16 1))))))
 (let (($x7832 (or (or $x7817 $x7821) (and $x6866 (= ghost_2_8 (- ghost_2_16 1))))))
 (let (($x7842 (>= ghost_2_16 1)))
 (let (($x7836 (and $x7842 (or (or $x7832 $x7830) (and $x6788 (= ghost_2_6 (- ghost_2_16 1)))))))
 (let (($x7177 (not c_16_6)))
 (let (($x7191 (or (and c_16_0 in_target_16) (and c_16_1 in_target_16) (and c_16_2 in_target_16) (and c_16_3 in_target_16) (and c_16_4 in_target_16) (and c_16_5 in_target_16) (and c_16_6 in_target_16))))
 (let (($x7178 (and $x7191 $x7177)))
 (let (($x7736 (= ghost_2_15 1)))
 (let (($x7756 (and c_29_6 $x7736)))
 (let (($x7749 (and c_7_6 $x7736)))
 (let (($x6757 (not c_5_6)))
 (let (($x6760 (and c_5_1 in_target_5)))
 (let (($x6759 (and c_5_0 in_target_5)))
 (let (($x6771 (or $x6759 $x6760 $x6762 $x6764 $x6766 $x6768 (and c_5_6 in_target_5))))
 (let (($x6758 (and $x6771 $x6757)))
 (let (($x7741 (and c_5_6 $x7736)))
 (let (($x7661 (not c_27_6)))
 (let (($x7675 (or (and c_27_0 in_target_27) (and c_27_1 in_target_27) (and c_27_2 in_target_27) (and c_27_3 in_target_27) (and c_27_4 in_target_27) (and c_27_5 in_target_27) (and c_27_6 in_target_27))))
 (let (($x7662 (and $x7675 $x7661)))
 (let (($x7744 (or (or false (and c_27_6 $x7736)) (and $x7662 (= ghost_2_27 (- ghost_2_15 1))))))
 (let (($x7750 (or (or $x7744 $x7741) (and $x6758 (= ghost_2_5 (- ghost_2_15 1))))))
 (let (($x7755 (or (or $x7750 $x7749) (and $x6822 (= ghost_2_7 (- ghost_2_15 1))))))
 (let (($x7775 (or (or $x7755 $x7756) (and $x7770 (= ghost_2_29 (- ghost_2_15 1))))))
 (let (($x7785 (>= ghost_2_15 1)))
 (let (($x7133 (not c_15_6)))
 (let (($x7147 (or (and c_15_0 in_target_15) (and c_15_1 in_target_15) (and c_15_2 in_target_15) (and c_15_3 in_target_15) (and c_15_4 in_target_15) (and c_15_5 in_target_15) (and c_15_6 in_target_15))))
 (let (($x7134 (and $x7147 $x7133)))
 (let (($x7788 (and (=> (and $x7147 c_15_6) (= ghost_2_15 0)) (=> $x7134 (and $x7785 $x7775)))))
 (let (($x7684 (= ghost_2_14 1)))
 (let (($x7725 (and c_5_6 $x7684)))
 (let (($x7717 (and c_6_6 $x7684)))
 (let (($x7691 (and c_28_6 $x7684)))
 (let (($x7627 (not c_26_6)))
 (let (($x7641 (or (and c_26_0 in_target_26) (and c_26_1 in_target_26) (and c_26_2 in_target_26) (and c_26_3 in_target_26) (and c_26_4 in_target_26) (and c_26_5 in_target_26) (and c_26_6 in_target_26))))
 (let (($x7628 (and $x7641 $x7627)))
 (let (($x7689 (or (or false (and c_26_6 $x7684)) (and $x7628 (= ghost_2_26 (- ghost_2_14 1))))))
 (let (($x7709 (or (or $x7689 $x7691) (and $x7706 (= ghost_2_28 (- ghost_2_14 1))))))
 (let (($x7722 (or (or $x7709 $x7717) (and $x6788 (= ghost_2_6 (- ghost_2_14 1))))))
 (let (($x7734 (>= ghost_2_14 1)))
 (let (($x7732 (and $x7734 (or (or $x7722 $x7725) (and $x6758 (= ghost_2_5 (- ghost_2_14 1)))))))
 (let (($x7099 (not c_14_6)))
 (let (($x7113 (or (and c_14_0 in_target_14) (and c_14_1 in_target_14) (and c_14_2 in_target_14) (and c_14_3 in_target_14) (and c_14_4 in_target_14) (and c_14_5 in_target_14) (and c_14_6 in_target_14))))
 (let (($x7100 (and $x7113 $x7099)))
 (let (($x7581 (= ghost_2_13 1)))
 (let (($x7646 (and c_27_6 $x7581)))
 (let (($x7637 (and c_5_6 $x7581)))
 (let (($x7603 (and c_26_6 $x7581)))
 (let (($x7597 (not c_25_6)))
 (let (($x7611 (or (and c_25_0 in_target_25) (and c_25_1 in_target_25) (and c_25_2 in_target_25) (and c_25_3 in_target_25) (and c_25_4 in_target_25) (and c_25_5 in_target_25) (and c_25_6 in_target_25))))
 (let (($x7601 (or (or false (and c_25_6 $x7581)) (and (and $x7611 $x7597) (= ghost_2_25 (- ghost_2_13 1))))))
 (let (($x7639 (or (or $x7601 $x7603) (and $x7628 (= ghost_2_26 (- ghost_2_13 1))))))
 (let (($x7647 (or (or $x7639 $x7637) (and $x6758 (= ghost_2_5 (- ghost_2_13 1))))))
 (let (($x7665 (or (or $x7647 $x7646) (and $x7662 (= ghost_2_27 (- ghost_2_13 1))))))
 (let (($x7681 (>= ghost_2_13 1)))
 (let (($x7069 (not c_13_6)))
 (let (($x7083 (or (and c_13_0 in_target_13) (and c_13_1 in_target_13) (and c_13_2 in_target_13) (and c_13_3 in_target_13) (and c_13_4 in_target_13) (and c_13_5 in_target_13) (and c_13_6 in_target_13))))
 (let (($x7070 (and $x7083 $x7069)))
 (let (($x7677 (and (=> (and $x7083 c_13_6) (= ghost_2_13 0)) (=> $x7070 (and $x7681 $x7665)))))
 (let (($x7527 (= ghost_2_12 1)))
 (let (($x7546 (and c_24_6 $x7527)))
 (let (($x7539 (and c_23_6 $x7527)))
 (let (($x7535 (and c_4_6 $x7527)))
 (let (($x7532 (or (or false (and c_17_6 $x7527)) (and $x7242 (= ghost_2_17 (- ghost_2_12 1))))))
 (let (($x7537 (or (or $x7532 $x7535) (and (and $x6731 (not c_4_6)) (= ghost_2_4 (- ghost_2_12 1))))))
 (let (($x7543 (or (or $x7537 $x7539) (and $x7506 (= ghost_2_23 (- ghost_2_12 1))))))
 (let (($x7569 (or (or $x7543 $x7546) (and $x7560 (= ghost_2_24 (- ghost_2_12 1))))))
 (let (($x7576 (>= ghost_2_12 1)))
 (let (($x7575 (and (=> (and $x7045 c_12_6) (= ghost_2_12 0)) (=> $x7032 (and $x7576 $x7569)))))
 (let (($x7469 (= ghost_2_11 1)))
 (let (($x7491 (and c_23_6 $x7469)))
 (let (($x7484 (and c_22_6 $x7469)))
 (let (($x7478 (and c_3_6 $x7469)))
 (let (($x7479 (or (or false (and c_4_6 $x7469)) (and (and $x6731 (not c_4_6)) (= ghost_2_4 (- ghost_2_11 1))))))
 (let (($x7487 (or (or $x7479 $x7478) (and (and $x6702 (not c_3_6)) (= ghost_2_3 (- ghost_2_11 1))))))
 (let (($x7489 (or (or $x7487 $x7484) (and $x7452 (= ghost_2_22 (- ghost_2_11 1))))))
 (let (($x7515 (or (or $x7489 $x7491) (and $x7506 (= ghost_2_23 (- ghost_2_11 1))))))
 (let (($x7522 (>= ghost_2_11 1)))
 (let (($x7524 (and (=> (and $x6991 c_11_6) (= ghost_2_11 0)) (=> $x6978 (and $x7522 $x7515)))))
 (let (($x7391 (= ghost_2_10 1)))
 (let (($x7434 (and c_22_6 $x7391)))
 (let (($x7406 (and c_21_6 $x7391)))
 (let (($x7402 (and c_20_6 $x7391)))
 (let (($x7400 (or (or false (and c_3_6 $x7391)) (and (and $x6702 (not c_3_6)) (= ghost_2_3 (- ghost_2_10 1))))))
 (let (($x7407 (or (or $x7400 $x7402) (and $x7369 (= ghost_2_20 (- ghost_2_10 1))))))
 (let (($x7432 (or (or $x7407 $x7406) (and $x7423 (= ghost_2_21 (- ghost_2_10 1))))))
 (let (($x7463 (or (or $x7432 $x7434) (and $x7452 (= ghost_2_22 (- ghost_2_10 1))))))
 (let (($x7468 (>= ghost_2_10 1)))
 (let (($x7470 (and (=> (and $x6962 c_10_6) (= ghost_2_10 0)) (=> $x6949 (and $x7468 $x7463)))))
 (let (($x7339 (= ghost_2_9 1)))
 (let (($x7372 (and c_3_6 $x7339)))
 (let (($x7351 (and c_20_6 $x7339)))
 (let (($x7347 (and c_19_6 $x7339)))
 (let (($x7349 (or (or false (and c_2_6 $x7339)) (and (and $x6673 (not c_2_6)) (= ghost_2_2 (- ghost_2_9 1))))))
 (let (($x7355 (or (or $x7349 $x7347) (and $x7315 (= ghost_2_19 (- ghost_2_9 1))))))
 (let (($x7378 (or (or $x7355 $x7351) (and $x7369 (= ghost_2_20 (- ghost_2_9 1))))))
 (let (($x7389 (or (or $x7378 $x7372) (and (and $x6702 (not c_3_6)) (= ghost_2_3 (- ghost_2_9 1))))))
 (let (($x7392 (>= ghost_2_9 1)))
 (let (($x7393 (and (=> (and $x6908 c_9_6) (= ghost_2_9 0)) (=> $x6895 (and $x7392 $x7389)))))
 (let (($x7265 (= ghost_2_8 1)))
 (let (($x7320 (and c_2_6 $x7265)))
 (let (($x7297 (and c_19_6 $x7265)))
 (let (($x7271 (and c_18_6 $x7265)))
 (let (($x7267 (or (or false (and c_16_6 $x7265)) (and $x7178 (= ghost_2_16 (- ghost_2_8 1))))))
 (let (($x7293 (or (or $x7267 $x7271) (and $x7286 (= ghost_2_18 (- ghost_2_8 1))))))
 (let (($x7322 (or (or $x7293 $x7297) (and $x7315 (= ghost_2_19 (- ghost_2_8 1))))))
 (let (($x7334 (or (or $x7322 $x7320) (and (and $x6673 (not c_2_6)) (= ghost_2_2 (- ghost_2_8 1))))))
 (let (($x7337 (>= ghost_2_8 1)))
 (let (($x7336 (and (=> (and $x6879 c_8_6) (= ghost_2_8 0)) (=> $x6866 (and $x7337 $x7334)))))
 (let (($x7210 (= ghost_2_7 1)))
 (let (($x7226 (and c_17_6 $x7210)))
 (let (($x7221 (and c_4_6 $x7210)))
 (let (($x7215 (and c_1_6 $x7210)))
 (let (($x7214 (or (or false (and c_15_6 $x7210)) (and $x7134 (= ghost_2_15 (- ghost_2_7 1))))))
 (let (($x7219 (or (or $x7214 $x7215) (and (and $x6643 (not c_1_6)) (= ghost_2_1 (- ghost_2_7 1))))))
 (let (($x7224 (or (or $x7219 $x7221) (and (and $x6731 (not c_4_6)) (= ghost_2_4 (- ghost_2_7 1))))))
 (let (($x7260 (>= ghost_2_7 1)))
 (let (($x7261 (and $x7260 (or (or $x7224 $x7226) (and $x7242 (= ghost_2_17 (- ghost_2_7 1)))))))
 (let (($x7155 (= ghost_2_6 1)))
 (let (($x7198 (and c_1_6 $x7155)))
 (let (($x7183 (and c_2_6 $x7155)))
 (let (($x7161 (and c_16_6 $x7155)))
 (let (($x7160 (or (or false (and c_14_6 $x7155)) (and $x7100 (= ghost_2_14 (- ghost_2_6 1))))))
 (let (($x7189 (or (or $x7160 $x7161) (and $x7178 (= ghost_2_16 (- ghost_2_6 1))))))
 (let (($x7197 (or (or $x7189 $x7183) (and (and $x6673 (not c_2_6)) (= ghost_2_2 (- ghost_2_6 1))))))
 (let (($x7199 (or (or $x7197 $x7198) (and (and $x6643 (not c_1_6)) (= ghost_2_1 (- ghost_2_6 1))))))
 (let (($x7203 (>= ghost_2_6 1)))
 (let (($x7205 (and (=> (and $x6801 c_6_6) (= ghost_2_6 0)) (=> $x6788 (and $x7203 $x7199)))))
 (let (($x7053 (= ghost_2_5 1)))
 (let (($x7118 (and c_15_6 $x7053)))
 (let (($x7111 (and c_1_6 $x7053)))
 (let (($x7077 (and c_14_6 $x7053)))
 (let (($x7073 (or (or false (and c_13_6 $x7053)) (and $x7070 (= ghost_2_13 (- ghost_2_5 1))))))
 (let (($x7107 (or (or $x7073 $x7077) (and $x7100 (= ghost_2_14 (- ghost_2_5 1))))))
 (let (($x7116 (or (or $x7107 $x7111) (and (and $x6643 (not c_1_6)) (= ghost_2_1 (- ghost_2_5 1))))))
 (let (($x7152 (>= ghost_2_5 1)))
 (let (($x7151 (and $x7152 (or (or $x7116 $x7118) (and $x7134 (= ghost_2_15 (- ghost_2_5 1)))))))
 (let (($x6998 (= ghost_2_4 1)))
 (let (($x7016 (and c_12_6 $x6998)))
 (let (($x7012 (and c_11_6 $x6998)))
 (let (($x7005 (and c_0_6 $x6998)))
 (let (($x7007 (or (or false (and c_7_6 $x6998)) (and $x6822 (= ghost_2_7 (- ghost_2_4 1))))))
 (let (($x7009 (or (or $x7007 $x7005) (and (and $x6574 (not c_0_6)) (= ghost_2_0 (- ghost_2_4 1))))))
 (let (($x7015 (or (or $x7009 $x7012) (and $x6978 (= ghost_2_11 (- ghost_2_4 1))))))
 (let (($x7047 (>= ghost_2_4 1)))
 (let (($x7049 (and $x7047 (or (or $x7015 $x7016) (and $x7032 (= ghost_2_12 (- ghost_2_4 1)))))))
 (let (($x6717 (not c_4_6)))
 (let (($x6718 (and $x6731 $x6717)))
 (let (($x6923 (= ghost_2_3 1)))
 (let (($x6958 (and c_11_6 $x6923)))
 (let (($x6931 (and c_10_6 $x6923)))
 (let (($x6927 (and c_9_6 $x6923)))
 (let (($x6928 (or (or false (and c_0_6 $x6923)) (and (and $x6574 (not c_0_6)) (= ghost_2_0 (- ghost_2_3 1))))))
 (let (($x6934 (or (or $x6928 $x6927) (and $x6895 (= ghost_2_9 (- ghost_2_3 1))))))
 (let (($x6960 (or (or $x6934 $x6931) (and $x6949 (= ghost_2_10 (- ghost_2_3 1))))))
 (let (($x6997 (>= ghost_2_3 1)))
 (let (($x6994 (and $x6997 (or (or $x6960 $x6958) (and $x6978 (= ghost_2_11 (- ghost_2_3 1)))))))
 (let (($x6688 (not c_3_6)))
 (let (($x6689 (and $x6702 $x6688)))
 (let (($x6843 (= ghost_2_2 1)))
 (let (($x6906 (and c_0_6 $x6843)))
 (let (($x6871 (and c_9_6 $x6843)))
 (let (($x6851 (and c_8_6 $x6843)))
 (let (($x6850 (or (or false (and c_6_6 $x6843)) (and $x6788 (= ghost_2_6 (- ghost_2_2 1))))))
 (let (($x6875 (or (or $x6850 $x6851) (and $x6866 (= ghost_2_8 (- ghost_2_2 1))))))
 (let (($x6900 (or (or $x6875 $x6871) (and $x6895 (= ghost_2_9 (- ghost_2_2 1))))))
 (let (($x6911 (or (or $x6900 $x6906) (and (and $x6574 (not c_0_6)) (= ghost_2_0 (- ghost_2_2 1))))))
 (let (($x6918 (>= ghost_2_2 1)))
 (let (($x6659 (not c_2_6)))
 (let (($x6660 (and $x6673 $x6659)))
 (let (($x6916 (and (=> (and $x6673 c_2_6) (= ghost_2_2 0)) (=> $x6660 (and $x6918 $x6911)))))
 (let (($x6738 (= ghost_2_1 1)))
 (let (($x6807 (and c_7_6 $x6738)))
 (let (($x6795 (and c_0_6 $x6738)))
 (let (($x6769 (and c_6_6 $x6738)))
 (let (($x6761 (or (or false (and c_5_6 $x6738)) (and $x6758 (= ghost_2_5 (- ghost_2_1 1))))))
 (let (($x6799 (or (or $x6761 $x6769) (and $x6788 (= ghost_2_6 (- ghost_2_1 1))))))
 (let (($x6804 (or (or $x6799 $x6795) (and (and $x6574 (not c_0_6)) (= ghost_2_0 (- ghost_2_1 1))))))
 (let (($x6837 (>= ghost_2_1 1)))
 (let (($x6839 (and $x6837 (or (or $x6804 $x6807) (and $x6822 (= ghost_2_7 (- ghost_2_1 1)))))))
 (let (($x6629 (not c_1_6)))
 (let (($x6630 (and $x6643 $x6629)))
 (let (($x6612 (= ghost_2_0 1)))
 (let (($x6696 (and c_4_6 $x6612)))
 (let (($x6665 (and c_3_6 $x6612)))
 (let (($x6641 (and c_2_6 $x6612)))
 (let (($x6639 (or (or false (and c_1_6 $x6612)) (and $x6630 (= ghost_2_1 (- ghost_2_0 1))))))
 (let (($x6667 (or (or $x6639 $x6641) (and $x6660 (= ghost_2_2 (- ghost_2_0 1))))))
 (let (($x6698 (or (or $x6667 $x6665) (and $x6689 (= ghost_2_3 (- ghost_2_0 1))))))
 (let (($x6733 (>= ghost_2_0 1)))
 (let (($x6736 (and $x6733 (or (or $x6698 $x6696) (and $x6718 (= ghost_2_4 (- ghost_2_0 1)))))))
 (let (($x6735 (not c_0_6)))
 (let (($x6734 (and $x6574 $x6735)))
 (let (($x6739 (and true (and (=> (and $x6574 c_0_6) (= ghost_2_0 0)) (=> $x6734 $x6736)))))
 (let (($x6841 (and $x6739 (and (=> (and $x6643 c_1_6) (= ghost_2_1 0)) (=> $x6630 $x6839)))))
 (let (($x6922 (and $x6841 $x6916)))
 (let (($x7001 (and $x6922 (and (=> (and $x6702 c_3_6) (= ghost_2_3 0)) (=> $x6689 $x6994)))))
 (let (($x7051 (and $x7001 (and (=> (and $x6731 c_4_6) (= ghost_2_4 0)) (=> $x6718 $x7049)))))
 (let (($x7156 (and $x7051 (and (=> (and $x6771 c_5_6) (= ghost_2_5 0)) (=> $x6758 $x7151)))))
 (let (($x7204 (and $x7156 $x7205)))
 (let (($x7264 (and $x7204 (and (=> (and $x6835 c_7_6) (= ghost_2_7 0)) (=> $x6822 $x7261)))))
 (let (($x7341 (and $x7264 $x7336)))
 (let (($x7396 (and $x7341 $x7393)))
 (let (($x7472 (and $x7396 $x7470)))
 (let (($x7526 (and $x7472 $x7524)))
 (let (($x7580 (and $x7526 $x7575)))
 (let (($x7685 (and $x7580 $x7677)))
 (let (($x7738 (and $x7685 (and (=> (and $x7113 c_14_6) (= ghost_2_14 0)) (=> $x7100 $x7732)))))
 (let (($x7789 (and $x7738 $x7788)))
 (let (($x7846 (and $x7789 (and (=> (and $x7191 c_16_6) (= ghost_2_16 0)) (=> $x7178 $x7836)))))
 (let (($x7900 (and $x7846 $x7893)))
 (let (($x7974 (and $x7900 (and (=> (and $x7299 c_18_6) (= ghost_2_18 0)) (=> $x7286 $x7972)))))
 (let (($x8033 (and $x7974 (and (=> (and $x7328 c_19_6) (= ghost_2_19 0)) (=> $x7315 $x8023)))))
 (let (($x8085 (and $x8033 $x8077)))
 (let (($x8159 (and $x8085 $x8161)))
 (let (($x8216 (and $x8159 $x8211)))
 (let (($x8270 (and $x8216 $x8265)))
 (let (($x9228 (and (and (and $x8270 $x8321) $x9224) (not (or $x9200 (and $x8488 (and $x8919 $x9218)))))))
 (let (($x9231 (or (and $x9228 (not (or $x8459 (and (and $x8434 $x8328) (or $x8450 $x8456))))) (or false $x6561))))
 (let (($x6535 (and (and c_40_1 (not (or c_40_2 c_40_3 c_40_4 c_40_5 c_40_6))) (= ghost_1_40 (- ghost_1_24 1)))))
 (let (($x6511 (= ghost_1_24 1)))
 (let (($x6534 (or c_40_2 c_40_3 c_40_4 c_40_5 c_40_6)))
 (let (($x6530 (and $x6534 $x6511)))
 (let (($x6499 (or c_39_2 c_39_3 c_39_4 c_39_5 c_39_6)))
 (let (($x6498 (not $x6499)))
 (let (($x6497 (and c_39_1 $x6498)))
 (let (($x6523 (and $x6499 $x6511)))
 (let (($x5794 (or c_12_2 c_12_3 c_12_4 c_12_5 c_12_6)))
 (let (($x5792 (not $x5794)))
 (let (($x5793 (and c_12_1 $x5792)))
 (let (($x6518 (and $x5794 $x6511)))
 (let (($x6279 (or c_31_2 c_31_3 c_31_4 c_31_5 c_31_6)))
 (let (($x6278 (not $x6279)))
 (let (($x6277 (and c_31_1 $x6278)))
 (let (($x6516 (or (or false (and $x6279 $x6511)) (and $x6277 (= ghost_1_31 (- ghost_1_24 1))))))
 (let (($x6522 (or (or $x6516 $x6518) (and $x5793 (= ghost_1_12 (- ghost_1_24 1))))))
 (let (($x6528 (or (or $x6522 $x6523) (and $x6497 (= ghost_1_39 (- ghost_1_24 1))))))
 (let (($x6541 (>= ghost_1_24 1)))
 (let (($x6094 (or c_24_2 c_24_3 c_24_4 c_24_5 c_24_6)))
 (let (($x6092 (not $x6094)))
 (let (($x6093 (and c_24_1 $x6092)))
 (let (($x6544 (and (=> (and c_24_1 $x6094) (= ghost_1_24 0)) (=> $x6093 (and $x6541 (or (or $x6528 $x6530) $x6535))))))
 (let (($x6476 (= ghost_1_23 1)))
 (let (($x6495 (and $x6499 $x6476)))
 (let (($x6464 (or c_38_2 c_38_3 c_38_4 c_38_5 c_38_6)))
 (let (($x6462 (not $x6464)))
 (let (($x6463 (and c_38_1 $x6462)))
 (let (($x6488 (and $x6464 $x6476)))
 (let (($x5759 (or c_11_2 c_11_3 c_11_4 c_11_5 c_11_6)))
 (let (($x5757 (not $x5759)))
 (let (($x5758 (and c_11_1 $x5757)))
 (let (($x6483 (and $x5759 $x6476)))
 (let (($x6482 (or (or false (and $x5794 $x6476)) (and $x5793 (= ghost_1_12 (- ghost_1_23 1))))))
 (let (($x6487 (or (or $x6482 $x6483) (and $x5758 (= ghost_1_11 (- ghost_1_23 1))))))
 (let (($x6492 (or (or $x6487 $x6488) (and $x6463 (= ghost_1_38 (- ghost_1_23 1))))))
 (let (($x6502 (or (or $x6492 $x6495) (and $x6497 (= ghost_1_39 (- ghost_1_23 1))))))
 (let (($x6506 (>= ghost_1_23 1)))
 (let (($x6059 (or c_23_2 c_23_3 c_23_4 c_23_5 c_23_6)))
 (let (($x6057 (not $x6059)))
 (let (($x6058 (and c_23_1 $x6057)))
 (let (($x6509 (and (=> (and c_23_1 $x6059) (= ghost_1_23 0)) (=> $x6058 (and $x6506 $x6502)))))
 (let (($x6440 (= ghost_1_22 1)))
 (let (($x6460 (and $x6464 $x6440)))
 (let (($x6429 (or c_37_2 c_37_3 c_37_4 c_37_5 c_37_6)))
 (let (($x6427 (not $x6429)))
 (let (($x6428 (and c_37_1 $x6427)))
 (let (($x6453 (and $x6429 $x6440)))
 (let (($x5749 (or c_10_2 c_10_3 c_10_4 c_10_5 c_10_6)))
 (let (($x5747 (not $x5749)))
 (let (($x5748 (and c_10_1 $x5747)))
 (let (($x6448 (and $x5749 $x6440)))
 (let (($x6447 (or (or false (and $x5759 $x6440)) (and $x5758 (= ghost_1_11 (- ghost_1_22 1))))))
 (let (($x6452 (or (or $x6447 $x6448) (and $x5748 (= ghost_1_10 (- ghost_1_22 1))))))
 (let (($x6457 (or (or $x6452 $x6453) (and $x6428 (= ghost_1_37 (- ghost_1_22 1))))))
 (let (($x6467 (or (or $x6457 $x6460) (and $x6463 (= ghost_1_38 (- ghost_1_22 1))))))
 (let (($x6471 (>= ghost_1_22 1)))
 (let (($x6024 (or c_22_2 c_22_3 c_22_4 c_22_5 c_22_6)))
 (let (($x6022 (not $x6024)))
 (let (($x6023 (and c_22_1 $x6022)))
 (let (($x6474 (and (=> (and c_22_1 $x6024) (= ghost_1_22 0)) (=> $x6023 (and $x6471 $x6467)))))
 (let (($x6401 (= ghost_1_21 1)))
 (let (($x6425 (and $x6429 $x6401)))
 (let (($x6421 (and (and c_36_1 (not (or c_36_2 c_36_3 c_36_4 c_36_5 c_36_6))) (= ghost_1_36 (- ghost_1_21 1)))))
 (let (($x6419 (or c_36_2 c_36_3 c_36_4 c_36_5 c_36_6)))
 (let (($x6415 (and $x6419 $x6401)))
 (let (($x6384 (or c_35_2 c_35_3 c_35_4 c_35_5 c_35_6)))
 (let (($x6382 (not $x6384)))
 (let (($x6383 (and c_35_1 $x6382)))
 (let (($x6408 (and $x6384 $x6401)))
 (let (($x6407 (or (or false (and $x5749 $x6401)) (and $x5748 (= ghost_1_10 (- ghost_1_21 1))))))
 (let (($x6412 (or (or $x6407 $x6408) (and $x6383 (= ghost_1_35 (- ghost_1_21 1))))))
 (let (($x6422 (or (or $x6412 $x6415) $x6421)))
 (let (($x6432 (or (or $x6422 $x6425) (and $x6428 (= ghost_1_37 (- ghost_1_21 1))))))
 (let (($x6437 (>= ghost_1_21 1)))
 (let (($x6014 (or c_21_2 c_21_3 c_21_4 c_21_5 c_21_6)))
 (let (($x6013 (not $x6014)))
 (let (($x6012 (and c_21_1 $x6013)))
 (let (($x6439 (and (=> (and c_21_1 $x6014) (= ghost_1_21 0)) (=> $x6012 (and $x6437 $x6432)))))
 (let (($x6365 (= ghost_1_20 1)))
 (let (($x6388 (and $x5749 $x6365)))
 (let (($x6380 (and $x6384 $x6365)))
 (let (($x6349 (or c_34_2 c_34_3 c_34_4 c_34_5 c_34_6)))
 (let (($x6348 (not $x6349)))
 (let (($x6347 (and c_34_1 $x6348)))
 (let (($x6373 (and $x6349 $x6365)))
 (let (($x5714 (or c_9_2 c_9_3 c_9_4 c_9_5 c_9_6)))
 (let (($x5712 (not $x5714)))
 (let (($x5713 (and c_9_1 $x5712)))
 (let (($x6372 (or (or false (and $x5714 $x6365)) (and $x5713 (= ghost_1_9 (- ghost_1_20 1))))))
 (let (($x6378 (or (or $x6372 $x6373) (and $x6347 (= ghost_1_34 (- ghost_1_20 1))))))
 (let (($x6387 (or (or $x6378 $x6380) (and $x6383 (= ghost_1_35 (- ghost_1_20 1))))))
 (let (($x6392 (or (or $x6387 $x6388) (and $x5748 (= ghost_1_10 (- ghost_1_20 1))))))
 (let (($x6396 (>= ghost_1_20 1)))
 (let (($x5979 (or c_20_2 c_20_3 c_20_4 c_20_5 c_20_6)))
 (let (($x5977 (not $x5979)))
 (let (($x5978 (and c_20_1 $x5977)))
 (let (($x6399 (and (=> (and c_20_1 $x5979) (= ghost_1_20 0)) (=> $x5978 (and $x6396 $x6392)))))
 (let (($x6331 (= ghost_1_19 1)))
 (let (($x6353 (and $x5714 $x6331)))
 (let (($x6345 (and $x6349 $x6331)))
 (let (($x6314 (or c_33_2 c_33_3 c_33_4 c_33_5 c_33_6)))
 (let (($x6313 (not $x6314)))
 (let (($x6312 (and c_33_1 $x6313)))
 (let (($x6338 (and $x6314 $x6331)))
 (let (($x5704 (or c_8_2 c_8_3 c_8_4 c_8_5 c_8_6)))
 (let (($x5703 (not $x5704)))
 (let (($x5702 (and c_8_1 $x5703)))
 (let (($x6336 (or (or false (and $x5704 $x6331)) (and $x5702 (= ghost_1_8 (- ghost_1_19 1))))))
 (let (($x6343 (or (or $x6336 $x6338) (and $x6312 (= ghost_1_33 (- ghost_1_19 1))))))
 (let (($x6352 (or (or $x6343 $x6345) (and $x6347 (= ghost_1_34 (- ghost_1_19 1))))))
 (let (($x6362 (>= ghost_1_19 1)))
 (let (($x6361 (and $x6362 (or (or $x6352 $x6353) (and $x5713 (= ghost_1_9 (- ghost_1_19 1)))))))
 (let (($x5944 (or c_19_2 c_19_3 c_19_4 c_19_5 c_19_6)))
 (let (($x5943 (not $x5944)))
 (let (($x5942 (and c_19_1 $x5943)))
 (let (($x6291 (= ghost_1_18 1)))
 (let (($x6318 (and $x5704 $x6291)))
 (let (($x6310 (and $x6314 $x6291)))
 (let (($x6305 (and (and c_32_1 (not (or c_32_2 c_32_3 c_32_4 c_32_5 c_32_6))) (= ghost_1_32 (- ghost_1_18 1)))))
 (let (($x6304 (or c_32_2 c_32_3 c_32_4 c_32_5 c_32_6)))
 (let (($x6300 (and $x6304 $x6291)))
 (let (($x6234 (or c_30_2 c_30_3 c_30_4 c_30_5 c_30_6)))
 (let (($x6232 (not $x6234)))
 (let (($x6233 (and c_30_1 $x6232)))
 (let (($x6297 (or (or false (and $x6234 $x6291)) (and $x6233 (= ghost_1_30 (- ghost_1_18 1))))))
 (let (($x6307 (or (or $x6297 $x6300) $x6305)))
 (let (($x6317 (or (or $x6307 $x6310) (and $x6312 (= ghost_1_33 (- ghost_1_18 1))))))
 (let (($x6326 (>= ghost_1_18 1)))
 (let (($x6327 (and $x6326 (or (or $x6317 $x6318) (and $x5702 (= ghost_1_8 (- ghost_1_18 1)))))))
 (let (($x5934 (or c_18_2 c_18_3 c_18_4 c_18_5 c_18_6)))
 (let (($x5932 (not $x5934)))
 (let (($x5933 (and c_18_1 $x5932)))
 (let (($x6255 (= ghost_1_17 1)))
 (let (($x6275 (and $x6279 $x6255)))
 (let (($x6267 (and $x5794 $x6255)))
 (let (($x5679 (or c_7_2 c_7_3 c_7_4 c_7_5 c_7_6)))
 (let (($x5678 (not $x5679)))
 (let (($x5677 (and c_7_1 $x5678)))
 (let (($x6263 (and $x5679 $x6255)))
 (let (($x6209 (or c_29_2 c_29_3 c_29_4 c_29_5 c_29_6)))
 (let (($x6207 (not $x6209)))
 (let (($x6208 (and c_29_1 $x6207)))
 (let (($x6262 (or (or false (and $x6209 $x6255)) (and $x6208 (= ghost_1_29 (- ghost_1_17 1))))))
 (let (($x6268 (or (or $x6262 $x6263) (and $x5677 (= ghost_1_7 (- ghost_1_17 1))))))
 (let (($x6272 (or (or $x6268 $x6267) (and $x5793 (= ghost_1_12 (- ghost_1_17 1))))))
 (let (($x6282 (or (or $x6272 $x6275) (and $x6277 (= ghost_1_31 (- ghost_1_17 1))))))
 (let (($x6286 (>= ghost_1_17 1)))
 (let (($x5909 (or c_17_2 c_17_3 c_17_4 c_17_5 c_17_6)))
 (let (($x5907 (not $x5909)))
 (let (($x5908 (and c_17_1 $x5907)))
 (let (($x6289 (and (=> (and c_17_1 $x5909) (= ghost_1_17 0)) (=> $x5908 (and $x6286 $x6282)))))
 (let (($x5664 (or c_6_2 c_6_3 c_6_4 c_6_5 c_6_6)))
 (let (($x5663 (not $x5664)))
 (let (($x5662 (and c_6_1 $x5663)))
 (let (($x6221 (= ghost_1_16 1)))
 (let (($x6242 (and $x5664 $x6221)))
 (let (($x6238 (and $x5704 $x6221)))
 (let (($x6230 (and $x6234 $x6221)))
 (let (($x6164 (or c_28_2 c_28_3 c_28_4 c_28_5 c_28_6)))
 (let (($x6162 (not $x6164)))
 (let (($x6163 (and c_28_1 $x6162)))
 (let (($x6227 (or (or false (and $x6164 $x6221)) (and $x6163 (= ghost_1_28 (- ghost_1_16 1))))))
 (let (($x6237 (or (or $x6227 $x6230) (and $x6233 (= ghost_1_30 (- ghost_1_16 1))))))
 (let (($x6243 (or (or $x6237 $x6238) (and $x5702 (= ghost_1_8 (- ghost_1_16 1))))))
 (let (($x6252 (>= ghost_1_16 1)))
 (let (($x6251 (and $x6252 (or (or $x6243 $x6242) (and $x5662 (= ghost_1_6 (- ghost_1_16 1)))))))
 (let (($x5864 (or c_16_2 c_16_3 c_16_4 c_16_5 c_16_6)))
 (let (($x5863 (not $x5864)))
 (let (($x5862 (and c_16_1 $x5863)))
 (let (($x6185 (= ghost_1_15 1)))
 (let (($x6205 (and $x6209 $x6185)))
 (let (($x6198 (and $x5679 $x6185)))
 (let (($x5652 (or c_5_2 c_5_3 c_5_4 c_5_5 c_5_6)))
 (let (($x5651 (not $x5652)))
 (let (($x5653 (and c_5_1 $x5651)))
 (let (($x6193 (and $x5652 $x6185)))
 (let (($x6139 (or c_27_2 c_27_3 c_27_4 c_27_5 c_27_6)))
 (let (($x6137 (not $x6139)))
 (let (($x6138 (and c_27_1 $x6137)))
 (let (($x6192 (or (or false (and $x6139 $x6185)) (and $x6138 (= ghost_1_27 (- ghost_1_15 1))))))
 (let (($x6197 (or (or $x6192 $x6193) (and $x5653 (= ghost_1_5 (- ghost_1_15 1))))))
 (let (($x6203 (or (or $x6197 $x6198) (and $x5677 (= ghost_1_7 (- ghost_1_15 1))))))
 (let (($x6212 (or (or $x6203 $x6205) (and $x6208 (= ghost_1_29 (- ghost_1_15 1))))))
 (let (($x6216 (>= ghost_1_15 1)))
 (let (($x5839 (or c_15_2 c_15_3 c_15_4 c_15_5 c_15_6)))
 (let (($x5837 (not $x5839)))
 (let (($x5838 (and c_15_1 $x5837)))
 (let (($x6219 (and (=> (and c_15_1 $x5839) (= ghost_1_15 0)) (=> $x5838 (and $x6216 $x6212)))))
 (let (($x6151 (= ghost_1_14 1)))
 (let (($x6172 (and $x5652 $x6151)))
 (let (($x6168 (and $x5664 $x6151)))
 (let (($x6160 (and $x6164 $x6151)))
 (let (($x6124 (or c_26_2 c_26_3 c_26_4 c_26_5 c_26_6)))
 (let (($x6122 (not $x6124)))
 (let (($x6123 (and c_26_1 $x6122)))
 (let (($x6157 (or (or false (and $x6124 $x6151)) (and $x6123 (= ghost_1_26 (- ghost_1_14 1))))))
 (let (($x6167 (or (or $x6157 $x6160) (and $x6163 (= ghost_1_28 (- ghost_1_14 1))))))
 (let (($x6173 (or (or $x6167 $x6168) (and $x5662 (= ghost_1_6 (- ghost_1_14 1))))))
 (let (($x6182 (>= ghost_1_14 1)))
 (let (($x6181 (and $x6182 (or (or $x6173 $x6172) (and $x5653 (= ghost_1_5 (- ghost_1_14 1)))))))
 (let (($x5824 (or c_14_2 c_14_3 c_14_4 c_14_5 c_14_6)))
 (let (($x5823 (not $x5824)))
 (let (($x5822 (and c_14_1 $x5823)))
 (let (($x6108 (= ghost_1_13 1)))
 (let (($x6135 (and $x6139 $x6108)))
 (let (($x6128 (and $x5652 $x6108)))
 (let (($x6120 (and $x6124 $x6108)))
 (let (($x6116 (and (and c_25_1 (not (or c_25_2 c_25_3 c_25_4 c_25_5 c_25_6))) (= ghost_1_25 (- ghost_1_13 1)))))
 (let (($x6112 (or c_25_2 c_25_3 c_25_4 c_25_5 c_25_6)))
 (let (($x6109 (and $x6112 $x6108)))
 (let (($x6117 (or (or false $x6109) $x6116)))
 (let (($x6127 (or (or $x6117 $x6120) (and $x6123 (= ghost_1_26 (- ghost_1_13 1))))))
 (let (($x6132 (or (or $x6127 $x6128) (and $x5653 (= ghost_1_5 (- ghost_1_13 1))))))
 (let (($x6142 (or (or $x6132 $x6135) (and $x6138 (= ghost_1_27 (- ghost_1_13 1))))))
 (let (($x6146 (>= ghost_1_13 1)))
 (let (($x5812 (or c_13_2 c_13_3 c_13_4 c_13_5 c_13_6)))
 (let (($x5811 (not $x5812)))
 (let (($x5813 (and c_13_1 $x5811)))
 (let (($x6149 (and (=> (and c_13_1 $x5812) (= ghost_1_13 0)) (=> $x5813 (and $x6146 $x6142)))))
 (let (($x6071 (= ghost_1_12 1)))
 (let (($x6090 (and $x6094 $x6071)))
 (let (($x6083 (and $x6059 $x6071)))
 (let (($x5628 (or c_4_2 c_4_3 c_4_4 c_4_5 c_4_6)))
 (let (($x5626 (not $x5628)))
 (let (($x5627 (and c_4_1 $x5626)))
 (let (($x6078 (and $x5628 $x6071)))
 (let (($x6077 (or (or false (and $x5909 $x6071)) (and $x5908 (= ghost_1_17 (- ghost_1_12 1))))))
 (let (($x6082 (or (or $x6077 $x6078) (and $x5627 (= ghost_1_4 (- ghost_1_12 1))))))
 (let (($x6087 (or (or $x6082 $x6083) (and $x6058 (= ghost_1_23 (- ghost_1_12 1))))))
 (let (($x6097 (or (or $x6087 $x6090) (and $x6093 (= ghost_1_24 (- ghost_1_12 1))))))
 (let (($x6101 (>= ghost_1_12 1)))
 (let (($x6104 (and (=> (and c_12_1 $x5794) (= ghost_1_12 0)) (=> $x5793 (and $x6101 $x6097)))))
 (let (($x6036 (= ghost_1_11 1)))
 (let (($x6055 (and $x6059 $x6036)))
 (let (($x6048 (and $x6024 $x6036)))
 (let (($x5618 (or c_3_2 c_3_3 c_3_4 c_3_5 c_3_6)))
 (let (($x5616 (not $x5618)))
 (let (($x5617 (and c_3_1 $x5616)))
 (let (($x6043 (and $x5618 $x6036)))
 (let (($x6042 (or (or false (and $x5628 $x6036)) (and $x5627 (= ghost_1_4 (- ghost_1_11 1))))))
 (let (($x6047 (or (or $x6042 $x6043) (and $x5617 (= ghost_1_3 (- ghost_1_11 1))))))
 (let (($x6052 (or (or $x6047 $x6048) (and $x6023 (= ghost_1_22 (- ghost_1_11 1))))))
 (let (($x6062 (or (or $x6052 $x6055) (and $x6058 (= ghost_1_23 (- ghost_1_11 1))))))
 (let (($x6066 (>= ghost_1_11 1)))
 (let (($x6069 (and (=> (and c_11_1 $x5759) (= ghost_1_11 0)) (=> $x5758 (and $x6066 $x6062)))))
 (let (($x5996 (= ghost_1_10 1)))
 (let (($x6020 (and $x6024 $x5996)))
 (let (($x6010 (and $x6014 $x5996)))
 (let (($x6003 (and $x5979 $x5996)))
 (let (($x6002 (or (or false (and $x5618 $x5996)) (and $x5617 (= ghost_1_3 (- ghost_1_10 1))))))
 (let (($x6007 (or (or $x6002 $x6003) (and $x5978 (= ghost_1_20 (- ghost_1_10 1))))))
 (let (($x6017 (or (or $x6007 $x6010) (and $x6012 (= ghost_1_21 (- ghost_1_10 1))))))
 (let (($x6027 (or (or $x6017 $x6020) (and $x6023 (= ghost_1_22 (- ghost_1_10 1))))))
 (let (($x6031 (>= ghost_1_10 1)))
 (let (($x6034 (and (=> (and c_10_1 $x5749) (= ghost_1_10 0)) (=> $x5748 (and $x6031 $x6027)))))
 (let (($x5960 (= ghost_1_9 1)))
 (let (($x5983 (and $x5618 $x5960)))
 (let (($x5975 (and $x5979 $x5960)))
 (let (($x5968 (and $x5944 $x5960)))
 (let (($x5608 (or c_2_2 c_2_3 c_2_4 c_2_5 c_2_6)))
 (let (($x5606 (not $x5608)))
 (let (($x5607 (and c_2_1 $x5606)))
 (let (($x5967 (or (or false (and $x5608 $x5960)) (and $x5607 (= ghost_1_2 (- ghost_1_9 1))))))
 (let (($x5973 (or (or $x5967 $x5968) (and $x5942 (= ghost_1_19 (- ghost_1_9 1))))))
 (let (($x5982 (or (or $x5973 $x5975) (and $x5978 (= ghost_1_20 (- ghost_1_9 1))))))
 (let (($x5991 (>= ghost_1_9 1)))
 (let (($x5992 (and $x5991 (or (or $x5982 $x5983) (and $x5617 (= ghost_1_3 (- ghost_1_9 1)))))))
 (let (($x5920 (= ghost_1_8 1)))
 (let (($x5948 (and $x5608 $x5920)))
 (let (($x5940 (and $x5944 $x5920)))
 (let (($x5930 (and $x5934 $x5920)))
 (let (($x5926 (or (or false (and $x5864 $x5920)) (and $x5862 (= ghost_1_16 (- ghost_1_8 1))))))
 (let (($x5937 (or (or $x5926 $x5930) (and $x5933 (= ghost_1_18 (- ghost_1_8 1))))))
 (let (($x5947 (or (or $x5937 $x5940) (and $x5942 (= ghost_1_19 (- ghost_1_8 1))))))
 (let (($x5957 (>= ghost_1_8 1)))
 (let (($x5956 (and $x5957 (or (or $x5947 $x5948) (and $x5607 (= ghost_1_2 (- ghost_1_8 1)))))))
 (let (($x5885 (= ghost_1_7 1)))
 (let (($x5905 (and $x5909 $x5885)))
 (let (($x5897 (and $x5628 $x5885)))
 (let (($x5595 (or c_1_2 c_1_3 c_1_4 c_1_5 c_1_6)))
 (let (($x5596 (not $x5595)))
 (let (($x5597 (and c_1_1 $x5596)))
 (let (($x5893 (and $x5595 $x5885)))
 (let (($x5892 (or (or false (and $x5839 $x5885)) (and $x5838 (= ghost_1_15 (- ghost_1_7 1))))))
 (let (($x5898 (or (or $x5892 $x5893) (and $x5597 (= ghost_1_1 (- ghost_1_7 1))))))
 (let (($x5902 (or (or $x5898 $x5897) (and $x5627 (= ghost_1_4 (- ghost_1_7 1))))))
 (let (($x5917 (>= ghost_1_7 1)))
 (let (($x5916 (and $x5917 (or (or $x5902 $x5905) (and $x5908 (= ghost_1_17 (- ghost_1_7 1)))))))
 (let (($x5851 (= ghost_1_6 1)))
 (let (($x5873 (and $x5595 $x5851)))
 (let (($x5868 (and $x5608 $x5851)))
 (let (($x5860 (and $x5864 $x5851)))
 (let (($x5856 (or (or false (and $x5824 $x5851)) (and $x5822 (= ghost_1_14 (- ghost_1_6 1))))))
 (let (($x5867 (or (or $x5856 $x5860) (and $x5862 (= ghost_1_16 (- ghost_1_6 1))))))
 (let (($x5872 (or (or $x5867 $x5868) (and $x5607 (= ghost_1_2 (- ghost_1_6 1))))))
 (let (($x5882 (>= ghost_1_6 1)))
 (let (($x5881 (and $x5882 (or (or $x5872 $x5873) (and $x5597 (= ghost_1_1 (- ghost_1_6 1)))))))
 (let (($x5808 (= ghost_1_5 1)))
 (let (($x5835 (and $x5839 $x5808)))
 (let (($x5828 (and $x5595 $x5808)))
 (let (($x5820 (and $x5824 $x5808)))
 (let (($x5817 (or (or false (and $x5812 $x5808)) (and $x5813 (= ghost_1_13 (- ghost_1_5 1))))))
 (let (($x5827 (or (or $x5817 $x5820) (and $x5822 (= ghost_1_14 (- ghost_1_5 1))))))
 (let (($x5833 (or (or $x5827 $x5828) (and $x5597 (= ghost_1_1 (- ghost_1_5 1))))))
 (let (($x5846 (>= ghost_1_5 1)))
 (let (($x5847 (and $x5846 (or (or $x5833 $x5835) (and $x5838 (= ghost_1_15 (- ghost_1_5 1)))))))
 (let (($x5771 (= ghost_1_4 1)))
 (let (($x5790 (and $x5794 $x5771)))
 (let (($x5783 (and $x5759 $x5771)))
 (let (($x5640 (or c_0_2 c_0_3 c_0_4 c_0_5 c_0_6)))
 (let (($x5641 (not $x5640)))
 (let (($x5642 (and c_0_1 $x5641)))
 (let (($x5778 (and $x5640 $x5771)))
 (let (($x5776 (or (or false (and $x5679 $x5771)) (and $x5677 (= ghost_1_7 (- ghost_1_4 1))))))
 (let (($x5782 (or (or $x5776 $x5778) (and $x5642 (= ghost_1_0 (- ghost_1_4 1))))))
 (let (($x5787 (or (or $x5782 $x5783) (and $x5758 (= ghost_1_11 (- ghost_1_4 1))))))
 (let (($x5801 (>= ghost_1_4 1)))
 (let (($x5802 (and $x5801 (or (or $x5787 $x5790) (and $x5793 (= ghost_1_12 (- ghost_1_4 1)))))))
 (let (($x5731 (= ghost_1_3 1)))
 (let (($x5755 (and $x5759 $x5731)))
 (let (($x5745 (and $x5749 $x5731)))
 (let (($x5738 (and $x5714 $x5731)))
 (let (($x5737 (or (or false (and $x5640 $x5731)) (and $x5642 (= ghost_1_0 (- ghost_1_3 1))))))
 (let (($x5742 (or (or $x5737 $x5738) (and $x5713 (= ghost_1_9 (- ghost_1_3 1))))))
 (let (($x5752 (or (or $x5742 $x5745) (and $x5748 (= ghost_1_10 (- ghost_1_3 1))))))
 (let (($x5766 (>= ghost_1_3 1)))
 (let (($x5767 (and $x5766 (or (or $x5752 $x5755) (and $x5758 (= ghost_1_11 (- ghost_1_3 1)))))))
 (let (($x5690 (= ghost_1_2 1)))
 (let (($x5718 (and $x5640 $x5690)))
 (let (($x5710 (and $x5714 $x5690)))
 (let (($x5700 (and $x5704 $x5690)))
 (let (($x5696 (or (or false (and $x5664 $x5690)) (and $x5662 (= ghost_1_6 (- ghost_1_2 1))))))
 (let (($x5707 (or (or $x5696 $x5700) (and $x5702 (= ghost_1_8 (- ghost_1_2 1))))))
 (let (($x5717 (or (or $x5707 $x5710) (and $x5713 (= ghost_1_9 (- ghost_1_2 1))))))
 (let (($x5726 (>= ghost_1_2 1)))
 (let (($x5727 (and $x5726 (or (or $x5717 $x5718) (and $x5642 (= ghost_1_0 (- ghost_1_2 1)))))))
 (let (($x5648 (= ghost_1_1 1)))
 (let (($x5675 (and $x5679 $x5648)))
 (let (($x5668 (and $x5640 $x5648)))
 (let (($x5660 (and $x5664 $x5648)))
 (let (($x5657 (or (or false (and $x5652 $x5648)) (and $x5653 (= ghost_1_5 (- ghost_1_1 1))))))
 (let (($x5667 (or (or $x5657 $x5660) (and $x5662 (= ghost_1_6 (- ghost_1_1 1))))))
 (let (($x5672 (or (or $x5667 $x5668) (and $x5642 (= ghost_1_0 (- ghost_1_1 1))))))
 (let (($x5687 (>= ghost_1_1 1)))
 (let (($x5686 (and $x5687 (or (or $x5672 $x5675) (and $x5677 (= ghost_1_7 (- ghost_1_1 1)))))))
 (let (($x5592 (= ghost_1_0 1)))
 (let (($x5624 (and $x5628 $x5592)))
 (let (($x5614 (and $x5618 $x5592)))
 (let (($x5604 (and $x5608 $x5592)))
 (let (($x5601 (or (or false (and $x5595 $x5592)) (and $x5597 (= ghost_1_1 (- ghost_1_0 1))))))
 (let (($x5611 (or (or $x5601 $x5604) (and $x5607 (= ghost_1_2 (- ghost_1_0 1))))))
 (let (($x5621 (or (or $x5611 $x5614) (and $x5617 (= ghost_1_3 (- ghost_1_0 1))))))
 (let (($x5638 (>= ghost_1_0 1)))
 (let (($x5639 (and $x5638 (or (or $x5621 $x5624) (and $x5627 (= ghost_1_4 (- ghost_1_0 1)))))))
 (let (($x5531 (or false (and c_24_2 (or (or c_31_2 c_31_3 c_31_4 c_31_5) c_31_6)))))
 (let (($x5532 (or $x5531 (and c_24_3 (or (or c_12_2 c_12_3 c_12_4 c_12_5) c_12_6)))))
 (let (($x5535 (or $x5532 (and c_24_4 (or (or c_39_2 c_39_3 c_39_4 c_39_5) c_39_6)))))
 (let (($x5545 (or $x5535 (and c_24_5 (or (or c_40_2 c_40_3 c_40_4 c_40_5) c_40_6)))))
 (let (($x5298 (or c_24_2 c_24_3 c_24_4 c_24_5)))
 (let (($x5513 (or false (and c_23_2 (or (or c_12_2 c_12_3 c_12_4 c_12_5) c_12_6)))))
 (let (($x5515 (or $x5513 (and c_23_3 (or (or c_11_2 c_11_3 c_11_4 c_11_5) c_11_6)))))
 (let (($x5517 (or $x5515 (and c_23_4 (or (or c_38_2 c_38_3 c_38_4 c_38_5) c_38_6)))))
 (let (($x5527 (or $x5517 (and c_23_5 (or (or c_39_2 c_39_3 c_39_4 c_39_5) c_39_6)))))
 (let (($x5280 (or c_23_2 c_23_3 c_23_4 c_23_5)))
 (let (($x5495 (or false (and c_22_2 (or (or c_11_2 c_11_3 c_11_4 c_11_5) c_11_6)))))
 (let (($x5497 (or $x5495 (and c_22_3 (or (or c_10_2 c_10_3 c_10_4 c_10_5) c_10_6)))))
 (let (($x5499 (or $x5497 (and c_22_4 (or (or c_37_2 c_37_3 c_37_4 c_37_5) c_37_6)))))
 (let (($x5508 (or $x5499 (and c_22_5 (or (or c_38_2 c_38_3 c_38_4 c_38_5) c_38_6)))))
 (let (($x5262 (or c_22_2 c_22_3 c_22_4 c_22_5)))
 (let (($x5469 (or false (and c_21_2 (or (or c_10_2 c_10_3 c_10_4 c_10_5) c_10_6)))))
 (let (($x5471 (or $x5469 (and c_21_3 (or (or c_35_2 c_35_3 c_35_4 c_35_5) c_35_6)))))
 (let (($x5480 (or $x5471 (and c_21_4 (or (or c_36_2 c_36_3 c_36_4 c_36_5) c_36_6)))))
 (let (($x5490 (or $x5480 (and c_21_5 (or (or c_37_2 c_37_3 c_37_4 c_37_5) c_37_6)))))
 (let (($x5252 (or c_21_2 c_21_3 c_21_4 c_21_5)))
 (let (($x5450 (or false (and c_20_2 (or (or c_9_2 c_9_3 c_9_4 c_9_5) c_9_6)))))
 (let (($x5453 (or $x5450 (and c_20_3 (or (or c_34_2 c_34_3 c_34_4 c_34_5) c_34_6)))))
 (let (($x5462 (or $x5453 (and c_20_4 (or (or c_35_2 c_35_3 c_35_4 c_35_5) c_35_6)))))
 (let (($x5465 (or $x5462 (and c_20_5 (or (or c_10_2 c_10_3 c_10_4 c_10_5) c_10_6)))))
 (let (($x5234 (or c_20_2 c_20_3 c_20_4 c_20_5)))
 (let (($x5433 (or false (and c_19_2 (or (or c_8_2 c_8_3 c_8_4 c_8_5) c_8_6)))))
 (let (($x5435 (or $x5433 (and c_19_3 (or (or c_33_2 c_33_3 c_33_4 c_33_5) c_33_6)))))
 (let (($x5444 (or $x5435 (and c_19_4 (or (or c_34_2 c_34_3 c_34_4 c_34_5) c_34_6)))))
 (let (($x5447 (or $x5444 (and c_19_5 (or (or c_9_2 c_9_3 c_9_4 c_9_5) c_9_6)))))
 (let (($x5216 (or c_19_2 c_19_3 c_19_4 c_19_5)))
 (let (($x5407 (or false (and c_18_2 (or (or c_30_2 c_30_3 c_30_4 c_30_5) c_30_6)))))
 (let (($x5417 (or $x5407 (and c_18_3 (or (or c_32_2 c_32_3 c_32_4 c_32_5) c_32_6)))))
 (let (($x5427 (or $x5417 (and c_18_4 (or (or c_33_2 c_33_3 c_33_4 c_33_5) c_33_6)))))
 (let (($x5429 (or $x5427 (and c_18_5 (or (or c_8_2 c_8_3 c_8_4 c_8_5) c_8_6)))))
 (let (($x5206 (or c_18_2 c_18_3 c_18_4 c_18_5)))
 (let (($x5388 (or false (and c_17_2 (or (or c_29_2 c_29_3 c_29_4 c_29_5) c_29_6)))))
 (let (($x5391 (or $x5388 (and c_17_3 (or (or c_7_2 c_7_3 c_7_4 c_7_5) c_7_6)))))
 (let (($x5392 (or $x5391 (and c_17_4 (or (or c_12_2 c_12_3 c_12_4 c_12_5) c_12_6)))))
 (let (($x5403 (or $x5392 (and c_17_5 (or (or c_31_2 c_31_3 c_31_4 c_31_5) c_31_6)))))
 (let (($x5192 (or c_17_2 c_17_3 c_17_4 c_17_5)))
 (let (($x5371 (or false (and c_16_2 (or (or c_28_2 c_28_3 c_28_4 c_28_5) c_28_6)))))
 (let (($x5380 (or $x5371 (and c_16_3 (or (or c_30_2 c_30_3 c_30_4 c_30_5) c_30_6)))))
 (let (($x5383 (or $x5380 (and c_16_4 (or (or c_8_2 c_8_3 c_8_4 c_8_5) c_8_6)))))
 (let (($x5385 (or $x5383 (and c_16_5 (or (or c_6_2 c_6_3 c_6_4 c_6_5) c_6_6)))))
 (let (($x5170 (or c_16_2 c_16_3 c_16_4 c_16_5)))
 (let (($x5352 (or false (and c_15_2 (or (or c_27_2 c_27_3 c_27_4 c_27_5) c_27_6)))))
 (let (($x5355 (or $x5352 (and c_15_3 (or (or c_5_2 c_5_3 c_5_4 c_5_5) c_5_6)))))
 (let (($x5357 (or $x5355 (and c_15_4 (or (or c_7_2 c_7_3 c_7_4 c_7_5) c_7_6)))))
 (let (($x5366 (or $x5357 (and c_15_5 (or (or c_29_2 c_29_3 c_29_4 c_29_5) c_29_6)))))
 (let (($x5156 (or c_15_2 c_15_3 c_15_4 c_15_5)))
 (let (($x5335 (or false (and c_14_2 (or (or c_26_2 c_26_3 c_26_4 c_26_5) c_26_6)))))
 (let (($x5344 (or $x5335 (and c_14_3 (or (or c_28_2 c_28_3 c_28_4 c_28_5) c_28_6)))))
 (let (($x5347 (or $x5344 (and c_14_4 (or (or c_6_2 c_6_3 c_6_4 c_6_5) c_6_6)))))
 (let (($x5348 (or $x5347 (and c_14_5 (or (or c_5_2 c_5_3 c_5_4 c_5_5) c_5_6)))))
 (let (($x5144 (or c_14_2 c_14_3 c_14_4 c_14_5)))
 (let (($x5308 (or false (and c_13_2 (or (or c_25_2 c_25_3 c_25_4 c_25_5) c_25_6)))))
 (let (($x5318 (or $x5308 (and c_13_3 (or (or c_26_2 c_26_3 c_26_4 c_26_5) c_26_6)))))
 (let (($x5321 (or $x5318 (and c_13_4 (or (or c_5_2 c_5_3 c_5_4 c_5_5) c_5_6)))))
 (let (($x5330 (or $x5321 (and c_13_5 (or (or c_27_2 c_27_3 c_27_4 c_27_5) c_27_6)))))
 (let (($x5134 (or c_13_2 c_13_3 c_13_4 c_13_5)))
 (let (($x5283 (or false (and c_12_2 (or $x5192 c_17_6)))))
 (let (($x5285 (or $x5283 (and c_12_3 (or $x5010 c_4_6)))))
 (let (($x5287 (or $x5285 (and c_12_4 (or $x5280 c_23_6)))))
 (let (($x5122 (or c_12_2 c_12_3 c_12_4 c_12_5)))
 (let (($x5265 (or false (and c_11_2 (or $x5010 c_4_6)))))
 (let (($x5267 (or $x5265 (and c_11_3 (or $x5000 c_3_6)))))
 (let (($x5269 (or $x5267 (and c_11_4 (or $x5262 c_22_6)))))
 (let (($x5104 (or c_11_2 c_11_3 c_11_4 c_11_5)))
 (let (($x5239 (or false (and c_10_2 (or $x5000 c_3_6)))))
 (let (($x5241 (or $x5239 (and c_10_3 (or $x5234 c_20_6)))))
 (let (($x5250 (or $x5241 (and c_10_4 (or $x5252 c_21_6)))))
 (let (($x5094 (or c_10_2 c_10_3 c_10_4 c_10_5)))
 (let (($x5221 (or false (and c_9_2 (or $x4990 c_2_6)))))
 (let (($x5223 (or $x5221 (and c_9_3 (or $x5216 c_19_6)))))
 (let (($x5232 (or $x5223 (and c_9_4 (or $x5234 c_20_6)))))
 (let (($x5076 (or c_9_2 c_9_3 c_9_4 c_9_5)))
 (let (($x5194 (or false (and c_8_2 (or $x5170 c_16_6)))))
 (let (($x5204 (or $x5194 (and c_8_3 (or $x5206 c_18_6)))))
 (let (($x5215 (or $x5204 (and c_8_4 (or $x5216 c_19_6)))))
 (let (($x5066 (or c_8_2 c_8_3 c_8_4 c_8_5)))
 (let (($x5176 (or false (and c_7_2 (or $x5156 c_15_6)))))
 (let (($x5179 (or $x5176 (and c_7_3 (or $x4980 c_1_6)))))
 (let (($x5181 (or $x5179 (and c_7_4 (or $x5010 c_4_6)))))
 (let (($x5052 (or c_7_2 c_7_3 c_7_4 c_7_5)))
 (let (($x5159 (or false (and c_6_2 (or $x5144 c_14_6)))))
 (let (($x5169 (or $x5159 (and c_6_3 (or $x5170 c_16_6)))))
 (let (($x5171 (or $x5169 (and c_6_4 (or $x4990 c_2_6)))))
 (let (($x5039 (or c_6_2 c_6_3 c_6_4 c_6_5)))
 (let (($x5132 (or false (and c_5_2 (or $x5134 c_13_6)))))
 (let (($x5143 (or $x5132 (and c_5_3 (or $x5144 c_14_6)))))
 (let (($x5145 (or $x5143 (and c_5_4 (or $x4980 c_1_6)))))
 (let (($x5029 (or c_5_2 c_5_3 c_5_4 c_5_5)))
 (let (($x5107 (or false (and c_4_2 (or $x5052 c_7_6)))))
 (let (($x5108 (or $x5107 (and c_4_3 (or $x5020 c_0_6)))))
 (let (($x5111 (or $x5108 (and c_4_4 (or $x5104 c_11_6)))))
 (let (($x5081 (or false (and c_3_2 (or $x5020 c_0_6)))))
 (let (($x5083 (or $x5081 (and c_3_3 (or $x5076 c_9_6)))))
 (let (($x5092 (or $x5083 (and c_3_4 (or $x5094 c_10_6)))))
 (let (($x5055 (or false (and c_2_2 (or $x5039 c_6_6)))))
 (let (($x5064 (or $x5055 (and c_2_3 (or $x5066 c_8_6)))))
 (let (($x5074 (or $x5064 (and c_2_4 (or $x5076 c_9_6)))))
 (let (($x5027 (or false (and c_1_2 (or $x5029 c_5_6)))))
 (let (($x5038 (or $x5027 (and c_1_3 (or $x5039 c_6_6)))))
 (let (($x5041 (or $x5038 (and c_1_4 (or $x5020 c_0_6)))))
 (let (($x4978 (or false (and c_0_2 (or $x4980 c_1_6)))))
 (let (($x4988 (or $x4978 (and c_0_3 (or $x4990 c_2_6)))))
 (let (($x4998 (or $x4988 (and c_0_4 (or $x5000 c_3_6)))))
 (let (($x4967 (not (and c_24_6 (not in_target_24)))))
 (let (($x4962 (not (and c_23_6 (not in_target_23)))))
 (let (($x4957 (not (and c_22_6 (not in_target_22)))))
 (let (($x4952 (not (and c_21_6 (not in_target_21)))))
 (let (($x4947 (not (and c_20_6 (not in_target_20)))))
 (let (($x4942 (not (and c_19_6 (not in_target_19)))))
 (let (($x4937 (not (and c_18_6 (not in_target_18)))))
 (let (($x4932 (not (and c_17_6 (not in_target_17)))))
 (let (($x4927 (not (and c_16_6 (not in_target_16)))))
 (let (($x4922 (not (and c_15_6 (not in_target_15)))))
 (let (($x4917 (not (and c_14_6 (not in_target_14)))))
 (let (($x4912 (not (and c_13_6 (not in_target_13)))))
 (let (($x4907 (not (and c_12_6 (not in_target_12)))))
 (let (($x4902 (not (and c_11_6 (not in_target_11)))))
 (let (($x4897 (not (and c_10_6 (not in_target_10)))))
 (let (($x4892 (not (and c_9_6 (not in_target_9)))))
 (let (($x4887 (not (and c_8_6 (not in_target_8)))))
 (let (($x4882 (not (and c_7_6 (not in_target_7)))))
 (let (($x4877 (not (and c_6_6 (not in_target_6)))))
 (let (($x4872 (not (and c_5_6 (not in_target_5)))))
 (let (($x4867 (not (and c_4_6 (not in_target_4)))))
 (let (($x4862 (not (and c_3_6 (not in_target_3)))))
 (let (($x4857 (not (and c_2_6 (not in_target_2)))))
 (let (($x4852 (not (and c_1_6 (not in_target_1)))))
 (let (($x4847 (not (and c_0_6 (not in_target_0)))))
 (let (($x4842 (or in_region_40 (and c_40_0 (not in_target_40)))))
 (let (($x4837 (or in_region_39 (and c_39_0 (not in_target_39)))))
 (let (($x4832 (or in_region_38 (and c_38_0 (not in_target_38)))))
 (let (($x4827 (or in_region_37 (and c_37_0 (not in_target_37)))))
 (let (($x4822 (or in_region_36 (and c_36_0 (not in_target_36)))))
 (let (($x4817 (or in_region_35 (and c_35_0 (not in_target_35)))))
 (let (($x4812 (or in_region_34 (and c_34_0 (not in_target_34)))))
 (let (($x4807 (or in_region_33 (and c_33_0 (not in_target_33)))))
 (let (($x4802 (or in_region_32 (and c_32_0 (not in_target_32)))))
 (let (($x4797 (or in_region_31 (and c_31_0 (not in_target_31)))))
 (let (($x4792 (or in_region_30 (and c_30_0 (not in_target_30)))))
 (let (($x4787 (or in_region_29 (and c_29_0 (not in_target_29)))))
 (let (($x4782 (or in_region_28 (and c_28_0 (not in_target_28)))))
 (let (($x4777 (or in_region_27 (and c_27_0 (not in_target_27)))))
 (let (($x4772 (or in_region_26 (and c_26_0 (not in_target_26)))))
 (let (($x4767 (or in_region_25 (and c_25_0 (not in_target_25)))))
 (let (($x4762 (or in_region_24 (and c_24_0 (not in_target_24)))))
 (let (($x4757 (or in_region_23 (and c_23_0 (not in_target_23)))))
 (let (($x4752 (or in_region_22 (and c_22_0 (not in_target_22)))))
 (let (($x4747 (or in_region_21 (and c_21_0 (not in_target_21)))))
 (let (($x4742 (or in_region_20 (and c_20_0 (not in_target_20)))))
 (let (($x4737 (or in_region_19 (and c_19_0 (not in_target_19)))))
 (let (($x4732 (or in_region_18 (and c_18_0 (not in_target_18)))))
 (let (($x4727 (or in_region_17 (and c_17_0 (not in_target_17)))))
 (let (($x4722 (or in_region_16 (and c_16_0 (not in_target_16)))))
 (let (($x4717 (or in_region_15 (and c_15_0 (not in_target_15)))))
 (let (($x4712 (or in_region_14 (and c_14_0 (not in_target_14)))))
 (let (($x4707 (or in_region_13 (and c_13_0 (not in_target_13)))))
 (let (($x4702 (or in_region_12 (and c_12_0 (not in_target_12)))))
 (let (($x4697 (or in_region_11 (and c_11_0 (not in_target_11)))))
 (let (($x4692 (or in_region_10 (and c_10_0 (not in_target_10)))))
 (let (($x4687 (or in_region_9 (and c_9_0 (not in_target_9)))))
 (let (($x4682 (or in_region_8 (and c_8_0 (not in_target_8)))))
 (let (($x4677 (or in_region_7 (and c_7_0 (not in_target_7)))))
 (let (($x4672 (or in_region_6 (and c_6_0 (not in_target_6)))))
 (let (($x4667 (or in_region_5 (and c_5_0 (not in_target_5)))))
 (let (($x4660 (not in_target_4)))
 (let (($x4661 (and c_4_0 $x4660)))
 (let (($x4662 (or in_region_4 $x4661)))
 (let (($x4655 (not in_target_3)))
 (let (($x4656 (and c_3_0 $x4655)))
 (let (($x4657 (or in_region_3 $x4656)))
 (let (($x4650 (not in_target_2)))
 (let (($x4651 (and c_2_0 $x4650)))
 (let (($x4652 (or in_region_2 $x4651)))
 (let (($x4645 (not in_target_1)))
 (let (($x4646 (and c_1_0 $x4645)))
 (let (($x4647 (or in_region_1 $x4646)))
 (let (($x4640 (not in_target_0)))
 (let (($x4641 (and c_0_0 $x4640)))
 (let (($x4642 (or in_region_0 $x4641)))
 (let (($x4643 (and true $x4642)))
 (let (($x4648 (and $x4643 $x4647)))
 (let (($x4653 (and $x4648 $x4652)))
 (let (($x4658 (and $x4653 $x4657)))
 (let (($x4663 (and $x4658 $x4662)))
 (let (($x4668 (and $x4663 $x4667)))
 (let (($x4673 (and $x4668 $x4672)))
 (let (($x4678 (and $x4673 $x4677)))
 (let (($x4683 (and $x4678 $x4682)))
 (let (($x4688 (and $x4683 $x4687)))
 (let (($x4693 (and $x4688 $x4692)))
 (let (($x4698 (and $x4693 $x4697)))
 (let (($x4703 (and $x4698 $x4702)))
 (let (($x4708 (and $x4703 $x4707)))
 (let (($x4713 (and $x4708 $x4712)))
 (let (($x4718 (and $x4713 $x4717)))
 (let (($x4723 (and $x4718 $x4722)))
 (let (($x4728 (and $x4723 $x4727)))
 (let (($x4733 (and $x4728 $x4732)))
 (let (($x4738 (and $x4733 $x4737)))
 (let (($x4743 (and $x4738 $x4742)))
 (let (($x4748 (and $x4743 $x4747)))
 (let (($x4753 (and $x4748 $x4752)))
 (let (($x4758 (and $x4753 $x4757)))
 (let (($x4763 (and $x4758 $x4762)))
 (let (($x4768 (and $x4763 $x4767)))
 (let (($x4773 (and $x4768 $x4772)))
 (let (($x4778 (and $x4773 $x4777)))
 (let (($x4783 (and $x4778 $x4782)))
 (let (($x4788 (and $x4783 $x4787)))
 (let (($x4793 (and $x4788 $x4792)))
 (let (($x4798 (and $x4793 $x4797)))
 (let (($x4803 (and $x4798 $x4802)))
 (let (($x4808 (and $x4803 $x4807)))
 (let (($x4813 (and $x4808 $x4812)))
 (let (($x4818 (and $x4813 $x4817)))
 (let (($x4823 (and $x4818 $x4822)))
 (let (($x4828 (and $x4823 $x4827)))
 (let (($x4833 (and $x4828 $x4832)))
 (let (($x4838 (and $x4833 $x4837)))
 (let (($x4843 (and $x4838 $x4842)))
 (let (($x4844 (and $x4843 in_region_0)))
 (let (($x4848 (and $x4844 $x4847)))
 (let (($x4853 (and $x4848 $x4852)))
 (let (($x4858 (and $x4853 $x4857)))
 (let (($x4863 (and $x4858 $x4862)))
 (let (($x4868 (and $x4863 $x4867)))
 (let (($x4873 (and $x4868 $x4872)))
 (let (($x4878 (and $x4873 $x4877)))
 (let (($x4883 (and $x4878 $x4882)))
 (let (($x4888 (and $x4883 $x4887)))
 (let (($x4893 (and $x4888 $x4892)))
 (let (($x4898 (and $x4893 $x4897)))
 (let (($x4903 (and $x4898 $x4902)))
 (let (($x4908 (and $x4903 $x4907)))
 (let (($x4913 (and $x4908 $x4912)))
 (let (($x4918 (and $x4913 $x4917)))
 (let (($x4923 (and $x4918 $x4922)))
 (let (($x4928 (and $x4923 $x4927)))
 (let (($x4933 (and $x4928 $x4932)))
 (let (($x4938 (and $x4933 $x4937)))
 (let (($x4943 (and $x4938 $x4942)))
 (let (($x4948 (and $x4943 $x4947)))
 (let (($x4953 (and $x4948 $x4952)))
 (let (($x4958 (and $x4953 $x4957)))
 (let (($x4963 (and $x4958 $x4962)))
 (let (($x4968 (and $x4963 $x4967)))
 (let (($x5017 (and $x4968 (=> $x5020 (or $x4998 (and c_0_5 (or $x5010 c_4_6)))))))
 (let (($x5053 (and $x5017 (=> $x4980 (or $x5041 (and c_1_5 (or $x5052 c_7_6)))))))
 (let (($x5079 (and $x5053 (=> $x4990 (or $x5074 (and c_2_5 (or $x5020 c_0_6)))))))
 (let (($x5105 (and $x5079 (=> $x5000 (or $x5092 (and c_3_5 (or $x5104 c_11_6)))))))
 (let (($x5123 (and $x5105 (=> $x5010 (or $x5111 (and c_4_5 (or $x5122 c_12_6)))))))
 (let (($x5157 (and $x5123 (=> $x5029 (or $x5145 (and c_5_5 (or $x5156 c_15_6)))))))
 (let (($x5175 (and $x5157 (=> $x5039 (or $x5171 (and c_6_5 (or $x4980 c_1_6)))))))
 (let (($x5193 (and $x5175 (=> $x5052 (or $x5181 (and c_7_5 (or $x5192 c_17_6)))))))
 (let (($x5219 (and $x5193 (=> $x5066 (or $x5215 (and c_8_5 (or $x4990 c_2_6)))))))
 (let (($x5237 (and $x5219 (=> $x5076 (or $x5232 (and c_9_5 (or $x5000 c_3_6)))))))
 (let (($x5263 (and $x5237 (=> $x5094 (or $x5250 (and c_10_5 (or $x5262 c_22_6)))))))
 (let (($x5281 (and $x5263 (=> $x5104 (or $x5269 (and c_11_5 (or $x5280 c_23_6)))))))
 (let (($x5299 (and $x5281 (=> $x5122 (or $x5287 (and c_12_5 (or $x5298 c_24_6)))))))
 (let (($x5333 (and $x5299 (=> $x5134 $x5330))))
 (let (($x5351 (and $x5333 (=> $x5144 $x5348))))
 (let (($x5369 (and $x5351 (=> $x5156 $x5366))))
 (let (($x5386 (and $x5369 (=> $x5170 $x5385))))
 (let (($x5405 (and $x5386 (=> $x5192 $x5403))))
 (let (($x5431 (and $x5405 (=> $x5206 $x5429))))
 (let (($x5449 (and $x5431 (=> $x5216 $x5447))))
 (let (($x5467 (and $x5449 (=> $x5234 $x5465))))
 (let (($x5493 (and $x5467 (=> $x5252 $x5490))))
 (let (($x5511 (and $x5493 (=> $x5262 $x5508))))
 (let (($x5529 (and $x5511 (=> $x5280 $x5527))))
 (let (($x5547 (and $x5529 (=> $x5298 $x5545))))
 (let (($x5645 (and $x5547 (and (=> (and c_0_1 $x5640) (= ghost_1_0 0)) (=> $x5642 $x5639)))))
 (let (($x5691 (and $x5645 (and (=> (and c_1_1 $x5595) (= ghost_1_1 0)) (=> $x5597 $x5686)))))
 (let (($x5730 (and $x5691 (and (=> (and c_2_1 $x5608) (= ghost_1_2 0)) (=> $x5607 $x5727)))))
 (let (($x5770 (and $x5730 (and (=> (and c_3_1 $x5618) (= ghost_1_3 0)) (=> $x5617 $x5767)))))
 (let (($x5805 (and $x5770 (and (=> (and c_4_1 $x5628) (= ghost_1_4 0)) (=> $x5627 $x5802)))))
 (let (($x5850 (and $x5805 (and (=> (and c_5_1 $x5652) (= ghost_1_5 0)) (=> $x5653 $x5847)))))
 (let (($x5886 (and $x5850 (and (=> (and c_6_1 $x5664) (= ghost_1_6 0)) (=> $x5662 $x5881)))))
 (let (($x5921 (and $x5886 (and (=> (and c_7_1 $x5679) (= ghost_1_7 0)) (=> $x5677 $x5916)))))
 (let (($x5961 (and $x5921 (and (=> (and c_8_1 $x5704) (= ghost_1_8 0)) (=> $x5702 $x5956)))))
 (let (($x5995 (and $x5961 (and (=> (and c_9_1 $x5714) (= ghost_1_9 0)) (=> $x5713 $x5992)))))
 (let (($x6035 (and $x5995 $x6034)))
 (let (($x6070 (and $x6035 $x6069)))
 (let (($x6105 (and $x6070 $x6104)))
 (let (($x6150 (and $x6105 $x6149)))
 (let (($x6186 (and $x6150 (and (=> (and c_14_1 $x5824) (= ghost_1_14 0)) (=> $x5822 $x6181)))))
 (let (($x6220 (and $x6186 $x6219)))
 (let (($x6256 (and $x6220 (and (=> (and c_16_1 $x5864) (= ghost_1_16 0)) (=> $x5862 $x6251)))))
 (let (($x6290 (and $x6256 $x6289)))
 (let (($x6330 (and $x6290 (and (=> (and c_18_1 $x5934) (= ghost_1_18 0)) (=> $x5933 $x6327)))))
 (let (($x6366 (and $x6330 (and (=> (and c_19_1 $x5944) (= ghost_1_19 0)) (=> $x5942 $x6361)))))
 (let (($x6400 (and $x6366 $x6399)))
 (let (($x6441 (and $x6400 $x6439)))
 (let (($x6475 (and $x6441 $x6474)))
 (let (($x6510 (and $x6475 $x6509)))
 (let (($x9232 (and (and $x6510 $x6544) $x9231)))
 (=> instance_0 $x9232))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(assert
 (or instance_0))
(check-sat)
