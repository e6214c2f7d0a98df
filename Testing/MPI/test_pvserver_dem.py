"""The DEM pipeline of issue 39 built by a client on `mpiexec -n 2 pvserver` (loopback), as
the GUI client builds it: GDALRasterReader -> DEMSurface -> RedistributeDataSet ->
MalleabilityPaint -> ChainMailDeformation (mpi_pipeline.plain_pipeline, case paint). The
reader gives the raster to rank 0; before DEMSurface took rank 1's empty raster as a piece
the server hung (rank 0 in RedistributeDataSet's MPI_Allreduce) and so did the client.
The client runs in a child pvpython with a time limit, so a hang fails the test and the
server is stopped; its figures (the deformed bounds, points displaced, the grasp's
malleability) must equal a builtin session's. Usage: test_pvserver_dem.py (the driver);
test_pvserver_dem.py client PORT OUT (one client: PORT 0 is builtin)."""
import json
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Python"))


def client(port, out):
    """Builds and updates the pipeline on the server at `port` (0: builtin), writes its
    figures to `out` (JSON)."""
    from paraview.simple import Connect, Disconnect, LoadPlugin
    import paraview.simple as simple
    from mpi_pipeline import plain_pipeline

    if port:
        Connect("127.0.0.1", port)
    # On the server (its filters) and, when connected, here too (the proxies' client side).
    for remote in ((False, True) if port else (False,)):
        LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], remote=remote, ns=vars(simple))
    _, chain = plain_pipeline("paint", os.environ["DEM_TIF"], vars(simple))
    chain.UpdatePipeline()
    chain.UpdatePropertyInformation()
    info = chain.GetDataInformation()
    figures = {"bounds": list(info.GetBounds()),
               "displaced": chain.GetProperty("NumberOfDisplacedPoints").GetData(),
               "grasp": chain.GetProperty("LastGraspMalleability").GetData()}
    with open(out, "w") as f:
        json.dump(figures, f)
    if port:
        Disconnect()


def driver():
    import pvserver_process
    from mpi_driver import ENV, fail, plain_parameters, run_client, write_dem
    import paraview.simple as simple

    with tempfile.TemporaryDirectory(dir=os.environ.get("GEOSHAPING_TEST_TMP")) as tmp:
        tif = os.path.join(tmp, "dem.tif")
        write_dem(tif)
        simple.LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=vars(simple))
        surface = vars(simple)["DEMSurface"](Input=simple.GDALRasterReader(FileName=tif))
        surface.UpdatePipeline()
        plain_parameters(surface.GetDataInformation().GetBounds())
        ENV["DEM_TIF"] = tif
        env = {k: v for k, v in ENV.items()
               if not (k.startswith("OMPI_") or k.startswith("PMIX_") or k.startswith("OPAL_"))}

        def client_answer(port, name):
            return run_client(__file__, port, os.path.join(tmp, name + ".json"), env)

        builtin, why = client_answer(0, "builtin")
        if builtin is None:
            fail("builtin: " + why)
        print("builtin: %s" % builtin)
        if builtin["displaced"] < 50:
            fail("only %d points displaced in the builtin session" % builtin["displaced"])
        proc, port, log = pvserver_process.start(2, os.path.join(tmp, "pvserver.log"))
        try:
            served, why = client_answer(port, "pvserver")
        finally:
            pvserver_process.stop(proc, 20)  # pvserver ends when its client disconnects
            log.seek(0)
            server_log = log.read()
        if served is None:
            fail("2-rank pvserver: %s\nserver log: %s" % (why, server_log[-2000:]))
        print("2-rank pvserver: %s" % served)
        if "ERR|" in server_log:
            fail("the server logged an error: " + server_log[-2000:])
        if served != builtin:
            fail("the 2-rank pvserver's figures differ from the builtin session's")
        print("ok: the 2-rank pvserver equals the builtin session")


if __name__ == "__main__":
    if sys.argv[1:2] == ["client"]:
        client(int(sys.argv[2]), sys.argv[3])
    else:
        driver()
