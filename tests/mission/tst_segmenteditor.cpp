// The generated segment editor and the coalesced preview: an editor built from the algorithm's
// description (built-in, or a server's with a parameter Sortie never heard of), values typed and
// checked by the definition, every set one undo step; figures of a survey as the operator types;
// the preview plans once per frame however many edits arrive, and only for its own row.
#include "AlgorithmCatalog.h"
#include "Camera.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "SegmentEditorModel.h"
#include "SegmentParameters.h"
#include "SegmentPreview.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>

using namespace sortie::mission;

namespace {
struct Fixture
{
    RouteModel model;
    QUndoStack stack;
    RouteEditor editor{&model, &stack};
    SegmentEditorModel fields{&model, &editor};
    SegmentPreview preview{&model, &editor};
    QAbstractItemModelTester tester{&fields, QAbstractItemModelTester::FailureReportingMode::QtTest};
    Fixture()
    {
        Route r;
        r.settings.initialSpeed = 6;
        Waypoint w;
        w.position = {56.95, 24.10};
        r.segments.push_back(w);
        model.resetRoute(r);
    }
    QVariant value(const QString &name) const
    {
        return fields.index(fields.indexOf(name)).data(SegmentEditorModel::ValueRole);
    }
};

const QList<QGeoCoordinate> kSquare{QGeoCoordinate(56.950, 24.100), QGeoCoordinate(56.950, 24.110),
                                    QGeoCoordinate(56.955, 24.110), QGeoCoordinate(56.955, 24.100)};
} // namespace

class TestSegmentEditor : public QObject
{
    Q_OBJECT
private slots:
    void everyToolGetsAnEditorFromItsDescription()
    {
        for (const AlgorithmDefinition &def : AlgorithmCatalog::builtIn().algorithms()) {
            if (def.kind == AlgorithmKind::Waypoint || def.kind == AlgorithmKind::TakeOff || def.kind == AlgorithmKind::Landing
                || def.kind == AlgorithmKind::AreaScan)
                continue;  // typed segments: their fields are Sortie's (areaScanFieldsAreWireNames)
            Fixture f;
            const QList<QGeoCoordinate> points = def.figure == FigureType::Polygon ? kSquare
                                               : def.figure == FigureType::Polyline ? kSquare.mid(0, 2) : kSquare.mid(0, 1);
            const int row = f.editor.addSegment(def.className, points);
            QVERIFY2(row == 1, qPrintable(def.displayName));
            f.fields.setRow(row);
            QVERIFY(f.fields.isValid());
            QVERIFY2(f.fields.rowCount() >= int(def.parameters.size()), qPrintable(def.displayName));
            for (const ParameterDefinition &p : def.parameters) {
                const QModelIndex i = f.fields.index(f.fields.indexOf(p.name));
                QVERIFY2(i.isValid(), qPrintable(p.name));
                QCOMPARE(i.data(SegmentEditorModel::LabelRole).toString(), p.displayName);
                QCOMPARE(i.data(SegmentEditorModel::UnitRole).toString(), p.unit());
                QVERIFY(i.data(SegmentEditorModel::KnownRole).toBool());
                if (p.name == QLatin1String("directionAngle"))
                    QCOMPARE(i.data(SegmentEditorModel::WidgetRole).toString(), QStringLiteral("angle"));
                if (p.name == QLatin1String("camera"))
                    QCOMPARE(i.data(SegmentEditorModel::WidgetRole).toString(), QStringLiteral("camera"));
            }
            f.preview.setRow(row);
            QVERIFY2(f.preview.problem().isEmpty(), qPrintable(def.displayName + QStringLiteral(": ") + f.preview.problem()));
            QVERIFY2(!f.preview.path().isEmpty(), qPrintable(def.displayName));
        }
    }

