// particlelab-cli record and the app's recorder, checked by decoding what it wrote: ffprobe for the codec,
// frame count, size and duration; libavcodec in this test for a frame of MP4 and WebM against the off-screen
// render of the same state (PSNR); the GIF's frame count and loop; a SIGINT leaves a clip with the frames so
// far, and a SIGKILL one that decodes without error up to about its last second; bad options are refused
// with exit 2 before anything is written.
#include "CliRunner.h"

#include "SimulationController.h"
#include "catalog/ModelCatalog.h"
#include "record/AppRecorder.h"
#include "record/ClipFrames.h"
#include "viewport/ScenePainter.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

using pl::test::runCli;
using pl::test::runProgram;

namespace {

constexpr int kFps = 10;
constexpr int kSteps = 10;    // --steps-per-frame
const QSize kSize(1280, 720); // the default size
// YUV → RGB as a player does it well: chroma interpolated to full resolution, exact rounding.
constexpr int kDecodeFlags = SWS_BICUBIC | SWS_FULL_CHR_H_INT | SWS_ACCURATE_RND;

struct Probe {
    QString codec;
    int width = 0, height = 0;
    long long frames = -1;
    double duration = -1; // [s]
    QString errors;       // what ffprobe reported while it demuxed and decoded every frame
};

Probe ffprobe(const QString& path) {
    const auto r = runProgram(
        "ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                    "stream=codec_name,width,height,nb_read_frames:format=duration", "-of", "json", path});
    Probe p;
    const QJsonObject root = QJsonDocument::fromJson(r.out.toUtf8()).object();
    const QJsonObject stream = root["streams"].toArray().at(0).toObject();
    p.codec = stream["codec_name"].toString();
    p.width = stream["width"].toInt();
    p.height = stream["height"].toInt();
    p.frames = stream["nb_read_frames"].toString("-1").toLongLong();
    p.duration = root["format"].toObject()["duration"].toString("-1").toDouble();
    p.errors = r.err.trimmed();
    return p;
}

// Frame `index` of the clip, decoded by libavcodec and converted to RGB32.
QImage decodeFrame(const QString& path, int index) {
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, path.toUtf8().constData(), nullptr, nullptr) < 0) return {};
    avformat_find_stream_info(format, nullptr);
    const int stream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    const AVCodec* codec = avcodec_find_decoder(format->streams[stream]->codecpar->codec_id);
    AVCodecContext* context = avcodec_alloc_context3(codec);
    avcodec_parameters_to_context(context, format->streams[stream]->codecpar);
    avcodec_open2(context, codec, nullptr);
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    QImage image;
    int seen = 0;
    auto drain = [&] {
        while (image.isNull() && avcodec_receive_frame(context, frame) == 0) {
            if (seen++ != index) continue;
            image = QImage(frame->width, frame->height, QImage::Format_RGB32);
            SwsContext* sws = sws_getContext(
                frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width,
                frame->height, AV_PIX_FMT_RGB32, kDecodeFlags, nullptr, nullptr, nullptr);
            uint8_t* out[1] = {image.bits()};
            const int stride[1] = {static_cast<int>(image.bytesPerLine())};
            sws_scale(sws, frame->data, frame->linesize, 0, frame->height, out, stride);
            sws_freeContext(sws);
        }
    };
    while (image.isNull() && av_read_frame(format, packet) >= 0) {
        if (packet->stream_index == stream) avcodec_send_packet(context, packet);
        av_packet_unref(packet);
        drain();
    }
    avcodec_send_packet(context, nullptr);
    drain();
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&context);
    avformat_close_input(&format);
    return image;
}

