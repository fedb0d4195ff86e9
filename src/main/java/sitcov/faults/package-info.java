/**
 * The seeded faults: the {@link sitcov.faults.Fault} catalogue and the per-run
 * {@link sitcov.faults.FaultSwitchboard} the autonomous car consults, which records each fault's
 * activation. Depends only on the engine.
 */
package sitcov.faults;
