// Coverage of 2,000 photos over a square kilometre (docs/performance.md, "Coverage"): a lawnmower
// survey of 1 km × 1 km from 100 m with a 1" 20 MP camera (150 × 100 m footprints), 86 % forward
// and 75 % side overlap (1,944 photos), judged on 0.5 m cells (4.6 million) and on the default
// cell (a 200th of the footprint's width, 0.75 m); then the GeoTIFF written. Issue 34's goal for
// the coverage raster: under 2 s.
#include "BenchClock.h"
#include "CoverageTestSurvey.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QTemporaryDir>

#include <cstdio>

using namespace sortie;

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QLoggingCategory::setFilterRules(QStringLiteral("sortie.coverage.info=false"));
    test::Survey plan;
    plan.widthMeters = 1000;
    plan.lengthMeters = 1000;
    plan.forward = 0.86;
    plan.side = 0.75;
    const auto shots = test::flySurvey(plan, test::surveyCamera());
    std::printf("bench_coverage: %zu photos over %.0f × %.0f m, load %.2f\n", shots.size(), plan.widthMeters, plan.lengthMeters, test::loadAverage());

    bool met = true;
    coverage::CoverageRaster raster;
    for (double cell : {0.5, 0.0}) {
        coverage::CoverageOptions options;
        options.camera = test::surveyCamera();
        options.cellMeters = cell;
        std::optional<coverage::CoverageReport> report;
        QString error;
        const test::Timing t = test::median(5, [&] { report = coverage::computeCoverage(shots, options, &raster, &error); });
        if (!report) {
            std::fprintf(stderr, "bench_coverage: %s\n", qPrintable(error));
            return 1;
        }
        const test::Verdict v = test::judge(t, 2000);
        met = met && v.met;
        std::printf("  coverage on %.2f m cells (%d × %d): %.0f ms wall, %.0f ms CPU (goal 2000 ms)%s; images per point p5 %.0f p50 %.0f, "
                    "forward %.1f %%, side %.1f %%, %zu holes\n",
                    report->cellMeters, raster.width, raster.height, t.wallMs, t.cpuMs, v.note, report->imagesPerPoint->p5,
                    report->imagesPerPoint->p50, report->forwardOverlap->p50, report->sideOverlap->p50, report->holes.size());
    }
    QTemporaryDir dir;
    QString error;
    const test::Timing write = test::median(3, [&] {
        if (!coverage::writeCoverageGeoTiff(raster, dir.filePath(QStringLiteral("overlap.tif")), &error))
            std::fprintf(stderr, "bench_coverage: %s\n", qPrintable(error));
    });
    std::printf("  GeoTIFF (%d × %d, deflate): %.0f ms wall, %.0f ms CPU\n", raster.width, raster.height, write.wallMs, write.cpuMs);
    return met ? 0 : 1;
}
