#include "GdalDataset.h"

#include <QCoreApplication>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_priv.h>

#include <cpl_http.h>
#include <cpl_minixml.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <ogr_srs_api.h>

#include <cerrno>
#include <vector>

#include <mutex>

namespace sortie::raster {

void GdalDatasetCloser::operator()(GDALDataset *dataset) const
{
    GDALClose(GDALDataset::ToHandle(dataset));
}

QString lastGdalError(const QString &fallback)
{
    const char *message = CPLGetLastErrorMsg();
    return message && *message ? QString::fromUtf8(message) : fallback;
}

namespace {
const char kNoListing[] = "GDAL_DISABLE_READDIR_ON_OPEN";
}

FolderNotListed::FolderNotListed()
{
    if (const char *previous = CPLGetThreadLocalConfigOption(kNoListing, nullptr))
        m_previous = previous, m_hadPrevious = true;
    CPLSetThreadLocalConfigOption(kNoListing, "TRUE");
}

FolderNotListed::~FolderNotListed()
{
    CPLSetThreadLocalConfigOption(kNoListing, m_hadPrevious ? m_previous.constData() : nullptr);
}

namespace {

// The formats docs/rasters.md promises: GeoTIFF (COGs and Copernicus tiles are GeoTIFFs), SRTM .hgt,
// DTED, ESRI ASCII grid, ERDAS Imagine, ESRI .bil/.flt, USGS DEM, and for orthophotos PNG, JPEG and
// JPEG 2000 with their world files. VRT only under a .vrt name (allowedDrivers).
constexpr const char *kAllowedDrivers[] = {"GTiff", "SRTMHGT", "DTED", "AAIGrid", "HFA", "EHdr", "USGSDEM",
                                           "PNG", "JPEG", "JP2OpenJPEG"};
constexpr int kMaxVrtDepth = 4;               // a .vrt naming a .vrt naming a .vrt…
constexpr vsi_l_offset kMaxVrtBytes = 64 << 20;  // a mosaic of 100,000 tiles is ~30 MiB of XML

// GDAL's file systems that reach the network: every one answers "no such file" instead.
constexpr const char *kNetworkFileSystems[] = {
    "/vsicurl/", "/vsicurl_streaming/", "/vsis3/", "/vsis3_streaming/", "/vsigs/", "/vsigs_streaming/",
    "/vsiaz/", "/vsiaz_streaming/", "/vsiadls/", "/vsioss/", "/vsioss_streaming/", "/vsiswift/",
    "/vsiswift_streaming/", "/vsiwebhdfs/", "/vsihdfs/"};

void *refuseOpen(void *, const char *, const char *)
{
    errno = EACCES;
    return nullptr;
}

int refuseStat(void *, const char *, VSIStatBufL *, int)
{
    errno = EACCES;
    return -1;
}

CPLHTTPResult *refuseFetch(const char *url, CSLConstList, GDALProgressFunc, void *, CPLHTTPFetchWriteFunc, void *, void *)
{
    auto *result = static_cast<CPLHTTPResult *>(CPLCalloc(1, sizeof(CPLHTTPResult)));
    result->nStatus = 1;
    const QByteArray why = QCoreApplication::translate("GdalDataset", "network access is off: Sortie reads local files only (%1)")
                               .arg(QString::fromUtf8(url)).toUtf8();
    result->pszErrBuf = CPLStrdup(why.constData());
    CPLError(CE_Failure, CPLE_AppDefined, "%s", result->pszErrBuf);
    return result;
}

// Once per process, before the first open: GDAL's drivers, and no way for a raster to reach the
// network (a VRT naming /vsicurl/ or a WMS URL, PROJ fetching grids).
void prepareGdal()
{
    GDALAllRegister();
    VSIFilesystemPluginCallbacksStruct *refuse = VSIAllocFilesystemPluginCallbacksStruct();
    refuse->open = refuseOpen;
    refuse->stat = refuseStat;
    for (const char *prefix : kNetworkFileSystems)
        VSIInstallPluginHandler(prefix, refuse);  // copies the callbacks
    VSIFreeFilesystemPluginCallbacksStruct(refuse);
    CPLHTTPSetFetchCallback(refuseFetch, nullptr);
    OSRSetPROJEnableNetwork(FALSE);
    CPLSetConfigOption("GDAL_VRT_ENABLE_PYTHON", "NO");
}

bool isVrtName(const QString &path)
{
    return path.endsWith(QLatin1String(".vrt"), Qt::CaseInsensitive);
}

QString allowedFormats()
{
    return QCoreApplication::translate("GdalDataset", "GeoTIFF (COG), SRTM .hgt, DTED, ESRI ASCII grid, ERDAS Imagine, ESRI .bil/.flt, "
                                                      "USGS DEM, PNG, JPEG, JPEG 2000 and .vrt mosaics of them");
}

// The driver whose signature `path` carries, among all GDAL has (a refused file is named with it).
// Only the drivers' Identify() runs, on the file's first bytes: GDALIdentifyDriverEx would also
// open the file with every driver that has none, which is what the allow-list is there to prevent.
QString identifiedDriver(const QByteArray &path)
{
    GDALOpenInfo info(path.constData(), GDAL_OF_RASTER | GDAL_OF_READONLY);
    GDALDriverManager *drivers = GetGDALDriverManager();
    for (int i = 0; i < drivers->GetDriverCount(); ++i) {
        GDALDriver *driver = drivers->GetDriver(i);
        if (!driver->GetMetadataItem(GDAL_DCAP_RASTER))
            continue;
        const int says = driver->pfnIdentifyEx ? driver->pfnIdentifyEx(driver, &info)
                         : driver->pfnIdentify ? driver->pfnIdentify(&info) : 0;
        if (says > 0)  // GDAL_IDENTIFY_TRUE; "unknown" (-1) is no claim
            return QString::fromUtf8(driver->GetDescription());
    }
    // Drivers without Identify() (EHdr's .bil) are asked by opening: only the allowed ones are.
    std::vector<const char *> allowed(std::begin(kAllowedDrivers), std::end(kAllowedDrivers));
    allowed.push_back(nullptr);
    GDALDriverH found = GDALIdentifyDriverEx(path.constData(), GDAL_OF_RASTER, allowed.data(), nullptr);
    return found ? QString::fromUtf8(GDALGetDriverShortName(found)) : QString();
}

QString driverNotAllowed(const QString &driver)
{
    if (driver == QLatin1String("VRT"))
        return QCoreApplication::translate("GdalDataset", "a GDAL VRT (driver VRT) under a name that is not .vrt: Sortie reads %1")
            .arg(allowedFormats());
    return QCoreApplication::translate("GdalDataset", "GDAL reads this file with its %1 driver, which Sortie does not use for the "
                                                      "operator's rasters: it reads %2")
        .arg(driver, allowedFormats());
}

bool driverAllowed(const QString &driver, bool vrtAllowed)
{
    if (driver == QLatin1String("VRT"))
        return vrtAllowed;
    for (const char *allowed : kAllowedDrivers)
        if (driver == QLatin1String(allowed))
            return true;
    return false;
}

bool isRegularFile(const QByteArray &path)
{
    VSIStatBufL stat;
    return VSIStatExL(path.constData(), &stat, VSI_STAT_EXISTS_FLAG | VSI_STAT_NATURE_FLAG) == 0 && VSI_ISREG(stat.st_mode);
}

// External overviews (`file.tif.ovr`) are opened by GDAL with any driver: one must be a GeoTIFF.
QString sideFileProblem(const QByteArray &path)
{
    for (const char *suffix : {".ovr", ".OVR"}) {
        const QByteArray side = path + suffix;
        if (!isRegularFile(side))
            continue;
        const QString driver = identifiedDriver(side);
        if (driver != QLatin1String("GTiff"))
            return QCoreApplication::translate("GdalDataset", "its overview file %1 is not a GeoTIFF (GDAL: %2)")
                .arg(QString::fromUtf8(side), driver.isEmpty() ? QStringLiteral("?") : driver);
    }
    return {};
}

QString vrtProblem(const QByteArray &path, int depth);

// Every file a VRT names, before GDAL opens any: a plain file (no URL, no connection string: the
// network file systems are off too), read by an allowed driver, a .vrt in turn checked; no raw band
// (it reads any file's bytes as pixels) and no derived band's code.
QString vrtNodeProblem(const CPLXMLNode *node, const QByteArray &vrtPath, int depth)
{
    for (; node; node = node->psNext) {
        if (node->eType != CXT_Element)
            continue;
        const QByteArray name(node->pszValue);
        if (name == "VRTRasterBand") {
            const char *subClass = CPLGetXMLValue(node, "subClass", "");
            if (EQUAL(subClass, "VRTRawRasterBand"))
                return QCoreApplication::translate("GdalDataset", "a raw band (VRTRawRasterBand) is not read");
        }
        if (name == "PixelFunctionCode")
            return QCoreApplication::translate("GdalDataset", "a pixel function's code is not run");
        if (name == "SourceFilename" || name == "SourceDataset") {
            QByteArray source(CPLGetXMLValue(node, nullptr, ""));
            const bool relative = CPLTestBool(CPLGetXMLValue(node, "relativeToVRT", "0")) || name == "SourceDataset";
            if (relative && CPLIsFilenameRelative(source.constData()))
                source = CPLFormFilename(CPLGetPath(vrtPath.constData()), source.constData(), nullptr);
            const QString shown = QString::fromUtf8(source);
            if (!isRegularFile(source))
                return QCoreApplication::translate("GdalDataset", "its source %1 is not a local file").arg(shown);
            const QString driver = identifiedDriver(source);
            if (!driverAllowed(driver, isVrtName(shown)))
                return QStringLiteral("%1: %2").arg(shown, driver.isEmpty()
                                                               ? QCoreApplication::translate("GdalDataset", "GDAL knows no raster format for this file")
                                                               : driverNotAllowed(driver));
            if (driver == QLatin1String("VRT"))
                if (const QString problem = vrtProblem(source, depth + 1); !problem.isEmpty())
                    return problem;
            continue;
        }
        if (const QString problem = vrtNodeProblem(node->psChild, vrtPath, depth); !problem.isEmpty())
            return problem;
    }
    return {};
}

QString vrtProblem(const QByteArray &path, int depth)
{
    if (depth > kMaxVrtDepth)
        return QCoreApplication::translate("GdalDataset", "VRTs nested more than %1 deep").arg(kMaxVrtDepth);
    VSIStatBufL stat;
    if (VSIStatExL(path.constData(), &stat, VSI_STAT_SIZE_FLAG) != 0 || vsi_l_offset(stat.st_size) > kMaxVrtBytes)
        return QCoreApplication::translate("GdalDataset", "%1: a VRT of more than %2 MiB").arg(QString::fromUtf8(path)).arg(kMaxVrtBytes >> 20);
    std::unique_ptr<CPLXMLNode, void (*)(CPLXMLNode *)> tree(CPLParseXMLFile(path.constData()), CPLDestroyXMLNode);
    if (!tree)
        return lastGdalError(QCoreApplication::translate("GdalDataset", "the VRT is not XML"));
    return vrtNodeProblem(tree.get(), path, depth);
}

} // namespace

GdalDatasetPtr openRaster(const QString &path, QString *error)
{
    static std::once_flag registered;
    std::call_once(registered, prepareGdal);
    auto fail = [&](const QString &why) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, why);
        return GdalDatasetPtr();
    };
    const QByteArray name = path.toUtf8();
    VSIStatBufL stat;  // through GDAL's file system: /vsimem/, /vsizip/... paths exist too
    if (VSIStatExL(name.constData(), &stat, VSI_STAT_EXISTS_FLAG) != 0)
        return fail(QCoreApplication::translate("GdalDataset", "no such file"));
    // GDAL reports its reasons through the error handler; keep them for the message instead of stderr.
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    struct PopHandler { ~PopHandler() { CPLPopErrorHandler(); } } pop;
    // Only the promised formats' drivers may read it: a VRT or a WMS description saved as `.tif` would
    // otherwise be followed to the files or URLs it names.
    const bool vrtAllowed = isVrtName(path);
    std::vector<const char *> allowed(std::begin(kAllowedDrivers), std::end(kAllowedDrivers));
    if (vrtAllowed)
        allowed.push_back("VRT");
    allowed.push_back(nullptr);
    const QString driver = identifiedDriver(name);
    if (!driver.isEmpty() && !driverAllowed(driver, vrtAllowed))
        return fail(driverNotAllowed(driver));
    if (const QString problem = sideFileProblem(name); !problem.isEmpty())
        return fail(problem);
    if (driver == QLatin1String("VRT"))
        if (const QString problem = vrtProblem(name, 0); !problem.isEmpty())
            return fail(problem);
    CPLErrorReset();
    GdalDatasetPtr dataset(GDALDataset::Open(name.constData(), GDAL_OF_RASTER | GDAL_OF_READONLY, allowed.data()));
    if (!dataset)
        return fail(lastGdalError(QCoreApplication::translate("GdalDataset", "GDAL knows no raster format for this file")));
    if (dataset->GetRasterCount() < 1)
        return fail(QCoreApplication::translate("GdalDataset", "the file has no raster band"));
    return dataset;
}

} // namespace sortie::raster
