/* ----------------------------------------------------------------------
   liggghts-crush: the elastic constants of an atom type, read from the youngsModulus and
   poissonsRatio of fix property/global (peratomtype), for fix crush, fix wall/servo and fix dt/stiffness.
------------------------------------------------------------------------- */
#ifndef LMP_TYPE_MATERIALS_H
#define LMP_TYPE_MATERIALS_H

#include "hertz_mindlin_contact_load.h"
#include "hertz_mindlin_scaled_law.h"

namespace LAMMPS_NS {

class Modify;

// E (Pa) and nu of atom type 'type' (1..ntypes); the lookup errors name the missing property.
crush::Material type_material(Modify *modify, int ntypes, int type, const char *caller);
// The same as shear modulus G = E / (2 (1 + nu)) and nu.
crush::ShearMaterial type_shear_material(Modify *modify, int ntypes, int type, const char *caller);

}  // namespace LAMMPS_NS

#endif
