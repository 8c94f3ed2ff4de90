// Compiled first by Icarus (scripts/conformance.py): a 1 ns unit for every module after it, so
// the testbench's 10 ns clock is real time in the waves. Verilator takes --timescale instead.
`timescale 1ns / 1ps
