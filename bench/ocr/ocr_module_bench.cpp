// What the processing-module wrapping costs: each OCR module (the plugin's classes), fed frames
// through a scheduler as a node runs it (record in, pass on the module's worker thread,
// Object2DList out), timed alternately frame by frame with the same pipeline instance called
// directly on the same frame. A control row times two instances of one pipeline against each
// other: they differ by more than the module adds (one instance's memory can run faster than
// another's), which is why the module is compared with its own instance. Prints a Markdown table;
// asserts nothing.
//
//   ocr_module_bench [--frames N]
#include <chrono>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "frame_timing.hpp"
#include "scenes.hpp"
#include "ocr_module.hpp"
#include "ubii/ocr/ocr.hpp"
#include "ubii/standalone_module.hpp"

namespace
{

namespace ocr = ubii::ocr;
using ubii::bench::time_frames_interleaved;

constexpr int warm_up_frames = 2;

// One module as a node runs it; read() feeds one frame and returns when its output arrived.
class ScheduledModule
{
  public:
    explicit ScheduledModule(std::unique_ptr<ocr::modules::OcrModule> module)
        : ocr_(module.get()), module_(std::move(module))
    {
        module_.scheduler().on_output(
            [this](const ubii::ProcessingModule &, const ubii::PassOutput &out) {
                if (out.name == "error")
                    error_ = out.value.as<std::string>();
                ++outputs_;
                return ubii::Status::ok;
            });
    }
    void read(const std::shared_ptr<const ubii::Record> &frame)
    {
        const std::size_t before = outputs_;
        module_.feed("image", frame);
        if (!module_.run_until([&] { return outputs_ > before; }, std::chrono::seconds(60)))
            throw std::runtime_error("no output within 60 s");
        if (!error_.empty())
            throw std::runtime_error(error_);
    }

    // The module's own pipeline, for the direct calls (between passes, never during one).
    ocr::Pipeline &pipeline()
    {
        return *ocr_->pipeline();
    }

  private:
    ocr::modules::OcrModule *ocr_;
    std::size_t outputs_ = 0;
    std::string error_;
    ubii::StandaloneModule module_;
};

std::shared_ptr<const ubii::Record> frame_record(const cv::Mat &bgr)
{
    const ocr::Image2DData data = ocr::mat_to_image(bgr);
    ubii::Image2D image;
    image.set_width(data.width);
    image.set_height(data.height);
    image.set_data_format(static_cast<ubii::Image2D::DataFormat>(data.format));
    image.set_data(data.data.data(), data.data.size());
    return std::make_shared<const ubii::Record>("/bench/image", std::move(image));
}

std::string fixed(double value, int digits)
{
    std::ostringstream text;
    text << std::fixed << std::setprecision(digits) << value;
    return text.str();
}

} // namespace

int main(int argc, char **argv)
{
    ocr::ensure_single_omp_thread(argc, argv);
    try {
        int frames = 20;
        if (argc == 3 && std::string(argv[1]) == "--frames")
            frames = std::stoi(argv[2]);
        const std::vector<std::function<std::unique_ptr<ocr::modules::OcrModule>()>> modules = {
            [] { return std::make_unique<ocr::modules::TesseractOcrPure>(); },
            [] { return std::make_unique<ocr::modules::TesseractOcrMser>(); },
            [] { return std::make_unique<ocr::modules::TextDetectionDb>(); }};
        std::cout << "OMP_THREAD_LIMIT=" << std::getenv("OMP_THREAD_LIMIT") << ", " << frames
                  << " frames per row, module and pipeline alternately after " << warm_up_frames
                  << " warm-up frames each\n\n"
                  << "| module | scene | module mean ms | pipeline mean ms | mean ratio | module "
                     "median ms | pipeline median ms | median ratio |\n"
                  << "|---|---|---|---|---|---|---|---|\n";
        const auto row = [](const std::string &name, const std::string &scene,
                            const ubii::bench::FrameStats &first,
                            const ubii::bench::FrameStats &second) {
            std::cout << "| " << name << " | " << scene << " | " << fixed(first.mean_ms, 1) << " | "
                      << fixed(second.mean_ms, 1) << " | "
                      << fixed(first.mean_ms / second.mean_ms, 3) << "x | "
                      << fixed(first.median_ms, 1) << " | " << fixed(second.median_ms, 1) << " | "
                      << fixed(first.median_ms / second.median_ms, 3) << "x |" << std::endl;
        };
        const auto scenes = ocr::testdata::all_scenes();
        for (const auto &make : modules) {
            auto made = make();
            const std::string name = made->name();
            const auto options = made->options();
            ScheduledModule module(std::move(made));
            for (const auto &scene : scenes) {
                const auto record = frame_record(scene.image);
                const auto [through_module, direct] = time_frames_interleaved(
                    warm_up_frames, frames, [&] { module.read(record); },
                    [&] { module.pipeline().recognise(scene.image); });
                row(name, scene.name, through_module, direct);
            }
            // Control: another instance of the same pipeline against the module's own.
            const auto other = ocr::make_pipeline(options);
            const auto &scene = scenes.front();
            const auto [second, first] = time_frames_interleaved(
                warm_up_frames, frames, [&] { other->recognise(scene.image); },
                [&] { module.pipeline().recognise(scene.image); });
            row(name + " (control: another instance / the module's)", scene.name, second, first);
        }
        std::cout << "\nThe module's time runs from handing the scheduler the Image2D record to "
                     "receiving its Object2DList: the conversion of the record into a cv::Mat, "
                     "the pass on the worker thread and the hand-over included. The medians resist "
                     "this machine's "
                     "bursts of noise (one slow frame moves a mean of 20 by 5 %).\n";
        return 0;
    } catch (const std::exception &error) {
        std::cerr << "ocr_module_bench: " << error.what() << "\n";
        return 1;
    }
}
