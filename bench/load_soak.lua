-- wrk script for bench/load_soak.sh: a mix of routes a studio's page and CI hit. Each thread cycles
-- through health, tune (64 different requests: cache misses, then hits), a preview request (cached
-- after the first), preview frames and the filmstrip, the page, the OpenAPI document and metrics.
-- Counts statuses per class (globals, which wrk's thread:get can read) and prints them with the latency percentiles at the end.
local preview_id = nil
local requests = {}
local counter = 0
local threads = {}

function setup(thread)
  table.insert(threads, thread)
end

function init(args)
  preview_id = args[1]
  ok_count, client_count, server_count = 0, 0, 0
  local h = {["Content-Type"] = "application/json"}
  local function add(method, path, body, headers) table.insert(requests, wrk.format(method, path, headers, body)) end
  for i = 0, 63 do
    add("POST", "/api/v1/tune", string.format('{"frequency_hz": %g, "damping_ratio": 0.3, "effective_mass": 1}', 1 + i * 0.25), h)
    add("GET", "/api/v1/health")
    if i % 4 == 0 then
      add("POST", "/api/v1/preview", '{"preset": "oscillator", "frames": 8, "size": "320x180"}', h)
      add("GET", "/api/v1/preview/" .. preview_id .. "/" .. (i % 8) .. ".png")
      add("GET", "/api/v1/preview/" .. preview_id .. "/filmstrip.png")
      add("GET", "/api/v1/preview/" .. preview_id)
    end
    if i % 8 == 0 then
      add("GET", "/")
      add("GET", "/api/v1/openapi.json")
      add("GET", "/metrics")
    end
  end
end

function request()
  counter = counter + 1
  return requests[(counter % #requests) + 1]
end

function response(status, headers, body)
  if status >= 500 then
    server_count = server_count + 1
  elseif status >= 400 then
    client_count = client_count + 1
  else
    ok_count = ok_count + 1
  end
end

function done(summary, latency, requests)
  local ok, client, server = 0, 0, 0
  for _, t in ipairs(threads) do
    ok = ok + t:get("ok_count")
    client = client + t:get("client_count")
    server = server + t:get("server_count")
  end
  io.write(string.format("LOAD requests=%d duration_s=%.1f rps=%.0f ok=%d status4xx=%d status5xx=%d " ..
    "socket_errors=%d timeouts=%d p50_ms=%.2f p90_ms=%.2f p99_ms=%.2f p999_ms=%.2f max_ms=%.2f\n",
    summary.requests, summary.duration / 1e6, summary.requests / (summary.duration / 1e6), ok, client, server,
    summary.errors.connect + summary.errors.read + summary.errors.write, summary.errors.timeout,
    latency:percentile(50) / 1000, latency:percentile(90) / 1000, latency:percentile(99) / 1000,
    latency:percentile(99.9) / 1000, latency.max / 1000))
end
