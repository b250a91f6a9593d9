/* liggghts-crush: elastic constants of an atom type (see type_materials.h). */
#include "type_materials.h"

#include "fix_property_global.h"
#include "modify.h"

namespace LAMMPS_NS {

crush::Material type_material(Modify *modify, int ntypes, int type, const char *caller)
{
  FixPropertyGlobal *E = static_cast<FixPropertyGlobal *>(
      modify->find_fix_property("youngsModulus", "property/global", "peratomtype", ntypes, 0, caller));
  FixPropertyGlobal *nu = static_cast<FixPropertyGlobal *>(
      modify->find_fix_property("poissonsRatio", "property/global", "peratomtype", ntypes, 0, caller));
  return crush::Material{E->compute_vector(type - 1), nu->compute_vector(type - 1)};
}

crush::ShearMaterial type_shear_material(Modify *modify, int ntypes, int type, const char *caller)
{
  const crush::Material m = type_material(modify, ntypes, type, caller);
  return crush::shear_material(m.youngs_modulus, m.poisson_ratio);
}

}  // namespace LAMMPS_NS
