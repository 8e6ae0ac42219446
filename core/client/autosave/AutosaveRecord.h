#pragma once

#include "MissionError.h"
#include "Route.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>

namespace sortie::client {

// What an autosave file holds: the route being edited, the route as last loaded from or saved to
// the server or a file (so "what changed since the last save" can be shown), where it belongs
// (server, user, route id and the version it was loaded at; empty / -1 when unknown) and when it
// was written.
struct AutosaveRecord
{
    mission::Route working;
    mission::Route baseline;
    QString server;
    QString user;
    int routeId = -1;
    int routeVersion = -1;
    QDateTime savedAt;
};

// The file: UTF-8 JSON, {"format": "sortie-autosave", "formatVersion": 1, "savedAt", "server",
// "user", "routeId", "routeVersion", "working": <.sortie document>, "baseline": <.sortie document>}.
// Both routes are complete .sortie documents (everything the server sent is kept). Pure.
QByteArray encodeAutosave(const AutosaveRecord &record);
// The same, with the routes already encoded by encodeAutosaveRoute (the baseline changes rarely:
// encoding it once saves time on every write of a big route).
QByteArray encodeAutosave(const AutosaveRecord &header, const QByteArray &working, const QByteArray &baseline);
QByteArray encodeAutosaveRoute(const mission::Route &route);
// Errors say what is wrong and where (line, or the JSON path of the part that is broken).
mission::Result<AutosaveRecord> decodeAutosave(const QByteArray &data);

} // namespace sortie::client
