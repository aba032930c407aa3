; holon proof obligation: system hex_growth, region hex:r2, property mass_conservation
; expected: unsat (the property holds for every configuration of the region)
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
(declare-fun in_target_9 () Bool)
(declare-fun rule_instance () Int)
(assert
 (let (($x25 (or false c_0_0)))
 (let (($x27 (or $x25 c_0_1)))
 (let (($x29 (or $x27 c_0_2)))
 (or $x29 c_0_3)))))
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
 (let (($x45 (or false c_1_0)))
 (let (($x47 (or $x45 c_1_1)))
 (let (($x49 (or $x47 c_1_2)))
 (or $x49 c_1_3)))))
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
 (let (($x65 (or false c_2_0)))
 (let (($x67 (or $x65 c_2_1)))
 (let (($x69 (or $x67 c_2_2)))
 (or $x69 c_2_3)))))
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
 (let (($x85 (or false c_3_0)))
 (let (($x87 (or $x85 c_3_1)))
 (let (($x89 (or $x87 c_3_2)))
 (or $x89 c_3_3)))))
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
 (let (($x105 (or false c_4_0)))
 (let (($x107 (or $x105 c_4_1)))
 (let (($x109 (or $x107 c_4_2)))
 (or $x109 c_4_3)))))
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
 (let (($x125 (or false c_5_0)))
 (let (($x127 (or $x125 c_5_1)))
 (let (($x129 (or $x127 c_5_2)))
 (or $x129 c_5_3)))))
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
 (let (($x145 (or false c_6_0)))
 (let (($x147 (or $x145 c_6_1)))
 (let (($x149 (or $x147 c_6_2)))
 (or $x149 c_6_3)))))
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
 (let (($x165 (or false c_7_0)))
 (let (($x167 (or $x165 c_7_1)))
 (let (($x169 (or $x167 c_7_2)))
 (or $x169 c_7_3)))))
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
 (let (($x185 (or false c_8_0)))
 (let (($x187 (or $x185 c_8_1)))
 (let (($x189 (or $x187 c_8_2)))
 (or $x189 c_8_3)))))
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
 (let (($x205 (or false c_9_0)))
 (let (($x207 (or $x205 c_9_1)))
 (let (($x209 (or $x207 c_9_2)))
 (or $x209 c_9_3)))))
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
 (let (($x225 (or false c_10_0)))
 (let (($x227 (or $x225 c_10_1)))
 (let (($x229 (or $x227 c_10_2)))
 (or $x229 c_10_3)))))
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
 (let (($x245 (or false c_11_0)))
 (let (($x247 (or $x245 c_11_1)))
 (let (($x249 (or $x247 c_11_2)))
 (or $x249 c_11_3)))))
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
 (let (($x265 (or false c_12_0)))
 (let (($x267 (or $x265 c_12_1)))
 (let (($x269 (or $x267 c_12_2)))
 (or $x269 c_12_3)))))
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
 (let (($x285 (or false c_13_0)))
 (let (($x287 (or $x285 c_13_1)))
 (let (($x289 (or $x287 c_13_2)))
 (or $x289 c_13_3)))))
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
 (let (($x305 (or false c_14_0)))
 (let (($x307 (or $x305 c_14_1)))
 (let (($x309 (or $x307 c_14_2)))
 (or $x309 c_14_3)))))
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
 (let (($x325 (or false c_15_0)))
 (let (($x327 (or $x325 c_15_1)))
 (let (($x329 (or $x327 c_15_2)))
 (or $x329 c_15_3)))))
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
 (let (($x345 (or false c_16_0)))
 (let (($x347 (or $x345 c_16_1)))
 (let (($x349 (or $x347 c_16_2)))
 (or $x349 c_16_3)))))
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
 (let (($x365 (or false c_17_0)))
 (let (($x367 (or $x365 c_17_1)))
 (let (($x369 (or $x367 c_17_2)))
 (or $x369 c_17_3)))))
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
 (let (($x385 (or false c_18_0)))
 (let (($x387 (or $x385 c_18_1)))
 (let (($x389 (or $x387 c_18_2)))
 (or $x389 c_18_3)))))
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
 (let (($x405 (or false d_0_0)))
 (let (($x407 (or $x405 d_0_1)))
 (let (($x409 (or $x407 d_0_2)))
 (or $x409 d_0_3)))))
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
 (let (($x425 (or false d_1_0)))
 (let (($x427 (or $x425 d_1_1)))
 (let (($x429 (or $x427 d_1_2)))
 (or $x429 d_1_3)))))
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
 (let (($x445 (or false d_2_0)))
 (let (($x447 (or $x445 d_2_1)))
 (let (($x449 (or $x447 d_2_2)))
 (or $x449 d_2_3)))))
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
 (let (($x465 (or false d_3_0)))
 (let (($x467 (or $x465 d_3_1)))
 (let (($x469 (or $x467 d_3_2)))
 (or $x469 d_3_3)))))
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
 (let (($x485 (or false d_4_0)))
 (let (($x487 (or $x485 d_4_1)))
 (let (($x489 (or $x487 d_4_2)))
 (or $x489 d_4_3)))))
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
 (let (($x505 (or false d_5_0)))
 (let (($x507 (or $x505 d_5_1)))
 (let (($x509 (or $x507 d_5_2)))
 (or $x509 d_5_3)))))
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
 (let (($x525 (or false d_6_0)))
 (let (($x527 (or $x525 d_6_1)))
 (let (($x529 (or $x527 d_6_2)))
 (or $x529 d_6_3)))))
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
 (let (($x545 (or false d_7_0)))
 (let (($x547 (or $x545 d_7_1)))
 (let (($x549 (or $x547 d_7_2)))
 (or $x549 d_7_3)))))
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
 (let (($x565 (or false d_8_0)))
 (let (($x567 (or $x565 d_8_1)))
 (let (($x569 (or $x567 d_8_2)))
 (or $x569 d_8_3)))))
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
 (let (($x585 (or false d_9_0)))
 (let (($x587 (or $x585 d_9_1)))
 (let (($x589 (or $x587 d_9_2)))
 (or $x589 d_9_3)))))
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
 (let (($x605 (or false d_10_0)))
 (let (($x607 (or $x605 d_10_1)))
 (let (($x609 (or $x607 d_10_2)))
 (or $x609 d_10_3)))))
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
 (let (($x625 (or false d_11_0)))
 (let (($x627 (or $x625 d_11_1)))
 (let (($x629 (or $x627 d_11_2)))
 (or $x629 d_11_3)))))
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
 (let (($x645 (or false d_12_0)))
 (let (($x647 (or $x645 d_12_1)))
 (let (($x649 (or $x647 d_12_2)))
 (or $x649 d_12_3)))))
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
 (let (($x665 (or false d_13_0)))
 (let (($x667 (or $x665 d_13_1)))
 (let (($x669 (or $x667 d_13_2)))
 (or $x669 d_13_3)))))
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
 (let (($x685 (or false d_14_0)))
 (let (($x687 (or $x685 d_14_1)))
 (let (($x689 (or $x687 d_14_2)))
 (or $x689 d_14_3)))))
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
 (let (($x705 (or false d_15_0)))
 (let (($x707 (or $x705 d_15_1)))
 (let (($x709 (or $x707 d_15_2)))
 (or $x709 d_15_3)))))
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
 (let (($x725 (or false d_16_0)))
 (let (($x727 (or $x725 d_16_1)))
 (let (($x729 (or $x727 d_16_2)))
 (or $x729 d_16_3)))))
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
 (let (($x745 (or false d_17_0)))
 (let (($x747 (or $x745 d_17_1)))
 (let (($x749 (or $x747 d_17_2)))
 (or $x749 d_17_3)))))
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
 (let (($x765 (or false d_18_0)))
 (let (($x767 (or $x765 d_18_1)))
 (let (($x769 (or $x767 d_18_2)))
 (or $x769 d_18_3)))))
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
 (let ((?x1232 (+ 0 (+ 0 (ite d_9_1 1 0)))))
 (let ((?x1237 (+ ?x1232 (+ 0 (ite d_10_1 1 0)))))
 (let ((?x1242 (+ ?x1237 (+ 0 (ite d_5_1 1 0)))))
 (let ((?x1247 (+ ?x1242 (+ 0 (ite d_4_1 1 0)))))
 (let ((?x1252 (+ ?x1247 (+ 0 (ite d_8_1 1 0)))))
 (let ((?x1257 (+ ?x1252 (+ 0 (ite d_13_1 1 0)))))
 (let ((?x1262 (+ ?x1257 (+ 0 (ite d_14_1 1 0)))))
 (let ((?x1267 (+ ?x1262 (+ 0 (ite d_11_1 1 0)))))
 (let ((?x1272 (+ ?x1267 (+ 0 (ite d_6_1 1 0)))))
 (let ((?x1277 (+ ?x1272 (+ 0 (ite d_2_1 1 0)))))
 (let ((?x1282 (+ ?x1277 (+ 0 (ite d_1_1 1 0)))))
 (let ((?x1287 (+ ?x1282 (+ 0 (ite d_0_1 1 0)))))
 (let ((?x1292 (+ ?x1287 (+ 0 (ite d_3_1 1 0)))))
 (let ((?x1297 (+ ?x1292 (+ 0 (ite d_7_1 1 0)))))
 (let ((?x1302 (+ ?x1297 (+ 0 (ite d_12_1 1 0)))))
 (let ((?x1307 (+ ?x1302 (+ 0 (ite d_16_1 1 0)))))
 (let ((?x1312 (+ ?x1307 (+ 0 (ite d_17_1 1 0)))))
 (let ((?x1317 (+ ?x1312 (+ 0 (ite d_18_1 1 0)))))
 (let ((?x934 (ite c_9_1 1 0)))
 (let ((?x935 (+ 0 ?x934)))
 (let ((?x1229 (+ 0 ?x935)))
 (let ((?x1234 (+ ?x1229 (+ 0 (ite c_10_1 1 0)))))
 (let ((?x1239 (+ ?x1234 (+ 0 (ite c_5_1 1 0)))))
 (let ((?x1244 (+ ?x1239 (+ 0 (ite c_4_1 1 0)))))
 (let ((?x1249 (+ ?x1244 (+ 0 (ite c_8_1 1 0)))))
 (let ((?x1254 (+ ?x1249 (+ 0 (ite c_13_1 1 0)))))
 (let ((?x1259 (+ ?x1254 (+ 0 (ite c_14_1 1 0)))))
 (let ((?x1264 (+ ?x1259 (+ 0 (ite c_11_1 1 0)))))
 (let ((?x1269 (+ ?x1264 (+ 0 (ite c_6_1 1 0)))))
 (let ((?x1274 (+ ?x1269 (+ 0 (ite c_2_1 1 0)))))
 (let ((?x1279 (+ ?x1274 (+ 0 (ite c_1_1 1 0)))))
 (let ((?x1284 (+ ?x1279 (+ 0 (ite c_0_1 1 0)))))
 (let ((?x1289 (+ ?x1284 (+ 0 (ite c_3_1 1 0)))))
 (let ((?x1294 (+ ?x1289 (+ 0 (ite c_7_1 1 0)))))
 (let ((?x1299 (+ ?x1294 (+ 0 (ite c_12_1 1 0)))))
 (let ((?x1304 (+ ?x1299 (+ 0 (ite c_16_1 1 0)))))
 (let ((?x1309 (+ ?x1304 (+ 0 (ite c_17_1 1 0)))))
 (let ((?x1314 (+ ?x1309 (+ 0 (ite c_18_1 1 0)))))
 (let (($x1325 (and (distinct (+ ?x1314 (+ 0 (ite c_15_1 1 0))) (+ ?x1317 (+ 0 (ite d_15_1 1 0)))) true)))
 (let (($x1219 (and true (=> c_15_0 d_15_1))))
 (let (($x1221 (and $x1219 (=> c_15_1 d_15_1))))
 (let (($x1223 (and $x1221 (=> c_15_2 d_15_1))))
 (let (($x1210 (and true (=> c_18_0 d_18_1))))
 (let (($x1212 (and $x1210 (=> c_18_1 d_18_1))))
 (let (($x1214 (and $x1212 (=> c_18_2 d_18_1))))
 (let (($x1201 (and true (=> c_17_0 d_17_1))))
 (let (($x1203 (and $x1201 (=> c_17_1 d_17_1))))
 (let (($x1205 (and $x1203 (=> c_17_2 d_17_1))))
 (let (($x1192 (and true (=> c_16_0 d_16_1))))
 (let (($x1194 (and $x1192 (=> c_16_1 d_16_1))))
 (let (($x1196 (and $x1194 (=> c_16_2 d_16_1))))
 (let (($x1183 (and true (=> c_12_0 d_12_1))))
 (let (($x1185 (and $x1183 (=> c_12_1 d_12_1))))
 (let (($x1187 (and $x1185 (=> c_12_2 d_12_1))))
 (let (($x1174 (and true (=> c_7_0 d_7_1))))
 (let (($x1176 (and $x1174 (=> c_7_1 d_7_1))))
 (let (($x1178 (and $x1176 (=> c_7_2 d_7_1))))
 (let (($x1165 (and true (=> c_3_0 d_3_1))))
 (let (($x1167 (and $x1165 (=> c_3_1 d_3_1))))
 (let (($x1169 (and $x1167 (=> c_3_2 d_3_1))))
 (let (($x1156 (and true (=> c_0_0 d_0_1))))
 (let (($x1158 (and $x1156 (=> c_0_1 d_0_1))))
 (let (($x1160 (and $x1158 (=> c_0_2 d_0_1))))
 (let (($x1147 (and true (=> c_1_0 d_1_1))))
 (let (($x1149 (and $x1147 (=> c_1_1 d_1_1))))
 (let (($x1151 (and $x1149 (=> c_1_2 d_1_1))))
 (let (($x1138 (and true (=> c_2_0 d_2_1))))
 (let (($x1140 (and $x1138 (=> c_2_1 d_2_1))))
 (let (($x1142 (and $x1140 (=> c_2_2 d_2_1))))
 (let (($x1129 (and true (=> c_6_0 d_6_1))))
 (let (($x1131 (and $x1129 (=> c_6_1 d_6_1))))
 (let (($x1133 (and $x1131 (=> c_6_2 d_6_1))))
 (let (($x1120 (and true (=> c_11_0 d_11_1))))
 (let (($x1122 (and $x1120 (=> c_11_1 d_11_1))))
 (let (($x1124 (and $x1122 (=> c_11_2 d_11_1))))
 (let (($x1111 (and true (=> c_14_0 d_14_2))))
 (let (($x1113 (and $x1111 (=> c_14_1 d_14_2))))
 (let (($x1115 (and $x1113 (=> c_14_2 d_14_2))))
 (let (($x1102 (and true (=> c_13_0 d_13_2))))
 (let (($x1104 (and $x1102 (=> c_13_1 d_13_2))))
 (let (($x1106 (and $x1104 (=> c_13_2 d_13_2))))
 (let (($x1093 (and true (=> c_8_0 d_8_2))))
 (let (($x1095 (and $x1093 (=> c_8_1 d_8_2))))
 (let (($x1097 (and $x1095 (=> c_8_2 d_8_2))))
 (let (($x1084 (and true (=> c_4_0 d_4_2))))
 (let (($x1086 (and $x1084 (=> c_4_1 d_4_2))))
 (let (($x1088 (and $x1086 (=> c_4_2 d_4_2))))
 (let (($x1075 (and true (=> c_5_0 d_5_2))))
 (let (($x1077 (and $x1075 (=> c_5_1 d_5_2))))
 (let (($x1079 (and $x1077 (=> c_5_2 d_5_2))))
 (let (($x1066 (and true (=> c_10_0 d_10_2))))
 (let (($x1068 (and $x1066 (=> c_10_1 d_10_2))))
 (let (($x1070 (and $x1068 (=> c_10_2 d_10_2))))
 (let (($x1057 (and true (=> c_9_0 d_9_3))))
 (let (($x1059 (and $x1057 (=> c_9_1 d_9_3))))
 (let (($x1061 (and $x1059 (=> c_9_2 d_9_3))))
 (let ((?x1049 (ite (or c_15_2 c_15_3) 1 0)))
 (let ((?x1047 (ite (or c_18_2 c_18_3) 1 0)))
 (let ((?x1045 (ite (or c_17_2 c_17_3) 1 0)))
 (let ((?x1043 (ite (or c_16_2 c_16_3) 1 0)))
 (let ((?x1041 (ite (or c_12_2 c_12_3) 1 0)))
 (let ((?x1039 (ite (or c_7_2 c_7_3) 1 0)))
 (let ((?x1037 (ite (or c_3_2 c_3_3) 1 0)))
 (let ((?x1035 (ite (or c_0_2 c_0_3) 1 0)))
 (let ((?x1033 (ite (or c_1_2 c_1_3) 1 0)))
 (let ((?x1031 (ite (or c_2_2 c_2_3) 1 0)))
 (let ((?x1029 (ite (or c_6_2 c_6_3) 1 0)))
 (let ((?x1027 (ite (or c_11_2 c_11_3) 1 0)))
 (let ((?x1025 (ite (or c_14_2 c_14_3) 1 0)))
 (let ((?x1023 (ite (or c_13_2 c_13_3) 1 0)))
 (let ((?x1021 (ite (or c_8_2 c_8_3) 1 0)))
 (let ((?x1019 (ite (or c_4_2 c_4_3) 1 0)))
 (let ((?x1017 (ite (or c_5_2 c_5_3) 1 0)))
 (let ((?x1015 (ite (or c_10_2 c_10_3) 1 0)))
 (let ((?x1011 (ite (or c_9_2 c_9_3) 1 0)))
 (let ((?x1013 (+ 0 ?x1011)))
 (let ((?x1016 (+ ?x1013 ?x1015)))
 (let ((?x1018 (+ ?x1016 ?x1017)))
 (let ((?x1020 (+ ?x1018 ?x1019)))
 (let ((?x1022 (+ ?x1020 ?x1021)))
 (let ((?x1024 (+ ?x1022 ?x1023)))
 (let ((?x1026 (+ ?x1024 ?x1025)))
 (let ((?x1028 (+ ?x1026 ?x1027)))
 (let ((?x1030 (+ ?x1028 ?x1029)))
 (let ((?x1032 (+ ?x1030 ?x1031)))
 (let ((?x1034 (+ ?x1032 ?x1033)))
 (let ((?x1036 (+ ?x1034 ?x1035)))
 (let ((?x1038 (+ ?x1036 ?x1037)))
 (let ((?x1040 (+ ?x1038 ?x1039)))
 (let ((?x1042 (+ ?x1040 ?x1041)))
 (let ((?x1044 (+ ?x1042 ?x1043)))
 (let ((?x1046 (+ ?x1044 ?x1045)))
 (let ((?x1048 (+ ?x1046 ?x1047)))
 (let ((?x970 (ite c_15_1 1 0)))
 (let ((?x968 (ite c_18_1 1 0)))
 (let ((?x966 (ite c_17_1 1 0)))
 (let ((?x964 (ite c_16_1 1 0)))
 (let ((?x962 (ite c_12_1 1 0)))
 (let ((?x960 (ite c_7_1 1 0)))
 (let ((?x958 (ite c_3_1 1 0)))
 (let ((?x956 (ite c_0_1 1 0)))
 (let ((?x954 (ite c_1_1 1 0)))
 (let ((?x952 (ite c_2_1 1 0)))
 (let ((?x950 (ite c_6_1 1 0)))
 (let ((?x948 (ite c_11_1 1 0)))
 (let ((?x946 (ite c_14_1 1 0)))
 (let ((?x944 (ite c_13_1 1 0)))
 (let ((?x942 (ite c_8_1 1 0)))
 (let ((?x940 (ite c_4_1 1 0)))
 (let ((?x938 (ite c_5_1 1 0)))
 (let ((?x936 (ite c_10_1 1 0)))
 (let ((?x937 (+ ?x935 ?x936)))
 (let ((?x939 (+ ?x937 ?x938)))
 (let ((?x941 (+ ?x939 ?x940)))
 (let ((?x943 (+ ?x941 ?x942)))
 (let ((?x945 (+ ?x943 ?x944)))
 (let ((?x947 (+ ?x945 ?x946)))
 (let ((?x949 (+ ?x947 ?x948)))
 (let ((?x951 (+ ?x949 ?x950)))
 (let ((?x953 (+ ?x951 ?x952)))
 (let ((?x955 (+ ?x953 ?x954)))
 (let ((?x957 (+ ?x955 ?x956)))
 (let ((?x959 (+ ?x957 ?x958)))
 (let ((?x961 (+ ?x959 ?x960)))
 (let ((?x963 (+ ?x961 ?x962)))
 (let ((?x965 (+ ?x963 ?x964)))
 (let ((?x967 (+ ?x965 ?x966)))
 (let ((?x969 (+ ?x967 ?x968)))
 (let (($x1054 (and (= (to_real (+ ?x969 ?x970)) 12.0) (= (to_real (+ ?x1048 ?x1049)) 0.0))))
 (let (($x933 (or c_15_0 c_15_1 c_15_2 c_15_3)))
 (let (($x925 (or c_18_0 c_18_1 c_18_2 c_18_3)))
 (let (($x917 (or c_17_0 c_17_1 c_17_2 c_17_3)))
 (let (($x909 (or c_16_0 c_16_1 c_16_2 c_16_3)))
 (let (($x901 (or c_12_0 c_12_1 c_12_2 c_12_3)))
 (let (($x893 (or c_7_0 c_7_1 c_7_2 c_7_3)))
 (let (($x885 (or c_3_0 c_3_1 c_3_2 c_3_3)))
 (let (($x877 (or c_0_0 c_0_1 c_0_2 c_0_3)))
 (let (($x869 (or c_1_0 c_1_1 c_1_2 c_1_3)))
 (let (($x861 (or c_2_0 c_2_1 c_2_2 c_2_3)))
 (let (($x853 (or c_6_0 c_6_1 c_6_2 c_6_3)))
 (let (($x845 (or c_11_0 c_11_1 c_11_2 c_11_3)))
 (let (($x837 (or c_14_0 c_14_1 c_14_2 c_14_3)))
 (let (($x829 (or c_13_0 c_13_1 c_13_2 c_13_3)))
 (let (($x821 (or c_8_0 c_8_1 c_8_2 c_8_3)))
 (let (($x813 (or c_4_0 c_4_1 c_4_2 c_4_3)))
 (let (($x805 (or c_5_0 c_5_1 c_5_2 c_5_3)))
 (let (($x797 (or c_10_0 c_10_1 c_10_2 c_10_3)))
 (let (($x789 (and c_9_1 in_target_9)))
 (let (($x785 (and true $x789)))
 (let (($x793 (and $x785 $x797)))
 (let (($x801 (and $x793 $x805)))
 (let (($x809 (and $x801 $x813)))
 (let (($x817 (and $x809 $x821)))
 (let (($x825 (and $x817 $x829)))
 (let (($x833 (and $x825 $x837)))
 (let (($x841 (and $x833 $x845)))
 (let (($x849 (and $x841 $x853)))
 (let (($x857 (and $x849 $x861)))
 (let (($x865 (and $x857 $x869)))
 (let (($x873 (and $x865 $x877)))
 (let (($x881 (and $x873 $x885)))
 (let (($x889 (and $x881 $x893)))
 (let (($x897 (and $x889 $x901)))
 (let (($x905 (and $x897 $x909)))
 (let (($x913 (and $x905 $x917)))
 (let (($x921 (and $x913 $x925)))
 (let (($x929 (and $x921 $x933)))
 (let (($x1055 (and $x929 $x1054)))
 (let (($x1064 (and $x1055 (and $x1061 (=> c_9_3 d_9_3)))))
 (let (($x1073 (and $x1064 (and $x1070 (=> c_10_3 d_10_2)))))
 (let (($x1082 (and $x1073 (and $x1079 (=> c_5_3 d_5_2)))))
 (let (($x1091 (and $x1082 (and $x1088 (=> c_4_3 d_4_2)))))
 (let (($x1100 (and $x1091 (and $x1097 (=> c_8_3 d_8_2)))))
 (let (($x1109 (and $x1100 (and $x1106 (=> c_13_3 d_13_2)))))
 (let (($x1118 (and $x1109 (and $x1115 (=> c_14_3 d_14_2)))))
 (let (($x1127 (and $x1118 (and $x1124 (=> c_11_3 d_11_1)))))
 (let (($x1136 (and $x1127 (and $x1133 (=> c_6_3 d_6_1)))))
 (let (($x1145 (and $x1136 (and $x1142 (=> c_2_3 d_2_1)))))
 (let (($x1154 (and $x1145 (and $x1151 (=> c_1_3 d_1_1)))))
 (let (($x1163 (and $x1154 (and $x1160 (=> c_0_3 d_0_1)))))
 (let (($x1172 (and $x1163 (and $x1169 (=> c_3_3 d_3_1)))))
 (let (($x1181 (and $x1172 (and $x1178 (=> c_7_3 d_7_1)))))
 (let (($x1190 (and $x1181 (and $x1187 (=> c_12_3 d_12_1)))))
 (let (($x1199 (and $x1190 (and $x1196 (=> c_16_3 d_16_1)))))
 (let (($x1208 (and $x1199 (and $x1205 (=> c_17_3 d_17_1)))))
 (let (($x1217 (and $x1208 (and $x1214 (=> c_18_3 d_18_1)))))
 (let (($x1228 (and (and true (and $x1217 (and $x1223 (=> c_15_3 d_15_1)))) true)))
 (let (($x1323 (= rule_instance 0)))
 (or false (and (and $x1323 $x1228) $x1325)))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
