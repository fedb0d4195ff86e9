/**
 * The live viewer (Swing), opened by {@code view}: a window that steps a run, and with a fault its
 * fault-free twin beside it, or a recorded row's runs, while a person watches
 * ({@link sitcov.viewer.ViewerWindow}), and the painter of one run as it stands, with what its controller
 * observed ({@link sitcov.viewer.RunPainter}), which paints off-screen as well. It owns the runs it
 * shows; the model never knows it is watched.
 */
package sitcov.viewer;
