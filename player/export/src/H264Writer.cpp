#include "H264Writer.h"

#include <lacrima/common/Diagnostics.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <unistd.h>
#include <cstdio>
#include <filesystem>

namespace lacrima::exporting {
namespace {

std::string averror(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

struct CodecDeleter {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct FrameDeleter {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct PacketDeleter {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct ScaleDeleter {
  void operator()(SwsContext* s) const { sws_freeContext(s); }
};
// An output context with its file.
struct FormatDeleter {
  void operator()(AVFormatContext* f) const {
    if (f->pb) avio_closep(&f->pb);
    avformat_free_context(f);
  }
};

}  // namespace

struct H264Writer::State {
  std::string path, temporary;
  QSize size;
  std::unique_ptr<AVFormatContext, FormatDeleter> format;
  std::unique_ptr<AVCodecContext, CodecDeleter> codec;
  std::unique_ptr<AVFrame, FrameDeleter> frame;
  std::unique_ptr<AVPacket, PacketDeleter> packet;
  std::unique_ptr<SwsContext, ScaleDeleter> scale;
  AVStream* stream = nullptr;
  std::int64_t next = 0;
  bool finished = false;

  [[noreturn]] void fail(const std::string& what, int code) const {
    throw FileError({path, 0, 0}, what + (code < 0 ? ": " + averror(code) : std::string()));
  }

  // Sends `f` (null: the end) and writes every packet the encoder has ready.
  void encode(const AVFrame* f) {
    int status = avcodec_send_frame(codec.get(), f);
    if (status < 0) fail("cannot encode the video", status);
    while ((status = avcodec_receive_packet(codec.get(), packet.get())) >= 0) {
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      status = av_interleaved_write_frame(format.get(), packet.get());
      if (status < 0) fail("cannot write the video", status);
    }
    if (status != AVERROR(EAGAIN) && status != AVERROR_EOF) fail("cannot encode the video", status);
  }
};

H264Writer::H264Writer(const std::string& path, QSize size, double fps)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = path;
  s.size = size;
  if (size.width() % 2 || size.height() % 2)
    s.fail("cannot write " + std::to_string(size.width()) + "x" + std::to_string(size.height()) +
               " as H.264 (yuv420p): width and height must be even",
           0);
  // A hidden name beside the target (the rename stays on one file system), one per process.
  const std::filesystem::path target(path);
  std::string hidden(".");
  hidden += target.filename().string();
  hidden += ".part-";
  hidden += std::to_string(::getpid());
  s.temporary = (target.parent_path() / hidden).string();
  AVFormatContext* format = nullptr;
  int status = avformat_alloc_output_context2(&format, nullptr, "mp4", s.temporary.c_str());
  if (status < 0 || !format) s.fail("cannot make an MP4 file", status);
  s.format.reset(format);
  // libx264 when Debian's FFmpeg has it (it does), else whatever H.264 encoder there is.
  const AVCodec* encoder = avcodec_find_encoder_by_name("libx264");
  if (!encoder) encoder = avcodec_find_encoder(AV_CODEC_ID_H264);
  if (!encoder)
    s.fail("cannot write H.264: FFmpeg has no H.264 encoder (libavcodec59 with libx264)", 0);
  s.stream = avformat_new_stream(format, nullptr);
  s.codec.reset(avcodec_alloc_context3(encoder));
  if (!s.stream || !s.codec) s.fail("out of memory for the video encoder", 0);
  AVCodecContext& c = *s.codec;
  const AVRational rate = av_d2q(fps, 100000);
  c.width = size.width();
  c.height = size.height();
  c.pix_fmt = AV_PIX_FMT_YUV420P;
  c.framerate = rate;
  c.time_base = av_inv_q(rate);
  c.gop_size = std::max(1, static_cast<int>(std::lround(fps)) * 2);
  c.color_range = AVCOL_RANGE_MPEG;
  c.colorspace = AVCOL_SPC_BT709;
  c.color_primaries = AVCOL_PRI_BT709;
  c.color_trc = AVCOL_TRC_BT709;
  if (format->oformat->flags & AVFMT_GLOBALHEADER) c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* options = nullptr;
  // Visually lossless for faces and water (crf 18), fast to encode; "main" profile plays on
  // every common player.
  av_dict_set(&options, "crf", "18", 0);
  av_dict_set(&options, "preset", "fast", 0);
  av_dict_set(&options, "profile", "main", 0);
  // x264's bitstream depends on its thread count, which "auto" takes from the machine's cores:
  // a fixed count gives the same bytes on every machine (batches compare them, docs/batch.md).
  c.thread_count = 4;
  status = avcodec_open2(&c, encoder, &options);
  av_dict_free(&options);
  if (status < 0) s.fail("cannot open the H.264 encoder", status);
  status = avcodec_parameters_from_context(s.stream->codecpar, &c);
  if (status < 0) s.fail("cannot set up the video stream", status);
  s.stream->time_base = c.time_base;
  s.stream->avg_frame_rate = rate;
  s.stream->r_frame_rate = rate;
  status = avio_open(&format->pb, s.temporary.c_str(), AVIO_FLAG_WRITE);
  if (status < 0) s.fail("cannot create the file", status);
  AVDictionary* muxerOptions = nullptr;
  av_dict_set(&muxerOptions, "movflags", "+faststart", 0);
  status = avformat_write_header(format, &muxerOptions);
  av_dict_free(&muxerOptions);
  if (status < 0) s.fail("cannot write the MP4 header", status);
  s.frame.reset(av_frame_alloc());
  s.packet.reset(av_packet_alloc());
  if (!s.frame || !s.packet) s.fail("out of memory for the video encoder", 0);
  s.frame->format = c.pix_fmt;
  s.frame->width = c.width;
  s.frame->height = c.height;
  status = av_frame_get_buffer(s.frame.get(), 0);
  if (status < 0) s.fail("out of memory for a video frame", status);
  // RGBA to BT.709 limited-range yuv420p, as the stream says.
  s.scale.reset(
      sws_getContext(c.width, c.height, AV_PIX_FMT_RGBA, c.width, c.height, AV_PIX_FMT_YUV420P,
                     // swscale's SIMD paths round differently from its C path and
                     // from each other; bit-exact rounding is the same on every CPU.
                     SWS_BICUBIC | SWS_BITEXACT | SWS_ACCURATE_RND, nullptr, nullptr, nullptr));
  if (!s.scale) s.fail("cannot convert RGBA to yuv420p", 0);
  sws_setColorspaceDetails(s.scale.get(), sws_getCoefficients(SWS_CS_ITU709), 1,
                           sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16, 1 << 16);
}

H264Writer::~H264Writer() {
  if (!state_->finished && !state_->temporary.empty()) {
    state_->format.reset();
    std::error_code ignored;
    std::filesystem::remove(state_->temporary, ignored);
  }
}

void H264Writer::write(const QImage& image) {
  State& s = *state_;
  QImage rgba = image.convertToFormat(QImage::Format_RGBA8888);
  if (rgba.size() != s.size)
    rgba = rgba.scaled(s.size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
  const int status = av_frame_make_writable(s.frame.get());
  if (status < 0) s.fail("out of memory for a video frame", status);
  const std::uint8_t* source[1] = {rgba.constBits()};
  const int stride[1] = {static_cast<int>(rgba.bytesPerLine())};
  sws_scale(s.scale.get(), source, stride, 0, rgba.height(), s.frame->data, s.frame->linesize);
  s.frame->pts = s.next++;
  s.encode(s.frame.get());
}

void H264Writer::finish() {
  State& s = *state_;
  s.encode(nullptr);
  const int status = av_write_trailer(s.format.get());
  if (status < 0) s.fail("cannot finish the MP4 file", status);
  s.format.reset();  // closes the file
  std::error_code error;
  std::filesystem::rename(s.temporary, s.path, error);
  if (error) s.fail("cannot move the finished video into place: " + error.message(), 0);
  s.finished = true;
}

std::string H264Writer::encoderName() const { return state_->codec->codec->name; }

}  // namespace lacrima::exporting
