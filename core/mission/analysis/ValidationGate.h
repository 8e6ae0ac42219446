#pragma once

#include "MissionError.h"
#include "RouteValidator.h"

namespace sortie::mission {

// Whether the operator has explicitly accepted a route with errors (a confirmation in the UI,
// --force on the command line). Nothing else lets an erroneous route out.
enum class ValidationOverride { None, AcceptErrors };

// Nothing with a validation error is saved or uploaded unless the operator overrides it; warnings
// never block. The error lists the first few issues so the operator knows what to fix.
Result<void> permitRelease(const ValidationReport &report, ValidationOverride override, const QString &what);

} // namespace sortie::mission
