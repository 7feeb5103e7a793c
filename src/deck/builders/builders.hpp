#pragma once
/// Builders turn one typed keyword record into model entities: read -> defaults -> checks ->
/// derived values, reporting problems at the field's deck location. One function per keyword
/// (keywords sharing a layout share a function); the table maps schema names to them.
#include <optional>
#include <string_view>
#include <vector>

#include "deck/record.hpp"
#include "model/model_database.hpp"

namespace mcdyna::deck {

using BuilderFn = void (*)(KeywordRecord&, model::ModelDatabase&);

struct BuilderEntry {
  std::string_view keyword;  ///< canonical schema name
  BuilderFn build;
};

/// Every builder, by the canonical name of the schema it reads.
const std::vector<BuilderEntry>& builder_table();

namespace builders {
// mesh.cpp
void title(KeywordRecord& r, model::ModelDatabase& m);
void node(KeywordRecord& r, model::ModelDatabase& m);
void element_solid(KeywordRecord& r, model::ModelDatabase& m);
void element_shell(KeywordRecord& r, model::ModelDatabase& m);
void element_beam(KeywordRecord& r, model::ModelDatabase& m);
void part(KeywordRecord& r, model::ModelDatabase& m);
void part_inertia(KeywordRecord& r, model::ModelDatabase& m);
// sections.cpp
void section_solid(KeywordRecord& r, model::ModelDatabase& m);
void section_solid_spg(KeywordRecord& r, model::ModelDatabase& m);
void section_shell(KeywordRecord& r, model::ModelDatabase& m);
void section_beam(KeywordRecord& r, model::ModelDatabase& m);
// materials.cpp
void mat_elastic(KeywordRecord& r, model::ModelDatabase& m);
void mat_null(KeywordRecord& r, model::ModelDatabase& m);
void mat_spotweld(KeywordRecord& r, model::ModelDatabase& m);
void mat_plastic_kinematic(KeywordRecord& r, model::ModelDatabase& m);
void mat_johnson_cook(KeywordRecord& r, model::ModelDatabase& m);
void mat_rigid(KeywordRecord& r, model::ModelDatabase& m);
void mat_piecewise_linear_plasticity(KeywordRecord& r, model::ModelDatabase& m);
void mat_add_erosion(KeywordRecord& r, model::ModelDatabase& m);
// eos_hourglass.cpp
void eos_linear_polynomial(KeywordRecord& r, model::ModelDatabase& m);
void eos_gruneisen(KeywordRecord& r, model::ModelDatabase& m);
void hourglass(KeywordRecord& r, model::ModelDatabase& m);
// controls.cpp
void control_termination(KeywordRecord& r, model::ModelDatabase& m);
void control_timestep(KeywordRecord& r, model::ModelDatabase& m);
void control_hourglass(KeywordRecord& r, model::ModelDatabase& m);
void control_contact(KeywordRecord& r, model::ModelDatabase& m);
void control_solid(KeywordRecord& r, model::ModelDatabase& m);
void control_energy(KeywordRecord& r, model::ModelDatabase& m);
void control_bulk_viscosity(KeywordRecord& r, model::ModelDatabase& m);
void control_accuracy(KeywordRecord& r, model::ModelDatabase& m);
void control_shell(KeywordRecord& r, model::ModelDatabase& m);
void control_rigid(KeywordRecord& r, model::ModelDatabase& m);
void damping_global(KeywordRecord& r, model::ModelDatabase& m);
// contact.cpp
void contact(KeywordRecord& r, model::ModelDatabase& m);
// boundary.cpp
void boundary_spc(KeywordRecord& r, model::ModelDatabase& m);
void boundary_prescribed_motion(KeywordRecord& r, model::ModelDatabase& m);
void load_body(KeywordRecord& r, model::ModelDatabase& m);
void load_point(KeywordRecord& r, model::ModelDatabase& m);
void load_segment(KeywordRecord& r, model::ModelDatabase& m);
void initial_velocity(KeywordRecord& r, model::ModelDatabase& m);
void initial_velocity_node(KeywordRecord& r, model::ModelDatabase& m);
void initial_velocity_generation(KeywordRecord& r, model::ModelDatabase& m);
void rigidwall_planar(KeywordRecord& r, model::ModelDatabase& m);
// rigidwall_geometric.cpp
void rigidwall_geometric(KeywordRecord& r, model::ModelDatabase& m);
// constrained.cpp
void constrained_extra_nodes(KeywordRecord& r, model::ModelDatabase& m);
void constrained_rigid_bodies(KeywordRecord& r, model::ModelDatabase& m);
void constrained_spotweld(KeywordRecord& r, model::ModelDatabase& m);
void constrained_nodal_rigid_body(KeywordRecord& r, model::ModelDatabase& m);
void constrained_joint(KeywordRecord& r, model::ModelDatabase& m);
// discrete.cpp
void element_discrete(KeywordRecord& r, model::ModelDatabase& m);
void section_discrete(KeywordRecord& r, model::ModelDatabase& m);
void mat_spring(KeywordRecord& r, model::ModelDatabase& m);
// sensors.cpp
void sensor_define_node(KeywordRecord& r, model::ModelDatabase& m);
void sensor_define_force(KeywordRecord& r, model::ModelDatabase& m);
void sensor_switch(KeywordRecord& r, model::ModelDatabase& m);
void sensor_control(KeywordRecord& r, model::ModelDatabase& m);
void joint_stiffness_generalized(KeywordRecord& r, model::ModelDatabase& m);
void define_coordinate_node(KeywordRecord& r, model::ModelDatabase& m);
// define_sets.cpp
void define_curve(KeywordRecord& r, model::ModelDatabase& m);
void define_vector(KeywordRecord& r, model::ModelDatabase& m);
void define_box(KeywordRecord& r, model::ModelDatabase& m);
void set_segment(KeywordRecord& r, model::ModelDatabase& m);
// sets.cpp: every form of the node, part and element sets (_LIST, _GENERATE(_INCREMENT),
// _COLUMN, _GENERAL, _COLLECT), by the keyword's name.
void set_node(KeywordRecord& r, model::ModelDatabase& m);
void set_part(KeywordRecord& r, model::ModelDatabase& m);
void set_element(KeywordRecord& r, model::ModelDatabase& m);
/// After the whole deck is read: the members of every _GENERAL set from its rules
/// (general_sets.cpp).
void resolve_general_sets(model::ModelDatabase& m, core::Diagnostics& d);
// database.cpp
void database_d3plot(KeywordRecord& r, model::ModelDatabase& m);
void database_ascii(KeywordRecord& r, model::ModelDatabase& m);
void database_restart_dump(KeywordRecord& r, model::ModelDatabase& m);
void database_history_node(KeywordRecord& r, model::ModelDatabase& m);
void database_extent_binary(KeywordRecord& r, model::ModelDatabase& m);

/// Title text of the _TITLE card if present, else "".
std::string title_of(const KeywordRecord& r);
/// The keyword's canonical name after `prefix` ("MAT_024" and "MAT_PIECEWISE_LINEAR_PLASTICITY"
/// both give "PIECEWISE_LINEAR_PLASTICITY" after "MAT_"): how the reports name what it made.
std::string keyword_after(const KeywordRecord& r, std::string_view prefix);
/// Stores a single-instance control, warning if the deck already gave one.
template <typename T>
void set_once(std::optional<T>& slot, T value, const KeywordRecord& r) {
  if (slot) {
    r.diags().warning(r.block().loc, "{} given again; this one replaces the earlier one (line {})",
                      r.display_name(), slot->loc.line);
  }
  slot = std::move(value);
}
}  // namespace builders

}  // namespace mcdyna::deck
