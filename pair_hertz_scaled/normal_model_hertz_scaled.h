/* ----------------------------------------------------------------------
   liggghts-crush: normal contact model hertz/scaled.

   PFC's simplified Hertz-Mindlin normal law with mean-property mixing, Ciantia et al. (2014) eq. 8:
     F_n = k_N U,  k_N = 2<G> sqrt(2 D1 D2/(D1+D2)) / (3 (1-<nu>)) sqrt(U)
   and the shear stiffness of eq. 9, k_S, handed to the tangential model in sidata.kt.
   Elastic by default (quasi-static runs use fix damp/local); 'viscous_damping on' adds LIGGGHTS'
   restitution-based normal damping for dynamic scenes. Walls: a plane is a sphere of infinite radius
   of the wall type's material (D1 D2/(D1+D2) -> D1). The formulas live in hertz_mindlin_scaled_law.h.
   Fix crush reads each contact's elastic force k_N U through the hook of LIGGGHTS' contact-model
   template (patches/0009), as for every model; when fix dt/stiffness is about to update the time
   step, each particle-particle contact adds its stiffness to the fix's sums
   (contact_stiffness_monitor.h).
------------------------------------------------------------------------- */
#ifdef NORMAL_MODEL
NORMAL_MODEL(HERTZ_SCALED,hertz/scaled,5)
#else
#ifndef NORMAL_MODEL_HERTZ_SCALED_H_
#define NORMAL_MODEL_HERTZ_SCALED_H_

#include <cmath>
#include <string>

#include "contact_models.h"
#include "error.h"
#include "lammps.h"
#include "crush_model_error.h"
#include "contact_stiffness_monitor.h"
#include "global_properties.h"
#include "hertz_mindlin_scaled_law.h"
#include "normal_model_base.h"

namespace MODEL_PARAMS
{
  // Per type pair: the material factors of eq. 8 ([i][j][0] normal, via 'hertzScaledNormal') and
  // eq. 9 ('hertzScaledShear'), from youngsModulus and poissonsRatio (G = E / (2 (1 + nu))).
  inline MatrixProperty *createHertzScaledCoefficient(PropertyRegistry &registry, const char *caller,
                                                      bool shear)
  {
    const int max_type = registry.max_type();
    registry.registerProperty("youngsModulus", &createYoungsModulus);
    registry.registerProperty("poissonsRatio", &createPoissonsRatio);
    const double *E = registry.getVectorProperty("youngsModulus", caller)->data;
    const double *nu = registry.getVectorProperty("poissonsRatio", caller)->data;
    MatrixProperty *matrix = new MatrixProperty(max_type + 1, max_type + 1);
    try {
      for (int i = 1; i <= max_type; i++)
        for (int j = 1; j <= max_type; j++) {
          const crush::ShearMaterial a = crush::shear_material(E[i], nu[i]);
          const crush::ShearMaterial b = crush::shear_material(E[j], nu[j]);
          const crush::HertzMindlinCoefficients c = crush::hertz_mindlin_coefficients(a, b);
          matrix->data[i][j] = shear ? c.shear : c.normal;
        }
    } catch (const crush::ModelError &e) {
      const std::string msg = std::string(caller) + ": youngsModulus/poissonsRatio: " + e.what();
      registry.getLAMMPS()->error->all(FLERR, msg.c_str());
    }
    return matrix;
  }
  inline MatrixProperty *createHertzScaledNormal(PropertyRegistry &registry, const char *caller, bool)
  {
    return createHertzScaledCoefficient(registry, caller, false);
  }
  inline MatrixProperty *createHertzScaledShear(PropertyRegistry &registry, const char *caller, bool)
  {
    return createHertzScaledCoefficient(registry, caller, true);
  }
}

namespace LIGGGHTS {
namespace ContactModels {

  template<>
  class NormalModel<HERTZ_SCALED> : public NormalModelBase
  {
  public:
    NormalModel(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *c) :
      NormalModelBase(lmp, hsetup, c), normal_coeff(NULL), shear_coeff(NULL),
      betaeff(NULL), viscous_damping(false), dedicated_loop(true), stiffness_monitor(lmp)
    {
    }

