#pragma once

#include <vector>

namespace roadscale {

// The median of `values`, the upper of the two middle ones for an even count; 0 for none.
// Takes a copy: it reorders it in linear time.
double Median(std::vector<double> values);

}  // namespace roadscale