    void areaScanFieldsAreWireNames()
    {
        Fixture f;
        const int row = f.editor.addSegment(QStringLiteral("AreaScanAlgorithm"), kSquare);
        f.fields.setRow(row);
        QCOMPARE(f.fields.kind(), QStringLiteral("areaScan"));
        for (const char *name : {"height", "overlapForward", "overlapSide", "sideDistance", "directionAngle", "overshoot", "tolerance", "camera"})
            QVERIFY2(f.fields.indexOf(QLatin1String(name)) >= 0, name);
        // The AGL tolerance is the server's until typed (shown empty, not 0), and is emptied back to it.
        const int tolerance = f.fields.indexOf(QStringLiteral("tolerance"));
        QVERIFY(!std::get<AreaScan>(f.model.segment(row)).parameters.toleranceMeters);
        QVERIFY(f.fields.set(tolerance, QStringLiteral("5")));
        QCOMPARE(std::get<AreaScan>(f.model.segment(row)).parameters.toleranceMeters, std::optional<double>(5.0));
        QVERIFY(f.fields.set(tolerance, QString()));
        QVERIFY(!std::get<AreaScan>(f.model.segment(row)).parameters.toleranceMeters);
        QCOMPARE(f.fields.index(f.fields.indexOf(QStringLiteral("overlapSide"))).data(SegmentEditorModel::UnitRole).toString(),
                 QStringLiteral("%"));
        // Choosing a camera by name brings its optics (one undo step).
        const Camera gopro = *builtInCamera(QStringLiteral("GoPro Hero3 Black Edition"));
        QVERIFY(f.fields.set(f.fields.indexOf(QStringLiteral("camera")), gopro.name));
        QCOMPARE(std::get<AreaScan>(f.model.segment(row)).parameters.camera, gopro);
        f.stack.undo();
        QVERIFY(!(std::get<AreaScan>(f.model.segment(row)).parameters.camera == gopro));
    }

    void aFreshAreaScanHasNoProblem()
    {
        // Its defaults (side distance 0: from the camera; the generic camera) are valid values.
        Fixture f;
        f.fields.setRow(f.editor.addSegment(QStringLiteral("AreaScanAlgorithm"), kSquare));
        for (int i = 0; i < f.fields.rowCount(); ++i) {
            const QModelIndex field = f.fields.index(i);
            QVERIFY2(field.data(SegmentEditorModel::ProblemRole).toString().isEmpty(),
                     qPrintable(field.data(SegmentEditorModel::NameRole).toString() + QStringLiteral(": ")
                                + field.data(SegmentEditorModel::ProblemRole).toString()));
        }
        QVERIFY(f.fields.isValid());
        // The picker lists the segment's own camera beside the built-in ones.
        const QModelIndex camera = f.fields.index(f.fields.indexOf(QStringLiteral("camera")));
        const QVariantList choices = camera.data(SegmentEditorModel::ChoicesRole).toList();
        QCOMPARE(choices.size(), qsizetype(builtInCameras().size() + 1));
        QCOMPARE(choices.first().toMap().value(QStringLiteral("value")).toString(), Camera{}.name);
        // A side distance below 0 is still refused.
        QVERIFY(!f.fields.set(f.fields.indexOf(QStringLiteral("sideDistance")), -1.0));
    }

    void setValuesTypedCheckedAndUndoable()
    {
        Fixture f;
        const int row = f.editor.addSegment(QStringLiteral("CircleAlgorithm"), kSquare.mid(0, 1));
        f.fields.setRow(row);
        QCOMPARE(f.fields.kind(), QStringLiteral("circle"));
        QCOMPARE(f.fields.radius(), 50.0);
        const int loops = f.fields.indexOf(QStringLiteral("loops"));
        QVERIFY(f.fields.set(loops, QStringLiteral("3")));  // a text field's number
        QCOMPARE(f.value(QStringLiteral("loops")).toDouble(), 3.0);
        QVERIFY(!f.fields.set(loops, QStringLiteral("many")));
        QVERIFY(f.fields.problem().contains(QStringLiteral("number")));
        QVERIFY(!f.fields.set(loops, 1000));  // above the definition's maximum
        QVERIFY(f.fields.problem().contains(QStringLiteral("loops")));
        QVERIFY(f.fields.set(f.fields.indexOf(QStringLiteral("flightClockwise")), false));
        QCOMPARE(f.value(QStringLiteral("flightClockwise")).toBool(), false);
        QVERIFY(f.fields.setRadius(80));
        QCOMPARE(f.fields.radius(), 80.0);
        const int steps = f.stack.count();
        f.stack.undo();
        QCOMPARE(f.fields.radius(), 50.0);
        f.stack.undo();
        QCOMPARE(f.value(QStringLiteral("flightClockwise")).toBool(), true);
        QCOMPARE(steps, 4);  // add, loops, clockwise, radius
    }

