#include "UploadReview.h"

#include "ValidationGate.h"

#include <QCoreApplication>

namespace sortie::client {

namespace {
// "Waypoint 3: the speed must be positive. Fix it before uploading." The gate decides; this names the
// first culprit and how many more there are.
QString refusal(const mission::ValidationReport &report, const QString &verb)
{
    QString first;
    for (const mission::ValidationIssue &issue : report.issues) {
        if (issue.severity == mission::Severity::Error) {
            first = issue.message;
            break;
        }
    }
    const int more = report.errorCount() - 1;
    if (more == 0)
        return QCoreApplication::translate("UploadReview", "%1 Fix it before %2.").arg(first, verb);
    return QCoreApplication::translate("UploadReview", "%1 (and %n more error(s)) Fix them before %2.", nullptr, more).arg(first, verb);
}

} // namespace

UploadReview reviewUpload(const mission::ValidationReport &report, bool unsavedEdits)
{
    UploadReview review;
    review.unsavedEdits = unsavedEdits;
    if (!mission::permitRelease(report, mission::ValidationOverride::None, QCoreApplication::translate("UploadReview", "Upload"))) {
        review.blocked = refusal(report, QCoreApplication::translate("UploadReview", "uploading"));
        for (const mission::ValidationIssue &issue : report.issues) {
            if (issue.severity == mission::Severity::Error) {
                review.culprit = issue.segment;
                break;
            }
        }
        return review;
    }
    for (const mission::ValidationIssue &issue : report.issues) {
        if (issue.severity == mission::Severity::Warning)
            review.warnings << issue.message;
    }
    return review;
}

QString UploadReview::question(const QString &vehicleName) const
{
    QStringList parts;
    if (unsavedEdits)
        parts << QCoreApplication::translate("UploadReview", "The route has edits that are not saved: the vehicle would fly what is on screen, not what the server holds.");
    if (!warnings.isEmpty()) {
        parts << QCoreApplication::translate("UploadReview", "The route has %n warning(s):", nullptr, int(warnings.size()));
        for (const QString &w : warnings)
            parts << QStringLiteral("• ") + w;
    }
    parts << QCoreApplication::translate("UploadReview", "Upload to %1?").arg(vehicleName);
    return parts.join(QLatin1Char('\n'));
}

QString saveRefusal(const mission::ValidationReport &report)
{
    return mission::permitRelease(report, mission::ValidationOverride::None, QCoreApplication::translate("UploadReview", "Saving")) ? QString() : refusal(report, QCoreApplication::translate("UploadReview", "saving"));
}

} // namespace sortie::client
