"""Numbers published by Ciantia, Arroyo, Calvetti & Gens (2014) that the runs are set against."""

# Table 3: initial particles N_i, final particles N_e, crushing events and runtime (minutes), per test
# (O: oedometric, I: isotropic) and upscaling factor N. N_e = N_i + 13 x events in every row.
TABLE3 = {
    "O2": (1304, 4372, 236, 31), "O1.5": (3084, 9974, 530, 67), "O1": (10397, 37658, 2097, 183),
    "I2": (1304, 5230, 302, 29), "I1.5": (3084, 10819, 595, 67), "I1": (10397, 40778, 2337, 203),
}
