/* The load a Hertzian contact puts on a particle (plain C++): eq. 4 (see hertz_mindlin_contact_load.h). */
#include "hertz_mindlin_contact_load.h"

#include "crush_model_error.h"

namespace crush {

static void check_material(const Material &m)
{
  require(m.youngs_modulus > 0.0 && m.youngs_modulus <= 3e13, "youngs_modulus", m.youngs_modulus, "in (0, 3e13] Pa");
  require(m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5, "poisson_ratio", m.poisson_ratio,
          "in (-1, 0.5)");
}

double effective_modulus(const Material &a, const Material &b)
{
  check_material(a);
  check_material(b);
  const double compliance = (1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                            (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus;
  return 1.0 / compliance;
}

}  // namespace crush
