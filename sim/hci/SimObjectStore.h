#pragma once

#include "HciProto.h"

#include <QObject>
#include <QString>

#include <map>
#include <memory>
#include <vector>

namespace sortie::sim {

namespace pb = com::ugcs::ucs::proto;

// The simulator's objects (Mission, Route, Vehicle, VehicleProfile, User, ...) in memory, keyed by
// object type and id. Every save bumps the object's version; a save carrying an older version than the
// stored one is refused, as two operators editing the same route must not overwrite each other.
class SimObjectStore : public QObject
{
    Q_OBJECT

public:
    struct SaveResult
    {
        std::shared_ptr<const pb::DomainObjectWrapper> object; // the stored object, null on error
        QString error;
        bool created = false;
    };

    explicit SimObjectStore(QObject *parent = nullptr);
    ~SimObjectStore() override;

    const pb::DomainObjectWrapper *find(const QString &type, int id) const;
    std::vector<const pb::DomainObjectWrapper *> list(const QString &type) const;
    QStringList types() const;
    int count() const;

    // Creates (no id) or updates (id of a stored object) an object of `type` held by `wrapper`.
    SaveResult save(const QString &type, const pb::DomainObjectWrapper &wrapper, qint64 nowMs);
    // Removes an object; returns false when it does not exist. `version` receives its last version.
    bool remove(const QString &type, int id, int *version = nullptr);
    // Puts an object as it is (seeding, loading a file): keeps its id and version.
    void insert(const QString &type, const pb::DomainObjectWrapper &wrapper);
    int allocateId() { return m_nextId++; }
    int nextId() const { return m_nextId; }
    void setNextId(int id) { m_nextId = id; }

signals:
    // modificationType is a pb::ModificationType (MT_CREATE, MT_UPDATE, MT_DELETE); object is empty on delete.
    void changed(int modificationType, const QString &type, int id, const pb::DomainObjectWrapper &object);

private:
    void completeComposites(const QString &type, google::protobuf::Message &object, bool created, qint64 nowMs);

    std::map<QString, std::map<int, std::shared_ptr<pb::DomainObjectWrapper>>> m_objects;
    int m_nextId = 1;
};

} // namespace sortie::sim
