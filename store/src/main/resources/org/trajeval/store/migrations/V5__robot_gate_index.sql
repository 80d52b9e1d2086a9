-- trajeval results store, schema v5: a gate on one robot between versions reads one index. V4's
-- (robot, software_version) index was taken by SQLite for the gate's per-side counts but not for its
-- pairing query at 10^6 runs, where the planner still preferred runs_by_version_gate (whose order saves
-- the GROUP BY's sort) and read every run of the version from the table to test its robot (0.28 s). This
-- index holds what that query reads, in the order it groups by, once the robot and version are fixed.
-- Immutable once released, like V1-V4.
DROP INDEX runs_by_robot_version;
CREATE INDEX runs_by_robot_gate ON runs (robot, software_version, method, route, seed, status, ate_trans_rmse_m,
    rpe_trans_rmse_m);
