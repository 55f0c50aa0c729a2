// No allocation inside a step (DESIGN.md §4): once an integrator is set up, advancing a
// multibody system through many steps, events included, allocates nothing. Global operator new
// is replaced in this test binary to count allocations while a flag is raised.
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "runtime/integrate/make_integrator.h"
#include "runtime/system.h"
#include "tests/runtime/model_fixtures.h"

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

// The replaced operators pair malloc with free; GCC, seeing free reached from code that called
// operator new once the replacements are inlined, warns of a mismatch that is not there.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t size) {
  if (counting) ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace sled::runtime {
namespace {

TEST(NoAllocation, AdvancingAllocatesNothing) {
  Model model;
  testing::AddSegment(model, "pelvis", -1, JointKind::kFree, 10.0, Vec3(0.1, 0.1, 0.1));
  testing::AddSegment(model, "arm", 0, JointKind::kBall, 2.0, Vec3(0.02, 0.02, 0.01),
                      Vec3(0, 0.2, 0.1), Vec3(0, 0, 0.15));
  testing::AddSegment(model, "forearm", 1, JointKind::kPin, 1.0, Vec3(0.01, 0.01, 0.002),
                      Vec3(0, 0, -0.15), Vec3(0, 0, 0.12), Vec3::UnitY());
  testing::AddSegment(model, "hand", 2, JointKind::kEuler, 0.5, Vec3(0.001, 0.001, 0.001),
                      Vec3(0, 0, -0.12), Vec3(0, 0, 0.05));
  model.joint_stop[2] = 0.5;
  model.joint_stop_impulse[2] = 1;
  model.joint_restitution[2] = 0.5;
  for (std::size_t k = 0; k < model.v0.size(); ++k)
    model.v0[k] = 1.0 + 0.1 * static_cast<double>(k);
  for (const char* method : {"exponential", "dopri5", "rosenbrock"}) {
    Data data = MakeData(model);
    MultibodySystem system(model, data);
    std::vector<double> y(system.size());
    system.Store(y);
    auto integrator = MakeIntegrator(method);
    IntegratorOptions options;
    options.relative_tolerance = 1e-8;
    integrator->Reset(system, 0.0, y, options);
    integrator->Advance(0.01);  // warm up any lazily sized buffer of the method
    allocations = 0;
    counting = true;
    for (int k = 2; k <= 100; ++k) integrator->Advance(0.01 * k);
    counting = false;
    EXPECT_EQ(allocations.load(), 0) << method;
    EXPECT_GT(integrator->stats().steps, 50) << method;
  }
}

TEST(NoAllocation, ContactsAllocateNothing) {
  // A ball on a floor and a hyper-ellipsoid dropped on it: plane pairs with friction, energy
  // loss and the first-contact impulse (an event and the history commit), and an ellipsoid pair.
  Model model;
  testing::AddSegment(model, "low", -1, JointKind::kFree, 1.0, Vec3(0.004, 0.004, 0.004));
  testing::AddSegment(model, "high", -1, JointKind::kFree, 1.0, Vec3(0.004, 0.004, 0.004));
  model.q0[2] = 0.12;
  model.q0[7] = 0.03;
  model.q0[9] = 0.35;
  model.v0[3] = 0.5;
  FunctionTable& f = model.functions;
  f.kind = {FunctionTable::Kind::kPolynomial};
  f.constant = {0};
  f.first = {0};
  f.count = {2};
  f.energy_loss = {0.4};
  f.permanent_set = {0.1};
  f.coefficients = {0.0, 1e4};
  ContactTable& c = model.contacts;
  c.ellipsoid_name = {"low", "high"};
  c.ellipsoid_frame = {{FrameRef::Kind::kSegment, 0}, {FrameRef::Kind::kSegment, 1}};
  c.ellipsoid_center = {Vec3::Zero(), Vec3::Zero()};
  c.ellipsoid_axes = {Mat3::Identity(), Mat3::Identity()};
  c.ellipsoid_semi_axes = {Vec3(0.1, 0.1, 0.1), Vec3(0.12, 0.1, 0.08)};
  c.ellipsoid_degree = {2.0, 4.0};
  c.ellipsoid_radius = {0.1, 0.15};
  c.plane_name = {"floor"};
  c.plane_frame = {{FrameRef::Kind::kGround, -1}};
  c.plane_origin = {Vec3(-1, -1, 0)};
  c.plane_edge_u = {Vec3(2, 0, 0)};
  c.plane_edge_v = {Vec3(0, 2, 0)};
  c.plane_normal = {Vec3::UnitZ()};
  c.pair_kind = {ContactTable::PairKind::kPlaneEllipsoid, ContactTable::PairKind::kPlaneEllipsoid,
                 ContactTable::PairKind::kEllipsoidEllipsoid};
  c.pair_first = {0, 1, 1};
  c.pair_second = {0, 0, 0};
  c.pair_function = {0, 0, 0};
  c.pair_damping = {20, 20, 20};
  c.pair_damping_depth = {1e-3, 1e-3, 1e-3};
  c.pair_friction = {0.5, 0.5, 0.5};
  c.pair_impulse = {1, 0, 1};
  c.pair_restitution = {0.5, 0, 0.5};
  c.pair_source = {{}, {}, {}};
  for (const char* method : {"exponential", "dopri5", "rosenbrock"}) {
    Data data = MakeData(model);
    MultibodySystem system(model, data);
    std::vector<double> y(system.size());
    system.Store(y);
    auto integrator = MakeIntegrator(method);
    IntegratorOptions options;
    options.relative_tolerance = 1e-6;
    integrator->Reset(system, 0.0, y, options);
    integrator->Advance(0.01);
    allocations = 0;
    counting = true;
    for (int k = 2; k <= 60; ++k) integrator->Advance(0.01 * k);
    counting = false;
    EXPECT_EQ(allocations.load(), 0) << method;
    EXPECT_GE(integrator->stats().events, 1) << method;
    EXPECT_GT(data.contacts.history[0].max_deflection, 0) << method;
  }
}

}  // namespace
}  // namespace sled::runtime
