#pragma once

#include "ElevationSource.h"

namespace sortie::terrain {

// The honest source when nothing else is configured: no terrain data anywhere. Never 0 m.
class NoElevationSource : public ElevationSource
{
    Q_OBJECT

public:
    using ElevationSource::ElevationSource;
    QString name() const override { return QStringLiteral("none"); }
    ElevationSample sample(const GeoPoint &) override { return ElevationSample::noData(); }
};

} // namespace sortie::terrain
