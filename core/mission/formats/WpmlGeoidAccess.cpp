#include "WpmlGeoidAccess.h"

#include "Egm96Geoid.h"

namespace sortie::mission::formats::wpml {

GeoidAccess::GeoidAccess(WpmlGeoid source) : m_source(std::move(source)) {}

GeoidAccess::~GeoidAccess() = default;

Result<const datum::Egm96Geoid *> GeoidAccess::get(const QString &what)
{
    if (m_source.geoid)
        return m_source.geoid;
    if (!m_owned) {
        QString error;
        m_owned = datum::Egm96Geoid::open(m_source.gridPath.isEmpty() ? datum::Egm96Geoid::defaultGridPath() : m_source.gridPath, &error);
        if (!m_owned)
            return MissionError{QStringLiteral("%1: %2").arg(what, error), {}, 0, 0, {}};
    }
    return static_cast<const datum::Egm96Geoid *>(m_owned.get());
}

} // namespace sortie::mission::formats::wpml
