// Nij, the neck injury criterion: at each instant Nij = Fz / Fzc + MOCy / Myc, where the
// critical intercepts Fzc and Myc are those of the load's current sense (tension or compression,
// flexion or extension). Each sample falls in exactly one of the four quadrants NTE, NTF, NCE,
// NCF; the criterion is the largest value over time. The moment about the occipital condyle is
// MOCy = My - D * Fx for a load cell D below it.
#pragma once

#include <array>
#include <span>

namespace sled::runtime::post {

// Critical intercepts [N, N*m], all positive.
struct NeckIntercepts {
  double tension = 0.0;
  double compression = 0.0;
  double flexion = 0.0;
  double extension = 0.0;
};
// Hybrid III 50th male, in position (FMVSS 208).
inline constexpr NeckIntercepts kHybridIII50thMale{6806.0, 6160.0, 310.0, 135.0};
// Nkm (Schmitt, Muser and Niederer, ESV 2001, paper 124: a neck criterion for rear impacts)
// has the same form with the shear force Fx in place of the axial force: Nkm = Fx / Fint +
// My / Mint, with Fint = 845 N for both shear senses, Mint = 88.1 N*m in flexion and 47.5 N*m in
// extension; its limit is 1.0. Pass the shear as `fz` to NeckInjuryCriterion; its tension and
// compression quadrants are then the anterior and posterior shear (NkmQuadrantName).
inline constexpr NeckIntercepts kNkmIntercepts{845.0, 845.0, 88.1, 47.5};
// The upper-neck load cell of the Hybrid III sits this far below the occipital condyle [m].
inline constexpr double kHybridIIICondyleOffset = 0.01778;

enum class NeckQuadrant {
  kTensionExtension,
  kTensionFlexion,
  kCompressionExtension,
  kCompressionFlexion
};
// "NTE", "NTF", "NCE", "NCF".
const char* QuadrantName(NeckQuadrant quadrant);
// The same quadrants of Nkm: "NEA", "NFA", "NEP", "NFP" (extension or flexion, anterior or
// posterior shear).
const char* NkmQuadrantName(NeckQuadrant quadrant);

struct QuadrantPeak {
  double value = 0.0;  // 0 when the load never entered the quadrant
  double time = 0.0;
  bool reached = false;
};

struct NijResult {
  double value = 0.0;  // the largest of the four
  double time = 0.0;
  NeckQuadrant quadrant = NeckQuadrant::kTensionExtension;
  std::array<QuadrantPeak, 4> quadrants{};  // by NeckQuadrant
};

// Signs as SAE J211 reads the upper neck load cell: fz > 0 tension, my > 0 flexion; fx shear.
// `condyle_offset` is D (0 when the moment is already taken about the condyle).
NijResult NeckInjuryCriterion(std::span<const double> fz, std::span<const double> fx,
                              std::span<const double> my, double condyle_offset,
                              const NeckIntercepts& intercepts, double sample_period,
                              double start_time);

}  // namespace sled::runtime::post
