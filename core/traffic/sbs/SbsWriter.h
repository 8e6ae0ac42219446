#pragma once

#include "SbsMessage.h"

#include <cstdint>
#include <string>

namespace sortie::traffic::sbs {

// Writes a message as one SBS-1 line ("MSG,3,1,1,4CA2D6,1,2026/11/26,18:44:00.000,...\r\n"), as
// dump1090 writes them: 22 fields, absent values empty, flags -1 (true) or 0, the generated and
// logged date and time both `timeMs` (milliseconds since the epoch, UTC). The simulator's feed.
std::string writeSbsLine(const SbsMessage &message, int64_t timeMs);

} // namespace sortie::traffic::sbs
