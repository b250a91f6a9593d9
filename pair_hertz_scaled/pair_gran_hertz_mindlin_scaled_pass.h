/* ----------------------------------------------------------------------
   liggghts-crush: the pair force pass of 'pair_style gran model hertz/scaled tangential
   mindlin/scaled' (eq. 8-9 with PFC's incremental shear force), a loop of its own.

   LIGGGHTS' generic loop (pair_gran_base.h) hands every neighbour to its sub-models through a
   SurfacesIntersectData of some 370 bytes, filling it whether the pair touches or not, and resets
   two ForceData per neighbour. This loop keeps each contact in registers, reads the per-type-pair
   constants once per pair, and for a neighbour that does not touch does only the distance test
   and the clearing of a contact that opened. The arithmetic is the generic loop's, operation for
   operation and in its order (the same inline laws: hertz_mindlin_scaled_law.h,
   hertz_mindlin_shear_law.h), so the forces are the same to the bit; tests/regression/
   test_dedicated_loop.py compares the two.

   It runs only when nothing needs the generic loop's per-contact record: no energy or virial
   tally, no compute pair/gran/local, no stored contact forces or normal-force sums, no multicontact
   radii, no fix insert/stream/predefined, no viscous damping (it needs the effective mass),
   spheres only, and forces being computed. Otherwise, or with the normal model's
   'dedicated_loop off', the generic loop runs. Fix crush's contact-load recorder and fix
   dt/stiffness's stiffness sums are fed as the models feed them.
------------------------------------------------------------------------- */
#ifndef PAIR_GRAN_HERTZ_MINDLIN_SCALED_PASS_H_
#define PAIR_GRAN_HERTZ_MINDLIN_SCALED_PASS_H_

#include <cmath>
#include <cstdio>

#include "atom.h"
#include "comm.h"
#include "contact_models.h"
#include "hertz_mindlin_scaled_law.h"
#include "hertz_mindlin_shear_law.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_gran.h"
#include "update.h"

