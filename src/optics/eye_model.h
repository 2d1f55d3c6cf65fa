// One schematic eye model as its data file describes it (data/eyes/<model>.json): the relaxed
// prescription, how it accommodates (a named law from accommodation_laws.h, with an
// accommodated state when the law interpolates towards one), and its accommodation range.
// Adding a model is adding a file; nothing in the code names a model.
#pragma once

#include <optional>
#include <string>

#include "optics/prescription.h"

namespace eyetrace::optics {

struct EyeModel {
  std::string name;     // the file's "model": also its camera name (Camera "navarro")
  std::string variant;  // the file's "variant" ("" = the model's default prescription)
  std::string origin;   // the file it came from, for messages
  Prescription relaxed;
  std::string accommodation_law;             // a name of accommodation_law_names()
  std::optional<Prescription> accommodated;  // the law's end state, when it has one
  double max_accommodation_D = 0.0;          // accepted range [0, max]
};

// Parses and validates a model file's text: the prescription format of prescription_io.h plus
//   "accommodation": { "law": "<name>", "source": "...", "max_D": 15,
//                      "accommodated": { "media": [...], "surfaces": [...], ... } }
// ("max_D" may be omitted where the law derives it; "accommodated" only for laws that need
// it). Throws OpticsError naming `origin` and the field.
EyeModel eye_model_from_json_text(const std::string& text, const std::string& origin);

}  // namespace eyetrace::optics
