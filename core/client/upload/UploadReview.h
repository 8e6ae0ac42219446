#pragma once

#include "RouteValidator.h"

#include <QString>
#include <QStringList>

namespace sortie::client {

// What stands between a route and a vehicle, decided before anything is sent: validation errors
// block (the first one's row is the culprit the views select), warnings and unsaved edits are asked
// about once, together. Pure: the rules live here, the views only show them.
struct UploadReview
{
    QString blocked;       // why the upload may not go; empty when it may
    int culprit = -1;      // the row of the first error, -1 for the route as a whole or none
    QStringList warnings;  // every warning, each naming its waypoint or scan
    bool unsavedEdits = false;

    bool isBlocked() const { return !blocked.isEmpty(); }
    bool needsConfirmation() const { return !isBlocked() && (unsavedEdits || !warnings.isEmpty()); }
    // The one question the operator answers before the upload goes, listing everything to know.
    QString question(const QString &vehicleName) const;
};

UploadReview reviewUpload(const mission::ValidationReport &report, bool unsavedEdits);

// The validation gate for saving: empty when the route may be saved, otherwise why not, naming the
// first culprits (ValidationGate's wording).
QString saveRefusal(const mission::ValidationReport &report);

} // namespace sortie::client
