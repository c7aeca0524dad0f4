// VideoEncoder: one output stream, frames numbered in the clip's time base (1/fps), each packet handed to
// the muxer as soon as the encoder gives it. Each container is written in whole pieces that play on their
// own: MP4 fragmented (a fragment per key frame, one a second), WebM in clusters of at most a second, GIF
// a frame at a time; each piece reaches the operating system the moment the muxer has it, so a process
// killed outright (SIGKILL) leaves a file that ends after a whole piece and decodes without error up to
// about its last second. The trailer is written on every orderly path. GIF: libavcodec's gif encoder on
// 8-bit indexed frames with a palette made once for the clip from its first frame (median cut) plus the
// scene's colour scale, so a clip never changes colours between frames and each frame is written the
// moment it is made (the palettegen filter needs the whole clip before the first frame).
#include "VideoEncoder.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <QPainter>
#include <algorithm>
#include <array>
#include <cstring>

namespace pl::ui {

namespace {

constexpr int kX264Crf = 14;        // PSNR ≥ 35 dB against the drawn frame for a moving gas at 720p
constexpr int kVp9Crf = 18;         // libvpx-vp9 constant quality (0 best … 63): ≥ 35 dB as H.264
constexpr int kVp9CpuUsed = 8;      // the fastest realtime setting: encodes 720p at ≥ 30 frames/s
constexpr int kClusterMs = 1000;    // WebM: a cluster (what a killed recording may lose) holds ≤ 1 s
constexpr int kGifColours = 256;    // an 8-bit GIF palette
constexpr int kGifHintColours = 32; // of which the scene's colour scale may take up to this many
constexpr int kBinBits = 5;         // palette histogram and look-up table: 5 bits per channel
constexpr int kBins = 1 << (3 * kBinBits);

std::string avError(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

int binOf(QRgb c) {
    return ((qRed(c) >> (8 - kBinBits)) << (2 * kBinBits)) | ((qGreen(c) >> (8 - kBinBits)) << kBinBits) |
           (qBlue(c) >> (8 - kBinBits));
}

std::array<int, 3> binCentre(int bin) {
    constexpr int mask = (1 << kBinBits) - 1, half = 1 << (7 - kBinBits);
    return {((bin >> (2 * kBinBits)) & mask) << (8 - kBinBits) | half,
            ((bin >> kBinBits) & mask) << (8 - kBinBits) | half, (bin & mask) << (8 - kBinBits) | half};
}

} // namespace

struct VideoEncoder::Impl {
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    SwsContext* scale = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    std::string codecName;
    std::vector<QRgb> palette;        // GIF
    std::vector<std::uint8_t> lookup; // GIF: histogram bin → palette index
    bool headerWritten = false;

