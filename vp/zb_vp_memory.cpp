#include "zb_vp_memory.h"

#include <algorithm>
#include <cstdlib>
#include <sys/mman.h>
#include <cstring>
#include <new>

namespace zb::vp {

namespace {

uint8_t* map_zeroed(uint64_t bytes) {
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE,
                 -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  madvise(p, bytes, MADV_HUGEPAGE);  // advice only: refused where the system has none
  return static_cast<uint8_t*>(p);
}

}  // namespace

void ZbVpMemory::Unmap::operator()(uint8_t* p) const { munmap(p, bytes); }

ZbVpMemory::ZbVpMemory(sc_core::sc_module_name name, const MemoryOptions& options)
    : sc_module(name), socket("socket"), options_(options),
      mem_(map_zeroed(std::max<uint64_t>(options.bytes, 1)), Unmap{std::max<uint64_t>(options.bytes, 1)}),
      bytes_(options.bytes) {
  socket.register_b_transport(this, &ZbVpMemory::b_transport);
  socket.register_transport_dbg(this, &ZbVpMemory::transport_dbg);
  socket.register_get_direct_mem_ptr(this, &ZbVpMemory::get_direct_mem_ptr);
}

void ZbVpMemory::invalidate_dmi() {
  for (unsigned i = 0; i < socket.size(); ++i) socket[int(i)]->invalidate_direct_mem_ptr(0, ~sc_dt::uint64{0});
}

// Any length and byte enables; streaming (a width below the length) is refused.
void ZbVpMemory::b_transport(int, tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) {
  ++transactions_;
  const uint64_t a = tx.get_address(), n = tx.get_data_length();
  if (a >= bytes_ || n > bytes_ - a) {
    tx.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
    return;
  }
  if (tx.get_streaming_width() < n) {
    tx.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    return;
  }
  uint8_t* m = mem_.get() + a;
  const uint8_t* be = tx.get_byte_enable_ptr();
  const unsigned be_len = tx.get_byte_enable_length();
  if (tx.is_read() || tx.is_write()) {
    for (uint64_t i = 0; i < n; ++i) {
      if (be && be[i % be_len] != TLM_BYTE_ENABLED) continue;
      if (tx.is_read()) tx.get_data_ptr()[i] = m[i];
      else m[i] = tx.get_data_ptr()[i];
    }
  }
  delay += options_.access + options_.beat * double((n + 7) / 8);
  tx.set_dmi_allowed(options_.dmi);
  tx.set_response_status(tlm::TLM_OK_RESPONSE);
}

unsigned ZbVpMemory::transport_dbg(int, tlm::tlm_generic_payload& tx) {
  const uint64_t a = tx.get_address();
  if (a >= bytes_) return 0;
  const uint64_t n = std::min<uint64_t>(tx.get_data_length(), bytes_ - a);
  if (tx.is_read()) std::memcpy(tx.get_data_ptr(), mem_.get() + a, n);
  else if (tx.is_write()) std::memcpy(mem_.get() + a, tx.get_data_ptr(), n);
  return unsigned(n);
}

bool ZbVpMemory::get_direct_mem_ptr(int, tlm::tlm_generic_payload& tx, tlm::tlm_dmi& dmi) {
  if (!options_.dmi || tx.get_address() >= bytes_) return false;
  dmi.set_dmi_ptr(mem_.get());
  dmi.set_start_address(0);
  dmi.set_end_address(bytes_ - 1);
  dmi.allow_read_write();
  dmi.set_read_latency(options_.beat);
  dmi.set_write_latency(options_.beat);
  return true;
}

}  // namespace zb::vp
