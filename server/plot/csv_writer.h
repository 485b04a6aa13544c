#pragma once
// CSV (RFC 4180): a header row and data rows; cells holding a comma, quote or newline are quoted.

#include <string>
#include <vector>

namespace softtune::plot {

std::string render_csv(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);

}  // namespace softtune::plot
