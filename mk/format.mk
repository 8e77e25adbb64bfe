# The C++ style (.clang-format): make format rewrites every source file in it, make format-check
# (run first by make test) fails on a file that differs. Both are tools/format_check.sh.
format:
	@tools/format_check.sh --fix
format-check: deps
	@tools/format_check.sh
