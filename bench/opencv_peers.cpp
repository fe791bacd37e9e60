#include "opencv_peers.h"

#include <opencv2/core.hpp>
#include <opencv2/ximgproc.hpp>

#include <cmath>
#include <cstring>
#include <memory>

namespace cgtmo::bench {

namespace {

// H x W x C float32 image from channels (each divided by its scale); background pixels as given.
cv::Mat guide_mat(const filters::GuidedInput& in, const std::vector<std::pair<filters::Channel, float>>& channels) {
  const int c = int(channels.size());
  cv::Mat m(in.height, in.width, CV_32FC(c));
  for (int y = 0; y < in.height; ++y) {
    float* row = m.ptr<float>(y);
    for (int x = 0; x < in.width; ++x) {
      const std::size_t i = std::size_t(y) * in.width + x;
      for (int k = 0; k < c; ++k) {
        const float v = channels[k].first[i] / channels[k].second;
        row[x * c + k] = std::isfinite(v) ? v : 0.0f;
      }
    }
  }
  return m;
}

cv::Mat signal_mat(const filters::GuidedInput& in) {
  cv::Mat m(in.height, in.width, CV_32FC1);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      const float v = in.log_lum[std::size_t(y) * in.width + x];
      m.at<float>(y, x) = std::isfinite(v) ? v : 0.0f;
    }
  return m;
}

void copy_out(const cv::Mat& m, float* out) {
  for (int y = 0; y < m.rows; ++y) std::memcpy(out + std::size_t(y) * m.cols, m.ptr<float>(y), sizeof(float) * m.cols);
}

}  // namespace

void opencv_set_threads(int n) { cv::setNumThreads(n); }
std::string opencv_version() { return CV_VERSION; }

std::vector<PeerMethod> opencv_peers(const filters::GuidedInput& in, const filters::FilterParams& p,
                                     float median_sigma_pos) {
  using filters::Channel;
  const float sp = median_sigma_pos > 0 ? median_sigma_pos : 1.0f;
  // Albedo luminance (Rec.709) as one guide channel for the 4-channel peer.
  auto albedo_y = std::make_shared<std::vector<float>>(in.pixel_count(), 0.0f);
  if (in.albedo[0])
    for (std::size_t i = 0; i < in.pixel_count(); ++i)
      (*albedo_y)[i] = 0.2126f * in.albedo[0][i] + 0.7152f * in.albedo[1][i] + 0.0722f * in.albedo[2][i];
  auto guide4 = std::make_shared<cv::Mat>(guide_mat(in, {{in.normal[0], p.sigma_normal},
                                                         {in.normal[1], p.sigma_normal},
                                                         {in.normal[2], p.sigma_normal},
                                                         {Channel{albedo_y->data(), 1}, p.sigma_albedo}}));
  auto guide9 = std::make_shared<cv::Mat>(guide_mat(
      in, {{in.position[0], sp}, {in.position[1], sp}, {in.position[2], sp}, {in.normal[0], p.sigma_normal},
           {in.normal[1], p.sigma_normal}, {in.normal[2], p.sigma_normal}, {in.albedo[0], p.sigma_albedo},
           {in.albedo[1], p.sigma_albedo}, {in.albedo[2], p.sigma_albedo}}));
  auto guide3 = std::make_shared<cv::Mat>(
      guide_mat(in, {{in.normal[0], p.sigma_normal}, {in.normal[1], p.sigma_normal}, {in.normal[2], p.sigma_normal}}));
  const double sigma_s = p.sigma_spatial_px;
  std::vector<PeerMethod> peers;
  peers.push_back({"opencv-dtFilter", "NC, 3 iterations; guide N xyz + albedo Y",
                   [=](const filters::GuidedInput& g, float* out) {
                     cv::Mat dst;
                     cv::ximgproc::dtFilter(*guide4, signal_mat(g), dst, sigma_s, 1.0, cv::ximgproc::DTF_NC, 3);
                     copy_out(dst, out);
                   }});
  for (int height : {4, 8}) {  // 8: about 16 times the cost of 4
    peers.push_back({"opencv-amFilter", "tree height " + std::to_string(height) + "; guide P N A (9 channels)",
                     [=](const filters::GuidedInput& g, float* out) {
                       cv::Ptr<cv::ximgproc::AdaptiveManifoldFilter> f =
                           cv::ximgproc::createAMFilter(sigma_s, 1.0, false);
                       f->setTreeHeight(height);
                       cv::Mat dst;
                       f->filter(signal_mat(g), dst, *guide9);
                       copy_out(dst, out);
                     },
                     height > 4 ? 1 : 3});
  }
  const int d = 2 * int(std::ceil(3.0 * sigma_s)) + 1;
  peers.push_back({"opencv-jointBilateralFilter", "d " + std::to_string(d) + "; guide N xyz (L1 range)",
                   [=](const filters::GuidedInput& g, float* out) {
                     cv::Mat dst;
                     cv::ximgproc::jointBilateralFilter(*guide3, signal_mat(g), dst, d, 1.0, sigma_s);
                     copy_out(dst, out);
                   },
                   1});
  return peers;
}

}  // namespace cgtmo::bench
