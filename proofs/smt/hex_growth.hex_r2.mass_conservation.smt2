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
 (let ((?x1395 (ite d_15_1 1 0)))
 (let ((?x1380 (ite d_18_1 1 0)))
 (let ((?x1365 (ite d_17_1 1 0)))
 (let ((?x1350 (ite d_16_1 1 0)))
 (let ((?x1335 (ite d_12_1 1 0)))
 (let ((?x1320 (ite d_7_1 1 0)))
 (let ((?x1305 (ite d_3_1 1 0)))
 (let ((?x1290 (ite d_0_1 1 0)))
 (let ((?x1275 (ite d_1_1 1 0)))
 (let ((?x1260 (ite d_2_1 1 0)))
 (let ((?x1245 (ite d_6_1 1 0)))
 (let ((?x1230 (ite d_11_1 1 0)))
 (let ((?x1215 (ite d_14_1 1 0)))
 (let ((?x1200 (ite d_13_1 1 0)))
 (let ((?x1185 (ite d_8_1 1 0)))
 (let ((?x1170 (ite d_4_1 1 0)))
 (let ((?x1155 (ite d_5_1 1 0)))
 (let ((?x1140 (ite d_10_1 1 0)))
 (let ((?x1125 (ite d_9_1 1 0)))
 (let ((?x1123 (+ 0 (ite d_9_0 0 0))))
 (let ((?x1126 (+ ?x1123 ?x1125)))
 (let ((?x1130 (+ ?x1126 (ite d_9_2 0 0))))
 (let ((?x1134 (+ ?x1130 (ite d_9_3 0 0))))
 (let ((?x1138 (+ ?x1134 (ite d_10_0 0 0))))
 (let ((?x1141 (+ ?x1138 ?x1140)))
 (let ((?x1145 (+ ?x1141 (ite d_10_2 0 0))))
 (let ((?x1149 (+ ?x1145 (ite d_10_3 0 0))))
 (let ((?x1153 (+ ?x1149 (ite d_5_0 0 0))))
 (let ((?x1156 (+ ?x1153 ?x1155)))
 (let ((?x1160 (+ ?x1156 (ite d_5_2 0 0))))
 (let ((?x1164 (+ ?x1160 (ite d_5_3 0 0))))
 (let ((?x1168 (+ ?x1164 (ite d_4_0 0 0))))
 (let ((?x1171 (+ ?x1168 ?x1170)))
 (let ((?x1175 (+ ?x1171 (ite d_4_2 0 0))))
 (let ((?x1179 (+ ?x1175 (ite d_4_3 0 0))))
 (let ((?x1183 (+ ?x1179 (ite d_8_0 0 0))))
 (let ((?x1186 (+ ?x1183 ?x1185)))
 (let ((?x1190 (+ ?x1186 (ite d_8_2 0 0))))
 (let ((?x1194 (+ ?x1190 (ite d_8_3 0 0))))
 (let ((?x1198 (+ ?x1194 (ite d_13_0 0 0))))
 (let ((?x1201 (+ ?x1198 ?x1200)))
 (let ((?x1205 (+ ?x1201 (ite d_13_2 0 0))))
 (let ((?x1209 (+ ?x1205 (ite d_13_3 0 0))))
 (let ((?x1213 (+ ?x1209 (ite d_14_0 0 0))))
 (let ((?x1216 (+ ?x1213 ?x1215)))
 (let ((?x1220 (+ ?x1216 (ite d_14_2 0 0))))
 (let ((?x1224 (+ ?x1220 (ite d_14_3 0 0))))
 (let ((?x1228 (+ ?x1224 (ite d_11_0 0 0))))
 (let ((?x1231 (+ ?x1228 ?x1230)))
 (let ((?x1235 (+ ?x1231 (ite d_11_2 0 0))))
 (let ((?x1239 (+ ?x1235 (ite d_11_3 0 0))))
 (let ((?x1243 (+ ?x1239 (ite d_6_0 0 0))))
 (let ((?x1246 (+ ?x1243 ?x1245)))
 (let ((?x1250 (+ ?x1246 (ite d_6_2 0 0))))
 (let ((?x1254 (+ ?x1250 (ite d_6_3 0 0))))
 (let ((?x1258 (+ ?x1254 (ite d_2_0 0 0))))
 (let ((?x1261 (+ ?x1258 ?x1260)))
 (let ((?x1265 (+ ?x1261 (ite d_2_2 0 0))))
 (let ((?x1269 (+ ?x1265 (ite d_2_3 0 0))))
 (let ((?x1273 (+ ?x1269 (ite d_1_0 0 0))))
 (let ((?x1276 (+ ?x1273 ?x1275)))
 (let ((?x1280 (+ ?x1276 (ite d_1_2 0 0))))
 (let ((?x1284 (+ ?x1280 (ite d_1_3 0 0))))
 (let ((?x1288 (+ ?x1284 (ite d_0_0 0 0))))
 (let ((?x1291 (+ ?x1288 ?x1290)))
 (let ((?x1295 (+ ?x1291 (ite d_0_2 0 0))))
 (let ((?x1299 (+ ?x1295 (ite d_0_3 0 0))))
 (let ((?x1303 (+ ?x1299 (ite d_3_0 0 0))))
 (let ((?x1306 (+ ?x1303 ?x1305)))
 (let ((?x1310 (+ ?x1306 (ite d_3_2 0 0))))
 (let ((?x1314 (+ ?x1310 (ite d_3_3 0 0))))
 (let ((?x1318 (+ ?x1314 (ite d_7_0 0 0))))
 (let ((?x1321 (+ ?x1318 ?x1320)))
 (let ((?x1325 (+ ?x1321 (ite d_7_2 0 0))))
 (let ((?x1329 (+ ?x1325 (ite d_7_3 0 0))))
 (let ((?x1333 (+ ?x1329 (ite d_12_0 0 0))))
 (let ((?x1336 (+ ?x1333 ?x1335)))
 (let ((?x1340 (+ ?x1336 (ite d_12_2 0 0))))
 (let ((?x1344 (+ ?x1340 (ite d_12_3 0 0))))
 (let ((?x1348 (+ ?x1344 (ite d_16_0 0 0))))
 (let ((?x1351 (+ ?x1348 ?x1350)))
 (let ((?x1355 (+ ?x1351 (ite d_16_2 0 0))))
 (let ((?x1359 (+ ?x1355 (ite d_16_3 0 0))))
 (let ((?x1363 (+ ?x1359 (ite d_17_0 0 0))))
 (let ((?x1366 (+ ?x1363 ?x1365)))
 (let ((?x1370 (+ ?x1366 (ite d_17_2 0 0))))
 (let ((?x1374 (+ ?x1370 (ite d_17_3 0 0))))
 (let ((?x1378 (+ ?x1374 (ite d_18_0 0 0))))
 (let ((?x1381 (+ ?x1378 ?x1380)))
 (let ((?x1385 (+ ?x1381 (ite d_18_2 0 0))))
 (let ((?x1389 (+ ?x1385 (ite d_18_3 0 0))))
 (let ((?x1393 (+ ?x1389 (ite d_15_0 0 0))))
 (let ((?x1396 (+ ?x1393 ?x1395)))
 (let ((?x1400 (+ ?x1396 (ite d_15_2 0 0))))
 (let ((?x862 (ite c_15_1 1 0)))
 (let ((?x860 (ite c_18_1 1 0)))
 (let ((?x858 (ite c_17_1 1 0)))
 (let ((?x856 (ite c_16_1 1 0)))
 (let ((?x854 (ite c_12_1 1 0)))
 (let ((?x852 (ite c_7_1 1 0)))
 (let ((?x850 (ite c_3_1 1 0)))
 (let ((?x848 (ite c_0_1 1 0)))
 (let ((?x846 (ite c_1_1 1 0)))
 (let ((?x844 (ite c_2_1 1 0)))
 (let ((?x842 (ite c_6_1 1 0)))
 (let ((?x840 (ite c_11_1 1 0)))
 (let ((?x838 (ite c_14_1 1 0)))
 (let ((?x836 (ite c_13_1 1 0)))
 (let ((?x834 (ite c_8_1 1 0)))
 (let ((?x832 (ite c_4_1 1 0)))
 (let ((?x830 (ite c_5_1 1 0)))
 (let ((?x828 (ite c_10_1 1 0)))
 (let ((?x826 (ite c_9_1 1 0)))
 (let ((?x1121 (+ 0 (ite c_9_0 0 0))))
 (let ((?x1124 (+ ?x1121 ?x826)))
 (let ((?x1128 (+ ?x1124 (ite c_9_2 0 0))))
 (let ((?x1132 (+ ?x1128 (ite c_9_3 0 0))))
 (let ((?x1136 (+ ?x1132 (ite c_10_0 0 0))))
 (let ((?x1139 (+ ?x1136 ?x828)))
 (let ((?x1143 (+ ?x1139 (ite c_10_2 0 0))))
 (let ((?x1147 (+ ?x1143 (ite c_10_3 0 0))))
 (let ((?x1151 (+ ?x1147 (ite c_5_0 0 0))))
 (let ((?x1154 (+ ?x1151 ?x830)))
 (let ((?x1158 (+ ?x1154 (ite c_5_2 0 0))))
 (let ((?x1162 (+ ?x1158 (ite c_5_3 0 0))))
 (let ((?x1166 (+ ?x1162 (ite c_4_0 0 0))))
 (let ((?x1169 (+ ?x1166 ?x832)))
 (let ((?x1173 (+ ?x1169 (ite c_4_2 0 0))))
 (let ((?x1177 (+ ?x1173 (ite c_4_3 0 0))))
 (let ((?x1181 (+ ?x1177 (ite c_8_0 0 0))))
 (let ((?x1184 (+ ?x1181 ?x834)))
 (let ((?x1188 (+ ?x1184 (ite c_8_2 0 0))))
 (let ((?x1192 (+ ?x1188 (ite c_8_3 0 0))))
 (let ((?x1196 (+ ?x1192 (ite c_13_0 0 0))))
 (let ((?x1199 (+ ?x1196 ?x836)))
 (let ((?x1203 (+ ?x1199 (ite c_13_2 0 0))))
 (let ((?x1207 (+ ?x1203 (ite c_13_3 0 0))))
 (let ((?x1211 (+ ?x1207 (ite c_14_0 0 0))))
 (let ((?x1214 (+ ?x1211 ?x838)))
 (let ((?x1218 (+ ?x1214 (ite c_14_2 0 0))))
 (let ((?x1222 (+ ?x1218 (ite c_14_3 0 0))))
 (let ((?x1226 (+ ?x1222 (ite c_11_0 0 0))))
 (let ((?x1229 (+ ?x1226 ?x840)))
 (let ((?x1233 (+ ?x1229 (ite c_11_2 0 0))))
 (let ((?x1237 (+ ?x1233 (ite c_11_3 0 0))))
 (let ((?x1241 (+ ?x1237 (ite c_6_0 0 0))))
 (let ((?x1244 (+ ?x1241 ?x842)))
 (let ((?x1248 (+ ?x1244 (ite c_6_2 0 0))))
 (let ((?x1252 (+ ?x1248 (ite c_6_3 0 0))))
 (let ((?x1256 (+ ?x1252 (ite c_2_0 0 0))))
 (let ((?x1259 (+ ?x1256 ?x844)))
 (let ((?x1263 (+ ?x1259 (ite c_2_2 0 0))))
 (let ((?x1267 (+ ?x1263 (ite c_2_3 0 0))))
 (let ((?x1271 (+ ?x1267 (ite c_1_0 0 0))))
 (let ((?x1274 (+ ?x1271 ?x846)))
 (let ((?x1278 (+ ?x1274 (ite c_1_2 0 0))))
 (let ((?x1282 (+ ?x1278 (ite c_1_3 0 0))))
 (let ((?x1286 (+ ?x1282 (ite c_0_0 0 0))))
 (let ((?x1289 (+ ?x1286 ?x848)))
 (let ((?x1293 (+ ?x1289 (ite c_0_2 0 0))))
 (let ((?x1297 (+ ?x1293 (ite c_0_3 0 0))))
 (let ((?x1301 (+ ?x1297 (ite c_3_0 0 0))))
 (let ((?x1304 (+ ?x1301 ?x850)))
 (let ((?x1308 (+ ?x1304 (ite c_3_2 0 0))))
 (let ((?x1312 (+ ?x1308 (ite c_3_3 0 0))))
 (let ((?x1316 (+ ?x1312 (ite c_7_0 0 0))))
 (let ((?x1319 (+ ?x1316 ?x852)))
 (let ((?x1323 (+ ?x1319 (ite c_7_2 0 0))))
 (let ((?x1327 (+ ?x1323 (ite c_7_3 0 0))))
 (let ((?x1331 (+ ?x1327 (ite c_12_0 0 0))))
 (let ((?x1334 (+ ?x1331 ?x854)))
 (let ((?x1338 (+ ?x1334 (ite c_12_2 0 0))))
 (let ((?x1342 (+ ?x1338 (ite c_12_3 0 0))))
 (let ((?x1346 (+ ?x1342 (ite c_16_0 0 0))))
 (let ((?x1349 (+ ?x1346 ?x856)))
 (let ((?x1353 (+ ?x1349 (ite c_16_2 0 0))))
 (let ((?x1357 (+ ?x1353 (ite c_16_3 0 0))))
 (let ((?x1361 (+ ?x1357 (ite c_17_0 0 0))))
 (let ((?x1364 (+ ?x1361 ?x858)))
 (let ((?x1368 (+ ?x1364 (ite c_17_2 0 0))))
 (let ((?x1372 (+ ?x1368 (ite c_17_3 0 0))))
 (let ((?x1376 (+ ?x1372 (ite c_18_0 0 0))))
 (let ((?x1379 (+ ?x1376 ?x860)))
 (let ((?x1383 (+ ?x1379 (ite c_18_2 0 0))))
 (let ((?x1387 (+ ?x1383 (ite c_18_3 0 0))))
 (let ((?x1391 (+ ?x1387 (ite c_15_0 0 0))))
 (let ((?x1394 (+ ?x1391 ?x862)))
 (let ((?x1398 (+ ?x1394 (ite c_15_2 0 0))))
 (let (($x1407 (and (distinct (+ ?x1398 (ite c_15_3 0 0)) (+ ?x1400 (ite d_15_3 0 0))) true)))
 (let (($x1110 (and true (=> c_15_0 d_15_1))))
 (let (($x1112 (and $x1110 (=> c_15_1 d_15_1))))
 (let (($x1114 (and $x1112 (=> c_15_2 d_15_1))))
 (let (($x1101 (and true (=> c_18_0 d_18_1))))
 (let (($x1103 (and $x1101 (=> c_18_1 d_18_1))))
 (let (($x1105 (and $x1103 (=> c_18_2 d_18_1))))
 (let (($x1092 (and true (=> c_17_0 d_17_1))))
 (let (($x1094 (and $x1092 (=> c_17_1 d_17_1))))
 (let (($x1096 (and $x1094 (=> c_17_2 d_17_1))))
 (let (($x1083 (and true (=> c_16_0 d_16_1))))
 (let (($x1085 (and $x1083 (=> c_16_1 d_16_1))))
 (let (($x1087 (and $x1085 (=> c_16_2 d_16_1))))
 (let (($x1074 (and true (=> c_12_0 d_12_1))))
 (let (($x1076 (and $x1074 (=> c_12_1 d_12_1))))
 (let (($x1078 (and $x1076 (=> c_12_2 d_12_1))))
 (let (($x1065 (and true (=> c_7_0 d_7_1))))
 (let (($x1067 (and $x1065 (=> c_7_1 d_7_1))))
 (let (($x1069 (and $x1067 (=> c_7_2 d_7_1))))
 (let (($x1056 (and true (=> c_3_0 d_3_1))))
 (let (($x1058 (and $x1056 (=> c_3_1 d_3_1))))
 (let (($x1060 (and $x1058 (=> c_3_2 d_3_1))))
 (let (($x1047 (and true (=> c_0_0 d_0_1))))
 (let (($x1049 (and $x1047 (=> c_0_1 d_0_1))))
 (let (($x1051 (and $x1049 (=> c_0_2 d_0_1))))
 (let (($x1038 (and true (=> c_1_0 d_1_1))))
 (let (($x1040 (and $x1038 (=> c_1_1 d_1_1))))
 (let (($x1042 (and $x1040 (=> c_1_2 d_1_1))))
 (let (($x1029 (and true (=> c_2_0 d_2_1))))
 (let (($x1031 (and $x1029 (=> c_2_1 d_2_1))))
 (let (($x1033 (and $x1031 (=> c_2_2 d_2_1))))
 (let (($x1020 (and true (=> c_6_0 d_6_1))))
 (let (($x1022 (and $x1020 (=> c_6_1 d_6_1))))
 (let (($x1024 (and $x1022 (=> c_6_2 d_6_1))))
 (let (($x1011 (and true (=> c_11_0 d_11_1))))
 (let (($x1013 (and $x1011 (=> c_11_1 d_11_1))))
 (let (($x1015 (and $x1013 (=> c_11_2 d_11_1))))
 (let (($x1002 (and true (=> c_14_0 d_14_2))))
 (let (($x1004 (and $x1002 (=> c_14_1 d_14_2))))
 (let (($x1006 (and $x1004 (=> c_14_2 d_14_2))))
 (let (($x993 (and true (=> c_13_0 d_13_2))))
 (let (($x995 (and $x993 (=> c_13_1 d_13_2))))
 (let (($x997 (and $x995 (=> c_13_2 d_13_2))))
 (let (($x984 (and true (=> c_8_0 d_8_2))))
 (let (($x986 (and $x984 (=> c_8_1 d_8_2))))
 (let (($x988 (and $x986 (=> c_8_2 d_8_2))))
 (let (($x975 (and true (=> c_4_0 d_4_2))))
 (let (($x977 (and $x975 (=> c_4_1 d_4_2))))
 (let (($x979 (and $x977 (=> c_4_2 d_4_2))))
 (let (($x966 (and true (=> c_5_0 d_5_2))))
 (let (($x968 (and $x966 (=> c_5_1 d_5_2))))
 (let (($x970 (and $x968 (=> c_5_2 d_5_2))))
 (let (($x957 (and true (=> c_10_0 d_10_2))))
 (let (($x959 (and $x957 (=> c_10_1 d_10_2))))
 (let (($x961 (and $x959 (=> c_10_2 d_10_2))))
 (let (($x948 (and true (=> c_9_0 d_9_3))))
 (let (($x950 (and $x948 (=> c_9_1 d_9_3))))
 (let (($x952 (and $x950 (=> c_9_2 d_9_3))))
 (let ((?x940 (ite (or c_15_2 c_15_3) 1 0)))
 (let ((?x938 (ite (or c_18_2 c_18_3) 1 0)))
 (let ((?x936 (ite (or c_17_2 c_17_3) 1 0)))
 (let ((?x934 (ite (or c_16_2 c_16_3) 1 0)))
 (let ((?x932 (ite (or c_12_2 c_12_3) 1 0)))
 (let ((?x930 (ite (or c_7_2 c_7_3) 1 0)))
 (let ((?x928 (ite (or c_3_2 c_3_3) 1 0)))
 (let ((?x926 (ite (or c_0_2 c_0_3) 1 0)))
 (let ((?x924 (ite (or c_1_2 c_1_3) 1 0)))
 (let ((?x922 (ite (or c_2_2 c_2_3) 1 0)))
 (let ((?x920 (ite (or c_6_2 c_6_3) 1 0)))
 (let ((?x918 (ite (or c_11_2 c_11_3) 1 0)))
 (let ((?x916 (ite (or c_14_2 c_14_3) 1 0)))
 (let ((?x914 (ite (or c_13_2 c_13_3) 1 0)))
 (let ((?x912 (ite (or c_8_2 c_8_3) 1 0)))
 (let ((?x910 (ite (or c_4_2 c_4_3) 1 0)))
 (let ((?x908 (ite (or c_5_2 c_5_3) 1 0)))
 (let ((?x906 (ite (or c_10_2 c_10_3) 1 0)))
 (let ((?x903 (ite (or c_9_2 c_9_3) 1 0)))
 (let ((?x905 (+ 0 ?x903)))
 (let ((?x907 (+ ?x905 ?x906)))
 (let ((?x909 (+ ?x907 ?x908)))
 (let ((?x911 (+ ?x909 ?x910)))
 (let ((?x913 (+ ?x911 ?x912)))
 (let ((?x915 (+ ?x913 ?x914)))
 (let ((?x917 (+ ?x915 ?x916)))
 (let ((?x919 (+ ?x917 ?x918)))
 (let ((?x921 (+ ?x919 ?x920)))
 (let ((?x923 (+ ?x921 ?x922)))
 (let ((?x925 (+ ?x923 ?x924)))
 (let ((?x927 (+ ?x925 ?x926)))
 (let ((?x929 (+ ?x927 ?x928)))
 (let ((?x931 (+ ?x929 ?x930)))
 (let ((?x933 (+ ?x931 ?x932)))
 (let ((?x935 (+ ?x933 ?x934)))
 (let ((?x937 (+ ?x935 ?x936)))
 (let ((?x939 (+ ?x937 ?x938)))
 (let ((?x827 (+ 0 ?x826)))
 (let ((?x829 (+ ?x827 ?x828)))
 (let ((?x831 (+ ?x829 ?x830)))
 (let ((?x833 (+ ?x831 ?x832)))
 (let ((?x835 (+ ?x833 ?x834)))
 (let ((?x837 (+ ?x835 ?x836)))
 (let ((?x839 (+ ?x837 ?x838)))
 (let ((?x841 (+ ?x839 ?x840)))
 (let ((?x843 (+ ?x841 ?x842)))
 (let ((?x845 (+ ?x843 ?x844)))
 (let ((?x847 (+ ?x845 ?x846)))
 (let ((?x849 (+ ?x847 ?x848)))
 (let ((?x851 (+ ?x849 ?x850)))
 (let ((?x853 (+ ?x851 ?x852)))
 (let ((?x855 (+ ?x853 ?x854)))
 (let ((?x857 (+ ?x855 ?x856)))
 (let ((?x859 (+ ?x857 ?x858)))
 (let ((?x861 (+ ?x859 ?x860)))
 (let (($x945 (and (= (to_real (+ ?x861 ?x862)) 12.0) (= (to_real (+ ?x939 ?x940)) 0.0))))
 (let (($x823 (or c_15_0 c_15_1 c_15_2 c_15_3)))
 (let (($x821 (or c_18_0 c_18_1 c_18_2 c_18_3)))
 (let (($x819 (or c_17_0 c_17_1 c_17_2 c_17_3)))
 (let (($x817 (or c_16_0 c_16_1 c_16_2 c_16_3)))
 (let (($x815 (or c_12_0 c_12_1 c_12_2 c_12_3)))
 (let (($x813 (or c_7_0 c_7_1 c_7_2 c_7_3)))
 (let (($x811 (or c_3_0 c_3_1 c_3_2 c_3_3)))
 (let (($x809 (or c_0_0 c_0_1 c_0_2 c_0_3)))
 (let (($x807 (or c_1_0 c_1_1 c_1_2 c_1_3)))
 (let (($x805 (or c_2_0 c_2_1 c_2_2 c_2_3)))
 (let (($x803 (or c_6_0 c_6_1 c_6_2 c_6_3)))
 (let (($x801 (or c_11_0 c_11_1 c_11_2 c_11_3)))
 (let (($x799 (or c_14_0 c_14_1 c_14_2 c_14_3)))
 (let (($x797 (or c_13_0 c_13_1 c_13_2 c_13_3)))
 (let (($x795 (or c_8_0 c_8_1 c_8_2 c_8_3)))
 (let (($x793 (or c_4_0 c_4_1 c_4_2 c_4_3)))
 (let (($x791 (or c_5_0 c_5_1 c_5_2 c_5_3)))
 (let (($x788 (or c_10_0 c_10_1 c_10_2 c_10_3)))
 (let (($x789 (and c_9_1 in_target_9)))
 (let (($x785 (and true $x789)))
 (let (($x786 (and $x785 $x788)))
 (let (($x790 (and $x786 $x791)))
 (let (($x787 (and $x790 $x793)))
 (let (($x794 (and $x787 $x795)))
 (let (($x792 (and $x794 $x797)))
 (let (($x796 (and $x792 $x799)))
 (let (($x800 (and $x796 $x801)))
 (let (($x798 (and $x800 $x803)))
 (let (($x804 (and $x798 $x805)))
 (let (($x802 (and $x804 $x807)))
 (let (($x808 (and $x802 $x809)))
 (let (($x810 (and $x808 $x811)))
 (let (($x806 (and $x810 $x813)))
 (let (($x812 (and $x806 $x815)))
 (let (($x814 (and $x812 $x817)))
 (let (($x816 (and $x814 $x819)))
 (let (($x818 (and $x816 $x821)))
 (let (($x822 (and $x818 $x823)))
 (let (($x946 (and $x822 $x945)))
 (let (($x955 (and $x946 (and $x952 (=> c_9_3 d_9_3)))))
 (let (($x964 (and $x955 (and $x961 (=> c_10_3 d_10_2)))))
 (let (($x973 (and $x964 (and $x970 (=> c_5_3 d_5_2)))))
 (let (($x982 (and $x973 (and $x979 (=> c_4_3 d_4_2)))))
 (let (($x991 (and $x982 (and $x988 (=> c_8_3 d_8_2)))))
 (let (($x1000 (and $x991 (and $x997 (=> c_13_3 d_13_2)))))
 (let (($x1009 (and $x1000 (and $x1006 (=> c_14_3 d_14_2)))))
 (let (($x1018 (and $x1009 (and $x1015 (=> c_11_3 d_11_1)))))
 (let (($x1027 (and $x1018 (and $x1024 (=> c_6_3 d_6_1)))))
 (let (($x1036 (and $x1027 (and $x1033 (=> c_2_3 d_2_1)))))
 (let (($x1045 (and $x1036 (and $x1042 (=> c_1_3 d_1_1)))))
 (let (($x1054 (and $x1045 (and $x1051 (=> c_0_3 d_0_1)))))
 (let (($x1063 (and $x1054 (and $x1060 (=> c_3_3 d_3_1)))))
 (let (($x1072 (and $x1063 (and $x1069 (=> c_7_3 d_7_1)))))
 (let (($x1081 (and $x1072 (and $x1078 (=> c_12_3 d_12_1)))))
 (let (($x1090 (and $x1081 (and $x1087 (=> c_16_3 d_16_1)))))
 (let (($x1099 (and $x1090 (and $x1096 (=> c_17_3 d_17_1)))))
 (let (($x1108 (and $x1099 (and $x1105 (=> c_18_3 d_18_1)))))
 (let (($x1119 (and (and true (and $x1108 (and $x1114 (=> c_15_3 d_15_1)))) true)))
 (let (($x1405 (= rule_instance 0)))
 (or false (and (and $x1405 $x1119) $x1407))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))))
(check-sat)
