// A 1 kg ball dropped 20 mm onto a floor whose contact stiffness and integrator settings the
// test chooses: with a stiffness far too high for the minimum step, every run fails at first
// touch (t = 63.9 ms), which the run and study tests use to see how a failure is reported.
#pragma once

#include <string>

namespace sled::testing {

// `outputs`: the statements of the output block.
inline std::string StiffFloor(const std::string& stiffness, const std::string& integrator,
                              const std::string& outputs = "position ball.sphere") {
  return R"(scenario "stiff floor" {
  time { end = 100 ms  output_every = 1 ms }
  )" + integrator +
         R"(
  plane floor on ground { corners = (-1, -1, 0) m, (1, -1, 0) m, (-1, 1, 0) m }
  body ball {
    segment sphere {
      mass = 1 kg
      inertia = (0.001, 0.001, 0.001) kg*m^2
      ellipsoid { semi_axes = (50, 50, 50) mm }
    }
  }
  contact ball.sphere with floor { force = )" +
         stiffness + R"( }
  initial ball { position = (0, 0, 70) mm }
  output {
    )" + outputs +
         R"(
  }
}
)";
}

}  // namespace sled::testing
