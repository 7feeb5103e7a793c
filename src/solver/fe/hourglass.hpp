#pragma once
/// Hourglass control of the under-integrated elements (solids ELFORM 1, shells): the form and
/// coefficient a part takes from *HOURGLASS or *CONTROL_HOURGLASS.
#include "model/model_database.hpp"
#include "solver/material/point_kinematics.hpp"  // BulkViscosityParams

namespace mcdyna::solver {

/// How the hourglass modes are resisted: IHQ 1-3 by viscous forces, 4-5 by stiffness.
enum class HourglassForm { viscous, stiffness };

struct HourglassParams {
  HourglassForm form = HourglassForm::viscous;  ///< from IHQ
  double coefficient = 0.1;                     ///< QM
  [[nodiscard]] bool stiffness() const { return form == HourglassForm::stiffness; }
};

namespace detail {
/// The part's *HOURGLASS (HGID), or null; and the hourglass type and coefficient it runs with
/// (*CONTROL_HOURGLASS without one), with its Q1, Q2 into `q`.
const model::Hourglass* part_hourglass(const model::ModelDatabase& m, const model::Part& part);
HourglassParams hourglass_of(const model::ModelDatabase& m, const model::Part& part,
                             BulkViscosityParams& q);
}  // namespace detail

}  // namespace mcdyna::solver
