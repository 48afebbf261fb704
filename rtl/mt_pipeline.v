// mt_pipeline: the paper's fixed-point Moller-Trumbore intersection pipeline (Baker et al., sec 3-5,
// figure 4) as synthesizable Verilog-2005, written from docs/pipeline.md (not from the C++ model).
//
// Parameters
//   N          fractional bits, 7..31 (the paper's "user-defined bitwidth").
//   SOFT_MULTS 0: every multiplier is Verilog's `*` (a synthesizer maps it to MULT18X18 / DSP48 blocks);
//              1: every multiplier is an explicit signed partial-product array of adders (slice logic,
//              for synthesis without block multipliers). Both compute the same bits.
//
//   T_GUARD    0: the paper's pipeline, the t_guard input is ignored (what scripts/synthesize records);
//              1: the guard band on t is built (the Verilated models of the board's RTL lanes).
//
// Static input
//   t_guard    the guard band on t, 8 bits unsigned (the wrapper's T_GUARD register [7:0]): with T_GUARD = 1
//              a segment is blocked only for t_guard < t*s < |det| - t_guard; t_guard = 0 is the paper's
//              test. Not pipelined: it must be held while tests are in flight (the wrapper changes it only
//              between passes). Its cost: one subtractor |det| - t_guard (age 26, from |det| at 25, held to
//              35 beside |det|) and the comparison 0 < t*s widened to t_guard < t*s, both of the t width
//              (S = N+4 bits); the latency is unchanged, the subtraction sits in the slack while u, v, t
//              are formed.
//
// Number formats (every value is an integer count of 2^-N, two's complement where signed; "s" = signed):
//   position  start, end, v0                      unsigned 0.N     N bits    [0, 2^N - 1]
//   difference  edge1, edge2, dir, tvec           s 1.N            N+1 bits  |d| <= 2^N - 1
//   cross product term (truncated)                s 1.N            N+1 bits
//   pvec, qvec component                          s 2.N            N+2 bits
//   det/u/v/t product term (truncated)            s 2.N            N+2 bits
//   first dot sum (x + y)                         s 3.N            N+3 bits
//   det, u, v, t; u*s, v*s, t*s; |det|            s 4.N            N+4 bits
//   u*s + v*s                                     s 5.N            N+5 bits
// Every product of two fixed-point values is truncated back to N fractional bits (the raw product's
// bits [N+W-1:N], i.e. floor(a*b / 2^N)); integer bits are never dropped (sec 3.4); sums and
// differences are exact at the widths above (docs/pipeline.md, "Register widths and the overflow
// proof"); the three products by sign(det) are real multipliers by a 2-bit s in {+1, -1} (det's most
// significant bit set: -1; so det = 0 counts as +1), exact, no truncation.
//
// Blocks (figure 4): 27 multipliers (6 pvec, 6 qvec, 3 det, 3 u, 3 v, 3 t, 3 sign) and 18 add/subs
// (3 tvec, 3 pvec, 3 qvec, 2 det, 2 u, 2 v, 2 t, 1 u*s+v*s). Outside them: direction = end - start
// (3 subtractors at the input), |det| (negate and select on det's sign bit), six comparators.
//
// Timing: one test per clock; latency 37. Every path from an input port to out_hit / out_valid passes
// exactly 37 registers: inputs presented before rising edge c are sampled at edge c (the "age 0"
// register; direction = end - start is formed combinationally ahead of it), and the result is in the
// age-36 register after edge c + 36, for a consumer to sample at edge c + 37. Register ages (the edge
// after the input edge at which a value is first held; LM = 7 is the latency of a fixed-point
// multiplier: product register, then 6 delay registers on the truncated result):
//   age 0        start, v0, edge1, edge2, dir, valid
//   stage 1      pvec products 7, pvec (subtract) 8;  tvec (subtract) 1;  stage 1 ends at age 12
//   stage 2      qvec products 19, qvec 20;  det products 19, det x+y 20, det 21;  ends at age 24
//   stage 3      |det| and s 25;  u, v, t products 31, x+y 32, u/v/t 33;  u*s, v*s, t*s 34;
//                |det| - t_guard 26;  u*s + v*s 35;  the six comparisons and their AND (out_hit), out_valid 36
// Values are held in delay registers (flip-flops, plain shift chains) between where they are formed and
// where they are used; the stage ends (12, 24, 36) are the ages at which the C++ cycle-level wrapper
// (board/cycle_wrapper.h) evaluates stages 1, 2 and 3.
//
// rst is synchronous and clears only the valid chain; data registers are not reset.

