// No allocation inside a step (docs/architecture.md, Model and Data): once an integrator is set up,
// advancing a multibody system through many steps, events included, allocates nothing. Global
// operator new is replaced in this test binary to count allocations while a flag is raised.
#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "runtime/integrate/make_integrator.h"
#include "runtime/run/system.h"
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

struct Counted {
  long allocations = 0;
  long steps = 0;
};

// Advances from 0 to each multiple of `interval` up to `outputs` of them with `method`, counting
// allocations after the first (which warms up any lazily sized buffer of the method) and calling
// `after_each` after every counted Advance.
template <typename AfterEach>
Counted AdvanceCounting(const Model& model, Data& data, const char* method, double interval,
                        int outputs, AfterEach after_each) {
  MultibodySystem system(model, data);
  std::vector<double> y(system.size());
  system.Store(y);
  auto integrator = MakeIntegrator(method);
  IntegratorOptions options;
  options.relative_tolerance = 1e-8;
  integrator->Reset(system, 0.0, y, options);
  integrator->Advance(interval);
  allocations = 0;
  counting = true;
  for (int k = 2; k <= outputs; ++k) {
    integrator->Advance(interval * k);
    after_each();
  }
  counting = false;
  return {allocations.load(), integrator->stats().steps};
}

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
    const Counted counted = AdvanceCounting(model, data, method, 0.01, 100, [] {});
    EXPECT_EQ(counted.allocations, 0) << method;
    EXPECT_GT(counted.steps, 50) << method;
  }
}

