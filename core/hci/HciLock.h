#pragma once

#include "HciClient.h"
#include "HciError.h"
#include "HciObjectType.h"
#include "HciReply.h"

#include <QObject>
#include <QPointer>

#include <functional>

namespace sortie::hci {

// The one way Sortie changes a locked server object (a route it saves, a vehicle it commands or
// uploads to): take the object's lock, run the work, release the lock whatever the work's outcome,
// and only then report that outcome. When the lock is refused (another operator holds it, the
// line is down) the work never runs and `done` gets refused(error). Callbacks are dropped when
// `context` is destroyed.
template<class Result>
struct LockedWork
{
    using Finish = std::function<void(Result)>;
    // Does the work while the lock is held; calls finish exactly once.
    std::function<void(Finish finish)> work;
    // The outcome when the lock could not be taken.
    std::function<Result(const HciError &refusal)> refused;
    // The outcome, after the lock is released again (or was never taken).
    std::function<void(Result)> done;
    // Optional: told when the lock is granted and when the release is sent, for progress.
    std::function<void()> locked;
    std::function<void()> releasing;
};

template<class Result>
void underLock(HciClient *client, HciObjectType type, int objectId, QObject *context, LockedWork<Result> steps)
{
    HciReply *lock = client->acquireLock(type, objectId);
    QObject::connect(lock, &HciReply::finished, context, [client = QPointer<HciClient>(client), type, objectId, context, lock, steps] {
        if (!lock->isOk()) {
            if (steps.done)
                steps.done(steps.refused(lock->error()));
            return;
        }
        if (steps.locked)
            steps.locked();
        steps.work([client, type, objectId, context, steps](Result result) {
            if (steps.releasing)
                steps.releasing();
            if (!client) {
                if (steps.done)
                    steps.done(std::move(result));
                return;
            }
            HciReply *release = client->releaseLock(type, objectId, true);
            QObject::connect(release, &HciReply::finished, context, [steps, result = std::move(result)] {
                if (steps.done)
                    steps.done(result);
            });
        });
    });
}

} // namespace sortie::hci
