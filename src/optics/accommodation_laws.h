// Accommodation laws: how an eye model's prescription changes with accommodation A (dioptres),
// each a named function that a model's data file refers to ("law": "navarro1985"). Laws name
// formulas and interpolation rules from the literature, never a model.
#pragma once

#include <string>
#include <vector>

#include "optics/prescription.h"

namespace eyetrace::optics {

struct EyeModel;

struct AccommodationLaw {
  const char* name;
  const char* description;  // one line, with its source
  bool needs_accommodated_state;
  // The model's prescription at A in [0, max] (the caller checks the range).
  Prescription (*apply)(const EyeModel& model, double A);
  // The largest accommodation the law can give this model; < 0: the data file must say
  // ("max_D"), because the law itself has no end.
  double (*max_D)(const EyeModel& model);
};

// Throws OpticsError listing the known laws when `name` is not one.
const AccommodationLaw& find_accommodation_law(const std::string& name);
std::vector<std::string> accommodation_law_names();

}  // namespace eyetrace::optics
