// sortie-log: record a UgCS server's vehicles into a flight log, describe a log, export its tracks,
// compare a flight with its plan, fit a vehicle's energy profile to its flights, geotag a flight's
// photos and judge their coverage. The work is in core/flightlog, core/endurance/fit, core/geotag and
// core/coverage; this file reads arguments.
#include "Camera.h"
#include "CertificateFingerprint.h"
#include "CoverageMap.h"
#include "DemOpener.h"
#include "EnergyProfile.h"
#include "FlightLog.h"
#include "FlightLogExport.h"
#include "FlightLogInfo.h"
#include "Geotagger.h"
#include "LogFit.h"
#include "MissionFiles.h"
#include "PhotoShots.h"
#include "ReflyRoute.h"
#include "RouteComparison.h"
#include "ServerRecording.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QSaveFile>
#include <QSettings>
#include <QSocketNotifier>
#include <QTextStream>

#include <cmath>
#include <csignal>
#include <sys/socket.h>
#include <unistd.h>

using namespace sortie;

namespace {

const char *const kUsage =
    "usage: sortie-log <command> [options]\n"
    "\n"
    "  record --server [tls://]HOST:PORT --user NAME [--password-file FILE] [--seconds N] [--max-size MB]\n"
    "         [--server-pin SHA256|CERT.pem] [--allow-cleartext] OUT\n"
    "      Record every vehicle of an HCI server until N seconds have passed or SIGINT/SIGTERM,\n"
    "      then close the log. The password is the first line of FILE (else $SORTIE_PASSWORD).\n"
    "      tls:// secures the connection: the certificate pinned with --server-pin, else one the\n"
    "      system trusts, else the one remembered on first use (its fingerprint is printed). To a\n"
    "      server that is not this computer, a plain connection is refused unless --allow-cleartext.\n"
    "  info LOG [--json]\n"
    "      Vehicles, fields, time span, sample counts, routes and events.\n"
    "  export LOG --format gpx|kml|csv [--vehicle NAME] [-o OUT]\n"
    "      Tracks as GPX 1.1, KML (gx:Track) or CSV; to stdout without -o.\n"
    "  compare LOG ROUTE_FILE --vehicle NAME [--route N] [--json]\n"
    "      The flown track against the planned route (.sortie, .plan, .waypoints): per leg the\n"
    "      largest and mean cross-track and altitude deviation, when each waypoint was reached.\n"
    "  geotag PHOTO_DIR --track LOG_OR_GPX --out DIR [--offset SECONDS] [--by-time] [--vehicle ID] [--json]\n"
    "      Places each photo on the track (a flight log, or a GPX file). A log that holds the\n"
    "      vehicle's photo events pairs the photos with them (the camera clock's offset found and said,\n"
    "      each event without a photo listed as missing, each photo without an event named); else, or\n"
    "      with --by-time, by its time: EXIF DateTimeOriginal, the camera's clock taken as UTC unless\n"
    "      OffsetTimeOriginal says otherwise, plus --offset. Writes geotagged copies into DIR (the originals are never changed), and\n"
    "      OpenDroneMap's geo.txt and geotags.csv (Pix4D, Metashape). --vehicle when the log holds\n"
    "      several. Its exit status: 0 every photo tagged, 2 some were not (named), 1 bad usage or input.\n"
    "  coverage PHOTO_DIR --track LOG_OR_GPX --camera NAME --out OVERLAP.tif [--offset SECONDS] [--by-time]\n"
    "           [--vehicle ID] [--dem PATH | --ground-amsl M] [--min-images N] [--cell M] [--refly ROUTE] [--json]\n"
    "      The ground the photos cover, each placed on the track as geotag places it, looking straight\n"
    "      down from its height above the ground under it (a DEM), above flat ground at --ground-amsl,\n"
    "      or else above the take-off point: images per cell as a GeoTIFF, forward and side overlap,\n"
    "      the ground sample distance, and the holes seen by fewer than N images (default 5).\n"
    "      --refly writes a route of an area scan per hole (the\n"
    "      survey's camera, height, overlap and legs; .sortie, .plan, ...), checked as sortie-plan checks\n"
    "      a route. Exit status: 0 no hole, 2 holes (listed), 1 bad usage or input.\n"
    "\n"
    "Exit status: 0 done, 1 failed, 2 bad usage (geotag, coverage: see above).\n";

enum Exit { Ok = 0, Failed = 1, Usage = 2 };

struct Args
{
    QStringList positional;
    QHash<QString, QString> options;
    QSet<QString> flags;
};

// Options with a value (--name VALUE) and flags (--json); anything else is positional.
std::optional<Args> parse(const QStringList &in, const QStringList &valued, const QStringList &flags, QTextStream &err)
{
    Args a;
    for (int i = 0; i < in.size(); ++i) {
        const QString &s = in[i];
        if (valued.contains(s)) {
            if (i + 1 >= in.size()) {
                err << "sortie-log: " << s << " needs a value\n";
                return std::nullopt;
            }
            a.options.insert(s, in[++i]);
        } else if (flags.contains(s)) {
            a.flags.insert(s);
        } else if (s.startsWith(QLatin1String("-")) && s.size() > 1) {
            err << "sortie-log: unknown option " << s << "\n";
            return std::nullopt;
        } else {
            a.positional.append(s);
        }
    }
    return a;
}

std::unique_ptr<flightlog::FlightLog> openLog(const QString &path, QTextStream &err)
{
    QString error;
    auto log = flightlog::FlightLog::open(path, &error);
    if (!log)
        err << "sortie-log: " << error << "\n";
    else if (const QString damage = log->damage(); !damage.isEmpty())
        err << "sortie-log: " << path << " is damaged: " << damage << "\n";
    return log;
}

int info(const QStringList &in, QTextStream &out, QTextStream &err)
{
    const auto a = parse(in, {}, {QStringLiteral("--json")}, err);
    if (!a || a->positional.size() != 1)
        return (err << kUsage, Usage);
    const auto log = openLog(a->positional.first(), err);
    if (!log)
        return Failed;
    if (a->flags.contains(QStringLiteral("--json")))
        out << QJsonDocument(flightlog::logInfoJson(*log)).toJson(QJsonDocument::Indented);
    else
        out << flightlog::logInfoText(*log);
    return Ok;
}

int exportTracks(const QStringList &in, QTextStream &out, QTextStream &err)
{
    const auto a = parse(in, {QStringLiteral("--format"), QStringLiteral("--vehicle"), QStringLiteral("-o")}, {}, err);
    if (!a || a->positional.size() != 1 || !a->options.contains(QStringLiteral("--format")))
        return (err << kUsage, Usage);
    const auto format = flightlog::exportFormatFromName(a->options.value(QStringLiteral("--format")));
    if (!format) {
        err << "sortie-log: unknown format \"" << a->options.value(QStringLiteral("--format")) << "\" (gpx, kml or csv)\n";
        return Usage;
    }
    const auto log = openLog(a->positional.first(), err);
    if (!log)
        return Failed;
    std::vector<int> vehicles;
    if (a->options.contains(QStringLiteral("--vehicle"))) {
        const int v = log->vehicleIndex(a->options.value(QStringLiteral("--vehicle")));
        if (v < 0) {
            err << "sortie-log: no vehicle \"" << a->options.value(QStringLiteral("--vehicle")) << "\" in " << log->path() << "\n";
            return Failed;
        }
        vehicles.push_back(v);
    }
    QString error;
    if (a->options.contains(QStringLiteral("-o"))) {
        QSaveFile file(a->options.value(QStringLiteral("-o")));
        if (!file.open(QIODevice::WriteOnly) || !flightlog::exportLog(*log, *format, vehicles, &file, &error) || !file.commit()) {
            err << "sortie-log: " << file.fileName() << ": " << (error.isEmpty() ? file.errorString() : error) << "\n";
            return Failed;
        }
        return Ok;
    }
    out.flush();
    QFile stdoutFile;
    stdoutFile.open(stdout, QIODevice::WriteOnly);
    if (!flightlog::exportLog(*log, *format, vehicles, &stdoutFile, &error)) {
        err << "sortie-log: " << error << "\n";
        return Failed;
    }
    return Ok;
}

int compare(const QStringList &in, QTextStream &out, QTextStream &err)
{
    const auto a = parse(in, {QStringLiteral("--vehicle"), QStringLiteral("--route")}, {QStringLiteral("--json")}, err);
    if (!a || a->positional.size() != 2 || !a->options.contains(QStringLiteral("--vehicle")))
        return (err << kUsage, Usage);
    const auto log = openLog(a->positional[0], err);
    if (!log)
        return Failed;
    const auto loaded = mission::formats::loadMission(a->positional[1]);
    if (!loaded) {
        err << "sortie-log: " << loaded.error().toString() << "\n";
        return Failed;
    }
    const auto &routes = loaded->mission.routes;
    bool ok = true;
    const int routeIndex = a->options.value(QStringLiteral("--route"), QStringLiteral("1")).toInt(&ok) - 1;
    if (!ok || routeIndex < 0 || size_t(routeIndex) >= routes.size()) {
        err << "sortie-log: " << a->positional[1] << " has " << routes.size() << " route(s); --route takes 1 to " << routes.size() << "\n";
        return Failed;
    }
    const QString vehicleName = a->options.value(QStringLiteral("--vehicle"));
    const int vehicle = log->vehicleIndex(vehicleName);
    const flightlog::ComparisonResult result = flightlog::compareRoute(*log, vehicle, routes[size_t(routeIndex)]);
    if (!result.comparison) {
        err << "sortie-log: " << (vehicle < 0 ? QStringLiteral("\"%1\": ").arg(vehicleName) : QString()) << result.error << "\n";
        return Failed;
    }
    if (a->flags.contains(QStringLiteral("--json")))
        out << QJsonDocument(result.comparison->toJson()).toJson(QJsonDocument::Indented);
    else
        out << result.comparison->toText();
    return Ok;
}

int fit(const QStringList &in, QTextStream &out, QTextStream &err)
{
    const auto a = parse(in, {QStringLiteral("--vehicle"), QStringLiteral("--capacity"), QStringLiteral("--out")}, {}, err);
    if (!a || a->positional.isEmpty())
        return (err << kUsage, Usage);
    endurance::fit::FitOptions options;
    if (a->options.contains(QStringLiteral("--capacity"))) {
        bool ok = false;
        const double wh = a->options.value(QStringLiteral("--capacity")).toDouble(&ok);
        if (!ok || !(wh > 0))
            return (err << "sortie-log: --capacity takes the battery's usable energy in Wh\n", Usage);
        options.capacityWh = wh;
    }
    const auto loaded = endurance::fit::loadFlights(a->positional, a->options.value(QStringLiteral("--vehicle")));
    for (const QString &failure : loaded.failures)
        err << "sortie-log: " << failure << "\n";
    for (const QString &warning : loaded.warnings)
        err << "sortie-log: " << warning << "\n";
    if (loaded.traces.empty()) {
        err << "sortie-log: no flight with battery telemetry to fit\n";
        return Failed;
    }
    const endurance::fit::EnergyFit result = endurance::fit::fitEnergy(loaded.traces, options);
    out << endurance::fit::fitReport(result);
    int code = loaded.failures.isEmpty() ? Ok : Failed;
    if (a->options.contains(QStringLiteral("--out"))) {
        const QString path = a->options.value(QStringLiteral("--out"));
        QString why;
        const auto profile = result.profile(QStringLiteral("fitted from %1 flight(s)").arg(result.flights), &why);
        if (!profile) {
            err << "sortie-log: no profile written to " << path << ": " << why << "\n";
            return Failed;
        }
        QSaveFile file(path);
        if (!file.open(QIODevice::WriteOnly) || file.write(endurance::writeEnergyProfile(*profile)) < 0 || !file.commit()) {
            err << "sortie-log: " << path << ": " << file.errorString() << "\n";
            return Failed;
        }
        out << "profile written to " << path << "\n";
    }
    return code;
}

// The track --track names: a flight log (its one vehicle, or --vehicle's) or a GPX file. nullopt
// after saying what is wrong on err.
std::optional<geotag::Track> trackOf(const Args &a, QTextStream &err)
{
    const QString trackPath = a.options.value(QStringLiteral("--track"));
    if (!QFileInfo(trackPath).isFile()) {
        err << "sortie-log: --track " << trackPath << ": no such file\n";
        return std::nullopt;
    }
    std::optional<geotag::Track> track;
    QString error;
    if (geotag::looksLikeFlightLog(trackPath)) {
        const auto log = openLog(trackPath, err);
        if (!log)
            return std::nullopt;
        int vehicle = -1;
        if (a.options.contains(QStringLiteral("--vehicle"))) {
            vehicle = log->vehicleIndex(a.options.value(QStringLiteral("--vehicle")));
            if (vehicle < 0) {
                err << "sortie-log: no vehicle \"" << a.options.value(QStringLiteral("--vehicle")) << "\" in " << log->path() << "\n";
                return std::nullopt;
            }
        } else if (log->vehicles().size() == 1) {
            vehicle = 0;
        } else {
            QStringList names;
            for (const auto &v : log->vehicles())
                names.append(v.name());
            err << "sortie-log: " << log->path() << " holds " << log->vehicles().size() << " vehicles (" << names.join(QStringLiteral(", "))
                << "): choose one with --vehicle\n";
            return std::nullopt;
        }
        track = geotag::flightLogTrack(*log, vehicle, &error);
    } else {
        if (a.options.contains(QStringLiteral("--vehicle"))) {
            err << "sortie-log: --vehicle chooses a vehicle of a flight log; " << trackPath << " is a GPX file\n";
            return std::nullopt;
        }
        track = geotag::readGpxTrack(trackPath, &error);
    }
    if (!track)
        err << "sortie-log: " << error << "\n";
    return track;
}

// --offset: seconds added to the camera's clock; --by-time: by it even when the log has photo
// events. false after saying what is wrong.
bool readOffset(const Args &a, geotag::MatchOptions *match, QTextStream &err)
{
    match->byEvents = !a.flags.contains(QStringLiteral("--by-time"));
    if (!a.options.contains(QStringLiteral("--offset")))
        return true;
    bool ok = false;
    const double offset = a.options.value(QStringLiteral("--offset")).toDouble(&ok);
    if (!ok || !std::isfinite(offset) || std::fabs(offset) > 366.0 * 86400) {
        err << "sortie-log: --offset takes seconds added to the camera's clock (e.g. -3.5), not \"" << a.options.value(QStringLiteral("--offset")) << "\"\n";
        return false;
    }
    match->offsetMs = std::llround(offset * 1000);
    return true;
}

// geotag's own exit status, as issue 34 gives it: 0 every photo tagged, 2 some not, 1 bad usage.
enum GeotagExit { AllTagged = 0, GeotagFailed = 1, SomeUntagged = 2 };

int geotagPhotos(const QStringList &in, QTextStream &out, QTextStream &err)
{
    const auto a = parse(in, {QStringLiteral("--track"), QStringLiteral("--out"), QStringLiteral("--offset"), QStringLiteral("--vehicle")},
                         {QStringLiteral("--json"), QStringLiteral("--by-time")}, err);
    if (!a)
        return GeotagFailed;
    if (a->positional.size() != 1) {
        err << "sortie-log: geotag takes one photo folder (PHOTO_DIR), " << a->positional.size() << " given\n";
        return GeotagFailed;
    }
    for (const char *required : {"--track", "--out"}) {
        if (!a->options.contains(QLatin1String(required))) {
            err << "sortie-log: geotag needs " << required << "\n";
            return GeotagFailed;
        }
    }
    geotag::GeotagOptions options;
    options.outFolder = a->options.value(QStringLiteral("--out"));
    if (!readOffset(*a, &options.match, err))
        return GeotagFailed;

    const auto track = trackOf(*a, err);
    if (!track)
        return GeotagFailed;
    QString error;
    const auto report = geotag::geotagFolder(a->positional.first(), *track, options, &error);
    if (!report) {
        err << "sortie-log: " << error << "\n";
        return GeotagFailed;
    }
    if (a->flags.contains(QStringLiteral("--json"))) {
        out << QJsonDocument(report->toJson()).toJson(QJsonDocument::Indented);
    } else {
        for (const auto &u : report->untagged)
            out << u.file << ": not tagged: " << u.reason << "\n";
        if (report->byEvents) {
            out << "paired with the vehicle's photo events: the camera's clock is " << report->offsetSeconds << " s off the vehicle's\n";
            for (int64_t sequence : report->missing)
                out << "photo " << sequence << " of the vehicle: no photo in the folder\n";
        }
        out << report->tagged.size() << " of " << report->photos << " photos tagged (offset " << report->offsetSeconds << " s); copies, "
            << geotag::kGeoTxtName << " and " << geotag::kCsvName << " in " << options.outFolder << "\n";
    }
    return report->untagged.empty() ? AllTagged : SomeUntagged;
}

// coverage's exit status, like geotag's: 0 no hole, 2 holes (listed), 1 bad usage or input.
enum CoverageExit { NoHole = 0, CoverageFailed = 1, Holes = 2 };

bool readNumber(const Args &a, const char *option, double low, double high, double *value, QTextStream &err)
{
    const QString name = QLatin1String(option);
    if (!a.options.contains(name))
        return true;
    bool ok = false;
    const double v = a.options.value(name).toDouble(&ok);
    if (!ok || !std::isfinite(v) || v < low || v > high) {
        err << "sortie-log: " << name << " takes a number from " << low << " to " << high << ", not \"" << a.options.value(name) << "\"\n";
        return false;
    }
    *value = v;
    return true;
}

int coveragePhotos(const QStringList &in, QTextStream &out, QTextStream &err)
{
    const auto a = parse(in, {QStringLiteral("--track"), QStringLiteral("--camera"), QStringLiteral("--out"), QStringLiteral("--offset"),
                              QStringLiteral("--vehicle"), QStringLiteral("--ground-amsl"), QStringLiteral("--min-images"), QStringLiteral("--cell"),
                              QStringLiteral("--refly"), QStringLiteral("--dem")},
                         {QStringLiteral("--json"), QStringLiteral("--by-time")}, err);
    if (!a)
        return CoverageFailed;
    if (a->positional.size() != 1) {
        err << "sortie-log: coverage takes one photo folder (PHOTO_DIR), " << a->positional.size() << " given\n";
        return CoverageFailed;
    }
    for (const char *required : {"--track", "--camera", "--out"}) {
        if (!a->options.contains(QLatin1String(required))) {
            err << "sortie-log: coverage needs " << required << "\n";
            return CoverageFailed;
        }
    }
    coverage::CoverageOptions options;
    const QString cameraName = a->options.value(QStringLiteral("--camera"));
    const auto camera = mission::builtInCamera(cameraName);
    if (!camera) {
        err << "sortie-log: no camera \"" << cameraName << "\"; the cameras Sortie knows:\n";
        for (const mission::Camera &c : mission::builtInCameras())
            err << "  " << c.name << "\n";
        return CoverageFailed;
    }
    options.camera = *camera;
    geotag::MatchOptions match;
    double minImages = options.minImages, ground = 0;
    if (!readOffset(*a, &match, err) || !readNumber(*a, "--cell", 0.01, 100, &options.cellMeters, err)
        || !readNumber(*a, "--min-images", 1, 1000, &minImages, err) || !readNumber(*a, "--ground-amsl", -500, 9000, &ground, err))
        return CoverageFailed;
    options.minImages = int(minImages);
    coverage::ShotOptions shotOptions;
    if (a->options.contains(QStringLiteral("--ground-amsl")))
        shotOptions.groundAmsl = ground;
    std::unique_ptr<terrain::ElevationSource> dem;
    if (a->options.contains(QStringLiteral("--dem"))) {
        if (shotOptions.groundAmsl) {
            err << "sortie-log: --dem and --ground-amsl both say where the ground is: give one\n";
            return CoverageFailed;
        }
        QString demError;
        dem = raster::openDem(a->options.value(QStringLiteral("--dem")), &demError);
        if (!dem) {
            err << "sortie-log: " << demError << "\n";
            return CoverageFailed;
        }
        shotOptions.groundAmslAt = [&dem](double latitude, double longitude) -> std::optional<double> {
            const terrain::ElevationSample s = dem->sample({latitude, longitude});
            return s.hasValue() ? std::optional<double>(s.ground) : std::nullopt;
        };
    }

    const auto track = trackOf(*a, err);
    if (!track)
        return CoverageFailed;
    QString error;
    const auto folder = geotag::readPhotoFolder(a->positional.first(), &error);
    if (!folder) {
        err << "sortie-log: " << error << "\n";
        return CoverageFailed;
    }
    const geotag::GeotagReport matched = geotag::matchPhotos(folder->photos, *track, match);
    coverage::CoverageRaster raster;
    auto report = coverage::computeCoverage(coverage::shotsFromPhotos(matched.tagged, *track, shotOptions, match), options, &raster, &error);
    if (!report) {
        // Why: the photos the track could not place, each with its reason, then what that left.
        for (const auto &u : folder->unreadable)
            err << u.file << ": not placed: " << u.reason << "\n";
        for (const auto &u : matched.untagged)
            err << u.file << ": not placed: " << u.reason << "\n";
        err << "sortie-log: " << error << "\n";
        return CoverageFailed;
    }
    // Every photo of the folder is counted, and the ones not on the track or not read named first.
    report->photos = folder->files;
    std::vector<coverage::Unplaced> unplaced;
    for (const auto &u : folder->unreadable)
        unplaced.push_back({u.file, u.reason});
    for (const auto &u : matched.untagged)
        unplaced.push_back({u.file, u.reason});
    report->unplaced.insert(report->unplaced.begin(), unplaced.begin(), unplaced.end());
    const QString rasterPath = a->options.value(QStringLiteral("--out"));
    if (!coverage::writeCoverageGeoTiff(raster, rasterPath, &error)) {
        err << "sortie-log: " << error << "\n";
        return CoverageFailed;
    }
    // The route that re-flies the holes: the survey's camera, height, overlap and legs.
    QJsonValue refly;
    QString reflyText;
    if (a->options.contains(QStringLiteral("--refly"))) {
        const QString reflyPath = a->options.value(QStringLiteral("--refly"));
        if (report->holes.empty()) {
            reflyText = QStringLiteral("no hole: nothing to re-fly, %1 not written\n").arg(reflyPath);
        } else {
            const coverage::ReflyOptions r = coverage::reflyOptionsFor(*report, options.camera);
            QStringList notes;
            const auto route = coverage::reflyRoute(report->holes, r, &notes);
            for (const QString &n : notes)
                err << "sortie-log: " << n << "\n";
            if (!route) {
                err << "sortie-log: no hole could be planned as an area scan; " << reflyPath << " not written\n";
                return CoverageFailed;
            }
            mission::Mission mission;
            mission.name = QFileInfo(reflyPath).completeBaseName();
            mission.routes.push_back(*route);
            const auto saved = mission::formats::saveMission(mission, reflyPath);
            if (!saved) {
                err << "sortie-log: " << saved.error().toString() << "\n";
                return CoverageFailed;
            }
            for (const QString &n : *saved)
                err << "sortie-log: " << n << "\n";
            refly = QJsonObject{{QStringLiteral("file"), reflyPath}, {QStringLiteral("scans"), int(route->segments.size())},
                                {QStringLiteral("notes"), QJsonArray::fromStringList(notes)}};
            reflyText = QStringLiteral("re-fly route of %1 area scan(s) at %2 m, %3/%4 %, written to %5\n")
                            .arg(route->segments.size()).arg(r.heightAboveGround).arg(r.frontOverlapPercent).arg(r.sideOverlapPercent).arg(reflyPath);
        }
    }
    if (a->flags.contains(QStringLiteral("--json"))) {
        QJsonObject json = report->toJson();
        json.insert(QStringLiteral("refly"), refly);
        json.insert(QStringLiteral("camera"), options.camera.name);
        json.insert(QStringLiteral("ground"), dem                     ? QStringLiteral("the DEM %1 under each photo").arg(dem->name())
                                              : shotOptions.groundAmsl ? QStringLiteral("flat at %1 m AMSL").arg(*shotOptions.groundAmsl)
                                                                       : QStringLiteral("flat at the take-off point"));
        json.insert(QStringLiteral("raster"), rasterPath);
        out << QJsonDocument(json).toJson(QJsonDocument::Indented);
    } else {
        for (const auto &u : report->unplaced)
            out << u.file << ": not placed: " << u.reason << "\n";
        out << report->placed << " of " << report->photos << " photos placed; " << std::lround(report->coveredFraction * 100) << " % of "
            << std::lround(report->areaSquareMeters) << " m² seen by at least " << report->minImages << " images";
        if (report->forwardOverlap && report->forwardOverlap->count)
            out << "; forward overlap " << std::lround(report->forwardOverlap->p50) << " %";
        if (report->sideOverlap && report->sideOverlap->count)
            out << ", side " << std::lround(report->sideOverlap->p50) << " %";
        if (report->gsdCm && report->gsdCm->count)
            out << "; " << QString::number(report->gsdCm->p50, 'f', 2) << " cm per pixel";
        out << "\n";
        for (const auto &h : report->holes)
            out << "hole of " << std::lround(h.areaSquareMeters) << " m² at " << QString::number(h.centreLatitude, 'f', 6) << ", "
                << QString::number(h.centreLongitude, 'f', 6) << "\n";
        out << "images per cell in " << rasterPath << " (" << report->crs << ", " << report->cellMeters << " m)\n" << reflyText;
    }
    return report->holes.empty() ? NoHole : Holes;
}

int signalPipe[2] = {-1, -1};

void onSignal(int)
{
    const char c = 1;
    [[maybe_unused]] const auto n = ::write(signalPipe[1], &c, 1);
}

int record(QCoreApplication &app, const QStringList &in, QTextStream &out, QTextStream &err)
{
    const auto a = parse(in, {QStringLiteral("--server"), QStringLiteral("--user"), QStringLiteral("--password-file"),
                              QStringLiteral("--seconds"), QStringLiteral("--max-size"), QStringLiteral("--server-pin")},
                         {QStringLiteral("--allow-cleartext")}, err);
    if (!a || a->positional.size() != 1 || !a->options.contains(QStringLiteral("--server")) || !a->options.contains(QStringLiteral("--user")))
        return (err << kUsage, Usage);
    flightlog::ServerRecording::Options options;
    options.server = a->options.value(QStringLiteral("--server"));
    options.user = a->options.value(QStringLiteral("--user"));
    options.path = a->positional.first();
    options.limits.maxFolderBytes = 0; // a file the operator named: never prune its folder
    options.allowCleartext = a->flags.contains(QStringLiteral("--allow-cleartext"));
    if (a->options.contains(QStringLiteral("--server-pin"))) {
        const auto pin = tls::pinFromArgument(QStringLiteral("--server-pin"), a->options.value(QStringLiteral("--server-pin")));
        if (pin.index() == 1)
            return (err << "sortie-log: " << std::get<1>(pin) << "\n", Usage);
        options.serverPin = std::get<0>(pin);
    }
    // Certificates trusted on first use are remembered here, as ssh keeps known hosts.
    QSettings trust;
    options.settings = &trust;
    bool ok = true;
    options.seconds = a->options.value(QStringLiteral("--seconds"), QStringLiteral("0")).toInt(&ok);
    if (!ok || options.seconds < 0)
        return (err << "sortie-log: --seconds takes a whole number of seconds\n", Usage);
    if (a->options.contains(QStringLiteral("--max-size"))) {
        const qint64 mb = a->options.value(QStringLiteral("--max-size")).toLongLong(&ok);
        if (!ok || mb <= 0)
            return (err << "sortie-log: --max-size takes a number of MB\n", Usage);
        options.limits.maxFileBytes = mb << 20;
    }
    if (a->options.contains(QStringLiteral("--password-file"))) {
        QFile file(a->options.value(QStringLiteral("--password-file")));
        if (!file.open(QIODevice::ReadOnly)) {
            err << "sortie-log: " << file.fileName() << ": " << file.errorString() << "\n";
            return Failed;
        }
        options.password = QString::fromUtf8(file.readLine()).trimmed();
    } else {
        options.password = qEnvironmentVariable("SORTIE_PASSWORD");
    }

    flightlog::ServerRecording recording(options);
    // SIGINT and SIGTERM close the log cleanly: the handler only writes a byte, the loop does the rest.
    ::socketpair(AF_UNIX, SOCK_STREAM, 0, signalPipe);
    QSocketNotifier notifier(signalPipe[0], QSocketNotifier::Read);
    QObject::connect(&notifier, &QSocketNotifier::activated, &recording, [&] {
        char c;
        [[maybe_unused]] const auto n = ::read(signalPipe[0], &c, 1);
        recording.stop();
    });
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    QObject::connect(&recording, &flightlog::ServerRecording::message, &app, [&out](const QString &line) {
        out << line << Qt::endl;
    });
    int code = Ok;
    QObject::connect(&recording, &flightlog::ServerRecording::finished, &app, [&](int exitCode, const QString &error) {
        if (!error.isEmpty())
            err << "sortie-log: " << error << Qt::endl;
        code = exitCode;
        app.quit();
    }, Qt::QueuedConnection);
    QString error;
    if (!recording.start(&error)) {
        err << "sortie-log: " << error << "\n";
        return Failed;
    }
    app.exec();
    return code;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("Sortie"));
    QCoreApplication::setApplicationName(QStringLiteral("sortie-log"));
    QLoggingCategory::setFilterRules(QStringLiteral("sortie.*.info=false\nsortie.*.debug=false"));
    QTextStream out(stdout), err(stderr);
    QStringList args = app.arguments().mid(1);
    if (args.isEmpty() || args.first() == QLatin1String("--help") || args.first() == QLatin1String("-h")) {
        (args.isEmpty() ? err : out) << kUsage;
        return args.isEmpty() ? Usage : Ok;
    }
    const QString command = args.takeFirst();
    if (command == QLatin1String("record"))
        return record(app, args, out, err);
    if (command == QLatin1String("info"))
        return info(args, out, err);
    if (command == QLatin1String("export"))
        return exportTracks(args, out, err);
    if (command == QLatin1String("compare"))
        return compare(args, out, err);
    if (command == QLatin1String("fit"))
        return fit(args, out, err);
    if (command == QLatin1String("geotag"))
        return geotagPhotos(args, out, err);
    if (command == QLatin1String("coverage"))
        return coveragePhotos(args, out, err);
    err << "sortie-log: unknown command \"" << command << "\"\n\n" << kUsage;
    return Usage;
}
