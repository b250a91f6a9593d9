/* ----------------------------------------------------------------------
   liggghts-crush: tangential contact model mindlin/scaled.

   PFC's incremental shear force with the shear stiffness k_S of eq. 9 (Ciantia et al. 2014), which
   the normal model hertz/scaled supplies in sidata.kt (the law: hertz_mindlin_shear_law.h):
     F_s <- R(F_s) - k_S du_s,   du_s = v_t dt,   |F_s| <= mu |F_n|   (Coulomb)
   R turns the stored force into the current tangent plane keeping its magnitude (the contact plane
   rotates with the particles). History: the shear force vector (3 values, N). LIGGGHTS' 'tangential
   history' instead stores the total displacement and multiplies it by the current k_t: the two agree
   while k_t is constant and differ when the overlap, hence k_t, changes during shearing.
   Tangential viscous damping only with 'viscous_damping on' on the normal model (sidata.gammat).
------------------------------------------------------------------------- */
#ifdef TANGENTIAL_MODEL
TANGENTIAL_MODEL(TANGENTIAL_MINDLIN_SCALED,mindlin/scaled,3)
#else
#ifndef TANGENTIAL_MODEL_MINDLIN_SCALED_H_
#define TANGENTIAL_MODEL_MINDLIN_SCALED_H_

#include <cmath>

#include "contact_models.h"
#include "global_properties.h"
#include "hertz_mindlin_shear_law.h"
#include "tangential_model_base.h"
#include "update.h"

namespace LIGGGHTS {
namespace ContactModels {

  template<>
  class TangentialModel<TANGENTIAL_MINDLIN_SCALED> : public TangentialModelBase
  {
  public:
    TangentialModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
      TangentialModelBase(lmp, hsetup, c), coeffFrict(NULL)
    {
      history_offset = hsetup->add_history_value("shear_force_x", "1");
      hsetup->add_history_value("shear_force_y", "1");
      hsetup->add_history_value("shear_force_z", "1");
    }

    inline void registerSettings(Settings &) {}
    inline void postSettings(IContactHistorySetup *, ContactModelBase *) {}

    inline void connectToProperties(PropertyRegistry &registry)
    {
      registry.registerProperty("coeffFrict", &MODEL_PARAMS::createCoeffFrict);
      registry.connect("coeffFrict", coeffFrict, "tangential_model mindlin/scaled");
    }

    inline void surfacesIntersect(const SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
      if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_TANGENTIAL_MODEL;
      const double *en = sidata.en;
      double *const shear = &sidata.contact_history[history_offset];
      // The stored shear force acts on i; j gets its opposite. The law: hertz_mindlin_shear_law.h.
      double Fs[3] = {shear[0], shear[1], shear[2]};
      const bool update_history = sidata.computeflag && sidata.shearupdate;
      if (update_history) {
        const double vt[3] = {sidata.vtr1, sidata.vtr2, sidata.vtr3};
        crush::increment_shear_force(Fs, en, sidata.kt * update->dt, vt);
      }
      double F[3] = {Fs[0], Fs[1], Fs[2]};
      if (crush::cap_at_coulomb(Fs, coeffFrict[sidata.itype][sidata.jtype] * fabs(sidata.Fn))) {
        // Sliding: the stored force stays on the Coulomb limit.
        for (int k = 0; k < 3; ++k) F[k] = Fs[k];
      } else if (sidata.gammat != 0.0) {
        F[0] -= sidata.gammat * sidata.vtr1;
        F[1] -= sidata.gammat * sidata.vtr2;
        F[2] -= sidata.gammat * sidata.vtr3;
      }
      if (update_history) {
        shear[0] = Fs[0];
        shear[1] = Fs[1];
        shear[2] = Fs[2];
      }

      const double tor1 = en[1] * F[2] - en[2] * F[1];
      const double tor2 = en[2] * F[0] - en[0] * F[2];
      const double tor3 = en[0] * F[1] - en[1] * F[0];
      const double scale = sidata.is_wall ? sidata.area_ratio : 1.0;
      i_forces.delta_F[0] += scale * F[0];
      i_forces.delta_F[1] += scale * F[1];
      i_forces.delta_F[2] += scale * F[2];
      i_forces.delta_torque[0] -= scale * sidata.cri * tor1;
      i_forces.delta_torque[1] -= scale * sidata.cri * tor2;
      i_forces.delta_torque[2] -= scale * sidata.cri * tor3;
      if (!sidata.is_wall) {
        j_forces.delta_F[0] -= F[0];
        j_forces.delta_F[1] -= F[1];
        j_forces.delta_F[2] -= F[2];
        j_forces.delta_torque[0] -= sidata.crj * tor1;
        j_forces.delta_torque[1] -= sidata.crj * tor2;
        j_forces.delta_torque[2] -= sidata.crj * tor3;
      }
    }

    inline void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
    {
      if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_TANGENTIAL_MODEL;
      if (!scdata.contact_history) return;
      double *const shear = &scdata.contact_history[history_offset];
      shear[0] = shear[1] = shear[2] = 0.0;
    }

    inline void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    inline void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

    // What the pair pass of hertz/scaled + mindlin/scaled reads (pair_gran_hertz_mindlin_scaled_pass.h).
    inline double **frictionCoefficients() const { return coeffFrict; }
    inline int historyOffset() const { return history_offset; }

  private:
    double **coeffFrict;
    int history_offset;
  };

}
}

#endif
#endif
