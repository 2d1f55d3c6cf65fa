// The published initial direction numbers from which lowdiscrepancy.cpp builds the Sobol'
// generator matrices (the data and its licence are in sobol_direction_numbers.cpp).
#pragma once
#include <cstddef>
#include <cstdint>

namespace eyetrace {

// Dimensions 1..1023 of the Sobol' sequence, packed as: degree s, polynomial a, m_1..m_s.
extern const uint16_t kJoeKuoDirectionNumbers[];
extern const size_t kJoeKuoDirectionNumbersSize;

}  // namespace eyetrace
