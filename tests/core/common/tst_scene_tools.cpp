// The SceneTools contract holds alike in every scene with tools (the gas, the fluid and the wind tunnel):
// centres and drag targets are clamped into the box, an index that names no obstacle is refused, a placed
// body rests at once, a scene without a piston refuses the piston's tools, heat / cool refuses a factor that
// is not positive; and the direction of time is the model's, refused where the dynamics cannot reverse.
#include "dsmc/DsmcModel.h"
#include "md/MdModel.h"
#include "pbf/PbfModel.h"
#include "tunnel/TunnelModel.h"

#include <QtTest>
#include <functional>
#include <limits>
#include <memory>

using namespace pl;

namespace {

using MakeScene = std::function<std::unique_ptr<Model>()>;

// The scene's box as the viewport draws it [L].
struct Box {
    double left, bottom, right, top;
    double centreX() const { return 0.5 * (left + right); }
    double centreY() const { return 0.5 * (bottom + top); }
};

Box boxOf(const Model& model) {
    const SceneView view = model.sceneView();
    return {view.left, view.bottom, view.right, view.top};
}

Obstacle discAt(double x, double y, double radius) {
    Obstacle disc;
    disc.x = x;
    disc.y = y;
    disc.radius = radius;
    return disc;
}

} // namespace

class TestSceneTools : public QObject {
    Q_OBJECT

    static void scenes() {
        QTest::addColumn<MakeScene>("make");
        QTest::newRow("gas") << MakeScene([] { return std::make_unique<MdModel>(); });
        QTest::newRow("fluid") << MakeScene([] { return std::make_unique<PbfModel>(); });
        QTest::newRow("tunnel") << MakeScene([] { return std::make_unique<TunnelModel>(); });
    }

private slots:
    void addedObstacleIsClampedIntoTheBox_data() { scenes(); }
    void addedObstacleIsClampedIntoTheBox() {
        QFETCH(MakeScene, make);
        const auto model = make();
        SceneTools* tools = model->tools();
        QVERIFY(tools);
        const Box box = boxOf(*model);
        tools->addObstacle(discAt(box.right + 1e6, box.bottom - 1e6, 0.01 * (box.right - box.left)));
        QCOMPARE(tools->obstacles().size(), std::size_t(1));
        QCOMPARE(tools->obstacles()[0].x, box.right);
        QCOMPARE(tools->obstacles()[0].y, box.bottom);
    }

    void placedObstacleIsClampedAndRests_data() { scenes(); }
    void placedObstacleIsClampedAndRests() {
        QFETCH(MakeScene, make);
        const auto model = make();
        SceneTools* tools = model->tools();
        const Box box = boxOf(*model);
        tools->addObstacle(discAt(box.centreX(), box.centreY(), 0.01 * (box.right - box.left)));
        tools->placeObstacle(0, box.left - 1e6, box.top + 1e6);
        const Obstacle& o = tools->obstacles()[0];
        QCOMPARE(o.x, box.left);
        QCOMPARE(o.y, box.top);
        QCOMPARE(o.vx, 0.0);
        QCOMPARE(o.vy, 0.0);
        QVERIFY(!tools->bodiesMoving());
    }

    // A target far outside the box: the body heads for the clamped corner, not along the raw direction.
    void dragTargetIsClampedIntoTheBox_data() { scenes(); }
    void dragTargetIsClampedIntoTheBox() {
        QFETCH(MakeScene, make);
        const auto model = make();
        SceneTools* tools = model->tools();
        const Box box = boxOf(*model);
        const double x0 = box.centreX(), y0 = box.centreY();
        tools->addObstacle(discAt(x0, y0, 0.01 * (box.right - box.left)));
        tools->dragObstacle(0, box.right + 1e6, box.top + 2e6); // raw direction: slope ≈ 2
        QVERIFY(tools->bodiesMoving());
        model->step();
        const Obstacle& o = tools->obstacles()[0];
        const double dx = o.x - x0, dy = o.y - y0;
        QVERIFY2(dx > 0 && dy > 0, qPrintable(QString("moved by (%1, %2)").arg(dx).arg(dy)));
        // Parallel to the way to the corner (right, top).
        const double cross = dx * (box.top - y0) - dy * (box.right - x0);
        QVERIFY2(std::abs(cross) <= 1e-9 * std::hypot(dx, dy) * std::hypot(box.right - x0, box.top - y0),
                 qPrintable(QString::number(cross)));
        const double dt = std::get<double>(model->params().at("dt"));
        QVERIFY(std::hypot(dx, dy) <= tools->toolSpeed() * std::abs(dt) * (1 + 1e-12));
    }

    void badIndexIsRefused_data() { scenes(); }
    void badIndexIsRefused() {
        QFETCH(MakeScene, make);
        const auto model = make();
        SceneTools* tools = model->tools();
        const Box box = boxOf(*model);
        tools->addObstacle(discAt(box.centreX(), box.centreY(), 0.01 * (box.right - box.left)));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, tools->removeObstacle(1));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, tools->dragObstacle(1, box.left, box.bottom));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, tools->releaseObstacle(1));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, tools->placeObstacle(1, box.left, box.bottom));
        QCOMPARE(tools->obstacles().size(), std::size_t(1)); // nothing changed
        QVERIFY(!tools->bodiesMoving());
        tools->removeObstacle(0);
        QVERIFY(tools->obstacles().empty());
    }

    void missingPistonIsRefused_data() { scenes(); }
    void missingPistonIsRefused() {
        QFETCH(MakeScene, make);
        const auto model = make();
        SceneTools* tools = model->tools();
        QVERIFY(!tools->hasPiston());
        QVERIFY_THROWS_EXCEPTION(std::logic_error, tools->dragPiston(0.0));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, tools->drivePiston(-1));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, tools->placePiston(0.0));
    }

    void heatRefusesAFactorThatIsNotPositive_data() { scenes(); }
    void heatRefusesAFactorThatIsNotPositive() {
        QFETCH(MakeScene, make);
        const auto model = make();
        SceneTools* tools = model->tools();
        for (double factor :
             {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
            QVERIFY_THROWS_EXCEPTION(std::invalid_argument, tools->scaleKineticEnergy(factor));
    }

    // Turning time round changes no parameter; only reversible dynamics accept −1.
    void directionOfTimeIsTheModels() {
        MdModel gas;
        const ParamValues before = gas.params();
        QCOMPARE(gas.timeDirection(), 1);
        gas.setTimeDirection(-1);
        QCOMPARE(gas.timeDirection(), -1);
        QVERIFY(gas.params() == before);
        gas.step();
        QVERIFY2(gas.time() < 0, qPrintable(QString::number(gas.time())));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, gas.setTimeDirection(0));

        PbfModel fluid;
        QVERIFY_THROWS_EXCEPTION(std::logic_error, fluid.setTimeDirection(-1));
        QCOMPARE(fluid.timeDirection(), 1);
        DsmcModel cell;
        QVERIFY_THROWS_EXCEPTION(std::logic_error, cell.setTimeDirection(-1));
        QVERIFY(cell.tools() == nullptr);
    }
};

QTEST_APPLESS_MAIN(TestSceneTools)
#include "tst_scene_tools.moc"
