// The conformance testbench's coverage counts, written at the end of each test's run (make
// conformance measures the suite's reach on the coverage plan, docs/coverage.md): to
// OUT/<test>/coverage.dat, the directory of the testbench's +out= plusarg.
module zb_conf_cov_writer;
  import "DPI-C" function void zb_cov_write(input string path);
  final begin
    string dir;
    if ($value$plusargs("out=%s", dir)) zb_cov_write({dir, "/coverage.dat"});
  end
endmodule

bind zb_conf_tb zb_conf_cov_writer u_cov_writer ();
