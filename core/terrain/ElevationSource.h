#pragma once

#include "ElevationSample.h"
#include "PathSampling.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <vector>

namespace sortie::terrain {

// A contiguous run of samples over which a source had no data (distances from the path's start).
struct NoDataStretch
{
    int leg = 0;
    double fromDistance = 0.0;
    double toDistance = 0.0;
    bool operator==(const NoDataStretch &) const = default;
};

// Where the ground is, from one kind of data. Synchronous sources (tiles on disk) answer at once;
// an asynchronous one (the UgCS server) answers Pending, asks in the background and emits
// dataChanged() when answers arrive, after which asking again gives them. Heights are metres above
// the EGM96 geoid ("above mean sea level"); a place without data is NoData, never 0 m.
class ElevationSource : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;

    // Short, for the operator: "SRTM tiles (/data/dem)", "UgCS server", "none".
    virtual QString name() const = 0;
    virtual ElevationSample sample(const GeoPoint &point) = 0;
    // One sample per path.points[i]. The default asks sample() for each point; a remote source asks
    // for the whole path at once.
    virtual void samplePath(const SampledPath &path, std::vector<ElevationSample> &out);
    // Files found unusable while answering (each naming its file): their places gave NoData.
    virtual QStringList problems() const { return {}; }

    // The stretches of a sampled path where `samples` have no data (Pending is not "no data").
    static std::vector<NoDataStretch> noDataStretches(const SampledPath &path, const std::vector<ElevationSample> &samples);

signals:
    // Answers arrived (or cached data was dropped): anything sampled before may differ now.
    void dataChanged();
};

} // namespace sortie::terrain