// Two spheres, each wrapped by a belt with friction and a lossy webbing function; the belts form
// a harness joined at a tie point with friction. Both spheres move into their belts.
TEST(NoAllocation, BeltsAllocateNothing) {
  Model model;
  model.gravity.setZero();
  for (const char* name : {"a", "b"}) {
    testing::AddSegment(model, name, -1, JointKind::kFree, 1.0, Vec3(2e-4, 2e-4, 2e-4));
  }
  model.q0[0] = 0.05;
  model.q0[1] = -0.5;
  model.q0[7] = 0.05;
  model.q0[8] = 0.5;
  model.v0[3] = 2.0;  // a: along its x
  model.v0[9] = 1.0;  // b: along its x
  model.v0[2] = 5.0;  // a spins
  testing::AddTableFunction(model.functions, {{0, 0}, {1, 20000}}, 0.4, 0.1);
  BeltTable& belts = model.belts;
  belts.harness_name.push_back("harness");
  belts.harness_friction.push_back(0.3);
  const Vec3 ends[2][2] = {{Vec3(0, -1, 0), Vec3(0, 0, 0)}, {Vec3(0, 0, 0), Vec3(0, 1, 0)}};
  for (int b = 0; b < 2; ++b) {
    belts.name.push_back(b == 0 ? "harness.left" : "harness.right");
    belts.function.push_back(0);
    belts.slack.push_back(0.001);
    belts.pretension.push_back(0.0);
    belts.friction.push_back(0.2);
    belts.harness.push_back(0);
    belts.first_point.push_back(3 * b);
    belts.point_count.push_back(3);
    for (int k = 0; k < 3; ++k) {
      const bool wraps = k == 1;
      belts.point_frame.push_back(wraps ? FrameRef{FrameRef::Kind::kSegment, b} : FrameRef{});
      belts.point_wraps.push_back(wraps ? 1 : 0);
      belts.point_position.push_back(wraps ? Vec3::Zero() : ends[b][k / 2]);
      belts.point_axes.push_back(Mat3::Identity());
      belts.point_semi_axes.push_back(wraps ? Vec3(0.03, 0.02, 0.02) : Vec3::Zero());
    }
  }
  belts.tie_points.push_back({2, 3});
  belts.tie_harness.push_back(0);
  for (const char* method : {"exponential", "dopri5", "rosenbrock"}) {
    Data data = MakeData(model);
    double largest = 0.0;
    const Counted counted = AdvanceCounting(model, data, method, 0.001, 60, [&] {
      largest = std::max(largest, data.belts.tension[1]);
    });
    EXPECT_EQ(counted.allocations, 0) << method;
    EXPECT_GT(largest, 10.0) << method;  // the belts did pull
    EXPECT_GT(counted.steps, 30) << method;
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

TEST(NoAllocation, AirbagsAllocateNothing) {
  // A ball falling into a ground-fixed bag that deploys, unfolds around it (the envelope's scale
  // solved by iteration), becomes full, pushes it back and vents until it is slack again: every
  // airbag event included.
  Model model;
  testing::AddSegment(model, "ball", -1, JointKind::kFree, 5.0, Vec3(0.05, 0.05, 0.05));
  model.q0[2] = 0.5;
  model.v0[5] = -3.0;  // the linear velocity of a free root follows its angular velocity
  FunctionTable& f = model.functions;
  f.kind = {FunctionTable::Kind::kTable};
  f.constant = {0};
  f.first = {0};
  f.count = {3};
  f.energy_loss = {0};
  f.permanent_set = {0};
  f.points_x = {0.0, 0.002, 0.01};
  f.points_y = {0.0, 5.0, 0.0};  // 25 g: more than fills it
  AirbagTable& bag = model.airbags;
  bag.name = {"bag"};
  bag.frame = {{FrameRef::Kind::kGround, -1}};
  bag.deploy_point = {Vec3::Zero()};
  bag.axes = {(Mat3() << 0, 0, -1, 0, 1, 0, 1, 0, 0).finished()};  // x up
  bag.semi_axes = {Vec3(0.2, 0.2, 0.2)};
  bag.deploy_time = {0.002};
  bag.inflow = {0};
  bag.inflow_temperature = {600};
  bag.vent_area = {1e-3};
  bag.discharge_coefficient = {0.6};
  bag.ambient_pressure = {101325};
  bag.gamma = {1.4};
  bag.gas_constant = {287};
  bag.state_address = {0};
  bag.free_bag = {0};
  bag.bag_mass = {0};
  bag.mass_factor = {1};
  bag.tether_stiffness = {0};
  bag.vent_opening_pressure = {0};
  bag.first_contact = {0};
  bag.contact_count = {1};
  bag.source = {{}};
  bag.contact_segment = {0};
  bag.contact_center = {Vec3::Zero()};
  bag.contact_axes = {Mat3::Identity()};
  bag.contact_semi_axes = {Vec3(0.1, 0.1, 0.1)};
  bag.contact_radius = {0.1};
  model.nw = 2;
  model.w0 = {0.0, 0.0};
  // Runs every method; `vents_slack`: the bag ends slack again (the energy bag unfolds again
  // once vented down to the ambient pressure; ATB's free bag stays full).
  auto run_all = [&](bool vents_slack) {
    for (const char* method : {"exponential", "dopri5", "rosenbrock"}) {
      Data data = MakeData(model);
      double peak_force = 0.0;
      bool was_full = false;
      const Counted counted = AdvanceCounting(model, data, method, 0.002, 50, [&] {
        peak_force = std::max(peak_force, data.airbags.force[0].norm());
        was_full = was_full || data.airbags.full[0] != 0;
      });
      EXPECT_EQ(counted.allocations, 0) << method;
      EXPECT_GT(peak_force, 0.0) << method;
      EXPECT_TRUE(was_full) << method;
      if (vents_slack) {
        EXPECT_EQ(data.airbags.full[0], 0) << method;
      }
    }
  };
  run_all(true);
  // The same bag as ATB's free bag on a spring: its motion starts at the full event.
  bag.free_bag = {1};
  bag.bag_mass = {0.1};
  bag.tether_stiffness = {1000};
  model.nw = AirbagTable::kFreeBagStates;
  model.w0.assign(static_cast<std::size_t>(AirbagTable::kFreeBagStates), 0.0);
  run_all(false);
}

}  // namespace
}  // namespace sled::runtime
