#include "history_report.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "pipeline/passes.h"
#include "rop/blend.h"

namespace zb {

using json = nlohmann::json;

namespace {

std::string rgba_text(Rgba8 c) { return fmt::format("({},{},{},{})", c.r, c.g, c.b, c.a); }

std::string depth_text(uint32_t z, int bits) {
  return fmt::format("{:#0{}x} ({:.6f})", z, (bits + 3) / 4 + 2, double(z) / double(depth_max(bits)));
}

std::string mask_text(uint8_t m) {
  std::string s;
  if (m & kMaskR) s += 'R';
  if (m & kMaskG) s += 'G';
  if (m & kMaskB) s += 'B';
  if (m & kMaskA) s += 'A';
  return s.empty() ? "none" : s;
}

std::string value_text(const FrameHistory& f, const PixelValue& v) {
  std::string s = fmt::format("colour {} depth {} coverage {} peel {}", rgba_text(v.color),
                              depth_text(v.depth, f.depth_bits), v.coverage, depth_text(v.peel, f.depth_bits));
  s += fmt::format(" accumulation ({},{},{},{}) revealage {}", v.acc[0], v.acc[1], v.acc[2], v.acc[3], v.reveal);
  if (v.layers.n) s += ", " + layers_text(v.layers, f.depth_bits);
  return s;
}

// The planes that changed, "colour A -> B, depth C -> D".
std::string changes_text(const FrameHistory& f, const PixelValue& a, const PixelValue& b) {
  std::string s;
  auto add = [&](bool changed, const std::string& from, const std::string& to, const char* name) {
    if (changed) s += fmt::format("{}{} {} -> {}", s.empty() ? "" : ", ", name, from, to);
  };
  add(a.color != b.color, rgba_text(a.color), rgba_text(b.color), "colour");
  add(a.depth != b.depth, depth_text(a.depth, f.depth_bits), depth_text(b.depth, f.depth_bits), "depth");
  add(a.coverage != b.coverage, std::to_string(a.coverage), std::to_string(b.coverage), "coverage");
  add(a.peel != b.peel, depth_text(a.peel, f.depth_bits), depth_text(b.peel, f.depth_bits), "peel");
  auto acc = [](const PixelValue& v) {
    return fmt::format("({},{},{},{}) revealage {}", v.acc[0], v.acc[1], v.acc[2], v.acc[3], v.reveal);
  };
  add(a.acc != b.acc || a.reveal != b.reveal, acc(a), acc(b), "accumulation");
  add(a.layers != b.layers, layers_text(a.layers, f.depth_bits), layers_text(b.layers, f.depth_bits),
      "layers");
  return s;
}

std::string state_text(const RopState& s) {
  std::string t = s.depth_test ? fmt::format("depth test {}", to_string(s.depth_func)) : "no depth test";
  t += fmt::format(", depth write {}", s.depth_write && s.depth_test ? "on" : "off");
  if (s.peel_test) t += ", peel test z > peel";
  t += fmt::format(", blend {}, colour mask {}", to_string(s.blend), mask_text(s.color_mask));
  if (s.blend == BlendMode::kLayers) t += fmt::format(", {} layers a pixel", int(s.layers));
  return t;
}

std::string writes_text(const FrameHistory& f, const PixelWrites& w) {
  std::string s;
  auto add = [&](const std::string& part) { s += (s.empty() ? "" : ", ") + part; };
  if (w.color) add("colour " + rgba_text(w.rgba));
  if (w.depth) add("depth " + depth_text(w.z, f.depth_bits));
  if (w.coverage) add(fmt::format("coverage {}", w.cov));
  if (w.accum)
    add(fmt::format("accumulation ({},{},{},{}) revealage {}", w.acc[0], w.acc[1], w.acc[2], w.acc[3], w.reveal));
  if (w.layers) add(layers_text(w.lay, f.depth_bits));
  return s.empty() ? "nothing written" : "wrote " + s;
}

// The blend's roundings per channel, as datapath.md pins them (m(x, y) the unorm8 multiply of
// rop/blend.h): "R m(0,77)+m(255,178)=0+178=178, ...". Empty for modes without them here.
// Under a declared arithmetic other than zblend's the alpha and additive blends show its rule:
// "R sum-round255(35*110+40*145)=38" (datapath.md "Declared arithmetic").
std::string rounding_text(BlendMode mode, Rgba8 s, Rgba8 d, const Arithmetic& r) {
  const uint8_t sv[4] = {s.r, s.g, s.b, s.a}, dv[4] = {d.r, d.g, d.b, d.a};
  const char names[4] = {'R', 'G', 'B', 'A'};
  const uint8_t a = s.a, t = uint8_t(255 - d.a);
  const std::string rule = to_string(r);
  const uint32_t one_v = one_value(r.one);
  std::string out;
  for (int c = 0; c < 4; ++c) {
    const uint8_t x = sv[c], y = dv[c];
    std::string one;
    if (!r.is_zblend() && mode == BlendMode::kAlpha) {
      one = fmt::format("{}({}*{}+{}*{})={}", rule, x, a, y, one_v - a, blend_alpha(r, x, a, y));
    } else if (!r.is_zblend() && mode == BlendMode::kAdditive) {
      one = r.round == BlendRound::kSum
                ? fmt::format("{}({}*{}+{}*{})={}", rule, x, a, y, one_v, blend_additive(r, x, a, y))
                : fmt::format("{}+{}({}*{})={}", y, rule, x, a, blend_additive(r, x, a, y));
    } else if (mode == BlendMode::kAlpha) {
      const int p = mul_unorm8(x, a), q = mul_unorm8(y, uint8_t(255 - a));
      one = fmt::format("m({},{})+m({},{})={}+{}={}", x, a, y, 255 - a, p, q, std::min(255, p + q));
    } else if (mode == BlendMode::kAdditive) {
      const int p = mul_unorm8(x, a);
      one = fmt::format("{}+m({},{})={}+{}={}", y, x, a, y, p, std::min(255, y + p));
    } else if (mode == BlendMode::kUnder && c < 3) {
      const uint8_t p = mul_unorm8(x, a);
      const int q = mul_unorm8(p, t);
      one = fmt::format("{}+m(m({},{}),{})={}+m({},{})={}", y, x, a, t, y, p, t, std::min(255, y + q));
    } else if (mode == BlendMode::kUnder) {
      const int q = mul_unorm8(a, t);
      one = fmt::format("{}+m({},{})={}+{}={}", y, a, t, y, q, std::min(255, y + q));
    } else {
      return "";
    }
    out += fmt::format("{}{} {}", c ? ", " : "", names[c], one);
  }
  return out;
}

// The accumulate blend's steps ("7. Accumulate blend"): the depth weight, each channel's term
// and saturating add, the revealage.
std::string accumulate_text(const FrameHistory& f, const Fragment& g, const PixelValue& before) {
  const WboitFormat& w = f.wboit;
  const uint32_t u = wboit_depth_u(g.z, f.depth_bits);
  const uint32_t weight_f = wboit_depth_weight(g.z, f.depth_bits, w.weight_bits);
  const uint32_t weight = g.color.a * weight_f;
  const int shift = wboit_term_shift(w);
  std::string s = fmt::format("u={} F=max(1,u^3>>{})={} w=a*F={}*{}={} S={}", u, 24 - w.weight_bits,
                              weight_f, g.color.a, weight_f, weight, shift);
  const uint8_t sv[3] = {g.color.r, g.color.g, g.color.b};
  const char names[4] = {'R', 'G', 'B', 'A'};
  for (int c = 0; c < 4; ++c) {
    const uint8_t p = c < 3 ? mul_unorm8(sv[c], g.color.a) : g.color.a;
    const uint32_t term = wboit_term(p, weight, shift);
    const uint32_t acc = before.acc[size_t(c)];
    s += fmt::format("; {} {}{}, p*w>>S={}, acc {}+{}={}", names[c],
                     c < 3 ? fmt::format("p=m({},{})=", sv[c], g.color.a) : "p=a=", p, term, acc,
                     term, wboit_accumulate(acc, term, w.acc_bits));
  }
  return s + fmt::format("; revealage k=255-a={} t=k+(k>>7)={} ({}*t+128)>>8={}", 255 - g.color.a,
                         wboit_transmit(g.color.a), before.reveal, wboit_reveal(before.reveal, g.color.a));
}

// The insert ("8. Layers"): the fragment's layer, where it went, and a merge's roundings.
std::string layers_steps_text(const FrameHistory& f, int k, const Fragment& g,
                              const PixelValue& before, const PixelWrites& w) {
  const Layer l = fragment_layer(g.z, g.color);
  std::string s = fmt::format("layer p=m(s,a) ({},{},{}) a {}", l.p.r, l.p.g, l.p.b, l.p.a);
  if (l.p.a == 0) return s + "; alpha 0: nothing inserted";
  if (w.layer_at < 0) return s;
  const int n = before.layers.n;
  if (n < k) return s + fmt::format("; inserted at position {} ({} of {} layers in use)", w.layer_at, n + 1, k);
  // K + 1 layers: the two farthest F (front) and B merged into slot K - 1.
  const auto [front, back] = farthest_two(before.layers, k, l, w.layer_at);
  const uint8_t t = uint8_t(255 - front.p.a);
  const uint8_t fb[4] = {front.p.r, front.p.g, front.p.b, front.p.a};
  const uint8_t bb[4] = {back.p.r, back.p.g, back.p.b, back.p.a};
  const Layer merged = merge_layers(front, back);
  const uint8_t mv[4] = {merged.p.r, merged.p.g, merged.p.b, merged.p.a};
  s += fmt::format("; {} K = {} full: the two farthest merged into slot {}, z {} (F's)",
                   w.layer_at == k ? "behind every layer," : fmt::format("inserted at {};", w.layer_at),
                   k, k - 1, depth_text(front.z, f.depth_bits));
  const char names[4] = {'R', 'G', 'B', 'A'};
  for (int c = 0; c < 4; ++c)
    s += fmt::format("; {} {}+m({},{})={}", names[c], fb[c], bb[c], t, mv[c]);
  return s;
}

// The resolve of the layers over the colour, step by step ("8. Layers").
std::string resolve_layers_text(const PixelValue& before) {
  std::string s;
  Rgba8 acc{0, 0, 0, 0};
  for (int i = 0; i < before.layers.n; ++i) {
    const Rgba8 next = layer_under(acc, before.layers.layer[size_t(i)].p);
    s += fmt::format("{}layer {} under t={}: {}", i ? "; " : "", i, 255 - acc.a, rgba_text(next));
    acc = next;
  }
  return s + fmt::format("; over {} with 255-A={}", rgba_text(before.color), 255 - acc.a);
}

// The coverage blend's case and its proportionate blend ("5. Coverage blend").
std::string coverage_text(const FrameHistory& f, const Fragment& g, const PixelValue& before) {
  const int n = f.coverage_samples, k = g.coverage, cs = before.coverage;
  const uint32_t z = g.z, zs = before.depth;
  const int combined = std::min(n, k + cs);
  std::string which, w_text;
  int w = k;
  bool p_first = true;
  if (z < zs) {
    which = "nearer (z < Zs)", w_text = "w=k";
  } else if (z > zs) {
    which = "farther (z > Zs)", w_text = "stored keeps its cs", w = cs, p_first = false;
  } else if (k + cs >= n) {
    return fmt::format("case equal and full (z == Zs, k+cs={}+{} >= N={}): the fragment's colour, "
                       "coverage N={}", k, cs, n, n);
  } else {
    which = fmt::format("equal, not full (z == Zs, k+cs={}+{} < N={})", k, cs, n), w_text = "w=k";
  }
  std::string s = fmt::format("case {}: {}={}, coverage min(N,k+cs)=min({},{}+{})={}", which, w_text,
                              w, n, k, cs, combined);
  const uint8_t fv[4] = {g.color.r, g.color.g, g.color.b, g.color.a};
  const uint8_t dv[4] = {before.color.r, before.color.g, before.color.b, before.color.a};
  const char names[4] = {'R', 'G', 'B', 'A'};
  for (int c = 0; c < 4; ++c) {
    const uint8_t p = p_first ? fv[c] : dv[c], d = p_first ? dv[c] : fv[c];
    s += fmt::format("; {} ({}*{}+{}*{}+{})>>{}={}", names[c], w, p, n - w, d, n / 2,
                     coverage_log2(n), blend_coverage(p, d, uint32_t(w), n));
  }
  return s;
}

std::string fragment_text(const FrameHistory& f, const PassRecord& pass, const HistoryEvent& e,
                          const Scene* scene) {
  const FragmentRecord& r = e.fragment;
  const Fragment& g = r.fragment;
  const std::string source = !f.from_scene ? ""
                             : pass.edges  ? fmt::format(", edge {}", g.prim)
                             : scene       ? ", " + triangle_source(*scene, g.prim)
                                           : fmt::format(", triangle {}", g.prim);
  std::string s = fmt::format("  fragment {} of the pass{}: z {} colour {}", r.index, source,
                              depth_text(g.z, f.depth_bits), rgba_text(g.color));
  if (pass.state.blend == BlendMode::kCoverage)
    s += fmt::format(" coverage {} of {}", int(g.coverage), f.coverage_samples);
  s += "\n    ";
  if (r.depth_tested)
    s += fmt::format("depth {} {} vs stored {}: {}; ", to_string(pass.state.depth_func),
                     depth_text(g.z, f.depth_bits), depth_text(e.before.depth, f.depth_bits),
                     r.depth_passed ? "pass" : "fail");
  if (r.peel_tested)
    s += fmt::format("peel z > {}: {}; ", depth_text(e.before.peel, f.depth_bits), r.peel_passed ? "pass" : "fail");
  if (r.depth_passed && r.peel_passed) {
    if (pass.state.blend == BlendMode::kAccumulate)
      s += fmt::format("accumulate onto ({},{},{},{}) revealage {}; ", e.before.acc[0], e.before.acc[1],
                       e.before.acc[2], e.before.acc[3], e.before.reveal);
    else if (pass.state.blend == BlendMode::kLayers)
      s += fmt::format("insert into {} (K = {}); ", layers_text(e.before.layers, f.depth_bits),
                       int(pass.state.layers));
    else if (pass.state.blend == BlendMode::kCoverage)
      s += fmt::format("coverage blend onto {} depth {} coverage {}; ", rgba_text(e.before.color),
                       depth_text(e.before.depth, f.depth_bits), e.before.coverage);
    else
      s += fmt::format("blend {} of {} onto {} = {}, mask {}; ", to_string(pass.state.blend),
                       rgba_text(g.color), rgba_text(e.before.color), rgba_text(r.blended),
                       mask_text(pass.state.color_mask));
  }
  s += writes_text(f, r.writes) + "\n";
  if (r.depth_passed && r.peel_passed) {
    const BlendMode mode = pass.state.blend;
    const std::string steps =
        mode == BlendMode::kAccumulate ? (pass.state.color_mask ? accumulate_text(f, g, e.before) : "")
        : mode == BlendMode::kLayers
            ? (r.writes.layers ? layers_steps_text(f, pass.state.layers, g, e.before, r.writes) : "")
        : mode == BlendMode::kCoverage ? coverage_text(f, g, e.before)
                                       : rounding_text(mode, g.color, e.before.color, f.arithmetic);
    if (!steps.empty()) s += "    roundings: " + steps + "\n";
  }
  return s;
}

// The RTL's retires of the event's fragment: the cycles, and any write that is not the golden
// model's.
std::string rtl_text(const FrameHistory& f, const PixelHistory& h, const HistoryEvent& e) {
  std::string s;
  bool accepted = false;
  for (const RetireRecord& r : h.rtl) {
    if (r.extra || r.pass != e.pass || r.index != e.fragment.index) continue;
    if (!accepted) s += fmt::format("    rtl: #{} accepted at cycle {}", r.stream, r.accepted);
    accepted = true;
    if (r.missing) {
      s += fmt::format("; {} MISSING: never retired", r.x11 ? "X11" : "X4");
      continue;
    }
    s += fmt::format("; {} at cycle {}", r.x11 ? "X11" : "X4", r.cycle);
    if (!same_stage_writes(r, e.fragment.writes)) s += " MISMATCH: the RTL " + writes_text(f, r.writes);
  }
  return accepted ? s + "\n" : "    rtl: no retire of this fragment seen\n";
}

std::string op_text(const FrameHistory& f, const HistoryEvent& e) {
  std::string s = fmt::format("  frame operation {}", to_string(e.op.kind));
  if (e.op.kind == FrameOpKind::kClearColor || e.op.kind == FrameOpKind::kResolveUnder)
    s += " " + rgba_text(e.op.value);
  if (e.op.kind == FrameOpKind::kClearDepth)
    s += " " + depth_text(std::min(e.op.depth, depth_max(f.depth_bits)), f.depth_bits);
  if (e.before == e.after) return s + ": the pixel unchanged\n";
  s += ": " + changes_text(f, e.before, e.after) + "\n";
  if (e.op.kind == FrameOpKind::kResolveLayers && e.before.layers.n)
    s += "    roundings: " + resolve_layers_text(e.before) + "\n";
  return s;
}

json rgba_json(Rgba8 c) { return json::array({c.r, c.g, c.b, c.a}); }
Rgba8 rgba_from(const json& j) {
  return Rgba8{j.at(0).get<uint8_t>(), j.at(1).get<uint8_t>(), j.at(2).get<uint8_t>(), j.at(3).get<uint8_t>()};
}

// The layers in use, nearest first: [{"z", "p": [r, g, b, a]}, ...].
json layers_json(const PixelLayers& px) {
  json a = json::array();
  for (int i = 0; i < px.n; ++i)
    a.push_back({{"z", px.layer[size_t(i)].z}, {"p", rgba_json(px.layer[size_t(i)].p)}});
  return a;
}
PixelLayers layers_from(const json& a) {
  PixelLayers px;
  if (a.size() > size_t(kMaxLayers)) throw std::invalid_argument("more than 8 layers");
  for (const json& l : a) {
    px.layer[size_t(px.n)] = Layer{l.at("z").get<uint32_t>(), rgba_from(l.at("p"))};
    ++px.n;
  }
  return px;
}

json value_json(const PixelValue& v) {
  return {{"color", rgba_json(v.color)}, {"depth", v.depth}, {"coverage", v.coverage},
          {"peel", v.peel}, {"accum", v.acc}, {"reveal", v.reveal},
          {"layers", layers_json(v.layers)}};
}
PixelValue value_from(const json& j) {
  PixelValue v;
  v.color = rgba_from(j.at("color"));
  v.depth = j.at("depth").get<uint32_t>();
  v.coverage = j.at("coverage").get<uint8_t>();
  v.peel = j.at("peel").get<uint32_t>();
  v.acc = j.at("accum").get<std::array<uint32_t, 4>>();
  v.reveal = j.at("reveal").get<uint32_t>();
  if (j.contains("layers")) v.layers = layers_from(j.at("layers"));  // written since version 1
  return v;
}

json event_json(const HistoryEvent& e) {
  json j{{"pass", e.pass}, {"before", value_json(e.before)}, {"after", value_json(e.after)}};
  if (e.kind == HistoryEvent::Kind::kFrameOp) {
    j["kind"] = "frame_op";
    j["op"] = {{"kind", to_string(e.op.kind)}, {"code", int(e.op.kind)},
               {"value", rgba_json(e.op.value)}, {"depth", e.op.depth}};
    return j;
  }
  const FragmentRecord& r = e.fragment;
  const Fragment& g = r.fragment;
  const PixelWrites& w = r.writes;
  j["kind"] = "fragment";
  j["index"] = r.index;
  j["fragment"] = {{"prim", g.prim}, {"z", g.z}, {"color", rgba_json(g.color)},
                   {"coverage", g.coverage}, {"front", g.front}, {"facing", g.facing}};
  j["depth_test"] = {{"tested", r.depth_tested}, {"passed", r.depth_passed}};
  j["peel_test"] = {{"tested", r.peel_tested}, {"passed", r.peel_passed}};
  j["blended"] = rgba_json(r.blended);
  j["writes"] = {{"depth", w.depth}, {"z", w.z}, {"coverage", w.coverage}, {"cov", w.cov},
                 {"color", w.color}, {"rgba", rgba_json(w.rgba)}, {"accum", w.accum},
                 {"acc", w.acc}, {"reveal", w.reveal}, {"layers", w.layers},
                 {"layer_at", w.layer_at}, {"lay", layers_json(w.lay)}};
  return j;
}

HistoryEvent event_from(const json& j, int x, int y) {
  HistoryEvent e;
  e.pass = j.at("pass").get<size_t>();
  e.before = value_from(j.at("before"));
  e.after = value_from(j.at("after"));
  const std::string kind = j.at("kind").get<std::string>();
  if (kind == "frame_op") {
    e.kind = HistoryEvent::Kind::kFrameOp;
    const json& op = j.at("op");
    const int code = op.at("code").get<int>();
    if (code < 0 || code >= int(kFrameOpKinds)) throw std::invalid_argument("frame operation code out of range");
    e.op.kind = FrameOpKind(code);
    e.op.value = rgba_from(op.at("value"));
    e.op.depth = op.at("depth").get<uint32_t>();
    return e;
  }
  if (kind != "fragment") throw std::invalid_argument("event kind '" + kind + "'");
  FragmentRecord& r = e.fragment;
  r.index = j.at("index").get<size_t>();
  const json& g = j.at("fragment");
  r.fragment.x = uint16_t(x);
  r.fragment.y = uint16_t(y);
  r.fragment.prim = g.at("prim").get<uint32_t>();
  r.fragment.z = g.at("z").get<uint32_t>();
  r.fragment.color = rgba_from(g.at("color"));
  r.fragment.coverage = g.at("coverage").get<uint8_t>();
  r.fragment.front = g.at("front").get<bool>();
  r.fragment.facing = g.at("facing").get<bool>();
  r.depth_tested = j.at("depth_test").at("tested").get<bool>();
  r.depth_passed = j.at("depth_test").at("passed").get<bool>();
  r.peel_tested = j.at("peel_test").at("tested").get<bool>();
  r.peel_passed = j.at("peel_test").at("passed").get<bool>();
  r.blended = rgba_from(j.at("blended"));
  const json& w = j.at("writes");
  r.writes.depth = w.at("depth").get<bool>();
  r.writes.z = w.at("z").get<uint32_t>();
  r.writes.coverage = w.at("coverage").get<bool>();
  r.writes.cov = w.at("cov").get<uint8_t>();
  r.writes.color = w.at("color").get<bool>();
  r.writes.rgba = rgba_from(w.at("rgba"));
  r.writes.accum = w.at("accum").get<bool>();
  r.writes.acc = w.at("acc").get<std::array<uint32_t, 4>>();
  r.writes.reveal = w.at("reveal").get<uint32_t>();
  if (w.contains("layers")) {
    r.writes.layers = w.at("layers").get<bool>();
    r.writes.layer_at = w.at("layer_at").get<int>();
    r.writes.lay = layers_from(w.at("lay"));
  }
  return e;
}

// A method that draws edges, judged as its error map and the lab judge it.
std::string line_verdict_text(EdgePixel want, Rgba8 got) {
  const bool drawn = got == kEdgeColor;
  const char* style = drawn ? "drawn in the visible style" : "not drawn in the visible style";
  switch (want) {
    case EdgePixel::kVisible:
      return fmt::format("exact line reference: a visible edge here; {}: {}\n", style,
                         drawn ? "right" : "WRONG (visible missing)");
    case EdgePixel::kHidden:
      return fmt::format("exact line reference: a hidden edge here; {}: {}\n", style,
                         drawn ? "WRONG (hidden drawn)" : "right");
    case EdgePixel::kNone: break;
  }
  return "exact line reference: no edge here (the line error does not count this pixel; the "
         "shaded CIEDE2000 means nothing for a line drawing)\n";
}

}  // namespace

std::string history_text(const FrameHistory& f, const PixelHistory& h, const Scene* scene) {
  std::string s = fmt::format("pixel ({}, {}), {}x{} frame, {}-bit depth\n", h.x, h.y, f.width,
                              f.height, f.depth_bits);
  s += "first  " + value_text(f, h.first) + "\n";
  size_t shown = size_t(-1);
  for (const HistoryEvent& e : h.events) {
    if (e.kind == HistoryEvent::Kind::kFrameOp) {
      s += e.pass < f.passes.size() ? fmt::format("before pass {}:", e.pass) : std::string("after the last pass:");
      s += op_text(f, e).substr(1);
      continue;
    }
    if (e.pass != shown) {
      const PassRecord& p = f.passes.at(e.pass);
      s += fmt::format("pass {}{}: {}\n", e.pass, p.name.empty() ? "" : " '" + p.name + "'", state_text(p.state));
      shown = e.pass;
    }
    s += fragment_text(f, f.passes.at(e.pass), e, scene);
    if (h.rtl_ran) s += rtl_text(f, h, e);
  }
  size_t fragments = 0;
  for (const HistoryEvent& e : h.events) fragments += e.kind == HistoryEvent::Kind::kFragment;
  if (fragments == 0) s += "  no fragment reached the pixel\n";
  for (const RetireRecord& r : h.rtl)
    if (r.extra) s += fmt::format("  rtl: EXTRA {} write at cycle {} with no fragment waiting: {}\n",
                                  r.x11 ? "X11" : "X4", r.cycle, writes_text(f, r.writes));
  s += "final  " + value_text(f, h.final_value) + "\n";
  if (h.rtl_ran)
    s += h.rtl_final == h.final_value
             ? "rtl    the same on every plane\n"
             : "rtl    DIFFERS: " + value_text(f, h.rtl_final) + "\n";
  if (h.reference) {
    const ReferencePixel& r = *h.reference;
    s += fmt::format("exact reference: {} layer{} nearest first", r.layers.size(), r.layers.size() == 1 ? "" : "s");
    if (r.behind) s += fmt::format(" ({} more behind the opaque one)", r.behind);
    s += r.layers.empty() ? ", the background" : ":";
    s += "\n";
    for (const ReferenceLayer& l : r.layers)
      s += fmt::format("  {}: z {:.6f} colour {}\n",
                       scene ? triangle_source(*scene, l.prim) : fmt::format("triangle {}", l.prim),
                       l.z_exact, rgba_text(l.color));
    if (h.line_reference) {
      s += fmt::format("  composited: colour {}\n", rgba_text(r.color));
      s += line_verdict_text(*h.line_reference, h.final_value.color);
      return s;
    }
    s += fmt::format("  composited: colour {}; this method's CIEDE2000 against it {:.2f}", rgba_text(r.color), h.delta_e);
    bool coverage = false;
    for (const PassRecord& p : f.passes) coverage = coverage || is_coverage_pass(p.state);
    s += coverage ? " (the error map and the lab judge coverage anti-aliasing against the "
                    "supersampled reference instead, which credits partial coverage: docs/lab.md)\n"
                  : "\n";
  }
  return s;
}

std::string triangle_source(const Scene& scene, uint32_t prim) {
  uint32_t first = 0;
  for (const Object& o : scene.objects) {
    const auto n = uint32_t(o.mesh.triangles.size());
    if (prim - first < n) {
      const std::string material =
          o.material < scene.materials.size() ? scene.materials[o.material].name : "?";
      return fmt::format("object '{}' triangle {}, material '{}'", o.name, prim - first, material);
    }
    first += n;
  }
  return fmt::format("triangle {}", prim);
}

std::string history_json(const FrameHistory& f, const std::string& scene_name, const std::string& method,
                         const Scene* scene) {
  json passes = json::array();
  for (const PassRecord& p : f.passes)
    passes.push_back({{"name", p.name}, {"state_bits", pack_state(p.state)}, {"edges", p.edges},
                      {"depth_test", p.state.depth_test}, {"depth_func", to_string(p.state.depth_func)},
                      {"depth_write", p.state.depth_write}, {"blend", to_string(p.state.blend)},
                      {"color_mask", p.state.color_mask}, {"peel_test", p.state.peel_test},
                      {"layers", p.state.layers}});
  json pixels = json::array();
  for (const PixelHistory& h : f.pixels) {
    json events = json::array();
    for (const HistoryEvent& e : h.events) {
      events.push_back(event_json(e));
      if (h.rtl_ran && e.kind == HistoryEvent::Kind::kFragment) {
        json rtl = json::array();
        for (const RetireRecord& r : h.rtl)
          if (!r.extra && r.pass == e.pass && r.index == e.fragment.index)
            rtl.push_back({{"stage", r.x11 ? "X11" : "X4"}, {"stream", r.stream}, {"missing", r.missing},
                           {"accepted", r.accepted}, {"cycle", r.cycle},
                           {"same_as_golden", !r.missing && same_stage_writes(r, e.fragment.writes)}});
        events.back()["rtl"] = rtl;
      }
      if (scene && e.kind == HistoryEvent::Kind::kFragment && !f.passes.at(e.pass).edges)
        events.back()["fragment"]["source"] = triangle_source(*scene, e.fragment.fragment.prim);
    }
    json p{{"x", h.x}, {"y", h.y}, {"first", value_json(h.first)}, {"events", events},
           {"final", value_json(h.final_value)}};
    if (h.rtl_ran) {
      json extra = json::array();
      for (const RetireRecord& r : h.rtl)
        if (r.extra) extra.push_back({{"stage", r.x11 ? "X11" : "X4"}, {"cycle", r.cycle}});
      p["rtl_extra"] = extra;
      p["rtl_final"] = value_json(h.rtl_final);
    }
    if (h.reference) {
      json layers = json::array();
      for (const ReferenceLayer& l : h.reference->layers) {
        layers.push_back({{"prim", l.prim}, {"z_exact", l.z_exact}, {"color", rgba_json(l.color)}});
        if (scene) layers.back()["source"] = triangle_source(*scene, l.prim);
      }
      p["reference"] = {{"layers", layers}, {"behind", h.reference->behind},
                        {"color", rgba_json(h.reference->color)}};
      p["delta_e"] = h.delta_e;
    }
    if (h.line_reference) {
      static const char* const kNames[] = {"none", "hidden", "visible"};  // EdgePixel
      p["line_reference"] = kNames[size_t(*h.line_reference)];
    }
    pixels.push_back(std::move(p));
  }
  const json doc{{"zblend_pixel_history", 1}, {"scene", scene_name}, {"method", method},
                 {"from_scene", f.from_scene},
                 {"width", f.width}, {"height", f.height}, {"depth_bits", f.depth_bits},
                 {"coverage_samples", f.coverage_samples},
                 {"wboit", {{"acc_bits", f.wboit.acc_bits}, {"rev_bits", f.wboit.rev_bits},
                            {"weight_bits", f.wboit.weight_bits}}},
                 {"passes", passes}, {"pixels", pixels}};
  return doc.dump(1) + "\n";
}

FrameHistory parse_history_json(const std::string& text) {
  try {
    const json doc = json::parse(text);
    if (!doc.contains("zblend_pixel_history")) throw std::invalid_argument("no 'zblend_pixel_history' key");
    FrameHistory f;
    f.width = doc.at("width").get<int>();
    f.height = doc.at("height").get<int>();
    f.depth_bits = doc.at("depth_bits").get<int>();
    f.coverage_samples = doc.at("coverage_samples").get<int>();
    f.from_scene = doc.at("from_scene").get<bool>();
    const json& wb = doc.at("wboit");
    f.wboit = WboitFormat{wb.at("acc_bits").get<int>(), wb.at("rev_bits").get<int>(), wb.at("weight_bits").get<int>()};
    if (f.depth_bits < kMinDepthBits || f.depth_bits > kMaxDepthBits || !valid_wboit_format(f.wboit) ||
        !valid_coverage_samples(f.coverage_samples))
      throw std::invalid_argument("depth bits, coverage samples or accumulation widths out of range");
    for (const json& p : doc.at("passes")) {
      PassRecord r;
      r.name = p.at("name").get<std::string>();
      if (!unpack_state(p.at("state_bits").get<uint16_t>(), r.state))
        throw std::invalid_argument("pass '" + r.name + "': state_bits is not a pass state");
      r.edges = p.at("edges").get<bool>();
      f.passes.push_back(r);
    }
    for (const json& p : doc.at("pixels")) {
      PixelHistory h;
      h.x = p.at("x").get<int>();
      h.y = p.at("y").get<int>();
      h.first = value_from(p.at("first"));
      h.final_value = value_from(p.at("final"));
      if (p.contains("reference")) {
        const json& r = p.at("reference");
        ReferencePixel ref;
        for (const json& l : r.at("layers"))
          ref.layers.push_back({l.at("prim").get<uint32_t>(), l.at("z_exact").get<double>(), rgba_from(l.at("color"))});
        ref.behind = r.at("behind").get<size_t>();
        ref.color = rgba_from(r.at("color"));
        h.reference = ref;
        h.delta_e = p.at("delta_e").get<double>();
      }
      if (p.contains("line_reference")) {
        const std::string l = p.at("line_reference").get<std::string>();
        if (l != "none" && l != "hidden" && l != "visible")
          throw std::invalid_argument("line_reference '" + l + "' is not none, hidden or visible");
        h.line_reference = l == "none" ? EdgePixel::kNone : l == "hidden" ? EdgePixel::kHidden : EdgePixel::kVisible;
      }
      for (const json& e : p.at("events")) {
        h.events.push_back(event_from(e, h.x, h.y));
        if (h.events.back().pass + (h.events.back().kind == HistoryEvent::Kind::kFragment) > f.passes.size())
          throw std::invalid_argument("an event names a pass the document does not have");
      }
      f.pixels.push_back(std::move(h));
    }
    return f;
  } catch (const json::exception& e) {
    throw std::invalid_argument(std::string("not a pixel history: ") + e.what());
  }
}

}  // namespace zb
