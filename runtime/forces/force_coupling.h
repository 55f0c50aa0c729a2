// Which segments each force element acting in space couples (contacts, spring-dampers, belts
// and harnesses, airbags), and a colouring of the segments by it, for the structured Jacobian
// (runtime/dynamics/multibody_jacobian.h): the wrench an element puts on a segment depends only on
// the poses and velocities of the segments it couples (and on vehicles and time), so segments that
// share no element, and no neighbour, can be moved at once in one difference quotient.
//
// A new force element that acts between frames adds its segments here (ElementSegments); one
// left out is not a wrong answer (the methods that use the Jacobian stay correct with any), but
// its stiffness may be attributed to the wrong segment and cost long steps.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/model/model.h"

namespace sled::runtime {

struct ForceCoupling {
  // Per element (contact pair, spring, belt or harness, airbag): the segments it couples (no
  // repeats). An airbag's auxiliary states (its gas) belong to its element.
  std::vector<std::vector<std::int32_t>> elements;
  // Per segment: the segments that share an element with it, itself included (sorted).
  std::vector<std::vector<std::int32_t>> neighbours;
  // Per segment: its colour, or -1 when no element couples it. Two segments of one colour
  // share no neighbour and are not neighbours.
  std::vector<std::int32_t> colour;
  std::int32_t colours = 0;
  // Per colour and segment: the segment of that colour among the segment's neighbours, or -1.
  std::vector<std::vector<std::int32_t>> owner;
  // Per airbag: its element's index in `elements`.
  std::vector<std::int32_t> airbag_element;
};

ForceCoupling MakeForceCoupling(const Model& model);

}  // namespace sled::runtime