    void aServerDescriptionBuildsTheEditor()
    {
        Fixture f;
        // A newer server's circle takes a parameter Sortie has never heard of, and a new tool.
        AlgorithmCatalog server = AlgorithmCatalog::builtIn();
        AlgorithmDefinition circle = *server.byKind(AlgorithmKind::Circle);
        ParameterDefinition tilt;
        tilt.name = QStringLiteral("gimbalTilt");
        tilt.displayName = QStringLiteral("Gimbal tilt");
        tilt.type = ParameterType::Double;
        tilt.quantity = Quantity::Angle;
        tilt.defaultValue = QStringLiteral("45");
        tilt.minimum = 0;
        tilt.maximum = 90;
        circle.parameters.push_back(tilt);
        server.insert(circle);
        AlgorithmDefinition orbit8;
        orbit8.className = QStringLiteral("com.ugcs.ucs.service.routing.impl.FigureEightAlgorithm");
        orbit8.displayName = QStringLiteral("Figure eight");
        orbit8.figure = FigureType::EightCurve;
        orbit8.parameters = {tilt};
        server.insert(orbit8);
        QSignalSpy reset(&f.fields, &QAbstractItemModel::modelReset);
        f.editor.setCatalog(&server);
        const int row = f.editor.addSegment(QStringLiteral("CircleAlgorithm"), kSquare.mid(0, 1));
        f.fields.setRow(row);
        const int i = f.fields.indexOf(QStringLiteral("gimbalTilt"));
        QVERIFY(i >= 0);
        QCOMPARE(f.fields.index(i).data(SegmentEditorModel::WidgetRole).toString(), QStringLiteral("angle"));
        QCOMPARE(f.value(QStringLiteral("gimbalTilt")).toDouble(), 45.0);  // the server's default, sent
        QVERIFY(!f.fields.set(i, 120));
        QVERIFY(f.fields.set(i, 30));
        QCOMPARE(std::get<AlgorithmSegment>(f.model.segment(row)).value(u"gimbalTilt")->toStdString(), std::string("30"));
        const int eight = f.editor.addSegment(QStringLiteral("com.ugcs.ucs.service.routing.impl.FigureEightAlgorithm"), kSquare.mid(0, 1));
        QVERIFY(eight > 0);
        f.fields.setRow(eight);
        QCOMPARE(f.fields.title(), QStringLiteral("Figure eight %1").arg(eight + 1));
        QCOMPARE(f.fields.rowCount(), 1);
        // Offline again: the built-in description; the server's extra value stays as raw text.
        f.editor.setCatalog(nullptr);
        f.fields.setRow(row);
        const int raw = f.fields.indexOf(QStringLiteral("gimbalTilt"));
        QVERIFY(raw >= 0);
        QVERIFY(!f.fields.index(raw).data(SegmentEditorModel::KnownRole).toBool());
        QCOMPARE(f.fields.index(raw).data(SegmentEditorModel::WidgetRole).toString(), QStringLiteral("text"));
        QVERIFY(f.fields.set(raw, QStringLiteral("whatever it takes")));  // raw text: kept, not checked
        QVERIFY(reset.count() >= 2);
    }

    void surveyFiguresFollowTheTyping()
    {
        Fixture f;
        const int row = f.editor.addSegment(QStringLiteral("PhotogrammetryAlgorithm"), kSquare);
        f.fields.setRow(row);
        QVERIFY(f.fields.set(f.fields.indexOf(QStringLiteral("camera")), builtInCameras().front().name));
        const auto before = f.fields.figures();
        QVERIFY(before);
        QVERIFY2(before->plan, qPrintable(before->message));
        QVERIFY2(f.fields.figuresText().contains(QStringLiteral("%1 photos").arg(before->plan->photoCount)), qPrintable(f.fields.figuresText()));
        QSignalSpy changed(&f.fields, &SegmentEditorModel::valuesChanged);
        QVERIFY(f.fields.set(f.fields.indexOf(QStringLiteral("groundSampleDistance")), 1.0));
        QVERIFY(changed.count() >= 1);
        const auto after = f.fields.figures();
        QVERIFY(after && after->plan);
        QVERIFY(after->height < before->height);
        QVERIFY(after->plan->photoCount > before->plan->photoCount);
        QVERIFY2(f.fields.figuresText().startsWith(QStringLiteral("%1 m high · 1.00 cm/px").arg(after->height, 0, 'f', 1)), qPrintable(f.fields.figuresText()));
        QVERIFY(f.fields.set(f.fields.indexOf(QStringLiteral("overlapSide")), 60));
        QVERIFY(f.fields.figures()->plan->transectSpacing < after->plan->transectSpacing);
        // A waypoint has no survey figures: no line at all, not a line of zeros.
        f.fields.setRow(0);
        QVERIFY(!f.fields.figures());
        QCOMPARE(f.fields.figuresText(), QString());
    }

