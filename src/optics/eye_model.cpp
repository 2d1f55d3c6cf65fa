// Eye model files: a prescription (prescription_io.h) plus its accommodation block.
#include "optics/eye_model.h"

#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "optics/accommodation_laws.h"
#include "optics/optics_error.h"
#include "optics/prescription_io.h"

namespace eyetrace::optics {

namespace {

using nlohmann::json;

// The accommodated state shares the relaxed file's header (model, wavelength, conventions);
// its own keys (media, surfaces, title, source, status, notes) replace the relaxed ones.
Prescription read_state(const json& file, const json& state, const std::string& where) {
  if (!state.is_object()) throw OpticsError(fmt::format("{}: expected a JSON object", where));
  json merged = file;
  merged.erase("accommodation");
  merged.erase("notes");
  for (const char* key : {"title", "source", "status"}) merged.erase(key);
  for (auto it = state.begin(); it != state.end(); ++it) {
    static const std::set<std::string> allowed = {"title", "source", "status", "media", "surfaces", "notes"};
    if (!allowed.count(it.key())) throw OpticsError(fmt::format("{}: unknown key '{}'", where, it.key()));
    merged[it.key()] = it.value();
  }
  if (!merged.contains("source")) merged["source"] = file.value("source", "");
  return prescription_from_json(merged, where);
}

double read_max(const json& a, const std::string& where) {
  if (!a.contains("max_D")) return -1.0;
  if (!a["max_D"].is_number() || !(a["max_D"].get<double>() >= 0.0))
    throw OpticsError(fmt::format("{}: 'max_D' must be a number >= 0", where));
  return a["max_D"].get<double>();
}

void read_accommodation(const json& file, const std::string& origin, EyeModel& m) {
  const std::string where = origin + ": accommodation";
  if (!file.contains("accommodation"))
    throw OpticsError(
        fmt::format("{}: missing 'accommodation' (an eye model names its accommodation law; "
                    "use {{\"law\": \"none\"}} for a relaxed-only model)",
                    origin));
  const json& a = file["accommodation"];
  if (!a.is_object()) throw OpticsError(fmt::format("{}: expected a JSON object", where));
  for (auto it = a.begin(); it != a.end(); ++it) {
    static const std::set<std::string> allowed = {"law",     "source",      "max_D", "published_max_D",
                                                  "why_max", "accommodated"};
    if (!allowed.count(it.key())) throw OpticsError(fmt::format("{}: unknown key '{}'", where, it.key()));
  }
  if (!a.contains("law") || !a["law"].is_string())
    throw OpticsError(fmt::format("{}: 'law' must name an accommodation law", where));
  m.accommodation_law = a["law"].get<std::string>();
  const AccommodationLaw* law;
  try {
    law = &find_accommodation_law(m.accommodation_law);
  } catch (const OpticsError& e) {
    throw OpticsError(fmt::format("{}: {}", where, e.what()));
  }
  if (law->needs_accommodated_state != a.contains("accommodated"))
    throw OpticsError(fmt::format("{}: law '{}' {} an 'accommodated' state", where, law->name,
                                  law->needs_accommodated_state ? "needs" : "takes no"));
  if (law->needs_accommodated_state) {
    m.accommodated = read_state(file, a["accommodated"], where + ".accommodated");
    if (m.accommodated->surfaces.size() != m.relaxed.surfaces.size())
      throw OpticsError(fmt::format("{}.accommodated: {} surfaces, the relaxed eye has {}", where,
                                    m.accommodated->surfaces.size(), m.relaxed.surfaces.size()));
  }
  const double from_file = read_max(a, where), from_law = law->max_D(m);
  if (from_file < 0.0 && from_law < 0.0)
    throw OpticsError(fmt::format("{}: law '{}' needs 'max_D', the accommodation range in dioptres", where, law->name));
  if (from_file >= 0.0 && from_law >= 0.0 && from_file > from_law)
    throw OpticsError(
        fmt::format("{}: 'max_D' {} D is beyond what law '{}' gives ({} D)", where, from_file, law->name, from_law));
  m.max_accommodation_D = from_file >= 0.0 ? from_file : from_law;
}

}  // namespace

EyeModel eye_model_from_json_text(const std::string& text, const std::string& origin) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw OpticsError(fmt::format("{}: invalid JSON: {}", origin, e.what()));
  }
  EyeModel m;
  try {
    m.relaxed = prescription_from_json(j, origin);
    m.name = m.relaxed.name;
    m.variant = m.relaxed.variant;
    m.origin = origin;
    read_accommodation(j, origin, m);
  } catch (const json::exception& e) {  // a value of the wrong type deep inside
    throw OpticsError(fmt::format("{}: {}", origin, e.what()));
  }
  if (m.name.empty()) throw OpticsError(fmt::format("{}: 'model' must not be empty", origin));
  return m;
}

}  // namespace eyetrace::optics
