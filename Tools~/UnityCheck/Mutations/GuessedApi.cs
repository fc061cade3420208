// Must NOT compile: calls the package API as the Editor/ and sample code once guessed it before the Unity
// layer existed (InbetweeningModel.CreateInbetweener, CheckContract). They now compile against the real
// Runtime/Unity, so a guess fails. `Tools~/UnityCheck/check` expects CS1061.
namespace DeltaInterpolator.Unity.MustFail
{
    internal static class GuessedApi
    {
        public static void Call(InbetweeningModel model)
        {
            model.CreateInbetweener();
            model.CheckContract();
        }
    }
}
