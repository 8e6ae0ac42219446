#pragma once

#include "JsonCursor.h"

namespace sortie::mission::formats {

// The current .sortie schema. Every older one has a step that lifts a document one version up,
// applied in order on the parsed JSON before it is read; a newer one is refused with a message.
constexpr int kSortieSchemaVersion = 3;

// Lifts doc from `from` to kSortieSchemaVersion in place. Throws JsonPathError on a document the
// steps cannot understand.
void migrateSortie(Json &doc, int from);

} // namespace sortie::mission::formats
