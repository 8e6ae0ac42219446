#pragma once

#include "GeoPoint.h"
#include "MissionError.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <map>
#include <optional>
#include <vector>

// A WPML document (waylines.wpml or template.kml) as read, before it means anything to Sortie: the
// elements Sortie uses, and the names of those it does not, so none vanishes silently.
namespace sortie::mission::formats::wpml {

struct ReadAction
{
    QString func;
    std::map<QString, QString> params;
};

struct ReadGroup
{
    int start = 0;
    int end = 0;
    QString trigger;  // empty in a startActionGroup
    std::optional<double> interval;
    std::vector<ReadAction> actions;
};

struct ReadPoint
{
    std::optional<GeoPoint> position;
    std::optional<int> index;
    std::optional<double> height;  // executeHeight (waylines) or height (template)
    std::optional<double> speed;
    QString turnMode;
    QString headingMode;
    QString headingAngle;
    QString poi;
    bool straight = true;
    std::vector<ReadGroup> groups;
    int line = 0;
};

struct ReadFolder
{
    QString heightMode;  // executeHeightMode or the template's heightMode
    QString templateType;
    std::optional<ReadGroup> startGroup;  // wpml:startActionGroup: before the wayline starts
    std::vector<ReadPoint> points;
    // Elements Sortie does not keep: their name, and the waypoint numbers (1-based; 0: the wayline's own).
    std::map<QString, std::vector<int>> unknown;
};

struct ReadDocument
{
    QString finishAction;
    std::optional<double> transitionalSpeed;
    std::optional<int> droneEnum, droneSubEnum, payloadEnum;
    QString takeOffRefPoint;  // "latitude,longitude,ellipsoidal height"
    std::optional<double> takeOffRefPointAglHeight;
    std::vector<ReadFolder> folders;
    QStringList unknown;  // "wpml:globalRTHHeight", "wpml:exitOnRCLost \"goContinue\""
};

// Reads a document by local names within the WPML and KML namespaces (any wpmz version). A damaged
// document fails with its file, line and column.
Result<ReadDocument> readDocument(const QByteArray &data, const QString &file);

} // namespace sortie::mission::formats::wpml