module mt_delay #(parameter W = 1, parameter D = 0) (
  input              clk,
  input  [W-1:0]     d,
  output [W-1:0]     q
);
  generate
    if (D == 0) begin : g_wire
      assign q = d;
    end else if (D == 1) begin : g_one
      reg [W-1:0] r;
      always @(posedge clk) r <= d;
      assign q = r;
    end else begin : g_chain
      reg [W*D-1:0] r;
      always @(posedge clk) r <= {r[W*(D-1)-1:0], d};
      assign q = r[W*D-1:W*(D-1)];
    end
  endgenerate
endmodule

// One row of an array multiplier: s = acc +- (x AND en). Kept as its own module in synthesis
// (keep_hierarchy): flattened, Yosys 0.23 merges the rows' adder chain into one macc and maps it to
// about three times the LUTs of the rows (8 x 8 bits: 488 LUTs against 161).
(* keep_hierarchy *)
module mt_row #(parameter W = 8, parameter SUB = 0) (
  input  [W-1:0] acc,
  input  [W-1:0] x,
  input          en,
  output [W-1:0] s
);
  wire [W-1:0] pp = x & {W{en}};
  generate
    if (SUB) begin : g_sub
      assign s = acc - pp;
    end else begin : g_add
      assign s = acc + pp;
    end
  endgenerate
endmodule

// Signed WA x WB multiplier, result bits [SHIFT+WO-1:SHIFT] of the exact product, LAT registers
// (the product register, then LAT-1 delay registers on the WO-bit result).
module mt_mul #(parameter WA = 8, parameter WB = 8, parameter WO = 8, parameter SHIFT = 7,
                parameter LAT = 1, parameter SOFT = 0) (
  input                  clk,
  input  signed [WA-1:0] a,
  input  signed [WB-1:0] b,
  output signed [WO-1:0] p
);
  localparam WP = WA + WB;
  wire signed [WP-1:0] full;
  generate
    if (SOFT) begin : g_array
      // The explicit array: row i adds a * b[i] * 2^i (an AND row into a WP-i bit adder on the upper
      // bits; the low i bits pass); the sign row (b's top bit, weight -2^(WB-1)) subtracts.
      wire signed [WP-1:0] a_ext = a;
      wire [WP*WB-1:0] acc /* verilator split_var */;
      assign acc[WP-1:0] = a_ext & {WP{b[0]}};
      genvar i;
      for (i = 1; i < WB; i = i + 1) begin : g_row
        mt_row #(.W(WP - i), .SUB(i == WB - 1)) row (
          .acc(acc[WP*i-1:WP*(i-1)+i]), .x(a_ext[WP-1-i:0]), .en(b[i]), .s(acc[WP*(i+1)-1:WP*i+i]));
        assign acc[WP*i+i-1:WP*i] = acc[WP*(i-1)+i-1:WP*(i-1)];
      end
      assign full = acc[WP*WB-1:WP*(WB-1)];
    end else begin : g_op
      assign full = a * b;
    end
  endgenerate
  reg signed [WO-1:0] r;
  always @(posedge clk) r <= full[SHIFT+WO-1:SHIFT];
  mt_delay #(.W(WO), .D(LAT-1)) d_out (.clk(clk), .d(r), .q(p));
endmodule

// A 3-vector of delay lines.
module mt_delay3 #(parameter W = 1, parameter D = 0) (
  input clk, input [3*W-1:0] d, output [3*W-1:0] q
);
  mt_delay #(.W(3*W), .D(D)) dl (.clk(clk), .d(d), .q(q));
