#pragma once

#include "WpmlPlan.h"

#include <QByteArray>

// The two XML documents of a WPML archive, printed from a plan: what the aircraft executes
// (wpmz/waylines.wpml) and the editable template (wpmz/template.kml).
namespace sortie::mission::formats::wpml {

// One wayline (a Folder of each document): its plan, and the distance (m) and duration (s) the
// executable file states.
struct Wayline
{
    const Plan *plan = nullptr;
    double distance = 0.0;
    double duration = 0.0;
};

// The mission: the waylines flown in order, the last one's finish action ending it.
struct Mission
{
    std::vector<Wayline> waylines;
    QString takeOffRefPoint;  // "latitude,longitude,ellipsoidal height"; empty: not known
};

QByteArray waylinesOf(const Mission &mission, const WpmlExportOptions &o, const DjiDroneModel &model, const DjiPayload &payload);
QByteArray templateOf(const Mission &mission, const WpmlExportOptions &o, const DjiDroneModel &model, const DjiPayload &payload);

} // namespace sortie::mission::formats::wpml
