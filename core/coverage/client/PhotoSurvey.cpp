#include "PhotoSurvey.h"

#include "Camera.h"
#include "FlightLog.h"
#include "PhotoShots.h"
#include "ReflyRoute.h"
#include "ReplayController.h"
#include "Track.h"

#include <QDir>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QUrl>
#include <QtConcurrent/QtConcurrentRun>

#include <cmath>

Q_LOGGING_CATEGORY(lcPhotoSurvey, "sortie.coverage.survey")

namespace sortie::coverage {
namespace {

QString localPath(const QString &pathOrUrl)
{
    const QUrl url(pathOrUrl);
    return url.isLocalFile() ? url.toLocalFile() : pathOrUrl;
}

// On the worker: everything `sortie-log coverage` does but write, for one vehicle of one log.
PhotoSurvey::Outcome survey(const QString &logPath, int vehicle, const QString &folder, const QString &cameraName, double offsetSeconds)
{
    PhotoSurvey::Outcome o;
    QString error;
    const auto log = flightlog::FlightLog::open(logPath, &error);
    if (!log) {
        o.error = error;
        return o;
    }
    if (vehicle < 0 || size_t(vehicle) >= log->vehicles().size()) {
        o.error = PhotoSurvey::tr("Choose the vehicle that took the photos.");
        return o;
    }
    o.vehicle = log->vehicles()[size_t(vehicle)].name();
    const auto track = geotag::flightLogTrack(*log, vehicle, &error);
    if (!track) {
        o.error = error;
        return o;
    }
    const auto photos = geotag::readPhotoFolder(folder, &error);
    if (!photos) {
        o.error = error;
        return o;
    }
    geotag::MatchOptions match;
    match.offsetMs = std::llround(offsetSeconds * 1000);
    geotag::GeotagReport placed = geotag::matchPhotos(photos->photos, *track, match);
    placed.photos = photos->files;
    placed.untagged.insert(placed.untagged.end(), photos->unreadable.begin(), photos->unreadable.end());
    o.files = photos->files;
    if (const auto camera = mission::builtInCamera(cameraName)) {
        CoverageOptions options;
        options.camera = *camera;
        o.coverage = computeCoverage(shotsFromPhotos(placed.tagged, *track, {}, match), options, nullptr, &o.coverageError);
    } else {
        o.coverageError = PhotoSurvey::tr("choose the camera that took them");
    }
    o.placed = std::move(placed);
    return o;
}

QString figure(const std::optional<Spread> &s, int decimals, const QString &unit)
{
    if (!s || s->count == 0)
        return PhotoSurvey::tr("not measured");
    return QStringLiteral("%1 %2").arg(s->p50, 0, 'f', decimals).arg(unit);
}

} // namespace

PhotoSurvey::PhotoSurvey(flightlog::ReplayController *replay, QObject *parent)
    : QObject(parent)
    , m_replay(replay)
    , m_camera(mission::builtInCameras().front().name)
{
    connect(&m_matching, &QFutureWatcher<Outcome>::finished, this, &PhotoSurvey::finished);
    connect(&m_writing, &QFutureWatcher<QString>::finished, this, [this] {
        m_written = m_writing.result();
        setBusy(false);
        emit writtenChanged();
    });
    if (m_replay)
        connect(m_replay, &flightlog::ReplayController::loadedChanged, this, &PhotoSurvey::clear); // another log: another flight
}

PhotoSurvey::~PhotoSurvey()
{
    m_matching.waitForFinished();
    m_writing.waitForFinished();
}

void PhotoSurvey::setPhotoFolder(const QString &folderOrUrl)
{
    const QString folder = localPath(folderOrUrl);
    if (folder == m_folder)
        return;
    m_folder = folder;
    emit settingsChanged();
}

void PhotoSurvey::setCamera(const QString &name)
{
    if (name == m_camera)
        return;
    m_camera = name;
    emit settingsChanged();
}

QStringList PhotoSurvey::cameras() const
{
    QStringList names;
    for (const mission::Camera &c : mission::builtInCameras())
        names << c.name;
    return names;
}

void PhotoSurvey::setOffsetSeconds(double seconds)
{
    if (!std::isfinite(seconds) || seconds == m_offsetSeconds)
        return;
    m_offsetSeconds = seconds;
    emit settingsChanged();
}

void PhotoSurvey::setBusy(bool busy)
{
    if (busy == m_busy)
        return;
    m_busy = busy;
    emit busyChanged();
}

void PhotoSurvey::match(int vehicleIndex)
{
    if (m_busy)
        return;
    const QString log = m_replay ? m_replay->path() : QString();
    m_placed.reset();
    m_coverage.reset();
    m_coverageError.clear();
    m_written.clear();
    m_reflyText.clear();
    emit reflyTextChanged();
    if (log.isEmpty() || m_folder.isEmpty()) {
        m_error = log.isEmpty() ? tr("Open the flight's log first.") : tr("Choose the folder of the flight's photos.");
        emit resultChanged();
        emit writtenChanged();
        return;
    }
    m_error.clear();
    emit resultChanged();
    emit writtenChanged();
    setBusy(true);
    qCInfo(lcPhotoSurvey).noquote() << "placing" << m_folder << "on" << log << "vehicle" << vehicleIndex;
    m_matchedLog = log;
    m_matching.setFuture(QtConcurrent::run(survey, log, vehicleIndex, m_folder, m_camera, m_offsetSeconds));
}

void PhotoSurvey::finished()
{
    Outcome o = m_matching.result();
    if (!m_replay || m_replay->path() != m_matchedLog) { // the log closed or changed meanwhile: not this flight's
        setBusy(false);
        clear();
        return;
    }
    m_error = o.error;
    m_vehicle = o.vehicle;
    m_files = o.files;
    m_placed = std::move(o.placed);
    m_coverage = std::move(o.coverage);
    m_coverageError = o.coverageError;
    setBusy(false);
    emit resultChanged();
}

void PhotoSurvey::writeCopies(const QString &folderOrUrl)
{
    if (m_busy)
        return;
    const QString out = localPath(folderOrUrl);
    if (!m_placed || m_placed->tagged.empty()) {
        m_written = tr("No photo is placed: nothing to write.");
        emit writtenChanged();
        return;
    }
    if (QFileInfo(out).canonicalFilePath() == QFileInfo(m_folder).canonicalFilePath()) {
        m_written = tr("%1 is the photos' own folder: the copies go elsewhere, the originals are never changed.").arg(out);
        emit writtenChanged();
        return;
    }
    setBusy(true);
    m_writing.setFuture(QtConcurrent::run([report = *m_placed, out]() mutable {
        QString error;
        if (!QDir().mkpath(out))
            return tr("%1: the folder cannot be made.").arg(out);
        const size_t untaggedBefore = report.untagged.size();
        if (!geotag::writeGeotagged(report, out, &error)) // a copy that fails moves to the untagged ones
            return error;
        QString text = tr("%n geotagged copies, geo.txt and geotags.csv written to %1.", nullptr, int(report.tagged.size())).arg(out);
        for (size_t i = untaggedBefore; i < report.untagged.size(); ++i)
            text += QLatin1Char(' ') + tr("%1 not written: %2.").arg(report.untagged[i].file, report.untagged[i].reason);
        return text;
    }));
}

void PhotoSurvey::clear()
{
    if (m_busy)
        return;
    m_placed.reset();
    m_coverage.reset();
    m_coverageError.clear();
    m_error.clear();
    m_written.clear();
    m_reflyText.clear();
    emit resultChanged();
    emit writtenChanged();
    emit reflyTextChanged();
}

void PhotoSurvey::reflyGaps()
{
    if (!m_coverage || m_coverage->holes.empty() || !m_openRoute)
        return;
    const auto camera = mission::builtInCamera(m_camera);
    if (!camera)
        return;
    const ReflyOptions options = reflyOptionsFor(*m_coverage, *camera);
    QStringList notes;
    auto route = reflyRoute(m_coverage->holes, options, &notes);
    if (!route) {
        m_reflyText = tr("No hole could be planned as an area scan: %1").arg(notes.join(QLatin1Char(' ')));
    } else {
        const int scans = int(route->segments.size());
        m_openRoute(std::move(*route), tr("Re-fly the gaps"));
        m_reflyText = tr("\"Re-fly the gaps\" is open in the mission editor: %n area scan(s) at %1 m, %2/%3 % overlap.", nullptr, scans)
                          .arg(options.heightAboveGround)
                          .arg(options.frontOverlapPercent)
                          .arg(options.sideOverlapPercent);
        if (!notes.isEmpty())
            m_reflyText += QLatin1Char(' ') + notes.join(QLatin1Char(' '));
    }
    emit reflyTextChanged();
}

QString PhotoSurvey::summary() const
{
    if (!m_placed)
        return {};
    if (m_placed->byEvents) {
        // Paired with the shutter as the vehicle reported it: the clock's offset was found, not given.
        QString text = tr("%1 of %n photos placed where %2 took them, paired with its photo events (camera clock %3 s off).", nullptr, m_files)
                           .arg(m_placed->tagged.size())
                           .arg(m_vehicle)
                           .arg(m_placed->offsetSeconds, 0, 'f', 1);
        if (!m_placed->missing.empty())
            text += QLatin1Char(' ') + tr("%n photo(s) the vehicle took are not in the folder.", nullptr, int(m_placed->missing.size()));
        return text;
    }
    return tr("%1 of %n photos placed on %2's track (camera clock %3 s).", nullptr, m_files)
        .arg(m_placed->tagged.size())
        .arg(m_vehicle)
        .arg(m_offsetSeconds, 0, 'f', 1);
}

QString PhotoSurvey::coverageSummary() const
{
    if (!m_placed)
        return {};
    if (!m_coverage)
        return tr("Coverage not judged: %1.").arg(m_coverageError);
    const CoverageReport &c = *m_coverage;
    return tr("%1 % of %2 m² seen by at least %3 images; forward overlap %4, side %5; %6 per pixel; %n hole(s).", nullptr, int(c.holes.size()))
        .arg(std::lround(c.coveredFraction * 100))
        .arg(std::lround(c.areaSquareMeters))
        .arg(c.minImages)
        .arg(figure(c.forwardOverlap, 0, QStringLiteral("%")), figure(c.sideOverlap, 0, QStringLiteral("%")), figure(c.gsdCm, 2, QStringLiteral("cm")));
}

QStringList PhotoSurvey::unplaced() const
{
    QStringList lines;
    if (m_placed)
        for (const geotag::UntaggedPhoto &u : m_placed->untagged)
            lines << tr("%1: %2").arg(u.file, u.reason);
    if (m_coverage)
        for (const Unplaced &u : m_coverage->unplaced)
            lines << tr("%1: %2").arg(u.file, u.reason);
    return lines;
}

QStringList PhotoSurvey::holeList() const
{
    QStringList lines;
    if (m_coverage)
        for (const Hole &h : m_coverage->holes)
            lines << tr("%1 m² at %2, %3").arg(std::lround(h.areaSquareMeters)).arg(h.centreLatitude, 0, 'f', 6).arg(h.centreLongitude, 0, 'f', 6);
    return lines;
}

const std::vector<geotag::TaggedPhoto> &PhotoSurvey::placedPhotos() const
{
    static const std::vector<geotag::TaggedPhoto> none;
    return m_placed ? m_placed->tagged : none;
}

const std::vector<Hole> &PhotoSurvey::holes() const
{
    static const std::vector<Hole> none;
    return m_coverage ? m_coverage->holes : none;
}

} // namespace sortie::coverage