// The picture through 4:2:0 and back without an encoder: what chroma subsampling alone costs.
QImage throughYuv420(const QImage& rgb) {
    const int w = rgb.width(), h = rgb.height();
    AVFrame* yuv = av_frame_alloc();
    yuv->format = AV_PIX_FMT_YUV420P;
    yuv->width = w;
    yuv->height = h;
    av_frame_get_buffer(yuv, 0);
    SwsContext* in = sws_getContext(w, h, AV_PIX_FMT_RGB32, w, h, AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr,
                                    nullptr, nullptr);
    const uint8_t* src[1] = {rgb.constBits()};
    const int srcStride[1] = {static_cast<int>(rgb.bytesPerLine())};
    sws_scale(in, src, srcStride, 0, h, yuv->data, yuv->linesize);
    QImage out(w, h, QImage::Format_RGB32);
    SwsContext* back = sws_getContext(w, h, AV_PIX_FMT_YUV420P, w, h, AV_PIX_FMT_RGB32, kDecodeFlags, nullptr,
                                      nullptr, nullptr);
    uint8_t* dst[1] = {out.bits()};
    const int dstStride[1] = {static_cast<int>(out.bytesPerLine())};
    sws_scale(back, yuv->data, yuv->linesize, 0, h, dst, dstStride);
    sws_freeContext(in);
    sws_freeContext(back);
    av_frame_free(&yuv);
    return out;
}

// Peak signal-to-noise ratio of b against a over the three colour channels [dB].
double psnr(const QImage& a, const QImage& b) {
    double sum = 0;
    for (int y = 0; y < a.height(); ++y) {
        const auto* pa = reinterpret_cast<const QRgb*>(a.constScanLine(y));
        const auto* pb = reinterpret_cast<const QRgb*>(b.constScanLine(y));
        for (int x = 0; x < a.width(); ++x) {
            const double dr = qRed(pa[x]) - qRed(pb[x]), dg = qGreen(pa[x]) - qGreen(pb[x]),
                         db = qBlue(pa[x]) - qBlue(pb[x]);
            sum += dr * dr + dg * dg + db * db;
        }
    }
    const double mse = sum / (3.0 * a.width() * a.height());
    return mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : 99.0;
}

// The scene after `steps` steps of the preset, drawn off screen as the recording draws it bare.
std::unique_ptr<pl::Model> stateAfter(const QString& preset, long long steps) {
    auto model = pl::createModel("gas");
    model->reset(pl::loadPreset(preset.toStdString()));
    for (long long s = 0; s < steps; ++s) model->step();
    return model;
}

QImage renderedState(const QString& preset, long long steps) {
    return pl::ui::renderScene(stateAfter(preset, steps)->sceneView(), kSize);
}

// The recording of the tests; `changed` replaces options of the same name ("--size", "321x240").
QStringList recordArgs(const QString& out, double seconds = 1.0, const QStringList& changed = {}) {
    QStringList args{"record",
                     "gas-classroom",
                     "--out",
                     out,
                     "--seconds",
                     QString::number(seconds),
                     "--fps",
                     QString::number(kFps),
                     "--steps-per-frame",
                     QString::number(kSteps),
                     "--size",
                     QStringLiteral("%1x%2").arg(kSize.width()).arg(kSize.height()),
                     "--backend",
                     "cpu",
                     "--quiet"};
    for (int i = 0; i + 1 < changed.size(); i += 2) {
        const qsizetype at = args.indexOf(changed[i]);
        if (at >= 0)
            args[at + 1] = changed[i + 1];
        else
            args << changed[i] << changed[i + 1];
    }
    return args;
}

