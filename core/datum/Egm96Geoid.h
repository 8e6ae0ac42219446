#pragma once

#include <QString>

#include <memory>
#include <optional>

// PROJ's types, kept out of every includer.
struct pj_ctx;
struct PJconsts;

namespace sortie::datum {

// The EGM96 geoid: converts WGS-84 ellipsoidal heights (what GNSS receivers and DJI's WGS84 height
// mode give) into heights above mean sea level (EGM96, what Sortie's AMSL altitudes are) and back,
// through PROJ's vertical grid shift over the 15' EGM96 grid (egm96_15.gtx, Debian's proj-data).
// One object per thread: a PROJ context is not shared between threads.
class Egm96Geoid
{
public:
    // Where Debian installs the grid.
    static QString defaultGridPath();
    // Opens the grid; null, with the reason naming the grid file, when it is missing or unreadable.
    static std::unique_ptr<Egm96Geoid> open(const QString &gridPath, QString *error);
    ~Egm96Geoid();
    Egm96Geoid(const Egm96Geoid &) = delete;
    Egm96Geoid &operator=(const Egm96Geoid &) = delete;

    // N, metres: how far the geoid lies above the ellipsoid here (h = H + N). Nullopt outside the
    // grid or for coordinates that are not degrees.
    std::optional<double> undulation(double latitudeDeg, double longitudeDeg) const;
    std::optional<double> amslFromEllipsoidal(double latitudeDeg, double longitudeDeg, double ellipsoidal) const;
    std::optional<double> ellipsoidalFromAmsl(double latitudeDeg, double longitudeDeg, double amsl) const;
    QString gridPath() const { return m_gridPath; }

private:
    Egm96Geoid(pj_ctx *context, PJconsts *shift, QString gridPath);
    pj_ctx *m_context;
    PJconsts *m_shift;  // ellipsoidal to orthometric: H = h - N
    QString m_gridPath;
};

} // namespace sortie::datum
