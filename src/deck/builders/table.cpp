// Schema name -> builder. The schema test checks that this table and keywords/ agree.
#include "deck/builders/builders.hpp"

namespace mcdyna::deck {

const std::vector<BuilderEntry>& builder_table() {
  using namespace builders;
  static const std::vector<BuilderEntry> table{
      {"TITLE", title},
      {"NODE", node},
      {"ELEMENT_SOLID", element_solid},
      {"ELEMENT_SHELL", element_shell},
      {"PART", part},
      {"SECTION_SOLID", section_solid},
      {"SECTION_SOLID_SPG", section_solid_spg},
      {"SECTION_SHELL", section_shell},
      {"MAT_ELASTIC", mat_elastic},
      {"MAT_PLASTIC_KINEMATIC", mat_plastic_kinematic},
      {"MAT_JOHNSON_COOK", mat_johnson_cook},
      {"MAT_RIGID", mat_rigid},
      {"MAT_PIECEWISE_LINEAR_PLASTICITY", mat_piecewise_linear_plasticity},
      {"MAT_ADD_EROSION", mat_add_erosion},
      {"EOS_LINEAR_POLYNOMIAL", eos_linear_polynomial},
      {"EOS_GRUNEISEN", eos_gruneisen},
      {"HOURGLASS", hourglass},
      {"CONTROL_TERMINATION", control_termination},
      {"CONTROL_TIMESTEP", control_timestep},
      {"CONTROL_HOURGLASS", control_hourglass},
      {"CONTROL_CONTACT", control_contact},
      {"CONTROL_SOLID", control_solid},
      {"CONTROL_ENERGY", control_energy},
      {"CONTROL_BULK_VISCOSITY", control_bulk_viscosity},
      {"CONTACT_AUTOMATIC_NODES_TO_SURFACE", contact},
      {"CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", contact},
      {"CONTACT_AUTOMATIC_SINGLE_SURFACE", contact},
      {"CONTACT_NODES_TO_SURFACE", contact},
      {"CONTACT_SURFACE_TO_SURFACE", contact},
      {"BOUNDARY_SPC_NODE", boundary_spc},
      {"BOUNDARY_SPC_SET", boundary_spc},
      {"BOUNDARY_PRESCRIBED_MOTION_NODE", boundary_prescribed_motion},
      {"BOUNDARY_PRESCRIBED_MOTION_SET", boundary_prescribed_motion},
      {"BOUNDARY_PRESCRIBED_MOTION_RIGID", boundary_prescribed_motion},
      {"INITIAL_VELOCITY", initial_velocity},
      {"INITIAL_VELOCITY_NODE", initial_velocity_node},
      {"INITIAL_VELOCITY_GENERATION", initial_velocity_generation},
      {"RIGIDWALL_PLANAR", rigidwall_planar},
      {"DEFINE_CURVE", define_curve},
      {"DEFINE_VECTOR", define_vector},
      {"DEFINE_BOX", define_box},
      {"SET_NODE_LIST", set_node_list},
      {"SET_NODE_LIST_GENERATE", set_node_list_generate},
      {"SET_PART_LIST", set_part_list},
      {"SET_SEGMENT", set_segment},
      {"DATABASE_BINARY_D3PLOT", database_d3plot},
      {"DATABASE_GLSTAT", database_ascii},
      {"DATABASE_MATSUM", database_ascii},
      {"DATABASE_RCFORC", database_ascii},
      {"DATABASE_NODOUT", database_ascii},
      {"DATABASE_SPCFORC", database_ascii},
      {"DATABASE_BNDOUT", database_ascii},
      {"DATABASE_RWFORC", database_ascii},
      {"DATABASE_HISTORY_NODE", database_history_node},
      {"DATABASE_HISTORY_NODE_SET", database_history_node},
      {"DATABASE_EXTENT_BINARY", database_extent_binary},
  };
  return table;
}

}  // namespace mcdyna::deck
