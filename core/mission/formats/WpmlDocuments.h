#pragma once

#include "WpmlPlan.h"

#include <QByteArray>

// The two XML documents of a WPML archive, printed from a plan: what the aircraft executes
// (wpmz/waylines.wpml) and the editable template (wpmz/template.kml).
namespace sortie::mission::formats::wpml {

// distance (m) and duration (s) of the whole wayline, which the executable file states.
QByteArray waylinesOf(const Plan &plan, const WpmlExportOptions &o, const DjiDroneModel &model, const DjiPayload &payload,
                      double distance, double duration);
QByteArray templateOf(const Plan &plan, const WpmlExportOptions &o, const DjiDroneModel &model, const DjiPayload &payload);

} // namespace sortie::mission::formats::wpml
