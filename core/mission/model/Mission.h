#pragma once

#include "ServerOrigin.h"
#include "Route.h"

#include <QString>

#include <vector>

namespace sortie::mission {

struct Mission
{
    QString name;
    QString description;
    std::vector<Route> routes;
    ServerOrigin origin;
    bool operator==(const Mission &) const = default;
};

} // namespace sortie::mission
