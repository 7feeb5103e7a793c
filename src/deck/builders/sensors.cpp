// *SENSOR_DEFINE_NODE, *SENSOR_DEFINE_FORCE, *SENSOR_SWITCH and *SENSOR_CONTROL: LS-DYNA's words
// (FTYPE, VID, CTYPE, LOGIC, INITSTT) become typed values here (one sensor or switch per line,
// as many lines as the keyword has); a word mcdyna does not run is
// refused at its field with what it does run.
#include <optional>

#include "deck/builders/builders.hpp"
#include "deck/numbers.hpp"
#include "deck/text_util.hpp"

namespace mcdyna::deck::builders {

namespace {

// A text field's word as the keywords compare it: trimmed, upper case.
std::string word(const Row& row, std::string_view field) {
  return upper(trim(row.text_or_default(field)));
}

// FTYPE (force sensors) and TYPE (controls): the entity kinds the solver can read and switch.
std::optional<model::SensedEntity> entity_kind(KeywordRecord& r, const Row& row,
                                               std::string_view field) {
  const std::string w = word(row, field);
  for (const auto kind : {model::SensedEntity::contact, model::SensedEntity::rigid_wall,
                          model::SensedEntity::prescribed_motion, model::SensedEntity::joint})
    if (w == model::sensed_entity_keyword(kind)) return kind;
  r.diags().error(row.loc(field), "{}: {} {} is not supported (CONTACT, RWALL, PRESC-MOT, JOINT)",
                  r.display_name(), field, w);
  return std::nullopt;
}

// A force sensor's VID: X, Y, Z, M or a *DEFINE_VECTOR.
model::SensorDirection force_direction(KeywordRecord& r, const Row& row) {
  const std::string w = word(row, "VID");
  model::SensorDirection d;
  if (w == "M") return d;
  d.magnitude = false;
  if (w == "X" || w == "Y" || w == "Z") {
    d.axis = w[0] - 'X';
  } else if (const auto n = parse_integer(w); n && *n > 0) {
    d.vector = *n;
  } else {
    r.diags().error(row.loc("VID"),
                    "{}: VID {} is not supported (X, Y, Z, M or a *DEFINE_VECTOR ID; moments "
                    "and local directions are not)",
                    r.display_name(), w);
  }
  return d;
}

}  // namespace

void sensor_define_node(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row& c1 = g.rows.front();
    model::NodeSensor s;
    s.id = c1.integer("SENSID");
    s.node = c1.integer("NODE1");
    s.loc = c1.loc();
    s.node_loc = c1.loc("NODE1");
    s.vector_loc = c1.loc("VID");
    if (const std::string vid = word(c1, "VID"); !vid.empty()) {
      const auto n = parse_integer(vid);
      if (!n || *n < 0) {
        r.diags().error(c1.loc("VID"), "{}: VID {} is not a *DEFINE_VECTOR ID", r.display_name(),
                        vid);
      } else if (*n > 0) {
        s.direction.magnitude = false;
        s.direction.vector = *n;
      }
    }
    const std::string ctype = word(c1, "CTYPE");
    if (ctype == "ACC") {
      s.quantity = model::NodeQuantity::acceleration;
    } else if (ctype == "VEL") {
      s.quantity = model::NodeQuantity::velocity;
    } else if (ctype == "COORD") {
      s.quantity = model::NodeQuantity::coordinate;
    } else {
      r.diags().error(c1.loc("CTYPE"), "{}: CTYPE {} is not supported (ACC, VEL, COORD)",
                      r.display_name(), ctype);
    }
    m.sensors.nodes.push_back(s);
  }
}

void sensor_define_force(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row& c1 = g.rows.front();
    model::ForceSensor s;
    s.id = c1.integer("SENSID");
    if (const auto kind = entity_kind(r, c1, "FTYPE")) s.kind = *kind;
    s.target = c1.integer("TYPEID");
    s.direction = force_direction(r, c1);
    s.loc = c1.loc();
    s.target_loc = c1.loc("TYPEID");
    s.vector_loc = c1.loc("VID");
    m.sensors.forces.push_back(s);
  }
}

void sensor_switch(KeywordRecord& r, model::ModelDatabase& m) {
  Group g;
  while (r.next_group(g)) {
    const Row& c1 = g.rows.front();
    model::SensorSwitch s;
    s.id = c1.integer("SWITID");
    const std::string type = word(c1, "TYPE");
    s.on_time = type == "TIME";
    if (!s.on_time && type != "SENSOR") {
      r.diags().error(c1.loc("TYPE"), "{}: TYPE {} is not SENSOR or TIME", r.display_name(), type);
    }
    s.sensor = c1.integer("SENSID");
    if (!s.on_time && s.sensor == 0) {
      r.diags().error(c1.loc("SENSID"), "{}: switch {} of TYPE SENSOR names no sensor (SENSID)",
                      r.display_name(), s.id);
    }
    const std::string logic = word(c1, "LOGIC");
    s.greater = logic == "GT";
    if (!s.greater && logic != "LT") {
      r.diags().error(c1.loc("LOGIC"), "{}: LOGIC {} is not LT or GT", r.display_name(), logic);
    }
    s.value = c1.real("VALUE");
    s.window = c1.real("TIMWIN");
    s.delay = c1.real("TDELAY");
    s.loc = c1.loc();
    s.sensor_loc = c1.loc("SENSID");
    m.sensors.switches.push_back(s);
  }
}

void sensor_control(KeywordRecord& r, model::ModelDatabase& m) {
  const Row& c1 = r.card("1");
  const Row& c2 = r.card("2");
  model::SensorControl c;
  c.id = c1.integer("CNTLID");
  if (const auto kind = entity_kind(r, c1, "TYPE")) c.kind = *kind;
  c.target = c1.integer("TYPEID");
  c.repeats = static_cast<int>(c1.integer("NREP"));
  const std::string initial = word(c2, "INITSTT");
  c.initially_on = initial != "OFF";
  if (c.initially_on && initial != "ON") {
    r.diags().error(c2.loc("INITSTT"), "{}: INITSTT {} is not ON or OFF", r.display_name(),
                    initial);
  }
  // The sequence ends at the first blank switch.
  for (const char* field : {"SWIT1", "SWIT2", "SWIT3", "SWIT4", "SWIT5", "SWIT6", "SWIT7"}) {
    const model::Id id = c2.integer(field);
    if (id == 0) break;
    c.switches.push_back(id);
  }
  if (c.switches.empty()) {
    r.diags().warning(c2.loc("SWIT1"), "{}: control {} has no switch (SWIT1): its status stays {}",
                      r.display_name(), c.id, c.initially_on ? "ON" : "OFF");
  }
  c.loc = c1.loc();
  c.target_loc = c1.loc("TYPEID");
  c.switches_loc = c2.loc();
  m.sensors.controls.push_back(c);
}

}  // namespace mcdyna::deck::builders
