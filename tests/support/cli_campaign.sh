# Sourced by tests/cli/*.sh campaign tests (not a test itself).
# strip FILE: a history/samples CSV without its wall_time_s column (the only column that differs between runs).
strip() { awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="wall_time_s") w=i} {s=""; for(i=1;i<=NF;i++) if(i!=w) s=s (s==""?"":",") $i; print s}' "$1"; }
# write_rosenbrock_campaign FILE EVAL_DELAY_MS MAX_EVALUATIONS: a 2-start COBYLA campaign on the analytic
# Rosenbrock objective inside the unit disc (the delay changes only the time, never a value).
write_rosenbrock_campaign() {
  cat > "$1" <<YAML
# hullopt optimize
optimize:
  algorithm: LN_COBYLA
  max_evaluations: $3
  starts: 2
  seed: 3
  variables: { x1: [-2, 2], x2: [-2, 2] }
  start: { x1: -0.5, x2: 0.5 }
  constraints: { radius_sq_max: 1.0 }
  objective: { analytic: rosenbrock, eval_delay_ms: $2 }
YAML
}
