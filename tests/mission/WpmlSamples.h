#pragma once

// WPML documents written by hand the way DJI Pilot 2 and FlightHub 2 lay them out (DJI Cloud API,
// "DJI WPML"), for the reader's tests: a mission config, Folders of Placemarks, action groups.
#include "ZipArchive.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace wpmlsample {

inline QString el(const QString &name, const QString &text)
{
    return QStringLiteral("<wpml:%1>%2</wpml:%1>").arg(name, text);
}

inline QString drone(int e, int sub, std::optional<int> payload = std::nullopt)
{
    return el(QStringLiteral("droneInfo"), el(QStringLiteral("droneEnumValue"), QString::number(e)) + el(QStringLiteral("droneSubEnumValue"), QString::number(sub)))
           + (payload ? el(QStringLiteral("payloadInfo"), el(QStringLiteral("payloadEnumValue"), QString::number(*payload))) : QString());
}

inline QString action(const QString &func, const QString &params = {})
{
    return el(QStringLiteral("action"), el(QStringLiteral("actionId"), QStringLiteral("0")) + el(QStringLiteral("actionActuatorFunc"), func)
                                            + el(QStringLiteral("actionActuatorFuncParam"), params));
}

inline QString gimbalPitch(double pitch)
{
    return action(QStringLiteral("gimbalRotate"), el(QStringLiteral("gimbalRotateMode"), QStringLiteral("absoluteAngle"))
                                                      + el(QStringLiteral("gimbalPitchRotateEnable"), QStringLiteral("1"))
                                                      + el(QStringLiteral("gimbalPitchRotateAngle"), QString::number(pitch)));
}

inline QString group(int start, int end, const QString &trigger, const QString &actions, const QString &param = {})
{
    return el(QStringLiteral("actionGroup"),
              el(QStringLiteral("actionGroupId"), QString::number(start)) + el(QStringLiteral("actionGroupStartIndex"), QString::number(start))
                  + el(QStringLiteral("actionGroupEndIndex"), QString::number(end)) + el(QStringLiteral("actionGroupMode"), QStringLiteral("sequence"))
                  + el(QStringLiteral("actionTrigger"), el(QStringLiteral("actionTriggerType"), trigger)
                                                            + (param.isEmpty() ? QString() : el(QStringLiteral("actionTriggerParam"), param)))
                  + actions);
}

// Waypoint `index` of a line north from 56.9760, 24.0700 (about 55.7 m apart). heightTag:
// executeHeight (waylines.wpml) or height (template.kml).
inline QString placemark(int index, double height, const QString &inner = {}, const QString &heightTag = QStringLiteral("executeHeight"))
{
    return QStringLiteral("<Placemark><Point><coordinates>24.07,%1</coordinates></Point>").arg(56.976 + index * 0.0005, 0, 'f', 4)
           + el(QStringLiteral("index"), QString::number(index)) + el(heightTag, QString::number(height))
           + el(QStringLiteral("waypointSpeed"), QStringLiteral("5"))
           + el(QStringLiteral("waypointTurnParam"), el(QStringLiteral("waypointTurnMode"), QStringLiteral("toPointAndStopWithDiscontinuityCurvature")))
           + inner + QStringLiteral("</Placemark>");
}

inline QString folder(const QString &heightMode, const QString &inner)
{
    return QStringLiteral("<Folder>") + el(QStringLiteral("templateId"), QStringLiteral("0")) + el(QStringLiteral("executeHeightMode"), heightMode)
           + el(QStringLiteral("waylineId"), QStringLiteral("0")) + inner + QStringLiteral("</Folder>");
}

inline QByteArray document(const QString &config, const QString &folders, const QString &finish = QStringLiteral("goHome"))
{
    return (QStringLiteral("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<kml xmlns=\"http://www.opengis.net/kml/2.2\" "
                           "xmlns:wpml=\"http://www.dji.com/wpmz/1.0.2\"><Document><wpml:missionConfig>")
            + el(QStringLiteral("finishAction"), finish) + el(QStringLiteral("globalTransitionalSpeed"), QStringLiteral("8")) + config
            + QStringLiteral("</wpml:missionConfig>") + folders + QStringLiteral("</Document></kml>"))
        .toUtf8();
}

inline QByteArray kmz(const QByteArray &waylines, const QByteArray &templateKml = {})
{
    std::vector<sortie::mission::formats::ZipEntry> entries;
    if (!templateKml.isEmpty())
        entries.push_back({QStringLiteral("wpmz/template.kml"), templateKml});
    entries.push_back({QStringLiteral("wpmz/waylines.wpml"), waylines});
    return *sortie::mission::formats::writeZip(entries);
}

} // namespace wpmlsample
