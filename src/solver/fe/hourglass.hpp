#pragma once
/// Hourglass control of the under-integrated elements (solids ELFORM 1, shells): the form and
/// coefficient a part takes from *HOURGLASS or *CONTROL_HOURGLASS.

namespace mcdyna::solver {

/// How the hourglass modes are resisted: IHQ 1-3 by viscous forces, 4-5 by stiffness.
enum class HourglassForm { viscous, stiffness };

struct HourglassParams {
  HourglassForm form = HourglassForm::viscous;  ///< from IHQ
  double coefficient = 0.1;                     ///< QM
  [[nodiscard]] bool stiffness() const { return form == HourglassForm::stiffness; }
};

}  // namespace mcdyna::solver
