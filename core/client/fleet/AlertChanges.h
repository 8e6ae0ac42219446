#pragma once

#include <QString>

#include <algorithm>
#include <vector>

namespace sortie::client {

// What changed between two checks of an alert monitor (ProximityMonitor, ZoneAlertMonitor): the
// alerts that rose (each logged once and announced) and the keys of those that cleared. An alert is
// the same alert while its key is, however its figures move.
template<class Alert>
struct AlertChanges
{
    std::vector<Alert> raised;
    std::vector<QString> cleared;

    AlertChanges(const std::vector<Alert> &before, const std::vector<Alert> &now)
    {
        const auto has = [](const std::vector<Alert> &list, const QString &key) {
            return std::any_of(list.begin(), list.end(), [&key](const Alert &a) { return a.key == key; });
        };
        for (const Alert &old : before)
            if (!has(now, old.key))
                cleared.push_back(old.key);
        for (const Alert &a : now)
            if (!has(before, a.key))
                raised.push_back(a);
    }
};

} // namespace sortie::client
