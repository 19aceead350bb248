// report_gallery.h: the top of the report page, what a reader sees first:
// per technique one row of thumbnails of the CPU images (a failing scene
// framed in red; a click opens its detail), with the technique's paper
// table beside it. Conformance scenes (many, alike, each one rule of the
// pipeline) are folded under their own heading, open when one fails.
#pragma once

#include <string>
#include <vector>

#include "app/report/report_page.h"

namespace st {

std::string report_gallery(const std::vector<ReportEntry>& entries);

}  // namespace st
