/**
 * The seeded faults: the {@link sitcov.faults.Fault} catalogue and the per-run
 * {@link sitcov.faults.FaultSwitchboard} the autonomous car consults, which records each fault's
 * activation. Depends only on the engine. The switchboard keeps no final instance fields: a
 * checkpoint copies it field by field ({@link sitcov.engine.ModelCopy}).
 */
package sitcov.faults;