namespace LIGGGHTS {
namespace PairStyles {

// Any other contact law: no pass of its own (the generic loop runs).
template <typename ContactModel>
inline bool dedicated_pass(LAMMPS_NS::LAMMPS *, ContactModel &, LAMMPS_NS::PairGran *, int, int, int)
{
  return false;
}

namespace HertzMindlinScaledPass {

using namespace ContactModels;

typedef ContactModels::ContactModel<GranStyle<HERTZ_SCALED, TANGENTIAL_MINDLIN_SCALED, COHESION_OFF,
                                              ROLLING_OFF, SURFACE_DEFAULT> > Model;

// Whether this force pass may run here (see the header).
inline bool applies(LAMMPS_NS::LAMMPS *lmp, const Model &cmodel, LAMMPS_NS::PairGran *pg, int eflag, int vflag,
                    int addflag)
{
  LAMMPS_NS::Atom *atom = lmp->atom;
  if (!cmodel.normal_model().dedicatedLoop() || cmodel.normal_model().viscousDamping()) return false;
  if (eflag || vflag || (pg->cpl() && addflag) || !pg->computeflag()) return false;
  if (pg->storeContactForces() || pg->storeContactForcesStress() || pg->storeSumDelta() ||
      pg->store_sum_normal_force())
    return false;
  if (!atom->sphere_flag || atom->shapetype_flag || !pg->listgranhistory) return false;
#ifdef SUPERQUADRIC_ACTIVE_FLAG
  if (atom->superquadric_flag) return false;
#endif
  return lmp->modify->n_fixes_style("insert/stream/predefined") == 0;
}

// Once per process, at the first pass: the log says which loop computes the forces.
inline void announce(LAMMPS_NS::LAMMPS *lmp)
{
  static bool announced = false;
  if (announced) return;
  announced = true;
  if (lmp->comm->me != 0) return;
  const char *note = "pair_style gran: hertz/scaled + mindlin/scaled forces by their dedicated loop "
                     "('dedicated_loop off': LIGGGHTS' generic loop)\n";
  if (lmp->screen) fputs(note, lmp->screen);
  if (lmp->logfile) fputs(note, lmp->logfile);
}

template <bool RECORD>
void run(LAMMPS_NS::LAMMPS *lmp, const Model &cmodel, LAMMPS_NS::PairGran *pg,
         const LAMMPS_NS::ContactLoadRecorder *recorder)
{
  LAMMPS_NS::Atom *atom = lmp->atom;
  pg->evflag = pg->vflag_fdotr = 0;

  double **const x = atom->x;
  double **const v = atom->v;
  double **const f = atom->f;
  double **const omega = atom->omega;
  double **const torque = atom->torque;
  const double *const radius = atom->radius;
  const int *const type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = lmp->force->newton_pair;

  const int inum = pg->list->inum;
  const int *const ilist = pg->list->ilist;
  const int *const numneigh = pg->list->numneigh;
  int **const firstneigh = pg->list->firstneigh;
  int **const first_contact_flag = pg->listgranhistory->firstneigh;
  double **const first_contact_hist = pg->listgranhistory->firstdouble;
  const int dnum = pg->dnum();
  const bool shearupdate = pg->shearupdate();
  const double close_factor_sq = lmp->neighbor->contactDistanceFactor * lmp->neighbor->contactDistanceFactor;
  const double dt = lmp->update->dt;

  double **const normal_coeff = cmodel.normal_model().normalCoefficients();
  double **const shear_coeff = cmodel.normal_model().shearCoefficients();
  double **const friction = cmodel.tangential_model().frictionCoefficients();
  const int shear_offset = cmodel.tangential_model().historyOffset();
  const LAMMPS_NS::ContactStiffnessRecorder *const sums = cmodel.normal_model().stiffnessRecorder();
  const int touching_flags = CONTACT_NORMAL_MODEL | CONTACT_TANGENTIAL_MODEL;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    const double radi = radius[i];
    const int itype = type[i];
    const double *const normal_i = normal_coeff[itype];
    const double *const shear_i = shear_coeff[itype];
    const double *const friction_i = friction[itype];
    int *const contact_flags = first_contact_flag[i];
    double *const all_contact_hist = first_contact_hist[i];
    const int *const jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xi - x[j][0];
      const double dely = yi - x[j][1];
      const double delz = zi - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radj = radius[j];
      const double radsum = radi + radj;
      double *const history = &all_contact_hist[dnum * jj];

      if (!(rsq < radsum * radsum)) {
        if (rsq < close_factor_sq * radsum * radsum) {
          // within contact_distance_factor: the models' surfacesClose
          contact_flags[jj] &= ~touching_flags;
          history[shear_offset] = history[shear_offset + 1] = history[shear_offset + 2] = 0.0;
        } else if (contact_flags[jj]) {
          // a contact that opened forgets its spring (patches/0011)
          contact_flags[jj] = 0;
          for (int d = 0; d < dnum; d++) history[d] = 0.0;
        }
        continue;
      }

      const double r = sqrt(rsq);
      if (__builtin_expect(!(r > 0.0), 0)) pg->zero_distance_contact(i, j);
      const double rinv = 1.0 / r;
      const double en[3] = {delx * rinv, dely * rinv, delz * rinv};
      const int jtype = type[j];

      // the default surface model: relative velocity at the contact point
      const double *const vi = v[i], *const vj = v[j];
      const double vr1 = vi[0] - vj[0];
      const double vr2 = vi[1] - vj[1];
      const double vr3 = vi[2] - vj[2];
      const double vn = vr1 * en[0] + vr2 * en[1] + vr3 * en[2];
      const double vt1 = vr1 - vn * en[0];
      const double vt2 = vr2 - vn * en[1];
      const double vt3 = vr3 - vn * en[2];
      const double deltan = radsum - r;
      const double cri = radi - 0.5 * deltan;
      const double crj = radj - 0.5 * deltan;
      const double *const wi = omega[i], *const wj = omega[j];
      const double wr1 = (cri * wi[0] + crj * wj[0]) * rinv;
      const double wr2 = (cri * wi[1] + crj * wj[1]) * rinv;
      const double wr3 = (cri * wi[2] + crj * wj[2]) * rinv;
      const double vtr[3] = {vt1 - (delz * wr2 - dely * wr3), vt2 - (delx * wr3 - delz * wr1),
                             vt3 - (dely * wr1 - delx * wr2)};

      // normal model hertz/scaled, elastic (eq. 8-9)
      const crush::HertzMindlinStiffness k = crush::contact_stiffness(
          {normal_i[jtype], shear_i[jtype]}, crush::diameter_term_from_radii(radi, radj), deltan);
      const double Fn = k.normal * deltan;
      if (sums) sums->record(i, j, k);

      // tangential model mindlin/scaled: the stored shear force acts on i, its opposite on j
      double *const shear = &history[shear_offset];
      double Fs[3] = {shear[0], shear[1], shear[2]};
      if (shearupdate) crush::increment_shear_force(Fs, en, k.shear * dt, vtr);
      crush::cap_at_coulomb(Fs, friction_i[jtype] * fabs(Fn));
      if (shearupdate) {
        shear[0] = Fs[0];
        shear[1] = Fs[1];
        shear[2] = Fs[2];
      }
      contact_flags[jj] |= touching_flags;
      const double tor1 = en[1] * Fs[2] - en[2] * Fs[1];
      const double tor2 = en[2] * Fs[0] - en[0] * Fs[2];
      const double tor3 = en[0] * Fs[1] - en[1] * Fs[0];
      if (RECORD)
        recorder->record(i, j, false, itype, jtype, recorder->total_force ? Fn : k.normal * deltan,
                         radi * radj / (radi + radj));

      // as the generic loop sums them: each model's part into the pair's increment, then into f
      const double relax_i = pg->relax(i);
      double *const fi = f[i], *const ti = torque[i];
      fi[0] += relax_i * (Fn * en[0] + Fs[0]);
      fi[1] += relax_i * (Fn * en[1] + Fs[1]);
      fi[2] += relax_i * (Fn * en[2] + Fs[2]);
      ti[0] += relax_i * -(cri * tor1);
      ti[1] += relax_i * -(cri * tor2);
      ti[2] += relax_i * -(cri * tor3);
      if (newton_pair || j < nlocal) {
        const double relax_j = pg->relax(j);
        double *const fj = f[j], *const tj = torque[j];
        fj[0] += relax_j * (-(Fn * en[0]) - Fs[0]);
        fj[1] += relax_j * (-(Fn * en[1]) - Fs[1]);
        fj[2] += relax_j * (-(Fn * en[2]) - Fs[2]);
        tj[0] += relax_j * -(crj * tor1);
        tj[1] += relax_j * -(crj * tor2);
        tj[2] += relax_j * -(crj * tor3);
      }
    }
  }
}

}  // namespace HertzMindlinScaledPass

// hertz/scaled + mindlin/scaled, no cohesion, no rolling resistance: the loop above, when it applies.
inline bool dedicated_pass(LAMMPS_NS::LAMMPS *lmp, HertzMindlinScaledPass::Model &cmodel, LAMMPS_NS::PairGran *pg,
                           int eflag, int vflag, int addflag)
{
  if (!HertzMindlinScaledPass::applies(lmp, cmodel, pg, eflag, vflag, addflag)) return false;
  HertzMindlinScaledPass::announce(lmp);
  if (const LAMMPS_NS::ContactLoadRecorder *recorder = cmodel.loadRecorder())
    HertzMindlinScaledPass::run<true>(lmp, cmodel, pg, recorder);
  else
    HertzMindlinScaledPass::run<false>(lmp, cmodel, pg, 0);
  return true;
}

}  // namespace PairStyles
}  // namespace LIGGGHTS

#endif
