#pragma once

#include "WpmlFormat.h"

#include <memory>

// The geoid a WPML read or write converts ellipsoidal heights with: the caller's, else the grid
// opened on first use (once per file), so a file with no ellipsoidal height never needs the grid.
namespace sortie::mission::formats::wpml {

class GeoidAccess
{
public:
    explicit GeoidAccess(WpmlGeoid source);
    ~GeoidAccess();
    // The geoid, or why there is none (the grid named), as a refusal of `what`.
    Result<const datum::Egm96Geoid *> get(const QString &what);

private:
    WpmlGeoid m_source;
    std::unique_ptr<datum::Egm96Geoid> m_owned;
};

} // namespace sortie::mission::formats::wpml
