#pragma once
/// The model database: everything a deck defines, as plain data keyed by user IDs, plus ID
/// indices built by the cross-checks. The solver compiles its state from this; the deck reader
/// fills it. Neither half sees the other's types.
#include <string>
#include <vector>

#include "model/conditions.hpp"
#include "model/controls.hpp"
#include "model/entities.hpp"
#include "model/id_index.hpp"
#include "model/sensors.hpp"

namespace mcdyna::model {

struct ModelDatabase {
  std::string title;

  std::vector<Node> nodes;
  std::vector<SolidElement> solids;
  std::vector<ShellElement> shells;
  std::vector<BeamElement> beams;
  std::vector<DiscreteElement> discretes;
  std::vector<Part> parts;
  std::vector<Section> sections;
  std::vector<Material> materials;
  std::vector<Erosion> erosions;
  std::vector<Eos> equations_of_state;
  std::vector<Hourglass> hourglasses;
  std::vector<Curve> curves;
  std::vector<Vector> vectors;
  std::vector<Box> boxes;
  std::vector<NodeSet> node_sets;
  std::vector<PartSet> part_sets;
  std::vector<SegmentSet> segment_sets;
  std::vector<ElementSet> element_sets;

  std::vector<Contact> contacts;
  std::vector<SpcConstraint> spcs;
  std::vector<PrescribedMotion> prescribed_motions;
  std::vector<InitialVelocity> initial_velocities;
  std::vector<BodyLoad> body_loads;
  std::vector<PointLoad> point_loads;
  std::vector<SegmentLoad> segment_loads;
  std::vector<RigidWall> rigid_walls;
  std::vector<ExtraNodes> extra_nodes;
  std::vector<RigidMerge> rigid_merges;
  std::vector<NodalRigidBody> nodal_rigid_bodies;
  std::vector<SpotWeld> spot_welds;
  std::vector<Joint> joints;
  std::vector<JointStiffness> joint_stiffnesses;
  std::vector<CoordinateSystem> coordinate_systems;
  Sensors sensors;

  Controls controls;
  OutputRequests outputs;

  /// ID indices; valid after model::check() (which builds them).
  struct Indices {
    IdIndex nodes, solids, shells, beams, parts, sections, materials, equations_of_state,
        hourglasses, curves, vectors, boxes, node_sets, part_sets, segment_sets;
  } index;

  template <typename Entity>
  static const Entity* lookup(const std::vector<Entity>& v, const IdIndex& index, Id id) {
    const auto i = index.find(id);
    return i == IdIndex::kNone ? nullptr : &v[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] const Part* part(Id id) const { return lookup(parts, index.parts, id); }
  [[nodiscard]] const Section* section(Id id) const { return lookup(sections, index.sections, id); }
  [[nodiscard]] const Material* material(Id id) const {
    return lookup(materials, index.materials, id);
  }
  [[nodiscard]] const Curve* curve(Id id) const { return lookup(curves, index.curves, id); }
  [[nodiscard]] const NodeSet* node_set(Id id) const {
    return lookup(node_sets, index.node_sets, id);
  }
  [[nodiscard]] const SegmentSet* segment_set(Id id) const {
    return lookup(segment_sets, index.segment_sets, id);
  }
  [[nodiscard]] const PartSet* part_set(Id id) const {
    return lookup(part_sets, index.part_sets, id);
  }
};

}  // namespace mcdyna::model
