// Route settings set by name, the way the route panel and scripts address them.
#include "RouteSettingNames.h"

namespace sortie::mission {

SettingAssignment assignRouteSetting(RouteSettings &s, const QString &name, const QVariant &value)
{
    bool ok = true;
    if (name == QLatin1String("name"))
        s.name = value.toString();
    else if (name == QLatin1String("safeAltitude"))
        s.safeAltitude = value.toDouble(&ok);
    else if (name == QLatin1String("maxAltitude"))
        s.maxAltitude = value.toDouble(&ok);
    else if (name == QLatin1String("initialSpeed"))
        s.initialSpeed = value.toDouble(&ok);
    else if (name == QLatin1String("maxSpeed"))
        s.maxSpeed = value.toDouble(&ok);
    else if (name == QLatin1String("cornerRadius"))
        s.cornerRadius = value.toDouble(&ok);
    else if (name == QLatin1String("takeoffHeight"))
        s.takeoffHeight = value.toDouble(&ok);
    else if (name == QLatin1String("maxHorizontalSpeed"))
        s.profile.maxHorizontalSpeed = value.toDouble(&ok);
    else
        return SettingAssignment::UnknownName;
    return ok ? SettingAssignment::Set : SettingAssignment::NotANumber;
}

} // namespace sortie::mission