    void profileCamerasLeadThePicker()
    {
        // A route from a server whose vehicle profile has a camera (id 7): the picker offers it first,
        // and choosing it plans the figures with its optics, not a built-in's.
        Fixture f;
        Camera wide = builtInCameras().front();
        wide.name = QStringLiteral("Profile wide");
        wide.focalLengthMm /= 2;  // twice the footprint of the built-in it is made from
        Route r = f.model.route();
        r.settings.profile.cameras = {{7, wide}};
        f.model.resetRoute(r);
        const int row = f.editor.addSegment(QStringLiteral("PhotogrammetryAlgorithm"), kSquare);
        f.fields.setRow(row);
        const int camera = f.fields.indexOf(QStringLiteral("camera"));
        const QVariantList choices = f.fields.index(camera).data(SegmentEditorModel::ChoicesRole).toList();
        QVERIFY(choices.size() > 1);
        QCOMPARE(choices.first().toMap().value(QStringLiteral("value")).toString(), QStringLiteral("7"));
        QCOMPARE(choices.first().toMap().value(QStringLiteral("text")).toString(), QStringLiteral("Profile wide (vehicle profile)"));
        QVERIFY(f.fields.set(camera, builtInCameras().front().name));
        const double builtInHeight = f.fields.figures()->height;
        QVERIFY(f.fields.set(camera, QStringLiteral("7")));
        const auto withProfile = f.fields.figures();
        QVERIFY(withProfile);
        QVERIFY2(withProfile->plan, qPrintable(withProfile->message));
        // The same GSD from half the focal length: half the height.
        QVERIFY2(std::abs(withProfile->height - builtInHeight / 2) < 0.01, qPrintable(QStringLiteral("%1 vs %2").arg(withProfile->height).arg(builtInHeight)));
    }

    void previewPlansOncePerFrame()
    {
        Fixture f;
        const int row = f.editor.addAreaScan(kSquare);
        const int other = f.editor.addSegment(QStringLiteral("CircleAlgorithm"), kSquare.mid(0, 1));
        f.preview.setRow(row);
        QCOMPARE(f.preview.figure().size(), 4);
        const int pathBefore = int(f.preview.path().size());
        QVERIFY(pathBefore >= 4);
        const int plans = f.preview.planCount();
        QSignalSpy changed(&f.preview, &SegmentPreview::changed);
        for (int i = 1; i <= 50; ++i)  // a drag: 50 steps within one frame
            f.editor.moveVertex(row, 2, QGeoCoordinate(56.955 + i * 1e-4, 24.110 + i * 1e-4), EditStep::Continuing);
        f.editor.moveVertex(row, 2, QGeoCoordinate(56.960, 24.115));
        QCOMPARE(f.preview.planCount(), plans);  // nothing planned yet: coalesced to the next frame
        QVERIFY(changed.wait(1000));
        QCOMPARE(f.preview.planCount(), plans + 1);
        QCOMPARE(changed.count(), 1);
        QVERIFY(f.preview.path().size() > pathBefore);  // a bigger area, more passes
        QCOMPARE(f.stack.count(), 3);  // add scan, add circle, the drag
        // Another row's edit plans nothing (a read would plan at once if it had to).
        QVERIFY(f.editor.setRadius(other, 70));
        QVERIFY(!f.preview.path().isEmpty());
        QCOMPARE(f.preview.planCount(), plans + 1);
        // A read while an edit is pending plans at once.
        f.editor.setParameter({row}, QStringLiteral("directionAngle"), 45);
        QCOMPARE(f.preview.path().size() > 0, true);
        QCOMPARE(f.preview.planCount(), plans + 2);
    }
};

QTEST_GUILESS_MAIN(TestSegmentEditor)
#include "tst_segmenteditor.moc"
