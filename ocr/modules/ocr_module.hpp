#ifndef UBII_OCR_MODULES_OCR_MODULE_HPP
#define UBII_OCR_MODULES_OCR_MODULE_HPP

// An OCR pipeline as a processing module: input `image` (ubii.dataStructure.Image2D), output
// `objects` (ubii.dataStructure.Object2DList, one Object2D per word) and `error` (string: why a
// frame could not be read, so that the sender sees it). Passes run on the module's worker thread
// (a frame takes 100-1000 ms); a frame arriving during a pass replaces any frame still waiting
// (latest wins, the replaced ones are counted in Timing::inputs_dropped).

#include <memory>
#include <string>

#include "ubii/module_arguments.hpp"
#include "ubii/ocr/pipeline_factory.hpp"
#include "ubii/processing_module.hpp"

namespace ubii::ocr::modules
{

class OcrModule : public ProcessingModule
{
  public:
    // The options are checked here; Tesseract and the model load in on_created, off the factory's
    // path (a registry makes one module of each kind just to read its spec).
    OcrModule(std::string name, std::string what, PipelineOptions options);
    ~OcrModule() override;

    const PipelineOptions &options() const noexcept
    {
        return options_;
    }
    // The pipeline its passes run (nullptr until created), for a benchmark that times the same
    // instance called directly: two instances of one pipeline can differ in speed by more than
    // the module adds (bench/ocr/ocr_module_bench.cpp).
    Pipeline *pipeline() noexcept
    {
        return pipeline_.get();
    }

  protected:
    void on_created() override;
    void on_processing(Pass &pass) override;
    void on_destroyed() override;

  private:
    PipelineOptions options_;
    std::unique_ptr<Pipeline> pipeline_;
};

// The four modules, by the names the thesis's Python OCR modules have (session specs written for
// them work unchanged), and TextDetection_DB.
class TesseractOcrPure final : public OcrModule
{
  public:
    explicit TesseractOcrPure(const ModuleArguments &arguments = {});
};
class TesseractOcrMser final : public OcrModule
{
  public:
    explicit TesseractOcrMser(const ModuleArguments &arguments = {});
};
class TesseractOcrEast final : public OcrModule
{
  public:
    explicit TesseractOcrEast(const ModuleArguments &arguments = {});
};
class TextDetectionDb final : public OcrModule
{
  public:
    explicit TextDetectionDb(const ModuleArguments &arguments = {});
};

} // namespace ubii::ocr::modules

#endif
