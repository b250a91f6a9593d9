// How the contact models find a fix's recorder (contact_monitor.h), and the stiffness sums they feed
// fix dt/stiffness (contact_stiffness_monitor.h): the same sums as adding each contact by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact_load_monitor.h"
#include "contact_stiffness_monitor.h"
#include "critical_step_law.h"

namespace {
// Stand-ins for two LAMMPS instances: the monitor only keys on the pointer.
LAMMPS_NS::LAMMPS *instance(int k) { return reinterpret_cast<LAMMPS_NS::LAMMPS *>(0x1000 + 0x100 * k); }
}  // namespace

TEST(ContactMonitor, SeesAttachAndDetachOfItsOwnInstanceOnly)
{
  using LAMMPS_NS::ContactStiffnessMonitor;
  LAMMPS_NS::ContactStiffnessRecorder a, b;
  ContactStiffnessMonitor first(instance(1)), second(instance(2));
  EXPECT_EQ(first.recorder(), nullptr);
  ContactStiffnessMonitor::attach(instance(1), &a);
  EXPECT_EQ(first.recorder(), &a);
  EXPECT_EQ(second.recorder(), nullptr);
  ContactStiffnessMonitor::attach(instance(2), &b);
  EXPECT_EQ(first.recorder(), &a);
  EXPECT_EQ(second.recorder(), &b);
  ContactStiffnessMonitor::attach(instance(1), nullptr);
  EXPECT_EQ(first.recorder(), nullptr);
  EXPECT_EQ(second.recorder(), &b);
  ContactStiffnessMonitor::attach(instance(2), nullptr);
  EXPECT_EQ(second.recorder(), nullptr);
}

TEST(ContactMonitor, KindsOfRecorderAreIndependent)
{
  LAMMPS_NS::ContactStiffnessRecorder sums;
  LAMMPS_NS::ContactLoadMonitor load(instance(3));
  LAMMPS_NS::ContactStiffnessMonitor stiffness(instance(3));
  LAMMPS_NS::ContactStiffnessMonitor::attach(instance(3), &sums);
  EXPECT_EQ(load.recorder(), nullptr);
  EXPECT_EQ(stiffness.recorder(), &sums);
  LAMMPS_NS::ContactStiffnessMonitor::attach(instance(3), nullptr);
}

TEST(ContactStiffnessRecorder, SumsBothPartnersAsTheWalkDid)
{
  // Three contacts among particles 0, 1, 2 (2 a ghost): each partner gets 1.5 k_N + k_S and k_S, the
  // same bits as crush::add_contact from the diameter term and overlap.
  const crush::ShearMaterial quartz{3e9, 0.3};
  const auto c = crush::hertz_mindlin_coefficients(quartz, quartz);
  const struct { int i, j; double dt, U; } contacts[] = {
      {0, 1, 1.0e-4, 2e-7}, {0, 2, 1.2e-4, 5e-8}, {1, 2, 0.8e-4, 1e-7}};
  std::vector<crush::ContactStiffness> sums(3), by_hand(3);
  LAMMPS_NS::ContactStiffnessRecorder recorder;
  recorder.sum = sums.data();
  for (const auto &k : contacts) {
    recorder.record(k.i, k.j, crush::contact_stiffness(c, k.dt, k.U));
    crush::add_contact(by_hand[k.i], c, k.dt, k.U);
    crush::add_contact(by_hand[k.j], c, k.dt, k.U);
  }
  for (int p = 0; p < 3; ++p) {
    EXPECT_EQ(sums[p].translational, by_hand[p].translational);
    EXPECT_EQ(sums[p].shear, by_hand[p].shear);
  }
  const double kN = c.normal * std::sqrt(1.0e-4 * 2e-7), kS = c.shear * std::sqrt(1.0e-4 * 2e-7);
  const double kN2 = c.normal * std::sqrt(1.2e-4 * 5e-8), kS2 = c.shear * std::sqrt(1.2e-4 * 5e-8);
  EXPECT_DOUBLE_EQ(sums[0].translational, 1.5 * kN + kS + 1.5 * kN2 + kS2);
  EXPECT_DOUBLE_EQ(sums[0].shear, kS + kS2);
}

namespace {
// The fields of LIGGGHTS' SurfacesIntersectData that the recorder reads.
struct Contact {
  int i, j, itype, jtype;
  bool is_wall;
  double radi, radj, kn, deltan, Fn;
};
}  // namespace

TEST(ContactLoadRecorder, ReadsAnyModelsContactThroughItsStiffnessOrItsTotalForce)
{
  LAMMPS_NS::ContactLoadRecorder recorder;
  std::vector<double> load(3, 0.0);
  std::vector<double> row(2, 4.0);  // (4E'/3)^2 = 4 Pa^2 for type 1 with 1
  std::vector<double *> factor = {row.data(), row.data()};
  recorder.load = load.data();
  recorder.limit_factor = factor.data();
  // a pair contact: r' = 2*3/(2+3) = 1.2, elastic force k_n U = 10 * 0.5 = 5 (total F_n 7: damping)
  const Contact pair = {0, 1, 1, 1, false, 2.0, 3.0, 10.0, 0.5, 7.0};
  recorder.record(pair);
  EXPECT_DOUBLE_EQ(load[0], 5.0 * 4.0 / (1.2 * 1.2));
  EXPECT_DOUBLE_EQ(load[1], load[0]);
  recorder.total_force = true;
  recorder.record(pair);
  EXPECT_DOUBLE_EQ(load[0], 7.0 * 4.0 / (1.2 * 1.2));
  // a wall: r' = r_i, the partner index is not written; a smaller load leaves the largest in place
  const Contact wall = {2, 0, 1, 1, true, 2.0, 0.0, 1.0, 0.5, 0.5};
  recorder.record(wall);
  EXPECT_DOUBLE_EQ(load[2], 0.5 * 4.0 / (2.0 * 2.0));
  EXPECT_DOUBLE_EQ(load[0], 7.0 * 4.0 / (1.2 * 1.2));
}
