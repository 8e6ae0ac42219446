#pragma once

#include "HciObjectType.h"

#include <QObject>
#include <QStringList>
#include <QVariantMap>

#include <chrono>

namespace sortie::hci {

class HciReply;
class HciSession;
class HciSubscription;

// Typed HCI calls on a session. Each builds the request, sends it and returns the HciReply at once;
// read the typed response in finished() with reply->response<pb::XxxResponse>(). Nothing blocks.
// Long operations (ProcessRoute, UploadRoute) report HciReply::progress.
class HciClient : public QObject
{
    Q_OBJECT

public:
    explicit HciClient(HciSession *session, QObject *parent = nullptr);
    HciSession *session() const { return m_session; }

    // Objects -> GetObjectListResponse, GetObjectResponse, CreateOrUpdateObjectResponse,
    // UpdateObjectFieldsResponse, DeleteObjectResponse.
    HciReply *listObjects(HciObjectType type, bool refreshDependencies = false);
    HciReply *listObjects(const QString &objectType, bool refreshDependencies = false);
    HciReply *getObject(HciObjectType type, int objectId, bool refreshDependencies = false);
    HciReply *getObject(const QString &objectType, int objectId, bool refreshDependencies = false);
    // Creates (no id) or updates (with id and version) any domain object: Route, Mission, Vehicle...
    HciReply *createOrUpdate(const google::protobuf::Message &object, bool acquireLock = false);
    // Updates only the named fields of an object (it must carry its id).
    HciReply *updateFields(const google::protobuf::Message &object, const QStringList &fieldNames, bool acquireLock = false);
    HciReply *deleteObject(HciObjectType type, int objectId);
    HciReply *deleteObject(const QString &objectType, int objectId);

    // Locks -> AcquireLockResponse, ReleaseLockResponse, CheckLockResponse (lock absent = free).
    HciReply *acquireLock(HciObjectType type, int objectId);
    HciReply *releaseLock(HciObjectType type, int objectId, bool ifExclusive = true);
    HciReply *checkLock(HciObjectType type, int objectId);

    // Vehicle commands -> SendCommandResponse (check commandResults[].commandStatus).
    HciReply *sendCommand(const pb::Vehicle &vehicle, const pb::Command &command);
    // A flight-controller command; numbers go as doubleValue (as UgCS expects), strings and bools as such.
    HciReply *sendCommand(const pb::Vehicle &vehicle, const QString &code, const QVariantMap &arguments = {});

    // Routes -> ProcessRouteResponse (check every segment's status), UploadRouteResponse (with progress).
    HciReply *processRoute(const pb::Route &route);
    HciReply *uploadRoute(const pb::Vehicle &vehicle, const pb::ProcessedRoute &route, bool addFirstWaypoint = true);

    // Telemetry history of a vehicle between two times (ms since the epoch) -> GetTelemetryResponse.
    HciReply *telemetryHistory(const pb::Vehicle &vehicle, qint64 fromTimeMs, qint64 toTimeMs, int limit = 7200);

    // Subscriptions owned by the session (they survive reconnects). vehicleId -1 = all vehicles.
    HciSubscription *subscribeTelemetry(int vehicleId = -1);
    HciSubscription *subscribeObjectChanges(HciObjectType type, int objectId = -1);
    HciSubscription *subscribeLocks(HciObjectType type, int objectId = -1);
    HciSubscription *subscribeCommands(const pb::Vehicle &vehicle);

    void setLongOperationTimeout(std::chrono::milliseconds timeout) { m_longTimeout = timeout; }

private:
    HciSession *m_session;
    std::chrono::milliseconds m_longTimeout{120000}; // ProcessRoute and UploadRoute on big routes
};

} // namespace sortie::hci
