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

}  // namespace
}  // namespace sled::runtime
