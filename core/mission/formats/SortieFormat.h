#pragma once

#include "Mission.h"
#include "MissionError.h"

#include <QByteArray>

namespace sortie::mission::formats {

// Sortie's native mission file (.sortie): UTF-8 JSON with "format": "sortie-mission" and a
// "schemaVersion". Everything in the model is written, including what a UgCS server sent that
// Sortie does not model (as base64 protobuf under "hci"), so a round trip is exact. Older schemas
// are migrated on read (SortieMigrations.h). Pure: bytes in, bytes out.
QByteArray writeSortie(const Mission &mission);
Result<Mission> readSortie(const QByteArray &data);

} // namespace sortie::mission::formats
