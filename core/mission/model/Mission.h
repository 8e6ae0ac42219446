#pragma once

#include "HciOrigin.h"
#include "Route.h"

#include <QString>

#include <vector>

namespace sortie::mission {

struct Mission
{
    QString name;
    QString description;
    std::vector<Route> routes;
    MissionOrigin origin;
    bool operator==(const Mission &) const = default;
};

} // namespace sortie::mission