// Whether a GIF's bytes end just after a whole block (the header, an extension, an image with all its
// data), with or without the trailer: a decoder then reads every frame whole. FFmpeg decodes a frame cut
// short without a word, so ffprobe alone cannot tell.
bool gifEndsAfterAWholeBlock(const QByteArray& gif) {
    const auto byte = [&gif](qsizetype at) { return static_cast<unsigned char>(gif.at(at)); };
    const auto subBlocks = [&](qsizetype at) { // past the sub-blocks from `at`, or -1 where they are cut
        while (at < gif.size() && byte(at) != 0) at += 1 + byte(at);
        return at < gif.size() ? at + 1 : -1;
    };
    if (gif.size() < 13) return false;
    qsizetype at = 13 + ((byte(10) & 0x80) ? 3 * (2 << (byte(10) & 7)) : 0); // the global colour table
    while (at >= 0 && at < gif.size()) {
        if (byte(at) == 0x3b) return at + 1 == gif.size(); // the trailer ends a finished GIF
        if (byte(at) == 0x21) {
            at = at + 2 < gif.size() ? subBlocks(at + 2) : -1;
        } else if (byte(at) == 0x2c && at + 10 < gif.size()) {
            const int flags = byte(at + 9);
            at += 10 + ((flags & 0x80) ? 3 * (2 << (flags & 7)) : 0) + 1; // a local table, the code size
            at = at <= gif.size() ? subBlocks(at) : -1;
        } else {
            return false;
        }
    }
    return at == gif.size();
}

// particlelab-cli with its stderr on a pseudo-terminal, as in a terminal window: there it draws its
// progress line ("\rframe 75/15000"), which says how many frames the recording has made so far.
class TerminalRun {
public:
    explicit TerminalRun(const QStringList& args) {
        master_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
        if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0) return;
        std::vector<QByteArray> words{QByteArray(PARTICLELAB_CLI)};
        for (const QString& arg : args) words.push_back(arg.toLocal8Bit());
        std::vector<char*> argv;
        for (QByteArray& word : words) argv.push_back(word.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
        posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
        posix_spawn_file_actions_addopen(&actions, 2, ::ptsname(master_), O_RDWR | O_NOCTTY, 0);
        if (::posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
        posix_spawn_file_actions_destroy(&actions);
    }
    ~TerminalRun() {
        kill();
        if (master_ >= 0) ::close(master_);
    }
    TerminalRun(const TerminalRun&) = delete;
    TerminalRun& operator=(const TerminalRun&) = delete;

    bool started() const { return pid_ > 0; }
    // Reads the progress line until it counts `frame` frames or more, the program ends or timeoutMs
    // passes; returns the last count read.
    long long waitForFrame(long long frame, int timeoutMs) {
        QElapsedTimer clock;
        clock.start();
        while (frames_ < frame && clock.elapsed() < timeoutMs) {
            pollfd ready{master_, POLLIN, 0};
            if (::poll(&ready, 1, 100) <= 0) continue;
            char buffer[4096];
            const ssize_t n = ::read(master_, buffer, sizeof buffer);
            if (n <= 0) break; // no writer left: the program ended
            line_.append(buffer, static_cast<qsizetype>(n));
            const qsizetype slash = line_.lastIndexOf('/');
            const qsizetype word = slash > 0 ? line_.lastIndexOf("frame ", slash) : -1;
            if (word >= 0) frames_ = line_.mid(word + 6, slash - word - 6).toLongLong();
            line_ = line_.mid(std::max<qsizetype>(0, line_.lastIndexOf('\r'))); // the line being drawn
        }
        return frames_;
    }
    // Ends it with SIGKILL, which it cannot catch; true when that is what ended it.
    bool kill() {
        if (pid_ <= 0) return false;
        ::kill(pid_, SIGKILL);
        int status = 0;
        const bool waited = ::waitpid(pid_, &status, 0) == pid_;
        pid_ = -1;
        return waited && WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
    }

private:
    pid_t pid_ = -1;
    int master_ = -1;
    QByteArray line_;
    long long frames_ = 0;
};

} // namespace

