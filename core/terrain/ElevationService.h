#pragma once

#include "ElevationSource.h"

#include <QObject>
#include <QPointer>
#include <QStringList>

#include <optional>
#include <vector>

namespace sortie::terrain {

// The sources of ground elevation in the operator's order of preference. A point's ground comes
// from the first source that has a value there, labelled with that source; where none has one it is
// NoData (or Pending while an asynchronous source that might have it is still asking). With no
// source at all, everything is NoData from "none". Sources are not owned.
class ElevationService : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QStringList sourceNames READ sourceNames NOTIFY changed)

public:
    explicit ElevationService(QObject *parent = nullptr);

    void setSources(const std::vector<ElevationSource *> &ordered);
    int sourceCount() const { return int(m_sources.size()); }
    ElevationSource *source(int index) const;
    QString sourceName(int index) const;  // "none" for -1
    QStringList sourceNames() const;      // in order; {"none"} without sources
    QString triedText() const;            // "SRTM tiles (/dem), UgCS server" for messages

    GroundSample sample(const GeoPoint &point);
    // The ground's height, nullopt where no source has it (yet): what RouteEditor's ground lookup takes.
    std::optional<double> groundAt(const GeoPoint &point)
    {
        const GroundSample g = sample(point);
        return g.hasValue() ? std::optional<double>(g.ground) : std::nullopt;
    }
    void samplePath(const SampledPath &path, std::vector<GroundSample> &out);

signals:
    // The order changed or a source got new data: recompute what depends on the ground.
    void changed();

private:
    std::vector<QPointer<ElevationSource>> m_sources;
    std::vector<ElevationSample> m_scratch;
};

} // namespace sortie::terrain
