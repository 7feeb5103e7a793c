#include "cli/report.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <map>
#include <ostream>

namespace mcdyna::cli {

namespace {

const char* side_type_name(int t) {
  switch (t) {
    case 0:
      return "segment set";
    case 1:
      return "shell set";
    case 2:
      return "part set";
    case 3:
      return "part";
    case 4:
      return "node set";
    case 5:
      return "all";
    case 6:
      return "all but part set";
    default:
      return "?";
  }
}

std::string section_label(const model::ModelDatabase& m, model::Id id) {
  const model::Section* s = m.section(id);
  if (s == nullptr) return fmt::format("{} (undefined)", id);
  return fmt::format("{} {}", id, s->summary);
}

// "main.k:12, 40; mesh.k:3" for the places a keyword occurs (first 12 shown).
std::string place_list(const deck::Deck& deck, const std::vector<core::SourceLoc>& places) {
  std::string out;
  std::uint32_t file = 0;
  for (std::size_t i = 0; i < places.size() && i < 12; ++i) {
    if (places[i].file != file) {
      file = places[i].file;
      out += fmt::format("{}{}:", i ? "; " : "", deck.files.file(file).path.filename().string());
    } else {
      out += ",";
    }
    out += fmt::format(" {}", places[i].line);
  }
  if (places.size() > 12) out += fmt::format(" ... ({} in all)", places.size());
  return out;
}

}  // namespace

ModelCounts count_model(const model::ModelDatabase& m) {
  ModelCounts c;
  c.elements_per_part.assign(m.parts.size(), 0);
  std::vector<char> spg_part(m.parts.size(), 0);
  for (std::size_t i = 0; i < m.parts.size(); ++i) {
    const model::Section* s = m.section(m.parts[i].section);
    spg_part[i] = s != nullptr && s->kind == model::SectionKind::solid_spg;
  }
  std::vector<char> particle(m.nodes.size(), 0);
  for (const model::SolidElement& e : m.solids) {
    const auto p = m.index.parts.find(e.part);
    if (p == model::IdIndex::kNone) continue;
    ++c.elements_per_part[static_cast<std::size_t>(p)];
    if (!spg_part[static_cast<std::size_t>(p)]) continue;
    for (model::Id n : e.nodes) {
      const auto k = m.index.nodes.find(n);
      if (k != model::IdIndex::kNone && !particle[static_cast<std::size_t>(k)]) {
        particle[static_cast<std::size_t>(k)] = 1;
        ++c.spg_particles;
      }
    }
  }
  for (const model::ShellElement& e : m.shells) {
    const auto p = m.index.parts.find(e.part);
    if (p != model::IdIndex::kNone) ++c.elements_per_part[static_cast<std::size_t>(p)];
  }
  for (const model::BeamElement& e : m.beams) {
    const auto p = m.index.parts.find(e.part);
    if (p != model::IdIndex::kNone) ++c.elements_per_part[static_cast<std::size_t>(p)];
  }
  for (const model::DiscreteElement& e : m.discretes) {
    const auto p = m.index.parts.find(e.part);
    if (p != model::IdIndex::kNone) ++c.elements_per_part[static_cast<std::size_t>(p)];
  }
  return c;
}

namespace {

void print_parts(std::ostream& out, const model::ModelDatabase& m, const ModelCounts& counts) {
  if (!m.parts.empty()) {
    fmt::print(out, "\nParts\n  {:>8} {:>10}  {:<26} {:<36} {:<10} {}\n", "ID", "elements",
               "section", "material", "EOS", "heading");
    for (std::size_t i = 0; i < m.parts.size(); ++i) {
      const model::Part& p = m.parts[i];
      const model::Material* mat = m.material(p.material);
      const std::string mat_label = mat ? fmt::format("{} {}", p.material, mat->keyword)
                                        : fmt::format("{} (undefined)", p.material);
      fmt::print(out, "  {:>8} {:>10}  {:<26} {:<36} {:<10} {}\n", p.id,
                 i < counts.elements_per_part.size() ? counts.elements_per_part[i] : 0,
                 section_label(m, p.section), mat_label, p.eos == 0 ? "-" : std::to_string(p.eos),
                 p.heading);
    }
  }
  fmt::print(out, "\nMaterials        {}", m.materials.size());
  std::map<std::string, int> by_kind;
  for (const auto& mat : m.materials)
    ++by_kind[mat.keyword];
  for (const auto& [k, n] : by_kind)
    fmt::print(out, "  {} x{}", k, n);
  fmt::print(out, "\nEOS              {}   hourglass sets {}   erosion criteria {}\n",
             m.equations_of_state.size(), m.hourglasses.size(), m.erosions.size());
}

void print_contacts(std::ostream& out, const model::ModelDatabase& m) {
  fmt::print(out, "\nContacts         {}\n", m.contacts.size());
  for (const model::Contact& c : m.contacts) {
    if (c.kind == model::ContactKind::force_transducer) {
      const std::string b = c.b.id == 0 && c.b.type != 5
                                ? std::string("- (every other contact)")
                                : fmt::format("{} {}", side_type_name(c.b.type), c.b.id);
      fmt::print(out, "  {:>4} {:<30} A: {} {}  B: {}\n", c.id, c.keyword, side_type_name(c.a.type),
                 c.a.id, b);
      continue;
    }
    fmt::print(out, "  {:>4} {:<30} A: {} {}  B: {} {}  FS {} FD {}\n", c.id, c.keyword,
               side_type_name(c.a.type), c.a.id, side_type_name(c.b.type), c.b.id,
               c.static_friction, c.dynamic_friction);
  }
}

void print_conditions(std::ostream& out, const model::ModelDatabase& m) {
  std::size_t spc_nodes = 0, spc_sets = 0;
  for (const auto& s : m.spcs)
    (s.is_set ? spc_sets : spc_nodes)++;
  fmt::print(out, "\nBoundary conditions\n  SPC nodes {}  SPC node sets {}  node TC/RC codes {}\n",
             spc_nodes, spc_sets,
             std::count_if(m.nodes.begin(), m.nodes.end(), [](const model::Node& n) {
               return n.translation_constraint != 0 || n.rotation_constraint != 0;
             }));
  for (const auto& p : m.prescribed_motions) {
    const char* target = p.target_kind == model::MotionTarget::node       ? "node"
                         : p.target_kind == model::MotionTarget::node_set ? "node set"
                                                                          : "rigid part";
    fmt::print(out, "  prescribed motion: {} {} DOF {} VAD {} curve {} x {}\n", target, p.target,
               p.dof, p.kind, p.curve, p.scale);
  }
  fmt::print(out, "  initial velocity definitions {}  rigid walls {}\n",
             m.initial_velocities.size(), m.rigid_walls.size());
  const model::Sensors& sn = m.sensors;
  if (!sn.nodes.empty() || !sn.forces.empty() || !sn.switches.empty() || !sn.controls.empty())
    fmt::print(out, "  sensors {} on nodes, {} on forces; switches {}; controls {}\n",
               sn.nodes.size(), sn.forces.size(), sn.switches.size(), sn.controls.size());
  for (const model::SensorControl& c : sn.controls)
    fmt::print(out, "  sensor control {}: {} {}, {} at first, switches {}{}\n", c.id,
               model::sensed_entity_keyword(c.kind), c.target, c.initially_on ? "on" : "off",
               fmt::join(c.switches, " "),
               c.repeats == 0  ? std::string()
               : c.repeats < 0 ? std::string(", NREP -1 (without end)")
                               : fmt::format(", NREP {}", c.repeats));
  fmt::print(out,
             "\nCurves {}  vectors {}  boxes {}  node sets {}  part sets {}  segment sets {}\n",
             m.curves.size(), m.vectors.size(), m.boxes.size(), m.node_sets.size(),
             m.part_sets.size(), m.segment_sets.size());
}

void print_outputs_and_controls(std::ostream& out, const model::ModelDatabase& m) {
  fmt::print(out, "\nOutputs\n");
  if (m.outputs.d3plot) {
    fmt::print(out, "  d3plot states every {} (VTK series d3plot.pvd)\n",
               m.outputs.d3plot->interval);
  }
  for (const auto& a : m.outputs.ascii) {
    fmt::print(out, "  {:<8} every {}\n", model::ascii_database_name(a.database), a.interval);
  }
  std::size_t history = 0;
  for (const auto& h : m.outputs.history_nodes)
    history += h.ids.size();
  if (history > 0) fmt::print(out, "  history nodes/sets {}\n", history);
  if (m.controls.termination) {
    fmt::print(out, "\nTermination      ENDTIM {}", m.controls.termination->end_time);
    if (m.controls.termination->end_cycle > 0) {
      fmt::print(out, "  ENDCYC {}", m.controls.termination->end_cycle);
    }
    fmt::print(out, "\n");
  }
  if (m.controls.time_step) {
    fmt::print(out, "Time step        TSSFAC {}  DTINIT {}  DT2MS {}\n",
               m.controls.time_step->scale_factor, m.controls.time_step->initial_step,
               m.controls.time_step->mass_scaling_step);
  }
}

}  // namespace

void print_summary(std::ostream& out, const deck::Deck& deck, const model::ModelDatabase& m,
                   const ModelCounts& counts) {
  fmt::print(out, "Model summary\n");
  if (!m.title.empty()) fmt::print(out, "  title            {}\n", m.title);
  fmt::print(out, "  files            {} ({:.1f} MB)\n", deck.files.size() - 1,
             static_cast<double>(deck.bytes_read) / 1.0e6);
  fmt::print(out, "  nodes            {}\n", m.nodes.size());
  fmt::print(out, "  solid elements   {}\n", m.solids.size());
  fmt::print(out, "  shell elements   {}\n", m.shells.size());
  if (!m.beams.empty()) fmt::print(out, "  beam elements    {}\n", m.beams.size());
  if (!m.discretes.empty()) fmt::print(out, "  discrete elements {}\n", m.discretes.size());
  fmt::print(out, "  SPG particles    {}\n", counts.spg_particles);
  fmt::print(out, "  parameters       {}\n", deck.parameters.size());
  print_parts(out, m, counts);
  print_contacts(out, m);
  print_conditions(out, m);
  print_outputs_and_controls(out, m);
}

std::size_t print_migration_report(std::ostream& out, const deck::Deck& deck,
                                   const std::vector<deck::KeywordUse>& uses) {
  struct Entry {
    deck::Support support;
    std::string reason;
    std::vector<core::SourceLoc> places;
  };
  std::map<std::string, Entry> by_name;
  for (const deck::KeywordUse& u : uses) {
    auto [it, fresh] = by_name.try_emplace(u.name, Entry{u.support, u.reason, {}});
    it->second.places.push_back(u.loc);
  }
  std::size_t counts[4] = {};
  for (const auto& [name, e] : by_name)
    ++counts[static_cast<int>(e.support)];
  fmt::print(out,
             "\nMigration report: {} keywords ({} distinct): {} supported, {} read without "
             "effect, {} unsupported output, {} unsupported\n",
             uses.size(), by_name.size(), counts[0], counts[1], counts[2], counts[3]);
  std::string supported;
  for (const auto& [name, e] : by_name) {
    if (e.support != deck::Support::supported) continue;
    supported += fmt::format("{}*{}{}", supported.empty() ? "" : " ", name,
                             e.places.size() > 1 ? fmt::format("(x{})", e.places.size()) : "");
  }
  if (!supported.empty()) fmt::print(out, "  supported: {}\n", supported);
  std::size_t physics = 0;
  for (deck::Support s :
       {deck::Support::no_effect, deck::Support::output_only, deck::Support::unsupported}) {
    for (const auto& [name, e] : by_name) {
      if (e.support != s) continue;
      const char* tag = s == deck::Support::no_effect     ? "read, no effect   "
                        : s == deck::Support::output_only ? "unsupported output"
                                                          : "UNSUPPORTED       ";
      fmt::print(out, "  {} *{} ({}): {}{}\n", tag, name, place_list(deck, e.places), e.reason,
                 s == deck::Support::unsupported ? " [changes the physics]" : "");
      if (s == deck::Support::unsupported) ++physics;
    }
  }
  return physics;
}

}  // namespace mcdyna::cli