class TestRecord : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        if (QStandardPaths::findExecutable("ffprobe").isEmpty())
            QFAIL("ffprobe is missing: .ci/install-deps.sh installs it (Debian's ffmpeg package) to read the "
                  "clips back");
    }

    void clipsHaveTheirCodecFramesSizeAndDuration_data() {
        QTest::addColumn<QString>("suffix");
        QTest::addColumn<QString>("codec");
        QTest::newRow("mp4") << "mp4"
                             << "h264";
        QTest::newRow("webm") << "webm"
                              << "vp9";
        QTest::newRow("gif") << "gif"
                             << "gif";
    }
    void clipsHaveTheirCodecFramesSizeAndDuration() {
        QFETCH(QString, suffix);
        QFETCH(QString, codec);
        QTemporaryDir dir;
        const QString out = dir.filePath("clip." + suffix);
        const auto r = runCli(recordArgs(out, 2.0));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const Probe p = ffprobe(out);
        QCOMPARE(p.codec, codec);
        QCOMPARE(p.frames, 2LL * kFps);
        QCOMPARE(QSize(p.width, p.height), kSize);
        // GIF delays are whole centiseconds: 10 frames/s is exact there too.
        QVERIFY2(std::abs(p.duration - 2.0) < 0.05, qPrintable(QString::number(p.duration)));
    }

    // A decoded frame is the off-screen render of the state after frame × steps-per-frame steps.
    void decodedFrameMatchesTheRenderedState_data() {
        QTest::addColumn<QString>("suffix");
        QTest::newRow("mp4") << "mp4";
        QTest::newRow("webm") << "webm";
    }
    void decodedFrameMatchesTheRenderedState() {
        QFETCH(QString, suffix);
        QTemporaryDir dir;
        const QString out = dir.filePath("clip." + suffix);
        const auto r = runCli(recordArgs(out) + QStringList{"--no-captions"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        constexpr int kFrame = 7;
        const QImage decoded = decodeFrame(out, kFrame);
        QCOMPARE(decoded.size(), kSize);
        const QImage rendered = renderedState("gas-classroom", kFrame * kSteps);
        const double db = psnr(rendered, decoded);
        qInfo("%s frame %d: PSNR %.1f dB (4:2:0 alone: %.1f dB)", qPrintable(suffix), kFrame, db,
              psnr(rendered, throughYuv420(rendered)));
        QVERIFY2(db >= 35.0, qPrintable(QString::number(db)));
        // Another state is far from it: the frame is this state, not any picture of the scene.
        QVERIFY(psnr(renderedState("gas-classroom", (kFrame + 3) * kSteps), decoded) < db - 3.0);
    }

    // The app takes a frame after every 10 steps inside the stepping, so frames of 3 steps (which a clip
    // frame falls inside of) still give the states after 0, 10, 20, … steps: the clip does not depend
    // on the frame rate.
    void appRecordingTakesAFrameEveryTenStepsWhateverTheFrameRate() {
        QTemporaryDir dir;
        const QString out = dir.filePath("app.mp4");
        pl::ui::SimulationController controller;
        controller.setBackend(pl::gl::Backend::Cpu);
        QVERIFY(controller.load(pl::loadPreset("gas-classroom")).isEmpty());
        controller.setStepsPerFrame(3);
        pl::ui::AppRecorder recorder(&controller);
        pl::ui::AppClipOptions tenSteps;
        tenSteps.stepsPerFrame = pl::ui::kAppStepsPerClipFrame;
        QVERIFY(recorder.start(out, "gas-classroom", tenSteps).isEmpty());
        QVERIFY(recorder.isRecording());
        for (int frame = 0; frame < 130; ++frame) controller.advanceFrame(); // 390 steps
        QSignalSpy finished(&recorder, &pl::ui::AppRecorder::finished);
        recorder.stop();
        QVERIFY(!recorder.isRecording());
        QVERIFY(finished.count() == 1 ||
                finished.wait(30000)); // the last frames encode off the window's thread
        QVERIFY2(finished.front().front().toString().startsWith("Clip saved"),
                 qPrintable(finished.front().front().toString()));
        QCOMPARE(recorder.frames(), 40LL); // after 0, 10, …, 390 steps
        QCOMPARE(recorder.framesInLastClip(), 40LL);
        // Without a number of steps, a clip frame is taken at the scene's watchable pace.
        QVERIFY(recorder.start(dir.filePath("paced.mp4"), "gas-classroom").isEmpty());
        QCOMPARE(recorder.options().stepsPerFrame,
                 pl::ui::watchableStepsPerFrame(controller, pl::ui::kAppClipFps));
        QVERIFY(recorder.options().stepsPerFrame >
                pl::ui::kAppStepsPerClipFrame); // 476 for the classroom gas
        recorder.finishNow();
        const Probe p = ffprobe(out);
        QCOMPARE(p.codec, QString("h264"));
        QCOMPARE(p.frames, 40LL);
        QCOMPARE(QSize(p.width, p.height), pl::ui::kAppClipSize);
        constexpr int kFrame = 35; // after the title's opening second
        pl::ui::ClipLook look;
        look.size = pl::ui::kAppClipSize;
        look.fps = pl::ui::kAppClipFps;
        look.title = "gas-classroom";
        look.timeUnit = "T";
        const auto model = stateAfter("gas-classroom", kFrame * pl::ui::kAppStepsPerClipFrame);
        const QImage expected = pl::ui::clipFrame(look, model->sceneView(), model->time(), kFrame);
        const double db = psnr(expected, decodeFrame(out, kFrame));
        qInfo("app frame %d: PSNR %.1f dB", kFrame, db);
        QVERIFY2(db >= 35.0, qPrintable(QString::number(db)));
    }

    // The Record dialog's choices reach the clip: size, frame rate, steps per frame, the plot beside the
    // scene (its share of the width) and the captions switched off.
    void appRecordingFollowsTheChosenOptions() {
        QTemporaryDir dir;
        const QString out = dir.filePath("options.webm");
        pl::ui::SimulationController controller;
        controller.setBackend(pl::gl::Backend::Cpu);
        QVERIFY(controller.load(pl::loadPreset("gas-classroom")).isEmpty());
        controller.setStepsPerFrame(2);
        pl::ui::AppRecorder recorder(&controller);
        pl::ui::AppClipOptions options;
        options.size = QSize(640, 360);
        options.fps = 12;
        options.stepsPerFrame = 7;
        options.captions = false;
        options.plot = "energyPlot";
        QVERIFY(recorder.start(out, "gas-classroom", options).isEmpty());
        for (int frame = 0; frame < 35; ++frame)
            controller.advanceFrame(); // 70 steps: frames after 0, 7, …, 70
        QSignalSpy finished(&recorder, &pl::ui::AppRecorder::finished);
        recorder.stop();
        QVERIFY(finished.count() == 1 || finished.wait(30000));
        QCOMPARE(recorder.frames(), 11LL);
        const Probe p = ffprobe(out);
        QCOMPARE(p.codec, QString("vp9"));
        QCOMPARE(p.frames, 11LL);
        QCOMPARE(QSize(p.width, p.height), options.size);
        QVERIFY2(std::abs(p.duration - 11.0 / 12) < 0.1, qPrintable(QString::number(p.duration)));
        // The scene's part of the last frame is the bare scene after 70 steps; the plot fills the rest.
        const QImage decoded = decodeFrame(out, 10);
        const int sceneWidth = 640 - static_cast<int>(std::lround(pl::ui::kClipPlotShare * 640));
        const auto model = stateAfter("gas-classroom", 70);
        const QImage scene = pl::ui::renderScene(model->sceneView(), QSize(sceneWidth, 360));
        const double db = psnr(scene, decoded.copy(0, 0, sceneWidth, 360));
        qInfo("scene beside the plot: PSNR %.1f dB", db);
        QVERIFY2(db >= 30.0, qPrintable(QString::number(db)));
        QVERIFY(psnr(scene, decoded.copy(640 - sceneWidth, 0, sceneWidth, 360)) < db - 3.0);
    }

    // Stop with frames still waiting for a slow encoder: they drain in the background (draining() counts
    // them down) and Cancel drops the rest; the clip is finished and plays the frames encoded.
    void cancellingTheDrainKeepsAPlayableClip() {
        QTemporaryDir dir;
        const QString out = dir.filePath("drain.webm");
        pl::ui::SimulationController controller;
        controller.setBackend(pl::gl::Backend::Cpu);
        QVERIFY(controller.load(pl::loadPreset("gas-classroom")).isEmpty());
        controller.setStepsPerFrame(1);
        pl::ui::AppRecorder recorder(&controller);
        pl::ui::AppClipOptions options;
        options.size = QSize(3840, 2160); // VP9 at 4K: far slower than taking a frame
        options.stepsPerFrame = 1;
        QVERIFY(recorder.start(out, "gas-classroom", options).isEmpty());
        for (int frame = 0; frame < 60; ++frame) controller.advanceFrame();
        QCOMPARE(recorder.frames(), 61LL); // the state at the start, then one a step
        QSignalSpy draining(&recorder, &pl::ui::AppRecorder::draining);
        QSignalSpy finished(&recorder, &pl::ui::AppRecorder::finished);
        recorder.stop();
        QVERIFY(recorder.isDraining());
        QCOMPARE(draining.count(), 1);
        const long long queued = draining.front().at(1).toLongLong();
        QVERIFY2(queued > 10, qPrintable(QString::number(queued)));
        QCOMPARE(recorder.start(dir.filePath("next.mp4"), "x"),
                 QString("The previous clip is still being finished."));
        recorder.cancelDraining();
        QVERIFY(finished.count() == 1 || finished.wait(60000));
        const QString sentence = finished.front().front().toString();
        QVERIFY2(sentence.startsWith("Encoding cancelled"), qPrintable(sentence));
        QVERIFY(!recorder.isDraining());
        const long long encoded = recorder.framesInLastClip();
        QVERIFY2(encoded > 0 && encoded < 61, qPrintable(QString::number(encoded)));
        QCOMPARE(ffprobe(out).frames, encoded);
    }

    // At the automatic pace an encoder that falls behind holds the steps, not the window: once its queue is
    // full a frame takes no more steps and is shown on time, and every step still gives its clip frame.
    // (Waiting for room inside the step loop made each frame as long as a 4K VP9 frame's encoding.)
    void aSlowEncoderHoldsTheAutomaticPaceNotTheWindow() {
        QTemporaryDir dir;
        pl::ui::SimulationController controller;
        controller.setBackend(pl::gl::Backend::Cpu);
        QVERIFY(controller.load(pl::loadPreset("gas-classroom")).isEmpty());
        controller.setAutomaticPace();
        pl::ui::AppRecorder recorder(&controller);
        pl::ui::AppClipOptions options;
        options.size = QSize(3840, 2160);
        options.stepsPerFrame = 1;
        QVERIFY(recorder.start(dir.filePath("behind.webm"), "gas-classroom", options).isEmpty());
        const long long first = controller.model()->stepCount();
        qint64 longest = 0;
        QElapsedTimer clock;
        for (int frame = 0; frame < 30; ++frame) {
            QTest::qWait(16); // a 60 Hz frame's wall time, for the pace to allow its steps
            clock.start();
            controller.advanceFrame();
            longest = std::max(longest, clock.elapsed());
        }
        const long long steps = controller.model()->stepCount() - first;
        const long long queued = recorder.isRecording() ? recorder.frames() : -1;
        QSignalSpy finished(&recorder, &pl::ui::AppRecorder::finished);
        recorder.stop();
        recorder.cancelDraining();
        QVERIFY(finished.count() == 1 || finished.wait(60000));
        qInfo("30 frames beside a 4K VP9 encoder: %lld steps, the longest frame %lld ms", steps, longest);
        QCOMPARE(queued, steps + 1); // a clip frame after every step: none dropped
        QVERIFY2(steps > 0, "the scene went on");
        // The step share of a frame and one clip frame's capture, with room for a loaded machine; one
        // frame encoded at 4K takes about a second here.
        QVERIFY2(longest < 250, qPrintable(QString::number(longest)));
    }

    void gifLoopsForEver() {
        QTemporaryDir dir;
        const QString out = dir.filePath("clip.gif");
        QVERIFY(runCli(recordArgs(out)).exitCode == 0);
        QFile file(out);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        const qsizetype at = bytes.indexOf("NETSCAPE2.0");
        QVERIFY2(at > 0, "no looping extension");
        QCOMPARE(bytes.mid(at + 11, 4), QByteArray("\x03\x01\x00\x00", 4)); // loop count 0: for ever
        QCOMPARE(bytes.back(), '\x3b');                                     // the GIF trailer
    }

    void sigintLeavesAPlayableClipOfTheFramesSoFar_data() {
        QTest::addColumn<QString>("suffix");
        QTest::newRow("mp4") << "mp4";
        QTest::newRow("webm") << "webm";
    }
    void sigintLeavesAPlayableClipOfTheFramesSoFar() {
        QFETCH(QString, suffix);
        QTemporaryDir dir;
        const QString out = dir.filePath("clip." + suffix);
        QProcess p;
        QStringList args = recordArgs(out, 600.0);
        args.removeAll("--quiet");
        p.start(PARTICLELAB_CLI, args);
        QVERIFY(p.waitForStarted());
        QElapsedTimer clock;
        clock.start();
        while (QFileInfo(out).size() < 20000 && clock.elapsed() < 30000) QTest::qWait(50);
        QVERIFY2(QFileInfo(out).size() >= 20000, "no frames were written while the recording went on");
        ::kill(static_cast<pid_t>(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 130);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        const QRegularExpression said("holds the (\\d+) frames");
        const auto match = said.match(err);
        QVERIFY2(match.hasMatch(), qPrintable(err));
        const Probe probe = ffprobe(out);
        QCOMPARE(probe.frames, match.captured(1).toLongLong());
        QVERIFY(probe.frames > 0 && probe.frames < 600LL * kFps);
    }

    // A recording killed outright (SIGKILL: `kill -9`, the out-of-memory killer) runs no handler and
    // finishes nothing: what is on disk must decode as it is, without an error, and hold every frame but
    // about the last second's. The container writes whole pieces of at most a second (an MP4 fragment, a
    // WebM cluster, a GIF frame), so the open piece and the few frames in the encoder (x264's look-ahead)
    // and in the writer's queue are lost: two seconds of frames at most.
    void aKilledRecordingDecodesUpToItsLastSecond_data() {
        QTest::addColumn<QString>("suffix");
        QTest::newRow("mp4") << "mp4";
        QTest::newRow("webm") << "webm";
        QTest::newRow("gif") << "gif";
    }
    void aKilledRecordingDecodesUpToItsLastSecond() {
        QFETCH(QString, suffix);
        constexpr int fps = 25;
        constexpr long long killAt = 4 * fps; // four seconds of clip made
        QTemporaryDir dir;
        const QString out = dir.filePath("killed." + suffix);
        QStringList args = recordArgs(out, 600.0, {"--fps", QString::number(fps), "--size", "640x360"});
        args.removeAll("--quiet");
        TerminalRun run(args);
        QVERIFY2(run.started(), "particlelab-cli did not start on a pseudo-terminal");
        const long long made = run.waitForFrame(killAt, 60000);
        QVERIFY2(made >= killAt, qPrintable(QString("the progress line stopped at frame %1").arg(made)));
        QVERIFY(run.kill());
        const Probe probe = ffprobe(out);
        qInfo("%s killed after frame %lld: %lld frames decode", qPrintable(suffix), made, probe.frames);
        QVERIFY2(probe.errors.isEmpty(), qPrintable(probe.errors));
        QCOMPARE(QSize(probe.width, probe.height), QSize(640, 360));
        QVERIFY2(probe.frames >= made - 2 * fps && probe.frames <= made + fps,
                 qPrintable(QString("%1 of %2 frames").arg(probe.frames).arg(made)));
        if (suffix == "gif") {
            QFile file(out);
            QVERIFY(file.open(QIODevice::ReadOnly));
            QVERIFY2(gifEndsAfterAWholeBlock(file.readAll()), "the GIF ends inside a frame");
        }
    }

    void badOptionsAreRefusedBeforeAnythingRuns_data() {
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<QString>("out");
        QTest::addColumn<QString>("message");
        QTest::newRow("suffix") << QStringList{} << "clip.avi"
                                << "needs the suffix of a clip format";
        QTest::newRow("odd size") << QStringList{"--size", "1281x720"} << "clip.mp4"
                                  << "odd side";
        QTest::newRow("zero") << QStringList{"--size", "0x720"} << "clip.mp4"
                              << "too small";
        QTest::newRow("beyond 8K") << QStringList{"--size", "7682x4320"} << "clip.webm"
                                   << "larger than 7680x4320";
        QTest::newRow("not a size") << QStringList{"--size", "big"} << "clip.gif"
                                    << "is not a size";
        QTest::newRow("fps 0") << QStringList{"--fps", "0"} << "clip.mp4"
                               << "--fps";
        QTest::newRow("seconds") << QStringList{"--seconds", "-1"} << "clip.mp4"
                                 << "--seconds";
        QTest::newRow("fraction of a frame") << QStringList{"--seconds", "0.05"} << "clip.mp4"
                                             << "whole number";
        QTest::newRow("plot") << QStringList{"--plot", "noSuchPlot"} << "clip.mp4"
                              << "is no plot of a gas scene";
    }
    void badOptionsAreRefusedBeforeAnythingRuns() {
        QFETCH(QStringList, options);
        QFETCH(QString, out);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const auto r = runCli(recordArgs(dir.filePath(out), 1.0, options));
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QCOMPARE(r.err.count('\n'), 1); // one sentence
        QVERIFY(!QFileInfo::exists(dir.filePath(out)));
    }

    // The clip's format, size and frames are checked by particlelab-cli itself (core/media/ClipFormat.h),
    // before it starts the media program: a copy of it alone, without particlelab-cli-media beside it,
    // still refuses a bad clip in its sentence, and says what is missing only for a good one.
    void badClipsAreRefusedWithoutTheMediaProgram() {
        QTemporaryDir dir;
        const QString alone = dir.filePath("particlelab-cli");
        QVERIFY(QFile::copy(PARTICLELAB_CLI, alone));
        const auto refused = pl::test::runProgram(alone, recordArgs(dir.filePath("clip.avi"), 1.0));
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains("needs the suffix of a clip format"), qPrintable(refused.err));
        const auto odd =
            pl::test::runProgram(alone, recordArgs(dir.filePath("clip.mp4"), 1.0, {"--size", "1281x720"}));
        QCOMPARE(odd.exitCode, 2);
        QVERIFY2(odd.err.contains("odd side"), qPrintable(odd.err));
        if (QFileInfo::exists(PARTICLELAB_MEDIA_PROGRAM_INSTALLED)) return; // installed: the copy finds it
        const auto good = pl::test::runProgram(alone, recordArgs(dir.filePath("clip.mp4"), 1.0));
        QCOMPARE(good.exitCode, 2);
        QVERIFY2(good.err.contains("particlelab-cli-media"), qPrintable(good.err));
    }

    void anInputIsNeverTheOutput() {
        QTemporaryDir dir;
        const QString preset = dir.filePath("mine.gif"); // a preset file, oddly named
        QFile::copy(QString(PARTICLELAB_TEST_DATA) + "/../../resources/presets/gas/gas-classroom.json",
                    preset);
        QVERIFY(QFileInfo::exists(preset));
        QStringList args = recordArgs(preset);
        args[1] = preset;
        const QByteArray before = [&] {
            QFile f(preset);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        }();
        const auto r = runCli(args);
        QCOMPARE(r.exitCode, 2);
        QFile f(preset);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), before);
    }
};

QTEST_MAIN(TestRecord)
#include "tst_record.moc"
