#include "renderer/app/report_job.h"

#include "materials/core/text.h"
#include "renderer/app/destination.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"

namespace glossy::app {

report::ReportResult makeReport(const report::ReportOptions& o, const std::string& siteName) {
  checkOutputFolder(o.site, siteName);
  const OutputLock lock(o.site, siteName);
  const report::ReportResult r = report::writeReport(o);
  const std::string sheets = r.sheets == r.materials.size() ? formatted("%zu materials", r.sheets)
                                                             : formatted("%zu sheets of %zu materials", r.sheets, r.materials.size());
  tell(formatted("glossy: wrote %s/index.html: %s, %zu images, %zu plot files", o.site.c_str(), sheets.c_str(), r.images, r.plots));
  return r;
}

}  // namespace glossy::app
