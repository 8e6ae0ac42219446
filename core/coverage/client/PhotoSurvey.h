#pragma once

#include "CoverageMap.h"
#include "Geotagger.h"
#include "Route.h"

#include <QFutureWatcher>
#include <QObject>
#include <QPointer>
#include <QStringList>

#include <functional>
#include <optional>

namespace sortie::flightlog {
class ReplayController;
}

namespace sortie::coverage {

// The replay's "Photos…" step (issue 34): a folder of the flight's photos placed on the replayed
// log's track of one vehicle, as `sortie-log geotag` places them, and the ground they cover judged
// as `sortie-log coverage` judges it; then, when asked, the geotagged copies written. The work runs
// on a worker thread (the log is opened there, the photos read there); the view reads the outcome
// as words, and the photo layer reads the positions and holes. One job at a time: a match or a
// write asked while one runs is not started (the view's buttons wait for `busy`).
class PhotoSurvey : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QString photoFolder READ photoFolder WRITE setPhotoFolder NOTIFY settingsChanged)
    Q_PROPERTY(QString camera READ camera WRITE setCamera NOTIFY settingsChanged)
    Q_PROPERTY(QStringList cameras READ cameras CONSTANT)
    Q_PROPERTY(double offsetSeconds READ offsetSeconds WRITE setOffsetSeconds NOTIFY settingsChanged)
    Q_PROPERTY(bool busy READ isBusy NOTIFY busyChanged)
    Q_PROPERTY(bool matched READ isMatched NOTIFY resultChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY resultChanged)
    Q_PROPERTY(QString summary READ summary NOTIFY resultChanged)
    Q_PROPERTY(QString coverageSummary READ coverageSummary NOTIFY resultChanged)
    Q_PROPERTY(QStringList unplaced READ unplaced NOTIFY resultChanged)
    Q_PROPERTY(QStringList holeList READ holeList NOTIFY resultChanged)
    Q_PROPERTY(int placedCount READ placedCount NOTIFY resultChanged)
    Q_PROPERTY(int holeCount READ holeCount NOTIFY resultChanged)
    Q_PROPERTY(QString written READ written NOTIFY writtenChanged)
    Q_PROPERTY(bool canRefly READ canRefly NOTIFY resultChanged)
    Q_PROPERTY(QString reflyText READ reflyText NOTIFY reflyTextChanged)

public:
    explicit PhotoSurvey(flightlog::ReplayController *replay, QObject *parent = nullptr);
    ~PhotoSurvey() override;

    QString photoFolder() const { return m_folder; }
    void setPhotoFolder(const QString &folderOrUrl); // a path or a file: URL
    QString camera() const { return m_camera; }
    void setCamera(const QString &name);
    QStringList cameras() const;
    double offsetSeconds() const { return m_offsetSeconds; }
    void setOffsetSeconds(double seconds);

    bool isBusy() const { return m_busy; }
    bool isMatched() const { return m_placed.has_value(); }
    QString errorString() const { return m_error; }
    QString summary() const;
    QString coverageSummary() const;
    QStringList unplaced() const;
    QStringList holeList() const;
    int placedCount() const { return m_placed ? int(m_placed->tagged.size()) : 0; }
    int holeCount() const { return m_coverage ? int(m_coverage->holes.size()) : 0; }
    QString written() const { return m_written; }
    bool canRefly() const { return holeCount() > 0 && bool(m_openRoute); }
    QString reflyText() const { return m_reflyText; }

    // Where a route made here goes: the mission editor's document (the graph hands it in, so this
    // room reaches no client). Without one, nothing is re-flown.
    using RouteOpener = std::function<void(mission::Route route, const QString &undoText)>;
    void setRouteOpener(RouteOpener opener) { m_openRoute = std::move(opener); emit resultChanged(); }

    // For the photo layer: where each placed photo was taken, and the holes.
    const std::vector<geotag::TaggedPhoto> &placedPhotos() const;
    const std::vector<Hole> &holes() const;

    // Places the folder's photos on the track of the log's vehicle `vehicleIndex` (the replay's
    // order) and judges their coverage. The outcome arrives with resultChanged.
    Q_INVOKABLE void match(int vehicleIndex);
    // Writes the placed photos' geotagged copies, geo.txt and geotags.csv into a folder (a path or
    // a file: URL); `written` says what was written, or why not.
    Q_INVOKABLE void writeCopies(const QString &folderOrUrl);
    // Forgets the outcome (the replay closed, another log opened).
    Q_INVOKABLE void clear();
    // "Re-fly the gaps": a route of an area scan per hole (reflyRoute: the camera, the photos'
    // median height, the measured overlap, the legs' bearing) opened in the mission editor, where
    // every rule checks it before it can be uploaded. `reflyText` says what was opened, or why not.
    Q_INVOKABLE void reflyGaps();

    struct Outcome
    {
        QString error;
        QString vehicle;
        int files = 0;
        std::optional<geotag::GeotagReport> placed;
        std::optional<CoverageReport> coverage;
        QString coverageError;
    };

signals:
    void settingsChanged();
    void busyChanged();
    void resultChanged();
    void writtenChanged();
    void reflyTextChanged();

private:
    void setBusy(bool busy);
    void finished();

    QPointer<flightlog::ReplayController> m_replay;
    QString m_folder, m_camera;
    double m_offsetSeconds = 0;
    bool m_busy = false;
    QString m_error, m_vehicle, m_written;
    QString m_matchedLog; // the log a running match reads
    int m_files = 0;
    std::optional<geotag::GeotagReport> m_placed;
    std::optional<CoverageReport> m_coverage;
    QString m_coverageError;
    RouteOpener m_openRoute;
    QString m_reflyText;
    QFutureWatcher<Outcome> m_matching;
    QFutureWatcher<QString> m_writing;
};

} // namespace sortie::coverage
