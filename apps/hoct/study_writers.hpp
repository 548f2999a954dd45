// Output of `hoct study`: the table as CSV and JSON, and an SVG chart of the PL error and the
// missed/spurious features against the number of triangles. All writes are atomic.
#pragma once

#include "analysis/case_study.hpp"

#include <string>
#include <vector>

namespace hoct {

void write_study_csv(const std::string &path, const std::vector<StudyRow> &rows);
void write_study_json(const std::string &path, const std::vector<StudyRow> &rows,
                      const std::string &input, double threshold);
void write_study_svg(const std::string &path, const std::vector<StudyRow> &rows,
                     const std::string &title);

} // namespace hoct