endmodule

// Cross product a x b (signed WA, WB), truncated terms of WT bits, components of WT+1 bits; vectors
// packed {z, y, x}. Six multipliers then three subtractors: component = first - second, in the order
// x: a.y*b.z - a.z*b.y, y: a.z*b.x - a.x*b.z, z: a.x*b.y - a.y*b.x. Latency LM + 1.
module mt_cross #(parameter WA = 8, parameter WB = 8, parameter WT = 8, parameter N = 7,
                  parameter LM = 7, parameter SOFT = 0) (
  input clk,
  input  [3*WA-1:0] a,
  input  [3*WB-1:0] b,
  output [3*(WT+1)-1:0] c
);
  wire signed [WA-1:0] ax = a[WA-1:0], ay = a[2*WA-1:WA], az = a[3*WA-1:2*WA];
  wire signed [WB-1:0] bx = b[WB-1:0], by = b[2*WB-1:WB], bz = b[3*WB-1:2*WB];
  wire signed [WT-1:0] m0, m1, m2, m3, m4, m5;
  mt_mul #(WA, WB, WT, N, LM, SOFT) u0 (clk, ay, bz, m0);
  mt_mul #(WA, WB, WT, N, LM, SOFT) u1 (clk, az, by, m1);
  mt_mul #(WA, WB, WT, N, LM, SOFT) u2 (clk, az, bx, m2);
  mt_mul #(WA, WB, WT, N, LM, SOFT) u3 (clk, ax, bz, m3);
  mt_mul #(WA, WB, WT, N, LM, SOFT) u4 (clk, ax, by, m4);
  mt_mul #(WA, WB, WT, N, LM, SOFT) u5 (clk, ay, bx, m5);
  reg signed [WT:0] cx, cy, cz;
  always @(posedge clk) begin
    cx <= m0 - m1;
    cy <= m2 - m3;
    cz <= m4 - m5;
  end
  assign c = {cz, cy, cx};
endmodule

// Dot product a . b: three multipliers (truncated terms of WT bits), then two serial adders
// (x + y) + z: WT+1 bits, then WT+2 bits. Latency LM + 2.
module mt_dot #(parameter WA = 8, parameter WB = 8, parameter WT = 8, parameter N = 7,
                parameter LM = 7, parameter SOFT = 0) (
  input clk,
  input  [3*WA-1:0] a,
  input  [3*WB-1:0] b,
  output signed [WT+1:0] d
);
  wire signed [WT-1:0] mx, my, mz, mz1;
  mt_mul #(WA, WB, WT, N, LM, SOFT) ux (clk, a[WA-1:0], b[WB-1:0], mx);
  mt_mul #(WA, WB, WT, N, LM, SOFT) uy (clk, a[2*WA-1:WA], b[2*WB-1:WB], my);
  mt_mul #(WA, WB, WT, N, LM, SOFT) uz (clk, a[3*WA-1:2*WA], b[3*WB-1:2*WB], mz);
  mt_delay #(.W(WT), .D(1)) dz (.clk(clk), .d(mz), .q(mz1));
  reg signed [WT:0] xy;
  reg signed [WT+1:0] sum;
  always @(posedge clk) begin
    xy <= mx + my;
    sum <= xy + mz1;
  end
  assign d = sum;
endmodule

