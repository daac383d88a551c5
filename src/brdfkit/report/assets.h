#pragma once
// The files every report folder ships, compiled into brdfkit (CMakeLists.txt embeds them): the
// charting library Apache ECharts (echarts.min.js and its LICENSE, from npm, installed by
// scripts/setup.sh), and the report's own report.js and report.css. Pages then open offline.
#include <string_view>
#include <utility>
#include <vector>

namespace brdfkit::report {

// (file name, contents) pairs; echarts.min.js is absent when brdfkit was built without it.
const std::vector<std::pair<std::string_view, std::string_view>>& embedded_assets();

}  // namespace brdfkit::report