    void registerSettings(Settings &settings)
    {
      settings.registerOnOff("viscous_damping", viscous_damping, false);
      settings.registerOnOff("dedicated_loop", dedicated_loop, true);
    }

    inline void postSettings(IContactHistorySetup *, ContactModelBase *) {}

    void connectToProperties(PropertyRegistry &registry)
    {
      registry.registerProperty("hertzScaledNormal", &MODEL_PARAMS::createHertzScaledNormal, "model hertz/scaled");
      registry.registerProperty("hertzScaledShear", &MODEL_PARAMS::createHertzScaledShear, "model hertz/scaled");
      registry.connect("hertzScaledNormal", normal_coeff, "model hertz/scaled");
      registry.connect("hertzScaledShear", shear_coeff, "model hertz/scaled");
      if (viscous_damping) {
        registry.registerProperty("betaeff", &MODEL_PARAMS::createBetaEff, "model hertz/scaled");
        registry.connect("betaeff", betaeff, "model hertz/scaled");
      }
    }

    inline double stressStrainExponent() { return 1.5; }

    inline void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)
    {
      if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
      const int itype = sidata.itype, jtype = sidata.jtype;
      const double diameter_term = sidata.is_wall ? 2.0 * sidata.radi
                                                  : crush::diameter_term_from_radii(sidata.radi, sidata.radj);
      const crush::HertzMindlinStiffness k = crush::contact_stiffness(
          {normal_coeff[itype][jtype], shear_coeff[itype][jtype]}, diameter_term, sidata.deltan);
      const double kn = k.normal;
      const double Fn_elastic = kn * sidata.deltan;
      double Fn = Fn_elastic;
      sidata.gamman = sidata.gammat = 0.0;
      if (viscous_damping) {
        // LIGGGHTS' hertz damping: gamma_n = -2 sqrt(5/6) beta sqrt(S_n m_eff), S_n = dF_n/dU = 1.5 k_N.
        const double sqrtFiveOverSix = 0.91287092917527685576;
        sidata.gamman = -2.0 * sqrtFiveOverSix * betaeff[itype][jtype] * sqrt(1.5 * kn * sidata.meff);
        Fn -= sidata.gamman * sidata.vn;
      }
      sidata.Fn = Fn;
      sidata.kn = kn;
      sidata.kt = k.shear;

      // The time step's stiffness sums; not from walls (fix dt/stiffness counts only fix wall/servo's)
      // nor from passes that compute no forces (compute pair/gran/local).
      if (const ContactStiffnessRecorder *sums = stiffness_monitor.recorder())
        if (!sidata.is_wall && sidata.computeflag) sums->record(sidata.i, sidata.j, k);

      const double scale = sidata.is_wall ? sidata.area_ratio : 1.0;
      i_forces.delta_F[0] += scale * Fn * sidata.en[0];
      i_forces.delta_F[1] += scale * Fn * sidata.en[1];
      i_forces.delta_F[2] += scale * Fn * sidata.en[2];
      if (!sidata.is_wall) {
        j_forces.delta_F[0] -= Fn * sidata.en[0];
        j_forces.delta_F[1] -= Fn * sidata.en[1];
        j_forces.delta_F[2] -= Fn * sidata.en[2];
      }
    }

    void surfacesClose(SurfacesCloseData &scdata, ForceData &, ForceData &)
    {
      if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_NORMAL_MODEL;
    }

    void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

    // What the pair pass of hertz/scaled + mindlin/scaled reads (pair_gran_hertz_mindlin_scaled_pass.h).
    inline double **normalCoefficients() const { return normal_coeff; }
    inline double **shearCoefficients() const { return shear_coeff; }
    inline bool viscousDamping() const { return viscous_damping; }
    inline bool dedicatedLoop() const { return dedicated_loop; }
    inline const ContactStiffnessRecorder *stiffnessRecorder() const { return stiffness_monitor.recorder(); }

  protected:
    double **normal_coeff;
    double **shear_coeff;
    double **betaeff;
    bool viscous_damping;
    bool dedicated_loop;  // 'dedicated_loop off': the pair forces by LIGGGHTS' generic loop
    ContactStiffnessMonitor stiffness_monitor;
  };

}
}

#endif
#endif
