#pragma once

#include "Segment.h"

#include <QString>
#include <QStringList>
#include <QVariant>

namespace sortie::mission {

// A segment's parameters by their UgCS wire names (`height`, `overlapSide`, `sideDistance`,
// `directionAngle`, `wpTurnType`, ... see docs/missions.md), in the wire's units: the one reader
// the editor, the generated segment editor and the HCI mapping all use, so that a name, a unit
// or a range is known in one place.
//
// Values are typed: a double, an int, a bool or a selection name as the parameter's type says.
// Text is accepted too, as the wire carries it ("60.0", "True", "AMSL"); anything else is refused.

// The names a segment of this kind has, in the order an editor shows them.
QStringList parameterNames(const Segment &segment);
// The value, typed; invalid when the segment has no such parameter (or it is not set).
QVariant parameterValue(const Segment &segment, const QString &name);
// Sets one parameter. On a bad value or an unknown name returns false, leaves the segment as it
// was and says why in *error.
bool setParameterValue(Segment &segment, const QString &name, const QVariant &value, QString *error = nullptr);

} // namespace sortie::mission
