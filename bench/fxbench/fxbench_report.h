#pragma once
// fxbench output: the Markdown tables on stdout (shaped like the thesis's Table 1, plus the new
// columns), JSON and CSV files.
#include <string>
#include <vector>

#include "fxbench_summary.h"

namespace fxbench {

/// Table 1 (Method | Setup | Min/Max/Average FPS) plus frame-time percentiles, ratio to hard,
/// particle-pass and fill-limit figures and image error; then per-pass medians; then notes.
std::string markdownReport(const Report& report);

/// One run as a JSON object (see README of fxbench in fxbench.cpp: the keys are fixed). Every
/// number is finite. `indent` prefixes every line (for nesting in sweep output).
std::string jsonReport(const Report& report, const std::string& indent = "");
/// CSV rows, one per selected mode; `header` prepends the column line. `point` labels a sweep
/// point (empty for a single run).
std::string csvRows(const Report& report, const std::string& point, bool header);

/// Writes `text` to `path`. False + error naming the path.
bool writeText(const std::string& path, const std::string& text, std::string* error);

/// JSON string literal.
std::string jsonQuote(const std::string& s);
/// A finite number for JSON/CSV ("0" for NaN/inf, which summaries never produce).
std::string num(double v, int precision = 6);

}  // namespace fxbench
