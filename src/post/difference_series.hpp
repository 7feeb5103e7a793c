#pragma once
/// The difference A - B of two d3plot families as a VTK series on B's mesh, to look at in
/// ParaView (`mcdyna compare A B --diff-series DIR`): DIR/difference.pvd and one
/// DIR/difference_NNNN.vtu per matched state, B's current coordinates as points, its elements as
/// cells, and the differences as point fields `displacement_difference` and
/// `velocity_difference` and cell fields `stress_difference` (solids, shells, particles),
/// `resultants_difference` (beams) and `plastic_strain_difference`; `compared` (points and
/// cells) is 1 where a value was compared and 0 where nothing was (an ID only B has, an eroded
/// element, a field one family lacks: the differences there 0, not NaN, which VTK's XML
/// writer stores in range keys its own reader refuses). `node_id`, `element_id` and `part_id`
/// say whose values they are.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "io/d3plot/d3plot_reader.hpp"
#include "post/state_compare.hpp"

namespace mcdyna::post {

class DifferenceSeries final : public DifferenceSink {
 public:
  DifferenceSeries(std::filesystem::path dir, const io::d3plot::Reader& b);

  void begin_state(double time_b, const std::vector<double>& x_b) override;
  void node(std::size_t b, const char* field, const double* a_minus_b) override;
  void element(const char* element_class, std::size_t b, const char* field, const double* a_minus_b,
               int components) override;
  void end_state() override;

  [[nodiscard]] std::size_t states() const { return entries_.size(); }
  [[nodiscard]] std::filesystem::path collection() const { return dir_ / "difference.pvd"; }

 private:
  [[nodiscard]] std::size_t cell(const char* element_class, std::size_t b) const;
  std::filesystem::path dir_;
  const io::d3plot::Reader& b_;
  double time_ = 0.0;
  std::vector<double> x_;
  std::vector<double> displacement_, velocity_;       ///< 3 per node
  std::vector<double> stress_, resultants_, strain_;  ///< 6, 6, 1 per cell
  std::vector<double> node_compared_, cell_compared_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace mcdyna::post
