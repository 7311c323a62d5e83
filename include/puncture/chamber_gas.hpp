#pragma once
// The gas of a sealed chamber under the membrane in one state (Preload::gas_volume_mm3,
// docs/model.md §17.1).

namespace puncture {

struct ChamberGas {
  double pressure_mpa = 0.0;  // gauge pressure p of the gas [MPa]
  // V, the volume between the membrane and its flat (clamp) plane [mm^3]: the gas fills V0 + V.
  double volume_mm3 = 0.0;
};

}  // namespace puncture
