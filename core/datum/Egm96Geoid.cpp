#include "Egm96Geoid.h"

#include <QFileInfo>

#include <proj.h>

#include <cmath>
#include <QCoreApplication>

namespace sortie::datum {

QString Egm96Geoid::defaultGridPath()
{
    return QStringLiteral("/usr/share/proj/egm96_15.gtx");
}

std::unique_ptr<Egm96Geoid> Egm96Geoid::open(const QString &gridPath, QString *error)
{
    // Checked first so the reason names the file rather than PROJ's generic grid error.
    const QFileInfo file(gridPath);
    if (!file.isFile() || !file.isReadable()) {
        *error = QCoreApplication::translate("Egm96Geoid", "the EGM96 geoid grid %1 is missing (Debian: install proj-data): ellipsoidal heights cannot be converted to AMSL").arg(gridPath);
        return nullptr;
    }
    PJ_CONTEXT *context = proj_context_create();
    proj_log_level(context, PJ_LOG_NONE);
    proj_context_set_enable_network(context, 0);  // the grid is local; never download one
    // A pipeline in degrees: vgridshift works in radians, longitude first. multiplier -1: the
    // forward direction subtracts the grid's N from the ellipsoidal height.
    const QByteArray definition = QStringLiteral("+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad "
                                                 "+step +proj=vgridshift +grids=%1 +multiplier=-1 "
                                                 "+step +proj=unitconvert +xy_in=rad +xy_out=deg")
                                      .arg(file.absoluteFilePath())
                                      .toUtf8();
    PJ *shift = proj_create(context, definition.constData());
    if (!shift) {
        *error = QCoreApplication::translate("Egm96Geoid", "the EGM96 geoid grid %1 cannot be used: %2")
                     .arg(gridPath, QString::fromUtf8(proj_context_errno_string(context, proj_context_errno(context))));
        proj_context_destroy(context);
        return nullptr;
    }
    return std::unique_ptr<Egm96Geoid>(new Egm96Geoid(context, shift, gridPath));
}

Egm96Geoid::Egm96Geoid(pj_ctx *context, PJconsts *shift, QString gridPath)
    : m_context(context), m_shift(shift), m_gridPath(std::move(gridPath))
{
}

Egm96Geoid::~Egm96Geoid()
{
    proj_destroy(m_shift);
    proj_context_destroy(m_context);
}

std::optional<double> Egm96Geoid::amslFromEllipsoidal(double latitudeDeg, double longitudeDeg, double ellipsoidal) const
{
    if (!std::isfinite(latitudeDeg) || !std::isfinite(longitudeDeg) || !std::isfinite(ellipsoidal)
        || std::abs(latitudeDeg) > 90.0 || std::abs(longitudeDeg) > 360.0)
        return std::nullopt;
    proj_errno_reset(m_shift);
    const PJ_COORD out = proj_trans(m_shift, PJ_FWD, proj_coord(longitudeDeg, latitudeDeg, ellipsoidal, 0.0));
    if (proj_errno(m_shift) != 0 || !std::isfinite(out.xyz.z) || out.xyz.z == HUGE_VAL)
        return std::nullopt;
    return out.xyz.z;
}

std::optional<double> Egm96Geoid::undulation(double latitudeDeg, double longitudeDeg) const
{
    const auto amsl = amslFromEllipsoidal(latitudeDeg, longitudeDeg, 0.0);
    return amsl ? std::optional<double>(-*amsl) : std::nullopt;
}

std::optional<double> Egm96Geoid::ellipsoidalFromAmsl(double latitudeDeg, double longitudeDeg, double amsl) const
{
    const auto n = undulation(latitudeDeg, longitudeDeg);
    return n ? std::optional<double>(amsl + *n) : std::nullopt;
}

} // namespace sortie::datum
