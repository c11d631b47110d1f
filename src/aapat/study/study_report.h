// The objective study as one self-contained web page: no network, no script,
// every figure inline (SVG, and PNG as data URIs). For each budget: the
// patterns drawn, their per-angle error W E1 every degree as a polar plot,
// scatter plots of the papers' and the recommended objective against the
// rendered RMSE with their correlations, renderings of the spiral side by
// side with their error images, and the tables.
#pragma once

#include <string>

#include "aapat/render/reference.h"
#include "aapat/study/objective_study.h"

namespace aapat {

// `references` renders (or reads from the cache) the crops' references.
std::string study_report_html(const StudyResult& result, const StudySettings& settings,
                              const ReferenceSource& references);

// Base64 of bytes (RFC 4648, padded), for data URIs.
std::string base64(const std::string& bytes);

}  // namespace aapat
