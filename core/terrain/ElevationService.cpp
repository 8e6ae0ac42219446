#include "ElevationService.h"

namespace sortie::terrain {

ElevationService::ElevationService(QObject *parent) : QObject(parent) {}

void ElevationService::setSources(const std::vector<ElevationSource *> &ordered)
{
    for (const auto &s : m_sources)
        if (s)
            disconnect(s, nullptr, this, nullptr);
    m_sources.assign(ordered.begin(), ordered.end());
    for (const auto &s : m_sources)
        connect(s, &ElevationSource::dataChanged, this, &ElevationService::changed);
    emit changed();
}

ElevationSource *ElevationService::source(int index) const
{
    return index >= 0 && index < int(m_sources.size()) ? m_sources[size_t(index)].data() : nullptr;
}

QString ElevationService::sourceName(int index) const
{
    const ElevationSource *s = source(index);
    return s ? s->name() : QStringLiteral("none");
}

QStringList ElevationService::sourceNames() const
{
    QStringList names;
    for (const auto &s : m_sources)
        if (s)
            names << s->name();
    if (names.isEmpty())
        names << QStringLiteral("none");
    return names;
}

QString ElevationService::triedText() const
{
    return sourceNames().join(QStringLiteral(", "));
}

GroundSample ElevationService::sample(const GeoPoint &point)
{
    GroundSample out;
    for (size_t i = 0; i < m_sources.size(); ++i) {
        if (!m_sources[i])
            continue;
        const ElevationSample s = m_sources[i]->sample(point);
        if (s.hasValue()) {
            out.ground = s.ground;
            out.status = SampleStatus::Value;
            out.source = int(i);
            return out;
        }
        if (s.status == SampleStatus::Pending)
            out.status = SampleStatus::Pending;
    }
    return out;
}

void ElevationService::samplePath(const SampledPath &path, std::vector<GroundSample> &out)
{
    const size_t n = path.points.size();
    out.assign(n, GroundSample{});
    size_t missing = n;
    for (size_t i = 0; i < m_sources.size() && missing > 0; ++i) {
        if (!m_sources[i])
            continue;
        m_sources[i]->samplePath(path, m_scratch);
        missing = 0;
        for (size_t k = 0; k < n; ++k) {
            GroundSample &o = out[k];
            if (o.hasValue())
                continue;
            const ElevationSample &s = m_scratch[k];
            if (s.hasValue()) {
                o.ground = s.ground;
                o.status = SampleStatus::Value;
                o.source = int(i);
                continue;
            }
            if (s.status == SampleStatus::Pending)
                o.status = SampleStatus::Pending;
            ++missing;
        }
    }
}

} // namespace sortie::terrain
