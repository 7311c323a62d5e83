#include "standard_test.hpp"

#include <algorithm>

namespace puncture::cli {

AstmF1306Outputs astm_f1306_outputs(const LoadingCurve& curve) {
  const PuncturePrediction& p = curve.puncture;
  AstmF1306Outputs out;
  out.maximum_force_n = p.force_n;
  for (const CurvePoint& pt : curve.points)
    if (pt.depth_mm <= p.depth_mm) out.maximum_force_n = std::max(out.maximum_force_n, pt.force_n);
  out.penetration_mm = p.depth_mm;
  out.energy_mj = p.energy_to_puncture_mj;
  return out;
}

}  // namespace puncture::cli
