// glossy report's job without the command line: the site's destination checked and locked, the site written
// (renderer/report/report_site.h), what it holds told. `glossy report` and the Python module's glossy.report
// run it, so the two write the same site.
#pragma once

#include "renderer/report/report_site.h"

#include <string>

namespace glossy::app {

// InputError naming the file or option for bad input (report_site.h), before anything is written; `siteName`
// is what messages call the site's folder: the option or keyword that gave it.
report::ReportResult makeReport(const report::ReportOptions& options, const std::string& siteName = "-o");

}  // namespace glossy::app
