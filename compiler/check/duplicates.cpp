// Elements declared twice. A contact pair declared twice doubles its force, and two output
// requests that write the same channels give two columns of one name (or criteria of one name):
// both are errors. Two belts along the same path or two springs between the same points can be
// meant (a double strap, two springs in parallel), so they are warnings that say what it does.
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "compiler/check/checkers.h"

namespace sled::compiler::internal {
namespace {

std::tuple<int, int, int, int> PairKey(const SurfaceRef& a, const SurfaceRef& b) {
  // Ellipsoid pairs are the same contact in either order.
  auto key_of = [](const SurfaceRef& s) {
    return std::make_pair(static_cast<int>(s.kind), s.index);
  };
  auto first = key_of(a), second = key_of(b);
  if (a.kind == b.kind && second < first) std::swap(first, second);
  return {first.first, first.second, second.first, second.second};
}

using PointKey = std::tuple<int, int, double, double, double>;
PointKey KeyOf(const FrameRef& frame, const Vec3& point) {
  return {static_cast<int>(frame.kind), frame.index, point[0], point[1], point[2]};
}

// The element declared first with this key, or null when `element` is the first.
template <class Key, class Element>
const Element* Earlier(std::map<Key, const Element*>& seen, Key key, const Element& element) {
  const auto [it, added] = seen.emplace(std::move(key), &element);
  return added ? nullptr : it->second;
}

}  // namespace

void DuplicateChecker::ReportDuplicate(DiagnosticKind kind, SourceRange again, SourceRange first,
                                       std::string message, std::string help) {
  auto diagnostic = lang::MakeDiagnostic(kind, again, std::move(message), "declared again here");
  diagnostic.labels.push_back({first, "first here", false});
  diagnostic.help = std::move(help);
  diagnostics_.Consume(std::move(diagnostic));
}

void DuplicateChecker::CheckDuplicates() {
  auto surface_name = [&](const SurfaceRef& s) {
    return s.kind == SurfaceRef::Kind::kPlane
               ? scenario_.planes[static_cast<std::size_t>(s.index)].name
               : scenario_.ellipsoids[static_cast<std::size_t>(s.index)].name;
  };
  std::map<std::tuple<int, int, int, int>, std::size_t> pairs;
  for (std::size_t i = 0; i < scenario_.contacts.size(); ++i) {
    const Contact& contact = scenario_.contacts[i];
    const auto [it, added] = pairs.emplace(PairKey(contact.first, contact.second), i);
    const Contact& first = scenario_.contacts[it->second];
    // One statement may name a segment whose ellipsoids meet a surface in several pairs.
    if (added || first.range.begin == contact.range.begin) continue;
    ReportDuplicate(DiagnosticKind::kDuplicateContact, contact.range, first.range,
                    fmt::format("`{}` and `{}` are in contact twice: the force would count twice",
                                surface_name(contact.first), surface_name(contact.second)),
                    "declare each pair of surfaces once; a segment in a contact stands for all "
                    "its ellipsoids");
  }

  std::map<std::pair<int, std::string>, const OutputRequest*> channels;
  for (const OutputRequest& output : scenario_.outputs) {
    const auto* first = Earlier(channels, {static_cast<int>(output.kind), output.label}, output);
    if (!first) continue;
    ReportDuplicate(DiagnosticKind::kDuplicateOutput, output.range, first->range,
                    fmt::format("a second request for the channels `{}.*` of this kind: two "
                                "columns of the same name",
                                output.label),
                    "remove one, or name each with `as NAME` (`acceleration occupant.head at "
                    "(0, 0, 50) mm as head_top`)");
  }
  std::map<std::tuple<int, int, int>, const Criterion*> criteria;
  for (const Criterion& criterion : scenario_.criteria) {
    const auto* first =
        Earlier(criteria, {static_cast<int>(criterion.kind), criterion.segment, criterion.joint},
                criterion);
    if (!first) continue;
    ReportDuplicate(DiagnosticKind::kDuplicateOutput, criterion.range, first->range,
                    "this criterion of this target is requested twice", "remove one of them");
  }

  std::map<std::vector<PointKey>, const Belt*> paths;
  for (const Belt& belt : scenario_.belts) {
    std::vector<PointKey> path;
    for (const BeltPoint& point : belt.path) {
      path.push_back(point.kind == BeltPoint::Kind::kAnchor
                         ? KeyOf(point.frame, point.point)
                         : PointKey{-1, point.segment, 0.0, 0.0, 0.0});
    }
    const auto* first = Earlier(paths, std::move(path), belt);
    if (!first) continue;
    ReportDuplicate(DiagnosticKind::kDuplicateElement, belt.range, first->range,
                    fmt::format("belt `{}` runs along the same path as `{}`: both pull, so the "
                                "restraint is twice as stiff",
                                belt.name, first->name),
                    "if one webbing is meant, remove the other; for a double strap, give one "
                    "webbing the force of both");
  }
  std::map<std::pair<PointKey, PointKey>, const SpringDamper*> ends;
  for (const SpringDamper& spring : scenario_.springs) {
    PointKey a = KeyOf(spring.first, spring.point_in_first);
    PointKey b = KeyOf(spring.second, spring.point_in_second);
    if (b < a) std::swap(a, b);
    const auto* first = Earlier(ends, {a, b}, spring);
    if (!first) continue;
    ReportDuplicate(DiagnosticKind::kDuplicateElement, spring.range, first->range,
                    fmt::format("spring `{}` joins the same two points as `{}`: they act in "
                                "parallel, their forces add",
                                spring.name, first->name),
                    "if one spring is meant, remove the other; for two in parallel, one spring "
                    "with the sum of their stiffnesses says so");
  }
}

}  // namespace sled::compiler::internal
