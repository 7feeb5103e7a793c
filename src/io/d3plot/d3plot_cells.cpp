#include "io/d3plot/d3plot_cells.hpp"

#include <stdexcept>
#include <string>

namespace mcdyna::io::d3plot {

namespace {

// Where a shell's own fields go among its words: layer l (0 mid, 1 inner, 2 outer) at 7 l.
constexpr int kMid = 0, kInner = 7, kOuter = 14, kThickness = 21, kEnergy = 24;

// The first words of an element: its stress and plastic strain (a shell's mean of the layers
// until its layers arrive).
void put_result(double* w, const solver::ElementResult& r) {
  for (int k = 0; k < 6; ++k)
    w[k] = r.stress[static_cast<std::size_t>(k)];
  w[6] = r.plastic_strain;
}

}  // namespace

StateCells::StateCells() {
  solids.corners = 8;
  solids.words = kSolidWords;
  beams.corners = 2;
  beams.words = kBeamWords;
  shells.corners = 4;
  shells.words = kShellWords;
  particles.corners = 1;
  particles.words = kParticleWords;
}

void StateCells::declare(std::string_view /*name*/,
                         std::initializer_list<const char*> /*components*/) {}

void StateCells::cell(solver::CellShape shape, const Index* nodes, const solver::CellValues& v) {
  switch (shape) {
    case solver::CellShape::hexahedron:
      last_ = &solids;
      break;
    case solver::CellShape::quadrilateral:
    case solver::CellShape::triangle:
      last_ = &shells;
      break;
    case solver::CellShape::line:
      last_ = &beams;
      break;
    case solver::CellShape::vertex:
      last_ = &particles;
      break;
  }
  ElementClass& c = *last_;
  const int n = solver::cell_nodes(shape);
  for (int k = 0; k < c.corners; ++k)
    c.nodes.push_back(nodes[k < n ? k : n - 1]);  // a triangle repeats its third corner
  c.ids.push_back(v.id);
  c.parts.push_back(v.part);
  c.deleted.push_back(v.deleted ? 1 : 0);
  const std::size_t first = c.values.size();
  c.values.resize(first + static_cast<std::size_t>(c.words), 0.0);
  // A beam's words are its resultants (its own field); a solid's and a shell's start with the
  // stress and plastic strain; a particle's with its pressure.
  double* w = &c.values[first];
  if (last_ == &particles) {
    w[0] = v.pressure;
    put_result(w + 1, v.result);
    w[8] = v.bond_damage;
    w[9] = v.particle_state;
  } else if (last_ != &beams) {
    put_result(w, v.result);
  }
}

void StateCells::value(std::string_view name, const double* values) {
  if (last_ == nullptr || last_ == &particles) return;
  ElementClass& c = *last_;
  double* w = &c.values[c.values.size() - static_cast<std::size_t>(c.words)];
  if (last_ == &beams) {
    // beam_resultants: N, Vs, Vt, T, Ms, Mt (elout's order); d3plot's: N, Vs, Vt, Ms, Mt, T.
    if (name == "beam_resultants") {
      w[0] = values[0];
      w[1] = values[1];
      w[2] = values[2];
      w[3] = values[4];
      w[4] = values[5];
      w[5] = values[3];
    }
    return;
  }
  if (last_ != &shells) return;
  auto stress = [&](int at) {
    for (int k = 0; k < 6; ++k)
      w[at + k] = values[k];
  };
  if (name == "stress_middle") {
    stress(kMid);
  } else if (name == "stress_bottom") {
    stress(kInner);
  } else if (name == "stress_top") {
    stress(kOuter);
  } else if (name == "layer_plastic_strain") {  // bottom, middle, top
    w[kInner + 6] = values[0];
    w[kMid + 6] = values[1];
    w[kOuter + 6] = values[2];
  } else if (name == "thickness") {
    w[kThickness] = values[0];
  } else if (name == "internal_energy_density") {
    w[kEnergy] = values[0];
  }
}

}  // namespace mcdyna::io::d3plot