module mt_pipeline #(parameter N = 15, parameter SOFT_MULTS = 0, parameter T_GUARD = 0) (
  input              clk,
  input              rst,
  input              in_valid,
  input  [N-1:0]     start_x, start_y, start_z,  // segment start, unsigned 0.N
  input  [N-1:0]     end_x, end_y, end_z,        // segment end, unsigned 0.N
  input  [N-1:0]     v0_x, v0_y, v0_z,           // triangle vertex 0, unsigned 0.N
  input  [N:0]       e1_x, e1_y, e1_z,           // edge1 = v1 - v0, signed 1.N
  input  [N:0]       e2_x, e2_y, e2_z,           // edge2 = v2 - v0, signed 1.N
  input  [7:0]       t_guard,                    // guard band on t in LSBs (static; see the header)
  output             out_valid,
  output             out_hit
);
  localparam LM = 7;      // multiplier latency
  localparam D = N + 1;   // a difference
  localparam C = N + 2;   // a cross component
  localparam S = N + 4;   // det, u, v, t

  // ---- age 0: input registers; direction = end - start formed ahead of them ----
  reg [N-1:0] st_x, st_y, st_z, vz_x, vz_y, vz_z;
  reg signed [D-1:0] a1_x, a1_y, a1_z, a2_x, a2_y, a2_z, dr_x, dr_y, dr_z;
  reg valid0;
  always @(posedge clk) begin
    st_x <= start_x; st_y <= start_y; st_z <= start_z;
    vz_x <= v0_x; vz_y <= v0_y; vz_z <= v0_z;
    a1_x <= e1_x; a1_y <= e1_y; a1_z <= e1_z;
    a2_x <= e2_x; a2_y <= e2_y; a2_z <= e2_z;
    dr_x <= $signed({1'b0, end_x}) - $signed({1'b0, start_x});
    dr_y <= $signed({1'b0, end_y}) - $signed({1'b0, start_y});
    dr_z <= $signed({1'b0, end_z}) - $signed({1'b0, start_z});
    valid0 <= in_valid & ~rst;
  end
  wire [3*D-1:0] dir0 = {dr_z, dr_y, dr_x};
  wire [3*D-1:0] edge1_0 = {a1_z, a1_y, a1_x};
  wire [3*D-1:0] edge2_0 = {a2_z, a2_y, a2_x};

  // ---- stage 1 (ages 1..12): pvec = dir x edge2 (age 8), tvec = start - v0 (age 1) ----
  wire [3*C-1:0] pvec8, pvec12;
  mt_cross #(D, D, D, N, LM, SOFT_MULTS) c_pvec (.clk(clk), .a(dir0), .b(edge2_0), .c(pvec8));
  mt_delay3 #(C, 12 - (LM + 1)) d_pvec12 (clk, pvec8, pvec12);
  reg signed [D-1:0] tv_x, tv_y, tv_z;
  always @(posedge clk) begin
    tv_x <= $signed({1'b0, st_x}) - $signed({1'b0, vz_x});
    tv_y <= $signed({1'b0, st_y}) - $signed({1'b0, vz_y});
    tv_z <= $signed({1'b0, st_z}) - $signed({1'b0, vz_z});
  end
  wire [3*D-1:0] tvec12;
  mt_delay3 #(D, 11) d_tvec12 (clk, {tv_z, tv_y, tv_x}, tvec12);
  wire [3*D-1:0] edge1_12;
  mt_delay3 #(D, 12) d_edge1 (clk, edge1_0, edge1_12);

  // ---- stage 2 (ages 13..24): qvec = tvec x edge1 (age 20), det = edge1 . pvec (age 21) ----
  wire [3*C-1:0] qvec20, qvec24;
  mt_cross #(D, D, D, N, LM, SOFT_MULTS) c_qvec (.clk(clk), .a(tvec12), .b(edge1_12), .c(qvec20));
  mt_delay3 #(C, 24 - 12 - (LM + 1)) d_qvec24 (clk, qvec20, qvec24);
  wire signed [S-1:0] det21, det24;
  mt_dot #(D, C, C, N, LM, SOFT_MULTS) d_det (.clk(clk), .a(edge1_12), .b(pvec12), .d(det21));
  mt_delay #(.W(S), .D(24 - 12 - (LM + 2))) d_det24 (.clk(clk), .d(det21), .q(det24));
  wire [3*D-1:0] tvec24;
  wire [3*C-1:0] pvec24;
  mt_delay3 #(D, 12) d_tvec24 (clk, tvec12, tvec24);
  mt_delay3 #(C, 12) d_pvec24 (clk, pvec12, pvec24);
  wire [3*D-1:0] dir24, edge2_24;
  mt_delay3 #(D, 24) d_dir24 (clk, dir0, dir24);
  mt_delay3 #(D, 24) d_edge2 (clk, edge2_0, edge2_24);

  // ---- stage 3 (ages 25..36) ----
  // u = tvec . pvec, v = dir . qvec, t = edge2 . qvec (age 33)
  wire signed [S-1:0] u33, v33, t33;
  mt_dot #(D, C, C, N, LM, SOFT_MULTS) d_u (.clk(clk), .a(tvec24), .b(pvec24), .d(u33));
  mt_dot #(D, C, C, N, LM, SOFT_MULTS) d_v (.clk(clk), .a(dir24), .b(qvec24), .d(v33));
  mt_dot #(D, C, C, N, LM, SOFT_MULTS) d_t (.clk(clk), .a(edge2_24), .b(qvec24), .d(t33));
  // |det| and s = sign(det) in parallel (age 25), held until they are used
  reg signed [S-1:0] abs25;
  reg signed [1:0] s25;
  always @(posedge clk) begin
    abs25 <= det24[S-1] ? -det24 : det24;
    s25 <= det24[S-1] ? 2'sb11 : 2'sb01;
  end
  wire signed [1:0] s33;
  wire signed [S-1:0] abs35;
  mt_delay #(.W(2), .D(33 - 25)) d_s33 (.clk(clk), .d(s25), .q(s33));
  mt_delay #(.W(S), .D(35 - 25)) d_abs35 (.clk(clk), .d(abs25), .q(abs35));
  // The t test's bounds: t_guard and |det| - t_guard (age 26; |det| < 2^(S-1) and t_guard < 2^8 <= 2^(S-1)
  // as S >= 11, so the difference fits S signed bits), or 0 and |det| without the guard (T_GUARD = 0)
  wire signed [S-1:0] guard_s, absg35;
  generate
    if (T_GUARD != 0) begin : g_guard
      assign guard_s = $signed({{(S - 8){1'b0}}, t_guard});
      reg signed [S-1:0] absg26;
      always @(posedge clk) absg26 <= abs25 - guard_s;
      mt_delay #(.W(S), .D(35 - 26)) d_absg35 (.clk(clk), .d(absg26), .q(absg35));
    end else begin : g_no_guard
      assign guard_s = {S{1'b0}};
      assign absg35 = abs35;
    end
  endgenerate
  // u*s, v*s, t*s (age 34): multipliers by the 2-bit sign, exact (no truncation), one register
  wire signed [S-1:0] us34, vs34, ts34;
  mt_mul #(S, 2, S, 0, 1, SOFT_MULTS) m_su (clk, u33, s33, us34);
  mt_mul #(S, 2, S, 0, 1, SOFT_MULTS) m_sv (clk, v33, s33, vs34);
  mt_mul #(S, 2, S, 0, 1, SOFT_MULTS) m_st (clk, t33, s33, ts34);
  // u*s + v*s (age 35)
  reg signed [S:0] uv35;
  reg signed [S-1:0] us35, vs35, ts35;
  always @(posedge clk) begin
    uv35 <= us34 + vs34;
    us35 <= us34; vs35 <= vs34; ts35 <= ts34;
  end
  // the decision (age 36): 0 < u*s < |det|, 0 < v*s, u*s + v*s < |det|, t_guard < t*s < |det| - t_guard;
  // all strict (t_guard = 0: the paper's 0 < t*s < |det|)
  wire signed [S:0] abs35_w = abs35;
  reg hit36;
  always @(posedge clk)
    hit36 <= (us35 > 0) & (us35 < abs35) & (vs35 > 0) & (uv35 < abs35_w) & (ts35 > guard_s) & (ts35 < absg35);
  // valid: age 0 -> 36
  reg [35:0] valid_chain;
  always @(posedge clk) valid_chain <= rst ? 36'd0 : {valid_chain[34:0], valid0};
  assign out_valid = valid_chain[35];
  assign out_hit = hit36;
endmodule
