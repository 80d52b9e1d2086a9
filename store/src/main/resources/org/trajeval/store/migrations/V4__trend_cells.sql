-- trajeval results store, schema v4: trends kept as aggregates (issue 14, scale), so a trend over the
-- whole history reads a few thousand cells instead of every run. Immutable once released, like V1-V3.
--
-- One row per (metric, slice column, slice value, software version, UTC day): the successful runs
-- (status 'ok', recorded_ms >= 0) with a finite value of the metric, as their count, the sum and the
-- sum of squares of the values, each sum kept as a compensated pair (sum + sum_lo: the rounding
-- error of every addition is added to sum_lo, Neumaier's summation, so the pair's total is the
-- exact sum in all but extreme cases) and the earliest and latest recording times. Every trend
-- bucket (day, week = day / 7, version) of every slice (robot, site, route, method,
-- software_version) is a sum of these rows. A label that is NULL in runs is '' here with its
-- *_missing flag 1 (a primary key column cannot be NULL, and '' is a label of its own).
-- Maintained by ResultsStore.record in the transaction that inserts the runs, from the runs that
-- were new (a re-recorded result adds nothing); this file fills it from the runs already stored.
CREATE TABLE trend_cells (
    metric            VARCHAR(32)      NOT NULL,
    slice             VARCHAR(32)      NOT NULL,
    day               BIGINT           NOT NULL,
    slice_value       TEXT             NOT NULL,
    slice_missing     SMALLINT         NOT NULL,
    software_version  TEXT             NOT NULL,
    version_missing   SMALLINT         NOT NULL,
    n                 BIGINT           NOT NULL,
    sum               DOUBLE PRECISION NOT NULL,
    sum_lo            DOUBLE PRECISION NOT NULL,
    sum_squares       DOUBLE PRECISION NOT NULL,
    sum_squares_lo    DOUBLE PRECISION NOT NULL,
    first_ms          BIGINT           NOT NULL,
    last_ms           BIGINT           NOT NULL,
    PRIMARY KEY (metric, slice, day, slice_value, slice_missing, software_version, version_missing)
);
INSERT INTO trend_cells (metric, slice, day, slice_value, slice_missing, software_version, version_missing, n, sum,
        sum_lo, sum_squares, sum_squares_lo, first_ms, last_ms)
    SELECT k.metric, k.slice, k.day, COALESCE(k.v, ''), CASE WHEN k.v IS NULL THEN 1 ELSE 0 END,
            COALESCE(k.ver, ''), CASE WHEN k.ver IS NULL THEN 1 ELSE 0 END, COUNT(*), SUM(k.x), 0, SUM(k.x * k.x), 0,
            MIN(k.ms), MAX(k.ms)
    FROM (SELECT m.column1 AS metric, s.column1 AS slice, r.recorded_ms / 86400000 AS day, r.recorded_ms AS ms,
                CASE s.column1 WHEN 'robot' THEN r.robot WHEN 'site' THEN r.site WHEN 'route' THEN r.route
                    WHEN 'method' THEN r.method ELSE r.software_version END AS v,
                r.software_version AS ver,
                CASE m.column1 WHEN 'coverage' THEN r.coverage WHEN 'ate_trans_rmse_m' THEN r.ate_trans_rmse_m
                    WHEN 'ate_trans_mean_m' THEN r.ate_trans_mean_m WHEN 'ate_rot_rmse_rad' THEN r.ate_rot_rmse_rad
                    WHEN 'rpe_trans_rmse_m' THEN r.rpe_trans_rmse_m WHEN 'rpe_rot_rmse_rad' THEN r.rpe_rot_rmse_rad
                    WHEN 'drift_trans_pct' THEN r.drift_trans_pct ELSE r.score END AS x
            FROM runs r
            CROSS JOIN (VALUES ('robot'), ('site'), ('route'), ('method'), ('software_version')) s
            CROSS JOIN (VALUES ('coverage'), ('ate_trans_rmse_m'), ('ate_trans_mean_m'), ('ate_rot_rmse_rad'),
                ('rpe_trans_rmse_m'), ('rpe_rot_rmse_rad'), ('drift_trans_pct'), ('score')) m
            WHERE r.status = 'ok' AND r.recorded_ms >= 0) k
    WHERE k.x IS NOT NULL
    GROUP BY k.metric, k.slice, k.day, k.v, k.ver;
-- A gate on one robot between versions (--baseline robot=bot-7,version=2.3): one robot's runs of one
-- version, instead of every run of the version read from the table to test its robot. SQLite takes it
-- once it has statistics (ResultsStore runs PRAGMA optimize); without them it keeps runs_by_version_gate,
-- whose order saves the GROUP BY's sort.
CREATE INDEX runs_by_robot_version ON runs (robot, software_version);
