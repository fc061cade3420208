// Must NOT compile: calls a Unity member the stubs do not declare (Animator.Play is real, but the glue
// does not use it, so the stubs lack it). `Tools~/UnityCheck/check` expects error CS1061 here.
namespace DeltaInterpolator.Unity.MustFail
{
    internal static class MissingMember
    {
        public static void Call(UnityEngine.Animator animator) => animator.Play("Idle");
    }
}
