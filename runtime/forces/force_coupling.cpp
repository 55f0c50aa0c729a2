#include "runtime/forces/force_coupling.h"

#include <algorithm>

namespace sled::runtime {
namespace {

void AddFrame(const FrameRef& frame, std::vector<std::int32_t>& segments) {
  if (frame.kind != FrameRef::Kind::kSegment) return;
  if (std::find(segments.begin(), segments.end(), frame.index) == segments.end()) {
    segments.push_back(frame.index);
  }
}

void AddSegment(std::int32_t segment, std::vector<std::int32_t>& segments) {
  AddFrame(FrameRef{FrameRef::Kind::kSegment, segment}, segments);
}

// A belt's path frames; a harness's belts pass webbing through their tie points, so a harness
// is one element.
void AddBelts(const BeltTable& belts, std::vector<std::vector<std::int32_t>>& elements) {
  std::vector<std::int32_t> element_of_harness(belts.harness_name.size(), -1);
  for (std::size_t b = 0; b < belts.size(); ++b) {
    std::vector<std::int32_t>* segments = nullptr;
    const std::int32_t harness = belts.harness[b];
    if (harness >= 0 && element_of_harness[static_cast<std::size_t>(harness)] >= 0) {
      segments = &elements[static_cast<std::size_t>(
          element_of_harness[static_cast<std::size_t>(harness)])];
    } else {
      elements.emplace_back();
      if (harness >= 0) {
        element_of_harness[static_cast<std::size_t>(harness)] =
            static_cast<std::int32_t>(elements.size() - 1);
      }
      segments = &elements.back();
    }
    const auto first = static_cast<std::size_t>(belts.first_point[b]);
    const auto count = static_cast<std::size_t>(belts.point_count[b]);
    for (std::size_t p = first; p < first + count; ++p) AddFrame(belts.point_frame[p], *segments);
  }
}

}  // namespace

ForceCoupling MakeForceCoupling(const Model& model) {
  ForceCoupling coupling;
  auto& elements = coupling.elements;
  const ContactTable& contacts = model.contacts;
  for (std::size_t k = 0; k < contacts.npair(); ++k) {
    elements.emplace_back();
    AddFrame(contacts.ellipsoid_frame[static_cast<std::size_t>(contacts.pair_first[k])],
             elements.back());
    const auto second = static_cast<std::size_t>(contacts.pair_second[k]);
    AddFrame(contacts.pair_kind[k] == ContactTable::PairKind::kPlaneEllipsoid
                 ? contacts.plane_frame[second]
                 : contacts.ellipsoid_frame[second],
             elements.back());
  }
  for (std::size_t k = 0; k < model.nspring(); ++k) {
    elements.emplace_back();
    AddFrame(model.spring_first[k], elements.back());
    AddFrame(model.spring_second[k], elements.back());
  }
  AddBelts(model.belts, elements);
  const AirbagTable& bags = model.airbags;
  for (std::size_t b = 0; b < bags.size(); ++b) {
    elements.emplace_back();
    AddFrame(bags.frame[b], elements.back());
    const auto first = static_cast<std::size_t>(bags.first_contact[b]);
    const auto count = static_cast<std::size_t>(bags.contact_count[b]);
    for (std::size_t c = first; c < first + count; ++c) {
      AddSegment(bags.contact_segment[c], elements.back());
    }
    coupling.airbag_element.push_back(static_cast<std::int32_t>(elements.size() - 1));
  }
  // Elements that touch no segment (a contact between a vehicle and the ground) couple nothing.

  const std::size_t n = model.nsegment();
  coupling.neighbours.assign(n, {});
  std::vector<char> coupled(n, 0);
  for (const auto& element : elements) {
    for (const std::int32_t a : element) {
      coupled[static_cast<std::size_t>(a)] = 1;
      auto& list = coupling.neighbours[static_cast<std::size_t>(a)];
      for (const std::int32_t b : element) {
        if (std::find(list.begin(), list.end(), b) == list.end()) list.push_back(b);
      }
    }
  }
  for (auto& list : coupling.neighbours) std::sort(list.begin(), list.end());

  // Greedy distance-2 colouring: a segment may not share a colour with any segment within two
  // steps (a neighbour, or a neighbour's neighbour).
  coupling.colour.assign(n, -1);
  std::vector<char> taken;
  for (std::size_t s = 0; s < n; ++s) {
    if (!coupled[s]) continue;
    taken.assign(static_cast<std::size_t>(coupling.colours) + 1, 0);
    for (const std::int32_t a : coupling.neighbours[s]) {
      for (const std::int32_t b : coupling.neighbours[static_cast<std::size_t>(a)]) {
        const std::int32_t c = coupling.colour[static_cast<std::size_t>(b)];
        if (c >= 0) taken[static_cast<std::size_t>(c)] = 1;
      }
    }
    std::int32_t c = 0;
    while (taken[static_cast<std::size_t>(c)]) ++c;
    coupling.colour[s] = c;
    coupling.colours = std::max(coupling.colours, c + 1);
  }
  coupling.owner.assign(static_cast<std::size_t>(coupling.colours),
                        std::vector<std::int32_t>(n, -1));
  for (std::size_t s = 0; s < n; ++s) {
    for (const std::int32_t a : coupling.neighbours[s]) {
      const std::int32_t c = coupling.colour[static_cast<std::size_t>(a)];
      coupling.owner[static_cast<std::size_t>(c)][s] = a;
    }
  }
  return coupling;
}

}  // namespace sled::runtime
