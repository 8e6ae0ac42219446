#pragma once

#include "SimServices.h"

#include <QString>

namespace sortie::sim {

class HciRequestDispatcher;
struct SimCall;

// GetObjectList, GetObject, CreateOrUpdateObject, UpdateObjectFields, DeleteObject on the world's
// store. CommandDefinitions are generated live from the vehicles; users never carry passwords.
// An object locked by another session cannot be changed or deleted.
class SimObjectService
{
public:
    explicit SimObjectService(SimServices services);
    void install(HciRequestDispatcher &dispatcher);

private:
    void list(SimCall &call);
    void get(SimCall &call);
    void createOrUpdate(SimCall &call);
    void updateFields(SimCall &call);
    void remove(SimCall &call);
    // Why `type` cannot be written by clients, or empty when it can.
    static QString readOnlyReason(const QString &type, bool creating);
    QString lockedReason(const SimCall &call, const QString &type, int id) const;

    SimServices m_s;
};

} // namespace sortie::sim
