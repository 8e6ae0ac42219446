#pragma once

#include "AlgorithmCatalog.h"
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
//
// A segment of another algorithm (AlgorithmSegment) keeps its values as wire text: its
// parameters are its algorithm's definition in `catalog` (the server's description, else the
// built-in one), checked by ParameterDefinition::check, plus any name it carries that no
// definition has, which is raw text: kept, shown and editable, never checked.

// The names a segment has, in the order an editor shows them.
QStringList parameterNames(const Segment &segment, const AlgorithmCatalog &catalog = AlgorithmCatalog::builtIn());
// The value, typed; invalid when the segment has no such parameter or does not set it.
QVariant parameterValue(const Segment &segment, const QString &name, const AlgorithmCatalog &catalog = AlgorithmCatalog::builtIn());
// Sets one parameter. On a bad value or an unknown name returns false, leaves the segment as it
// was and says why in *error. An empty text unsets an AlgorithmSegment's parameter ("not set").
bool setParameterValue(Segment &segment, const QString &name, const QVariant &value, QString *error = nullptr,
                       const AlgorithmCatalog &catalog = AlgorithmCatalog::builtIn());

} // namespace sortie::mission
