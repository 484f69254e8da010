// nbscope io: the JSON report of a headless run (the report types: check/report.hpp).
#pragma once
#include <string>

#include "check/report.hpp"

namespace nbscope {

// Writes the report as JSON, atomically (see DESIGN.md; keys documented in report_json.cpp).
void write_run_report(const std::string& path, const RunReport& report);
// The same JSON as a string (tests).
std::string run_report_json(const RunReport& report);

}  // namespace nbscope
