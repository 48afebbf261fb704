// RtlPipeline over one Verilated model class (Vmt_pipeline_w<N>[_array]), included only by the
// generated registry. Ports are the bit patterns of the values: signed edges are masked to N+1 bits.
#pragma once

#include <cstdint>
#include <memory>
#include <type_traits>

#include "verilated.h"

#include "rtl/sim/rtl_pipeline.h"

namespace rc::rtl::detail {

template <class Model>
class VerilatedLane final : public RtlPipeline {
 public:
  explicit VerilatedLane(int bits) : bits_(bits), context_(std::make_unique<VerilatedContext>()) {
    model_ = std::make_unique<Model>(context_.get(), "lane");
    model_->clk = 0;
    model_->rst = 0;
    model_->in_valid = 0;
    model_->eval();
  }
  ~VerilatedLane() override { model_->final(); }

  int bits() const override { return bits_; }

  void reset() override {
    model_->rst = 1;
    edge();
    model_->rst = 0;
  }

  void clock(const RtlInputs& in) override {
    const std::uint64_t position = (std::uint64_t(1) << bits_) - 1, difference = (std::uint64_t(1) << (bits_ + 1)) - 1;
    auto set = [](auto& port, std::int64_t value, std::uint64_t mask) {
      port = static_cast<std::remove_reference_t<decltype(port)>>(static_cast<std::uint64_t>(value) & mask);
    };
    model_->in_valid = in.valid;
    set(model_->start_x, in.start.x, position);
    set(model_->start_y, in.start.y, position);
    set(model_->start_z, in.start.z, position);
    set(model_->end_x, in.end.x, position);
    set(model_->end_y, in.end.y, position);
    set(model_->end_z, in.end.z, position);
    set(model_->v0_x, in.face.v0.x, position);
    set(model_->v0_y, in.face.v0.y, position);
    set(model_->v0_z, in.face.v0.z, position);
    set(model_->e1_x, in.face.edge1.x, difference);
    set(model_->e1_y, in.face.edge1.y, difference);
    set(model_->e1_z, in.face.edge1.z, difference);
    set(model_->e2_x, in.face.edge2.x, difference);
    set(model_->e2_y, in.face.edge2.y, difference);
    set(model_->e2_z, in.face.edge2.z, difference);
    set(model_->t_guard, in.t_guard, 0xFF);
    edge();
  }

  bool out_valid() const override { return model_->out_valid != 0; }
  bool out_hit() const override { return model_->out_hit != 0; }

 private:
  void edge() {
    model_->clk = 1;
    model_->eval();
    model_->clk = 0;
    model_->eval();
  }

  int bits_;
  std::unique_ptr<VerilatedContext> context_;
  std::unique_ptr<Model> model_;
};

}  // namespace rc::rtl::detail
