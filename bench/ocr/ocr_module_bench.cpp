// What the processing-module wrapping costs: each OCR module of the plugin, fed frames through a
// scheduler as a node runs it (record in, pass on the module's worker thread, Object2DList out),
// timed alternately frame by frame with its pipeline called directly on the same frame. Prints a
// Markdown table with the ratio module / pipeline; asserts nothing.
//
//   ocr_module_bench [--frames N]
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "frame_timing.hpp"
#include "scenes.hpp"
#include "ubii/module_discovery.hpp"
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
    explicit ScheduledModule(std::unique_ptr<ubii::ProcessingModule> module)
        : module_(std::move(module))
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

  private:
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
        ubii::ModuleRegistry registry;
        for (const auto &report : ubii::load_plugins(registry, UBII_OCR_PLUGIN))
            for (const auto &error : report.errors)
                throw std::runtime_error(error);
        const std::pair<const char *, ocr::PipelineKind> modules[] = {
            {"TesseractOCR_PURE", ocr::PipelineKind::pure},
            {"TesseractOCR_MSER", ocr::PipelineKind::mser},
            {"TextDetection_DB", ocr::PipelineKind::db}};
        std::cout << "OMP_THREAD_LIMIT=" << std::getenv("OMP_THREAD_LIMIT") << ", " << frames
                  << " frames per row, module and pipeline alternately after " << warm_up_frames
                  << " warm-up frames each\n\n"
                  << "| module | scene | module mean ms | pipeline mean ms | mean ratio | module "
                     "median ms | pipeline median ms | median ratio |\n"
                  << "|---|---|---|---|---|---|---|---|\n";
        for (const auto &[name, kind] : modules) {
            ScheduledModule module(registry.create(name));
            // The pipeline with the options the module makes without arguments.
            auto defaults = ocr::default_options(kind);
            if (kind == ocr::PipelineKind::pure)
                ocr::tesseract_options(defaults).segmentation = ocr::Segmentation::sparse_text;
            const auto pipeline = ocr::make_pipeline(defaults);
            for (const auto &scene : ocr::testdata::all_scenes()) {
                const auto record = frame_record(scene.image);
                const auto [through_module, direct] = time_frames_interleaved(
                    warm_up_frames, frames, [&] { module.read(record); },
                    [&] { pipeline->recognise(scene.image); });
                std::cout << "| " << name << " | " << scene.name << " | "
                          << fixed(through_module.mean_ms, 1) << " | " << fixed(direct.mean_ms, 1)
                          << " | " << fixed(through_module.mean_ms / direct.mean_ms, 3) << "x | "
                          << fixed(through_module.median_ms, 1) << " | "
                          << fixed(direct.median_ms, 1) << " | "
                          << fixed(through_module.median_ms / direct.median_ms, 3) << "x |"
                          << std::endl;
            }
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