    ~Impl() {
        av_packet_free(&packet);
        av_frame_free(&frame);
        sws_freeContext(scale);
        avcodec_free_context(&codec);
        if (format) {
            if (format->pb) avio_closep(&format->pb);
            avformat_free_context(format);
        }
    }
};

VideoEncoder::VideoEncoder(const std::string& path, int width, int height, int fps,
                           std::vector<QRgb> paletteHints, EncoderShare share)
    : d_(std::make_unique<Impl>()), width_(width), height_(height), fps_(fps),
      paletteHints_(std::move(paletteHints)) {
    const auto format = clipFormatOf(path);
    if (!format) throw VideoError("'" + path + "' has no clip suffix: use .mp4, .webm or .gif");
    format_ = *format;
    if (const std::string refusal = clipSizeRefusal(format_, width, height); !refusal.empty())
        throw VideoError(refusal);

    av_log_set_level(AV_LOG_ERROR); // the encoders' statistics are not the program's output
    const char* muxer = format_ == ClipFormat::Mp4 ? "mp4" : format_ == ClipFormat::WebM ? "webm" : "gif";
    if (avformat_alloc_output_context2(&d_->format, nullptr, muxer, path.c_str()) < 0 || !d_->format)
        throw VideoError(std::string("this FFmpeg has no ") + muxer + " writer");
    const AVCodec* codec = nullptr;
    switch (format_) {
    case ClipFormat::Mp4:
        codec = avcodec_find_encoder_by_name("libx264");
        if (!codec) codec = avcodec_find_encoder(AV_CODEC_ID_H264);
        break;
    case ClipFormat::WebM:
        codec = avcodec_find_encoder_by_name("libvpx-vp9");
        if (!codec) codec = avcodec_find_encoder(AV_CODEC_ID_VP9);
        break;
    case ClipFormat::Gif:
        codec = avcodec_find_encoder(AV_CODEC_ID_GIF);
        break;
    }
    if (!codec) throw VideoError("this FFmpeg has no encoder for " + clipFormatName(format_));
    d_->codecName = codec->name;

    d_->codec = avcodec_alloc_context3(codec);
    AVCodecContext* c = d_->codec;
    c->width = width;
    c->height = height;
    c->time_base = AVRational{1, fps};
    c->framerate = AVRational{fps, 1};
    c->gop_size = fps; // a key frame (and an MP4 fragment) every second
    const bool alone = share == EncoderShare::Alone;
    c->thread_count = alone ? 0 : 1; // 0: the encoder's own choice of threads
    c->pix_fmt = format_ == ClipFormat::Gif ? AV_PIX_FMT_PAL8 : AV_PIX_FMT_YUV420P;
    if (d_->format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* options = nullptr;
    if (d_->codecName == "libx264") {
        av_dict_set(&options, "preset", alone ? "veryfast" : "ultrafast", 0);
        av_dict_set_int(&options, "crf", kX264Crf, 0);
    } else if (d_->codecName == "libvpx-vp9") {
        c->bit_rate = 0; // constant quality
        av_dict_set(&options, "deadline", "realtime", 0);
        // Realtime encoding needs no frames ahead, yet libvpx's default look-ahead of 25 frames held back a
        // second more of what a killed recording loses; without it the clip of the classroom gas at 720p
        // is the same size and quality.
        av_dict_set_int(&options, "lag-in-frames", 0, 0);
        av_dict_set_int(&options, "cpu-used", kVp9CpuUsed, 0);
        av_dict_set_int(&options, "row-mt", alone ? 1 : 0, 0);
        av_dict_set_int(&options, "tile-columns", 2, 0); // log2: 4 columns, encoded side by side
        av_dict_set_int(&options, "crf", kVp9Crf, 0);
    }
    const int opened = avcodec_open2(c, codec, &options);
    av_dict_free(&options);
    if (opened < 0)
        throw VideoError("the " + d_->codecName + " encoder refused the clip: " + avError(opened));

    d_->stream = avformat_new_stream(d_->format, nullptr);
    if (!d_->stream) throw VideoError("no memory for the clip's stream");
    d_->stream->time_base = c->time_base;
    d_->stream->avg_frame_rate = c->framerate;
    avcodec_parameters_from_context(d_->stream->codecpar, c);

    if (const int e = avio_open(&d_->format->pb, path.c_str(), AVIO_FLAG_WRITE); e < 0)
        throw VideoError("cannot write '" + path + "': " + avError(e));
    AVDictionary* muxOptions = nullptr;
    if (format_ == ClipFormat::Mp4)
        av_dict_set(&muxOptions, "movflags", "frag_keyframe+empty_moov+default_base_moof", 0);
    // Matroska starts a cluster at a key frame only once the open one holds 4 KiB: a nearly still scene
    // would otherwise fill clusters of up to 5 s, all of which a killed recording loses.
    if (format_ == ClipFormat::WebM) av_dict_set_int(&muxOptions, "cluster_time_limit", kClusterMs, 0);
    if (format_ == ClipFormat::Gif) av_dict_set_int(&muxOptions, "loop", 0, 0); // 0: loop for ever
    const int header = avformat_write_header(d_->format, &muxOptions);
    av_dict_free(&muxOptions);
    if (header < 0) throw VideoError("cannot write the start of '" + path + "': " + avError(header));
    avio_flush(d_->format->pb); // a clip killed before its first piece still names its stream
    d_->headerWritten = true;

    d_->frame = av_frame_alloc();
    d_->frame->format = c->pix_fmt;
    d_->frame->width = width;
    d_->frame->height = height;
    if (av_frame_get_buffer(d_->frame, 0) < 0) throw VideoError("no memory for a frame of the clip");
    d_->packet = av_packet_alloc();
    if (format_ != ClipFormat::Gif) {
        // QImage::Format_RGB32 is 0xffRRGGBB in native order: FFmpeg's AV_PIX_FMT_RGB32.
        d_->scale = sws_getContext(width, height, AV_PIX_FMT_RGB32, width, height, AV_PIX_FMT_YUV420P,
                                   SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
        if (!d_->scale) throw VideoError("no colour conversion to YUV 4:2:0 in this libswscale");
    }
}

VideoEncoder::~VideoEncoder() {
    try {
        finish();
    } catch (...) { // a destructor that runs while unwinding must not throw
    }
}

std::string VideoEncoder::codecDescription() const {
    switch (format_) {
    case ClipFormat::Mp4:
        return "H.264 (" + d_->codecName + ")";
    case ClipFormat::WebM:
        return "VP9 (" + d_->codecName + ")";
    case ClipFormat::Gif:
        return "GIF (" + d_->codecName + ", one palette for the clip)";
    }
    return d_->codecName;
}

void VideoEncoder::write(const QImage& image) {
    if (finished_) throw VideoError("the clip is already finished");
    QImage rgb = image.size() == QSize(width_, height_) ? image : image.scaled(width_, height_);
    if (rgb.format() != QImage::Format_RGB32) rgb = rgb.convertToFormat(QImage::Format_RGB32);
    if (av_frame_make_writable(d_->frame) < 0) throw VideoError("no memory for a frame of the clip");
    if (format_ == ClipFormat::Gif) {
        mapToPalette(rgb);
    } else {
        const std::uint8_t* source[1] = {rgb.constBits()};
        const int stride[1] = {static_cast<int>(rgb.bytesPerLine())};
        sws_scale(d_->scale, source, stride, 0, height_, d_->frame->data, d_->frame->linesize);
    }
    d_->frame->pts = frames_;
    try {
        encode(false);
    } catch (const VideoError&) {
        failed_ = true;
        throw;
    }
    ++frames_;
}

void VideoEncoder::encode(bool flush) {
    const int sent = avcodec_send_frame(d_->codec, flush ? nullptr : d_->frame);
    if (sent < 0 && sent != AVERROR_EOF) throw VideoError("the encoder refused a frame: " + avError(sent));
    for (;;) {
        const int got = avcodec_receive_packet(d_->codec, d_->packet);
        if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
        if (got < 0) throw VideoError("the encoder failed: " + avError(got));
        av_packet_rescale_ts(d_->packet, d_->codec->time_base, d_->stream->time_base);
        d_->packet->stream_index = d_->stream->index;
        const int written = av_interleaved_write_frame(d_->format, d_->packet); // takes the packet's data
        if (written < 0)
            throw VideoError("the clip could not be written (is the disk full?): " + avError(written));
        // The muxers build a fragment or cluster in memory and hand it over whole, so after a packet the
        // I/O buffer holds only whole pieces. Left there, they would reach the file in 32 KiB blocks that
        // cut a piece anywhere, and a killed process would leave a torn last piece that fails to decode.
        if (d_->format->pb) avio_flush(d_->format->pb);
        if (d_->format->pb && d_->format->pb->error < 0)
            throw VideoError("the clip could not be written (is the disk full?): " +
                             avError(d_->format->pb->error));
    }
}

void VideoEncoder::finish() {
    if (finished_ || !d_->headerWritten) return;
    finished_ = true;
    std::string problem;
    try {
        if (!failed_) encode(true);
    } catch (const VideoError& e) {
        problem = e.what();
    }
    const int trailer = av_write_trailer(d_->format);
    if (d_->format->pb) avio_closep(&d_->format->pb);
    if (problem.empty() && trailer < 0 && !failed_)
        problem = "the end of the clip could not be written: " + avError(trailer);
    if (!problem.empty() && !failed_) throw VideoError(problem);
}

// Median cut over a 5-bit-per-channel histogram of the first frame: boxes of colours are split along
// their longest side at the median pixel until there are enough; each entry is its box's mean colour.
std::vector<QRgb> VideoEncoder::gifPalette(const QImage& first) const {
    std::vector<std::uint32_t> count(kBins, 0);
    for (int y = 0; y < first.height(); ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(first.constScanLine(y));
        for (int x = 0; x < first.width(); ++x) ++count[static_cast<std::size_t>(binOf(line[x]))];
    }
    std::vector<QRgb> palette;
    for (QRgb hint : paletteHints_) {
        if (palette.size() >= static_cast<std::size_t>(kGifHintColours)) break;
        palette.push_back(hint | 0xff000000u);
    }
    struct Box {
        std::vector<int> bins;
        std::uint64_t pixels = 0;
    };
    std::vector<Box> boxes(1);
    for (int b = 0; b < kBins; ++b)
        if (count[static_cast<std::size_t>(b)] > 0) {
            boxes[0].bins.push_back(b);
            boxes[0].pixels += count[static_cast<std::size_t>(b)];
        }
    const std::size_t wanted = kGifColours - palette.size();
    while (boxes.size() < wanted) {
        // The box to split: the most pixels times the widest channel range, among those of two or more bins.
        int best = -1, bestAxis = 0;
        double bestScore = 0;
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            if (boxes[i].bins.size() < 2) continue;
            std::array<int, 3> lo{255, 255, 255}, hi{0, 0, 0};
            for (int b : boxes[i].bins) {
                const auto c = binCentre(b);
                for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
            }
            int axis = 0;
            for (int k = 1; k < 3; ++k)
                if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
            const double score = static_cast<double>(boxes[i].pixels) * (hi[axis] - lo[axis]);
            if (score > bestScore) bestScore = score, best = static_cast<int>(i), bestAxis = axis;
        }
        if (best < 0) break;
        Box& box = boxes[static_cast<std::size_t>(best)];
        std::sort(box.bins.begin(), box.bins.end(),
                  [bestAxis](int a, int b) { return binCentre(a)[bestAxis] < binCentre(b)[bestAxis]; });
        std::uint64_t seen = 0;
        std::size_t cut = 1;
        for (; cut < box.bins.size(); ++cut) {
            seen += count[static_cast<std::size_t>(box.bins[cut - 1])];
            if (2 * seen >= box.pixels) break;
        }
        cut = std::min(cut, box.bins.size() - 1);
        Box upper;
        upper.bins.assign(box.bins.begin() + static_cast<std::ptrdiff_t>(cut), box.bins.end());
        box.bins.resize(cut);
        box.pixels = 0;
        for (int b : box.bins) box.pixels += count[static_cast<std::size_t>(b)];
        for (int b : upper.bins) upper.pixels += count[static_cast<std::size_t>(b)];
        boxes.push_back(std::move(upper));
    }
    for (const Box& box : boxes) {
        if (box.pixels == 0) continue;
        std::array<double, 3> sum{};
        for (int b : box.bins) {
            const auto c = binCentre(b);
            for (int k = 0; k < 3; ++k)
                sum[k] += static_cast<double>(count[static_cast<std::size_t>(b)]) * c[k];
        }
        const auto mean = [&](int k) {
            return static_cast<int>(sum[k] / static_cast<double>(box.pixels) + 0.5);
        };
        palette.push_back(qRgb(mean(0), mean(1), mean(2)));
    }
    return palette;
}

void VideoEncoder::mapToPalette(const QImage& rgb) {
    if (d_->palette.empty()) {
        d_->palette = gifPalette(rgb);
        // Every bin's nearest palette entry, once: a frame then costs one look-up per pixel.
        d_->lookup.resize(kBins);
        for (int b = 0; b < kBins; ++b) {
            const auto c = binCentre(b);
            int best = 0, bestDistance = 1 << 30;
            for (std::size_t i = 0; i < d_->palette.size(); ++i) {
                const int dr = qRed(d_->palette[i]) - c[0], dg = qGreen(d_->palette[i]) - c[1],
                          db = qBlue(d_->palette[i]) - c[2];
                const int distance = 2 * dr * dr + 4 * dg * dg + 3 * db * db; // weighted as the eye does
                if (distance < bestDistance) bestDistance = distance, best = static_cast<int>(i);
            }
            d_->lookup[static_cast<std::size_t>(b)] = static_cast<std::uint8_t>(best);
        }
    }
    for (int y = 0; y < height_; ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
        std::uint8_t* out = d_->frame->data[0] + static_cast<std::ptrdiff_t>(y) * d_->frame->linesize[0];
        for (int x = 0; x < width_; ++x) out[x] = d_->lookup[static_cast<std::size_t>(binOf(line[x]))];
    }
    auto* palette = reinterpret_cast<std::uint32_t*>(d_->frame->data[1]);
    for (int i = 0; i < kGifColours; ++i)
        palette[i] =
            i < static_cast<int>(d_->palette.size()) ? d_->palette[static_cast<std::size_t>(i)] : 0xff000000u;
}

} // namespace pl::ui
