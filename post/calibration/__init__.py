"""fix crush's calibration (doc/calibration.md), one module a step; post/calibrate.py is its command line.

  strength         the model every step shares: eq. 4-6/10 (E', sigma_lim <-> F_f, the size effect),
                   the defaults and Table 1, the Weibull cv, survival curves
  data             the input CSVs read and checked (DataError names the file, the line and the value)
  single_particle  single-particle crushing tests: the fits, intervals and goodness of fit, the fix
                   crush line, figures and report (single-particle), and synthetic tests (synthetic)
  summary          published summary statistics per size class (summary)
  moduli           published Weibull moduli and size ratios without strengths (moduli)
  dem_check        the DEM check of a fit: the population of grains and its comparison (population,
                   compare)
  oedometer        O-N runs for a grid of (sigma_lim0, cv) against a lab compression curve (oedometer)
"""
