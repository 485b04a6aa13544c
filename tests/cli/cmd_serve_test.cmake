# `softtune serve` refuses bad flags before it binds (exit 2, a problem naming the flag): here the
# per-client connection limit (server/http/limits.h kMaxConnectionsPerClient), 1 to 1024.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)

foreach(bad 0 1025 1.5 -3)
  expect_problem("--max-client-connections" serve --port 0 --max-client-connections ${bad})
endforeach()
expect_problem("--threads" serve --port 0 --threads 0)
